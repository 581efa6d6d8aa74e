# SPDX-License-Identifier: MIT
# cli_lib.sh: what the CLI test scripts share (sourced by test_cli.sh and
# test_fit_cli.sh): pass/fail counters, a relative comparison, a JSON key.
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
near() { # near VALUE WANT RELTOL
    awk -v x="$1" -v y="$2" -v t="$3" 'BEGIN { d = x - y; if (d < 0) d = -d; s = y < 0 ? -y : y; exit !(d <= t * s) }'
}
key() { # key JSON NAME -> the value of the top-level key NAME as JSON
    # ("q31" with its quotes, null, true, a number); nothing if the text is
    # not one JSON object or has no such key. NAME.SUB: a key of an object.
    printf '%s' "$1" | /usr/bin/python3 -c '
import json, sys
try:
    v = json.loads(sys.stdin.read())
    for k in sys.argv[1].split("."):
        v = v[k]
except Exception:
    sys.exit(0)
print(json.dumps(v))' "$2"
}
