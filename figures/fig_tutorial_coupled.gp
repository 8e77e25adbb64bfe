# Step 7 of docs/tutorial.md: the figure of its command's run, the coupled drum of
# verification/scenes/tutorial_coupled.toml (25 cells per diameter, 10 s), drawn as Fig. 7c.
# needs: run_tutorial_coupled
# reads: tutorial_coupled/fields_lab.dat tutorial_coupled/history.dat tutorial_coupled/initial_lab.dat
# The student's own run: gnuplot -e "dir='out/coupled'; outfile='out/coupled.png'" figures/fig7c_tumbler.gp
dir = rundir.'/tutorial_coupled'
load 'figures/fig7c_tumbler.gp'
