# The half-filled square drum and the triangular drum after three turns (docs/drum_shapes.md):
# phi_hat of the bed cells in the lab frame, the wall drawn where it stands at t_end.
# needs: bench_drum_shapes
# reads: drum_square/frames/frame_030.dat drum_triangle/frames/frame_030.dat
# Data: DIR/frames/frame_NNN.dat (x z phi_hat of the bed cells, lab frame), DIR = benchdir/drum_square
#       and benchdir/drum_triangle (verification/scenes/drum_*.toml: D = 0.1 m across the circle
#       through the corners, 60 cells across it, 0.2 rps, 15 s, frames every 0.5 s).
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_drum_shapes.gp
width = 1400; height = 700; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
h = 100 * 0.1 / 60   # cell size, cm
R = 5.0              # radius of the circle through the corners, cm
turns = 3.0          # 0.2 rps for 15 s: the walls stand where they started
# Corner k of a regular n-gon with a side at the bottom (orientation 0), turned by `turns`.
corner_x(n, k) = R * cos(-pi/2 - pi/n + 2*pi*k/n + 2*pi*turns)
corner_z(n, k) = R * sin(-pi/2 - pi/n + 2*pi*k/n + 2*pi*turns)
# The command that makes polygon object 1 the wall of the n-gon (corners k..n by recursion).
corners(n, k) = k > n ? "" : sprintf(" to %g,%g", corner_x(n, k), corner_z(n, k)).corners(n, k + 1)
wall(n) = sprintf("set object 1 polygon from %g,%g", corner_x(n, 0), corner_z(n, 0)).corners(n, 1). \
          " front fillstyle empty border lc rgb 'black' lw 2"
set multiplot layout 1,2 title "phi_hat (small-particle share) after three turns, bidisperse 50/50 mixture at t = 0, lab frame"
set size ratio -1
set xrange [-5.3:5.3]
set yrange [-5.3:5.3]
set xlabel "x  [cm]"
set ylabel "z  [cm]"
set cbrange [0:1]
set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c")
do for [n = 4:3:-1] {
    dir = benchdir.(n == 4 ? '/drum_square' : '/drum_triangle')
    set title (n == 4 ? "(a) square drum, half full" : "(b) triangular drum, filled to half its height")
    eval(wall(n))
    plot dir.'/frames/frame_030.dat' u (100*$1):(100*$2):(h/2):(h/2):3 w boxxy fs solid 1.0 noborder fc palette notitle
}
unset multiplot
