#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench_fit_map.sh: `mdr fit --map` on N curves (the spring engine's
# approach-retract cycles of the benchmark's scene, 1 000 retract points
# each, noise 1 % of the pull-off force, z and F offsets per curve), wall
# clock with one thread and with every core, in one run; prints Markdown
# rows for host_tests/bench/fit.md (make bench-fit).
# Usage: bash host_tests/bench_fit_map.sh build/host/mdr N
set -eu
MDR=$1
N=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
"$MDR" cycle --profile paraboloid --R 20e-9 --E 1e9 --w 0.05 --w-adv 0.05 --control machine --k-machine 0.2 \
    --path -1e-8,2e-8,-4e-8 --steps-per-segment 1000 --springs 1024 --arith f64 2>/dev/null > "$TMP/cycle.csv"
awk -F, -v n="$N" 'BEGIN { srand(3); print "curve,z,F" } NR > 1 { z[NR] = $2; F[NR] = $4; m = NR }
    END { for (c = 0; c < n; c++) { dz = 1e-6 + 1e-9 * c; db = 1e-11 * (c % 7);
            for (i = 2; i <= m; i++) { u = 0; for (k = 0; k < 12; k++) u += rand();
                printf "p%d,%.12g,%.12g\n", c, z[i] + dz, F[i] + db + 4.7e-11 * (u - 6) } } }' \
    "$TMP/cycle.csv" > "$TMP/map.csv"
cores=$(getconf _NPROCESSORS_ONLN)
run() { # run JOBS -> seconds
    local t0 t1
    t0=$(date +%s.%N)
    "$MDR" fit --map "$TMP/map.csv" --profile paraboloid --R 20e-9 --k-machine 0.2 --approach --jobs "$1" > "$TMP/res$1.csv" 2>/dev/null || true
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}
t1=$(run 1)
tn=$(run "$cores")
cmp -s "$TMP/res1.csv" "$TMP/res$cores.csv" || { echo "bench_fit_map: 1 and $cores threads differ" >&2; exit 1; }
okc=$(grep -c ',ok,' "$TMP/res1.csv" || true)
load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
echo
echo "| \`mdr fit --map\`, $N curves of 2 001 rows ($okc fitted), CSV parsing included | wall clock | curves/s |"
echo "| --- | ---: | ---: |"
awk -v n="$N" -v t="$t1" 'BEGIN { printf "| --jobs 1 | %.2f s | %.0f |\n", t, n / t }'
awk -v n="$N" -v t="$tn" -v c="$cores" -v t1="$t1" \
    'BEGIN { printf "| --jobs %d (all cores) | %.2f s | %.0f (x %.2f) |\n", c, t, n / t, t1 / t }'
awk -v t="$t1" -v n="$N" -v c="$cores" \
    'BEGIN { printf "\nA 256 x 256 map (65 536 such curves) at the --jobs 1 rate on %d cores: %.0f s.\n", c, 65536 / (n / t) / c }'
echo
echo "Load average when measured: $load (the machine's $cores cores are shared; the threaded figure counts what the other processes left)."
