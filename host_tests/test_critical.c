/* SPDX-License-Identifier: MIT */
/*
 * test_critical.c: the critical-state search of issue 16 and the sampled
 * profiles of the contact module (MDR_PROFILE_TABLE): named cases from
 * CHECK_VALUES and the issue, starts as hints, the most tensile force of the
 * path, the wavy profile at gripper scale against a brute-force retraction,
 * tables against the closed forms they sample (worn flats: Kendall), and
 * every error path. The sweep over the parameter ranges is
 * host_tests/crit_sweep.c (make stress).
 *
 * Tolerances (relative; depths relative to max(|d|, dl(a))):
 *   REL_CV  1e-11  CHECK_VALUES (12 digits)
 *   REL64   1e-12  closed forms in double
 *   REL32   3e-6   f32 (the sweep's worst 2.5e-6 of a power law: kappa_n in
 *                  float to ~30 ulp)
 *   COND32  2e-6 * 1/(n - 1/2)  f32 near n = 1/2, where the radius is
 *                  ill-conditioned (a relative error e of s moves it by e/(n - 1/2))
 *   NEARHALF 16 eps/|n - 1/2|  f64 next to n = 1/2 (eps = 2^-53; measured
 *                  3.2 to 7.7 against 50 digits); within 2^10 eps of 1/2:
 *                  MDR_E_RADIUS
 *   KENDALL 1e-9   a worn tip's separation at its rim, sampled (the goal of
 *                  issue 16; measured 0 in f64: g = 0 on the flat exactly)
 *   TAB_ORD 2.3    fitted order of g, G of a sampled sphere (claim 2.5), 1.3
 *                  for g' (the derivative of a piecewise-linear f' model:
 *                  order 1.5 claimed)
 *   WAVY    1e-6   gripper-scale wavy critical radius against a brute-force
 *                  retraction on 64 points per wavelength refined by golden
 *                  section (measured: equal to the printed digits)
 *   TAB_SPH 1e-5   a sphere sampled at 2000 intervals to 0.9 R against the
 *                  exact sphere: the model's error (measured printed below)
 *   FT_WIN  1e-9   the flattened tip's pull-off control under grips and
 *                  through machines, b/a* over 0.20 ... 0.30, against the
 *                  least control of the closed forms (4.82, 4.83) over
 *                  (0, a_start] (grid and golden section in long double;
 *                  the f64 goal)
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "mdr.h"
#include "applies.h"

#if !(MDR_CFG_F32 && MDR_CFG_F64 && MDR_CFG_STRESS && MDR_CFG_ALL_PROFILES)
MDR_TEST_NOT_APPLICABLE("f32, f64, stress and every profile")
#else
#include "test_util.h"
#include "contact_util.h"

#define REL_CV 1e-11
#define REL64 1e-12
#define REL32 3e-6
#define KENDALL 1e-9
#define WAVY 1e-6
#define TAB_SPH 1e-5

/* ------------------------------------------------------------ named */

/* CHECK_VALUES, power laws sharper than a cone (E* = w = C = 1) */
static void powerlaw_below_one(void **st)
{
    (void)st;
    /* f32 near n = 1/2: the radius is ill-conditioned by 1/(n - 1/2) */
    crit_both(MDR_PROFILE_POWERLAW, 1, 0.6, 0, 1, 1, MDR_CONTROL_LOAD, 0, 4118452.7333, 7630.41636019,
         -2618792426.23, REL_CV, 2e-6 / 0.1, "n = 0.6 load (CHECK_VALUES)");
    crit_both(MDR_PROFILE_POWERLAW, 1, 0.6, 0, 1, 1, MDR_CONTROL_GRIPS, 0, 69.7463586732, -3.48898781902,
         -2007.58961561, REL_CV, 2e-6 / 0.1, "n = 0.6 grips");
    crit_both(MDR_PROFILE_POWERLAW, 1, 0.9, 0, 1, 1, MDR_CONTROL_LOAD, 0, 12.4842955703, 5.90446695301,
         -46.5556488168, REL_CV, 2e-6 / 0.4, "n = 0.9 load");
    crit_both(MDR_PROFILE_POWERLAW, 1, 0.9, 0, 1, 1, MDR_CONTROL_GRIPS, 0, 0.800867934242, -0.996983265699,
         -2.64749849968, REL_CV, 2e-6 / 0.4, "n = 0.9 grips");
}

/* the issue's example: n = 0.6, C = 0.005, E* = 1 GPa, w = 0.05 gave
 * a = 4e-26 m (the start) with MDR_OK; 4.70-4.72 worked out here */
static void issue_powerlaw_example(void **st)
{
    double n = 0.6, C = 0.005, E = 1e9, w = 0.05;
    double kap = sqrt(M_PI) * tgamma(n / 2 + 1) / tgamma((n + 1) / 2), c = sqrt(2 * M_PI * w / E);
    double a = pow(1.5 * c / (n * kap * C), 1 / (n - 0.5));
    double d = kap * C * pow(a, n) - c * sqrt(a);
    double F = 2 * E * (n / (n + 1) * kap * C * pow(a, n + 1) - c * pow(a, 1.5));
    (void)st;
    print_message("issue example: a_c = %.6g m (the old default start returned 4e-26 m)\n", a);
    crit_both(MDR_PROFILE_POWERLAW, C, n, 0, E, w, MDR_CONTROL_LOAD, 0, a, d, F, REL64, 2e-6 / 0.1,
         "n = 0.6, C = 0.005, E* = 1 GPa");
}

/* A power law with n next to 1/2 (helper-62, stop 68): its fixed-load
 * radius (3c/(2 n kappa C))^(1/(n - 1/2)) moves by e/|n - 1/2| for a
 * relative error e of the slope term, so within 2^10 eps of 1/2 (eps the
 * unit roundoff) the arithmetic does not resolve it to 1 %: f64 answered
 * n = 1/2 + 1 ulp with a = d = F = 0 and one jump, MDR_OK, for a true
 * pull-off at 38 769 m, and 94 % off at 2 ulp. There every control is
 * refused, MDR_E_RADIUS, from the default start (the profile's length, as
 * for n = 1/2) and from a hint at the true radius, the output untouched;
 * beyond, the fixed-load pull-off above 1/2 is answered within NEARHALF of
 * the closed form in long double (f64) and COND32 (f32), each scene's C
 * making its load radius aL, and below 1/2 every control peels to a = 0. Tolerance: NEARHALF 16 eps/|n - 1/2|
 * (measured against 50 digits: 3.2 to 7.7). */
/* one search of powerlaw_near_half in arithmetic S (T its type, MK its
 * contact maker): from the default start (*s1, its a, d, F in g) and, where
 * refused, from the hint aL (*s2), each refusal leaving the output untouched */
