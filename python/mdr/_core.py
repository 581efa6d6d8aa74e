# SPDX-License-Identifier: MIT
"""The extension, the error type and the array plumbing shared by the
package's modules."""
import numpy as np

from ._mdr_cffi import ffi, lib

#: status code -> name ("MDR_E_RADIUS"), from the constants the extension
#: was compiled with (mdr_types.h)
STATUS_NAMES = {getattr(lib, n): n for n in dir(lib) if n == "MDR_OK" or n.startswith("MDR_E_")}

ARITHS = {"f32": lib.MDRPY_F32, "f64": lib.MDRPY_F64, "q31": lib.MDRPY_Q31}
CONTROLS = {"load": lib.MDR_CONTROL_LOAD, "grips": lib.MDR_CONTROL_GRIPS, "machine": lib.MDR_CONTROL_MACHINE}


def status_text(code):
    """The library's text for a status code (mdr_status_str)."""
    return ffi.string(lib.mdr_status_str(code)).decode()


def event_name(code):
    """The library's name of an event code (mdr_event_str): "pull-off", ..."""
    return ffi.string(lib.mdr_event_str(code)).decode()


class ResolutionWarning(UserWarning):
    """A spring table too coarse for its profile (issued by mdr.Engine, like
    `mdr cycle`'s summary "warnings"): a wavy profile's table with fewer
    than 8 springs per wavelength, whose folds and jumps it does not resolve
    (docs/engine.md). The run goes on; more springs or a smaller a_max
    resolve the waves."""


class Error(ValueError):
    """A refusal of libmdr.

    Attributes:
        status: the library's status name, e.g. "MDR_E_RADIUS"
        code: its value (negative)
        message: the library's text (mdr_status_str), e.g. "contact radius
            outside the profile's domain"
        where: what was refused (call, element, tick, value)
        index: the element (int, or a tuple for arrays of more than one
            dimension) or tick that failed, or None
        value: the refused input value, or None
        partial: Engine.run only: the Run of the ticks completed before the
            refusal (None elsewhere)
    """

    def __init__(self, code, where="", index=None, value=None, hint="", partial=None):
        self.code = int(code)
        self.status = STATUS_NAMES.get(self.code, "MDR status %d" % self.code)
        self.message = status_text(self.code)
        self.where = where
        self.index = index
        self.value = value
        self.hint = hint
        self.partial = partial
        super().__init__(str(self))

    def __str__(self):
        s = "%s (%s)" % (self.message, self.status)
        if self.where:
            s = "%s: %s" % (self.where, s)
        return s + ("; " + self.hint if self.hint else "")


def check(code, where, **kw):
    """Raise Error unless code is MDR_OK."""
    if code != lib.MDR_OK:
        raise Error(code, where, **kw)


FLT_MAX = float(np.finfo(np.float32).max)
FLT_MIN = float(np.finfo(np.float32).tiny)


def narrow(arith, where, **values):
    """The values as floats; for f32 a finite value beyond float's range is
    refused (MDR_E_OVERFLOW) instead of becoming inf on the way to C, and
    a nonzero one below float's normal range likewise (0 or losing digits),
    as the CLI refuses its flags. A bool
    is no number here (k_machine=True is a mistake, not 1 N/m), nor a string
    (R="10e-6" was read as a number, helper-22 at stop 54): TypeError."""
    out = []
    for name, v in values.items():
        # (nor None, an array, a list or a complex number: None raised
        # float()'s own TypeError, np.array([1e6]) was taken as its element;
        # helper-56)
        if (isinstance(v, (bool, np.bool_, str, bytes, list, tuple, complex, np.complexfloating)) or v is None or
                np.ndim(v) != 0):
            raise TypeError("%s: %s must be a number, not %r" % (where, name, v))
        try:
            out.append(float(v))
        except (TypeError, ValueError):
            raise TypeError("%s: %s must be a number, not %r" % (where, name, v)) from None
    if arith == "f32":
        for (name, _), v in zip(values.items(), out):
            if abs(v) > FLT_MAX and v - v == 0:
                raise Error(lib.MDR_E_OVERFLOW, "%s: %s = %.9g (beyond float)" % (where, name, v), value=v)
            # (nor a nonzero value below float's normal range, as the CLI's
            # flags: float rounds it to 0, k_machine=1e-300 became no
            # machine at all, stop 58, or keeps only some of its digits,
            # 1e-40 as 9.99995e-41)
            if v != 0 and abs(v) < FLT_MIN:
                why = "it would be 0" if np.float32(v) == 0 else "subnormal in float: it loses digits"
                raise Error(lib.MDR_E_OVERFLOW, "%s: %s = %.9g (below float's normal range %.9g: %s)" %
                            (where, name, v, FLT_MIN, why), value=v)
    return out


