# Fig. 7c: phi_hat after 25 s in the kinematic drum (inertial frame), with the radial profile and
# the segregation index over time.
# needs: verify_tumbler_kinematic
# reads: tumbler_final.dat tumbler_outline.dat tumbler_shells.dat tumbler_metrics.dat
# Data: tumbler_final.dat (x z phi_hat), tumbler_outline.dat, tumbler_shells.dat (r phi_hat_initial
#       phi_hat_final cells), tumbler_metrics.dat (t index core ring periphery mean core_deviation).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7c_tumbler_kinematic.gp
#   Any run of a tumbler-kinematic scene, whatever its grid and length: datadir='out/drum40' (the
#   cell size is read from tumbler_final.dat, the run's length from tumbler_metrics.dat).
width = 1500; height = 720; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
cells = datadir.'/tumbler_final.dat'
outline = datadir.'/tumbler_outline.dat'
shells = datadir.'/tumbler_shells.dat'
metrics = datadir.'/tumbler_metrics.dat'
h = real(system("sed -n 's/.*cell size \\([0-9.e+-]*\\) m.*/\\1/p' ".cells))   # m
stats outline index 0 u 1 nooutput
D = STATS_max - STATS_min
stats metrics u 1 nooutput
t_end = STATS_max
r_core = 1.7
r_ring = 2.5
set multiplot title sprintf("Fig. 7c: kinematic drum after %g s, %d cells per diameter", t_end, int(D/h + 0.5))

set origin 0, 0
set size 0.52, 0.95
set title sprintf("phi_hat at t = %g s (dashed circles: r_core = d - delta0, d)", t_end)
set size ratio -1
set xrange [-5.3:5.3]
set yrange [-5.3:5.3]
set xlabel "x  [cm]"
set ylabel "z  [cm]"
set cbrange [0:1]
set cblabel "phi_hat"
set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c")
set parametric
set trange [0:2*pi]
plot cells u (100*$1):(100*$2):(50*h):(50*h):3 w boxxy fs solid 1.0 noborder fc palette notitle, \
     outline index 0 u (100*$1):(100*$2) w l lw 2 lc rgb "black" notitle, \
     outline index 1 u (100*$1):(100*$2) w l lw 2 lc rgb "#444444" notitle, \
     outline index 2 u (100*$1):(100*$2) w l lw 1.5 dt 2 lc rgb "#444444" notitle, \
     r_core*cos(t), r_core*sin(t) w l lw 1 dt 3 lc rgb "black" notitle, \
     r_ring*cos(t), r_ring*sin(t) w l lw 1 dt 3 lc rgb "black" notitle
unset parametric
unset colorbox

set origin 0.53, 0.48
set size 0.46, 0.46
set size noratio
set title "phi_hat averaged in radial shells"
set xrange [0:5]
set yrange [0:1]
set xlabel "r  [cm]"
set ylabel "phi_hat"
set key bottom left
set arrow 1 from r_core, 0 to r_core, 1 nohead dt 3
set arrow 2 from r_ring, 0 to r_ring, 1 nohead dt 3
set arrow 3 from 4, 0 to 4, 1 nohead dt 3
set label 1 "core" at 0.3, 0.93
set label 2 "ring" at 1.85, 0.07
set label 3 "periphery" at 4.05, 0.93
plot shells u (100*$1):2 w lp pt 6 lc rgb "#888888" t "t = 0", \
     shells u (100*$1):3 w lp pt 7 lc rgb "#d7191c" t sprintf("t = %g s", t_end)
unset arrow
unset label

set origin 0.53, 0.0
set size 0.46, 0.46
set title "index std(phi_hat)/sqrt(m(1-m)) and regional fractions"
set xrange [0:t_end]
set yrange [0:1]
set xlabel "t  [s]"
set ylabel ""
set key at graph 0.98, graph 0.42 top right horizontal maxrows 2   # between the periphery and the others
plot metrics u 1:2 w l lw 2 lc rgb "black" t "index", \
     metrics u 1:4 w l lw 2 lc rgb "#d7191c" t "ring", \
     metrics u 1:3 w l lw 2 lc rgb "#fdae61" t "core", \
     metrics u 1:5 w l lw 2 lc rgb "#2c7bb6" t "periphery"
unset multiplot
