# Closures of Sect. 2.1 against Phi for three mixtures, and the packing fits.
# needs: verify_closures
# reads: closures_vs_Phi.dat packing_table.dat packing_fit.dat
# Data: closures_vs_Phi.dat (blocks phi_hat = 0, 0.4, 1 at T = 1e-4 m^2/s^2),
#       packing_table.dat (substitute data) and packing_fit.dat (degree-4 GSL fits).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig_closures.gp
width = 1400; height = 1000; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
set multiplot layout 2,2 title "Sect. 2.1 closures (substitute material, docs/assumptions.md)"
set key top left
set grid

set title "(a) packing limits: table and polynomial fits"
set xlabel "phi_hat = phi / Phi"
set ylabel "volume fraction"
set yrange [0.56:0.71]   # room above the curves for the key
set key top center maxrows 2
plot datadir.'/packing_table.dat' u 1:2 w p pt 7 lc rgb "#1f77b4" t "Phi_rcp table", \
     datadir.'/packing_fit.dat'   u 1:2 w l lw 2 lc rgb "#1f77b4" t "Phi_rcp fit", \
     datadir.'/packing_table.dat' u 1:3 w p pt 5 lc rgb "#d62728" t "Phi_co table", \
     datadir.'/packing_fit.dat'   u 1:3 w l lw 2 lc rgb "#d62728" t "Phi_co fit"

set autoscale y
set key top left
set title "(b) compressibility factor g (eq. 18 substitute)"
set xlabel "Phi"
set ylabel "g"
set logscale y
set format y "%.0e"
plot for [i=0:2] datadir.'/closures_vs_Phi.dat' index i u 2:3 w l lw 2 \
     t sprintf("phi_hat = %s", word("0 0.4 1", i+1))

set title "(c) pressure p = p_k + p_y at T = 1e-4 m^2/s^2 (dashed: p_k)"
set ylabel "p / rho*  [m^2/s^2]"
set key bottom right
plot for [i=0:2] datadir.'/closures_vs_Phi.dat' index i u 2:6 w l lw 2 lc i+1 \
     t sprintf("p, phi_hat = %s", word("0 0.4 1", i+1)), \
     for [i=0:2] datadir.'/closures_vs_Phi.dat' index i u 2:4 w l dt 2 lc i+1 notitle

set title "(d) viscosity eta at T = 1e-4 m^2/s^2 (jumps in slope at Phi_co)"
set ylabel "eta  [m^2/s]"
set key top left
plot for [i=0:2] datadir.'/closures_vs_Phi.dat' index i u 2:7 w l lw 2 \
     t sprintf("phi_hat = %s", word("0 0.4 1", i+1))
unset multiplot
