/* SPDX-License-Identifier: MIT */
/*
 * test_engine.c: the real-time spring engine (lib/src/mdr_engine_t.c)
 * against closed forms, the foundation's equilibrium curves and critical
 * states, a naive O(N) spring sum, a generated const table, and every error
 * path. No reference data needed (the GSL comparisons and the convergence
 * in N are in test_engine_ref.c).
 *
 * Tolerances (relative unless said; MDR_TOL_REPORT=1 prints the share of
 * each that the run used):
 *   TOL_X64 = 5e-14, TOL_X32 = 2e-5: paraboloid results that the table holds
 *     exactly (its g is quadratic): pull-off under load/grips against JKR
 *     closed forms, loading branches against Hertz / JKR, in f64 / f32
 *     (measured 1.2e-15 and 2.1e-6, the f32 load pull-off depth
 *     d = g - c sqrt(a), 1/4 of its terms; 8.6e-15 and 3.1e-6 before the
 *     table builders took g and q from g', profile/mdr_table.inc); depths
 *     against the 12-digit CHECK_VALUES: 1e-11;
 *   TOL_GRIPS32(k) = 0.8 u k + 12 u (u = 2^-24 = TOL_U32, k = a_g/h the
 *     spring index of the grips pull-off radius a_g): the f32 JKR grips
 *     pull-off force on tables of 128 and 1024 springs to 3 ... 20 um
 *     (grips_pull_off_f32). At a grips fold F is not stationary
 *     (dF/da = -2E* dl), so it moves with the fold, which moves with the
 *     engine's g' there: with d'' = 3/R at the JKR fold, dF/F = 0.8 dg'/g'.
 *     The engine's g' in spring i is (g_{i+1} - g_i)/h plus the
 *     quadratic's term, and each stored g_i is rounded to half an ulp,
 *     |e_i| <= u |g_i|: |dg'|/g' <= u (|g_i| + |g_{i+1}|)/(h g') = u k
 *     (g = x^2/R, g/g' = x/2) + O(u), no builder can do better with f32
 *     nodes; hence 0.8 u k. The 12 u: the engine's own rounding at the
 *     fold, as under load: the sign test of dU/dt = 2t g' - c (~3 u of g',
 *     2.4 u of F), F = 2E*(a d - G) (a d and -G of one sign there: ~4 u),
 *     d at the fold (~2 u), the nodes beyond a_g (k + 2) and the
 *     quadratic's B (~2 u), rounded up. Measured 0.58 of it (1.4e-6 at
 *     128 springs, a 3.4 um table; 7.5e-6 at 1024; the engine's part
 *     alone, the f32 engine against the f64 one on the same f32 node
 *     values, 4e-7). It grows with N at a fixed extent: at 4096 springs
 *     the bound passes the 1e-5 goal (2.5e-5 measured) for tables shorter
 *     than ~8 a_g. Before the builders took Dg and q from g' the same
 *     sweep measured 8.9e-6 (3.6 of this tolerance) and 7.0e-5;
 *   TOL_LOAD32 = 8 u: the f32 JKR pull-off force under fixed load on the
 *     same tables. F is stationary at the fold, so its position does not
 *     enter: F0 = 2E* U with U = a D - G (one sign; D = g - c t cancels to
 *     1/4 of its terms: ~4 u), the node values there (~2 u), 2E* (u):
 *     measured 4.9 u (2.9e-7);
 *   machine pull-off against mdr_critical_f64: 3e-13 (the fold's bisection
 *     and mdr_critical's both at rounding level, plus conditioning 1/k_m;
 *     measured 4.4e-14); z = d + F/k_m the same before and after: 1e-15
 *     of z (d1 = z: the sum's own rounding is half an ulp of z, 1.1e-16 of
 *     it; this was relative to d0 before, 1/35 of z at k_m = 0.3, where an
 *     ulp of z is 7e-15 and the check passed only while the two roundings
 *     happened to agree);
 *   TOL_CURVE = 5e-10 of max|F| (f64, sphere, 4096 springs): retraction
 *     branch against mdr_eq_f64 at the engine's radius (the table's error,
 *     measured 1.0e-10);
 *   TOL_ORACLE64 = 2e-14, TOL_ORACLE32 = 1e-5 of max|F|: engine force
 *     against the naive O(N) sum over the springs at the same (a, d)
 *     (measured 3.6e-15, 1.1e-6); the pinned band from the table's
 *     interpolant recomputed here and dl from the inputs: TOL_BAND64 = 5e-15,
 *     TOL_BAND32 = 1e-6 of g + dl (measured 9e-16, 5e-7);
 *   wavy (seed 4.54, Fig. 4.9): pull-off within 1e-6 of mdr_critical_f64
 *     from the same radius (4096 springs over 20 wavelengths: the table's
 *     error, measured 1.5e-7), and the published figures to their last digit:
 *     +18.6 % and +2.8 % maximal separation force, critical grips depth
 *     1.101 and 1.017 times the smooth paraboloid's (seed: "about 19 %";
 *     CHECK_VALUES.md); coarse wavy tables: jump counts exactly those of
 *     20 000 ticks per segment, whatever the tick (no tolerance: a count);
 *   tabulated f: a paraboloid sampled at 40 uneven radii gives g to TOL_X64
 *     (f64) of g(x_max); a sampled sphere converges with fitted order >= 2.3;
 *     energy of a JKR cycle to 1e-6 of the closed form integral (step size
 *     1/20000 of the path; measured 1.3e-7); a non-adhesive cycle
 *     dissipates nothing: 2e-9 of the loading work (the trapezoid rule on
 *     different ticks up and down; measured
 *     3.4e-10);
 *   no fold the profile does not have (no_false_folds: the sphere, cone and
 *     power laws n = 2 to 8 on 2 to 1024 springs, f64 and f32): without
 *     adhesion exact event counts (one contact, one separation, no jump)
 *     and F >= -1e-12 (f32: -1e-6) of the cycle's max|F|; w_adv = 0 touches
 *     with event CONTACT and no jump under every control; the flattened tip
 *     one jump-in and one pull-off, no other jump;
 *   a dimpled tip's pull-off without adhesion inside spring 0
 *     (dimple_pull_off_in_spring_0; its g is quadratic, so the table is
 *     exact): a0, d0, F0 to TOL_X64 / TOL_X32 of the closed forms (measured
 *     8.7e-15, 1.3e-6); q31 a0 to 32 LSB of L (the fold's radius is
 *     ill-conditioned: U is flat there; measured 13.3), F0 to 2 LSB of F0
 *     (measured 0.82), d0 to 2 L/a0 + 2 LSB of D0 (under load
 *     d = (F/(2E*) + G)/a: G's LSB grows by L/a; measured 0.5 L/a0);
 *   the adhesion a float engine resolves (adhesion_resolved_float): an
 *     accepted init pulls off within TOL_ADH = 1/MDR_ENGINE_ADH_COND of
 *     the closed form (paraboloid) or of the f64 engine (cone); a refusal
 *     only where the closed form's bound exceeds TOL_ADH/4;
 *   a flat's rim inside spring 0 (rim_in_spring0): every init whose true
 *     pull-off lies in spring 0 refused; an accepted one within TOL_RIM0 =
 *     1e-2 of the closed forms' pull-off d (grips) and F (load), measured
 *     5.6e-3.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mdr.h"
#include "applies.h"
#include "closed_forms.h"

#if !(MDR_CFG_F32 && MDR_CFG_F64 && MDR_CFG_Q31 && MDR_CFG_ENGINE && MDR_CFG_ALL_PROFILES)
MDR_TEST_NOT_APPLICABLE("f32, f64, q31, the spring engine and every profile")
#else
#include "first_eq.h"
#include "naive_sum.h"
#include "bench_matrix.h"
#include "test_util.h"

/* On a target (QEMU, soft double on the M4F) the longest sweeps take
 * every TGT_STRIDE-th point (rim_in_spring0's adhesions,
 * first_equilibrium_coarse_tables' spring counts, the f64 moduli of
 * tiny_tables_float and adhesion_resolved_float, a decade apart on the
 * host; rim_in_spring0_sampled the diagonal of its tables; and
 * gap_table_order, dimple_pull_off_in_spring_0 their own, there): the same
 * code on the core, in the CI's minutes (the four took 127 s of the M4F's
 * 217 at every point; stop 72 took every 4th, not every 2nd, for the CI's
 * 15 minutes); the host runs every point. */
#ifdef MDR_TARGET_TEST
#define TGT_STRIDE 4
#else
#define TGT_STRIDE 1
#endif

#define TOL_X64 5e-14
#define TOL_X32 2e-5
#define TOL_MACHINE 3e-13
#define TOL_CURVE 5e-10
#define TOL_ORACLE64 2e-14
#define TOL_ORACLE32 1e-5
#define TOL_BAND64 5e-15
#define TOL_BAND32 1e-6
#define TOL_WAVY 1e-6
#define TOL_ENERGY 1e-6
/* (u = 2^-24, f32's unit roundoff; grips_pull_off_f32) */
#define TOL_U32 5.9604644775390625e-8
#define TOL_GRIPS32(k) (0.8 * TOL_U32 * (k) + 12.0 * TOL_U32)
#define TOL_LOAD32 (8.0 * TOL_U32)

/* generated by `mdr table` at build time (Makefile: gen_tip.c) */
extern const mdr_table_f32 gen_tip;

/* JKR scene of CHECK_VALUES: R = 10 um, E* = 1 MPa, w = 0.05 J/m^2 */
#define JR 10e-6
#define JE 1e6
#define JW 0.05
#define PI_ M_PI

static mdr_node_f64 nodes64[MDR_TABLE_NODES(MDR_SPRINGS_MAX)];
static mdr_node_f32 nodes32[MDR_TABLE_NODES(MDR_SPRINGS_MAX)];

static void table64(mdr_table_f64 *t, uint8_t kind, const double p[3], uint16_t n, double x_max)
{
    mdr_contact_f64 c;
    assert_int_equal(mdr_contact_init_f64(&c, kind, p, 1.0, 0.0), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f64(t, nodes64, n, &c, x_max), MDR_OK);
}

static void table32(mdr_table_f32 *t, uint8_t kind, const float p[3], uint16_t n, float x_max)
{
    mdr_contact_f32 c;
    assert_int_equal(mdr_contact_init_f32(&c, kind, p, 1.0f, 0.0f), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f32(t, nodes32, n, &c, x_max), MDR_OK);
}

typedef mdr_status (*step64_fn)(mdr_engine_f64 *, double, mdr_step_f64 *);
typedef mdr_status (*step32_fn)(mdr_engine_f32 *, float, mdr_step_f32 *);

static step64_fn step64_of(uint8_t control)
{
    return control == MDR_CONTROL_LOAD    ? mdr_engine_step_F_f64
           : control == MDR_CONTROL_GRIPS ? mdr_engine_step_d_f64
                                          : mdr_engine_step_z_f64;
}

static step32_fn step32_of(uint8_t control)
{
    return control == MDR_CONTROL_LOAD    ? mdr_engine_step_F_f32
           : control == MDR_CONTROL_GRIPS ? mdr_engine_step_d_f32
                                          : mdr_engine_step_z_f32;
}

/* Drive linearly from u0 to u1 in n steps (u0 excluded); return the last
 * pull-off step (event PULL_OFF) in *po if any. */
static int run64(mdr_engine_f64 *e, uint8_t control, double u0, double u1, long n,
                 mdr_step_f64 *po, mdr_step_f64 *last)
{
    step64_fn f = step64_of(control);
    int found = 0;
    long i;
    for (i = 1; i <= n; i++) {
        mdr_step_f64 o;
        assert_int_equal(f(e, u0 + (u1 - u0) * (double)i / (double)n, &o), MDR_OK);
        if (o.event == MDR_EV_PULL_OFF) {
            *po = o;
            found = 1;
        }
        if (last) {
            *last = o;
        }
    }
    return found;
}

static int run32(mdr_engine_f32 *e, uint8_t control, double u0, double u1, long n,
                 mdr_step_f32 *po)
{
    step32_fn f = step32_of(control);
    int found = 0;
    long i;
    for (i = 1; i <= n; i++) {
        mdr_step_f32 o;
        assert_int_equal(f(e, (float)(u0 + (u1 - u0) * (double)i / (double)n), &o), MDR_OK);
        if (o.event == MDR_EV_PULL_OFF) {
            *po = o;
            found = 1;
        }
    }
    return found;
}

/* ------------------------------------------------------ closed forms */

/* JKR pull-off under fixed load and fixed grips (CHECK_VALUES), both
 * arithmetics, approaching with w_adv = 0 and with w_adv = w. */
static void paraboloid_pull_off(void **st)
{
    const double Fl = -1.5 * PI_ * JW * JR, dl = -0.226148482694e-6;
    const double Fg = -5.0 / 6.0 * PI_ * JW * JR, dg = -0.470407800461e-6;
    const double pd[3] = {JR, 0, 0};
    const float pf[3] = {(float)JR, 0, 0};
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    int adv;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 256, 12e-6);
    table32(&t32, MDR_PROFILE_PARABOLOID, pf, 256, 12e-6f);
    for (adv = 0; adv < 2; adv++) {
        mdr_engine_f64 e;
        mdr_engine_f32 f;
        mdr_step_f64 po;
        mdr_step_f32 po32;
        double wa = adv ? JW : 0.0;
        /* load */
        assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, wa, 0), MDR_OK);
        run64(&e, MDR_CONTROL_LOAD, 0, 5e-6, 500, &po, NULL);
        assert_true(run64(&e, MDR_CONTROL_LOAD, 5e-6, -5e-6, 2000, &po, NULL));
        rel_le(po.F0, Fl, 0, TOL_X64, "load pull-off F (f64)");
        rel_le(po.d0, dl, 0, 1e-11, "load pull-off d (f64, 12-digit table)");
        assert_int_equal(e.contact, 0);
        assert_int_equal(e.en.cycles, 1);
        assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)JE, (float)JW, (float)wa, 0), MDR_OK);
        run32(&f, MDR_CONTROL_LOAD, 0, 5e-6, 500, &po32);
        assert_true(run32(&f, MDR_CONTROL_LOAD, 5e-6, -5e-6, 2000, &po32));
        rel_le(po32.F0, Fl, 0, TOL_X32, "load pull-off F (f32)");
        rel_le(po32.d0, dl, 0, TOL_X32, "load pull-off d (f32)");
        /* grips */
        assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, wa, 0), MDR_OK);
        run64(&e, MDR_CONTROL_GRIPS, 0, 1e-6, 500, &po, NULL);
        assert_true(run64(&e, MDR_CONTROL_GRIPS, 1e-6, -1e-6, 2000, &po, NULL));
        rel_le(po.F0, Fg, 0, TOL_X64, "grips pull-off F (f64)");
        rel_le(po.d0, dg, 0, 1e-11, "grips pull-off d (f64)");
        assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)JE, (float)JW, (float)wa, 0), MDR_OK);
        run32(&f, MDR_CONTROL_GRIPS, 0, 1e-6, 500, &po32);
        assert_true(run32(&f, MDR_CONTROL_GRIPS, 1e-6, -1e-6, 2000, &po32));
        rel_le(po32.F0, Fg, 0, TOL_X32, "grips pull-off F (f32)");
        rel_le(po32.d0, dg, 0, TOL_X32, "grips pull-off d (f32)");
    }
}

/* The f32 JKR pull-off on short and fine tables (R = 10 um, E* = 1 MPa,
 * w = 0.05 J/m^2): 40 extents from 3 to 20 um (the grips pull-off radius
 * a_g = 1.252 um lies 1/16 to 3/8 of the way out), 128, 1024 and 4096
 * springs. Each table is driven under fixed grips with w_adv = 0 (an
 * approach to 0.9 of the extent) and, where the jump-in's landing (3.155
 * um) lies inside it, with w_adv = w, and under fixed load (w_adv = 0),
 * then retracted through the pull-off: F0 against -5/6 pi w R
 * (TOL_GRIPS32(a_g/h)) and -3/2 pi w R (TOL_LOAD32). The table holds the
 * paraboloid's g but for rounding, so what is left is f32's: a grips
 * pull-off moves to first order with the engine's g' at its fold, which
 * comes from node values rounded to half an ulp (TOL_GRIPS32). Prints the
 * worst of each per N. */
static void grips_pull_off_f32(void **st)
{
    static const uint16_t ns[3] = {128, 1024, 4096};
    static mdr_node_f32 nd[MDR_TABLE_NODES(4096)];
    const double Fg = -5.0 / 6.0 * PI_ * JW * JR, Fl = -1.5 * PI_ * JW * JR;
    const double a_g = 1.25220844971e-6, a_in = cbrt(2.0 * PI_ * JW * JR * JR / JE);
    const float pf[3] = {(float)JR, 0, 0};
    mdr_contact_f32 c;
    int in, i, runs = 0;
    (void)st;
    assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, pf, 1.0f, 0.0f), MDR_OK);
    for (in = 0; in < 3; in++) {
        double eg = 0, egt = 0, el = 0, Lg = 0;
        for (i = 0; i < 40; i++) {
            const double L = 3e-6 + 17e-6 * i / 39.0, at = 0.9 * L, dt = at * at / JR;
            const double Ft = 4.0 / 3.0 * JE * sqrt(JR) * pow(dt, 1.5);
            mdr_table_f32 t;
            mdr_engine_f32 e;
            mdr_step_f32 po;
            double k;
            int adv;
            assert_int_equal(mdr_table_init_profile_f32(&t, nd, ns[in], &c, (float)L), MDR_OK);
            k = a_g / (double)t.h;
            for (adv = 0; adv < 2; adv++) {
                /* (reversible: the JKR depth of the same radius, or a
                 * touch, which lands at a_in) */
                const double du = adv ? fmax(dt - sqrt(2.0 * PI_ * JW / JE * at), 1e-9) : dt;
                if (adv && !(a_in < 0.99 * L)) {
                    continue;
                }
                assert_int_equal(mdr_engine_init_f32(&e, &t, (float)JE, (float)JW, adv ? (float)JW : 0.0f, 0),
                                 MDR_OK);
                run32(&e, MDR_CONTROL_GRIPS, 0, du, 2000, &po);
                assert_true(run32(&e, MDR_CONTROL_GRIPS, du, -1e-6, 2000, &po));
                rel_le(po.F0, Fg, 0, TOL_GRIPS32(k), "grips pull-off F (f32, TOL_GRIPS32(a_g/h))");
                if (fabs(po.F0 / Fg - 1) > eg) {
                    eg = fabs(po.F0 / Fg - 1);
                    Lg = L;
                }
                egt = fmax(egt, fabs(po.F0 / Fg - 1) / TOL_GRIPS32(k));
                runs++;
            }
            assert_int_equal(mdr_engine_init_f32(&e, &t, (float)JE, (float)JW, 0.0f, 0), MDR_OK);
            run32(&e, MDR_CONTROL_LOAD, 0, Ft, 2000, &po);
            assert_true(run32(&e, MDR_CONTROL_LOAD, Ft, -3e-6, 2000, &po));
            rel_le(po.F0, Fl, 0, TOL_LOAD32, "load pull-off F (f32, TOL_LOAD32)");
            el = fmax(el, fabs(po.F0 / Fl - 1));
        }
        printf("  f32 JKR pull-off, %4u springs, tables to 3 ... 20 um: grips %.1e (a %.2f um table; %.2f of "
               "TOL_GRIPS32), load %.1e\n",
               (unsigned)ns[in], eg, Lg * 1e6, egt, el);
    }
    assert_true(runs > 200); /* (the jump-in's landing is inside all but the shortest tables) */
}

/* Without adhesion a load back to F = 0 ends the contact at a = 0: the
 * receding branch meets the control exactly there (U(0) = 0). The scan
 * took node 0 for the end of a bracket and found a root a rounding above
 * it (f32: a = 1.8e-12 L), whose band's slope overflowed: MDR_E_OVERFLOW
 * on the last tick for about half the extents near 3.5 um (found by a
 * helper through mdr cycle). 21 extents, f32 and f64, 1024 springs: every
 * tick accepted, the last a separation to d = F = 0 (exact). */
static void load_to_zero_without_adhesion(void **st)
{
    static mdr_node_f64 n64[MDR_TABLE_NODES(1024)];
    static mdr_node_f32 n32[MDR_TABLE_NODES(1024)];
    const double pd[3] = {JR, 0, 0};
    const float pf[3] = {(float)JR, 0, 0};
    int k, i;
    (void)st;
    for (k = 0; k <= 20; k++) {
        const double L = 3.5e-6 * (1.0 + 0.002 * k);
        mdr_contact_f64 c64;
        mdr_contact_f32 c32;
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        mdr_engine_f64 e;
        mdr_engine_f32 f;
        mdr_step_f64 o;
        mdr_step_f32 o32;
        assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_PARABOLOID, pd, JE, 0.0), MDR_OK);
        assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pf, (float)JE, 0.0f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f64(&t64, n64, 1024, &c64, L), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t32, n32, 1024, &c32, (float)L), MDR_OK);
        assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, 0.0, 0.0, 0.0), MDR_OK);
        assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)JE, 0.0f, 0.0f, 0.0f), MDR_OK);
        for (i = 0; i <= 1000; i++) {
            const double u = i <= 500 ? 3e-6 * i / 500 : 3e-6 * (1000 - i) / 500;
            assert_int_equal(mdr_engine_step_F_f64(&e, u, &o), MDR_OK);
            assert_int_equal(mdr_engine_step_F_f32(&f, (float)u, &o32), MDR_OK);
        }
        assert_int_equal(o.event, MDR_EV_SEPARATION);
        assert_int_equal(o32.event, MDR_EV_SEPARATION);
        assert_true(o.d == 0.0 && o.F == 0.0 && o32.d == 0.0f && o32.F == 0.0f);
        assert_int_equal(e.contact, 0);
        assert_int_equal(f.contact, 0);
    }
}

/* The jump-in at first touch under fixed load (w_adv = w) whose landing
 * lies inside spring 0: 2 and 4 springs to 12 and 20 um, 1024 springs to
 * 5 mm (h = 4.9 um), against 4 springs to 12 um (landing beyond spring 0).
 * At t = 0 dU/dt is 0 under load whatever the adhesion, and the f32 and
 * f64 engines took the touch point for stable: the scan found the landing
 * as a plain root, "contact" with no jump (found by a helper attacking the
 * engines; the q31 engine had it right). The event must be a jump-in from
 * a = 0 landing at the JKR radius of F = 0, a = (9 pi w R^2 / (2 E*))^(1/3)
 * (seed 4.36 with F = 0), to TOL_X64 / TOL_X32 (spring 0 of the
 * paraboloid's table is exact). */
static void jump_in_inside_spring_0(void **st)
{
    static const struct {
        uint16_t n;
        double L;
    } c[] = {{2, 12e-6}, {4, 20e-6}, {1024, 5e-3}, {4, 12e-6}};
    const double a1 = cbrt(9.0 * PI_ * JW * JR * JR / (2.0 * JE));
    const double pd[3] = {JR, 0, 0};
    const float pf[3] = {(float)JR, 0, 0};
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    mdr_engine_f64 e;
    mdr_engine_f32 f;
    mdr_step_f64 o;
    mdr_step_f32 o32;
    int i;
    (void)st;
    for (i = 0; i < (int)(sizeof c / sizeof c[0]); i++) {
        table64(&t64, MDR_PROFILE_PARABOLOID, pd, c[i].n, c[i].L);
        table32(&t32, MDR_PROFILE_PARABOLOID, pf, c[i].n, (float)c[i].L);
        assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, JW, 0), MDR_OK);
        assert_int_equal(mdr_engine_step_F_f64(&e, 1e-7, &o), MDR_OK);
        assert_int_equal(o.event, MDR_EV_JUMP_IN);
        assert_int_equal(o.jumps, 1);
        rel_le(o.a0, 0.0, 0, 0.0, "jump-in from a = 0 (f64)");
        rel_le(o.a1, a1, 0, TOL_X64, "jump-in landing at F = 0 (f64)");
        assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)JE, (float)JW, (float)JW, 0), MDR_OK);
        assert_int_equal(mdr_engine_step_F_f32(&f, 1e-7f, &o32), MDR_OK);
        assert_int_equal(o32.event, MDR_EV_JUMP_IN);
        assert_int_equal(o32.jumps, 1);
        rel_le(o32.a1, a1, 0, TOL_X32, "jump-in landing at F = 0 (f32)");
    }
}

