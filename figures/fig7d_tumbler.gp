# Fig. 7d: the coupled drum after the run: the granular volume fraction Phi (lab frame), and Phi
# against phi_hat in the resting bed, where packing feedback makes mixed material pack denser.
# needs: verify_tumbler
# Data: DIR/fields_lab.dat (x z Phi phi_hat ... inside urel_x urel_z ...), DIR/summary.dat
#       (... packing_contrast packing_spread ...), DIR as in fig7a_tumbler.gp. Resting: speed
#       relative to the drum below 5 % of the wall speed (0.0016 m/s in the Sect. 4.2 drum).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7d_tumbler.gp
if (!exists("dir")) dir = datadir.'/tumbler'
f = dir.'/fields_lab.dat'
load 'figures/tumbler_common.gp'
# three digits; nan (no pure or mixed cells) as printed
summary(col) = system(sprintf("awk '!/^#/ {v = $%d; if (v ~ /nan/) print v; else printf \"%%.3g\", v}' %s/summary.dat", col, dir))
v_rest = 0.05 * 2 * pi * 0.1 * R / 100
set terminal pngcairo size 1500,720 font "Sans,11" noenhanced
set output outfile
set multiplot title sprintf("Fig. 7d: granular volume fraction Phi at the end of the run, %d cells per diameter; contrast mixed - pure at equal depth %s (spread %s)", n, summary(16), summary(17))
set origin 0, 0
set size 0.52, 0.95
set title "Phi (bed cells, Phi > 0.3)"
set cbrange [0.56:0.66]
set cblabel "Phi"
set palette defined (0 "#f7fbff", 0.5 "#6baed6", 1 "#08306b")
set parametric
set trange [0:1]
plot f u (100*$1):(100*$2):(50*h):(50*h):(bed($10, $3) ? $3 : 1/0) w boxxy fs solid 1.0 noborder fc palette notitle, \
     R*cos(2*pi*t), R*sin(2*pi*t) w l lw 2 lc rgb "black" notitle
unset parametric
unset colorbox
set origin 0.53, 0.05
set size 0.46, 0.85
set size noratio
set title "resting bed cells: Phi against phi_hat"
set xrange [0:1]
set yrange [0.56:0.66]
set xlabel "phi_hat"
set ylabel "Phi"
set key bottom center
set arrow 1 from 0.3, 0.56 to 0.3, 0.66 nohead dt 3
set arrow 2 from 0.7, 0.56 to 0.7, 0.66 nohead dt 3
set arrow 3 from 0.1, 0.56 to 0.1, 0.66 nohead dt 2 lc rgb "#888888"
set arrow 4 from 0.9, 0.56 to 0.9, 0.66 nohead dt 2 lc rgb "#888888"
plot f u (bed($10, $3) && sqrt($11**2 + $12**2) <= v_rest ? $4 : 1/0):3 w p pt 7 ps 0.4 lc rgb "#08306b" t "resting bed cell"
unset multiplot
