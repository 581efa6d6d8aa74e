# SPDX-License-Identifier: MIT
"""mdr.fit: from a measured force curve to E*, w, the contact point z0 and the
force baseline, over libmdr's fit kernel (lib/include/mdr_fit.h,
mdr_fit_t.h; docs/fitting.md), the same C code as `mdr fit --curve`.
"""
import numpy as np

from ._build import FIT_DOUBLES
from ._core import Error, dptr, ffi, lib, narrow, real_array
from .contact import Contact

METHODS = {"full": lib.MDR_FIT_FULL, "two-point": lib.MDR_FIT_TWO_POINT}
_METHOD_NAMES = {v: k for k, v in METHODS.items()}
Z_E_DEFAULT = 0.3e-9  # MDR_FIT_Z_E_DEFAULT (python/tests/test_fit.py checks it against the header)


class FitResult:
    """The result of mdr.fit(): the keys of `mdr fit --curve`'s JSON as
    attributes (SI units).

    E [Pa], w [J/m^2], z0 [m] (base position of first touch at zero force),
    F_base [N] (force baseline at z0), F_slope [N/m] (the baseline's slope:
    it is F_base + F_slope (z - z0); 0 with flat_baseline=True; two-point:
    the free part's own line's), E_err, w_err, z0_err, F_base_err, F_slope_err (one
    standard error each; f64: with the unit z was written to, docs/fitting.md), mu (Tabor parameter), R_mu [m] (the tip radius in
    mu), z_e [m], regime ("JKR", "transition", "DMT"), rms [N] (residual),
    pull_off_F [N] (the model's pull-off force relative to the baseline,
    negative), pull_off_z [m], a_pull_off [m] (contact radius at pull-off),
    n (retract points used), n_pinned (samples at the top of the retract
    left out as its pinned part: w_adv < w), method ("full", "two-point"), iterations
    (Levenberg-Marquardt; 0 for two-point), arith; with approach=True also
    w_adv, w_adv_err [J/m^2] and n_approach (else w_adv is None).
    contact: the profile fitted (an mdr.Contact with the fitted E*, w);
    k_machine, z, F: what was fitted.

    model(): the fitted model's force at every sample (as `mdr fit --model`).
    as_dict(): the JSON's fields as a dict.
    """

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def as_dict(self):
        """The JSON fields of `mdr fit --curve` (without status) as a dict."""
        keys = ["E", "w", "z0", "F_base", "E_err", "w_err", "z0_err", "F_base_err", "F_slope", "F_slope_err", "mu",
                "R_mu", "z_e", "regime",
                "rms", "pull_off_F", "pull_off_z", "a_pull_off"]
        if self.n_approach:
            keys += ["w_adv", "w_adv_err", "n_approach"]
        keys += ["n", "n_pinned", "method", "iterations", "arith"]
        return {k: getattr(self, k) for k in keys}

    def model(self):
        """(F_model, top): the fitted model at every sample z of the fit [N],
        and the index of the first retract sample (the last largest z). Up
        to top the approach branch (work of adhesion w_adv when it was
        fitted, else w), from top on the retract (w); both with the fitted
        E*, z0, baseline (F_base + F_slope (z - z0)) and k_machine, computed in f64 whatever the fit's
        arithmetic (mdr_fit_model, as `mdr fit --model`). The approach must
        be monotonic in z for this (else mdr.Error MDR_E_ORDER)."""
        c = self._tip.replace(arith="f64")
        n = self._z.size
        work = ffi.new("%s[]" % c._T, lib.mdrpy_fit_work_len(n))
        Fm = np.empty(n)
        top = ffi.new("uint32_t *")
        w_app = self.w_adv if self.n_approach else self.w
        st = getattr(lib, "mdrpy_fit_model_" + c.arith)(c._c, self.k_machine, self._res, w_app, dptr(self._z), n,
                                                         work, len(work), dptr(Fm), top)
        if st != lib.MDR_OK:
            raise Error(st, "FitResult.model")
        return Fm, int(top[0])

    def __repr__(self):
        s = "<mdr.FitResult %s %s: E = %.6g +- %.2g Pa, w = %.6g +- %.2g J/m^2, z0 = %.9g m, F_base = %.6g N" % (
            self.method, self.arith, self.E, self.E_err, self.w, self.w_err, self.z0, self.F_base)
        s += ", F_slope = %.4g N/m" % self.F_slope
        if self.n_approach:
            s += ", w_adv = %.6g J/m^2" % self.w_adv
        return s + ", mu = %.3g (%s), %d points>" % (self.mu, self.regime, self.n)


