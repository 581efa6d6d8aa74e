# SPDX-License-Identifier: MIT
"""cffi (API mode) build of the extension mdr._mdr_cffi.

The C compiler, not cffi's parser, reads libmdr's headers: the cdef below
declares only what the package uses, and the extension's source includes the
real headers (mdr.h, python/src/mdr_py.h). Everything declared here is
checked against them when the extension is compiled:

  - constants are ``#define NAME ...``: their values come from the headers;
  - structs are declared with ``...;``: the compiler lays them out, and cffi
    checks each field named here by taking its address as a pointer of the
    declared type (a field of another type is an incompatible-pointer or
    pointer-sign warning, made an error below; a missing field an error);
  - the source checks the rest after the headers (declarations()): the
    typedefs again (a different one is a conflicting-types error), each
    function's address assigned to a pointer of the declared type (missing:
    an undeclared identifier; another type: an incompatible-pointer error),
    each declared field's address likewise (this catches the signedness of
    an integer field, which cffi itself takes from the cdef).

So the package cannot drift from the library: a changed header fails the
build. The per-arithmetic declarations are written once with {T} (float or
double) and {S} (f32 or f64), like the library's own templates
(lib/include/mdr_each_arith.h). ``python/tests/test_build.py`` proves that
a deliberate mismatch fails to compile.

The library's sources and python/src/mdr_py.c are compiled with the
library's own flags by setup.py (LIB_SOURCES, LIB_CFLAGS) and linked into
the extension.
"""
import os
import re

import cffi

HERE = os.path.dirname(os.path.abspath(__file__))
PKG = os.path.dirname(HERE)  # python/
ROOT = os.path.dirname(PKG)  # the repository
INCLUDE_DIRS = [
    os.path.join(ROOT, "lib", "include"),
    os.path.join(ROOT, "port", "host"),
    os.path.join(ROOT, "examples"),
    os.path.join(PKG, "src"),
]
LIB_SOURCES = [os.path.join(ROOT, "lib", "src", f) for f in ("mdr_f32.c", "mdr_f64.c", "mdr_q31.c", "mdr_status.c")]
HELPER_SOURCES = [os.path.join(PKG, "src", "mdr_py.c")]
# lib/Filelists.mk's MDR_REQUIRED_CFLAGS and the Makefile's WARN
# (python/tests/test_build.py checks that they agree)
LIB_CFLAGS = ["-std=c99", "-ffreestanding", "-fno-math-errno", "-ffunction-sections", "-fdata-sections"]
WARN = ["-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wdouble-promotion", "-Wshadow", "-Wvla", "-Werror"]
HELPER_CFLAGS = ["-std=c99", "-fno-math-errno"] + WARN
# the generated module: the warnings that reveal a mismatch of a declaration
# with the headers are errors
MODULE_CFLAGS = [
    "-Werror=incompatible-pointer-types",
    "-Werror=pointer-sign",
    "-Werror=int-conversion",
    "-Werror=implicit-function-declaration",
]

