/* SPDX-License-Identifier: MIT */
/*
 * bench_matrix.h: the configurations of the benchmark matrix (make bench),
 * shared by the host (bench_matrix.c: time, callgrind instructions, error
 * against ref) and the emulated Cortex-M4F (target/bench_target.c: QEMU
 * icount), so that every column of a row is of the same computation.
 *
 * A row: one scene of scenes.h, one method, one arithmetic, one N:
 *   engine_d / engine_F / engine_z  one step of the spring engine
 *       (w_adv = w: the edge moves on almost every tick) driven by the depth,
 *       the force or a machine's base position along the scene's
 *       approach-retract cycle through pull-off (BM_NUP + BM_NDOWN ticks);
 *       f32, f64 and q31 (the q31 table converted from the f64 one, its
 *       constants from the double init, inputs rounded to Q2.29);
 *   naive  the same fixed-grips step followed by the force summed directly
 *       over the springs (host_tests/naive_sum.h, in double: the O(N)
 *       baseline the prefix sums replace); f32 and f64 tables;
 *   closed_form  one mdr_eq (d, F and the rest of the equilibrium at a
 *       given radius from the closed forms of the seed) at each radius the
 *       fixed-grips cycle visits; f32 and f64; none for the tabulated tip;
 *   gsl_ref  one ref_eq_at (GSL quadrature: the reference), host only.
 * Tables: f32 from the profile (or the gap samples) in float, as a float
 * firmware builds them; f64 likewise in double; extent scene->L.
 */
#ifndef BENCH_MATRIX_H
#define BENCH_MATRIX_H

#include <stdint.h>

#include "mdr.h"
#include "scenes.h"

#define BM_NUP 1000
#define BM_NDOWN 3000
#define BM_STEPS (BM_NUP + BM_NDOWN)
#define BM_NSIZES 5
#define BM_NMAX 4096

static const uint16_t bm_sizes[BM_NSIZES] = {16, 64, 256, 1024, 4096};
enum { BM_F32, BM_F64, BM_Q31, BM_NARITH };
static const char *const bm_arith[BM_NARITH] = {"f32", "f64", "q31"};
/* method names by control mode (MDR_CONTROL_LOAD 1, _GRIPS 2, _MACHINE 3) */
static const char *const bm_engine[4] = {"", "engine_F", "engine_d", "engine_z"};

typedef struct {
    const scene *sc;
    scene_path P;
    mdr_contact_f32 c32;
    mdr_contact_f64 c64;
    mdr_table_f32 t32;
    mdr_table_f64 t64;
    mdr_table_q31 tq;
    mdr_status tq_st; /* MDR_OK, or why the q31 table was refused (its rows fail) */
    uint16_t n;
    /* engines at the start of a cycle of control ctl; inputs for each */
    int ctl;
    mdr_engine_f32 e32;
    mdr_engine_f64 e64;
    mdr_engine_q31 eq;
    double unit_q; /* SI value of one Q2.29 input step times 2^29 */
    long nradii;   /* radii of the closed-form rows */
} bm_scene;

static mdr_node_f32 bm_n32[MDR_TABLE_NODES(BM_NMAX)];
static mdr_node_f64 bm_n64[MDR_TABLE_NODES(BM_NMAX)];
static mdr_node_q31 bm_nq[MDR_TABLE_NODES(BM_NMAX)];
static float bm_in32[BM_STEPS + 1];
static double bm_in64[BM_STEPS + 1];
static int32_t bm_inq[BM_STEPS + 1];
static float bm_a32[BM_STEPS];
static double bm_a64[BM_STEPS];

/* A scene: contacts, the control path (from its 1024-spring f64 table) and
 * the radii of the closed-form rows (the contact states of the fixed-grips
 * cycle on that table). */
SCENE_FN mdr_status bm_scene_init(bm_scene *b, const scene *sc)
{
    mdr_status st;
    mdr_engine_f64 e;
    mdr_step_f64 o;
    const float p32[3] = {(float)sc->s.p[0], (float)sc->s.p[1], (float)sc->s.p[2]};
    long i;
    b->sc = sc;
    b->nradii = 0;
    if ((st = mdr_contact_init_f64(&b->c64, (uint8_t)sc->s.kind, sc->s.p, sc->s.E, sc->s.w)) != MDR_OK ||
        (st = mdr_contact_init_f32(&b->c32, (uint8_t)sc->s.kind, p32, (float)sc->s.E, (float)sc->s.w)) !=
            MDR_OK ||
        (st = scene_table_f64(sc, &b->t64, bm_n64, 1024)) != MDR_OK ||
        (st = scene_path_of(sc, &b->t64, BM_NUP, BM_NDOWN, &b->P)) != MDR_OK ||
        (st = mdr_engine_init_f64(&e, &b->t64, sc->s.E, sc->s.w, sc->s.w, 0)) != MDR_OK) {
        return st;
    }
    for (i = 1; i <= BM_STEPS; i++) {
        if ((st = mdr_engine_step_d_f64(&e, scene_u(&b->P, MDR_CONTROL_GRIPS, BM_NUP, BM_NDOWN, i), &o)) !=
            MDR_OK) {
            return st;
        }
        if (e.contact && !sc->gap) {
            bm_a64[b->nradii] = o.a;
            bm_a32[b->nradii++] = (float)o.a;
        }
    }
    return MDR_OK;
}

/* The scene's tables with n springs (q31: n a power of two). A q31 table
 * the library refuses (e.g. MDR_E_OVERFLOW: the flattened tip's slope after
 * the rim beyond Q28 at 4096 springs) is no failure of the whole scene: its
 * status is kept in b->tq_st, the q31 rows report it, the others run. */