/* A table so coarse that the pull-off lies inside spring 0 (8 springs over
 * 50 um, h = 6.25 um; JKR grips pull-off at a = 1.25 um, load at 2.6 um,
 * the equilibrium at d = 0 at a = (2 pi w R^2/E*)^(1/3) = 3.15 um). Spring 0
 * of an adhesive branch holds the fold whatever its node values say; found
 * by fuzz_step: the edge landed on a = 0 in contact at d = 0, and peeled
 * "smoothly" with no pull-off below. The table is exact for the paraboloid,
 * so the closed forms hold to TOL_X64 / TOL_X32, and the q31 engine to 4 LSB
 * (of D0 for the depth residual of its state, of F0 for F: here 1 LSB of F0
 * is 7e-5 of the pull-off force, the table spanning 37 000 times the
 * cycle's force). */
static void pull_off_inside_spring_0(void **st)
{
    const double Fl = -1.5 * PI_ * JW * JR, Fg = -5.0 / 6.0 * PI_ * JW * JR;
    const double a_d0 = cbrt(2 * PI_ * JW * JR * JR / JE);
    const double pd[3] = {JR, 0, 0};
    const float pf[3] = {(float)JR, 0, 0};
    static mdr_node_q31 nq[MDR_TABLE_NODES(8)];
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    mdr_table_q31 tq;
    mdr_engine_f64 e;
    mdr_engine_f32 f;
    mdr_engine_q31 q;
    mdr_step_f64 o, po;
    mdr_step_f32 o32, po32;
    mdr_step_q31 oq;
    int i, found = 0;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 8, 50e-6);
    table32(&t32, MDR_PROFILE_PARABOLOID, pf, 8, 50e-6f);
    /* grips: deep, then d = 0 in one step, then down to pull-off */
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, JW, 0), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f64(&e, 5e-6, &o), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f64(&e, 0.0, &o), MDR_OK);
    assert_int_equal(e.contact, 1);
    rel_le(o.a, a_d0, 0, TOL_X64, "a at d = 0 (f64)");
    assert_true(run64(&e, MDR_CONTROL_GRIPS, 0, -1e-6, 1000, &po, NULL));
    rel_le(po.F0, Fg, 0, TOL_X64, "grips pull-off in spring 0 (f64)");
    assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)JE, (float)JW, (float)JW, 0), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f32(&f, 5e-6f, &o32), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f32(&f, 0.0f, &o32), MDR_OK);
    rel_le(o32.a, a_d0, 0, TOL_X32, "a at d = 0 (f32)");
    assert_true(run32(&f, MDR_CONTROL_GRIPS, 0, -1e-6, 1000, &po32));
    rel_le(po32.F0, Fg, 0, TOL_X32, "grips pull-off in spring 0 (f32)");
    /* load */
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, JW, 0), MDR_OK);
    run64(&e, MDR_CONTROL_LOAD, 0, 5e-6, 10, &po, NULL);
    assert_true(run64(&e, MDR_CONTROL_LOAD, 5e-6, -5e-6, 2000, &po, NULL));
    rel_le(po.F0, Fl, 0, TOL_X64, "load pull-off in spring 0 (f64)");
    assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)JE, (float)JW, (float)JW, 0), MDR_OK);
    run32(&f, MDR_CONTROL_LOAD, 0, 5e-6, 10, &po32);
    assert_true(run32(&f, MDR_CONTROL_LOAD, 5e-6, -5e-6, 2000, &po32));
    rel_le(po32.F0, Fl, 0, TOL_X32, "load pull-off in spring 0 (f32)");
    /* q31, grips */
    assert_int_equal(mdr_table_q31_from_f64(&tq, nq, &t64), MDR_OK);
    assert_int_equal(mdr_engine_init_q31_f64(&q, &tq, JE, JW, JW, 0), MDR_OK);
    for (i = 0; i <= 1000; i++) {
        double d = i == 0 ? 5e-6 : -1e-6 * (i - 1) / 999.0;
        assert_int_equal(mdr_engine_step_d_q31(&q, mdr_q31_in(&q, MDR_Q_D, (float)d), &oq), MDR_OK);
        if (i == 1) {
            /* the state's depth residual d(a) - 0 (a is set by d to
             * ~20 LSB of L per LSB of D0 here: da/dd ~ 2) */
            double a = mdr_q31_out(&q, MDR_Q_A, oq.a);
            rel_le(a * a / JR - sqrt(2 * PI_ * a * JW / JE), 0.0, 4 * (double)q.D0 / 536870912.0, 1,
                   "d(a) at d = 0 (q31, 4 LSB of D0)");
        }
        if (oq.event == MDR_EV_PULL_OFF) {
            rel_le(mdr_q31_out(&q, MDR_Q_F, oq.F0), Fg, 4 * (double)q.F0 / 536870912.0, 1,
                   "grips pull-off in spring 0 (q31, 4 LSB)");
            found = 1;
        }
    }
    assert_true(found);
}

/* A tip with a dimple, f(r) = A r^2 - B r (g(x) = 2A x^2 - (pi/2) B x,
 * seed 4.13 term by term), without adhesion: g falls from the touch point
 * to its least value at x_m = pi B/(8A) and rises beyond, so the receding
 * branch under load has a fold at x_m, where dF/da = 2E* a g'(a) = 0:
 * d0 = g(x_m) = -2A x_m^2 and F0 = 2E* (x_m g(x_m) - G(x_m))
 * = -(4/3) E* A x_m^3. With x_m at 0.55 .. 0.95 of spring 0 the table's
 * node values fall from node 0 to node 1 (no clamp: mdr_table.inc), and
 * spring 0 holds the fold. One load tick from deep contact to 1.5 F0
 * crosses it: a pull-off at the fold, not a slide to a = 0 (the scan's
 * test for a branch that turns before the touch point, mdr_e_touch_turns;
 * without it, event SEPARATION for x_m <= 0.65 h). 4, 8 and 64 springs,
 * f64, f32 and q31 (the q31 table from the f64 one). One grips tick to
 * 1.5 d0 pulls off at the same fold (d0 = g(x_m)). */
static void dimple_pull_off_in_spring_0(void **st)
{
    static const uint16_t ns[] = {4, 8, 64};
    static double r[801], f[801];
    static float rf[801], ff[801];
    static mdr_node_q31 nq[MDR_TABLE_NODES(64)];
    const double E = 1e6, A = 1e5, h = 1e-7, LSB = 1.0 / 536870912.0;
#ifdef MDR_TARGET_TEST
    const int ns_ = 201; /* samples (g is quadratic: the table is exact for any) */
    const int kstep = 2; /* (x_m 0.55, 0.65 .. 0.95 h: 7.3 of QEMU's 13.2 s at every 0.05) */
#else
    const int ns_ = 801;
    const int kstep = 1;
#endif
    int in, k, i, ctl;
    (void)st;
    for (in = 0; in < 3; in++) {
        for (k = 0; k <= 8; k += kstep) {
            const uint16_t n = ns[in];
            const double xm = (0.55 + 0.05 * k) * h, B = 8.0 * A * xm / PI_;
            const double gm = -2.0 * A * xm * xm, Fm = -4.0 / 3.0 * E * A * xm * xm * xm;
            const double dmax = 2.0 * A * pow(0.9 * n * h, 2) - 0.5 * PI_ * B * 0.9 * n * h;
            mdr_table_f64 t64;
            mdr_table_f32 t32;
            mdr_table_q31 tq;
            for (i = 0; i < ns_; i++) {
                r[i] = n * h * i / (ns_ - 1.0);
                f[i] = A * r[i] * r[i] - B * r[i];
                rf[i] = (float)r[i], ff[i] = (float)f[i];
            }
            assert_int_equal(mdr_table_init_gap_f64(&t64, nodes64, n, r, f, (uint16_t)ns_), MDR_OK);
            assert_int_equal(mdr_table_init_gap_f32(&t32, nodes32, n, rf, ff, (uint16_t)ns_), MDR_OK);
            assert_int_equal(mdr_table_q31_from_f64(&tq, nq, &t64), MDR_OK);
            assert_true(t64.node[1].g < 0.0); /* falls node to node: spring 0 keeps its turn */
            for (ctl = 0; ctl < 2; ctl++) {
                const double u = ctl ? 1.5 * Fm : 1.5 * gm;
                mdr_engine_f64 e;
                mdr_engine_f32 e32;
                mdr_engine_q31 q;
                mdr_step_f64 o;
                mdr_step_f32 o32;
                mdr_step_q31 oq;
                assert_int_equal(mdr_engine_init_f64(&e, &t64, E, 0.0, 0.0, 0), MDR_OK);
                assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)E, 0.0f, 0.0f, 0), MDR_OK);
                assert_int_equal(mdr_engine_init_q31_f64(&q, &tq, E, 0.0, 0.0, 0), MDR_OK);
                for (i = 1; i <= 50; i++) {
                    assert_int_equal(mdr_engine_step_d_f64(&e, dmax * i / 50, &o), MDR_OK);
                    assert_int_equal(mdr_engine_step_d_f32(&e32, (float)(dmax * i / 50), &o32), MDR_OK);
                    assert_int_equal(mdr_engine_step_d_q31(&q, mdr_q31_in(&q, MDR_Q_D, (float)(dmax * i / 50)), &oq),
                                     MDR_OK);
                }
                assert_true(e.contact && e32.contact && q.a > 0);
                if (ctl) {
                    assert_int_equal(mdr_engine_step_F_f64(&e, u, &o), MDR_OK);
                    assert_int_equal(mdr_engine_step_F_f32(&e32, (float)u, &o32), MDR_OK);
                    assert_int_equal(mdr_engine_step_F_q31(&q, mdr_q31_in(&q, MDR_Q_F, (float)u), &oq), MDR_OK);
                } else {
                    assert_int_equal(mdr_engine_step_d_f64(&e, u, &o), MDR_OK);
                    assert_int_equal(mdr_engine_step_d_f32(&e32, (float)u, &o32), MDR_OK);
                    assert_int_equal(mdr_engine_step_d_q31(&q, mdr_q31_in(&q, MDR_Q_D, (float)u), &oq), MDR_OK);
                }
                if (o.event != MDR_EV_PULL_OFF || o32.event != MDR_EV_PULL_OFF || oq.event != MDR_EV_PULL_OFF) {
                    printf("  N %u x_m %.2f h, %s: events f64 %d f32 %d q31 %d\n", n, xm / h, ctl ? "load" : "grips",
                           o.event, o32.event, oq.event);
                }
                assert_int_equal(o.event, MDR_EV_PULL_OFF);
                assert_int_equal(o32.event, MDR_EV_PULL_OFF);
                assert_int_equal(oq.event, MDR_EV_PULL_OFF);
                assert_int_equal(o.jumps + o32.jumps + oq.jumps, 3);
                rel_le(o.a0, xm, 0, TOL_X64, "dimple: a at the fold (f64)");
                rel_le(o.d0, gm, 0, TOL_X64, "dimple: d at the fold (f64)");
                rel_le(o.F0, Fm, 0, TOL_X64, "dimple: F at the fold (f64)");
                rel_le(o32.a0, xm, 0, TOL_X32, "dimple: a at the fold (f32)");
                rel_le(o32.d0, gm, 0, TOL_X32, "dimple: d at the fold (f32)");
                rel_le(o32.F0, Fm, 0, TOL_X32, "dimple: F at the fold (f32)");
                {
                    const double a0 = mdr_q31_out(&q, MDR_Q_A, oq.a0);
                    rel_le(a0, xm, q.L, 16.0 * LSB, /* 32 LSB of Q1.30 */ "dimple: a at the fold (q31, 32 LSB of L)");
                    rel_le(mdr_q31_out(&q, MDR_Q_F, oq.F0), Fm, q.F0, 2.0 * LSB, "dimple: F at the fold (q31, 2 LSB)");
                    rel_le(mdr_q31_out(&q, MDR_Q_D, oq.d0), gm, q.D0, (2.0 * n * h / xm + 2.0) * LSB,
                           "dimple: d at the fold (q31, 2 L/a + 2 LSB)");
                }
            }
        }
    }
}

/* Machine control: the pull-off equals the foundation's critical state for
 * the same stiffness (soft: near fixed load; stiff: near fixed grips). */
static void paraboloid_machine(void **st)
{
    const double pd[3] = {JR, 0, 0};
    const double kms[3] = {0.3, 3.0, 300.0};
    mdr_table_f64 t64;
    mdr_contact_f64 c;
    int i;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 512, 12e-6);
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, pd, JE, JW), MDR_OK);
    for (i = 0; i < 3; i++) {
        mdr_engine_f64 e;
        mdr_step_f64 po;
        mdr_critstate_f64 cr;
        double z1 = 1e-6 + 2e-6 / kms[i];
        assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, JW, kms[i]), MDR_OK);
        run64(&e, MDR_CONTROL_MACHINE, 0, z1, 1000, &po, NULL);
        assert_true(run64(&e, MDR_CONTROL_MACHINE, z1, -3 * z1, 12000, &po, NULL));
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_MACHINE, kms[i], e.tab->h * 400, &cr),
                         MDR_OK);
        rel_le(po.F0, cr.F, 0, TOL_MACHINE, "machine pull-off F");
        rel_le(po.d0, cr.d, 0, TOL_MACHINE, "machine pull-off d");
        rel_le(po.a0, cr.a, 0, TOL_MACHINE, "machine pull-off a");
        /* z = d + F/k_m on the reported states */
        rel_le(po.d0 + po.F0 / kms[i], po.d1 + po.F1 / kms[i], fabs(po.d1), 1e-15, "jump at constant z");
    }
}

/* Loading: w_adv = 0 follows Hertz (a = sqrt(R d), F = 4/3 E* sqrt(R) d^1.5)
 * with a plain contact event; w_adv = w jumps in at first touch to
 * a = (c R)^(2/3) and then follows the JKR curve. */
static void loading_branches(void **st)
{
    const double pd[3] = {JR, 0, 0};
    const double c = sqrt(2 * PI_ * JW / JE);
    mdr_table_f64 t64;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    int i;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 256, 12e-6);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 0.0, 0), MDR_OK);
    for (i = 1; i <= 400; i++) {
        double d = 1e-6 * i / 400.0;
        assert_int_equal(mdr_engine_step_d_f64(&e, d, &o), MDR_OK);
        assert_int_equal(o.event, i == 1 ? MDR_EV_CONTACT : MDR_EV_NONE);
        rel_le(o.a, sqrt(JR * d), 0, TOL_X64, "Hertz a");
        rel_le(o.F, 4.0 / 3.0 * JE * sqrt(JR) * pow(d, 1.5), 0, TOL_X64, "Hertz F");
    }
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, JW, 0), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f64(&e, -1e-7, &o), MDR_OK);
    assert_int_equal(o.event, MDR_EV_NONE);
    assert_int_equal(e.contact, 0);
    for (i = 0; i <= 400; i++) {
        double d = 1e-6 * i / 400.0, a;
        assert_int_equal(mdr_engine_step_d_f64(&e, d, &o), MDR_OK);
        if (i == 0) {
            assert_int_equal(o.event, MDR_EV_NONE); /* d = 0 is touch, not yet inside */
            continue;
        }
        if (i == 1) {
            assert_int_equal(o.event, MDR_EV_JUMP_IN);
            assert_int_equal(o.jumps, 1);
            assert_true(o.a0 == 0 && o.d0 == 0 && o.F0 == 0);
            rel_le(o.a1, pow(c * JR, 2.0 / 3.0), 0, TOL_X64, "jump-in radius");
            rel_le(o.d1, 0.0, 1e-9, TOL_X64, "jump-in at d = 0");
        } else {
            assert_int_equal(o.event, MDR_EV_NONE);
        }
        a = o.a;
        rel_le(o.d, a * a / JR - c * sqrt(a), a * a / JR + c * sqrt(a), TOL_X64, "JKR d(a)");
        rel_le(o.F, 4 * JE * a * a * a / (3 * JR) - 2 * sqrt(2 * PI_ * JW * JE) * pow(a, 1.5),
               4 * JE * a * a * a / (3 * JR), TOL_X64, "JKR F(a) (of the Hertz term)");
    }
}

/* The retraction branch of the exact sphere (non-polynomial g: the table
 * interpolates) lies on the foundation's equilibrium curve, whole curve. */
static void retraction_is_equilibrium(void **st)
{
    const double R = 1e-6, E = 1e6, w = 0.05;
    const double pd[3] = {R, 0, 0};
    mdr_table_f64 t64;
    mdr_engine_f64 e;
    mdr_contact_f64 c;
    mdr_step_f64 o;
    double Fmax = 0, dmax = 0.15e-6;
    long i, n = 4000, moved = 0;
    (void)st;
    table64(&t64, MDR_PROFILE_SPHERE, pd, 4096, 0.9 * R);
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_SPHERE, pd, E, w), MDR_OK);
    /* approach with w_adv = w: every retraction step then moves the edge */
    assert_int_equal(mdr_engine_init_f64(&e, &t64, E, w, w, 0), MDR_OK);
    run64(&e, MDR_CONTROL_GRIPS, 0, dmax, 1000, &o, NULL);
    Fmax = e.F;
    for (i = 1; i <= n; i++) {
        double a_before = e.a;
        assert_int_equal(mdr_engine_step_d_f64(&e, dmax - 0.4e-6 * (double)i / (double)n, &o),
                         MDR_OK);
        if (o.event == MDR_EV_NONE && e.contact && o.a != a_before) {
            mdr_eqstate_f64 q;
            assert_int_equal(mdr_eq_f64(&c, o.a, &q), MDR_OK);
            rel_le(o.d, q.d, dmax, TOL_CURVE, "retraction d(a)");
            rel_le(o.F, q.F, Fmax, TOL_CURVE, "retraction F(a)");
            moved++;
        }
    }
    assert_true(moved > 3000);
    assert_int_equal(e.contact, 0);
}

/* ------------------------------------------------------ naive oracle */

/* Whole approach-retract cycles of the sphere and the wavy profile under all
 * three controls: after every step the engine's force equals the naive
 * spring sum at its (a, d), and (a, d) is admissible: the edge is inside the
 * pinned band g - dl_w <= d <= g - dl_adv (to rounding). */
static void oracle_cycles(void **st)
{
    const double E = 1e6, w = 0.05, wa = 0.02;
    const double sph[3] = {1e-6, 0, 0};
    uint8_t ctl;
    (void)st;
    for (ctl = 1; ctl <= 3; ctl++) {
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        mdr_engine_f64 e;
        mdr_engine_f32 f;
        const float sphf[3] = {1e-6f, 0, 0};
        /* to about a = 0.3 R and back beyond the pull-off (F = -0.21 E* R^2
         * under load, d = -0.22 R under grips: CHECK_VALUES, w/(E* R) = 0.05) */
        double k_m = ctl == MDR_CONTROL_MACHINE ? 20.0 : 0.0;
        double umax = ctl == MDR_CONTROL_LOAD ? 1e-7 : 0.1e-6 + 1e-7 / 20.0;
        double umin = ctl == MDR_CONTROL_LOAD ? -0.4e-6 : -0.3e-6 - 0.4e-6 / 20.0;
        double Fmax = 4e-8; /* at least the peak force of each cycle */
        long i, n = 3000;
        table64(&t64, MDR_PROFILE_SPHERE, sph, 300, 0.7e-6);
        table32(&t32, MDR_PROFILE_SPHERE, sphf, 300, 0.7e-6f);
        assert_int_equal(mdr_engine_init_f64(&e, &t64, E, w, wa, k_m), MDR_OK);
        assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)E, (float)w, (float)wa, (float)k_m),
                         MDR_OK);
        for (i = 0; i <= 2 * n; i++) {
            double u = i <= n ? umax * (double)i / (double)n
                              : umax + (umin - umax) * (double)(i - n) / (double)n;
            mdr_step_f64 o;
            mdr_step_f32 o32;
            assert_int_equal(step64_of(ctl)(&e, u, &o), MDR_OK);
            assert_int_equal(step32_of(ctl)(&f, (float)u, &o32), MDR_OK);
            Fmax = fmax(Fmax, fabs(o.F));
            if (e.contact) {
                /* the band from the table's interpolant recomputed here and dl
                 * from the inputs (rounding: TOL_BAND64 of g + dl) */
                double g = table_g_f64(&t64, o.a), dw = sqrt(2 * PI_ * o.a * w / E);
                double da = sqrt(2 * PI_ * o.a * wa / E), tb = TOL_BAND64 * (g + dw);
                rel_le(o.F, naive_F_f64(&t64, E, o.a, o.d), Fmax, TOL_ORACLE64, "oracle F (f64)");
                rel_le(fmin(o.d - (g - dw), 0) + fmax(o.d - (g - da), 0), 0, tb, 1, "band (f64)");
            }
            if (f.contact) {
                double g = table_g_f32(&t32, o32.a), dw = sqrt(2 * PI_ * o32.a * (float)w / (float)E);
                double da = sqrt(2 * PI_ * o32.a * (float)wa / (float)E), tb = TOL_BAND32 * (g + dw);
                rel_le(o32.F, naive_F_f32(&t32, E, f.a, f.d), Fmax, TOL_ORACLE32, "oracle F (f32)");
                rel_le(fmin(o32.d - (g - dw), 0) + fmax(o32.d - (g - da), 0), 0, tb, 1, "band (f32)");
            }
        }
        assert_int_equal(e.en.cycles, 1);
        assert_int_equal(f.en.cycles, 1);
        assert_true(e.en.dissipated > 0);
    }
}

/* ------------------------------------------------------ energy */

/* Dissipated energy of one fixed-grips JKR cycle with w_adv = 0: the area
 * between Hertz loading and the JKR unloading curve down to the grips
 * pull-off, by the closed forms integrated with Simpson's rule in a. */
static void energy_jkr_cycle(void **st)
{
    const double pd[3] = {JR, 0, 0};
    const double c = sqrt(2 * PI_ * JW / JE);
    const double dmax = 0.5e-6, ac = 1.25220844971e-6;
    mdr_table_f64 t64;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    double a1, Wl, Wu = 0, want;
    long i, m = 20000;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 256, 12e-6);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 0.0, 0), MDR_OK);
    run64(&e, MDR_CONTROL_GRIPS, 0, dmax, 20000, &o, NULL);
    run64(&e, MDR_CONTROL_GRIPS, dmax, -dmax, 20000, &o, NULL);
    assert_int_equal(e.en.cycles, 1);
    /* loading: int_0^dmax 4/3 E sqrt(R) d^1.5 dd */
    Wl = 4.0 / 3.0 * JE * sqrt(JR) * pow(dmax, 2.5) / 2.5;
    /* pinned unloading from dmax at a = sqrt(R dmax) until d = D(a1) */
    a1 = sqrt(JR * dmax);
    {
        double dp = a1 * a1 / JR - c * sqrt(a1);
        double G1 = a1 * a1 * a1 / (3 * JR);
        /* F = 2E(a1 d - G1) linear in d from dmax down to dp */
        Wu += 2 * JE * (a1 * 0.5 * (dp * dp - dmax * dmax) - G1 * (dp - dmax));
        /* then along the JKR curve from a1 down to ac: int F dd = int F(a) d'(a) da */
        for (i = 0; i <= m; i++) {
            double a = a1 + (ac - a1) * (double)i / (double)m;
            double F = 4 * JE * a * a * a / (3 * JR) - 2 * sqrt(2 * PI_ * JW * JE) * pow(a, 1.5);
            double dd = 2 * a / JR - 0.5 * c / sqrt(a);
            double wgt = (i == 0 || i == m) ? 1 : (i % 2 ? 4 : 2);
            Wu += wgt * F * dd * (ac - a1) / (3.0 * m);
        }
    }
    want = Wl + Wu;
    rel_le(e.en.dissipated, want, 0, TOL_ENERGY, "dissipated energy of a JKR grips cycle");
    rel_le(e.en.last_cycle, want, 0, TOL_ENERGY, "last cycle energy");
    /* touching again is a re-contact; a second identical cycle dissipates the same */
    assert_int_equal(mdr_engine_step_d_f64(&e, 1e-12, &o), MDR_OK);
    assert_int_equal(o.event, MDR_EV_RECONTACT);
    run64(&e, MDR_CONTROL_GRIPS, 1e-12, dmax, 20000, &o, NULL);
    run64(&e, MDR_CONTROL_GRIPS, dmax, -dmax, 20000, &o, NULL);
    assert_int_equal(e.en.cycles, 2);
    rel_le(e.en.last_cycle, want, 0, TOL_ENERGY, "second cycle energy");
}