# status codes by name (mdr_types.h); python/tests/test_build.py checks that
# the list holds every MDR_E_* of the header
STATUS_NAMES = [
    "MDR_OK", "MDR_E_NULL", "MDR_E_NONFINITE", "MDR_E_PARAM", "MDR_E_KIND", "MDR_E_RADIUS",
    "MDR_E_POSITION", "MDR_E_CONTROL", "MDR_E_NOCONV", "MDR_E_SINGULAR", "MDR_E_OVERFLOW",
    "MDR_E_OUTSIDE", "MDR_E_TABLE", "MDR_E_SIZE", "MDR_E_DISABLED", "MDR_E_FEW", "MDR_E_ORDER",
    "MDR_E_NOCONTACT", "MDR_E_NOPULLOFF", "MDR_E_FITCAP", "MDR_E_DEGENERATE", "MDR_E_JUMPS",
    "MDR_E_PINNED", "MDR_E_MISFIT",
]
PROFILE_NAMES = ["PARABOLOID", "CONE", "POWERLAW", "FLATPUNCH", "SPHERE", "FLATTIP", "WAVY", "TABLE"]
EVENT_NAMES = ["NONE", "CONTACT", "JUMP_IN", "JUMP", "PULL_OFF", "RECONTACT", "SEPARATION"]
CONSTANTS = (
    STATUS_NAMES
    + ["MDR_PROFILE_" + p for p in PROFILE_NAMES]
    + ["MDR_CONTROL_LOAD", "MDR_CONTROL_GRIPS", "MDR_CONTROL_MACHINE"]
    + ["MDR_EV_" + e for e in EVENT_NAMES]
    + ["MDR_FLAG_OUTSIDE", "MDR_FLAG_NOCONV", "MDR_FLAG_SAT"]
    + ["MDR_SPRINGS_MIN", "MDR_SPRINGS_MAX", "MDR_TABLE_MIN_POINTS", "MDR_POWERLAW_N_MAX", "MDR_TABLE_BLOCK",
       "MDR_WAVY_SPRINGS_PER_WAVELENGTH"]
    + ["MDR_VERSION_MAJOR", "MDR_VERSION_MINOR"]
    + ["MDR_FIT_FULL", "MDR_FIT_TWO_POINT", "MDR_FIT_MIN_POINTS", "MDR_FIT_MIN_CONTACT", "MDR_FIT_MIN_RECEDE",
       "MDR_FIT_ITER_MAX"]
    + ["MDR_REGIME_JKR", "MDR_REGIME_TRANSITION", "MDR_REGIME_DMT"]
    + ["MDRPY_F32", "MDRPY_F64", "MDRPY_Q31", "MDRPY_MORE"]
    + ["MDRPY_EQ_" + c for c in ("A", "D", "F", "DD_DA", "DF_DA", "DL", "K_I", "G", "N")]
    + ["MDRPY_EQ_STABLE_LOAD", "MDRPY_EQ_STABLE_GRIPS", "MDRPY_EQ_NFLAGS"]
    + ["MDRPY_ST_" + c for c in ("A", "D", "F", "K_I", "G", "N")]
    + ["MDRPY_PR_" + c for c in ("G", "DG", "GINT", "N")]
    + ["MDRPY_EV_" + c for c in ("A0", "D0", "F0", "A1", "D1", "F1", "N")]
)

# the double fields of mdrpy_fit_res (python/src/mdr_py.h), in its order
FIT_DOUBLES = ("E", "w", "z0", "F_base", "E_err", "w_err", "z0_err", "F_base_err", "rms", "pull_off_F",
               "pull_off_z", "a_pull_off", "mu", "R_mu", "w_adv", "w_adv_err", "F_slope", "F_slope_err")

# structs: cffi lays them out ("...;"); the fields the package reads, each
# (type, name), are checked by the compiler (CHECK below)
STRUCTS = {
    "mdr_node_q31": [],
    "mdrpy_engine": [],
    "mdrpy_info": [("double", f) for f in ("a", "d", "F", "dissipated", "last_cycle", "a_max", "L", "D0", "F0", "Z0")]
    + [("uint32_t", "cycles"), ("uint16_t", "springs"), ("uint8_t", "contact"), ("uint8_t", "flags")],
    "mdrpy_fit_res": [("double", f) for f in FIT_DOUBLES]
    + [("uint32_t", "n"), ("uint32_t", "n_approach"), ("uint32_t", "n_pinned"), ("uint16_t", "iterations"), ("uint8_t", "method"),
       ("uint8_t", "regime")],
}
STRUCTS_T = {
    "mdr_contact_{S}": [],
    "mdr_critstate_{S}": [("{T}", "a"), ("{T}", "d"), ("{T}", "F"), ("uint16_t", "jumps"), ("{T}", "F_min"),
                          ("{T}", "d_F_min")],
    "mdr_node_{S}": [],
}

