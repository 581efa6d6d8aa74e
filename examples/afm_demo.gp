# SPDX-License-Identifier: MIT
# examples/afm_demo.gp: the plots of make demo from afm_demo's CSV files in
# the directory `dir` (gnuplot -e "dir='build/demo'" examples/afm_demo.gp):
#   afm_fd.png     equilibrium force against depth of the exact sphere on
#                  each substrate, with its fixed-load pull-off (libmdr) and
#                  the JKR closed form -1.5 pi w R of the paraboloid
#   afm_cycle.png  the real-time force against base position z of the
#                  cantilever cycle, approach and retract, jump-in and
#                  pull-off marked
# Physical units: nm and nN. The legends sit below the panels.
set datafile separator ','
set terminal pngcairo size 1200,600 noenhanced font ',11'
subs = 'PDMS polystyrene'
nm = 1e9
nN = 1e9
is(s) = strcol(1) eq s

set output dir.'/afm_fd.png'
set multiplot layout 1,2 title 'Si3N4 tip R = 20 nm, exact sphere: equilibrium F(d) (libmdr f32)'
set grid
set key outside bottom center horizontal
set xlabel 'indentation depth d [nm]'
set ylabel 'force F [nN] (tensile < 0)'
do for [s in subs] {
    set title s
    # the JKR value of this substrate (a constant: plotted as a function, so
    # that it does not widen the depth axis)
    stats dir.'/afm_marks.csv' using (is(s) && strcol(2) eq 'JKR -1.5 pi w R' ? $4*nN : 1/0) nooutput
    jkr = STATS_min
    plot dir.'/afm_fd.csv' using (is(s) ? $3*nm : 1/0):($4*nN) with lines lw 2 lc rgb '#1f77b4' title 'equilibrium', \
         dir.'/afm_marks.csv' using (is(s) && strcol(2) eq 'fixed-load pull-off' ? $3*nm : 1/0):($4*nN) \
             with points pt 7 ps 1.6 lc rgb '#d62728' title 'pull-off, fixed load (libmdr)', \
         '' using (is(s) && strcol(2) eq 'fixed-load pull-off' ? $3*nm : 1/0):($4*nN):(sprintf(' %.2f nN', $4*nN)) \
             with labels left offset 1,-0.6 tc rgb '#d62728' notitle, \
         jkr with lines dt 2 lw 2 lc rgb '#555555' title sprintf('JKR -1.5 pi w R = %.2f nN (paraboloid)', jkr)
}
unset multiplot

set output dir.'/afm_cycle.png'
set multiplot layout 1,2 title 'Real-time force spectroscopy through a 0.2 N/m cantilever (spring engine, 512 springs, f32)'
set xlabel 'base position z [nm]'
do for [s in subs] {
    set title s
    plot dir.'/afm_cycle.csv' using (is(s) && strcol(8) eq 'approach' ? $3*nm : 1/0):($5*nN) \
             with lines lw 2 lc rgb '#1f77b4' title 'approach', \
         '' using (is(s) && strcol(8) eq 'retract' ? $3*nm : 1/0):($5*nN) \
             with lines lw 2 lc rgb '#ff7f0e' title 'retract', \
         dir.'/afm_marks.csv' using (is(s) && strcol(2) eq 'jump-in' ? $3*nm : 1/0):($5*nN) \
             with points pt 9 ps 1.8 lc rgb '#2ca02c' title 'jump-in', \
         '' using (is(s) && strcol(2) eq 'jump-in' ? $3*nm : 1/0):($5*nN):(sprintf(' jump-in %.2f nN', $5*nN)) \
             with labels left offset 1,-0.8 tc rgb '#2ca02c' notitle, \
         '' using (is(s) && strcol(2) eq 'pull-off' ? $3*nm : 1/0):($4*nN) \
             with points pt 7 ps 1.6 lc rgb '#d62728' title 'pull-off', \
         '' using (is(s) && strcol(2) eq 'pull-off' ? $3*nm : 1/0):($4*nN):(sprintf(' pull-off %.2f nN', $4*nN)) \
             with labels left offset 1,0 tc rgb '#d62728' notitle
}
unset multiplot
