# SPDX-License-Identifier: MIT
# mk/callgrind_rows.awk: one callgrind dump of host_tests/bench_matrix.c
# (make bench) -> "engine,arith,control,N,instructions per evaluation".
# The dump's trigger names the row and its evaluation count as
# "engine,arith,control,N,count"; the summary line is its instruction total.
/^desc: Trigger: Client Request: / {
    sub(/^desc: Trigger: Client Request: /, "")
    split($0, f, ",")
    key = f[1] "," f[2] "," f[3] "," f[4]
    cnt = f[5]
}
/^summary: / { printf "%s,%.1f\n", key, $2 / cnt }
