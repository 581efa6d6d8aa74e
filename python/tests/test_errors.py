# SPDX-License-Identifier: MIT
"""Every refusal raises mdr.Error with the library's status name and text,
names the element, tick or path value that failed, and no NaN or infinity
escapes. Tolerances: none (statuses and texts are compared exactly)."""
import math

import numpy as np
import pytest

import mdr

P = dict(E=1e6, w=0.05)

# the library's texts (lib/src/mdr_status.c), written here independently
TEXT = {
    "MDR_E_NONFINITE": "input is NaN or infinite",
    "MDR_E_PARAM": "parameter out of range",
    "MDR_E_KIND": "unknown profile kind, or one this function does not take (a scene: paraboloid, cone, power law of integer n)",
    "MDR_E_RADIUS": "contact radius outside the profile's domain",
    "MDR_E_POSITION": "radial position outside [0, a)",
    "MDR_E_CONTROL": "unknown control mode, or machine stiffness not > 0 or out of range",
    "MDR_E_SINGULAR": "quantity is singular at this point",
    "MDR_E_OVERFLOW": "result beyond the arithmetic's range (too large, or too small to keep its digits: a table too small, or a scene's contact too small against its units)",
    "MDR_E_OUTSIDE": "contact edge beyond the last spring of the table",
    "MDR_E_TABLE": "tabulated profile unusable (r not from 0 or not increasing, too few points, or g(0) not 0)",
    "MDR_E_SIZE": "number of springs out of range",
    "MDR_E_NOCONV": "iteration cap reached",
}


def refused(status, fn, *args, index=None, **kw):
    """fn(*args, **kw) raises mdr.Error with this status and text; returns it."""
    with pytest.raises(mdr.Error) as err:
        fn(*args, **kw)
    e = err.value
    assert e.status == status and e.message == TEXT[status], str(e)
    assert isinstance(e, ValueError) and e.code < 0 and status in str(e) and e.message in str(e)
    if index is not None:
        assert e.index == index, str(e)
    return e


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_contact_refusals(arith):
    refused("MDR_E_KIND", mdr.Contact, "teapot", R=1e-6, **P)
    for profile, params, status in (
            ("paraboloid", dict(R=-1e-6), "MDR_E_PARAM"), ("paraboloid", dict(R=0.0), "MDR_E_PARAM"),
            ("paraboloid", dict(R=math.nan), "MDR_E_NONFINITE"), ("sphere", dict(R=math.inf), "MDR_E_NONFINITE"),
            ("cone", dict(theta=math.pi / 2), "MDR_E_PARAM"), ("cone", dict(theta=-0.1), "MDR_E_PARAM"),
            ("powerlaw", dict(C=1.0, n=8.5), "MDR_E_PARAM"), ("powerlaw", dict(C=-1.0, n=2.0), "MDR_E_PARAM"),
            ("flatpunch", dict(a0=0.0), "MDR_E_PARAM"), ("flattip", dict(R=1e-5, b=-1e-6), "MDR_E_PARAM"),
            ("wavy", dict(R=1e-5, h=1e-8, lam=0.0), "MDR_E_PARAM"), ("wavy", dict(R=1e-5, h=-1e-8, lam=1e-7),
                                                                      "MDR_E_PARAM")):
        refused(status, mdr.Contact, profile, arith=arith, **P, **params)
    refused("MDR_E_PARAM", mdr.Contact, "paraboloid", R=1e-6, E=0.0, w=0.05, arith=arith)
    refused("MDR_E_PARAM", mdr.Contact, "paraboloid", R=1e-6, E=1e6, w=-0.01, arith=arith)
    refused("MDR_E_NONFINITE", mdr.Contact, "paraboloid", R=1e-6, E=1e6, w=math.nan, arith=arith)


def test_contact_argument_errors():
    with pytest.raises(TypeError, match="missing R"):
        mdr.Contact("paraboloid", **P)
    with pytest.raises(TypeError, match="unexpected theta"):
        mdr.Contact("paraboloid", R=1e-6, theta=0.3, **P)
    with pytest.raises(TypeError):
        mdr.Contact("paraboloid", R=1e-6)  # E and w are required
    with pytest.raises(ValueError, match="arith"):
        mdr.Contact("paraboloid", R=1e-6, arith="q31", **P)
    with pytest.raises(mdr.Error, match="at least 3"):  # sampled tips: tests/test_table.py
        mdr.Contact("table", r=[0, 1e-6], f=[0, 1e-9], **P)
    with pytest.raises(TypeError, match="missing f"):
        mdr.Contact("table", r=[0, 1e-6, 2e-6], **P)