#define NEAR_HALF_ONE(T, S, MK)                                                                    \
    static void near_half_##S(double C, double n, double E, double w, uint8_t ctl, double aL, int refused, \
                              mdr_status *s1, mdr_status *s2, double g[3])                         \
    {                                                                                              \
        mdr_contact_##S c = MK(MDR_PROFILE_POWERLAW, C, n, 0, E, w);                                \
        mdr_critstate_##S o;                                                                       \
        T a0 = 0;                                                                                  \
        assert_int_equal(mdr_default_start_##S(&c, &a0), MDR_OK);                                 \
        memset(&o, GUARD, sizeof o);                                                               \
        *s1 = mdr_critical_##S(&c, ctl, (T)1, a0, &o);                                             \
        g[0] = (double)o.a;                                                                        \
        g[1] = (double)o.d;                                                                        \
        g[2] = (double)o.F;                                                                        \
        *s2 = MDR_E_RADIUS;                                                                        \
        if (refused) {                                                                             \
            assert_true(untouched(&o, sizeof o));                                                  \
            *s2 = mdr_critical_##S(&c, ctl, (T)1, (T)aL, &o);                                      \
            assert_true(untouched(&o, sizeof o));                                                  \
        }                                                                                          \
    }
NEAR_HALF_ONE(float, f32, mk32)
NEAR_HALF_ONE(double, f64, mk64)
#define NEARHALF(p, eps) (16.0 * (eps) / fabs(p))
#define COND32(p) (2e-6 / fabs(p))
static void powerlaw_near_half(void **st)
{
    static const double aLs[3] = {1e-9, 3e-6, 0.2}, Es[3] = {1e3, 1e6, 1e10}, ws[3] = {1e-3, 0.05, 10.0};
    static const uint8_t ctl[3] = {MDR_CONTROL_LOAD, MDR_CONTROL_GRIPS, MDR_CONTROL_MACHINE};
    /* steps of n from 1/2 in units of eps (above) or eps/2 (below: the
     * spacing halves); <= 1024 eps refused */
    static const double up[] = {0, 1, 2, 8, 1023, 1024, 1025, 4096, 1048576};
    static const double dn[] = {1, 2048, 2050, 65536};
    int arith, i, k, sc, nref = 0, nans = 0;
    double worst = 0;
    (void)st;
    for (arith = 0; arith < 2; arith++) {
        const double eps = arith ? 0x1p-24 : 0x1p-53;
        for (i = 0; i < (int)(sizeof up / sizeof up[0] + sizeof dn / sizeof dn[0]); i++) {
            const int below = i >= (int)(sizeof up / sizeof up[0]);
            const double p = below ? -dn[i - (int)(sizeof up / sizeof up[0])] * eps / 2 : up[i] * eps;
            const double n = 0.5 + p;
            const int refused = fabs(p) <= 1024 * eps;
            for (sc = 0; sc < 3; sc++) {
                const double E = Es[sc], w = ws[(sc + i) % 3], aL = aLs[(sc + 2 * i) % 3];
                long double nl = n, El = E, wl = w, cl, kap, Cl, a, d, F, dl;
                double C;
                char what[128];
                if (arith) {
                    El = (float)E;
                    wl = (float)w;
                }
                cl = sqrtl(2 * M_PI * wl / El);
                kap = sqrtl(M_PI) * expl(lgammal(nl / 2 + 1) - lgammal((nl + 1) / 2));
                C = (double)(1.5L * cl / (nl * kap * powl(aL, nl - 0.5L)));
                if (arith) {
                    C = (float)C;
                }
                Cl = C;
                a = p == 0 ? 0 : powl(1.5L * cl / (nl * kap * Cl), 1 / (nl - 0.5L));
                d = kap * Cl * powl(a, nl) - cl * sqrtl(a);
                dl = cl * sqrtl(a);
                F = 2 * El * (a * d - kap * Cl * powl(a, nl + 1) / (nl + 1));
                snprintf(what, sizeof what, "%s n = 1/2 %+.1f eps, C %.6g, E* %g, w %g, aL %g", arith ? "f32" : "f64",
                         p / eps, C, E, w, aL);
                for (k = 0; k < 3; k++) {
                    mdr_status s1, s2;
                    double g[3], ga, gd, gF;
                    if (arith) {
                        near_half_f32(C, n, E, w, ctl[k], aL, refused, &s1, &s2, g);
                    } else {
                        near_half_f64(C, n, E, w, ctl[k], aL, refused, &s1, &s2, g);
                    }
                    ga = g[0];
                    gd = g[1];
                    gF = g[2];
                    if (refused) {
                        if (s1 != MDR_E_RADIUS || s2 != MDR_E_RADIUS) {
                            fail_msg("%s, control %d: status %d and %d (hint aL), want MDR_E_RADIUS (%d)", what,
                                     ctl[k], s1, s2, MDR_E_RADIUS);
                        }
                        nref++;
                        continue;
                    }
                    if (below) {
                        /* n < 1/2: stable below its fold, from the default
                         * start the contact peels to a = 0 under every control */
                        if (s1 != MDR_OK || ga != 0 || gd != 0 || gF != 0) {
                            fail_msg("%s, control %d: status %d a %g d %g F %g, want MDR_OK and a = d = F = 0", what,
                                     ctl[k], s1, ga, gd, gF);
                        }
                        nans++;
                        continue;
                    }
                    if (ctl[k] != MDR_CONTROL_LOAD) {
                        continue; /* (the grips radius is 3^(-1/(n - 1/2)) of it: below the range) */
                    }
                    {
                        const double tol = arith ? COND32(p) : NEARHALF(p, eps);
                        const double ea = fabs(ga - (double)a) / (double)a;
                        if (s1 != MDR_OK) {
                            fail_msg("%s, load: status %d, want MDR_OK (a = %.6Lg)", what, s1, a);
                        }
                        rel_le(ga, (double)a, 0, tol, what);
                        rel_le(gd, (double)d, fmax(fabs((double)d), (double)dl), tol, what);
                        rel_le(gF, (double)F, 0, tol, what);
                        if (!arith && ea * fabs(p) / eps > worst) {
                            worst = ea * fabs(p) / eps;
                        }
                        nans++;
                    }
                }
            }
        }
    }
    print_message("power law next to n = 1/2: %d refused, %d answered, f64 radius within %.2f eps/|n - 1/2|\n", nref,
                  nans, worst);
}

/* the exact sphere beyond 0.9 R (CHECK_VALUES w = 5) and the issue's f32
 * NOCONV (R = 20 nm, E* = 1 MPa, w = 0.3) */
static void sphere_near_R(void **st)
{
    mdr_contact_f32 c32 = mk32(MDR_PROFILE_SPHERE, 20e-9, 0, 0, 1e6, 0.3);
    mdr_contact_f64 c64 = mk64(MDR_PROFILE_SPHERE, 20e-9, 0, 0, 1e6, 0.3);
    mdr_critstate_f32 of;
    mdr_critstate_f64 o;
    float a0f;
    double a0;
    (void)st;
    crit_both(MDR_PROFILE_SPHERE, 1, 0, 0, 1, 5, MDR_CONTROL_LOAD, 0, 0.931509435763, -3.85431932452,
         -7.89129674995, REL_CV, REL32, "sphere w = 5 load, a = 0.93 R");
    crit_both(MDR_PROFILE_SPHERE, 1, 0, 0, 1, 5, MDR_CONTROL_GRIPS, 0, 0.788756074688, -4.13540655475,
         -6.90880201948, REL_CV, REL32, "sphere w = 5 grips");
    assert_int_equal(mdr_default_start_f32(&c32, &a0f), MDR_OK);
    assert_int_equal(mdr_critical_f32(&c32, MDR_CONTROL_LOAD, 0, a0f, &of), MDR_OK);
    assert_int_equal(mdr_default_start_f64(&c64, &a0), MDR_OK);
    assert_int_equal(mdr_critical_f64(&c64, MDR_CONTROL_LOAD, 0, a0, &o), MDR_OK);
    rel_le(of.a, o.a, 0, REL32, "issue: f32 sphere R = 20 nm, w = 0.3 (was MDR_E_NOCONV)");
    rel_le(of.F, o.F, 0, REL32, "issue: f32 sphere F");
    /* a -> R: w/E* so large that the critical radius lies within rounding
     * of R in float: a named error, in double still a result */
    {
        mdr_contact_f32 cs = mk32(MDR_PROFILE_SPHERE, 1, 0, 0, 1, 1e14);
        mdr_contact_f64 cd = mk64(MDR_PROFILE_SPHERE, 1, 0, 0, 1, 1e14);
        memset(&of, GUARD, sizeof of);
        a0f = 123.0f;
        assert_int_equal(mdr_default_start_f32(&cs, &a0f), MDR_E_RADIUS);
        assert_int_equal(mdr_critical_f32(&cs, MDR_CONTROL_LOAD, 0, 0.999999f, &of), MDR_E_RADIUS);
        assert_true(untouched(&of, sizeof of) && a0f == 123.0f);
        assert_int_equal(mdr_default_start_f64(&cd, &a0), MDR_OK);
        assert_int_equal(mdr_critical_f64(&cd, MDR_CONTROL_LOAD, 0, a0, &o), MDR_OK);
        print_message("sphere E* R/(pi w) = 3e-15: a_c = 1 - %.3g R (f64; within rounding of R in f32)\n", 1 - o.a);
        assert_true(o.a < 1 && o.a > 1 - 1e-7);
        /* from a start far below, the jump-in target (F grows only like
         * log(1/(1 - a/R))) lies within rounding of R even in double */
        assert_int_equal(mdr_critical_f64(&cd, MDR_CONTROL_LOAD, 0, 0.5, &o), MDR_E_RADIUS);
    }
}

/* A pull-off below the arithmetic's normal range is a named status, never
 * a number short of its digits (helper-33, stop 58): the power law n = 0.52,
 * C = 0.8276877377646706, E* = 1 kPa, w = 10 pulls off at a = 1.39e-33 m
 * with F = -1.75e-47 N; f32 returned F = -0.0 (underflowed), MDR_OK.
 * Grips, the closed form worked out here: d(a) = kappa C a^n - c sqrt(a)
 * (c = sqrt(2 pi w/E*), kappa = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2))
 * has its fold at a^(n - 1/2) = c/(2 n kappa C), where F = 2E* (a d - G),
 * G = kappa C a^(n+1)/(n+1). f64 holds it: REL64 (the conditioning near
 * n = 1/2 aside, 1/(n - 1/2) = 50: REL64 x 50). */
static void pull_off_below_range(void **st)
{
    const double n = 0.52, C = 0.8276877377646706, E = 1e3, w = 10.0;
    const double c = sqrt(2.0 * M_PI * w / E), kap = sqrt(M_PI) * tgamma(0.5 * n + 1.0) / tgamma(0.5 * n + 0.5);
    const double a = pow(c / (2.0 * n * kap * C), 1.0 / (n - 0.5)), d = kap * C * pow(a, n) - c * sqrt(a);
    const double F = 2.0 * E * (a * d - kap * C * pow(a, n + 1.0) / (n + 1.0));
    static const uint8_t ctl[2] = {MDR_CONTROL_GRIPS, MDR_CONTROL_MACHINE};
    mdr_contact_f32 c32 = mk32(MDR_PROFILE_POWERLAW, C, n, 0, E, w);
    mdr_contact_f64 c64 = mk64(MDR_PROFILE_POWERLAW, C, n, 0, E, w);
    mdr_critstate_f32 of;
    mdr_critstate_f64 o;
    float a0f;
    double a0;
    int k;
    (void)st;
    assert_int_equal(mdr_default_start_f64(&c64, &a0), MDR_OK);
    assert_int_equal(mdr_critical_f64(&c64, MDR_CONTROL_GRIPS, 0, a0, &o), MDR_OK);
    rel_le(o.a, a, 0, 50 * REL64, "power law n = 0.52 pull-off radius at 1.4e-33 m (f64)");
    rel_le(o.F, F, 0, 50 * REL64, "power law n = 0.52 pull-off force -1.7e-47 N (f64)");
    assert_true(F < 0.0 && fabs(F) < 1.4e-45 && a < 1e-30);
    for (k = 0; k < 2; k++) {
        if (mdr_default_start_f32(&c32, &a0f) != MDR_OK) {
            a0f = (float)a0;
        }
        memset(&of, GUARD, sizeof of);
        assert_int_equal(mdr_critical_f32(&c32, ctl[k], 2e-6f, a0f, &of), MDR_E_OVERFLOW);
        assert_true(untouched(&of, sizeof of));
    }
}

/* A contact no init filled (zeroed: a static one whose init was refused,
 * its status ignored) is refused, MDR_E_KIND, by the critical search and
 * the table builder, in both arithmetics, their outputs untouched;
 * helper-32, stop 58: mdr_critical answered a = d = F = 0 and
 * mdr_table_init_profile built an all-zero table, MDR_OK. */
static void zeroed_contact(void **st)
{
    static const mdr_contact_f32 z32;
    static const mdr_contact_f64 z64;
    mdr_critstate_f32 of;
    mdr_critstate_f64 o;
    (void)st;
    memset(&of, GUARD, sizeof of);
    memset(&o, GUARD, sizeof o);
    assert_int_equal(mdr_critical_f32(&z32, MDR_CONTROL_GRIPS, 0, 1e-6f, &of), MDR_E_KIND);
    assert_int_equal(mdr_critical_f64(&z64, MDR_CONTROL_LOAD, 0, 1e-6, &o), MDR_E_KIND);
    assert_true(untouched(&of, sizeof of) && untouched(&o, sizeof o));
#if MDR_CFG_ENGINE
    {
        static mdr_node_f32 n32[MDR_TABLE_NODES(16)];
        static mdr_node_f64 n64[MDR_TABLE_NODES(16)];
        mdr_table_f32 t32;
        mdr_table_f64 t64;
        memset(&t32, GUARD, sizeof t32);
        memset(&t64, GUARD, sizeof t64);
        assert_int_equal(mdr_table_init_profile_f32(&t32, n32, 16, &z32, 1e-6f), MDR_E_KIND);
        assert_int_equal(mdr_table_init_profile_f64(&t64, n64, 16, &z64, 1e-6), MDR_E_KIND);
        assert_true(untouched(&t32, sizeof t32) && untouched(&t64, sizeof t64));
    }
#endif
}

/* The facts the flattened tip's structure rests on (mdr_critical.inc), in
 * closed form: s = sqrt(a) g'(a) has its single minimum on (b, inf) at
 * y_m^2 = (9 + sqrt 57)/12; above it sigma = d ln s/d ln a rises from 0 to
 * 3/2 and where it is below 2 - sqrt 3 (the machine threshold's largest
 * slope tau) it rises faster than tau can change (|d tau/d ln a| <= 0.101),
 * so ln(s/(c phi)) falls, then rises: at most two roots; and the threshold
 * 0.7475 a* of the seed. */
static void flattip_structure(void **st)
{
    const long double ym = sqrtl((9 + sqrtl(57.0L)) / 12), tmax = 2 - sqrtl(3.0L);
    long double prev = -1, mind = 1e30L, maxt = 0;
    (void)st;
    /* sigma = 1/2 + 4y^2/(2y^2 - 1) - y^2/(y^2 - 1) = 3/2 - 1/((2y^2 - 1)(y^2 - 1)) */
    for (long double y = ym; y < 100; y *= 1.0001L) {
        long double y2 = y * y, sig = 1.5L - 1 / ((2 * y2 - 1) * (y2 - 1));
        long double yh = y * 1.000001L, yh2 = yh * yh;
        long double sh = 1.5L - 1 / ((2 * yh2 - 1) * (yh2 - 1));
        long double dsig = (sh - sig) / logl(1.000001L);
        assert_true(sig > prev); /* rising */
        prev = sig;
        if (sig < tmax) {
            mind = fminl(mind, dsig);
        }
    }
    for (long double x = 1e-8L; x < 1e8L; x *= 1.001L) {
        long double t = x / (0.5L + 2 * x + 1.5L * x * x);
        long double dt = x * (0.5L - 1.5L * x * x) / ((0.5L + 2 * x + 1.5L * x * x) * (0.5L + 2 * x + 1.5L * x * x));
        assert_true(t <= tmax + 1e-15L);
        maxt = fmaxl(maxt, fabsl(dt));
    }
    print_message("flattened tip: y_m = %.6Lf, min d sigma/d ln a where sigma < 0.268: %.2Lf, max |d tau/d ln a| %.4Lf, "
                  "threshold b/a* = %.6Lf\n",
                  ym, mind, maxt, powl(2 / (sqrtl(ym) * (2 * ym * ym - 1) / sqrtl(ym * ym - 1)), 2.0L / 3));
    assert_true(mind > maxt);
    assert_true(fabsl(powl(2 / (sqrtl(ym) * (2 * ym * ym - 1) / sqrtl(ym * ym - 1)), 2.0L / 3) - 0.7475L) < 1e-4L);
}

/* The flattened tip's pull-off where its unstable window (r1, r2) above
 * the rim is narrow (b/a* near 1/4; helper-59, stop 67): the answer's
 * control is the least control of the closed forms over (0, a_start]
 * (retracting from a_start the edge meets the fold at r2 first; where
 * the control there is above the rim's, it jumps to (b, r1) and separates
 * at the rim: either way the least value), found here on a grid of the
 * closed forms (4.82, 4.83) refined by golden section. The library
 * returned the rim for b/a* in [0.2457, 0.2499] under grips and stiff
 * machines, its bracket's steps down having passed over the window
 * (d 8.7 % off). */
#define FT_WIN 1e-9

/* Golden-section search for a minimum of f on [lo, hi], iters steps: the
 * least value it evaluated, at *xm (this file's brute-force references) */
typedef long double (*golden_fn)(long double x, const void *ctx);
static long double golden_min(golden_fn f, const void *ctx, long double lo, long double hi, int iters, long double *xm)
{
    const long double gr = 0.6180339887498948482L;
    long double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo), f1 = f(x1, ctx), f2 = f(x2, ctx);
    for (int it = 0; it < iters; it++) {
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - gr * (hi - lo);
            f1 = f(x1, ctx);
        } else {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + gr * (hi - lo);
            f2 = f(x2, ctx);
        }
    }
    *xm = f1 < f2 ? x1 : x2;
    return fminl(f1, f2);
}

/* the flattened tip's control (4.82, 4.83: d under grips, d + F/km through a
 * machine) at radius a */
typedef struct {
    long double R, b, E, w, km;
} ft_par;

