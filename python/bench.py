# SPDX-License-Identifier: MIT
"""Benchmark of the Python package (make python-bench): what the C loops
save. All figures come from one run on this machine, so they can be
compared with each other; absolute times are not portable, the ratios are
the claim. Each time is the best of REPEAT runs (the least disturbed).

1. c.eq over 1e6 radii (one call, the loop in C) against a Python loop of
   scalar calls c.eq(a) (timed over SCALAR_N calls, per call x 1e6).
   Goal: at least 50x.
2. Engine.run of a 2 001-tick path (an approach-retract cycle through the
   pull-off, a machine of 0.2 N/m) against the C step's time per tick,
   measured in the same run by the same C loop (mdrpy_run) without arrays
   or events, and the fixed cost of a run (a 2-tick path). Goal: the run's
   time per tick beyond the fixed cost within 2x of the C step's.
3. mdr.fit of a 1 000-point noisy retract (docs/fitting.md's scene) against
   the C call it makes (mdrpy_fit_*) on buffers prepared once: the
   package's overhead per fit.

    /usr/bin/python3 python/bench.py [fit]  (after make python; fit: part 3 only)
    /usr/bin/python3 python/bench.py fit --readme python/README.md   (part 3 into it)
"""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mdr  # noqa: E402
from mdr import ffi, lib  # noqa: E402

REPEAT = 21
SCALAR_N = 20000


def best(fn, repeat=REPEAT, setup=None):
    t = []
    for _ in range(repeat):
        if setup:
            setup()
        t0 = time.perf_counter_ns()
        fn()
        t.append(time.perf_counter_ns() - t0)
    return min(t) * 1e-9


def best_pair(f, g, repeat=REPEAT):
    """best() of two calls timed alternately (the same conditions for both:
    a call of milliseconds varies by 10 % between runs on a shared machine,
    more than the overhead that the pair measures)"""
    a, b = [], []
    for _ in range(repeat):
        t0 = time.perf_counter_ns()
        f()
        a.append(time.perf_counter_ns() - t0)
        t0 = time.perf_counter_ns()
        g()
        b.append(time.perf_counter_ns() - t0)
    return min(a) * 1e-9, min(b) * 1e-9