# typedefs and function prototypes of the package (valid C)
DECLS = """
typedef int8_t mdr_status;
const char *mdr_status_str(mdr_status s);
const char *mdr_event_str(uint8_t event);
const char *mdr_regime_str(uint8_t regime);
size_t mdrpy_fit_work_len(size_t n);
double mdr_host_path_value(const double *path, long steps, long seg, long j);
int mdr_host_f32_shape_refused(uint8_t kind, const double p[3], double *change);
double mdrpy_f32_eq_max(void);
double mdrpy_f32_answer_max(void);
double mdrpy_f32_slope_max(void);
double mdrpy_f32_crit_max(void);
double mdrpy_f32_fit_max(void);
double mdrpy_f32_fit_err(void);
int mdrpy_f32_fit_check(const double p32[3], const double e32[3], const double p64[3], const double e64[3], int n,
                        int *which, double *x);
const char *mdrpy_f32_fit_which(int which);
double mdrpy_f32_crit_wrong(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m, double E,
                            double w, uint8_t control, double k_m, const double *a0, double a32, double d32, double F32,
                            double Fm32);
size_t mdrpy_f32_eq_check(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m, double E,
                          double w, size_t n, const double *a, const double *d, size_t k, const double *d32,
                          const double *F32, const double *dd32, const double *dF32, const double *K32, int *what,
                          double *value);
size_t mdrpy_f32_stress_wrong(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m,
                              double E, double w, size_t n, const double *a, const double *d, const double *rr,
                              const double *s32, double *err);
mdr_status mdrpy_extent(uint8_t arith, uint8_t kind, const double p[3], double E, double w,
                        uint8_t control, double k_m, const double *path, size_t npath,
                        double *a_max);
mdr_status mdrpy_extent_q31(uint8_t kind, const double p[3], double E, double w, double w_adv,
                            uint8_t control, double k_m, uint16_t springs, const double *path,
                            size_t npath, long steps, double *a_max);
mdr_status mdrpy_engine_profile(mdrpy_engine *x, uint8_t arith, uint8_t kind, const double p[3],
                                double E, double w, double w_adv, double k_m, uint16_t springs,
                                double a_max, mdr_node_f32 *n32, mdr_node_f64 *n64,
                                mdr_node_q31 *nq);
mdr_status mdrpy_engine_tip(mdrpy_engine *x, uint8_t arith, const double *r, const double *f,
                            uint16_t m, double E, double w, double w_adv, double k_m,
                            uint16_t springs, mdr_node_f32 *n32, mdr_node_f64 *n64,
                            mdr_node_q31 *nq);
mdr_status mdrpy_engine_reset(mdrpy_engine *x);
void mdrpy_engine_info(const mdrpy_engine *x, mdrpy_info *o);
mdr_status mdrpy_check_path(const mdrpy_engine *x, uint8_t control, const double *path,
                            size_t npath, size_t *bad);
mdr_status mdrpy_run(mdrpy_engine *x, uint8_t control, const double *path, size_t npath, long steps,
                     size_t tick0, size_t nticks, double *z, double *d, double *F, double *a,
                     uint8_t *event, size_t ev_cap, size_t *ev_n, size_t *ev_step,
                     uint8_t *ev_code, double *ev_val, size_t *done);
"""
DECLS_T = """
mdr_status mdr_contact_init_{S}(mdr_contact_{S} *c, uint8_t kind, const {T} p[3], {T} E, {T} w);
mdr_status mdr_critical_{S}(const mdr_contact_{S} *c, uint8_t control, {T} k_m, {T} a_start,
                            mdr_critstate_{S} *out);
mdr_status mdr_default_start_{S}(const mdr_contact_{S} *c, {T} *a_start);
mdr_status mdr_engine_check_{S}({T} E, {T} w, {T} w_adv, {T} k_m);
mdr_status mdrpy_eq_{S}(const mdr_contact_{S} *c, size_t n, const double *a, double *out,
                        uint8_t *flags, size_t *fail);
mdr_status mdrpy_state_{S}(const mdr_contact_{S} *c, size_t n, const double *a, const double *d,
                           double *out, size_t *fail);
mdr_status mdrpy_stress_{S}(const mdr_contact_{S} *c, size_t n, const double *a, const double *d,
                            const double *r, double *sigma, size_t *fail);
mdr_status mdrpy_profile_{S}(const mdr_contact_{S} *c, size_t n, const double *x, double *out,
                             size_t *fail);
mdr_status mdrpy_contact_tip_{S}(mdr_contact_{S} *c, const double *r, const double *f, uint16_t m, double E,
                                 double w, double *s, {T} *buf);
mdr_status mdrpy_fit_{S}(const mdr_contact_{S} *tip, double k_m, double z_e, double E0, double w0,
                         uint8_t method, uint8_t approach, uint8_t unpinned, uint8_t flat, const double *z,
                         const double *F, uint32_t n,
                         {T} *work, size_t work_len, mdrpy_fit_res *o, size_t *fail);
mdr_status mdrpy_fit_model_{S}(const mdr_contact_{S} *tip, double k_m, const mdrpy_fit_res *res,
                               double w_approach, const double *z, uint32_t n, {T} *work, size_t work_len,
                               double *Fm, uint32_t *top);
"""
ARITHS = (("float", "f32"), ("double", "f64"))

