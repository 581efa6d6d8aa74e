# SPDX-License-Identifier: MIT
"""mdr.fit (libmdr's fit kernel, lib/include/mdr_fit.h): round trips on
curves made by the spring engine (mdr.Engine under machine control: a
forward model independent of the fit's, which follows the contact module's
equilibrium) and by JKR closed forms worked out here; sampled and worn
tips; the result against `mdr fit --curve` (the same C code); every
refusal.

Tolerances, relative; the worst error measured in brackets (printed at the
end of the run). The issue asks for E*, w, z0 to 1e-6 in f64: every f64
bound below is tighter.
  ENG64 = 2e-9     f64 E*, w, z0, F_base, w_adv (and F_slope of a tilted
                   one) from an engine curve (paraboloid; its table holds g
                   exactly) [3.4e-13]
  ENG32 = 1e-3     f32 the same; the curve's z carries a 1 um offset that
                   float keeps to 6e-14 m, 6e-5 of the indentation
                   (host_tests/test_fit_cli.sh) [1.4e-5]
  MODEL64 = 3e-10  f64 the fitted model against the engine curve, relative
                   to its largest force [5.1e-14]
  JKR64 = 9e-8     f64 E*, w, z0, F_base, pull-off force from the JKR
                   closed-form curve (bisection to rounding here) [3.2e-12]
  WORN = 1e-5      f64 worn tip from an engine curve: the engine's table
                   smears the rim over one spring (test_fit_cli.sh: 1e-5,
                   measured 1.0e-6 there) [5.4e-6]; f32: ENG32 [6.5e-6]
  TWO = 0.2        two-point method, E* (the CLI test's bound; a method of
                   two points, not a fit)
  PULL = 5         reported errors: |estimate - truth| of w_adv on noisy
                   closed-form curves (jkr_curves.py) [printed by the test]
  F32FIT = 5e-5    an f32 answer's E*, w against the truth where beyond 3
                   of its reported errors (f32's promise: the fit checks
                   it against f64's fit of the same samples and refuses
                   beyond, MDR_E_PARAM) [printed by the test]
  0                against `mdr fit --curve`: every JSON field equal (f64
                   printed with 17 digits, f32 with 9: compared as floats),
                   and model() equal to `--model`'s column
"""
import json
import math
import subprocess

import numpy as np
import pytest

import jkr_curves
import mdr
from conftest import ROOT, Worst

ENG = {"f64": 2e-9, "f32": 1e-3}
MODEL64, JKR64, WORN, TWO, PULL, F32FIT = 3e-10, 9e-8, 1e-5, 0.2, 5.0, 5e-5
within = Worst("test_fit")


def rel(x, want):
    return abs(x / want - 1)


def engine_curve(c, k=0.2, path=(-1e-8, 2e-8, -4e-8), steps=1000, z0=1e-6, Fb=2e-10, w_adv=None, arith="f64"):
    """An approach-retract curve of the spring engine under machine control
    (as host_tests/test_fit_cli.sh's cycle()), offset by z0 and Fb."""
    eng = mdr.Engine(c, springs=1024, w_adv=c.w if w_adv is None else w_adv, k_machine=k, arith=arith)
    run = eng.run(list(path), control="machine", steps_per_segment=steps)
    return run.z + z0, run.F + Fb


SCENES = [  # (E*, w, R, k_machine, path)
    (1e9, 0.05, 20e-9, 0.2, (-1e-8, 2e-8, -4e-8)),
    (2e9, 0.08, 20e-9, 0.2, (-1e-8, 2e-8, -6e-8)),
    (1e9, 0.02, 50e-9, 1.0, (-1e-8, 2e-8, -4e-8)),
]


@pytest.mark.parametrize("arith", ["f64", "f32"])
@pytest.mark.parametrize("scene", SCENES, ids=["afm", "stiffer", "blunt"])
def test_engine_round_trip(cli, tmp_path, scene, arith):
    """E*, w, z0, F_base (and w_adv with approach=True) recovered from the
    engine's curve; the result equals `mdr fit --curve` field for field."""
    E, w, R, k, path = scene
    c = mdr.Contact("paraboloid", E=E, w=w, R=R)
    z, F = engine_curve(c, k=k, path=path)
    res = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, arith=arith, approach=True)
    tol = ENG[arith]
    for q, want in (("E", E), ("w", w), ("z0", 1e-6), ("F_base", 2e-10), ("w_adv", w)):
        assert within(rel(getattr(res, q), want), tol, "engine " + arith), (q, res)
    assert res.method == "full" and res.iterations > 0 and res.n == 1 + (len(z) - 1) // 2
    assert res.n_approach == (len(z) - 1) // 2
    mu = (R * w**2 / (E**2 * 0.3e-9**3)) ** (1 / 3)  # Tabor, the default z_e
    assert rel(res.mu, mu) < 10 * tol and res.R_mu == pytest.approx(R, rel=tol)
    assert res.regime == ("JKR" if res.mu >= 5 else "transition" if res.mu > 0.1 else "DMT")
    # the Contact form gives the same answer, and its E*, w are not used
    res2 = mdr.fit(z, F, mdr.Contact("paraboloid", E=3.0, w=7.0, R=R), k_machine=k, arith=arith, approach=True)
    assert res2.as_dict() == res.as_dict()
    assert res.contact.E == res.E and res.contact.w == res.w and res.contact.profile == "paraboloid"
    # the CLI on the same samples: every field
    curve = tmp_path / "c.csv"
    curve.write_text("z,F\n" + "".join("%.17g,%.17g\n" % zf for zf in zip(z, F)))
    model = tmp_path / "m.csv"
    p = subprocess.run([cli, "fit", "--curve", str(curve), "--profile", "paraboloid", "--R", "%.17g" % R,
                        "--k-machine", "%.17g" % k, "--arith", arith, "--approach", "--model", str(model)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    js = json.loads(p.stdout)
    same = (lambda a, b: np.float32(a) == np.float32(b)) if arith == "f32" else (lambda a, b: a == b)
    for key, val in res.as_dict().items():
        assert same(val, js[key]) if isinstance(val, float) else val == js[key], (key, val, js[key])
    assert set(js) - set(res.as_dict()) == {"status", "input", "units"}  # (the CLI echoes its inputs)
    # model(): the CLI's --model column, the approach and retract branches
    Fm, top = res.model()
    cols = np.loadtxt(model, delimiter=",", skiprows=1, usecols=(0, 1, 2))
    assert np.array_equal(cols[:, 0], z) and np.array_equal(cols[:, 2], Fm) and top == (len(z) - 1) // 2
    if arith == "f64":
        assert within(float(np.max(np.abs(Fm - F)) / np.max(np.abs(F))), MODEL64, "model f64")


def test_two_point_tilted_short_tail():
    """The two-point method on a tilted baseline (+-2 %, +-5 % of the pull-off
    force across the curve) with a short free tail (0.1 to 0.4 of the
    contact part's span), jkr_curves' closed forms through levers of 0.01 to
    100 N/m, approach and retract, noise 0 to 0.3 %: every answer within
    PULL of its reported errors in ln E* and ln w, or refused (helper-61,
    stop 68: where the tail's line was not read, its mean was, and the tilt
    was in neither the answer nor its errors: 7 of 324 answers of these
    400 curves beyond PULL, the worst E* 0.09 x the truth at 14 errors; the
    helper's, a 2.5 um sphere through 0.0105 N/m, 300 samples, 0.01 %
    noise, -5 %: 0.02 x at 49). Now 300 answers, the worst 2.1 errors."""
    rng = np.random.default_rng(68)
    lu = lambda a, b: float(np.exp(rng.uniform(np.log(a), np.log(b))))
    answered, worst = 0, 0.0
    for s in range(400):
        R, E, w, k = lu(5e-9, 1e-5), lu(1e5, 1e11), lu(1e-3, 1), lu(0.01, 100)
        n = int(rng.choice([40, 100, 300]))
        noise = float(rng.choice([0, 1e-4, 1e-3, 3e-3]))
        tilt = float(rng.choice([-0.05, -0.02, 0.02, 0.05]))
        top, free = lu(1.5, 6), float(rng.uniform(0.1, 0.4))
        z, F, _ = jkr_curves.curve(R, E, w, w, k, n, top, free, noise, tilt=tilt, seed=s)
        try:
            r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, method="two-point", unpinned=True)
        except mdr.Error as e:
            assert e.status in ("MDR_E_DEGENERATE", "MDR_E_MISFIT", "MDR_E_FEW"), (s, e.status)
            continue
        answered += 1
        dev = max(abs(math.log(r.E / E)) / (r.E_err / r.E), abs(math.log(r.w / w)) / (r.w_err / r.w))
        worst = max(worst, dev)
        assert dev <= PULL, (s, R, E, w, k, n, noise, tilt, free, r.E / E, r.w / w, dev)
    print("two-point, tilted, short tail: %d of 400 answered, worst %.2f errors" % (answered, worst))
    assert answered >= 200


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_tilted_baseline(cli, tmp_path, arith):
    """A tilted baseline (F + s (z - z0), s = 3e-3 N/m: 4 % of the pull-off
    force over the curve) on the engine's curve: E*, w, z0, F_slope and
    F_base (the baseline at z0) recovered as from the flat curve (ENG);
    model() carries the slope (the CLI's --model column, field for field);
    flat_baseline=True holds F_slope at 0 and, on the flat curve, answers
    as the slope's fit within ENG with smaller errors."""
    c = mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9)
    z, F = engine_curve(c)
    s = 3e-3
    Ft = F + s * (z - 1e-6)
    tol = ENG[arith]
    res = mdr.fit(z, Ft, "paraboloid", R=20e-9, k_machine=0.2, arith=arith)
    for q, want in (("E", 1e9), ("w", 0.05), ("z0", 1e-6), ("F_slope", s), ("F_base", 2e-10)):
        assert within(rel(getattr(res, q), want), 10 * tol if q == "F_base" else tol, "engine " + arith), (q, res)
    assert res.F_slope_err > 0 and "F_slope" in res.as_dict() and "F_slope_err" in res.as_dict()
    Fm, top = res.model()
    if arith == "f64":
        assert within(float(np.max(np.abs(Fm - Ft)) / np.max(np.abs(Ft))), MODEL64, "model f64")
    curve, model = tmp_path / "t.csv", tmp_path / "m.csv"
    curve.write_text("z,F\n" + "".join("%.17g,%.17g\n" % zf for zf in zip(z, Ft)))
    p = subprocess.run([cli, "fit", "--curve", str(curve), "--profile", "paraboloid", "--R", "2e-08",
                        "--k-machine", "0.2", "--arith", arith, "--model", str(model)], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    cols = np.loadtxt(model, delimiter=",", skiprows=1, usecols=(0, 1, 2))
    assert np.array_equal(cols[:, 2], Fm)
    flat = mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, arith=arith, flat_baseline=True)
    free = mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, arith=arith)
    assert flat.F_slope == 0 and flat.F_slope_err == 0
    for q, want in (("E", 1e9), ("w", 0.05), ("z0", 1e-6)):
        assert within(rel(getattr(flat, q), want), tol, "engine " + arith), (q, flat)
    assert flat.E_err < free.E_err and flat.w_err <= free.w_err