def fit(z, F, c_or_profile, k_machine, *, method="full", z_e=None, arith="f64", E0=None, w0=None,
        approach=False, unpinned=False, flat_baseline=False, **params):
    """Fit E*, w, the contact point z0 and the baseline F_base + F_slope (z - z0) to a force
    curve (libmdr's mdr_fit_curve: the same code as `mdr fit --curve`).

    z, F: 1-D arrays of one length, the curve in time order: z the base
        (piezo) position [m], increasing toward the sample; F the force [N],
        compressive positive (the cantilever's stiffness times its
        deflection). The curve may hold the approach and the retract; the
        retract is the part from the last largest z on (it must not
        increase).
    c_or_profile: an mdr.Contact (its profile; its E* and w are not used)
        or a profile name with its parameters as keywords, as mdr.Contact
        takes them (mdr.fit(z, F, "paraboloid", R=20e-9, k_machine=0.2);
        "table" with r=, f=). Every profile but the flat punch.
    k_machine: the cantilever (machine) stiffness [N/m], > 0.
    method: "full" (Levenberg-Marquardt over every retract point, started
        from the two-point method or E0, w0) or "two-point" (the pull-off
        force and the zero-force point only).
    z_e: equilibrium distance of the Tabor parameter [m] (default 0.3e-9).
    arith: "f64" (default) or "f32" (what firmware computes). An f32
        answer is checked against f64's fit of the same samples, as `mdr
        fit --arith f32` checks it: E*, w or w_adv further from f64's than
        5e-5 (relative; mdr._mdr.lib.mdrpy_f32_fit_max()) and 3 of its own
        reported errors raises MDR_E_PARAM (the figure in the hint), and
        samples f64 refuses raise f64's status.
    E0, w0: first guesses [Pa, J/m^2], both or neither.
    approach: also fit w_adv to the approach part (E*, z0, F_base held).
    unpinned: the caller knows the retract recedes from its top (no
        adhesion hysteresis, w_adv = w): no pinned top is looked for (every
        retract sample is fitted, n_pinned = 0), and a retract straight
        within its noise to the pull-off is fitted instead of refused
        (MDR_E_PINNED).
    flat_baseline: the caller knows the baseline is flat (its slope
        subtracted already): F_slope held at 0, one parameter fewer (smaller
        errors of E*; a tilted baseline then biases it). Default: the slope
        is fitted.

    Returns a FitResult. A curve or an argument the library refuses raises
    mdr.Error with its status: MDR_E_FEW (too few points, or none), MDR_E_NOCONTACT,
    MDR_E_NOPULLOFF (never separates), MDR_E_ORDER (z increases within the
    retract, or the curve is in reversed time order), MDR_E_NONFINITE (a NaN or inf sample, .index its position),
    MDR_E_PARAM (k_machine, z_e, E0/w0), MDR_E_KIND (flat punch),
    MDR_E_FITCAP, MDR_E_DEGENERATE (the data do not determine E* or w:
    a relative standard error of 1 or more), MDR_E_MISFIT (the fitted model
    does not reproduce the curve: a poor E0/w0, z not in metres; or its
    pull-off is no fold, as an approach passed in reversed time order
    ends), MDR_E_NOCONV,
    MDR_E_JUMPS, MDR_E_PINNED (a retract
    straight to its pull-off: pinned until it ruptures, or, in noisy data
    without unpinned=True or approach=True, a pinned top the noise may hide,
    also where a straight start leaves too few samples below it: a coarse
    curve), MDR_E_RADIUS, ...
    TypeError: a bool for a number (k_machine, z_e, E0, w0), approach,
    unpinned or flat_baseline other than True, False, 0 or 1, samples that
    are not real numbers (complex, bool, strings, objects). ValueError: arith, or masked
    samples in z or F (pass the unmasked ones).
    """
    if arith not in ("f32", "f64"):
        raise ValueError("fit: arith must be 'f32' or 'f64', not %r" % (arith,))
    if method not in METHODS:
        raise Error(lib.MDR_E_PARAM, "fit: method %r (full or two-point)" % (method,))
    if (E0 is None) != (w0 is None):
        raise Error(lib.MDR_E_PARAM, "fit: E0 and w0 go together (first guesses of both, or neither)")
    if isinstance(c_or_profile, Contact):
        if params:
            raise TypeError("fit: profile parameters (%s) go with a profile name, not with an mdr.Contact"
                            % ", ".join(sorted(params)))
        tip = c_or_profile.replace(arith=arith)
    elif isinstance(c_or_profile, str):
        tip = Contact(c_or_profile, E=1.0, w=0.0, arith=arith, **params)  # E*, w unused (as mdr fit)
    else:
        raise TypeError("fit: c_or_profile must be an mdr.Contact or a profile name, not %r" % (c_or_profile,))
    for name, v in (("approach", approach), ("unpinned", unpinned), ("flat_baseline", flat_baseline)):
        if not isinstance(v, (bool, np.bool_)) and not (isinstance(v, (int, np.integer)) and v in (0, 1)):
            raise TypeError("fit: %s must be True or False, not %r" % (name, v))
    for name, v in (("z", z), ("F", F)):
        if np.ma.isMaskedArray(v) and np.ma.getmaskarray(v).any():
            raise ValueError("fit: %s has masked samples; pass the unmasked ones (both arrays, the same "
                             "samples)" % name)
    for name, v in (("z", z), ("F", F)):  # (a file name: numpy said "could not convert string to float")
        if isinstance(v, (str, bytes)) or v is None:
            raise TypeError("fit: %s must be an array of samples, not %r (read a file with numpy.loadtxt, "
                            "or use `mdr fit --curve FILE`)" % (name, v))
    # real numbers only (real_array: complex samples were fitted by their real
    # part with numpy's ComplexWarning, bool and object arrays read as numbers;
    # helper-28, stop 57)
    z = np.array(real_array(z, "fit", "z"), dtype=np.float64).copy(order="C")
    F = np.array(real_array(F, "fit", "F"), dtype=np.float64).copy(order="C")
    if z.ndim != 1 or z.shape != F.shape:
        raise Error(lib.MDR_E_PARAM, "fit: z and F must be 1-D arrays of one length (got shapes %s and %s)"
                    % (z.shape, F.shape))
    n = z.size
    if n == 0:
        raise Error(lib.MDR_E_FEW, "fit: no samples")
    if n > 2**31 - 1:
        raise Error(lib.MDR_E_SIZE, "fit: %d samples (at most 2^31 - 1)" % n)
    z_e = Z_E_DEFAULT if z_e is None else z_e
    k, ze, e0, ww0 = narrow(arith, "fit", k_machine=k_machine, z_e=z_e, E0=0.0 if E0 is None else E0,
                            w0=0.0 if w0 is None else w0)
    work = ffi.new("%s[]" % tip._T, max(lib.mdrpy_fit_work_len(n), 1))
    res = ffi.new("mdrpy_fit_res *")
    fail = ffi.new("size_t *", n)
    st = getattr(lib, "mdrpy_fit_" + arith)(tip._c, k, ze, e0, ww0, METHODS[method], 1 if approach else 0,
                                            1 if unpinned else 0, 1 if flat_baseline else 0, dptr(z),
                                            dptr(F), n, work, len(work), res, fail)
    if st != lib.MDR_OK:
        raise _fit_error(st, z, F, fail[0] if fail[0] < n else None, method, arith,
                         slope=method == "full" and not flat_baseline, unpinned=bool(unpinned),
                         approach=bool(approach))
    out = {f: float(getattr(res, f)) for f in FIT_DOUBLES}
    if not res.n_approach:
        out["w_adv"] = out["w_adv_err"] = None
    if arith == "f32":
        _check_f32(out, z, F, tip, k_machine, method=method, z_e=z_e, E0=E0, w0=w0, approach=approach,
                   unpinned=unpinned, flat_baseline=flat_baseline)
    fitted = tip.replace(E=out["E"], w=out["w"])
    return FitResult(**out, n=int(res.n), n_approach=int(res.n_approach), n_pinned=int(res.n_pinned), iterations=int(res.iterations),
                     method=_METHOD_NAMES[res.method], regime=ffi.string(lib.mdr_regime_str(res.regime)).decode(),
                     z_e=float(ze), arith=arith, k_machine=float(k), contact=fitted, z=z, F=F, _tip=tip, _z=z,
                     _res=res)


