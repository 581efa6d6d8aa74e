/* SPDX-License-Identifier: MIT */
/*
 * test_scene.c: the table-free scene engine (lib/src/mdr_scene_t.c) against
 * the spring engine on tables that hold the same g exactly (paraboloid and
 * cone: g quadratic resp. linear in x), against the JKR closed forms, f32
 * against f64, the output groups, and every error path.
 *
 * Tolerances (relative to the cycle's max|F| unless said; MDR_TOL_REPORT=1
 * prints the share of each that the run used):
 *   TOL_ENG64 = 5e-14: scene f64 against the f64 spring engine (4096
 *     springs) at every tick of approach-retract cycles under each control,
 *     with w_adv = w/2 and w_adv = w (both hold g exactly, so only rounding
 *     differs: the roots to 4 eps in t, F = 2E*(a d - G) loses a factor ~10
 *     to cancellation near pull-off; measured 7.0e-15);
 *   TOL_32 = 1e-5 (the accuracy goal): scene f32 against scene f64, same
 *     cycles (measured 6.4e-6, the cone through a machine);
 *   the same two for an AFM tip through soft cantilevers, in fine and
 *     coarse ticks (scene_soft_machine; measured 1.0e-15 and 1.8e-7 on the
 *     host and with the M4F's fused multiply-adds; 4.4e-7 and 4.6e-7 before
 *     a move's d and F through the machine came from the last evaluation's
 *     parts of U, mdr_mono_float.inc);
 *   the same through a machine over whole ranges (scene_machine_sweep: n 1
 *     to 8, w_adv/w 0 to 1, k_m 1e4 to 1e-4 times 2E* a_s, 1 to 1e5 ticks
 *     per cycle, random walks, stops at and across the pull-off, touches):
 *     F and d within TOL_32 of max|F|, max|d| away from the pull-off
 *     (measured 1.7e-6 and 4.6e-7; 1.9e-6 and 4.3e-7 before d5a81a8),
 *     and TOL_32 + TOL_FOLD eps sqrt(|z_po|/|z - z_po|) near it, z at the
 *     control that last moved both edges (the fold's condition: measured
 *     1.7e-4 and 2.9e-4 at z_po itself, 0.23 and 0.40 of the term, host;
 *     0.45 for d on the M4F; the same before); z = d + F/k_m within
 *     TOL_Z_ULP = 8 eps of the parts' scale |z| + |d| + g + 2E* a (|d| +
 *     g)/k_m (measured 0.96, f64 1.11; 1.08 before); the same events
 *     but a crossing of the pull-off within TOL_EV = 1e-6 of z_po
 *     (measured: all within 1e-7);
 *   scene_z_other_controls: z under grips and under load through a
 *     machine within 4 eps of |d| + |F/k_m| of d + F/k_m from the step's own
 *     d and F (scene and spring engine, f64 and f32; measured 1.5);
 *   TOL_JKR = 2e-15 (f64): pull-off force under fixed load -1.5 pi w R and
 *     under fixed grips -5/6 pi w R (seed 4.36, 4.38), relative (measured
 *     3.4e-16);
 *   events: the same event codes and tick as the spring engine;
 *   energy: dissipated energy of a cycle within 1e-12 of the engine's
 *     (measured 1.3e-13).
 * The q31 scene (mdr_scene_q31.h), made from the f64 scene, against it at
 * the same (quantised) control over whole cycles of the paraboloid, the
 * cone and the power law n = 3 under each control:
 *   TOL_Q31_LSB = 256 LSB of Q2.29 in d and F (measured 109.7, d of the
 *     cone under load; 95.6 the paraboloid's; 1.8 to 11.8 under fixed grips: the large errors
 *     are d in the last ticks before a pull-off under load or a soft
 *     machine, where the edge is ill-conditioned: U' -> 0 at the fold, so a
 *     rounding of U of one LSB moves tau by ~sqrt(2 LSB/U''));
 *     TOL_Q31_GRIPS = 24 LSB under fixed grips (measured 8.5, n = 8);
 *     relative to the cycle's max|F| and max|d|, TOL_Q31_REL = 3e-5
 *     (measured 6.2e-6, d of the paraboloid under load); the same event
 *     codes at the same ticks, one completed cycle each, dissipated energy
 *     within TOL_Q31_EN = 1e-5 relative (measured 1.2e-6);
 *   TOL_Q31_JKR = 1 LSB of F0 (measured 0.1): its pull-off forces against
 *     the JKR closed forms;
 *   single ticks of any size (scene_q31_any_step: from separated or a small
 *     contact to 20 ... 100 % of the cycle's largest control and back, one
 *     tick each): accepted as by the f64 scene, d and F within
 *     TOL_Q31_STEP = 32 LSB (measured 6.6: no ill-conditioned fold here);
 *     the same tolerance for a stiff machine's pinned band near a = L
 *     (scene_q31_stiff_top).
 * The adhesion's resolution (scene_q31_adhesion_range: power laws n = 1 to
 * 8, w_adv = w/2, a_max from 1.2 to 300 times the pull-off radius, under
 * fixed load): init refuses (MDR_E_PARAM) exactly the ranges whose pull-off
 * force lies below MDR_Q31_ADH_LSB LSB of F (computed here from the f64
 * scene's fold and F0; 33 of the 64 ranges), and an accepted one pulls
 * off like the f64 scene: one pull-off each, its force within TOL_Q31_PO =
 * 2 LSB of F (measured 0.9 LSB, 4.1e-4 relative; before the check, n = 7 at
 * ten times the radius lost its adhesion entirely: c_w 0, a separation at
 * F = 0, and n = 8 at three times pulled off 3.7 % away).
 * Force only against every output (scene_force_only): the step's own paths
 * and the full tick give d and F bit for bit (tolerance 0) over dithered
 * cycles, f64, f32 and q31, with at least TICKS/40 ticks held right after
 * a move in each (measured 180 of 4000), and with a NaN control and a
 * change of control mode right after a move (test_step's
 * control_switch_after_move checks such a change against the closed
 * forms).
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

#if !(MDR_CFG_F32 && MDR_CFG_F64 && MDR_CFG_ENGINE && MDR_CFG_SCENE && MDR_CFG_EVENTS && MDR_CFG_ALL_PROFILES)
MDR_TEST_NOT_APPLICABLE("f32, f64, the spring engine, scenes with events, every profile")
#else

#include "test_util.h"

#define TOL_ENG64 5e-14
#define TOL_32 1e-5
#define TOL_FOLD 2.0  /* scene_machine_sweep: near the pull-off, times eps sqrt(|z_po|/|z - z_po|) */
#define TOL_Z_ULP 8.0 /* scene_machine_sweep: z - (d + F/k_m), eps of the parts' scale */
#define TOL_EV 1e-6   /* scene_machine_sweep: an event may differ within this of z_po */
#define TOL_JKR 2e-15
#define TOL_EN 1e-12
#define TICKS 4000
#define TOL_Q31_LSB 256.0
#define TOL_Q31_GRIPS 24.0
#define TOL_Q31_REL 3e-5
#define TOL_Q31_EN 1e-5
#define TOL_Q31_JKR 1.0
#define TOL_Q31_STEP 32.0
#define TOL_Q31_PO 2.0 /* LSB of F */

static const double R = 1e-6, E = 1e6, W = 0.05;

/* The path of a cycle: 0 -> umax -> umin -> 0 (in the control's unit). */
static double path(int i, double umax, double umin)
{
    int q = TICKS / 4;
    if (i <= q) {
        return umax * i / q;
    }
    if (i <= 3 * q) {
        return umax + (umin - umax) * (i - q) / (2 * q);
    }
    return umin + (0.0 - umin) * (i - 3 * q) / q;
}

/* control: 1 load, 2 grips, 3 machine; the path's extremes per control:
 * from the pull-off state of mdr_critical_f64, 1.5x beyond it on retraction
 * and 4x its magnitude on approach */
static void extremes(const mdr_contact_f64 *c, int ctl, double k_m, double *umax, double *umin)
{
    double a0, u;
    mdr_critstate_f64 cr;
    assert_int_equal(mdr_default_start_f64(c, &a0), MDR_OK);
    assert_int_equal(mdr_critical_f64(c, (uint8_t)ctl, k_m, a0, &cr), MDR_OK);
    u = ctl == MDR_CONTROL_LOAD ? cr.F : ctl == MDR_CONTROL_GRIPS ? cr.d : cr.d + cr.F / k_m;
    *umax = 4 * fabs(u);
    *umin = u - 0.5 * fabs(u);
}

typedef struct {
    double F[TICKS + 1], d[TICKS + 1], a[TICKS + 1];
    uint8_t ev[TICKS + 1];
    double dissipated;
} run;

static mdr_status step_scene64(mdr_scene_f64 *s, int ctl, double u, mdr_step_f64 *o)
{
    return ctl == MDR_CONTROL_LOAD    ? mdr_scene_step_F_f64(s, u, o)
           : ctl == MDR_CONTROL_GRIPS ? mdr_scene_step_d_f64(s, u, o)
                                      : mdr_scene_step_z_f64(s, u, o);
}

static mdr_status step_scene32(mdr_scene_f32 *s, int ctl, float u, mdr_step_f32 *o)
{
    return ctl == MDR_CONTROL_LOAD    ? mdr_scene_step_F_f32(s, u, o)
           : ctl == MDR_CONTROL_GRIPS ? mdr_scene_step_d_f32(s, u, o)
                                      : mdr_scene_step_z_f32(s, u, o);
}

#if MDR_CFG_Q31
static mdr_status step_scene_q31(mdr_scene_q31 *s, int ctl, int32_t u, mdr_step_q31 *o)
{
    return ctl == MDR_CONTROL_LOAD    ? mdr_scene_step_F_q31(s, u, o)
           : ctl == MDR_CONTROL_GRIPS ? mdr_scene_step_d_q31(s, u, o)
                                      : mdr_scene_step_z_q31(s, u, o);
}

/* One tick of a q31 scene under grips or load at the raw control nearest u
 * (unit: its LSB in SI) and of the f64 scene it was made from at that same
 * control (o: the f64 scene's output) */
static void step_q31_pair(mdr_scene_f64 *r64, mdr_scene_q31 *q, int ctl, double u, double unit, mdr_step_f64 *o)
{
    const int32_t raw = (int32_t)lround(u / unit);
    mdr_step_q31 oq;
    assert_int_equal(step_scene64(r64, ctl, raw * unit, o), MDR_OK);
    assert_int_equal(step_scene_q31(q, ctl, raw, &oq), MDR_OK);
}
#endif

static mdr_status step_eng64(mdr_engine_f64 *e, int ctl, double u, mdr_step_f64 *o)
{
    return ctl == MDR_CONTROL_LOAD    ? mdr_engine_step_F_f64(e, u, o)
           : ctl == MDR_CONTROL_GRIPS ? mdr_engine_step_d_f64(e, u, o)
                                      : mdr_engine_step_z_f64(e, u, o);
}

static double maxabs(const double *v)
{
    double m = 0;
    int i;
    for (i = 0; i <= TICKS; i++) {
        m = fabs(v[i]) > m ? fabs(v[i]) : m;
    }
    return m;
}

/* one profile (paraboloid or cone), every control, both w_adv */
static void compare_profile(uint8_t kind, double p0, double x_max)
{
    static mdr_node_f64 nodes[MDR_TABLE_NODES(4096)];
    static run rs, re, r32;
    const double p[3] = {p0, 0, 0};
    const float pf[3] = {(float)p0, 0, 0};
    const double k_m = 2.0 * E * R; /* kappa a ~ 1: the machine matters */
    int ctl, wi, i;
    mdr_contact_f64 c;
    mdr_contact_f32 c32;
    mdr_table_f64 tab;
    assert_int_equal(mdr_contact_init_f64(&c, kind, p, E, W), MDR_OK);
    assert_int_equal(mdr_contact_init_f32(&c32, kind, pf, (float)E, (float)W), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f64(&tab, nodes, 4096, &c, x_max), MDR_OK);
    for (ctl = 1; ctl <= 3; ctl++) {
        for (wi = 0; wi < 2; wi++) {
            double w_adv = wi == 0 ? 0.5 * W : W, umax, umin, e64 = 0, e32 = 0, mF;
            int skipped = 0;
            mdr_scene_f64 s;
            mdr_scene_f32 s32;
            mdr_engine_f64 eng;
            mdr_energy_f64 en;
            extremes(&c, ctl, k_m, &umax, &umin);
            assert_int_equal(mdr_scene_init_contact_f64(&s, &c, w_adv, k_m, MDR_OUT_ALL, &en), MDR_OK);
            assert_int_equal(mdr_scene_init_contact_f32(&s32, &c32, (float)w_adv, (float)k_m, MDR_OUT_ALL, NULL),
                             MDR_OK);
            assert_int_equal(mdr_engine_init_f64(&eng, &tab, E, W, w_adv, k_m), MDR_OK);
            for (i = 0; i <= TICKS; i++) {
                double u = path(i, umax, umin);
                mdr_step_f64 o, oe;
                mdr_step_f32 o32;
                assert_int_equal(step_scene64(&s, ctl, u, &o), MDR_OK);
                assert_int_equal(step_eng64(&eng, ctl, u, &oe), MDR_OK);
                assert_int_equal(step_scene32(&s32, ctl, (float)u, &o32), MDR_OK);
                rs.F[i] = o.F;
                rs.d[i] = o.d;
                rs.a[i] = o.a;
                rs.ev[i] = o.event;
                re.F[i] = oe.F;
                re.d[i] = oe.d;
                re.a[i] = oe.a;
                re.ev[i] = oe.event;
                r32.F[i] = o32.F;
                r32.d[i] = o32.d;
                if (o.event != oe.event) {
                    fail_msg("kind %u control %d w_adv %g tick %d: event %s, engine %s", kind, ctl, w_adv, i,
                             mdr_event_str(o.event), mdr_event_str(oe.event));
                }
            }
            mF = maxabs(re.F);
            for (i = 0; i <= TICKS; i++) {
                double x = fabs(rs.F[i] - re.F[i]) / mF, y = fabs((double)r32.F[i] - rs.F[i]) / mF;
                e64 = x > e64 ? x : e64;
                if ((rs.F[i] != 0.0) != (r32.F[i] != 0.0f)) {
                    skipped++; /* the path crossed the fold within rounding */
                    continue;
                }
                e32 = y > e32 ? y : e32;
            }
            assert_true(skipped <= 1);
            printf("  kind %u control %d w_adv/w %.1f: F scene-engine %.2e, f32-f64 %.2e; dissipated %.6e J "
                   "(engine %.6e)\n",
                   kind, ctl, w_adv / W, e64, e32, en.dissipated, eng.en.dissipated);
            {
                char what[96];
                snprintf(what, sizeof what, "kind %u control %d: F scene f64 - engine f64", kind, ctl);
                err_le(e64, TOL_ENG64, what);
                snprintf(what, sizeof what, "kind %u control %d: F scene f32 - scene f64", kind, ctl);
                err_le(e32, TOL_32, what);
                snprintf(what, sizeof what, "kind %u control %d: dissipated scene - engine", kind, ctl);
                rel_le(en.dissipated, eng.en.dissipated, 0, TOL_EN, what);
            }
            assert_true(en.cycles == eng.en.cycles);
        }
    }
}

static void scene_paraboloid_vs_engine(void **state)
{
    (void)state;
    compare_profile(MDR_PROFILE_PARABOLOID, R, 4.0 * R);
}

static void scene_cone_vs_engine(void **state)
{
    (void)state;
    compare_profile(MDR_PROFILE_CONE, 0.3, 1e-4);
}

/* An AFM tip through a soft cantilever (kappa = 2E* a/k_m of tens to
 * hundreds over the cycle, where the cycles above have ~1): a 20 nm
 * paraboloid on polystyrene (E* = 3.8 GPa, w = 0.066 J/m^2; the afm cycle of
 * make step-cost) through k_m = 0.2 and 0.02 N/m, z from -10 nm to 50 nm and
 * back past the pull-off (-57 nm, -477 nm) in 2000 ticks and in 40 (steps of
 * 3 nm and more: the fast path's tangent start far from the root); the f64 scene against the f64 engine
 * (TOL_ENG64, the same events at the same ticks, TOL_EN on the dissipated
 * energy), the f32 scene against the f64 scene (TOL_32) */
