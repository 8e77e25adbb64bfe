# Fig. 7c and 7d of the whole model side by side, for the README: phi_hat and Phi after the run of
# make fig7 (100 cells per diameter, 25 s); the same maps as the left panels of full_fig7c_tumbler.gp
# and full_fig7d_tumbler.gp.
# needs: run_tumbler
# reads: tumbler/fields_lab.dat tumbler/initial_lab.dat
# Data: the coupled drum of verification/scenes/tumbler.toml, run by make into rundir/tumbler
#       (fields_lab.dat: x z Phi phi_hat ... inside ...).
dir = rundir.'/tumbler'
f = dir.'/fields_lab.dat'
load 'figures/tumbler_common.gp'
width = 1500; height = 700; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
set multiplot layout 1,2 title sprintf("The paper's drum after 25 s, %d cells per diameter: Fig. 7c (small-particle share phi_hat) and Fig. 7d (granular volume fraction Phi)", n)
set title "Fig. 7c: phi_hat"
set cblabel "phi_hat"
plot f u (100*$1):(100*$2):(50*h):(50*h):(bed($10, $3) ? $4 : 1/0) w boxxy fs solid 1.0 noborder fc palette notitle
set title "Fig. 7d: Phi (denser where mixed)"
set cbrange [0.56:0.66]
set cblabel "Phi"
set palette defined (0 "#f7fbff", 0.5 "#6baed6", 1 "#08306b")
plot f u (100*$1):(100*$2):(50*h):(50*h):(bed($10, $3) ? $3 : 1/0) w boxxy fs solid 1.0 noborder fc palette notitle
unset multiplot
