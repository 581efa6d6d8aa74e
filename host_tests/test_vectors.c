/* SPDX-License-Identifier: MIT */
/*
 * test_vectors.c: lib/ (f32 and f64) against the committed reference vectors
 * of ref/ (ref/vectors/critical.csv and curves.csv, made by ref/mdr_refgen.c with GSL).
 *
 * Tolerances. f32: the goals of issue 2 (measured worst within 3x of each);
 * f64: within 10x of the measured worst (the committed vectors are fixed;
 * the reference itself is proved against the seed's closed forms to 1e-10
 * in test_ref.c, and agrees with the library far better than that):
 *   critical states, every control mode: |a - a_ref| <= tol a_ref,
 *     |F - F_ref| <= tol max(|F_ref|, Fs), |d - d_ref| <= tol max(|d_ref|,
 *     dl(a_ref)); jumps equal. f32 2e-6, f64 5e-14 (measured 1.6e-6, 5.8e-15)
 *     Fs = 2E* a dl(a) at a_ref, the size of the two terms of F = 2E*(a d - G)
 *     = 2E* a (hbar - dl) (4.26), as depths are measured against dl: the
 *     terms cancel to F = 2E* a dl (1/2 - n)/(n + 1) at a power law's
 *     fixed-load critical state, 1/7 of them for n = 0.75 (whose critical
 *     states these vectors held wrongly before issue 16: the search returned
 *     its start), where f32 measures 2.05e-6 of F, 2.9e-7 of Fs
 *   whole curves (200 radii from 1e-4 a_c to 10 a_c), per scene:
 *     max |F - F_ref| <= tol max|F_ref|, max |d - d_ref| <= tol max|d_ref|:
 *     f32 5e-6, f64 5e-14 (measured 9.5e-7, 4.7e-15 on the vectors
 *     regenerated for issue 16, whose power-law curves changed with their
 *     critical radii; the old vectors measured 6.4e-6, 2.4e-14; issue 2's
 *     goal for f32 is 1e-5)
 *   equivalent profile g, g' on the same radii: relative 2e-6 (f32), 2e-14
 *     (f64), 3e-12 for the wavy profile in f64 (the reference's Struve
 *     integrals: measured 3.5e-13; the others 5.2e-15) (wavy: relative to
 *     a^2/R + (pi^2 h/lambda) a min(1, sqrt(2/(pi z))), the size of its two
 *     terms, since they can cancel to 1/30 of that);
 *   derivatives dd/da and dF/da on the curves, relative to the size of their
 *     terms (|g'| + dl/(2a), resp. 2E*(a|g'| + 1.5 dl), with g' at least 2a/R
 *     for the wavy profile as above): as g, g';
 *     the stability flags equal the signs of the reference's dd/da and dF/da
 *     wherever those exceed 10x the tolerance of that comparison;
 *   K_I and G of every equilibrium state against what the inputs say they
 *     must be (4.17, 4.14): K_I = sqrt(2 E* w), G = w, relative 2e-6 (f32),
 *     8e-15 (f64; measured 6e-7, 8.9e-16);
 *   g' in f32 too, relative to the same scale as in f64.
 * Inputs are rounded to float for f32, exactly as a float caller would; the
 * f32 result is compared with the reference moved to those inputs through
 * the f64 library (critical states: at the reference's radius).
 * Prints the largest error per profile and arithmetic (README figures).
 *
 * F64_EVERY: the f64 checks run on every F64_EVERY-th scene (1 on the host;
 * make target-test builds with 16: on a Cortex-M4 double is soft-float, and
 * the f64 critical states of every scene would take minutes under QEMU).
 * The f32 checks always cover every row.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <cmocka.h>

#include "fl.h"
#include "mdr.h"
#include "applies.h"

#if !(MDR_CFG_F32 && MDR_CFG_F64 && MDR_CFG_ALL_PROFILES)
MDR_TEST_NOT_APPLICABLE("f32, f64 and every profile")
#else

#ifndef MDR_VECTORS_DIR
#define MDR_VECTORS_DIR "ref/vectors"
#endif

#ifndef F64_EVERY
#ifdef MDR_TARGET_TEST
#define F64_EVERY 16
#else
#define F64_EVERY 1
#endif
#endif

#define TOL_CRIT_F32 2e-6
#define TOL_CRIT_F64 5e-14
#define TOL_CURVE_F32 5e-6
#define TOL_CURVE_F64 5e-14
#define TOL_G_F32 2e-6
#define TOL_G_F64 2e-14
#define TOL_G_F64_WAVY 3e-12
#define TOL_KI_F32 2e-6
#define TOL_KI_F64 8e-15

static const char *kind_name[] = {"?", "paraboloid", "cone", "powerlaw", "flatpunch",
                                  "sphere", "flattip", "wavy"};

/* worst[kind][arith][quantity]: 0 crit, 1 curve F, 2 curve d, 3 g/g', 4 dd/da,
 * dF/da, 5 K_I, G */
