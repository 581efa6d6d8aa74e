# SPDX-License-Identifier: MIT
"""The figures of docs/fitting.md's "z's rounding at the pull-off" (stop 81):
300 random noisy curves in realistic AFM ranges (jkr_curves, f64; R 5 to
50 nm, E* 0.5 to 20 GPa, w 10 to 100 mJ/m^2, w_adv w/4 to w, levers 0.05
to 1 N/m, 100 to 1 000 samples a branch, noise 1e-4 to 3e-3 of the
pull-off force, piezo offsets 0 to 5 um), each fitted with z as computed
(binary) and as a file writes it: in nm with 1, 2 or 3 decimals, and C's
%g (6 significant digits, in metres). Per way of writing z: the curves
answered, the refusals by status, and the answers off (more than 5
reported errors and 1e-3 of the truth in E* or w). Not a test (about 5
minutes):
    PYTHONPATH=python /usr/bin/python3 python/tests/sweep_nm.py
Another commit's figures: the same command with PYTHONPATH at its python/.
"""
import os
import re
import sys
from collections import Counter

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jkr_curves  # noqa: E402

import mdr  # noqa: E402

FORMATS = ("binary", "nm3", "nm2", "nm1", "g6")
PULL, REL = 5.0, 1e-3  # off: beyond PULL reported errors and REL of the truth


def _written(z, fmt):
    """z [m] as a file with format fmt writes it, read back"""
    if fmt == "binary":
        return z
    if fmt.startswith("nm"):
        return np.array([float("%.*f" % (int(fmt[2:]), v)) for v in z * 1e9]) * 1e-9
    return np.array([float("%g" % v) for v in z])


def _status(e):
    m = re.search(r"\((MDR_E_[A-Z0-9_]+)\)", str(e))
    return m.group(1) if m else "error"


def main():
    rng = np.random.default_rng(11)
    res = {f: [Counter(), 0] for f in FORMATS}
    for _ in range(300):
        R = 10 ** rng.uniform(np.log10(5e-9), np.log10(5e-8))
        E = 10 ** rng.uniform(8.7, 10.3)
        w = 10 ** rng.uniform(-2, -1)
        wa = w * rng.uniform(0.25, 1.0)
        k = 10 ** rng.uniform(-1.3, 0)
        n = int(10 ** rng.uniform(2, 3))
        top, free = rng.uniform(1, 4), rng.uniform(0.5, 1)
        noise = 10 ** rng.uniform(-4, -2.5)
        z0 = rng.uniform(0, 5e-6)
        seed = int(rng.integers(1 << 30))
        z, F, _ = jkr_curves.curve(R, E, w, wa, k, n, top, free, noise, z0=z0, Fb=0.1, seed=seed)
        for fmt in FORMATS:
            try:
                r = mdr.fit(_written(z, fmt), F, "paraboloid", R=R, k_machine=k)
            except mdr.Error as e:
                res[fmt][0][_status(e)] += 1
                continue
            res[fmt][0]["answered"] += 1
            dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
            if dev > PULL and max(abs(r.E / E - 1), abs(r.w / w - 1)) > REL:
                res[fmt][1] += 1
    print("%-8s %9s %5s  %s" % ("z", "answered", "off", "refused"))
    for fmt in FORMATS:
        c, off = res[fmt]
        ref = ", ".join("%s %d" % (s, m) for s, m in sorted(c.items()) if s != "answered")
        print("%-8s %9d %5d  %s" % (fmt, c["answered"], off, ref))


if __name__ == "__main__":
    main()
