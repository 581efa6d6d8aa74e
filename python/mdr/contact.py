# SPDX-License-Identifier: MIT
"""mdr.Contact: closed-form equilibrium, critical states and stress of an
adhesive axisymmetric contact (libmdr's contact module, lib/include/
mdr_contact_t.h). SI units; compressive force and depth into the surface
positive; w is the work of adhesion (a paraboloid pulls off at -1.5 pi w R).
"""
import types

import numpy as np

from ._core import (Error, broadcast, check, control_code, dptr, element_error, f32_contact_args, f32_eq_check,
                    f32_eq_error, f32_range_error, f32_range_first, f32_shape, f32_wrong, f32_wrong_error, ffi, lib,
                    narrow, real_array, shaped, shaped_bool)

#: profile name -> (MDR_PROFILE_*, its parameters in the order of p[0..2])
PROFILES = {
    "paraboloid": (lib.MDR_PROFILE_PARABOLOID, ("R",)),
    "cone": (lib.MDR_PROFILE_CONE, ("theta",)),
    "powerlaw": (lib.MDR_PROFILE_POWERLAW, ("C", "n")),
    "flatpunch": (lib.MDR_PROFILE_FLATPUNCH, ("a0",)),
    "sphere": (lib.MDR_PROFILE_SPHERE, ("R",)),
    "flattip": (lib.MDR_PROFILE_FLATTIP, ("R", "b")),
    "wavy": (lib.MDR_PROFILE_WAVY, ("R", "h", "lam")),
}


class _Result:
    """A record of named results (arrays, or floats for scalar input)."""

    __slots__ = ()

    def __init__(self, **kw):
        for k in self.__slots__:
            setattr(self, k, kw[k])

    def __repr__(self):
        return "%s(%s)" % (type(self).__name__, ", ".join("%s=%r" % (k, getattr(self, k)) for k in self.__slots__))


class EqState(_Result):
    """Equilibrium (Griffith) states at contact radii a (seed 4.19-4.26).

    a [m], d [m], F [N], dd_da [1], dF_da [N/m], dl = sqrt(2 pi a w/E*) [m],
    K_I [Pa m^0.5] (= sqrt(2 E* w)), G [J/m^2] (= w), stable_load (dF/da > 0),
    stable_grips (dd/da > 0): arrays in the shape of a, or scalars."""

    __slots__ = ("a", "d", "F", "dd_da", "dF_da", "dl", "K_I", "G", "stable_load", "stable_grips")


class State(_Result):
    """Any state (a, d), the edge pinned or not: F = 2E*(a d - G(a)) (4.26
    with G(a) = int_0^a g; computed as `mdr eq --d` does, the same float;
    as F_eq + 2E* a (d - d_eq) only where G(a) underflows), K_I = E*(g(a) - d)/sqrt(pi a) (4.17, negative when
    the edge is compressed), G = K_I^2/(2E*) (4.14). The edge of a state
    recedes where G > w and advances where G < w_adv (rule of Hess)."""

    __slots__ = ("a", "d", "F", "K_I", "G")


class Critical(_Result):
    """The last stable state of quasi-static retraction (mdr_critical): a,
    d, F, and the jumps to smaller stable radii before it; a = d = F = 0 when
    the contact peels off continuously. max_tensile_F [N] and max_tensile_d
    [m]: the most tensile force of the quasi-static path and its depth (as
    `mdr critical` prints them; under grips the paraboloid's -1.5 pi w R at
    its fold's depth, while F is the last stable state's)."""

    __slots__ = ("a", "d", "F", "jumps", "control", "k_machine", "a_start", "max_tensile_F", "max_tensile_d")


class Profile(_Result):
    """The equivalent profile at x: g [m], dg = g'(x) [1], G = int_0^x g [m^2]."""

    __slots__ = ("x", "g", "dg", "G")


