/* SPDX-License-Identifier: MIT */
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
 * the N whose error is above 1e-13 (rounding). Tolerances: the fitted orders
 * of the exact sphere (whose g is smooth: the asymptotic orders show from
 * N = 16) within 0.15 of the theory's, 3 for e_F (the quadratic springs
 * interpolate g to O(h^3)) and 2 for e_po (the grips fold's position follows
 * g', matched to O(h^2)); the wavy profile's (its coarse N do not resolve
 * the waves) at least 2.8 and 2.5 (measured 3.35, 2.89); e_F and e_po at
 * N = 4096 below the scene's bounds, ~4x the measured (sphere 1.4e-11,
 * 6.2e-9; wavy 2.0e-9, 8.8e-9).
 *
 * Jumps of the wavy profile (seed 4.54, N = 4096, fixed load and grips, from
 * the radius of mdr_default_start): the engine's number of jumps equals the
 * reference's own count (ref_critical, a finer scan with Brent's method) +
 * 1 (the pull-off); every jump keeps the control (to rounding) and lands
 * on a stable state of the reference's equilibrium curve, below the fold,
 * with its force and depth within TOL_LAND of the reference at the landing
 * radius (of the cycle's max|F| and max|d|); the pull-off force within
 * TOL_LAND of ref_critical's under load (F is stationary at a load fold),
 * TOL_PO_GRIPS = 5e-7 under grips (the force at a grips fold moves with the
 * fold's position, which follows g' to O(h^2): measured 1.5e-7).
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

#include "test_util.h"

#define NSIZES 9
#define TOL_LAND 2e-8
#define TOL_PO_GRIPS 5e-7

static mdr_node_f64 nodes[MDR_TABLE_NODES(4096)];

typedef struct {
    const char *name;
    ref_scene s;
    double x_max, d_max, d_min;
    double order_F_min, order_F_max, order_po_min, order_po_max; /* fitted orders */
    double tol_F, tol_po; /* e_F, e_po at N = 4096 */
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
        assert_int_equal(e.en.cycles, 1);
        Ns[k] = n;
        eF[k] = worst / fmax(Fmax, fabs(rc.F));
        ePo[k] = fabs(po.F0 - rc.F) / fabs(rc.F);
        printf("    %5u  %.3e  %.3e\n", (unsigned)n, eF[k], ePo[k]);
    }
    *order_F = fit_order(Ns, eF, NSIZES);
    *order_po = fit_order(Ns, ePo, NSIZES);
    printf("    fitted order: e_F %.2f, e_pull-off %.2f\n", *order_F, *order_po);
    err_le(eF[NSIZES - 1], sc->tol_F, "e_F at N = 4096 [scene]");
    err_le(ePo[NSIZES - 1], sc->tol_po, "e_po at N = 4096 [scene]");
    assert_true(*order_F >= sc->order_F_min && *order_F <= sc->order_F_max);
    assert_true(*order_po >= sc->order_po_min && *order_po <= sc->order_po_max);
}

static void convergence_sphere(void **st)
{
    /* exact sphere (4.74), R = 1 um, w/(E* R) = 0.05: g has all orders */
    const scene sc = {"exact sphere", {MDR_PROFILE_SPHERE, {1e-6, 0, 0}, 1e6, 0.05}, 0.9e-6, 0.15e-6, -0.3e-6,
                      2.85, 3.15, 1.85, 2.15, 5e-11, 3e-8};
    double oF, oP;
    (void)st;
    converge(&sc, &oF, &oP);
}

static void convergence_wavy(void **st)
{
    /* seed Fig. 4.9 (h/lambda = 0.03, lambda/R = 0.05, 2 pi w/(E* R) = 0.05),
     * 10 wavelengths in the table: the coarse N do not resolve the waves */
    const scene sc = {"wavy (seed 4.54)",
                      {MDR_PROFILE_WAVY, {100e-6, 0.15e-6, 5e-6}, 1e6, 0.05 * 1e6 * 100e-6 / (2 * M_PI)},
                      50e-6, 2e-6, -9e-6, 2.8, 4.0, 2.5, 4.0, 1e-8, 4e-8};
    double oF, oP;
    (void)st;
    converge(&sc, &oF, &oP);
}

