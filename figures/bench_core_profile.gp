# The full model's drum at t_end along the vertical line through its axis: the small-particle share
# phi_hat, the shear rate kappa_max - kappa_min and the granular temperature T against the height z
# (one curve per grid). Grey lines: the core's edges z = +-r_core (r < d - layer, the coarsest grid's
# run); dashed lines: the lowest and the highest shear-rate threshold of the runs (ii), at or below
# which they switch the segregation off.
# The flowing layer is the top of the bed, where the shear rate and T rise by decades; below it the
# bed creeps (docs/sect4.2_results.md, "The core"; docs/generated/core_attribution.md).
# needs: bench_core_attribution
# reads: core_profile.dat core_attribution.dat
# Data: core_profile.dat (cells z T shear_rate phi_hat r_core_layer; one block per grid),
#       core_attribution.dat (part cells dt_max min_shear_rate core core_se ...; part 1: the runs (ii)).
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_core_profile.gp
profile = benchdir.'/core_profile.dat'
runs = benchdir.'/core_attribution.dat'
width = 1500; height = 650; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
stats profile u 6 index 0 nooutput
r_core = 1e3 * STATS_max
stats runs u 3 nooutput
dt_default = STATS_max  # the runs at a shorter step repeat the first grid
stats runs u (($1 == 0 && $3 == dt_default) ? $2 : 1/0) nooutput
blocks = STATS_records  # one full-model run at the default step and one profile block per grid
array cells[blocks]
do for [b = 1:blocks] {
    stats profile index (b - 1) u 1 nooutput
    cells[b] = STATS_max
}
stats runs u ($1 == 1 ? $4 : 1/0) nooutput
thr_lo = STATS_min; thr_hi = STATS_max
set multiplot layout 1,3 title "The full model at t_end on the vertical line through the drum's axis (grey: the core's edges; dashed: the lowest and highest threshold of the runs (ii))"
set grid
set ylabel "z [mm]"
set key top left
set style line 9 lc rgb "#888888" lw 2
set arrow 1 from graph 0, first r_core to graph 1, first r_core nohead ls 9
set arrow 2 from graph 0, first -r_core to graph 1, first -r_core nohead ls 9
set title "small-particle share"
set xlabel "phi_hat"
plot for [b = 1:blocks] profile index (b - 1) u 5:(1e3 * $2) w lp lw 2 pt 7 ps 0.6 t sprintf("%d cells", cells[b])
set title "shear rate kappa_max - kappa_min"
set xlabel "shear rate [1/s]"
set logscale x
set arrow 3 from first thr_lo, graph 0 to first thr_lo, graph 1 nohead lw 2 dt 2 lc rgb "#444444"
set arrow 4 from first thr_hi, graph 0 to first thr_hi, graph 1 nohead lw 2 dt 2 lc rgb "#444444"
plot for [b = 1:blocks] profile index (b - 1) u 4:(1e3 * $2) w lp lw 2 pt 7 ps 0.6 t sprintf("%d cells", cells[b])
unset arrow 3; unset arrow 4
set title "granular temperature"
set xlabel "T [m^2/s^2]"
set format x "1e%L"
plot for [b = 1:blocks] profile index (b - 1) u 3:(1e3 * $2) w lp lw 2 pt 7 ps 0.6 t sprintf("%d cells", cells[b])
unset multiplot
