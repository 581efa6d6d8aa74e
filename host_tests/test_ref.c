/* SPDX-License-Identifier: MIT */
/*
 * test_ref.c: proves the GSL reference (ref/) against the closed forms of the
 * seed chapter before anything is compared against it.
 *
 * Tolerance: REL = 5e-12 relative on every quantity (depths of power laws
 * relative to the scale dl(a), since d_c = 0 exactly at n = 1.5): the
 * design asks for ~1e-10; measured 6.4e-13 (the curves' F, GSL's adaptive
 * quadrature), so a change that loosens the reference shows here first
 * (MDR_TOL_REPORT=1 prints the share of REL each check used).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "mdr_ref.h"
#include "mdr_types.h"
#include "test_util.h"

#define REL 5e-12

static void near(double got, double want, double scale, const char *what)
{
    double tol = REL * (scale > 0 ? scale : fabs(want));
    mdr_tol_note(what, fabs(got - want) / tol);
    if (!(fabs(got - want) <= tol)) {
        print_error("%s: got %.17g want %.17g (|diff| %.3g > %.3g)\n", what, got, want,
                    fabs(got - want), tol);
        fail();
    }
}

static double dl_of(const ref_scene *s, double a)
{
    return sqrt(2 * M_PI * a * s->w / s->E);
}

/* 4.30, 4.31 over a range of radii; 4.36 and 4.37 critical states */
static void paraboloid_jkr(void **st)
{
    ref_scene s = {MDR_PROFILE_PARABOLOID, {10e-6, 0, 0}, 1e6, 0.05};
    double R = 10e-6, E = 1e6, w = 0.05;
    ref_crit c;
    (void)st;
    for (double a = 1e-8; a < 3e-5; a *= 1.9) {
        ref_eq e;
        ref_eq_at(&s, a, &e);
        near(e.d, a * a / R - dl_of(&s, a), 0, "4.30 d(a)");
        near(e.F, 4 * E * a * a * a / (3 * R) - sqrt(8 * M_PI * a * a * a * E * w), 0, "4.31 F(a)");
    }
    ref_critical(&s, MDR_CONTROL_LOAD, 0, 8e-6, &c);
    near(c.a, cbrt(9 * M_PI * R * R * w / (8 * E)), 0, "4.36 a_c");
    near(c.F, -1.5 * M_PI * R * w, 0, "4.36 F_c");
    near(c.d, -cbrt(3 * M_PI * M_PI * R * w * w / (64 * E * E)), 0, "4.36 d_c");
    ref_critical(&s, MDR_CONTROL_GRIPS, 0, 8e-6, &c);
    near(c.a, cbrt(M_PI * R * R * w / (8 * E)), 0, "4.37 a_c");
    near(c.F, -5.0 / 6.0 * M_PI * R * w, 0, "4.37 F_c");
    near(c.d, -0.75 * cbrt(M_PI * M_PI * R * w * w / (E * E)), 0, "4.37 d_c");
}

/* 4.57 and 4.59 */
static void cone(void **st)
{
    double th = 0.3, E = 2.0, w = 0.7, t = tan(th);
    ref_scene s = {MDR_PROFILE_CONE, {th, 0, 0}, E, w};
    ref_crit c;
    (void)st;
    for (double a = 1e-3; a < 1e3; a *= 3.1) {
        ref_eq e;
        ref_eq_at(&s, a, &e);
        near(e.F, 0.5 * M_PI * E * t * a * a - sqrt(8 * M_PI * a * a * a * E * w), 0, "4.57 F(a)");
    }
    ref_critical(&s, MDR_CONTROL_LOAD, 0, 200.0, &c);
    near(c.a, 18 * w / (M_PI * t * t * E), 0, "4.59 a_c");
    near(c.F, -54 * w * w / (M_PI * t * t * t * E), 0, "4.59 F_c");
    near(c.d, 3 * w / (t * E), 0, "4.59 d_c");
}

/* 4.63 Kendall */
static void flat_punch(void **st)
{
    ref_scene s = {MDR_PROFILE_FLATPUNCH, {1, 0, 0}, 1, 1};
    ref_crit c;
    (void)st;
    ref_critical(&s, MDR_CONTROL_LOAD, 0, 1.0, &c);
    near(c.F, -sqrt(8 * M_PI), 0, "4.63 F");
    near(c.d, -sqrt(2 * M_PI), 0, "4.61 d");
    near(c.a, 1.0, 0, "a = a0");
}