/* The work of a moving edge at any tick (mdr_machine.inc's MDR_M(stretch)).
 * One JKR cycle of the paraboloid (g = x^2/R, seed 4.28) with w_adv on
 * approach and w on retraction, under load and under grips, against its
 * closed form (closed_forms.h, jkr_cycle_work). The table of the
 * paraboloid holds g exactly (its
 * springs are quadratics in x), so that the engine's only errors are its
 * rounding, whatever the tick: S ticks per segment from 3 to 1 000, the
 * control to 1.5 times the pull-off's; three scenes, the third without
 * adhesion (w = w_adv = 0: elastic, a cycle down to -0.1 of its peak
 * dissipates nothing at any tick). Tolerances, of the cycle's gross
 * work (the sum of |int F dd| over its pieces): TOL_EN_TICK64 = 1e-14
 * (measured 1.9e-16), TOL_EN_TICK32 = 1e-6 (measured 1.05e-7: f32's
 * states each within u of their scale). And of the dissipation itself,
 * against the same cycle's losses where they arise (jkr_cycle_loss, free
 * of the stored energy's cancellation): TOL_EN_LOOP64 = 1e-12, TOL_EN_LOOP32
 * = 1e-4 (measured below). The second scene stores some 2e6 times what it
 * dissipates: summed as work (the cycle's work at its end, stop 64) f32
 * resolved its dissipation only to that share of its gross work, 5 %;
 * since stop 65 the engine sums the cycle's losses (mdr_energy). Before
 * stop 64, the trapezoid over each tick: a negative dissipation at 1 000
 * ticks under load in the second scene (-1.05e-12 J for 9.365e-12:
 * helper-31, stop 58), and in the first at S = 3 1.4e-2 of the gross work
 * off, half its dissipation (2.86e-12 J for 5.96e-12). */
#define TOL_EN_TICK64 1e-14
#define TOL_EN_TICK32 1e-6
#define TOL_EN_LOOP64 1e-12
#define TOL_EN_LOOP32 1e-4

static void energy_any_tick(void **st)
{
    const jkr_scene *sc = jkr_scenes;
    static const long ticks[4] = {3, 10, 100, 1000};
    const double pd[3] = {0, 0, 0};
    double worst64 = 0, worst32 = 0, loop64 = 0, loop32 = 0, work64 = 0;
    int i, j, c;
    (void)st;
    for (i = 0; i < 3; i++) {
        const double p64[3] = {sc[i].R, pd[1], pd[2]};
        const float p32[3] = {(float)sc[i].R, 0, 0};
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        table64(&t64, MDR_PROFILE_PARABOLOID, p64, 1024, 1.25 * sc[i].a_max);
        table32(&t32, MDR_PROFILE_PARABOLOID, p32, 1024, (float)(1.25 * sc[i].a_max));
        for (c = 0; c < 2; c++) {
            const uint8_t ctl = c == 0 ? MDR_CONTROL_LOAD : MDR_CONTROL_GRIPS;
            double gross, u_max, u_end;
            const double want = jkr_cycle(&sc[i], ctl, &gross, &u_max, &u_end);
            const double loss = jkr_cycle_loss(sc[i].E, sc[i].R, sc[i].w, sc[i].wa, ctl, sc[i].a_max);
            /* (the two closed forms agree to the rounding of the first's gross work) */
            assert_true(fabs(loss - want) <= 1e-14 * gross);
            for (j = 0; j < 4; j++) {
                mdr_engine_f64 e;
                mdr_engine_f32 f;
                mdr_step_f64 o;
                mdr_step_f32 o32;
                assert_int_equal(mdr_engine_init_f64(&e, &t64, sc[i].E, sc[i].w, sc[i].wa, 0), MDR_OK);
                assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)sc[i].E, (float)sc[i].w, (float)sc[i].wa, 0),
                                 MDR_OK);
                long k;
                double pk64;
                float pk32;
                run64(&e, ctl, 0, u_max, ticks[j], &o, NULL);
                (void)run32(&f, ctl, 0, u_max, ticks[j], &o32);
                pk64 = e.a; /* (each engine's own peak: a receded edge is on the retraction branch) */
                pk32 = f.a;
                for (k = 1; k <= ticks[j]; k++) {
                    /* the work so far (en.work, reset at the cycle's end)
                     * at each state on the retraction branch */
                    const double u = u_max + (u_end - u_max) * (double)k / (double)ticks[j];
                    double g2, um, uo;
                    assert_int_equal(step64_of(ctl)(&e, u, &o), MDR_OK);
                    assert_int_equal(step32_of(ctl)(&f, (float)u, &o32), MDR_OK);
                    if (e.contact && e.a < pk64) {
                        const double wt =
                            jkr_work_to(sc[i].E, sc[i].R, sc[i].w, sc[i].wa, ctl, sc[i].a_max, e.a, &g2, &um, &uo);
                        rel_le(e.en.work - e.en.work_c, wt, gross, TOL_EN_TICK64, "f64 work to a state");
                        work64 = fmax(work64, fabs(e.en.work - e.en.work_c - wt) / gross);
                    }
                    if (f.contact && f.a < pk32) {
                        rel_le(f.en.work - f.en.work_c,
                               jkr_work_to(sc[i].E, sc[i].R, sc[i].w, sc[i].wa, ctl, sc[i].a_max, f.a, &g2, &um, &uo),
                               gross, TOL_EN_TICK32, "f32 work to a state");
                    }
                }
                assert_int_equal(e.en.cycles, 1);
                assert_int_equal(f.en.cycles, 1);
                if (i == 1 && ctl == MDR_CONTROL_LOAD) {
                    assert_true(e.en.last_cycle > 0); /* (negative before) */
                }
                rel_le(e.en.last_cycle, want, gross, TOL_EN_TICK64, "f64 cycle work at any tick");
                rel_le(f.en.last_cycle, want, gross, TOL_EN_TICK32, "f32 cycle work at any tick");
                worst64 = fmax(worst64, fabs(e.en.last_cycle - want) / gross);
                worst32 = fmax(worst32, fabs(f.en.last_cycle - want) / gross);
                if (loss != 0) {
                    rel_le(e.en.last_cycle, loss, 0, TOL_EN_LOOP64, "f64 cycle's dissipation");
                    rel_le(f.en.last_cycle, loss, 0, TOL_EN_LOOP32, "f32 cycle's dissipation");
                    loop64 = fmax(loop64, fabs(e.en.last_cycle / loss - 1));
                    loop32 = fmax(loop32, fabs(f.en.last_cycle / loss - 1));
                } else {
                    assert_true(e.en.last_cycle == 0 && f.en.last_cycle == 0);
                }
            }
        }
    }
    printf("  cycle work at 3 to 1000 ticks: f64 %.2e, f32 %.2e of the gross work (tolerances %.0e, %.0e); "
           "of the dissipation itself f64 %.2e, f32 %.2e (tolerances %.0e, %.0e); the work to each state of "
           "the retraction branch f64 %.2e of the gross work\n",
           worst64, worst32, TOL_EN_TICK64, TOL_EN_TICK32, loop64, loop32, TOL_EN_LOOP64, TOL_EN_LOOP32, work64);
}

/* A stiff loop's dissipation (mdr_energy's loss): the paraboloid R = 1 um,
 * w = 0.05 J/m^2, w_adv = 0 (Hertz-like loading), under grips to
 * d = 1 nm (a_max = sqrt(R d), Hertz) and back past the pull-off (to
 * 1e-3 of the peak beyond: at E* = 1e35 the fold's depth, -1e-26 m, is
 * within the rounding of U at the table's first spring), on 1 024
 * springs to 1.25 a_max, at 5 and 1 000 ticks per segment, E* from 1e12 to
 * 1e35 Pa in f64 and to 1e25 Pa in f32 (f32 refuses from 3.2e29 on this
 * table: engine.md): a cycle that stores up to 1e19 times what it
 * dissipates. Against jkr_cycle_loss: TOL_EN_LOOP64 and TOL_EN_LOOP32 of
 * the dissipation (measured below). Summed as work (stop 64) the
 * dissipation came out negative in f32 from E* = 1e20 (-5e-14 J for
 * 1.57e-16 at S = 5) and in f64 at 1e35 (-3.8e-7 J). */
static void energy_stiff_loop(void **st)
{
    static const double E64[4] = {1e12, 1e16, 1e20, 1e35}, E32[4] = {1e12, 1e16, 1e20, 1e25};
    static const long ticks[2] = {5, 1000};
    const double R = 1e-6, w = 0.05, dmax = 1e-9, a_max = sqrt(R * dmax), pd[3] = {R, 0, 0};
    const float pf[3] = {(float)R, 0, 0};
    double worst64 = 0, worst32 = 0;
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    int i, j;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 1024, 1.25 * a_max);
    table32(&t32, MDR_PROFILE_PARABOLOID, pf, 1024, (float)(1.25 * a_max));
    for (i = 0; i < 4; i++) {
        for (j = 0; j < 2; j++) {
            double gross, u_max, u_off, want;
            mdr_engine_f64 e;
            mdr_engine_f32 f;
            mdr_step_f64 o;
            mdr_step_f32 o32;
            want = jkr_cycle_loss(E64[i], R, w, 0, MDR_CONTROL_GRIPS, a_max);
            (void)jkr_cycle_work(E64[i], R, w, 0, MDR_CONTROL_GRIPS, a_max, &gross, &u_max, &u_off);
            assert_int_equal(mdr_engine_init_f64(&e, &t64, E64[i], w, 0, 0), MDR_OK);
            run64(&e, MDR_CONTROL_GRIPS, 0, dmax, ticks[j], &o, NULL);
            run64(&e, MDR_CONTROL_GRIPS, dmax, 1.5 * u_off - 1e-3 * dmax, ticks[j], &o, NULL);
            assert_int_equal(e.en.cycles, 1);
            rel_le(e.en.last_cycle, want, 0, TOL_EN_LOOP64, "f64 stiff loop's dissipation");
            worst64 = fmax(worst64, fabs(e.en.last_cycle / want - 1));
            want = jkr_cycle_loss(E32[i], R, w, 0, MDR_CONTROL_GRIPS, a_max);
            (void)jkr_cycle_work(E32[i], R, w, 0, MDR_CONTROL_GRIPS, a_max, &gross, &u_max, &u_off);
            assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)E32[i], (float)w, 0, 0), MDR_OK);
            (void)run32(&f, MDR_CONTROL_GRIPS, 0, dmax, ticks[j], &o32);
            (void)run32(&f, MDR_CONTROL_GRIPS, dmax, 1.5 * u_off - 1e-3 * dmax, ticks[j], &o32);
            assert_int_equal(f.en.cycles, 1);
            rel_le(f.en.last_cycle, want, 0, TOL_EN_LOOP32, "f32 stiff loop's dissipation");
            worst32 = fmax(worst32, fabs(f.en.last_cycle / want - 1));
        }
    }
    printf("  stiff loops (E* to 1e35 Pa in f64, 1e25 in f32): dissipation within f64 %.2e, f32 %.2e "
           "(tolerances %.0e, %.0e)\n",
           worst64, worst32, TOL_EN_LOOP64, TOL_EN_LOOP32);
}

/* A pull-off's loss over many springs (mdr_machine.inc's MDR_M(jump_loss):
 * the elastic energy the jump releases, summed over every spring in
 * contact): a flat punch a0 = 100 nm, E* = 1 GPa, w = 0.05 J/m^2, w_adv = 0,
 * under load to 1 uN and back past Kendall's pull-off, 7 ticks a segment,
 * 16, 1 024 and MDR_SPRINGS_MAX springs: its cycle dissipates what the
 * pull-off releases, E* a0 d_po^2 = 2 pi w a0^2 (d_po = -sqrt(2 pi a0 w/E*)).
 * Within TOL_EN_LOOP64 (f64) and 1e-6 (f32: measured below) of it; the
 * plain sum over 16 384 springs was 8.6e-5 off in f32 (helper-54). */
static void energy_flat_punch_springs(void **st)
{
#ifdef MDR_TARGET_TEST /* (a table of MDR_SPRINGS_MAX springs in soft double: host only) */
    static const uint16_t ns[3] = {16, 256, 1024};
#else
    static const uint16_t ns[3] = {16, 1024, MDR_SPRINGS_MAX};
#endif
    const double a0 = 1e-7, E = 1e9, w = 0.05, pd[3] = {a0, 0, 0}, want = 2 * M_PI * w * a0 * a0;
    const float pf[3] = {(float)a0, 0, 0};
    double worst64 = 0, worst32 = 0;
    int i;
    (void)st;
    for (i = 0; i < 3; i++) {
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        mdr_engine_f64 e;
        mdr_engine_f32 f;
        mdr_step_f64 o;
        mdr_step_f32 o32;
        table64(&t64, MDR_PROFILE_FLATPUNCH, pd, ns[i], a0);
        table32(&t32, MDR_PROFILE_FLATPUNCH, pf, ns[i], (float)a0);
        assert_int_equal(mdr_engine_init_f64(&e, &t64, E, w, 0, 0), MDR_OK);
        assert_int_equal(mdr_engine_init_f32(&f, &t32, (float)E, (float)w, 0, 0), MDR_OK);
        run64(&e, MDR_CONTROL_LOAD, 0, 1e-6, 7, &o, NULL);
        run64(&e, MDR_CONTROL_LOAD, 1e-6, -1e-5, 7, &o, NULL);
        (void)run32(&f, MDR_CONTROL_LOAD, 0, 1e-6, 7, &o32);
        (void)run32(&f, MDR_CONTROL_LOAD, 1e-6, -1e-5, 7, &o32);
        assert_int_equal(e.en.cycles, 1);
        assert_int_equal(f.en.cycles, 1);
        rel_le(e.en.last_cycle, want, 0, TOL_EN_LOOP64, "f64 flat punch's dissipation");
        rel_le(f.en.last_cycle, want, 0, 1e-6, "f32 flat punch's dissipation");
        worst64 = fmax(worst64, fabs(e.en.last_cycle / want - 1));
        worst32 = fmax(worst32, fabs(f.en.last_cycle / want - 1));
    }
    printf("  flat punch, 16 to %d springs: dissipation within f64 %.2e, f32 %.2e of 2 pi w a0^2\n", (int)ns[2],
           worst64, worst32);
}

/* A profile with jumps inside the contact (the wavy one, seed 4.54, 64
 * springs over 16 wavelengths; its jumps tick-invariant:
 * wavy_jumps_tick_invariant): the state's path in (d, F) does not depend
 * on the tick (the jumps happen at their folds' controls, whatever the
 * tick), so neither does a cycle's work (to past every pull-off: -4 times
 * the peak, through the soft machine z = -2 mm), now that each tick's is
 * exact (a
 * tick that jumps and goes on from the landing measures its last stretch
 * from there). Every control, w_adv 0 and 0.39 J/m^2, 10 to 1 000 ticks per
 * segment against 20 000: within TOL_EN_INV = 1e-13 of the cycle's gross
 * work, the sum of |work| over its ticks (measured 1.4e-15); 20 jumps or more
 * inside the contact in the six cycles (29). Before, the trapezoid: 1.8e-3
 * of the gross work at 10 ticks. */
#define TOL_EN_INV 1e-13
static double wavy_cycle_work(const mdr_table_f64 *t, uint8_t ctl, double wa, long n, double *gross, int *jumps)
{
    const double umax = ctl == MDR_CONTROL_LOAD ? 2e-3 : 3e-6, umin = ctl == MDR_CONTROL_MACHINE ? -2e-3 : -4 * umax;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    assert_int_equal(mdr_engine_init_f64(&e, t, 1e6, 0.7957747154594767, wa, ctl == MDR_CONTROL_MACHINE ? 0.5 : 0),
                     MDR_OK);
    *gross = 0;
    *jumps = 0;
    for (long i = 1; i <= 2 * n; i++) {
        const double u = i <= n ? umax * (double)i / (double)n : umax + (umin - umax) * (double)(i - n) / (double)n;
        const double w0 = e.en.work;
        assert_int_equal(step64_of(ctl)(&e, u, &o), MDR_OK);
        *gross += fabs(e.en.cycles == 1 && o.event == MDR_EV_PULL_OFF ? e.en.last_cycle - w0 : e.en.work - w0);
        *jumps += o.event == MDR_EV_JUMP;
    }
    assert_int_equal(e.en.cycles, 1);
    return e.en.last_cycle;
}

static void energy_tick_invariant(void **st)
{
    const double pd[3] = {100e-6, 0.5e-6, 5e-6};
    mdr_table_f64 t;
    double worst = 0;
    int jumps_all = 0;
    (void)st;
    table64(&t, MDR_PROFILE_WAVY, pd, 64, 80e-6);
    for (int k = 0; k < 6; k++) {
        const uint8_t ctl = (uint8_t)(1 + k / 2);
        const double wa = 0.39 * (k % 2);
        double gross, g;
        int jumps, j;
        const double ref = wavy_cycle_work(&t, ctl, wa, 20000, &gross, &jumps);
        jumps_all += jumps;
        for (long n = 10; n <= 1000; n = n * 3 + 1) {
            const double w = wavy_cycle_work(&t, ctl, wa, n, &g, &j);
            rel_le(w, ref, gross, TOL_EN_INV, "wavy cycle work against 20 000 ticks");
            worst = fmax(worst, fabs(w - ref) / gross);
        }
    }
    printf("  wavy cycle work at 10 to 1000 ticks against 20 000: %.2e of the gross work (tolerance %.0e); %d jumps "
           "inside the contact in the six cycles\n", worst, TOL_EN_INV, jumps_all);
    assert_true(jumps_all >= 20);
}

/* Without adhesion the contact peels smoothly to a = 0 (event SEPARATION,
 * no pull-off) and a cycle dissipates nothing: Hertz is elastic. Tolerance:
 * 1e-6 of the loading work (trapezoid rule over 20000 ticks). */
static void non_adhesive_cycle(void **st)
{
    const double pd[3] = {JR, 0, 0};
    mdr_table_f64 t64;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    long i, seps = 0;
    double Wl = 4.0 / 3.0 * JE * sqrt(JR) * pow(0.5e-6, 2.5) / 2.5;
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 256, 12e-6);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, 0.0, 0.0, 0), MDR_OK);
    for (i = 1; i <= 40000; i++) {
        double d = i <= 20000 ? 0.5e-6 * i / 20000.0 : 0.5e-6 - 0.6e-6 * (i - 20000) / 20000.0;
        assert_int_equal(mdr_engine_step_d_f64(&e, d, &o), MDR_OK);
        assert_true(o.event != MDR_EV_PULL_OFF && o.event != MDR_EV_JUMP);
        seps += o.event == MDR_EV_SEPARATION;
    }
    assert_int_equal(seps, 1);
    assert_int_equal(e.en.cycles, 1);
    rel_le(e.en.dissipated, 0.0, Wl, 2e-9, "Hertz cycle dissipates nothing");
}

/* No fold the profile does not have (profile/mdr_table.inc's clamp of a
 * spring's quadratic, stop 48; a helper's attack): g rises monotonically
 * from g(0) = 0 for the sphere, the paraboloid, the cone and every power
 * law, so (physics, not the code) without adhesion a grips cycle touches
 * and separates without a jump or a tensile force, and Hertz-like loading
 * (w_adv = 0, w > 0) touches without a jump under every control. Before,
 * the quadratic holding a spring's integral dipped below its start for
 * g ~ x^n, n > 2 (and the sphere's spring 0): the retraction "pulled off"
 * at -1e-22 N and n >= 5 jumped in. Tables of 2, 8, 64 and 1024 springs,
 * f64 and f32; sphere to 0.5, 0.9 and 0.99 R, power laws n = 2 to 8, the
 * cone. Tolerance: F >= -1e-12 of the cycle's max|F| (f32: -1e-6), exact
 * event counts. And the flattened tip (w_adv = w, N = 1024): one jump-in,
 * one pull-off, no jump at the node above its rim (the quadratic there
 * had g' = 0 at its end: a turn of the table only, stop 46's extra jump). */
/* The same for sampled convex tips (helpers' attacks, stops 48 and 49):
 * f = r^n / (2 R^(n-1)), n = 3 to 8, a sphere to 0.99 R and a double cone
 * (slope 0.2, 1 beyond 0.4 of the range), 20, 60 and 200 samples to 0.9 R,
 * even and crowded to r = 0 (r ~ u^2), tables of 256 and 2048 springs by mdr_table_init_gap, f64 and f32. The samples' model
 * (profile/mdr_abel.inc) dips where its f' drops at a sample, most at a
 * steep start (the centred curvature makes f' < 0 near r = 0: g_1 < 0 at
 * 600 samples of r^5), and fine tables sampled the dips as folds: false
 * pull-offs and jumps without adhesion. Convex samples' node values now
 * never fall (profile/mdr_table.inc mdr_e_convex), and a w = 0 grips
 * cycle has one contact, one separation, no other event and no jump (f32
 * r^7, r^8 crowded to r = 0 on fine tables have a g that underflows to a
 * start flat to rounding, left at once at F = 0: there one jump to
 * separation whose F is 0 to rounding is allowed). On a target: 20
 * samples, 256 springs. */