static void scene_soft_machine(void **state)
{
    static mdr_node_f64 nodes[MDR_TABLE_NODES(4096)];
    static run rs, re, r32;
    const double Rt = 20e-9, Et = 3.8e9, Wt = 0.066, p[3] = {Rt, 0, 0};
    const float pf[3] = {(float)Rt, 0, 0};
    static const double kms[2] = {0.2, 0.02};
    static const int nts[2] = {2000, 40};
    mdr_contact_f64 c;
    mdr_contact_f32 c32;
    mdr_table_f64 tab;
    int ki, ni, wi, i;
    (void)state;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, p, Et, Wt), MDR_OK);
    assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pf, (float)Et, (float)Wt), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f64(&tab, nodes, 4096, &c, 4.0 * Rt), MDR_OK);
    for (ki = 0; ki < 2; ki++) {
        for (ni = 0; ni < 2; ni++) {
            for (wi = 0; wi < 2; wi++) {
                const int n = nts[ni], h = n / 2;
                const double w_adv = wi == 0 ? 0.5 * Wt : Wt;
                /* below the pull-off: 1.5 times the cantilever's deflection
                 * at the JKR force under load, 1.5 pi w R, and 10 nm */
                const double zlo = -1.5 * (1.5 * M_PI * Wt * Rt) / kms[ki] - 10e-9;
                double e64 = 0, e32 = 0, mF;
                mdr_scene_f64 s;
                mdr_scene_f32 s32;
                mdr_engine_f64 eng;
                mdr_energy_f64 en;
                char what[96];
                assert_int_equal(mdr_scene_init_contact_f64(&s, &c, w_adv, kms[ki], MDR_OUT_ALL, &en), MDR_OK);
                assert_int_equal(mdr_scene_init_contact_f32(&s32, &c32, (float)w_adv, (float)kms[ki], MDR_OUT_ALL, NULL),
                                 MDR_OK);
                assert_int_equal(mdr_engine_init_f64(&eng, &tab, Et, Wt, w_adv, kms[ki]), MDR_OK);
                for (i = 0; i <= n; i++) {
                    const double z = i <= h ? -10e-9 + 60e-9 * i / h : 50e-9 - (50e-9 - zlo) * (i - h) / h;
                    mdr_step_f64 o, oe;
                    mdr_step_f32 o32;
                    assert_int_equal(mdr_scene_step_z_f64(&s, z, &o), MDR_OK);
                    assert_int_equal(mdr_engine_step_z_f64(&eng, z, &oe), MDR_OK);
                    assert_int_equal(mdr_scene_step_z_f32(&s32, (float)z, &o32), MDR_OK);
                    rs.F[i] = o.F;
                    re.F[i] = oe.F;
                    r32.F[i] = o32.F;
                    if (o.event != oe.event) {
                        fail_msg("k_m %g, %d ticks, w_adv %g, tick %d: event %s, engine %s", kms[ki], n, w_adv, i,
                                 mdr_event_str(o.event), mdr_event_str(oe.event));
                    }
                }
                for (i = n + 1; i <= TICKS; i++) {
                    rs.F[i] = re.F[i] = r32.F[i] = 0.0;
                }
                mF = maxabs(re.F);
                for (i = 0; i <= n; i++) {
                    double x = fabs(rs.F[i] - re.F[i]) / mF, y = fabs((double)r32.F[i] - rs.F[i]) / mF;
                    e64 = x > e64 ? x : e64;
                    e32 = y > e32 ? y : e32;
                }
                printf("  soft machine k_m %g N/m, %d ticks, w_adv/w %.1f: F scene-engine %.2e, f32-f64 %.2e; "
                       "dissipated %.6e J (engine %.6e)\n",
                       kms[ki], n, w_adv / Wt, e64, e32, en.dissipated, eng.en.dissipated);
                snprintf(what, sizeof what, "soft machine k_m %g, %d ticks: F scene f64 - engine f64", kms[ki], n);
                err_le(e64, TOL_ENG64, what);
                snprintf(what, sizeof what, "soft machine k_m %g, %d ticks: F scene f32 - scene f64", kms[ki], n);
                err_le(e32, TOL_32, what);
                snprintf(what, sizeof what, "soft machine k_m %g, %d ticks: dissipated scene - engine", kms[ki], n);
                rel_le(en.dissipated, eng.en.dissipated, 0, TOL_EN, what);
                assert_true(en.cycles == 1 && eng.en.cycles == 1);
            }
        }
    }
}

/* The same control twice after a move gives the same d and F (tolerance
 * 0): the move's tick and the pinned tick after it compute the pinned
 * relation alike (the grips band's F through mdr_m_pin_F: with fused
 * multiply-adds, MDR_FMA, a move that rounded kF d + F0 twice left F an ulp
 * off the pinned tick's; found by a differential fuzz of the fused build),
 * under grips on an approach (the edge advances every tick) and a
 * retraction, f32 and f64 */
static void scene_repeat_control(void **state)
{
    int i, k;
    (void)state;
    for (k = 0; k < 2; k++) {
        mdr_scene_f32 s;
        mdr_scene_f64 s64;
        assert_int_equal(mdr_scene_init_paraboloid_f32(&s, (float)R, (float)E, (float)W, (float)W / 2, 0.0f,
                                                       k == 0 ? MDR_OUT_FORCE : MDR_OUT_ALL, NULL),
                         MDR_OK);
        assert_int_equal(mdr_scene_init_paraboloid_f64(&s64, R, E, W, W / 2, 0.0, k == 0 ? MDR_OUT_FORCE : MDR_OUT_ALL,
                                                       NULL),
                         MDR_OK);
        for (i = 1; i <= 800; i++) {
            const double d = i <= 400 ? 1e-9 * i : 400e-9 - 1e-9 * (i - 400); /* approach, then back */
            mdr_step_f32 a, b;
            mdr_step_f64 a64, b64;
            assert_int_equal(mdr_scene_step_d_f32(&s, (float)d, &a), MDR_OK);
            assert_int_equal(mdr_scene_step_d_f32(&s, (float)d, &b), MDR_OK);
            assert_int_equal(mdr_scene_step_d_f64(&s64, d, &a64), MDR_OK);
            assert_int_equal(mdr_scene_step_d_f64(&s64, d, &b64), MDR_OK);
            if (a.F != b.F || a.d != b.d || a64.F != b64.F || a64.d != b64.d) {
                fail_msg("tick %d, d %g, outputs %d: the same d twice gave F %a then %a (f64 %a then %a)", i, d, k,
                         (double)a.F, (double)b.F, a64.F, b64.F);
            }
        }
    }
}

/* JKR pull-off: load -1.5 pi w R, grips -5/6 pi w R (4.36, 4.38), the f64
 * scene and (q31 builds) the q31 scene made from it, on the same path */
static void scene_jkr_pull_off(void **state)
{
    int ctl;
    (void)state;
    for (ctl = 1; ctl <= 2; ctl++) {
        mdr_scene_f64 s;
        mdr_step_f64 o;
        double umax, umin, want = ctl == MDR_CONTROL_LOAD ? -1.5 * M_PI * W * R : -5.0 / 6.0 * M_PI * W * R;
        int i, seen = 0;
        mdr_contact_f64 c;
        const double p[3] = {R, 0, 0};
#if MDR_CFG_Q31
        mdr_scene_q31 q;
        mdr_step_q31 oq;
        double unit;
        int seen_q = 0;
#endif
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, p, E, W), MDR_OK);
        extremes(&c, ctl, 0.0, &umax, &umin);
        assert_int_equal(mdr_scene_init_paraboloid_f64(&s, R, E, W, W, 0.0, MDR_OUT_EVENTS, NULL), MDR_OK);
#if MDR_CFG_Q31
        assert_int_equal(mdr_scene_init_q31_f64(&q, &s, 2e-6), MDR_OK);
        unit = (ctl == MDR_CONTROL_GRIPS ? q.D0 : q.F0) / 536870912.0;
#endif
        for (i = 0; i <= TICKS; i++) {
            assert_int_equal(step_scene64(&s, ctl, path(i, umax, umin), &o), MDR_OK);
            if (o.event == MDR_EV_PULL_OFF) {
                printf("  control %d: pull-off F0 %.15e (JKR %.15e)\n", ctl, o.F0, want);
                rel_le(o.F0, want, 0, TOL_JKR, ctl == MDR_CONTROL_LOAD ? "JKR load" : "JKR grips");
                seen++;
            }
#if MDR_CFG_Q31
            {
                const int32_t raw = (int32_t)lround(path(i, umax, umin) / unit);
                assert_int_equal(step_scene_q31(&q, ctl, raw, &oq), MDR_OK);
                if (oq.event == MDR_EV_PULL_OFF) {
                    const double lsb = q.F0 / 536870912.0, err = fabs(oq.F0 * lsb - want) / lsb;
                    printf("  q31 control %d: pull-off F0 %.9e, %.2f LSB from JKR\n", ctl, oq.F0 * lsb, err);
                    assert_true(err <= TOL_Q31_JKR);
                    seen_q++;
                }
            }
#endif
        }
        assert_int_equal(seen, 1);
#if MDR_CFG_Q31
        assert_int_equal(seen_q, 1);
#endif
    }
}

/* Force only: a, z, event and the jump states are not written. */
static void scene_outputs(void **state)
{
    mdr_scene_f32 s;
    mdr_step_f32 o;
    int i;
    (void)state;
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.05f, 0.0f, MDR_OUT_FORCE, NULL),
                     MDR_OK);
    memset(&o, 0x7f, sizeof o);
    for (i = 0; i < 100; i++) {
        assert_int_equal(mdr_scene_step_d_f32(&s, 1e-8f * (float)i, &o), MDR_OK);
    }
    assert_true(o.F > 0.0f && fabsf(o.d - 99e-8f) <= 1e-6f * 99e-8f);
    assert_true(o.a > 1e30f && o.z > 1e30f && o.event == 0x7f && o.a0 > 1e30f);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.05f, 0.0f, MDR_OUT_RADIUS, NULL),
                     MDR_OK);
    memset(&o, 0x7f, sizeof o);
    assert_int_equal(mdr_scene_step_d_f32(&s, 1e-8f, &o), MDR_OK);
    assert_true(o.a > 0.0f && o.a < 1e-6f && o.event == 0x7f);
}

/* every error path; a refused call leaves the instance unchanged */
/* Without adhesion (w = 0) the scene's units come from the profile's own
 * length (mdr_mono_float.inc's init; before stop 48 a_s = 1 m, D_s = C and
 * F_s = 2E* C, so that on a steep power law real forces over F_s
 * underflowed float: n = 5 at a 100 nm scale returned F 54 % off under
 * grips and a 2.2 times too large under load, MDR_OK; a helper's attack).
 * Against the Hertz closed forms of the power law f = C r^n, g = k_n C x^n
 * with k_n = sqrt(pi) Gamma(n/2 + 1)/Gamma((n + 1)/2) (seed 4.19 and 4.20
 * with w = 0): a = (d/(k_n C))^(1/n) and F = 2E* a d n/(n + 1) under grips,
 * a = (F (n + 1)/(2E* n k_n C))^(1/(n + 1)), d = k_n C a^n under load; n 2
 * to 8, the profile's scale R from 10 nm to 1 mm (C = R^(1-n)), E* 1e5 to
 * 1e11, 24 ticks per control from 1e-3 to 0.3 R in a. Each tick within
 * TOL_32 of the closed form in f32 (relative: F under grips, a and d under
 * load), 1e-12 in f64; an init the arithmetic cannot hold (C beyond float)
 * is refused, and at least 3/4 of the f32 cases run. */
#define SCALE_CASES (7 * 6 * 4)
static void scene_hertz_scale(void **state)
{
    static const double Rs[] = {1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3}, Es[] = {1e5, 1e7, 1e9, 1e11};
    double worst[2] = {0, 0};
    int n, ir, ie, i, ran32 = 0;
    (void)state;
    for (n = 2; n <= 8; n++) {
        const double kn = sqrt(M_PI) * tgamma(n / 2.0 + 1) / tgamma((n + 1) / 2.0);
        for (ir = 0; ir < 6; ir++) {
            for (ie = 0; ie < 4; ie++) {
                const double R = Rs[ir], E = Es[ie], C = pow(R, 1 - n);
                const double p64[3] = {C, n, 0};
                const float p32[3] = {(float)C, (float)n, 0};
                mdr_contact_f64 c64;
                mdr_contact_f32 c32;
                mdr_scene_f64 s64;
                mdr_scene_f32 s32;
                int ok32, ctl;
                assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_POWERLAW, p64, E, 0.0), MDR_OK);
                assert_int_equal(mdr_scene_init_contact_f64(&s64, &c64, 0.0, 0.0, MDR_OUT_ALL, NULL), MDR_OK);
                ok32 = mdr_contact_init_f32(&c32, MDR_PROFILE_POWERLAW, p32, (float)E, 0.0f) == MDR_OK &&
                       mdr_scene_init_contact_f32(&s32, &c32, 0.0f, 0.0f, MDR_OUT_ALL, NULL) == MDR_OK;
                ran32 += ok32;
                for (ctl = 0; ctl < 2; ctl++) {
                    if (ctl == 1) {
                        assert_int_equal(mdr_scene_init_contact_f64(&s64, &c64, 0.0, 0.0, MDR_OUT_ALL, NULL), MDR_OK);
                        if (ok32) {
                            assert_int_equal(mdr_scene_init_contact_f32(&s32, &c32, 0.0f, 0.0f, MDR_OUT_ALL, NULL), MDR_OK);
                        }
                    }
                    for (i = 0; i < 24; i++) {
                        const double a = R * 1e-3 * pow(300.0, i / 23.0), d = kn * C * pow(a, n);
                        const double F = 2 * E * a * d * n / (n + 1.0);
                        /* the control as float rounds it: the closed form at that value */
                        const float u32 = (float)(ctl == 0 ? d : F);
                        const double d32 = ctl == 0 ? (double)u32 : 0, F32 = ctl == 1 ? (double)u32 : 0;
                        const double aw = ctl == 0 ? pow(d32 / (kn * C), 1.0 / n)
                                                   : pow(F32 * (n + 1.0) / (2 * E * n * kn * C), 1.0 / (n + 1.0));
                        mdr_step_f64 o64;
                        mdr_step_f32 o32;
                        double e64, e32;
                        assert_int_equal(ctl == 0 ? mdr_scene_step_d_f64(&s64, d, &o64) : mdr_scene_step_F_f64(&s64, F, &o64),
                                         MDR_OK);
                        e64 = ctl == 0 ? fabs(o64.F - F) / F : fmax(fabs(o64.a - a) / a, fabs(o64.d - d) / d);
                        worst[0] = fmax(worst[0], e64);
                        if (e64 > 1e-12) {
                            printf("  f64 n %d R %g E %g %s tick %d: error %.2e\n", n, R, E, ctl ? "load" : "grips", i, e64);
                        }
                        assert_true(e64 <= 1e-12);
                        if (!ok32) {
                            continue;
                        }
                        assert_int_equal(ctl == 0 ? mdr_scene_step_d_f32(&s32, u32, &o32) : mdr_scene_step_F_f32(&s32, u32, &o32),
                                         MDR_OK);
                        e32 = ctl == 0 ? fabs(o32.F - 2 * E * aw * d32 * n / (n + 1.0)) / (2 * E * aw * d32 * n / (n + 1.0))
                                       : fmax(fabs(o32.a - aw) / aw, fabs(o32.d - kn * C * pow(aw, n)) / (kn * C * pow(aw, n)));
                        worst[1] = fmax(worst[1], e32);
                        if (e32 > TOL_32) {
                            printf("  f32 n %d R %g E %g %s tick %d: error %.2e\n", n, R, E, ctl ? "load" : "grips", i, e32);
                        }
                        assert_true(e32 <= TOL_32);
                    }
                }
            }
        }
    }
    printf("  w = 0, n 2..8, R 1e-8..1e-3 m, E* 1e5..1e11: %d of %d f32 scenes (the rest refused), worst f64 %.1e, "
           "f32 %.1e (tolerance %.0e)\n",
           ran32, SCALE_CASES, worst[0], worst[1], TOL_32);
    assert_true(4 * ran32 >= 3 * SCALE_CASES);
}

/* Contacts small against the scene's units (helper-67's attack: a power
 * law n = 4 without adhesion, a ~ 1e-8 m against a_s ~ 6 m, F ~ 1e-33 N:
 * f32 answered F 8.3e-3 off with MDR_OK, the scene's force tau^(2n+2)
 * below float's normal range, F_s 3e11 N). Over a = 1e-20 R to R,
 * approach and retraction under fixed grips and load, n = 1 to 8, R 1 um
 * and 1 m, E* 1e4 and 1e10 Pa: each tick either answers within the closed
 * form's tolerance (1e-12 f64, TOL_32 f32, relative to the tick's own
 * value, plus for f32 where the scene's units are at most SI's, F_s <= 1 N
 * and D_s <= 1 m, the absolute floor 2^(2n+2) FLT_MIN of mdr_scene_t.h in N
 * and m) or, only where the units are larger (or the control is below
 * float's normal range), is refused with MDR_E_OVERFLOW, the scene unchanged, and only where the scene's force
 * scale (a/a_s)^(n+1) lies within 2^40 of FLT_MIN; f64 answers all. */