def _check_f32(out, z, F, tip, k_machine, **opts):
    """An f32 answer against f64's fit of the same samples, as `mdr fit
    --arith f32` checks it (mdr_host_f32_fit_check, one rule for both): f64
    refusing the samples raises its status; E*, w or w_adv further from
    f64's than mdrpy_f32_fit_max() (5e-5) and 3 of the f32 answer's own
    reported errors, or an error of theirs reported more than
    mdrpy_f32_fit_err() (3) times below f64's, raises MDR_E_PARAM, with the
    figure in the hint."""
    where = "fit(%d samples, method=%r, arith='f32')" % (z.size, opts["method"])
    try:
        r64 = fit(z, F, tip.replace(arith="f64"), k_machine, arith="f64", **opts)
    except Error as e:  # f64's own refusal and its hint: f32 alone answered
        raise Error(e.code, where, index=e.index, value=e.value,
                    hint="f32's fit answered, but f64's fit of the same samples refuses them (an f32 answer is "
                    "checked against f64's)" + ("; " + e.hint if e.hint else "")) from None
    p32 = ffi.new("double[3]", [out["E"], out["w"], out["w_adv"] or 0.0])
    e32 = ffi.new("double[3]", [out["E_err"], out["w_err"], out["w_adv_err"] or 0.0])
    p64 = ffi.new("double[3]", [r64.E, r64.w, r64.w_adv or 0.0])
    e64 = ffi.new("double[3]", [r64.E_err, r64.w_err, r64.w_adv_err or 0.0])
    which, x = ffi.new("int *"), ffi.new("double *")
    k = lib.mdrpy_f32_fit_check(p32, e32, p64, e64, 3 if opts["approach"] else 2, which, x)
    if k == 0:
        return
    name = ffi.string(lib.mdrpy_f32_fit_which(which[0])).decode()
    if k == 1:
        raise Error(lib.MDR_E_PARAM, where, hint="f32's %s is %.2g off f64's fit of the same samples (more than %g "
                    "and 3 of its reported errors); use arith='f64'" % (name, x[0], lib.mdrpy_f32_fit_max()))
    if k == 2:
        raise Error(lib.MDR_E_PARAM, where, hint="f32's reported error of %s is %.2g times below f64's for the same "
                    "samples (more than %g); use arith='f64'" % (name, x[0], lib.mdrpy_f32_fit_err()))


