# Verification (e) of the flow solver: convergence on a manufactured solution of the full system.
# needs: verify_flow_order
# Data: flow_order.dat (n h error_Phi error_u error_T).
set terminal pngcairo size 800,600 font "Sans,11" noenhanced
set output outfile
set title "Flow (e): mean |error| at t = 0.05 s, manufactured solution (frame turning at 20 rad/s, gravity, walls)"
set grid
set logscale xy
set format y "%.0e"
set xlabel "h [m]"
set ylabel "mean |numerical - exact|"
set key bottom right
plot datadir.'/flow_order.dat' u 2:3 w lp pt 7 t "Phi", \
     datadir.'/flow_order.dat' u 2:($4/100) w lp pt 5 t "|u| / (100 m/s)", \
     datadir.'/flow_order.dat' u 2:5 w lp pt 9 t "T [m^2/s^2]", \
     datadir.'/flow_order.dat' u 2:(0.06*$2) w l dt 2 lc rgb "black" t "slope 1"
