# Fig. 7a: the initial composition phi_hat in the kinematic drum (perfectly mixed, 0.5), inertial frame.
# needs: verify_tumbler_kinematic
# reads: tumbler_initial.dat tumbler_outline.dat
# Data: tumbler_initial.dat (bed cells: x z phi_hat, h = 1 mm), tumbler_outline.dat (wall, surface,
#       layer bottom), written by verify_tumbler_kinematic from figures/tumbler_kinematic.toml.
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7a_tumbler_kinematic.gp
width = 800; height = 760; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
cells = datadir.'/tumbler_initial.dat'
outline = datadir.'/tumbler_outline.dat'
h = 0.001
set title "Fig. 7a: phi_hat at t = 0 (mixed), D = 0.1 m, 75 % fill, inertial frame"
set size ratio -1
set xrange [-5.3:5.3]
set yrange [-5.3:5.3]
set xlabel "x  [cm]"
set ylabel "z  [cm]"
set cbrange [0:1]
set cblabel "phi_hat (small-particle share)"
set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c")
set key top left
plot cells u (100*$1):(100*$2):(50*h):(50*h):3 w boxxy fs solid 1.0 noborder fc palette notitle, \
     outline index 0 u (100*$1):(100*$2) w l lw 2 lc rgb "black" t "drum wall", \
     outline index 1 u (100*$1):(100*$2) w l lw 2 lc rgb "#444444" t "free surface", \
     outline index 2 u (100*$1):(100*$2) w l lw 1.5 dt 2 lc rgb "#444444" t "layer bottom"