def test_slope_degenerate_hint():
    """The slope's price: 2 % noise and 10 nm of free path in each branch
    (the noise drawn with seed 3) do not determine E* with the slope fitted:
    MDR_E_DEGENERATE, its message naming what to do; flat_baseline=True
    answers (within 5 errors)."""
    c = mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9)
    z, F = engine_curve(c, path=(-1e-8, 2e-8, -3.5e-8), steps=750, z0=2e-6, Fb=3e-10)
    F = F + 1e-10 * np.random.default_rng(3).standard_normal(len(F))
    err = raises("MDR_E_DEGENERATE", z, F, "paraboloid", R=20e-9, k_machine=0.2, approach=True)
    assert "flat_baseline=True" in str(err)
    res = mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, approach=True, flat_baseline=True)
    assert abs(res.E - 1e9) <= 5 * res.E_err


def jkr_retract(E, w, R, k, n=1200, z0=0.0, Fb=0.0):
    """The retract of a JKR paraboloid through a machine of stiffness k,
    from closed forms: d(a) = a^2/R - sqrt(2 pi w a/E*), F(a) = 4E* a^3/(3R)
    - 2E* a sqrt(2 pi w a/E*), base z'(a) = d + F/k. The contact follows
    the stable branch (dz'/da > 0) down to the fold, then jumps off (F = 0,
    z' = d). z' from 3 pull-off radii down past the fold; a(z') by
    bisection."""
    def zp(a):
        dl = np.sqrt(2 * np.pi * w * a / E)
        d = a * a / R - dl
        F = 4 * E * a**3 / (3 * R) - 2 * E * a * dl
        return d + F / k, F

    def dzp(a):
        s = np.sqrt(2 * np.pi * w / E)
        return 2 * a / R - 0.5 * s / np.sqrt(a) + (4 * E * a * a / R - 3 * E * s * np.sqrt(a)) / k

    lo, hi = 1e-30, 10 * R
    for _ in range(400):  # the fold: dz'/da = 0 (one root: dz'/da rises through 0)
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if dzp(mid) < 0 else (lo, mid)
    af = 0.5 * (lo + hi)
    ac = (9 * np.pi * w * R * R / (8 * E)) ** (1 / 3)
    ztop, zf = zp(3 * ac)[0], zp(af)[0]
    z = np.linspace(ztop, zf - 0.4 * (ztop - zf), n)
    F = np.zeros(n)
    on = z >= zf
    lo, hi = np.full(on.sum(), af), np.full(on.sum(), 3 * ac)
    for _ in range(200):  # a(z') on the stable branch, z' increasing in a
        mid = 0.5 * (lo + hi)
        up = zp(mid)[0] < z[on]
        lo, hi = np.where(up, mid, lo), np.where(up, hi, mid)
    F[on] = zp(0.5 * (lo + hi))[1]
    return z + z0, F + Fb, zp(af)[1]


JKR_SCENES = [  # (E*, w, R, k): AFM, soft AFM, micro-gripper finger
    (1e9, 0.05, 20e-9, 0.2),
    (1e6, 0.05, 10e-6, 0.5),
    (1e5, 0.02, 2e-3, 200.0),
]


@pytest.mark.parametrize("scene", JKR_SCENES, ids=["afm", "soft", "gripper"])
def test_jkr_closed_form_round_trip(scene):
    E, w, R, k = scene
    z0, Fb = 3e-7 * (R / 20e-9) ** 0.5, -1e-3 * 1.5 * math.pi * w * R
    z, F, F_fold = jkr_retract(E, w, R, k, z0=z0, Fb=Fb)
    res = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    for q, want in (("E", E), ("w", w), ("z0", z0), ("F_base", Fb)):
        assert within(rel(getattr(res, q), want), JKR64, "jkr f64"), (q, res)
    assert within(rel(res.pull_off_F, F_fold), JKR64, "jkr f64")
    assert res.n == len(z)
    # f32 too, at the bound of the engine's f32 round trip
    res32 = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, arith="f32")
    for q, want in (("E", E), ("w", w)):
        assert within(rel(getattr(res32, q), want), ENG["f32"], "engine f32"), (q, res32)
    # two-point method: the pull-off force and the zero-force point only
    two = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, method="two-point")
    assert two.method == "two-point" and two.iterations == 0 and rel(two.E, E) < TWO
    # first guesses
    g = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, E0=2 * E, w0=0.6 * w)
    assert within(rel(g.E, E), JKR64, "jkr f64") and within(rel(g.w, w), JKR64, "jkr f64")


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_sampled_tip(arith):
    """A sampled paraboloid fits as the paraboloid (the samples' model holds
    it exactly), its Tabor radius from the apex samples; a worn tip's
    engine curve fitted with its samples."""
    R, E, w = 20e-9, 1e9, 0.05
    z, F = engine_curve(mdr.Contact("paraboloid", E=E, w=w, R=R))
    r = np.arange(161) * 0.25e-9
    res = mdr.fit(z, F, "table", r=r, f=r * r / (2 * R), k_machine=0.2, arith=arith)
    for q, want in (("E", E), ("w", w), ("z0", 1e-6)):
        assert within(rel(getattr(res, q), want), ENG[arith], "engine " + arith), (q, res)
    assert rel(res.R_mu, R) < 10 * ENG[arith] and res.contact.profile == "table"
    # the worn tip (flat to b = 1.5 nm): its engine curve from the samples
    b = 1.5e-9
    fw = np.where(r < b, 0.0, (r * r - b * b) / (2 * R))
    tip = mdr.Contact("table", E=E, w=w, r=r, f=fw)
    zw, Fw = engine_curve(tip)
    res = mdr.fit(zw, Fw, tip, k_machine=0.2, arith=arith)
    for q, want in (("E", E), ("w", w)):
        assert within(rel(getattr(res, q), want), max(WORN, ENG[arith]), "worn " + arith), (q, res)
    a = res.a_pull_off  # no apex curvature: R_mu = a_c^2/g(a_c), g = (a/R) sqrt(a^2 - b^2)
    assert rel(res.R_mu, a * a / ((a / R) * math.sqrt(a * a - b * b))) < 1e-6


