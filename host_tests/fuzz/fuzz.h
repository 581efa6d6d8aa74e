/* SPDX-License-Identifier: MIT */
/*
 * fuzz.h: what the libFuzzer targets of host_tests/fuzz/ share: a reader of
 * the fuzzer's bytes, the mapping of bytes to physical values, and the
 * checks every call must pass (FZ_CHECK aborts, so libFuzzer and the replay
 * of the regression corpus report it as a crash):
 *   - a call returns MDR_OK or a named status (mdr_status_str knows it);
 *     a step never returns MDR_E_NOCONV (its contract: not expected);
 *   - a refused call leaves its instance and its outputs as they were (for
 *     the engines: except the sticky flags, which report the refusal);
 *   - every output of an accepted call is finite;
 *   - an engine state stays inside its table: 0 <= a <= x_max, t > 0 in
 *     contact (a = t^2 may underflow; q31: see fz_check_q31), a = t = F = 0
 *     when separated, the edge's spring k holds a
 *     (x_k <= a <= x_{k+1}), F = 0 when separated, and the Hess rule holds
 *     after every accepted step:
 *     g(a) - dl_w(a) <= d <= g(a) - dl_adv(a) up to rounding (DESIGN 2).
 * Built with clang -fsanitize=fuzzer,address,undefined (make fuzz); the same
 * sources with replay.c run the committed corpus under gcc in make test.
 */
#ifndef FUZZ_H
#define FUZZ_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mdr.h"

#define FZ_CHECK(cond)                                                                   \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            fprintf(stderr, "fuzz check failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
            abort();                                                                     \
        }                                                                                \
    } while (0)

/* the fuzzer's bytes, read front to back; zeros once they run out */
typedef struct {
    const uint8_t *p;
    size_t n;
} fz_in;

static inline uint8_t fz_u8(fz_in *in)
{
    uint8_t v = 0;
    if (in->n > 0) {
        v = *in->p++;
        in->n--;
    }
    return v;
}

static inline uint32_t fz_u32(fz_in *in)
{
    uint32_t v = 0;
    int i;
    for (i = 0; i < 4; i++) {
        v = v << 8 | fz_u8(in);
    }
    return v;
}

/* A value of magnitude 10^lo ... 10^hi (log-uniform over 2^24 steps), with
 * one selector byte that also yields the edge cases: raw float bits (NaN,
 * inf, subnormals, anything), zero, negatives, and the extremes. */
static inline double fz_val(fz_in *in, double lo, double hi)
{
    uint8_t sel = fz_u8(in);
    uint32_t bits = fz_u32(in);
    double u = (double)(bits & 0xffffffu) / 16777215.0, v = pow(10.0, lo + (hi - lo) * u);
    switch (sel & 15u) {
    case 0: {
        float f;
        memcpy(&f, &bits, sizeof f);
        return (double)f;
    }
    case 1:
        return 0.0;
    case 2:
        return -v;
    case 3:
        return (sel & 16u) ? pow(10.0, lo) : pow(10.0, hi);
    default:
        return v;
    }
}

static inline void fz_status(mdr_status st)
{
    FZ_CHECK(st <= 0);
    FZ_CHECK(strcmp(mdr_status_str(st), "unknown status") != 0);
}

static inline int fz_fin(double x)
{
    return isfinite(x);
}

/* the controls of fz_step_<type>() */
enum { FZ_D, FZ_F, FZ_Z };

/* the f32 and f64 engine checks and steps, written once */
#define FZ_T float
#define FZ_SFX(name) name##_f32
#include "fuzz_engine_t.h"
#undef FZ_T
#undef FZ_SFX
#define FZ_T double
#define FZ_SFX(name) name##_f64
#include "fuzz_engine_t.h"
#undef FZ_T
#undef FZ_SFX

/* A q31 step refused with MDR_E_OUTSIDE (the engine, the scene): the
 * target v (raw Q2.29 of its control's unit, saturated to +-2 units) lies
 * beyond the advancing branch's value at the range's end, where the depth
 * is D and G the integral of g (units of D0 and L D0): U = D (grips),
 * D - G (load), D + kappa (D - G) (machine, kappa = 1/al_z - 1, z as a
 * depth z 2^sz), to 8 LSB of its format (1 + kappa for the machine) */