static void no_false_folds_sampled(void **st)
{
    static double r[200], f[200];
    static float rf[200], ff[200];
#ifdef MDR_TARGET_TEST
    static const uint16_t ms[] = {20};
    static const int Ns[] = {256};
#else
    static const uint16_t ms[] = {20, 60, 200};
    static const int Ns[] = {256, 2048};
#endif
    const double E = 1e6, R = 1e-6;
    long cases = 0, flat = 0;
    int prof, im, sp, in, ar, i;
    (void)st;
    for (prof = 0; prof < 8; prof++) {
        for (im = 0; im < (int)(sizeof ms / sizeof ms[0]); im++) {
            for (sp = 0; sp < 2; sp++) {
                const uint16_t m = ms[im];
                for (i = 0; i < m; i++) {
                    const double u = (double)i / (m - 1), x = 0.9 * R * (sp ? u * u : u);
                    r[i] = x;
                    f[i] = prof < 6    ? pow(x, prof + 3) / (2.0 * pow(R, prof + 2))
                           : prof == 6 ? R - sqrt((R - x / 0.9 * 0.99) * (R + x / 0.9 * 0.99))
                                       : (x < 0.36 * R ? 0.2 * x : 0.072 * R + (x - 0.36 * R));
                    rf[i] = (float)r[i], ff[i] = (float)f[i];
                }
                for (in = 0; in < (int)(sizeof Ns / sizeof Ns[0]); in++) {
                    const int N = Ns[in];
                    for (ar = 0; ar < 2; ar++) {
                        mdr_table_f64 t64;
                        mdr_table_f32 t32;
                        mdr_engine_f64 e64;
                        mdr_engine_f32 e32;
                        int ev[16] = {0}, jumps = 0, falls = 0;
                        double dmax, Fmax = 0, Fjump = 0;
                        if (ar == 0) {
                            assert_int_equal(mdr_table_init_gap_f64(&t64, nodes64, (uint16_t)N, r, f, m), MDR_OK);
                            assert_int_equal(mdr_engine_init_f64(&e64, &t64, E, 0.0, 0.0, 0), MDR_OK);
                            for (i = 1; i <= N; i++) {
                                falls += nodes64[i].g < nodes64[i - 1].g;
                            }
                            dmax = nodes64[(int)(0.8 * N)].g;
                        } else {
                            assert_int_equal(mdr_table_init_gap_f32(&t32, nodes32, (uint16_t)N, rf, ff, m), MDR_OK);
                            assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)E, 0.0f, 0.0f, 0), MDR_OK);
                            for (i = 1; i <= N; i++) {
                                falls += nodes32[i].g < nodes32[i - 1].g;
                            }
                            dmax = nodes32[(int)(0.8 * N)].g;
                        }
                        for (i = 1; i <= 800; i++) {
                            const double d = i <= 400 ? dmax * i / 400.0 : dmax - 1.1 * dmax * (i - 400) / 400.0;
                            if (ar == 0) {
                                mdr_step_f64 o;
                                assert_int_equal(mdr_engine_step_d_f64(&e64, d, &o), MDR_OK);
                                ev[o.event & 15]++, jumps += o.jumps;
                                Fmax = fmax(Fmax, fabs(o.F));
                                Fjump = o.jumps ? fmax(Fjump, fmax(fabs(o.F0), fabs(o.F1))) : Fjump;
                            } else {
                                mdr_step_f32 o;
                                assert_int_equal(mdr_engine_step_d_f32(&e32, (float)d, &o), MDR_OK);
                                ev[o.event & 15]++, jumps += o.jumps;
                                Fmax = fmax(Fmax, fabs((double)o.F));
                                Fjump = o.jumps ? fmax(Fjump, fmax(fabs((double)o.F0), fabs((double)o.F1))) : Fjump;
                            }
                        }
                        /* (one jump to separation at F = 0 to rounding where a
                         * start flat to rounding leaves at once: f32 r^7, r^8
                         * crowded to 0, whose g underflows there) */
                        flat += ev[MDR_EV_PULL_OFF] == 1 && jumps == 1 && Fjump <= (ar ? 1e-6 : 1e-12) * Fmax;
                        if (falls || ev[MDR_EV_CONTACT] != 1 || ev[MDR_EV_SEPARATION] + ev[MDR_EV_PULL_OFF] != 1 ||
                            ev[MDR_EV_JUMP] || ev[MDR_EV_JUMP_IN] || (jumps && Fjump > (ar ? 1e-6 : 1e-12) * Fmax) ||
                            jumps > 1) {
                            printf("  sampled profile %d, %u samples%s, N %d %s: %d falls, contact %d separation %d "
                                   "pull-off %d jump %d jump-in %d, %d jumps, |F| at a jump %.3g of max|F|\n",
                                   prof, m, sp ? " crowded to 0" : "", N, ar ? "f32" : "f64", falls,
                                   ev[MDR_EV_CONTACT], ev[MDR_EV_SEPARATION], ev[MDR_EV_PULL_OFF], ev[MDR_EV_JUMP],
                                   ev[MDR_EV_JUMP_IN], jumps, Fjump / Fmax);
                        }
                        assert_int_equal(falls, 0);
                        assert_int_equal(ev[MDR_EV_CONTACT], 1);
                        assert_int_equal(ev[MDR_EV_SEPARATION] + ev[MDR_EV_PULL_OFF], 1);
                        assert_int_equal(ev[MDR_EV_JUMP] + ev[MDR_EV_JUMP_IN], 0);
                        assert_true(jumps <= 1 && Fjump <= (ar ? 1e-6 : 1e-12) * Fmax);
                        cases++;
                    }
                }
            }
        }
    }
    printf("  no false folds, sampled convex tips: %ld tables (r^3 .. r^8, sphere, double cone; %u to %u samples, "
           "even and crowded; N %d to %d; f64 and f32), %ld leaving a flat start at F = 0\n",
           cases, ms[0], ms[sizeof ms / sizeof ms[0] - 1], Ns[0], Ns[sizeof Ns / sizeof Ns[0] - 1], flat);
}

static void no_false_folds(void **st)
{
    static const uint16_t ns[] = {2, 8, 64, 1024};
    const double E = 1e6, R = 1e-5;
    long cases = 0;
    int prof, in, ar;
    (void)st;
    for (prof = 0; prof < 11; prof++) {
        /* 0..2 sphere to 0.5, 0.9, 0.99 R; 3 cone; 4..10 power law n = 2..8 (C R^(n-1) = 1/2) */
        const uint8_t kind = prof < 3 ? MDR_PROFILE_SPHERE : prof == 3 ? MDR_PROFILE_CONE : MDR_PROFILE_POWERLAW;
        const int np = prof - 2;
        const double p[3] = {prof < 3 ? R : prof == 3 ? 0.3 : 0.5 * pow(R, 1 - np), prof < 4 ? 0 : np, 0};
        const double xm = prof == 0 ? 0.5 * R : prof == 2 ? 0.99 * R : 0.9 * R;
        for (in = 0; in < 4; in++) {
            for (ar = 0; ar < 2; ar++) {
                mdr_contact_f64 c;
                double g8, dmax, Fmax = 0, Fmin = 0;
                int ctl, i, ev[16] = {0}, jumps = 0;
                mdr_table_f64 t64;
                mdr_table_f32 t32;
                mdr_engine_f64 e64;
                mdr_engine_f32 e32;
                const float p32[3] = {(float)p[0], (float)p[1], 0};
                table64(&t64, kind, p, ns[in], xm);
                table32(&t32, kind, p32, ns[in], (float)xm);
                assert_int_equal(mdr_contact_init_f64(&c, kind, p, E, 0.0), MDR_OK);
                assert_int_equal(mdr_profile_eval_f64(&c, 0.8 * xm, &g8, NULL, NULL), MDR_OK);
                dmax = g8;
                /* (a) w = 0: a grips cycle */
                assert_int_equal(mdr_engine_init_f64(&e64, &t64, E, 0.0, 0.0, 0), MDR_OK);
                assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)E, 0.0f, 0.0f, 0), MDR_OK);
                for (i = 1; i <= 800; i++) {
                    const double d = i <= 400 ? dmax * i / 400.0 : dmax - 1.1 * dmax * (i - 400) / 400.0;
                    double F;
                    int evi;
                    if (ar == 0) {
                        mdr_step_f64 o;
                        assert_int_equal(mdr_engine_step_d_f64(&e64, d, &o), MDR_OK);
                        F = o.F, evi = o.event, jumps += o.jumps;
                    } else {
                        mdr_step_f32 o;
                        assert_int_equal(mdr_engine_step_d_f32(&e32, (float)d, &o), MDR_OK);
                        F = o.F, evi = o.event, jumps += o.jumps;
                    }
                    Fmax = fmax(Fmax, fabs(F));
                    Fmin = fmin(Fmin, F);
                    ev[evi & 15]++;
                }
                if (ev[MDR_EV_CONTACT] != 1 || ev[MDR_EV_SEPARATION] != 1 || ev[MDR_EV_PULL_OFF] || ev[MDR_EV_JUMP] ||
                    ev[MDR_EV_JUMP_IN] || jumps || Fmin < -(ar ? 1e-6 : 1e-12) * Fmax) {
                    printf("  w = 0, profile %d N %u %s: contact %d separation %d pull-off %d jump %d jump-in %d, "
                           "%d jumps, least F %.3g of max|F|\n",
                           prof, ns[in], ar ? "f32" : "f64", ev[MDR_EV_CONTACT], ev[MDR_EV_SEPARATION],
                           ev[MDR_EV_PULL_OFF], ev[MDR_EV_JUMP], ev[MDR_EV_JUMP_IN], jumps, Fmin / Fmax);
                }
                assert_int_equal(ev[MDR_EV_CONTACT], 1);
                assert_int_equal(ev[MDR_EV_SEPARATION], 1);
                assert_int_equal(ev[MDR_EV_PULL_OFF] + ev[MDR_EV_JUMP] + ev[MDR_EV_JUMP_IN] + jumps, 0);
                assert_true(Fmin >= -(ar ? 1e-6 : 1e-12) * Fmax);
                /* (b) w > 0, w_adv = 0: the first touch under each control */
                for (ctl = (int)MDR_CONTROL_LOAD; ctl <= (int)MDR_CONTROL_MACHINE; ctl++) {
                    const double w = 0.05 * E * R / 100, km = ctl == MDR_CONTROL_MACHINE ? E * xm : 0;
                    const double u = ctl == MDR_CONTROL_LOAD ? 1e-6 * E * xm * dmax : 1e-3 * dmax;
                    int evt;
                    unsigned jt;
                    mdr_status ri = ar == 0 ? mdr_engine_init_f64(&e64, &t64, E, w, 0.0, km)
                                            : mdr_engine_init_f32(&e32, &t32, (float)E, (float)w, 0.0f, (float)km);
                    if (ri == MDR_E_PARAM && t64.rim0 == 2u && t32.rim0 == 2u) {
                        continue; /* a power law's pull-off in spring 0 (powerlaw_pull_off_spring0) */
                    }
                    assert_int_equal(ri, MDR_OK);
                    if (ar == 0) {
                        mdr_step_f64 o;
                        assert_int_equal(step64_of((uint8_t)ctl)(&e64, u, &o), MDR_OK);
                        evt = o.event, jt = o.jumps;
                    } else {
                        mdr_step_f32 o;
                        assert_int_equal(step32_of((uint8_t)ctl)(&e32, (float)u, &o), MDR_OK);
                        evt = o.event, jt = o.jumps;
                    }
                    if (evt != (int)MDR_EV_CONTACT || jt != 0) {
                        printf("  w_adv = 0, profile %d N %u %s control %d: event %d, %u jumps\n", prof, ns[in],
                               ar ? "f32" : "f64", ctl, evt, jt);
                    }
                    assert_int_equal(evt, MDR_EV_CONTACT);
                    assert_int_equal(jt, 0);
                }
                cases++;
            }
        }
    }
    {
        /* the helper's case (mdr cycle --profile powerlaw --C 1 --n N --E 1
         * --w 0.1 --control grips --path 0,0.1,-1 --steps-per-segment 1000):
         * n = 5 to 8, 1024 springs to the CLI's a_max, w_adv = 0; a slope of 0
         * at a node (the clamp without its margin) jumped in at n = 8 */
        static const double amax[4] = {0.96206293954610911, 0.99350039677455126, 1.0177869407367752,
                                       1.0372432683485249};
        int n;
        for (n = 5; n <= 8; n++) {
            const double p[3] = {1.0, n, 0};
            mdr_table_f64 t64;
            mdr_table_f32 t32;
            mdr_engine_f64 e64;
            mdr_engine_f32 e32;
            const float p32[3] = {1.0f, (float)n, 0};
            mdr_step_f64 o64;
            mdr_step_f32 o32;
            table64(&t64, MDR_PROFILE_POWERLAW, p, 1024, amax[n - 5]);
            table32(&t32, MDR_PROFILE_POWERLAW, p32, 1024, (float)amax[n - 5]);
            assert_int_equal(mdr_engine_init_f64(&e64, &t64, 1.0, 0.1, 0.0, 0), MDR_OK);
            assert_int_equal(mdr_engine_init_f32(&e32, &t32, 1.0f, 0.1f, 0.0f, 0), MDR_OK);
            assert_int_equal(mdr_engine_step_d_f64(&e64, 1e-4, &o64), MDR_OK);
            assert_int_equal(mdr_engine_step_d_f32(&e32, 1e-4f, &o32), MDR_OK);
            if (o64.event != MDR_EV_CONTACT || o64.jumps || o32.event != MDR_EV_CONTACT || o32.jumps) {
                printf("  power law n = %d, C = 1, E* = 1: f64 event %u (%u jumps), f32 event %u (%u jumps)\n", n,
                       o64.event, o64.jumps, o32.event, o32.jumps);
            }
            assert_int_equal(o64.event, MDR_EV_CONTACT);
            assert_int_equal(o64.jumps, 0);
            assert_int_equal(o32.event, MDR_EV_CONTACT);
            assert_int_equal(o32.jumps, 0);
        }
    }
    {
        /* the flattened tip of test_q31's scene (R 1 um, flat to 0.2 um, E* 1e6, w = w_adv = 0.01) */
        const double pf[3] = {1e-6, 0.2e-6, 0};
        mdr_table_f64 t64;
        int ctl;
        table64(&t64, MDR_PROFILE_FLATTIP, pf, 1024, 0.9e-6);
        for (ctl = (int)MDR_CONTROL_GRIPS; ctl <= (int)MDR_CONTROL_MACHINE; ctl++) {
            mdr_engine_f64 e;
            mdr_step_f64 o;
            int i, njump = 0, nin = 0, npo = 0;
            const double top = ctl == MDR_CONTROL_GRIPS ? 0.3e-6 : 0.3e-6 + 0.3e-6, bot = -0.3e-6;
            assert_int_equal(mdr_engine_init_f64(&e, &t64, 1e6, 0.01, 0.01, ctl == MDR_CONTROL_MACHINE ? 0.6 : 0), MDR_OK);
            for (i = 1; i <= 4000; i++) {
                const double u = i <= 2000 ? top * i / 2000.0 : top + (bot - top) * (i - 2000) / 2000.0;
                assert_int_equal(step64_of((uint8_t)ctl)(&e, u, &o), MDR_OK);
                njump += o.event == MDR_EV_JUMP;
                nin += o.event == MDR_EV_JUMP_IN;
                npo += o.event == MDR_EV_PULL_OFF;
            }
            printf("  flattened tip, control %d: jump-in %d, pull-off %d, other jumps %d\n", ctl, nin, npo, njump);
            assert_int_equal(nin, 1);
            assert_int_equal(npo, 1);
            assert_int_equal(njump, 0);
        }
    }
    printf("  no false folds: %ld tables (11 profiles, N 2 to 1024, f64 and f32), w = 0 cycles and w_adv = 0 touches\n",
           cases);
}

/* ------------------------------------------------------ wavy (seed 4.54) */

static void wavy_case(double hl, int quiet, double *ratio_load, double *ratio_dgrips)
{
    /* h/lambda = hl, lambda/R = 0.05, 2 pi w/(E* R) = 0.05; R = 100 um */
    const double R = 100e-6, E = 1e6, lam = 0.05 * R, w = 0.05 * E * R / (2 * PI_);
    const double pd[3] = {R, hl * lam, lam};
    mdr_contact_f64 c;
    mdr_table_f64 t64;
    mdr_engine_f64 e;
    mdr_step_f64 o, po = {0};
    mdr_critstate_f64 cr;
    mdr_eqstate_f64 q;
    double a_start, x_max;
    int ctl;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_WAVY, pd, E, w), MDR_OK);
    assert_int_equal(mdr_default_start_f64(&c, &a_start), MDR_OK);
    x_max = 1.05 * a_start;
    table64(&t64, MDR_PROFILE_WAVY, pd, 4096, x_max);
    for (ctl = (int)MDR_CONTROL_LOAD; ctl <= (int)MDR_CONTROL_GRIPS; ctl++) {
        long i, n = 40000, jumps = 0;
        double u1, umin;
        assert_int_equal(mdr_eq_f64(&c, a_start, &q), MDR_OK);
        u1 = ctl == (int)MDR_CONTROL_LOAD ? q.F : q.d;
        umin = ctl == (int)MDR_CONTROL_LOAD ? -2 * q.F : -q.d;
        /* approach with w_adv = w: the contact ends on the equilibrium curve */
        assert_int_equal(mdr_engine_init_f64(&e, &t64, E, w, w, 0), MDR_OK);
        run64(&e, (uint8_t)ctl, 0, u1, 4000, &o, NULL);
        rel_le(e.a, a_start, 0, 1e-9, "approach radius");
        if (!quiet) {
            printf("  wavy h/lambda = %.3f, %s: jumps on retraction at a/R =", hl,
                   ctl == (int)MDR_CONTROL_LOAD ? "fixed load" : "fixed grips");
        }
        for (i = 1; i <= n; i++) {
            double u = u1 + (umin - u1) * (double)i / (double)n;
            assert_int_equal(step64_of((uint8_t)ctl)(&e, u, &o), MDR_OK);
            if (o.event == MDR_EV_JUMP || o.event == MDR_EV_PULL_OFF) {
                jumps += o.jumps;
                if (!quiet) {
                    printf(" %.4f%s", o.a0 / R, o.event == MDR_EV_PULL_OFF ? " (pull-off)" : "");
                }
            }
            if (o.event == MDR_EV_PULL_OFF) {
                po = o;
            }
        }
        if (!quiet) {
            printf("\n");
        }
        assert_int_equal(e.contact, 0);
        assert_int_equal(mdr_critical_f64(&c, (uint8_t)ctl, 0, a_start, &cr), MDR_OK);
        rel_le(po.F0, cr.F, 0, TOL_WAVY, "wavy pull-off F vs mdr_critical");
        rel_le(po.d0, cr.d, fabs(cr.d) + sqrt(2 * PI_ * w * cr.a / E), TOL_WAVY,
               "wavy pull-off d vs mdr_critical");
        assert_int_equal(jumps, (long)cr.jumps + 1); /* intermediate jumps + the pull-off */
        if (!quiet) {
            printf("    %ld jumps; pull-off F = %.6g N, d = %.6g m, a = %.6g m\n", jumps, po.F0,
                   po.d0, po.a0);
        }
        if (ctl == (int)MDR_CONTROL_LOAD) {
            *ratio_load = po.F0 / (-1.5 * PI_ * w * R);
        } else {
            /* smooth paraboloid grips pull-off depth: -3 (1/6)^(2/3) (pi^2 w^2 R/K^2)^(1/3) */
            double K = 4 * E / 3;
            double dsm = -3 * pow(1.0 / 6.0, 2.0 / 3.0) * cbrt(PI_ * PI_ * w * w * R / (K * K));
            *ratio_dgrips = po.d0 / dsm;
        }
    }
}

static void wavy_seed_fig_4_9(void **st)
{
    double rl, rg;
    (void)st;
    wavy_case(0.03, 0, &rl, &rg);
    printf("    h/lambda = 0.03: max separation force / smooth = %.4f, critical depth (grips) / "
           "smooth = %.4f\n", rl, rg);
    assert_true(fabs(rl - 1.186) < 0.0005); /* +18.6 % (seed: about 19 %) */
    assert_true(fabs(rg - 1.101) < 0.0005); /* the critical depth 10.1 % deeper */
    wavy_case(0.005, 0, &rl, &rg);
    printf("    h/lambda = 0.005: max separation force / smooth = %.4f, critical depth / smooth = "
           "%.4f\n", rl, rg);
    assert_true(fabs(rl - 1.028) < 0.0005); /* +2.8 % */
    assert_true(fabs(rg - 1.017) < 0.0005);
}

/* ------------------------------------------------------ flat punch wall */

/* Jumps do not depend on the tick: a quasi-static path's folds are the
 * path's, not its sampling's. Wavy tips (R = 100 um, lambda = 5 um,
 * h = 0.25 ... 1.5 um) on tables of 16 to 64 springs over 16 wavelengths,
 * where a fold and the next rise of the branch lie one or two springs
 * apart; every control, w = 0.796 J/m^2, w_adv = 0, 0.39, 0.78 J/m^2 (up to
 * 0.98 w); approach to 2 mN or
 * 3 um, retract to the opposite: the number of jumps of the cycle at n ticks
 * per segment equals its number at 20 000, for every n of a geometric sweep
 * from 10 to 2 294, in all 180 cases. Until stop 46 it held only from a
 * tick count listed per case (one spring per wavelength: from up to 301;
 * six cases never settled), because a tick that crossed two folds inside
 * one spring saw one: the scan now tests each spring's ends for a turn of
 * the branch (mdr_edge_table.inc, mdr_e_turn). */
#ifndef MDR_TARGET_TEST
static int wavy_cycle_jumps(const mdr_table_f64 *t, uint8_t ctl, double wa, long n)
{
    const double umax = ctl == MDR_CONTROL_LOAD ? 2e-3 : 3e-6;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    int jumps = 0;
    assert_int_equal(mdr_engine_init_f64(&e, t, 1e6, 0.7957747154594767, wa, ctl == MDR_CONTROL_MACHINE ? 0.5 : 0),
                     MDR_OK);
    for (long i = 1; i <= 2 * n; i++) {
        const double u = i <= n ? umax * (double)i / (double)n : umax - 2 * umax * (double)(i - n) / (double)n;
        const bool sep = e.contact == 0;
        assert_int_equal(step64_of(ctl)(&e, u, &o), MDR_OK);
        /* a tick that begins separated and ends in contact reports its touch,
         * whatever jumps follow in it (a touch and two jumps were reported
         * MDR_EV_JUMP, the touch lost: helper-57) */
        if (sep && o.a > 0) {
            assert_true(o.event == MDR_EV_CONTACT || o.event == MDR_EV_RECONTACT || o.event == MDR_EV_JUMP_IN);
        }
        jumps += o.jumps;
    }
    return jumps;
}

static void wavy_jumps_tick_invariant(void **st)
{
    static const double hs[] = {0.25e-6, 0.5e-6, 1e-6, 1.5e-6};
    static const uint16_t ns[] = {16, 20, 24, 32, 64};
    int cases = 0;
    (void)st;
    for (size_t ih = 0; ih < 4; ih++) {
        for (size_t in = 0; in < sizeof ns / sizeof ns[0]; in++) {
            const double pd[3] = {100e-6, hs[ih], 5e-6};
            mdr_table_f64 t;
            table64(&t, MDR_PROFILE_WAVY, pd, ns[in], 80e-6);
            for (int k = 0; k < 9; k++) {
                const uint8_t ctl = (uint8_t)(1 + k / 3);
                const double wa = 0.39 * (k % 3);
                const int ref = wavy_cycle_jumps(&t, ctl, wa, 20000);
                for (long n = 10; n <= 2294; n = n * 3 / 2 + 1) {
                    const int j = wavy_cycle_jumps(&t, ctl, wa, n);
                    if (j != ref) {
                        printf("wavy h = %g m, %u springs, control %u, w_adv = %.2f J/m^2: %d jumps at %ld "
                               "ticks a segment, %d at 20000\n",
                               hs[ih], ns[in], ctl, 0.39 * (k % 3), j, n, ref);
                    }
                    assert_int_equal(j, ref);
                }
                cases++;
            }
        }
    }
    assert_int_equal(cases, 4 * 5 * 9);
}
#endif

/* The jumps an engine knows from init (mdr_engine_t.h: u_min, t_in, k_in,
 * t_fold, k_fold, u_fold: the pull-off and the jump-in from a = 0 without a
 * scan) against the same engine with that knowledge cleared, which scans:
 * two approach-retract cycles per profile, control, arithmetic and w_adv,
 * tick by tick: identical (events, jump counts, d, F, a: no tolerance; the
 * known jumps are the scan's own results, kept at init, and the outermost
 * fold is searched from the same nodes). Profiles: the sphere (300
 * springs), the wavy profile (64 and 1024 springs: folds inside the table,
 * the outermost one not a pull-off), a coarse paraboloid (8 springs: the
 * pull-off inside spring 0), the cone. */
