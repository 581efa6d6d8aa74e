/* SPDX-License-Identifier: MIT */
/*
 * mdr_host.h: host-side helpers shared by the mdr CLI (examples/mdr_cli.c)
 * and the Python package (python/src/mdr_py.c), so that both drive the
 * engines the same way and give the same numbers:
 *   - the value of the controlled variable at a tick of a piecewise-linear
 *     path;
 *   - the q31 engine in SI units: the units of its Q formats in double and
 *     the conversions SI <-> raw (lib/include/mdr_q31.h, "Units");
 *   - the contact of a sampled tip from radii and slopes in double (the
 *     spring table of `mdr cycle --profile table` and Engine.from_tip).
 * Host code (double arithmetic); static inline functions, nothing from the C
 * library. The per-arithmetic helpers are in mdr_host_t.h.
 */
#ifndef MDR_HOST_H
#define MDR_HOST_H

#include <float.h>
#include <math.h>

#include "mdr.h"

/**
 * @brief Value of the controlled variable at tick j of segment seg of a
 *        piecewise-linear path: path[seg] + (path[seg+1] - path[seg]) j/steps.
 * @param path  the path's vertices (at least seg + 2 of them)
 * @param steps ticks per segment, >= 1; j = 0 is path[seg], j = steps is
 *              path[seg+1] exactly (the formula's rounding is relative to the
 *              larger vertex: a path 0, 1e20, -1e-3 ended at 0 instead of
 *              -1e-3, in contact at a tensile force with no pull-off, status
 *              ok; helper-30, stop 57)
 */
static inline double mdr_host_path_value(const double *path, long steps, long seg, long j)
{
    return j == steps ? path[seg + 1] : path[seg] + (path[seg + 1] - path[seg]) * (double)j / (double)steps;
}

/* v rounded to float in double (v finite within float's range), through
 * a volatile float: with (double)(float)v, GCC 12 at -O2 gave v itself in
 * mdr_host_f32_eq_change (the CLI's check of the flattened tip at a = b
 * (1 + 5.6e-3) saw 4.8e-7 where the rounding moves the state 4.6e-6, as
 * -O0 and the volatile show) */
static inline double mdr_host_f32_round(double v)
{
    volatile float f = (float)v;
    return (double)f;
}

/* v finite within float's range (not NaN): one the f32 input checks have
 * not refused, which mdr_host_f32_round may convert */
static inline int mdr_host_in_float(double v)
{
    return v >= -(double)FLT_MAX && v <= (double)FLT_MAX;
}

/** Above this change of its coefficients (relative), f32's rounding of a
 *  profile's parameters is refused (mdr_host_f32_shape_change()): the
 *  cone's critical F moves 3 times the change of tan(theta), a twice, d
 *  once (measured in f64, theta = 1.4), so with f32's own error (5.2e-7
 *  for the cone's critical state, docs/accuracy.md) a critical state stays
 *  within f32's goal for them, 2e-6. The rounding of theta (up to 6e-8
 *  rad) reaches it only past theta ~ 1.45 (sin theta cos theta < 0.12): a
 *  half-angle under 7 degrees. */
#define MDR_HOST_F32_SHAPE_MAX 5e-7

/**
 * @brief How far rounding a profile's parameters to float moves the
 *        profile: the largest relative change of its derived coefficients
 *        (the contact's k[], its shape: the cone's (pi/2) tan(theta)),
 *        between the parameters p and p rounded to float, both in f64.
 *        Every profile follows its parameters to about their rounding
 *        (6e-8) except the cone near pi/2: its tan(theta) changes by
 *        |dtheta| / (sin theta cos theta), and f32's rounding of theta by up
 *        to 6e-8 rad made `mdr critical --profile cone --theta 1.5707962
 *        --arith f32` answer a 2.8 times f64's, status ok (helper-37, stop
 *        59). The host's f32 callers (the CLI, the Python package) refuse
 *        a change beyond MDR_HOST_F32_SHAPE_MAX (mdr_host_f32_shape_refused).
 * @param kind  an analytic profile (MDR_PROFILE_*, not MDR_PROFILE_TABLE)
 * @param p     its parameters in double
 * @return the change; 0 where p is beyond float or the f64 contact
 *         refuses it (the f32 input checks and init name those); DBL_MAX
 *         where it takes p and refuses p rounded (theta rounded up to pi/2)
 */
static inline double mdr_host_f32_shape_change(uint8_t kind, const double p[3])
{
    mdr_contact_f64 c, r;
    double q[3], m = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        if (!mdr_host_in_float(p[i])) {
            return 0.0; /* (beyond float or NaN: the f32 input checks' case) */
        }
        q[i] = mdr_host_f32_round(p[i]);
    }
    if (mdr_contact_init_f64(&c, kind, p, 1.0, 0.0) != MDR_OK) {
        return 0.0;
    }
    if (mdr_contact_init_f64(&r, kind, q, 1.0, 0.0) != MDR_OK) {
        return DBL_MAX;
    }
    for (i = 0; i < 3; i++) {
        const double e = c.k[i] != 0.0 ? (r.k[i] - c.k[i]) / c.k[i] : 0.0;
        m = e > m ? e : -e > m ? -e : m;
    }
    return m;
}

/**
 * @brief Whether the host's f32 callers refuse the profile p: rounded to
 *        float it moves by more than MDR_HOST_F32_SHAPE_MAX
 *        (mdr_host_f32_shape_change(), written to *change).
 */
