# SPDX-License-Identifier: MIT
# mk/callgrind_fit.awk: one callgrind dump of host_tests/bench_fit.c (make
# bench-fit) -> a Markdown row: instructions per curve (32 curves per dump),
# or per model point for the "model" dumps (32 x 2000 points).
/^desc: Trigger: Client Request: / { sub(/^desc: Trigger: Client Request: /, ""); l = $0 }
/^summary: / {
    if (l ~ /^model/) printf "| %s | | %.0f |\n", l, $2 / 32 / 2000
    else printf "| %s | %.0f | |\n", l, $2 / 32
}