#define TOL_KNOWN64 0.0
#define TOL_KNOWN32 0.0
#define KNOWN_CYCLES(SFX, T, TOL)                                                                              \
    static void known_cycles_##SFX(const mdr_table_##SFX *t, uint8_t ctl, double umax, double umin, double wa,   \
                                   int *po, int *ji)                                                            \
    {                                                                                                           \
        mdr_engine_##SFX e, s;                                                                                  \
        double dm = 0, Fm = 0, am = 0, dd = 0, dF = 0, da = 0;                                                  \
        const long n = 1500;                                                                                    \
        long i;                                                                                                 \
        assert_int_equal(mdr_engine_init_##SFX(&e, t, (T)1e6, (T)0.05, (T)wa,                                 \
                                                (T)(ctl == MDR_CONTROL_MACHINE ? 2.0 : 0.0)),                  \
                         MDR_OK);                                                                               \
        s = e;                                                                                                  \
        for (i = 0; i < 3; i++) {                                                                               \
            s.k_in[i] = s.k_fold[i] = 0xFFFF;                                                                   \
            s.u_min[i] = s.u_fold[i] = -(T)INFINITY;                                                            \
        }                                                                                                       \
        for (i = 1; i <= 4 * n; i++) {                                                                          \
            const long q = i % (2 * n);                                                                         \
            const double u = q <= n ? umin + (umax - umin) * (double)q / (double)n                              \
                                    : umax + (umin - umax) * (double)(q - n) / (double)n;                       \
            mdr_step_##SFX a, b;                                                                                \
            const mdr_status ra = step_##SFX##_of(ctl)(&e, (T)u, &a), rb = step_##SFX##_of(ctl)(&s, (T)u, &b); \
            assert_int_equal(ra, rb);                                                                           \
            if (ra != MDR_OK) {                                                                                 \
                fail_msg(#SFX " control %u, w_adv %g: tick %ld (u %g) refused (%d)", ctl, wa, i, u, ra);       \
            }                                                                                                   \
            if (a.event != b.event || a.jumps != b.jumps) {                                                     \
                fail_msg(#SFX " control %u, w_adv %g: tick %ld, event %u (%u jumps) known, %u (%u) scanned",    \
                         ctl, wa, i, a.event, a.jumps, b.event, b.jumps);                                       \
            }                                                                                                   \
            *po += a.event == MDR_EV_PULL_OFF;                                                                  \
            *ji += a.event == MDR_EV_JUMP_IN;                                                                   \
            dm = fmax(dm, fabs((double)a.d));                                                                   \
            Fm = fmax(Fm, fabs((double)a.F));                                                                   \
            am = fmax(am, (double)a.a);                                                                         \
            dd = fmax(dd, fabs((double)a.d - (double)b.d));                                                     \
            dF = fmax(dF, fabs((double)a.F - (double)b.F));                                                     \
            da = fmax(da, fabs((double)a.a - (double)b.a));                                                     \
        }                                                                                                       \
        rel_le(dd, 0, dm, TOL, #SFX " known jumps: d against the scan's");                                      \
        rel_le(dF, 0, Fm, TOL, #SFX " known jumps: F against the scan's");                                      \
        rel_le(da, 0, am, TOL, #SFX " known jumps: a against the scan's");                                      \
    }
#define step_f64_of step64_of
#define step_f32_of step32_of
KNOWN_CYCLES(f64, double, TOL_KNOWN64)
KNOWN_CYCLES(f32, float, TOL_KNOWN32)

static void known_jumps_match_scan(void **st)
{
    const double sph[3] = {1e-6, 0, 0}, wav[3] = {100e-6, 0.5e-6, 5e-6}, par[3] = {10e-6, 0, 0},
                 con[3] = {1.2, 0, 0};
    const struct {
        uint8_t kind;
        const double *p;
        uint16_t n;
        double x_max, dmax, dmin, Fmax, Fmin;
    } cases[] = {
        {MDR_PROFILE_SPHERE, sph, 300, 0.7e-6, 0.1e-6, -0.3e-6, 1e-7, -0.4e-6},
        {MDR_PROFILE_WAVY, wav, 64, 80e-6, 3e-6, -3e-6, 2e-3, -2e-3},
        {MDR_PROFILE_WAVY, wav, 1024, 80e-6, 3e-6, -3e-6, 2e-3, -2e-3},
        {MDR_PROFILE_PARABOLOID, par, 8, 50e-6, 2e-6, -2e-6, 1e-4, -1e-4},
        {MDR_PROFILE_CONE, con, 256, 20e-6, 0.5e-6, -0.5e-6, 1e-4, -1e-4},
    };
    int po = 0, ji = 0;
    (void)st;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        float pf[3] = {(float)cases[c].p[0], (float)cases[c].p[1], (float)cases[c].p[2]};
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        table64(&t64, cases[c].kind, cases[c].p, cases[c].n, cases[c].x_max);
        table32(&t32, cases[c].kind, pf, cases[c].n, (float)cases[c].x_max);
        for (uint8_t ctl = 1; ctl <= 3; ctl++) {
            const double umax = ctl == MDR_CONTROL_LOAD ? cases[c].Fmax : cases[c].dmax;
            const double umin = ctl == MDR_CONTROL_LOAD ? cases[c].Fmin : cases[c].dmin;
            for (int k = 0; k < 2; k++) {
                known_cycles_f64(&t64, ctl, umax, umin, 0.01 + 0.01 * k, &po, &ji);
                known_cycles_f32(&t32, ctl, umax, umin, 0.01 + 0.01 * k, &po, &ji);
            }
        }
    }
    if (getenv("MDR_TOL_REPORT")) {
        printf("  known jumps: %d pull-offs, %d jump-ins\n", po, ji);
    }
    assert_true(po >= 100 && ji >= 80); /* the known jumps were there to take (measured 104, 88) */
}

static void flat_punch_wall(void **st)
{
    const double pd[3] = {1e-6, 0, 0};
    mdr_table_f64 t64;
    mdr_engine_f64 e;
    mdr_step_f64 o, po;
    (void)st;
    table64(&t64, MDR_PROFILE_FLATPUNCH, pd, 64, 1e-6);
    assert_int_equal(t64.wall, 1);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, 1e6, 0.05, 0.0, 0), MDR_OK);
    run64(&e, MDR_CONTROL_GRIPS, 0, 1e-8, 10, &po, &o);
    rel_le(e.a, 1e-6, 0, 1e-15, "punch held at its rim");
    rel_le(o.F, 2 * 1e6 * 1e-6 * 1e-8, 0, 1e-12, "punch stiffness 2 E* a0");
    assert_true(run64(&e, MDR_CONTROL_GRIPS, 1e-8, -1e-6, 10000, &po, NULL));
    /* Kendall (4.63): d = -sqrt(2 pi a0 w/E*), F = -sqrt(8 pi a0^3 w E*) */
    rel_le(po.d0, -sqrt(2 * PI_ * 1e-6 * 0.05 / 1e6), 0, TOL_X64, "Kendall d");
    rel_le(po.F0, -sqrt(8 * PI_ * 1e-18 * 0.05 * 1e6), 0, TOL_X64, "Kendall F");
}


/* ------------------------------------------------------ rims on nodes */

/* The rim of a flat on a spring node (issue 16): the analytic flattened tip
 * (R = 1 um, b = 0.2 um, E* = 1 MPa, w = 0.01; table asked to 0.9 um with
 * 1024 springs, where b would lie at 227.6 springs) and a worn tip sampled
 * every 0.25 nm (paraboloid R = 20 nm flat to b = 5.25 nm, E* = 1 GPa,
 * w = 0.05; samples to 40 nm, b at 134.4 springs of the unshifted table).
 * The table moves its nodes so that b is one (rim_node: x_k = b exactly
 * where g is evaluated, the table longer or, for samples, shorter by less
 * than a spring's share). Under fixed grips both rupture at the rim:
 * Kendall's F = -sqrt(8 pi b^3 E* w), d = -sqrt(2 pi b w/E*) to TOL_RIM64
 * in f64 (measured 1.8e-15) and TOL_RIM32 in f32 (measured below); the
 * flattened tip's pull-off through a soft machine (a fold above the rim) against the contact
 * module's mdr_critical to TOL_RIM_MACHINE (the issue's goal 1e-5; measured
 * below). With b inside a spring all of these were 3.7e-3 to 4.5e-3. */
#define TOL_RIM64 1e-12
#define TOL_RIM32 1e-5
#define TOL_RIM_MACHINE 1e-5

/* A sampled tip whose first kink lies below the first node (a spike of
 * 2 m in 1e-27 m, found by fuzz_table): the table starts at g(0) = 0 (the
 * gap builder evaluated node 0 at that kink, g_0 = pi), and a grips step
 * pins the edge where d = g(a) - c t on the table's own quadratic */
static void gap_spike_below_first_node(void **st)
{
    static const double r[] = {0.0, 1e-27, 1e-6, 5.2e-6}, f[] = {0.0, 2.0, 0.0, 4.232};
    mdr_table_f64 t;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    (void)st;
    assert_int_equal(mdr_table_init_gap_f64(&t, nodes64, 4, r, f, 4), MDR_OK);
    assert_true(nodes64[0].g == 0.0);
    assert_int_equal(mdr_engine_init_f64(&e, &t, 2.955e8, 0.0131, 0.0131, 0.0), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f64(&e, 0.38, &o), MDR_OK);
    assert_true(e.contact);
    /* pinned in the Hess band (here w = w_adv): d = g - c t at the edge,
     * to the rounding of the root (fuzz_engine_t.h's check) */
    assert_true(e.a > 0.0 && e.k < 4u);
    assert_true(fabs(e.d - (e.g - e.c_w * e.t)) <= 1e-12 * (fabs(e.g) + fabs(e.d)));
}

static void rims_on_nodes(void **st)
{
    const double pd[3] = {1e-6, 0.2e-6, 0}, b = 0.2e-6, E = 1e6, w = 0.01;
    const float pf[3] = {1e-6f, 0.2e-6f, 0};
    const double Fk = -sqrt(8 * PI_ * b * b * b * E * w), dk = -sqrt(2 * PI_ * b * w / E);
    mdr_contact_f64 c;
    mdr_contact_f32 cf;
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    mdr_engine_f64 e;
    mdr_engine_f32 e32;
    mdr_step_f64 po;
    mdr_step_f32 po32;
    mdr_critstate_f64 k;
    double a0, worst32 = 0, worstm = 0;
    static double r[161], f[161];
    static float rf[161], ff[161];
    int i;
    (void)st;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_FLATTIP, pd, E, w), MDR_OK);
    assert_int_equal(mdr_contact_init_f32(&cf, MDR_PROFILE_FLATTIP, pf, (float)E, (float)w), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, 1024, &c, 0.9e-6), MDR_OK);
    rel_le(t64.h * 227, b, 0, 4e-16, "the rim on node 227");
    assert_true(t64.h * 1024 >= 0.9e-6 && t64.h * 1024 < 0.9e-6 * (1 + 1.0 / 227));
    assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, 1024, &cf, 0.9e-6f), MDR_OK);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, E, w, 0.0, 0), MDR_OK);
    assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)E, (float)w, 0.0f, 0), MDR_OK);
    assert_true(run64(&e, MDR_CONTROL_GRIPS, 0, 0.3e-6, 4000, &po, NULL) == 0);
    assert_true(run64(&e, MDR_CONTROL_GRIPS, 0.3e-6, -0.5e-6, 8000, &po, NULL));
    rel_le(po.F0, Fk, 0, TOL_RIM64, "flattened tip, grips: Kendall F");
    rel_le(po.d0, dk, 0, TOL_RIM64, "flattened tip, grips: Kendall d");
    assert_true(run32(&e32, MDR_CONTROL_GRIPS, 0, 0.3e-6, 4000, &po32) == 0);
    assert_true(run32(&e32, MDR_CONTROL_GRIPS, 0.3e-6, -0.5e-6, 8000, &po32));
    worst32 = fmax(fabs(po32.F0 - Fk) / fabs(Fk), fabs(po32.d0 - dk) / fabs(dk));
    /* a soft machine (2E* b/100): its pull-off is a fold above the rim */
    assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
    assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_MACHINE, 0.02 * E * b, a0, &k), MDR_OK);
    assert_true(k.a > 1.2 * b);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, E, w, 0.0, 0.02 * E * b), MDR_OK);
    /* (loaded to F = k z ~ 1e-7 N, beyond the fold's radius, then retracted) */
    assert_true(run64(&e, MDR_CONTROL_MACHINE, 0, 30e-6, 4000, &po, NULL) == 0);
    assert_true(run64(&e, MDR_CONTROL_MACHINE, 30e-6, -20e-6, 20000, &po, NULL));
    worstm = fmax(fabs(po.F0 - k.F) / fabs(k.F), fabs(po.a0 - k.a) / k.a);
    rel_le(po.F0, k.F, 0, TOL_RIM_MACHINE, "flattened tip, machine: pull-off F");
    /* the worn tip's samples, f64 and f32 */
    for (i = 0; i <= 160; i++) {
        r[i] = i * 0.25e-9;
        f[i] = r[i] < 5.25e-9 ? 0 : (r[i] * r[i] - 5.25e-9 * 5.25e-9) / 40e-9;
        rf[i] = (float)r[i];
        ff[i] = (float)f[i];
    }
    {
        const double bw = 5.25e-9, Ew = 1e9, ww = 0.05;
        const double Fw = -sqrt(8 * PI_ * bw * bw * bw * Ew * ww), dw = -sqrt(2 * PI_ * bw * ww / Ew);
        assert_int_equal(mdr_table_init_gap_f64(&t64, nodes64, 1024, r, f, 161), MDR_OK);
        assert_true(t64.h * 1024 <= 40e-9 && t64.h * 1024 > 40e-9 * (1 - 1.0 / 134));
        assert_int_equal(mdr_engine_init_f64(&e, &t64, Ew, ww, 0.0, 0), MDR_OK);
        assert_true(run64(&e, MDR_CONTROL_GRIPS, 0, 5e-9, 4000, &po, NULL) == 0);
        assert_true(run64(&e, MDR_CONTROL_GRIPS, 5e-9, -5e-9, 8000, &po, NULL));
        rel_le(po.F0, Fw, 0, TOL_RIM64, "worn tip, grips: Kendall F");
        rel_le(po.d0, dw, 0, TOL_RIM64, "worn tip, grips: Kendall d");
        assert_int_equal(mdr_table_init_gap_f32(&t32, nodes32, 1024, rf, ff, 161), MDR_OK);
        assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)Ew, (float)ww, 0.0f, 0), MDR_OK);
        assert_true(run32(&e32, MDR_CONTROL_GRIPS, 0, 5e-9, 4000, &po32) == 0);
        assert_true(run32(&e32, MDR_CONTROL_GRIPS, 5e-9, -5e-9, 8000, &po32));
        worst32 = fmax(worst32, fmax(fabs(po32.F0 - Fw) / fabs(Fw), fabs(po32.d0 - dw) / fabs(dw)));
    }
    print_message("rims on nodes: f32 against Kendall %.2e, flattened tip's machine pull-off %.2e\n", worst32,
                  worstm);
    assert_true(worst32 <= TOL_RIM32);
}

/* The flattened tip's f32 pull-off at its rim over spring counts and table
 * lengths: Kendall's F and d to TOL_RIM32_NODE under fixed grips
 * (w_adv = 0) and fixed load (w_adv = w), for a helper's case (stop 51:
 * R = 1 mm, b = 50 um, E* = 1 GPa, w = 0.01; the rim at 0.56 to 0.79 of the
 * table) and an AFM tip (R = 20 nm, b = 5 nm, E* = 1 GPa, w = 0.05;
 * 0.42 to 0.5). The fold at the rim is kept as (k, t) in the spring above it, whose
 * quadratic rises steeply (g ~ sqrt(x - b)); with e = (t^2 - x_k)/h read
 * one ulp below the node (e = -2.3e-4) the pull-off was 1.2e-4 to 4.9e-4
 * off, one ulp above it 2.3e-6 to 9.6e-6, growing with N, until e became
 * (t - t_k)(t + t_k)/h, 0 at the node's own t (mdr_table_float.inc's
 * mdr_e_at_sp). Measured after: 1.7e-7, a few f32 roundings:
 * TOL_RIM32_NODE = 1e-6. */
#define TOL_RIM32_NODE 1e-6
static void rim_pull_off_f32(void **st)
{
    static const uint16_t ns[] = {256, 512, 1024, 2048, 4096};
    static const struct {
        float R, b, E, w, L[3];
        double d_top, F_top, F_bot;
    } tips[] = {{1e-3f, 5e-5f, 1e9f, 0.01f, {6.3e-5f, 7.1e-5f, 8.9e-5f}, 2e-7, 0.0112, -0.0084},
                {2e-8f, 5e-9f, 1e9f, 0.05f, {1.0e-8f, 1.1e-8f, 1.2e-8f}, 1.5e-9, 1e-8, -2e-8}};
    double worst = 0;
    unsigned i, j, c, m;
    (void)st;
    for (m = 0; m < 2; m++) {
        const double b = tips[m].b, E = tips[m].E, w = tips[m].w;
        const double Fk = -sqrt(8 * PI_ * b * b * b * E * w), dk = -sqrt(2 * PI_ * b * w / E);
        const float pf[3] = {tips[m].R, tips[m].b, 0};
        mdr_contact_f32 cf;
        assert_int_equal(mdr_contact_init_f32(&cf, MDR_PROFILE_FLATTIP, pf, tips[m].E, tips[m].w), MDR_OK);
        for (i = 0; i < sizeof ns / sizeof ns[0]; i++) {
            for (j = 0; j < 3; j++) {
                mdr_table_f32 t32;
                assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, ns[i], &cf, tips[m].L[j]), MDR_OK);
                for (c = 0; c < 2; c++) {
                    const bool load = c == 1;
                    mdr_engine_f32 e32;
                    mdr_step_f32 po;
                    double err;
                    assert_int_equal(mdr_engine_init_f32(&e32, &t32, tips[m].E, tips[m].w, load ? tips[m].w : 0.0f, 0),
                                     MDR_OK);
                    if (load) {
                        assert_true(run32(&e32, MDR_CONTROL_LOAD, 0, tips[m].F_top, 2000, &po) == 0);
                        assert_true(run32(&e32, MDR_CONTROL_LOAD, tips[m].F_top, tips[m].F_bot, 2000, &po));
                    } else {
                        assert_true(run32(&e32, MDR_CONTROL_GRIPS, 0, tips[m].d_top, 2000, &po) == 0);
                        assert_true(run32(&e32, MDR_CONTROL_GRIPS, tips[m].d_top, -tips[m].d_top, 2000, &po));
                    }
                    err = fmax(fabs(po.F0 - Fk) / fabs(Fk), fabs(po.d0 - dk) / fabs(dk));
                    worst = fmax(worst, err);
                    if (err > TOL_RIM32_NODE) {
                        print_message("tip %u, N = %u, x_max = %g, %s: %.2e\n", m, ns[i], (double)tips[m].L[j],
                                      load ? "load" : "grips", err);
                    }
                    assert_true(err <= TOL_RIM32_NODE);
                }
            }
        }
    }
    print_message("flattened tips' f32 pull-off at the rim, 2 tips x 5 spring counts x 3 lengths x 2 controls: "
                  "worst %.2e against Kendall\n",
                  worst);
}

/* The tick on which the f32 pull-off at a flattened tip's rim happens, not
 * only the fold's values (rim_pull_off_f32): a helper's scene (stop 57; R
 * = 1 mm, b = 50 um, E* = 1e10 Pa, w = 1e-7 and 1e-6 J/m^2, tables to
 * 60 um) on 1 024, 4 096 and 16 384 springs, fixed grips and fixed load
 * (w_adv = w): pressed to 3 times Kendall's control in RIMTICK_TICKS
 * ticks, retracted to -2 times it in twice as many (the helper's path).
 * Every tick in contact stays above Kendall's control less
 * TOL_RIM32_NODE of it, the pull-off comes within one tick of passing it
 * and not before, and under load every tick in contact with the edge at
 * the rim has d = F/(2E* b) (G(b) = 0) within half of what the table's g
 * moves over one ulp of t above the rim (f32's resolution of d there:
 * 2.6e-11 m at 1 024 springs, 1.0e-10 at 16 384, Kendall's depth 5.6e-11
 * at w = 1e-7) and TOL_RIMTICK_D of Kendall's depth (measured: 5.7e-4).
 * Before: the fast path converged on the rim's node and set the band's
 * end to the control itself, not U there: the contact held to 1.89 times
 * Kendall's depth (1.22 at 1 024 springs), under load past 1.9 times its
 * force; a scan from that node that took the flat below it for the fold
 * whatever the control (the first fix's own defect) pulled off at a tenth
 * of Kendall's depth (a helper's attack, stop 57). */
#define RIMTICK_TICKS 20000
#define TOL_RIMTICK_D 1e-3
#ifndef MDR_TARGET_TEST /* (host only: 720 000 ticks; the target runs the same fast path in rim_pull_off_f32) */
static void rim_pull_off_tick_f32(void **st)
{
    static const uint16_t ns[] = {1024, 4096, 16384};
    static const float ws[] = {1e-7f, 1e-6f};
    const float pf[3] = {1e-3f, 5e-5f, 0}, E = 1e10f;
    const double b = 5e-5;
    double worst = 0, worstd = 0;
    unsigned i, j, c, kr;
    (void)st;
    for (j = 0; j < 2; j++) {
        const double w = ws[j], Fk = -sqrt(8 * PI_ * b * b * b * E * w), dk = -sqrt(2 * PI_ * b * w / E);
        mdr_contact_f32 cf;
        assert_int_equal(mdr_contact_init_f32(&cf, MDR_PROFILE_FLATTIP, pf, E, ws[j]), MDR_OK);
        for (i = 0; i < sizeof ns / sizeof ns[0]; i++) {
            mdr_table_f32 t32;
            double gres, e1;
            float t1;
            assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, ns[i], &cf, 6e-5f), MDR_OK);
            for (kr = 1; kr < ns[i] && nodes32[kr + 1].g == 0; kr++) {
            }
            /* g of the rim's spring one ulp of t above the rim's node */
            t1 = nextafterf(nodes32[kr].t, 1.0f);
            e1 = ((double)t1 - nodes32[kr].t) * ((double)t1 + nodes32[kr].t) / t32.h;
            gres = e1 * ((nodes32[kr + 1].g - nodes32[kr].g) + 6 * nodes32[kr].q / t32.h * (1 - e1));
            for (c = 0; c < 2; c++) {
                const bool load = c == 1;
                const uint8_t ctl = load ? MDR_CONTROL_LOAD : MDR_CONTROL_GRIPS;
                const double uk = load ? Fk : dk, step = 5 * fabs(uk) / (2 * RIMTICK_TICKS);
                const step32_fn f = step32_of(ctl);
                mdr_engine_f32 e32;
                double umin = 0, upo = 0;
                long k;
                int po = 0;
                assert_int_equal(mdr_engine_init_f32(&e32, &t32, E, ws[j], ws[j], 0), MDR_OK);
                for (k = 1; k <= 3 * RIMTICK_TICKS && !po; k++) {
                    const double uu = k <= RIMTICK_TICKS ? -3 * uk * (double)k / RIMTICK_TICKS
                                                          : -3 * uk - step * (double)(k - RIMTICK_TICKS);
                    mdr_step_f32 o;
                    assert_int_equal(f(&e32, (float)uu, &o), MDR_OK);
                    if (o.event == MDR_EV_PULL_OFF) {
                        po = 1;
                        upo = uu;
                    } else if (o.a > 0) {
                        umin = fmin(umin, uu);
                        if (load && fabs(o.a - b) <= 1e-6 * b) {
                            worstd = fmax(worstd, (fabs(o.d - o.F / (2.0 * E * b)) - 0.5 * gres) / fabs(dk));
                        }
                    }
                }
                assert_true(po);
                worst = fmax(worst, (uk - umin) / fabs(uk));
                if (!(umin >= uk * (1 + TOL_RIM32_NODE)) || !(upo >= uk - step * (1 + 1e-6)) ||
                    !(upo <= uk * (1 - TOL_RIM32_NODE))) {
                    print_message("N = %u, w = %g, %s: deepest in contact %.9g, pull-off at %.9g, Kendall %.9g\n",
                                  ns[i], w, load ? "load" : "grips", umin, upo, uk);
                }
                assert_true(umin >= uk * (1 + TOL_RIM32_NODE));
                assert_true(upo >= uk - step * (1 + 1e-6));
                assert_true(upo <= uk * (1 - TOL_RIM32_NODE)); /* (not before it) */
            }
        }
    }
    print_message("flattened tip's f32 pull-off tick: deepest control in contact %.2e of Kendall's beyond it; "
                  "d at the rim under load beyond half g's change per ulp of t: %.2e of Kendall's depth\n",
                  worst, worstd);
    assert_true(worstd <= TOL_RIMTICK_D);
}
#endif