static inline int mdr_host_f32_shape_refused(uint8_t kind, const double p[3], double *change)
{
    *change = mdr_host_f32_shape_change(kind, p);
    return *change > MDR_HOST_F32_SHAPE_MAX;
}

/** Above this change (relative, mdr_host_f32_eq_change()), f32's rounding
 *  of an equilibrium's inputs is refused: with f32's own error in such a
 *  state (at most 5.2e-7 for the smooth profiles, docs/accuracy.md) an
 *  answer stays within f32's goal of 2e-6. */
#define MDR_HOST_F32_EQ_MAX 1.5e-6

/* the scales on which docs/accuracy.md compares a state (d, F) at a with
 * dl (4.21): o[2] = max(|d|, dl), o[3] = max(|F|, 2 E* a dl) */
static inline void mdr_host_dF_scales(double E, double a, double dl, double d, double F, double o[4])
{
    o[2] = fabs(d) > dl ? fabs(d) : dl;
    o[3] = fabs(F) > 2.0 * E * a * dl ? fabs(F) : 2.0 * E * a * dl;
}

/* The force of the state (a, d), pinned or in equilibrium: 2 E* (a d -
 * G(a)) (4.26; at fixed a, F is linear in d), G = G(a) and the
 * equilibrium's d_eq, F_eq at a, in double: directly where G is a normal
 * number of the arithmetic (tmin its least: an underflowed G, a tiny
 * cone's at a = 3e-26 m in f32, has lost its digits), else as F_eq +
 * 2 E* a (d - d_eq), whose terms carry the adhesion's -2 E* a dl and
 * +2 E* a dl and cancel where |F| is small against them (that form alone,
 * before: helper-62, the paraboloid R 10 um, E* 1 MPa, w 0.05 at
 * a = 1 nm, d = 0 6.3 % off in f32, a power law C 1e20, n 8 at a = 30 um
 * 100 % (0) in f32 and 1.5e-6 in f64). (a d: exact in double for f32.) */
/* the least normal number and the largest finite one of each arithmetic */
static inline double mdr_host_tmin_f32(void)
{
    return (double)FLT_MIN;
}
static inline double mdr_host_tmin_f64(void)
{
    return DBL_MIN;
}
static inline double mdr_host_tmax_f32(void)
{
    return (double)FLT_MAX;
}
static inline double mdr_host_tmax_f64(void)
{
    return DBL_MAX;
}

static inline double mdr_host_state_F(double E, double a, double d, double G, double F_eq, double d_eq,
                                      double tmin)
{
    if (G >= tmin) {
        return 2.0 * E * (a * d - G);
    }
    return F_eq + 2.0 * E * a * (d - d_eq);
}

/* d and F of the f64 equilibrium at a of the contact c (of modulus E), or
 * of the state (a, *d) (F = F_eq + 2 E* a (d - d_eq), as `mdr eq --d`),
 * with the scales docs/accuracy.md compares them on (d: max(|d|, dl), F:
 * max(|F|, 2 E* a dl)), in o[0..3]; the equilibrium's dd/da and dF/da in
 * o[4..5] with the sizes of their terms in o[6..7] (dd/da = g'(a) -
 * dl/(2a): |g'(a)| + dl/(2a); dF/da = 2 E* (a dd/da - dl): 2 E* (a o[6] +
 * dl)); false where f64 refuses them */
static inline int mdr_host_eq64_c(const mdr_contact_f64 *c, double E, double a, const double *d, double o[8])
{
    mdr_eqstate_f64 e;
    double G = 0.0;
    if (mdr_eq_f64(c, a, &e) != MDR_OK || (d != NULL && mdr_profile_eval_f64(c, e.a, NULL, NULL, &G) != MDR_OK)) {
        return 0;
    }
    o[0] = d != NULL ? *d : e.d;
    o[1] = d != NULL ? mdr_host_state_F(E, e.a, *d, G, e.F, e.d, DBL_MIN) : e.F;
    mdr_host_dF_scales(E, e.a, e.dl, o[0], o[1], o);
    o[4] = e.dd_da;
    o[5] = e.dF_da;
    /* (g' = dd/da + dl/(2a): the two terms without another evaluation) */
    o[6] = fabs(e.dd_da + 0.5 * e.dl / e.a) + 0.5 * e.dl / e.a;
    o[7] = 2.0 * E * (e.a * o[6] + e.dl);
    return o[0] - o[0] == 0.0 && o[1] - o[1] == 0.0;
}

/* How far (d, F) lies from (d0, F0) on the scales o[2], o[3] of
 * mdr_host_eq64_c() (d: max(|d|, dl), F: max(|F|, 2 E* a dl)): the larger
 * relative error of the two, as docs/accuracy.md compares f32 with f64 */
static inline double mdr_host_dF_err(double d, double F, double d0, double F0, const double *o)
{
    const double ed = fabs(d - d0) / o[2], eF = fabs(F - F0) / o[3];
    return ed > eF ? ed : eF;
}

/* The two f64 contacts of mdr_host_f32_eq_change(): at the values given
 * (profile, E, w) and at their roundings to float, made once for every
 * radius of a caller (the CLI's curve rows, the Python package's f32 eq:
 * mdrpy_f32_eq_check in python/src/mdr_py.c); cok, rok: f64 takes them */
typedef struct {
    mdr_contact_f64 c, r;
    double E;
    int cok, rok;
} mdr_host_f32_eq_pair;

