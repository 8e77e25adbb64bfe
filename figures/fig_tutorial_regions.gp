# Fig. 4a for the left state of docs/tutorial.md, step 2: regions A-F of Q_R for Q_L = (0.1, 0.5).
# needs: verify_table1_figures
# reads: tutorial_fig4a_regions.dat tutorial_fig4a_labels.dat
# Data: tutorial_fig4a_regions.dat (case of every Q_R of a 400 x 400 grid), tutorial_fig4a_labels.dat.
name = "tutorial_fig4a"; panel = "a"; QL_phi = 0.1; QL_Phi = 0.5
load 'figures/table1_regions.gnuplot'