static long double ft_ctl(long double a, const void *ctx)
{
    const ft_par *q = ctx;
    const long double R = q->R, b = q->b, E = q->E, w = q->w, km = q->km;
    const long double s2 = a > b ? (a - b) * (a + b) : 0;
    const long double d = a / R * sqrtl(s2) - sqrtl(2 * M_PI * a * w / E);
    const long double F = 2 * E / (3 * R) * (2 * a * a + b * b) * sqrtl(s2) - sqrtl(8 * M_PI * a * a * a * E * w);
    return km > 0 ? d + F / km : d;
}

static void flattip_narrow_window(void **st)
{
    static const double scale[][3] = {{1e-5, 1e6, 0.05}, {2e-8, 3.8e9, 0.066}, {1e-3, 1e5, 0.5}};
    static const double kap[] = {0, 1000, 30};
    double worst = 0;
    long n = 0;
    (void)st;
    for (size_t si = 0; si < sizeof scale / sizeof scale[0]; si++) {
        const double R = scale[si][0], E = scale[si][1], w = scale[si][2];
        const double astar = cbrt(9 * M_PI * R * R * w / (8 * E));
        for (int i = 0; i <= 200; i++) {
            const double b = (0.20 + 0.10 * i / 200) * astar;
            const mdr_contact_f64 c = mk64(MDR_PROFILE_FLATTIP, R, b, 0, E, w);
            double a0;
            assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
            for (size_t ki = 0; ki < sizeof kap / sizeof kap[0]; ki++) {
                const long double km = kap[ki] * 2 * E * astar;
                const ft_par q = {R, b, E, w, km};
                mdr_critstate_f64 o;
                long double best = 1e300L, abest = 0, xm, ref, got;
                const int m = 4000;
                const long double r = powl((long double)a0 / (1e-6L * b), 1.0L / m);
                long double a = (long double)b * 1e-6L;
                for (int j = 0; j <= m; j++, a *= r) { /* log grid over (1e-6 b, a_start] */
                    const long double v = ft_ctl(a, &q);
                    if (v < best) {
                        best = v;
                        abest = a;
                    }
                }
                ref = fminl(best, golden_min(ft_ctl, &q, abest / r, abest * r, 200, &xm));
                ref = fminl(ref, ft_ctl(b, &q)); /* (the rim: a kink) */
                assert_int_equal(mdr_critical_f64(&c, kap[ki] > 0 ? MDR_CONTROL_MACHINE : MDR_CONTROL_GRIPS,
                                                  (double)km, a0, &o),
                                 MDR_OK);
                got = kap[ki] > 0 ? (long double)o.d + (long double)o.F / km : (long double)o.d;
                if (fabsl(got - ref) / fabsl(ref) > worst) {
                    worst = (double)(fabsl(got - ref) / fabsl(ref));
                }
                if (fabsl(got - ref) > FT_WIN * fabsl(ref)) {
                    fail_msg("flattened tip R %g E %g w %g, b/a* %.4f, kappa %g: pull-off control %.12Lg at a/b "
                             "%.9g, least control %.12Lg",
                             R, E, w, b / astar, kap[ki], got, o.a / b, ref);
                }
                if (si == 0 && ki == 0) { /* f32 under grips: REL32 */
                    const mdr_contact_f32 c32 = mk32(MDR_PROFILE_FLATTIP, R, b, 0, E, w);
                    mdr_critstate_f32 o32;
                    float a32;
                    assert_int_equal(mdr_default_start_f32(&c32, &a32), MDR_OK);
                    assert_int_equal(mdr_critical_f32(&c32, MDR_CONTROL_GRIPS, 0.0f, a32, &o32), MDR_OK);
                    if (fabsl((long double)o32.d - ref) > REL32 * fabsl(ref)) {
                        fail_msg("f32 flattened tip b/a* %.4f: pull-off depth %.9g, least depth %.12Lg", b / astar,
                                 (double)o32.d, ref);
                    }
                }
                n++;
            }
        }
    }
    print_message("flattened tip, b/a* 0.20 ... 0.30 (grips, machines 1000 and 30 x 2E* a*): %ld pull-offs, control "
                  "within %.2g of the closed forms' least (tolerance %.0e)\n",
                  n, worst, FT_WIN);
}

/* ------------------------------------------------------------ hints */

/* any start on the unstable branch (or at the root, or far out) gives the
 * same critical state; the flat punch from any start is Kendall's at a0;
 * where no stable state is reachable: MDR_E_RADIUS */
static void starts_are_hints(void **st)
{
    static const struct {
        uint8_t kind;
        double p0, p1;
    } sc[] = {
        {MDR_PROFILE_PARABOLOID, 1e-5, 0}, {MDR_PROFILE_CONE, 0.3, 0},    {MDR_PROFILE_POWERLAW, 1, 0.6},
        {MDR_PROFILE_POWERLAW, 1, 3.0},    {MDR_PROFILE_SPHERE, 1e-6, 0}, {MDR_PROFILE_FLATTIP, 1e-5, 1e-7},
    };
    (void)st;
    for (size_t i = 0; i < sizeof sc / sizeof sc[0]; i++) {
        for (uint8_t ctl = 1; ctl <= 3; ctl++) {
            mdr_contact_f64 c = mk64(sc[i].kind, sc[i].p0, sc[i].p1, 0, 1e6, 0.05);
            mdr_critstate_f64 ref, o;
            double a0;
            assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
            assert_int_equal(mdr_critical_f64(&c, ctl, 1.0, a0, &ref), MDR_OK);
            for (double f = 1e-6; f < 1e4; f *= 7.3) {
                double as = f * ref.a;
                if (sc[i].kind == MDR_PROFILE_SPHERE && as >= sc[i].p0) {
                    continue;
                }
                assert_int_equal(mdr_critical_f64(&c, ctl, 1.0, as, &o), MDR_OK);
                rel_le(o.a, ref.a, 0, 1e-14, "the same critical radius from any start");
                rel_le(o.F, ref.F, 0, 1e-14, "the same critical force from any start");
            }
        }
    }
    {
        mdr_contact_f64 c = mk64(MDR_PROFILE_FLATPUNCH, 1, 0, 0, 1, 1);
        mdr_critstate_f64 o;
        for (double as = 1e-6; as <= 1; as *= 3.7) {
            assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, as, &o), MDR_OK);
            rel_le(o.F, -sqrt(8 * M_PI), 0, REL64, "Kendall from any start (the rim is a wall)");
        }
    }
    {
        /* n < 1/2: stable below its fold (peels to a = 0); above it c falls
         * for ever: no stable state to jump in to */
        mdr_contact_f64 c = mk64(MDR_PROFILE_POWERLAW, 1, 0.4, 0, 1, 1);
        mdr_contact_f32 cf = mk32(MDR_PROFILE_POWERLAW, 1, 0.4, 0, 1, 1);
        mdr_critstate_f64 o;
        mdr_critstate_f32 of;
        double a0;
        assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, a0, &o), MDR_OK);
        assert_true(o.a == 0 && o.F == 0 && o.d == 0);
        memset(&o, GUARD, sizeof o);
        memset(&of, GUARD, sizeof of);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, 1e6, &o), MDR_E_RADIUS);
        assert_int_equal(mdr_critical_f32(&cf, MDR_CONTROL_GRIPS, 0, 1e6f, &of), MDR_E_RADIUS);
        assert_true(untouched(&o, sizeof o) && untouched(&of, sizeof of));
    }
    {
        /* a sampled cone (tan 0.3, 10 samples to 0.9 um, E* 1 MPa, w 0.05)
         * whose load pull-off lies beyond its samples: sqrt(a*) = 3 c_w /
         * (pi tan) with c_w = sqrt(2 pi w/E*), a* = 3.0 um (the cone's
         * F = E* (pi/2) tan a^2 - 2 E* c_w a^(3/2)), so every start is
         * unstable under load and none reaches a stable state: MDR_E_RADIUS
         * from anywhere, also one ulp below the last sample (there c came
         * back to c(start) to rounding, and the search peeled to a = 0
         * with MDR_OK: a helper's attack, stop 49) */
        static double r[10], sl[9];
        mdr_contact_f64 c;
        mdr_critstate_f64 o;
        const double t3 = tan(0.3), cw = sqrt(2 * M_PI * 0.05 / 1e6), as = pow(3 * cw / (M_PI * t3), 2);
        for (int i = 0; i < 10; i++) {
            r[i] = 0.9e-6 * i / 9;
        }
        for (int i = 0; i < 9; i++) {
            sl[i] = (t3 * r[i + 1] - t3 * r[i]) / (r[i + 1] - r[i]);
        }
        assert_true(as > 3 * r[9]);
        assert_int_equal(mdr_contact_init_table_f64(&c, r, sl, 10, 1e6, 0.05), MDR_OK);
        const double starts[] = {r[9], nextafter(r[9], 0), 0.5 * r[9], 0.1 * r[9], 1e-3 * r[9]};
        for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++) {
            memset(&o, GUARD, sizeof o);
            assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, starts[i], &o), MDR_E_RADIUS);
            assert_true(untouched(&o, sizeof o));
        }
    }
}

/* the default start lies on the last stable branch of every control */
static void default_start_is_stable(void **st)
{
    static const struct {
        uint8_t kind;
        double p0, p1, w;
    } sc[] = {
        {MDR_PROFILE_PARABOLOID, 1e-5, 0, 0.05}, {MDR_PROFILE_CONE, 0.3, 0, 0.05},
        {MDR_PROFILE_POWERLAW, 0.005, 0.6, 0.05}, {MDR_PROFILE_POWERLAW, 1, 0.51, 1},
        {MDR_PROFILE_POWERLAW, 1, 8, 1},         {MDR_PROFILE_SPHERE, 1, 0, 5},
        {MDR_PROFILE_SPHERE, 1, 0, 1e3},         {MDR_PROFILE_FLATTIP, 1e-5, 3e-7, 0.05},
    };
    (void)st;
    for (size_t i = 0; i < sizeof sc / sizeof sc[0]; i++) {
        mdr_contact_f64 c = mk64(sc[i].kind, sc[i].p0, sc[i].p1, 0, sc[i].kind == MDR_PROFILE_POWERLAW &&
                                 sc[i].p0 < 0.1 ? 1e9 : 1, sc[i].w);
        mdr_eqstate_f64 e;
        double a0;
        assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
        assert_int_equal(mdr_eq_f64(&c, a0, &e), MDR_OK);
        assert_true(e.dF_da > 0 && e.dd_da > 0); /* load stable: every control is */
        if (sc[i].kind == MDR_PROFILE_SPHERE) {
            assert_true(a0 < sc[i].p0);
        }
    }
}

/* ------------------------------------------------- the path's tension */

/* under grips the path passes the fixed-load fold: -1.5 pi w R, while the
 * fold itself is at -5/6 pi w R; a machine in between; fixed load: F */
static void most_tensile_force(void **st)
{
    double R = 10e-6, E = 1e6, w = 0.05;
    mdr_contact_f64 c = mk64(MDR_PROFILE_PARABOLOID, R, 0, 0, E, w);
    mdr_contact_f32 cf = mk32(MDR_PROFILE_PARABOLOID, R, 0, 0, E, w);
    mdr_critstate_f64 o;
    mdr_critstate_f32 of;
    double a0, dc = -cbrt(3 * M_PI * M_PI * R * w * w / (64 * E * E));
    float a0f;
    (void)st;
    assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
    assert_int_equal(mdr_default_start_f32(&cf, &a0f), MDR_OK);
    for (uint8_t ctl = 1; ctl <= 3; ctl++) {
        assert_int_equal(mdr_critical_f64(&c, ctl, 0.3, a0, &o), MDR_OK);
        assert_int_equal(mdr_critical_f32(&cf, ctl, 0.3f, a0f, &of), MDR_OK);
        rel_le(o.F_min, -1.5 * M_PI * w * R, 0, REL64, "most tensile force: -1.5 pi w R");
        rel_le(o.d_F_min, dc, 0, REL64, "at the fixed-load critical depth (4.36)");
        rel_le(of.F_min, -1.5 * M_PI * w * R, 0, REL32, "most tensile force (f32)");
        if (ctl == MDR_CONTROL_GRIPS) {
            rel_le(o.F, -5.0 / 6 * M_PI * w * R, 0, REL64, "the fold force stays -5/6 pi w R");
        }
    }
    /* a start below the fixed-load fold (on the grips branch): the path
     * never reaches it; the most tensile state is the start itself (F falls
     * with a there... rises as a falls) */
    {
        double a1 = 0.8 * cbrt(9 * M_PI * R * R * w / (8 * E));
        mdr_eqstate_f64 e;
        assert_int_equal(mdr_eq_f64(&c, a1, &e), MDR_OK);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_GRIPS, 0, a1, &o), MDR_OK);
        rel_le(o.F_min, e.F, 0, REL64, "path from below the load fold: F_min at the start");
    }
}