/* false where a parameter, E or w is beyond float (the change is then 0:
 * the f32 input checks name those) */
static inline int mdr_host_f32_eq_pair_init(mdr_host_f32_eq_pair *x, uint8_t kind, const double p[3], double E,
                                            double w)
{
    double q[3];
    int i;
    for (i = 0; i < 3; i++) {
        if (!mdr_host_in_float(p[i])) {
            return 0;
        }
        q[i] = mdr_host_f32_round(p[i]);
    }
    if (!mdr_host_in_float(E) || !mdr_host_in_float(w)) {
        return 0;
    }
    x->E = E;
    x->cok = mdr_contact_init_f64(&x->c, kind, p, E, w) == MDR_OK;
    x->rok = mdr_contact_init_f64(&x->r, kind, q, mdr_host_f32_round(E), mdr_host_f32_round(w)) == MDR_OK;
    return 1;
}

/* The pair of a sampled tip (mdr_host_tip_contact: radii r, slopes s of m
 * samples, in double): the f64 contact at those, and at their conversions
 * to float, which the f32 contact holds (rd: caller storage of 2 m values,
 * kept while the pair is used), with E and w rounded. On a measured tip
 * f32's arithmetic is within 2e-7 of f64 on the same float samples
 * (test_critical table_measured_tips_f32), but the conversion itself moves
 * the model: each radius by up to eps r/2, so the heights beyond a slope
 * jump (quantized heights) drift by that times the jump, and near a node
 * the state depends on a - r_k, which float resolves to eps a. A 20 nm
 * sphere at 1 000 radii with heights quantized to 0.1 nm: 4e-5 of max|F|
 * (docs/accuracy.md). false (the change is then 0) where a value is beyond
 * float (the f32 conversion refuses those, MDR_E_OVERFLOW). */
static inline int mdr_host_f32_eq_pair_init_tip(mdr_host_f32_eq_pair *x, const double *r, const double *s, uint16_t m,
                                                double E, double w, double *rd)
{
    uint16_t i;
    if (!mdr_host_in_float(E) || !mdr_host_in_float(w)) {
        return 0;
    }
    for (i = 0; i < m; i++) {
        if (!mdr_host_in_float(r[i]) || (i + 1 < m && !mdr_host_in_float(s[i]))) {
            return 0;
        }
        rd[i] = mdr_host_f32_round(r[i]);
        rd[m + i] = i + 1 < m ? mdr_host_f32_round(s[i]) : 0.0;
    }
    x->E = E;
    x->cok = mdr_contact_init_table_f64(&x->c, r, s, m, E, w) == MDR_OK;
    x->rok = mdr_contact_init_table_f64(&x->r, rd, rd + m, m, mdr_host_f32_round(E), mdr_host_f32_round(w)) == MDR_OK;
    return 1;
}

/** Above this error (relative, on mdr_host_f32_eq_change()'s scales) an
 *  f32 equilibrium's answer is refused (mdr_host_f32_eq_pair_err()):
 *  f32's goal for a state (docs/accuracy.md). */
#define MDR_HOST_F32_ANSWER_MAX 2e-6

/** Above this error (relative to the sizes of its terms,
 *  mdr_host_eq64_c()) an f32 equilibrium's dd/da or dF/da is refused
 *  (mdr_host_f32_eq_pair_err()): a derivative carries one cancellation more
 *  than d and F, and f32's goal for it is wider. Measured against f64 at the
 *  same float inputs over 2 000 radii (1 nm to 3 um) of each analytic
 *  profile, E* 1e6 to 1e11, w 0.01 to 0.5 (stop 63): the wavy profile 3.9e-5,
 *  the flattened tip at its rim 7.4e-6, the sphere near a = R 2.5e-6, the
 *  rest below 2.4e-7. A measured tip's samples converted to float moved it
 *  beyond (a 20 nm sphere at 1 000 radii, heights quantized to 0.1 nm: 8e-5
 *  and 2.1e-4 at two radii where d and F were within 3e-7, printed by `mdr
 *  eq` with exit 0 before). */
#define MDR_HOST_F32_SLOPE_MAX 5e-5

/* the tolerance of mdr_host_f32_eq_pair_check()'s quantity k (0 d, 1 F,
 * 2 dd/da, 3 dF/da, 4 a state's K_I) */
static inline double mdr_host_f32_max(int k)
{
    return k == 2 || k == 3 ? MDR_HOST_F32_SLOPE_MAX : MDR_HOST_F32_ANSWER_MAX;
}

/* How far an f32 K_I of the state (a, d) lies from f64's at the values
 * given, relative to the larger of |K_I| and the critical value
 * sqrt(2 E* w) it is compared with (G_rel = K_I^2/(2E*) then within twice
 * that of w): K_I = E* (g(a) - d)/sqrt(pi a) of a pinned state is a
 * difference of g(a) and d, which float keeps to eps g(a): where g(a) is
 * far above g(a) - d f32 prints nothing of it (helper-65, stop 71: R 1 cm,
 * E* 1e12, a 9 mm, a state 2e-10 m inside its equilibrium: K_I 0 and G_rel
 * 0 for 1218.5 and 0.742 w, exit 0; R 100 um, E* 100 GPa, a 90 um: 4.6e-5
 * of sqrt(2 E* w) off). 0 where f64 refuses the state. */
