# Fig. 3 of the paper: integral curves through a critical state Q* and the transition curve Gamma.
# needs: verify_table1_figures
# reads: fig3_curves.dat
# Data: fig3_curves.dat (block 0: standing-wave curve f = f(Q*); block 1: wave curve Phi = Phi*;
#       blocks 2..: curves f = const, one block per branch), S = T = 1.
width = 900; height = 800; fontsize = 12
load 'figures/png_terminal.gnuplot'
set output outfile
set title "Fig. 3: integral curves through the critical state Q* = (0.25, 0.5)"
set xlabel "phi (small particles)"
set ylabel "Phi (all particles)"
set xrange [0:1]
set yrange [0:1]
set size ratio -1
set key bottom right box opaque
set grid lc rgb "#eeeeee"
set object 1 polygon from 0,0 to 1,0 to 1,1 to 0,0 back fc rgb "#999999" fillstyle solid 0.25 noborder
set label 1 "phi > Phi: unphysical" at 0.62,0.25 tc rgb "#555555"
set label 2 "Gamma" at 0.455,0.86 tc rgb "black"
set label 3 "left of Gamma: lambda_1 < 0" at 0.02,0.97 tc rgb "#555555"
set label 4 "right of Gamma: lambda_1 > 0" at 0.56,0.97 tc rgb "#555555"
set label 5 "Q*" at 0.27,0.47
plot for [i=2:13] datadir.'/fig3_curves.dat' index i u 1:2 w l lw 1 lc rgb "#aaaaaa" notitle, \
     NaN w l lw 1 lc rgb "#aaaaaa" t "f = const (standing waves, r_0)", \
     '+' u 1:(2*$1) w l lw 2 lc rgb "black" t "Gamma", \
     datadir.'/fig3_curves.dat' index 0 u 1:2 w l lw 3 lc rgb "#d62728" t "f = f(Q*): standing wave through Q*", \
     datadir.'/fig3_curves.dat' index 1 u 1:2 w l lw 3 lc rgb "#1f77b4" t "Phi = Phi*: shocks, rarefactions (r_1)", \
     '+' every ::0::0 u (0.25):(0.5) w p pt 7 ps 1.5 lc rgb "black" notitle
