# The tumbler-flow scene at 100 cells per diameter after 25 s (the acceptance run of make bench).
# needs: bench_tumbler
# Data: tumbler_flow/fields_lab.dat (x z Phi u_x u_y u_z T p inside; one block per row),
#       tumbler_flow/history.dat and tumbler_flow_explicit/history.dat (t steps angle points flowing
#       max_speed ke mass mass_change dt layer_thickness): the semi-implicit and the explicit run.
set terminal pngcairo size 1600,900 font "Sans,11" noenhanced
set output outfile
set multiplot layout 2,2 title "tumbler-flow (Sect. 4.2 without segregation), 100 cells per diameter, t = 25 s, lab frame"
f = benchdir.'/tumbler_flow/fields_lab.dat'
set size ratio -1
set xrange [-0.055:0.055]
set yrange [-0.055:0.055]
set xlabel "x [m]"
set ylabel "z [m]"
set object 1 circle at 0,0 size 0.05 front fillstyle empty border lc rgb "black" lw 2
set title "(a) Phi and the velocity (arrows, lab frame; 5 mm per 0.03 m/s, the wall speed)"
set palette defined (0 "white", 0.3 "#c6dbef", 0.6 "#08306b")
set cbrange [0:0.65]
plot f u 1:2:($9 > 0.5 ? $3 : 1/0) w p pt 5 ps 0.5 lc palette notitle, \
     f u 1:2:($9 > 0.5 && $3 > 0.3 ? 0.005*$4/0.03 : 1/0):($9 > 0.5 && $3 > 0.3 ? 0.005*$6/0.03 : 1/0) every 6:6 w vectors head size 0.002,20 lc rgb "#d62728" notitle
set title "(b) speed relative to the drum, |u_lab - Omega x r| [m/s]"
set palette defined (0 "white", 0.005 "#fdd0a2", 0.03 "#d94801", 0.1 "#7f2704")
set cbrange [0:0.1]
plot f u 1:2:($9 > 0.5 && $3 > 0.05 ? sqrt(($4 + 0.6283*$2)**2 + ($6 - 0.6283*$1)**2) : 1/0) w p pt 5 ps 0.5 lc palette notitle
set title "(c) log10 T [m^2/s^2]"
set palette defined (-12 "#f7fcf5", -8 "#74c476", -4 "#00441b")
set cbrange [-12:-4]
plot f u 1:2:($9 > 0.5 && $3 > 0.05 ? log10($7) : 1/0) w p pt 5 ps 0.5 lc palette notitle
unset object 1
set size noratio
set autoscale
set title "(d) free-surface angle (fit of the Phi = Phi_co/2 contour) and flowing-layer thickness, both modes"
set xlabel "t [s]"
set ylabel "angle [deg]"
set y2label "layer thickness [mm]"
set y2tics
set yrange [0:*]
set ytics nomirror
set grid
set key bottom right
plot benchdir.'/tumbler_flow/history.dat' u 1:3 w l lw 2 lc rgb "#1f77b4" t "angle, semi-implicit", \
     benchdir.'/tumbler_flow_explicit/history.dat' u 1:3 w l lw 1 lc rgb "#d62728" t "angle, explicit", \
     benchdir.'/tumbler_flow/history.dat' u 1:(1e3*$11) axes x1y2 w l lw 1 dt 3 lc rgb "#1f77b4" t "layer, semi-implicit", \
     benchdir.'/tumbler_flow_explicit/history.dat' u 1:(1e3*$11) axes x1y2 w l lw 1 dt 3 lc rgb "#d62728" t "layer, explicit", \
     atan(sqrt(2*1.9e-4*1.3e3/3))*180/pi w l dt 2 lc rgb "black" t "friction angle atan(mu)"
unset multiplot