static inline double mdr_host_f32_K_err(const mdr_contact_f64 *c, double a, double d, double K32)
{
    double K64, sc;
    if (mdr_stress_intensity_f64(c, a, d, &K64, NULL) != MDR_OK) {
        return 0.0;
    }
    sc = sqrt(2.0 * c->E * c->w);
    sc = fabs(K64) > sc ? fabs(K64) : sc;
    return fabs(K32 - K64) / sc;
}

/* Both f32 checks of an equilibrium (or the state (a, *d)) through the
 * pair x, from one f64 state at the values given: *change (not NULL) the
 * rounding's (mdr_host_f32_eq_pair_change(): against the f64 state at the
 * roundings; DBL_MAX where f64 refuses those), *err (with ans, the f32
 * answer d32, F32, and with dv also its equilibrium's dd/da, dF/da, with
 * K (a state's, d not NULL) its K_I, mdr_host_f32_K_err()) the
 * answer's (mdr_host_f32_eq_pair_err(); *which, not NULL: the quantity
 * furthest beyond its tolerance, 0 d, 1 F, 2 dd/da, 3 dF/da, 4 K_I: *err is its
 * error, refused beyond mdr_host_f32_max(*which)); each 0 where a, d are beyond
 * float or f64 refuses the values given (the f32 call names those). The
 * Python package's f32 Contact.eq takes both in one call per point
 * (mdrpy_f32_eq_check). */
static inline void mdr_host_f32_eq_pair_check(const mdr_host_f32_eq_pair *x, double a, const double *d,
                                              double *change, const double ans[2], const double *dv,
                                              const double *K, double *err, int *which)
{
    double v[8];
    if (change != NULL) {
        *change = 0.0;
    }
    if (err != NULL) {
        *err = 0.0;
    }
    if (!x->cok || !mdr_host_in_float(a) || (d != NULL && !mdr_host_in_float(*d)) ||
        !mdr_host_eq64_c(&x->c, x->E, a, d, v)) {
        return;
    }
    if (err != NULL) {
        /* (the quantity furthest beyond its tolerance, mdr_host_f32_max) */
        int k, best = 0, n = dv != NULL ? 4 : 2;
        *err = 0.0;
        for (k = 0; k < n; k++) {
            const double e = fabs((k < 2 ? ans[k] : dv[k - 2]) - v[k < 2 ? k : k + 2]) / v[k < 2 ? k + 2 : k + 4];
            if (k == 0 || e / mdr_host_f32_max(k) > *err / mdr_host_f32_max(best)) {
                *err = e;
                best = k;
            }
        }
        if (K != NULL && d != NULL) {
            const double e = mdr_host_f32_K_err(&x->c, a, *d, *K);
            if (e / mdr_host_f32_max(4) > *err / mdr_host_f32_max(best)) {
                *err = e;
                best = 4;
            }
        }
        if (which != NULL) {
            *which = best;
        }
    }
    if (change != NULL) {
        double u[8];
        const double dr = d != NULL ? mdr_host_f32_round(*d) : 0.0;
        *change = x->rok && mdr_host_eq64_c(&x->r, mdr_host_f32_round(x->E), mdr_host_f32_round(a),
                                            d != NULL ? &dr : NULL, u)
                      ? mdr_host_dF_err(u[0], u[1], v[0], v[1], v)
                      : DBL_MAX;
    }
}

/* How far an f32 answer (d32, F32: computed at the inputs' roundings; with
 * dv also its equilibrium's dd/da and dF/da, on their scales over a,
 * mdr_host_eq64_c) lies from the f64 state at the values given (x's first
 * contact), on mdr_host_f32_eq_change()'s scales: the rounding's change
 * and f32's own arithmetic together. The derivatives amplify what moves
 * the samples of a measured tip: a 20 nm sphere sampled at 1 000 radii,
 * heights quantized to 0.1 nm, answered dd/da up to 6.6e-6 off (stop 63)
 * where d and F were within 3e-7. The second is within f32's goal on the profiles
 * and tips the tests sweep, but not everywhere: on a coarse table near its
 * axis f' is the small difference of an interval's slope and curvature
 * terms, eps h/a of it in float (5 samples of a 1 mm sphere, a 1.3 % of
 * the first interval: 9.3e-6 with the rounding's change 2.7e-7; helper-50,
 * stop 62). The CLI's f32 eq and curve rows and the Python package's f32
 * Contact.eq refuse an error beyond MDR_HOST_F32_ANSWER_MAX. 0 where f64
 * refuses the values given (the f32 call names those). */
static inline double mdr_host_f32_eq_pair_err(const mdr_host_f32_eq_pair *x, double a, const double *d, double d32,
                                              double F32, const double *dv, const double *K, int *which)
{
    const double ans[2] = {d32, F32};
    double er;
    mdr_host_f32_eq_pair_check(x, a, d, NULL, ans, dv, K, &er, which);
    return er;
}

/* the name of mdr_host_f32_eq_pair_check()'s *which in the refusals: the
 * state's d and F are "answer", as before the derivatives were checked */
static inline const char *mdr_host_f32_which(int which)
{
    return which == 2 ? "dd_da" : which == 3 ? "dF_da" : which == 4 ? "K_I" : "answer";
}

