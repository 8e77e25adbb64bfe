# Fig. 7a: the coupled drum (scene kind tumbler) at t = 0: phi_hat of the bed, lab frame.
# needs: verify_tumbler
# Data: DIR/initial_lab.dat (x z Phi phi_hat u_x u_z T ds_x ds_z inside urel_x urel_z a_x a_z; one
#       block per row), DIR = datadir/tumbler (verify_tumbler, 32 cells per diameter) unless the
#       caller sets dir (figures/full_fig7a_tumbler.gp: make fig7, 100 cells per diameter).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7a_tumbler.gp
if (!exists("dir")) dir = datadir.'/tumbler'
f = dir.'/initial_lab.dat'
load 'figures/tumbler_common.gp'
set terminal pngcairo size 800,760 font "Sans,11" noenhanced
set output outfile
set title sprintf("Fig. 7a: phi_hat at t = 0 (perfectly mixed), %d cells per diameter, lab frame", n)
set cblabel "phi_hat (small-particle share)"
set parametric
set trange [0:1]
plot f u (100*$1):(100*$2):(50*h):(50*h):(bed($10, $3) ? $4 : 1/0) w boxxy fs solid 1.0 noborder fc palette notitle, \
     R*cos(2*pi*t), R*sin(2*pi*t) w l lw 2 lc rgb "black" t "drum wall"
