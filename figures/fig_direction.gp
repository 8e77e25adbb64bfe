# The Sect. 2.3 direction procedure: stability near a repeated eigenvalue, and the tilt of d_s
# when shear and extension combine.
# needs: verify_direction verify_direction_stability
# reads: direction_stability.dat direction_tilt.dat
# Data: direction_stability.dat (relative_gap err_iterative err_closed_form bound) and
#       direction_tilt.dat (e_over_gamma tilt_deg tilt_exact_deg).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig_direction.gp
width = 1400; height = 560; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
set multiplot layout 1,2 title "Sect. 2.3 segregation direction d_s"
set grid

set title "(a) error of d_s near a repeated extreme eigenvalue (max over 400 rotations)"
set logscale xy
set format x "1e%T"
set format y "1e%T"
set xlabel "relative gap g = (kappa_max - kappa_mid)/(kappa_max - kappa_min)"
set ylabel "|d_s - exact|"
set key top right
plot datadir.'/direction_stability.dat' u 1:2 w lp pt 7 lw 2 t "Eigen compute (iterative, default)", \
     datadir.'/direction_stability.dat' u 1:3 w lp pt 5 lw 2 t "Eigen computeDirect (closed form)", \
     datadir.'/direction_stability.dat' u 1:4 w l dt 2 lw 2 lc rgb "black" t "stated bound 8 eps/g"

set title "(b) shear gamma plus planar extension e: tilt of d_s from the shear normal"
unset logscale
set format x "%g"
set format y "%g"
set xlabel "e / gamma"
set ylabel "angle between d_s and e_z  [deg]"
set key top left
plot datadir.'/direction_tilt.dat' u 1:3 w l lw 2 lc rgb "#1f77b4" t "exact (1/2) abs(atan(2e/gamma))", \
     datadir.'/direction_tilt.dat' u 1:2 w p pt 7 ps 0.6 lc rgb "#d62728" t "granseg"
unset multiplot
