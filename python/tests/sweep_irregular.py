# SPDX-License-Identifier: MIT
"""The figures of docs/fitting.md on z on a decimal grid with irregular steps
(stop 79): 100 random noise-free stiff contacts through soft levers
(jkr_curves, f64; R 25 to 300 nm, E* 6 to 25 GPa, w 3 to 100 mJ/m^2, w_adv
w/4 or w/2, 0.1 to 0.4 N/m, 80 to 320 samples a branch, z0 0 to 10 um), each
in binary and with z moved down to whole units 0, 1 and 2 digits below the
mean step's leading one (test_fit.py's _piezo_decimal, a random phase; F
computed at those z), and with z rounded down alike but F computed at the
positions before (a file's rounding of z, units 0 to 3 digits below):
per row the curves refused and the answers off by more than 5 reported
errors and 1e-3. Not a test (about 20 seconds):
    PYTHONPATH=python /usr/bin/python3 python/tests/sweep_irregular.py [seed]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jkr_curves  # noqa: E402
import mdr  # noqa: E402
from test_fit import _piezo_decimal  # noqa: E402


def main():
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    rows = {d: [0, 0, 0] for d in (-1, 0, 1, 2)}
    rounded = {d: [0, 0, 0] for d in (0, 1, 2, 3)}
    rng = np.random.default_rng(seed)
    for i in range(100):
        R, E, w, k, n, rest = _draw(rng)
        for digits in (-1, 0, 1, 2):
            snap = None if digits < 0 else _piezo_decimal(digits, rng.uniform(0, 1))
            z, F, _ = jkr_curves.curve(R, E, w, *rest, seed=i, snap=snap)
            _count(rows[digits], z, F, R, E, w, k)
    rng = np.random.default_rng(seed)  # (the same curves)
    for i in range(100):
        R, E, w, k, n, rest = _draw(rng)
        z, F, _ = jkr_curves.curve(R, E, w, *rest, seed=i)
        for digits in (0, 1, 2, 3):
            za = _piezo_decimal(digits, rng.uniform(0, 1))(z[:n])
            _count(rounded[digits], np.concatenate([za, za[::-1]]), F, R, E, w, k)
    for d, (m, refused, off) in rows.items():
        name = "binary z " if d < 0 else "exact z, unit %d down" % d
        print("%s: %d curves, %d refused, %d off beyond 5 errors and 1e-3" % (name, m, refused, off))
    for d, (m, refused, off) in rounded.items():
        print("rounded z, unit %d down: %d curves, %d refused, %d off beyond 5 errors and 1e-3" % (d, m, refused, off))


def _draw(rng):
    """a stiff contact through a soft lever: R, E, w, k, n and the rest of
    jkr_curves.curve's arguments after w"""
    R, E, w = 10 ** rng.uniform(-7.6, -6.5), 10 ** rng.uniform(9.8, 10.4), 10 ** rng.uniform(-2.5, -1)
    k, n = 10 ** rng.uniform(-1, -0.4), int(10 ** rng.uniform(1.9, 2.5))
    wa = w * rng.choice((0.25, 0.5))
    top, free, z0 = rng.uniform(1, 3), rng.uniform(0.8, 1.5), rng.uniform(0, 1e-5)
    return R, E, w, k, n, (wa, k, n, top, free, 0.0, z0, 0.1)


def _count(row, z, F, R, E, w, k):
    """one more curve in row (curves, refused, off)"""
    row[0] += 1
    try:
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    except mdr.Error:
        row[1] += 1
        return
    row[2] += _off(r, E, w)


def _off(r, E, w):
    """beyond 5 reported errors and 1e-3 of the truth"""
    dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
    return dev > 5 and max(abs(r.E / E - 1), abs(r.w / w - 1)) > 1e-3


if __name__ == "__main__":
    main()