static void scene_contact_small_against_units(void **state)
{
    static const double Rs[] = {1e-5, 1.0}, Es[] = {1e4, 1e10};
    double worst[2] = {0, 0};
    int n, ir, ie, ctl, k, refused = 0, answered = 0, floored = 0;
    (void)state;
    for (n = 1; n <= 8; n++) {
        const double kn = sqrt(M_PI) * tgamma(n / 2.0 + 1) / tgamma((n + 1) / 2.0);
        for (ir = 0; ir < 2; ir++) {
            for (ie = 0; ie < 2; ie++) {
                const double R = Rs[ir], E = Es[ie], C = pow(R, 1 - n);
                const double p64[3] = {C, n, 0};
                const float p32[3] = {(float)C, (float)n, 0};
                mdr_contact_f64 c64;
                mdr_contact_f32 c32;
                assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_POWERLAW, p64, E, 0.0), MDR_OK);
                assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_POWERLAW, p32, (float)E, 0.0f), MDR_OK);
                for (ctl = 0; ctl < 2; ctl++) {
                    mdr_scene_f64 s64;
                    mdr_scene_f32 s32;
                    int small_units;
                    double floor;
                    assert_int_equal(mdr_scene_init_contact_f64(&s64, &c64, 0.0, 0.0, MDR_OUT_ALL, NULL), MDR_OK);
                    assert_int_equal(mdr_scene_init_contact_f32(&s32, &c32, 0.0f, 0.0f, MDR_OUT_ALL, NULL), MDR_OK);
                    small_units = s32.Fs <= 1.0f && s32.Ds <= 1.0f;
                    floor = small_units ? ldexp(FLT_MIN, 2 * n + 2) : 0.0;
                    for (k = -40; k <= 41; k++) { /* a = R 10^(-|k|/2): in, out, then u = 0 */
                        const double a = R * pow(10.0, -0.5 * abs(k)), d = kn * C * pow(a, n);
                        const double F = 2 * E * a * d * n / (n + 1.0);
                        const float u32 = k == 41 ? 0.0f : (float)(ctl == 0 ? d : F);
                        const double u = k == 41 ? 0.0 : ctl == 0 ? d : F;
                        /* the closed form at the control as float rounds it */
                        const double aw = ctl == 0 ? pow((double)u32 / (kn * C), 1.0 / n)
                                                   : pow((double)u32 * (n + 1.0) / (2 * E * n * kn * C), 1.0 / (n + 1.0));
                        const double dw = kn * C * pow(aw, n), Fw = 2 * E * aw * dw * n / (n + 1.0);
                        mdr_step_f64 o64;
                        mdr_step_f32 o32;
                        mdr_scene_f32 b32 = s32;
                        int st;
                        st = ctl == 0 ? mdr_scene_step_d_f64(&s64, u, &o64) : mdr_scene_step_F_f64(&s64, u, &o64);
                        assert_int_equal(st, MDR_OK);
                        if (k < 41) {
                            const double e = ctl == 0 ? fabs(o64.F - F) / F : fmax(fabs(o64.a - a) / a, fabs(o64.d - d) / d);
                            worst[0] = fmax(worst[0], e);
                            if (e > 1e-12) {
                                printf("  f64 n %d R %g E %g %s a/R %.1e: error %.2e\n", n, R, E, ctl ? "load" : "grips", a / R, e);
                            }
                            assert_true(e <= 1e-12);
                        }
                        st = ctl == 0 ? mdr_scene_step_d_f32(&s32, u32, &o32) : mdr_scene_step_F_f32(&s32, u32, &o32);
                        if (st == MDR_E_OVERFLOW) {
                            const double scale = pow(a / (double)s32.as, n + 1.0);
                            const int same = memcmp(&b32, &s32, sizeof s32) == 0;
                            const int sub = (double)u32 < FLT_MIN; /* (a control float does not resolve) */
                            if ((small_units && !sub) || !(scale < 0x1p40 * FLT_MIN) || !same) {
                                printf("  f32 n %d R %g E %g %s a/R %.1e: refused at (a/a_s)^(n+1) %.2e, F_s %.1e N, D_s %.1e m%s\n",
                                       n, R, E, ctl ? "load" : "grips", a / R, scale, (double)s32.Fs, (double)s32.Ds,
                                       same ? "" : ", the scene changed");
                            }
                            assert_true(!small_units || sub);
                            assert_true(scale < 0x1p40 * FLT_MIN);
                            assert_true(same);
                            refused++;
                            continue;
                        }
                        assert_int_equal(st, MDR_OK);
                        answered++;
                        if (k < 41 && (double)u32 >= FLT_MIN) { /* (a control below float's normal
                                                                       range has no closed form to check) */
                            /* relative to the tick's value; the floor in N (F) and m (d) */
                            const double eF = fabs(o32.F - Fw) / (Fw + floor / TOL_32);
                            const double e = ctl == 0 ? eF
                                                      : fmax(fabs(o32.a - aw) / aw, fabs(o32.d - dw) / (dw + floor / TOL_32));
                            floored += ctl == 0 ? Fw < floor / TOL_32 : dw < floor / TOL_32;
                            worst[1] = fmax(worst[1], e);
                            if (!(e <= TOL_32)) {
                                printf("  f32 n %d R %g E %g %s a/R %.1e: error %.2e\n", n, R, E, ctl ? "load" : "grips", a / R, e);
                            }
                            assert_true(e <= TOL_32);
                        } else if (k == 41) {
                            assert_true(o32.a == 0.0f && o32.F == 0.0f);
                        }
                    }
                    assert_true(s64.contact == 0 && s32.contact == 0);
                }
            }
        }
    }
    printf("  w = 0, n 1..8, a/R 1e-20..1: f32 answered %d ticks (%d below the floor's scale), refused %d; "
           "worst f64 %.1e, f32 %.1e (tolerance %.0e)\n",
           answered, floored, refused, worst[0], worst[1], TOL_32);
    assert_true(refused > 0 && answered > 4 * refused);
}

/* A contact whose pinned coefficients leave float's range (dtau/du per
 * newton or metre overflows at an edge that small) is kept by a lazy move
 * (load, machine), and every later tick asked for those coefficients first
 * and was refused: a separating control included, forever (helper-69,
 * stop 72: a paraboloid under loads of 8.4e-45 and 2.8e-45 N, refused at
 * 1.4e-45 N, then at 0, -1 and 1e-3 N; a power law n = 7 through a
 * machine the same). Now a tick whose control leaves the band the move
 * kept moves from it: the same paths separate at 0 (MDR_OK, a = 0) and
 * touch again at a control of ordinary size. */
static void scene_tiny_contact_not_stuck(void **state)
{
    static const float F[] = {8.40779e-45f, 2.8026e-45f, 1.4013e-45f, 0.0f, -1.0f, 1e-3f};
    static const float z[] = {5.70328e-43f, 2.28412e-43f, 1.13505e-43f, 0.0f, -1.0f, 1e-3f};
    const float q[3] = {1.262062e-11f, 7, 0};
    mdr_scene_f32 s;
    mdr_contact_f32 c;
    mdr_step_f32 o;
    int i, st;
    (void)state;
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 6.48162862e-07f, 0.0334777525f, 0, 0, 0, MDR_OUT_ALL, NULL), MDR_OK);
    for (i = 0; i < 6; i++) {
        mdr_scene_f32 b = s;
        st = mdr_scene_step_F_f32(&s, F[i], &o);
        if (st != MDR_OK) { /* (the contact at 1.4e-45 N: its coefficients overflow) */
            assert_int_equal(st, MDR_E_OVERFLOW);
            assert_int_equal(i, 2);
            assert_memory_equal(&b, &s, sizeof s);
            continue;
        }
        assert_int_equal(s.contact, F[i] > 0.0f);
    }
    assert_true(o.a > 0.0f && o.F == 1e-3f);
    assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_POWERLAW, q, 0.00102911887f, 0), MDR_OK);
    assert_int_equal(mdr_scene_init_contact_f32(&s, &c, 0, 0.0110870311f, MDR_OUT_ALL, NULL), MDR_OK);
    for (i = 0; i < 6; i++) {
        mdr_scene_f32 b = s;
        st = mdr_scene_step_z_f32(&s, z[i], &o);
        if (st != MDR_OK) {
            assert_int_equal(st, MDR_E_OVERFLOW);
            assert_int_equal(i, 2);
            assert_memory_equal(&b, &s, sizeof s);
            continue;
        }
        assert_int_equal(s.contact, z[i] > 0.0f);
    }
    assert_true(o.a > 0.0f);
}

static void scene_errors(void **state)
{
    mdr_scene_f32 s, before;
    mdr_step_f32 o;
    mdr_contact_f32 c;
    const float sp[3] = {1e-6f, 0, 0};
    (void)state;
    assert_int_equal(mdr_scene_init_paraboloid_f32(NULL, 1e-6f, 1e6f, 0.05f, 0.0f, 0.0f, 0, NULL), MDR_E_NULL);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, NAN, 1e6f, 0.05f, 0.0f, 0.0f, 0, NULL), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, -1.0f, 1e6f, 0.05f, 0.0f, 0.0f, 0, NULL), MDR_E_PARAM);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 0.0f, 0.05f, 0.0f, 0.0f, 0, NULL), MDR_E_PARAM);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.1f, 0.0f, 0, NULL), MDR_E_PARAM);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.0f, -1.0f, 0, NULL), MDR_E_CONTROL);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.0f, 0.0f, 9, NULL), MDR_E_PARAM);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, INFINITY, 0.0f, 0.0f, 0, NULL),
                     MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 3e38f, 1e-38f, 10.0f, 0.0f, 0.0f, 0, NULL),
                     MDR_E_OVERFLOW);
    /* 2E* / k_m beyond float (2e44) though 2E* a_s / k_m is not: refused, the
     * instance untouched (a helper's attack, stop 48: accepted before, its
     * z and F then wrong) */
    memset(&s, 0x5a, sizeof s);
    before = s;
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.05f, 1e-38f, 0, NULL), MDR_E_CONTROL);
    assert_memory_equal(&s, &before, sizeof s);
    /* and 1/k_m beyond float (k_m = 1e-39, subnormal) where 2E* / k_m is not
     * (E* = 1e-30): the engines' shared machine check (mdr_e_material) */
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e-30f, 0.0f, 0.0f, 1e-39f, 0, NULL), MDR_E_CONTROL);
    assert_memory_equal(&s, &before, sizeof s);
    assert_int_equal(mdr_scene_init_contact_f32(&s, NULL, 0.0f, 0.0f, 0, NULL), MDR_E_NULL);
    assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_SPHERE, sp, 1e6f, 0.05f), MDR_OK);
    assert_int_equal(mdr_scene_init_contact_f32(&s, &c, 0.0f, 0.0f, 0, NULL), MDR_E_KIND);
    {
        const float pl[3] = {1e3f, 1.5f, 0};
        assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_POWERLAW, pl, 1e6f, 0.05f), MDR_OK);
        assert_int_equal(mdr_scene_init_contact_f32(&s, &c, 0.0f, 0.0f, 0, NULL), MDR_E_KIND);
    }
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.0f, 0.0f, 0, NULL), MDR_OK);
    assert_int_equal(mdr_scene_step_d_f32(&s, 1e-8f, &o), MDR_OK);
    before = s;
    assert_int_equal(mdr_scene_step_d_f32(NULL, 1e-8f, &o), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_d_f32(&s, 1e-8f, NULL), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_d_f32(&s, NAN, &o), MDR_E_NONFINITE);
    /* (in contact under grips, force only: the step's own move, per
     * direction, must leave these to the slow path) */
    assert_int_equal(mdr_scene_step_d_f32(&s, INFINITY, &o), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_step_d_f32(&s, -INFINITY, &o), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_step_F_f32(&s, INFINITY, &o), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_step_z_f32(&s, 1e-8f, &o), MDR_E_CONTROL); /* no machine */
    assert_int_equal(mdr_scene_step_z_f32(&s, -1e-8f, &o), MDR_E_CONTROL);
    {
        /* separated, force only, without a machine: no z is a separated
         * tick, whatever its sign (the step's own path must not answer it) */
        mdr_scene_f32 s2, k2;
        assert_int_equal(mdr_scene_init_paraboloid_f32(&s2, 1e-6f, 1e6f, 0.05f, 0.0f, 0.0f, MDR_OUT_FORCE, NULL),
                         MDR_OK);
        k2 = s2;
        assert_int_equal(mdr_scene_step_z_f32(&s2, -1e-8f, &o), MDR_E_CONTROL);
        assert_int_equal(mdr_scene_step_z_f32(&s2, 0.0f, &o), MDR_E_CONTROL);
        assert_memory_equal(&s2, &k2, sizeof s2);
    }
    assert_int_equal(mdr_scene_step_z_f32(NULL, 1e-8f, &o), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_F_f32(&s, 1e-8f, NULL), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_d_f32(&s, 3e38f, &o), MDR_E_OVERFLOW);
    assert_memory_equal(&s, &before, sizeof s);
}


/* z = d + F/k_m of a scene's outputs where F/k_m is finite but F iFs kap
 * (the order the scene once multiplied in) passes the largest float: a
 * paraboloid under a soft machine (k_m = 1e-9 N/m) at F = 1e25 N (a ~ 20 km:
 * the scene has no range to leave): accepted, z finite and within 4 eps of
 * d + F/k_m in double (found by fuzz_step: z was +inf with MDR_OK); the same
 * F on an f32 scene whose z is beyond float refuses (MDR_E_OVERFLOW),
 * unchanged. */
static void scene_z_range(void **state)
{
    mdr_scene_f32 s, k;
    mdr_step_f32 o;
    (void)state;
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.025f, 1e-9f, MDR_OUT_ALL, NULL),
                     MDR_OK);
    assert_int_equal(mdr_scene_step_F_f32(&s, 1e25f, &o), MDR_OK);
    assert_true(isfinite(o.z));
    rel_le((double)o.z, (double)o.d + 1e25 / 1e-9, 0, 4 * FLT_EPSILON, "scene f32 z at F = 1e25 N");
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.025f, 1e-12f, MDR_OUT_ALL, NULL),
                     MDR_OK);
    assert_int_equal(mdr_scene_step_F_f32(&s, 1e25f, &o), MDR_OK);
    k = s;
    assert_int_equal(mdr_scene_step_F_f32(&s, 1e30f, &o), MDR_E_OVERFLOW); /* z = 1e42 m */
    assert_memory_equal(&s, &k, sizeof s);
}

/* One paraboloid scene four ways, for the z tests below: the f64 and f32
 * scenes and spring engines (on the paraboloid's tables t64, t32), w_adv =
 * w/2, through a machine k_m */
typedef struct {
    mdr_scene_f64 s64;
    mdr_scene_f32 s32;
    mdr_engine_f64 e64;
    mdr_engine_f32 e32;
} four_ways;

/* the paraboloid's tables of n springs to a_max, f64 and f32 */
static void four_tables(double Rs, double Es, double Ws, uint16_t n, double amax, mdr_table_f64 *t64,
                        mdr_node_f64 *n64, mdr_table_f32 *t32, mdr_node_f32 *n32)
{
    const double pd[3] = {Rs, 0, 0};
    const float pf[3] = {(float)Rs, 0, 0};
    mdr_contact_f64 c64;
    mdr_contact_f32 c32;
    assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_PARABOLOID, pd, Es, Ws), MDR_OK);
    assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pf, (float)Es, (float)Ws), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f64(t64, n64, n, &c64, amax), MDR_OK);
    assert_int_equal(mdr_table_init_profile_f32(t32, n32, n, &c32, (float)amax), MDR_OK);
}

static void four_init(four_ways *f, const mdr_table_f64 *t64, const mdr_table_f32 *t32, double Rs, double Es,
                      double Ws, double km)
{
    assert_int_equal(mdr_scene_init_paraboloid_f64(&f->s64, Rs, Es, Ws, Ws / 2, km, MDR_OUT_ALL, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&f->s32, (float)Rs, (float)Es, (float)Ws, (float)Ws / 2, (float)km,
                                                   MDR_OUT_ALL, NULL),
                     MDR_OK);
    assert_int_equal(mdr_engine_init_f64(&f->e64, t64, Es, Ws, Ws / 2, km), MDR_OK);
    assert_int_equal(mdr_engine_init_f32(&f->e32, t32, (float)Es, (float)Ws, (float)Ws / 2, (float)km), MDR_OK);
}

/* one tick of control ctl (MDR_CONTROL_*) to u, each way: o[0] and q[0] the
 * scenes' (f64, f32), o[1] and q[1] the engines' */
static void four_step(four_ways *f, uint8_t ctl, double u, mdr_step_f64 o[2], mdr_step_f32 q[2])
{
    const float uf = (float)u;
    if (ctl == MDR_CONTROL_GRIPS) {
        assert_int_equal(mdr_scene_step_d_f64(&f->s64, u, &o[0]), MDR_OK);
        assert_int_equal(mdr_engine_step_d_f64(&f->e64, u, &o[1]), MDR_OK);
        assert_int_equal(mdr_scene_step_d_f32(&f->s32, uf, &q[0]), MDR_OK);
        assert_int_equal(mdr_engine_step_d_f32(&f->e32, uf, &q[1]), MDR_OK);
    } else if (ctl == MDR_CONTROL_LOAD) {
        assert_int_equal(mdr_scene_step_F_f64(&f->s64, u, &o[0]), MDR_OK);
        assert_int_equal(mdr_engine_step_F_f64(&f->e64, u, &o[1]), MDR_OK);
        assert_int_equal(mdr_scene_step_F_f32(&f->s32, uf, &q[0]), MDR_OK);
        assert_int_equal(mdr_engine_step_F_f32(&f->e32, uf, &q[1]), MDR_OK);
    } else {
        assert_int_equal(mdr_scene_step_z_f64(&f->s64, u, &o[0]), MDR_OK);
        assert_int_equal(mdr_engine_step_z_f64(&f->e64, u, &o[1]), MDR_OK);
        assert_int_equal(mdr_scene_step_z_f32(&f->s32, uf, &q[0]), MDR_OK);
        assert_int_equal(mdr_engine_step_z_f32(&f->e32, uf, &q[1]), MDR_OK);
    }
}

/* A machine so soft that F/k_m cancels d: an AFM-like paraboloid (R =
 * 10 um, E* = 1 MPa, w = 0.05) through k_m = 1e-3 ... 1e-32 N/m, z up to
 * 1e-7 m and back to -1e-6 m. The state's F is known to ~eps 2E* a d
 * (2.8e-13 N in f32 here), so d + F/k_m knew z to that over k_m: the f32
 * scene reported z 1.2 % off at k_m = 1e-3 and z = d (5.7e-7 m for a
 * control of 1e-7) at 1e-20 (a helper's attack, stop 48). z is the control
 * of step_z and is reported as given: every tick of the scenes (f32, f64)
 * and the spring engines (1024 springs, f32 and f64) returns z exactly,
 * F = k_m (z - d) to TOL_32 of the JKR pull-off force 1.5 pi w R (measured
 * below 2e-7), and the f32 d within TOL_32 of the f64 scene's. */
