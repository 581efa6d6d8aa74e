# SPDX-License-Identifier: MIT
# mk/instance_sizes.awk: `nm -S sizes.o` of a core (port/sizes.c: one object
# mdr_sizeof_<type> per instance type, its size the sizeof) -> one line
# "<core> <type> <bytes> ..." (make size; -v k=<core>).
function hex(h,    i, v) {
    v = 0
    for (i = 1; i <= length(h); i++) v = 16 * v + index("0123456789abcdef", substr(h, i, 1)) - 1
    return v
}
{ n = $4; sub(/^mdr_sizeof_/, "", n); s = s sprintf(" %s %d", n, hex($2)) }
END { printf "%-10s%s\n", k, s }
