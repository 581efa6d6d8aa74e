# SPDX-License-Identifier: MIT
"""mdr.Contact: closed-form equilibrium, critical states and stress of an
adhesive axisymmetric contact (libmdr's contact module, lib/include/
mdr_contact_t.h). SI units; compressive force and depth into the surface
positive; w is the work of adhesion (a paraboloid pulls off at -1.5 pi w R).
"""
import numpy as np

from ._core import Error, broadcast, check, control_code, dptr, element_error, ffi, lib, narrow, shaped, shaped_bool

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
    with G(a) = int_0^a g), K_I = E*(g(a) - d)/sqrt(pi a) (4.17, negative when
    the edge is compressed), G = K_I^2/(2E*) (4.14). The edge of a state
    recedes where G > w and advances where G < w_adv (rule of Hess)."""

    __slots__ = ("a", "d", "F", "K_I", "G")


class Critical(_Result):
    """The last stable state of quasi-static retraction (mdr_critical): a,
    d, F, and the jumps to smaller stable radii before it; a = d = F = 0 when
    the contact peels off continuously."""

    __slots__ = ("a", "d", "F", "jumps", "control", "k_machine", "a_start")


class Profile(_Result):
    """The equivalent profile at x: g [m], dg = g'(x) [1], G = int_0^x g [m^2]."""

    __slots__ = ("x", "g", "dg", "G")


class Contact:
    """A contact scene: profile and material.

        mdr.Contact("paraboloid", E=1e6, w=0.05, R=10e-6)

    Profiles and their parameters [SI]: paraboloid R; cone theta [rad];
    powerlaw C n (f = C r^n); flatpunch a0; sphere R (exact sphere);
    flattip R b (paraboloid flattened for r < b); wavy R h lam (paraboloid
    with a radial waveform of amplitude h, wavelength lam).
    E is the effective modulus E* [Pa], w the work of adhesion [J/m^2].
    arith: "f64" (double, default) or "f32" (float, what an FPU firmware
    computes). A parameter the library refuses raises mdr.Error.
    """

    def __init__(self, profile, *, E, w, arith="f64", **params):
        if profile == "table":
            raise NotImplementedError(
                "Contact('table', r=..., f=...): sampled tips reach the contact module in a later "
                "version; the spring engine takes them now: mdr.Engine.from_tip(r, f, E=..., w=...)")
        if profile not in PROFILES:
            raise Error(lib.MDR_E_KIND, "Contact(%r): profiles are %s" % (profile, ", ".join(PROFILES)))
        if arith not in ("f32", "f64"):
            raise ValueError("Contact: arith must be 'f32' or 'f64', not %r" % (arith,))
        kind, names = PROFILES[profile]
        missing = [n for n in names if n not in params]
        extra = [n for n in params if n not in names]
        if missing or extra:
            raise TypeError("Contact(%r) takes E, w, %s%s%s" % (
                profile, ", ".join(names), "; missing " + ", ".join(missing) if missing else "",
                "; unexpected " + ", ".join(extra) if extra else ""))
        self.profile = profile
        self.kind = kind
        self.arith = arith
        vals = narrow(arith, "Contact(%r)" % profile, E=E, w=w, **{n: params[n] for n in names})
        self.E, self.w = vals[:2]
        self.params = dict(zip(names, vals[2:]))
        self._T = "float" if arith == "f32" else "double"
        self._f = {name: getattr(lib, "%s_%s" % (name, arith)) for name in (
            "mdr_contact_init", "mdr_critical", "mdr_default_start", "mdrpy_eq", "mdrpy_state",
            "mdrpy_stress", "mdrpy_profile")}
        p = [self.params[n] for n in names] + [0.0] * (3 - len(names))
        self.p = tuple(p)
        self._c = ffi.new("mdr_contact_%s *" % arith)
        check(self._f["mdr_contact_init"](self._c, kind, p, self.E, self.w),
              "Contact(%r, %s)" % (profile, self._args()))

    def _args(self):
        return ", ".join(["E=%.9g" % self.E, "w=%.9g" % self.w] + ["%s=%.9g" % kv for kv in self.params.items()])

    def __repr__(self):
        return "mdr.Contact(%r, %s, arith=%r)" % (self.profile, self._args(), self.arith)

    def _loop(self, name, what, names, inputs, ncols, nflags=0, nullable=None):
        """Call the C loop name over the broadcast inputs; (shape, out, flags,
        the flat inputs)."""
        shape, flat = broadcast(*inputs)
        n = flat[0].size
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
        if st != lib.MDR_OK:
            raise element_error(st, what, shape, fail[0], names, flat)
        return shape, out, flags, flat

    def eq(self, a, d=None):
        """Equilibrium states at contact radii a [m] (float or array): an
        EqState (d, F, dd_da, dF_da, dl, K_I, G, stable_load, stable_grips).

        With d [m] (broadcast against a): any state (a, d), e.g. pinned
        states of the spring engine: a State (F, K_I, G).
        A refused element raises mdr.Error naming it (.index)."""
        if d is not None:
            shape, out, _, _ = self._loop("mdrpy_state", "eq", ("a", "d"), (a, d), lib.MDRPY_ST_N)
            return State(**{k: shaped(out[getattr(lib, "MDRPY_ST_" + k.upper())], shape) for k in State.__slots__})
        shape, out, flags, _ = self._loop("mdrpy_eq", "eq", ("a",), (a,), lib.MDRPY_EQ_N, lib.MDRPY_EQ_NFLAGS)
        cols = {k: shaped(out[getattr(lib, "MDRPY_EQ_" + k.upper())], shape) for k in EqState.__slots__[:8]}
        for k in EqState.__slots__[8:]:
            cols[k] = shaped_bool(flags[getattr(lib, "MDRPY_EQ_" + k.upper())], shape)
        return EqState(**cols)

    def stress(self, a, r, d=None):
        """Normal stress sigma_zz [Pa] at radial positions r [m], 0 <= r < a,
        in the equilibrium contact of radius a [m] (4.27), or held at depth d
        [m]; negative in compression. a, r (and d) broadcast together."""
        if d is None:
            shape, out, _, _ = self._loop("mdrpy_stress", "stress", ("a", "r"), (a, r), 1, nullable=1)
        else:
            shape, out, _, _ = self._loop("mdrpy_stress", "stress", ("a", "d", "r"), (a, d, r), 1)
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
        from (default: default_start()). Returns a Critical (a, d, F, jumps)."""
        ctl = control_code(control, "critical")
        if a_start is None:
            a_start = self.default_start()
        k, a_start = narrow(self.arith, "critical", k_machine=0.0 if k_machine is None else k_machine,
                            a_start=a_start)
        out = ffi.new("mdr_critstate_%s *" % self.arith)
        check(self._f["mdr_critical"](self._c, ctl, k, a_start, out),
              "critical(%r, k_machine=%s, a_start=%.9g)" % (control, k_machine, a_start))
        return Critical(a=float(out.a), d=float(out.d), F=float(out.F), jumps=int(out.jumps), control=control,
                        k_machine=k_machine, a_start=float(a_start))

