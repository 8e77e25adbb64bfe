# Shared by fig4a_regions.gp and fig4b_regions.gp (loaded after they set `name`, `QL_phi`,
# `QL_Phi`, `panel`): the Table 1 regions of Q_R = (phi_R, Phi_R) for a fixed Q_L, from the
# classifier (verify_table1_figures), drawn as an image with one colour per case.
width = 900; height = 820; fontsize = 12
load 'figures/png_terminal.gnuplot'
set output outfile
set title sprintf("Fig. 4%s: regions of Q_R for Q_L = (%g, %g), S = T = 1", panel, QL_phi, QL_Phi)
set xlabel "phi_R"
set ylabel "Phi_R"
set xrange [0:1]
set yrange [0:1]
set size ratio -1
set cbrange [-0.5:10.5]
set palette maxcolors 11
set palette defined (0 "#bbbbbb", 1 "#a6cee3", 2 "#1f78b4", 3 "#b2df8a", 4 "#33a02c", 5 "#fb9a99", \
                     6 "#e31a1c", 7 "#fdbf6f", 8 "#ff7f00", 9 "#cab2d6", 10 "#6a3d9a")
unset colorbox
set key bottom right box opaque
letters = "ABCDEFGHIJ"
set style textbox opaque fillcolor "white" border lc rgb "black" margins 1,1
plot datadir.'/'.name.'_regions.dat' u 1:2:3 w image notitle, \
     '+' u 1:(2*$1) w l lw 2 lc rgb "black" t "Gamma (Phi = 2 phi)", \
     '+' u 1:1 w l lw 1 dt 2 lc rgb "black" t "phi = Phi (below: unphysical)", \
     datadir.'/'.name.'_labels.dat' u 1:2:(sprintf("%s (%d)", substr(letters, int($3), int($3)), int($3))) w labels boxed font "Sans Bold,13" tc rgb "black" notitle, \
     '+' every ::0::0 u (QL_phi):(QL_Phi) w p pt 7 ps 2 lc rgb "black" t "Q_L", \
     '+' every ::0::0 u (QL_Phi/2):(QL_Phi) w p pt 6 ps 2 lw 2 lc rgb "black" t "Q* = (Phi_L/2, Phi_L)"