static double worst[8][2][6];

static FILE *open_vec(const char *name)
{
    char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", MDR_VECTORS_DIR, name);
    f = fopen(path, "r");
    if (f == NULL) {
        print_error("cannot open %s\n", path);
        fail();
    }
    return f;
}

static int read_row(FILE *f, double *v, int n)
{
    char line[2048], *p, *end;
    int i;
    if (fgets(line, sizeof line, f) == NULL) {
        return 0;
    }
    p = line;
    for (i = 0; i < n; i++) {
        v[i] = strtod(p, &end);
        if (end == p) {
            return -1;
        }
        p = (*end == ',') ? end + 1 : end;
    }
    return 1;
}

static void note(int kind, int ar, int q, double e)
{
    if (e > worst[kind][ar][q]) {
        worst[kind][ar][q] = e;
    }
}

static void check(double err, double tol, const char *what, int scene, int ctl, int ar)
{
    if (!(err <= tol)) {
        print_error("scene %d control %d %s %s: relative error %.3g > %.3g\n", scene, ctl,
                    ar ? "f64" : "f32", what, err, tol);
        fail();
    }
}

/* a critical state (a, d, F) of arithmetic ar (0 f32, 1 f64) against the
 * reference (ra, rd, rF): a relative to ra, F to max(|rF|, Fscale), d to
 * dscale (absolute where the scale is 0); the largest noted, each checked */
static void check_crit(double a, double d, double F, double ra, double rd, double rF,
                       double dscale, double Fscale, int kind, int scene, int ctl, int ar)
{
    double tol = ar ? TOL_CRIT_F64 : TOL_CRIT_F32;
    double ea = ra > 0 ? fabs(a - ra) / ra : fabs(a);
    double Fs = fmax(fabs(rF), Fscale);
    double eF = Fs != 0 ? fabs(F - rF) / Fs : fabs(F);
    double ed = dscale > 0 ? fabs(d - rd) / dscale : fabs(d);
    note(kind, ar, 0, fmax(ea, fmax(eF, ed)));
    check(ea, tol, "critical a", scene, ctl, ar);
    check(eF, tol, "critical F", scene, ctl, ar);
    check(ed, tol, "critical d", scene, ctl, ar);
}

static void critical_vs_ref(void **state)
{
    double v[14];
    int rc, rows = 0;
    FILE *f = open_vec("critical.csv");
    char skip[512];
    (void)state;
    if (fgets(skip, sizeof skip, f) == NULL) {
        fail();
    }
    while ((rc = read_row(f, v, 14)) == 1) {
        int scene = (int)v[0], kind = (int)v[1], ctl = (int)v[7];
        double ra = v[10], rd = v[11], rF = v[12];
        double dl = sqrt(2 * M_PI * ra * v[6] / v[5]);
        double dscale = fabs(rd) > dl ? fabs(rd) : dl, Fscale = 2 * v[5] * ra * dl;
        mdr_contact_f32 c32;
        mdr_contact_f64 c64;
        mdr_critstate_f32 o32;
        mdr_critstate_f64 o64;
        float p32[3] = {(float)v[2], (float)v[3], (float)v[4]};
        double p64[3] = {v[2], v[3], v[4]};
        int f64 = scene % F64_EVERY == 0;
        rows++;
        assert_int_equal(mdr_contact_init_f32(&c32, (uint8_t)kind, p32, (float)v[5], (float)v[6]), MDR_OK);
        assert_int_equal(mdr_critical_f32(&c32, (uint8_t)ctl, (float)v[8], (float)v[9], &o32), MDR_OK);
        {
            check_crit(o32.a, o32.d, o32.F, ra, rd, rF, dscale, Fscale, kind, scene, ctl, 0);
            assert_int_equal(o32.jumps, (int)v[13]);
        }
        if (f64) {
            assert_int_equal(mdr_contact_init_f64(&c64, (uint8_t)kind, p64, v[5], v[6]), MDR_OK);
            assert_int_equal(mdr_critical_f64(&c64, (uint8_t)ctl, v[8], v[9], &o64), MDR_OK);
            check_crit(o64.a, o64.d, o64.F, ra, rd, rF, dscale, Fscale, kind, scene, ctl, 1);
            assert_int_equal(o64.jumps, (int)v[13]);
        }
    }
    fclose(f);
    assert_int_equal(rc, 0);
    assert_true(rows > 500);
}

struct curve_acc {
    int scene, kind, n, f64;
    double maxF, maxd, errF[2], errd[2];
};