/* (mdr_host_f32_stress_err on the f64 contact c of modulus E, below) */
static inline double mdr_host_stress_err_c(const mdr_contact_f64 *c, double E, double a, const double *d, double r,
                                           double s32)
{
    double s64, g, t1, sc, er;
    /* (g(a) - d: at the equilibrium dl = c_dl sqrt(a), 4.21, as mdr_stress
     * takes it; not through mdr_eq, which refuses the flattened tip's rim,
     * its pull-off under load and grips: the check answered 0 there, and a
     * stress 1.3e-5 to 3.4e-2 off f64's passed, helper-52, stop 63) */
    if ((d != NULL ? mdr_stress_at_f64(c, a, *d, r, &s64) : mdr_stress_f64(c, a, r, &s64)) != MDR_OK ||
        mdr_profile_eval_f64(c, a, &g, NULL, NULL) != MDR_OK) {
        return 0.0;
    }
    t1 = E / 3.14159265358979323846 * (d != NULL ? g - *d : c->c_dl * sqrt(a)) / sqrt((a - r) * (a + r));
    sc = (t1 < 0.0 ? -t1 : t1) + (t1 - s64 < 0.0 ? s64 - t1 : t1 - s64);
    er = (s32 - s64) / sc;
    return er < 0.0 ? -er : er;
}

/* The same for an f32 stress s32 at r in the state (a, *d) (d NULL: the
 * equilibrium at a): against the f64 stress at the values given, relative
 * to the size of the two terms of 4.27, E* |g(a) - d|/(pi sqrt(a^2 - r^2))
 * and the Abel integral's (docs/accuracy.md's scale for the stress). On
 * measured tips (quantized or noisy heights) f32's stress missed f64 by up
 * to 1.4e-3 of max|sigma| (test_critical table_measured_tips_f32); the CLI's
 * f32 `stress --a` and the Python package's f32 Contact.stress refuse an
 * error beyond MDR_HOST_F32_ANSWER_MAX. 0 where f64 refuses the values. */
static inline double mdr_host_f32_stress_err(const mdr_host_f32_eq_pair *x, double a, const double *d, double r,
                                             double s32)
{
    if (!x->cok || !mdr_host_in_float(a) || !mdr_host_in_float(r) || (d != NULL && !mdr_host_in_float(*d))) {
        return 0.0;
    }
    return mdr_host_stress_err_c(&x->c, x->E, a, d, r, s32);
}

/* f64's critical state o of x's first contact at the values given, from
 * the start *a0 as given (NULL: f64's default start; the f32 one, the last
 * radius rounded, can lie beyond f64's table); false where f64 refuses */
static inline int mdr_host_crit64(const mdr_host_f32_eq_pair *x, uint8_t control, double k_m, const double *a0,
                                  mdr_critstate_f64 *o)
{
    double s0 = 0.0;
    return x->cok && (a0 != NULL || mdr_default_start_f64(&x->c, &s0) == MDR_OK) &&
           mdr_critical_f64(&x->c, control, k_m, a0 != NULL ? *a0 : s0, o) == MDR_OK;
}

/** Above this difference (relative to f64's value; w_adv's to f64's w) an
 *  f32 fit's E*, w or w_adv is refused where 3 of its own reported errors do
 *  not cover it either (mdr_host_f32_fit_off()): the f32 fit's round trips
 *  promise 5e-5 (docs/fitting.md, Accuracy), and its reported errors leave
 *  out the arithmetic's own (on noise-free data they are the rounding's).
 *  Through a lever about 20 times softer than the contact a noise-free f32
 *  fit answered w 1.02e-4 off at 13.5 reported errors, status ok
 *  (helper-68, stop 71; f64 within 2e-15). */
#define MDR_HOST_F32_FIT_MAX 5e-5

/* How far an f32 fit lies from f64's fit of the same samples: of E*, w and
 * (n = 3, with the approach) w_adv, p32 and its reported errors e32
 * against f64's p64, the largest |p32 - p64|/|p64| (w_adv's over |w64|)
 * among those whose difference also exceeds 3 e32, and which one in *which
 * (0 E*, 1 w, 2 w_adv; -1 and 0 where every difference is within 3 of its
 * errors); mdr_host_f32_fit_check() refuses a value beyond
 * MDR_HOST_F32_FIT_MAX. */
static inline double mdr_host_f32_fit_off(const double p32[3], const double e32[3], const double p64[3], int n,
                                          int *which)
{
    double worst = 0.0;
    int k;
    *which = -1;
    for (k = 0; k < n && k < 3; k++) {
        const double dv = fabs(p32[k] - p64[k]), off = dv / fabs(p64[k == 2 ? 1 : k]);
        if (dv > 3.0 * e32[k] && off > worst) {
            worst = off;
            *which = k;
        }
    }
    return worst;
}

/** Above this ratio of f64's reported error to f32's, for the same samples,
 *  an f32 fit's error of E*, w or w_adv is refused
 *  (mdr_host_f32_fit_err_low()): the two fits see the same data, so their
 *  errors agree (noisy curves, correct options: f32's over f64's 0.55 to
 *  1.0 in 841 fits, stop 73); an f32 error far below f64's claims a
 *  precision f32's answer lacks (helper-72: a noise-free curve with
 *  hysteresis fitted --unpinned, w 0.0224563 +- 3.7e-8 in f32, 899 of its
 *  errors from the truth, against +- 3.1e-5 in f64, status ok). */
#define MDR_HOST_F32_FIT_ERR 3.0

