# Verification (b) of the flow solver: homogeneous simple shear against eq. (45).
# needs: verify_flow_shear
# Data: flow_shear_scan.dat (gamma_dot T T_eq45 tau_over_p p_k),
#       flow_shear_profiles.dat (gamma_dot Phi z u_x T p; one block per run).
set terminal pngcairo size 1500,480 font "Sans,11" noenhanced
set output outfile
set multiplot layout 1,3 title "Flow (b): homogeneous simple shear between walls at -U/2 and +U/2 (yield regime unless noted)"
set grid
set title "(a) T against eq. (45), T = 3 eta0 gamma_dot^2/(2 eps0)"
set logscale xy
set format y "%.0e"
set xlabel "gamma_dot [1/s]"
set ylabel "T [m^2/s^2]"
set key top left
plot datadir.'/flow_shear_scan.dat' u 1:3 w l lw 2 lc rgb "#999999" t "eq. (45)", \
     datadir.'/flow_shear_scan.dat' u 1:2 w p pt 7 ps 1.5 t "solver, steady state", \
     datadir.'/flow_shear_scan.dat' u 1:($5/1e3) w lp pt 5 t "p_k / 1000 [m^2/s^2] (slope 2)"
set title "(b) stress ratio tau/p"
unset logscale y
set format y "%.3f"
set ylabel "tau / p"
set yrange [0.35:0.45]
plot sqrt(2*1.9e-4*1.3e3/3) w l lw 2 lc rgb "#999999" t "sqrt(2 eta0 eps0/3)", \
     datadir.'/flow_shear_scan.dat' u 1:4 w p pt 7 ps 1.5 t "solver"
set title "(c) velocity profiles u_x/(gamma_dot H) (kinetic regime: last)"
unset logscale x
set format y "%g"
set yrange [*:*]
set xlabel "u_x / (gamma_dot H)"
set ylabel "z / H"
set key bottom right
plot for [i=0:3] datadir.'/flow_shear_profiles.dat' index i u ($4/($1*0.01)):($3/0.01) w lp pt 7+i \
       t sprintf("gamma_dot = %s 1/s%s", word("1 10 100 100", i+1), i == 3 ? " (kinetic)" : "")
unset multiplot