/* ------------------------------------------------------- wavy at scale */

/* Independent retraction: c(a) of the control on 64 points per wavelength
 * (mdr_eq), from the library's start down; an unstable start first moves up
 * to where c regains its value; local minima refined by golden section;
 * the lowest, and the records before it. */
/* brute_n's control at radius a (mdr_eq) */
typedef struct {
    const mdr_contact_f64 *c;
    uint8_t ctl;
    double km;
} eq_par;

static long double eq_ctl(long double a, const void *ctx)
{
    const eq_par *q = ctx;
    mdr_eqstate_f64 e;
    assert_int_equal(mdr_eq_f64(q->c, (double)a, &e), MDR_OK);
    return q->ctl == MDR_CONTROL_LOAD ? e.F : q->ctl == MDR_CONTROL_GRIPS ? e.d : e.d + e.F / q->km;
}

static void brute_n(const mdr_contact_f64 *c, uint8_t ctl, double km, double as, double lam, double per,
                    double *amin, int *jumps)
{
    const eq_par q = {c, ctl, km};
    double best = INFINITY, v0, vprev = NAN, vpp = NAN, aprev = 0, ab = 0, h = lam / per;
    int nrec = 0;
    v0 = (double)eq_ctl(as, &q);
    {
        /* jump in: the first a above with c >= c(start) */
        double a = as, v;
        do {
            a += h;
            v = (double)eq_ctl(a, &q);
        } while (v < v0 && a < 2 * as);
        if (a - h > as) {
            as = a;
        }
    }
    for (double a = as; a > 0.05 * lam; a -= (a > 2 * lam ? h : a / 512)) {
        const double v = (double)eq_ctl(a, &q);
        if (!isnan(vpp) && vprev < vpp && vprev <= v) {
            /* a local minimum near aprev: golden section on [a, aprev + step] */
            long double xm;
            const double fm = (double)golden_min(eq_ctl, &q, a, aprev + (aprev - a), 80, &xm);
            if (fm < best) {
                best = fm;
                ab = (double)xm;
                nrec++;
            }
        }
        vpp = vprev;
        vprev = v;
        aprev = a;
    }
    *amin = ab;
    *jumps = nrec - 1;
}

static void brute(const mdr_contact_f64 *c, uint8_t ctl, double km, double as, double lam, double *amin,
                  int *jumps)
{
    brute_n(c, ctl, km, as, lam, 64, amin, jumps);
}

/* Folds just below the start and narrow ones (a helper's attack, stop 57,
 * whose reference evaluated g at 30 digits): a wavy profile whose default
 * start (5.709 lambda) lies 0.05 lambda above a fold was answered with 4
 * jumps for 5, and a start 0.001 to 0.003 lambda above a fold missed that
 * fold (the cell below the start was never searched for a hidden pair); a
 * load case with a fold 0.03 lambda wide at 51.6 lambda answered 2 jumps
 * for 3 from some starts (one golden section over two cells lost it beside
 * a maximum). Each count against brute_n() at 4 096 points a wavelength
 * and the helper's (host only: about 10^6 evaluations): grips, starts
 * default, 3.03e-8, 3.05e-8 m: 5, 4, 4; load, starts default, 52 and 53
 * lambda: 3, 3, 3. */
#ifndef MDR_TARGET_TEST
static void wavy_jumps_near_start(void **st)
{
    const double lam1 = 6.43209610233014e-09, lam2 = 3.432944270195321e-08;
    const mdr_contact_f64 c1 = mk64(MDR_PROFILE_WAVY, 4.61569549380821e-06, 2.0927219124069958e-12, lam1,
                                    1527210490.4172254, 2.0924068235626915e-05);
    const mdr_contact_f64 c2 = mk64(MDR_PROFILE_WAVY, 4.915124374473876e-07, 1.530973428112789e-10, lam2,
                                    72792866.0002434, 395.00362604610575);
    const struct {
        const mdr_contact_f64 *c;
        uint8_t ctl;
        double lam, as;
        int want;
    } cs[] = {{&c1, MDR_CONTROL_GRIPS, lam1, 0, 5},        {&c1, MDR_CONTROL_GRIPS, lam1, 3.03e-8, 4},
              {&c1, MDR_CONTROL_GRIPS, lam1, 3.05e-8, 4},  {&c2, MDR_CONTROL_LOAD, lam2, 0, 3},
              {&c2, MDR_CONTROL_LOAD, lam2, 52 * lam2, 3}, {&c2, MDR_CONTROL_LOAD, lam2, 53 * lam2, 3}};
    (void)st;
    for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        mdr_critstate_f64 o;
        double as = cs[i].as, ab;
        int jb;
        if (as == 0) {
            assert_int_equal(mdr_default_start_f64(cs[i].c, &as), MDR_OK);
        }
        assert_int_equal(mdr_critical_f64(cs[i].c, cs[i].ctl, 0, as, &o), MDR_OK);
        brute_n(cs[i].c, cs[i].ctl, 1.0, as, cs[i].lam, 4096, &ab, &jb);
        print_message("wavy near its start (%s, start %.4f lambda): %u jumps (brute %d, the helper's %d)\n",
                      cs[i].ctl == MDR_CONTROL_LOAD ? "load" : "grips", as / cs[i].lam, o.jumps, jb, cs[i].want);
        assert_int_equal(o.jumps, cs[i].want);
        assert_int_equal(jb, cs[i].want);
        rel_le(o.a, ab, 0, WAVY, "wavy near its start: critical radius vs brute force");
    }
}
#endif

/* R = 2 mm, lambda = 0.5 um: ~650 wavelengths inside the default start,
 * folds in every one of them (h = 1 and 5 nm); the search completes (it hit
 * its scan cap before issue 16) and agrees with the brute force */
static void wavy_gripper_scale(void **st)
{
    static const double hs[] = {1e-9, 5e-9};
    (void)st;
    for (size_t i = 0; i < sizeof hs / sizeof hs[0]; i++) {
        mdr_contact_f64 c = mk64(MDR_PROFILE_WAVY, 2e-3, hs[i], 0.5e-6, 1e6, 0.05);
        mdr_contact_f32 cf = mk32(MDR_PROFILE_WAVY, 2e-3, hs[i], 0.5e-6, 1e6, 0.05);
        double a0;
        float a0f;
        assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
        assert_int_equal(mdr_default_start_f32(&cf, &a0f), MDR_OK);
        for (uint8_t ctl = 1; ctl <= 3; ctl++) {
            mdr_critstate_f64 o;
            mdr_critstate_f32 of;
            double ab;
            int jb;
            assert_int_equal(mdr_critical_f64(&c, ctl, 1e3, a0, &o), MDR_OK);
            assert_int_equal(mdr_critical_f32(&cf, ctl, 1e3f, a0f, &of), MDR_OK);
            brute(&c, ctl, 1e3, a0, 0.5e-6, &ab, &jb);
            print_message("wavy R = 2 mm, h = %g m, control %u: %.0f wavelengths, a_c = %.9g m (brute %.9g), "
                          "jumps %u (brute %d), f32 %.7g m, %u jumps\n",
                          hs[i], ctl, a0 / 0.5e-6, o.a, ab, o.jumps, jb, (double)of.a, of.jumps);
            rel_le(o.a, ab, 0, WAVY, "gripper-scale wavy critical radius vs brute force");
            assert_int_equal(o.jumps, jb);
            assert_true(o.jumps > 100);
            rel_le(of.a, o.a, 0, 1e-5, "gripper-scale wavy f32");
            assert_int_equal(of.jumps, o.jumps);
        }
    }
    {
        /* beyond the cap (65536 wavelengths below the stable radius):
         * MDR_E_NOCONV, output untouched */
        mdr_contact_f64 c = mk64(MDR_PROFILE_WAVY, 1.0, 5e-9, 0.5e-6, 1e6, 0.05);
        mdr_critstate_f64 o;
        memset(&o, GUARD, sizeof o);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, 0.1, &o), MDR_E_NOCONV);
        assert_true(untouched(&o, sizeof o));
    }
}

/* ------------------------------------------------------------- tables */

static double tr[4097], tf[4097], ts[4096];
static float trf[4097], tsf[4096];

/* samples of f on [0, rmax], m points, f(r) + off; slopes in double */
static void sample(double (*f)(double, const double *), const double *par, int m, double rmax, double off)
{
    for (int i = 0; i < m; i++) {
        tr[i] = rmax * i / (m - 1);
        tf[i] = off + f(tr[i], par);
        trf[i] = (float)tr[i];
    }
    for (int i = 0; i + 1 < m; i++) {
        ts[i] = (tf[i + 1] - tf[i]) / (tr[i + 1] - tr[i]);
        tsf[i] = (float)ts[i];
    }
}

static double f_par(double r, const double *p)
{
    return r * r / (2 * p[0]);
}

static double f_flat(double r, const double *p)
{
    return r < p[1] ? 0 : (r * r - p[1] * p[1]) / (2 * p[0]);
}

static double f_sph(double r, const double *p)
{
    return p[0] - sqrt((p[0] - r) * (p[0] + r));
}

/* g, g', G of a sampled paraboloid, and of a paraboloid with a flat ending
 * at a node, are those of the closed forms to rounding (the kink is kept) */
static void table_exact_for_quadratics(void **st)
{
    const double R = 1e-5, b = 2.4e-6, par[2] = {R, b};
    (void)st;
    for (int flat = 0; flat < 2; flat++) {
        mdr_contact_f64 t, ref;
        sample(flat ? f_flat : f_par, par, 101, 12e-6, 0);
        assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, 101, 1e6, 0.05), MDR_OK);
        ref = flat ? mk64(MDR_PROFILE_FLATTIP, R, b, 0, 1e6, 0.05) : mk64(MDR_PROFILE_PARABOLOID, R, 0, 0, 1e6, 0.05);
        for (double x = 1e-8; x < 12e-6; x *= 1.05) {
            double g, dg, G, g0, dg0, G0;
            if (flat && fabs(x - b) < 1e-3 * b) {
                continue;
            }
            assert_int_equal(mdr_profile_eval_f64(&t, x, &g, &dg, &G), MDR_OK);
            assert_int_equal(mdr_profile_eval_f64(&ref, x, &g0, &dg0, &G0), MDR_OK);
            rel_le(g, g0, x * x / R, 1e-13, "sampled g");
            rel_le(dg, dg0, fabs(dg0) + x / R, flat ? 1e-11 : 1e-13, "sampled g' (the kink kept)");
            rel_le(G, G0, x * x * x / R, 1e-13, "sampled G");
        }
    }
}

/* order of the sampled sphere's g, G (2.5) and g' (1.5) in the spacing */
static void table_order(void **st)
{
    const double R = 1e-6, par[1] = {R};
    mdr_contact_f64 ref = mk64(MDR_PROFILE_SPHERE, R, 0, 0, 1e6, 0.05);
    double lnN[6], eg[6], ed[6], eG[6], og, od, oG;
    (void)st;
    print_message("sampled sphere (to 0.6 R): M, largest error of g, g', G (of their values at 0.6 R)\n");
    for (int k = 0; k < 6; k++) {
        int m = (16 << k) + 1;
        mdr_contact_f64 t;
        double wg = 0, wd = 0, wG = 0, gm, dgm, Gm;
        sample(f_sph, par, m, 0.6 * R, 0);
        assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, (uint16_t)m, 1e6, 0.05), MDR_OK);
        assert_int_equal(mdr_profile_eval_f64(&ref, 0.6 * R, &gm, &dgm, &Gm), MDR_OK);
        for (double x = 0.6 * R / 200; x < 0.6 * R; x += 0.6 * R / 200) {
            double g, dg, G, g0, dg0, G0;
            assert_int_equal(mdr_profile_eval_f64(&t, x, &g, &dg, &G), MDR_OK);
            assert_int_equal(mdr_profile_eval_f64(&ref, x, &g0, &dg0, &G0), MDR_OK);
            wg = fmax(wg, fabs(g - g0) / gm);
            wd = fmax(wd, fabs(dg - dg0) / dgm);
            wG = fmax(wG, fabs(G - G0) / Gm);
        }
        print_message("  %5d  %.3e %.3e %.3e\n", m - 1, wg, wd, wG);
        lnN[k] = log(m - 1.0);
        eg[k] = log(wg);
        ed[k] = log(wd);
        eG[k] = log(wG);
    }
    og = -(eg[5] - eg[2]) / (lnN[5] - lnN[2]);
    od = -(ed[5] - ed[2]) / (lnN[5] - lnN[2]);
    oG = -(eG[5] - eG[2]) / (lnN[5] - lnN[2]);
    print_message("  orders: g %.2f, g' %.2f, G %.2f\n", og, od, oG);
    assert_true(og >= 2.3 && oG >= 2.3 && od >= 1.3);
}

