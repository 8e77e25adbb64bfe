# make fig7's own summary (Makefile, target fig7): reads the run's summary.dat, prints the Fig. 7
# numbers of this run as a markdown table on stdout (README.md shows it as a generated table,
# docs/generated/fig7_run.md), and writes its cost to the file `cost` (docs/generated/fig7_cost.md).
# The columns are read by the names of summary.dat's first line.
#   awk -v cost=build/runs/fig7_cost.md -f verification/fig7_tables.awk build/runs/tumbler/summary.dat
NR == 1 { for (i = 2; i <= NF; i++) col[$i] = i - 1; next }
/^#/ { next }
{
    print "| Fig. 7 quantity, make fig7 (100 cells per diameter, 25 s) | value |"
    print "|---|---|"
    printf "| dynamic angle of repose (deg), mean over t >= 10 s | %.2f |\n", $col["angle_mean_deg"]
    printf "| flowing-layer thickness (mm), mean over t >= 10 s | %.2f |\n", 1000 * $col["layer_mean"]
    printf "| segregation index | %.3f |\n", $col["segregation_index"]
    printf "| ring, small-particle share | %.3f |\n", $col["ring_layer"]
    printf "| periphery, small-particle share | %.4f |\n", $col["periphery_layer"]
    printf "| core, small-particle share | %.3f |\n", $col["core_layer"]
    printf "| Fig. 7d contrast (Phi mixed - pure) | %.4f |\n", $col["packing_contrast"]
    printf "| small-particle share within 0.05 D of the axis | %.3f |\n", $col["axis_layer"]
    print ""
    print "Printed by `make fig7` from its run's `summary.dat` (`verification/scenes/tumbler.toml`, the default time stepping)."
    print "| make fig7's drum run | value |\n|---|---|" > cost
    printf "| wall time (s) | %.0f |\n| CPU time, all threads (s) | %.0f |\n| threads | %d |\n| flow steps | %d |\n",
           $col["wall_seconds"], $col["cpu_seconds"], $col["threads"], $col["steps"] > cost
    print "\nWritten by `make fig7`: the cost of its drum run on the machine that ran it." > cost
}
