# Fig. 7b: close-up of the surface region of the kinematic drum after 25 s: phi_hat (colour), the
# inertial velocity (arrows, every 2nd cell) and the segregation direction d_s (black, layer cells).
# needs: verify_tumbler_kinematic
# reads: tumbler_final.dat tumbler_flow.dat tumbler_outline.dat
# Data: tumbler_final.dat (x z phi_hat), tumbler_flow.dat (x z in_layer ux uz ds_x ds_z T a_x a_z),
#       tumbler_outline.dat.
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7b_tumbler_kinematic.gp
width = 1300; height = 800; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
cells = datadir.'/tumbler_final.dat'
flow = datadir.'/tumbler_flow.dat'
outline = datadir.'/tumbler_outline.dat'
h = 0.001
idx(c) = int(floor((c + 0.05) / h))
keep(x, z, k) = (idx(x) % k == 0 && idx(z) % k == 0)
set title "Fig. 7b: surface region at t = 25 s: velocity u (grey, every 2nd cell) and d_s (black, layer cells), inertial frame"
set size ratio -1
set xrange [-5.2:3.2]
set yrange [-0.5:4.6]
set xlabel "x  [cm]"
set ylabel "z  [cm]"
set cbrange [0:1]
set cblabel "phi_hat"
set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c")
set key bottom right opaque
sc = 2.0    # cm per (m/s)
ds = 0.16   # cm, length of a d_s segment
plot cells u (100*$1):(100*$2):(50*h):(50*h):3 w boxxy fs solid 1.0 noborder fc palette notitle, \
     outline index 0 u (100*$1):(100*$2) w l lw 2 lc rgb "black" t "drum wall", \
     outline index 1 u (100*$1):(100*$2) w l lw 2 lc rgb "#444444" t "free surface", \
     outline index 2 u (100*$1):(100*$2) w l lw 1.5 dt 2 lc rgb "#444444" t "layer bottom", \
     flow u (keep($1, $2, 2) ? 100*$1 : 1/0):(100*$2):(sc*$4):(sc*$5) w vectors head size 0.08,20 filled lc rgb "#555555" t "u", \
     flow u ($3 > 0 && keep($1 + h, $2 + h, 2) ? 100*$1 - ds/2*$6 : 1/0):(100*$2 - ds/2*$7):(ds*$6):(ds*$7) \
          w vectors nohead lw 1.5 lc rgb "black" t "d_s"