_PROTO = re.compile(r"^(?P<ret>.*?[\s*])(?P<name>\w+)\s*\((?P<args>.*)\)$", re.S)


def all_decls():
    """The typedefs and prototypes, every arithmetic."""
    return DECLS + "".join(DECLS_T.format(T=t, S=s) for t, s in ARITHS)


def all_structs():
    """{struct: [(type, field), ...]}, every arithmetic."""
    structs = dict(STRUCTS)
    for t, s in ARITHS:
        structs.update({n.format(S=s): [(ty.format(T=t), f) for ty, f in fl] for n, fl in STRUCTS_T.items()})
    return structs


def declarations(decls=None, structs=None, constants=None):
    """(cdef, check): the text cffi parses, and the C the extension's source
    adds after the headers to check it: the typedefs again (a different one
    is a conflicting-types error), every function's address assigned to a
    pointer of the declared type (a missing function is an undeclared
    identifier, a different type an incompatible-pointer error) and every
    declared field's address to a pointer of its declared type (a missing
    field is an error, another type an incompatible-pointer or pointer-sign
    error). decls, structs, constants replace the package's (the build test
    plants mismatches this way)."""
    decls = all_decls() if decls is None else decls
    structs = all_structs() if structs is None else structs
    constants = CONSTANTS if constants is None else constants
    cdef = "".join("#define %s ...\n" % c for c in constants)
    cdef += "".join("typedef struct { %s...; } %s;\n" % ("".join("%s %s; " % tf for tf in fields), name)
                    for name, fields in structs.items())
    cdef += decls
    typedefs, checks = [], []
    for d in (x.strip() for x in decls.split(";")):
        if d.startswith("typedef"):
            typedefs.append(d + ";")
        elif d:
            m = _PROTO.match(d)
            checks.append("    { %s(*mdr_fn)(%s) = &%s; (void)mdr_fn; }" % (m["ret"], m["args"], m["name"]))
    for name, fields in structs.items():
        checks += ["    { %s *p = (%s *)any; %s *mdr_fld = &p->%s; (void)mdr_fld; }" % (name, name, t, f)
                   for t, f in fields]
    check = "\n".join(typedefs) + (
        "\n__attribute__((unused)) static void mdr_cffi_declarations_match(void *any)\n{\n%s\n}\n"
        % "\n".join(checks))
    return cdef, check


def make_ffibuilder(cdef=None, check=None):
    """The FFI builder of the extension; cdef/check replace the package's
    declarations (see declarations())."""
    if cdef is None:
        cdef, check = declarations()
    ffi = cffi.FFI()
    ffi.cdef(cdef)
    ffi.set_source(
        "mdr._mdr_cffi",
        '#include "mdr.h"\n#include "mdr_py.h"\n'
        "/* the cdef checked against the headers (python/mdr/_build.py, declarations()) */\n" + check,
        include_dirs=INCLUDE_DIRS,
        extra_compile_args=MODULE_CFLAGS,
    )
    return ffi


ffibuilder = make_ffibuilder()

if __name__ == "__main__":
    ffibuilder.compile(verbose=True)
