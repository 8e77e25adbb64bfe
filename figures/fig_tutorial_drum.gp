# Step 6 of docs/tutorial.md: the figure of its command's run, the kinematic drum of
# verification/scenes/tutorial_drum.toml (40 cells per diameter, 25 s), drawn as Fig. 7c.
# needs: run_tutorial_drum
# reads: tutorial_drum/tumbler_final.dat tutorial_drum/tumbler_outline.dat tutorial_drum/tumbler_shells.dat tutorial_drum/tumbler_metrics.dat
# The student's own run: gnuplot -e "datadir='out/drum40'; outfile='out/drum40.png'" figures/fig7c_tumbler_kinematic.gp
datadir = rundir.'/tutorial_drum'
load 'figures/fig7c_tumbler_kinematic.gp'