static void scene_z_soft_machine(void **state)
{
    static mdr_node_f32 n32[MDR_TABLE_NODES(1024)];
    static mdr_node_f64 n64[MDR_TABLE_NODES(1024)];
    static const double kms[] = {1e-3, 1e-12, 1e-20, 1e-32};
    const double Rs = 1e-5, Es = 1e6, Ws = 0.05, Fs = 1.5 * M_PI * Ws * Rs;
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    double ef = 0, ed = 0, dmax = 0;
    int k, i;
    (void)state;
    four_tables(Rs, Es, Ws, 1024, 5e-6, &t64, n64, &t32, n32);
    for (k = 0; k < 4; k++) {
        const double km = kms[k];
        four_ways f;
        four_init(&f, &t64, &t32, Rs, Es, Ws, km);
        for (i = 0; i <= 400; i++) {
            const double z = i <= 100 ? 1e-7 * i / 100 : 1e-7 - 1.1e-6 * (i - 100) / 300;
            const float zf = (float)z;
            mdr_step_f64 o[2];
            mdr_step_f32 q[2];
            int j;
            four_step(&f, MDR_CONTROL_MACHINE, z, o, q);
            for (j = 0; j < 2; j++) {
                if (o[j].z != z || q[j].z != zf) {
                    printf("  k_m %g tick %d %s: z %.9g (f64), %.9g (f32) for %.9g\n", km, i, j ? "engine" : "scene",
                           o[j].z, (double)q[j].z, z);
                }
                assert_true(o[j].z == z && q[j].z == zf);
                ef = fmax(ef, fabs(o[j].F - km * (z - o[j].d)) / Fs);
                ef = fmax(ef, fabs((double)q[j].F - km * ((double)zf - (double)q[j].d)) / Fs);
                rel_le(o[j].F, km * (z - o[j].d), Fs, TOL_32, "soft machine: F = k_m (z - d) (f64)");
                rel_le(q[j].F, km * ((double)zf - (double)q[j].d), Fs, TOL_32, "soft machine: F = k_m (z - d) (f32)");
                dmax = fmax(dmax, fabs(o[0].d));
            }
            ed = fmax(ed, fabs((double)q[0].d - o[0].d));
        }
    }
    printf("  soft machine: z as given, F - k_m (z - d) %.2g of 1.5 pi w R, f32 d %.2g of max|d|\n", ef, ed / dmax);
    rel_le(ed, 0.0, dmax, TOL_32, "soft machine: f32 d against f64");
}

/* The state's force through a soft machine (helper-69, stop 72): the slow
 * path's state (a first touch, a jump-in's landing, a root of the slow
 * move) took F = 2E* (a d - G) from d = (z/k_m-scaled control + kappa G)/(1 + kappa a),
 * whose two terms agree to about log10(kappa a) digits through a soft
 * machine (kappa = 2E* a_s/k_m): an AFM tip's jump-in (R 20.6 nm, E* 206
 * MPa, w 0.205, w_adv 0.205, k_m 0.012 N/m) f32 3.3e-5 of max|F| off f64,
 * a power law n = 1 with kappa 4e8 answered +2.5e-5 N for -3.0e-7 N, MDR_OK
 * (f64 4e-8 of it). AFM-like paraboloids (R 5 nm to 1 um, E* 1 MPa to
 * 200 GPa, w 0.01 to 1, w_adv w/2 and 0.99 w, k_m 1e-3 to 10 N/m): a touch
 * at z = 1e-6 of the depth scale a0^2/R (a jump-in), 20 ticks to a0^2/R,
 * 20 back to -a0^2/R; every tick of the scenes and the spring engines (1024
 * springs, two radii) within the machine's equilibrium F = k_m (z - d),
 * computed here from the tick's own d, to TOL_MF64 = 1e-12 (f64) and TOL_32
 * (f32) of the path's max|F| (plus 4 eps k_m (|z| + |d|), the rounding of
 * that d), and the f32 F within TOL_32 of the f64 one. */
#define TOL_MF64 1e-12
static void soft_machine_tick(const char *what, double km, double z, double d, double F, double Fmax, double tol,
                              double eps, double *worst)
{
    /* (k_m (z - d) from the tick's d carries k_m eps |d| of its rounding:
     * a stiff machine's, where z - d is small against d) */
    const double e = fabs(F - km * (z - d)) / (Fmax + 4 * eps * km * (fabs(z) + fabs(d)) / tol);
    *worst = fmax(*worst, e / tol);
    if (!(e <= tol)) {
        printf("  %s: F %.9g, k_m (z - d) %.9g (z %.9g, d %.9g): %.2e of max|F|\n", what, F, km * (z - d), z, d, e);
    }
    assert_true(e <= tol);
}

static void scene_soft_machine_state(void **state)
{
    static mdr_node_f32 n32[MDR_TABLE_NODES(1024)];
    static mdr_node_f64 n64[MDR_TABLE_NODES(1024)];
    static const double Rs[] = {5e-9, 2e-8, 1e-7, 1e-6}, Es[] = {1e6, 1e8, 2e11}, Ws[] = {0.01, 0.2, 1.0};
    static const double kms[] = {1e-3, 1e-2, 0.2, 10.0}, adv[] = {0.5, 0.99};
    double worst[3] = {0, 0, 0};
    int ir, ie, iw, ia, ik, i, runs = 0;
    (void)state;
    for (ir = 0; ir < 4; ir++) {
        for (ie = 0; ie < 3; ie++) {
            for (iw = 0; iw < 3; iw++) {
                const double R = Rs[ir], E = Es[ie], w = Ws[iw];
                const double a0 = cbrt(9 * M_PI * w * R * R / (2 * E)), dj = a0 * a0 / R;
                const int eng = ir == 1 || ir == 3; /* (the spring engines at two radii) */
                mdr_table_f64 t64;
                mdr_table_f32 t32;
                if (eng) {
                    four_tables(R, E, w, 1024, 3 * a0, &t64, n64, &t32, n32);
                }
                for (ia = 0; ia < 2; ia++) {
                    for (ik = 0; ik < 4; ik++) {
                        const double wa = adv[ia] * w, km = kms[ik];
                        const double kmf = (double)(float)km;
                        mdr_scene_f64 s64;
                        mdr_scene_f32 s32;
                        mdr_engine_f64 e64;
                        mdr_engine_f32 e32;
                        mdr_step_f64 o[41][2];
                        mdr_step_f32 q[41][2];
                        double zs[41], Fmax = 0;
                        assert_int_equal(mdr_scene_init_paraboloid_f64(&s64, R, E, w, wa, km, MDR_OUT_ALL, NULL), MDR_OK);
                        assert_int_equal(mdr_scene_init_paraboloid_f32(&s32, (float)R, (float)E, (float)w, (float)wa,
                                                                       (float)km, MDR_OUT_ALL, NULL),
                                         MDR_OK);
                        if (eng) {
                            assert_int_equal(mdr_engine_init_f64(&e64, &t64, E, w, wa, km), MDR_OK);
                            assert_int_equal(mdr_engine_init_f32(&e32, &t32, (float)E, (float)w, (float)wa, (float)km),
                                             MDR_OK);
                        }
                        for (i = 0; i < 41; i++) {
                            const double z = i == 0 ? 1e-6 * dj : i <= 20 ? dj * i / 20 : dj * (1 - (i - 20) / 10.0);
                            const float zf = (float)z;
                            zs[i] = z;
                            assert_int_equal(mdr_scene_step_z_f64(&s64, z, &o[i][0]), MDR_OK);
                            assert_int_equal(mdr_scene_step_z_f32(&s32, zf, &q[i][0]), MDR_OK);
                            if (eng) {
                                assert_int_equal(mdr_engine_step_z_f64(&e64, z, &o[i][1]), MDR_OK);
                                assert_int_equal(mdr_engine_step_z_f32(&e32, zf, &q[i][1]), MDR_OK);
                            }
                            Fmax = fmax(Fmax, fabs(o[i][0].F));
                        }
                        assert_true(o[0][0].event == MDR_EV_JUMP_IN && Fmax > 0);
                        for (i = 0; i < 41; i++) {
                            int j;
                            for (j = 0; j <= eng; j++) {
                                const char *name = j ? "engine" : "scene";
                                char what[160];
                                snprintf(what, sizeof what, "%s f64 R %g E %g w %g w_adv %g k_m %g tick %d", name, R, E, w,
                                         wa, km, i);
                                soft_machine_tick(what, km, zs[i], o[i][j].d, o[i][j].F, Fmax, TOL_MF64, DBL_EPSILON, &worst[0]);
                                snprintf(what, sizeof what, "%s f32 R %g E %g w %g w_adv %g k_m %g tick %d", name, R, E, w,
                                         wa, km, i);
                                soft_machine_tick(what, kmf, (double)(float)zs[i], (double)q[i][j].d, (double)q[i][j].F,
                                                  Fmax, TOL_32, FLT_EPSILON, &worst[1]);
                                worst[2] = fmax(worst[2], fabs((double)q[i][j].F - o[i][j].F) / Fmax / TOL_32);
                                if (!(fabs((double)q[i][j].F - o[i][j].F) <= TOL_32 * Fmax)) {
                                    printf("  %s: f32 F %.9g, f64 %.9g\n", what, (double)q[i][j].F, o[i][j].F);
                                }
                                assert_true(fabs((double)q[i][j].F - o[i][j].F) <= TOL_32 * Fmax);
                            }
                        }
                        runs++;
                    }
                }
            }
        }
    }
    printf("  soft machines, %d paths from a jump-in: F = k_m (z - d) within %.2g (f64) and %.2g (f32) of their "
           "tolerances, f32 F against f64 %.2g\n",
           runs, worst[0], worst[1], worst[2]);
}

/* z under grips and under load with a machine (k_m > 0): the machine's base
 * position d + F/k_m of the state reached (the control is d or F, so z
 * comes from the state, not from the step's input: the providers' own
 * z, which a machine-controlled step, above, does not read). Scene and
 * spring engine, f64 and f32, a cycle in and out of contact under each
 * control; z within 4 eps of |d| + |F/k_m| (one rounding of 1/k_m, the
 * product and the sum), worked out here from the step's own d and F. */
static void scene_z_other_controls(void **state)
{
    static mdr_node_f32 n32[MDR_TABLE_NODES(256)];
    static mdr_node_f64 n64[MDR_TABLE_NODES(256)];
    const double Rs = 1e-5, Es = 1e9, Ws = 0.05, km = 20.0, Fs = 1.5 * M_PI * Ws * Rs;
    const double D0 = cbrt(M_PI * M_PI * Ws * Ws * Rs / (Es * Es)); /* the JKR depth scale */
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    double worst = 0.0;
    int ctl, i, moved = 0;
    (void)state;
    four_tables(Rs, Es, Ws, 256, 5e-6, &t64, n64, &t32, n32);
    for (ctl = 0; ctl < 2; ctl++) { /* grips, load */
        four_ways f;
        four_init(&f, &t64, &t32, Rs, Es, Ws, km);
        for (i = 0; i <= 300; i++) {
            /* grips: d from 0 to 5 D0 and back to -3 D0; load: F from 0 to 10 Fs and back to -1.2 Fs,
             * past the pull-off (-Fs): separated ticks at the end */
            const double top = ctl == 0 ? 5.0 * D0 : 10.0 * Fs, bot = ctl == 0 ? -3.0 * D0 : -1.2 * Fs;
            const double u = i <= 100 ? top * i / 100 : top + (bot - top) * (i - 100) / 200;
            mdr_step_f64 o[2];
            mdr_step_f32 q[2];
            int j;
            four_step(&f, ctl == 0 ? MDR_CONTROL_GRIPS : MDR_CONTROL_LOAD, u, o, q);
            for (j = 0; j < 2; j++) {
                const double z64 = o[j].d + o[j].F / km, sc64 = fabs(o[j].d) + fabs(o[j].F / km);
                const double z32 = (double)q[j].d + (double)q[j].F / km,
                             sc32 = fabs((double)q[j].d) + fabs((double)q[j].F / km);
                const double e64r = sc64 > 0 ? fabs(o[j].z - z64) / (DBL_EPSILON * sc64) : fabs(o[j].z);
                const double e32r = sc32 > 0 ? fabs((double)q[j].z - z32) / (FLT_EPSILON * sc32) : fabs((double)q[j].z);
                if (!(e64r <= 4.0 && e32r <= 4.0)) {
                    printf("  %s, tick %d, %s: z %.17g for d + F/k_m %.17g (f64), %.9g for %.9g (f32)\n",
                           ctl == 0 ? "grips" : "load", i, j ? "engine" : "scene", o[j].z, z64, (double)q[j].z, z32);
                }
                assert_true(e64r <= 4.0 && e32r <= 4.0);
                worst = fmax(worst, fmax(e64r, e32r));
                moved += o[j].F != 0.0 && q[j].F != 0.0f;
            }
        }
    }
    printf("  z under grips and load through a machine: within %.2g eps of |d| + |F/k_m| (%d ticks with a force)\n",
           worst, moved);
    assert_true(moved > 400);
}

/* ------------------------------------------------ scene_machine_sweep */

/* The f32 scene against the f64 scene through a machine (step_z) over
 * whole ranges (the header's TOL_32, TOL_FOLD, TOL_Z_ULP, TOL_EV): a
 * tick's z = d + F/k_m, its control's rounding scale, the pull-off's
 * control z_po (the f64 scene's retraction fold) */
#ifdef MDR_TARGET_TEST
#define SW_NN 3
#define SW_NW 2
#define SW_NK 5
#define SW_WALK 400
#define SW_TOP 1000
#else
#define SW_NN 6
#define SW_NW 4
#define SW_NK 9
#define SW_WALK 4000
#define SW_TOP 100000
#endif

typedef struct {
    double zmax, zmin, zpo;
    int kind, n; /* kind 0: 3 triangle cycles of n ticks; 1: a random walk;
                    2: in and down to z_po (1 + del) and up; 3: touches */
    double del;
} sw_path;

typedef struct {
    double eF, ed, eFf, edf, ez32, ez64, dF, ddd;
    int forks, ticks;
} sw_res;

/* one output v32 (f32) against v64 (f64) at tick i of path p, relative to
 * the cycle's max|.| m: within TOL_32 plus the fold's allowance fold;
 * the worst error (*worst; *far away from the pull-off) and the share of
 * the allowance used (*share) */
static void sw_part(const char *what, const sw_path *p, int i, double z, const char *name, double v32, double v64,
                    double m, double fold, double *worst, double *far, double *share)
{
    const double e = fabs(v32 - v64) / m;
    *worst = e > *worst ? e : *worst;
    if (fold < 0.1 * TOL_32) {
        *far = e > *far ? e : *far;
    }
    if (e > TOL_32 + fold) {
        fail_msg("%s, path %d/%d (del %g) tick %d z %.9g (z_po %.9g): %s f32 %.9g f64 %.9g, %.3g of max|%s| "
                 "(tolerance %.3g)",
                 what, p->kind, p->n, p->del, i, z, p->zpo, name, v32, v64, e, name, TOL_32 + fold);
    }
    if (e > TOL_32) {
        *share = (e - TOL_32) / fold > *share ? (e - TOL_32) / fold : *share;
    }
}

/* z at tick i of path p (i < sw_len(p)); the walk: xorshift from the
 * seed in *r, steps log-uniform from 1e-6 to 1 of the range, reflected */
static int sw_len(const sw_path *p)
{
    return p->kind == 0 ? (p->n == SW_TOP ? p->n : 3 * p->n) : p->kind == 1 ? SW_WALK : p->kind == 2 ? 60 : 8;
}

static double sw_z(const sw_path *p, int i, uint64_t *r, double *zc)
{
    if (p->kind == 0) {
        const double f = (double)(i % p->n + 1) / p->n;
        return f < 0.25 ? p->zmax * f * 4 : f < 0.75 ? p->zmax + (p->zmin - p->zmax) * (f - 0.25) * 2
                                                     : p->zmin * (1 - (f - 0.75) * 4);
    }
    if (p->kind == 1) {
        double u, v, st;
        *r ^= *r << 13, *r ^= *r >> 7, *r ^= *r << 17;
        u = (double)(*r >> 11) / 9007199254740992.0;
        *r ^= *r << 13, *r ^= *r >> 7, *r ^= *r << 17;
        v = (double)(*r >> 11) / 9007199254740992.0;
        st = (p->zmax - p->zmin) * pow(10.0, -6 * u) * (v < 0.5 ? -1 : 1);
        *zc += st;
        *zc = *zc > p->zmax ? 2 * p->zmax - *zc : *zc < p->zmin ? 2 * p->zmin - *zc : *zc;
        return *zc;
    }
    if (p->kind == 2) {
        const double zs = p->zpo + p->del * fabs(p->zpo);
        return i < 20 ? p->zmax * (i + 1) / 20 : i < 40 ? p->zmax + (zs - p->zmax) * (i - 19) / 20
                                                        : zs + (p->zmax - zs) * (i - 39) / 20;
    }
    { /* touches: just above 0 (the jump-in or contact), then back */
        static const double t[8] = {1e-20, 0, 1e-7, -1e-7, 1e-3, 0, 1, -1e-20};
        return i == 6 ? p->zmax : t[i] * p->zmax;
    }
}

/* one path from a fresh pair of scenes (f64: first alone, for max|F| and
 * max|d|); worst errors into *w */