def f32_shape(kind, p, names, where):
    """Refuse (mdr.Error, MDR_E_PARAM) a profile that f32's rounding of its
    parameters p moves beyond f32's accuracy: the cone near pi/2, where
    theta rounded to float changes tan(theta) by |dtheta|/(sin cos); the
    same test as the CLI's (mdr_host_f32_shape_refused, examples/mdr_host.h;
    helper-37, stop 59: theta = 1.5707962 answered a 2.8 times f64's)."""
    ch = ffi.new("double *")
    if lib.mdr_host_f32_shape_refused(kind, [float(v) for v in p], ch):
        for n, v in zip(names, p):
            if float(np.float32(v)) != v:
                raise Error(lib.MDR_E_PARAM, "%s: %s = %.15g: f32 rounds it to %.9g, %s; use arith='f64'%s" % (
                    where, n, v, np.float32(v),
                    "which moves the profile by %.2g" % ch[0] if ch[0] < 1e300 else "outside the profile's range",
                    ", or the cone as Contact('powerlaw', C=tan(theta), n=1)" if kind == lib.MDR_PROFILE_CONE else ""))


def f32_contact_args(contact):
    """The contact as the f32 checks take it (mdr_py.h): kind, p, a sampled
    tip's radii and slopes (the cdata formed as the contact formed them) or
    NULL for an analytic profile, their count, E and w as given."""
    tip = contact.kind == lib.MDR_PROFILE_TABLE
    return (contact.kind, [float(v) for v in contact.p], dptr(contact.r) if tip else ffi.NULL,
            contact._slopes if tip else ffi.NULL, contact.r.size if tip else 0, contact.E, contact.w)


def _f32_head(contact, k, a, d):
    """f32_contact_args and the k points a (and d, or NULL)."""
    return f32_contact_args(contact) + (k, dptr(a), dptr(d) if d is not None else ffi.NULL)


def f32_eq_check(contact, flat, k, d32, F32, dd32=None, dF32=None, K32=None):
    """The CLI's two f32 checks of `mdr eq` and each row of `mdr curve` over
    the flat inputs (a, or a and d), in one C call (mdrpy_f32_eq_check: one
    pair of f64 contacts, one f64 state per point): (i, what, value) of the
    first refused point, or None. what 0: f32's rounding of the inputs (p,
    E, w as given, a, d) moves its state by value, more than
    MDR_HOST_F32_EQ_MAX (helper-41, stop 60: the exact sphere at
    a = R (1 - 1e-5) answered 4e-5 off f64); what 1: its f32 answer (d32,
    F32, the first k points answered) lies value from f64's at the values
    given, more than MDR_HOST_F32_ANSWER_MAX (helper-50, stop 62: a coarse
    table near its axis answered 9.5e-6 off f64), and with dd32, dF32 (an
    equilibrium's) its dd/da and dF/da (stop 63: a quantized measured tip's
    6.6e-6 off with d and F within 3e-7), and with K32 (a state's) its K_I
    (what 4, relative to the larger of |K_I| and sqrt(2 E* w): helper-65,
    stop 71: a pinned state's K_I printed 0 for 1218.5). The rounding is checked
    up to point k (where the f32 loop refused, if it did) and refused
    first, the answers below k."""
    n = flat[0].size
    a, d = flat[0], (flat[1] if len(flat) > 1 else None)
    what, value = ffi.new("int *"), ffi.new("double *")
    i = lib.mdrpy_f32_eq_check(*_f32_head(contact, n, a, d), k,
                               dptr(np.ascontiguousarray(d32, dtype=np.float64)),
                               dptr(np.ascontiguousarray(F32, dtype=np.float64)),
                               ffi.NULL if dd32 is None else dptr(np.ascontiguousarray(dd32, dtype=np.float64)),
                               ffi.NULL if dF32 is None else dptr(np.ascontiguousarray(dF32, dtype=np.float64)),
                               ffi.NULL if K32 is None else dptr(np.ascontiguousarray(K32, dtype=np.float64)),
                               what, value)
    return (int(i), int(what[0]), float(value[0])) if i < n else None


def f32_wrong(contact, flat, s32):
    """The CLI's check of an f32 stress (`mdr stress --a`,
    mdrpy_f32_stress_wrong: mdr_host_f32_stress_err): (i, error) of the
    first of the points (flat: a, (d,) r) whose f32 stress s32 lies more
    than MDR_HOST_F32_ANSWER_MAX from f64's at the values given, relative
    to the two terms of 4.27, or None (a measured tip's stress up to 6e-3,
    stop 62)."""
    k = s32.size
    pts = [np.ascontiguousarray(v[:k]) for v in flat]
    err = ffi.new("double *")
    i = lib.mdrpy_f32_stress_wrong(*_f32_head(contact, k, pts[0], pts[1] if len(pts) > 2 else None),
                                   dptr(pts[-1]), dptr(np.ascontiguousarray(s32, dtype=np.float64)), err)
    return (int(i), float(err[0])) if i < k else None