def test_header_constants():
    """The package's default z_e is the header's."""
    import re

    with open(ROOT + "/lib/include/mdr_fit.h") as f:
        m = re.search(r"#define MDR_FIT_Z_E_DEFAULT ([0-9.e+-]+)", f.read())
    assert float(m.group(1)) == mdr.fitting.Z_E_DEFAULT


@pytest.fixture(scope="module")
def curve():
    c = mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9)
    return engine_curve(c)


def raises(status, *args, **kw):
    with pytest.raises(mdr.Error) as err:
        mdr.fit(*args, **kw)
    assert err.value.status == status, str(err.value)
    return err.value


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_refusals(curve, arith):
    z, F = curve
    tip = dict(R=20e-9, k_machine=0.2, arith=arith)
    top = int(np.argmax(z))
    raises("MDR_E_FEW", z[-5:], F[-5:], "paraboloid", **tip)  # too few points
    e = raises("MDR_E_FEW", z[:top + 6], F[:top + 6], "paraboloid", **tip)
    assert "needs" in str(e)
    raises("MDR_E_NOCONTACT", z[-400:], np.full(400, 1e-12), "paraboloid", **tip)  # no contact
    raises("MDR_E_NOPULLOFF", z[:1400], F[:1400], "paraboloid", **tip)  # never separates (test_fit_cli.sh)
    for arr in ("z", "F"):  # NaN, inf: the sample named
        for bad in (np.nan, np.inf):
            zz, FF = z.copy(), F.copy()
            (zz if arr == "z" else FF)[1500] = bad
            e = raises("MDR_E_NONFINITE", zz, FF, "paraboloid", **tip)
            assert e.index == 1500 and "sample 1500" in str(e)
    zz = z.copy()
    zz[1600] = zz[1599] + 1e-12  # z rises within the retract
    e = raises("MDR_E_ORDER", zz, F, "paraboloid", **tip)
    assert e.index == 1600
    if arith == "f32":
        zz = z.copy()
        zz[7] = 1e39
        e = raises("MDR_E_OVERFLOW", zz, F, "paraboloid", **tip)
        assert e.index == 7
    for k in (0.0, -0.2):
        raises("MDR_E_PARAM", z, F, "paraboloid", R=20e-9, k_machine=k, arith=arith)
    raises("MDR_E_NONFINITE", z, F, "paraboloid", R=20e-9, k_machine=np.nan, arith=arith)
    raises("MDR_E_PARAM", z, F, "paraboloid", z_e=0.0, **tip)
    raises("MDR_E_PARAM", z, F, "paraboloid", E0=1e9, **tip)  # E0 without w0
    with pytest.raises(TypeError, match="numpy.loadtxt"):  # a file name (helper-22, stop 54)
        mdr.fit("nosuch.csv", None, "paraboloid", **tip)
    raises("MDR_E_PARAM", z, F, "paraboloid", E0=-1e9, w0=0.05, **tip)
    raises("MDR_E_PARAM", z, F, "paraboloid", method="lsq", **tip)
    raises("MDR_E_KIND", z, F, "flatpunch", a0=1e-8, k_machine=0.2, arith=arith)
    raises("MDR_E_KIND", z, F, "banana", R=1e-8, k_machine=0.2, arith=arith)
    raises("MDR_E_PARAM", z, F[:-1], "paraboloid", **tip)
    raises("MDR_E_PARAM", z[:2000].reshape(2, -1), F[:2000].reshape(2, -1), "paraboloid", **tip)
    raises("MDR_E_PARAM", z, F, "paraboloid", R=-1.0, k_machine=0.2, arith=arith)  # the profile's refusal
    with pytest.raises(ValueError):
        mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, arith="q31")
    with pytest.raises(TypeError):
        mdr.fit(z, F, mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9), k_machine=0.2, R=20e-9)
    with pytest.raises(TypeError):
        mdr.fit(z, F, "paraboloid", k_machine=0.2)  # missing R
    with pytest.raises(TypeError):
        mdr.fit(z, F, 3.0, k_machine=0.2)
    # (a helper's finds, stop 39) a bool is no stiffness, a string no flag, a
    # masked sample no sample, an empty curve no curve
    with pytest.raises(TypeError):
        mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=True, arith=arith)
    for flag in ("approach", "unpinned", "flat_baseline"):
        with pytest.raises(TypeError):
            mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, arith=arith, **{flag: "no"})
        with pytest.raises(TypeError):
            mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, arith=arith, **{flag: 2})
    # samples that are no real numbers: complex ones were fitted by their real
    # part with only numpy's ComplexWarning (helper-28, stop 57)
    for bad in (F + 0j, F.astype(object), F > 0):
        with pytest.raises(TypeError, match="fit: F must be real numbers"):
            mdr.fit(z, bad, "paraboloid", **tip)
    with pytest.raises(TypeError, match="fit: z must be real numbers"):
        mdr.fit(z + 1e-30j, F, "paraboloid", **tip)
    zm = np.ma.masked_array(z, mask=np.arange(len(z)) == 5)
    with pytest.raises(ValueError):
        mdr.fit(zm, F, "paraboloid", **tip)
    with pytest.raises(ValueError):
        mdr.fit(z, np.ma.masked_array(F, mask=np.arange(len(F)) == 5), "paraboloid", **tip)
    raises("MDR_E_FEW", z[:0], F[:0], "paraboloid", **tip)


def test_units_hint(curve):
    """A curve in nm (z alone, then z and F, then F alone in nN) is refused
    with a hint asking for SI units (it was the slope's or the pinned top's
    hint, a diagnosis of the curve's shape: helper-56, helper-66)."""
    z, F = curve
    for fs in (1.0, 1e9):
        with pytest.raises(mdr.Error) as err:
            mdr.fit(z * 1e9, F * fs, "paraboloid", R=20e-9, k_machine=0.2)
        assert "must be in metres and newtons (SI)" in err.value.hint, str(err.value)
    # F alone in nN (helper-66, stop 71: MDR_E_DEGENERATE with the baseline
    # slope's hint): the hint names F's span
    with pytest.raises(mdr.Error) as err:
        mdr.fit(z, F * 1e9, "paraboloid", R=20e-9, k_machine=0.2)
    assert err.value.hint.startswith("F spans ") and "must be in metres and newtons (SI)" in err.value.hint, \
        str(err.value)


def test_outlier_hint(curve):
    """One outlier above the top inside the retract moves the retract's start
    there: the refusal's hint names that sample (helper-56)."""
    z, F = curve
    z = z.copy()
    i = int(np.argmax(z)) + (len(z) - int(np.argmax(z))) // 2
    z[i] = 5e-6
    with pytest.raises(mdr.Error) as err:
        mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2)
    assert "the retract is the part from the largest z on: sample %d (z = 5e-06 m)" % i in err.value.hint, \
        str(err.value)


def test_hidden_pinned_top(curve):
    """Through the 0.2 N/m lever with noise of 1 % of the pull-off force the
    whole retract is straight within its noise: a pinned top could hide in
    it (w_adv = w/2: E* 33-46 % high, docs/fitting.md), so the fit refuses
    unless the caller (unpinned=True) or the approach (w_adv within 6 errors
    of w) rules it out. Estimates within 5 reported errors."""
    c = mdr.Contact("paraboloid", E=1e9, w=0.05, R=20e-9)
    rng = np.random.default_rng(3)
    for w_adv in (0.05, 0.025):
        z, F = engine_curve(c, w_adv=w_adv)
        F = F + 0.01 * np.max(np.abs(F - 2e-10)) * rng.standard_normal(len(F))
        raises("MDR_E_PINNED", z, F, "paraboloid", R=20e-9, k_machine=0.2)
        if w_adv < 0.05:
            err = raises("MDR_E_PINNED", z, F, "paraboloid", R=20e-9, k_machine=0.2, approach=True)
            # the hint says what the approach found (helper-56: the message's
            # "fit with the approach" read as if it had not been given)
            assert err.hint.startswith("with approach=True: the approach did not rule a pinned top out"), err.hint
            continue
        for kw in (dict(approach=True), dict(unpinned=True)):
            res = mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2, **kw)
            assert abs(res.E - 1e9) <= 5 * res.E_err and abs(res.w - 0.05) <= 5 * res.w_err, (kw, res)


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_wadv_at_its_bound(arith):
    """w_adv's fit stops at its bound 0 only as a limit, never on it: at
    s = sqrt(w_adv) = 0 the model's force at fixed z is Hertz's to first
    order in w_adv, so every cost is stationary there and the fit, once
    projected onto s = 0, stopped there whatever the data, with the error
    2 s sigma_s = 0. A helper's curves without hysteresis (w_adv = w) through
    a 2.6 N/m lever, 3 707 samples a branch, 0.77 % noise, a tilted
    baseline: the retract's false pinned top moves the held E* and z0, and
    w_adv came back 0 +- 0, status ok, in 3 of 30 draws (f64; 2 in f32).
    Every answer within PULL of its errors, none of them 0, and some at the
    bound (w_adv below 1e-2 of w: the case is exercised; f64 stops within
    1e-8 of w of it, f32 within 6e-3)."""
    R, E, w, k = 1.1724835271931731e-06, 258141221.2102252, 0.13875230321587065, 2.5733658037794167
    at_bound, worst = 0, 0.0
    for seed in range(30):
        z, F, _ = jkr_curves.curve(R, E, w, w, k, n=3707, top=14.171884836361553, free=0.7779194795412934,
                                   noise=0.007695096447905933, Fb=-0.00994869684175441,
                                   tilt=-0.027408803961932682, seed=seed)
        res = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True, arith=arith)
        assert res.w_adv_err > 0 and abs(res.w_adv - w) <= PULL * res.w_adv_err, (seed, res)
        at_bound += res.w_adv < 1e-2 * w
        worst = max(worst, abs(res.w_adv - w) / res.w_adv_err)
    print("w_adv at its bound (%s): %d of 30 draws, worst pull %.2f" % (arith, at_bound, worst))
    assert at_bound >= 1



