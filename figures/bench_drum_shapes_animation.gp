# The square and the triangular drum over their three turns as an animated GIF (written next to
# the PNG: the PNG's name with .gif; both drums side by side, walls turning with them) and, in the
# PNG, six frames of the triangular drum (docs/drum_shapes.md).
# needs: bench_drum_shapes
# reads: drum_square/frames/frame_030.dat drum_triangle/frames/frame_030.dat
# Data: DIR/frames/frame_NNN.dat (x z phi_hat of the bed cells, lab frame; frame 0 at t = 0, then
#       every 0.5 s to 15 s), DIR = benchdir/drum_square and benchdir/drum_triangle.
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_drum_shapes_animation.gp
h = 100 * 0.1 / 60   # cell size, cm
R = 5.0              # radius of the circle through the corners, cm
frames = 30
t_end = 15.0
rps = 0.2
frame(name, i) = sprintf("%s/%s/frames/frame_%03d.dat", benchdir, name, i)
# Corner k of a regular n-gon with a side at the bottom at t = 0, turned by the drum at time t.
corner_x(n, k, t) = R * cos(-pi/2 - pi/n + 2*pi*k/n + 2*pi*rps*t)
corner_z(n, k, t) = R * sin(-pi/2 - pi/n + 2*pi*k/n + 2*pi*rps*t)
# The command that makes polygon object 1 the wall of the n-gon at time t (corners k..n by recursion).
corners(n, k, t) = k > n ? "" : sprintf(" to %g,%g", corner_x(n, k, t), corner_z(n, k, t)).corners(n, k + 1, t)
wall(n, t) = sprintf("set object 1 polygon from %g,%g", corner_x(n, 0, t), corner_z(n, 0, t)).corners(n, 1, t). \
             " front fillstyle empty border lc rgb 'black' lw 2"
set size ratio -1
set xrange [-5.3:5.3]
set yrange [-5.3:5.3]
set cbrange [0:1]
set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c")
unset key
unset colorbox
gif = outfile[1:strstrt(outfile, ".png") - 1].".gif"
set terminal gif animate delay 15 size 900,450 font "Sans,10"
set output gif.".tmp"
do for [i = 0:frames] {
    t = i * t_end / frames
    set multiplot layout 1,2 title sprintf("phi_hat, t = %.1f s (lab frame)", t)
    do for [n = 4:3:-1] {
        name = (n == 4 ? 'drum_square' : 'drum_triangle')
        eval(wall(n, t))
        plot frame(name, i) u (100*$1):(100*$2):(h/2):(h/2):3 w boxxy fs solid 1.0 noborder fc palette
    }
    unset multiplot
}
unset output
system("mv '".gif.".tmp' '".gif."'")
width = 1500; height = 1000; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
set multiplot layout 2,3 title sprintf("triangular drum: phi_hat over three turns (animation of both drums: %s)", gif)
do for [j = 0:5] {
    i = int(j * frames / 5.0 + 0.5)
    t = i * t_end / frames
    set title sprintf("t = %.1f s", t)
    eval(wall(3, t))
    plot frame('drum_triangle', i) u (100*$1):(100*$2):(h/2):(h/2):3 w boxxy fs solid 1.0 noborder fc palette
}
unset multiplot
