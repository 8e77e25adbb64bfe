# Cost of the flow solver on the tumbler-flow drum, both time-stepping modes (make bench).
# needs: bench_flow
# Data: bench_flow.dat (semi_implicit cells_per_diameter threads inside_cells ns_per_cell_step dt
#       steps_per_drum_second wall_per_drum_second seconds_for_25s solves_per_step newton_per_solve
#       krylov_per_newton temperature_cg_per_step, share_<stage> for the eight stages of FlowStage
#       in flow/flow_solver.hpp, ratio_explicit_to_semi); the plots use columns 2, 5, 7 and 8.
set terminal pngcairo size 1500,480 font "Sans,11" noenhanced
set output outfile
set multiplot layout 1,3 title "Flow solver on the tumbler-flow drum, from its initial state: medians of 5 windows"
set grid
f = benchdir.'/bench_flow.dat'
set logscale x
set xrange [40:250]
set xlabel "cells per diameter"
set key top left
# rows per size: explicit 1 thread, semi 1 thread, explicit 2 threads, semi 2 threads
set title "(a) cost of one step"
set ylabel "ns per cell and step"
plot f every 4::0 u 2:5 w lp pt 7 t "explicit, 1 thread", f every 4::1 u 2:5 w lp pt 5 t "semi-implicit, 1 thread", \
     f every 4::2 u 2:5 w lp pt 6 t "explicit, 2 threads", f every 4::3 u 2:5 w lp pt 4 t "semi-implicit, 2 threads"
set title "(b) steps per second of drum time"
set ylabel "steps per drum second"
set logscale y
plot f every 4::0 u 2:7 w lp pt 7 t "explicit (sound speed)", f every 4::1 u 2:7 w lp pt 5 t "semi-implicit (dt_max)"
set title "(c) wall time per second of drum time, 2 threads"
set ylabel "wall seconds per drum second"
plot f every 4::2 u 2:8 w lp pt 6 t "explicit", f every 4::3 u 2:8 w lp pt 4 t "semi-implicit", 30.0/25 w l dt 2 lc rgb "black" t "target 30 s for 25 s"
unset multiplot
