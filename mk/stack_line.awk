# SPDX-License-Identifier: MIT
# mk/stack_line.awk: the deepest line of port/stack_depth.awk ("root depth
# path [+ helpers ]") -> "<core> <arith> <depth> <root>  + <n> libgcc/mem
# helpers" (make size; -v k=<core> -v a=<arith>).
{
    ext = $0
    if (!sub(/^.*\[\+ /, "", ext)) ext = ""
    sub(/ \]$/, "", ext)
    n = split(ext, x, " ")
    printf "%-10s %s %5d   %s%s\n", k, a, $2, $3, (n ? sprintf("  + %d libgcc/mem helpers", n) : "")
}
