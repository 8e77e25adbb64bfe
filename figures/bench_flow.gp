# Cost of the flow solver on the tumbler-flow drum (make bench).
# needs: bench_flow
# Data: bench_flow.dat (cells_per_diameter threads inside_cells Mcell_updates_per_s dt
#       steps_for_25s seconds_for_25s share_closures share_convection share_viscosity share_temperature).
set terminal pngcairo size 1500,480 font "Sans,11" noenhanced
set output outfile
set multiplot layout 1,3 title "Flow solver on the tumbler-flow drum: medians of 5 windows from the initial state"
set grid
f = benchdir.'/bench_flow.dat'
set title "(a) cell updates per second"
set xlabel "cells per diameter"
set ylabel "Mcell-updates/s"
set logscale x
set xrange [40:250]
set key bottom left
# rows alternate: 1 thread, 2 threads
plot f every 2::0 u 1:4 w lp pt 7 t "1 thread", f every 2::1 u 1:4 w lp pt 5 t "2 threads"
set title "(b) time step and estimated wall time for 25 s"
set ylabel "dt [s]"
set y2label "wall time for 25 s [s]"
set logscale y
set logscale y2
set ytics nomirror
set y2tics
set key bottom left
set y2range [10:1e4]
plot f every 2::0 u 1:5 w lp pt 7 t "dt (CFL 0.9 on |u|+c)", \
     f every 2::0 u 1:7 axes x1y2 w lp pt 6 t "25 s, 1 thread", \
     f every 2::1 u 1:7 axes x1y2 w lp pt 4 t "25 s, 2 threads", 60 axes x1y2 w l dt 2 lc rgb "black" t "target 60 s"
unset logscale y
unset logscale y2
unset y2tics
unset y2label
set ytics mirror
set title "(c) share of the step time (1 thread)"
set style data histograms
set style histogram rowstacked
set style fill solid 0.8 border -1
set boxwidth 0.6
unset logscale x
set xrange [*:*]
set yrange [0:1]
set xlabel "cells per diameter"
set ylabel "share"
set key outside right
plot f every 2::0 u 8:xtic(1) t "closures", '' every 2::0 u 9 t "convection", \
     '' every 2::0 u 10 t "viscosity", '' every 2::0 u 11 t "temperature"
unset multiplot