@pytest.mark.parametrize("arith", ["f64", "f32", "q31"])
def test_tip_with_a_dip_refused(arith):
    """A sampled tip whose f falls with r (a dip) is refused, MDR_E_TABLE,
    naming the sample, by Contact and Engine.from_tip, as mdr refuses such
    a file (one test: tip_slopes, examples/tip_csv.h; both took it before,
    an attack after stop 59); equal heights (a flat) are taken."""
    r = [0, 1e-7, 2e-7, 3e-7]
    f = [0, 1e-9, 0.5e-9, 9e-9]
    if arith != "q31":
        e = refused("MDR_E_TABLE", mdr.Contact, "table", r=r, f=f, arith=arith, **P)
        assert "f falls at sample 2 (f = 5e-10 after 1e-09)" in str(e), str(e)
        mdr.Contact("table", r=r, f=[0, 0, 1e-9, 9e-9], arith=arith, **P)
    refused("MDR_E_TABLE", mdr.Engine.from_tip, r, f, arith=arith, **P)
    if arith != "q31":  # (q31: these 4 samples' table is beyond its Q formats, MDR_E_OVERFLOW)
        mdr.Engine.from_tip(r, [0, 0, 1e-9, 9e-9], arith=arith, **P)


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_eq_refusals_name_the_element(arith):
    c = mdr.Contact("paraboloid", R=10e-6, arith=arith, **P)
    e = refused("MDR_E_RADIUS", c.eq, [1e-6, 2e-6, -1e-6, 3e-6], index=2)
    assert e.value == -1e-6 and "element 2 (a = -1e-06)" in str(e)
    refused("MDR_E_RADIUS", c.eq, 0.0, index=None)
    refused("MDR_E_NONFINITE", c.eq, [1e-6, math.nan], index=1)
    e = refused("MDR_E_RADIUS", c.eq, np.array([[1e-6, 2e-6], [3e-6, 0.0]]), index=(1, 1))
    assert "element (1, 1)" in str(e)
    refused("MDR_E_NONFINITE", c.eq, [1e-6, 2e-6], d=[0.0, math.inf], index=1)
    refused("MDR_E_RADIUS", c.eq, [1e-6, -2e-6], d=0.0, index=1)
    refused("MDR_E_RADIUS", mdr.Contact("sphere", R=1e-6, arith=arith, **P).eq, [0.5e-6, 1e-6], index=1)
    refused("MDR_E_RADIUS", mdr.Contact("flatpunch", a0=1e-6, arith=arith, **P).eq, 1.5e-6)
    refused("MDR_E_OVERFLOW", mdr.Contact("flattip", R=1e-5, b=1e-6, arith=arith, **P).eq, [2e-6, 1e-6], index=1)
    refused("MDR_E_RADIUS", c.equivalent, [1e-6, 0.0], index=1)
    if arith == "f32":  # beyond float's range: not converted to inf
        refused("MDR_E_OVERFLOW", c.eq, [1e-6, 1e39], index=1)


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_stress_refusals(arith):
    c = mdr.Contact("paraboloid", R=10e-6, arith=arith, **P)
    refused("MDR_E_POSITION", c.stress, 1e-6, [0.0, 0.5e-6, 1e-6], index=2)
    refused("MDR_E_POSITION", c.stress, 1e-6, -1e-9)
    refused("MDR_E_RADIUS", c.stress, [1e-6, -1e-6], 0.0, index=1)
    refused("MDR_E_NONFINITE", c.stress, 1e-6, 0.5e-6, d=math.nan)
    refused("MDR_E_SINGULAR", mdr.Contact("cone", theta=0.3, arith=arith, **P).stress, 1e-6, [0.5e-6, 0.0], index=1)
    refused("MDR_E_SINGULAR", mdr.Contact("flattip", R=1e-5, b=1e-6, arith=arith, **P).stress, 2e-6, 1e-6)


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_critical_refusals(arith):
    c = mdr.Contact("paraboloid", R=10e-6, arith=arith, **P)
    refused("MDR_E_CONTROL", c.critical, "sideways")
    refused("MDR_E_CONTROL", c.critical, "machine")  # no k_machine
    refused("MDR_E_CONTROL", c.critical, "machine", k_machine=-1.0)
    refused("MDR_E_NONFINITE", c.critical, "machine", k_machine=math.inf)
    refused("MDR_E_NONFINITE", c.critical, "load", a_start=math.nan)
    refused("MDR_E_RADIUS", c.critical, "load", a_start=-1e-6)
    # a wavy contact of more than 65 536 wavelengths below its stable radius:
    # the critical search's cell cap (MDR_CRIT_SCAN_MAX)
    wavy = mdr.Contact("wavy", R=1.0, h=5e-9, lam=0.5e-6, E=1e6, w=0.05, arith=arith)
    refused("MDR_E_NOCONV", wavy.critical, "load", a_start=0.1)
    # a power law close to n = 1/2 and blunt: its pull-off radius (4.70) is
    # 1e100 x CHECK_VALUES' n = 0.6 radius 4118452.7333 (C^(-1/(n - 1/2)));
    # beyond float's range in f32 (before issue 16 both answered MDR_E_NOCONV)
    blunt = mdr.Contact("powerlaw", C=1e-10, n=0.6, E=1.0, w=1.0, arith=arith)
    if arith == "f32":
        refused("MDR_E_OVERFLOW", blunt.default_start)
        refused("MDR_E_OVERFLOW", blunt.critical, "load")
    else:
        assert blunt.critical("load").a == pytest.approx(4118452.7333e100, rel=2e-11)  # its 11 digits
    # n within 2^10 eps of 1/2 (n = 1/2 included): the pull-off radius is not
    # resolved (helper-62: 1 ulp above 1/2 answered a = d = F = 0 for 38 769 m)
    eps = 2.0 ** (-24 if arith == "f32" else -53)
    for n in (0.5, 0.5 + eps, 0.5 + 1024 * eps, 0.5 - 2048 * eps / 2):
        near = mdr.Contact("powerlaw", C=1e-3, n=n, E=1e6, w=0.05, arith=arith)
        for ctl, km in (("load", None), ("grips", None), ("machine", 1.0)):
            refused("MDR_E_RADIUS", near.critical, ctl, k_machine=km)
    if arith == "f32":  # beyond float's range: refused, not passed on as inf
        refused("MDR_E_OVERFLOW", mdr.Contact, "paraboloid", R=1e39, **P, arith=arith)
        refused("MDR_E_OVERFLOW", mdr.Contact, "paraboloid", R=1e-6, E=1e300, w=0.05, arith=arith)
        refused("MDR_E_OVERFLOW", c.critical, "machine", k_machine=1e40)


