# Fig. 5 of the paper: an exact solution with Q_R in region C (case 3), Q_L = (0.1, 0.5),
# Q_R = (0.3, 0.8), S = T = 1: rarefaction Q_L -> Q*, standing wave Q* -> Q-check_R, shock to Q_R.
# needs: verify_table1_figures
# reads: fig5_states.dat fig5_path.dat fig5_flux_curves.dat fig5_profile.dat
# Data: fig5_states.dat, fig5_path.dat (the waves in state space), fig5_flux_curves.dat,
#       fig5_profile.dat (phi and Phi against xi = z/t).
width = 1500; height = 560; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
set multiplot layout 1,3 title "Fig. 5: exact solution for Q_R in region C (case 3): rarefaction, standing wave, shock; flux f_L^min"
set grid lc rgb "#eeeeee"
names = "Q_L Q* Q-check_R Q_R"

set title "(a) state space"
set xlabel "phi"
set ylabel "Phi"
set xrange [0:1]
set yrange [0.3:1]
set key bottom right box opaque
set object 1 polygon from 0.3,0.3 to 1,0.3 to 1,1 to 0.3,0.3 back fc rgb "#999999" fillstyle solid 0.25 noborder
plot '+' u 1:(2*$1) w l lw 1 lc rgb "black" t "Gamma", \
     datadir.'/fig5_path.dat' index 0 u 1:2 w l lw 3 lc rgb "#1f77b4" t "rarefaction (Phi = Phi_L)", \
     datadir.'/fig5_path.dat' index 1 u 1:2 w l lw 3 lc rgb "#2ca02c" t "standing wave (f = f_L^min)", \
     datadir.'/fig5_path.dat' index 2 u 1:2 w l lw 3 dt 2 lc rgb "#d62728" t "shock (Phi = Phi_R)", \
     datadir.'/fig5_states.dat' u 1:2 w p pt 7 ps 1.5 lc rgb "black" notitle, \
     datadir.'/fig5_states.dat' u 1:2:(word(names, int(column(0)) + 1)) w labels offset 0,1.2 notitle
unset object 1

set title "(b) the two flux curves, f_L = f(.; Phi_L), f_R = f(.; Phi_R)"
set xlabel "phi"
set ylabel "f"
set xrange [0:0.8]
set yrange [-0.34:0.01]
set key bottom left box opaque
plot datadir.'/fig5_flux_curves.dat' u 1:2 w l lw 1 lc rgb "#555555" t "f_L", \
     datadir.'/fig5_flux_curves.dat' u 1:3 w l lw 1 dt 4 lc rgb "#555555" t "f_R", \
     datadir.'/fig5_path.dat' index 0 u 1:3 w l lw 3 lc rgb "#1f77b4" t "rarefaction on f_L", \
     datadir.'/fig5_path.dat' index 1 u 1:3 w l lw 3 lc rgb "#2ca02c" t "standing wave: f_L(phi-) = f_R(phi+)", \
     datadir.'/fig5_path.dat' index 2 u 1:3 w l lw 3 dt 2 lc rgb "#d62728" t "shock: chord of f_R", \
     datadir.'/fig5_states.dat' u 1:3 w p pt 7 ps 1.5 lc rgb "black" notitle, \
     datadir.'/fig5_states.dat' u 1:3:(word(names, int(column(0)) + 1)) w labels offset 0,-1.2 notitle

set title "(c) profile at time t: phi(z/t) and Phi(z/t)"
set xlabel "xi = z/t"
set ylabel "volume fraction"
set xrange [-1:1]
set yrange [0:0.9]
set key top left box opaque
set arrow 1 from 0,0 to 0,0.9 nohead dt 3 lc rgb "#2ca02c"
plot datadir.'/fig5_profile.dat' u 1:3 w l lw 2 dt 2 lc rgb "black" t "Phi", \
     datadir.'/fig5_profile.dat' u 1:2 w l lw 3 lc rgb "#1f77b4" t "phi", \
     datadir.'/fig5_profile.dat' u 1:($3/2) w l lw 1 lc rgb "#888888" t "Phi/2 (Gamma)"
unset multiplot
