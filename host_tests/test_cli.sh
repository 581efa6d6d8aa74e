#!/usr/bin/env bash
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
    for k in pull_off_F pull_off_d events dissipated; do
        [ -n "$(key "$j" $k)" ] && ok || bad "cycle: key $k missing in $j"
    done
    near "$(key "$j" pull_off_F)" -1.308996939e-6 1e-5 && ok || bad "cycle grips pull-off F ($arith): $j"
    near "$(key "$j" pull_off_d)" -0.470407800461e-6 1e-5 && ok || bad "cycle grips pull-off d ($arith)"
    [ "$(key "$j" arith)" = "\"$arith\"" ] && ok || bad "cycle arith key ($arith): $j"
    [ "$(key "$j" events)" = 2 ] && ok || bad "cycle: contact + pull-off = 2 events: $j"
    grep -q ',contact$' "$TMP/c.csv" && grep -q ',pull-off$' "$TMP/c.csv" && ok || bad "cycle event column"
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
$MDR table --profile table --file "$TMP/tip.csv" --springs 16 --name my_tip >"$TMP/t.c" || bad "table exit"
grep -q '^const mdr_table_f32 my_tip = {my_tip_nodes, ' "$TMP/t.c" && ok || bad "table C output"
[ "$(grep -c '^    {' "$TMP/t.c")" -eq 17 ] && ok || bad "table: 17 nodes for 16 springs"
# outside the table: exit 1 with a message
$MDR cycle $P --control grips --path 0,1e-6 --steps-per-segment 10 --a-max 2e-6 >/dev/null 2>&1
[ $? -eq 1 ] && ok || bad "cycle beyond the table exits 1"

# bad arguments: exit 2, one line on stderr
expect2() {
    local err
    err=$("$MDR" "$@" 2>&1 >/dev/null)
    local rc=$?
    [ $rc -eq 2 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && [ -n "$err" ] && ok ||
        bad "expected exit 2 and one line for: $* (rc $rc, '$err')"
}
expect2
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
    [ "$(grep -c '^    {' "$TMP/crlf.c")" -eq 9 ] && ok || bad "tip file with comments, CRLF, no final newline"
expect2 table $P
expect2 table --profile paraboloid --R 1e-5 --a-max 1e-6 --name 9lives
expect2 eq --profile table --file "$TMP/tip.csv" --E 1 --w 1 --a 1

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