def _vdw_curve(f, D0, seed, n=1000, noise=0.001):
    """jkr_curves' curve (20 nm tip, E* 1 GPa, w 0.05, 0.2 N/m, no
    hysteresis) with a van der Waals-like attraction after the pull-off:
    the free retract less f |F_po| (D0/(D + D0))^2, D the base's travel
    past the lever's fold"""
    R, E, w, k = 20e-9, 1e9, 0.05, 0.2
    z, F, Fc = jkr_curves.curve(R, E, w, w, k, n, 3.0, 1.0, noise, seed=seed)
    zr = z[n:] - 2e-6
    zc = float(jkr_curves._zp(jkr_curves._fold(R, E, w, k), R, E, w, k))
    free = zr < zc
    F[n:][free] -= f * abs(Fc) * (D0 / (zc - zr[free] + D0)) ** 2
    return z, F, R, E, k


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_long_range_tail(arith):
    """A long-range tail after the pull-off (helper-28, stop 57) is a curve
    the model (JKR without long-range forces) does not describe: before
    stop 58 f = 2 % to 10 % of the pull-off force, D0 = 1 to 3 nm, noise
    0.1 %, gave E* 1.01 to 1.15 times the truth, 2 to 10 errors off,
    status ok. Every such curve is refused, MDR_E_MISFIT; weaker tails
    (f = 0.5 %, 1 %) are refused or answered within PULL errors; the
    same curves without the tail are answered within PULL."""
    refused = answered = 0
    worst = 0.0
    for f in (0.0, 0.005, 0.01, 0.02, 0.05, 0.1):
        for D0 in (1e-9, 2e-9, 3e-9):
            for seed in range(4):
                z, F, R, E, k = _vdw_curve(f, D0, seed)
                try:
                    res = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, unpinned=True, arith=arith)
                except mdr.Error as e:
                    assert f > 0 and e.status == "MDR_E_MISFIT", (f, D0, seed, e)
                    assert f >= 0.005, (f, D0, seed)
                    refused += 1
                    continue
                assert f < 0.02, (f, D0, seed, res.E / E)
                pull = abs(res.E - E) / res.E_err
                assert pull <= PULL, (f, D0, seed, pull)
                answered += f > 0
                worst = max(worst, pull) if f > 0 else worst
    print("long-range tail (%s): of 60 tailed curves %d refused, %d answered (f <= 1 %%), worst %.2f errors"
          % (arith, refused, answered, worst))


def test_clean_curves_not_refused_as_tails():
    """The free part's window test (mdr_f_tail_held) on clean curves over a
    wide range (R 5 nm to 1 um, E* 1 MPa to 10 GPa, w 0.01 to 0.3, levers
    0.03 to 30 N/m, 30 to 3 000 samples a branch, noise 0.01 % to 3 %,
    flat or tilted, with and without hysteresis): no MDR_E_MISFIT among
    200 random draws (a false refusal would be one)."""
    rng = np.random.default_rng(1)
    status = {}
    for i in range(200):
        R, E, w = 10 ** rng.uniform(-8.3, -6), 10 ** rng.uniform(6, 10), 10 ** rng.uniform(-2, -0.5)
        k, n, noise = 10 ** rng.uniform(-1.5, 1.5), int(10 ** rng.uniform(1.5, 3.5)), 10 ** rng.uniform(-4, -1.5)
        w_adv = w * rng.choice([1.0, 1.0, 0.5])
        z, F, _ = jkr_curves.curve(R, E, w, w_adv, k, n, rng.uniform(1, 4), rng.uniform(0.2, 2), noise,
                                   Fb=0.1, tilt=rng.choice([0, 0.02]), seed=i)
        try:
            mdr.fit(z, F, "paraboloid", R=R, k_machine=k, unpinned=bool(w_adv == w))
            st = "ok"
        except mdr.Error as e:
            st = e.status
        status[st] = status.get(st, 0) + 1
    print("clean random curves:", sorted(status.items()))
    assert "MDR_E_MISFIT" not in status, status


def test_detector_lag_refused_then_trimmed():
    """A curve whose force went through a first-order detector filter (an RC
    of half a sample) lags the pull-off jump: its first free samples lie far
    below the baseline, a transient the model does not hold. The fit refuses
    it, MDR_E_MISFIT (the free part next to the jump off its line; helper-34,
    stop 58: before the check these curves were answered with E* biased by
    about +1.3 of its errors); with the first 2 free samples dropped, as
    docs/fitting.md advises, every curve is answered within PULL errors."""
    R, E, w, k, n = 20e-9, 1e9, 0.05, 0.2, 1000
    a = math.exp(-2.0)  # tau = 0.5 sample
    worst = 0.0
    for seed in range(8):
        z, F, _ = jkr_curves.curve(R, E, w, w, k, n, 4.0, 1.0, 0.003, Fb=0.1, tilt=0.02, seed=seed)
        y = np.empty_like(F)
        acc = F[0]
        for i, v in enumerate(F):  # y_i = a y_(i-1) + (1 - a) F_i
            acc = a * acc + (1 - a) * v
            y[i] = acc
        with pytest.raises(mdr.Error) as e:
            mdr.fit(z, y, "paraboloid", R=R, k_machine=k, unpinned=True)
        assert e.value.status == "MDR_E_MISFIT", (seed, e.value)
        j = n + int(np.argmax(np.diff(y[n:])))  # the last contact sample
        keep = np.ones(z.size, bool)
        keep[j + 1:j + 3] = False
        res = mdr.fit(z[keep], y[keep], "paraboloid", R=R, k_machine=k, unpinned=True)
        pull = abs(res.E - E) / res.E_err
        assert pull <= PULL, (seed, pull)
        worst = max(worst, pull, abs(res.w - w) / res.w_err)
    print("detector lag (tau 0.5 sample): 8 of 8 refused, answered with 2 samples dropped, worst %.2f errors"
          % worst)


def test_coarse_curve_without_hysteresis():
    """A coarse curve without hysteresis (R 20 nm, E* 1 GPa, w = w_adv =
    0.05, a 2 N/m lever, 51 samples a branch, noise 0.3 %): its receding
    branch's top looks straight within the noise and leaves fewer than 16
    samples below. The default fit refuses it MDR_E_PINNED (a pinned top
    may hide there: the message says to fit the approach or state
    unpinned), approach=True answers it within PULL errors (stop 59; stops
    51 to 58 refused it MDR_E_FEW, "too few points", either way)."""
    R, E, w, k = 20e-9, 1e9, 0.05, 2.0
    answered = 0
    for seed in range(6):
        z, F, _ = jkr_curves.curve(R, E, w, w, k, 51, 2.0, 1.0, 0.003, seed=seed)
        with pytest.raises(mdr.Error) as e:
            mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
        assert e.value.status in ("MDR_E_PINNED", "MDR_E_FEW"), e.value.status
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True)
        assert abs(math.log(r.E / E)) <= PULL * r.E_err / r.E, (seed, r.E / E, r.E_err / r.E)
        assert abs(math.log(r.w / w)) <= PULL * r.w_err / r.w, (seed, r.w / w, r.w_err / r.w)
        answered += 1
    assert answered == 6


