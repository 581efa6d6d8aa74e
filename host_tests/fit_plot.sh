#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# fit_plot.sh: the plot of docs/fitting.md (make fit-plot). A noisy
# approach-retract curve made by the spring engine (`mdr cycle`, machine
# control), fitted with `mdr fit --approach --model`, drawn with gnuplot:
# data and fitted model, force [nN] against z - z0 [nm].
# Also leaves OUTDIR/curve.csv and OUTDIR/map.csv (that curve and a flat
# one), the examples of docs/fitting.md.
# Usage: bash host_tests/fit_plot.sh build/host/mdr OUTDIR docs/fit_curve.png
set -eu
MDR=$1
OUT=$2
PNG=$3
mkdir -p "$OUT"
TIP="--profile paraboloid --R 20e-9"
# the scene of the benchmark: E* = 1 GPa, w = 0.05 J/m^2 (reversible: the
# model has no pinned part at the top of the retract), a 0.2 N/m lever;
# z offset 2 um, a baseline of 0.3 nN tilted by 4e-3 N/m (as virtual
# deflection tilts raw curves; 0.32 nN, 7 % of the pull-off force, over
# the 80 nm the curve spans); noise 0.1 nN (2 % of the pull-off force),
# 4000 samples
"$MDR" cycle $TIP --E 1e9 --w 0.05 --w-adv 0.05 --control machine --k-machine 0.2 \
    --path -6e-8,2e-8,-6e-8 --steps-per-segment 2000 --springs 1024 --arith f64 2>/dev/null |
    awk -F, 'BEGIN { srand(7) } NR == 1 { print "z,F"; next }
        { u = 0; for (k = 0; k < 12; k++) u += rand()
          printf "%.17g,%.17g\n", $2 + 2e-6, $4 + 3e-10 + 4e-3 * $2 + 1e-10 * (u - 6) }' \
    > "$OUT/curve.csv"
"$MDR" fit --curve "$OUT/curve.csv" $TIP --k-machine 0.2 --approach --model "$OUT/model.csv" > "$OUT/fit.json"
# a map for docs/fitting.md's example: this curve, and one without contact
{ echo "curve,z,F"; awk -F, 'NR > 1 { print "x0y0," $0 }' "$OUT/curve.csv"
  awk -F, 'NR > 1 { print "x1y0," $1 ",1e-12" }' "$OUT/curve.csv"; } > "$OUT/map.csv"
cat "$OUT/fit.json"
get() { tr -d '{}' < "$OUT/fit.json" | tr ',' '\n' | awk -F': ' -v k="\"$1\"" '$1 ~ k { gsub(/[ "]/, "", $2); print $2 }'; }
z0=$(get z0)
label=$(awk -v E="$(get E)" -v Ee="$(get E_err)" -v w="$(get w)" -v we="$(get w_err)" -v wa="$(get w_adv)" \
    -v mu="$(get mu)" -v rg="$(get regime)" -v sl="$(get F_slope)" -v se="$(get F_slope_err)" \
    'BEGIN { printf "fit: E* = %.2f ± %.2f GPa, w = %.2f ± %.2f mJ/m^2, w_{adv} = %.1f mJ/m^2, baseline slope %.2f ± %.2f mN/m, μ = %.2f (%s)", \
             E / 1e9, Ee / 1e9, w * 1e3, we * 1e3, wa * 1e3, sl * 1e3, se * 1e3, mu, rg }')
awk -F, -v z0="$z0" 'NR > 1 { printf "%.9g %.9g %.9g %s\n", ($1 - z0) * 1e9, $2 * 1e9, $3 * 1e9, $4 }' \
    "$OUT/model.csv" > "$OUT/plot.dat"
gnuplot <<GP
set terminal pngcairo size 900,560 font "DejaVu Sans,11"
set output "$PNG"
set xlabel "base position z - z0 [nm] (toward the sample)"
set ylabel "force F [nN] (compressive positive)"
set title "$label" font ",10"
set key bottom right
set grid lc rgb "#dddddd"
plot "$OUT/plot.dat" using (strcol(4) eq "approach" ? \$1 : 1/0):2 with points pt 7 ps 0.3 lc rgb "#9ecae1" title "data, approach", \
     "" using (strcol(4) eq "retract" ? \$1 : 1/0):2 with points pt 7 ps 0.3 lc rgb "#fdae6b" title "data, retract", \
     "" using (strcol(4) eq "approach" ? \$1 : 1/0):3 with lines lw 2 lc rgb "#08519c" title "model, approach (w_{adv})", \
     "" using (strcol(4) eq "retract" ? \$1 : 1/0):3 with lines lw 2 lc rgb "#a63603" title "model, retract (w), jump-off at the fold"
GP
echo "fit-plot: $PNG"
