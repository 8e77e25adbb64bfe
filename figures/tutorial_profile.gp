# The column profiles of docs/tutorial.md (steps 3 and 4): phi and Phi against z of one or more
# profile.dat files that a segregation1d run wrote, whatever their grid (columns z Phi T phi).
# Usage: gnuplot -e "files='out/a/profile.dat out/b/profile.dat'; outfile='out/x.png'" figures/tutorial_profile.gp
#   optional: zmin, zmax (the window in z, default the whole column)
width = 1000; height = 600; fontsize = 12
load 'figures/png_terminal.gnuplot'
set output outfile
set title "phi (points) and Phi (line) against z"
set xlabel "z"
set ylabel "volume fraction"
if (exists("zmin") && exists("zmax")) { set xrange [zmin:zmax] }
set key below horizontal
set offsets graph 0, graph 0, graph 0.05, graph 0.05   # a constant Phi off the frame
run(i) = system("basename $(dirname '".word(files, i)."')")   # the run's directory names it
plot for [i=1:words(files)] word(files, i) u 1:4 w p pt 7 ps 0.7 lc i t run(i).": phi", \
     for [i=1:words(files)] word(files, i) u 1:2 w l lw 1.5 lc i t run(i).": Phi"
