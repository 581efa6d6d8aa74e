# SPDX-License-Identifier: MIT
# mk/splice.awk: put a benchmark's Markdown into a document between its
# markers (make bench, bench-fit):
#   awk -v name=bench [-v from='## Summary' -v to='## Every row'] -f mk/splice.awk NEW.md DOC.md > OUT
# replaces what DOC.md holds between "<!-- NAME:begin" and "<!-- NAME:end"
# with NEW.md (with from/to: only its lines from the line starting with
# `from` up to the one starting with `to`, "## " headings made bold).
FNR == NR {
    if (from == "" || index($0, from) == 1) on = 1
    if (to != "" && index($0, to) == 1) on = 0
    if (on) {
        if (from != "" && /^## /) { sub(/^## /, ""); $0 = "**" $0 "**" }
        t = t $0 "\n"
    }
    next
}
index($0, "<!-- " name ":begin") == 1 { print; printf "%s", t; skip = 1; next }
index($0, "<!-- " name ":end") == 1 { skip = 0 }
!skip
