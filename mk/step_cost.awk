# SPDX-License-Identifier: MIT
# mk/step_cost.awk: make step-cost's CSV (host_tests/target/step_cost.c,
#   engine,arith,core,cycle,mean,max,separated,pinned,moving)
# -> the Markdown of docs/performance.md's step-cost section: every line as a
# table row, then the goals of issue 20 beside the measured values (the
# verdicts are computed here from the same lines, so they never go stale):
#   awk -F, -f mk/step_cost.awk build/bench/step_cost.csv
function v(x) { return x == "" ? "-" : x }
# remember a value for a goal; met stays 1 while every value is within lim
# (brief: only the range and the worst line's name, for goals over many lines)
function take(g, lim, x, label, brief) {
    if (x == "") return
    if (!(g in met)) { met[g] = 1; lo[g] = x + 0; hi[g] = x + 0; hil[g] = label }
    if (x + 0 < lo[g]) lo[g] = x + 0
    if (x + 0 > hi[g]) { hi[g] = x + 0; hil[g] = label }
    if (x + 0 > lim) met[g] = 0
    if (brief) meas[g] = sprintf("%s to %s (worst: %s)", lo[g], hi[g], hil[g])
    else meas[g] = meas[g] (meas[g] == "" ? "" : ", ") label " " x
}
function row(g, text) {
    printf "| %s | %s | %s |\n", text, (meas[g] == "" ? "-" : meas[g]),
        (!(g in met) ? "no measurement" : met[g] ? "yes" : "**no**")
}
NR == 1 {
    print "| engine | arith | core | cycle | mean | max | separated | pinned | moving |"
    print "| --- | --- | --- | --- | ---: | ---: | ---: | ---: | ---: |"
    next
}
NF >= 9 {
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, v($5), v($6), v($7), v($8), v($9)
    e = $1; a = $2; c = $3; cy = $4
    if (e == "scene" && a == "f32" && c == "m4f") take("scene", 60, $5, cy)
    if (e == "spring" && a == "f32" && c == "m4f") { take("spring", 150, $5, cy); take("worst", 1500, $6, cy) }
    if (e == "spring" && a == "q31" && c == "m3") take("q31", 250, $5, cy)
    if (e == "scene" && a == "q31" && c == "m3") take("sq31", 100, $5, cy)
    if (c == "m4f" || a == "q31") take("sep", 20, $7, e " " a " " c " " cy, 1)
    if (a == "f32" && c == "m4f") take("pin", 30, $8, e " " cy)
}
END {
    print ""
    print "**Goals of issue 20** (instructions per tick, force-only step; the M4F runs f32 in"
    print "hardware, the M3 in soft float, so the f32 goals are the M4F's)"
    print ""
    print "| goal | measured | met |"
    print "| --- | --- | --- |"
    row("scene", "scene f32 mean <= 60, both cycles (M4F)")
    row("spring", "spring f32 mean <= 150 (M4F, N = 1024)")
    row("q31", "spring q31 mean <= 250 on the M3 (N = 1024)")
    row("sq31", "scene q31 mean <= 100 on the M3, both cycles")
    row("sep", "separated tick <= 20, every engine (M4F; q31 on the M3)")
    row("pin", "pinned tick <= 30, f32 (M4F)")
    row("worst", "worst spring f32 tick <= 1500 (M4F)")
}
