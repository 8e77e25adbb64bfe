# Shared by figures/fig7*_tumbler.gp (not a figure itself): reads the run's fields at t = 0,
# dir/initial_lab.dat, whose grid is not yet turned (a later field's x extent grows with the turn),
# sets the cell size h (cm) and cells per diameter n from it, the drum radius R (cm), the bed test,
# the map's axes and the phi_hat palette. The fields file holds all n x n cells, one block per row.
stats dir.'/initial_lab.dat' u 1 nooutput
n = int(sqrt(STATS_records) + 0.5)
R = 100 * (STATS_max - STATS_min) * n / (n - 1) / 2
h = 2 * R / n / 100
bed(inside, Phi) = inside > 0.5 && Phi > 0.3
set size ratio -1
set xrange [-1.06*R:1.06*R]
set yrange [-1.06*R:1.06*R]
set xlabel "x  [cm]"
set ylabel "z  [cm]"
set cbrange [0:1]
set palette defined (0 "#2c7bb6", 0.5 "#ffffbf", 1 "#d7191c")
set key top left
