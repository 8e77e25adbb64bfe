# Fig. 7b, first version: the kinematic rolling-drum flow with the segregation direction d_s.
# needs: verify_kinematic_flow
# reads: kinematic_cells.dat kinematic_outline.dat
# Data: kinematic_cells.dat (bed cells: x z in_layer ux uz urel_x urel_z ds_x ds_z speed angle_deg,
#       inertial frame, 100 cells per diameter) and kinematic_outline.dat (wall, surface, layer bottom).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7b_kinematic.gp
width = 1700; height = 700; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
cells = datadir.'/kinematic_cells.dat'
outline = datadir.'/kinematic_outline.dat'
set multiplot title "Kinematic rolling drum (D = 0.1 m, 75 % fill, 0.1 rps), inertial frame"
set size ratio -1
set palette defined (0 "#313695", 1 "#74add1", 2 "#fee090", 3 "#f46d43", 4 "#a50026")
set cblabel "|u|  [m/s]"
set xlabel "x  [m]"
set ylabel "z  [m]"
# Cell index along an axis from a cell-centre coordinate (h = 1 mm, origin -R = -0.05 m).
idx(c) = int((c + 0.05) * 1000)
keep(x, z, k) = (idx(x) % k == 0 && idx(z) % k == 0)

set title "(a) velocity (every 4th cell), free surface and layer bottom"
set origin 0, 0
set size 0.4, 0.95
set xrange [-0.052:0.052]
set yrange [-0.052:0.052]
sc = 0.06
plot outline index 0 u 1:2 w l lw 2 lc rgb "black" t "drum wall", \
     outline index 1 u 1:2 w l lw 2 lc rgb "#1f77b4" t "free surface", \
     outline index 2 u 1:2 w l lw 1.5 dt 2 lc rgb "#d62728" t "layer bottom", \
     cells u (keep($1, $2, 4) ? $1 : 1/0):2:($4*sc):($5*sc):10 w vectors head size 0.002,20 filled lc palette t "u"

set title "(b) surface region: u (every 2nd cell) and d_s (black, layer cells)"
set origin 0.4, 0
set size 0.6, 0.95
set key bottom right opaque
set xrange [-0.052:0.032]
set yrange [-0.004:0.044]
sc = 0.02
ds = 0.0016
plot outline index 1 u 1:2 w l lw 2 lc rgb "#1f77b4" t "free surface", \
     outline index 2 u 1:2 w l lw 1.5 dt 2 lc rgb "#d62728" t "layer bottom", \
     outline index 0 u 1:2 w l lw 2 lc rgb "black" notitle, \
     cells u (keep($1, $2, 2) ? $1 : 1/0):2:($4*sc):($5*sc):10 w vectors head size 0.0012,20 filled lc palette t "u", \
     cells u ($3 > 0 && keep($1 + 0.001, $2 + 0.001, 2) ? $1 - ds/2*$8 : 1/0):($2 - ds/2*$9):(ds*$8):(ds*$9) \
           w vectors nohead lw 1.5 lc rgb "black" t "d_s"
unset multiplot