static void sw_run(const mdr_contact_f64 *c, const mdr_contact_f32 *c32, double w_adv, double k_m,
                   const sw_path *p, sw_res *w, const char *what)
{
    const int m = sw_len(p);
    const float kf = (float)k_m;
    double mF = 0, md = 0, zc = 0, zpe = HUGE_VAL;
    uint64_t r = 88172645463325252ull;
    mdr_scene_f64 s;
    mdr_scene_f32 s32;
    int i, forked = 0;
    assert_int_equal(mdr_scene_init_contact_f64(&s, c, w_adv, k_m, MDR_OUT_ALL, NULL), MDR_OK);
    for (i = 0; i < m; i++) {
        mdr_step_f64 o;
        assert_int_equal(mdr_scene_step_z_f64(&s, sw_z(p, i, &r, &zc), &o), MDR_OK);
        mF = fabs(o.F) > mF ? fabs(o.F) : mF;
        md = fabs(o.d) > md ? fabs(o.d) : md;
    }
    assert_int_equal(mdr_scene_init_contact_f64(&s, c, w_adv, k_m, MDR_OUT_ALL, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_contact_f32(&s32, c32, (float)w_adv, kf, MDR_OUT_ALL, NULL), MDR_OK);
    r = 88172645463325252ull;
    zc = 0;
    for (i = 0; i < m; i++) {
        const double z = sw_z(p, i, &r, &zc), zp = fabs(z - p->zpo), t0 = s.tau;
        const float zf = (float)z, t32 = s32.tau;
        mdr_step_f64 o;
        mdr_step_f32 o32;
        double e, fold;
        assert_int_equal(mdr_scene_step_z_f64(&s, z, &o), MDR_OK);
        assert_int_equal(mdr_scene_step_z_f32(&s32, zf, &o32), MDR_OK);
        /* the pull-off's condition: near it a rounding of the control
         * moves the edge by eps sqrt(|z_po| / |z - z_po|) relative (up to
         * sqrt(eps) at z_po), at the control that last moved both edges
         * (a pinned edge keeps its error) */
        zpe = s.tau != t0 && s32.tau != t32 ? zp : zpe;
        fold = TOL_FOLD * FLT_EPSILON *
               sqrt(fabs(p->zpo) / (zpe > FLT_EPSILON * fabs(p->zpo) ? zpe : FLT_EPSILON * fabs(p->zpo)));
        if (!isfinite(o32.F) || !isfinite(o32.d) || !isfinite(o32.z)) {
            fail_msg("%s, path %d/%d tick %d z %.9g: f32 d %g F %g", what, p->kind, p->n, i, z, (double)o32.d,
                     (double)o32.F);
        }
        if (s.contact) { /* the f64 scene's z against its control */
            const double g = s.Ds * pow(o.a / s.as, s.n),
                         sc = fabs(o.d) + fabs(z) + g + 2 * E * o.a * (fabs(o.d) + g) / k_m;
            e = fabs(o.d + o.F / k_m - z) / (DBL_EPSILON * sc);
            w->ez64 = e > w->ez64 ? e : w->ez64;
        }
        if (forked) {
            continue;
        }
        if (o.event != o32.event || s.contact != s32.contact) {
            /* a crossing of the pull-off within rounding, after which
             * the two go their own ways: the path's comparison ends */
            if (!(zp <= TOL_EV * fabs(p->zpo))) {
                fail_msg("%s, path %d/%d (del %g) tick %d z %.9g (z_po %.9g): event f64 %s, f32 %s", what, p->kind,
                         p->n, p->del, i, z, p->zpo, mdr_event_str(o.event), mdr_event_str(o32.event));
            }
            forked = 1;
            w->forks++;
            continue;
        }
        w->ticks++;
        sw_part(what, p, i, z, "F", (double)o32.F, o.F, mF, fold, &w->eF, &w->eFf, &w->dF);
        sw_part(what, p, i, z, "d", (double)o32.d, o.d, md, fold, &w->ed, &w->edf, &w->ddd);
        if (s32.contact) { /* z = d + F/k_m against the f32 control */
            const double a = (double)o32.a, g = (double)s32.Ds * pow(a / (double)s32.as, s32.n),
                         sc = fabs((double)o32.d) + fabs((double)zf) + g +
                              2 * E * a * (fabs((double)o32.d) + g) / (double)kf;
            e = fabs((double)o32.d + (double)o32.F / (double)kf - (double)zf) / (FLT_EPSILON * sc);
            w->ez32 = e > w->ez32 ? e : w->ez32;
            if (e > TOL_Z_ULP) {
                fail_msg("%s, path %d/%d tick %d z %.9g: f32 d + F/k_m = %.9g, %.1f eps of the parts' scale %.3g",
                         what, p->kind, p->n, i, (double)zf, (double)o32.d + (double)o32.F / (double)kf, e, sc);
            }
        }
    }
}

/* the sweep: g = C x^n, n = 1 (cone), 2 (paraboloid), 3, 4, 6, 8 (power
 * law, f = r^n/L^(n-1)); w_adv/w 0, 1/4, 1/2, 1; k_m 1e4 ... 1e-4 times the
 * contact's stiffness 2E* a_s (a_s: the scene's radius unit, near the
 * pull-off radius), by decades; on each, from fresh scenes: 3 triangle
 * cycles 0 -> 4|z_po| -> z_po - |z_po|/2 -> 0 in 1, 2, 3, 7, 40, 1000 ticks
 * and one cycle in SW_TOP; a random walk of SW_WALK ticks, steps 1e-6 to 1
 * of that range, reflected at its ends (many reversals); in, down to
 * z_po (1 + del) and back up, del from 1e-1 to 1e-6 and -1e-7 to -1e-1
 * (0 and +-1e-7: a crossing within rounding is allowed); touches just
 * above 0 and back (MDR_TARGET_TEST: fewer of each) */
static void scene_machine_sweep(void **state)
{
#ifdef MDR_TARGET_TEST
    static const int ns[SW_NN] = {1, 2, 3};
    static const double wfs[SW_NW] = {0, 1};
    static const double krs[SW_NK] = {1e4, 1e2, 1, 1e-2, 1e-4};
#else
    static const int ns[SW_NN] = {1, 2, 3, 4, 6, 8};
    static const double wfs[SW_NW] = {0, 0.25, 0.5, 1};
    static const double krs[SW_NK] = {1e4, 1e3, 1e2, 1e1, 1, 1e-1, 1e-2, 1e-3, 1e-4};
#endif
    static const int tks[7] = {1, 2, 3, 7, 40, 1000, SW_TOP};
    static const double dels[14] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 0, -1e-7, -1e-6, -1e-5, -1e-4, -1e-3, -1e-1};
    sw_res w = {0};
    int ni, wi, ki, j, paths = 0;
    (void)state;
    for (ni = 0; ni < SW_NN; ni++) {
        const int n = ns[ni], kind = n == 1 ? MDR_PROFILE_CONE : n == 2 ? MDR_PROFILE_PARABOLOID : MDR_PROFILE_POWERLAW;
        const double L = n >= 6 ? 1e-5 : 1e-6, p[3] = {n == 1 ? 0.3 : n == 2 ? L : pow(L, 1.0 - n), n, 0};
        const float pf[3] = {(float)p[0], (float)p[1], 0};
        mdr_contact_f64 c;
        mdr_contact_f32 c32;
        assert_int_equal(mdr_contact_init_f64(&c, (uint8_t)kind, p, E, W), MDR_OK);
        assert_int_equal(mdr_contact_init_f32(&c32, (uint8_t)kind, pf, (float)E, (float)W), MDR_OK);
        for (wi = 0; wi < SW_NW; wi++) {
            for (ki = 0; ki < SW_NK; ki++) {
                const double w_adv = wfs[wi] * W;
                double k_m;
                char what[96];
                sw_path q;
                mdr_scene_f64 s;
                assert_int_equal(mdr_scene_init_contact_f64(&s, &c, w_adv, 1.0, MDR_OUT_ALL, NULL), MDR_OK);
                k_m = krs[ki] * 2 * E * s.as;
                assert_int_equal(mdr_scene_init_contact_f64(&s, &c, w_adv, k_m, MDR_OUT_ALL, NULL), MDR_OK);
                q.zpo = s.uf[2] * s.Ds;
                q.zmax = 4 * fabs(q.zpo);
                q.zmin = q.zpo - 0.5 * fabs(q.zpo);
                q.del = 0;
                snprintf(what, sizeof what, "machine sweep n %d w_adv/w %g k_m/(2E* a_s) %g", n, wfs[wi], krs[ki]);
                for (j = 0; j < 7; j++) {
                    q.kind = 0;
                    q.n = tks[j];
                    sw_run(&c, &c32, w_adv, k_m, &q, &w, what);
                }
                q.kind = 1;
                q.n = SW_WALK;
                sw_run(&c, &c32, w_adv, k_m, &q, &w, what);
                for (j = 0; j < 14; j++) {
                    q.kind = 2;
                    q.n = 0;
                    q.del = dels[j];
                    sw_run(&c, &c32, w_adv, k_m, &q, &w, what);
                }
                q.kind = 3;
                q.del = 0;
                sw_run(&c, &c32, w_adv, k_m, &q, &w, what);
                paths += 23;
            }
        }
    }
    printf("  machine sweep, f32 - f64: %d paths, %d ticks compared, %d crossings of the pull-off within rounding; "
           "F %.2e of max|F|, d %.2e of max|d| (away from the pull-off %.2e, %.2e; beyond TOL_32: %.2f, %.2f of "
           "TOL_FOLD's term); z = d + F/k_m %.2f eps (f64 %.2f) of the parts' scale\n",
           paths, w.ticks, w.forks, w.eF, w.ed, w.eFf, w.edf, w.dF, w.ddd, w.ez32, w.ez64);
    err_le(w.eFf, TOL_32, "machine sweep: F f32 - f64 away from the pull-off");
    err_le(w.edf, TOL_32, "machine sweep: d f32 - f64 away from the pull-off");
    err_le(w.ez64, TOL_Z_ULP, "machine sweep: f64 z = d + F/k_m in eps of the parts' scale");
    assert_true(w.forks <= 3 * paths / 23);
}

/* The work of a moving edge at any tick, as test_engine's energy_any_tick:
 * the f64 and f32 paraboloid scenes and the q31 scene made from the f64
 * one, one JKR cycle under load and under grips at 3 to 1 000 ticks per
 * segment against its closed form (closed_forms.h, jkr_cycle_work; the
 * third scene without adhesion, whose cycle dissipates nothing; the
 * q31 scene at its own quantised controls, whose peak and so whose work
 * differ from the closed form's: against the f64 scene at the same raw
 * controls, itself within TOL_EN_TICK64 of the closed form at the exact
 * peak; the second scene's adhesion is below q31's resolution, which init
 * refuses, MDR_E_PARAM). Tolerances of the cycle's gross work:
 * TOL_EN_TICK64, _32 as the spring engine's (measured 2.2e-16 and
 * 6.7e-8), TOL_EN_TICK_Q31 = 1e-6 of it between q31 and f64 (measured
 * 1.7e-7: the q31 states' error, up to ~100 LSB of Q2.29 in d before a
 * pull-off under load, TOL_Q31_LSB, times the force there). And of the
 * dissipation itself, against the cycle's losses where they arise
 * (jkr_cycle_loss; mdr_energy's loss, stop 65): TOL_EN_LOOP64 = 1e-12,
 * TOL_EN_LOOP32 = 1e-4 as test_engine's, TOL_EN_LOOP_Q31 = 1e-6 between
 * q31 and f64 (measured below; summed as work, stop 64, f32 resolved the
 * second scene's only to 5 %). */
#define TOL_EN_TICK64 1e-14
#define TOL_EN_TICK32 1e-6
#define TOL_EN_TICK_Q31 1e-6
#define TOL_EN_LOOP64 1e-12
#define TOL_EN_LOOP32 1e-4
#define TOL_EN_LOOP_Q31 1e-6
#define TOL_EN_LOOP_Q31_PL 2
#define TOL_EN_LOOP_Q31_PLR 1e-5
static void scene_energy_any_tick(void **state)
{
    const jkr_scene *sc = jkr_scenes;
    static const long ticks[4] = {3, 10, 100, 1000};
    double worst64 = 0, worst32 = 0, worstq = 0, loop64 = 0, loop32 = 0, loopq = 0, work64 = 0, workq = 0;
    int i, j, c;
    long k;
    (void)state;
    for (i = 0; i < 3; i++) {
        for (c = 0; c < 2; c++) {
            const uint8_t ctl = c == 0 ? MDR_CONTROL_LOAD : MDR_CONTROL_GRIPS;
            double gross, u_max, u_end;
            const double want = jkr_cycle(&sc[i], ctl, &gross, &u_max, &u_end);
            const double loss = jkr_cycle_loss(sc[i].E, sc[i].R, sc[i].w, sc[i].wa, ctl, sc[i].a_max);
            for (j = 0; j < 4; j++) {
                mdr_scene_f64 s64;
                mdr_scene_f32 s32;
                mdr_energy_f64 en64;
                mdr_energy_f32 en32;
                mdr_step_f64 o;
                mdr_step_f32 o32;
                const long n = ticks[j];
                double pk64 = 0;
                float pk32 = 0;
                assert_int_equal(mdr_scene_init_paraboloid_f64(&s64, sc[i].R, sc[i].E, sc[i].w, sc[i].wa, 0,
                                                               MDR_OUT_ALL, &en64),
                                 MDR_OK);
                assert_int_equal(mdr_scene_init_paraboloid_f32(&s32, (float)sc[i].R, (float)sc[i].E,
                                                               (float)sc[i].w, (float)sc[i].wa, 0, MDR_OUT_ALL,
                                                               &en32),
                                 MDR_OK);
                for (k = 1; k <= 2 * n; k++) {
                    const double u = k <= n ? u_max * (double)k / (double)n
                                            : u_max + (u_end - u_max) * (double)(k - n) / (double)n;
                    double g2, um, uo;
                    assert_int_equal(step_scene64(&s64, ctl, u, &o), MDR_OK);
                    assert_int_equal(step_scene32(&s32, ctl, (float)u, &o32), MDR_OK);
                    /* the work so far at each state of the retraction branch
                     * (en.work, reset at the cycle's end) */
                    if (k == n) { /* (each scene's own peak: a receded edge is on the retraction branch) */
                        pk64 = o.a;
                        pk32 = o32.a;
                    }
                    if (k > n && s64.contact && o.a < pk64) {
                        const double wt =
                            jkr_work_to(sc[i].E, sc[i].R, sc[i].w, sc[i].wa, ctl, sc[i].a_max, o.a, &g2, &um, &uo);
                        rel_le(en64.work - en64.work_c, wt, gross, TOL_EN_TICK64, "f64 scene work to a state");
                        work64 = fmax(work64, fabs(en64.work - en64.work_c - wt) / gross);
                    }
                    if (k > n && s32.contact && o32.a < pk32) {
                        const double wt =
                            jkr_work_to(sc[i].E, sc[i].R, sc[i].w, sc[i].wa, ctl, sc[i].a_max, o32.a, &g2, &um, &uo);
                        rel_le(en32.work - en32.work_c, wt, gross, TOL_EN_TICK32, "f32 scene work to a state");
                    }
                }
                assert_int_equal(en64.cycles, 1);
                assert_int_equal(en32.cycles, 1);
                rel_le(en64.last_cycle, want, gross, TOL_EN_TICK64, "f64 scene cycle work at any tick");
                rel_le(en32.last_cycle, want, gross, TOL_EN_TICK32, "f32 scene cycle work at any tick");
                worst64 = fmax(worst64, fabs(en64.last_cycle - want) / gross);
                worst32 = fmax(worst32, fabs(en32.last_cycle - want) / gross);
                if (loss != 0) {
                    rel_le(en64.last_cycle, loss, 0, TOL_EN_LOOP64, "f64 scene cycle's dissipation");
                    rel_le(en32.last_cycle, loss, 0, TOL_EN_LOOP32, "f32 scene cycle's dissipation");
                    loop64 = fmax(loop64, fabs(en64.last_cycle / loss - 1));
                    loop32 = fmax(loop32, fabs(en32.last_cycle / loss - 1));
                } else {
                    assert_true(en64.last_cycle == 0 && en32.last_cycle == 0);
                }
#if MDR_CFG_Q31
                {
                    mdr_scene_q31 q;
                    mdr_scene_f64 r64;
                    mdr_energy_f64 er64;
                    double unit;
                    assert_int_equal(mdr_scene_init_paraboloid_f64(&r64, sc[i].R, sc[i].E, sc[i].w, sc[i].wa, 0,
                                                                   MDR_OUT_ALL, &er64),
                                     MDR_OK);
                    if (i == 1) { /* (its adhesion below q31's resolution: refused) */
                        assert_int_equal(mdr_scene_init_q31_f64(&q, &r64, 1.01 * sc[i].a_max), MDR_E_PARAM);
                        continue;
                    }
                    assert_int_equal(mdr_scene_init_q31_f64(&q, &r64, 1.01 * sc[i].a_max), MDR_OK);
                    unit = (ctl == MDR_CONTROL_GRIPS ? q.D0 : q.F0) / 536870912.0;
                    for (k = 1; k <= 2 * n; k++) {
                        step_q31_pair(&r64, &q, ctl,
                                      k <= n ? u_max * (double)k / (double)n
                                             : u_max + (u_end - u_max) * (double)(k - n) / (double)n,
                                      unit, &o);
                        if (k == n) {
                            pk64 = o.a;
                        }
                        if (k > n && q.contact && r64.contact && o.a < pk64) {
                            rel_le(mdr_scene_q31_energy(&q, q.en.work), er64.work - er64.work_c, gross,
                                   TOL_EN_TICK_Q31, "q31 scene work to a state");
                            workq = fmax(workq,
                                         fabs(mdr_scene_q31_energy(&q, q.en.work) - (er64.work - er64.work_c)) / gross);
                        }
                    }
                    assert_int_equal(q.en.cycles, 1);
                    assert_int_equal(er64.cycles, 1);
                    rel_le(mdr_scene_q31_energy(&q, q.en.last_cycle), er64.last_cycle, gross, TOL_EN_TICK_Q31,
                           "q31 scene cycle work at any tick");
                    worstq = fmax(worstq, fabs(mdr_scene_q31_energy(&q, q.en.last_cycle) - er64.last_cycle) / gross);
                    if (loss != 0) {
                        rel_le(mdr_scene_q31_energy(&q, q.en.last_cycle), er64.last_cycle, 0, TOL_EN_LOOP_Q31,
                               "q31 scene cycle's dissipation");
                        loopq = fmax(loopq, fabs(mdr_scene_q31_energy(&q, q.en.last_cycle) / er64.last_cycle - 1));
                    } else {
                        assert_true(q.en.last_cycle == 0);
                    }
                }
#endif
            }
        }
    }
    printf("  scene cycle work at 3 to 1000 ticks: f64 %.2e, f32 %.2e of the gross work against the closed form, "
           "q31 %.2e against f64 (tolerances %.0e, %.0e, %.0e); of the dissipation f64 %.2e, f32 %.2e, q31 "
           "%.2e (tolerances %.0e, %.0e, %.0e); the work to each state of the retraction branch f64 %.2e, q31 %.2e "
           "of the gross work\n",
           worst64, worst32, worstq, TOL_EN_TICK64, TOL_EN_TICK32, TOL_EN_TICK_Q31, loop64, loop32, loopq,
           TOL_EN_LOOP64, TOL_EN_LOOP32, TOL_EN_LOOP_Q31, work64, workq);
}

