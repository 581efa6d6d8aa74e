#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""mk/step_trace.py: where a real-time step's instructions go (make step-trace).

Reads QEMU's instruction trace (-singlestep -d exec,nochain: one line per
executed instruction, its address) of host_tests/target/step_cost.c built with
-DSTEP_TRACE and sets it beside that program's own per-tick counts
("tick,<n>,<k>,<class>"). A tick is the instructions between the timing
function's call of the step and the return into it (the step and everything
it calls); its length must equal step_cost's count for that tick (checked:
the two methods count alike). Each address is named by addr2line (-f -i: the
innermost inlined function, its inlining callers and its source line), and the
ticks of one class are summed per function (with depth - 1 of its callers) and
per source line, printed as instructions per tick of that class, the top
largest first and then what the rest add up to.

The step runs from RAM (MDR_STEP_SECTION=".ramfunc", on every core here:
QEMU's counts do not depend on where code sits), so QEMU need only log the
.data section (where .ramfunc lands), the timing function, the library's
functions and the runtime's helpers (not the harness, printf and the rest of
libc): `step_trace.py ELF --dfilter --line ...` prints that -dfilter.

usage: step_trace.py ELF --dfilter --line engine,arith,cycle
       step_trace.py ELF QEMU_LOG TICKS_LOG --line engine,arith,cycle
                     [--class moving|pinned|separated|all|worst] [--depth N] [--top N]
                     [--prefix arm-none-eabi-]
