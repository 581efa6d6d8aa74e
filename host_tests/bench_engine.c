/* SPDX-License-Identifier: MIT */
/*
 * bench_engine.c: cost per step of the spring engine against the number of
 * springs N (make bench). All figures come from one run, so they can be
 * compared with each other on a shared, noisy machine; absolute ns are not
 * portable, the ratios are the claim.
 *
 * Scene: exact sphere R = 1 um, E* = 1 MPa, w = 0.05 J/m^2, w_adv = 0.02,
 * table to 0.7 R. One step = one control tick of an approach-retract cycle
 * under fixed grips (d from 0 to 0.1 um and back to -0.3 um, past the
 * pull-off) of STEPS ticks; the edge moves on most ticks. Timed: the best of
 * REPEAT runs of the cycle (the minimum is the least disturbed).
 *
 * Columns: ns per step of mdr_engine_step_d; its ratio to N = 64 (goal
 * <= 1.2: the step cost does not grow with N); nodes the edge passes per
 * step on average (the only N-dependent work: it is O(1) while that stays
 * below ~1); ns per step of the naive O(N) alternative, the same step
 * followed by the force summed directly over the attached springs (what
 * the prefix sums G_i save); and naive / engine. The q31 engine runs the
 * same scene (its table converted from the f64 one, raw Q2.29 inputs) and
 * is reported beside f32 as q31/f32 at the same N. All inputs are converted
 * before timing.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#include "mdr.h"
#include "bench_scene.h"
#include "naive_sum.h"

#define REPEAT 7

static mdr_node_f32 n32[MDR_TABLE_NODES(4096)];
static mdr_node_f64 n64[MDR_TABLE_NODES(4096)];
static mdr_node_q31 nq[MDR_TABLE_NODES(4096)];
static float in_f32[STEPS + 1];
static double in_f64[STEPS + 1];
static int32_t in_q31[STEPS + 1];
static volatile double sink;

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

#define BENCH(T, SFX, NODES, NAIVE)                                                               \
    static void bench_##SFX(uint16_t n, double *ns, double *ns_naive, double *nodes_per_step)    \
    {                                                                                             \
        const T p[3] = {(T)1e-6, 0, 0};                                                           \
        mdr_contact_##SFX c;                                                                      \
        mdr_table_##SFX t;                                                                        \
        mdr_engine_##SFX e;                                                                       \
        mdr_step_##SFX o;                                                                         \
        int r, naive;                                                                             \
        long i, moved = 0;                                                                        \
        mdr_contact_init_##SFX(&c, MDR_PROFILE_SPHERE, p, (T)1e6, (T)0.05);                       \
        mdr_table_init_profile_##SFX(&t, NODES, n, &c, (T)0.7e-6);                                \
        for (naive = 0; naive < 2; naive++) {                                                     \
            double best = 1e300;                                                                  \
            for (r = 0; r < REPEAT; r++) {                                                        \
                double t0, t1, acc = 0;                                                           \
                mdr_engine_init_##SFX(&e, &t, (T)1e6, (T)0.05, (T)0.02, 0);                       \
                t0 = now_ns();                                                                    \
                for (i = 1; i <= STEPS; i++) {                                                    \
                    uint16_t k0 = e.k;                                                            \
                    if (mdr_engine_step_d_##SFX(&e, in_##SFX[i], &o) != MDR_OK) {                 \
                        fprintf(stderr, "bench: step failed\n");                                  \
                        return;                                                                   \
                    }                                                                             \
                    acc += (double)o.F;                                                           \
                    if (naive && e.contact) {                                                     \
                        acc += (double)NAIVE(&t, e.E, e.a, e.d);                                  \
                    }                                                                             \
                    if (r == 0 && !naive) {                                                       \
                        moved += e.k > k0 ? e.k - k0 : k0 - e.k;                                  \
                    }                                                                             \
                }                                                                                 \
                t1 = now_ns();                                                                    \
                sink = acc;                                                                       \
                best = fmin(best, (t1 - t0) / STEPS);                                             \
            }                                                                                     \
            if (naive) {                                                                          \
                *ns_naive = best;                                                                 \
            } else {                                                                              \
                *ns = best;                                                                       \
            }                                                                                     \
        }                                                                                         \
        *nodes_per_step = (double)moved / STEPS;                                                  \
    }

BENCH(float, f32, n32, naive_F_f32)
BENCH(double, f64, n64, naive_F_f64)

/* Scenes (issue 7): the table-free paraboloid scene with force only and
 * with every output and the energy, the spring engine on a table of the
 * same paraboloid (N = 1024), and one closed-form evaluation F(a) at the
 * radius of each tick, on the cycle of bench_scene.h with R = 1 um as a
 * paraboloid. Runs interleaved, REPEAT times, best of each. */