/* The scenes' power laws, profiles f = C r^n (n = 2, 3, 5, 8; C such that
 * f(10 um) = 1 um; g = kappa_n C x^n, the contact's k[0]), E* = 1 MPa,
 * w = 0.05, w_adv = 0.02 J/m^2, one cycle under load and under grips to
 * a = 20 um and back past the pull-off at 10 and 1 000 ticks a segment: the
 * dissipation against the cycle's losses worked out in closed form
 * (closed_forms.h, mono_cycle_loss) within TOL_EN_LOOP64 (f64) and
 * TOL_EN_LOOP32 (f32) of itself; the q31 scene's against the f64 scene's at
 * the same raw controls within TOL_EN_LOOP_Q31_PLR = 1e-5 of itself plus
 * TOL_EN_LOOP_Q31_PL = 2 LSB of its energy format (Q15.48 of W0 = F0 D0) a
 * tick: a steep power law's W0 is up to 7e9 times this cycle's dissipation
 * (n = 5), and each tick's work of adhesion rounds to that LSB (measured
 * below; n = 8's adhesion q31 refuses at this range, MDR_E_PARAM). A jump spans the contact (the jump-in from a = 0, the pull-off to
 * it), where the 3-point rule of a moving edge is exact only for n <= 2:
 * with it, 8.4e-4 off at n = 3 and 3.8e-2 at n = 8 (helper-54). */
static void scene_energy_power_laws(void **state)
{
    static const int ns[4] = {2, 3, 5, 8};
    static const long ticks[2] = {10, 1000};
    const double Es = 1e6, w = 0.05, wa = 0.02, a_max = 20e-6;
    double worst64 = 0, worst32 = 0, worstq = 0;
    int i, c, j, refused = 0;
    (void)state;
    for (i = 0; i < 4; i++) {
        const double C = 1e-6 * pow(10e-6, -ns[i]), k[3] = {C, ns[i], 0};
        mdr_contact_f64 c64;
        mdr_contact_f32 c32;
        const float kf[3] = {(float)C, (float)ns[i], 0};
        assert_int_equal(mdr_contact_init_f64(&c64, MDR_PROFILE_POWERLAW, k, Es, w), MDR_OK);
        assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_POWERLAW, kf, (float)Es, (float)w), MDR_OK);
        for (c = 0; c < 2; c++) {
            const uint8_t ctl = c == 0 ? MDR_CONTROL_LOAD : MDR_CONTROL_GRIPS;
            double u_max, u_off;
            /* (g = k[0] x^n: the contact's coefficient of g, kappa_n C) */
            const double want = mono_cycle_loss(Es, c64.k[0], ns[i], w, wa, ctl, a_max, &u_max, &u_off);
            for (j = 0; j < 2; j++) {
                const long n = ticks[j];
                mdr_scene_f64 s64, r64;
                mdr_scene_f32 s32;
                mdr_energy_f64 en64, er64;
                mdr_energy_f32 en32;
                mdr_step_f64 o;
                mdr_step_f32 o32;
                long kk;
                assert_int_equal(mdr_scene_init_contact_f64(&s64, &c64, wa, 0, MDR_OUT_ALL, &en64), MDR_OK);
                assert_int_equal(mdr_scene_init_contact_f32(&s32, &c32, (float)wa, 0, MDR_OUT_ALL, &en32), MDR_OK);
                for (kk = 1; kk <= 2 * n; kk++) {
                    const double u = kk <= n ? u_max * (double)kk / (double)n
                                             : u_max + (1.5 * u_off - u_max) * (double)(kk - n) / (double)n;
                    assert_int_equal(step_scene64(&s64, ctl, u, &o), MDR_OK);
                    assert_int_equal(step_scene32(&s32, ctl, (float)u, &o32), MDR_OK);
                }
                assert_int_equal(en64.cycles, 1);
                assert_int_equal(en32.cycles, 1);
                rel_le(en64.last_cycle, want, 0, TOL_EN_LOOP64, "f64 power-law scene's dissipation");
                rel_le(en32.last_cycle, want, 0, TOL_EN_LOOP32, "f32 power-law scene's dissipation");
                worst64 = fmax(worst64, fabs(en64.last_cycle / want - 1));
                worst32 = fmax(worst32, fabs(en32.last_cycle / want - 1));
#if MDR_CFG_Q31
                {
                    mdr_scene_q31 q;
                    double unit;
                    mdr_status st;
                    assert_int_equal(mdr_scene_init_contact_f64(&r64, &c64, wa, 0, MDR_OUT_ALL, &er64), MDR_OK);
                    st = mdr_scene_init_q31_f64(&q, &r64, 1.01 * a_max);
                    if (st == MDR_E_PARAM) { /* (n = 8: its adhesion below q31's resolution at this range) */
                        refused++;
                        continue;
                    }
                    assert_int_equal(st, MDR_OK);
                    unit = (ctl == MDR_CONTROL_GRIPS ? q.D0 : q.F0) / 536870912.0;
                    for (kk = 1; kk <= 2 * n; kk++) {
                        step_q31_pair(&r64, &q, ctl,
                                      kk <= n ? u_max * (double)kk / (double)n
                                              : u_max + (1.5 * u_off - u_max) * (double)(kk - n) / (double)n,
                                      unit, &o);
                    }
                    assert_int_equal(q.en.cycles, 1);
                    assert_int_equal(er64.cycles, 1);
                    {
                        /* (q31's energy resolution: each tick's terms round to
                         * 2^-48 W0, W0 = F0 D0; a steep power law's W0 is up
                         * to 1e9 times this cycle's dissipation) */
                        const double lsb = q.F0 * q.D0 / 281474976710656.0, lim = TOL_EN_LOOP_Q31_PL * (double)(2 * n) * lsb;
                        const double err = fabs(mdr_scene_q31_energy(&q, q.en.last_cycle) - er64.last_cycle);
                        err_le(err, TOL_EN_LOOP_Q31_PLR * fabs(er64.last_cycle) + lim, "q31 power-law scene's dissipation");
                        worstq = fmax(worstq, err / (TOL_EN_LOOP_Q31_PLR * fabs(er64.last_cycle) + lim));
                    }
                }
#else
                (void)r64, (void)er64;
#endif
            }
        }
    }
    printf("  power-law scenes n = 2 to 8: dissipation within f64 %.2e, f32 %.2e of the closed form (tolerances "
           "%.0e, %.0e); q31 off f64 by %.2f of its bound, TOL_EN_LOOP_Q31_PLR = %g of itself plus "
           "TOL_EN_LOOP_Q31_PL = %g LSB of Q15.48 of W0 a tick (%d of 16 refused by the q31 init)\n",
           worst64, worst32, TOL_EN_LOOP64, TOL_EN_LOOP32, worstq, TOL_EN_LOOP_Q31_PLR, (double)TOL_EN_LOOP_Q31_PL,
           refused);
    assert_true(refused <= 4);
}

#if MDR_CFG_Q31
/* One cycle of the q31 scene against the f64 scene it was made from, at
 * the same raw control: the worst error in LSB of Q2.29 and relative to
 * the cycle's peaks; events, cycles and dissipated energy equal */
static double q31_cycle(uint8_t kind, double p0, double p1, int ctl, double k_m)
{
    mdr_contact_f64 c;
    mdr_scene_f64 s;
    mdr_scene_q31 q;
    mdr_energy_f64 en;
    const double k[3] = {p0, p1, 0};
    double worst = 0, eabs_d = 0, eabs_F = 0, Fpk = 0, dpk = 0, umax, umin, a_max = 0;
    int i;
    assert_int_equal(mdr_contact_init_f64(&c, kind, k, E, W), MDR_OK);
    extremes(&c, ctl, k_m, &umax, &umin);
    /* the cycle's largest radius (f64), a little more: the q31 scene's a_max */
    assert_int_equal(mdr_scene_init_contact_f64(&s, &c, W / 2, k_m, MDR_OUT_ALL, NULL), MDR_OK);
    for (i = 0; i <= TICKS; i++) {
        mdr_step_f64 o;
        assert_int_equal(step_scene64(&s, ctl, path(i, umax, umin), &o), MDR_OK);
        a_max = fmax(a_max, o.a);
    }
    assert_int_equal(mdr_scene_init_contact_f64(&s, &c, W / 2, k_m, MDR_OUT_ALL, &en), MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, 1.01 * a_max), MDR_OK);
    assert_int_equal(q.outputs, MDR_OUT_ALL | MDR_OUT_ENERGY);
    for (i = 0; i <= TICKS; i++) {
        const double u = path(i, umax, umin);
        const double unit = (ctl == MDR_CONTROL_GRIPS ? q.D0 : ctl == MDR_CONTROL_LOAD ? q.F0 : q.Z0) / 536870912.0;
        const int32_t raw = (int32_t)lround(u / unit);
        mdr_step_f64 o;
        mdr_step_q31 oq;
        double ed, eF;
        assert_int_equal(step_scene64(&s, ctl, raw * unit, &o), MDR_OK);
        assert_int_equal(step_scene_q31(&q, ctl, raw, &oq), MDR_OK);
        assert_int_equal(o.event, oq.event);
        ed = fabs(oq.d * (q.D0 / 536870912.0) - o.d);
        eF = fabs(oq.F * (q.F0 / 536870912.0) - o.F);
        eabs_d = fmax(eabs_d, ed);
        eabs_F = fmax(eabs_F, eF);
        worst = fmax(worst, fmax(ed / q.D0, eF / q.F0) * 536870912.0);
        Fpk = fmax(Fpk, fabs(o.F));
        dpk = fmax(dpk, fabs(o.d));
    }
    assert_int_equal(q.flags, 0);
    assert_int_equal(q.en.cycles, en.cycles);
    assert_int_equal(en.cycles, 1);
    {
        rel_le(mdr_scene_q31_energy(&q, q.en.last_cycle), en.last_cycle, 0, TOL_Q31_EN, "q31 scene energy");
    }
    printf("  (profile %d control %d k_m %g: %.2e of max|F|, %.2e of max|d|, %.1f LSB; energy %.2e)\n", kind, ctl,
           k_m, eabs_F / Fpk, eabs_d / dpk, worst,
           fabs(mdr_scene_q31_energy(&q, q.en.last_cycle) / en.last_cycle - 1.0));
    rel_le(Fpk + eabs_F, Fpk, 0, TOL_Q31_REL, "q31 scene F / max|F|");
    rel_le(dpk + eabs_d, dpk, 0, TOL_Q31_REL, "q31 scene d / max|d|");
    return worst;
}

/* every monomial (paraboloid, cone, power laws n = 3 and n = 8, the
 * steepest: the int64 headroom of U' and U'') under every control, the
 * machine soft and stiff: the worst of run over them (its LSB); a cycle
 * under fixed grips within TOL_Q31_GRIPS where grips_tol */
static double q31_each(double (*run)(uint8_t, double, double, int, double), int grips_tol)
{
    static const struct {
        uint8_t kind;
        double p0, p1;
    } prof[4] = {{MDR_PROFILE_PARABOLOID, 1e-6, 0},
                 {MDR_PROFILE_CONE, 0.3, 0},
                 {MDR_PROFILE_POWERLAW, 1e12, 3},
                 {MDR_PROFILE_POWERLAW, 1e42, MDR_POWERLAW_N_MAX}};
    double worst = 0;
    int j, ctl;
    for (j = 0; j < 4; j++) {
        for (ctl = 1; ctl <= 3; ctl++) {
            const double w = run(prof[j].kind, prof[j].p0, prof[j].p1, ctl, ctl == 3 ? 0.5 : 0.0);
            if (grips_tol) {
                printf("  q31 scene profile %d control %d: %.1f LSB\n", prof[j].kind, ctl, w);
                assert_true(ctl != MDR_CONTROL_GRIPS || w <= TOL_Q31_GRIPS);
            }
            worst = fmax(worst, w);
        }
        worst = fmax(worst, run(prof[j].kind, prof[j].p0, prof[j].p1, MDR_CONTROL_MACHINE, 20.0));
    }
    return worst;
}

/* whole cycles of four monomials under each control against f64 */
static void scene_q31_vs_f64(void **state)
{
    double worst = q31_each(q31_cycle, 1);
    (void)state;
    printf("  q31 scene against f64: worst %.1f LSB (tolerance %.0f)\n", worst, TOL_Q31_LSB);
    assert_true(worst <= TOL_Q31_LSB);
}

/* One tick of any size: the q31 scene answers every control its range
 * holds, as the f64 scene does, whatever the distance from the edge (the
 * cycles above move a little per tick; a root search climbing from a small
 * contact toward a root near a = L must not step past L and refuse). Per
 * profile, control and start (separated, or a contact at 5 % of the
 * largest control), one tick to 20, 50, 80 and 100 % of it, then one back
 * to the start: both scenes accept, the same event, d and F within
 * TOL_Q31_STEP. */
static double q31_any_step(uint8_t kind, double p0, double p1, int ctl, double k_m)
{
    mdr_contact_f64 c;
    mdr_scene_f64 s0, s;
    mdr_scene_q31 q0, q;
    const double k[3] = {p0, p1, 0}, to[4] = {0.2, 0.5, 0.8, 1.0}, from[2] = {-1.0, 0.05};
    double umax, umin, a_max = 0, worst = 0, unit;
    int i, j, m;
    assert_int_equal(mdr_contact_init_f64(&c, kind, k, E, W), MDR_OK);
    extremes(&c, ctl, k_m, &umax, &umin);
    assert_int_equal(mdr_scene_init_contact_f64(&s0, &c, W / 2, k_m, MDR_OUT_ALL, NULL), MDR_OK);
    s = s0;
    for (i = 0; i <= TICKS / 4; i++) { /* the largest radius: at umax */
        mdr_step_f64 o;
        assert_int_equal(step_scene64(&s, ctl, path(i, umax, umin), &o), MDR_OK);
        a_max = fmax(a_max, o.a);
    }
    assert_int_equal(mdr_scene_init_q31_f64(&q0, &s0, 1.01 * a_max), MDR_OK);
    unit = (ctl == MDR_CONTROL_GRIPS ? q0.D0 : ctl == MDR_CONTROL_LOAD ? q0.F0 : q0.Z0) / 536870912.0;
    for (j = 0; j < 2; j++) {
        for (m = 0; m < 4; m++) {
            /* separated: a control below the touch point (grips, machine:
             * a negative depth; load: F = 0, which touches without a jump
             * only at w_adv = 0, so load starts from its small contact) */
            const double u0 = j == 0 ? (ctl == MDR_CONTROL_LOAD ? 0.05 * umax : -0.5 * umax) : from[j] * umax;
            const double us[3] = {u0, to[m] * umax, u0};
            int t;
            s = s0;
            q = q0;
            for (t = 0; t < 3; t++) {
                const int32_t raw = (int32_t)lround(us[t] / unit);
                mdr_step_f64 o;
                mdr_step_q31 oq;
                mdr_status sq = step_scene_q31(&q, ctl, raw, &oq);
                assert_int_equal(step_scene64(&s, ctl, raw * unit, &o), MDR_OK);
                if (sq != MDR_OK) {
                    printf("q31 scene profile %d control %d k_m %g: tick %d to %g of umax from %g refused (%d)\n",
                           kind, ctl, k_m, t, us[t] / umax, u0 / umax, sq);
                }
                assert_int_equal(sq, MDR_OK);
                assert_int_equal(oq.event, o.event);
                worst = fmax(worst, fabs(oq.d * (q.D0 / 536870912.0) - o.d) / q.D0 * 536870912.0);
                worst = fmax(worst, fabs(oq.F * (q.F0 / 536870912.0) - o.F) / q.F0 * 536870912.0);
            }
        }
    }
    return worst;
}

static void scene_q31_any_step(void **state)
{
    double worst = q31_each(q31_any_step, 0);
    (void)state;
    printf("  q31 scene, single ticks of any size against f64: worst %.1f LSB (tolerance %.0f)\n", worst,
           TOL_Q31_STEP);
    assert_true(worst <= TOL_Q31_STEP);
}

/* Force only against every output: the step answers a tick asked for d
 * and F alone by its own paths (a pinned tick, a move, the first pinned
 * tick after a move, which computes the coefficients the moves left,
 * MDR_M_LAZY), a tick with outputs through the full tick; both must give
 * the same state. A cycle that dithers (every 8 ticks: back 3 ticks of the
 * path, held there a tick, then on), per profile and control, f64, f32 and
 * q31: d and F bit for bit at every tick, and the test counts the ticks it
 * is about (the edge held right after it moved; the same edge radius as
 * the tick before, with every output). Now and then right after a move
 * (stale coefficients) a NaN control (refused: the instance unchanged) and
 * a tick under the other control of d or F at the state's own value (a
 * change of control mode; at a band's end, so whether the edge then moves
 * is rounding's call: test_step checks a change to the band's middle),
 * both again bit for bit. Returns the count. */
