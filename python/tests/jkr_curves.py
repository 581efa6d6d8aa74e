# SPDX-License-Identifier: MIT
"""Approach-retract AFM curves of a paraboloid tip from the JKR closed forms
(numpy only: no libmdr), for the fit's tests.

JKR equilibrium at contact radius a (E* the effective modulus, w the work
of adhesion):  d = a^2/R - sqrt(2 pi w a/E*),  F = 4/3 E* a^3/R -
sqrt(8 pi w E* a^3); through a lever of stiffness k the base position is
z = z0 + d + F/k. The approach (w_adv) is free (F = 0) below z' = 0,
touches there and follows its stable branch; the retract follows the
branch of w (pinned at the top radius, F linear in d with slope 2 E* a_t,
while w_adv < w and the pinned line lies above that branch) down to its
fold under the lever (dz'/da = 0: the pull-off), then is free. A
baseline Fb + tilt (z'/span) in units of the pull-off force, and Gaussian
noise of `noise` times it.
"""
import numpy as np


def _d(a, R, E, w):
    return a * a / R - np.sqrt(2 * np.pi * w * a / E)


def _F(a, R, E, w):
    return 4.0 / 3.0 * E * a**3 / R - np.sqrt(8 * np.pi * w * E * a**3)


def _zp(a, R, E, w, k):
    return _d(a, R, E, w) + _F(a, R, E, w) / k


def _bisect(fun, lo, hi):
    """the root of fun (negative at lo, positive at hi, elementwise),
    halving in log space to rounding"""
    lo, hi = np.broadcast_arrays(np.asarray(lo, float), np.asarray(hi, float))
    lo, hi = lo.copy(), hi.copy()
    for _ in range(400):
        mid = np.sqrt(lo * hi)
        neg = fun(mid) < 0
        lo, hi = np.where(neg, mid, lo), np.where(neg, hi, mid)
        if np.all(hi / lo - 1 < 1e-15):
            break
    return np.sqrt(lo * hi)


def _fold(R, E, w, k):
    """the contact radius of the lever's fold on the branch of w (0 for w = 0)"""
    if w == 0:
        return 0.0

    def slope(a):
        return 2 * a / R - 0.5 * np.sqrt(2 * np.pi * w / (E * a)) + (
            4 * E * a * a / R - 1.5 * np.sqrt(8 * np.pi * w * E * a)) / k

    hi = R
    while slope(hi) < 0:
        hi *= 10
    return float(_bisect(slope, 1e-30, hi))


def _a_at(zp, R, E, w, k, lo, hi):
    zp = np.asarray(zp, float)
    return _bisect(lambda a: _zp(a, R, E, w, k) - zp, np.full(zp.shape, lo), np.full(zp.shape, hi))


def curve(R, E, w, w_adv, k, n, top, free, noise, z0=2e-6, Fb=0.0, tilt=0.0, seed=0, snap=None):
    """n samples each way, in time order (approach, then retract). top: the
    largest force in units of the pull-off force |F_c|; free: the free
    path below the pull-off in units of the contact part's span. snap: a
    function that moves the approach's base positions z (absolute, the
    same reversed for the retract) to the exact ones the curve is computed
    at (a piezo's decimal grid); the top then the last of them. Returns
    z, F and the pull-off force F_c (negative)."""
    ac = _fold(R, E, w, k)
    zc, Fc = float(_zp(ac, R, E, w, k)), float(_F(ac, R, E, w))
    aa = _fold(R, E, w_adv, k) if w_adv > 0 else 0.0
    hi = R
    while _F(hi, R, E, w_adv) < top * abs(Fc):
        hi *= 2
    a0 = (9 * np.pi * w_adv * R * R / (2 * E)) ** (1 / 3) if w_adv > 0 else 1e-30  # F = 0
    at = float(_bisect(lambda a: _F(a, R, E, w_adv) - top * abs(Fc), max(a0, aa, 1e-30), hi))
    zt = float(_zp(at, R, E, w_adv, k))
    zpa = np.linspace(zc - free * (zt - zc), zt, n)
    if snap is not None:
        zpa = snap(zpa + z0) - z0
        zt = float(zpa[-1])
    zpr = zpa[::-1].copy()
    Fa, Fr = np.zeros(n), np.zeros(n)
    on = zpa >= 0
    Fa[on] = _F(_a_at(zpa[on], R, E, w_adv, k, max(aa, 1e-30), at * (1 + 1e-7)), R, E, w_adv)
    if snap is not None:
        at = float(_a_at(np.array([zt]), R, E, w_adv, k, max(aa, 1e-30), at * (1 + 1e-7))[0])
    if w_adv < w:  # pinned at a_t down to the branch of w (or to the fold)
        zend = float(_zp(at, R, E, w, k))
        S = 2 * E * at
        pin = zpr >= zend
        Fr[pin] = _F(at, R, E, w_adv) + S * (zpr[pin] - zt) / (1 + S / k)
        rec = (zpr < zend) & (zpr >= (zc if at > ac else zend))
    else:
        rec = zpr >= zc
    Fr[rec] = _F(_a_at(zpr[rec], R, E, w, k, ac, at * (1 + 1e-7)), R, E, w)
    zp = np.concatenate([zpa, zpr])
    F = np.concatenate([Fa, Fr]) + abs(Fc) * (Fb + tilt * zp / (zt - zpa[0]))
    F = F + np.random.default_rng(seed).normal(0, noise * abs(Fc), F.size)
    return zp + z0, F, Fc
