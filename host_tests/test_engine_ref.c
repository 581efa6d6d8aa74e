/*
 * test_engine_ref.c: convergence of the spring engine in the number of
 * springs N against the GSL reference (ref/, called at run time), f64.
 *
 * For each scene an approach (w_adv = w, fixed grips) to d_max and a
 * retraction to separation are driven through tables of N = 16 ... 4096
 * springs over the same x_max. Errors, relative to the largest |F| of the
 * cycle resp. to the reference pull-off force:
 *   e_F   largest |F_engine(d) - F_ref(d)| over 64 retraction states, with
 *         F_ref(d) = F_ref(a) + (d - d_ref(a)) (dF/da)/(dd/da) at the
 *         engine's radius a (first order in the tiny d error);
 *   e_po  |F_pull-off - F_ref_critical| (ref_critical, fixed grips, from the
 *         radius the approach reached).
 * The fitted order is the least-squares slope of -log e against log N over
 * the N whose error is above 1e-13 (rounding). Tolerances: the order of e_F
 * at least ORDER_MIN = 2.5 (the table interpolates g to O(h^3)), e_F and
 * e_po below 1e-8 at N = 4096.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "mdr.h"
#include "mdr_ref.h"

#define ORDER_MIN 2.5
#define TOL_4096 1e-8
#define NSIZES 9

static mdr_node_f64 nodes[4097];

typedef struct {
    const char *name;
    ref_scene s;
    double x_max, d_max, d_min;
} scene;

static double fit_order(const double *n, const double *e, int k)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int i, m = 0;
    for (i = 0; i < k; i++) {
        if (e[i] > 1e-13) {
            double x = log(n[i]), y = log(e[i]);
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            m++;
        }
    }
    if (m < 2) {
        return INFINITY;
    }
    return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

static void converge(const scene *sc, double *order_F, double *order_po)
{
    double Ns[NSIZES], eF[NSIZES], ePo[NSIZES];
    mdr_contact_f64 c;
    ref_crit rc;
    int k;
    assert_int_equal(mdr_contact_init_f64(&c, (uint8_t)sc->s.kind, sc->s.p, sc->s.E, sc->s.w), MDR_OK);
    printf("  %s: N, e_F (of max|F|), e_pull-off (relative)\n", sc->name);
    for (k = 0; k < NSIZES; k++) {
        uint16_t n = (uint16_t)(16u << k);
        mdr_table_f64 t;
        mdr_engine_f64 e;
        mdr_step_f64 o, po = {0};
        double Fmax = 0, worst = 0;
        long i, steps = 20000, every;
        assert_int_equal(mdr_table_init_profile_f64(&t, nodes, n, &c, sc->x_max), MDR_OK);
        assert_int_equal(mdr_engine_init_f64(&e, &t, sc->s.E, sc->s.w, sc->s.w, 0), MDR_OK);
        for (i = 1; i <= 2000; i++) {
            assert_int_equal(mdr_engine_step_d_f64(&e, sc->d_max * i / 2000.0, &o), MDR_OK);
        }
        Fmax = e.F;
        if (k == 0) {
            assert_int_equal(ref_critical(&sc->s, MDR_CONTROL_GRIPS, 0, e.a, &rc), 0);
            Fmax = fmax(Fmax, fabs(rc.F));
        }
        every = steps / 64;
        for (i = 1; i <= steps; i++) {
            double d = sc->d_max + (sc->d_min - sc->d_max) * (double)i / (double)steps;
            assert_int_equal(mdr_engine_step_d_f64(&e, d, &o), MDR_OK);
            if (o.event == MDR_EV_PULL_OFF) {
                po = o;
            }
            if (e.contact && i % every == 0) {
                ref_eq q;
                double Fr;
                assert_int_equal(ref_eq_at(&sc->s, e.a, &q), 0);
                Fr = q.F + (d - q.d) * q.dF_da / q.dd_da;
                worst = fmax(worst, fabs(o.F - Fr));
            }
        }
        assert_int_equal(e.cycles, 1);
        Ns[k] = n;
        eF[k] = worst / fmax(Fmax, fabs(rc.F));
        ePo[k] = fabs(po.F0 - rc.F) / fabs(rc.F);
        printf("    %5u  %.3e  %.3e\n", (unsigned)n, eF[k], ePo[k]);
    }
    *order_F = fit_order(Ns, eF, NSIZES);
    *order_po = fit_order(Ns, ePo, NSIZES);
    printf("    fitted order: e_F %.2f, e_pull-off %.2f\n", *order_F, *order_po);
    assert_true(eF[NSIZES - 1] < TOL_4096);
    assert_true(ePo[NSIZES - 1] < TOL_4096);
}

static void convergence_sphere(void **st)
{
    /* exact sphere (4.74), R = 1 um, w/(E* R) = 0.05: g has all orders */
    const scene sc = {"exact sphere", {MDR_PROFILE_SPHERE, {1e-6, 0, 0}, 1e6, 0.05}, 0.9e-6, 0.15e-6, -0.3e-6};
    double oF, oP;
    (void)st;
    converge(&sc, &oF, &oP);
    assert_true(oF >= ORDER_MIN);
}

static void convergence_wavy(void **st)
{
    /* seed Fig. 4.9 (h/lambda = 0.03, lambda/R = 0.05, 2 pi w/(E* R) = 0.05),
     * 10 wavelengths in the table: the coarse N do not resolve the waves */
    const scene sc = {"wavy (seed 4.54)",
                      {MDR_PROFILE_WAVY, {100e-6, 0.15e-6, 5e-6}, 1e6, 0.05 * 1e6 * 100e-6 / (2 * M_PI)},
                      50e-6, 2e-6, -9e-6};
    double oF, oP;
    (void)st;
    converge(&sc, &oF, &oP);
    assert_true(oF >= ORDER_MIN);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(convergence_sphere),
        cmocka_unit_test(convergence_wavy),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
