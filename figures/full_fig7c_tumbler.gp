# The figure of figures/fig7c_tumbler.gp at 100 cells per diameter (make figures-full).
# needs: bench_tumbler
# Data: the coupled drum of verification/scenes/tumbler.toml, run by bench_tumbler into benchdir/tumbler.
dir = benchdir.'/tumbler'
load 'figures/fig7c_tumbler.gp'