/* a worn tip (flat for r < b, b at a node, above the threshold 0.7475 a*
 * under load and its grips counterpart): Kendall's separation at a = b,
 * F = -sqrt(8 pi b^3 E* w), d = -sqrt(2 pi b w/E*), in the contact module,
 * under load, grips and a machine, to 1e-9 (f64) and REL32 (f32) */
static void table_worn_tip_kendall(void **st)
{
    const double R = 1e-5, E = 1e6, w = 0.05, astar = cbrt(9 * M_PI * R * R * w / (8 * E));
    (void)st;
    for (int k = 0; k < 3; k++) {
        const int m = 1201;
        double rmax = 4 * astar, b = tr[0];
        int kb = (int)((0.9 + 0.3 * k) * astar / rmax * (m - 1));
        double par[2];
        mdr_contact_f64 t;
        mdr_contact_f32 tf32;
        for (int i = 0; i < m; i++) {
            tr[i] = rmax * i / (m - 1);
        }
        b = tr[kb];
        par[0] = R;
        par[1] = b;
        sample(f_flat, par, m, rmax, 0.3); /* a height offset: only slopes enter */
        assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, (uint16_t)m, E, w), MDR_OK);
        assert_int_equal(mdr_contact_init_table_f32(&tf32, trf, tsf, (uint16_t)m, (float)E, (float)w), MDR_OK);
        for (uint8_t ctl = 1; ctl <= 3; ctl++) {
            mdr_critstate_f64 o;
            mdr_critstate_f32 of;
            double a0, Fk = -sqrt(8 * M_PI * b * b * b * E * w), dk = -sqrt(2 * M_PI * b * w / E);
            float a0f;
            assert_int_equal(mdr_default_start_f64(&t, &a0), MDR_OK);
            assert_int_equal(mdr_critical_f64(&t, ctl, 2 * E * b, a0, &o), MDR_OK);
            assert_int_equal(mdr_default_start_f32(&tf32, &a0f), MDR_OK);
            assert_int_equal(mdr_critical_f32(&tf32, ctl, (float)(2 * E * b), a0f, &of), MDR_OK);
            print_message("worn tip b = %.3f a*, control %u: F/Kendall - 1 = %.1e (f64), %.1e (f32)\n", b / astar,
                          ctl, o.F / Fk - 1, of.F / Fk - 1);
            assert_true(o.a == b);
            rel_le(o.F, Fk, 0, KENDALL, "worn tip: Kendall's F at the rim");
            rel_le(o.d, dk, 0, KENDALL, "worn tip: Kendall's d at the rim");
            rel_le(of.F, Fk, 0, REL32, "worn tip f32");
        }
    }
}

/* a sampled flattened tip below its threshold, under all controls, against
 * the analytic flattened tip (the table reproduces it to rounding); and a
 * sampled sphere against the exact sphere within the model's error */
/* Sampled cones (f = r tan(theta), a straight first interval) whose grips
 * fold lies in the first sample interval (helper-25, stop 56: the walk
 * stopped at a bound that is then the fold itself and answered a = d = F = 0,
 * MDR_OK, in 57 of these 400 scenes in f64 and 73 in f32): 400 scenes, theta
 * 0.05 .. 1.45, E* 1e3 .. 1e11 Pa, w 1e-6 .. 1 J/m^2, 3 .. 62 uniform
 * samples to 1.5 (m - 1) grips pull-off radii; grips and a machine 1e3
 * times stiffer than E* times the pull-off radius, f64 and f32, against the
 * cone's critical state: a within REL_CONE64 = 1e-9 (f64) and REL32 (f32)
 * and F likewise. */
#define REL_CONE64 1e-9
static void table_cone_fold_first_interval(void **st)
{
    double worst[2] = {0, 0};
    int it, k;
    (void)st;
    for (it = 0; it < 400; it++) {
        const double th = 0.05 + 1.4 * (it % 37) / 37.0, E = pow(10, 3 + (it % 9)), w = pow(10, -6 + (it % 7));
        const int m = 3 + (it * 7) % 60;
        const double pc[3] = {th, 0, 0};
        mdr_contact_f64 cone, c;
        mdr_contact_f32 cf;
        mdr_critstate_f64 oc, o;
        mdr_critstate_f32 of;
        double a0, rmax, r[64], sl[64];
        float rf[64], sf[64];
        int i;
        assert_int_equal(mdr_contact_init_f64(&cone, MDR_PROFILE_CONE, pc, E, w), MDR_OK);
        assert_int_equal(mdr_default_start_f64(&cone, &a0), MDR_OK);
        assert_int_equal(mdr_critical_f64(&cone, MDR_CONTROL_GRIPS, 0, a0, &oc), MDR_OK);
        rmax = oc.a * (m - 1) * 1.5;
        for (i = 0; i < m; i++) {
            r[i] = rmax * i / (m - 1);
            rf[i] = (float)r[i];
        }
        for (i = 0; i + 1 < m; i++) {
            sl[i] = tan(th);
            sf[i] = (float)sl[i];
        }
        assert_int_equal(mdr_contact_init_table_f64(&c, r, sl, (uint16_t)m, E, w), MDR_OK);
        assert_int_equal(mdr_contact_init_table_f32(&cf, rf, sf, (uint16_t)m, (float)E, (float)w), MDR_OK);
        for (k = 0; k < 2; k++) { /* grips; a stiff machine */
            const uint8_t ctl = k == 0 ? MDR_CONTROL_GRIPS : MDR_CONTROL_MACHINE;
            const double km = k == 0 ? 0 : 1e3 * E * oc.a;
            mdr_critstate_f64 ock = oc;
            double e64, e32, as;
            float asf;
            if (k == 1) {
                assert_int_equal(mdr_critical_f64(&cone, ctl, km, a0, &ock), MDR_OK);
            }
            assert_int_equal(mdr_default_start_f64(&c, &as), MDR_OK);
            assert_int_equal(mdr_default_start_f32(&cf, &asf), MDR_OK);
            assert_int_equal(mdr_critical_f64(&c, ctl, km, as, &o), MDR_OK);
            assert_int_equal(mdr_critical_f32(&cf, ctl, (float)km, asf, &of), MDR_OK);
            e64 = fmax(fabs(o.a / ock.a - 1), fabs(o.F / ock.F - 1));
            e32 = fmax(fabs(of.a / ock.a - 1), fabs(of.F / ock.F - 1));
            if (!(e64 <= REL_CONE64) || !(e32 <= REL32)) {
                print_message("theta %.3f E %g w %g m %d control %u: f64 a %.6g F %.6g, f32 a %.6g F %.6g, cone a %.6g "
                              "F %.6g\n", th, E, w, m, ctl, o.a, o.F, (double)of.a, (double)of.F, ock.a, ock.F);
            }
            worst[0] = fmax(worst[0], e64);
            worst[1] = fmax(worst[1], e32);
            assert_true(e64 <= REL_CONE64 && e32 <= REL32);
        }
    }
    print_message("sampled cones, fold in the first interval, 400 scenes x grips, stiff machine: worst f64 %.2e, "
                  "f32 %.2e of the cone's a and F\n", worst[0], worst[1]);
}

/* The stress inside a sampled worn tip (a flattened tip R = 1, b = 0.3
 * sampled every 0.025 to 1, its rim on a sample; the samples' model is that
 * tip exactly): the samples' g' peaks as
 * 1/sqrt just above the rim, and one quadrature panel over it gave
 * -689194 Pa at r = 0.1 for the flattened tip's 0.085 (helper-25, stop 56).
 * At a = 0.5, r from 0 to 0.49 (the rim itself MDR_E_SINGULAR, as the
 * flattened tip's): f64 within TOL_WORN64 = 1e-6 and f32 within TOL_WORN32 =
 * 2e-3 of the largest |sigma| of the analytic flattened tip's stress in f64
 * (measured 4.8e-9 and 5.7e-4). */
#define TOL_WORN64 1e-6
#define TOL_WORN32 2e-3
static void table_worn_tip_stress(void **st)
{
    const double R = 1.0, b = 0.3, a = 0.5, E = 1.0, w = 0.05, pf[3] = {R, b, 0};
    double r[41], sl[40], worst[2] = {0, 0}, smax = 0, x;
    float rf[41], sf[40];
    mdr_contact_f64 ft, c;
    mdr_contact_f32 cf;
    int i, k;
    (void)st;
    for (i = 0; i < 41; i++) {
        r[i] = 0.025 * i;
        rf[i] = (float)r[i];
    }
    for (i = 0; i < 40; i++) {
        /* (the flattened tip: f = (r^2 - b^2)/(2R) past the rim, whose
         * piecewise-linear f' the samples' model is exactly) */
        const double f0 = r[i] <= b ? 0 : (r[i] * r[i] - b * b) / (2 * R);
        const double f1 = r[i + 1] <= b ? 0 : (r[i + 1] * r[i + 1] - b * b) / (2 * R);
        sl[i] = (f1 - f0) / (r[i + 1] - r[i]);
        sf[i] = (float)sl[i];
    }
    assert_int_equal(mdr_contact_init_f64(&ft, MDR_PROFILE_FLATTIP, pf, E, w), MDR_OK);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, sl, 41, E, w), MDR_OK);
    assert_int_equal(mdr_contact_init_table_f32(&cf, rf, sf, 41, (float)E, (float)w), MDR_OK);
    for (x = 0; x < 0.49; x += 0.0049) {
        double s0;
        assert_int_equal(mdr_stress_f64(&ft, a, x, &s0), MDR_OK);
        smax = fmax(smax, fabs(s0));
    }
    for (k = 0; k <= 100; k++) {
        const double xr = 0.49 * k / 100.0;
        double s0, s64;
        float s32;
        if (xr == r[12]) {
            continue;
        }
        assert_int_equal(mdr_stress_f64(&ft, a, xr, &s0), MDR_OK);
        assert_int_equal(mdr_stress_f64(&c, a, xr, &s64), MDR_OK);
        assert_int_equal(mdr_stress_f32(&cf, (float)a, (float)xr, &s32), MDR_OK);
        worst[0] = fmax(worst[0], fabs(s64 - s0) / smax);
        worst[1] = fmax(worst[1], fabs((double)s32 - s0) / smax);
    }
    {
        double s;
        float s32;
        assert_int_equal(mdr_stress_f64(&c, a, r[12], &s), MDR_E_SINGULAR); /* (the rim: sample 12) */
        assert_int_equal(mdr_stress_f32(&cf, (float)a, rf[12], &s32), MDR_E_SINGULAR);
    }
    print_message("sampled worn tip's stress against the flattened tip's, r/a 0 .. 0.98: f64 %.2e, f32 %.2e of "
                  "max|sigma|\n", worst[0], worst[1]);
    assert_true(worst[0] <= TOL_WORN64 && worst[1] <= TOL_WORN32);
}

/* A sampled cone's stress toward the axis (a helper's attack, stop 57): 17
 * samples of f = tan(0.3) r to 40 um (the model is the cone exactly), a =
 * 1 um, E* = 1e6 Pa, w = 0.05: sigma at r = a 10^-k, k = 1 .. 36, against
 * 4.27 in closed form worked out here, -(E* tan(theta)/2) acosh(a/r) +
 * E* dl/(pi sqrt(a^2 - r^2)) (g' = (pi/2) tan(theta)), relative to the
 * larger of the two terms: within TOL_AXIS64 (f64) and TOL_AXIS32 (f32);
 * at r = 0, where it is -inf, MDR_E_SINGULAR (as the analytic cone); a
 * sampled paraboloid (f'(0+) = 0) answers at r = 0, within TOL_AXIS64 of
 * its closed form. (f32 below r = 1e-24 a: within TOL_AXIS32 or
 * MDR_E_OVERFLOW, from 1e-29 a, where the rule's nodes underflow.) Before: panels only at the kinks, 1.05e-6 off at r =
 * 1e-6 a, 1.6e-2 at 1e-24 a, and -8.37e6 Pa at r = 0, status ok. Measured
 * after: f64 2.9e-13, f32 4.9e-7. */
