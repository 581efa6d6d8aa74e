# SPDX-License-Identifier: MIT
"""The figures of docs/fitting.md's "Curves as written down" (stop 78): 300
random noise-free curves (jkr_curves, f64; R 5 nm to 0.5 um, E* 1 MPa to
30 GPa, w 3 mJ to 0.3 J/m^2, w_adv 0, w/4, w/2 or w, 0.05 to 20 N/m, 25 to
1 000 samples a branch, z0 0 to 10 um), each with F on an ADC's grid of
1e-6 to 1e-3 pull-off forces, and with z and F written with 5 to 17
significant digits: the fits' statuses, the answers beyond 5 reported
errors and those of them more than 1e-3 off. Not a test (about 2 minutes):
    PYTHONPATH=python /usr/bin/python3 python/tests/sweep_written.py
"""
import math
import os
import sys
from collections import Counter

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jkr_curves  # noqa: E402
import mdr  # noqa: E402
from test_fit import _written as written  # noqa: E402  (as test_written_curve writes them)

CASES = (("grid", 1e-6), ("grid", 1e-5), ("grid", 1e-4), ("grid", 1e-3), ("digits", 5), ("digits", 6),
         ("digits", 7), ("digits", 9), ("digits", 12), ("digits", 15), ("digits", 17))


def main():
    rng = np.random.default_rng(7)
    res = {c: [] for c in CASES}
    for i in range(300):
        R, E, w = 10 ** rng.uniform(-8.3, -6.3), 10 ** rng.uniform(6, 10.5), 10 ** rng.uniform(-2.5, -0.5)
        k, n = 10 ** rng.uniform(-1.3, 1.3), int(10 ** rng.uniform(1.4, 3))
        wa = w * rng.choice((0, 0.25, 0.5, 1.0))
        top, free, z0 = rng.uniform(0.5, 4), rng.uniform(0.3, 1.5), rng.uniform(0, 1e-5)
        z, F, Fc = jkr_curves.curve(R, E, w, wa, k, n, top, free, 0.0, z0=z0, Fb=0.1, seed=i)
        for kind, v in CASES:
            if kind == "grid":
                q = v * abs(Fc)
                zz, FF = z, np.round(F / q) * q
            else:
                zz, FF = written(z, v), written(F, v)
            try:
                r = mdr.fit(zz, FF, "paraboloid", R=R, k_machine=k)
            except mdr.Error as e:
                res[(kind, v)].append((e.status, None, None))
                continue
            dev = max(abs(math.log(r.E / E)) / (r.E_err / r.E), abs(math.log(r.w / w)) / (r.w_err / r.w))
            res[(kind, v)].append(("ok", dev, max(abs(r.E / E - 1), abs(r.w / w - 1))))
    for c in CASES:
        st = Counter(s for s, _, _ in res[c])
        off = [(d, e) for s, d, e in res[c] if s == "ok" and d > 5]
        print("%-6s %-5g: %3d answered, %2d beyond 5 errors, %d of them more than 1e-3 off; refused %s" % (
            c[0], c[1], st["ok"], len(off), sum(e > 1e-3 for _, e in off),
            ", ".join("%s %d" % (s, m) for s, m in sorted(st.items()) if s != "ok")))


if __name__ == "__main__":
    main()