def test_low_noise_without_hysteresis():
    """300 random curves without hysteresis at low noise (R 5 to 300 nm, E*
    1 MPa to 10 GPa, w 0.01 to 0.3, levers 0.1 to 20 N/m, 31 to 1 000
    samples a branch, noise 0.01 % to 0.1 %), fitted by default and with
    approach=True: no answer beyond PULL errors, no MDR_E_FEW (helper-28,
    stop 57: a straight start leaving too few samples refused 27 and 27 of
    them "too few points"; stop 59: the default's refusals MDR_E_PINNED,
    294 answered with the approach, 267 before), at least 290 of 300
    answered with the approach. Figures: pytest -s -k low_noise."""
    for approach in (False, True):
        rng = np.random.default_rng(5)
        status, bad = {}, []
        for i in range(300):
            R, E, w = 10 ** rng.uniform(-8.3, -6.5), 10 ** rng.uniform(6, 10), 10 ** rng.uniform(-2, -0.5)
            k, n, noise = 10 ** rng.uniform(-1, 1.3), int(10 ** rng.uniform(1.5, 3)), 10 ** rng.uniform(-4, -3)
            z, F, _ = jkr_curves.curve(R, E, w, w, k, n, rng.uniform(1, 4), rng.uniform(0.2, 2), noise, Fb=0.1, seed=i)
            try:
                r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=approach)
                st = "ok"
                dev = max(abs(math.log(r.E / E)) / (r.E_err / r.E), abs(math.log(r.w / w)) / (r.w_err / r.w))
                if dev > PULL:
                    bad.append((i, dev))
            except mdr.Error as e:
                st = e.status
            status[st] = status.get(st, 0) + 1
        print("low noise, no hysteresis, approach=%s:" % approach, sorted(status.items()))
        assert not bad, bad
        assert "MDR_E_FEW" not in status, status
        if approach:
            assert status.get("ok", 0) >= 290, status


# Known, open defects (helper-35, stop 59; docs/fitting.md "Known defects"):
# silent wrong answers, each a curve of jkr_curves.curve (R, E, w, w_adv, k,
# n, top, free, noise, seed), its options and arithmetic. Strict xfail: a
# fix turns them into passes, which fail the suite until the mark goes.
KNOWN_WRONG = [
    # approach=True misses a pinned top near the fold: w_adv fitted with E*
    # held at the retract's answer passes the hysteresis check
    ("A1", (1.93e-7, 1.55e9, 0.222, 0.0, 1.25, 600, 0.5, 1.0, 0.01), 1, dict(approach=True), "f64"),
    # default options, w_adv = 0.75 w, 30 samples a branch, 1.65 % noise
    ("B1", (3.68222688773627e-08, 4079967.47917802, 0.108539308599417, 0.75 * 0.108539308599417,
            3.712603058030764, 30, 1.7395543782602922, 1.5029825828511876, 0.0165), 3, {}, "f64"),
]

# noise-free, f32 missed the pinned top f64 finds: E* 0.75 off, status ok
# (helper-35's C1, a known defect until f32 answers were checked against f64)
C1 = ((1.2946797545293861e-08, 64039665588.73452, 0.034297295400197124, 0.0, 2.6514226033377333, 157,
       3.366052633015884, 0.20147588126012217, 0.0), 637)


@pytest.mark.parametrize("name,args,seed,opts,arith", KNOWN_WRONG, ids=[c[0] for c in KNOWN_WRONG])
@pytest.mark.xfail(strict=True, reason="known defect (helper-35, stop 59): a silent wrong answer")
def test_known_wrong_answers(name, args, seed, opts, arith):
    """An answer within PULL reported errors, or a named refusal."""
    R, E, w, k = args[0], args[1], args[2], args[4]
    z, F, _ = jkr_curves.curve(*args, seed=seed)
    try:
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, arith=arith, **opts)
    except mdr.Error:
        return
    dev = max(abs(math.log(r.E / E)) / (r.E_err / r.E), abs(math.log(r.w / w)) / (r.w_err / r.w))
    assert dev <= PULL, (name, r.E / E, r.w / w, dev)


# helper-80 (stop 76; docs/fitting.md "Known defects"): pinned tops missed or
# cut short in instrument-like curves, silent wrong answers; each a
# jkr_curves.curve (R, E, w, w_adv, k, n, top, free, noise), its keyword
# arguments, what the instrument does to it (flaw(z, F, Fc) -> z, F) and the
# fit's options (f64). Strict xfail, as KNOWN_WRONG.
def _drift(z, F, Fc):
    """a baseline drifting linearly in time, 0.06 % of the pull-off force over the cycle"""
    return z, F - 0.0006209327136782898 * abs(Fc) * np.arange(F.size) / (F.size - 1)


def _as_is(z, F, Fc):
    return z, F


def _small_glitch(z, F, Fc):
    """helper-81 (stop 77): one sample of the pinned top 0.081 pull-off
    forces high, 8 noise widths, under the 1.5 tolerances of a glitch that
    the straight start leaves out, so the line ends there (a larger one 5
    samples before it is left out)"""
    F = F.copy()
    F[1319] += 0.4743715109332766 * abs(Fc)
    F[1324] += 0.08070719328632511 * abs(Fc)
    return z, F


KNOWN_WRONG_H80 = [
    ("drift", (6.531729339699188e-07, 34091866.83759898, 0.0634612993982725, 0.05837037679800404,
               2.2801082661423484, 1566, 2.4398801183863963, 0.4033229526814466, 0.0003687014850187292),
     dict(seed=85), _drift, dict(approach=True)),
    # noise-free, 7 samples in contact (5 pinned): too few for the straight start
    ("tiny_contact", (1.3306971991886335e-07, 23121456.508901328, 0.4377028473271046, 0.03280656094481652,
                      0.11655192668925304, 100, 2.908045613617874, 15.268032760009259, 0.0),
     dict(seed=68), _as_is, {}),
    # noisy; one glitch of under 1.5 tolerances ends the straight start (E* 1.055 x, w 1.014 x,
    # 19.8 errors off; before stop 77 the first, larger glitch ended it and the fit refused)
    ("small_glitch", (4.4654656018725993e-07, 1969485.5489684741, 0.00820196228747908, 0.00205049057186977,
                      0.24971294114084258, 1210, 4.8970364669941215, 1.1921240387314902, 0.01),
     dict(z0=0, seed=960876), _small_glitch, {}),
]


@pytest.mark.parametrize("name,args,kw,flaw,opts", KNOWN_WRONG_H80, ids=[c[0] for c in KNOWN_WRONG_H80])
@pytest.mark.xfail(strict=True, reason="known defect (helper-80, stop 76): a silent wrong answer")
def test_known_wrong_helper80(name, args, kw, flaw, opts):
    """An answer within PULL reported errors (E*, w and, with the approach,
    w_adv), or a named refusal."""
    R, E, w, w_adv, k = args[:5]
    z, F = flaw(*jkr_curves.curve(*args, **kw))
    try:
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, **opts)
    except mdr.Error:
        return
    dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
    if opts.get("approach"):
        dev = max(dev, abs(r.w_adv - w_adv) / r.w_adv_err)
    assert dev <= PULL, (name, r.E / E, r.w / w, dev)


# helper-80's noise-free curve whose F on an ADC's grid of 3e-6 pull-off
# forces was answered E* 1.21 x, w 6.2 errors off (n_pinned 0, status ok;
# its unrounded samples exact with 60 pinned): the rounding ended the
# pinned top's straight start. Fixed at stop 78 (mdr_f_written, f64); the
# same curve written with 6 to 15 significant digits was answered as off
# (12 digits: E* 1.21 x, 5.6 errors).
H80_ADC = (4.181937063688731e-07, 9289027980.139282, 0.013127881426942021, 0.005298155229193303,
           0.18128919613903974, 167, 1.6170172194168544, 0.6043846583364665, 0.0)


def _written(x, digits):
    """x as a file with that many significant digits keeps it"""
    return np.array([float("%.*e" % (digits - 1, v)) for v in x])


@pytest.mark.parametrize("flaw", ["grid1e-7", "grid1e-6", "grid3.05e-6", "grid1e-5", "grid3e-5", "digits6", "digits7",
                                  "digits9", "digits12", "digits13", "digits14", "digits15"])