def f32_range_first(flat):
    """(i, name index) of the first element of the flat inputs beyond float's
    range (nonzero and below its normal range, or finite and above it), or
    None: the f32 calls refuse it as the CLI refuses such a flag (`outside
    the range of --arith f32`), not through a check that happens to see it
    (a d of 1e-50 was taken as 0 and answered, stop 62's review)."""
    first = None
    for k, v in enumerate(flat):
        bad = np.flatnonzero(((v != 0) & (np.abs(v) < FLT_MIN)) | ((np.abs(v) > FLT_MAX) & np.isfinite(v)))
        if bad.size and (first is None or bad[0] < first[0]):
            first = (int(bad[0]), k)
    return first


def f32_range_error(what, shape, i, k, names, values):
    """mdr.Error (MDR_E_OVERFLOW, as narrow's) for element i of
    f32_range_first, naming the input k."""
    return element_error(lib.MDR_E_OVERFLOW, what, shape, i, names, values,
                         hint="%s = %.9g: outside the range of arith='f32' (0 or |v| in [%.9g, %.9g])" % (
                             names[k], values[k][i], FLT_MIN, FLT_MAX))


def f32_wrong_error(what, shape, i, err, names, values, q="answer"):
    """mdr.Error (MDR_E_PARAM, as the CLI's exit 2) for point i of f32_wrong
    or f32_eq_check; q: what is off, "answer" (d, F, a stress), "dd_da" or
    "dF_da" (an equilibrium's derivative), "K_I" (a state's), as the CLI
    names it."""
    mx = lib.mdrpy_f32_answer_max() if q in ("answer", "K_I") else lib.mdrpy_f32_slope_max()
    return element_error(lib.MDR_E_PARAM, what, shape, i, names, values,
                         hint="f32's %s is %.2g off f64's at the values given (more than %g); use arith='f64'" % (
                             q, err, mx))


def f32_eq_error(what, shape, i, change, names, values):
    """mdr.Error (MDR_E_PARAM, as f32_shape: the CLI's usage error, exit 2)
    for point i of f32_eq, named as element_error names it."""
    return element_error(lib.MDR_E_PARAM, what, shape, i, names, values,
                         hint="f32's rounding of the inputs to float %s; use arith='f64'" % (
                             "moves the state by %.2g (more than %g)" % (change, lib.mdrpy_f32_eq_max())
                             if change < 1e300 else "puts the state outside the profile"))


def control_code(control, where):
    try:
        return CONTROLS[control]
    except (KeyError, TypeError):
        raise Error(lib.MDR_E_CONTROL, "%s: control %r (load, grips or machine)" % (where, control)) from None


def real_array(x, where, name):
    """x (a number or an array of them) as a float64 array: real numbers only.
    A bool, a string, None, complex or object values are refused (TypeError:
    numpy had read eq(True) as a = 1 m, eq("1e-6") as a number, None as NaN
    and complex values by their real part; helper-24, stop 56), and a masked
    array with masked elements (ValueError: numpy reads under the mask)."""
    if x is None or isinstance(x, (bool, np.bool_, str, bytes)):
        raise TypeError("%s: %s must be a real number or an array of them, not %r" % (where, name, x))
    if np.ma.isMaskedArray(x):
        if np.ma.getmaskarray(x).any():
            raise ValueError("%s: %s has masked elements; pass the unmasked ones" % (where, name))
        x = np.ma.getdata(x)
    a = np.asarray(x)
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: %s must be real numbers, not an array of %s" % (where, name, a.dtype))
    return a.astype(np.float64, copy=False)


def broadcast(where, names, xs):
    """(shape, flat float64 contiguous arrays) of the broadcast inputs xs
    (named names: real numbers, real_array)."""
    arrs = np.broadcast_arrays(*[real_array(x, where, n) for n, x in zip(names, xs)])
    return arrs[0].shape, [np.ascontiguousarray(a).reshape(-1) for a in arrs]


def dptr(a):
    """double * to a contiguous float64 array (no copy)."""
    return ffi.from_buffer("double[]", a)


def element_error(code, what, shape, i, names, values, hint=""):
    """Error for element i of a vectorised call (flat index i into shape)."""
    if shape == ():
        index = None
        where = what
    else:
        index = int(i) if len(shape) == 1 else tuple(int(k) for k in np.unravel_index(i, shape))
        where = "%s: element %s" % (what, index)
    vals = ", ".join("%s = %.9g" % (n, v[i]) for n, v in zip(names, values))
    return Error(code, "%s (%s)" % (where, vals), index=index, value=tuple(float(v[i]) for v in values)
                 if len(values) > 1 else float(values[0][i]), hint=hint)


def shaped(a, shape):
    """A result column in the input's shape; a float for scalar input."""
    return a.reshape(shape) if shape != () else float(a[0])


def shaped_bool(a, shape):
    return a.view(np.bool_).reshape(shape) if shape != () else bool(a[0])
