# The figure of figures/fig7c_tumbler.gp at 100 cells per diameter (make fig7, make figures-full).
# needs: run_tumbler
# reads: tumbler/fields_lab.dat tumbler/history.dat
# Data: the coupled drum of verification/scenes/tumbler.toml, run by make into rundir/tumbler.
dir = rundir.'/tumbler'
load 'figures/fig7c_tumbler.gp'