def test_engine_refusals():
    c = mdr.Contact("paraboloid", R=10e-6, **P)
    refused("MDR_E_SIZE", mdr.Engine, c, springs=1, a_max=1e-5)
    refused("MDR_E_SIZE", mdr.Engine, c, springs=16385, a_max=1e-5)
    refused("MDR_E_SIZE", mdr.Engine, c, springs=100000)
    refused("MDR_E_SIZE", mdr.Engine, c, springs=-1)
    refused("MDR_E_SIZE", mdr.Engine, c, springs=100, arith="q31", a_max=1e-5)  # q31: a power of two
    refused("MDR_E_PARAM", mdr.Engine, c, w_adv=0.1, a_max=1e-5)  # w_adv > w
    refused("MDR_E_PARAM", mdr.Engine, c, w_adv=-0.01, a_max=1e-5)
    refused("MDR_E_CONTROL", mdr.Engine, c, k_machine=-1.0, a_max=1e-5)
    # q31: a lever far softer than the contact, kappa = 2 E* L / k_m above 2^16 (a helper's: the text
    # named only a stiffness not > 0 before)
    stiff = mdr.Engine(mdr.Contact("paraboloid", E=2e11, w=0.05, R=1e-6), k_machine=0.01, arith="q31")
    refused("MDR_E_CONTROL", stiff.run, [0, -1e-9], control="machine", steps_per_segment=10)
    refused("MDR_E_NONFINITE", mdr.Engine, c, k_machine=math.nan, a_max=1e-5)
    refused("MDR_E_NONFINITE", mdr.Engine, c, a_max=math.nan)
    refused("MDR_E_RADIUS", mdr.Engine, mdr.Contact("sphere", R=1e-6, **P), a_max=2e-6)
    # an adhesion the arithmetic does not resolve on the table (MDR_ENGINE_ADH_COND): the pull-off at
    # 1e-5 of the first spring in f32, where its quadratic rounds the force to 1e-2; f64 resolves it
    absurd = mdr.Contact("paraboloid", R=1e-6, E=1e35, w=0.05)
    refused("MDR_E_PARAM", mdr.Engine, absurd, arith="f32", a_max=4e-8)
    mdr.Engine(absurd, arith="f64", a_max=4e-8)
    # a flat's rim inside the first spring (b = 0.99 of it), where the pull-off may lie and no spring
    # resolves it (f64 pulled off at 3% of Kendall's force before): refused in every arithmetic; with
    # the rim on node 1 (90 springs) the run goes
    rim = mdr.Contact("flattip", R=1e-6, b=5e-9, E=1e9, w=1e-8)
    for ar in ("f32", "f64"):
        refused("MDR_E_PARAM", mdr.Engine, rim, springs=89, a_max=4.5e-7, arith=ar)
        mdr.Engine(rim, springs=90, a_max=4.5e-7, arith=ar).run([0, 2.1e-10, -4.2e-10], control="grips",
                                                                steps_per_segment=20)
    refused("MDR_E_PARAM", mdr.Engine, mdr.Contact("flattip", R=1e-6, b=5e-9, E=1e9, w=1e-3), springs=16,
            a_max=4.5e-7, arith="q31")
    with pytest.raises(TypeError):
        mdr.Engine(c, springs=2.5)
    with pytest.raises(TypeError):
        mdr.Engine("paraboloid")
    with pytest.raises(ValueError, match="arith"):
        mdr.Engine(c, arith="q15")
    # springs out of range are refused at once, not at the first run, whose
    # table is built then (helper-22, stop 54), with the range in the text
    for n, ar in ((1, "f64"), (0, "f32"), (1000, "q31")):
        e = refused("MDR_E_SIZE", mdr.Engine, c, springs=n, arith=ar)
        assert "(2 ... 16384; q31: a power of two)" in str(e), str(e)
    # the material and machine settings are refused at once too, without a_max (the table waits for
    # the first run; helper-30, stop 57: refused only there), in every arithmetic
    for ar in ("f32", "f64", "q31"):
        refused("MDR_E_PARAM", mdr.Engine, c, w_adv=0.1, arith=ar)
        refused("MDR_E_PARAM", mdr.Engine, c, w_adv=-0.01, arith=ar)
        refused("MDR_E_CONTROL", mdr.Engine, c, k_machine=-1.0, arith=ar)
        refused("MDR_E_NONFINITE", mdr.Engine, c, w_adv=math.inf, arith=ar)
        refused("MDR_E_PARAM", mdr.Engine.from_tip, [0, 1e-6, 2e-6], [0, 1e-7, 4e-7], E=1e6, w=0.05, w_adv=0.1,
                arith=ar)
    # a lever so soft that float rounds its stiffness to 0 would be no lever at all (stop 58)
    refused("MDR_E_OVERFLOW", mdr.Engine, c, k_machine=1e-300, arith="f32")
    refused("MDR_E_OVERFLOW", mdr.Contact, "paraboloid", R=10e-6, E=1e6, w=1e-300, arith="f32")
    # a subnormal float keeps only some of its digits (1e-40 as 9.99995e-41): refused as the CLI's
    # flags are, by name, in f32, the fit's settings too; taken in f64
    for kw in (dict(k_machine=1e-40), dict(w_adv=1e-40)):
        e = refused("MDR_E_OVERFLOW", mdr.Engine, c, arith="f32", **kw)
        assert "subnormal in float" in str(e) and list(kw)[0] in str(e), str(e)
        mdr.Engine(c, arith="f64", **kw)
    e = refused("MDR_E_OVERFLOW", mdr.Contact, "paraboloid", R=1e-40, E=1e6, w=0.05, arith="f32")
    assert "R = 1e-40" in str(e), str(e)
    z = np.linspace(0.0, 1e-8, 50)
    for kw in (dict(k_machine=1e-40), dict(k_machine=0.2, z_e=1e-40), dict(k_machine=0.2, E0=1e-40, w0=0.05),
               dict(k_machine=0.2, E0=1e9, w0=1e-40)):
        e = refused("MDR_E_OVERFLOW", mdr.fit, z, np.zeros_like(z), "paraboloid", R=20e-9, arith="f32", **kw)
        assert "below float's normal range" in str(e), str(e)
    with pytest.raises(TypeError, match="R must be a number"):
        mdr.Contact("paraboloid", R="10e-6", E=1e6, w=0.05)
    with pytest.raises(TypeError, match="w must be a number"):
        mdr.Contact("cone", theta=0.3, E=1e6, w=b"0.05")
    # None, a one-element array, a list, a complex number: named too (None
    # raised float()'s own message, np.array([1e6]) was taken; helper-56)
    for bad in (None, np.array([1e6]), [1e6], 1e6 + 0j, object()):
        with pytest.raises(TypeError, match="E must be a number"):
            mdr.Contact("paraboloid", R=10e-6, E=bad, w=0.05)
    with pytest.raises(TypeError, match="k_machine must be a number"):
        mdr.Engine(mdr.Contact("paraboloid", R=10e-6, E=1e6, w=0.05), springs=64, k_machine=np.array([0.2]))
    assert mdr.Contact("paraboloid", R=10e-6, E=np.float32(1e6), w=np.array(0.05)).w == 0.05  # numpy scalars


