# Work against error of the flow solver's two time-stepping modes (docs/flow_solver.md Sect. 3): error
# against CPU time of the solve (one thread, median of 3 runs), one curve per mode and time-step
# rule, the resolution written at each point.
# needs: bench_flow_work
# Data: bench_flow_work.dat (problem semi_implicit dt_rule n steps dt_mean cg_per_step cpu_seconds
#       wall_seconds error_Phi error_u error_T angle_cpu_seconds angle_wall_seconds angle_error_deg); gnuplot
#       index 0-3: manufactured solution, explicit and semi-implicit with dt_max = 0.25, 1, 4 s/m h;
#       index 4-6: inclined plane, explicit and semi-implicit with dt_max = 1e-3 s, 1e-4 s.
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_flow_work.gp
set terminal pngcairo size 1500,1100 font "Sans,11" noenhanced
set output outfile
f = benchdir.'/bench_flow_work.dat'
set style line 1 lw 2 dt 1 pt 7 ps 1.2 lc rgb "#1f77b4"
set style line 2 lw 2 dt 1 pt 5 ps 1.2 lc rgb "#d62728"
set style line 3 lw 2 dt 2 pt 9 ps 1.3 lc rgb "#ff7f0e"
set style line 4 lw 2 dt 3 pt 13 ps 1.3 lc rgb "#2ca02c"
array ms[4] = ["explicit (sound speed)", "semi-implicit, dt_max = 0.25 s/m h", "semi-implicit, dt_max = 1 s/m h", \
              "semi-implicit, dt_max = 4 s/m h"]
array inc[3] = ["explicit (sound speed)", "semi-implicit, dt_max = 1e-3 s", "semi-implicit, dt_max = 1e-4 s"]
set multiplot layout 2,2 title "Flow solver, work against error: explicit and semi-implicit steps (numbers at the points: cells per side / per column)"
set grid
set logscale xy
set format x "%g"
set format y "%.0e"
set xlabel "CPU seconds of the solve (one thread, median of 3)"
set key bottom left box opaque

set title "(a) manufactured solution (verify_flow_order): velocity"
set ylabel "mean |u - u_exact| at t_end [m/s]"
plot for [i=0:3] f index i u 8:11 w lp ls i+1 t ms[i+1], \
     for [i=0:3] f index i u 8:11:(sprintf("%d", $4)) w labels offset 0.6,0.7 font ",9" tc ls i+1 notitle

set title "(b) manufactured solution: granular volume fraction Phi"
set ylabel "mean |Phi - Phi_exact| at t_end"
plot for [i=0:3] f index i u 8:10 w lp ls i+1 t ms[i+1], \
     for [i=0:3] f index i u 8:10:(sprintf("%d", $4)) w labels offset 0.6,0.7 font ",9" tc ls i+1 notitle

set title "(c) inclined plane (verify_flow_incline): velocity profile after 2 s at the solver's critical angle"
set ylabel "max |u - u_bvp| / u_bvp(depth)"
plot for [i=0:2] f index 4+i u 8:11 w lp ls i+1 t inc[i+1], \
     for [i=0:2] f index 4+i u 8:11:(sprintf("%d", $4)) w labels offset 0.6,0.7 font ",9" tc ls i+1 notitle

set title "(d) inclined plane: critical angle by bisection (11 runs of 1.5 s) against atan(mu)"
set xlabel "CPU seconds of the 11 runs"
set ylabel "|theta_c - atan(mu)| [deg]"
plot for [i=0:2] f index 4+i u 13:15 w lp ls i+1 t inc[i+1], \
     for [i=0:2] f index 4+i u 13:15:(sprintf("%d", $4)) w labels offset 0.6,0.7 font ",9" tc ls i+1 notitle
unset multiplot