#define TOL_AXIS64 1e-12
#define TOL_AXIS32 2e-6
static void table_cone_stress_axis(void **st)
{
    const double th = 0.3, a = 1e-6, E = 1e6, w = 0.05, dl = sqrt(2 * M_PI * a * w / E);
    double r[17], sl[16], worst64 = 0, worst32 = 0;
    float rf[17], sf[16];
    mdr_contact_f64 c;
    mdr_contact_f32 cf;
    int i, k;
    (void)st;
    for (i = 0; i < 17; i++) {
        r[i] = 40e-6 * i / 16.0;
        rf[i] = (float)r[i];
    }
    for (i = 0; i < 16; i++) {
        sl[i] = tan(th);
        sf[i] = (float)sl[i];
    }
    assert_int_equal(mdr_contact_init_table_f64(&c, r, sl, 17, E, w), MDR_OK);
    assert_int_equal(mdr_contact_init_table_f32(&cf, rf, sf, 17, (float)E, (float)w), MDR_OK);
    for (k = 1; k <= 36; k++) {
        const double x = a * pow(10.0, -k), t1 = E * tan(th) / 2 * acosh(a / x);
        const double t2 = E * dl / (M_PI * sqrt((a - x) * (a + x))), want = -t1 + t2;
        double s;
        float s32;
        assert_int_equal(mdr_stress_f64(&c, a, x, &s), MDR_OK);
        worst64 = fmax(worst64, fabs(s - want) / fmax(t1, t2));
        if (k <= 24) {
            assert_int_equal(mdr_stress_f32(&cf, (float)a, (float)x, &s32), MDR_OK);
            worst32 = fmax(worst32, fabs((double)s32 - want) / fmax(t1, t2));
        } else if (x >= 1.2e-38) {
            /* (further in, the rule's nodes at u ~ r underflow in float:
             * answered within TOL_AXIS32, or refused by name) */
            const mdr_status st32 = mdr_stress_f32(&cf, (float)a, (float)x, &s32);
            assert_true(st32 == MDR_E_OVERFLOW ||
                        (st32 == MDR_OK && fabs((double)s32 - want) <= TOL_AXIS32 * fmax(t1, t2)));
        }
    }
    {
        double s;
        float s32;
        assert_int_equal(mdr_stress_f64(&c, a, 0.0, &s), MDR_E_SINGULAR);
        assert_int_equal(mdr_stress_f32(&cf, (float)a, 0.0f, &s32), MDR_E_SINGULAR);
    }
    {
        /* a sampled paraboloid R = 10 um: finite on the axis */
        const double R = 10e-6;
        double rp[37], sp[36], s, want;
        mdr_contact_f64 cp;
        for (i = 0; i < 37; i++) {
            rp[i] = 10e-6 * i / 36.0;
        }
        for (i = 0; i < 36; i++) {
            sp[i] = (rp[i + 1] * rp[i + 1] - rp[i] * rp[i]) / (2 * R) / (rp[i + 1] - rp[i]);
        }
        assert_int_equal(mdr_contact_init_table_f64(&cp, rp, sp, 37, E, w), MDR_OK);
        assert_int_equal(mdr_stress_f64(&cp, a, 0.0, &s), MDR_OK);
        /* 4.27 for the paraboloid at r = 0: -2 E* a/(pi R) + E* dl/(pi a) */
        want = -2 * E / (M_PI * R) * a + E * dl / (M_PI * a);
        assert_true(fabs(s - want) <= TOL_AXIS64 * fmax(2 * E / (M_PI * R) * a, E * dl / (M_PI * a)));
    }
    print_message("sampled cone's stress toward the axis, r/a 1e-1 .. 1e-36 (f32 to 1e-24): f64 %.2e, f32 %.2e of the "
                  "larger term\n",
                  worst64, worst32);
    assert_true(worst64 <= TOL_AXIS64 && worst32 <= TOL_AXIS32);
}

/* The flattened tip's stress at a = b (the contact on its flat, its grips
 * pull-off state in the helper's case): g' = 0 on (0, b) and g(b) = 0, so
 * 4.27 at equilibrium (d = -dl) is E* dl/(pi sqrt(b^2 - r^2)), finite; it
 * was refused MDR_E_OVERFLOW, mdr_stress taking the whole mdr_eq, whose
 * dd/da is infinite at the rim (a helper's attack, stop 57). r/b from 0 to
 * 0.95, f64 and f32, within TOL_RIMSTRESS of that closed form. */
#define TOL_RIMSTRESS 1e-6
static void flattip_stress_at_rim(void **st)
{
    const double R = 1e-5, b = 2e-6, E = 1e6, w = 0.05, dl = sqrt(2 * M_PI * b * w / E);
    const double pd[3] = {R, b, 0};
    const float pf[3] = {(float)R, (float)b, 0};
    mdr_contact_f64 c;
    mdr_contact_f32 cf;
    double worst = 0;
    int k;
    (void)st;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_FLATTIP, pd, E, w), MDR_OK);
    assert_int_equal(mdr_contact_init_f32(&cf, MDR_PROFILE_FLATTIP, pf, (float)E, (float)w), MDR_OK);
    for (k = 0; k <= 19; k++) {
        const double r = b * 0.05 * k, want = E * dl / (M_PI * sqrt((b - r) * (b + r)));
        double s;
        float s32;
        assert_int_equal(mdr_stress_f64(&c, b, r, &s), MDR_OK);
        assert_int_equal(mdr_stress_f32(&cf, (float)b, (float)r, &s32), MDR_OK);
        worst = fmax(worst, fmax(fabs(s - want), fabs((double)s32 - want)) / want);
    }
    print_message("flattened tip's stress at a = b: %.2e of the closed form (f64 and f32)\n", worst);
    assert_true(worst <= TOL_RIMSTRESS);
}

/* A sampled cone has no jump (a helper's attack, stop 57): 2 000 samples of
 * f = tan(0.3) r to 40 um, uniform and randomly spaced, the slopes
 * differenced in double as the CLI does (each one rounds to eps r/h of
 * itself: one ulp lower at node 78 of the uniform ones was taken for a
 * concave kink, mdr_a_kink): mdr_critical under load and grips answers
 * no jump, and the cone's a, d, F within TOL_CONE_SAMPLED. Before: 1 jump
 * (uniform, grips), 37 and 39 (random, load and grips). Host only (O(m^2)
 * per search). */
#define TOL_CONE_SAMPLED 1e-12
#ifndef MDR_TARGET_TEST
static void table_cone_no_false_kinks(void **st)
{
    enum { M = 2000 };
    static double r[M], f[M], sl[M - 1];
    const double th = 0.3, E = 1e6, w = 0.05, pc[3] = {th, 0, 0};
    uint64_t x = 0x2545F4914F6CDD1Dull;
    mdr_contact_f64 cone, c;
    int pass, i, ctl;
    (void)st;
    assert_int_equal(mdr_contact_init_f64(&cone, MDR_PROFILE_CONE, pc, E, w), MDR_OK);
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < M; i++) {
            double u;
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            u = (double)(x >> 11) / 9007199254740992.0;
            r[i] = pass == 0 ? 40e-6 * i / (M - 1) : (i == 0 ? 0.0 : r[i - 1] + 40e-6 / (M - 1) * (0.2 + 1.6 * u));
            f[i] = tan(th) * r[i];
        }
        for (i = 0; i + 1 < M; i++) {
            sl[i] = (f[i + 1] - f[i]) / (r[i + 1] - r[i]);
        }
        assert_int_equal(mdr_contact_init_table_f64(&c, r, sl, M, E, w), MDR_OK);
        for (ctl = 0; ctl < 2; ctl++) {
            const uint8_t control = ctl ? MDR_CONTROL_GRIPS : MDR_CONTROL_LOAD;
            mdr_critstate_f64 got, want;
            double a0, a0c;
            assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
            assert_int_equal(mdr_default_start_f64(&cone, &a0c), MDR_OK);
            assert_int_equal(mdr_critical_f64(&c, control, 0, a0, &got), MDR_OK);
            assert_int_equal(mdr_critical_f64(&cone, control, 0, a0c, &want), MDR_OK);
            if (got.jumps != 0) {
                print_message("sampled cone (%s spacing, %s): %u jumps\n", pass ? "random" : "uniform",
                              ctl ? "grips" : "load", (unsigned)got.jumps);
            }
            assert_int_equal(got.jumps, 0);
            assert_true(fabs(got.a - want.a) <= TOL_CONE_SAMPLED * want.a);
            assert_true(fabs(got.d - want.d) <= TOL_CONE_SAMPLED * fabs(want.d));
            assert_true(fabs(got.F - want.F) <= TOL_CONE_SAMPLED * fabs(want.F));
        }
    }
}
#endif

static void table_critical_vs_profiles(void **st)
{
    const double R = 1e-5, E = 1e6, w = 0.05, astar = cbrt(9 * M_PI * R * R * w / (8 * E));
    (void)st;
    {
        const int m = 801;
        double rmax = 4 * astar, b, par[2];
        mdr_contact_f64 t, ref;
        int kb = (int)(0.5 * astar / rmax * (m - 1));
        for (int i = 0; i < m; i++) {
            tr[i] = rmax * i / (m - 1);
        }
        b = tr[kb];
        par[0] = R;
        par[1] = b;
        sample(f_flat, par, m, rmax, 0);
        assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, (uint16_t)m, E, w), MDR_OK);
        ref = mk64(MDR_PROFILE_FLATTIP, R, b, 0, E, w);
        for (uint8_t ctl = 1; ctl <= 3; ctl++) {
            mdr_critstate_f64 o, o0;
            double a0, a00;
            assert_int_equal(mdr_default_start_f64(&t, &a0), MDR_OK);
            assert_int_equal(mdr_default_start_f64(&ref, &a00), MDR_OK);
            assert_int_equal(mdr_critical_f64(&t, ctl, 2 * E * astar, a0, &o), MDR_OK);
            assert_int_equal(mdr_critical_f64(&ref, ctl, 2 * E * astar, a00, &o0), MDR_OK);
            rel_le(o.a, o0.a, 0, 1e-9, "sampled flattened tip: critical radius");
            rel_le(o.F, o0.F, 0, 1e-9, "sampled flattened tip: critical force");
            print_message("sampled flattened tip b = 0.5 a*, control %u: a/a* = %.6f, F_min = %.9g (analytic %.9g)\n",
                          ctl, o.a / astar, o.F_min, o0.F_min);
            rel_le(o.F_min, o0.F_min, 0, 1e-9, "sampled flattened tip: most tensile force");
            assert_int_equal(o.jumps, o0.jumps);
        }
    }
    {
        const double par[1] = {R};
        mdr_contact_f64 t, ref = mk64(MDR_PROFILE_SPHERE, R, 0, 0, E, w);
        sample(f_sph, par, 2001, 0.9 * R, 0);
        assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, 2001, E, w), MDR_OK);
        for (uint8_t ctl = 1; ctl <= 3; ctl++) {
            mdr_critstate_f64 o, o0;
            double a0;
            assert_int_equal(mdr_default_start_f64(&t, &a0), MDR_OK);
            assert_int_equal(mdr_critical_f64(&t, ctl, 2 * E * astar, a0, &o), MDR_OK);
            assert_int_equal(mdr_critical_f64(&ref, ctl, 2 * E * astar, a0, &o0), MDR_OK);
            print_message("sampled sphere (2000 intervals to 0.9 R), control %u: F %.1e, a %.1e off the exact sphere\n",
                          ctl, fabs(o.F / o0.F - 1), fabs(o.a / o0.a - 1));
            rel_le(o.F, o0.F, 0, TAB_SPH, "sampled sphere: critical force (model error)");
            rel_le(o.a, o0.a, 0, TAB_SPH, "sampled sphere: critical radius");
        }
    }
}

/* f32 with a 1 m height offset on a 10 um sphere (the issue: 46 % before
 * the slopes were formed in double) */
static void table_f32_height_offset(void **st)
{
    const double R = 10e-6, E = 1e6, w = 0.05, par[1] = {R};
    mdr_contact_f32 t;
    mdr_contact_f64 ref = mk64(MDR_PROFILE_SPHERE, R, 0, 0, E, w);
    (void)st;
    sample(f_sph, par, 401, 0.8 * R, 1.0);
    assert_int_equal(mdr_contact_init_table_f32(&t, trf, tsf, 401, (float)E, (float)w), MDR_OK);
    for (uint8_t ctl = 1; ctl <= 3; ctl++) {
        mdr_critstate_f32 o;
        mdr_critstate_f64 o0;
        float a0;
        double a00;
        assert_int_equal(mdr_default_start_f32(&t, &a0), MDR_OK);
        assert_int_equal(mdr_critical_f32(&t, ctl, (float)(2e6 * 2.6e-6), a0, &o), MDR_OK);
        assert_int_equal(mdr_default_start_f64(&ref, &a00), MDR_OK);
        assert_int_equal(mdr_critical_f64(&ref, ctl, 2e6 * 2.6e-6, a00, &o0), MDR_OK);
        print_message("f32 table with a 1 m offset, control %u: pull-off F/F_sphere - 1 = %.1e\n", ctl,
                      (double)o.F / o0.F - 1);
        rel_le(o.F, o0.F, 0, 1e-5, "f32 table with a 1 m height offset: pull-off");
    }
}