@pytest.mark.parametrize("arith", ["f32", "f64", "q31"])
def test_run_refusals(arith):
    c = mdr.Contact("paraboloid", R=10e-6, **P)
    eng = mdr.Engine(c, springs=256, arith=arith, a_max=5e-6)
    refused("MDR_E_CONTROL", eng.run, [0, 1e-7], control="sideways", steps_per_segment=10)
    e = refused("MDR_E_CONTROL", eng.run, [0, 1e-7], control="machine", steps_per_segment=10, index=0)
    assert len(e.partial) == 0
    refused("MDR_E_PARAM", eng.run, [0.0], control="grips", steps_per_segment=10)
    refused("MDR_E_PARAM", eng.run, [[0, 1e-7]], control="grips", steps_per_segment=10)
    refused("MDR_E_PARAM", eng.run, [0, 1e-7], control="grips", steps_per_segment=0)
    refused("MDR_E_PARAM", eng.run, [0, 1e-7], control="grips", steps_per_segment=2.0)
    for bad in (math.nan, math.inf, -math.inf):
        e = refused("MDR_E_NONFINITE", eng.run, [0, 1e-7, bad, 0], control="grips", steps_per_segment=10, index=2)
        assert "path[2]" in str(e)
    assert eng.state == (0.0, 0.0, 0.0, False)  # a refused path moves nothing
    if arith == "f32":
        refused("MDR_E_OVERFLOW", eng.run, [0, 1e39], control="load", steps_per_segment=10, index=1)
        refused("MDR_E_OVERFLOW", mdr.Engine, c, k_machine=1e40, arith=arith, a_max=5e-6)
    if arith == "q31":
        # beyond the steps' documented input range, 2 units: refused, not saturated
        u = eng.q31_units
        for ctl, unit in (("grips", u["D0"]), ("load", u["F0"])):
            e = refused("MDR_E_OVERFLOW", eng.run, [0, -2.01 * unit], control=ctl, steps_per_segment=10, index=1)
            assert "q31 takes |value| <= 2 units" in str(e)
        assert eng.run([0, -2 * u["F0"]], control="load", steps_per_segment=10).F[-1] == 0.0
    # a path without a table yet: its NaN is refused before the extent is taken from it
    refused("MDR_E_NONFINITE", mdr.Engine(c, arith=arith).run, [0, math.nan], control="grips",
            steps_per_segment=10, index=1)