def test_written_curve(flaw):
    """helper-80's noise-free curve with F on an ADC's grid of that many
    pull-off forces, or z and F written with that many digits: answered
    within PULL reported errors, its pinned top found (at least 57 of its
    60 pinned samples; 6 digits take 65: the line holds to its rounding
    into the receding branch's first samples)."""
    R, E, w, _, k = H80_ADC[:5]
    z, F, Fc = jkr_curves.curve(*H80_ADC)
    if flaw.startswith("grid"):
        q = float(flaw[4:]) * abs(Fc)
        F = np.round(F / q) * q
    else:
        z, F = _written(z, int(flaw[6:])), _written(F, int(flaw[6:]))
    r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
    assert dev <= PULL and r.n_pinned >= 57, (r.E / E, r.w / w, dev, r.n_pinned)


# helper-82 (stop 78): z on an exact decimal grid (a piezo's uniform steps
# of whole units of its last digit, F computed at those z) with one retract
# row lost or written twice. The first form of the rule took the uneven
# step for a file's rounding of z (half a step), and the straight start
# swallowed the kink where the stiff contact's pinned top meets its
# receding branch through the soft lever: E* 1.15 to 1.57 x at 13 to 22
# errors, n_pinned 0, status ok (f470698: exact). Now z whose steps but
# for 1/16 lie on one grid is taken as unrounded.
H82_GRID = [  # (R, E, w, w_adv, k, n, top, free), z0, seed, digits below the step's leading one, row
    ((2.834498460600735e-08, 7439599425.891973, 0.0954581656608898, 0.02386454141522245, 0.12453004301406125, 95,
      2.6628389008924875, 0.944814443380706), 8.064760508859368e-06, 5001, 0, 4),
    ((2.5482085433354233e-07, 7079714901.0426035, 0.09367374064995025, 0.023418435162487563, 0.3582310553271102,
      196, 1.1059475882200833, 1.0680350060572406), 8.939189106613193e-06, 5279, 0, 10),
    ((7.087719549541681e-08, 21603412885.186565, 0.004254298692994276, 0.002127149346497138, 0.20316864006965898,
      281, 2.218273926210215, 1.4676831609811773), 7.82847313605893e-06, 5126, 1, 9),
]
GRID_REL = 1e-8
SCALE_REL = 0.5  # test_written_irregular: E* from z scaled by one written unit, where the unit refuses


def _unit_exp(za, digits):
    """the exponent (of nm) of the unit `digits` below the leading digit of
    the mean step of the positions za [m]"""
    zn = za * 1e9
    return math.floor(math.log10((zn[-1] - zn[0]) / (len(zn) - 1))) - digits


def _decimals(m, e):
    """whole units m of 10^e nm as the doubles nearest their decimals [m]"""
    return np.array([float("%de%d" % (int(v), e - 9)) for v in m])


def _piezo_grid(digits):
    """a snap for jkr_curves.curve: the approach's z on a uniform grid of
    whole units (digits below the step's leading digit), each the double
    nearest its decimal"""
    def snap(za):
        zn, e = za * 1e9, _unit_exp(za, digits)
        st = max(1, round((zn[-1] - zn[0]) / (len(zn) - 1) / 10.0 ** e))
        return _decimals(math.floor(zn[-1] / 10.0 ** e) - st * np.arange(len(zn))[::-1], e)
    return snap


@pytest.mark.parametrize("case,row", [(c, op) for c in range(len(H82_GRID)) for op in ("lost", "twice")])
def test_written_grid_row(case, row):
    """each curve with one retract row lost or written twice: E* and w
    within GRID_REL of the truth, its pinned top found (as without it)"""
    args, z0, seed, digits, j = H82_GRID[case]
    R, E, w, w_adv, k, n = args[:6]
    z, F, _ = jkr_curves.curve(*args, 0.0, z0=z0, Fb=0.1, seed=seed, snap=_piezo_grid(digits))
    clean = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    if row == "lost":
        z, F = np.delete(z, n + j), np.delete(F, n + j)
    else:
        z, F = np.insert(z, n + j, z[n + j]), np.insert(F, n + j, F[n + j])
    r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    assert max(abs(r.E / E - 1), abs(r.w / w - 1)) <= GRID_REL and abs(r.n_pinned - clean.n_pinned) <= 1, (
        r.E / E, r.w / w, r.n_pinned, clean.n_pinned)


# z on a decimal grid with irregular steps (a piezo's positions moved down
# to whole units of a digit below the mean step's leading one, so its steps
# differ by a unit; F computed at those z), stiff contacts through soft
# levers: taken for a file's rounding of z, the straight start swallowed
# the kink where the pinned top meets the receding branch, E* 1.27 to
# 1.59 x at 8 to 32 errors, n_pinned 0, status ok (stop 79's sweep: 24, 26
# and 5 of 100 such curves, units 0, 1 and 2 digits below the step's).
# mdr_f_zexact: F a smooth function of the z written says z is exact.
IRR_DEC = [  # (R, E, w, w_adv, k, n, top, free), z0, seed, digits below the step's leading one, phase
    ((7.47637062499858e-08, 14193161446.127378, 0.04043492863427725, 0.010108732158569313, 0.3747661462820935, 117,
      2.29709441415965, 1.2873511976691088), 2.9272074901248717e-06, 1, 0, 0.001),
    ((1.2390796367451023e-07, 9525720937.191868, 0.04098595133955803, 0.010246487834889507, 0.2712057449093275, 107,
      2.6597737485486244, 1.2603565476112704), 6.8279890786035034e-06, 3, 1, 0.429),
    ((2.324492788316327e-07, 7267615678.47971, 0.05951857245932448, 0.01487964311483112, 0.17232821897863257, 154,
      2.396852689894187, 1.0043850311914957), 8.711391497935892e-06, 4, 2, 0.400),
    ((3.181422290592121e-08, 13429147525.057083, 0.07623268090594, 0.019058170226485, 0.2176472774452556, 221,
      2.684230774197828, 1.320804440528737), 8.131637391945609e-06, 10, 1, 0.254),
    ((1.1146088099810581e-07, 8023185060.540741, 0.04484823883831598, 0.011212059709578994, 0.36524024113679227, 167,
      1.1285006432960842, 1.0909913467434555), 8.473039702317087e-06, 14, 0, 0.237),
    ((5.1068025829956375e-08, 21479939568.945004, 0.006579656197909452, 0.001644914049477363, 0.2116558792880678, 100,
      2.8038132831550318, 1.4178456558106884), 1.346801677859081e-06, 20, 1, 0.893),
]


def _piezo_decimal(digits, phase):
    """a snap for jkr_curves.curve: each base position moved down to a
    whole unit (digits below the mean step's leading digit; phase in units
    shifts where the steps of a unit more fall), the double nearest its
    decimal; the top moves down too, so the curve stays one of w_adv"""
    def snap(za):
        e = _unit_exp(za, digits)
        return _decimals(np.floor(za * 1e9 / 10.0 ** e + phase) - 1, e)
    return snap


@pytest.mark.parametrize("case", range(len(IRR_DEC)))
def test_written_irregular(case):
    """E* and w within GRID_REL of the truth and the pinned top found, as
    with z in binary (the same curve unsnapped); or refused
    MDR_E_DEGENERATE where z's written unit leaves E* undetermined (the
    errors carry z's scale within a unit over the contact part's span, since
    stop 80: such z cannot be told from a file's rounding that drifts,
    test_written_drift), which the same F with z scaled by one unit over
    that span either way confirms: no answer within SCALE_REL of E*"""
    args, z0, seed, digits, phase = IRR_DEC[case]
    R, E, w, w_adv, k, n = args[:6]
    z, F, _ = jkr_curves.curve(*args, 0.0, z0=z0, Fb=0.1, seed=seed, snap=_piezo_decimal(digits, phase))
    try:
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    except mdr.Error as ex:
        assert ex.status == "MDR_E_DEGENERATE", ex
        unit = 10.0 ** _unit_exp(z[:n], digits) * 1e-9
        jump = n + int(np.argmin(F[n:]))
        for s in (-1, 1):
            zs = z[jump] + (z - z[jump]) * (1 + s * unit / (z[n] - z[jump]))
            try:
                rs = mdr.fit(zs, F, "paraboloid", R=R, k_machine=k)
            except mdr.Error:
                continue
            assert abs(rs.E / E - 1) > SCALE_REL, (s, rs.E / E)
        return
    zb, Fb_, _ = jkr_curves.curve(*args, 0.0, z0=z0, Fb=0.1, seed=seed)
    binary = mdr.fit(zb, Fb_, "paraboloid", R=R, k_machine=k)
    assert max(abs(r.E / E - 1), abs(r.w / w - 1)) <= GRID_REL and abs(r.n_pinned - binary.n_pinned) <= 1, (
        r.E / E, r.w / w, r.n_pinned, binary.n_pinned)