#define SCENE_BENCH(T, SFX, NODES)                                                                    \
    static void scene_bench_##SFX(double ns[4])                                                       \
    {                                                                                                 \
        const T p[3] = {(T)1e-6, 0, 0};                                                               \
        static T a_of[STEPS + 1];                                                                     \
        mdr_contact_##SFX c;                                                                          \
        mdr_table_##SFX t;                                                                            \
        int r, k;                                                                                     \
        long i;                                                                                       \
        mdr_contact_init_##SFX(&c, MDR_PROFILE_PARABOLOID, p, (T)1e6, (T)0.05);                       \
        mdr_table_init_profile_##SFX(&t, NODES, 1024, &c, (T)1.2e-6);                                 \
        ns[0] = ns[1] = ns[2] = ns[3] = 1e300;                                                        \
        for (r = 0; r < REPEAT; r++) {                                                                \
            for (k = 0; k < 4; k++) {                                                                 \
                mdr_scene_##SFX s;                                                                    \
                mdr_energy_##SFX en;                                                                  \
                mdr_engine_##SFX e;                                                                   \
                mdr_eqstate_##SFX q;                                                                  \
                mdr_step_##SFX o;                                                                     \
                double t0, acc = 0;                                                                   \
                int st = MDR_OK;                                                                      \
                if (k < 2) {                                                                          \
                    st = mdr_scene_init_paraboloid_##SFX(&s, (T)1e-6, (T)1e6, (T)0.05, (T)0.02, 0,    \
                                                         k ? MDR_OUT_ALL : MDR_OUT_FORCE,             \
                                                         k ? &en : NULL);                             \
                } else if (k == 2) {                                                                  \
                    st = mdr_engine_init_##SFX(&e, &t, (T)1e6, (T)0.05, (T)0.02, 0);                  \
                }                                                                                     \
                if (st != MDR_OK) {                                                                   \
                    fprintf(stderr, "bench: scene setup failed\n");                                   \
                    return;                                                                           \
                }                                                                                     \
                t0 = now_ns();                                                                        \
                for (i = 1; i <= STEPS; i++) {                                                        \
                    if (k < 2) {                                                                      \
                        st = mdr_scene_step_d_##SFX(&s, in_##SFX[i], &o);                             \
                    } else if (k == 2) {                                                              \
                        st = mdr_engine_step_d_##SFX(&e, in_##SFX[i], &o);                            \
                        a_of[i] = o.a;                                                                \
                    } else {                                                                          \
                        st = a_of[i] > 0 ? mdr_eq_##SFX(&c, a_of[i], &q) : MDR_OK;                    \
                        o.F = q.F;                                                                    \
                    }                                                                                 \
                    if (st != MDR_OK) {                                                               \
                        fprintf(stderr, "bench: scene step failed (%d)\n", st);                       \
                        return;                                                                       \
                    }                                                                                 \
                    acc += (double)o.F;                                                               \
                }                                                                                     \
                ns[k] = fmin(ns[k], (now_ns() - t0) / STEPS);                                         \
                sink = acc;                                                                           \
            }                                                                                         \
        }                                                                                             \
    }
SCENE_BENCH(float, f32, n32)
SCENE_BENCH(double, f64, n64)

/* the q31 engine on the same scene: table from the f64 one, constants by the
 * double init, the same path as raw Q2.29 depths (converted before timing,
 * as for f32 and f64) */