/* Jumps of the seed's wavy profile against the reference (see the top). */
static void wavy_jumps_vs_ref(void **st)
{
    static const double hls[2] = {0.03, 0.005};
    int h, ctl;
    (void)st;
    for (h = 0; h < 2; h++) {
        const double R = 100e-6, E = 1e6, lam = 0.05 * R, w = 0.05 * E * R / (2 * M_PI);
        const ref_scene rs = {MDR_PROFILE_WAVY, {R, hls[h] * lam, lam}, E, w};
        mdr_contact_f64 c;
        mdr_table_f64 t;
        double a_start;
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_WAVY, rs.p, E, w), MDR_OK);
        assert_int_equal(mdr_default_start_f64(&c, &a_start), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f64(&t, nodes, 4096, &c, 1.05 * a_start), MDR_OK);
        for (ctl = (int)MDR_CONTROL_LOAD; ctl <= (int)MDR_CONTROL_GRIPS; ctl++) {
            mdr_engine_f64 e;
            mdr_step_f64 o;
            ref_crit rc;
            ref_eq q;
            long i, n = 40000, jumps = 0;
            double u1, umin, Fmax, dmax, pull_F = 0;
            assert_int_equal(ref_eq_at(&rs, a_start, &q), 0);
            u1 = ctl == MDR_CONTROL_LOAD ? q.F : q.d;
            umin = ctl == MDR_CONTROL_LOAD ? -2 * q.F : -q.d;
            Fmax = fabs(q.F);
            dmax = fabs(q.d);
            assert_int_equal(mdr_engine_init_f64(&e, &t, E, w, w, 0), MDR_OK);
            for (i = 1; i <= 4000; i++) {
                double u = u1 * (double)i / 4000.0;
                assert_int_equal(ctl == MDR_CONTROL_LOAD ? mdr_engine_step_F_f64(&e, u, &o)
                                                         : mdr_engine_step_d_f64(&e, u, &o), MDR_OK);
            }
            for (i = 1; i <= n; i++) {
                double u = u1 + (umin - u1) * (double)i / (double)n;
                assert_int_equal(ctl == MDR_CONTROL_LOAD ? mdr_engine_step_F_f64(&e, u, &o)
                                                         : mdr_engine_step_d_f64(&e, u, &o), MDR_OK);
                if (o.jumps == 0) {
                    continue;
                }
                jumps += o.jumps;
                assert_int_equal(o.jumps, 1); /* the path is fine enough for one jump a tick */
                assert_true(o.a1 < o.a0);
                if (o.event == MDR_EV_PULL_OFF) {
                    pull_F = o.F0;
                    continue;
                }
                if (ctl == MDR_CONTROL_LOAD) {
                    rel_le(o.F1, o.F0, Fmax, 1e-14, "a jump keeps the force [wavy]");
                } else {
                    rel_le(o.d1, o.d0, dmax, 1e-14, "a jump keeps the depth [wavy]");
                }
                /* the landing: a stable state of the reference's curve */
                assert_int_equal(ref_eq_at(&rs, o.a1, &q), 0);
                assert_true(ctl == MDR_CONTROL_LOAD ? q.dF_da > 0 : q.dd_da > 0);
                rel_le(o.F1, q.F, Fmax, TOL_LAND, "landing F against ref [wavy]");
                rel_le(o.d1, q.d, fmax(dmax, q.dl), TOL_LAND, "landing d against ref [wavy]");
            }
            assert_int_equal(e.contact, 0);
            assert_int_equal(ref_critical(&rs, ctl, 0, a_start, &rc), 0);
            printf("  wavy h/lambda = %.3f, %s: %ld jumps (ref: %d + the pull-off), pull-off F %.9e "
                   "(ref %.9e)\n", hls[h], ctl == MDR_CONTROL_LOAD ? "load" : "grips", jumps, rc.jumps,
                   pull_F, rc.F);
            assert_int_equal(jumps, rc.jumps + 1);
            rel_le(pull_F, rc.F, 0, ctl == MDR_CONTROL_LOAD ? TOL_LAND : TOL_PO_GRIPS,
                   ctl == MDR_CONTROL_LOAD ? "wavy pull-off F against ref_critical [load]"
                                           : "wavy pull-off F against ref_critical [grips]");
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(convergence_sphere),
        cmocka_unit_test(convergence_wavy),
        cmocka_unit_test(wavy_jumps_vs_ref),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