@pytest.mark.parametrize("arith", ["f32", "f64", "q31"])
def test_tip_refusals(arith):
    r = np.linspace(0, 1e-6, 11)
    f = r**2 / 2e-5
    kw = dict(E=1e6, w=0.05, springs=64, arith=arith)
    refused("MDR_E_TABLE", mdr.Engine.from_tip, r + 1e-8, f, **kw)  # r[0] != 0
    refused("MDR_E_TABLE", mdr.Engine.from_tip, r[::-1], f, **kw)
    refused("MDR_E_TABLE", mdr.Engine.from_tip, r[:2], f[:2], **kw)
    refused("MDR_E_TABLE", mdr.Engine.from_tip, r, f[:5], **kw)
    refused("MDR_E_TABLE", mdr.Engine.from_tip, np.zeros(70000), np.zeros(70000), **kw)
    f2 = f.copy()
    f2[4] = math.nan
    refused("MDR_E_NONFINITE", mdr.Engine.from_tip, r, f2, **kw)
    refused("MDR_E_SIZE", mdr.Engine.from_tip, r, f, E=1e6, w=0.05, springs=1, arith=arith)
    refused("MDR_E_PARAM", mdr.Engine.from_tip, r, f, E=1e6, w=0.05, w_adv=1.0, arith=arith)


