# SPDX-License-Identifier: MIT
# host_tests/bench_plot.gp: the run-time/error plane of the benchmark matrix
# (make bench). Data: bench_matrix.c --plot, one block per method and
# arithmetic with lines "N ns/eval max-error" (medians of time over the
# scenes, worst error over the smooth ones); the last block is the GSL
# reference's time (a vertical line: it is the reference, error 0).
# Usage: gnuplot -e "datafile='plot.dat'; outfile='bench.png'" bench_plot.gp
# blocks (the last is the reference) and the reference's time
stats datafile using 2 nooutput
nb = STATS_blocks
stats datafile index (nb - 1) using 2 nooutput
tref = STATS_max
set terminal pngcairo size 1100,720 font ",11" noenhanced
set output outfile
set logscale xy
set format x "1e%L"
set format y "1e%L"
set xlabel "time per evaluation on the host [ns] (median over the scenes)"
set ylabel "max error over a cycle, of peak |F| (worst smooth scene)"
set title "libmdr: run time against error (labels: number of springs N, f32 engine and naive sum)"
set grid
set key outside right top
set xrange [3:3e5]
set yrange [1e-17:1]
set arrow from tref, graph 0 to tref, graph 1 nohead dashtype 2 lc rgb "black"
set label "GSL reference\n(error 0 by definition)" at tref, 1e-14 right offset -1,0
plot for [i=0:nb-2] datafile index i using 2:3 with linespoints pt (i % 7) + 4 title columnheader(1), \
     for [i=0:nb-2] datafile index i using 2:3:4 with labels offset 1.5,0.6 font ",9" notitle
