# The tumbler-flow scene at 32 cells per diameter after 25 s (lab frame) and its surface angle.
# needs: verify_flow_tumbler
# Data: flow_tumbler/fields_lab.dat (x z Phi u_x u_y u_z T p inside; one block per row),
#       flow_tumbler/history.dat (t steps angle points flowing max_speed ke mass mass_change dt).
set terminal pngcairo size 1600,900 font "Sans,11" noenhanced
set output outfile
set multiplot layout 2,2 title "tumbler-flow (Sect. 4.2 without segregation), 32 cells per diameter, t = 25 s, lab frame"
f = datadir.'/flow_tumbler/fields_lab.dat'
set size ratio -1
set xrange [-0.055:0.055]
set yrange [-0.055:0.055]
set xlabel "x [m]"
set ylabel "z [m]"
set title "(a) Phi and the velocity (arrows, lab frame; 5 mm per 0.03 m/s, the wall speed)"
set object 1 circle at 0,0 size 0.05 front fillstyle empty border lc rgb "black" lw 2
set palette defined (0 "white", 0.3 "#c6dbef", 0.6 "#08306b")
set cbrange [0:0.65]
plot f u 1:2:($9 > 0.5 ? $3 : 1/0) w p pt 5 ps 1.6 lc palette notitle, \
     f u 1:2:($9 > 0.5 && $3 > 0.3 ? 0.005*$4/0.03 : 1/0):($9 > 0.5 && $3 > 0.3 ? 0.005*$6/0.03 : 1/0) every 2:2 w vectors head size 0.002,20 lc rgb "#d62728" notitle
set title "(b) speed relative to the drum, |u_lab - Omega x r| [m/s]"
set palette defined (0 "white", 0.005 "#fdd0a2", 0.03 "#d94801", 0.1 "#7f2704")
set cbrange [0:0.1]
plot f u 1:2:($9 > 0.5 && $3 > 0.05 ? sqrt(($4 + 0.6283*$2)**2 + ($6 - 0.6283*$1)**2) : 1/0) w p pt 5 ps 1.6 lc palette notitle
set title "(c) log10 T [m^2/s^2]"
set palette defined (-12 "#f7fcf5", -8 "#74c476", -5 "#00441b")
set cbrange [-12:-4]
plot f u 1:2:($9 > 0.5 && $3 > 0.05 ? log10($7) : 1/0) w p pt 5 ps 1.6 lc palette notitle
unset object 1
set size noratio
set autoscale
set title "(d) free-surface angle against the horizontal"
set xlabel "t [s]"
set ylabel "angle [deg]"
set grid
set key bottom right
plot datadir.'/flow_tumbler/history.dat' u 1:3 w l lw 2 t "surface angle (fit of the Phi = Phi_co/2 contour)", \
     atan(sqrt(2*1.9e-4*1.3e3/3))*180/pi w l dt 2 lc rgb "black" t "friction angle atan(mu)"
unset multiplot