# helper-83 (stop 79): z rounded by a file to whole units of a few digits
# whose rounding errors vary linearly over most of the curve (a grid's
# steps near a whole number of units with rows lost; an uneven grid scaled
# by a few units over its span), F at the positions before. F is a smooth
# function of the z written but where the errors wrap, and mdr_f_zexact
# takes such z for exact (its uneven steps come from the positions, not
# the rounding): answered off with status ok where f81244a refused (47 of
# 7 500 of the helper's curves; 40 refused before). Where the errors do not
# wrap, the z written is the true one scaled within a unit over the span:
# since stop 80 the reported errors carry that scale (mdr_f_written's ez,
# the column MDR_F_ZS), and 41 of the 47 lie within 5 errors, 2 refused.
# The first case's grid drifts by 7.8 units, its rounding wraps 7 times
# and its pinned top is lost (n_pinned 0, E* 1.17 x at 6.9 errors): known
# defect (docs/fitting.md), a strict xfail.
H83 = [  # (R, E, w, w_adv, k, n, top, free), kind, down, (phase, phase2, wraps) or (delta, phase, p, dropseed)
    pytest.param(
        (7.875887233871767e-08, 20818662451.856304, 0.04293499721508571, 0.021467498607542854, 0.25540310280160855,
         980, 1.7249572590970275, 1.2985833146918482), 474682247, "drift", 2,
        (0.07815235138305454, 0.03754733955187606, -7.806013693322661),
        marks=pytest.mark.xfail(strict=True, reason="known defect: a drifted grid whose rounding wraps, taken "
                                "for exact z (mdr_f_zexact), loses its pinned top (helper-83)")),
    ((1.9616905935774065e-07, 5222287908.101501, 0.037268813397865426, 0.0, 0.071710210908473, 411,
      3.4653444591083344, 1.0143840836426683), 63033670, "lost", 2,
     (-0.00024255186989286562, 0.24083164574898752, 0.061501947719779425, 174228027)),
    ((1.3329660730850428e-07, 18368490166.544613, 0.04146100573421805, 0.0, 0.06289339623519523, 668,
      1.991371503362657, 1.3209194178795916), 105635330, "drift", 2,
     (0.2974268321541855, 0.9643176044086891, 0.23689390447400133)),
    ((1.9701302958615118e-07, 15003351571.774277, 0.09429688973906229, 0.047148444869531146, 0.07651452152127382,
      111, 2.2579023994494873, 0.8844294646222476), 501810884, "drift", 2,
     (0.7960714975513338, 0.6106128892372602, 0.640798944058442)),
    ((2.700764269813582e-07, 6755231531.134417, 0.06401717557821139, 0.016004293894552848, 0.11312201963642013,
      109, 2.1180465798731665, 1.0506210870641224), 1031384766, "lost", 2,
     (-0.0006852598464537788, 0.8086975873263418, 0.11172450180974133, 713098713)),
]


def _h83_curve(args, seed, kind, down, q):
    """helper-83's curve: true positions (a drifted whole-unit grid, or a
    progression near a whole number of units), z rounded to the unit as a
    file in m, rows lost at random (never the ends or the top)"""
    n = args[5]
    st = {}

    def snap(za):
        zn, e = za * 1e9, _unit_exp(za, down)
        st["e"], u = e, 10.0 ** e
        if kind == "drift":
            g = (np.floor(zn / u + q[0]) - 1) * u
            return (g + q[2] * u / (g[-1] - g[0]) * (g - g[-1]) - q[1] * u) * 1e-9
        s = (max(1, math.ceil((za[-1] - za[0]) / (n - 1) / (u * 1e-9))) + q[0]) * u * 1e-9
        return (za[-1] - q[1] * u * 1e-9) - (n - 1 - np.arange(n)) * s
    z, F, _ = jkr_curves.curve(*args, 0.0, z0=0.0, Fb=0.1, seed=seed, snap=snap)
    e = st["e"]
    z = _decimals(np.round(z * 1e9 / 10.0 ** e), e)
    if kind == "lost":
        sel = np.random.default_rng(q[3]).uniform(size=z.size) < q[2]
        sel[[0, n - 2, n - 1, n, n + 1, 2 * n - 1]] = False
        z, F = z[~sel], F[~sel]
    return z, F


@pytest.mark.parametrize("args, seed, kind, down, q", H83)
def test_written_drift(args, seed, kind, down, q):
    """answered within PULL reported errors, or refused"""
    R, E, w, k = args[0], args[1], args[2], args[4]
    _within_pull_or_refused(*_h83_curve(args, seed, kind, down, q), R, E, w, k)


def _within_pull_or_refused(z, F, R, E, w, k):
    """the fit of z, F answers E* and w within PULL reported errors, or refuses"""
    try:
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
    except mdr.Error:
        return
    dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
    assert dev <= PULL, (r.E / E, r.w / w, dev, r.n_pinned)


# helper-84's attack on z's written unit in the errors (stop 80): no answer
# it found off or refused was answered otherwise at 6ac3dc8 (before the
# unit), but these remain (known defects, docs/fitting.md; strict xfails):
# z in nm written to 0.01 nm (w 8.9 errors off); z in nm stored as float32
# (a binary rounding, no decimal unit: the pinned top lost, E* 1.17 x at 6.3
# errors, n_pinned 0 against 181 in binary); z written "%.5g" in metres
# across z = 0 (its unit changes through the curve: w 6.2 errors off, 12.6
# at 6ac3dc8). Each: (R, E, w, w_adv, k, n, top, free, noise), z0, seed,
# F's decimals in nN (None: as computed), how z is written.
H84 = [
    ((1.564457763186484e-08, 7288233456.740156, 0.018940801647576028, 0.004735200411894007, 0.14433217836146622,
      203, 1.2921687349480506, 0.9169563152248117, 1e-4), 2.408576103543462e-06, 355346646, 4, "nm2"),
    ((1.67062327060671e-08, 18715538126.604336, 0.020840723469855875, 0.005210180867463969, 0.06330888563165164,
      595, 3.22226572911125, 0.8423429132768643, 0.0), -1.198157783822138e-06, 137984818, None, "nm_f32"),
    ((5.096581048022764e-08, 782941201.3485187, 0.03850654268395559, 0.019253271341977796, 0.06886090936205053,
      152, 3.664507497230163, 0.9398202346997135, 0.0), 0.0, 908535462, None, "g5"),
]


def _h84_write(z, how):
    """z [m] as helper-84's files wrote it"""
    if how == "nm2":
        return np.array([float("%.2f" % v) for v in z * 1e9]) * 1e-9
    if how == "nm_f32":
        return (z * 1e9).astype(np.float32).astype(np.float64) * 1e-9
    return np.array([float("%.5g" % v) for v in z])


@pytest.mark.xfail(strict=True, reason="known defects: z written coarsely, in float32, or with a unit that changes "
                   "through the curve (helper-84)")
@pytest.mark.parametrize("args, z0, seed, fdec, how", H84)
def test_written_helper84(args, z0, seed, fdec, how):
    """answered within PULL reported errors, or refused"""
    R, E, w, k = args[0], args[1], args[2], args[4]
    z, F, _ = jkr_curves.curve(*args, z0=z0, Fb=0.1, seed=seed)
    if fdec is not None:
        F = np.array([float("%.*f" % (fdec, v)) for v in F * 1e9]) * 1e-9
    _within_pull_or_refused(_h84_write(z, how), F, R, E, w, k)


# helper-80's noise-free curve that a 5 um piezo offset turned into a wrong
# answer (E* 1.39 x, w 21 errors off, n_pinned 0; exact at 0, 2, 10 and
# 15 um): z's rounding broke the pinned top's straight start (fixed at stop
# 77, mdr_f_line; test_fit.c's test_pinned_offset_clean sweeps the three
# regimes)
H80_OFFSET = (1.5439963038965335e-08, 3662565996.230533, 0.0023497089766510277, 0.0005767187289244071,
              0.017724242256548724, 112, 1.7825228296845663, 0.8008566345382027, 0.0)
OFFSET_REL = 1e-8


def test_pinned_offset_clean():
    """helper-80's noise-free curve at piezo offsets 0 to 20 um in 0.25 um:
    every fit answers E* and w within OFFSET_REL (relative) with the same
    pinned samples as at 0 (43)."""
    R, E, w, _, k = H80_OFFSET[:5]
    worst, pinned = 0.0, set()
    for i in range(81):
        z, F, _ = jkr_curves.curve(*H80_OFFSET, z0=i * 0.25e-6)
        r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
        worst = max(worst, abs(r.E / E - 1), abs(r.w / w - 1))
        pinned.add(r.n_pinned)
        assert worst <= OFFSET_REL and pinned == {43}, (i * 0.25, r.E / E, r.w / w, r.n_pinned)