static inline void fz_q31_beyond(int ctl, int32_t v, double D, double G, int machine, int32_t al_z, unsigned sz)
{
    double kap = machine ? 1073741824.0 / al_z - 1 : 0;
    double vs = (v > 2 * MDR_Q29_ONE ? 2 * MDR_Q29_ONE : v < -2 * MDR_Q29_ONE ? -2 * MDR_Q29_ONE : v) / 536870912.0;
    double U = ctl == FZ_D ? D : ctl == FZ_F ? D - G : D + kap * (D - G);
    double u = ctl == FZ_Z ? vs * (double)(1u << sz) : vs;
    FZ_CHECK(U < u + 8.0 / 536870912.0 * (1 + kap));
}

/* q31 engine: the same checks in its integer formats */
static inline void fz_check_q31(const mdr_engine_q31 *e, const mdr_engine_q31 *before, mdr_status st,
                         const mdr_step_q31 *out, const mdr_step_q31 *out0)
{
    const mdr_table_q31 *tab = e->tab;
    fz_status(st);
    FZ_CHECK(st != MDR_E_NOCONV);
    if (st != MDR_OK) {
        mdr_engine_q31 x = *e;
        x.flags = before->flags;
        FZ_CHECK(memcmp(&x, before, sizeof x) == 0);
        FZ_CHECK(memcmp(out, out0, sizeof *out) == 0);
        return;
    }
    FZ_CHECK(e->a >= 0 && e->a <= MDR_Q30_ONE);
    /* separated: nothing left. In contact a and t may be 0: the q31 edge
     * lives in t = sqrt(a/L), so a radius below 1 LSB of a (a/L < 2^-30)
     * has a = 0 and t > 0, and one below 1 LSB of t (a/L < 2^-60: a nearly
     * flat cone touching at 6e-22 m on a 0.8 m table) has t = 0 too */
    FZ_CHECK(e->contact || (e->a == 0 && e->t == 0 && e->F == 0));
    FZ_CHECK(e->k < tab->n);
    if (e->contact) {
        /* a in spring k: k L/n <= a <= (k+1) L/n, a Q1.30 of L */
        int64_t lo = (int64_t)e->k << (30 - tab->m), hi = (int64_t)(e->k + 1) << (30 - tab->m);
        /* a = t^2 rounded, node t the floor of the exact root: at node k
         * t >= sqrt(x_k) - 2^-30, so t^2 >= x_k - 2 sqrt(x_k) 2^-30, up to
         * 2 LSB of a below x_k with the rounding (sqrt(x_k) <= 1: found by
         * make fuzz, a = lo - 2 at x_k = 7/8); above, t <= t_(k+1) <= the
         * exact root: 1 LSB covers the rounding */
        FZ_CHECK(e->a >= lo - 2 && e->a <= hi + 1);
    }
    FZ_CHECK(out->F == e->F && out->d == e->d && out->a == e->a);
}

/* One q31 step (raw Q2.29 input), checked; an input beyond the documented
 * +-2 units saturates and sets MDR_FLAG_SAT. */
static inline mdr_status fz_step_q31(mdr_engine_q31 *e, int ctl, int32_t v, mdr_step_q31 *out)
{
    const mdr_engine_q31 before = *e;
    mdr_step_q31 o0;
    mdr_status st;
    memset(out, 0x5a, sizeof *out);
    o0 = *out;
    st = ctl == FZ_D ? mdr_engine_step_d_q31(e, v, out)
         : ctl == FZ_F ? mdr_engine_step_F_q31(e, v, out)
                       : mdr_engine_step_z_q31(e, v, out);
    fz_check_q31(e, &before, st, out, &o0);
    if (st == MDR_E_OUTSIDE) {
        /* refused only where the target lies beyond the last node (as the
         * float engines, fuzz_engine_t.h), in units of D0 and L D0: at a = L
         * D = (g_n Dg 2^-30 - dl_adv(L))/D0, z = D + kappa (D - G) with
         * kappa = 1/al_z - 1, the target v saturated to +-2 units, to
         * 8 LSB of its format (1 + kappa for the machine) */
        const mdr_table_q31 *tab = e->tab;
        const mdr_node_q31 *nn = &tab->node[tab->n];
        double sc = (double)tab->Dg / (double)e->D0 / 1073741824.0;
        FZ_CHECK(!tab->wall);
        fz_q31_beyond(ctl, v, nn->g * sc - e->c_adv / 536870912.0, nn->G * sc, e->machine, e->al_z, e->sz);
    }
    if (v > 2 * MDR_Q29_ONE || v < -2 * MDR_Q29_ONE) {
        FZ_CHECK(st != MDR_OK || (e->flags & MDR_FLAG_SAT));
    }
    return st;
}