def _fit_error(st, z, F, i, method, arith, slope=False, unpinned=False, approach=False):
    """mdr.Error of a refused fit, naming the sample where there is one."""
    where = "fit(%d samples, method=%r, arith=%r)" % (z.size, method, arith)
    if st == lib.MDR_E_NONFINITE and i is None:
        bad = np.flatnonzero(~(np.isfinite(z) & np.isfinite(F)))
        i = int(bad[0]) if bad.size else None
    top = z.size - 1 - int(np.argmax(z[::-1])) if z.size else 0  # the retract's start: the last largest z
    if st == lib.MDR_E_ORDER and i is None:
        up = np.flatnonzero(np.diff(z[top:]) > 0)
        i = top + 1 + int(up[0]) if up.size else None
    if i is not None:
        return Error(st, "%s: sample %d (z = %.9g, F = %.9g)" % (where, i, z[i], F[i]), index=i,
                     value=(float(z[i]), float(F[i])))
    hints = {
        lib.MDR_E_FEW: "the retract (from the largest z on) needs %d points or more, %d of them in contact "
        "(%d receding in contact after a pinned top; with approach=True the approach %d points)"
        % (lib.MDR_FIT_MIN_POINTS, lib.MDR_FIT_MIN_CONTACT, lib.MDR_FIT_MIN_RECEDE, lib.MDR_FIT_MIN_POINTS),
        lib.MDR_E_NOCONTACT: "no retract force above the baseline by more than the noise",
        lib.MDR_E_NOPULLOFF: "no pull-off jump followed by free points (the curve must end separated)",
        lib.MDR_E_KIND: "the flat punch cannot be fitted (its pull-off is Kendall's closed form)",
        lib.MDR_E_ORDER: "the samples are not in time order: z rises to the end (no retract), or the "
        "approach is in contact a step below the retract's pull-off (a curve read backwards)",
    }
    if slope:
        hints[lib.MDR_E_DEGENERATE] = ("the baseline's slope is fitted too: give the whole free path of both "
                                       "branches, or flat_baseline=True where the slope is subtracted already")
    if unpinned:
        hints[lib.MDR_E_PINNED] = ("with unpinned=True: a line to the pull-off explains the retract better than a "
                                   "receding branch (a contact pinned until it ruptures, or a branch straight "
                                   "within the noise)")
    elif approach:
        hints[lib.MDR_E_PINNED] = ("with approach=True: the approach did not rule a pinned top out (its w_adv "
                                   "more than 6 errors below w, adhesion hysteresis, or its own E* more than 3 "
                                   "errors from the retract's), or the contact is pinned until it ruptures; the "
                                   "fit does not model a pinned top the noise hides: a stiffer lever or less "
                                   "noise shows where the retract recedes (docs/fitting.md)")
    hint = hints.get(st, "")
    if st in (lib.MDR_E_NOCONTACT, lib.MDR_E_NOPULLOFF, lib.MDR_E_FEW) and z.size:
        # where the retract begins: an outlier above the top moves it
        # (helper-56: one sample at z = 5e-6 m gave MDR_E_NOCONTACT)
        hint += "; the retract is the part from the largest z on: sample %d (z = %.9g m), %d samples" % (
            top, z[top], z.size - top)
    span = float(np.max(z) - np.min(z)) if z.size else 0.0
    fspan = float(np.max(F) - np.min(F)) if F.size else 0.0
    if span > 1e-2:
        # (nm taken for metres were refused with a diagnosis of the curve's
        # shape; helper-56): 1 cm is beyond a piezo's or an indenter's travel
        hint = "z spans %.3g m: z and F must be in metres and newtons (SI), not nm, um or nN" % span
    elif fspan > 1.0:
        # 1 N is beyond an adhesive contact's forces at any scale the fit
        # serves (nN taken for newtons: MDR_E_DEGENERATE with the baseline
        # hint; helper-66, stop 71), as the CLI's FIT_FSPAN_SI
        hint = "F spans %.3g N: z and F must be in metres and newtons (SI), not nm, um or nN" % fspan
    return Error(st, where, hint=hint)