static double force_only(uint8_t kind, double p0, double p1, int ctl, double k_m)
{
    mdr_contact_f64 c;
    mdr_scene_f64 a64, b64;
    mdr_scene_f32 a32, b32;
    mdr_scene_q31 aq, bq;
    const double k[3] = {p0, p1, 0};
    double umax, umin, unit, a_max = 0, a_prev = 0;
    int i, moved = 0, held_after_move = 0, switched = 0;
    mdr_step_f64 last64;
    mdr_step_f32 last32;
    mdr_step_q31 lastq;
    assert_int_equal(mdr_contact_init_f64(&c, kind, k, E, W), MDR_OK);
    extremes(&c, ctl, k_m, &umax, &umin);
    assert_int_equal(mdr_scene_init_contact_f64(&a64, &c, W / 2, k_m, MDR_OUT_FORCE, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_contact_f64(&b64, &c, W / 2, k_m, MDR_OUT_ALL, NULL), MDR_OK);
    {
        mdr_contact_f32 c32;
        const float k32[3] = {(float)p0, (float)p1, 0};
        assert_int_equal(mdr_contact_init_f32(&c32, kind, k32, (float)E, (float)W), MDR_OK);
        assert_int_equal(mdr_scene_init_contact_f32(&a32, &c32, (float)W / 2, (float)k_m, MDR_OUT_FORCE, NULL),
                         MDR_OK);
        assert_int_equal(mdr_scene_init_contact_f32(&b32, &c32, (float)W / 2, (float)k_m, MDR_OUT_ALL, NULL),
                         MDR_OK);
    }
    for (i = 0; i <= TICKS / 4; i++) { /* the largest radius: at umax */
        mdr_step_f64 o;
        assert_int_equal(step_scene64(&b64, ctl, path(i, umax, umin), &o), MDR_OK);
        a_max = fmax(a_max, o.a);
    }
    assert_int_equal(mdr_scene_init_contact_f64(&b64, &c, W / 2, k_m, MDR_OUT_ALL, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(&aq, &a64, 1.01 * a_max), MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(&bq, &b64, 1.01 * a_max), MDR_OK);
    unit = (ctl == MDR_CONTROL_GRIPS ? aq.D0 : ctl == MDR_CONTROL_LOAD ? aq.F0 : aq.Z0) / 536870912.0;
    for (i = 0; i <= TICKS; i++) {
        const double u = path(i % 8 == 5 || i % 8 == 6 ? i - 3 : i, umax, umin);
        const int32_t raw = (int32_t)lround(u / unit);
        mdr_step_f64 oa, ob;
        mdr_step_f32 pa, pb;
        mdr_step_q31 qa, qb;
        assert_int_equal(step_scene64(&a64, ctl, u, &oa), MDR_OK);
        assert_int_equal(step_scene64(&b64, ctl, u, &ob), MDR_OK);
        assert_int_equal(step_scene32(&a32, ctl, (float)u, &pa), MDR_OK);
        assert_int_equal(step_scene32(&b32, ctl, (float)u, &pb), MDR_OK);
        assert_int_equal(step_scene_q31(&aq, ctl, raw, &qa), MDR_OK);
        assert_int_equal(step_scene_q31(&bq, ctl, raw, &qb), MDR_OK);
        if (!(oa.d == ob.d && oa.F == ob.F && pa.d == pb.d && pa.F == pb.F && qa.d == qb.d && qa.F == qb.F)) {
            printf("profile %d control %d k_m %g tick %d: force only d %.17g F %.17g (f32 %.9g %.9g, q31 %ld "
                   "%ld), every output d %.17g F %.17g (f32 %.9g %.9g, q31 %ld %ld)\n",
                   kind, ctl, k_m, i, oa.d, oa.F, (double)pa.d, (double)pa.F, (long)qa.d, (long)qa.F, ob.d, ob.F,
                   (double)pb.d, (double)pb.F, (long)qb.d, (long)qb.F);
            fail();
        }
        if (ob.a > 0 && ob.a == a_prev && moved) {
            held_after_move++;
        }
        if (ob.a > 0 && moved && i % 97 == 0) {
            /* right after a move (the coefficients stale): one tick under
             * the other control of d or F at the state's own value, and a
             * NaN control (refused, the instance unchanged), then on under
             * ctl (a new control mode: the slow path's full band) */
            const int other = ctl == MDR_CONTROL_GRIPS ? MDR_CONTROL_LOAD : MDR_CONTROL_GRIPS;
            const mdr_scene_f64 keep64 = a64;
            const mdr_scene_f32 keep32 = a32;
            assert_int_equal(step_scene64(&a64, ctl, NAN, &last64), MDR_E_NONFINITE);
            assert_int_equal(step_scene32(&a32, ctl, NAN, &last32), MDR_E_NONFINITE);
            assert_memory_equal(&a64, &keep64, sizeof a64);
            assert_memory_equal(&a32, &keep32, sizeof a32);
            assert_int_equal(step_scene64(&a64, other, other == MDR_CONTROL_GRIPS ? oa.d : oa.F, &oa), MDR_OK);
            assert_int_equal(step_scene64(&b64, other, other == MDR_CONTROL_GRIPS ? ob.d : ob.F, &ob), MDR_OK);
            assert_int_equal(step_scene32(&a32, other, other == MDR_CONTROL_GRIPS ? pa.d : pa.F, &pa), MDR_OK);
            assert_int_equal(step_scene32(&b32, other, other == MDR_CONTROL_GRIPS ? pb.d : pb.F, &pb), MDR_OK);
            assert_int_equal(other == MDR_CONTROL_GRIPS ? mdr_scene_step_d_q31(&aq, qa.d, &lastq)
                                                        : mdr_scene_step_F_q31(&aq, qa.F, &lastq),
                             MDR_OK);
            qa = lastq;
            assert_int_equal(other == MDR_CONTROL_GRIPS ? mdr_scene_step_d_q31(&bq, qb.d, &lastq)
                                                        : mdr_scene_step_F_q31(&bq, qb.F, &lastq),
                             MDR_OK);
            qb = lastq;
            if (!(oa.d == ob.d && oa.F == ob.F && pa.d == pb.d && pa.F == pb.F && qa.d == qb.d && qa.F == qb.F)) {
                printf("profile %d control %d k_m %g tick %d, switched to control %d: force only and every "
                       "output differ\n", kind, ctl, k_m, i, other);
                fail();
            }
            switched++;
        }
        moved = ob.a != a_prev;
        a_prev = ob.a;
    }
    assert_true(switched > 0);
    return held_after_move;
}

static void scene_force_only(void **state)
{
    static const struct {
        uint8_t kind;
        double p0, p1;
    } prof[3] = {{MDR_PROFILE_PARABOLOID, 1e-6, 0}, {MDR_PROFILE_CONE, 0.3, 0}, {MDR_PROFILE_POWERLAW, 1e12, 3}};
    double least = TICKS;
    int j, ctl;
    (void)state;
    for (j = 0; j < 3; j++) {
        for (ctl = 1; ctl <= 4; ctl++) { /* (4: the machine at k_m 20) */
            least = fmin(least, force_only(prof[j].kind, prof[j].p0, prof[j].p1, ctl < 4 ? ctl : (int)MDR_CONTROL_MACHINE,
                                           ctl == 3 ? 0.5 : ctl == 4 ? 20.0 : 0.0));
        }
    }
    printf("  scene force only = every output, bit for bit, f64 f32 q31: %.0f ticks at least held right after "
           "a move (of %d)\n", least, TICKS);
    assert_true(least >= TICKS / 40);
}

/* A stiff machine's pinned band near a = L: z 2^sz = (1 + kappa x) D -
 * kappa G at a band end is a depth of (1 + kappa x) times the scene's
 * (tens of units of D0 at kappa ~ 160), which only its quotient by 2^sz
 * brings back into range (a band end saturated before that division put
 * the band's lower end at 2^-5 units, so a retract's ticks stayed pinned
 * far below the receding branch: d 0.5 % of D0 off, found by fuzz_step).
 * The paraboloid with little adhesion (w = W/1000, w_adv = w/2: D ~ g, so
 * the band's ends are large) under a machine of kappa 160 at L: 600
 * ticks of z up to where a = 0.98 L, 600 back down to half that z, against
 * the f64 scene at the same raw control: the same events, d and F within
 * TOL_Q31_STEP. */
static void scene_q31_stiff_top(void **state)
{
    mdr_scene_f64 s0, s;
    mdr_scene_q31 q;
    double z_top = 0, worst = 0, unit, km;
    int i, pinned = 0, moved = 0;
    (void)state;
    assert_int_equal(mdr_scene_init_paraboloid_f64(&s0, R, E, W / 1000, W / 2000, 1.0, MDR_OUT_ALL, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s0, 0.7e-6), MDR_OK);
    km = 2.0 * E * (double)q.L / 160.0; /* kappa 160 at L */
    assert_int_equal(mdr_scene_init_paraboloid_f64(&s0, R, E, W / 1000, W / 2000, km, MDR_OUT_ALL, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s0, 0.7e-6), MDR_OK);
    unit = q.Z0 / 536870912.0;
    s = s0;
    for (i = 1; z_top == 0; i++) { /* the f64 scene's z at a = 0.98 L */
        mdr_step_f64 o;
        assert_true(i < 100000);
        assert_int_equal(mdr_scene_step_z_f64(&s, i * 1e-4 * q.Z0, &o), MDR_OK);
        z_top = o.a >= 0.98 * (double)q.L ? o.z : 0;
    }
    s = s0;
    for (i = 0; i <= 1200; i++) {
        const double z = i <= 600 ? z_top * i / 600 : z_top * (1.0 - 0.5 * (i - 600) / 600);
        const int32_t raw = (int32_t)lround(z / unit);
        const double t0 = s.tau;
        mdr_step_f64 o;
        mdr_step_q31 oq;
        assert_int_equal(mdr_scene_step_z_f64(&s, raw * unit, &o), MDR_OK);
        assert_int_equal(mdr_scene_step_z_q31(&q, raw, &oq), MDR_OK);
        assert_int_equal(oq.event, o.event);
        pinned += i > 600 && s.tau == t0;
        moved += i > 600 && s.tau < t0;
        worst = fmax(worst, fabs(oq.d * (q.D0 / 536870912.0) - o.d) / q.D0 * 536870912.0);
        worst = fmax(worst, fabs(oq.F * (q.F0 / 536870912.0) - o.F) / q.F0 * 536870912.0);
    }
    printf("  q31 scene, kappa 160 up to a = 0.98 L and back (f64: %d pinned, %d receding ticks): worst %.1f LSB "
           "(tolerance %.0f)\n",
           pinned, moved, worst, TOL_Q31_STEP);
    assert_true(pinned >= 5 && moved > 100);
    assert_true(worst <= TOL_Q31_STEP);
}

/* A load's pull-off at a fold whose radius is below the resolution of x
 * (found by fuzz_step): a cone with very little adhesion (w = 1e-6 J/m^2
 * at E* = 5e11 Pa: the load's fold at a ~ 1e-12 L, x = a/L = 0 in Q1.30),
 * where the state's depth u/x + g/(n+1) divided by x = 0. Its pull-off
 * force lies far below one LSB of F: init now refuses the scene
 * (MDR_E_PARAM, the adhesion unresolved: MDR_Q31_ADH_LSB), so no fold that
 * low is reached (the state's guard of x = 0 stays). */
static void scene_q31_load_fold_unresolved(void **state)
{
    mdr_contact_f64 c;
    mdr_scene_f64 s;
    mdr_scene_q31 q;
    const double p[3] = {0.78196078431372551, 0, 0};
    (void)state;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_CONE, p, 521971822043.56415, 1e-6), MDR_OK);
    assert_int_equal(mdr_scene_init_contact_f64(&s, &c, 2.1176470588235293e-07, 35776054287.813957, MDR_OUT_ALL, NULL),
                     MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, 0.78636642643426413), MDR_E_PARAM);
}

/* The adhesion's resolution against a_max (tolerances at the top): a power
 * law g = C x^n (C = 0.1 (10 um)^(1-n)), E* = 1e6 Pa, w = 0.05 J/m^2,
 * w_adv = w/2, a_max = f a_po (a_po the f64 scene's pull-off radius under
 * fixed load); L and F0 of the q31 scene worked out here as its init
 * documents them (L = a_s 4^k, the least >= a_max; D0 = D_s 2^j, the least
 * power of two >= g(L) + dl_w(L); F0 = F_s (L/a_s) 2^j), the pull-off
 * force in LSB of F from the f64 scene's. Then under fixed load: touch,
 * press to 2 |F_po|, pull to -2 |F_po| in 4000 ticks, both scenes at the
 * same raw control. */
static void scene_q31_adhesion_range(void **state)
{
    static const double f[] = {1.2, 2.0, 3.0, 5.0, 10.0, 30.0, 100.0, 300.0};
    int n, i, accepted = 0, refused = 0;
    double worst = 0.0, worst_rel = 0.0;
    (void)state;
    for (n = 1; n <= MDR_POWERLAW_N_MAX; n++) {
        for (i = 0; i < (int)(sizeof f / sizeof f[0]); i++) {
            const double pl[3] = {0.1 * pow(10e-6, 1 - n), n, 0};
            mdr_contact_f64 c;
            mdr_scene_f64 s;
            mdr_scene_q31 q;
            double apo, amax, L, tL = 1.0, gL, M, D0, F0, Fpo, lsb, po64 = 0.0, poq = 0.0;
            int st, k, ev64 = 0, evq = 0;
            assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_POWERLAW, pl, E, W), MDR_OK);
            assert_int_equal(mdr_scene_init_contact_f64(&s, &c, W / 2, 0.0, MDR_OUT_ALL, NULL), MDR_OK);
            apo = s.as * s.tf[0] * s.tf[0];
            amax = f[i] * apo;
            for (L = s.as; L < amax; L *= 4.0) {
                tL *= 2.0;
            }
            for (; L / 4.0 >= amax; L /= 4.0) {
                tL /= 2.0;
            }
            gL = pow(tL, 2.0 * n);
            M = gL + s.gw * tL;
            D0 = s.Ds * pow(2.0, ceil(log2(M)));
            F0 = s.Fs * (L / s.as) * (D0 / s.Ds);
            Fpo = s.uf[0] * s.Fs; /* (< 0) */
            lsb = -Fpo / (F0 / 536870912.0);
            st = mdr_scene_init_q31_f64(&q, &s, amax);
            if (lsb < MDR_Q31_ADH_LSB * 0.99) {
                assert_int_equal(st, MDR_E_PARAM);
                refused++;
                continue;
            }
            if (lsb > MDR_Q31_ADH_LSB * 1.01) {
                assert_int_equal(st, MDR_OK);
            } else if (st != MDR_OK) { /* (at the limit either) */
                continue;
            }
            assert_true(fabs(q.F0 - F0) <= 1e-6 * F0); /* (the units worked out as init does) */
            for (k = 0; k <= 4000; k++) {
                const double u = k <= 1000 ? -2.0 * Fpo * k / 1000 : -2.0 * Fpo + 4.0 * Fpo * (k - 1000) / 3000;
                const int32_t raw = (int32_t)lround(u / (q.F0 / 536870912.0));
                mdr_step_f64 o;
                mdr_step_q31 oq;
                assert_int_equal(mdr_scene_step_F_f64(&s, raw * (q.F0 / 536870912.0), &o), MDR_OK);
                assert_int_equal(mdr_scene_step_F_q31(&q, raw, &oq), MDR_OK);
                if (o.event == MDR_EV_PULL_OFF) {
                    assert_int_equal(ev64, 0);
                    ev64 = k;
                    po64 = o.F0;
                }
                if (oq.event == MDR_EV_PULL_OFF) {
                    assert_int_equal(evq, 0);
                    evq = k;
                    poq = oq.F0 * (q.F0 / 536870912.0);
                }
            }
            assert_true(ev64 > 1000 && evq > 1000);
            worst = fmax(worst, fabs(poq - po64) / (q.F0 / 536870912.0));
            worst_rel = fmax(worst_rel, fabs(poq - po64) / fabs(po64));
            assert_true(fabs(poq - po64) <= TOL_Q31_PO * (q.F0 / 536870912.0));
            accepted++;
        }
    }
    printf("  q31 scene's adhesion against a_max: %d ranges accepted, %d refused (below %d LSB); worst pull-off "
           "%.1f LSB (tolerance %.0f), %.1e relative\n",
           accepted, refused, MDR_Q31_ADH_LSB, worst, TOL_Q31_PO, worst_rel);
    assert_true(accepted >= 2 * MDR_POWERLAW_N_MAX && refused >= 2 * MDR_POWERLAW_N_MAX);
}

/* A pull-off by a load at the documented range's end (-2 units, raw
 * -2^30, and one LSB inside it): every output in range, so no saturation
 * flag (the slow path used to evaluate the pinned relation at the control
 * before it knew the edge moves, and its d saturated; found by a helper).
 * The same pull-off as from a load just past it (-1e6 raw). */
static void scene_q31_pull_at_range_end(void **state)
{
    static const int32_t v[] = {-1073741824, -1073741823, -1000000};
    mdr_scene_f32 s;
    mdr_scene_q31 q;
    mdr_step_q31 o, ref;
    int i;
    (void)state;
    memset(&ref, 0, sizeof ref);
    assert_int_equal(mdr_scene_init_paraboloid_f32(&s, 10e-6f, 1e6f, 0.05f, 0.025f, 0.f, MDR_OUT_ALL, NULL), MDR_OK);
    for (i = 2; i >= 0; i--) {
        assert_int_equal(mdr_scene_init_q31_f32(&q, &s, 20e-6f), MDR_OK);
        assert_int_equal(mdr_scene_step_F_q31(&q, 20000000, &o), MDR_OK);
        assert_int_equal(mdr_scene_step_F_q31(&q, v[i], &o), MDR_OK);
        assert_int_equal(o.event, MDR_EV_PULL_OFF);
        assert_int_equal(q.flags, 0);
        if (i == 2) {
            ref = o;
        }
        assert_int_equal(o.d, ref.d);
        assert_int_equal(o.F0, ref.F0);
        assert_int_equal(o.d0, ref.d0);
    }
}

