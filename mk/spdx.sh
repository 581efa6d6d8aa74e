#!/bin/sh
# SPDX-License-Identifier: MIT
# mk/spdx.sh: every source file of the repository carries the line
# "SPDX-License-Identifier: MIT" in its first five lines (LICENSE).
#   mk/spdx.sh          check (make spdx-check, in make test): names each
#                       file without it and fails
#   mk/spdx.sh --add    add it where missing: "/* ... */" as the first line
#                       of C, headers, templates and linker scripts, "# ..."
#                       after the "#!" line of scripts and as the first
#                       line of make, CMake, Python, gnuplot, awk, TOML,
#                       Doxyfile and *.in files
# Source files: what git tracks or would track (not ignored), but the fuzz
# corpus (data).
set -eu
cd "$(dirname "$0")/.."
mode=${1:-check}
list() {
    git ls-files --cached --others --exclude-standard | sort -u | while read -r f; do
        [ -f "$f" ] || continue
        case $f in host_tests/fuzz/corpus/*) continue ;; esac
        case $f in
        *.c|*.h|*.inc|*.ld) echo "c $f" ;;
        *.py|*.sh|*.mk|*.gp|*.awk|*.cmake|*.toml|*.in|*/Makefile|Makefile|CMakeLists.txt|*/CMakeLists.txt|Doxyfile|.ci/run|*/run-qemu)
            echo "sh $f" ;;
        esac
    done
}
bad=0
n=0
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
list > "$tmp"
while read -r kind f; do
    n=$((n + 1))
    head -n 5 "$f" | grep -q 'SPDX-License-Identifier: MIT' && continue
    if [ "$mode" = --add ]; then
        if [ "$kind" = c ]; then
            { echo '/* SPDX-License-Identifier: MIT */'; cat "$f"; } > "$f.spdx"
        elif head -n 1 "$f" | grep -q '^#!'; then
            { head -n 1 "$f"; echo '# SPDX-License-Identifier: MIT'; tail -n +2 "$f"; } > "$f.spdx"
        else
            { echo '# SPDX-License-Identifier: MIT'; cat "$f"; } > "$f.spdx"
        fi
        chmod --reference="$f" "$f.spdx" && mv "$f.spdx" "$f"
        echo "spdx: added to $f"
    else
        echo "spdx: $f has no 'SPDX-License-Identifier: MIT' line in its first 5 lines"
        bad=$((bad + 1))
    fi
done < "$tmp"
if [ "$mode" != --add ]; then
    [ "$bad" = 0 ] || { echo "spdx: $bad of $n source files without the licence line (mk/spdx.sh --add)"; exit 1; }
    echo "spdx: all $n source files carry SPDX-License-Identifier: MIT"
fi