def bench_eq():
    print("## c.eq: one call over 1e6 radii against a Python loop of scalar calls\n")
    print("| profile | arith | vector, ns/radius | scalar call, ns | scalar / vector |")
    print("| --- | --- | --- | --- | --- |")
    rows = []
    for profile, params in (("paraboloid", dict(R=10e-6)), ("sphere", dict(R=10e-6)),
                            ("wavy", dict(R=10e-6, h=1e-8, lam=5e-7))):
        for arith in ("f64", "f32"):
            c = mdr.Contact(profile, E=1e6, w=0.05, arith=arith, **params)
            a = np.linspace(1e-8, 9e-6, 1000000)
            tv = best(lambda: c.eq(a), repeat=7) / a.size
            sub = [float(v) for v in a[:: a.size // SCALAR_N]]

            def loop():
                for v in sub:
                    c.eq(v)
            ts = best(loop, repeat=3) / len(sub)
            rows.append((profile, arith, tv, ts / tv))
            print("| %s | %s | %.1f | %.0f | %.0f |" % (profile, arith, tv * 1e9, ts * 1e9, ts / tv))
    short = [r for r in rows if r[3] < 50]
    print("\ngoal >= 50x: met for %d of %d%s\n" % (len(rows) - len(short), len(rows), "".join(
        "; NOT MET for %s %s (%.0fx): its kernel alone takes %.0f ns a radius, so a scalar call's Python "
        "overhead cannot be 50x of it" % (p, a, r, tv * 1e9) for p, a, tv, r in short)))


def bench_run():
    print("## Engine.run of a 2 001-tick path against the C step\n")
    print("| arith | C step, ns/tick | run of 2 001 ticks, us | fixed cost (2-tick run), us |"
          " run per tick beyond the fixed cost, ns | / C step |")
    print("| --- | --- | --- | --- | --- | --- |")
    worst = 0
    c = mdr.Contact("paraboloid", E=1e6, w=0.05, R=10e-6)
    path = np.array([0.0, 1e-6, -20e-6])
    steps = 1000
    n = 1 + 2 * steps
    for arith in ("f32", "f64", "q31"):
        eng = mdr.Engine(c, springs=1024, w_adv=0.025, k_machine=0.2, arith=arith, a_max=12e-6)
        run = eng.run(path, control="machine", steps_per_segment=steps)
        assert run.pull_off is not None and len(run) == n
        pp = ffi.from_buffer("double[]", path)
        ev_n, done = ffi.new("size_t *"), ffi.new("size_t *")
        N = ffi.NULL

        def c_loop():
            st = lib.mdrpy_run(eng._x, lib.MDR_CONTROL_MACHINE, pp, path.size, steps, 0, n, N, N, N, N, N, 0, ev_n,
                               N, N, N, done)
            assert st == lib.MDR_OK and done[0] == n
        t_c = best(c_loop, setup=eng.reset) / n
        t_run = best(lambda: eng.run(path, control="machine", steps_per_segment=steps), setup=eng.reset)
        t_fix = best(lambda: eng.run(path[:2], control="machine", steps_per_segment=1), setup=eng.reset)
        per_tick = (t_run - t_fix) / (n - 2)
        worst = max(worst, per_tick / t_c)
        print("| %s | %.1f | %.1f | %.1f | %.1f | %.2f |" % (arith, t_c * 1e9, t_run * 1e6, t_fix * 1e6,
                                                              per_tick * 1e9, per_tick / t_c))
    print("\nlargest ratio: %.2f (goal <= 2: %s); a run costs its fixed cost plus that per tick\n"
          % (worst, "met" if worst <= 2 else "NOT MET"))


def bench_fit():
    print("## mdr.fit against the C fit kernel it calls\n")
    print("The scene of docs/fitting.md's Speed (make bench-fit): paraboloid R = 20 nm, E* = 1 GPa, "
          "w = 0.05 J/m^2, k_m = 0.2 N/m, an engine curve (1 024 springs) with a 1 000-point retract and "
          "1 % noise (two-point: 0.1 %, at which it answers), fitted with unpinned=True (the curve's truth: "
          "its noisy straight retract is refused without); the C time is the same call (mdrpy_fit_*: mdr_fit_curve and the samples' "
          "conversion) on buffers prepared once, measured in this run.\n")
    print("| method | arith | C kernel, us | mdr.fit, us | overhead, us | mdr.fit / C |")
    print("| --- | --- | --- | --- | --- | --- |")
    R, E, w, k = 20e-9, 1e9, 0.05, 0.2
    c = mdr.Contact("paraboloid", E=E, w=w, R=R)
    run = mdr.Engine(c, springs=1024, w_adv=w, k_machine=k).run([-1e-8, 2e-8, -4e-8], control="machine",
                                                                 steps_per_segment=1000)
    top = int(np.argmax(run.z))
    z, F0 = run.z[top:], run.F[top:]
    worst = 0.0
    # (two-point at 0.1 % noise: at 1 % through this lever it refuses the
    # curve, MDR_E_DEGENERATE, as it does most such curves: docs/fitting.md)
    for method, arith, noise in (("full", "f64", 0.01), ("full", "f32", 0.01), ("two-point", "f64", 0.001)):
        F = F0 + noise * float(np.max(np.abs(F0))) * np.random.default_rng(1).standard_normal(F0.size)
        tip = mdr.Contact("paraboloid", E=1.0, w=0.0, R=R, arith=arith)
        # (unpinned: the curve's truth, w_adv = w; without it the noisy straight
        # retract through this lever is refused, MDR_E_PINNED)
        res = mdr.fit(z, F, tip, k_machine=k, method=method, arith=arith, unpinned=True)
        n = z.size
        work = ffi.new("%s[]" % tip._T, lib.mdrpy_fit_work_len(n))
        out, fail = ffi.new("mdrpy_fit_res *"), ffi.new("size_t *")
        zp, Fp = ffi.from_buffer("double[]", z), ffi.from_buffer("double[]", F)
        fn = getattr(lib, "mdrpy_fit_" + arith)
        code = mdr.fitting.METHODS[method]

        def kernel():
            assert fn(tip._c, k, 0.3e-9, 0.0, 0.0, code, 0, 1, 0, zp, Fp, n, work, len(work), out, fail) == lib.MDR_OK
        t_c, t_py = best_pair(kernel, lambda: mdr.fit(z, F, tip, k_machine=k, method=method, arith=arith,
                                                      unpinned=True), 3 * REPEAT)
        assert out.E == res.E  # the same answer
        if method == "two-point":
            worst = t_py - t_c  # (the shortest call: the overhead above its noise)
        print("| %s | %s | %.0f | %.0f | %.1f | %.2f |" % (method, arith, t_c * 1e6, t_py * 1e6, (t_py - t_c) * 1e6,
                                                          t_py / t_c))
    print("\nmdr.fit's fixed overhead (argument checks, array copies, the result object, a Contact of the "
          "fitted E*, w): %.0f us a call, from the two-point row (a full fit's milliseconds vary between calls "
          "on a shared machine by more than the overhead: its rows' differences are that noise)\n" % (worst * 1e6))


def main():
    print("mdr %s, numpy %s, Python %s\n" % (mdr.__version__, np.__version__, sys.version.split()[0]))
    bench_eq()
    bench_run()
    bench_fit()


def into_readme(fn, path, marker):
    """Run fn, print its output and put it into the file at path between
    <!-- marker:begin --> and <!-- marker:end -->."""
    import contextlib
    import io

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        fn()
    print(buf.getvalue(), end="")
    with open(path) as f:
        text = f.read()
    begin, end = "<!-- %s:begin -->\n" % marker, "<!-- %s:end -->" % marker
    i, j = text.index(begin) + len(begin), text.index(end)
    with open(path, "w") as f:
        md = "\n".join("**%s**" % ln[3:] if ln.startswith("## ") else ln for ln in buf.getvalue().splitlines())
        f.write(text[:i] + "\n" + md.strip() + "\n\n" + text[j:])


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--readme":
        # the tables also into README.md between its python-bench markers
        into_readme(main, sys.argv[2], "python-bench")
    elif len(sys.argv) == 4 and sys.argv[1:3] == ["fit", "--readme"]:
        # part 3 into python/README.md between its python-fit-bench markers
        into_readme(bench_fit, sys.argv[3], "python-fit-bench")
    elif sys.argv[1:] == ["fit"]:
        bench_fit()
    else:
        main()
