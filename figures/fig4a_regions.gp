# Fig. 4a of the paper: regions A-F of Q_R for Q_L = (0.15, 0.5), left of Gamma.
# needs: verify_table1_figures
# reads: fig4a_regions.dat fig4a_labels.dat
# Data: fig4a_regions.dat (case of every Q_R of a 400 x 400 grid), fig4a_labels.dat.
name = "fig4a"; panel = "a"; QL_phi = 0.15; QL_Phi = 0.5
load 'figures/table1_regions.gnuplot'