/* Of E*, w and (n = 3) w_adv, the largest ratio e64/e32 of f64's reported
 * error to f32's for the same samples, and which (0 E*, 1 w, 2 w_adv) in
 * *which (-1 and 0 where f32's is not below f64's);
 * mdr_host_f32_fit_check() refuses a ratio beyond MDR_HOST_F32_FIT_ERR. */
static inline double mdr_host_f32_fit_err_low(const double e32[3], const double e64[3], int n, int *which)
{
    double worst = 0.0;
    int k;
    *which = -1;
    for (k = 0; k < n && k < 3; k++) {
        const double r = e64[k] / e32[k];
        if (e64[k] > e32[k] && r > worst) {
            worst = r;
            *which = k;
        }
    }
    return worst;
}

/* The f32 fit's check against f64's fit of the same samples, the one rule
 * of the CLI's `fit --arith f32` and the Python package's
 * fit(arith="f32"): of E*, w and (n = 3) w_adv, p32 and e32 the f32
 * answer and its reported errors, p64 and e64 f64's. 0: the answer
 * stands; 1: a value lies beyond MDR_HOST_F32_FIT_MAX and 3 of its errors
 * from f64's (mdr_host_f32_fit_off: *x the relative difference); 2: an
 * error lies below f64's by more than MDR_HOST_F32_FIT_ERR
 * (mdr_host_f32_fit_err_low: *x the ratio). *which: 0 E*, 1 w, 2 w_adv
 * (mdr_host_f32_fit_which names it). */
static inline int mdr_host_f32_fit_check(const double p32[3], const double e32[3], const double p64[3],
                                         const double e64[3], int n, int *which, double *x)
{
    *x = mdr_host_f32_fit_off(p32, e32, p64, n, which);
    if (*x > MDR_HOST_F32_FIT_MAX) {
        return 1;
    }
    *x = mdr_host_f32_fit_err_low(e32, e64, n, which);
    return *x > MDR_HOST_F32_FIT_ERR ? 2 : 0;
}

/* the name of mdr_host_f32_fit_check()'s which */
static inline const char *mdr_host_f32_fit_which(int which)
{
    return which == 0 ? "E*" : which == 1 ? "w" : "w_adv";
}

/** Above this error an f32 critical state is refused
 *  (mdr_host_f32_crit_err()): the critical search's f32 tolerance
 *  (host_tests/test_critical.c REL32; its sweep's worst 2.5e-6). */
#define MDR_HOST_F32_CRIT_MAX 3e-6

/* How far an f32 critical state (a32, d32, F32 and the most tensile force
 * Fm32: mdr_critical at the inputs' roundings) lies from f64's at the
 * values given, from the start *a0 as given (NULL: f64's default start; the
 * f32 one, the last radius rounded, can lie beyond f64's table): a relative to itself, d to
 * max(|d|, dl), F to max(|F|, 2 E* a dl) (dl at f64's a), the most tensile
 * force to the larger of that and its own size. 5 exact samples of a 1 mm
 * sphere to 0.75 mm, E* 1e11, w 0.05, pull off at 2.4 % of the first
 * interval, where f32's eq misses its goal (mdr_host_f32_eq_pair_err): its
 * most tensile force 3.4e-6 off (stop 62). The CLI's f32 `critical` and the Python package's f32
 * Contact.critical refuse an error beyond MDR_HOST_F32_CRIT_MAX. 0 where f64
 * refuses (the f32 answer stands). */
static inline double mdr_host_f32_crit_err(const mdr_host_f32_eq_pair *x, uint8_t control, double k_m,
                                           const double *a0, double a32, double d32, double F32, double Fm32)
{
    mdr_critstate_f64 o;
    double v[4], ea, eM;
    if (!mdr_host_crit64(x, control, k_m, a0, &o)) {
        return 0.0;
    }
    if (o.a == 0.0) { /* (no contact at the end: compared as is) */
        ea = a32 != 0.0 ? 1.0 : 0.0;
        return ea;
    }
    /* the scales of mdr_host_eq64_c() at the state (o.a, o.d, o.F), an
     * equilibrium, with dl = c_dl sqrt(a) (4.21): not through mdr_eq,
     * which refuses the flattened tip's rim, its pull-off (the check was 0
     * there; helper-52, stop 63) */
    mdr_host_dF_scales(x->E, o.a, x->c.c_dl * sqrt(o.a), o.d, o.F, v);
    ea = fabs(a32 - o.a) / o.a;
    eM = fabs(Fm32 - o.F_min) / (fabs(o.F_min) > v[3] ? fabs(o.F_min) : v[3]);
    ea = ea > eM ? ea : eM;
    eM = mdr_host_dF_err(d32, F32, o.d, o.F, v);
    return ea > eM ? ea : eM;
}

/* The same for `stress --control` in f32: its stress s32 at the fraction
 * rf of its critical radius, against f64's stress at rf of f64's critical
 * radius (mdr_host_crit64), on the scale of mdr_host_f32_stress_err: what
 * f64 answers to the same command. Not at f32's own radius: at a flat's
 * rim (the flattened tip's pull-off) the stress depends on a - b as a
 * root, and float's rounding of b moves it (2.7e-4 at a = b + 1 ulp with
 * f32's answer within 1.3e-7 of f64's). The critical state is checked
 * first (mdr_host_f32_crit_err); its tolerance, MDR_HOST_F32_CRIT_MAX,
 * carries into the stress (a power law through a machine at rf = 0.99:
 * 2.5e-6). 0 where f64 refuses. */