SCENE_FN mdr_status bm_tables(bm_scene *b, uint16_t n)
{
    mdr_status st;
    b->n = n;
    if (b->sc->gap) {
        static double r[GAP_SAMPLES], f[GAP_SAMPLES];
        static float r32[GAP_SAMPLES], f32[GAP_SAMPLES];
        int i;
        scene_gap(b->sc, r, f);
        for (i = 0; i < GAP_SAMPLES; i++) {
            r32[i] = (float)r[i];
            f32[i] = (float)f[i];
        }
        st = mdr_table_init_gap_f32(&b->t32, bm_n32, n, r32, f32, GAP_SAMPLES);
    } else {
        st = mdr_table_init_profile_f32(&b->t32, bm_n32, n, &b->c32, (float)b->sc->L);
    }
    if (st != MDR_OK || (st = scene_table_f64(b->sc, &b->t64, bm_n64, n)) != MDR_OK) {
        return st;
    }
    b->tq_st = mdr_table_q31_from_f64(&b->tq, bm_nq, &b->t64);
    return MDR_OK;
}

/* Engines at the start of a cycle under control ctl, and its inputs. */
SCENE_FN mdr_status bm_engines(bm_scene *b, int ctl)
{
    const double E = b->sc->s.E, w = b->sc->s.w, km = ctl == MDR_CONTROL_MACHINE ? b->P.km : 0;
    mdr_status st;
    long i;
    b->ctl = ctl;
    if ((st = mdr_engine_init_f32(&b->e32, &b->t32, (float)E, (float)w, (float)w, (float)km)) != MDR_OK ||
        (st = mdr_engine_init_f64(&b->e64, &b->t64, E, w, w, km)) != MDR_OK ||
        (b->tq_st == MDR_OK && (st = mdr_engine_init_q31_f64(&b->eq, &b->tq, E, w, w, km)) != MDR_OK)) {
        return st;
    }
    b->unit_q = b->tq_st != MDR_OK           ? 0
                : ctl == MDR_CONTROL_GRIPS ? (double)b->eq.D0
                : ctl == MDR_CONTROL_LOAD  ? 2 * E * ((double)b->tq.L + (double)b->tq.L_lo) * (double)b->eq.D0
                                           : (double)b->eq.Z0;
    for (i = 1; i <= BM_STEPS; i++) {
        double u = scene_u(&b->P, ctl, BM_NUP, BM_NDOWN, i), q = b->unit_q > 0 ? u / b->unit_q * 536870912.0 : 0;
        bm_in64[i] = u;
        bm_in32[i] = (float)u;
        bm_inq[i] = (int32_t)(q < 0 ? q - 0.5 : q + 0.5);
    }
    return MDR_OK;
}

/* One cycle of the engine of arithmetic SFX from the start state *e0 under
 * control ctl; the force summed into *acc (so that no step is optimised
 * away).
 * Returns the first status that is not MDR_OK (the cycle stops there). */
#define BM_LOOP(SFX, STEP)                                                    \
    for (i = 1; i <= BM_STEPS; i++) {                                      \
        if ((st = STEP(&e, in[i], &o)) != MDR_OK) {                        \
            break;                                                         \
        }                                                                  \
        s BM_OP_##SFX o.F;                                                 \
    }
#define BM_CYCLE(SFX, IN)                                                                        \
    SCENE_FN mdr_status bm_cycle_##SFX(const mdr_engine_##SFX *e0, int ctl, double *acc)         \
    {                                                                                            \
        mdr_engine_##SFX e = *e0;                                                                \
        mdr_step_##SFX o;                                                                        \
        mdr_status st = MDR_OK;                                                                  \
        const IN *in = BM_IN_##SFX;                                                              \
        IN s = 0;                                                                                \
        long i;                                                                                  \
        if (ctl == MDR_CONTROL_GRIPS) {                                                          \
            BM_LOOP(SFX, mdr_engine_step_d_##SFX)                                            \
        } else if (ctl == MDR_CONTROL_LOAD) {                                                    \
            BM_LOOP(SFX, mdr_engine_step_F_##SFX)                                            \
        } else {                                                                                 \
            BM_LOOP(SFX, mdr_engine_step_z_##SFX)                                            \
        }                                                                                        \
        *acc += (double)s;                                                                       \
        return st;                                                                               \
    }
/* the forces are folded in the engine's own type (no double arithmetic
 * in the loop: it would be soft float on the target) */
#define BM_OP_f32 +=
#define BM_OP_f64 +=
#define BM_OP_q31 ^=
#define BM_IN_f32 bm_in32
#define BM_IN_f64 bm_in64
#define BM_IN_q31 bm_inq
BM_CYCLE(f32, float)
BM_CYCLE(f64, double)
BM_CYCLE(q31, int32_t)

/* One closed-form evaluation mdr_eq at each radius of the scene. */
#define BM_CLOSED(SFX, T, C, A)                                                                       \
    SCENE_FN mdr_status bm_closed_##SFX(const bm_scene *b, double *acc)                          \
    {                                                                                            \
        mdr_eqstate_##SFX q;                                                                     \
        mdr_status st;                                                                           \
        T s = 0;                                                                                 \
        long i;                                                                                  \
        for (i = 0; i < b->nradii; i++) {                                                        \
            if ((st = mdr_eq_##SFX(&b->C, A[i], &q)) != MDR_OK) {                   \
                return st;                                                                       \
            }                                                                                    \
            s += q.F;                                                                            \
        }                                                                                        \
        *acc += (double)s;                                                                               \
        return MDR_OK;                                                                           \
    }
BM_CLOSED(f32, float, c32, bm_a32)
BM_CLOSED(f64, double, c64, bm_a64)

#endif /* BENCH_MATRIX_H */
