# The coupled drum's phi_hat over the run as an animated GIF (written next to the PNG: the PNG's
# name with .gif) and, in the PNG, six of its frames.
# needs: verify_tumbler
# Data: DIR/frames/frame_NNN.dat (x z phi_hat of the bed cells, lab frame; frame 0 at t = 0,
#       then every t_end/frames), DIR/history.dat (for the time), DIR as in fig7a_tumbler.gp.
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7e_tumbler_animation.gp
if (!exists("dir")) dir = datadir.'/tumbler'
f = dir.'/initial_lab.dat'
frames = int(system("ls ".dir."/frames | wc -l")) - 1
stats dir.'/history.dat' u 1 nooutput
t_end = STATS_max
load 'figures/tumbler_common.gp'   # after the stats: it sets the x range, which stats would filter by
frame(i) = sprintf("%s/frames/frame_%03d.dat", dir, i)
gif = outfile[1:strstrt(outfile, ".png") - 1].".gif"
set terminal gif animate delay 12 size 600,600 font "Sans,10"
set output gif.".tmp"
unset key
do for [i = 0:frames] {
    set title sprintf("phi_hat, t = %.1f s (lab frame)", i * t_end / frames)
    plot frame(i) u (100*$1):(100*$2):(50*h):(50*h):3 w boxxy fs solid 1.0 noborder fc palette notitle
}
unset output
system("mv '".gif.".tmp' '".gif."'")
set terminal pngcairo size 1500,1000 font "Sans,11" noenhanced
set output outfile
set multiplot layout 2,3 title sprintf("phi_hat over the run (animation: %s), %d cells per diameter", gif, n)
unset colorbox
do for [j = 0:5] {
    i = int(j * frames / 5.0 + 0.5)
    set title sprintf("t = %.1f s", i * t_end / frames)
    plot frame(i) u (100*$1):(100*$2):(50*h):(50*h):3 w boxxy fs solid 1.0 noborder fc palette notitle
}
unset multiplot
