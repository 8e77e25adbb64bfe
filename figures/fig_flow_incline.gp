# Verification (c) of the flow solver: a layer on an inclined plane.
# needs: verify_flow_incline
# Data: flow_incline_angles.dat (nz theta_c atan_mu), flow_incline_below.dat (nz z u_x u_creep T),
#       flow_incline_profiles.dat (nz z Phi Phi_bvp u_x u_bvp T T_bvp; blocks nz = 32, 64).
set terminal pngcairo size 1500,480 font "Sans,11" noenhanced
set output outfile
set multiplot layout 1,3 title "Flow (c): inclined plane, 1 cm layer, no-slip adiabatic bottom"
set grid
set title "(a) critical angle of the solver -> atan(mu)"
set logscale x
set xlabel "cells per 2 cm"
set ylabel "angle [deg]"
set key bottom right
set xrange [10:100]
plot datadir.'/flow_incline_angles.dat' u 1:3 w l lw 2 lc rgb "#999999" t "atan(sqrt(2 eta0 eps0/3))", \
     datadir.'/flow_incline_angles.dat' u 1:2 w lp pt 7 ps 1.5 t "solver (bisection)"
unset logscale x
set xrange [*:*]
set title "(b) 18 deg: the flow stops; creep left by T_floor"
set xlabel "u_x [m/s]"
set ylabel "z [m]"
set key top left
set format x "%.1e"
set xtics 1e-5
plot datadir.'/flow_incline_below.dat' index 1 u ($4 > 0 ? $4 : 1/0):2 w l lw 2 lc rgb "#999999" t "tan(theta) sqrt(T_floor) z / eta0", \
     for [i=0:1] datadir.'/flow_incline_below.dat' index i u 3:2 w p pt 7+i t sprintf("solver, %s cells", word("40 80", i+1))
set format x "%g"
set xtics autofreq
set title "(c) critical angle: u, T against the BVP (uniform T)"
set xlabel "u_x [m/s]   and   1000 T [m^2/s^2]"
set key top left Left reverse samplen 1 font ",9"
plot for [i=0:1] datadir.'/flow_incline_profiles.dat' index i u ($3 > 0.3 ? $5 : 1/0):2 w p pt 7+i t sprintf("u, %s cells", word("32 64", i+1)), \
     datadir.'/flow_incline_profiles.dat' index 1 u ($3 > 0.3 && $6 > 0 ? $6 : 1/0):2 w l lw 2 lc rgb "#999999" t "u, BVP", \
     for [i=0:1] datadir.'/flow_incline_profiles.dat' index i u ($3 > 0.3 ? 1000*$7 : 1/0):2 w p pt 4+i t sprintf("1000 T, %s cells", word("32 64", i+1)), \
     datadir.'/flow_incline_profiles.dat' index 1 u ($3 > 0.3 ? 1000*$8 : 1/0):2 w l lw 2 dt 2 lc rgb "#999999" t "1000 T, BVP (mean)"
unset multiplot
