#!/usr/bin/env bash
# test_cli.sh: the mdr CLI's interface contract (subcommands, flags, JSON keys,
# CSV columns, exit status 2 with a one-line message on bad arguments).
# Usage: bash host_tests/test_cli.sh build/host/mdr
# Values are checked against the closed forms (JKR, CHECK_VALUES) to 1e-6.
set -u
MDR=${1:-build/host/mdr}
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
near() { # near VALUE WANT RELTOL
    awk -v x="$1" -v y="$2" -v t="$3" 'BEGIN { d = x - y; if (d < 0) d = -d; s = y < 0 ? -y : y; exit !(d <= t * s) }'
}
key() { # key JSON NAME -> value
    printf '%s' "$1" | tr -d '{}' | tr ',' '\n' | awk -F': ' -v k="\"$2\"" '$1 ~ k { gsub(/ /, "", $2); print $2 }'
}
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

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