PROFILES = [("paraboloid", dict(R=1e-6)), ("cone", dict(theta=0.4)), ("powerlaw", dict(C=3e4, n=3.0)),
            ("flatpunch", dict(a0=1e-6)), ("sphere", dict(R=1e-6)), ("flattip", dict(R=1e-6, b=1e-7)),
            ("wavy", dict(R=1e-6, h=1e-9, lam=5e-8))]


@pytest.mark.parametrize("arith", ["f64", "f32"])
@pytest.mark.parametrize("profile,params", PROFILES)
def test_no_silent_nan(arith, profile, params):
    """Over radii and depths from 1e-30 m to 1e30 m (and their negatives),
    every scalar call either raises mdr.Error or returns finite numbers."""
    c = mdr.Contact(profile, arith=arith, **P, **params)
    xs = np.concatenate([-np.geomspace(1e-30, 1e30, 61), [0.0], np.geomspace(1e-30, 1e30, 121)])
    answered = 0
    for a in xs:
        for call in (lambda: c.eq(a), lambda: c.eq(a, d=-a), lambda: c.stress(a, 0.5 * a),
                     lambda: c.equivalent(a)):
            try:
                out = call()
            except mdr.Error:
                continue
            values = [out] if isinstance(out, float) else [getattr(out, k) for k in out.__slots__]
            assert all(np.isfinite(v) for v in values if not isinstance(v, bool)), (a, out)
            answered += 1
    assert answered > 100


@pytest.mark.parametrize("arith", ["f64", "f32"])
def test_inputs_real_numbers_only(arith):
    """A bool, a string, None, complex or object values are no radius (numpy
    had read eq(True) as a = 1 m, eq("1e-6") as a number, None as NaN, and
    complex values by their real part: helper-24, stop 56); a masked array is
    taken only without masked elements; integers are numbers."""
    c = mdr.Contact("paraboloid", R=10e-6, arith=arith, **P)
    for bad in (True, np.bool_(False), "1e-6", b"1e-6", None, [1e-6, None], np.array([1e-6 + 0j]),
                np.array([1e-6], dtype=object), [True, False]):
        with pytest.raises(TypeError, match="eq: a must be "):
            c.eq(bad)
    with pytest.raises(TypeError, match="stress: r must be "):
        c.stress(2e-6, "0")
    with pytest.raises(TypeError, match="eq: d must be "):
        c.eq(2e-6, d=True)
    with pytest.raises(TypeError, match="equivalent: x must be "):
        c.equivalent(None)
    m = np.ma.masked_array([1e-6, 2e-6], mask=[False, True])
    with pytest.raises(ValueError, match="eq: a has masked elements"):
        c.eq(m)
    ok = c.eq(np.ma.masked_array([1e-6, 2e-6], mask=[False, False])).F
    assert np.array_equal(ok, c.eq(np.array([1e-6, 2e-6])).F)
    assert c.eq(np.int64(1)).F == c.eq(1.0).F and c.eq([1, 2]).F[1] == c.eq(2.0).F
    # a machine's stiffness under another control is refused, as by mdr critical
    with pytest.raises(TypeError, match="k_machine"):
        c.critical("load", k_machine=0.2)
    # the engine's path too
    e = mdr.Engine(c, springs=64)
    with pytest.raises(TypeError, match="Engine.run: path must be "):
        e.run([False, True], control="grips", steps_per_segment=4)