static inline double mdr_host_f32_crit_stress_err(const mdr_host_f32_eq_pair *x, uint8_t control, double k_m,
                                                  const double *a0, double rf, double s32)
{
    mdr_critstate_f64 o;
    if (!mdr_host_in_float(rf) || !mdr_host_crit64(x, control, k_m, a0, &o) || !(o.a > 0.0)) {
        return 0.0;
    }
    return mdr_host_stress_err_c(&x->c, x->E, o.a, NULL, rf * o.a, s32);
}

/* mdr_host_f32_eq_change() at a (and *d) of the pair x */
static inline double mdr_host_f32_eq_pair_change(const mdr_host_f32_eq_pair *x, double a, const double *d)
{
    double ch;
    mdr_host_f32_eq_pair_check(x, a, d, &ch, NULL, NULL, NULL, NULL, NULL);
    return ch;
}

/**
 * @brief How far f32's rounding of an equilibrium's inputs moves it: the
 *        f64 state at the values given and at their roundings to float
 *        (the profile's parameters, E*, w, a and, for a state (a, d), d),
 *        compared as docs/accuracy.md compares f32 with f64 (d relative to
 *        max(|d|, dl), F to max(|F|, 2 E* a dl)). Where an answer depends
 *        on a small difference of its inputs, the rounding alone moves it
 *        beyond f32's accuracy though f32 computes its own inputs to a few
 *        ulp: the exact sphere at a = R (1 - 1e-5), 4e-5 to 3.3e-4 off
 *        f64 for the typed values (R = 1 um, a = 9.9999e-7: 4e-5), 3.3e-2
 *        at a = R (1 - 1.2e-7); the flattened tip just above its flat, a =
 *        b (1 + 1e-7), 1.8e-3 (helper-41, stop 60).
 *        The CLI refuses a change beyond MDR_HOST_F32_EQ_MAX (`eq`, and
 *        each row of `curve`), and so does the Python package's f32
 *        Contact.eq (both through mdr_host_f32_eq_pair: its contacts made
 *        once for all their radii).
 * @param kind  an analytic profile (not MDR_PROFILE_TABLE)
 * @param d     the state's depth, or NULL: the equilibrium at a
 * @return the larger change of d and F; 0 where a value is beyond float or
 *         f64 refuses the values given (the f32 call names those); DBL_MAX
 *         where f64 takes them and refuses their rounding
 */
static inline double mdr_host_f32_eq_change(uint8_t kind, const double p[3], double E, double w, double a,
                                            const double *d)
{
    mdr_host_f32_eq_pair x;
    return mdr_host_f32_eq_pair_init(&x, kind, p, E, w) ? mdr_host_f32_eq_pair_change(&x, a, d) : 0.0;
}

/** The q31 engine with its table and the SI units of its Q formats, in
 *  double (from L + L_lo, D0, Z0 and F0 = 2 E* L D0). */
typedef struct {
    mdr_table_q31 t;
    mdr_engine_q31 e;
    double L;  /**< length unit [m] (a: Q1.30 of L) */
    double D0; /**< depth unit [m] (d: Q2.29 of D0) */
    double F0; /**< force unit [N] (F: Q2.29 of F0) */
    double Z0; /**< base position unit [m] (z: Q2.29 of Z0) */
} mdr_host_q31;

/**
 * @brief The SI units of a q31 engine, after its table (t) and engine (e)
 *        were initialised.
 * @param E  the effective modulus E* [Pa] the engine was initialised with,
 *           as a double (F0 = 2 E* L D0 to double precision)
 */
static inline void mdr_host_q31_units(mdr_host_q31 *q, double E)
{
    q->L = (double)q->t.L + (double)q->t.L_lo;
    q->D0 = (double)q->e.D0;
    q->F0 = 2.0 * E * q->L * q->D0;
    q->Z0 = (double)q->e.Z0;
}

/**
 * @brief SI value -> raw Q2.29 of unit, rounded to nearest (ties away from 0).
 * @param v     value [SI]
 * @param unit  D0, F0 or Z0 of the engine [SI], > 0
 * @param[out] raw  the raw value; unchanged on MDR_E_NONFINITE
 * @return MDR_OK; MDR_E_NONFINITE (v is NaN or +-inf: nothing converted);
 *         MDR_E_OVERFLOW (|v| beyond the steps' documented input range of
 *         2 units, raw +-2^30: *raw is then the value clamped to the int32
 *         range, which a step saturates to +-2^30, setting MDR_FLAG_SAT)
 */
static inline mdr_status mdr_host_q31_raw(double v, double unit, int32_t *raw)
{
    double s;
    if (!(v - v == 0.0)) { /* NaN or +-inf (v - v is NaN for both) */
        return MDR_E_NONFINITE;
    }
    s = v / unit * 536870912.0;
    s = s > 2147483647.0 ? 2147483647.0 : s < -2147483648.0 ? -2147483648.0 : s;
    *raw = (int32_t)(s < 0 ? -(long long)(0.5 - s) : (long long)(s + 0.5));
    if (*raw > MDR_Q30_ONE || *raw < -MDR_Q30_ONE) {
        return MDR_E_OVERFLOW;
    }
    return MDR_OK;
}

/** The q31 unit of the controlled value [m or N]: D0 (grips), F0 (load), Z0 (machine). */
static inline double mdr_host_q31_unit(const mdr_host_q31 *q, uint8_t control)
{
    return control == MDR_CONTROL_GRIPS ? q->D0 : control == MDR_CONTROL_LOAD ? q->F0 : q->Z0;
}

