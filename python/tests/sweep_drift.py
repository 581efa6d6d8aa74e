# SPDX-License-Identifier: MIT
"""The figures of docs/fitting.md on z as a file writes it (helper-83's
attack, stop 79; the errors with z's written unit, stop 80): random
noise-free (or slightly noisy) curves (jkr_curves, f64; half of them
sweep_written's broad ranges, half stiff contacts through soft levers) whose
positions are rounded to whole units of a few digits below the mean step's
leading one, in 15 families: fixed decimals of a uniform grid, %.Ne, a
progression within a small part of a unit of a whole number of units (with
rows lost or written twice), an uneven whole-unit grid scaled by a
calibration of 0.2 to 10 units over its span, jittered or nonlinear
positions, exact decimal z with noisy or written F, rows written twice, the
approach fitted too; F at the positions before rounding. Per family: the
curves answered, refused, and the answers off (more than 5 reported errors
and 1e-3 of the truth in E* or w); seeds 1 (200 curves a family) and 2
(300). Not a test (about 2 minutes):
    PYTHONPATH=python /usr/bin/python3 python/tests/sweep_drift.py
Another commit's figures: the same command with PYTHONPATH at its python/.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jkr_curves  # noqa: E402

import mdr  # noqa: E402

FAMILIES = ("fixed_nm", "sig_m", "near_int", "near_int_lost", "near_int_dup", "drift_grid", "jitter", "nonlinear",
            "exact_noise", "dups", "approach", "drift_grid_noisy", "near_int_lost_noisy", "jitter_noisy",
            "fixed_nm_noisy")
RUNS = ((200, 1), (300, 2))  # (curves a family, seed)
PULL, REL = 5.0, 1e-3  # off: beyond PULL reported errors and REL of the truth


def _base(rng):
    """curve parameters: half broad (sweep_written's ranges), half stiff
    contacts through soft levers (sweep_irregular's)"""
    if rng.uniform() < 0.5:
        R, E, w = 10 ** rng.uniform(-8.3, -6.3), 10 ** rng.uniform(6, 10.5), 10 ** rng.uniform(-2.5, -0.5)
        k, n = 10 ** rng.uniform(-1.3, 1.3), int(10 ** rng.uniform(1.4, 3))
        top, free = rng.uniform(0.5, 4), rng.uniform(0.3, 1.5)
    else:
        R, E, w = 10 ** rng.uniform(-7.6, -6.5), 10 ** rng.uniform(9.8, 10.4), 10 ** rng.uniform(-2.5, -1)
        k, n = 10 ** rng.uniform(-1.3, -0.4), int(10 ** rng.uniform(1.4, 3))
        top, free = rng.uniform(1, 3), rng.uniform(0.8, 1.5)
    wa = w * float(rng.choice((0.0, 0.25, 0.5, 1.0)))
    z0 = float(rng.choice((0.0, rng.uniform(0, 1e-5))))
    return dict(R=R, E=E, w=w, wa=wa, k=k, n=n, top=top, free=free, z0=z0, noise=0.0, seed=int(rng.integers(1 << 30)))


def cases(fam, N, seed):
    """N curves' parameters of family fam"""
    rng = np.random.default_rng([seed, sum(map(ord, fam))])
    out = []
    noisy = fam.endswith("_noisy")
    if noisy:  # a small noise on F: 1e-5 to 3e-3 of the pull-off force, or none
        fam = fam[:-6]
    for _ in range(N):
        c = _base(rng)
        if noisy:
            c["noise"] = float(rng.choice((0.0, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3)))
        c["fam"], c["approach"] = fam, False
        if fam == "fixed_nm":  # a uniform grid, z written with fixed decimals
            c["down"], c["conv"] = int(rng.integers(-1, 4)), str(rng.choice(["m", "nm"]))
        elif fam == "sig_m":  # %.Ne in metres
            c["sig"] = int(rng.integers(4, 10))
        elif fam in ("near_int", "near_int_lost", "near_int_dup"):  # steps (m + delta) units
            c["down"] = int(rng.integers(0, 3))
            c["delta"] = float(rng.choice((-1, 1)) * 10 ** rng.uniform(-4.5, -1.5))
            c["phase"] = float(rng.uniform(0, 1))
            c["conv"] = str(rng.choice(["m", "nm"]))
            if fam != "near_int":
                c["p"] = float(10 ** rng.uniform(-1.7, -0.8))
                c["dropseed"] = int(rng.integers(1 << 30))
        elif fam == "drift_grid":  # an uneven whole-unit grid times (1 + eps): a calibration
            c["down"] = int(rng.integers(0, 3))
            c["phase"], c["phase2"] = float(rng.uniform(0, 1)), float(rng.uniform(0, 1))
            c["wraps"] = float(10 ** rng.uniform(-0.7, 1.0)) * float(rng.choice((-1, 1)))
            c["conv"] = str(rng.choice(["m", "nm"]))
        elif fam == "jitter":
            c["down"], c["jit"] = int(rng.integers(0, 4)), float(rng.uniform(0.02, 0.45))
            c["jseed"] = int(rng.integers(1 << 30))
        elif fam == "nonlinear":  # a piezo's nonlinearity
            c["down"] = int(rng.integers(-1, 4))
            c["a"], c["b"] = float(rng.uniform(-0.15, 0.15)), float(rng.uniform(-0.3, 0.3))
            c["conv"] = str(rng.choice(["m", "nm"]))
        elif fam == "exact_noise":  # exact decimal z (uneven whole units), F noisy and/or written
            c["down"], c["phase"] = int(rng.integers(0, 3)), float(rng.uniform(0, 1))
            c["noise"] = float(rng.choice((0.0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2)))
            c["Fsig"] = int(rng.choice((0, 0, 6, 8, 10, 12)))
        elif fam == "dups":  # a uniform grid with fixed decimals, rows written twice
            c["down"], c["conv"] = int(rng.integers(-1, 4)), "m"
            c["p"] = float(10 ** rng.uniform(-1.7, -0.8))
            c["dropseed"] = int(rng.integers(1 << 30))
        elif fam == "approach":  # one of four families with the approach fitted
            sub = str(rng.choice(["near_int", "drift_grid", "fixed_nm", "near_int_lost"]))
            c = cases(sub, 1, int(rng.integers(1 << 30)))[0]
            c["approach"] = True
            c["wa"] = c["w"] * float(rng.choice((0.0, 0.25, 0.5)))
        out.append(c)
    return out


def _unit_exp(za, n, down):
    """the exponent (of nm) of the unit `down` digits below the mean step's leading one"""
    zn = za * 1e9
    return math.floor(math.log10((zn[-1] - zn[0]) / (n - 1))) - down


def _write(z, e, conv):
    """z [m] rounded to whole units 10^e nm, read back as a file in m (conv
    'm') or in nm times 1e-9 ('nm')"""
    m = np.round(z * 1e9 / 10.0 ** e)
    if conv == "m":
        return np.array([float("%de%d" % (int(v), e - 9)) for v in m])
    if e <= 0:
        return np.array([float("%.*f" % (-e, v * 10.0 ** e)) for v in m]) * 1e-9
    return np.array([float("%d" % (int(v) * 10 ** e)) for v in m]) * 1e-9


def curve(c):
    """z as written and F of the curve of c"""
    fam, n = c["fam"], c["n"]
    st = {}

    def snap(za):
        e = st["e"] = _unit_exp(za, n, c.get("down", 0))
        u = 10.0 ** e
        if fam in ("near_int", "near_int_lost", "near_int_dup"):
            um = u * 1e-9
            step = (max(1, math.ceil((za[-1] - za[0]) / (n - 1) / um)) + c["delta"]) * um
            return (za[-1] - c["phase"] * um) - (n - 1 - np.arange(n)) * step
        if fam in ("drift_grid", "exact_noise"):
            g = (np.floor(za * 1e9 / u + c["phase"]) - 1) * u  # whole units [nm], the top moved down
            if fam == "exact_noise":
                return np.array([float("%de%d" % (int(round(v / u)), e - 9)) for v in g])
            eps = c["wraps"] * u / (g[-1] - g[0])
            return (g + eps * (g - g[-1]) - c["phase2"] * u) * 1e-9
        if fam == "jitter":
            j = np.random.default_rng(c["jseed"]).uniform(-1, 1, n) * c["jit"] * ((za[-1] - za[0]) / (n - 1))
            j[-1] = -abs(j[-1])
            return za + j
        if fam == "nonlinear":
            x = (za - za[0]) / (za[-1] - za[0])
            return za[0] + (za[-1] - za[0]) * (x + c["a"] * x * (1 - x) + c["b"] * x * (1 - x) * (x - 0.5))
        return za

    z, F, _ = jkr_curves.curve(c["R"], c["E"], c["w"], c["wa"], c["k"], n, c["top"], c["free"], c["noise"],
                               z0=c["z0"], Fb=0.1, seed=c["seed"], snap=snap)
    if fam == "sig_m":
        z = np.array([float("%.*e" % (c["sig"] - 1, v)) for v in z])
    elif fam == "exact_noise":
        if c["Fsig"]:
            F = np.array([float("%.*e" % (c["Fsig"] - 1, v)) for v in F])
    else:
        z = _write(z, st["e"], c.get("conv", "m"))
    if "p" in c:  # rows lost (near_int_lost) or written twice; never the ends or the top
        sel = np.random.default_rng(c["dropseed"]).uniform(size=z.size) < c["p"]
        sel[[0, n - 2, n - 1, n, n + 1, 2 * n - 1]] = False
        if fam == "near_int_lost":
            z, F = z[~sel], F[~sel]
        else:
            rep = np.where(sel, 2, 1)
            z, F = np.repeat(z, rep), np.repeat(F, rep)
    return z, F


def fit(c):
    """'refused', 'ok' or 'off'"""
    try:
        z, F = curve(c)
    except ValueError:
        return None  # (a parameter set the generator cannot make)
    try:
        r = mdr.fit(z, F, "paraboloid", R=c["R"], k_machine=c["k"], approach=c["approach"])
    except mdr.Error:
        return "refused"
    dev = max(abs(r.E - c["E"]) / r.E_err if r.E_err > 0 else math.inf,
              abs(r.w - c["w"]) / r.w_err if r.w_err > 0 else math.inf)
    rel = max(abs(r.E / c["E"] - 1), abs(r.w / c["w"] - 1))
    return "off" if dev > PULL and rel > REL else "ok"


def main():
    tot = {"ok": 0, "off": 0, "refused": 0}
    print("%-20s %9s %9s %9s" % ("family", "answered", "refused", "off"))
    for fam in FAMILIES:
        cnt = {"ok": 0, "off": 0, "refused": 0}
        for N, seed in RUNS:
            for c in cases(fam, N, seed):
                res = fit(c)
                if res is not None:
                    cnt[res] += 1
        for k in tot:
            tot[k] += cnt[k]
        print("%-20s %9d %9d %9d" % (fam, cnt["ok"] + cnt["off"], cnt["refused"], cnt["off"]), flush=True)
    print("%-20s %9d %9d %9d" % ("all", tot["ok"] + tot["off"], tot["refused"], tot["off"]))


if __name__ == "__main__":
    main()