/* bad input: named errors, the scene unchanged; saturation flagged */
/* A scene no init filled (zeroed: a static instance after a refused init,
 * its status ignored) is refused in contact, MDR_E_NULL, in every
 * arithmetic, and left as it was; helper-32, stop 58: a firmware built
 * without MDR_CFG_EVENTS kept its MDR_OUT_ALL init (MDR_E_DISABLED) and the
 * f32 scene then answered F = 0 at every depth, MDR_OK. (A control at or
 * below 0 is a separated tick, answered as such.) */
static void scene_zeroed(void **state)
{
    static const mdr_scene_f32 z32;
    static const mdr_scene_f64 z64;
    static const mdr_scene_q31 zq;
    mdr_scene_f32 s32 = z32;
    mdr_scene_f64 s64 = z64;
    mdr_scene_q31 q = zq;
    mdr_step_f32 o32;
    mdr_step_f64 o64;
    mdr_step_q31 oq;
    (void)state;
    assert_int_equal(mdr_scene_step_d_f32(&s32, 2e-9f, &o32), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_F_f32(&s32, 1e-9f, &o32), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_d_f64(&s64, 2e-9, &o64), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_F_f64(&s64, 1e-9, &o64), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_d_q31(&q, 1 << 20, &oq), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_F_q31(&q, 1 << 20, &oq), MDR_E_NULL);
    assert_memory_equal(&s32, &z32, sizeof s32);
    assert_memory_equal(&s64, &z64, sizeof s64);
    assert_memory_equal(&q, &zq, sizeof q);
    assert_int_equal(mdr_scene_step_d_f32(&s32, -2e-9f, &o32), MDR_OK);
    assert_true(o32.F == 0.0f);
}

/* A slow retraction toward the pull-off, one LSB of the control a tick
 * (helper-74): on every such tick the f64 scene recedes, and the q31 scene
 * made from it, at the same raw control, gives a d within the f64 scene's
 * own spread over one LSB of the control (f64's d at raw - 1 from the
 * state before the tick, and that state's, at raw + 1) and TOL_Q31_SPREAD
 * LSB of D0, but for the last TOL_Q31_FOLD_LSB before the fold. Near the
 * fold one LSB of the control moves the edge far (here up to 9 000 LSB of
 * d), and where the slow path's move recomputed the band's end from the
 * rounded edge (an LSB beyond the control), the next tick held the edge
 * where it recedes, d moved along the pinned line instead: 120 LSB of D0
 * beyond f64's spread (13 ticks held), MDR_OK, no flag (the helper's cycle
 * of this cone: 4 279 LSB of D0 off the f64 scene at the same control).
 * Scenes whose pull-off is resolved to a few thousand LSB of the control
 * (a_max 3.8 times the cycle's largest radius): a cone under load and a
 * power law n = 3 through a machine, the helper's; approach to 58 times
 * the fold's control, retract to 0.985 of it, then one LSB a tick to the
 * pull-off. A third, helper-79's (stop 76), a known limit held to its size:
 * a paraboloid through a soft machine (kappa ~ 245; approach to 4 fold
 * controls; a_max twice the helper's, at whose own the free d after the
 * pull-off saturates, flagged), where the edge lies 1.0 to 1.6 LSB of U
 * from its root (U's rounding, MDR_S_UTOL) and one LSB of z moves d by
 * hundreds of LSB of D0: up to TOL_Q31_SPREAD_FOLD beyond f64's spread
 * (docs/fixed-point.md; a wider U near the fold would bring it to
 * TOL_Q31_SPREAD). */
#define TOL_Q31_SPREAD 8.0  /* LSB of D0 beyond f64's spread [measured 0; 120 before] */
#define TOL_Q31_SPREAD_FOLD 250.0 /* the third case's known limit [measured 137.1: the helper's 547 at its a_max,
                                     whose LSB of D0 is 4 times finer] */
#define TOL_Q31_FOLD_LSB 4 /* the last LSB of the control before the fold, where U's rounding
                              (MDR_S_UTOL) decides: not compared [there 13 LSB of D0] */
static void scene_q31_slow_recede(void **state)
{
    static const struct {
        uint8_t kind, ctl;
        double p0, n, E, w, wadv, km, amax, tol, top; /* top: the approach's end, in fold controls */
        const char *what;
    } cs[] = {
        {MDR_PROFILE_CONE, MDR_CONTROL_LOAD, 0.97797550030657299, 0, 71677417.801328987, 0.0013997867144185145,
         0.00044450683308676256, 0.0, 1.0455577881926018e-09, TOL_Q31_SPREAD, 58.0, "load, cone"},
        {MDR_PROFILE_POWERLAW, MDR_CONTROL_MACHINE, 20159997182256.438, 3, 4768231380.1649618, 0.0021231243243786556,
         0.0016985702512746024, 65.538197386957009, 1.5337201626124437e-07, TOL_Q31_SPREAD, 58.0,
         "machine, power law n = 3"},
        {MDR_PROFILE_PARABOLOID, MDR_CONTROL_MACHINE, 0.000134494632597772, 0, 2887894.1151408623,
         0.0036134902846169546, 0.0, 0.10157109065133932, 2.8070560156612664e-05, TOL_Q31_SPREAD_FOLD, 4.0,
         "machine, paraboloid, helper-79's"},
    };
    unsigned k;
    (void)state;
    for (k = 0; k < sizeof cs / sizeof cs[0]; k++) {
        const double p[3] = {cs[k].p0, cs[k].n, 0};
        const int ctl = cs[k].ctl;
        mdr_contact_f64 c;
        mdr_scene_f64 s;
        mdr_scene_q31 q;
        double D0, unit, lsb_d, worst = 0.0;
        int32_t raw_f, raw, mid;
        int i, slow = 0, moved = 0, po = 0, jd, held = 0;
        assert_int_equal(mdr_contact_init_f64(&c, cs[k].kind, p, cs[k].E, cs[k].w), MDR_OK);
        assert_int_equal(mdr_scene_init_contact_f64(&s, &c, cs[k].wadv, cs[k].km, MDR_OUT_ALL, NULL), MDR_OK);
        assert_int_equal(mdr_scene_init_q31_f64(&q, &s, cs[k].amax), MDR_OK);
        /* the units exactly (the float fields are rounded): D0 = D_s 2^j,
         * F0 = F_s (L/a_s) 2^j with L/a_s a power of 4, Z0 = 2^sz D0 */
        jd = (int)lround(log2((double)q.D0 / s.Ds));
        D0 = ldexp(s.Ds, jd);
        lsb_d = D0 / 536870912.0;
        unit = ctl == MDR_CONTROL_LOAD ? ldexp(s.Fs, jd + (int)lround(log2((double)q.L / s.as))) / 536870912.0
                                       : D0 * q.z_mul / 536870912.0;
        raw_f = (int32_t)lround((ctl == MDR_CONTROL_LOAD ? s.uf[0] * s.Fs : s.uf[2] * s.Ds) / unit);
        mid = (int32_t)lround(0.985 * raw_f);
        for (i = 0; !po; i++) {
            mdr_scene_f64 prev = s, alt;
            const mdr_scene_q31 qprev = q;
            mdr_step_f64 o, oa;
            mdr_step_q31 oq;
            raw = i <= 2000   ? (int32_t)lround(-cs[k].top * raw_f * i / 2000)
                  : i <= 3000 ? (int32_t)lround(-cs[k].top * raw_f + (mid + cs[k].top * raw_f) * (i - 2000) / 1000)
                              : mid - (i - 3000);
            assert_true(i < 3000 + 2 * (mid - raw_f) + 100);
            assert_int_equal(step_scene64(&s, ctl, raw * unit, &o), MDR_OK);
            assert_int_equal(step_scene_q31(&q, ctl, raw, &oq), MDR_OK);
            assert_int_equal(q.flags, 0);
            po = o.event == MDR_EV_PULL_OFF || oq.event == MDR_EV_PULL_OFF;
            if (i <= 3000 || po) {
                continue;
            }
            /* a tick of the slow retraction, both in contact */
            alt = prev;
            assert_int_equal(step_scene64(&alt, ctl, (raw - 1) * unit, &oa), MDR_OK);
            slow++;
            if (s.tau < prev.tau) {
                moved++;
                held += !(q.tau < qprev.tau);
            }
            if (raw - raw_f > TOL_Q31_FOLD_LSB) {
                const double dq = oq.d * lsb_d, lo = fmin(oa.d, prev.d), hi = fmax(oa.d, prev.d);
                const double ex = (dq < lo ? lo - dq : dq > hi ? dq - hi : 0.0) / lsb_d;
                worst = fmax(worst, ex);
                assert_true(ex <= cs[k].tol);
            }
        }
        printf("  q31 scene, slow retraction (%s): %d ticks of one LSB, f64 receded on %d, q31 held its edge on %d "
               "of them; d beyond f64's spread over one LSB %.1f LSB of D0 (tolerance %.0f)\n",
               cs[k].what, slow, moved, held, worst, cs[k].tol);
        assert_true(slow >= 40 && moved == slow);
    }
}

static void scene_q31_errors(void **state)
{
    mdr_scene_f64 s;
    mdr_scene_q31 q, before;
    mdr_step_q31 o;
    int32_t raw = 7;
    int i;
    (void)state;
    assert_int_equal(mdr_scene_init_paraboloid_f64(&s, R, E, W, W / 2, 0.0, MDR_OUT_ALL, NULL), MDR_OK);
    assert_int_equal(mdr_scene_init_q31_f64(NULL, &s, 1e-6), MDR_E_NULL);
    assert_int_equal(mdr_scene_init_q31_f64(&q, NULL, 1e-6), MDR_E_NULL);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, NAN), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, INFINITY), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, 0.0), MDR_E_PARAM);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, -1e-6), MDR_E_PARAM);
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, 1e-9), MDR_E_PARAM); /* below the folds */
    {
        mdr_scene_f64 m;
        assert_int_equal(mdr_scene_init_paraboloid_f64(&m, R, E, W, W / 2, 1e-9, MDR_OUT_ALL, NULL), MDR_OK);
        assert_int_equal(mdr_scene_init_q31_f64(&q, &m, 1e-6), MDR_E_CONTROL); /* kappa 2e6 */
    }
    assert_int_equal(mdr_scene_init_q31_f64(&q, &s, 0.7e-6), MDR_OK);
    assert_int_equal(mdr_scene_q31_from_si(&q, MDR_Q_D, 1e-8f, &raw), MDR_OK);
    assert_int_equal(mdr_scene_step_d_q31(&q, raw, &o), MDR_OK);
    assert_int_equal(q.contact, 1);
    before = q;
    assert_int_equal(mdr_scene_step_d_q31(NULL, raw, &o), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_d_q31(&q, raw, NULL), MDR_E_NULL);
    assert_int_equal(mdr_scene_step_z_q31(&q, raw, &o), MDR_E_CONTROL); /* no machine */
    assert_memory_equal(&q, &before, sizeof q);
    /* past a = L (d of 2 units is far beyond g(L) here): refused */
    assert_int_equal(mdr_scene_step_d_q31(&q, 2 * MDR_Q29_ONE, &o), MDR_E_OUTSIDE);
    assert_int_equal(q.flags, MDR_FLAG_OUTSIDE);
    q.flags = 0;
    assert_memory_equal(&q, &before, sizeof q);
    assert_int_equal(mdr_scene_step_F_q31(&q, 2 * MDR_Q29_ONE, &o), MDR_E_OUTSIDE);
    assert_int_equal(mdr_scene_clear_flags_q31(&q), MDR_FLAG_OUTSIDE);
    assert_int_equal(mdr_scene_clear_flags_q31(NULL), 0);
    assert_memory_equal(&q, &before, sizeof q);
    /* an input beyond +-2 units saturates and sets MDR_FLAG_SAT: the
     * separated body at d = -2 units */
    assert_int_equal(mdr_scene_step_d_q31(&q, INT32_MIN, &o), MDR_OK);
    assert_int_equal(o.d, -2 * MDR_Q29_ONE);
    assert_int_equal(o.F, 0);
    assert_int_equal(q.contact, 0);
    assert_int_equal(mdr_scene_clear_flags_q31(&q), MDR_FLAG_SAT);
    for (i = 0; i < 3; i++) { /* in range: no flag */
        assert_int_equal(mdr_scene_step_d_q31(&q, -MDR_Q29_ONE, &o), MDR_OK);
    }
    assert_int_equal(q.flags, 0);
    {
        /* without a machine no z is answered, whatever its sign or range,
         * separated and force only as well (the step's own path must not
         * take it), and nothing is flagged */
        mdr_scene_f64 f;
        mdr_scene_q31 k;
        const int32_t zs[4] = {-MDR_Q29_ONE, 0, INT32_MIN, INT32_MAX};
        assert_int_equal(mdr_scene_init_paraboloid_f64(&f, R, E, W, W / 2, 0.0, MDR_OUT_FORCE, NULL), MDR_OK);
        assert_int_equal(mdr_scene_init_q31_f64(&q, &f, 0.7e-6), MDR_OK);
        k = q;
        for (i = 0; i < 4; i++) {
            assert_int_equal(mdr_scene_step_z_q31(&q, zs[i], &o), MDR_E_CONTROL);
        }
        assert_memory_equal(&q, &k, sizeof q);
    }
    {
        /* a machine with 2^sz = 64 (kappa = 2 E* L/k_m in [63, 127)): the
         * last z whose depth z 2^6 fits (-2^25: d = INT32_MIN exactly) and
         * the first beyond it, separated, with every output (the full
         * tick) and force only (the step's own separated path) */
        int m;
        for (m = 0; m < 2; m++) {
            mdr_scene_f64 f;
            double km;
            assert_int_equal(mdr_scene_init_paraboloid_f64(&f, R, E, W, W / 2, 1.0, m ? MDR_OUT_FORCE : MDR_OUT_ALL,
                                                           NULL),
                             MDR_OK);
            assert_int_equal(mdr_scene_init_q31_f64(&q, &f, 0.7e-6), MDR_OK);
            km = 2.0 * E * (double)q.L / 90.0; /* kappa 90 */
            assert_int_equal(mdr_scene_init_paraboloid_f64(&f, R, E, W, W / 2, km, m ? MDR_OUT_FORCE : MDR_OUT_ALL,
                                                           NULL),
                             MDR_OK);
            assert_int_equal(mdr_scene_init_q31_f64(&q, &f, 0.7e-6), MDR_OK);
            assert_int_equal(q.sz, 6);
            assert_int_equal(mdr_scene_step_z_q31(&q, -(1 << 25), &o), MDR_OK);
            assert_int_equal(o.d, INT32_MIN);
            assert_int_equal(o.F, 0);
            assert_int_equal(q.flags, 0);
            assert_int_equal(mdr_scene_step_z_q31(&q, -(1 << 25) - 1, &o), MDR_OK);
            assert_int_equal(o.d, INT32_MIN);
            assert_int_equal(q.flags, MDR_FLAG_SAT);
            q.flags = 0;
            assert_int_equal(mdr_scene_step_z_q31(&q, -(1 << 25) + 1, &o), MDR_OK);
            assert_int_equal(o.d, INT32_MIN + 64);
            assert_int_equal(q.flags, 0);
            assert_int_equal(q.contact, 0);
        }
    }
    /* conversions */
    assert_int_equal(mdr_scene_q31_from_si(NULL, MDR_Q_D, 1e-8f, &raw), MDR_E_NULL);
    assert_int_equal(mdr_scene_q31_from_si(&q, 9, 1e-8f, &raw), MDR_E_PARAM);
    assert_int_equal(mdr_scene_q31_from_si(&q, MDR_Q_D, NAN, &raw), MDR_E_NONFINITE);
    assert_int_equal(mdr_scene_q31_from_si(&q, MDR_Q_D, 1.0f, &raw), MDR_E_OVERFLOW);
    assert_true(mdr_scene_q31_out(NULL, MDR_Q_D, 5) == 0.0f);
    assert_true(fabs(mdr_scene_q31_out(&q, MDR_Q_F, MDR_Q29_ONE) - q.F0) <= 1e-7 * q.F0);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scene_paraboloid_vs_engine),
        cmocka_unit_test(scene_cone_vs_engine),
        cmocka_unit_test(scene_soft_machine),
        cmocka_unit_test(scene_repeat_control),
        cmocka_unit_test(scene_jkr_pull_off),
        cmocka_unit_test(scene_outputs),
        cmocka_unit_test(scene_errors),
        cmocka_unit_test(scene_hertz_scale),
        cmocka_unit_test(scene_contact_small_against_units),
        cmocka_unit_test(scene_tiny_contact_not_stuck),
        cmocka_unit_test(scene_z_range),
        cmocka_unit_test(scene_z_soft_machine),
        cmocka_unit_test(scene_soft_machine_state),
        cmocka_unit_test(scene_z_other_controls),
        cmocka_unit_test(scene_machine_sweep),
        cmocka_unit_test(scene_energy_any_tick),
        cmocka_unit_test(scene_energy_power_laws),
#if MDR_CFG_Q31
        cmocka_unit_test(scene_q31_vs_f64),
        cmocka_unit_test(scene_q31_any_step),
        cmocka_unit_test(scene_force_only),
        cmocka_unit_test(scene_q31_stiff_top),
        cmocka_unit_test(scene_q31_load_fold_unresolved),
        cmocka_unit_test(scene_q31_adhesion_range),
        cmocka_unit_test(scene_q31_pull_at_range_end),
        cmocka_unit_test(scene_q31_slow_recede),
        cmocka_unit_test(scene_q31_errors),
        cmocka_unit_test(scene_zeroed),
#endif
    };
    printf("sizeof mdr_scene_f32 %u B, mdr_scene_f64 %u B\n", (unsigned)sizeof(mdr_scene_f32),
           (unsigned)sizeof(mdr_scene_f64));
    return MDR_RUN_TESTS(tests);
}

#endif /* applies */