"""
import argparse
import array
import collections
import re
import subprocess
import sys

CLASSES = {"separated": 0, "pinned": 1, "moving": 2}


def symbols(elf, prefix):
    """function symbols: name -> (start, end), addresses without the Thumb bit;
    one without a size (assembly: libgcc's __aeabi_ldivmod) ends at the next"""
    out = subprocess.run([prefix + "nm", "-nS", "--defined-only", elf], capture_output=True, text=True,
                         check=True).stdout
    rows = []
    for line in out.splitlines():
        f = line.split()
        if len(f) in (3, 4) and f[-2] in "tTwW" and len(f[-2]) == 1:
            rows.append((int(f[0], 16) & ~1, int(f[1], 16) if len(f) == 4 else None, f[-1]))
    syms = {}
    for i, (a, n, name) in enumerate(rows):
        if n is None:
            n = next((b for b, _, _ in rows[i + 1:] if b > a), a + 4) - a
        syms[name] = (a, a + n)
    return syms


def ticks_of(log, lo, hi, entries):
    """the address lists of the calls from [lo, hi) into a function entry"""
    pat = re.compile(r"^Trace \d+: \S+ \[[0-9a-f]+/([0-9a-f]+)/")
    ticks, cur, prev_here, last = [], None, False, -1
    add = None
    with open(log, errors="replace") as fh:
        for line in fh:
            m = pat.match(line)
            if not m:
                continue
            pc = int(m.group(1), 16)
            if pc == last:
                continue  # (an instruction QEMU ran again: its icount budget ran out in it)
            last = pc
            here = lo <= pc < hi
            if cur is not None:
                if here:  # back in the timing function: the step returned
                    ticks.append(cur)
                    cur = None
                else:
                    add(pc)
            elif prev_here and not here and pc in entries:
                cur = array.array("I", [pc])
                add = cur.append
            prev_here = here
    return ticks


def dfilter(elf, prefix, syms, timed):
    """QEMU's -dfilter: .data (.ramfunc), the timing function, the library, helpers"""
    out = subprocess.run([prefix + "readelf", "-SW", elf], capture_output=True, text=True, check=True).stdout
    rng = []
    for ln in out.splitlines():
        f = ln.replace("[ ", "[").split()
        if len(f) > 5 and f[1] == ".data":
            rng.append((int(f[3], 16), int(f[3], 16) + int(f[5], 16)))
    rng.append(syms[timed])
    # the library (a step in RAM may call into flash, through a veneer) and
    # the runtime's helpers; not the harness, printf and the rest of libc
    rng += [v for k, v in syms.items() if k.startswith(("mdr_", "__", "mem"))]
    rng.sort()
    merged = []
    for lo, hi in rng:
        if merged and lo <= merged[-1][1] + 64:
            merged[-1] = (merged[-1][0], max(hi, merged[-1][1]))
        else:
            merged.append((lo, hi))
    return ",".join("0x%x..0x%x" % (lo, hi - 1) for lo, hi in merged if hi > lo)


def names(elf, pcs, prefix):
    """pc -> (the inlined functions from the innermost out, file:line of the innermost)"""
    pcs = sorted(pcs)
    out = subprocess.run([prefix + "addr2line", "-e", elf, "-f", "-i", "-a"] + ["%x" % p for p in pcs],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    res, i = {}, 0
    while i < len(out):
        pc = int(out[i], 16)
        fns, loc = [out[i + 1]], re.sub(r" \(discriminator \d+\)", "", out[i + 2].rsplit("/", 1)[-1])
        i += 3
        while i < len(out) and not out[i].startswith("0x"):
            fns.append(out[i])  # (the inlining callers)
            i += 2
        res[pc] = (fns, loc)
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("elf")
    ap.add_argument("qemu_log", nargs="?")
    ap.add_argument("ticks_log", nargs="?")
    ap.add_argument("--dfilter", action="store_true")
    ap.add_argument("--line", required=True, help="engine,arith,cycle (STEP_TRACE)")
    ap.add_argument("--class", dest="cls", default="moving", choices=list(CLASSES) + ["all", "worst"])
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--depth", type=int, default=1,
                    help="name a function with this many of its inlining callers (1: the innermost alone)")
    ap.add_argument("--prefix", default="arm-none-eabi-")
    a = ap.parse_args()
    line = a.line.split(",")
    if len(line) != 3 or line[0] not in ("spring", "scene") or line[1] not in ("f32", "q31") or \
            line[2] not in ("grips", "afm"):
        print("step_trace: TRACE=%s is not a line of make step-cost (engine,arith,cycle: spring|scene, "
              "f32|q31, grips|afm)" % a.line, file=sys.stderr)
        sys.exit(2)
    if a.depth < 1 or a.top < 1:
        ap.error("--depth and --top count from 1")
    if not a.dfilter and (a.qemu_log is None or a.ticks_log is None):
        ap.error("the trace and the ticks' log are needed")
    syms = symbols(a.elf, a.prefix)
    timed = "timed_%s_%s" % (line[0], line[1])  # (the timing function of the line's step)
    if a.dfilter:
        print(dfilter(a.elf, a.prefix, syms, timed))
        return
    lo, hi = syms[timed]
    ticks = ticks_of(a.qemu_log, lo, hi, {v[0] for k, v in syms.items() if k.startswith("mdr_")})
    counts = []  # (read after the trace: QEMU writes both at once, the trace may be a pipe)
    with open(a.ticks_log) as fh:
        for row in fh:
            if row.startswith("tick,"):
                k, c = row.strip().split(",")[2:]
                counts.append((int(k), int(c)))
    # the timing function is also called for its empty step (16 times, first)
    ticks = ticks[len(ticks) - len(counts):] if counts else []
    if not counts or len(ticks) != len(counts):
        sys.exit("step_trace: %d ticks in the trace, %d counted" % (len(ticks), len(counts)))
    bad = [i for i, (t, (k, _)) in enumerate(zip(ticks, counts)) if len(t) != k]
    if bad:
        sys.exit("step_trace: %d ticks differ, the first: %s" % (len(bad), ", ".join(
            "tick %d: %d in the trace, %d counted" % (j + 1, len(ticks[j]), counts[j][0]) for j in bad[:6])))
    if a.cls == "worst":  # the line's max: the first of its longest ticks
        w = max(range(len(counts)), key=lambda j: (counts[j][0], -j))
        print("the worst tick is tick %d (class %d)" % (w + 1, counts[w][1]))
        sel = [ticks[w]]
    else:
        sel = [t for t, (_, c) in zip(ticks, counts) if a.cls == "all" or c == CLASSES[a.cls]]
    if not sel:
        sys.exit("step_trace: no %s ticks" % a.cls)
    nm = names(a.elf, {pc for t in sel for pc in t}, a.prefix)
    by_fn, by_line = collections.Counter(), collections.Counter()
    for t in sel:
        for pc in t:
            fns, loc = nm[pc]
            fn = " < ".join(fns[:a.depth])
            by_fn[fn] += 1
            by_line[(loc, fn)] += 1
    n = float(len(sel))
    total = sum(by_fn.values()) / n
    print("%d %s ticks of %d, %.1f instructions each (trace and count agree on every tick)"
          % (len(sel), a.cls, len(counts), total))
    head = "function" if a.depth == 1 else "function < its inlining callers"
    for title, cnt in ((head, by_fn), ("source line (%s)" % head, by_line)):
        print("\n%-9s %s" % ("instr/tick", title))
        top = cnt.most_common(a.top)
        for key, k in top:
            print("%9.1f  %s" % (k / n, key if isinstance(key, str) else "%s (%s)" % key))
        rest = sum(cnt.values()) - sum(k for _, k in top)
        if rest:
            print("%9.1f  (the other %d)" % (rest / n, len(cnt) - len(top)))


if __name__ == "__main__":
    main()
