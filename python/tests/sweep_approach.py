# SPDX-License-Identifier: MIT
"""The figures of docs/fitting.md's known defect "A pinned top that
--approach misses" (stop 59): a grid around helper-35's curves and 600
random curves each without and with hysteresis, fitted with approach=True;
statuses and the answers beyond 5 reported errors. Not a test (about 30 s):
    PYTHONPATH=python /usr/bin/python3 python/tests/sweep_approach.py
"""
import math
import os
import sys
from collections import Counter

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jkr_curves  # noqa: E402
import mdr  # noqa: E402


def fit(z, F, R, E, w, k):
    """the status and, answered, the worst of the two distances in errors"""
    try:
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True)
    except mdr.Error as e:
        return e.status, None
    return "ok", max(abs(math.log(r.E / E)) / (r.E_err / r.E), abs(math.log(r.w / w)) / (r.w_err / r.w))


def report(label, res):
    c = Counter(st for st, _ in res)
    devs = [d for _, d in res if d is not None]
    print("%s: %d curves, %s, %d beyond 5 errors (worst %.1f)" % (label, len(res), sorted(c.items()),
                                                                  sum(d > 5 for d in devs), max(devs, default=0)))


def grid():
    R, E, w, k = 1.93e-7, 1.55e9, 0.222, 1.25
    res = []
    for ra in (0.0, 0.25, 0.5):
        for n in (100, 200, 400, 600):
            for top in (0.5, 0.8, 1.1, 1.4):
                for noise in (0.003, 0.01):
                    for seed in range(3):
                        z, F, _ = jkr_curves.curve(R, E, w, ra * w, k, n, top, 1.0, noise, seed=seed)
                        res.append(fit(z, F, R, E, w, k))
    report("grid around helper-35's curves (w_adv/w 0, 1/4, 1/2)", res)


def random(label, ratios, seed0):
    rng = np.random.default_rng(seed0)
    res = []
    for i in range(600):
        R, E, w = 10 ** rng.uniform(-8.3, -6.3), 10 ** rng.uniform(6, 10.5), 10 ** rng.uniform(-2, -0.5)
        k, n, noise = 10 ** rng.uniform(-1.3, 1.3), int(10 ** rng.uniform(1.4, 2.8)), 10 ** rng.uniform(-3.5, -1.5)
        wa = w * rng.choice(ratios)
        top, free = rng.uniform(0.5, 4), rng.uniform(0.3, 1.5)
        z, F, _ = jkr_curves.curve(R, E, w, wa, k, n, top, free, noise, Fb=0.1, seed=i)
        res.append(fit(z, F, R, E, w, k))
    report(label, res)


if __name__ == "__main__":
    grid()
    random("random, no hysteresis", [1.0], 11)
    random("random, w_adv/w 0, 1/4, 1/2", [0.0, 0.25, 0.5], 12)
