#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# test_cli.sh: the mdr CLI's interface contract (subcommands, flags, JSON keys,
# CSV columns, exit status 2 with a one-line message on bad arguments).
# Usage: bash host_tests/test_cli.sh build/host/mdr
# Values are checked against the closed forms (JKR, CHECK_VALUES) to 1e-6.
set -u
MDR=${1:-build/host/mdr}
. "$(dirname "$0")/cli_lib.sh"
P="--profile paraboloid --R 10e-6 --E 1e6 --w 0.05"

out=$($MDR eq $P --a 2.6e-6) || bad "eq exit"
for k in a d F dd_da dF_da dl K_I stable_load stable_grips; do
    [ -n "$(key "$out" $k)" ] && ok || bad "eq: key $k missing in $out"
done
near "$(key "$out" K_I)" 316.227766 1e-6 && ok || bad "eq K_I = sqrt(2 E w)"

for arith in f32 f64; do
    out=$($MDR critical $P --control load --arith $arith) || bad "critical exit"
    near "$(key "$out" F)" -2.35619449019e-6 1e-6 && ok || bad "critical load F ($arith): $out"
    near "$(key "$out" a)" 2.60469853934e-6 1e-6 && ok || bad "critical load a ($arith)"
    near "$(key "$out" d)" -0.226148482694e-6 1e-6 && ok || bad "critical load d ($arith)"
    out=$($MDR critical $P --control grips --arith $arith) || bad "critical grips exit"
    near "$(key "$out" F)" -1.308996939e-6 1e-6 && ok || bad "critical grips F ($arith): $out"
done
out=$($MDR critical $P --control machine --k-machine 1e9 --a-start 8e-6 --arith f64) || bad "machine exit"
near "$(key "$out" F)" -1.308996939e-6 1e-6 && ok || bad "stiff machine = grips: $out"

# a state (a, d) as given (issue 16): F, K_I, G of that state against the
# closed forms F = 2E*(a d - a^3/(3R)), K_I = E*(a^2/R - d)/sqrt(pi a), G = K_I^2/(2E*)
for arith in f32 f64; do
    out=$($MDR eq $P --a 2.6e-6 --d 0.1e-6 --arith $arith) || bad "eq --d exit ($arith)"
    for k in a d F dd_da dF_da dl K_I G stable_load stable_grips d_eq F_eq; do
        [ -n "$(key "$out" $k)" ] && ok || bad "eq --d: key $k missing in $out"
    done
    near "$(key "$out" F)" "$(awk 'BEGIN { a = 2.6e-6; printf "%.17g", 2e6 * (a * 0.1e-6 - a^3 / 30e-6) }')" 1e-6 && ok ||
        bad "eq --d F of the state ($arith): $out"
    near "$(key "$out" K_I)" "$(awk 'BEGIN { a = 2.6e-6; printf "%.17g", 1e6 * (a * a / 10e-6 - 0.1e-6) / sqrt(3.14159265358979324 * a) }')" 1e-6 &&
        ok || bad "eq --d K_I of the state ($arith): $out"
    near "$(key "$out" G)" "$(awk 'BEGIN { a = 2.6e-6; k = 1e6 * (a * a / 10e-6 - 0.1e-6) / sqrt(3.14159265358979324 * a); printf "%.17g", k * k / 2e6 }')" 1e-5 &&
        ok || bad "eq --d G of the state ($arith): $out"
    # sigma(r) of the state: (E*/pi)((g(a) - d)/sqrt(a^2 - r^2) - (2/R) sqrt(a^2 - r^2)) (4.27, 4.41)
    out=$($MDR stress $P --a 2e-6 --d 0.1e-6 --r 1e-6 --arith $arith) || bad "stress --d exit ($arith)"
    near "$(key "$out" sigma)" "$(awk 'BEGIN { a = 2e-6; r = 1e-6; s = sqrt(a * a - r * r); printf "%.17g", 1e6 / 3.14159265358979324 * ((a * a / 10e-6 - 0.1e-6) / s - 2 / 10e-6 * s) }')" 1e-6 &&
        ok || bad "stress --d ($arith): $out"
    # the most tensile force of the quasi-static path: -1.5 pi w R under
    # grips (the fold force is -5/6 pi w R), at the fixed-load critical depth
    out=$($MDR critical $P --control grips --arith $arith) || bad "critical grips exit"
    near "$(key "$out" max_tensile_F)" -2.35619449019e-6 1e-6 && ok || bad "critical grips max_tensile_F ($arith): $out"
    near "$(key "$out" max_tensile_d)" -0.226148482694e-6 1e-6 && ok || bad "critical grips max_tensile_d ($arith): $out"
    near "$(key "$out" F)" -1.308996939e-6 1e-6 && ok || bad "critical grips F stays the fold's ($arith): $out"
    out=$($MDR critical $P --control load --arith $arith) || bad "critical load exit"
    near "$(key "$out" max_tensile_F)" -2.35619449019e-6 1e-6 && ok || bad "critical load max_tensile_F = F ($arith)"
done
out=$($MDR critical $P --control machine --k-machine 1 --arith f64) || bad "critical machine exit"
near "$(key "$out" max_tensile_F)" -2.35619449019e-6 1e-9 && ok || bad "critical machine max_tensile_F: $out"

csv=$($MDR curve $P --a-max 1e-5 --n 50) || bad "curve exit"
[ "$(printf '%s\n' "$csv" | head -1)" = "a,d,F" ] && ok || bad "curve header"
[ "$(printf '%s\n' "$csv" | wc -l)" -eq 51 ] && ok || bad "curve rows"
[ "$(printf '%s\n' "$csv" | tail -1 | awk -F, '{print NF}')" -eq 3 ] && ok || bad "curve columns"

out=$($MDR stress $P --a 2e-6 --r 1e-6) || bad "stress exit"
[ -n "$(key "$out" sigma)" ] && ok || bad "stress: sigma missing"
out=$($MDR stress $P --control load --r 0.5 --arith f64) || bad "stress at critical exit"
[ -n "$(key "$out" sigma)" ] && ok || bad "stress at critical: sigma missing"

for p in "cone --theta 0.5" "powerlaw --C 2 --n 3" "flatpunch --a0 1e-6" "sphere --R 1e-5" \
         "flattip --R 1e-5 --b 1e-6" "wavy --R 1e-5 --h 1e-8 --lambda 5e-7"; do
    $MDR critical --profile $p --E 1e6 --w 0.05 --control load >/dev/null && ok || bad "critical $p"
done

# cycle: CSV step,z,d,F,a,event on stdout, JSON summary on stderr
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
for arith in f32 f64 q31; do
    $MDR cycle $P --control grips --path 0,0.5e-6,-0.6e-6 --steps-per-segment 2000 --springs 256 \
        --arith $arith >"$TMP/c.csv" 2>"$TMP/c.json" || bad "cycle grips exit ($arith)"
    [ "$(head -1 "$TMP/c.csv")" = "step,z,d,F,a,event" ] && ok || bad "cycle header"
    [ "$(wc -l <"$TMP/c.csv")" -eq 4002 ] && ok || bad "cycle rows: 2 segments x 2000 + 1 + header"
    [ "$(tail -1 "$TMP/c.csv" | awk -F, '{print NF}')" -eq 6 ] && ok || bad "cycle columns"
    j=$(cat "$TMP/c.json")
    for k in pull_off_F pull_off_d events dissipated max_tensile_F max_tensile_d; do
        [ -n "$(key "$j" $k)" ] && ok || bad "cycle: key $k missing in $j"
    done
    near "$(key "$j" pull_off_F)" -1.308996939e-6 1e-5 && ok || bad "cycle grips pull-off F ($arith): $j"
    near "$(key "$j" pull_off_d)" -0.470407800461e-6 1e-5 && ok || bad "cycle grips pull-off d ($arith)"
    [ "$(key "$j" arith)" = "\"$arith\"" ] && ok || bad "cycle arith key ($arith): $j"
    [ "$(key "$j" events)" = 2 ] && ok || bad "cycle: contact + pull-off = 2 events: $j"
    grep -q ',contact$' "$TMP/c.csv" && grep -q ',pull-off$' "$TMP/c.csv" && ok || bad "cycle event column"
    # the most tensile force along the path: loaded like Hertz (w_adv = 0)
    # to d = 0.5 um the edge is pinned at a = sqrt(R d) = 2.236 um (below the
    # fixed-load critical radius) and recedes at d = a^2/R - dl(a), where F
    # = F_JKR(a) = 4E* a^3/(3R) - sqrt(8 pi a^3 E* w); smaller radii are less
    # tensile. The path is sampled: the steps straddle that point, and one
    # step of d (5.5e-10 m) moves the pinned F by 2E* a 5.5e-10 = 1.1e-3 of F
    near "$(key "$j" max_tensile_F)" "$(awk 'BEGIN { a = sqrt(5e-12); printf "%.17g", 4e6 * a^3 / 30e-6 - sqrt(8 * 3.14159265358979324 * a^3 * 1e6 * 0.05) }')" 1.1e-3 &&
        ok || bad "cycle grips max_tensile_F ($arith): $j"
    near "$(key "$j" max_tensile_d)" "$(awk 'BEGIN { a = sqrt(5e-12); printf "%.17g", a * a / 10e-6 - sqrt(2 * 3.14159265358979324 * a * 0.05 / 1e6) }')" 2e-3 &&
        ok || bad "cycle grips max_tensile_d ($arith): $j"
    # reversible loading (w_adv = w) past the fixed-load critical radius: the
    # fixed-load fold -1.5 pi w R is passed under grips (the fold force is
    # -5/6 pi w R)
    j=$($MDR cycle $P --control grips --path 0,0.5e-6,-0.6e-6 --steps-per-segment 2000 --springs 256 \
        --w-adv 0.05 --arith $arith 2>&1 >/dev/null) || bad "cycle grips w_adv exit ($arith)"
    near "$(key "$j" max_tensile_F)" -2.35619449019e-6 1e-5 && ok || bad "cycle grips max_tensile_F = -1.5 pi w R ($arith): $j"
    near "$(key "$j" max_tensile_d)" -0.226148482694e-6 2e-3 && ok || bad "cycle grips max_tensile_d ($arith): $j"
    near "$(key "$j" pull_off_F)" -1.308996939e-6 1e-5 && ok || bad "cycle grips w_adv pull-off ($arith): $j"
done
for arith in f32 f64 q31; do
    j=$($MDR cycle $P --control grips --path 0,0.5e-6,0.4e-6 --steps-per-segment 100 --springs 256 \
        --arith $arith 2>&1 >/dev/null) || bad "cycle without tension exit ($arith)"
    [ "$(key "$j" max_tensile_F)" = null ] && [ "$(key "$j" max_tensile_d)" = null ] && ok ||
        bad "cycle with nothing tensile: max_tensile null ($arith): $j"
