# Fig. 4b of the paper: regions G-J of Q_R for Q_L = (0.4, 0.5), right of Gamma.
# needs: verify_table1_figures
# reads: fig4b_regions.dat fig4b_labels.dat
# Data: fig4b_regions.dat (case of every Q_R of a 400 x 400 grid), fig4b_labels.dat.
name = "fig4b"; panel = "b"; QL_phi = 0.4; QL_Phi = 0.5
load 'figures/table1_regions.gnuplot'
