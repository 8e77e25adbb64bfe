# Verification (a) of the flow solver: a bed settling to the lithostatic balance.
# needs: verify_flow_rest
# Data: flow_rest_profiles.dat (nz z Phi Phi_reference; blocks nz = 15, 30, 60),
#       flow_rest_history.dat (t max_momentum, nz = 60).
set terminal pngcairo size 1400,560 font "Sans,11" noenhanced
set output outfile
set multiplot layout 1,2 title "Flow (a): bed at rest under gravity (T_floor = 1e-8 m^2/s^2 for a fast settling)"
set grid
set title "(a) Phi(z) after 12 s against the lithostatic balance (GSL odeiv2)"
set xlabel "Phi"
set ylabel "z [m]"
set key bottom left
set xrange [0.608:0.63]
set yrange [0:0.045]
plot datadir.'/flow_rest_profiles.dat' index 2 u 4:2 w l lw 3 lc rgb "#999999" t "dp/dz = -Phi |g| (GSL)", \
     for [i=0:2] datadir.'/flow_rest_profiles.dat' index i u 3:2 w p pt 7+i ps 0.9 \
       t sprintf("solver, %s cells", word("15 30 60", i+1))
set title "(b) largest momentum |Phi u| while settling (60 cells)"
set xlabel "t [s]"
set ylabel "max |Phi u| [m/s]"
set logscale y
set format y "%.0e"
set xrange [*:*]
set yrange [*:*]
set key top right
plot datadir.'/flow_rest_history.dat' u 1:2 w l lw 2 t "max |Phi u|", 1e-13*0.6*0.6262 w l dt 2 lc rgb "black" t "round-off level (check)"
unset multiplot