/* 4.68, 4.70-4.72 (Yao & Gao) for several n, kappa_n from libm's tgamma */
static void power_law(void **st)
{
    static const double ns[] = {0.75, 1.5, 2.0, 3.0, 4.0};
    (void)st;
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++) {
        double n = ns[i], C = 1.3, E = 1.7, w = 0.4;
        double kap = sqrt(M_PI) * tgamma(n / 2 + 1) / tgamma((n + 1) / 2);
        ref_scene s = {MDR_PROFILE_POWERLAW, {C, n, 0}, E, w};
        double ac = pow(9 * M_PI * w / (2 * n * n * kap * kap * C * C * E), 1 / (2 * n - 1));
        double Fc = (1 - 2 * n) / (n + 1) *
                    pow(pow(3 / (2 * n * kap * C), 3) * pow(2 * M_PI * w, n + 1) * pow(E, n - 2),
                        1 / (2 * n - 1));
        double dc = (1 - 2 * n / 3) * pow(9 * M_PI * w / (2 * n * n * E) * pow(1 / (kap * C), 1 / n),
                                          n / (2 * n - 1));
        ref_crit c;
        ref_eq e;
        ref_eq_at(&s, 0.7 * ac, &e);
        near(e.F, 2 * E * n / (n + 1) * kap * C * pow(0.7 * ac, n + 1) -
                      sqrt(8 * M_PI * pow(0.7 * ac, 3) * E * w), 0, "4.68 F(a)");
        if (n > 0.5) {
            ref_critical(&s, MDR_CONTROL_LOAD, 0, 4 * ac, &c);
            near(c.a, ac, 0, "4.70 a_c");
            near(c.F, Fc, 0, "4.71 F_c");
            near(c.d, dc, dl_of(&s, ac), "4.72 d_c");
        }
    }
}

/* 4.77 exact sphere over a/R in [1e-3, 0.95]; CHECK_VALUES critical states */
static void sphere(void **st)
{
    ref_scene s = {MDR_PROFILE_SPHERE, {1, 0, 0}, 1, 0.05};
    ref_crit c;
    (void)st;
    for (double a = 1e-3; a < 0.95; a *= 1.7) {
        ref_eq e;
        ref_eq_at(&s, a, &e);
        /* 4.77 is itself cancellation-prone at small a: scale by E* R a */
        near(e.F, (1 + a * a) / 2 * log((1 + a) / (1 - a)) - a - sqrt(8 * M_PI * a * a * a * 0.05),
             fabs(e.F) + a * a * a, "4.77 F(a)");
    }
    ref_critical(&s, MDR_CONTROL_LOAD, 0, 0.9, &c);
    near(c.a, 0.494294810525, 1e2 * 0.494294810525, "sphere a_c (12 digits)");
    near(c.F, -0.209776616592, 1e2 * 0.209776616592, "sphere F_c (12 digits)");
}

/* CHECK_VALUES: power laws sharper than a cone and the soft sphere, from
 * starts below the critical radius (unstable: the reference jumps in to
 * the stable branch first, as mdr_critical does) */
static void critical_from_unstable_starts(void **st)
{
    static const struct {
        double n, aL, dL, FL, aG, dG, FG;
    } pw[] = {
        {0.6, 4118452.7333, 7630.41636019, -2618792426.23, 69.7463586732, -3.48898781902, -2007.58961561},
        {0.9, 12.4842955703, 5.90446695301, -46.5556488168, 0.800867934242, -0.996983265699, -2.64749849968},
    };
    (void)st;
    for (size_t i = 0; i < sizeof pw / sizeof pw[0]; i++) {
        ref_scene s = {MDR_PROFILE_POWERLAW, {1, pw[i].n, 0}, 1, 1};
        ref_crit c;
        assert_int_equal(ref_critical(&s, MDR_CONTROL_LOAD, 0, 0.5, &c), 0);
        near(c.a, pw[i].aL, 1e1 * pw[i].aL, "n < 1 load a (CHECK_VALUES, 12 digits)");
        near(c.F, pw[i].FL, -1e1 * pw[i].FL, "n < 1 load F");
        near(c.d, pw[i].dL, 1e1 * fabs(pw[i].dL), "n < 1 load d");
        assert_int_equal(ref_critical(&s, MDR_CONTROL_GRIPS, 0, 0.5, &c), 0);
        near(c.a, pw[i].aG, 1e1 * pw[i].aG, "n < 1 grips a");
        near(c.F, pw[i].FG, -1e1 * pw[i].FG, "n < 1 grips F");
        near(c.d, pw[i].dG, 1e1 * fabs(pw[i].dG), "n < 1 grips d");
    }
    {
        ref_scene s = {MDR_PROFILE_SPHERE, {1, 0, 0}, 1, 5};
        ref_crit c;
        assert_int_equal(ref_critical(&s, MDR_CONTROL_LOAD, 0, 0.9, &c), 0);
        near(c.a, 0.931509435763, 1e2 * 0.931509435763, "sphere w = 5 load a beyond 0.9 R");
        near(c.F, -7.89129674995, 1e2 * 7.89129674995, "sphere w = 5 load F");
        near(c.d, -3.85431932452, 1e2 * 3.85431932452, "sphere w = 5 load d");
        assert_int_equal(ref_critical(&s, MDR_CONTROL_GRIPS, 0, 0.9, &c), 0);
        near(c.a, 0.788756074688, 1e2 * 0.788756074688, "sphere w = 5 grips a");
        near(c.F, -6.90880201948, 1e2 * 6.90880201948, "sphere w = 5 grips F");
    }
}