done
j=$($MDR cycle $P --control load --path 0,3e-6,-3e-6 --steps-per-segment 1000 --w-adv 0.05 \
    --springs 128 --arith f64 2>&1 >/dev/null) || bad "cycle load exit"
near "$(key "$j" pull_off_F)" -2.35619449019e-6 1e-9 && ok || bad "cycle load pull-off: $j"
# the q31 engine under load: pull-off to 1e-6 of JKR (the paraboloid table is exact)
j=$($MDR cycle $P --control load --path 0,3e-6,-3e-6 --steps-per-segment 1000 --w-adv 0.05 \
    --springs 128 --arith q31 2>&1 >/dev/null) || bad "cycle load q31 exit"
near "$(key "$j" pull_off_F)" -2.35619449019e-6 1e-6 && ok || bad "cycle load pull-off q31: $j"
# a q31 const table compiles; N must be a power of two for q31
$MDR table --profile sphere --R 1e-6 --springs 64 --a-max 5e-7 --arith q31 --name tq >"$TMP/tq.c" &&
    ${CC:-cc} -std=c99 -Wall -Werror -Ilib/include -c "$TMP/tq.c" -o "$TMP/tq.o" && ok ||
    bad "mdr table --arith q31 compiles"
grep -q 'const mdr_table_q31 tq = ' "$TMP/tq.c" && ok || bad "q31 table header"
$MDR table --profile sphere --R 1e-6 --springs 100 --a-max 5e-7 --arith q31 >/dev/null 2>&1
[ $? -ne 0 ] && ok || bad "q31 table with N = 100 fails"
j=$($MDR cycle $P --control machine --k-machine 1 --path 0,5e-6,-15e-6 --steps-per-segment 2000 \
    --arith f64 2>&1 >/dev/null) || bad "cycle machine exit"
[ "$(key "$j" pull_off_F)" != null ] && ok || bad "cycle machine pulls off: $j"
# a tabulated tip: a paraboloid sampled in a CSV file is reproduced exactly
awk 'BEGIN { print "r,f"; for (i = 0; i <= 60; i++) { r = 12e-6 * i / 60; printf "%.17g,%.17g\n", r, r * r / 20e-6 } }' >"$TMP/tip.csv"
j=$($MDR cycle --profile table --file "$TMP/tip.csv" --E 1e6 --w 0.05 --control load \
    --path 0,3e-6,-3e-6 --steps-per-segment 1000 --springs 512 --arith f64 2>&1 >/dev/null) ||
    bad "cycle table exit"
near "$(key "$j" pull_off_F)" -2.35619449019e-6 1e-9 && ok || bad "tabulated paraboloid pull-off: $j"
# every command takes a tabulated tip (issue 16): the sampled paraboloid
# against JKR, in f64 to 1e-9; in f32 with a 1 m height offset to 1e-6 (the
# slopes are formed in double before the conversion)
awk 'BEGIN { print "r,f"; for (i = 0; i <= 60; i++) { r = 12e-6 * i / 60; printf "%.17g,%.17g\n", r, 1 + r * r / 20e-6 } }' >"$TMP/tip1m.csv"
T="--profile table --file $TMP/tip.csv --E 1e6 --w 0.05"
for arith in f32 f64; do
    tol=$([ $arith = f64 ] && echo 1e-9 || echo 1e-6)
    for f in "$TMP/tip.csv" "$TMP/tip1m.csv"; do
        out=$($MDR critical --profile table --file "$f" --E 1e6 --w 0.05 --control load --arith $arith) ||
            bad "critical table exit ($arith, $f)"
        near "$(key "$out" F)" -2.35619449019e-6 $tol && ok || bad "critical table load F ($arith, $f): $out"
        near "$(key "$out" a)" 2.60469853934e-6 $tol && ok || bad "critical table load a ($arith, $f): $out"
        out=$($MDR critical --profile table --file "$f" --E 1e6 --w 0.05 --control grips --arith $arith) ||
            bad "critical table grips exit"
        near "$(key "$out" F)" -1.308996939e-6 $tol && ok || bad "critical table grips F ($arith, $f): $out"
        near "$(key "$out" d)" -0.470407800461e-6 $tol && ok || bad "critical table grips d ($arith, $f): $out"
    done
    out=$($MDR critical $T --control machine --k-machine 1 --arith $arith) || bad "critical table machine exit"
    want=$($MDR critical $P --control machine --k-machine 1 --a-start 8e-6 --arith f64)
    near "$(key "$out" F)" "$(key "$want" F)" $tol && ok || bad "critical table machine ($arith): $out vs $want"
    out=$($MDR eq $T --a 2.6e-6 --arith $arith) || bad "eq table exit"
    near "$(key "$out" K_I)" 316.227766 $tol && ok || bad "eq table K_I ($arith): $out"
    near "$(key "$out" F)" "$(awk 'BEGIN { a = 2.6e-6; printf "%.17g", 4e6 * a^3 / 30e-6 - sqrt(8 * 3.14159265358979324 * a^3 * 1e6 * 0.05) }')" \
        $tol && ok || bad "eq table F ($arith): $out"
    out=$($MDR stress $T --a 2e-6 --r 1e-6 --arith $arith) || bad "stress table exit"
    want=$($MDR stress $P --a 2e-6 --r 1e-6 --arith f64)
    near "$(key "$out" sigma)" "$(key "$want" sigma)" 1e-6 && ok || bad "stress table ($arith): $out vs $want"
    csv=$($MDR curve $T --a-max 1.2e-5 --n 12 --arith $arith) || bad "curve table exit"
    [ "$(printf '%s\n' "$csv" | wc -l)" -eq 13 ] && ok || bad "curve table rows"
done
# a worn tip: flat for r < b (b at a node, above 0.7475 a*): Kendall's
# separation at a = b under load and grips, to 1e-9 (f64)
awk 'BEGIN { print "r,f"; b = 2.4e-6; for (i = 0; i <= 100; i++) { r = 12e-6 * i / 100; printf "%.17g,%.17g\n", r, (r < b ? 0 : (r * r - b * b) / 20e-6) } }' >"$TMP/worn.csv"
for ctl in load grips; do
    out=$($MDR critical --profile table --file "$TMP/worn.csv" --E 1e6 --w 0.05 --control $ctl --arith f64) ||
        bad "critical worn tip exit ($ctl)"
    near "$(key "$out" F)" "$(awk 'BEGIN { b = 2.4e-6; printf "%.17g", -sqrt(8 * 3.14159265358979324 * b^3 * 1e6 * 0.05) }')" 1e-9 &&
        ok || bad "worn tip: Kendall F at a = b ($ctl): $out"
    near "$(key "$out" d)" "$(awk 'BEGIN { b = 2.4e-6; printf "%.17g", -sqrt(2 * 3.14159265358979324 * b * 0.05 / 1e6) }')" 1e-9 &&
        ok || bad "worn tip: Kendall d at a = b ($ctl): $out"
done
# a sampled worn tip too steep at its rim for a q31 table of 8 192 springs:
# the remedy named is fewer springs alone (its extent is the last sample;
# helper-64, stop 70: "or a higher --a-max", which is refused)
awk 'BEGIN { print "r,f"; b = 1.5e-6; for (i = 0; i <= 800; i++) { r = 1e-8 * i; printf "%.17g,%.17g\n", r, (r < b ? 0 : (r * r - b * b) / 20e-6) } }' >"$TMP/worn8.csv"
refuse '^mdr: q31 table: the profile is too steep inside the table \(spring slope [0-9.]+ >= 8 of Q3.28, in max\|g\| per spring, at x = 1.5e-06 m: a rim or kink\); fewer --springs \(8192\)$' \
    cycle --profile table --file "$TMP/worn8.csv" --E 1e6 --w 0.05 --control grips --path 0,3e-7,-2e-6 --steps-per-segment 10 --springs 8192 --arith q31
$MDR table --profile table --file "$TMP/tip.csv" --springs 16 --name my_tip >"$TMP/t.c" || bad "table exit"
grep -q '^const mdr_table_f32 my_tip = {my_tip_nodes, ' "$TMP/t.c" && ok || bad "table C output"
[ "$(grep -c '^    {' "$TMP/t.c")" -eq 19 ] && ok || bad "table: 17 nodes and 2 of block bounds for 16 springs"
# outside the table: exit 1 with a message
$MDR cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --a-max 2e-6 >/dev/null 2>&1
[ $? -eq 1 ] && ok || bad "cycle beyond the table exits 1"
# --k-machine under grips or load is taken (docs/engine.md: the CSV's z =
# d + F/k_m, without it z = d), not ignored: kept, and said in mdr cycle
# --help (an attack after stop 59 took it for ignored)
$MDR cycle --help | tr '\n' ' ' | grep -q 'under grips or load it sets the CSV.s z = *d + F/K' && ok ||
    bad "mdr cycle --help: what --k-machine does under grips or load"
for ctl in grips load; do
    $MDR cycle $P --control $ctl --path 0,0.5e-6,-0.6e-6 --steps-per-segment 4 --k-machine 10 --arith f64 2>/dev/null |
        awk -F, 'NR > 1 { z = $3 + $4 / 10; d = z - $2; if (d < 0) d = -d; if (d > 1e-15 * (z < 0 ? -z : z) + 1e-30) bad = 1; n++ }
                 END { exit bad || n != 9 }' && ok || bad "cycle --control $ctl --k-machine: z = d + F/k_m"
done
# ... with one line on stderr, the step's (the JSON summary followed it: two
# lines; an attack after stop 59)
$MDR cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --a-max 2e-6 >/dev/null 2>"$TMP/err"
[ $? -eq 1 ] && [ "$(wc -l <"$TMP/err")" -eq 1 ] && grep -q '^mdr: step [0-9]* (value .*): .*raise --a-max$' "$TMP/err" &&
    ok || bad "a failed cycle: one line on stderr ($(head -c 300 "$TMP/err"))"