/* The adhesion a float engine resolves (MDR_ENGINE_ADH_COND; the init's
 * adh_resolved, mdr_table_float.inc). A paraboloid R = 1 um, w = 0.05 on
 * 64 and 1 024 springs to 40 nm, E* from 1e12 Pa up in steps of 10^0.5
 * (f32) or 10 (f64) to the arithmetic's range: either init refuses
 * (MDR_E_PARAM) or the pull-off under grips and under load is within
 * TOL_ADH = 1/MDR_ENGINE_ADH_COND of -(5/6) pi w R and -(3/2) pi w R. The
 * pull-off moves into spring 0 as E* grows (a_c = (pi w R^2/(8 E*))^(1/3)
 * under grips), where the spring's quadratic cancels to about 2u/e of
 * itself at e = a_c/h (u = the unit roundoff): before the check, f32 was
 * 5.7e-3 off at E* = 1e32 and 0.1 at 1e36, f64 2.3x too small at 1e65
 * and tensile at 1e70. A refusal only where that closed-form bound is
 * above TOL_ADH/4 (not a premature one), every larger E* refused too, and
 * both seen in each sweep (pressed under load to 1e-6 N, past the
 * pull-off's radius: a receding contact that never reached it pulls off
 * from its pinned edge, at another force). A cone (0.3 rad) in f32, whose pull-off force
 * under load in engine units, F/(2E*), falls below FLT_MIN (a subnormal:
 * 1e-2 off at 1e21, F = 0 at 1e22): each E* from 1e9 in decades either
 * refused or within TOL_ADH of the f64 engine's pull-off on the same
 * path, and refused from 1e22 on. Measured: paraboloid f32 refused from
 * E* = 3.2e29 on 1 024 springs (1e26 on 64), worst accepted 4.9e-4; f64
 * from 1e56 (1e52), worst 2.2e-4; cone refused from 1e19, worst 1.1e-6. */
#define TOL_ADH (1.0 / MDR_ENGINE_ADH_COND)
static int adh_run64(const mdr_table_f64 *t, double E, uint8_t ctl, double F_top, double *F0)
{
    mdr_engine_f64 e;
    mdr_step_f64 po;
    const bool load = ctl == MDR_CONTROL_LOAD;
    const mdr_status st = mdr_engine_init_f64(&e, t, E, JW, 0, 0);
    if (st != MDR_OK) {
        assert_int_equal(st, MDR_E_PARAM);
        return 0;
    }
    assert_true(run64(&e, ctl, 0, load ? F_top : 5e-10, 200, &po, NULL) == 0);
    assert_true(run64(&e, ctl, load ? F_top : 5e-10, load ? -5e-7 : -5e-10, 400, &po, NULL));
    *F0 = po.F0;
    return 1;
}

static int adh_run32(const mdr_table_f32 *t, double E, uint8_t ctl, double F_top, double *F0)
{
    mdr_engine_f32 e;
    mdr_step_f32 po;
    const bool load = ctl == MDR_CONTROL_LOAD;
    const mdr_status st = mdr_engine_init_f32(&e, t, (float)E, (float)JW, 0, 0);
    if (st != MDR_OK) {
        assert_int_equal(st, MDR_E_PARAM);
        return 0;
    }
    assert_true(run32(&e, ctl, 0, load ? F_top : 5e-10, 200, &po) == 0);
    assert_true(run32(&e, ctl, load ? F_top : 5e-10, load ? -5e-7 : -5e-10, 400, &po));
    *F0 = po.F0;
    return 1;
}

static void adhesion_resolved_float(void **st)
{
    static const uint16_t ns[] = {64, 1024};
    const double R = 1e-6, L = 40e-9, Fg = -5.0 / 6.0 * PI_ * JW * R, Fl = -1.5 * PI_ * JW * R;
    double worst[2] = {0, 0}, cone = 0;
    unsigned i, m;
    (void)st;
    for (m = 0; m < 2; m++) { /* 0: f32, 1: f64 */
        const double u = m == 0 ? TOL_U32 : DBL_EPSILON / 2, top = m == 0 ? 3e38 : 1e300;
        for (i = 0; i < 2; i++) {
            int refused = 0, accepted = 0;
            double E;
            mdr_contact_f64 c64;
            mdr_contact_f32 c32;
            mdr_table_f64 t64;
            mdr_table_f32 t32;
            const double pd[3] = {R, 0, 0};
            const float pf[3] = {(float)R, 0, 0};
            assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_PARABOLOID, pd, 1.0, 0.0), MDR_OK);
            assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pf, 1.0f, 0.0f), MDR_OK);
            assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, ns[i], &c64, L), MDR_OK);
            assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, ns[i], &c32, (float)L), MDR_OK);
            for (E = 1e12; E < top; E *= m == 0 ? sqrt(10.0) : pow(10.0, TGT_STRIDE)) {
                const double e = cbrt(PI_ * JW * R * R / (8 * E)) / (L / ns[i]), bound = 2 * u / e;
                double Fgot, Flot;
                const int okg = m == 0 ? adh_run32(&t32, E, MDR_CONTROL_GRIPS, 0, &Fgot)
                                       : adh_run64(&t64, E, MDR_CONTROL_GRIPS, 0, &Fgot);
                const int okl = m == 0 ? adh_run32(&t32, E, MDR_CONTROL_LOAD, 1e-6, &Flot)
                                       : adh_run64(&t64, E, MDR_CONTROL_LOAD, 1e-6, &Flot);
                assert_int_equal(okg, okl); /* (one init decides both) */
                if (!okg) {
                    if (!(bound > TOL_ADH / 4)) {
                        print_message("%s, %u springs, E* = %g: refused, bound %.2e\n", m ? "f64" : "f32", ns[i], E,
                                      bound);
                    }
                    assert_true(bound > TOL_ADH / 4);
                    if (!refused) {
                        print_message("%s, %u springs: refused from E* = %.2g (e = %.2e)\n", m ? "f64" : "f32",
                                      ns[i], E, e);
                    }
                    refused = 1;
                    continue;
                }
                assert_false(refused); /* every E* above a refused one refused */
                accepted = 1;
                worst[m] = fmax(worst[m], fmax(fabs(Fgot / Fg - 1), fabs(Flot / Fl - 1)));
                if (!(fabs(Fgot / Fg - 1) <= TOL_ADH && fabs(Flot / Fl - 1) <= TOL_ADH)) {
                    print_message("%s, %u springs, E* = %g: %.2e, %.2e\n", m ? "f64" : "f32", ns[i], E,
                                  Fgot / Fg - 1, Flot / Fl - 1);
                }
                assert_true(fabs(Fgot / Fg - 1) <= TOL_ADH && fabs(Flot / Fl - 1) <= TOL_ADH);
            }
            assert_true(refused && accepted);
        }
    }
    {
        const double pd[3] = {0.3, 0, 0};
        const float pf[3] = {0.3f, 0, 0};
        mdr_contact_f64 c64;
        mdr_contact_f32 c32;
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        double E;
        int refused = 0;
        assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_CONE, pd, 1.0, 0.0), MDR_OK);
        assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_CONE, pf, 1.0f, 0.0f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, 1024, &c64, 40e-9), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, 1024, &c32, 40e-9f), MDR_OK);
        for (E = 1e9; E < 3e38; E *= 10) {
            uint8_t ctl;
            for (ctl = MDR_CONTROL_LOAD; ctl <= MDR_CONTROL_GRIPS; ctl++) {
                double F32, F64;
                assert_true(adh_run64(&t64, E, ctl, 1e-7, &F64));
                if (!adh_run32(&t32, E, ctl, 1e-7, &F32)) {
                    if (!refused) {
                        print_message("cone, f32: refused from E* = %.2g\n", E);
                    }
                    refused = 1;
                    continue;
                }
                assert_false(refused);
                assert_true(E < 1e22);
                cone = fmax(cone, fabs(F32 / F64 - 1));
                assert_true(fabs(F32 / F64 - 1) <= TOL_ADH);
            }
        }
        assert_true(refused);
    }
    print_message("resolved adhesion: worst accepted pull-off f32 %.2e, f64 %.2e of the closed form; cone f32 %.2e "
                  "of f64 (TOL_ADH %.2e)\n",
                  worst[0], worst[1], cone, TOL_ADH);
}

/* Tables at the bottom of the arithmetic's range (a helper's attack, stop
 * 52): a paraboloid with w = 1e-15 J/m^2, R = 1 cm on 256 springs and
 * R = 1 um on 1 024, tabulated to 4 a_c (a_c the grips pull-off radius),
 * E* from 1e3 Pa up in steps of 10^0.5 (f32 to 1e38, f64 to 1e300): the
 * table is refused (MDR_E_OVERFLOW, mdr_table.inc: a curvature term that
 * matters, q ~ h |Dg_{i+1} - Dg_i|/12, below the smallest normal number,
 * or G not normal down to eps of its largest), or the engine
 * (MDR_E_PARAM, adhesion_resolved_float), or the pull-off under grips and
 * load is within TOL_ADH of the closed forms. Before the table's check,
 * f32 at R = 1 cm, E* = 1.8e21 Pa stored every q_i as 0 (g piecewise
 * linear): the grips fold sat on a node, 4.7e-3 off; at R = 1 um,
 * E* = 1e32 every G was 0 too: F = 0 and no pull-off. Both a table
 * refusal and an accurate pull-off are seen in each sweep. Measured:
 * tables refused from E* = 3.2e14 (f32, R = 1 cm), 1e9 (f32, 1 um: there
 * q = h^3/(6R) is subnormal), 1e276 and 1e272 (f64, G); worst accepted
 * 5.5e-6 (f32), 1.8e-14 (f64). */
static void tiny_tables_float(void **st)
{
    static const struct {
        double R;
        uint16_t n;
    } cs[] = {{1e-2, 256}, {1e-6, 1024}};
    const double w = 1e-15;
    double worst[2] = {0, 0};
    unsigned i, m;
    (void)st;
    for (m = 0; m < 2; m++) {
        for (i = 0; i < 2; i++) {
            const double R = cs[i].R, Fg = -5.0 / 6.0 * PI_ * w * R, Fl = -1.5 * PI_ * w * R;
            int tab_refused = 0, accepted = 0;
            double E, tab_from = 0;
            for (E = 1e3; E < (m == 0 ? 3e38 : 1e300); E *= m == 0 ? sqrt(10.0) : pow(10.0, TGT_STRIDE)) {
                const double ac = cbrt(PI_ * w * R * R / (8 * E)), dc = ac * ac / R;
                double Fgot = 0, Flot = 0, errg, errl;
                mdr_status sg, sl;
                if (m == 0) {
                    mdr_contact_f32 c;
                    mdr_table_f32 t;
                    mdr_engine_f32 e[2];
                    mdr_step_f32 po;
                    const float p[3] = {(float)R, 0, 0};
                    assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, p, 1.0f, 0.0f), MDR_OK);
                    sg = mdr_table_init_profile_f32(&t, nodes32, cs[i].n, &c, (float)(4 * ac));
                    if (sg != MDR_OK) { /* (MDR_E_RADIUS: x_max itself subnormal) */
                        assert_true(sg == MDR_E_OVERFLOW || sg == MDR_E_RADIUS);
                        tab_from = tab_refused ? tab_from : E;
                        tab_refused = 1;
                        continue;
                    }
                    sg = mdr_engine_init_f32(&e[0], &t, (float)E, (float)w, 0, 0);
                    sl = mdr_engine_init_f32(&e[1], &t, (float)E, (float)w, 0, 0);
                    assert_int_equal(sg, sl);
                    if (sg != MDR_OK) {
                        assert_int_equal(sg, MDR_E_PARAM);
                        continue;
                    }
                    assert_true(run32(&e[0], MDR_CONTROL_GRIPS, 0, 3 * dc, 200, &po) == 0);
                    assert_true(run32(&e[0], MDR_CONTROL_GRIPS, 3 * dc, -6 * dc, 400, &po));
                    Fgot = po.F0;
                    assert_true(run32(&e[1], MDR_CONTROL_LOAD, 0, -2 * Fl, 200, &po) == 0);
                    assert_true(run32(&e[1], MDR_CONTROL_LOAD, -2 * Fl, 2 * Fl, 400, &po));
                    Flot = po.F0;
                } else {
                    mdr_contact_f64 c;
                    mdr_table_f64 t;
                    mdr_engine_f64 e[2];
                    mdr_step_f64 po;
                    const double p[3] = {R, 0, 0};
                    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, p, 1.0, 0.0), MDR_OK);
                    sg = mdr_table_init_profile_f64(&t, nodes64, cs[i].n, &c, 4 * ac);
                    if (sg != MDR_OK) { /* (MDR_E_RADIUS: x_max itself subnormal) */
                        assert_true(sg == MDR_E_OVERFLOW || sg == MDR_E_RADIUS);
                        tab_from = tab_refused ? tab_from : E;
                        tab_refused = 1;
                        continue;
                    }
                    sg = mdr_engine_init_f64(&e[0], &t, E, w, 0, 0);
                    sl = mdr_engine_init_f64(&e[1], &t, E, w, 0, 0);
                    assert_int_equal(sg, sl);
                    if (sg != MDR_OK) {
                        assert_int_equal(sg, MDR_E_PARAM);
                        continue;
                    }
                    assert_true(run64(&e[0], MDR_CONTROL_GRIPS, 0, 3 * dc, 200, &po, NULL) == 0);
                    assert_true(run64(&e[0], MDR_CONTROL_GRIPS, 3 * dc, -6 * dc, 400, &po, NULL));
                    Fgot = po.F0;
                    assert_true(run64(&e[1], MDR_CONTROL_LOAD, 0, -2 * Fl, 200, &po, NULL) == 0);
                    assert_true(run64(&e[1], MDR_CONTROL_LOAD, -2 * Fl, 2 * Fl, 400, &po, NULL));
                    Flot = po.F0;
                }
                accepted = 1;
                errg = fabs(Fgot / Fg - 1);
                errl = fabs(Flot / Fl - 1);
                worst[m] = fmax(worst[m], fmax(errg, errl));
                if (!(errg <= TOL_ADH && errl <= TOL_ADH)) {
                    print_message("%s, R = %g, %u springs, E* = %g: grips %.2e, load %.2e\n", m ? "f64" : "f32", R,
                                  cs[i].n, E, errg, errl);
                }
                assert_true(errg <= TOL_ADH && errl <= TOL_ADH);
            }
            print_message("%s, R = %g, %u springs: tables refused from E* = %.2g\n", m ? "f64" : "f32", R,
                          cs[i].n, tab_from);
            assert_true(tab_refused && accepted);
        }
    }
    print_message("tables at the bottom of the range: worst accepted pull-off f32 %.2e, f64 %.2e\n", worst[0],
                  worst[1]);
    { /* a cone (q = 0, exact): its G = (pi/4) tan(theta) x^2 must stay
         normal down to eps of its largest (f32: G_n >= 2^24 FLT_MIN) */
        mdr_contact_f32 c;
        mdr_table_f32 t;
        const float p[3] = {0.3f, 0, 0};
        assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_CONE, p, 1.0f, 0.0f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t, nodes32, 1024, &c, 1e-14f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t, nodes32, 1024, &c, 1e-17f), MDR_E_OVERFLOW);
    }
    { /* a paraboloid R = 1 um on 16 384 springs: to 1e-12 m its G is normal
         (G_n 3.3e-31) but q = h^3/(6R) is 3.8e-44, 5 bits of a subnormal;
         to 1e-10 m q is 3.8e-38, normal */
        mdr_contact_f32 c;
        mdr_table_f32 t;
        const float p[3] = {1e-6f, 0, 0};
        assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, p, 1.0f, 0.0f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t, nodes32, 16384, &c, 1e-10f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t, nodes32, 16384, &c, 1e-12f), MDR_E_OVERFLOW);
    }
}

/* ------------------------------------------------------ tabulated tips */

/* A paraboloid sampled at uneven radii: the piecewise-quadratic f is exact,
 * so the Abel integration must give g = x^2/R to rounding. */
static void gap_table_exact_for_quadratic(void **st)
{
    const double R = 2e-6;
    double r[40], f[40];
    float rf[40], ff[40];
    mdr_table_f64 t;
    mdr_table_f32 t32;
    int i;
    (void)st;
    for (i = 0; i < 40; i++) {
        r[i] = 1e-6 * pow(i / 39.0, 1.3);
        f[i] = 0.3e-6 + r[i] * r[i] / (2 * R); /* f(0) offset is irrelevant */
        rf[i] = (float)r[i];
        ff[i] = (float)f[i];
    }
    assert_int_equal(mdr_table_init_gap_f64(&t, nodes64, 100, r, f, 40), MDR_OK);
    for (i = 0; i <= 100; i++) {
        double x = t.h * i;
        rel_le(t.node[i].g, x * x / R, 1e-12 / R, TOL_X64, "g of sampled paraboloid");
        rel_le(t.node[i].G, x * x * x / (3 * R), 1e-18 / R, TOL_X64, "G of sampled paraboloid");
    }
    assert_int_equal(mdr_table_init_gap_f32(&t32, nodes32, 100, rf, ff, 40), MDR_OK);
    for (i = 0; i <= 100; i++) {
        double x = t.h * i;
        rel_le(t32.node[i].g, x * x / R, 1e-12 / R, 1e-5, "g of sampled paraboloid (f32)");
    }
}

/* Order of the Abel integration of a sampled smooth profile: the exact
 * sphere (f = R - sqrt(R^2 - r^2), R = 1 um) sampled at M = 16 ... 2048
 * uniform radii up to 0.6 R; error of g at 64 nodes against the closed form
 * (mdr_profile_eval_f64), relative to g(x_max). Fitted order >= 2.3 (the
 * claim: 2.5; f' linear per interval has error O(h^2), the Abel kernel's
 * integrable end point adds h^(1/2)). */
static void gap_table_order(void **st)
{
    static double r[2049], f[2049];
    const double R = 1e-6, rmax = 0.6e-6;
#ifdef MDR_TARGET_TEST /* (the target: M to 512; the soft double of 1 024 and 2 048 took 14.5 of QEMU's 18.8 s.
                        * The host runs M to 2 048: its fitted order 2.47, 2.45 from the six to 512) */
    enum { NK = 6 };
#else
    enum { NK = 8 };
#endif
    double lnN[8], lnE[8], sx = 0, sy = 0, sxx = 0, sxy = 0, order;
    mdr_contact_f64 c;
    const double pd[3] = {R, 0, 0};
    int k, i;
    (void)st;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_SPHERE, pd, 1, 0), MDR_OK);
    printf("  sampled sphere: M, largest g error (of g(x_max))\n");
    for (k = 0; k < NK; k++) {
        int m = 16 << k;
        mdr_table_f64 t;
        double worst = 0, gmax;
        for (i = 0; i <= m; i++) {
            r[i] = rmax * i / m;
            f[i] = R - sqrt((R - r[i]) * (R + r[i]));
        }
        assert_int_equal(mdr_table_init_gap_f64(&t, nodes64, 64, r, f, (uint16_t)(m + 1)), MDR_OK);
        assert_int_equal(mdr_profile_eval_f64(&c, rmax, &gmax, NULL, NULL), MDR_OK);
        for (i = 1; i <= 64; i++) {
            double g;
            assert_int_equal(mdr_profile_eval_f64(&c, t.h * i, &g, NULL, NULL), MDR_OK);
            worst = fmax(worst, fabs(t.node[i].g - g) / gmax);
        }
        printf("    %5d  %.3e\n", m, worst);
        lnN[k] = log(m);
        lnE[k] = log(worst);
    }
    for (k = 0; k < NK; k++) {
        sx += lnN[k];
        sy += lnE[k];
        sxx += lnN[k] * lnN[k];
        sxy += lnN[k] * lnE[k];
    }
    order = -(NK * sxy - sx * sy) / (NK * sxx - sx * sx);
    printf("    fitted order %.2f\n", order);
    assert_true(order >= 2.3);
}

/* The generated const table (mdr table, compiled in) equals the one built at
 * init, bit for bit, and drives the engine the same way. */
static void generated_table_matches(void **st)
{
    const float pf[3] = {1e-6f, 0, 0};
    mdr_table_f32 t;
    (void)st;
    table32(&t, MDR_PROFILE_SPHERE, pf, 64, 0.5e-6f);
    assert_int_equal(gen_tip.n, t.n);
    assert_true(gen_tip.h == t.h);
    assert_int_equal(gen_tip.wall, t.wall);
    assert_memory_equal(gen_tip.node, t.node, MDR_TABLE_BYTES_F32(64));
}

/* Regression (found by make bench): in f32 with 4096 springs, U is flat
 * near a fold to within its rounding error, and the landing scan took the
 * node next to the fold for the landing, which folded again at the same
 * point until the iteration cap (MDR_E_NOCONV). These three cycles of the
 * benchmark matrix (power law under fixed grips; sphere and wavy profile
 * through a machine) now run through every tick and pull off. */
static void f32_fold_landing_rounding(void **st)
{
    static const struct {
        int scene, ctl;
    } cases[] = {{2, MDR_CONTROL_GRIPS}, {4, MDR_CONTROL_MACHINE}, {6, MDR_CONTROL_MACHINE}};
    static bm_scene b;
    size_t k;
    (void)st;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double acc = 0;
        assert_int_equal(bm_scene_init(&b, &scenes[cases[k].scene]), MDR_OK);
        assert_int_equal(bm_tables(&b, 4096), MDR_OK);
        assert_int_equal(bm_engines(&b, cases[k].ctl), MDR_OK);
        assert_int_equal(bm_cycle_f32(&b.e32, cases[k].ctl, &acc), MDR_OK);
        assert_true(isfinite(acc));
    }
}

/* ------------------------------------------------------ coarse tables */

/* The first equilibrium on the way (mdr_engine_t.h: the edge follows U while
 * dU/da > 0, and jumps where it turns), on tables so coarse that the
 * interpolant's g turns inside a spring: 2 to 8 springs of spheres tabulated
 * to 0.5 ... 0.99 R, of a wavy profile over a few wavelengths and of the
 * paraboloid, with and without adhesion, under each control. A helper
 * attacking the engines found the first case (stop 45): a 2-spring sphere
 * table to 0.99 R, a grips tick receding from a = 0.77 L to a much lower d;
 * the edge passed the stable equilibrium inside spring 1 (no node there
 * shows it: U at both ends of the spring is on the same side of d) and a
 * fold after it, and stopped in spring 0, with no event, in every
 * arithmetic. Oracle, written here from the model of mdr_engine_t.h: U(t)
 * of the branch on the table's interpolant, sampled ORACLE_M times per
 * spring from the edge in the direction of motion; the first sample past
 * the control is a root (refined by bisection), a sample below the one
 * before it, before any root, is a fold (a jump). Ticks where the branch's
 * highest point before the oracle's answer comes within TOL_FIRST_TIE of
 * the control (relative to the range of U on the table) are skipped (the
 * sampling cannot tell); the run prints how many. The engine must agree:
 * a root without a jump at the oracle's radius within TOL_FIRST64 /
 * TOL_FIRST32 of L (f64 / f32 engine, each on its own node values: the
 * root of the f64 bisection is to rounding; f32's U carries ~1e-6 of its
 * range, which moves a root by that over the branch's slope, measured
 * below 2e-5), a jump where the oracle meets a fold first, and the edge
 * left where it is where the control lies in the pinned band. */
#define TOL_FIRST64 1e-9
#define TOL_FIRST32 1e-5

