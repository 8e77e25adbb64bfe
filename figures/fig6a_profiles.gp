# Fig. 6a: the 1-D segregation column of Sect. 4.1 at t = 0.75, N = 50 cells, every scheme.
# needs: verify_overshoot
# reads: fig6_profiles.dat
# Data: fig6_profiles.dat (columns z Phi T phi0, then one per row of the scheme table:
#       modified_godunov modified_godunov_2 classic_upwind classic_godunov rusanov);
#       profiles Phi, T: docs/assumptions.md G4.
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig6a_profiles.gp
width = 1100; height = 750; fontsize = 12
load 'figures/png_terminal.gnuplot'
set output outfile
f = datadir.'/fig6_profiles.dat'
set title "Fig. 6a: small particles phi(z) at t = 0.75 (eq. 66, S = 1, 50 cells, CFL 0.9)"
set xlabel "z (height; gravity points to -z)"
set ylabel "volume fraction phi, Phi;  temperature T"
set xrange [0:1]
set yrange [0:1.05]
set grid
set key top left box opaque width 1
plot f u 1:3 w l dt 3 lw 2 lc rgb "#555555" t "T(z)", \
     f u 1:2 w l dt 2 lw 2.5 lc rgb "black" t "Phi(z) (upper bound of phi)", \
     f u 1:4 w l lw 3 lc rgb "#c8c8c8" t "phi at t = 0 (Phi/2)", \
     f u 1:8 w p pt 6 ps 1.4 lc rgb "#d62728" t "classic Godunov (interface Phi, T)", \
     f u 1:7 w p pt 2 ps 1.2 lc rgb "#ff7f0e" t "classic upwind (interface Phi, T)", \
     f u 1:9 w p pt 4 ps 1.0 lc rgb "#9467bd" t "Rusanov (each cell's own f; teaching row)", \
     f u 1:5 w lp pt 7 ps 0.7 lw 2 lc rgb "#1f77b4" t "modified Godunov (eq. 63)", \
     f u 1:6 w l lw 2 lc rgb "#2ca02c" t "modified Godunov, 2nd order (phi_hat, SSP-RK(3,2))"