static void flush_curve(struct curve_acc *c)
{
    int ar;
    if (c->n == 0) {
        return;
    }
    for (ar = 0; ar < 1 + c->f64; ar++) {
        double eF = c->errF[ar] / c->maxF, ed = c->errd[ar] / c->maxd;
        double tol = ar ? TOL_CURVE_F64 : TOL_CURVE_F32;
        note(c->kind, ar, 1, eF);
        note(c->kind, ar, 2, ed);
        check(eF, tol, "curve F", c->scene, 0, ar);
        check(ed, tol, "curve d", c->scene, 0, ar);
    }
}

/* One row of curves.csv: the equilibrium state at radius a (F, d, dd/da,
 * dF/da, stability, K_I, G) and the profile (g, g') in f32 and f64 against
 * the reference. c64r is the f64 contact at the float-rounded inputs: f32
 * receives float-rounded inputs (a and the profile's and material's
 * parameters), exactly as a float caller would, and is compared with the
 * reference moved to those inputs, ref + (f64 lib at the float inputs - f64
 * lib at the double inputs); the f64 library agrees with ref to ~1e-14, so
 * the shift is known far below the f32 tolerances. */
static void curve_row(const double *v, const mdr_contact_f32 *c32, const mdr_contact_f64 *c64,
                      const mdr_contact_f64 *c64r, struct curve_acc *acc)
{
    const int scene = (int)v[0], kind = (int)v[1];
    const double a = v[7], E = v[5], w = v[6];
    const double dl = sqrt(2 * M_PI * a * w / E), KI = sqrt(2 * E * w);
    /* scales of g' (wavy: at least that of its smooth part, 2a/R, since its
     * wave term can cancel it) and of the derivatives: the size of their terms */
    const double dgs = kind == MDR_PROFILE_WAVY ? fmax(fabs(v[13]), 2 * a / v[2]) : fabs(v[13]);
    const double sdd = dgs + dl / (2 * a), sdF = 2 * E * (a * dgs + 1.5 * dl);
    mdr_eqstate_f32 e32;
    mdr_eqstate_f64 e64, e64r;
    double ref[4]; /* d, F, dd/da, dF/da at the float inputs */
    int ar;
    assert_int_equal(mdr_eq_f32(c32, (float)a, &e32), MDR_OK);
    assert_int_equal(mdr_eq_f64(c64, a, &e64), MDR_OK);
    assert_int_equal(mdr_eq_f64(c64r, fl(a), &e64r), MDR_OK);
    ref[0] = v[8] + (e64r.d - e64.d);
    ref[1] = v[9] + (e64r.F - e64.F);
    ref[2] = v[10] + (e64r.dd_da - e64.dd_da);
    ref[3] = v[11] + (e64r.dF_da - e64.dF_da);
    acc->n++;
    acc->maxF = fmax(acc->maxF, fabs(v[9]));
    acc->maxd = fmax(acc->maxd, fabs(v[8]));
    acc->errF[0] = fmax(acc->errF[0], fabs(e32.F - ref[1]));
    acc->errd[0] = fmax(acc->errd[0], fabs(e32.d - ref[0]));
    if (acc->f64) {
        acc->errF[1] = fmax(acc->errF[1], fabs(e64.F - v[9]));
        acc->errd[1] = fmax(acc->errd[1], fabs(e64.d - v[8]));
    }
    for (ar = 0; ar < 1 + acc->f64; ar++) {
        double tol = ar ? (kind == MDR_PROFILE_WAVY ? TOL_G_F64_WAVY : TOL_G_F64) : TOL_G_F32;
        double tk = ar ? TOL_KI_F64 : TOL_KI_F32;
        double dd = ar ? e64.dd_da : e32.dd_da, dF = ar ? e64.dF_da : e32.dF_da;
        double rdd = ar ? v[10] : ref[2], rdF = ar ? v[11] : ref[3];
        bool sg = ar ? e64.stable_grips : e32.stable_grips, sl = ar ? e64.stable_load : e32.stable_load;
        double edd = fabs(dd - rdd) / sdd, edF = fabs(dF - rdF) / sdF;
        note(kind, ar, 4, fmax(edd, edF));
        check(edd, tol, "dd/da", scene, 0, ar);
        check(edF, tol, "dF/da", scene, 0, ar);
        if (fabs(rdd) > 10 * tol * sdd) {
            assert_int_equal(sg, rdd > 0);
        }
        if (fabs(rdF) > 10 * tol * sdF) {
            assert_int_equal(sl, rdF > 0);
        }
        if (w > 0) {
            double K = ar ? e64.K_I : e32.K_I, G = ar ? e64.G : e32.G;
            double wr = ar ? w : fl(w), Kr = ar ? KI : sqrt(2 * fl(E) * fl(w));
            double eK = fmax(fabs(K - Kr) / Kr, fabs(G - wr) / wr);
            note(kind, ar, 5, eK);
            check(eK, tk, "K_I, G = sqrt(2 E* w), w", scene, 0, ar);
        }
    }
    if (v[12] > 0) {
        float g32, dg32;
        double g64, dg64, gr, dgr, eg32, eg64;
        /* wavy: relative to the size of its two terms, a^2/R and
         * (pi^2 h/lambda) a |H0|, with |H0| <= min(1, sqrt(2/(pi z))):
         * near a small value of H0 the wave term is known to an absolute
         * error on its own scale, and g can be 30 times smaller than it */
        double zz = 2 * M_PI * a / v[4];
        double wave = M_PI * M_PI * v[3] / v[4] * a * fmin(1.0, sqrt(2 / (M_PI * zz)));
        double gs = kind == MDR_PROFILE_WAVY ? fmax(v[12], a * a / v[2] + wave) : v[12];
        assert_int_equal(mdr_profile_eval_f32(c32, (float)a, &g32, &dg32, NULL), MDR_OK);
        assert_int_equal(mdr_profile_eval_f64(c64, a, &g64, &dg64, NULL), MDR_OK);
        assert_int_equal(mdr_profile_eval_f64(c64r, fl(a), &gr, &dgr, NULL), MDR_OK);
        eg32 = fmax(fabs(g32 - (v[12] + (gr - g64))) / gs, fabs(dg32 - (v[13] + (dgr - dg64))) / dgs);
        eg64 = fmax(fabs(g64 - v[12]) / gs, fabs(dg64 - v[13]) / dgs);
        note(kind, 0, 3, eg32);
        check(eg32, TOL_G_F32, "g, g'", scene, 0, 0);
        if (acc->f64) {
            note(kind, 1, 3, eg64);
            check(eg64, kind == MDR_PROFILE_WAVY ? TOL_G_F64_WAVY : TOL_G_F64, "g, g'", scene, 0, 1);
        }
    }
}

