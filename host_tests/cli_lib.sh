# cli_lib.sh: what the CLI test scripts share (sourced by test_cli.sh and
# test_fit_cli.sh): pass/fail counters, a relative comparison, a JSON key.
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