/* eq, stress and curves of a table through the public calls */
static void table_eq_and_stress(void **st)
{
    const double R = 1e-5, par[1] = {R};
    mdr_contact_f64 t, ref = mk64(MDR_PROFILE_PARABOLOID, R, 0, 0, 1e6, 0.05);
    mdr_contact_f32 tf32;
    (void)st;
    sample(f_par, par, 61, 12e-6, 0);
    assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, 61, 1e6, 0.05), MDR_OK);
    assert_int_equal(mdr_contact_init_table_f32(&tf32, trf, tsf, 61, 1e6f, 0.05f), MDR_OK);
    for (double a = 1e-7; a < 12e-6; a *= 1.3) {
        mdr_eqstate_f64 e, e0;
        mdr_eqstate_f32 ef;
        assert_int_equal(mdr_eq_f64(&t, a, &e), MDR_OK);
        assert_int_equal(mdr_eq_f64(&ref, a, &e0), MDR_OK);
        assert_int_equal(mdr_eq_f32(&tf32, (float)a, &ef), MDR_OK);
        rel_le(e.F, e0.F, 2e6 * a * (a * a / R + e0.dl), 1e-13, "table eq F");
        rel_le(e.dF_da, e0.dF_da, 2e6 * (a * a / R + e0.dl), 1e-12, "table eq dF/da");
        rel_le(ef.F, e0.F, 2e6 * a * (a * a / R + e0.dl), REL32, "table eq F (f32)");
        for (double s = 0; s < 0.99; s += 0.14) {
            double sg, sg0;
            assert_int_equal(mdr_stress_f64(&t, a, s * a, &sg), MDR_OK);
            assert_int_equal(mdr_stress_f64(&ref, a, s * a, &sg0), MDR_OK);
            rel_le(sg, sg0, fabs(sg0) + 1e6 * (a * a / R + e0.dl) / (M_PI * a), 1e-9, "table stress");
        }
    }
}

/* every error path of mdr_contact_init_table, nothing written on error */
static void table_errors(void **st)
{
    double r[5] = {0, 1, 2, 3, 4}, s[4] = {0, 1, 2, 3};
    float rf[5] = {0, 1, 2, 3, 4}, sf[4] = {0, 1, 2, 3};
    mdr_contact_f64 c;
    mdr_contact_f32 cf;
    double g;
    (void)st;
    memset(&c, GUARD, sizeof c);
    memset(&cf, GUARD, sizeof cf);
    assert_int_equal(mdr_contact_init_table_f64(NULL, r, s, 5, 1, 1), MDR_E_NULL);
    assert_int_equal(mdr_contact_init_table_f64(&c, NULL, s, 5, 1, 1), MDR_E_NULL);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, NULL, 5, 1, 1), MDR_E_NULL);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 2, 1, 1), MDR_E_TABLE);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 0, 1), MDR_E_PARAM);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 1, -1), MDR_E_PARAM);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, NAN, 1), MDR_E_NONFINITE);
    assert_int_equal(mdr_contact_init_table_f32(&cf, rf, sf, 5, 1, INFINITY), MDR_E_NONFINITE);
    r[0] = 0.5;
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 1, 1), MDR_E_TABLE);
    r[0] = 0;
    r[3] = 2;
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 1, 1), MDR_E_TABLE);
    r[3] = NAN;
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 1, 1), MDR_E_NONFINITE);
    r[3] = 3;
    s[2] = INFINITY;
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 1, 1), MDR_E_NONFINITE);
    sf[1] = 3e38f; /* finite slopes, g beyond float */
    assert_int_equal(mdr_contact_init_table_f32(&cf, rf, sf, 5, 1, 1), MDR_E_OVERFLOW);
    assert_true(untouched(&c, sizeof c));
    assert_true(untouched(&cf, sizeof cf));
    /* the general init refuses the kind */
    {
        double p[3] = {1, 1, 1};
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_TABLE, p, 1, 1), MDR_E_KIND);
        assert_true(untouched(&c, sizeof c));
    }
    /* outside the samples */
    s[2] = 2;
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 5, 1, 1), MDR_OK);
    assert_int_equal(mdr_profile_eval_f64(&c, 4.0, &g, NULL, NULL), MDR_OK);
    assert_int_equal(mdr_profile_eval_f64(&c, 4.000001, &g, NULL, NULL), MDR_E_RADIUS);
    assert_int_equal(mdr_profile_eval_f64(&c, 0.0, &g, NULL, NULL), MDR_E_RADIUS);
    /* a table ending on the unstable branch: no stable state to start from */
    {
        const double par[1] = {1e-5};
        mdr_critstate_f64 o;
        double a0;
        sample(f_par, par, 21, 1e-6, 0);
        assert_int_equal(mdr_contact_init_table_f64(&c, tr, ts, 21, 1e6, 0.05), MDR_OK);
        assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
        memset(&o, GUARD, sizeof o);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, a0, &o), MDR_E_RADIUS);
        assert_true(untouched(&o, sizeof o));
    }
#if MDR_CFG_SCENE
    /* the scene of a table is not a monomial */
    {
        mdr_scene_f64 sc;
        assert_int_equal(mdr_scene_init_contact_f64(&sc, &c, 0, 0, MDR_OUT_FORCE, NULL), MDR_E_KIND);
    }
#endif
}
/* Quantized heights (a profilometer's step q): a worn tip, flat below b,
 * f = q round((r - b)^2/(2 L)/q), m samples r_i = L (i/(m-1))^2. The
 * slope changes of quantized samples come in equal pairs of opposite sign,
 * so no node is a kink, and g carries -D sqrt(2 r_k (a - r_k)) above a node
 * that g' leaves out: a fold a fraction of a float's spacing above the node,
 * where either end of the bracket is off by D sqrt(2 r_k u). f32 answered the
 * pull-off of the CLI's 1001-sample tip 4.2e-3 off f64, exit 0 (mdr critical
 * --control grips). Sweep: q 5e-9, 1e-8, 5e-8 m, b/L 0 and 0.07, w 3e-5
 * J/m^2, E* 6.35 MPa, L = 114 um, m = 201, load, grips and a machine (15
 * of its 18 cases failed before the fix; 24 tips, q from 2e-9, b/L to
 * 0.155, w to 8.98e-5, cost 13 s of the suite for no more);
 * f32 against f64 on the same (float) samples: F and d of the pull-off
 * within REL32 (d relative to max(|d|, dl)), the radius within REL32 and the
 * same jumps. Measured: f32 up to 1.7e-3 off before the fix (mdr_c_atroot),
 * 4.4e-7 after. */
static void table_quantized_heights_f32(void **st)
{
    static const double qs[3] = {5e-9, 1e-8, 5e-8}, bs[2] = {0, 0.07};
    const double w = 3e-5;
    const double L = 1.14e-4, E = 6.35e6;
    const int m = 201;
    double worst = 0;
    int iq, ib, i;
    (void)st;
    for (iq = 0; iq < 3; iq++) {
        for (ib = 0; ib < 2; ib++) {
            {
                const double q = qs[iq], b = bs[ib] * L;
                mdr_contact_f64 t;
                mdr_contact_f32 tf32;
                for (i = 0; i < m; i++) {
                    const double x = L * i / (m - 1.0) * i / (m - 1.0), y = x < b ? 0 : (x - b) * (x - b) / (2 * L);
                    tf[i] = q * nearbyint(y / q);
                    trf[i] = (float)x;
                    tr[i] = trf[i];
                }
                for (i = 0; i + 1 < m; i++) {
                    tsf[i] = (float)((tf[i + 1] - tf[i]) / (tr[i + 1] - tr[i]));
                    ts[i] = tsf[i];
                }
                assert_int_equal(mdr_contact_init_table_f64(&t, tr, ts, (uint16_t)m, E, w), MDR_OK);
                assert_int_equal(mdr_contact_init_table_f32(&tf32, trf, tsf, (uint16_t)m, (float)E, (float)w), MDR_OK);
                for (uint8_t ctl = 1; ctl <= 3; ctl++) {
                    const double km = 2 * E * 0.1 * L;
                    mdr_critstate_f64 o;
                    mdr_critstate_f32 of;
                    double a0, dl, e;
                    float a0f;
                    assert_int_equal(mdr_default_start_f64(&t, &a0), MDR_OK);
                    assert_int_equal(mdr_default_start_f32(&tf32, &a0f), MDR_OK);
                    assert_int_equal(mdr_critical_f64(&t, ctl, km, a0, &o), MDR_OK);
                    assert_int_equal(mdr_critical_f32(&tf32, ctl, (float)km, a0f, &of), MDR_OK);
                    dl = sqrt(2 * M_PI * o.a * w / E);
                    e = fmax(fabs(of.F - o.F) / fabs(o.F), fabs(of.d - o.d) / fmax(fabs(o.d), dl));
                    if (!(e <= REL32)) {
                        print_message("quantized q %g b %g w %g control %u: f32 F %.9g d %.9g, f64 F %.9g d %.9g\n", q,
                                      b, w, ctl, (double)of.F, (double)of.d, o.F, o.d);
                    }
                    worst = fmax(worst, e);
                    rel_le(of.F, o.F, 0, REL32, "quantized heights: f32 pull-off F");
                    rel_le(of.d, o.d, fmax(fabs(o.d), dl), REL32, "quantized heights: f32 pull-off d");
                    rel_le(of.a, o.a, 0, REL32, "quantized heights: f32 pull-off radius");
                    assert_int_equal(of.jumps, o.jumps);
                }
            }
        }
    }
    print_message("quantized heights, 6 tips x load, grips, machine: f32 pull-off F, d within %.1e of f64\n", worst);
}

/* A sampled paraboloid that ends at its pull-off radius (helper-45, stop
 * 61): the last sample at a_c (1 + delta), a_c JKR's fold under fixed grips,
 * a^3 = pi w R^2/(8 E*), or under fixed load, a^3 = 9 pi w R^2/(8 E*),
 * worked out here; 3, 5 and 17 samples on a uniform and a quadratic grid;
 * delta from -3e-6 to 3e-6 (f32's rounding of the end) and 0. Where the
 * fold's slope at the end rounds to 0 the walk saw no sign change below
 * the start and peeled: a = d = F = 0 with MDR_OK (f32: 96 of 27 000 such
 * tables, f64: grips at delta = 0). Each answer is MDR_E_RADIUS (the tip
 * ends before the pull-off) or, from the default start (the last sample),
 * JKR's pull-off force, -5/6 pi w R (grips),
 * -3/2 pi w R (load), within REL32 (f32) or 1e-9 (f64: the end itself is
 * the fold to delta^2); never a = 0. */
