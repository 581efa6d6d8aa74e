# SPDX-License-Identifier: MIT
# cli_lib.sh: what the CLI test scripts share (sourced by test_cli.sh,
# test_cli_f32.sh and test_fit_cli.sh): pass/fail counters, a relative
# comparison, a JSON key, a number read without a process, a refusal, a
# check of a JSON object.
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
near() { # near VALUES WANTS RELTOL: each value (space-separated) within RELTOL of its want
    awk -v x="$1" -v y="$2" -v t="$3" 'BEGIN { n = split(x, u, " "); if (split(y, v, " ") != n) exit 1
        for (k = 1; k <= n; k++) { d = u[k] - v[k]; if (d < 0) d = -d; s = v[k] < 0 ? -v[k] : v[k]; if (!(d <= t * s)) exit 1 } }'
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
# nums JSON KEY...: the numbers of the first "KEY": of each KEY in JSON, in
# $NUMS, space-separated (bash's own regex: no process, where the sweeps of
# test_cli_f32.sh read six keys of two answers per state); returns 1, NUMS
# naming the key, where one has no number
nums() {
    local j=$1 k re
    shift
    NUMS=""
    for k in "$@"; do
        re="\"$k\": ([-0-9.e+]+)"
        [[ $j =~ $re ]] || { NUMS="no number for $k"; return 1; }
        NUMS="$NUMS${NUMS:+ }${BASH_REMATCH[1]}"
    done
}
# refuse PATTERN ARGS...: exit 2, nothing on stdout, one line on stderr that
# matches the (grep -E) PATTERN
refuse() {
    local pat=$1 out err rc
    shift
    out=$(timeout 60 "$MDR" "$@" 2>"$TMP/err") # a read that never ends fails, not hangs
    rc=$?
    err=$(cat "$TMP/err")
    [ $rc -eq 2 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] &&
        printf '%s' "$err" | grep -Eq -- "$pat" && ok ||
        bad "refuse /$pat/: $* (rc $rc, stdout ${#out} chars, stderr '$err')"
}
# jcheck JSON PYTHON-EXPR: the expression over j (the object) is true
jcheck() {
    printf '%s' "$1" | /usr/bin/python3 -c '
import json, sys
j = json.loads(sys.stdin.read())
sys.exit(0 if eval(sys.argv[1]) else 1)' "$2" 2>/dev/null && ok || bad "json: $2 in $1"
}
