# The drum's dynamic angle of repose against the cell size h, both time-stepping modes (make figures-full).
# needs: bench_drum_angle
# Data: bench_drum_angle.dat (cells semi_implicit dt_max h_mm steps wall_s angle_mean_deg angle_std_deg
#       ke_min_over_mean ke_max_over_mean friction_deg layer_mm steps_halved), one row per run of bench_drum_angle;
#       bench_drum_angle_gap.dat (h_mm explicit_deg semi_implicit_deg gap_deg), the modes' gap at equal h.
set terminal pngcairo size 1500,1000 font "Sans,11" noenhanced
set output outfile
set multiplot layout 2,2 title "tumbler-flow drum (D = 0.1 m, 75 % fill, 0.1 rps), 25 s, statistics over t >= 10 s"
set grid
f = benchdir.'/bench_drum_angle.dat'
set xlabel "h = D / cells per diameter [mm]"
set xrange [0:3.5]
# rows: explicit; semi-implicit at dt_max = 1 ms; semi-implicit at dt_max = 0.1 ms (1/0 drops the others;
# the semi-implicit runs at other dt_max are panel (d)'s)
explicit(c) = $2 == 0 ? c : 1/0
semi(c) = $2 == 1 && $3 == 1e-3 ? c : 1/0
semi_small(c) = $2 == 1 && $3 == 1e-4 ? c : 1/0
# the semi-implicit points are shifted by 0.05 mm so that their error bars do not hide the explicit ones
dx = 0.05
stats f u 11 nooutput
friction = STATS_mean
# the gap's power law C h^p (log-log), then a + b h^p through each mode's runs at dt_max 1 ms with
# that p (bench_drum_angle prints the same fits)
g = benchdir.'/bench_drum_angle_gap.dat'
set fit quiet nolog
lc = 1.0; p = 1.0
fit lc + p * x g u (log($1)):(log($4)) via lc, p
a = 20.0; b = 1.0
fit a + b * x**p f u (explicit($4)):7 via a, b
c = 20.0; d = 1.0
fit c + d * x**p f u (semi($4)):7 via c, d
set title "(a) dynamic angle of repose: mean +- standard deviation"
set ylabel "angle [deg]"
set key top right
set yrange [10:35]
plot friction w l lw 2 dt 2 lc rgb "black" t sprintf("friction angle atan(mu) = %.2f deg", friction), \
     a + b * x**p w l lw 1.5 lc rgb "#1f77b4" dt 3 t sprintf("explicit, a + b h^p: %.2f deg at h = 0", a), \
     c + d * x**p w l lw 1.5 lc rgb "#d62728" dt 3 t sprintf("semi-implicit, a + b h^p: %.2f deg at h = 0", c), \
     f u (explicit($4)):7:8 w yerrorlines pt 7 ps 1.3 lc rgb "#1f77b4" t "explicit", \
     f u (semi($4 + dx)):7:8 w yerrorlines pt 5 ps 1.3 lc rgb "#d62728" t "semi-implicit, dt_max 1 ms", \
     f u (semi_small($4 + dx)):7:8 w yerrorlines pt 9 ps 1.5 lc rgb "#2ca02c" t "semi-implicit, dt_max 0.1 ms"
set title "(b) rolling or slumping: kinetic energy (drum frame) min / mean"
set ylabel "min / mean of the kinetic energy"
set logscale y
set format y "%.0e"
set yrange [*:2]
set key center right
plot f u (explicit($4)):9 w lp pt 7 ps 1.3 lc rgb "#1f77b4" t "explicit", \
     f u (semi($4 + dx)):9 w lp pt 5 ps 1.3 lc rgb "#d62728" t "semi-implicit, dt_max 1 ms", \
     f u (semi_small($4 + dx)):9 w lp pt 9 ps 1.5 lc rgb "#2ca02c" t "semi-implicit, dt_max 0.1 ms"
set title "(c) gap between the modes at equal h (dt_max 1 ms)"
set ylabel "explicit - semi-implicit angle [deg]"
set xlabel "h [mm]"
set logscale xy
set format y "%g"
set xrange [0.4:4]
set yrange [0.5:10]
set xtics (0.5, 1, 2, 3)
set ytics (0.5, 1, 2, 3, 5, 10)
set key top left
plot g u 1:4 w p pt 7 ps 1.5 lc rgb "black" t "measured gap", \
     exp(lc) * x**p w l lw 1.5 lc rgb "black" dt 2 t sprintf("C h^p, p = %.2f (log-log least squares)", p)
set title "(d) semi-implicit: angle (left) and flowing-layer thickness (right) against dt_max"
set xlabel "dt_max [ms]"
set ylabel "angle [deg]"
set y2label "layer thickness [mm]"
set logscale x
unset logscale y
set xrange [0.2:5]
set xtics (0.25, 0.5, 1, 2, 4)
set yrange [18:25]
set ytics auto nomirror
set y2range [0:20]
set y2tics auto
set key bottom left
# the runs are not in dt_max order in the file, and a line through 1/0-filtered rows breaks at every
# dropped row: copy each resolution's semi-implicit runs to a table first (dt_max [ms], angle, std, layer)
set table $d50
plot f u (1e3 * $3):7:8:12 w table if ($2 == 1 && $1 == 50)
set table $d100
plot f u (1e3 * $3):7:8:12 w table if ($2 == 1 && $1 == 100)
unset table
plot friction w l lw 2 dt 2 lc rgb "black" t "friction angle", \
     $d50 u 1:2:3 w yerrorbars pt 5 ps 1.3 lc rgb "#d62728" t "angle, 50 cells", \
     $d50 u 1:2 smooth unique w l lc rgb "#d62728" notitle, \
     $d100 u 1:2:3 w yerrorbars pt 7 ps 1.3 lc rgb "#9467bd" t "angle, 100 cells", \
     $d100 u 1:2 smooth unique w l lc rgb "#9467bd" notitle, \
     $d50 u 1:4 axes x1y2 smooth unique w lp pt 4 ps 1.3 dt 2 lc rgb "#d62728" t "layer, 50 cells", \
     $d100 u 1:4 axes x1y2 smooth unique w lp pt 6 ps 1.3 dt 2 lc rgb "#9467bd" t "layer, 100 cells"
unset multiplot