# bad arguments: exit 2, one line on stderr
expect2() {
    local err
    err=$("$MDR" "$@" 2>&1 >/dev/null)
    local rc=$?
    [ $rc -eq 2 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && [ -n "$err" ] && ok ||
        bad "expected exit 2 and one line for: $* (rc $rc, '$err')"
}
expect2 frobnicate $P
expect2 eq $P
expect2 eq --profile paraboloid --E 1e6 --w 0.05 --a 1
expect2 eq --profile teapot --R 1 --E 1 --w 1 --a 1
expect2 eq $P --a abc
expect2 eq $P --a 1e-6 --bogus 3
expect2 eq --profile paraboloid --R -1 --E 1e6 --w 0.05 --a 1e-6
expect2 eq --profile sphere --R 1e-6 --E 1e6 --w 0.05 --a 2e-6
expect2 eq $P --a nan
expect2 eq $P --a 1e-6 --arith f16
expect2 critical $P
expect2 critical $P --control sideways
expect2 critical $P --control machine
expect2 critical $P --control machine --k-machine -1
expect2 curve $P --a-max 1e-5
expect2 curve $P --a-max 1e-5 --n 0
expect2 stress $P --a 1e-6 --r 2e-6
expect2 stress --profile cone --theta 0.5 --E 1 --w 1 --a 1 --r 0
expect2 cycle $P --control grips --path 0,1e-6
expect2 eq $P --a 1e-6 --arith q31
expect2 eq $P --a 1e-6 --arith q15
expect2 cycle $P --control grips --steps-per-segment 10
expect2 cycle $P --path 0,1e-6 --steps-per-segment 10
expect2 cycle $P --control grips --path 0,x --steps-per-segment 10
expect2 cycle $P --control grips --path 1e-6 --steps-per-segment 10
expect2 cycle $P --control grips --path 0,1e-6 --steps-per-segment 0
expect2 cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --springs 1
expect2 cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --springs 100000
expect2 cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --w-adv 0.1
expect2 cycle $P --control machine --path 0,1e-6 --steps-per-segment 10
expect2 cycle $P --control machine --k-machine 0 --path 0,1e-6 --steps-per-segment 10
expect2 cycle --profile table --E 1e6 --w 0.05 --control grips --path 0,1e-6 --steps-per-segment 10
expect2 cycle --profile table --file /nonexistent --E 1e6 --w 0.05 --control grips --path 0,1 --steps-per-segment 1
printf 'r,f\n0,0\n2e-6,1e-9\n1e-6,2e-9\n' >"$TMP/bad.csv"
expect2 cycle --profile table --file "$TMP/bad.csv" --E 1e6 --w 0.05 --control grips --path 0,1e-9 --steps-per-segment 1
# the tip file parser (examples/tip_csv.h): malformed lines, a NUL byte and
# an over-long line are refused; comments, blank lines and CRLF are accepted
for body in 'r,f\n0,0\n1e-6,x\n' 'r,f\n0,0\n1e-6\n' 'r,f\nr,f\n0,0\n1e-6,1e-9\n' '0,0\n1e-6,1e-9\n2e-6,4e-9,7\n' \
    '0,0\n1e-6,1e-9\0\n2e-6,4e-9\n'; do
    printf "$body" >"$TMP/bad.csv"
    expect2 table --profile table --file "$TMP/bad.csv" --springs 16
done
{ printf '0,0\n'; printf '%0300d\n' 1; } >"$TMP/bad.csv"
expect2 table --profile table --file "$TMP/bad.csv" --springs 16
printf '# tip\r\nr,f\r\n\r\n0, 0\r\n# mid\r\n1e-6 ,5e-14\r\n2e-6,2e-13\r\n3e-6,4.5e-13' >"$TMP/ok.csv"
$MDR table --profile table --file "$TMP/ok.csv" --springs 8 --name crlf >"$TMP/crlf.c" &&
    [ "$(grep -c '^    {' "$TMP/crlf.c")" -eq 11 ] && ok || bad "tip file with comments, CRLF, no final newline"
expect2 table $P
expect2 table --profile paraboloid --R 1e-5 --a-max 1e-6 --name 9lives
expect2 eq --profile table --file "$TMP/tip.csv" --E 1 --w 1 --a 1
expect2 eq --profile table --E 1 --w 1 --a 1e-6
expect2 stress $P --control load --d 1e-7 --r 0.5
expect2 curve $P --a-max 1e-5 --n 5 --d 1e-7
expect2 critical $P --control load --d 1e-7
expect2 eq $P --a 2e-6 --d nan
printf 'r,f\n0,0\n1e-6,1e-9\n1e-6,2e-9\n' >"$TMP/bad.csv"
expect2 critical --profile table --file "$TMP/bad.csv" --E 1e6 --w 0.05 --control load
# a table that ends on the unstable branch: the pull-off lies beyond it
awk 'BEGIN { print "r,f"; for (i = 0; i <= 20; i++) { r = 1e-6 * i / 20; printf "%.17g,%.17g\n", r, r * r / 20e-6 } }' >"$TMP/short.csv"
expect2 critical --profile table --file "$TMP/short.csv" --E 1e6 --w 0.05 --control load

# ---- the CLI contract of issue 19 ------------------------------------------
# every quantity of the object (a number that is not a count) and of its
# input has a unit
COUNTS='{"events", "cycles", "jumps", "springs", "steps_per_segment", "n", "points", "status_code", "iterations", "n_approach", "n_pinned"}'
has_units() {
    jcheck "$1" "all(k in j['units'] for o in (j, j['input']) for k, v in o.items() if isinstance(v, float) or (isinstance(v, int) and not isinstance(v, bool) and k not in $COUNTS))"
}

# help and version: stdout, exit 0
for args in "--help" "help" "-h" "eq --help" "critical --help" "curve -h" "stress --help" "cycle --help" \
    "table --help" "fit --help" "help cycle" "help fit" "eq $P --a 1e-6 --help"; do
    out=$($MDR $args 2>"$TMP/err")
    [ $? -eq 0 ] && [ "${out#usage: mdr}" != "$out" ] && [ ! -s "$TMP/err" ] && ok || bad "mdr $args: usage on stdout, exit 0"
done
[ "$($MDR cycle --help | head -1)" != "$($MDR eq --help | head -1)" ] && ok || bad "each command has its own help"
out=$($MDR --version 2>"$TMP/err")
[ $? -eq 0 ] && printf '%s' "$out" | grep -Eq '^mdr \(libmdr [0-9]+\.[0-9]+\)$' && [ ! -s "$TMP/err" ] && ok || bad "mdr --version: $out"
# bare mdr: one line naming the problem, exit 2, as every refusal (since
# stop 56; it printed the 23 lines of the usage on stderr: helper-24)
refuse '^mdr: no command \(mdr --help lists them\)$'
# help on help: the commands; extra words after --version and --help refused
for h in "help help" "help --help" "help -h"; do
    [ "$($MDR $h)" = "$($MDR --help)" ] && ok || bad "mdr $h: the commands"
done
refuse '^mdr: --version takes no arguments: x$' --version x
refuse '^mdr: --help takes no arguments \(mdr help COMMAND\): extra$' --help extra
# a flag without its value, the next flag after it: named as such
refuse '^mdr: flag needs a value: --a \(found the flag --d\)$' eq $P --a --d 0
# a C keyword as the table's name (its .c did not compile)
refuse '^mdr: --name must be a C identifier, not a keyword: int$' table --profile paraboloid --R 1e-5 \
    --a-max 1e-6 --springs 16 --name int
refuse 'help: unknown command: teapot' help teapot
refuse 'unknown command: frobnicate' frobnicate $P

# --flag=value everywhere --flag value is
[ "$($MDR eq --profile=paraboloid --R=10e-6 --E=1e6 --w=0.05 --a=2.6e-6 --arith=f64)" = \
  "$($MDR eq $P --a 2.6e-6 --arith f64)" ] && ok || bad "eq with --flag=value"
[ "$($MDR cycle $P --control=grips --path=0,0.5e-6,-0.6e-6 --steps-per-segment=50 --springs=64 --arith=q31 2>&1)" = \
  "$($MDR cycle $P --control grips --path 0,0.5e-6,-0.6e-6 --steps-per-segment 50 --springs 64 --arith q31 2>&1)" ] &&
    ok || bad "cycle with --flag=value"
refuse 'not a finite number' eq $P --a=
refuse 'flag needs a value: --a$' eq $P --a
refuse 'expected a flag' eq $P 2.6e-6

# duplicate, unknown and misplaced flags: refused by name
refuse 'given twice: --arith' cycle $P --control grips --path 0,1e-7 --steps-per-segment 4 --arith q31 --arith f32
refuse 'given twice: --a$' eq $P --a 1e-6 --a=2e-6
refuse 'given twice: --R' eq $P --a 1e-6 --R 1e-6
refuse 'unknown flag: --bogus' eq $P --a 1e-6 --bogus 3
refuse 'unknown flag: --bogus' eq $P --a 1e-6 --bogus=3
refuse '^mdr: --control: not a flag of mdr eq' eq $P --a 1e-6 --control load
refuse '^mdr: --path: not a flag of mdr critical' critical $P --control load --path 0,1
refuse '^mdr: --w-adv: not a flag of mdr eq' eq $P --a 1e-6 --w-adv 0.01
# a tick that begins separated and ends in contact reports its touch (contact,
# re-contact or jump-in), whatever jumps follow in it: on a wavy profile at
# coarse ticks a second jump in the touch's tick was reported "jump", the
# touch lost from the CSV and the summary (helper-57; w_adv > 0 and 0)
W1="--profile wavy --R 1.1781515138768505e-05 --h 3.2821178646335334e-11 --lambda 9.248639412848431e-09 --E 3380733000.748379
    --w 0.000528330301574831 --w-adv 0.00037622969562134916 --control machine --k-machine 8.522732789818788
    --path 0,2.8139843130499678e-08,-2.989529844412959e-08,2.8139843130499678e-08,-2.989529844412959e-08 --steps-per-segment 18 --springs 16384"
W2="--profile wavy --R 1.7602070512737214e-09 --h 5.047989714172304e-13 --lambda 2.2836224380413973e-11 --E 47372046.34005171
    --w 0.0003642409320265705 --w-adv 0 --control machine --k-machine 0.000522986811835003
    --path 0,2.9865632842801785e-08,-1.2779675377570804e-08,2.9865632842801785e-08,-1.2779675377570804e-08 --steps-per-segment 873"
for W in "$W1" "$W2"; do
    for arith in f64 f32 q31; do
        # shellcheck disable=SC2086
        t=$($MDR cycle $W --arith $arith 2>/dev/null |
            awk -F, 'NR > 1 { if (pa == 0 && $5 > 0) { n++; if ($6 != "contact" && $6 != "re-contact" && $6 != "jump-in") bad++ }
                              pa = $5 } END { print n + 0, bad + 0 }')
        [ "${t% *}" -eq 2 ] && [ "${t#* }" -eq 0 ] && ok || bad "wavy touches with jumps ($arith): touches, wrong events: $t"
    done
done
# w_adv beyond [0, w] named (it was the engine's "parameter out of range": helper-56)
refuse '^mdr: --w-adv 0.1: outside \[0, --w\] = \[0, 0.05\]' cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --w-adv 0.1
refuse '^mdr: --w-adv -0.01: outside \[0, --w\]' cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --w-adv -0.01
refuse '^mdr: --springs: not a flag of mdr eq' eq $P --a 1e-6 --springs 64
refuse '^mdr: --summary: not a flag of mdr eq' eq $P --a 1e-6 --summary "$TMP/s.json"
refuse '^mdr: --name: not a flag of mdr cycle' cycle $P --control grips --path 0,1e-7 --steps-per-segment 4 --name x
refuse '^mdr: --E: not a flag of mdr table' table --profile sphere --R 1e-6 --a-max 5e-7 --E 1e6
refuse '^mdr: --n: not a parameter of --profile paraboloid' eq $P --a 1e-6 --n 3
refuse '^mdr: --R: not a parameter of --profile cone' eq --profile cone --theta 0.5 --R 1 --E 1e6 --w 0.05 --a 1e-6
refuse '^mdr: --k-machine goes with --control machine' critical $P --control load --k-machine 1
refuse '^mdr: --file goes with --profile table' eq $P --a 1e-6 --file "$TMP/tip.csv"
refuse '^mdr: --a-start goes with --control' stress $P --a 1e-6 --r 0 --a-start 1e-6
refuse '^mdr: flag takes no value: --approach$' fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-5 --k-machine 1 --approach=1
refuse '^mdr: unknown flag: --bogus' fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-5 --k-machine 1 --bogus 1
refuse '^mdr: --control: not a flag of mdr fit' fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-5 --k-machine 1 --control load
refuse 'given twice: --k-machine' fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-5 --k-machine 1 --k-machine=2
# the power law's exponent is --n: curve's count is then --points
csv=$($MDR curve --profile powerlaw --C 5e4 --n 2 --E 1e6 --w 0.05 --a-max 1e-5 --points 20 --arith f64) &&
    [ "$(printf '%s\n' "$csv" | wc -l)" -eq 21 ] && ok || bad "curve powerlaw --points"
# C r^2 with C = 1/(2R) is the paraboloid: the same curve
near "$(printf '%s\n' "$csv" | tail -1 | cut -d, -f3)" "$($MDR curve $P --a-max 1e-5 --n 20 --arith f64 | tail -1 | cut -d, -f3)" 1e-12 && ok ||
    bad "powerlaw n = 2, C = 1/(2R) = paraboloid R"
refuse 'count once' curve $P --a-max 1e-5 --n 20 --points 20
# a radius refused part-way: one line, no partial CSV (every row is computed
# before the first is written; helper-24, stop 56: the header and 4 rows, then
# the refusal)
refuse 'MDR_E_RADIUS' curve $P --a-max 0 --n 10
refuse 'MDR_E_RADIUS' curve --profile sphere --R 1e-6 --E 1e6 --w 0.05 --a-max 2e-6 --n 10
refuse 'MDR_E_OVERFLOW' curve --profile cone --theta 0.5 --E 1e6 --w 0.05 --a-max 1e30 --n 3
# a power law's pull-off in the first springs, whose quadratics are not its
# C r^n (n = 1.5: -31 % of mdr critical's force, exit 0, before stop 56;
# helper-23): refused with its cause; on 4096 springs (five spring widths:
# more) taken, within 1 % of mdr critical's force
for arith in f32 f64; do
    refuse 'the pull-off lies in the first two of 64 springs' cycle --profile powerlaw --C 1e3 --n 1.5 --E 1e6 \
        --w 0.05 --control grips --path 0,1e-3,-2e-6 --steps-per-segment 500 --springs 64 --arith $arith
done
j=$($MDR cycle --profile powerlaw --C 1e3 --n 1.5 --E 1e6 --w 0.05 --control grips --path 0,1e-3,-2e-6 \
    --steps-per-segment 500 --springs 4096 --arith f64 2>&1 >/dev/null)
cr=$($MDR critical --profile powerlaw --C 1e3 --n 1.5 --E 1e6 --w 0.05 --control grips --arith f64)
near "$(key "$j" pull_off_F)" "$(key "$cr" F)" 1e-2 && ok || bad "power law n = 1.5 on 4096 springs: $j"
# q31 through a machine: a base position below z_min (where a free body's
# depth no longer fits) refused, with an explicit --a-max as with the default
# extent (before stop 56 the former ran with exit 0, its energy 32 % low and
# its free depths saturated: helper-23)
refuse "^mdr: --path value 3 .*below the q31 machine's least base position z_min" cycle --profile paraboloid \
    --R 20e-9 --E 1e9 --w 0.05 --control machine --k-machine 0.01 --path 0,20e-9,-1e-6 --steps-per-segment 200 \
    --arith q31 --a-max 1.65e-8
refuse "^mdr: --path value 3 .*below the q31 machine's least base position z_min" cycle --profile paraboloid \
    --R 1e-4 --E 1e11 --w 0.005 --control machine --k-machine 20 --path 0,3e-6,-1e-6 --steps-per-segment 200 \
    --arith q31
# a tip file with fewer than 3 points: named with its count (was MDR_E_TABLE's
# "order, count or g(0)": helper-24)
printf 'r,f\n0,0\n1e-7,1e-9\n' > "$TMP/two.csv"
refuse 'two.csv: 2 points; a tip needs at least 3 rows' table --profile table --file "$TMP/two.csv" --a-max 1e-7 \
    --springs 16
printf 'r,f\n' > "$TMP/zero.csv"
refuse 'zero.csv: 0 points; a tip needs at least 3 rows' eq --profile table --file "$TMP/zero.csv" --E 1e6 \
    --w 0.05 --a 5e-8
# a tip whose f falls with r (a gap decreasing with the radius) is refused
# by its line, in every command that reads a tip (it was taken, exit 0; an
# attack after stop 59); f equal to the one before (a flat) is taken
printf 'r,f\n0,0\n1e-7,1e-9\n# dip\n2e-7,0.5e-9\n3e-7,9e-9\n' > "$TMP/dip.csv"
for cmd in "eq --a 1e-7 --E 1e6 --w 0.05" "table --springs 16" "fit --curve $TMP/tip.csv --k-machine 1"; do
    refuse "dip.csv:5: f must not decrease with r \(f = 5[0-9.]*e-10 after 1[0-9.]*e-09\)" $cmd --profile table --file "$TMP/dip.csv"
done
printf 'r,f\n0,0\n1e-7,0\n2e-7,1e-9\n' > "$TMP/flat0.csv"
$MDR table --profile table --file "$TMP/flat0.csv" --springs 16 >/dev/null && ok || bad "a tip with a flat (f equal) is taken"
printf 'r,f\n0,0\n1e-7,1e-310\n2e-7,1e-9\n' > "$TMP/subn.csv"
refuse "subn.csv:3: a subnormal number" table --profile table --file "$TMP/subn.csv" --springs 16
# a nonzero number below double's range is refused, not read as 0: flags
# and lists (helper-24, stop 56: --w 1e-400 ran with w = 0, exit 0)
for arith in f32 f64; do
    refuse "^mdr: --w: a nonzero number below double.s range \\(it underflows to 0\\): 1e-400$" eq --profile paraboloid --R 10e-6 --E 1e6 --w 1e-400 --a 2e-6 --arith $arith
done
refuse "^mdr: --path: value 2 is not a finite number" cycle $P --control grips --path 0,1e-400,0 \
    --steps-per-segment 4 --a-max 2e-6
# a subnormal double is refused where it is given, naming its flag, in
# every arithmetic and command (--E 1e-310 blamed --w; --w, --a 1e-310 ran
# with exit 0 on values that had lost digits; an attack after stop 59)
for arith in f32 f64; do
    refuse "^mdr: --E: a subnormal number .*: 1e-310$" eq --profile paraboloid --R 10e-6 --E 1e-310 --w 0.05 --a 2e-6 --arith $arith
    refuse "^mdr: --E: a subnormal number" cycle --profile paraboloid --R 10e-6 --E 1e-310 --w 0.05 --control grips \
        --path 0,1e-7,-1e-7 --steps-per-segment 4 --arith $arith
    refuse "^mdr: --w: a subnormal number .*: 1e-310$" eq --profile paraboloid --R 10e-6 --E 1e6 --w 1e-310 --a 2e-6 --arith $arith
    refuse "^mdr: --a: a subnormal number .*: -1e-310$" eq $P --a -1e-310 --arith $arith
    refuse "^mdr: --R: a subnormal number" critical --profile paraboloid --R 4e-320 --E 1e6 --w 0.05 --control load --arith $arith
    refuse "^mdr: --path: value 2 \(.*\) is a subnormal number" cycle $P --control grips --path 0,1e-310,0 \
        --steps-per-segment 4 --a-max 2e-6 --arith $arith
    refuse "^mdr: --k-machine: a subnormal number" fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-5 \
        --k-machine 1e-310 --arith $arith
done
# each valid alone, w/E* beyond the arithmetic: both named (it named --w)
refuse "^mdr: --E/--w \(w/E\* beyond this arithmetic" eq --profile paraboloid --R 10e-6 --E 1e-300 --w 1e10 --a 2e-6 --arith f64
refuse "^mdr: --E/--w \(w/E\* beyond this arithmetic" eq --profile paraboloid --R 10e-6 --E 1e-30 --w 1e10 --a 2e-6

# white space around a number is refused naming the flag, leading as
# trailing (--E ' 1e9' ran, --E '1e9 ' was "not a finite number"; an attack
# after stop 59), in --path values and in fit's flags too
for v in ' 1e9' '1e9 ' $'\t1e9' $'1e9\n'; do
    refuse "^mdr: --E: white space around the number \(give the number alone\): " eq --profile paraboloid --R 10e-6 \
        --E "$v" --w 0.05 --a 2e-6
done
refuse "^mdr: --a: white space around the number" eq $P --a=' 2e-6' --arith f64
refuse "^mdr: --path: value 2 is white space around the number" cycle $P --control grips --path '0, 1e-7,0' \
    --steps-per-segment 4 --a-max 2e-6
refuse "^mdr: --path: value 2 is white space around the number" cycle $P --control grips --path '0,1e-7 ,0' \
    --steps-per-segment 4 --a-max 2e-6
refuse "^mdr: --k-machine: white space around the number" fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-5 \
    --k-machine ' 1'
# a value with a line break is echoed with it escaped: the message stays one line
refuse '^mdr: --E: not a finite number: 1e9\\nx$' eq --profile paraboloid --R 10e-6 --a 2e-6 --E $'1e9\nx' --w 0.05
refuse '^mdr: unknown profile: a\\nb$' eq --profile $'a\nb' --E 1e6 --w 0.05 --a 1e-6
# ... and so is a tip file's name in the library's refusal of its table
# (cli_fail printed it raw: two lines)
printf '0,0\n1e-6,1e30\n2e-6,3e37\n' >"$TMP/"$'tip\nx.csv'
refuse '^mdr: .*tip\\nx.csv: result beyond .*\(MDR_E_OVERFLOW, status -10\)$' eq --profile table --file "$TMP/"$'tip\nx.csv' \
    --E 1e6 --w 0.05 --a 1e-6
# a radius outside the domain named by the flag or file it came from (each
# said "critical: contact radius outside the profile's domain"; an attack
# after stop 59): --a-start itself, or a tip tabulated short of the pull-off
for arith in f32 f64; do
    refuse "^mdr: --a-start -1: outside the profile's domain \(MDR_E_RADIUS" critical $P --control load --a-start -1 --arith $arith
    refuse "^mdr: --a-start 2e-06: outside the profile's domain" critical --profile sphere --R 1e-6 --E 1e6 --w 0.05 \
        --control grips --a-start 2e-6 --arith $arith
    refuse "^mdr: --a-start 0: outside the profile's domain" stress $P --control load --a-start 0 --r 0.5 --arith $arith
    awk 'BEGIN { print "r,f"; for (i = 0; i <= 20; i++) { r = 1e-6 * i / 20; printf "%.17g,%.17g\n", r, r * r / 20e-6 } }' >"$TMP/short.csv"
    refuse "short.csv: the tip ends \(its last sample r = 1e-06 m\) before the pull-off.*tabulate the tip further" \
        critical --profile table --file "$TMP/short.csv" --E 1e6 --w 0.05 --control load --arith $arith
done
# every number checked before it is used, in every arithmetic
for arith in f32 f64; do
    for v in nan inf -inf 1e999 0x1p99999; do
        refuse "^mdr: --a: not a finite number: $v" eq $P --a $v --arith $arith
        refuse "^mdr: --E: not a finite number: $v" critical --profile paraboloid --R 10e-6 --E $v --w 0.05 --control load --arith $arith
    done
done
for arith in f32 f64 q31; do
    # f32: a value float cannot hold is refused first (below)
    [ $arith = f32 ] && interp=1e30 || interp=1e308
    for v in nan inf -inf; do
        refuse "^mdr: --path: value 3 is not a finite number" cycle $P --control grips --path 0,1e-7,$v \
            --steps-per-segment 4 --a-max 2e-6 --arith $arith
    done
    # the interpolation a + (b - a) j/S overflows: refused by its segment, before step 0
    if [ $arith != f32 ]; then
        refuse '^mdr: --path segment 1 \(0 to -1e\+308\): the interpolation overflows' cycle $P --control grips \
            --path 0,-1e308 --steps-per-segment 4 --arith $arith
        refuse '^mdr: --path segment 2 .*the interpolation overflows' cycle $P --control load \
            --path 0,1e-7,1.7e308 --steps-per-segment 2 --arith $arith
    else
        refuse '^mdr: --path value 2 \(-1e\+308\): outside the range of --arith f32' cycle $P --control grips \
            --path 0,-1e308 --steps-per-segment 4 --arith $arith
    fi
done
refuse '^mdr: --path segment 1 .*overflows' cycle $P --control grips --path -1e303,1e303 --steps-per-segment 1e6 --arith f64
# in f32 a value float cannot hold is refused where it is given, not at step 0
# (1e-300: a double below float; 1e-308, subnormal in double, is refused as such above)
refuse '^mdr: --k-machine 1e-300: outside the range of --arith f32' critical $P --control machine --k-machine 1e-300
refuse '^mdr: --k-machine .*outside the range of --arith f32' cycle $P --control machine --k-machine 1e-300 --path 0,1e-7 --steps-per-segment 4
refuse '^mdr: --E 1e\+39: outside the range of --arith f32' eq --profile paraboloid --R 10e-6 --E 1e39 --w 0.05 --a 1e-6
refuse '^mdr: --path value 2 .*outside the range of --arith f32' cycle $P --control load --path 0,1e39 --steps-per-segment 4
refuse '^mdr: --R 1e-40: outside the range of --arith f32' fit --curve "$TMP/tip.csv" --profile paraboloid --R 1e-40 --k-machine 1 --arith f32
out=$($MDR critical $P --control machine --k-machine 1e-300 --arith f64 2>&1)
[ $? -ne 2 ] || printf '%s' "$out" | grep -vq 'outside the range' && ok || bad "1e-300 is a double: not refused for range in f64: $out"
# q31: a path value beyond the input range (+-2 units) is refused, by value and range
refuse '^mdr: --path value 2 \(0.001 m\): outside the q31 input range \+-2 D0 = \+-[0-9.e-]+ m' cycle $P \
    --control grips --path 0,1e-3 --a-max 2e-6 --steps-per-segment 4 --arith q31
refuse '^mdr: --path value 3 \(-1 N\): outside the q31 input range \+-2 F0' cycle $P \
    --control load --path 0,1e-7,-1 --a-max 2e-6 --steps-per-segment 4 --arith q31
# within the range: a vertex at -1.9 D0 (2 D0 from the message above; the
# body apart, no contact) runs, at -2.1 D0 it is refused
D2=$($MDR cycle $P --control grips --path 0,1e-3 --a-max 2e-6 --steps-per-segment 4 --arith q31 2>&1 | sed -n 's/.*= +-\([0-9.e+-]*\) m$/\1/p')
$MDR cycle $P --control grips --path 0,$(awk -v d="$D2" 'BEGIN { printf "%.9g", -0.95 * d }') --a-max 2e-6 \
    --steps-per-segment 4 --arith q31 >/dev/null 2>&1 && ok || bad "q31 path within +-2 D0 (2 D0 = $D2) runs"
refuse 'outside the q31 input range' cycle $P --control grips --path 0,$(awk -v d="$D2" 'BEGIN { printf "%.9g", -1.05 * d }') \
    --a-max 2e-6 --steps-per-segment 4 --arith q31
# the range check converts as the step does (in double, over the double
# unit): the flat punch a0 = 2 um has F0 = 2E* a0 D0 = 3.814697265625e-6 N;
# 2 F0 itself runs, a value just above it is refused before step 0 (not
# stepped until the step's own conversion fails)
FP="--profile flatpunch --a0 2e-6 --E 1e6 --w 0.05 --control load --steps-per-segment 10 --arith q31"
$MDR cycle $FP --path 0,7.62939453125e-06,-7.62939453125e-06 >/dev/null 2>&1 && ok || bad "q31 path at exactly 2 F0 runs"
refuse '^mdr: --path value 2 \(7.62939454e-06 N\): outside the q31 input range \+-2 F0 = \+-7.62939453e-06 N$' \
    cycle $FP --path 0,7.62939454e-06,-7.62939454e-06
refuse '^mdr: --path value 3 \(-7.62939454e-06 N\): outside the q31 input range' cycle $FP --path 0,1e-6,-7.62939454e-06
# a segment's last tick is its vertex exactly: a + (b - a) 13/13 rounded
# this b (raw 2^30, just in range) one ulp up, to raw 2^30 + 1, which was
# refused until stop 57 (mdr_host_path_value; a path 0, 1e20, -1e-3 ended at
# 0, in contact, no pull-off: helper-30); now it runs and ends on b
$MDR cycle ${FP/--steps-per-segment 10/--steps-per-segment 13} --path -3.898088070211341e-06,7.629394534802712e-06 \
    2>/dev/null | tail -1 | grep -q '^13,[^,]*,[^,]*,7.62939453125e-06,' && ok || bad "q31 segment ending on its vertex (2 F0)"
$MDR cycle --profile paraboloid --R 10e-6 --E 1e6 --w 0.05 --control grips --path 0,1e20,-1e-3 --steps-per-segment 10 \
    --arith f64 2>/dev/null | tail -1 | grep -q '^20,-0.001,-0.001,0,0,pull-off$' && ok || bad "path 0,1e20,-1e-3 ends on -1e-3"

# tip files: bounded reads, errors with file:line, comma/tab/space separated
start=$(date +%s)
refuse '^mdr: /dev/zero:1: a NUL byte' eq --profile table --file /dev/zero --E 1e6 --w 0.05 --a 1e-6
[ $(($(date +%s) - start)) -le 2 ] && ok || bad "/dev/zero refused quickly"
yes '1e-6,1e-9' | head -c 17000000 >"$TMP/big.csv"
refuse 'big.csv: larger than 16776960 bytes' table --profile table --file "$TMP/big.csv" --springs 16
awk 'BEGIN { print "r,f"; for (i = 0; i <= 65535; i++) printf "%d,0\n", i }' >"$TMP/many.csv"
refuse 'many.csv:65537: more than 65535 points' table --profile table --file "$TMP/many.csv" --springs 16
refuse '/nonexistent.csv' table --profile table --file /nonexistent.csv --springs 16
printf 'r,f\n0,0\n1e-6,x\n' >"$TMP/bad.csv"
refuse 'bad.csv:3: expected two numbers r f' table --profile table --file "$TMP/bad.csv" --springs 16
printf '# a tip\n\nr\tf\n0\t0\n1e-6\t1e-9\n1e-6\t2e-9\n' >"$TMP/bad.csv"
refuse 'bad.csv:6: r must increase strictly' table --profile table --file "$TMP/bad.csv" --springs 16
# a first radius other than 0 is named with its line and the rule (helper-66,
# stop 71: 'tabulated profile unusable (order, count or g(0))' before)
printf '# shifted\nr,f\n1e-9,0\n2e-9,1e-10\n3e-9,3e-10\n' >"$TMP/bad.csv"
refuse '^mdr: .*bad.csv:3: the first radius must be 0 \(r = 1.0000000000000001e-09\): a tip.s samples start on its axis$' \
    eq --profile table --file "$TMP/bad.csv" --E 1e9 --w 0.05 --a 2e-9
{ printf '0,0\n'; printf '%0300d\n' 1; } >"$TMP/bad.csv"
refuse 'bad.csv:2: line longer than 255 characters' table --profile table --file "$TMP/bad.csv" --springs 16
printf 'r,f\n0,0\n1e-6,1e-9\0\n2e-6,4e-9\n' >"$TMP/bad.csv"
refuse 'bad.csv:3: a NUL byte' table --profile table --file "$TMP/bad.csv" --springs 16
printf 'r,f\n0,0\n1e-6,1e-9\n2e-6,4e-9,7\n' >"$TMP/bad.csv"
refuse 'bad.csv:4: expected two numbers' table --profile table --file "$TMP/bad.csv" --springs 16
printf 'r,f\n0,0\n1e-6,1e-9\n2e-6,inf\n' >"$TMP/bad.csv"
refuse 'bad.csv:4: not a finite number' table --profile table --file "$TMP/bad.csv" --springs 16
# the same sampled paraboloid with tabs and with spaces gives the comma file's table
tr ',' '\t' <"$TMP/tip.csv" >"$TMP/tab.csv"
tr ',' ' ' <"$TMP/tip.csv" | sed 's/ /   /' >"$TMP/space.csv"
want=$($MDR table --profile table --file "$TMP/tip.csv" --springs 32 --arith f64)
for f in tab space; do
    [ "$($MDR table --profile table --file "$TMP/$f.csv" --springs 32 --arith f64)" = "$want" ] && ok ||
        bad "a $f-separated tip file reads as the comma one"
done

# --summary FILE: the JSON in the file, stderr empty, the CSV unchanged
CY="cycle $P --control grips --path 0,0.5e-6,-0.6e-6 --steps-per-segment 200 --springs 256"
for arith in f32 f64 q31; do
    $MDR $CY --arith $arith >"$TMP/a.csv" 2>"$TMP/a.json" || bad "cycle exit ($arith)"
    $MDR $CY --arith $arith --summary "$TMP/s.json" >"$TMP/b.csv" 2>"$TMP/b.err" || bad "cycle --summary exit ($arith)"
    cmp -s "$TMP/a.csv" "$TMP/b.csv" && [ ! -s "$TMP/b.err" ] && ok || bad "cycle --summary: same CSV, nothing on stderr ($arith)"
    j=$(cat "$TMP/s.json")
    [ "$(key "$j" pull_off_F)" = "$(key "$(cat "$TMP/a.json")" pull_off_F)" ] && [ -n "$(key "$j" pull_off_F)" ] && ok ||
        bad "cycle --summary: the summary ($arith): $j"
done
# a run that fails: the error alone on stderr, the summary (up to the failure) in the file
$MDR cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --a-max 2e-6 --summary "$TMP/s.json" \
    >/dev/null 2>"$TMP/err"
[ $? -eq 1 ] && [ "$(wc -l <"$TMP/err")" -eq 1 ] && grep -q '^mdr: step [0-9]* (value .*): .*raise --a-max' "$TMP/err" &&
    [ "$(key "$(cat "$TMP/s.json")" events)" = 1 ] && ok || bad "cycle --summary on a failure: $(cat "$TMP/err")"
refuse 'cannot write --summary: /nonexistent/s.json' $CY --summary /nonexistent/s.json
# a summary file that opens but takes no byte: refused before the CSV goes
# to stdout (not exit 2 after the whole CSV)
if [ -w /dev/full ]; then
    refuse '^mdr: cannot write --summary: /dev/full \(No space left on device\)$' $CY --summary /dev/full
fi

# units and inputs in every JSON object; G_rel (the energy release rate)
for arith in f32 f64; do
    j=$($MDR eq $P --a 2.6e-6 --arith $arith)
    has_units "$j"
    jcheck "$j" "j['units']['F'] == 'N' and j['units']['d'] == 'm' and j['units']['K_I'] == 'Pa m^0.5' and j['units']['G_rel'] == 'J/m^2'"
    jcheck "$j" "j['input'] == {'command': 'eq', 'profile': 'paraboloid', 'R': 1e-5, 'E': 1e6, 'w': 0.05, 'arith': '$arith', 'a': 2.6e-6}"
    jcheck "$j" "j['G'] == j['G_rel'] and abs(j['G_rel'] - 0.05) <= 1e-6 * 0.05"
    j=$($MDR eq $P --a 2.6e-6 --d 0.1e-6 --arith $arith)
    has_units "$j"
    jcheck "$j" "j['input']['d'] == 1e-7 and j['G'] == j['G_rel']"
    j=$($MDR critical $P --control machine --k-machine 1 --arith $arith)
    has_units "$j"
    jcheck "$j" "j['input']['control'] == 'machine' and j['input']['k_m'] == 1 and j['units']['k_m'] == 'N/m'"
    j=$($MDR critical --profile wavy --R 1e-5 --h 1e-8 --lambda 5e-7 --E 1e6 --w 0.05 --control load --arith $arith)
    has_units "$j"
    jcheck "$j" "j['input']['profile'] == 'wavy' and j['input']['lambda'] == 5e-7 and j['input']['h'] == 1e-8 and 'k_m' not in j['input']"
    j=$($MDR stress $P --control load --r 0.5 --arith $arith)
    has_units "$j"
    jcheck "$j" "j['input']['r_over_a_c'] == 0.5 and j['units']['sigma'] == 'Pa'"
    j=$($MDR stress $P --a 2e-6 --r 1e-6 --arith $arith)
    has_units "$j"
    j=$($MDR eq --profile table --file "$TMP/tip.csv" --E 1e6 --w 0.05 --a 2.6e-6 --arith $arith)
    has_units "$j"
    jcheck "$j" "j['input']['profile'] == 'table' and j['input']['file'].endswith('tip.csv') and j['input']['points'] == 61"
done
for arith in f32 f64 q31; do
    j=$($MDR cycle $P --control load --path 0,3e-6,-3e-6 --steps-per-segment 100 --springs 128 --arith $arith 2>&1 >/dev/null)
    has_units "$j"
    jcheck "$j" "j['input']['w_adv'] == 0 and j['input']['k_m'] == 0 and j['input']['springs'] == 128 and j['input']['control'] == 'load' and j['input']['path'] == [0, 3e-6, -3e-6] and j['units']['path'] == 'N' and j['units']['pull_off_F'] == 'N' and j['units']['F0'] == 'N' and j['input']['arith'] == j['arith'] == '$arith'"
    j=$($MDR cycle $P --control machine --k-machine 2 --w-adv 0.02 --path 0,3e-6,-3e-6 --steps-per-segment 100 --springs 128 --arith $arith 2>&1 >/dev/null)
    jcheck "$j" "j['input']['w_adv'] == 0.02 and j['input']['k_m'] == 2 and j['units']['path'] == 'm'"
done

# mdr table: the header declaring the table, next to --output FILE.c or at --header FILE
cat >"$TMP/use.c" <<'EOF'
#include "tipq.h"
#include "tipf.h"
int main(void) { return tipf.n == MDR_TABLE_TIPF_SPRINGS && tipq.n == MDR_TABLE_TIPQ_SPRINGS ? 0 : 1; }
EOF
$MDR table --profile sphere --R 1e-6 --springs 64 --a-max 5e-7 --name tipf --output "$TMP/tipf.c" >"$TMP/out" &&
    [ ! -s "$TMP/out" ] && [ -s "$TMP/tipf.h" ] && grep -q '^#include "tipf.h"' "$TMP/tipf.c" && ok || bad "table --output writes .c and .h"
$MDR table --profile sphere --R 1e-6 --springs 64 --a-max 5e-7 --name tipq --arith q31 --header "$TMP/tipq.h" >"$TMP/tipq.c" &&
    grep -q '^extern const mdr_table_q31 tipq;' "$TMP/tipq.h" && grep -q '^#include "tipq.h"' "$TMP/tipq.c" && ok ||
    bad "table --header writes the header, the .c on stdout includes it"
${CC:-cc} -std=c99 -Wall -Wextra -Werror -Ilib/include -I"$TMP" "$TMP/use.c" "$TMP/tipf.c" "$TMP/tipq.c" \
    "$(dirname "$MDR")/libmdr.a" ${MDR_LINK_FLAGS:-} -lm -o "$TMP/use" && "$TMP/use" && ok || bad "a program using the generated headers links and runs"
refuse 'output names a .c file' table --profile sphere --R 1e-6 --springs 64 --a-max 5e-7 --output "$TMP/x.txt"
refuse 'cannot write: /nonexistent/t.h' table --profile sphere --R 1e-6 --springs 64 --a-max 5e-7 --header /nonexistent/t.h

# the default table extent is what the help says: 1.25 x the largest radius
# the path reaches (w_adv = w: the path follows the equilibrium curve of w,
# whose crossing of the path's largest value the extent is formed from; to
# 1e-2: the engine's radius on 1024 springs), for every control and profile
# (the wavy one crossing that value more than once below its first
# crossing); the q31 engine on the reproducer's power law then agrees with
# f64 to 1e-6 of the peak force (3.7e-8 measured; 3.4e-5 = 3.7 x with the
# old extent)
E="--E 1e6 --w 0.05 --w-adv 0.05 --steps-per-segment 2000 --arith f64"
for p in "paraboloid --R 10e-6" "sphere --R 10e-6" "cone --theta 0.3" "powerlaw --C 1e34 --n 8" \
    "flattip --R 10e-6 --b 1e-6" "wavy --R 10e-6 --h 1e-8 --lambda 5e-7" "wavy --R 10e-6 --h 2e-7 --lambda 1e-6"; do
    for c in "grips --path 0,0.5e-6,-0.6e-6" "load --path 0,3e-6,-3e-6" "machine --k-machine 1 --path 0,0.5e-6,-1e-6"; do
        $MDR cycle --profile $p $E --control $c >"$TMP/x.csv" 2>"$TMP/x.json" || bad "cycle $p $c: exit"
        am=$(key "$(cat "$TMP/x.json")" a_max)
        awk -F, -v am="$am" 'NR > 1 && $5 > m { m = $5 } END { r = 1.25 * m / am; exit !(r >= 0.99 && r <= 1.0001) }' \
            "$TMP/x.csv" && ok || bad "default a_max = 1.25 x the radius reached: $p $c (a_max $am)"
    done
done
PL="--profile powerlaw --C 1e34 --n 8 --E 1e6 --w 0.05 --w-adv 0.025 --control load --path 0,1e-5,-3e-5 --steps-per-segment 1000"
$MDR cycle $PL --arith f64 >"$TMP/f.csv" 2>/dev/null && $MDR cycle $PL --arith q31 >"$TMP/q.csv" 2>/dev/null &&
    paste -d, "$TMP/f.csv" "$TMP/q.csv" | awk -F, 'NR > 1 { d = $4 - $10; d = d < 0 ? -d : d; m = d > m ? d : m; p = $4 < 0 ? -$4 : $4; pk = p > pk ? p : pk }
        END { exit !(m <= 1e-6 * pk) }' && ok || bad "q31 = f64 to 1e-6 of the peak force on the default extent (power law)"

# q31's default extent widens until the whole path fits the q31 ranges
# (mdr_host_extent_q31, shared with the Python package): a machine path
# driven far past the pull-off (the free body's depth d = z 2^sz beyond the
# step's int32 at the f64 extent, which saturates there) runs by default on
# a doubled extent, unsaturated, and agrees with the f64 engine on the same
# table to the documented 8 LSB of F0 (docs/fixed-point.md; F0 from the
# range message of a load path on that table)
S="--profile sphere --R 20e-9 --E 1e9 --w 0.05 --w-adv 0.02 --steps-per-segment 2000"
SM="$S --k-machine 0.2 --control machine --path -5e-9,3e-9,-40e-9"
$MDR cycle $SM --arith f64 >/dev/null 2>"$TMP/f.json" || bad "q31 widening: f64 run"
af=$(key "$(cat "$TMP/f.json")" a_max)
# (on the f64 extent itself, an explicit --a-max, the path's end lies below
# z_min: refused, as mdr help cycle says; before stop 56 it ran saturated,
# exit 0, with a warning on stderr)
refuse "below the q31 machine's least base position z_min" cycle $SM --arith q31 --a-max "$af"
$MDR cycle $SM --arith q31 >"$TMP/q.csv" 2>"$TMP/q.json" && ! grep -q saturated "$TMP/q.json" &&
    ok || bad "q31 machine path far past pull-off runs unsaturated by default: $(head -c 300 "$TMP/q.json")"
aq=$(key "$(cat "$TMP/q.json")" a_max)
awk -v a="$aq" -v b="$af" 'BEGIN { r = a / b; k = log(r) / log(2); exit !(r > 1.5 && k <= 8.0001 && (k - int(k + 0.5)) ^ 2 < 1e-12) }' &&
    ok || bad "q31 default extent $aq = 2^k x the f64 one $af, 1 <= k <= 8"
F2=$($MDR cycle $S --control load --path 0,1 --a-max "$aq" --arith q31 2>&1 | sed -n 's/.*= +-\([0-9.e+-]*\) N$/\1/p')
$MDR cycle $SM --arith f64 --a-max "$aq" >"$TMP/f.csv" 2>/dev/null &&
    paste -d, "$TMP/f.csv" "$TMP/q.csv" | awk -F, -v F2="$F2" 'NR > 1 { d = $4 - $10; d = d < 0 ? -d : d; m = d > m ? d : m; n++ }
        END { exit !(n == 4001 && F2 > 0 && m <= 8 * (F2 / 2) / 536870912) }' &&
    ok || bad "q31 (widened) = f64 on the same table to 8 LSB of F0 (2 F0 = $F2)"

# a spring table without a q31 form: the message names the real cause
# (mdr_table_q31_from: N not a power of two; a spring slope >= 8 in Q3.28,
# here the sphere tabulated to 0.999 R; a curvature term >= 2 in Q1.30, a
# kinked tip over 2 springs), not a power of two for an N that is one
S="--profile sphere --R 10e-6 --E 1e6 --w 0.05"
refuse '^mdr: q31 table \(--springs must be a power of two\)' table --profile sphere --R 1e-6 --springs 100 --a-max 5e-7 --arith q31
refuse '^mdr: q31 table: the profile is too steep over the table .*lower --a-max \(9.99e-06 m\), further below the sphere' \
    cycle $S --control grips --path 0,1e-6 --steps-per-segment 10 --a-max 9.99e-6 --arith q31
refuse '^mdr: q31 table: the profile is too steep over the table' table --profile sphere --R 10e-6 --a-max 9.99e-6 --arith q31
# (the same at 4 096 and 16 384 springs, whose nodes the C library returns to
# the system when freed: the message was built after the free and the CLI
# crashed, SIGSEGV, helper-21 at stop 54)
for n in 4096 16384; do
    refuse '^mdr: q31 table: the profile is too steep over the table' \
        cycle $S --control grips --path 0,1e-7,-1e-7 --steps-per-segment 10 --springs $n --a-max 9.99e-6 --arith q31
done
# the steepest spring inside the table (the flattened tip's rim): fewer
# springs or a longer table, not a shorter one (which steepens it: the message
# said "lower --a-max", helper-27 at stop 57); the remedy it names is accepted
F5="--profile flattip --R 1e-3 --b 5e-5 --E 1e10 --w 1e-6 --control grips --path 0,1e-10,-1e-9 --steps-per-segment 20"
refuse '^mdr: q31 table: the profile is too steep inside the table .*at x = 5e-05 m: a rim or kink\); fewer --springs \(1024\) or a higher --a-max' \
    cycle $F5 --springs 1024 --arith q31 --a-max 6e-5
$MDR cycle $F5 --springs 256 --arith q31 --a-max 1e-4 >/dev/null 2>&1 && ok || bad "flattened tip in q31 on 256 springs to 100 um"
# a profile or material out of range: the line names the argument and the
# status by name and number (it said "profile/material ... (status -3)",
# helper-22 at stop 54), and the profile's range (helper-66, stop 71: a cone
# of --theta 30, degrees for radians, was "parameter out of range" alone)
refuse '^mdr: profile paraboloid \(--R; R > 0, finite in this arithmetic\): parameter out of range \(MDR_E_PARAM, status -3\)$' \
    eq --profile paraboloid --R -10e-6 --E 1e6 --w 0.05 --a 1e-6
refuse '^mdr: profile wavy \(--R, --h, --lambda; R > 0, h >= 0, lambda > 0, finite in this arithmetic\): parameter out of range \(MDR_E_PARAM, status -3\)$' \
    eq --profile wavy --R 1e-5 --h -1e-8 --lambda 5e-7 --E 1e6 --w 0.05 --a 1e-6
refuse '^mdr: profile cone \(--theta; 0 < theta < pi/2 rad, finite in this arithmetic\): parameter out of range \(MDR_E_PARAM, status -3\)$' \
    eq --profile cone --theta 30 --E 1e6 --w 0.05 --a 1e-6
refuse '^mdr: profile powerlaw \(--C, --n; C > 0, 0 < n <= 8, finite in this arithmetic\): parameter out of range' \
    eq --profile powerlaw --C 1 --n 9 --E 1e6 --w 0.05 --a 1e-6
refuse '^mdr: --E: parameter out of range \(MDR_E_PARAM, status -3\)$' eq --profile paraboloid --R 10e-6 --E 0 --w 0.05 --a 1e-6
refuse '^mdr: --w: parameter out of range \(MDR_E_PARAM, status -3\)$' critical --profile cone --theta 0.5 --E 1e6 --w -0.05 --control load
# every status of the header has its name in the CLI's table (cli_stname)
ROOT=$(cd "$(dirname "$0")/.." && pwd)
want=$(grep -o '^#define MDR_E_[A-Z_]* ' "$ROOT/lib/include/mdr_types.h" | awk '{ print $2 }' | sort)
have=$(grep -o 'CLI_ST(MDR_E_[A-Z_]*)' "$ROOT/examples/mdr_cli.c" | sed 's/CLI_ST(\(.*\))/\1/' | sort)
[ -n "$want" ] && [ "$want" = "$have" ] && ok || bad "the CLI names every MDR_E_* status: $(echo $want) against $(echo $have)"
# a file that cannot be opened or read: the line gives the system's reason
# (helper-22 at stop 54: "cannot open: nosuch.csv" and nothing more)
refuse '^mdr: cannot open: '"$TMP"'/nosuch.csv \(No such file or directory\)$' \
    critical --profile table --file "$TMP/nosuch.csv" --E 1e6 --w 0.05 --control grips
refuse '^mdr: read error in: '"$TMP"' \(Is a directory\)$' critical --profile table --file "$TMP" --E 1e6 --w 0.05 --control grips
# a machine too soft for the q31 engine (kappa = 2 E* L / k_m > 2^16): named,
# with the least stiffness on this table, which (1 % above it) is taken (the
# message was "unknown control mode", helper-21 at stop 54)
Pm="--profile paraboloid --R 10e-6 --E 1e6 --w 0.05 --control machine --path 0,3e-6,-3e-6 --steps-per-segment 100 --springs 128"
refuse '^mdr: q31 engine \(--k-machine, --E, --a-max\): the machine is too soft for q31 on this table: kappa = 2 E\* L / k_m = 1.03[0-9]*e\+06 .*above 2 E\* L / 65536 = [0-9.e+-]* N/m' \
    cycle $Pm --k-machine 1e-5 --arith q31
km=$($MDR cycle $Pm --k-machine 1e-5 --arith q31 2>&1 >/dev/null | sed -n 's/.* = \([0-9.e+-]*\) N\/m on this table.*/\1/p')
$MDR cycle $Pm --k-machine "$(awk -v k="$km" 'BEGIN { printf "%.6g", 1.01 * k }')" --arith q31 >/dev/null 2>&1 && ok ||
    bad "q31 machine: the stiffness the refusal names ($km N/m, 1 % above) is taken"
printf 'r,f\n0,0\n1e-6,0\n1.0001e-6,1e-6\n2e-6,1.00001e-6\n' >"$TMP/kink.csv"
refuse '^mdr: q31 table: too few springs for the profile.s curvature .*raise --springs \(2\)' \
    table --profile table --file "$TMP/kink.csv" --springs 2 --arith q31

# a q31 table so far beyond the pull-off radius that the adhesion is below
# MDR_Q31_ADH_LSB LSB of F (0.03 LSB here): refused, named by its cause
# (the material is valid: the float engine takes it), not as a parameter
P="--profile paraboloid --R 10e-6 --E 1e6 --w 0.05 --w-adv 0.05 --control load --path 0,1e-6 --steps-per-segment 10"
refuse '^mdr: q31 engine \(--a-max, table to 0.005 m\): the pull-off force is below 1024 LSB' cycle $P --a-max 5e-3 --arith q31
refuse '^mdr: --w-adv 0.06: outside \[0, --w\]' cycle --profile paraboloid --R 10e-6 --E 1e6 --w 0.05 \
    --w-adv 0.06 --control load --path 0,1e-6 --steps-per-segment 10 --a-max 5e-3 --arith q31
out=$("$MDR" cycle $P --a-max 5e-3 --arith f64 --summary "$TMP/s.json" 2>/dev/null) && grep -q '"event": "jump-in"' "$TMP/s.json" &&
    ok || bad "the same table in f64: a jump-in"

# a float table whose first spring is ~1e4 pull-off radii wide (E* = 1e35 Pa:
# the pull-off at 1e-5 of spring 0, where f32 rounds it to 1e-2):
# refused, named by its cause; f64 resolves it
P="--profile paraboloid --R 1e-6 --E 1e35 --w 0.05 --control grips --path 0,1e-9,-1e-9 --steps-per-segment 5"
refuse '^mdr: engine \(--springs, --a-max, table to 3.95285e-08 m\): the pull-off lies so deep inside the first of 1024 springs' \
    cycle $P
refuse '^mdr: --w-adv 0.06: outside \[0, --w\]' cycle $P --w-adv 0.06
out=$("$MDR" cycle $P --arith f64 2>&1 >/dev/null) && [ "$(key "$out" pull_off_F)" = "-1.3089969389752541e-07" ] &&
    ok || bad "the same scene in f64: pull-off -(5/6) pi w R ($out)"
# a table so small that its springs' curvature terms are subnormal (f32:
# every q flushed to 0, the grips pull-off 4.7e-3 off before): refused at
# the table, named; f64 takes it
P="--profile paraboloid --R 1e-2 --E 1.78e21 --w 1e-15 --control grips --springs 256 --a-max 8.4e-14 --path 0,1.6e-25,-1e-24 --steps-per-segment 50"
refuse '^mdr: --a-max: the table.s values leave this arithmetic.s range, .* curvature terms lose their digits; --arith f64' cycle $P
out=$("$MDR" cycle $P --arith f64 2>&1 >/dev/null) && awk -v F="$(key "$out" pull_off_F)" 'BEGIN { r = F / (-5 / 6 * 3.141592653589793 * 1e-15 * 1e-2) - 1; exit !(r * r < 1e-20) }' &&
    ok || bad "the same table in f64: pull-off -(5/6) pi w R ($out)"

# a flat's rim inside spring 0 (b = 0.99 of a spring): its pull-off there is
# resolved by no spring (f64 pulled off at 3% of Kendall's force before):
# refused in every arithmetic, named by its cause; with the rim on node 1
# (90 springs) Kendall's -sqrt(8 pi b^3 E* w)
P="--profile flattip --R 1e-6 --b 5e-9 --E 1e9 --control grips --a-max 4.5e-7 --path 0,2.1e-10,-4.2e-10 --steps-per-segment 200"
for ar in f32 f64; do
    refuse "^mdr: engine \(--springs, --a-max, table to 4.5e-07 m\): the flat.s rim \(--b, or the samples. flat end or first kink\) lies inside the first of 89 springs" \
        cycle $P --w 1e-8 --springs 89 --arith $ar
done
refuse "^mdr: q31 engine \(--springs, --a-max, table to 4.5e-07 m\): the flat.s rim" cycle $P --springs 16 --w 1e-3 --arith q31
# the same worn tip sampled, its rim between two samples (10.5 intervals on
# the flat: no kink the kink test sees; a helper's attack, stop 53: exit 0
# at 15% of Kendall's d before), flagged by the end of the samples' flat
awk 'BEGIN { R = 1e-6; b = 5e-9; dr = b / 10.5; for (i = 0; i < 1000; i++) { r = i * dr; printf "%.17g,%.17g\n", r, r <= b ? 0 : (r * r - b * b) / (2 * R) } }' > "$TMP/worn.csv"
refuse "^mdr: engine \(--springs, --a-max, table to 4.5e-07 m\): the flat.s rim .* lies inside the first of 64 springs" \
    cycle --profile table --file "$TMP/worn.csv" --E 1e9 --w 1e-8 --control grips --springs 64 --a-max 4.5e-7 \
    --path 0,8.9e-10,-1.7e-12 --steps-per-segment 100 --arith f64
out=$("$MDR" cycle $P --w 1e-8 --springs 90 --arith f64 2>&1 >/dev/null) && awk -v F="$(key "$out" pull_off_F)" 'BEGIN { r = F / -sqrt(8 * 3.141592653589793 * 1.25e-25 * 1e9 * 1e-8) - 1; exit !(r * r < 1e-20) }' &&
    ok || bad "the rim on node 1: Kendall's pull-off ($out)"

# helper-37 (stop 59): a state --a --d beyond the arithmetic printed "F": inf
# with exit 0; a q31 path vertex below half an LSB rounded to 0 (no contact,
# no event, exit 0); a cycle's summary lost on stderr exited 0; --output and
# --header the same file wrote a .c that included itself
refuse '^mdr: --a/--d: result beyond' eq --profile paraboloid --R 1e6 --E 1e30 --w 0.05 --a 1e3 --d 1e6
refuse '^mdr: --a/--d: result beyond' eq --profile paraboloid --R 1e200 --E 1e200 --w 0.05 --a 1e100 --d 1e10 --arith f64
# helper-62 (stop 68): the force of a state (a, d) given both, as F_eq + 2 E* a
# (d - d_eq), lost its digits to the adhesion's terms (6.3 % off in f32 here;
# 2E* (a d - G(a)) now: -2E* a^3/(3R) at d = 0, a as the arithmetic holds it)
for arith in f32 f64; do
    tol=$([ $arith = f32 ] && echo 2e-6 || echo 3e-14)
    j=$($MDR eq --profile paraboloid --R 10e-6 --E 1e6 --w 0.05 --a 1e-9 --d 0 --arith $arith)
    jcheck "$j" "abs(j['F'] / (-2e6 * j['a'] ** 3 / 3e-5) - 1) <= $tol"
done
# helper-62 (stop 68): a power law at n = 1/2 + 1 ulp pulled off at a = d = F = 0,
# exit 0 (the true radius 38 769 m); within 2^10 eps of 1/2 the radius is not
# resolved: refused, naming n, as n = 1/2 (every control; stress at the state too)
for ctl in "load" "grips" "machine --k-machine 1"; do
    # shellcheck disable=SC2086
    refuse '^mdr: --n 0.50000000000000011: within 2\^10 eps of 1/2 \(1.1e-13 in f64\) a power law.s critical radius .* \(MDR_E_RADIUS, status -5\)$' \
        critical --profile powerlaw --C 0.0038992998543832206 --n 0.5000000000000001 --E 2583821.9795740326 \
        --w 1.194092379323328 --control $ctl --arith f64
done
refuse '^mdr: --n 0.5: within 2\^10 eps of 1/2 \(6.1e-05 in f32\)' critical --profile powerlaw --C 1 --n 0.5 --E 1e6 \
    --w 0.05 --control load
refuse '^mdr: --n 0.50000999999999995: within 2\^10 eps of 1/2 \(6.1e-05 in f32\)' stress --profile powerlaw --C 1 \
    --n 0.50001 --E 1e6 --w 0.05 --control load --r 0.5
# 4 504 eps above 1/2, C for a fixed-load radius of 1 um: answered within 1 %
C=$(/usr/bin/python3 -c 'import math; n = 0.5000000000005; c = math.sqrt(2 * math.pi * 0.05 / 1e6)
k = math.sqrt(math.pi) * math.exp(math.lgamma(n / 2 + 1) - math.lgamma(n / 2 + 0.5)); print(repr(1.5 * c / (n * k) * 1e-6 ** (0.5 - n)))')
out=$($MDR critical --profile powerlaw --C "$C" --n 0.5000000000005 --E 1e6 --w 0.05 --control load --arith f64) &&
    near "$(key "$out" a)" 1e-6 1e-2 && ok || bad "power law 4504 eps above 1/2, C $C: $out"
refuse '^mdr: --path value 2 \(2e-12 N\): below half a q31 LSB of F0' cycle --profile paraboloid --R 1e-3 --E 1e6 \
    --w 0.05 --w-adv 0.05 --control load --path 0,2e-12,-1e-3 --steps-per-segment 10 --arith q31
if [ -w /dev/full ]; then
    $MDR cycle --profile paraboloid --R 1e-3 --E 1e6 --w 0.05 --control grips --path 0,1e-6,-3e-6 \
        --steps-per-segment 10 >/dev/null 2>/dev/full
    [ $? -eq 1 ] && ok || bad "cycle: the summary on stderr lost (/dev/full) exits 1"
    # the usage and the version lost to /dev/full: exit 1, one line (exit 0
    # before; an attack after stop 59)
    for args in "--help" "-h" "help" "help cycle" "help help" "cycle --help" "eq --a 1 --help" "fit --help" "--version"; do
        $MDR $args >/dev/full 2>"$TMP/err"
        [ $? -eq 1 ] && [ "$(wc -l <"$TMP/err")" -eq 1 ] && grep -q '^mdr: stdout: ' "$TMP/err" && ok ||
            bad "mdr $args >/dev/full: exit 1 and one line ($(cat "$TMP/err"))"
    done
fi
# a wavy profile's table with fewer than 8 springs per wavelength says so
# (helper-63, stop 70: silent before): the summary's "warnings" (empty
# otherwise, for every command that has a table), and a line on stderr where
# stderr is free of the summary (--summary FILE, table). 64 springs over the
# default extent of this path: 6.32 per wavelength; 1 024: 25.3.
WV="--profile wavy --R 1e-5 --h 1.5e-8 --lambda 5e-7 --E 1e6 --w 0.05 --control grips --path 0,5e-7,-5e-7 --steps-per-segment 10"
for arith in f64 f32; do
    # shellcheck disable=SC2086
    j=$($MDR cycle $WV --springs 64 --arith $arith 2>&1 >/dev/null)
    jcheck "$j" "len(j['warnings']) == 1 and j['warnings'][0].startswith('6.32 springs per wavelength (--lambda 5e-07 m') and j['jumps'] > 0"
    # shellcheck disable=SC2086
    j=$($MDR cycle $WV --arith $arith 2>&1 >/dev/null)
    jcheck "$j" "j['warnings'] == [] and j['springs'] == 1024"
    # shellcheck disable=SC2086
    $MDR cycle $WV --springs 64 --arith $arith --summary "$TMP/wv.json" >/dev/null 2>"$TMP/err"
    [ $? -eq 0 ] && [ "$(wc -l <"$TMP/err")" -eq 1 ] &&
        grep -q '^mdr: warning: 6.32 springs per wavelength .*below 8 the waves are not resolved; more --springs or a lower --a-max$' "$TMP/err" &&
        jcheck "$(cat "$TMP/wv.json")" "len(j['warnings']) == 1" || bad "cycle --summary: the warning on stderr ($(cat "$TMP/err"))"
done
j=$($MDR cycle --profile paraboloid --R 10e-6 --E 1e6 --w 0.05 --control grips --path 0,1e-6 --steps-per-segment 10 --springs 2 2>&1 >/dev/null)
jcheck "$j" "j['warnings'] == []"
$MDR table --profile wavy --R 1e-5 --h 1.5e-8 --lambda 5e-7 --springs 64 --a-max 4.5e-6 >/dev/null 2>"$TMP/err"
[ $? -eq 0 ] && [ "$(wc -l <"$TMP/err")" -eq 1 ] && grep -q '^mdr: warning: 7.11 springs per wavelength' "$TMP/err" &&
    ok || bad "table: the wavy warning ($(cat "$TMP/err"))"
$MDR table --profile wavy --R 1e-5 --h 1.5e-8 --lambda 5e-7 --springs 64 --a-max 3.9e-6 >/dev/null 2>"$TMP/err"
[ $? -eq 0 ] && [ ! -s "$TMP/err" ] && ok || bad "table: 8.2 springs per wavelength, no warning ($(cat "$TMP/err"))"
refuse '^mdr: --output and --header name the same file' table --profile paraboloid --R 1e-3 --a-max 1e-4 \
    --header "$TMP/same.h" --output "$TMP/same.h"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
