# Fig. 7c: the coupled drum after the run: phi_hat (lab frame) and the pattern metrics over time.
# needs: verify_tumbler
# Data: DIR/fields_lab.dat (x z Phi phi_hat ... inside ...), DIR/history.dat (t steps mass_small
#       mass_large segregation_index surface_angle_deg ring periphery core ...), DIR as in
#       fig7a_tumbler.gp. Regions (pattern_metrics.hpp): core r < 1.7 cm, ring 1.7..2.5 cm,
#       periphery r >= 4 cm in the Sect. 4.2 drum.
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7c_tumbler.gp
if (!exists("dir")) dir = datadir.'/tumbler'
f = dir.'/fields_lab.dat'
history = dir.'/history.dat'
stats history u 1 nooutput
t_end = STATS_max
load 'figures/tumbler_common.gp'   # after the stats: it sets the x range, which stats would filter by
set terminal pngcairo size 1500,720 font "Sans,11" noenhanced
set output outfile
set multiplot title sprintf("Fig. 7c: the coupled drum after %g s, S0 = 1 s^2/m, %d cells per diameter", t_end, n)
set origin 0, 0
set size 0.52, 0.95
set title sprintf("phi_hat at t = %g s (dashed: r = 0.34 R, 0.5 R, 0.8 R)", t_end)
set cblabel "phi_hat"
set parametric
set trange [0:1]
plot f u (100*$1):(100*$2):(50*h):(50*h):(bed($10, $3) ? $4 : 1/0) w boxxy fs solid 1.0 noborder fc palette notitle, \
     R*cos(2*pi*t), R*sin(2*pi*t) w l lw 2 lc rgb "black" notitle, \
     0.34*R*cos(2*pi*t), 0.34*R*sin(2*pi*t) w l dt 3 lc rgb "black" notitle, \
     0.5*R*cos(2*pi*t), 0.5*R*sin(2*pi*t) w l dt 3 lc rgb "black" notitle, \
     0.8*R*cos(2*pi*t), 0.8*R*sin(2*pi*t) w l dt 3 lc rgb "black" notitle
unset parametric
unset colorbox
set origin 0.53, 0.05
set size 0.46, 0.85
set size noratio
set title "index std(phi_hat)/sqrt(m(1-m)) and the regions' small-particle fractions"
set xrange [0:t_end]
set yrange [0:1]
set xlabel "t  [s]"
set ylabel ""
set key below horizontal   # off the curves, whatever the run
plot history u 1:5 w l lw 2 lc rgb "black" t "index", \
     history u 1:7 w l lw 2 lc rgb "#d7191c" t "ring", \
     history u 1:9 w l lw 2 lc rgb "#fdae61" t "core", \
     history u 1:8 w l lw 2 lc rgb "#2c7bb6" t "periphery"
unset multiplot
