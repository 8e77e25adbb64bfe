# The coupled drum's time-step error: the Fig. 7 quantities against dt_max on fixed grids, without
# (blue) and with (red) packing feedback, each transport (solid: muscl, dashed: donor-cell) and grid
# (circles: the coarser, squares: the finer); bars: sampling errors. A curve that flattens towards
# small dt_max has reached its dt -> 0 limit; its height above that at the largest dt_max (the
# default step) is the time error (docs/generated/time_step.md gives the fitted numbers). The last
# panel: error against cost, the full model's shares of core (circles) and axis (squares) off their
# dt -> 0 limits against each run's CPU seconds (docs/generated/time_step_cost.md), per grid and
# transport (solid muscl, dashed donor-cell).
# needs: bench_time_step
# reads: time_step_runs.dat time_step_cost.dat
# Data: time_step_runs.dat (feedback transport cells dt_max dt_mean dt_max_share steps wall_seconds
#       cpu_seconds, then per quantity value and _se: angle layer_mm index ring core contrast axis;
#       transport 0 muscl, 1 donor-cell); time_step_cost.dat (transport cells dt_max dt_mean steps
#       acoustic_share cpu_seconds, then per quantity _error and _bound: angle index core axis).
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_time_step.gp
runs = benchdir.'/time_step_runs.dat'
cost = benchdir.'/time_step_cost.dat'
width = 1800; height = 1100; fontsize = 11
load 'figures/png_terminal.gnuplot'
set output outfile
stats runs u 3 nooutput
n_lo = STATS_min; n_hi = STATS_max
array names[7] = ["dynamic angle of repose [deg]", "flowing-layer thickness [mm]", "segregation index", \
                  "ring: small-particle share", "core: small-particle share", "Fig. 7d contrast (Phi mixed - pure)", \
                  "share within 0.05 D of the axis"]
array cols[7] = [10, 12, 14, 16, 18, 20, 22]
sel(fb, tr, n, v) = ($1 == fb && $2 == tr && $3 == n) ? v : 1/0
set multiplot layout 2,4 title sprintf("The coupled drum against dt_max (grids %d and %d cells per diameter): blue without, red with packing feedback; solid muscl, dashed donor-cell; circles %d cells, squares %d cells", n_lo, n_hi, n_lo, n_hi)
set grid
set logscale x 2
set offsets graph 0.05, graph 0.05, 0, 0
set xlabel "dt_max [ms]"
unset key
do for [q = 1:7] {
    set title names[q]
    c = cols[q]
    # series s = 4 fb + 2 tr + g: feedback, transport, grid
    plot for [s = 0:7] runs u (sel(s/4, (s/2)%2, s%2 == 0 ? n_lo : n_hi, 1e3 * $4)):(column(c)):(column(c + 1)) \
         w yerrorlines lw 2 dt 1+(s/2)%2 pt (s%2 == 0 ? 7 : 5) lc rgb (s/4 == 0 ? "#1f77b4" : "#d62728")
}
# (none without the feedback part: the panel says so)
undefine STATS_*
stats cost u 7 nooutput
set title "full model: share off its dt -> 0 limit against cost"
if (exists("STATS_records")) {
    set xlabel "CPU seconds of the run"
    set ylabel "|share - limit|"
    set logscale xy 10
    set key top right
    grid(tr, n, v) = ($1 == tr && $2 == n && v > 0) ? v : 1/0
    # series s = 2 tr + g: transport (solid muscl, dashed donor-cell), grid (red/orange coarser, purple/brown finer)
    plot for [s = 0:3] cost u (grid(s/2, s%2 == 0 ? n_lo : n_hi, $7)):13 w lp lw 2 dt 1+s/2 pt 7 \
             lc rgb (s%2 == 0 ? "#d62728" : "#9467bd") t (s/2 == 0 ? sprintf("core, %d cells", s%2 == 0 ? n_lo : n_hi) : ""), \
         for [s = 0:3] cost u (grid(s/2, s%2 == 0 ? n_lo : n_hi, $7)):15 w lp lw 2 dt 1+s/2 pt 5 \
             lc rgb (s%2 == 0 ? "#ff7f0e" : "#8c564b") t (s/2 == 0 ? sprintf("axis, %d cells", s%2 == 0 ? n_lo : n_hi) : ""), \
         0.01 w l dt 3 lc rgb "black" t "target 0.01"
} else {
    unset border; unset tics; unset xlabel; unset logscale
    set label 1 "no cost runs (--parts without feedback)" at graph 0.5, 0.5 center
    plot [0:1][0:1] -1 notitle
}
unset multiplot