class Contact:
    """A contact scene: profile and material.

        mdr.Contact("paraboloid", E=1e6, w=0.05, R=10e-6)

    Profiles and their parameters [SI]: paraboloid R; cone theta [rad] (the
    flank's angle to the sample surface, f = tan(theta) r: pi/2 minus a
    tip's half-angle);
    powerlaw C n (f = C r^n); flatpunch a0; sphere R (exact sphere);
    flattip R b (paraboloid flattened for r < b); wavy R h lam (paraboloid
    with a radial waveform of amplitude h, wavelength lam); table r f: a
    sampled (measured or worn) tip, gap heights f [m] at radii r [m] (1-D
    arrays, r[0] = 0, strictly increasing, 3 ... 65535 samples; f' linear on
    each interval, the slopes formed in double as `mdr ... --profile table`
    forms them, so the CLI and Python build the same contact). The contact
    keeps read-only copies of r and f (attributes r, f; the C contact points
    into storage this object holds).
    E is the effective modulus E* [Pa], w the work of adhesion [J/m^2].
    arith: "f64" (double, default) or "f32" (float, what an FPU firmware
    computes). A parameter the library refuses raises mdr.Error.
    """

    def __init__(self, profile, *, E, w, arith="f64", **params):
        if profile != "table" and profile not in PROFILES:
            raise Error(lib.MDR_E_KIND, "Contact(%r): profiles are %s, table" % (profile, ", ".join(PROFILES)))
        if arith not in ("f32", "f64"):
            raise ValueError("Contact: arith must be 'f32' or 'f64', not %r" % (arith,))
        self._f = {name: getattr(lib, "%s_%s" % (name, arith)) for name in (
            "mdr_contact_init", "mdr_critical", "mdr_default_start", "mdrpy_eq", "mdrpy_state",
            "mdrpy_stress", "mdrpy_profile", "mdrpy_contact_tip")}
        self._T = "float" if arith == "f32" else "double"
        self.arith = arith
        self._c = ffi.new("mdr_contact_%s *" % arith)
        if profile == "table":
            self._init_table(E, w, params)
            self._frozen = True
            return
        kind, names = PROFILES[profile]
        missing = [n for n in names if n not in params]
        extra = [n for n in params if n not in names]
        if missing or extra:
            raise TypeError("Contact(%r) takes E, w, %s%s%s" % (
                profile, ", ".join(names), "; missing " + ", ".join(missing) if missing else "",
                "; unexpected " + ", ".join(extra) if extra else ""))
        self.profile = profile
        self.kind = kind
        vals = narrow(arith, "Contact(%r)" % profile, E=E, w=w, **{n: params[n] for n in names})
        self.E, self.w = vals[:2]
        self.params = types.MappingProxyType(dict(zip(names, vals[2:])))
        p = [self.params[n] for n in names] + [0.0] * (3 - len(names))
        self.p = tuple(p)
        self.r = self.f = None
        if arith == "f32":
            f32_shape(kind, p, names, "Contact(%r)" % profile)
        check(self._f["mdr_contact_init"](self._c, kind, p, self.E, self.w),
              "Contact(%r, %s)" % (profile, self._args()))
        self._frozen = True

    def __setattr__(self, name, value):
        # read-only once made: the C contact holds E*, w and the profile, and
        # a changed attribute gave two physics on one object (c.w = 0.1:
        # c.critical() with 0.05, Engine(c) and repr with 0.1; helper-30,
        # stop 57). A new material: c.replace(E=..., w=...)
        if getattr(self, "_frozen", False):
            raise AttributeError("mdr.Contact is read-only (%s); c.replace(E=..., w=..., arith=...) makes "
                                 "another" % name)
        object.__setattr__(self, name, value)

    def _init_table(self, E, w, params):
        """Contact("table", r=..., f=...): the samples' slopes formed in
        double (mdrpy_contact_tip, as the CLI), r and the slopes converted
        into storage this object keeps (the C contact points into it)."""
        if sorted(params) != ["f", "r"]:
            raise TypeError("Contact('table') takes E, w, r, f (arrays of the radii and gap heights)%s" % (
                "; unexpected " + ", ".join(sorted(set(params) - {"r", "f"})) if set(params) - {"r", "f"} else
                "; missing " + ", ".join(sorted({"r", "f"} - set(params)))))
        # copies: the contact must not change when the caller's arrays do;
        # real numbers only, none masked (real_array: a masked outlier was read
        # under its mask, the pull-off 6 000 times off; bool gaps read as 0/1 m,
        # complex by their real part; helper-30, stop 57)
        r = np.array(real_array(params["r"], "Contact('table')", "r"), dtype=np.float64).copy(order="C")
        f = np.array(real_array(params["f"], "Contact('table')", "f"), dtype=np.float64).copy(order="C")
        if r.ndim != 1 or r.shape != f.shape or r.size > 65535:
            raise Error(lib.MDR_E_TABLE, "Contact('table'): r and f must be 1-D arrays of one length "
                        "%d ... 65535 (got shapes %s and %s)" % (lib.MDR_TABLE_MIN_POINTS, r.shape, f.shape))
        self.E, self.w = narrow(self.arith, "Contact('table')", E=E, w=w)
        self.profile = "table"
        self.kind = lib.MDR_PROFILE_TABLE
        self.params = types.MappingProxyType({})
        self.p = (0.0, 0.0, 0.0)
        r.flags.writeable = False
        f.flags.writeable = False
        self.r, self.f = r, f
        m = r.size
        self._slopes = ffi.new("double[]", max(m - 1, 1))
        self._buf = ffi.new("%s[]" % self._T, max(2 * m, 1))  # the contact points into it
        st = self._f["mdrpy_contact_tip"](self._c, dptr(r), dptr(f), m, self.E, self.w, self._slopes, self._buf)
        if st != lib.MDR_OK:
            raise Error(st, "Contact('table', %s)" % self._args(), hint=_table_hint(st, r, f))

    def _args(self):
        if self.profile == "table":
            return "E=%.9g, w=%.9g, %d samples to r=%.9g" % (self.E, self.w, self.r.size,
                                                              self.r[-1] if self.r.size else float("nan"))
        return ", ".join(["E=%.9g" % self.E, "w=%.9g" % self.w] + ["%s=%.9g" % kv for kv in self.params.items()])

    def replace(self, *, E=None, w=None, arith=None):
        """The same profile (and samples) with another E*, w or arithmetic
        ("f32", "f64"): a new Contact (self when nothing changes)."""
        E = self.E if E is None else E
        w = self.w if w is None else w
        arith = self.arith if arith is None else arith
        if (E, w, arith) == (self.E, self.w, self.arith):
            return self
        if self.profile == "table":
            return Contact("table", E=E, w=w, arith=arith, r=self.r, f=self.f)
        return Contact(self.profile, E=E, w=w, arith=arith, **self.params)

    def __repr__(self):
        return "mdr.Contact(%r, %s, arith=%r)" % (self.profile, self._args(), self.arith)

    def _loop(self, name, what, names, inputs, ncols, nflags=0, nullable=None, rounding=False, answer=False):
        """Call the C loop name over the broadcast inputs; (shape, out, flags,
        the flat inputs). rounding: an f32 equilibrium (eq), whose points are
        checked as `mdr eq` and `mdr curve` check theirs, in one call after
        the loop (f32_eq_check: the rounding of the inputs, then the answer
        against f64 at the values given), and the first refused point raises
        as the CLI's row would (a refusal of the library at a point refused
        for its rounding is not raised: the rounding's is). answer: a stress,
        whose f32 answer is checked as `mdr stress --a` checks it
        (f32_wrong)."""
        shape, flat = broadcast(what, names, inputs)
        n = flat[0].size
        beyond = f32_range_first(flat) if self.arith == "f32" else None
        if beyond is not None:  # (the points before it computed and checked, then it refused)
            shape0, flat0 = shape, flat
            flat = [v[:beyond[0]] for v in flat]
            n = beyond[0]
        out = np.empty((ncols, n))
        flags = np.empty((nflags, n), dtype=np.uint8) if nflags else None
        fail = ffi.new("size_t *")
        args = [dptr(a) for a in flat]
        if nullable is not None:  # an optional input given as NULL
            args.insert(nullable, ffi.NULL)
        if nflags:
            st = self._f[name](self._c, n, *args, dptr(out), ffi.from_buffer("uint8_t[]", flags), fail)
        else:
            st = self._f[name](self._c, n, *args, dptr(out), fail)
        if (rounding or answer) and self.arith == "f32":
            k = fail[0] if st != lib.MDR_OK else n  # the points answered
            if answer:
                wrong = f32_wrong(self, flat, out[0][:k])
                if wrong is not None:
                    raise f32_wrong_error(what, shape, wrong[0], wrong[1], names, flat)
            else:
                dd32 = dF32 = K32 = None
                if len(flat) == 1:  # (equilibria: their derivatives too, as `mdr eq` prints them)
                    d32, F32 = out[lib.MDRPY_EQ_D], out[lib.MDRPY_EQ_F]
                    dd32, dF32 = out[lib.MDRPY_EQ_DD_DA], out[lib.MDRPY_EQ_DF_DA]
                else:  # a state: its d as the CLI reads it, in float
                    d32, F32 = flat[1].astype(np.float32).astype(np.float64), out[lib.MDRPY_ST_F]
                    K32 = out[lib.MDRPY_ST_K_I]
                refused = f32_eq_check(self, flat, k, d32, F32, dd32, dF32, K32)
                if refused is not None:
                    i, why, v = refused
                    if why == 0:
                        raise f32_eq_error(what, shape, i, v, names, flat)
                    raise f32_wrong_error(what, shape, i, v, names, flat, q={2: "dd_da", 3: "dF_da", 4: "K_I"}.get(why, "answer"))
        if st != lib.MDR_OK:
            raise element_error(st, what, shape, fail[0], names, flat)
        if beyond is not None:
            raise f32_range_error(what, shape0, beyond[0], beyond[1], names, flat0)
        return shape, out, flags, flat

    def eq(self, a, d=None):
        """Equilibrium states at contact radii a [m] (float or array): an
        EqState (d, F, dd_da, dF_da, dl, K_I, G, stable_load, stable_grips).

        With d [m] (broadcast against a): any state (a, d), e.g. pinned
        states of the spring engine: a State (F, K_I, G).
        A refused element raises mdr.Error naming it (.index). In f32 an
        element whose state the rounding of its inputs to float moves by
        more than 1.5e-6 is refused (MDR_E_PARAM), as `mdr eq` and `mdr
        curve --arith f32` refuse it (the sphere near a = R, the flattened
        tip just above its flat, a measured tip whose samples float moves:
        quantized or noisy heights; docs/accuracy.md)."""
        if d is not None:
            shape, out, _, _ = self._loop("mdrpy_state", "eq", ("a", "d"), (a, d), lib.MDRPY_ST_N, rounding=True)
            return State(**{k: shaped(out[getattr(lib, "MDRPY_ST_" + k.upper())], shape) for k in State.__slots__})
        shape, out, flags, _ = self._loop("mdrpy_eq", "eq", ("a",), (a,), lib.MDRPY_EQ_N, lib.MDRPY_EQ_NFLAGS,
                                          rounding=True)
        cols = {k: shaped(out[getattr(lib, "MDRPY_EQ_" + k.upper())], shape) for k in EqState.__slots__[:8]}
        for k in EqState.__slots__[8:]:
            cols[k] = shaped_bool(flags[getattr(lib, "MDRPY_EQ_" + k.upper())], shape)
        return EqState(**cols)

    def stress(self, a, r, d=None):
        """Normal stress sigma_zz [Pa] at radial positions r [m], 0 <= r < a,
        in the equilibrium contact of radius a [m] (4.27), or held at depth d
        [m]; negative in compression. a, r (and d) broadcast together. In
        f32 an element whose stress lies more than 2e-6 (of the two terms
        of 4.27) from f64's at the values given is refused, MDR_E_PARAM, as
        `mdr stress --arith f32` refuses it (a measured tip's, quantized or
        noisy heights: up to 6e-3 off; docs/accuracy.md)."""
        if d is None:
            shape, out, _, _ = self._loop("mdrpy_stress", "stress", ("a", "r"), (a, r), 1, nullable=1, answer=True)
        else:
            shape, out, _, _ = self._loop("mdrpy_stress", "stress", ("a", "d", "r"), (a, d, r), 1, answer=True)
        return shaped(out[0], shape)

    def equivalent(self, x):
        """The MDR equivalent profile at x [m] (float or array): a Profile
        with g(x) [m], dg = g'(x) [1] and G(x) = int_0^x g [m^2]."""
        shape, out, _, flat = self._loop("mdrpy_profile", "equivalent", ("x",), (x,), lib.MDRPY_PR_N)
        return Profile(x=shaped(flat[0], shape), g=shaped(out[lib.MDRPY_PR_G], shape),
                       dg=shaped(out[lib.MDRPY_PR_DG], shape), G=shaped(out[lib.MDRPY_PR_GINT], shape))

    def default_start(self):
        """A starting radius for critical() well inside the contact [m]
        (mdr_default_start)."""
        a0 = ffi.new(self._T + " *")
        check(self._f["mdr_default_start"](self._c, a0), "default_start")
        return float(a0[0])

    def critical(self, control="load", k_machine=None, a_start=None):
        """The critical (pull-off) state of quasi-static retraction under
        control "load" (fixed load), "grips" (fixed grips) or "machine" (a
        machine of stiffness k_machine [N/m] between the controlled base and
        the contact). a_start [m]: the equilibrium radius retraction starts
        from (default: default_start()). Returns a Critical (a, d, F, jumps,
        max_tensile_F, max_tensile_d)."""
        ctl = control_code(control, "critical")
        if k_machine is not None and ctl != lib.MDR_CONTROL_MACHINE:
            # (echoed and ignored before stop 56; mdr critical refuses it too)
            raise TypeError("critical: k_machine is the machine's stiffness; control %r takes none" % (control,))
        given = a_start
        if a_start is None:
            a_start = self.default_start()
        k, a_start = narrow(self.arith, "critical", k_machine=0.0 if k_machine is None else k_machine,
                            a_start=a_start)
        out = ffi.new("mdr_critstate_%s *" % self.arith)
        what = "critical(%r, k_machine=%s, a_start=%.9g)" % (control, k_machine, a_start)
        check(self._f["mdr_critical"](self._c, ctl, k, a_start, out), what)
        if self.arith == "f32":
            # f32's state against f64's at the values given, as `mdr critical
            # --arith f32` checks it (mdrpy_f32_crit_wrong)
            a0 = ffi.new("double *", float(given)) if given is not None else ffi.NULL
            er = lib.mdrpy_f32_crit_wrong(*f32_contact_args(self), ctl, 0.0 if k_machine is None else float(k_machine),
                                          a0, float(out.a), float(out.d), float(out.F), float(out.F_min))
            if er > lib.mdrpy_f32_crit_max():
                raise Error(lib.MDR_E_PARAM, what, hint="f32's critical state is %.2g off f64's at the values given "
                            "(more than %g); use arith='f64'" % (er, lib.mdrpy_f32_crit_max()))
        return Critical(a=float(out.a), d=float(out.d), F=float(out.F), jumps=int(out.jumps), control=control,
                        k_machine=k_machine, a_start=float(a_start), max_tensile_F=float(out.F_min),
                        max_tensile_d=float(out.d_F_min))


def _table_hint(st, r, f):
    """What is wrong with the samples, for the messages of MDR_E_TABLE and
    MDR_E_NONFINITE."""
    if st == lib.MDR_E_NONFINITE:
        bad = np.flatnonzero(~(np.isfinite(r) & np.isfinite(f)))
        if bad.size:
            return "sample %d: r = %.9g, f = %.9g" % (bad[0], r[bad[0]], f[bad[0]])
    if st == lib.MDR_E_TABLE:
        if r.size < lib.MDR_TABLE_MIN_POINTS:
            return "%d samples (at least %d)" % (r.size, lib.MDR_TABLE_MIN_POINTS)
        if r[0] != 0:
            return "r[0] = %.9g (must be 0)" % r[0]
        bad = np.flatnonzero(~(np.diff(r) > 0))
        if bad.size:
            return "r not strictly increasing at sample %d (r = %.9g after %.9g)" % (bad[0] + 1, r[bad[0] + 1],
                                                                                    r[bad[0]])
        bad = np.flatnonzero(np.diff(f) < 0)
        if bad.size:
            return "f falls at sample %d (f = %.9g after %.9g): the gap of a tip grows with the radius" % (
                bad[0] + 1, f[bad[0] + 1], f[bad[0]])
    return ""
