# Fig. 7b: the coupled drum after the run: close-up of the surface region with the lab-frame
# velocity (arrows coloured by speed) and the segregation direction d_s (black) as in the paper.
# needs: verify_tumbler
# Data: DIR/fields_lab.dat (x z Phi phi_hat u_x u_z T ds_x ds_z inside urel_x urel_z ...; lab frame),
#       DIR as in fig7a_tumbler.gp. Arrows every k-th cell (k ~ n/32); d_s in the flowing cells
#       (faster than 5 % of the wall speed relative to the drum).
# Usage (from the Makefile): gnuplot -e "datadir='build/data'; outfile='x.png'" figures/fig7b_tumbler.gp
if (!exists("dir")) dir = datadir.'/tumbler'
f = dir.'/fields_lab.dat'
load 'figures/tumbler_common.gp'
set terminal pngcairo size 1300,800 font "Sans,11" noenhanced
set output outfile
k = n > 40 ? int(n / 32.0 + 0.5) : 1
keep(x) = int(floor((x + R/100) / (h/100) + 0.5)) % k == 0
wall_speed = 2 * pi * 0.1 * R / 100          # m/s at 0.1 rps
sc = 0.8 * k * 100 * h / wall_speed          # cm per (m/s): the wall speed draws 0.8 of the arrow spacing
ds = 0.8 * k * 100 * h                       # cm, length of a d_s segment
v_flow = 0.05 * wall_speed                   # flowing: faster than this relative to the drum (check c)
set title sprintf("Fig. 7b: surface region at the end of the run: velocity (lab frame, colour = speed) and d_s (black), %d cells per diameter", n)
set xrange [-1.0*R:0.8*R]
set yrange [-0.3*R:0.95*R]
set cbrange [0:*]
set cblabel "|u|  [m/s]"
set palette defined (0 "#313695", 1 "#74add1", 2 "#fee090", 3 "#f46d43", 4 "#a50026")
set key bottom right opaque
set parametric
set trange [0:1]
plot f u (bed($10, $3) ? 100*$1 : 1/0):(100*$2):(50*h):(50*h) w boxxy fs solid 0.15 noborder lc rgb "#888888" notitle, \
     R*cos(2*pi*t), R*sin(2*pi*t) w l lw 2 lc rgb "black" notitle, \
     f u (bed($10, $3) && keep($1) && keep($2) ? 100*$1 : 1/0):(100*$2):(sc*$5):(sc*$6):(sqrt($5**2 + $6**2)) \
       w vectors head size 0.1,20 filled lc palette t "u (lab frame)", \
     f u (bed($10, $3) && sqrt($11**2 + $12**2) > v_flow && keep($1) && keep($2) ? 100*$1 - ds/2*$8 : 1/0):(100*$2 - ds/2*$9):(ds*$8):(ds*$9) \
       w vectors nohead lw 1.5 lc rgb "black" t "d_s (flowing cells)"