/**
 * @brief The first value of a path outside the q31 input range, by the
 *        conversion the step makes (mdr_host_q31_raw()): each vertex, then
 *        each tick of the interpolation (which may round a vertex's value by
 *        an ulp), as `mdr cycle` steps them.
 * @param raw_min   the least raw value accepted besides the range (a
 *                   machine's z_min, below which a free body's depth
 *                   saturates; INT32_MIN: none)
 * @param[out] seg   that vertex (0-based; *tick = 0), or the segment of that
 *                   tick (*tick in 1..steps); written unless MDR_OK
 * @return MDR_OK, or mdr_host_q31_raw()'s status for that value
 *         (MDR_E_OVERFLOW below raw_min)
 */
static inline mdr_status mdr_host_q31_path(const double *path, long npath, long steps, double unit, int32_t raw_min,
                                           long *seg, long *tick)
{
    long s, j;
    int32_t raw = 0;
    mdr_status st;
    for (s = 0; s < npath; s++) {
        st = mdr_host_q31_raw(path[s], unit, &raw);
        if (st == MDR_OK && raw < raw_min) {
            st = MDR_E_OVERFLOW;
        }
        if (st != MDR_OK) {
            *seg = s;
            *tick = 0;
            return st;
        }
    }
    for (s = 0; s + 1 < npath; s++) {
        for (j = 1; j <= steps; j++) {
            st = mdr_host_q31_raw(mdr_host_path_value(path, steps, s, j), unit, &raw);
            if (st == MDR_OK && raw < raw_min) {
                st = MDR_E_OVERFLOW;
            }
            if (st != MDR_OK) {
                *seg = s;
                *tick = j;
                return st;
            }
        }
    }
    return MDR_OK;
}

/**
 * @brief The first nonzero vertex of a path that the q31 conversion
 *        (mdr_host_q31_raw()) rounds to 0 LSB of unit: below half an LSB,
 *        a cycle the q31 engine never makes (a path to 2e-12 N under load
 *        gave no event and every row 0, with exit 0 in the CLI, helper-37
 *        at stop 59; and in Python's q31 Engine.run, found after it).
 *        Ticks between vertices may round to 0 (they pass near 0); a
 *        vertex is what the user asked for. `mdr cycle --arith q31` and
 *        Python's Engine.run (q31) refuse the path with this one check.
 * @param unit  D0, F0 or Z0 of the engine (mdr_host_q31_unit()), > 0
 * @return the vertex's index (0-based), or -1 if none
 */
static inline long mdr_host_q31_lost(const double *path, long npath, double unit)
{
    long s;
    for (s = 0; s < npath; s++) {
        int32_t raw;
        if (path[s] != 0.0 && mdr_host_q31_raw(path[s], unit, &raw) == MDR_OK && raw == 0) {
            return s;
        }
    }
    return -1;
}

/**
 * @brief One tick of the q31 engine in SI: the controlled value v [m or N]
 *        converted to raw, the step, its outputs converted to SI in double.
 * @param control  MDR_CONTROL_GRIPS (v = d), _LOAD (v = F), else z (machine)
 * @param strict   1: refuse a value beyond the documented input range
 *                 (MDR_E_OVERFLOW, no step); 0: step with it (the step
 *                 saturates it and sets MDR_FLAG_SAT)
 * @param[out] o   written on MDR_OK only
 * @return MDR_E_NONFINITE (v NaN or inf; no step), MDR_E_OVERFLOW (strict),
 *         or the step's status
 */
static inline mdr_status mdr_host_q31_step(mdr_host_q31 *q, uint8_t control, double v, int strict,
                                           mdr_step_f64 *o)
{
    const double unit = mdr_host_q31_unit(q, control);
    int32_t raw = 0;
    mdr_step_q31 s;
    mdr_status st = mdr_host_q31_raw(v, unit, &raw);
    if (st == MDR_E_NONFINITE || (st != MDR_OK && strict)) {
        return st;
    }
    if (control == MDR_CONTROL_GRIPS) {
        st = mdr_engine_step_d_q31(&q->e, raw, &s);
    } else if (control == MDR_CONTROL_LOAD) {
        st = mdr_engine_step_F_q31(&q->e, raw, &s);
    } else {
        st = mdr_engine_step_z_q31(&q->e, raw, &s);
    }
    if (st == MDR_OK) {
        const double ua = q->L / 1073741824.0, ud = q->D0 / 536870912.0;
        const double uF = q->F0 / 536870912.0, uz = q->Z0 / 536870912.0;
        o->z = s.z * (q->e.machine ? uz : ud);
        o->d = s.d * ud;
        o->F = s.F * uF;
        o->a = s.a * ua;
        o->a0 = s.a0 * ua;
        o->d0 = s.d0 * ud;
        o->F0 = s.F0 * uF;
        o->a1 = s.a1 * ua;
        o->d1 = s.d1 * ud;
        o->F1 = s.F1 * uF;
        o->event = s.event;
        o->jumps = s.jumps;
    }
    return st;
}

/** @brief Raw Q15.48 energy of a q31 engine -> J (unit W0 = F0 D0). */
static inline double mdr_host_q31_energy(const mdr_host_q31 *q, int64_t v)
{
    return (double)v * (q->F0 * q->D0 / 281474976710656.0);
}

#endif /* MDR_HOST_H */