static void curves_vs_ref(void **state)
{
    double v[14];
    int rc, rows = 0;
    struct curve_acc acc = {-1, 0, 0, 0, 0, 0, {0, 0}, {0, 0}};
    FILE *f = open_vec("curves.csv");
    char skip[512];
    mdr_contact_f32 c32;
    mdr_contact_f64 c64, c64r;
    (void)state;
    if (fgets(skip, sizeof skip, f) == NULL) {
        fail();
    }
    while ((rc = read_row(f, v, 14)) == 1) {
        int scene = (int)v[0];
        rows++;
        if (scene != acc.scene) {
            uint8_t kind = (uint8_t)v[1];
            float p32[3] = {(float)v[2], (float)v[3], (float)v[4]};
            double p64[3] = {v[2], v[3], v[4]}, pr[3] = {fl(v[2]), fl(v[3]), fl(v[4])};
            flush_curve(&acc);
            acc.scene = scene;
            acc.kind = kind;
            acc.n = 0;
            acc.f64 = scene % F64_EVERY == 0;
            acc.maxF = acc.maxd = acc.errF[0] = acc.errF[1] = acc.errd[0] = acc.errd[1] = 0;
            assert_int_equal(mdr_contact_init_f32(&c32, kind, p32, (float)v[5], (float)v[6]), MDR_OK);
            assert_int_equal(mdr_contact_init_f64(&c64, kind, p64, v[5], v[6]), MDR_OK);
            assert_int_equal(mdr_contact_init_f64(&c64r, kind, pr, fl(v[5]), fl(v[6])), MDR_OK);
        }
        curve_row(v, &c32, &c64, &c64r, &acc);
    }
    flush_curve(&acc);
    fclose(f);
    assert_int_equal(rc, 0);
    assert_true(rows > 10000);
}

static void report(void)
{
    int k, ar;
    printf("largest error vs ref/ (relative; curves relative to max|F|, max|d| of the curve)\n");
    printf("%-11s %-5s %10s %10s %10s %10s %10s %10s\n", "profile", "arith", "critical", "curve F",
           "curve d", "g, g'", "dd, dF", "K_I, G");
    for (k = 1; k < 8; k++) {
        for (ar = 0; ar < 2; ar++) {
            printf("%-11s %-5s %10.2e %10.2e %10.2e %10.2e %10.2e %10.2e\n", kind_name[k],
                   ar ? "f64" : "f32", worst[k][ar][0], worst[k][ar][1], worst[k][ar][2],
                   worst[k][ar][3], worst[k][ar][4], worst[k][ar][5]);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(critical_vs_ref),
        cmocka_unit_test(curves_vs_ref),
    };
    int rc = cmocka_run_group_tests_name("lib_vs_ref_vectors", tests, NULL, NULL);
    report(); /* the README's accuracy table */
    return rc;
}

#endif /* applies */