# helper-80's curve whose pinned top one glitch cut short (E* 1.12 x at 6.7
# errors, n_pinned 88 of 581; fixed at stop 77: mdr_f_line leaves out a
# sample off the line whose next two lie on it)
H80_GLITCH = (1.5794778036675073e-08, 26394118.893559154, 0.3568266808973725, 0.025503097127587276,
              0.05908202316917645, 982, 4.440482231498521, 0.42474765538482573, 0.003569369419635753)


def test_pinned_glitch():
    """helper-80's noisy curve with one sample of its pinned top moved by
    -0.3, -0.14, +0.05, +0.14 pull-off forces, at every 8th sample from the
    9th of the retract to the 201st (a glitch among the top's first 5
    samples is still a known defect: the line has too few samples to tell
    it): every answer within PULL reported errors, and at least 90 %
    answered."""
    R, E, w, _, k = H80_GLITCH[:5]
    z, F0, Fc = jkr_curves.curve(*H80_GLITCH, seed=342)
    top = F0.size // 2
    answered = worst = 0
    cases = [(pos, size) for pos in range(top + 8, top + 201, 8) for size in (0.3, 0.14, -0.05, -0.14)]
    for pos, size in cases:
        F = F0.copy()
        F[pos] -= size * abs(Fc)
        try:
            r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k)
        except mdr.Error:
            continue
        answered += 1
        dev = max(abs(r.E - E) / r.E_err, abs(r.w - w) / r.w_err)
        worst = max(worst, dev)
        assert dev <= PULL, (pos - top, size, r.E / E, r.w / w, dev, r.n_pinned)
    assert 10 * answered >= 9 * len(cases), (answered, len(cases))


def test_f32_checked_against_f64(tmp_path, cli):
    """An f32 fit is checked against f64's fit of the same samples (as the
    CLI's and the package's other f32 answers are): helper-35's C1, which f32
    answered E* 0.75 off (status ok), is refused MDR_E_PARAM, the figure in
    the hint, and `mdr fit --arith f32` refuses it the same (status,
    exit 1). Over 60 noise-free closed-form curves through levers 0.01 to
    10 N/m (R 5 nm to 0.3 um, E* 3 MPa to 30 GPa, w 2 mJ to 0.2 J/m^2, no
    hysteresis, unpinned=True), where f32 answered w up to 1.2e-4 off f64's
    at more than 3 of its errors (helper-68's soft levers: 5 of them, status
    ok before), every f32 answer lies within F32FIT of the truth or within 3
    of its reported errors (+1e-9 for f64's own), and some are refused.
    helper-72's noise-free curve with hysteresis fitted unpinned=True, whose
    f32 w carried an error 850 times below f64's (899 of them from the
    truth, status ok), is refused by the errors' rule; and where f64 refuses
    the samples, f32 raises f64's status with f64's own hint kept."""
    args, seed = C1
    R, E, w, k = args[0], args[1], args[2], args[4]
    z, F, _ = jkr_curves.curve(*args, seed=seed)
    with pytest.raises(mdr.Error) as e:
        mdr.fit(z, F, "paraboloid", R=R, k_machine=k, arith="f32")
    assert e.value.status == "MDR_E_PARAM" and e.value.hint.startswith("f32's E* is 0.75 off f64's fit"), e.value
    path = tmp_path / "c1.csv"
    np.savetxt(path, np.column_stack([z, F]), delimiter=",", header="z,F", comments="", fmt="%.17g")
    p = subprocess.run([cli, "fit", "--curve", str(path), "--profile", "paraboloid", "--R", repr(R),
                        "--k-machine", repr(k), "--arith", "f32"], capture_output=True, text=True)
    out = json.loads(p.stdout)
    assert p.returncode == 1 and out["status"] == "MDR_E_PARAM" and out["hint"].startswith(
        "f32's E* is 0.75 off f64's fit"), (p.returncode, out)
    R, k = 8.377248503077025e-07, 0.01677082275550277
    z, F, _ = jkr_curves.curve(R, 415255449.7851958, 0.02248944102271455, 0.011244720511357276, k, 1316,
                               1.738912495578485, 0.34383488599545253, 0.0, Fb=0.3098147065989212, seed=29902250)
    with pytest.raises(mdr.Error) as e:
        mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True, unpinned=True, arith="f32")
    assert e.value.status == "MDR_E_PARAM" and e.value.hint.startswith("f32's reported error of w is 8.5e+02 times "
                                                                       "below f64's"), e.value
    R, k = 8.211665647770888e-07, 31.40414001757029
    z, F, _ = jkr_curves.curve(R, 38109889999.489235, 0.09566693357015627, 0.0717502001776172, k, 1113,
                               2.626776472573501, 0.45854646783022457, 0.01, tilt=0.00013046814177155447,
                               seed=591767725)
    with pytest.raises(mdr.Error) as e64:
        mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True)
    with pytest.raises(mdr.Error) as e:
        mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True, arith="f32")
    assert e.value.status == e64.value.status == "MDR_E_PINNED" and e.value.hint == (
        "f32's fit answered, but f64's fit of the same samples refuses them (an f32 answer is checked against "
        "f64's); " + e64.value.hint), e.value
    np.savetxt(path, np.column_stack([z, F]), delimiter=",", header="z,F", comments="", fmt="%.17g")
    p = subprocess.run([cli, "fit", "--curve", str(path), "--profile", "paraboloid", "--R", repr(R), "--k-machine",
                        repr(k), "--approach", "--arith", "f32"], capture_output=True, text=True)
    out = json.loads(p.stdout)
    assert p.returncode == 1 and out["status"] == "MDR_E_PINNED" and out["hint"].startswith(
        "f32's fit answered, but f64's fit of the same samples refuses them (an f32 answer is checked against "
        "f64's); with --approach: the approach did not rule"), (p.returncode, out)
    rng = np.random.default_rng(1)
    answered = refused = 0
    for i in range(60):
        R, E, w = 10 ** rng.uniform(-8.3, -6.5), 10 ** rng.uniform(6.5, 10.5), 10 ** rng.uniform(-2.7, -0.7)
        k = 10 ** rng.uniform(-2, 1)
        z, F, _ = jkr_curves.curve(R, E, w, w, k, 400, rng.uniform(1.2, 3), rng.uniform(0.3, 1), 0.0, seed=i)
        try:
            r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, arith="f32", unpinned=True)
        except mdr.Error as e:
            assert e.status != "MDR_E_PARAM" or "off f64's fit" in e.hint, e
            refused += 1
            continue
        answered += 1
        for got, want, err in ((r.E, E, r.E_err), (r.w, w, r.w_err)):
            off = abs(got - want)
            if off > 3 * err + 1e-9 * want:  # (1e-9: f64's own distance from the truth, which the check takes)
                assert within(off / want - 1e-9, F32FIT, "f32 beyond 3 errors"), (i, R, E, w, k, got / want - 1,
                                                                                  off / err)
    print("f32 soft levers: %d answered, %d refused" % (answered, refused))
    assert answered >= 40 and refused >= 3


def test_approach_own_modulus():
    """helper-35's curve A2 (R 193 nm, E* 1.55 GPa, w 0.222, w_adv = w/4,
    1.25 N/m, 600 samples a branch, a top of half the pull-off force, 0.3 %
    noise): the retract took its pinned top in, E* 2.03 x the truth at 12
    errors, and the approach's w_adv, fitted with that E* held, ruled the
    pinned top out (status ok). Now the approach's own E* (MDR_F_APP_EPULL)
    disagrees and the fit refuses MDR_E_PINNED, or answers within PULL
    errors; the same curve without hysteresis is answered within PULL."""
    R, E, w, k = 1.93e-7, 1.55e9, 0.222, 1.25
    z, F, _ = jkr_curves.curve(R, E, w, 0.0555, k, 600, 0.5, 1.0, 0.003, seed=0)
    with pytest.raises(mdr.Error) as e:
        mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True)
    assert e.value.status == "MDR_E_PINNED", e.value.status
    z, F, _ = jkr_curves.curve(R, E, w, w, k, 600, 0.5, 1.0, 0.003, seed=0)
    r = mdr.fit(z, F, "paraboloid", R=R, k_machine=k, approach=True)
    assert abs(math.log(r.E / E)) <= PULL * r.E_err / r.E and abs(math.log(r.w / w)) <= PULL * r.w_err / r.w