/* one engine (f64 or f32: step through the given function pointers) on
 * one table: a random walk of large control steps; returns the ticks the
 * oracle judged, counts per answer in cnt[] */
static void first_eq_case(const mdr_node_f64 *nodes, uint16_t n, double h, double E, double w, double km,
                          uint8_t ctl, int f32, const mdr_table_f64 *t64, const mdr_table_f32 *t32,
                          long cnt[5], double *worst)
{
    mdr_engine_f64 e;
    mdr_engine_f32 e32;
    const double cw = sqrt(2 * PI_ * w / E), cadv = sqrt(2 * PI_ * (w / 2) / E);
    const double al = ctl == MDR_CONTROL_LOAD ? 0.0 : 1.0;
    const double ka = ctl == MDR_CONTROL_GRIPS ? 0.0 : ctl == MDR_CONTROL_LOAD ? 1.0 : 2 * E / km;
    const double us = ctl == MDR_CONTROL_LOAD ? 2 * E : 1.0; /* the control per unit of U */
    const or_branch badv = {al, ka, cadv}, brec = {al, ka, cw};
    double umax = -1e300, umin = 1e300, span;
    unsigned long r = 12345u + 977u * n + 31u * ctl;
    int i;
    for (i = 0; i <= n * ORACLE_M; i++) {
        double x = h * n * i / (n * ORACLE_M);
        double ua = or_U(nodes, n, h, &badv, x, NULL), ur = or_U(nodes, n, h, &brec, x, NULL);
        umax = fmax(umax, fmax(ua, ur));
        umin = fmin(umin, fmin(ua, ur));
    }
    span = umax - umin;
    if (f32) {
        assert_int_equal(mdr_engine_init_f32(&e32, t32, (float)E, (float)w, (float)(w / 2), (float)km), MDR_OK);
    } else {
        assert_int_equal(mdr_engine_init_f64(&e, t64, E, w, w / 2, km), MDR_OK);
    }
    for (i = 0; i < 60; i++) {
        double u, a0, x0, xr = 0, a1;
        int want, contact, jumps;
        r = r * 1103515245u + 12345u;
        /* controls over the range of U up to 0.9 of the table's top (the
         * edge stays inside it), the first one a touch */
        u = i == 0 ? umin + 0.5 * span : umin - 0.05 * span + 0.9 * span * (double)((r >> 8) % 10007u) / 10006.0;
        if (f32) {
            mdr_step_f32 o;
            a0 = e32.a;
            contact = e32.contact;
            assert_int_equal(step32_of(ctl)(&e32, (float)(u * us), &o), MDR_OK);
            a1 = o.a;
            jumps = o.jumps;
            u = (double)(float)(u * us) / us;
        } else {
            mdr_step_f64 o;
            a0 = e.a;
            contact = e.contact;
            assert_int_equal(step64_of(ctl)(&e, u * us, &o), MDR_OK);
            a1 = o.a;
            jumps = o.jumps;
        }
        if (!contact) {
            continue;
        }
        x0 = a0;
        want = or_tick(nodes, n, h, al, ka, cadv, cw, x0, u, span, &xr);
        cnt[want]++;
        if (want == OR_ROOT) {
            double err = fabs(a1 - xr) / (h * n);
            if (jumps != 0 || err > (f32 ? TOL_FIRST32 : TOL_FIRST64)) {
                printf("  n %u ctl %u %s w %g: tick %d from a = %.9g to u = %.9g: oracle root a = %.9g, "
                       "engine a = %.9g, %d jumps\n",
                       n, ctl, f32 ? "f32" : "f64", w, i, a0, u, xr, a1, jumps);
            }
            assert_int_equal(jumps, 0);
            assert_true(err <= (f32 ? TOL_FIRST32 : TOL_FIRST64));
            *worst = fmax(*worst, err);
        } else if (want == OR_FOLD) {
            if (jumps == 0) {
                printf("  n %u ctl %u %s w %g: tick %d from a = %.9g to u = %.9g: oracle fold first, engine "
                       "a = %.9g without a jump\n",
                       n, ctl, f32 ? "f32" : "f64", w, i, a0, u, a1);
            }
            assert_true(jumps >= 1);
        } else if (want == OR_PINNED) {
            assert_true(a1 == a0);
        }
    }
}

static void first_equilibrium_coarse_tables(void **st)
{
    static const uint16_t ns[] = {2, 3, 4, 6, 8};
    const double R = 4.35e-5, E = 2.87e6;
    long cnt[2][5] = {{0}};
    double worst[2] = {0, 0};
    int pk, wi, f32;
    size_t in;
    uint8_t ctl;
    (void)st;
    for (pk = 0; pk < 5; pk++) {
        for (in = 0; in < sizeof ns / sizeof ns[0]; in += TGT_STRIDE) {
            const uint16_t n = ns[in];
            static const double lr[3] = {0.99, 0.9, 0.5};
            const uint8_t kind = pk < 3 ? MDR_PROFILE_SPHERE : pk == 3 ? MDR_PROFILE_WAVY : MDR_PROFILE_PARABOLOID;
            const double p[3] = {R, pk == 3 ? 0.02 * R : 0, pk == 3 ? 0.3 * R : 0};
            const float pf[3] = {(float)p[0], (float)p[1], (float)p[2]};
            const double L = pk < 3 ? lr[pk] * R : 0.9 * R;
            mdr_table_f64 t;
            mdr_table_f32 t32;
            static mdr_node_f64 n32d[MDR_TABLE_NODES(8)];
            int j;
            table64(&t, kind, p, n, L);
            table32(&t32, kind, pf, n, (float)L);
            for (j = 0; j <= n; j++) {
                n32d[j].g = t32.node[j].g;
                n32d[j].G = t32.node[j].G;
                n32d[j].t = t32.node[j].t;
                n32d[j].q = t32.node[j].q;
            }
            for (wi = 0; wi < 2; wi++) {
                /* no adhesion; adhesion with 2 pi w/(E* R) = 0.05 */
                const double w = wi == 0 ? 0.0 : 0.05 * E * R / (2 * PI_);
                for (ctl = (int)MDR_CONTROL_LOAD; ctl <= (int)MDR_CONTROL_MACHINE; ctl++) {
                    const double km = ctl == MDR_CONTROL_MACHINE ? 2 * E * L : 0.0; /* kappa L = 1 */
                    for (f32 = 0; f32 < 2; f32++) {
                        first_eq_case(f32 ? n32d : t.node, n, f32 ? (double)t32.h : t.h, E, w, km, ctl, f32,
                                      &t, &t32, cnt[f32], &worst[f32]);
                    }
                }
            }
        }
    }
    for (f32 = 0; f32 < 2; f32++) {
        printf("  %s: %ld roots (worst %.1e of L, tolerance %.0e), %ld folds, %ld pinned, %ld to an end, %ld "
               "ties skipped\n",
               f32 ? "f32" : "f64", cnt[f32][OR_ROOT], worst[f32], f32 ? TOL_FIRST32 : TOL_FIRST64,
               cnt[f32][OR_FOLD], cnt[f32][OR_PINNED], cnt[f32][OR_END], cnt[f32][OR_TIE]);
        assert_true(cnt[f32][OR_ROOT] > 500 && cnt[f32][OR_FOLD] > 50);
    }
}

/* ------------------------------------------------------ errors */

static void engine_errors(void **st)
{
    const double pd[3] = {JR, 0, 0};
    mdr_table_f64 t64, bad;
    mdr_engine_f64 e, keep;
    mdr_step_f64 o;
    double r[5] = {0, 1e-7, 2e-7, 3e-7, 4e-7}, f[5] = {0, 1e-9, 4e-9, 9e-9, 16e-9}, g[5] = {0};
    (void)st;
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 64, 3e-6);
    /* table builders */
    assert_int_equal(mdr_table_init_profile_f64(NULL, nodes64, 64, NULL, 1e-6), MDR_E_NULL);
    {
        mdr_contact_f64 c;
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, pd, 1, 0), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f64(&bad, nodes64, 1, &c, 1e-6), MDR_E_SIZE);
        assert_int_equal(mdr_table_init_profile_f64(&bad, nodes64, MDR_SPRINGS_MAX + 1, &c, 1e-6),
                         MDR_E_SIZE);
        assert_int_equal(mdr_table_init_profile_f64(&bad, nodes64, 64, &c, NAN), MDR_E_NONFINITE);
        assert_int_equal(mdr_table_init_profile_f64(&bad, nodes64, 64, &c, -1e-6), MDR_E_RADIUS);
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_SPHERE, pd, 1, 0), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f64(&bad, nodes64, 64, &c, 2 * JR), MDR_E_RADIUS);
    }
    assert_int_equal(mdr_table_init_gap_f64(&bad, nodes64, 64, r, f, 2), MDR_E_TABLE);
    r[2] = 1e-7; /* not strictly increasing */
    assert_int_equal(mdr_table_init_gap_f64(&bad, nodes64, 64, r, f, 5), MDR_E_TABLE);
    r[2] = 2e-7;
    r[0] = 1e-8; /* does not start at r = 0 */
    assert_int_equal(mdr_table_init_gap_f64(&bad, nodes64, 64, r, f, 5), MDR_E_TABLE);
    r[0] = 0;
    f[3] = INFINITY;
    assert_int_equal(mdr_table_init_gap_f64(&bad, nodes64, 64, r, f, 5), MDR_E_NONFINITE);
    f[3] = 9e-9;
    assert_int_equal(mdr_table_init_gap_f64(&bad, nodes64, MDR_SPRINGS_MAX + 1, r, f, 5), MDR_E_SIZE);
    assert_int_equal(mdr_table_init_gap_f64(&bad, nodes64, 64, r, NULL, 5), MDR_E_NULL);
    assert_int_equal(mdr_table_init_g_f64(&bad, nodes64, 4, 1e-7, g), MDR_OK);
    g[0] = 1e-9;
    assert_int_equal(mdr_table_init_g_f64(&bad, nodes64, 4, 1e-7, g), MDR_E_TABLE);
    g[0] = 0;
    assert_int_equal(mdr_table_init_g_f64(&bad, nodes64, 4, 0.0, g), MDR_E_PARAM);
    assert_int_equal(mdr_table_init_g_f64(&bad, nodes64, 4, NAN, g), MDR_E_NONFINITE);
    g[2] = NAN;
    assert_int_equal(mdr_table_init_g_f64(&bad, nodes64, 4, 1e-7, g), MDR_E_NONFINITE);
    table64(&t64, MDR_PROFILE_PARABOLOID, pd, 64, 3e-6);
    /* engine init */
    assert_int_equal(mdr_engine_init_f64(&e, NULL, JE, JW, 0, 0), MDR_E_NULL);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, NAN, JW, 0, 0), MDR_E_NONFINITE);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, INFINITY, 0, 0), MDR_E_NONFINITE);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, -JE, JW, 0, 0), MDR_E_PARAM);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, -JW, 0, 0), MDR_E_PARAM);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 2 * JW, 0), MDR_E_PARAM);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, -JW, 0), MDR_E_PARAM);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 0, -1.0), MDR_E_CONTROL);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 0, INFINITY), MDR_E_NONFINITE);
    /* a machine beyond the arithmetic: 2E* / k_m (kappa) or 1/k_m not
     * finite (k_m subnormal), refused as the scene refuses it (the shared
     * mdr_e_material), the instance untouched */
    keep = e;
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 0, 1e-305), MDR_E_CONTROL);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, 1e-300, 0, 0, 1e-310), MDR_E_CONTROL);
    assert_memory_equal(&e, &keep, sizeof e);
    /* w / E* beyond the range (c_w = sqrt(2 pi w / E*) infinite): refused,
     * as mdr_contact_init refuses it, in both arithmetics and for w_adv */
    keep = e;
    assert_int_equal(mdr_engine_init_f64(&e, &t64, 1e-300, 1e300, 0, 0), MDR_E_PARAM);
    assert_int_equal(mdr_engine_init_f64(&e, &t64, 1e-300, 1e300, 1e300, 0), MDR_E_PARAM);
    assert_memory_equal(&e, &keep, sizeof e);
    {
        static mdr_node_f32 n32w[MDR_TABLE_NODES(64)];
        const float pf[3] = {(float)JR, 0, 0};
        mdr_contact_f32 cf;
        mdr_table_f32 t32;
        mdr_engine_f32 e32, k32;
        assert_int_equal(mdr_contact_init_f32(&cf, MDR_PROFILE_PARABOLOID, pf, (float)JE, (float)JW), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t32, n32w, 64, &cf, 3e-6f), MDR_OK);
        memset(&e32, 0x5a, sizeof e32);
        k32 = e32;
        assert_int_equal(mdr_contact_init_f32(&cf, MDR_PROFILE_PARABOLOID, pf, 1e-38f, 3e38f), MDR_E_PARAM);
        assert_int_equal(mdr_engine_init_f32(&e32, &t32, 1e-38f, 3e38f, 0, 0), MDR_E_PARAM);
        assert_int_equal(mdr_engine_init_f32(&e32, &t32, 1e-38f, 3e38f, 3e38f, 0), MDR_E_PARAM);
        assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)JE, (float)JW, 0, 1e-38f), MDR_E_CONTROL);
        assert_int_equal(mdr_engine_init_f32(&e32, &t32, 1e-30f, 0, 0, 1e-39f), MDR_E_CONTROL);
        assert_memory_equal(&e32, &k32, sizeof e32);
        {
            static const float mf[][4] = {{1e-38f, 3e38f, 0, 0},     {1e-38f, 3e38f, 3e38f, 0}, {(float)JE, (float)JW, 0, 1e-38f},
                                          {1e-30f, 0, 0, 1e-39f},    {(float)JE, (float)JW, 0, 0}, {(float)JE, -1.0f, 0, 0},
                                          {(float)JE, (float)JW, 0.2f, 0}, {(float)JE, (float)JW, 0, 0.2f}};
            size_t i;
            for (i = 0; i < sizeof mf / sizeof mf[0]; i++) {
                const mdr_status st = mdr_engine_check_f32(mf[i][0], mf[i][1], mf[i][2], mf[i][3]);
                assert_int_equal(st, mdr_engine_init_f32(&e32, &t32, mf[i][0], mf[i][1], mf[i][2], mf[i][3]));
                assert_true(i == 4 || i == 7 ? st == MDR_OK : st != MDR_OK);
            }
        }
    }
    /* mdr_engine_check: the init's material and machine checks alone, the
     * same status for each (the Python package refuses an Engine's
     * settings with it where they are given) */
    {
        static const double mat[][4] = {{JE, JW, 0, 0},        {NAN, JW, 0, 0},      {JE, INFINITY, 0, 0},
                                        {-JE, JW, 0, 0},       {JE, -JW, 0, 0},      {JE, JW, 2 * JW, 0},
                                        {JE, JW, -JW, 0},      {JE, JW, 0, -1.0},    {JE, JW, 0, INFINITY},
                                        {JE, JW, 0, 1e-305},   {1e-300, 0, 0, 1e-310}, {1e-300, 1e300, 0, 0},
                                        {1e-300, 1e300, 1e300, 0}, {JE, JW, JW, 0.2}};
        size_t i;
        for (i = 0; i < sizeof mat / sizeof mat[0]; i++) {
            const mdr_status st = mdr_engine_check_f64(mat[i][0], mat[i][1], mat[i][2], mat[i][3]);
            assert_int_equal(st, mdr_engine_init_f64(&e, &t64, mat[i][0], mat[i][1], mat[i][2], mat[i][3]));
            assert_true(i == 0 || i == 13 ? st == MDR_OK : st != MDR_OK);
        }
    }
    bad = t64;
    bad.n = MDR_SPRINGS_MAX + 1;
    assert_int_equal(mdr_engine_init_f64(&e, &bad, JE, JW, 0, 0), MDR_E_SIZE);
    /* steps: bad input leaves the state unchanged */
    assert_int_equal(mdr_engine_init_f64(&e, &t64, JE, JW, 0, 0), MDR_OK);
    assert_int_equal(mdr_engine_step_d_f64(&e, 0.2e-6, &o), MDR_OK);
    keep = e;
    assert_int_equal(mdr_engine_step_d_f64(&e, NAN, &o), MDR_E_NONFINITE);
    assert_int_equal(mdr_engine_step_F_f64(&e, INFINITY, &o), MDR_E_NONFINITE);
    assert_int_equal(mdr_engine_step_z_f64(&e, -INFINITY, &o), MDR_E_NONFINITE);
    assert_int_equal(mdr_engine_step_z_f64(&e, 0.1e-6, &o), MDR_E_CONTROL); /* no machine */
    assert_int_equal(mdr_engine_step_d_f64(NULL, 0.1e-6, &o), MDR_E_NULL);
    assert_int_equal(mdr_engine_step_d_f64(&e, 0.1e-6, NULL), MDR_E_NULL);
    assert_int_equal(mdr_engine_step_z_f64(&e, -0.1e-6, &o), MDR_E_CONTROL);
    assert_int_equal(mdr_engine_step_z_f64(NULL, 0.1e-6, &o), MDR_E_NULL);
    assert_int_equal(mdr_engine_step_F_f64(&e, 0.1e-6, NULL), MDR_E_NULL);
    assert_memory_equal(&e, &keep, sizeof e);
    {
        /* separated, without a machine: no z is a separated tick, whatever
         * its sign (the step's fast path must not answer it) */
        mdr_engine_f64 e2, keep2;
        mdr_engine_f32 f2;
        mdr_table_f32 t32;
        mdr_step_f32 o32;
        const float p32[3] = {(float)JR, 0, 0};
        assert_int_equal(mdr_engine_init_f64(&e2, &t64, JE, JW, 0, 0), MDR_OK);
        assert_int_equal(mdr_engine_outputs_f64(&e2, MDR_OUT_FORCE), MDR_OK);
        keep2 = e2;
        assert_int_equal(mdr_engine_step_z_f64(&e2, 0.0, &o), MDR_E_CONTROL);
        assert_int_equal(mdr_engine_step_z_f64(&e2, -0.1e-6, &o), MDR_E_CONTROL);
        assert_int_equal(mdr_engine_step_z_f64(&e2, NAN, &o), MDR_E_NONFINITE);
        assert_memory_equal(&e2, &keep2, sizeof e2);
        table32(&t32, MDR_PROFILE_PARABOLOID, p32, 64, 2e-6f);
        assert_int_equal(mdr_engine_init_f32(&f2, &t32, (float)JE, (float)JW, 0, 0), MDR_OK);
        assert_int_equal(mdr_engine_outputs_f32(&f2, MDR_OUT_FORCE), MDR_OK);
        assert_int_equal(mdr_engine_step_z_f32(&f2, -0.1e-6f, &o32), MDR_E_CONTROL);
        assert_int_equal(mdr_engine_step_z_f32(&f2, 0.0f, &o32), MDR_E_CONTROL);
        assert_int_equal(f2.flags, 0);
        assert_int_equal(f2.mode, 0);
        /* with a machine the same z is a separated tick: d = z, F = 0 */
        assert_int_equal(mdr_engine_init_f32(&f2, &t32, (float)JE, (float)JW, 0, 1.0f), MDR_OK);
        assert_int_equal(mdr_engine_outputs_f32(&f2, MDR_OUT_FORCE), MDR_OK);
        assert_int_equal(mdr_engine_step_z_f32(&f2, -0.1e-6f, &o32), MDR_OK);
        assert_true(o32.d == -0.1e-6f && o32.F == 0.0f && f2.d == -0.1e-6f);
        assert_int_equal(mdr_engine_step_z_f32(&f2, -INFINITY, &o32), MDR_E_NONFINITE);
    }
    /* outside the table: named status, sticky flag, state unchanged */
    assert_int_equal(mdr_engine_step_d_f64(&e, 1e-6, &o), MDR_E_OUTSIDE);
    assert_int_equal(e.flags, MDR_FLAG_OUTSIDE);
    e.flags = 0;
    assert_memory_equal(&e, &keep, sizeof e);
    e.flags = MDR_FLAG_OUTSIDE;
    assert_int_equal(mdr_engine_step_d_f64(&e, 0.25e-6, &o), MDR_OK); /* still usable */
    assert_int_equal(e.flags, MDR_FLAG_OUTSIDE);                        /* and sticky */
    assert_int_equal(mdr_engine_clear_flags_f64(&e), MDR_FLAG_OUTSIDE);
    assert_int_equal(e.flags, 0);
    assert_string_equal(mdr_status_str(MDR_E_OUTSIDE), "contact edge beyond the last spring of the table");
    assert_string_equal(mdr_event_str(MDR_EV_PULL_OFF), "pull-off");
    assert_string_equal(mdr_event_str(200), "unknown event");
}

/* A flat's rim inside spring 0 (the table's rim0; mdr_edge_table.inc's
 * landings): the flattened tip (seed 4.80-4.83), R = 1 um, E* = 1 GPa, on
 * 64 springs of h = 10 nm, the rim b from 0.01 h to 0.99 h (rim0) and at
 * 1 h and 2.5 h (on a node), w from a paraboloid-like pull-off radius a*
 * of 0.2 h to 30 h (w = 8 E* a*^3/(9 pi R^2)). The pull-off of a
 * decreasing control from a contact of 0.7 x_max is the least of the
 * closed forms d(a) = (a/R) sqrt(a^2 - b^2) - sqrt(2 pi a w/E*) (grips) and
 * F(a) = 2 E* (2a^2 + b^2) sqrt(a^2 - b^2)/(3R) - sqrt(8 pi a^3 E* w) (load)
 * over a >= b (below b, -sqrt(2 pi a w/E*) and -sqrt(8 pi a^3 E* w) are
 * above their values at b), found here by a scan and golden sections.
 * Each f32 and f64 init on a rim0 table either refuses (MDR_E_PARAM, the
 * instance unchanged) or pulls off under both controls within TOL_RIM0 of
 * the closed forms' least d and F (the controlled variable's pull-off
 * value; the other one, d under load and F under grips, is ill-conditioned
 * where the rim's fold and the sphere-like one are nearly as deep, and
 * moves between them); every table whose true pull-off (either control)
 * lies inside spring 0 is refused, as is its q31 table's init, and no
 * accepted one pulls off there (the engine's pull-off radius at least h); a
 * rim on a node is never refused. Before the check, the f64 engine pulled
 * off at 3% of Kendall's force (b = 0.99 h: the CLI's case in
 * docs/accuracy.md).
 * Measured: 116 of 204 inits refused, worst accepted 5.6e-3 (b = 0.99 h,
 * a* = 3.35 h, grips: the springs' resolution a few springs above the rim,
 * 8.1e-3 there with the rim on node 1, 3.4e-2 at a* = 1.79 h); TOL_RIM0 =
 * 1e-2. */
#define TOL_RIM0 1e-2

/* the flattened tip's closed forms (seed 4.82, 4.83) */
static double ft_d(double a, double R, double b, double c)
{
    return a / R * sqrt(a * a - b * b) - c * sqrt(a);
}

static double ft_F(double a, double R, double b, double E, double w)
{
    return 2 * E / (3 * R) * (2 * a * a + b * b) * sqrt(a * a - b * b) - sqrt(8 * PI_ * a * a * a * E * w);
}

/* the least of d (load: F) over [b, L], at *am: a scan of 20 000 points, then
 * golden sections around the least */