static void bench_q31(uint16_t n, double *ns, double *nodes_per_step)
{
    const double p[3] = {1e-6, 0, 0};
    mdr_contact_f64 c;
    mdr_table_f64 t;
    mdr_table_q31 tq;
    mdr_engine_q31 e;
    mdr_step_q31 o;
    double best = 1e300;
    long i, moved = 0;
    int r;
    mdr_contact_init_f64(&c, MDR_PROFILE_SPHERE, p, 1e6, 0.05);
    mdr_table_init_profile_f64(&t, n64, n, &c, 0.7e-6);
    if (mdr_table_q31_from_f64(&tq, nq, &t) != MDR_OK ||
        mdr_engine_init_q31_f64(&e, &tq, 1e6, 0.05, 0.02, 0) != MDR_OK) {
        fprintf(stderr, "bench: q31 setup failed\n");
        return;
    }
    for (i = 1; i <= STEPS; i++) {
        in_q31[i] = (int32_t)lround(in_f64[i] / (double)e.D0 * 536870912.0);
    }
    for (r = 0; r < REPEAT; r++) {
        double t0, t1, acc = 0;
        mdr_engine_init_q31_f64(&e, &tq, 1e6, 0.05, 0.02, 0);
        t0 = now_ns();
        for (i = 1; i <= STEPS; i++) {
            uint16_t k0 = e.k;
            if (mdr_engine_step_d_q31(&e, in_q31[i], &o) != MDR_OK) {
                fprintf(stderr, "bench: q31 step failed\n");
                return;
            }
            acc += (double)o.F;
            if (r == 0) {
                moved += e.k > k0 ? e.k - k0 : k0 - e.k;
            }
        }
        t1 = now_ns();
        sink = acc;
        best = fmin(best, (t1 - t0) / STEPS);
    }
    *ns = best;
    *nodes_per_step = (double)moved / STEPS;
}

int main(void)
{
    double f32ns[7] = {0};
    long i;
    int a;
    for (i = 1; i <= STEPS; i++) {
        in_f64[i] = bench_path(i);
        in_f32[i] = (float)in_f64[i];
    }
    printf("engine step cost vs springs N (sphere, fixed grips, %d-tick approach-retract cycle, "
           "best of %d)\n", STEPS, REPEAT);
    for (a = 0; a < 2; a++) {
        double base = 0, worst = 0;
        uint16_t n;
        int j = 0;
        printf("%s\n     N   ns/step  ratio-to-64  nodes/step   naive-ns  naive/engine\n",
               a ? "f64" : "f32");
        for (n = 64; n <= 4096; n = (uint16_t)(n * 2), j++) {
            double ns = 0, nn = 0, mv = 0;
            if (a) {
                bench_f64(n, &ns, &nn, &mv);
            } else {
                bench_f32(n, &ns, &nn, &mv);
                f32ns[j] = ns;
            }
            if (n == 64) {
                base = ns;
            }
            worst = fmax(worst, ns / base);
            printf("  %5u  %8.1f  %11.2f  %10.3f  %9.1f  %12.1f\n", (unsigned)n, ns, ns / base, mv,
                   nn, nn / ns);
        }
        printf("  largest ratio to N = 64: %.2f (goal <= 1.2)\n", worst);
    }
    {
        double base = 0, worst = 0;
        uint16_t n;
        int j = 0;
        printf("q31 (integer step; host: 64-bit multiply and divide in hardware)\n"
               "     N   ns/step  ratio-to-64  nodes/step   q31/f32\n");
        for (n = 64; n <= 4096; n = (uint16_t)(n * 2), j++) {
            double ns = 0, mv = 0;
            bench_q31(n, &ns, &mv);
            if (n == 64) {
                base = ns;
            }
            worst = fmax(worst, ns / base);
            printf("  %5u  %8.1f  %11.2f  %10.3f  %8.2f\n", (unsigned)n, ns, ns / base, mv,
                   ns / f32ns[j]);
        }
        printf("  largest ratio to N = 64: %.2f (goal <= 1.2)\n", worst);
    }
    {
        int k;
        printf("scenes (paraboloid R = 1 um, the same cycle; ns/step, best of %d, interleaved)\n"
               "  arith  scene-force  scene-all+energy  all/force  engine-N1024  engine/scene-force  "
               "closed-form-F(a)  scene-force/closed-form\n", REPEAT);
        for (k = 0; k < 2; k++) {
            double ns[4];
            if (k) {
                scene_bench_f64(ns);
            } else {
                scene_bench_f32(ns);
            }
            printf("  %s  %11.1f  %16.1f  %9.2f  %12.1f  %18.2f  %16.1f  %23.2f\n", k ? "f64" : "f32", ns[0],
                   ns[1], ns[1] / ns[0], ns[2], ns[2] / ns[0], ns[3], ns[0] / ns[3]);
        }
    }
    return 0;
}
