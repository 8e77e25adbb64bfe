# The Fig. 7 quantities against the cell size h (solution verification of the paper's drum): each
# run with its sampling error, both transports (and the explicit mode if run); the band f1 +- U (where the h -> 0 value
# lies, clipped to the quantity's physical range) from the finest run to h = 0 and the least-squares limit f0 at h = 0;
# the dt_max study's runs (dt_max times factors below 1) beside the coarsest and the finest grid; in the last panel
# the core's retained share by material points and tracer, with the limits whose fit lies inside [0, 1].
# needs: bench_fig7_convergence
# reads: fig7_runs.dat fig7_convergence.dat
# Data: fig7_runs.dat (kind explicit cells h_mm dt_factor dt_mean_ms steps wall_s cpu_s, then per
#       quantity value and _se: angle layer index ring periphery core contrast axis from column 10,
#       then transport (0 the reference, 1 the second, -1 explicit) dt_max_ms dt_max_share points
#       points_se: the material points' retained share of the core in the tracer runs);
#       fig7_convergence.dat (quantity series runs x1 f1 se_max condition p f0 p_u fs sigma U e_a e_ext
#       chi2 chi2_95 lo hi outside band_lo band_hi; series 0 the reference transport, 1 explicit, 2 dt at
#       the finest grid, 3 tracer, 4 the second transport, 5 dt at the coarsest grid, 6 material points).
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_fig7_convergence.gp
runs = benchdir.'/fig7_runs.dat'
conv = benchdir.'/fig7_convergence.dat'
set terminal pngcairo size 1800,1500 font "Sans,11" noenhanced
set output outfile
array names[8] = ["dynamic angle of repose [deg]", "flowing-layer thickness [mm]", "segregation index", \
                  "ring: small-particle share", "periphery: small-particle share", "core: small-particle share", \
                  "Fig. 7d contrast (Phi mixed - pure)", "share within 0.05 D of the axis"]
# sel(q, s): a row of fig7_convergence.dat for quantity q and series s (also keeps other rows out of autoscale)
sel(q, s) = column(1) == q && column(2) == s
cond(c) = c == 0 ? "monotone" : c == 1 ? "oscillatory" : c == 2 ? "divergent" : c == 3 ? "within noise" : c == 4 ? "two grids" : "undetermined"
stats runs u 4 nooutput
hmax = 1.15 * STATS_max
set multiplot layout 3,3 title "Fig. 7 quantities against the cell size h. Blue circles: the reference transport (first of --transports); orange: the second; red squares: explicit; green: the reference with dt_max times factors below 1 (left of its grid); dt ~ h on every grid\nbars: sampling error; shaded: the finest run's value +- its uncertainty U, clipped to the quantity's range (least-squares fit over all grids, Fs by Roy's rule; red: two grids, Fs 3, order 1 assumed); diamonds at h = 0: extrapolated limits"
set grid
set xrange [0:hmax]
set xlabel "h [mm]"
unset key
set style fill transparent solid 0.18 noborder
do for [q = 0:7] {
    stats conv u (($1 == q && $2 == 0) ? $7 : 1/0) nooutput
    c = STATS_max
    p = 0
    if (c == 0) { stats conv u (($1 == q && $2 == 0) ? $8 : 1/0) nooutput; p = STATS_max }
    set title sprintf("%s\nreference: %s%s", names[q+1], cond(c), c == 0 ? sprintf(", p = %.2f", p) : "")
    v = 10 + 2*q
    plot conv u (sel(q, 0) ? $4/2 : 1/0):(sel(q, 0) ? $5 : 1/0):(0):($4):(sel(q, 0) ? $21 : 1/0):(sel(q, 0) ? $22 : 1/0) w boxxyerror lc rgb "#1f77b4" t "reference: f1 +- U", \
         conv u (sel(q, 4) ? $4/2 : 1/0):(sel(q, 4) ? $5 : 1/0):(0):($4):(sel(q, 4) ? $21 : 1/0):(sel(q, 4) ? $22 : 1/0) w boxxyerror lc rgb "#ff7f0e" t "second transport: f1 +- U", \
         conv u (sel(q, 1) ? $4/2 : 1/0):(sel(q, 1) ? $5 : 1/0):(0):($4):(sel(q, 1) ? $21 : 1/0):(sel(q, 1) ? $22 : 1/0) w boxxyerror lc rgb "#d62728" t "explicit: f1 +- U (Fs 3)", \
         runs u (($1 == 0 && $2 == 0 && $26 == 0) ? $4 : 1/0):v:(column(v+1)) w yerrorlines lw 2 pt 7 lc rgb "#1f77b4" t "reference transport", \
         runs u (($1 == 0 && $2 == 0 && $26 == 1) ? $4 : 1/0):v:(column(v+1)) w yerrorlines lw 2 pt 9 lc rgb "#ff7f0e" t "second transport", \
         runs u (($1 == 0 && $2 == 1) ? $4 : 1/0):v:(column(v+1)) w yerrorlines lw 2 pt 5 lc rgb "#d62728" t "explicit", \
         runs u (($1 == 1) ? $4 * (1 - 0.08 * (1 - $5)) : 1/0):v:(column(v+1)) w yerrorbars pt 11 ps 1.3 lc rgb "#2ca02c" t "dt study", \
         conv u (($1 == q && $2 == 0 && $20 == 0) ? 0 : 1/0):9 w p pt 13 ps 2 lc rgb "#1f77b4" t "reference: limit", \
         conv u (($1 == q && $2 == 4 && $20 == 0) ? 0 : 1/0):9 w p pt 13 ps 2 lc rgb "#ff7f0e" t "second transport: limit", \
         conv u (($1 == q && $2 == 1 && $20 == 0) ? 0 : 1/0):9 w p pt 12 ps 2 lc rgb "#d62728" t "explicit: extrapolated (p = 1)"
}
set title "share of the core at t_end that started there\nbrown: material points (no numerical diffusion); purple: tracer (full model)"
set key bottom right
plot conv u (sel(5, 6) ? $4/2 : 1/0):(sel(5, 6) ? $5 : 1/0):(0):($4):(sel(5, 6) ? $21 : 1/0):(sel(5, 6) ? $22 : 1/0) w boxxyerror lc rgb "#8c564b" t "material points: f1 +- U", \
     conv u (sel(5, 3) ? $4/2 : 1/0):(sel(5, 3) ? $5 : 1/0):(0):($4):(sel(5, 3) ? $21 : 1/0):(sel(5, 3) ? $22 : 1/0) w boxxyerror lc rgb "#9467bd" t "tracer: f1 +- U", \
     runs u (($1 == 2) ? $4 : 1/0):29:30 w yerrorlines lw 2 pt 5 lc rgb "#8c564b" t "material points", \
     runs u (($1 == 2) ? $4 : 1/0):20:21 w yerrorlines lw 2 pt 7 lc rgb "#9467bd" t "tracer runs", \
     conv u (($1 == 5 && $2 == 6 && $20 == 0) ? 0 : 1/0):9 w p pt 13 ps 2 lc rgb "#8c564b" t "material points: limit", \
     conv u (($1 == 5 && $2 == 3 && $20 == 0) ? 0 : 1/0):9 w p pt 13 ps 2 lc rgb "#9467bd" t "tracer: limit (where inside [0, 1])"
unset multiplot