static double ft_min(int load, double R, double b, double E, double w, double L, double *am)
{
    const double c = sqrt(2 * PI_ * w / E), gr = (sqrt(5.0) - 1) / 2;
    double best = 0, lo, hi, x1, x2, f1, f2;
    int i, k = 0;
    for (i = 0; i <= 20000; i++) {
        const double a = b + (L - b) * i / 20000.0, v = load ? ft_F(a, R, b, E, w) : ft_d(a, R, b, c);
        if (i == 0 || v < best) {
            best = v;
            k = i;
        }
    }
    lo = b + (L - b) * (k > 0 ? k - 1 : 0) / 20000.0;
    hi = b + (L - b) * (k < 20000 ? k + 1 : 20000) / 20000.0;
    x1 = hi - gr * (hi - lo);
    x2 = lo + gr * (hi - lo);
    f1 = load ? ft_F(x1, R, b, E, w) : ft_d(x1, R, b, c);
    f2 = load ? ft_F(x2, R, b, E, w) : ft_d(x2, R, b, c);
    for (i = 0; i < 100; i++) {
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - gr * (hi - lo);
            f1 = load ? ft_F(x1, R, b, E, w) : ft_d(x1, R, b, c);
        } else {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + gr * (hi - lo);
            f2 = load ? ft_F(x2, R, b, E, w) : ft_d(x2, R, b, c);
        }
    }
    *am = f1 < f2 ? x1 : x2;
    best = fmin(best, fmin(f1, f2));
    if (k == 0) { /* at the rim */
        *am = b;
    }
    return best;
}

/* The f64 (m = 0) or f32 (m = 1) engine of a table pair initialised on
 * painted instances (0x5a), w_adv = 0, no machine: its status; a refusal
 * leaves the instance as it was. */
static mdr_status init_either(int m, mdr_engine_f64 *e64, const mdr_table_f64 *t64, mdr_engine_f32 *e32,
                              const mdr_table_f32 *t32, double E, double w)
{
    mdr_engine_f64 s64;
    mdr_engine_f32 s32;
    mdr_status r;
    memset(&s64, 0x5a, sizeof s64);
    memset(&s32, 0x5a, sizeof s32);
    *e64 = s64;
    *e32 = s32;
    r = m == 0 ? mdr_engine_init_f64(e64, t64, E, w, 0, 0)
               : mdr_engine_init_f32(e32, t32, (float)E, (float)w, 0.0f, 0);
    if (r != MDR_OK) {
        assert_memory_equal(e64, &s64, sizeof s64);
        assert_memory_equal(e32, &s32, sizeof s32);
    }
    return r;
}

/* That engine (initialised) through a grips cycle 0 -> dt -> d1 and, from a
 * fresh init, a load cycle 0 -> Ft -> F1 (2000 ticks out, n1 back): each
 * pulls off on the way back; the state before the jump, {d0, F0, a0}, in
 * g[] and l[] */
static void pull_offs(int m, mdr_engine_f64 *e64, const mdr_table_f64 *t64, mdr_engine_f32 *e32,
                      const mdr_table_f32 *t32, double E, double w, double dt, double d1, double Ft, double F1,
                      long n1, double g[3], double l[3])
{
    mdr_step_f64 p64;
    mdr_step_f32 p32;
    if (m == 0) {
        assert_true(run64(e64, MDR_CONTROL_GRIPS, 0, dt, 2000, &p64, NULL) == 0);
        assert_true(run64(e64, MDR_CONTROL_GRIPS, dt, d1, n1, &p64, NULL));
        g[0] = p64.d0, g[1] = p64.F0, g[2] = p64.a0;
        assert_int_equal(mdr_engine_init_f64(e64, t64, E, w, 0, 0), MDR_OK);
        assert_true(run64(e64, MDR_CONTROL_LOAD, 0, Ft, 2000, &p64, NULL) == 0);
        assert_true(run64(e64, MDR_CONTROL_LOAD, Ft, F1, n1, &p64, NULL));
        l[0] = p64.d0, l[1] = p64.F0, l[2] = p64.a0;
    } else {
        assert_true(run32(e32, MDR_CONTROL_GRIPS, 0, dt, 2000, &p32) == 0);
        assert_true(run32(e32, MDR_CONTROL_GRIPS, dt, d1, n1, &p32));
        g[0] = p32.d0, g[1] = p32.F0, g[2] = p32.a0;
        assert_int_equal(mdr_engine_init_f32(e32, t32, (float)E, (float)w, 0.0f, 0), MDR_OK);
        assert_true(run32(e32, MDR_CONTROL_LOAD, 0, Ft, 2000, &p32) == 0);
        assert_true(run32(e32, MDR_CONTROL_LOAD, Ft, F1, n1, &p32));
        l[0] = p32.d0, l[1] = p32.F0, l[2] = p32.a0;
    }
}

#ifndef MDR_TARGET_TEST /* (host only: the registration below) */
/* A power law C r^n with n neither 1 nor 2 (helper-23's attack, stop 56):
 * spring 0's quadratic is not its g, and a pull-off inside spring 0 came
 * out O(1) off with MDR_OK (n = 1.5: -73 % with springs 16 to 30 times the
 * pull-off radius wide; n = 0.75 with the true fold at half a spring: a
 * fold found in spring 1, the force 2.6 times the true one). On 64 springs
 * from 1/8 to 32 times the grips pull-off radius wide (C for a pull-off
 * radius near 100 nm), n = 0.75, 1.5, 2.5, 3 (flagged rim0 = 2) and 1, 2
 * (not flagged), f64 and f32: every init is refused (MDR_E_PARAM, the
 * instance unchanged) or pulls off under grips and under load (where the
 * cycle's top, a = 0.3 L, lies beyond that control's fold) within
 * TOL_POW0 = 3e-2 of mdr_critical_f64's force (measured 2.1e-2: n = 0.75
 * with the fold two springs out, the springs' own resolution of so coarse
 * a table); refused and accepted inits both occur, and n = 1, 2 (spring 0
 * exact) are never refused. */
#define TOL_POW0 3e-2
static void powerlaw_pull_off_spring0(void **st)
{
    static const double ns[] = {0.75, 1.5, 2.5, 3.0, 1.0, 2.0};
    static const double wr[] = {0.125, 0.5, 0.9, 2.0, 8.0, 32.0}; /* spring width / grips pull-off radius */
    const double E = 1e6, w = 0.05;
    double worst = 0;
    int refused = 0, accepted = 0;
    unsigned i, j, m;
    (void)st;
    for (i = 0; i < sizeof ns / sizeof ns[0]; i++) {
        /* C for a pull-off radius near 100 nm: C a^n ~ sqrt(2 pi w/E*) a^(1/2) */
        const double p[3] = {sqrt(2 * PI_ * 0.05 / 1e6) * pow(1e-7, 0.5 - ns[i]), ns[i], 0};
        const int exact = ns[i] == 1.0 || ns[i] == 2.0;
        mdr_contact_f64 c;
        mdr_critstate_f64 cg, cl;
        double a0;
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_POWERLAW, p, E, w), MDR_OK);
        assert_int_equal(mdr_default_start_f64(&c, &a0), MDR_OK);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_GRIPS, 0, a0, &cg), MDR_OK);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_LOAD, 0, a0, &cl), MDR_OK);
        for (j = 0; j < sizeof wr / sizeof wr[0]; j++) {
            const double h = wr[j] * cg.a, L = 64 * h;
            const float pf[3] = {(float)p[0], (float)ns[i], 0};
            mdr_contact_f32 c32;
            mdr_table_f64 t64;
            mdr_table_f32 t32;
            mdr_eqstate_f64 top;
            double dt, Ft;
            assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_POWERLAW, pf, (float)E, (float)w), MDR_OK);
            assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, 64, &c, L), MDR_OK);
            assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, 64, &c32, (float)L), MDR_OK);
            assert_int_equal(t64.rim0, exact ? 0 : 2);
            assert_int_equal(t32.rim0, exact ? 0 : 2);
            assert_int_equal(mdr_eq_f64(&c, 0.3 * L, &top), MDR_OK);
            /* the approach (w_adv = 0: d = g(a)) to a = 0.3 L: d = g there,
             * F = F_eq + 2 E* a (d - d_eq) (F linear in d at fixed a) */
            assert_int_equal(mdr_profile_eval_f64(&c, 0.3 * L, &dt, NULL, NULL), MDR_OK);
            Ft = top.F + 2 * E * top.a * (dt - top.d);
            for (m = 0; m < 2; m++) { /* 0: f64, 1: f32 */
                mdr_engine_f64 e64;
                mdr_engine_f32 e32;
                double g[3], l[3], Fg, Fl, err;
                mdr_status r = init_either((int)m, &e64, &t64, &e32, &t32, E, w);
                if (r != MDR_OK) {
                    assert_int_equal(r, MDR_E_PARAM);
                    assert_false(exact);
                    refused++;
                    continue;
                }
                accepted++;
                pull_offs((int)m, &e64, &t64, &e32, &t32, E, w, dt, cg.d - dt, Ft, 2 * cl.F, 4000, g, l);
                Fg = g[1];
                Fl = l[1];
                /* (a control's pull-off judged where the cycle's top, a = 0.3 L,
                 * lies beyond its fold: n = 0.75's under load, 81 times the grips
                 * pull-off radius, is beyond the table's end here) */
                err = fmax(0.3 * L > 1.5 * cg.a ? fabs(Fg / cg.F - 1) : 0.0,
                           0.3 * L > 1.5 * cl.a ? fabs(Fl / cl.F - 1) : 0.0);
                if (!(err <= TOL_POW0)) {
                    print_message("n = %.2f, spring %.3g pull-off radii wide, %s: grips F %.3e, load F %.3e off\n",
                                  ns[i], wr[j], m ? "f32" : "f64", Fg / cg.F - 1, Fl / cl.F - 1);
                }
                worst = fmax(worst, err);
                assert_true(err <= TOL_POW0);
            }
        }
    }
    print_message("power laws n = 0.75..3 on 64 springs 1/8..32 pull-off radii wide: %d inits refused, %d "
                  "accepted, worst accepted %.2e of mdr_critical's pull-off force\n",
                  refused, accepted, worst);
    assert_true(refused > 0 && accepted > 0);
}
#endif

static void rim_in_spring0(void **st)
{
    static const double bh[] = {0.01, 0.1, 0.3, 0.6, 0.9, 0.99, 1.0, 2.5};
    static mdr_node_q31 nq[MDR_TABLE_NODES(64)];
    const double R = 1e-6, E = 1e9, h = 10e-9, L = 64 * h;
    double worst = 0;
    int refused = 0, accepted0 = 0;
    unsigned i, j, m;
    (void)st;
    for (i = 0; i < sizeof bh / sizeof bh[0]; i++) {
        const double b = bh[i] * h;
        const double pd[3] = {R, b, 0};
        const float pf[3] = {(float)R, (float)b, 0};
        mdr_contact_f64 c64;
        mdr_contact_f32 c32;
        mdr_table_f64 t64;
        mdr_table_f32 t32;
        mdr_table_q31 tq;
        assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_FLATTIP, pd, 1.0, 0.0), MDR_OK);
        assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_FLATTIP, pf, 1.0f, 0.0f), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, 64, &c64, L), MDR_OK);
        assert_int_equal(mdr_table_init_profile_f32(&t32, nodes32, 64, &c32, (float)L), MDR_OK);
        assert_int_equal(t64.rim0, bh[i] < 1.0);
        assert_int_equal(t32.rim0, bh[i] < 1.0);
        memset(&tq, 0x5a, sizeof tq);
        assert_int_equal(mdr_table_q31_from_f64(&tq, nq, &t64), MDR_OK);
        assert_int_equal(tq.rim0, t64.rim0);
        for (j = 0; j <= 16; j += TGT_STRIDE) {
            const double as = h * 0.2 * pow(150.0, j / 16.0), w = 8 * E * as * as * as / (9 * PI_ * R * R);
            const double top = 0.7 * L, dt = ft_d(top, R, b, 0), Ft = ft_F(top, R, b, E, 0);
            double ag, al, dmin, Fmin, dF, Fd;
            int in0;
            dmin = ft_min(0, R, b, E, w, L, &ag);
            Fmin = ft_min(1, R, b, E, w, L, &al);
            dF = ft_F(ag, R, b, E, w); /* the force at the grips pull-off */
            Fd = ft_d(al, R, b, sqrt(2 * PI_ * w / E));
            in0 = ag < h || al < h;
            for (m = 0; m < 2; m++) { /* 0: f64, 1: f32 */
                mdr_engine_f64 e64;
                mdr_engine_f32 e32;
                double g[3], l[3], Fg, dg, Fl, dl, ag_e, al_e, err; /* (ag_e, al_e: the engine's pull-off radii) */
                mdr_status r = init_either((int)m, &e64, &t64, &e32, &t32, E, w);
                if (r != MDR_OK) {
                    assert_int_equal(r, MDR_E_PARAM);
                    assert_true(bh[i] < 1.0); /* a rim on a node: never */
                    refused++;
                    continue;
                }
                if (in0) {
                    print_message("b = %.2f h, a* = %.2f h, %s: the pull-off at a = %.2f h (grips), %.2f h "
                                  "(load), inside spring 0, accepted\n",
                                  bh[i], as / h, m ? "f32" : "f64", ag / h, al / h);
                }
                assert_false(in0);
                accepted0 += bh[i] < 1.0;
                pull_offs((int)m, &e64, &t64, &e32, &t32, E, w, dt, 2 * dmin, Ft, 2 * Fmin, 2000, g, l);
                dg = g[0], Fg = g[1], ag_e = g[2];
                dl = l[0], Fl = l[1], al_e = l[2];
                if (bh[i] >= 1.0) {
                    continue; /* (a rim on a node: its springs' resolution, rim_pull_off_f32) */
                }
                /* an accepted rim0 table never pulls off inside spring 0 */
                assert_true(ag_e >= h && al_e >= h);
                err = fmax(fabs(dg / dmin - 1), fabs(Fl / Fmin - 1));
                if (!(err <= TOL_RIM0)) {
                    print_message("b = %.2f h, a* = %.2f h, %s: grips %.3e (F %.3e), load %.3e (d %.3e)\n", bh[i],
                                  as / h, m ? "f32" : "f64", dg / dmin - 1, Fg / dF - 1, Fl / Fmin - 1, dl / Fd - 1);
                }
                worst = fmax(worst, err);
                assert_true(err <= TOL_RIM0);
            }
            if (in0) {
                mdr_engine_q31 q;
                assert_int_equal(mdr_engine_init_q31_f64(&q, &tq, E, w, 0, 0), MDR_E_PARAM);
            }
        }
    }
    print_message("flattened tip, rim at 0.01..2.5 springs, 17 adhesions: %d inits refused, %d accepted with the "
                  "rim inside spring 0; worst accepted %.2e against the closed forms\n",
                  refused, accepted0, worst);
    assert_true(refused > 0 && accepted0 > 0);
}

/* The same flattened tip sampled (R = 1 um, b = 5 nm, f = 0 to b, then
 * (r^2 - b^2)/(2R)), its rim on a sample or 0.2, 0.5, 0.65 of an interval
 * past one, with 1, 2, 3 and 10 intervals on the flat, tabulated on 64
 * springs to 450 nm (h = 7 nm > b) by mdr_table_init_gap and through the
 * tabulated contact profile: every table flagged rim0 (the kink test sees
 * the rim only on a sample with at least 4 flat intervals; the end of the
 * samples' flat is flagged too: a helper's attack, stop 53, had such a worn
 * tip pull off at 15% of Kendall's d, exit 0), and the f32 and f64 inits
 * with w = 1e-8 J/m^2, E* = 1 GPa (the closed forms' pull-off at the rim,
 * in spring 0) refused. Samples of the paraboloid (no flat) are not flagged.
 * On 1 024 springs (the rim outside spring 0) the tabulated contact's
 * table pulls off under grips within TOL_RIM_SAMPLED = 0.06 of the gap
 * table of the same samples (measured 0.048: the tables' springs differ,
 * the contact's to 450 nm, the gap's to the last sample; both 0.66 to 0.94
 * of Kendall's d with 1 to 3 flat intervals, the samples' own resolution
 * of a rim between them),
 * and with 10 flat intervals both tables within TOL_RIM_SAMPLED10 = 0.08 of
 * Kendall's d (measured 0.062 and 0.0625). Before the tabulated contact's tables raised convex
 * samples' falling nodes (as mdr_table_init_gap's do), they kept the
 * model's dip before the rim and pulled off at 1.9 (10.5 flat intervals)
 * and 4.0 (3) times Kendall's d. */
#define TOL_RIM_SAMPLED 0.06
#define TOL_RIM_SAMPLED10 0.08
static void rim_in_spring0_sampled(void **st)
{
    double worst = 0, worst10 = 0;
    static const double fr[] = {0, 0.2, 0.5, 0.65};
    static const double kf[] = {1, 2, 3, 10};
    static double r[2000], f[2000], sl[2000];
    static float r32[2000], f32[2000];
    const double R = 1e-6, b = 5e-9, L = 4.5e-7, E = 1e9, w = 1e-8;
    unsigned i, j, k, m, par;
    (void)st;
    for (par = 0; par < 2; par++) {
        for (i = 0; i < 4; i++) {
            for (j = 0; j < 4; j++) {
                const double dr = b / (kf[i] + fr[j]);
                mdr_table_f64 t64;
                mdr_table_f32 t32;
                mdr_contact_f64 c64;
                mdr_engine_f64 e64;
                mdr_engine_f32 e32;
                double am;
#ifdef MDR_TARGET_TEST
                if (i != j || (par && i == 3)) { /* (the target: the diagonal, every flat count and rim
                               * offset once, the paraboloid's 961 samples not (the same test of rim0 as
                               * at the other three; 4 s); its soft double took 58 s of QEMU for the 16;
                               * the host runs all) */
                    continue;
                }
#endif
                m = (unsigned)(L / dr) + 3u;
                assert_true(m <= 2000u);
                for (k = 0; k < m; k++) {
                    r[k] = k * dr;
                    f[k] = par ? r[k] * r[k] / (2 * R) : r[k] <= b ? 0 : (r[k] * r[k] - b * b) / (2 * R);
                    r32[k] = (float)r[k];
                    f32[k] = (float)f[k];
                }
                for (k = 0; k + 1 < m; k++) {
                    sl[k] = (f[k + 1] - f[k]) / (r[k + 1] - r[k]);
                }
                assert_int_equal(mdr_table_init_gap_f64(&t64, nodes64, 64, r, f, (uint16_t)m), MDR_OK);
                assert_int_equal(mdr_table_init_gap_f32(&t32, nodes32, 64, r32, f32, (uint16_t)m), MDR_OK);
                assert_int_equal(t64.rim0, !par);
                assert_int_equal(t32.rim0, !par);
                if (par) {
                    continue;
                }
                assert_true(ft_min(0, R, b, E, w, L, &am) < 0 && am < t64.h); /* the pull-off at the rim */
                assert_int_equal(mdr_engine_init_f64(&e64, &t64, E, w, 0, 0), MDR_E_PARAM);
                assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)E, (float)w, 0.0f, 0), MDR_E_PARAM);
                assert_int_equal(mdr_contact_init_table_f64(&c64, r, sl, (uint16_t)m, 1.0, 0.0), MDR_OK);
                assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, 64, &c64, L), MDR_OK);
                assert_int_equal(t64.rim0, 1);
                assert_int_equal(mdr_engine_init_f64(&e64, &t64, E, w, 0, 0), MDR_E_PARAM);
#ifndef MDR_TARGET_TEST /* (1 024-spring tables of the tabulated contact: host only) */
                /* on 1 024 springs (the rim outside spring 0) the tabulated
                 * contact's table pulls off as the gap table of the same
                 * samples, and with 10 flat intervals near Kendall's d */
                double dd[2];
                for (k = 0; k < 2; k++) {
                    mdr_step_f64 po;
                    const double dk = -sqrt(2 * PI_ * b * w / E);
                    if (k == 0) {
                        assert_int_equal(mdr_table_init_gap_f64(&t64, nodes64, 1024, r, f, (uint16_t)m), MDR_OK);
                    } else {
                        assert_int_equal(mdr_table_init_profile_f64(&t64, nodes64, 1024, &c64, L), MDR_OK);
                    }
                    assert_int_equal(t64.rim0, 0);
                    assert_int_equal(mdr_engine_init_f64(&e64, &t64, E, w, 0, 0), MDR_OK);
                    assert_true(run64(&e64, MDR_CONTROL_GRIPS, 0, 8.87e-10, 400, &po, NULL) == 0);
                    assert_true(run64(&e64, MDR_CONTROL_GRIPS, 8.87e-10, -2.0e-11, 2000, &po, NULL));
                    dd[k] = po.d0 / dk;
                }
                worst = fmax(worst, fabs(dd[1] / dd[0] - 1));
                if (!(fabs(dd[1] / dd[0] - 1) <= TOL_RIM_SAMPLED) ||
                    (kf[i] == 10 && !(fmax(fabs(dd[0] - 1), fabs(dd[1] - 1)) <= TOL_RIM_SAMPLED10))) {
                    print_message("%g + %g flat intervals: pull-off d %.4f (gap), %.4f (tabulated contact) of Kendall's\n",
                                  kf[i], fr[j], dd[0], dd[1]);
                }
                assert_true(fabs(dd[1] / dd[0] - 1) <= TOL_RIM_SAMPLED);
                if (kf[i] == 10) { /* (both tables: the gap's and the tabulated contact's, whose pull-off was 1.9 x) */
                    worst10 = fmax(worst10, fmax(fabs(dd[0] - 1), fabs(dd[1] - 1)));
                    assert_true(fabs(dd[0] - 1) <= TOL_RIM_SAMPLED10);
                    assert_true(fabs(dd[1] - 1) <= TOL_RIM_SAMPLED10);
                }
#endif
            }
        }
    }
#ifndef MDR_TARGET_TEST
    print_message("sampled worn tips on 1 024 springs: tabulated contact against gap table %.3f, 10 flat intervals "
                  "against Kendall %.3f\n",
                  worst, worst10);
#else
    (void)worst, (void)worst10;
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(paraboloid_pull_off),
        cmocka_unit_test(grips_pull_off_f32),
        cmocka_unit_test(pull_off_inside_spring_0),
        cmocka_unit_test(dimple_pull_off_in_spring_0),
        cmocka_unit_test(jump_in_inside_spring_0),
        cmocka_unit_test(load_to_zero_without_adhesion),
        cmocka_unit_test(paraboloid_machine),
        cmocka_unit_test(loading_branches),
        cmocka_unit_test(retraction_is_equilibrium),
        cmocka_unit_test(oracle_cycles),
        cmocka_unit_test(energy_jkr_cycle),
        cmocka_unit_test(energy_any_tick),
        cmocka_unit_test(energy_tick_invariant),
        cmocka_unit_test(energy_stiff_loop),
        cmocka_unit_test(energy_flat_punch_springs),
        cmocka_unit_test(non_adhesive_cycle),
        cmocka_unit_test(no_false_folds),
        cmocka_unit_test(no_false_folds_sampled),
        cmocka_unit_test(wavy_seed_fig_4_9),
        cmocka_unit_test(flat_punch_wall),
        cmocka_unit_test(rims_on_nodes),
        cmocka_unit_test(rim_pull_off_f32),
#ifndef MDR_TARGET_TEST
        cmocka_unit_test(rim_pull_off_tick_f32),
#endif
        cmocka_unit_test(adhesion_resolved_float),
#ifndef MDR_TARGET_TEST /* (its soft-double critical searches: host only; the target runs the same
                          inits in rim_in_spring0) */
        cmocka_unit_test(powerlaw_pull_off_spring0),
#endif
        cmocka_unit_test(rim_in_spring0),
        cmocka_unit_test(rim_in_spring0_sampled),
        cmocka_unit_test(tiny_tables_float),
        cmocka_unit_test(gap_spike_below_first_node),
        cmocka_unit_test(gap_table_exact_for_quadratic),
        cmocka_unit_test(gap_table_order),
        cmocka_unit_test(generated_table_matches),
        cmocka_unit_test(f32_fold_landing_rounding),
#ifndef MDR_TARGET_TEST /* (2.7 M ticks: host only; the target runs the same code) */
        cmocka_unit_test(wavy_jumps_tick_invariant),
#endif
        cmocka_unit_test(known_jumps_match_scan),
        cmocka_unit_test(first_equilibrium_coarse_tables),
        cmocka_unit_test(engine_errors),
    };
    return MDR_RUN_TESTS(tests);
}

#endif /* applies */
