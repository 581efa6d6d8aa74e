# SPDX-License-Identifier: MIT
# port/stack_depth.awk: worst-case stack depth of functions from GCC's
# call-graph files (-fcallgraph-info=su, one .ci per object). Depth of f =
# its own frame + the deepest callee (lib/ has no recursion and no calls
# through pointers, so the graph is a finite DAG). Callees outside the
# files (libgcc helpers) have no frame size here: they are listed.
#   awk -v roots='regex' -f port/stack_depth.awk *.ci
# prints one line per function whose name matches roots:
#   name  depth-bytes  deepest-path  [+ external callees]
function fname(t) { sub(/^.*:/, "", t); return t }
function depth(n,    i, d, best, c) {
    if (n in memo) return memo[n]
    best = 0; path[n] = ""
    for (i = 1; i <= nout[n]; i++) {
        c = out[n, i]
        if (!(c in size)) { ext[n] = ext[n] " " fname(c); continue }
        d = depth(c)
        if (d > best) { best = d; path[n] = " > " fname(c) path[c] }
        if (ext[c] != "") ext[n] = ext[n] ext[c]
    }
    memo[n] = size[n] + best
    return memo[n]
}
/^node:/ {
    match($0, /title: "[^"]*"/); t = substr($0, RSTART + 8, RLENGTH - 9)
    if (match($0, /\\n[0-9]+ bytes/)) {
        s = substr($0, RSTART + 2, RLENGTH - 2); sub(/ bytes/, "", s); size[t] = s + 0
        if ($0 ~ /dynamic/ && $0 !~ /bounded/) unbounded[t] = 1
    }
}
/^edge:/ {
    match($0, /sourcename: "[^"]*"/); s = substr($0, RSTART + 13, RLENGTH - 14)
    match($0, /targetname: "[^"]*"/); d = substr($0, RSTART + 13, RLENGTH - 14)
    if (!((s, d) in seen)) { seen[s, d] = 1; out[s, ++nout[s]] = d }
}
END {
    for (n in size) {
        if (fname(n) !~ roots) continue
        d = depth(n)
        e = ""; split(ext[n], xs, " "); delete u
        for (i in xs) if (xs[i] != "" && !(xs[i] in u)) { u[xs[i]] = 1; e = e " " xs[i] }
        printf "%-28s %5d  %s%s%s\n", fname(n), d, fname(n), path[n], (e != "" ? "  [+" e " ]" : "")
        if (n in unbounded) printf "  (%s has a dynamic frame)\n", fname(n)
    }
}
