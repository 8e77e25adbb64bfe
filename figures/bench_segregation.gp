# Work-precision of the segregation schemes: L1 error against CPU time (median of 5 runs),
# N = 50 .. 12800, and the cell updates per second.
# needs: bench_segregation
# Data: bench_segregation.dat (gnuplot index = 4*problem + scheme; problem 0 two-shock, 1 fig6,
#       2 graded; scheme 0 modified-godunov, 1 modified-godunov-2, 2 classic-upwind,
#       3 classic-godunov; columns problem scheme N L1 cpu_median cpu_min cpu_max updates Mupd/s).
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_segregation.gp
set terminal pngcairo size 1500,1100 font "Sans,11" noenhanced
set output outfile
f = benchdir.'/bench_segregation.dat'
names = "modified-godunov modified-godunov-2 classic-upwind classic-godunov"
set style line 1 lw 2 dt 1 pt 7 ps 1.1 lc rgb "#1f77b4"
set style line 2 lw 2 dt 1 pt 5 ps 1.1 lc rgb "#2ca02c"
set style line 3 lw 2 dt 2 pt 2 ps 1.3 lc rgb "#ff7f0e"
set style line 4 lw 2 dt 3 pt 6 ps 1.3 lc rgb "#d62728"
set multiplot layout 2,2 title "Segregation schemes: work-precision (CPU time of the time loop, median of 5 runs; see the .dat header for the load)"
set grid
set logscale xy
set format x "%.0e"
set format y "%.0e"
set xlabel "CPU time per run [s]"
set ylabel "L1 error of phi"
set key bottom left box opaque

set title "(a) two-shock batch (exact solution); dotted: L1 = 1e-3"
plot for [s=0:3] f index s u 5:4 w lp ls s+1 t word(names, s+1), \
     1e-3 w l dt 3 lc rgb "black" notitle

set title "(b) Fig. 6 column (reference: modified-godunov, N = 102400)"
plot for [s=0:3] f index 4+s u 5:4 w lp ls s+1 t word(names, s+1)

set title "(c) graded batch: fan and shocks (exact solution)"
plot for [s=0:3] f index 8+s u 5:4 w lp ls s+1 t word(names, s+1)

set title "(d) throughput on the Fig. 6 column"
set xlabel "cells N"
set ylabel "million cell updates per second"
set format x "%g"
set format y "%g"
unset logscale y
set yrange [0:*]
set key bottom right
plot for [s=0:3] f index 4+s u 3:9 w lp ls s+1 t word(names, s+1)
unset multiplot
