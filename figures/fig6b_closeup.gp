# Fig. 6b: close-up of the bottom layer, where the classic schemes push phi above Phi, and the
# size of that overshoot against the number of cells.
# needs: verify_overshoot
# reads: fig6_profiles.dat fig6_overshoot.dat
# Data: fig6_profiles.dat (N = 50, t = 0.75) and fig6_overshoot.dat (max over the run of
#       phi - Phi for N = 50 .. 3200); one column per row of the scheme table, in its order
#       (modified_godunov modified_godunov_2 classic_upwind classic_godunov rusanov).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig6b_closeup.gp
width = 1400; height = 650; fontsize = 12
load 'figures/png_terminal.gnuplot'
set output outfile
f = datadir.'/fig6_profiles.dat'
g = datadir.'/fig6_overshoot.dat'
set multiplot layout 1,2 title "Fig. 6b: the classic schemes (and Rusanov) overshoot phi <= Phi; the modified ones never do"
set grid

set title "(left) close-up of the bottom layer, t = 0.75, 50 cells"
set xlabel "z"
set ylabel "phi, Phi"
set xrange [0:0.22]
set yrange [0.535:0.575]
set key top left box opaque   # above the profiles, which lie below Phi(z) near the bottom
plot f u 1:2 w l dt 2 lw 2.5 lc rgb "black" t "Phi(z)", \
     f u 1:8 w p pt 6 ps 1.8 lc rgb "#d62728" t "classic Godunov", \
     f u 1:7 w p pt 2 ps 1.5 lc rgb "#ff7f0e" t "classic upwind", \
     f u 1:9 w p pt 4 ps 1.2 lc rgb "#9467bd" t "Rusanov", \
     f u 1:5 w lp pt 7 ps 0.9 lw 2 lc rgb "#1f77b4" t "modified Godunov", \
     f u 1:6 w lp pt 5 ps 0.7 lw 1.5 lc rgb "#2ca02c" t "modified Godunov, 2nd order"

set title "(right) largest phi - Phi over the run against N"
set xlabel "number of cells N"
set ylabel "max over cells and steps of (phi - Phi)"
set logscale xy
set format y "%.0e"
set xrange [40:4000]
set yrange [1e-5:1e-2]
unset key
set key top right box opaque
set label 1 "modified schemes: max(phi - Phi) <= 0 at every N" at 60,2e-5 tc rgb "#1f77b4"
plot g u 1:5 w lp pt 6 ps 1.5 lw 2 lc rgb "#d62728" t "classic Godunov", \
     g u 1:4 w lp pt 2 ps 1.2 lw 1 dt 2 lc rgb "#ff7f0e" t "classic upwind", \
     g u 1:6 w lp pt 4 ps 1.0 lw 1 dt 4 lc rgb "#9467bd" t "Rusanov", \
     g u 1:(2e-3*50/$1) w l dt 3 lw 1.5 lc rgb "black" t "slope -1 (~ 1/N)"
unset multiplot
