# Work against error for the paper's drum: each run's CPU time against its distance from the
# reference, the finest grid's smallest-dt run, per transport, grid and dt_max; the cells per
# diameter at each point; the reference's band (grid plus dt uncertainty) as a grey band, below
# which an error ranks nothing; the tolerances of a quick look, a figure and a paper (fig7_work.cpp).
# needs: bench_fig7_convergence
# reads: fig7_work.dat
# Data: fig7_work.dat (transport cells dt_factor cpu_s wall_s err_angle err_layer err_index err_ring
#       err_periphery err_core err_contrast err_axis, then u_angle ... u_axis: the reference's band;
#       transport 0 the reference, 1 the second, -1 explicit).
# Usage (from the Makefile): gnuplot -e "benchdir='build/bench-data'; outfile='x.png'" figures/bench_fig7_work.gp
f = benchdir.'/fig7_work.dat'
set terminal pngcairo size 1500,1100 font "Sans,11" noenhanced
set output outfile
set multiplot layout 2,2 title "The paper's drum, work against error (reference: the finest grid's smallest-dt run)\nBlue: the reference transport; orange: the second; red: explicit; green: the reference transport with a smaller dt_max (numbers: cells per diameter)"
set grid
set logscale xy
set format x "%g"
set format y "%g"
set xlabel "CPU time of the run, all threads [s]"
set key bottom left font ",9" opaque
array cols[4] = [6, 8, 7, 11]
array titles[4] = ["(a) dynamic angle of repose: |angle - reference| [deg]", "(b) segregation index: |index - reference|", \
                   "(c) flowing-layer thickness: |layer - reference| [mm]", "(d) core: |share - reference|"]
array tol_quick[2] = [2.0, 0.1]
array tol_figure[2] = [0.5, 0.02]
array tol_paper[2] = [0.2, 0.01]
do for [i = 1:4] {
    c = cols[i]
    set title titles[i]
    set ylabel "error"
    set autoscale y
    stats f u (column(c + 8)) nooutput
    set object 4 rect from graph 0, graph 0 to graph 1, first STATS_max fc rgb "gray80" fs transparent solid 0.4 noborder behind
    set label 4 "below: within the reference's uncertainty" at graph 0.98, first STATS_max right offset 0,-0.8 font ",9"
    if (i <= 2) {
        set yrange [*:3 * tol_quick[i]]  # the tolerance lines and their labels inside the frame
        set arrow 1 from graph 0, first tol_quick[i] to graph 1, first tol_quick[i] nohead dt 3 lc rgb "gray30"
        set arrow 2 from graph 0, first tol_figure[i] to graph 1, first tol_figure[i] nohead dt 2 lc rgb "black"
        set arrow 3 from graph 0, first tol_paper[i] to graph 1, first tol_paper[i] nohead dt 4 lc rgb "gray30"
        set label 1 "quick look" at graph 0.02, first tol_quick[i] offset 0,0.5 font ",9"
        set label 2 "figure" at graph 0.02, first tol_figure[i] offset 0,0.5 font ",9"
        set label 3 "paper" at graph 0.02, first tol_paper[i] offset 0,0.5 font ",9"
    } else {
        unset arrow 1; unset arrow 2; unset arrow 3; unset label 1; unset label 2; unset label 3
    }
    plot f u (($1 == 0 && $3 == 1 && column(c) > 0) ? $4 : 1/0):c w lp lw 2 pt 7 lc rgb "#1f77b4" t "reference transport", \
         f u (($1 == 1 && column(c) > 0) ? $4 : 1/0):c w lp lw 2 pt 9 lc rgb "#ff7f0e" t "second transport", \
         f u (($1 == -1 && column(c) > 0) ? $4 : 1/0):c w lp lw 2 pt 5 lc rgb "#d62728" t "explicit", \
         f u (($1 == 0 && $3 != 1 && column(c) > 0) ? $4 : 1/0):c w p pt 11 ps 1.4 lc rgb "#2ca02c" t "reference transport, smaller dt_max", \
         f u (column(c) > 0 ? $4 : 1/0):c:(sprintf("%d", $2)) w labels offset 0,1 font ",9" notitle
}
unset multiplot