#if MDR_CFG_SCENE
/* One step of a q31 scene (raw Q2.29 input), checked as the q31 engine's:
 * a named status, never MDR_E_NOCONV; refused: nothing changed (the sticky
 * flags aside), no output written, and MDR_E_OUTSIDE only for a target
 * beyond a = L (fz_q31_beyond, at tau = 1: D = g(L)/D0 - c_adv, G = g(L)/D0
 * /(n+1)); accepted: outputs the state's, 0 <= tau, a <= 2^30, tau = F = 0
 * separated, and, where nothing saturated, the edge inside the Hess band
 * g(tau) - c_w tau <= d <= g(tau) - c_adv tau (D0 units, g = gc tau^2n), to
 * FZ_Q31_BAND_LSB LSB of Q2.29 plus 2^-22 of its terms (tau's rounding
 * moves g by 2n LSB, the pinned relation's products a few more). Where
 * the control is coarser than d, plus FZ_Q31_CTL_LSB LSB of the control in
 * d (a jump-in aims MDR_S_UTOL = 4 LSB of the control past the fold's, the
 * band's ends round, so the edge may sit that far from the control's own
 * root): held at fixed load, over x = tau^2 (d = (F + G)/x: at a small
 * contact one LSB of F spans 1/x LSB of d); held by a machine, times
 * (1 + kappa)/(1 + kappa x) (the solver's control z 2^sz/(1 + kappa),
 * Q2.29 of D0, resolves the depth term of z 2^sz = (1 + kappa x) d -
 * kappa G to 1 + kappa LSB) */
#define FZ_Q31_BAND_LSB 64.0
#define FZ_Q31_CTL_LSB 8.0
static inline void fz_scene_step_q31(mdr_scene_q31 *s, int ctl, int32_t v)
{
    const mdr_scene_q31 before = *s;
    mdr_step_q31 o, o0;
    mdr_status st;
    memset(&o, 0x5a, sizeof o);
    o0 = o;
    st = ctl == FZ_D ? mdr_scene_step_d_q31(s, v, &o)
         : ctl == FZ_F ? mdr_scene_step_F_q31(s, v, &o)
                       : mdr_scene_step_z_q31(s, v, &o);
    fz_status(st);
    FZ_CHECK(st != MDR_E_NOCONV);
    if (v > 2 * MDR_Q29_ONE || v < -2 * MDR_Q29_ONE) {
        FZ_CHECK(st != MDR_OK || (s->flags & MDR_FLAG_SAT));
    }
    if (st != MDR_OK) {
        mdr_scene_q31 x = *s;
        x.flags = before.flags;
        FZ_CHECK(memcmp(&x, &before, sizeof x) == 0);
        FZ_CHECK(memcmp(&o, &o0, sizeof o) == 0);
        if (st == MDR_E_OUTSIDE) {
            double gL = s->gc / 1073741824.0;
            fz_q31_beyond(ctl, v, gL - s->c_adv / 536870912.0, gL / (s->n + 1), s->machine, s->al_z, s->sz);
        }
        return;
    }
    FZ_CHECK(o.d == s->d && o.F == s->F);
    FZ_CHECK(s->tau >= 0 && s->tau <= MDR_Q30_ONE && o.a >= 0 && o.a <= MDR_Q30_ONE);
    FZ_CHECK(s->contact || (s->tau == 0 && s->F == 0 && o.a == 0));
    if (s->contact && !(s->flags & MDR_FLAG_SAT)) {
        double t = s->tau / 1073741824.0, g = s->gc / 1073741824.0 * pow(t, 2.0 * s->n);
        double cw = s->c_w / 536870912.0 * t, ca = s->c_adv / 536870912.0 * t, d = s->d / 536870912.0;
        double tol = FZ_Q31_BAND_LSB / 536870912.0 + (g + cw + fabs(d)) / 4194304.0 +
                     ((s->mode & 0x7Fu) == MDR_CONTROL_LOAD ? FZ_Q31_CTL_LSB / 536870912.0 / (t * t) : 0.0);
        if ((s->mode & 0x7Fu) == MDR_CONTROL_MACHINE) { /* (bit 7: the stale mark of a move) */
            const double kap = 1073741824.0 / s->al_z - 1.0;
            tol += FZ_Q31_CTL_LSB / 536870912.0 * (1.0 + kap) / (1.0 + kap * t * t);
        }
        FZ_CHECK(d >= g - cw - tol && d <= g - ca + tol);
    }
}
#endif

#endif /* FUZZ_H */