static void table_ends_at_pull_off(void **st)
{
    const double R = 10e-6, E = 1e6, w = 0.05;
    const int ns[3] = {3, 5, 17};
    int ctl, in, grid, k, i, answered = 0, refused = 0;
    (void)st;
    for (ctl = 0; ctl < 2; ctl++) {
        const uint8_t control = ctl == 0 ? MDR_CONTROL_GRIPS : MDR_CONTROL_LOAD;
        const double ac = cbrt((ctl == 0 ? 1.0 : 9.0) * M_PI * w * R * R / (8 * E));
        const double Fpo = -(ctl == 0 ? 5.0 / 6.0 : 1.5) * M_PI * w * R;
        for (in = 0; in < 3; in++) {
            for (grid = 0; grid < 2; grid++) {
                for (k = -6; k <= 6; k++) {
                    const int n = ns[in];
                    const double end = ac * (1 + 5e-7 * k);
                    for (int f32 = 0; f32 < 2; f32++) {
                        double r[17], f[17], s[16];
                        float rf[17], sf[16];
                        mdr_status rc;
                        double a, F;
                        for (i = 0; i < n; i++) {
                            const double x = (double)i / (n - 1);
                            r[i] = end * (grid == 0 ? x : x * x);
                            rf[i] = (float)r[i];
                            if (f32) {
                                r[i] = rf[i];
                            }
                            f[i] = r[i] * r[i] / (2 * R);
                        }
                        for (i = 0; i + 1 < n; i++) {
                            s[i] = (f[i + 1] - f[i]) / (r[i + 1] - r[i]);
                            sf[i] = (float)s[i];
                        }
                        if (f32) {
                            mdr_contact_f32 t;
                            mdr_critstate_f32 o;
                            assert_int_equal(mdr_contact_init_table_f32(&t, rf, sf, (uint16_t)n, (float)E, (float)w),
                                             MDR_OK);
                            float a0;
                            assert_int_equal(mdr_default_start_f32(&t, &a0), MDR_OK);
                            rc = mdr_critical_f32(&t, control, 0.0f, a0, &o);
                            a = o.a;
                            F = o.F;
                        } else {
                            mdr_contact_f64 t;
                            mdr_critstate_f64 o;
                            assert_int_equal(mdr_contact_init_table_f64(&t, r, s, (uint16_t)n, E, w), MDR_OK);
                            double a0;
                            assert_int_equal(mdr_default_start_f64(&t, &a0), MDR_OK);
                            rc = mdr_critical_f64(&t, control, 0.0, a0, &o);
                            a = o.a;
                            F = o.F;
                        }
                        if (rc == MDR_E_RADIUS) {
                            refused++;
                            continue;
                        }
                        if (rc != MDR_OK || !(a > 0) || !(fabs(F / Fpo - 1) <= (f32 ? REL32 : 1e-9))) {
                            print_message("table to a_c (1 + %g), %d samples, grid %d, %s, control %u: status %d, a %.9g, "
                                          "F %.9g (JKR %.9g)\n",
                                          5e-7 * k, n, grid, f32 ? "f32" : "f64", control, (int)rc, a, F, Fpo);
                        }
                        assert_int_equal(rc, MDR_OK);
                        assert_true(a > 0);
                        rel_le(F, Fpo, 0, f32 ? REL32 : 1e-9, "a table that ends at its pull-off: JKR's force");
                        answered++;
                    }
                }
            }
        }
    }
    print_message("tables ending at the pull-off radius: %d answered JKR's force, %d MDR_E_RADIUS, none peeled\n",
                  answered, refused);
}

/* A radius far below the first sample (helper-49, stop 62): the piece cut
 * at x took (r_1 - x)/(2x), which overflows where r_1/x exceeds the
 * arithmetic's range, and mdr_profile_eval answered MDR_E_OVERFLOW for a g
 * that is 0 to rounding there (f32: r = 0, 1e-3, 2e-3 mm-scale slopes 0.1,
 * 0.3, f'(0) = 0 by the curvature, at x = 1e-42 and 1e-44; f64 r = 0, 1, 2
 * at 1e-309 .. 1e-320). Now MDR_OK with g, g' and G finite and at most
 * the first interval's slope times x (g' at most its largest slope). */
static void table_subnormal_radius(void **st)
{
    const float rf[3] = {0.0f, 1e-3f, 2e-3f}, sf[2] = {0.1f, 0.3f};
    const double r[3] = {0.0, 1.0, 2.0}, s[2] = {0.1, 0.3};
    const float xf[3] = {1e-42f, 3e-42f, 1e-44f};
    const double xd[4] = {1e-308, 1e-309, 5e-310, 1e-320};
    mdr_contact_f32 cf;
    mdr_contact_f64 c;
    int i;
    (void)st;
    assert_int_equal(mdr_contact_init_table_f32(&cf, rf, sf, 3, 1e6f, 0.05f), MDR_OK);
    assert_int_equal(mdr_contact_init_table_f64(&c, r, s, 3, 1e6, 0.05), MDR_OK);
    for (i = 0; i < 3; i++) {
        float g, dg, G;
        assert_int_equal(mdr_profile_eval_f32(&cf, xf[i], &g, &dg, &G), MDR_OK);
        assert_true(isfinite(g) && fabsf(g) <= 0.3f * xf[i] && isfinite(dg) && fabsf(dg) <= 0.3f && isfinite(G));
    }
    for (i = 0; i < 4; i++) {
        double g, dg, G;
        assert_int_equal(mdr_profile_eval_f64(&c, xd[i], &g, &dg, &G), MDR_OK);
        assert_true(isfinite(g) && fabs(g) <= 0.3 * xd[i] && isfinite(dg) && fabs(dg) <= 0.3 && isfinite(G));
    }
}

/* Measured tips in f32: the arithmetic of the Abel model (mdr_abel.inc).
 * A 20 nm sphere sampled to 15 nm, its heights quantized to 0.1 nm (1 000
 * and 16 384 uniform radii), or with 0.02 nm of noise made monotone on
 * 1 000 random radii (a profilometer's tip), E* 1 GPa, w 0.05; the slopes
 * differenced in double as the CLI does. f32 against f64 on the same float
 * radii and slopes (the error of f32's arithmetic alone: rounding the
 * samples to float moves the model itself, up to 6.6e-4 of max|F| on the
 * quantized tips, docs/accuracy.md), mdr_eq at 300 radii to 14 nm: F, d and
 * dd/da within ARITH_TIP32 of their largest magnitude over the radii.
 * Measured 1.6e-7 at most (F 1.0e-7, 1.6e-7, 9.1e-8; dd/da 1.8e-7). Before
 * (the curvature moments formed as a difference, mdr_a_curv's spacing as
 * one): F 4.4e-5, 6.7e-4 and 4.7e-4 off, dd/da 5.4e-5, 2.5e-4, 1.2e-5.
 * Open, held from getting worse: mdr_stress on the two 1 000-sample tips
 * (25 radii, r/a = 0, 0.3, 0.6, 0.9; on the axis the noisy tip is
 * MDR_E_SINGULAR in both) within STRESS_TIP32 of max|sigma|, measured
 * 3.5e-5 (quantized) and 1.4e-3 (noisy); the cause is not measured yet
 * (likely f32's quadrature of the model's g', whose slope has a
 * 1/sqrt(x - r_k) part above every sample of such a tip, at abscissas
 * float rounds; docs/accuracy.md). */
#define ARITH_TIP32 1e-6
#define STRESS_TIP32 3e-3
#ifndef MDR_TARGET_TEST
static void table_measured_tips_f32(void **st)
{
    enum { M = 16384, NA = 300 };
    static double r[M], f[M], sl[M], rd[M], sd[M];
    static float rf[M], sf[M];
    static double got[3][NA], want[3][NA];
    const double R = 20e-9, L = 15e-9, q = 1e-10;
    uint64_t x = 0x9E3779B97F4A7C15ull;
    int tip;
    (void)st;
    for (tip = 0; tip < 3; tip++) {
        const int m = tip == 1 ? M : 1000;
        double mx[3] = {0, 0, 0}, worst[3] = {0, 0, 0};
        mdr_contact_f32 c32;
        mdr_contact_f64 c64;
        int i, k;
        for (i = 0; i < m; i++) {
            double u, v;
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            u = (double)(x >> 11) / 9007199254740992.0;
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            v = (double)(x >> 11) / 9007199254740992.0;
            /* random radii: steps of 0.2 to 1.8 of the mean, scaled to L below */
            r[i] = tip < 2 ? L * i / (m - 1) : (i == 0 ? 0.0 : r[i - 1] + (0.2 + 1.6 * u));
            if (tip == 2) {
                /* noise: a sum of two uniforms, 0.02 nm rms */
                f[i] = 0.02e-9 * sqrt(6.0) * (u + v - 1.0);
            }
        }
        for (i = 0; i < m; i++) {
            if (tip == 2) {
                r[i] *= L / r[m - 1];
            }
            {
                const double h = r[i] * r[i] / (R + sqrt(R * R - r[i] * r[i]));
                f[i] = tip < 2 ? q * floor(h / q + 0.5) : h + f[i];
            }
            if (i > 0 && f[i] < f[i - 1]) {
                f[i] = f[i - 1]; /* monotone */
            }
        }
        for (i = 0; i < m; i++) {
            f[i] -= tip == 2 ? f[0] : 0.0;
            rf[i] = (float)r[i];
            rd[i] = rf[i];
        }
        for (i = 0; i + 1 < m; i++) {
            sl[i] = (f[i + 1] - f[i]) / (r[i + 1] - r[i]);
            sf[i] = (float)sl[i];
            sd[i] = sf[i];
        }
        assert_int_equal(mdr_contact_init_table_f32(&c32, rf, sf, (uint16_t)m, 1e9f, 0.05f), MDR_OK);
        assert_int_equal(mdr_contact_init_table_f64(&c64, rd, sd, (uint16_t)m, 1e9, 0.05), MDR_OK);
        for (i = 0; i < NA; i++) {
            const float a = (float)(14e-9 * (i + 1) / NA);
            mdr_eqstate_f32 e32;
            mdr_eqstate_f64 e64;
            assert_int_equal(mdr_eq_f32(&c32, a, &e32), MDR_OK);
            assert_int_equal(mdr_eq_f64(&c64, (double)a, &e64), MDR_OK);
            got[0][i] = e32.F;
            got[1][i] = e32.d;
            got[2][i] = e32.dd_da;
            want[0][i] = e64.F;
            want[1][i] = e64.d;
            want[2][i] = e64.dd_da;
            for (k = 0; k < 3; k++) {
                mx[k] = fmax(mx[k], fabs(want[k][i]));
            }
        }
        for (i = 0; i < NA; i++) {
            for (k = 0; k < 3; k++) {
                worst[k] = fmax(worst[k], fabs(got[k][i] - want[k][i]) / mx[k]);
            }
        }
        print_message("measured tip %d (%d samples): f32 arithmetic F %.2g, d %.2g, dd/da %.2g of max\n", tip, m,
                      worst[0], worst[1], worst[2]);
        if (m == 1000) {
            /* stress at 25 radii, r/a = 0, 0.3, 0.6, 0.9: open (its f32
             * quadrature over the model's rough g'), held below
             * STRESS_TIP32 */
            double sm = 0, se = 0;
            for (i = 0; i < 25; i++) {
                const float a = (float)(14e-9 * (i + 1) / 25);
                for (k = 0; k < 4; k++) {
                    float sg = 0;
                    double sg64 = 0;
                    /* (on the axis the noisy tip's f'(0+) is not 0: both
                     * MDR_E_SINGULAR) */
                    const mdr_status s32 = mdr_stress_f32(&c32, a, a * (float)(0.3 * k), &sg);
                    assert_int_equal(mdr_stress_f64(&c64, (double)a, (double)(a * (float)(0.3 * k)), &sg64), s32);
                    assert_true(s32 == MDR_OK || (k == 0 && s32 == MDR_E_SINGULAR));
                    got[0][4 * i + k] = sg;
                    want[0][4 * i + k] = sg64;
                    sm = fmax(sm, fabs(sg64));
                }
            }
            for (i = 0; i < 100; i++) {
                se = fmax(se, fabs(got[0][i] - want[0][i]) / sm);
            }
            print_message("measured tip %d: f32 stress %.2g of max|sigma| (open)\n", tip, se);
            assert_true(se <= STRESS_TIP32);
        }
        for (k = 0; k < 3; k++) {
            assert_true(worst[k] <= ARITH_TIP32);
        }
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(powerlaw_below_one),
        cmocka_unit_test(powerlaw_near_half),
        cmocka_unit_test(issue_powerlaw_example),
        cmocka_unit_test(sphere_near_R),
        cmocka_unit_test(flattip_structure),
        cmocka_unit_test(flattip_narrow_window),
        cmocka_unit_test(starts_are_hints),
        cmocka_unit_test(default_start_is_stable),
        cmocka_unit_test(most_tensile_force),
        cmocka_unit_test(wavy_gripper_scale),
#ifndef MDR_TARGET_TEST
        cmocka_unit_test(wavy_jumps_near_start),
#endif
        cmocka_unit_test(table_exact_for_quadratics),
        cmocka_unit_test(table_order),
        cmocka_unit_test(table_worn_tip_kendall),
        cmocka_unit_test(table_cone_fold_first_interval),
        cmocka_unit_test(table_worn_tip_stress),
        cmocka_unit_test(table_cone_stress_axis),
        cmocka_unit_test(flattip_stress_at_rim),
#ifndef MDR_TARGET_TEST
        cmocka_unit_test(table_cone_no_false_kinks),
#endif
        cmocka_unit_test(table_critical_vs_profiles),
        cmocka_unit_test(table_f32_height_offset),
        cmocka_unit_test(table_quantized_heights_f32),
        cmocka_unit_test(table_subnormal_radius),
#ifndef MDR_TARGET_TEST
        cmocka_unit_test(table_measured_tips_f32),
#endif
        cmocka_unit_test(table_ends_at_pull_off),
        cmocka_unit_test(table_eq_and_stress),
        cmocka_unit_test(table_errors),
        cmocka_unit_test(pull_off_below_range),
        cmocka_unit_test(zeroed_contact),
    };
    return MDR_RUN_TESTS_NAME("critical", tests);
}

#endif /* applies */