/* 4.83 flattened tip */
static void flat_tip(void **st)
{
    double R = 2.0, b = 0.3, E = 1.5, w = 0.2;
    ref_scene s = {MDR_PROFILE_FLATTIP, {R, b, 0}, E, w};
    (void)st;
    for (double a = 0.31; a < 5; a *= 1.4) {
        ref_eq e;
        double sq = sqrt(a * a - b * b);
        ref_eq_at(&s, a, &e);
        near(e.d, a / R * sq - dl_of(&s, a), 0, "4.82 d(a)");
        near(e.F, 2 * E / (3 * R) * (2 * a * a + b * b) * sq - sqrt(8 * M_PI * a * a * a * E * w), 0,
             "4.83 F(a)");
    }
}

/* 4.49 and 4.51 with Struve functions from their integral representations */
static void wavy(void **st)
{
    double R = 1, lam = 0.05, h = 0.03 * lam, E = 1, w = 0.05 / (2 * M_PI);
    ref_scene s = {MDR_PROFILE_WAVY, {R, h, lam}, E, w};
    (void)st;
    for (double a = 0.01; a < 3.0; a *= 1.37) { /* a/lambda up to 60 */
        ref_eq e;
        double z = 2 * M_PI * a / lam, H0 = ref_struve_h0(z), H1 = ref_struve_h1(z);
        ref_eq_at(&s, a, &e);
        near(e.d, a * a / R + M_PI * M_PI * a * h / lam * H0 - dl_of(&s, a), a * a / R, "4.49 d(a)");
        near(e.F, 4.0 / 3.0 * E * a * a * a / R + E * M_PI * a * h * (z * H0 - H1) -
                      sqrt(8 * M_PI * a * a * a * E * w),
             4.0 / 3.0 * E * a * a * a / R, "4.51 F(a)");
    }
}

/* Struve H0 at known values (DLMF tables / Abramowitz & Stegun 12.1) */
static void struve_values(void **st)
{
    (void)st;
    /* small-argument series 4.48 summed in long double */
    for (double z = 0.1; z < 8; z += 0.7) {
        long double s0 = 0, s1 = 0, t = 1;
        for (int k = 0; k < 60; k++) {
            long double g1 = tgammal(k + 1.5L), g2 = tgammal(k + 1.5L), g3 = tgammal(k + 2.5L);
            long double x = powl(z / 2.0L, 2 * k + 1);
            s0 += t * x / (g1 * g2);
            s1 += t * x * (z / 2.0L) / (g1 * g3);
            t = -t;
        }
        near(ref_struve_h0(z), (double)s0, fabs((double)s0) + 1e-3, "H0 series 4.48");
        near(ref_struve_h1(z), (double)s1, fabs((double)s1) + 1e-3, "H1 series 4.48");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(paraboloid_jkr), cmocka_unit_test(cone),   cmocka_unit_test(flat_punch),
        cmocka_unit_test(power_law),      cmocka_unit_test(sphere), cmocka_unit_test(flat_tip),
        cmocka_unit_test(wavy),           cmocka_unit_test(struve_values),
        cmocka_unit_test(critical_from_unstable_starts),
    };
    int rc = cmocka_run_group_tests_name("ref_vs_closed_forms", tests, NULL, NULL);
    /* diagnostics, not a test (see ref/mdr_ref.c) */
    printf("ref: %d inner quadratures above 1e-10 estimated error\n", ref_failures());
    return rc;
}
