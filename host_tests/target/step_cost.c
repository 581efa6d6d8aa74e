/* SPDX-License-Identifier: MIT */
/*
 * host_tests/target/step_cost.c: instructions per tick of every real-time
 * engine on the emulated Cortex-M4F and Cortex-M3 (make step-cost: QEMU
 * mps2-an386 / mps2-an385 with -icount shift=7). One CSV line per engine,
 * arithmetic, core and cycle:
 *   engine,arith,core,cycle,mean,max,separated,pinned,moving
 * mean over the cycle's ticks, the worst single tick, and the mean per tick
 * class: separated (no contact before or after), pinned (in contact, the
 * edge where it was, no event), moving (the rest: the edge moved, touched,
 * jumped or let go). Engines: `spring` (N = 1024 springs) and `scene`
 * (table-free), each force only (MDR_OUT_FORCE: F and d; no radius, z,
 * events or energy), in f32 and q31 (inputs converted to raw Q2.29 before
 * counting; the q31 scene made from the f32 one with a_max the spring
 * table's x_max). Cycles: `grips`, the README's 20 000-tick approach-retract of
 * the exact sphere (spring engine; the scene runs the paraboloid of the
 * same radius) under fixed grips (host_tests/bench_scene.h); `afm`, an
 * approach-retract of a 20 nm paraboloid tip on polystyrene (E* = 3.8 GPa,
 * w = 0.066 J/m^2, w_adv = w/2) through a 0.2 N/m cantilever, 1 000 ticks
 * each way, base position from -10 nm to +50 nm and back to -60 nm.
 *
 * Counting. With -icount shift=7 QEMU advances its virtual clock by 128 ns
 * per instruction and the SysTick counts that clock at the board's 25 MHz:
 * 3.2 counts per instruction (the scale is measured by a loop of known
 * length, not assumed). The SysTick counts whole periods, so c counts
 * between two reads are floor(3.2 k) or one more for k instructions,
 * whatever the phase: k is the one integer with 3.2 k in [c - 1, c + 1)
 * (decode), the exact number of instructions between the reads (make
 * step-trace checks it against QEMU's instruction trace, tick by tick).
 * Rounding c / 3.2 is not exact: it counted the spring f32 grips cycle's
 * pinned ticks 24.2 on average where they take 24.0. Each step is called
 * through a timing function of its type (never inlined or specialised:
 * noipa), which reads the SysTick, calls the step through a pointer and
 * reads it again; the same
 * function calling an empty step of the same type gives the count of
 * everything but the step, so a tick's cost is its count minus the empty
 * one's, plus the empty step's own two instructions: the instructions of the
 * step from its entry to its return, none of the harness's. Exactly
 * reproducible.
 *
 * Built with -DSTEP_TRACE='"engine,arith,cycle"' (make step-trace) it runs
 * that line alone and prints each tick's count and class ("tick,<n>,<k>,
 * <class>"), for mk/step_trace.py to set beside QEMU's instruction trace.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mdr.h"
#include "../bench_scene.h"
#include "mdr_port.h"

#ifndef BENCH_CORE
#define BENCH_CORE "m4f"
#endif
#define AFM_TICKS 2000

static mdr_node_f32 n32[MDR_TABLE_NODES(1024)];
static mdr_node_q31 nq[MDR_TABLE_NODES(1024)];
static float in_f32[STEPS + 1];
static int32_t in_q31[STEPS + 1];

typedef struct {
    double sum, cls_sum[3];
    long n, cls_n[3];
    uint32_t max;
    long imax;
} stats;

static double scale; /* SysTick counts per instruction */

static uint32_t counts(uint32_t t0, uint32_t t1)
{
    return (t0 - t1) & MDR_PORT_CYCLES_MASK; /* SysTick counts down */
}

/* the timing function of a step type, its empty step, and the count the
 * timing function gives for the empty step (the least of 16 calls) */
#define TIMED(NAME, ENG, UT, OUT)                                                                     \
    __attribute__((noinline, noipa)) static mdr_status NAME(mdr_status (*f)(ENG *, UT, OUT *), ENG *e, UT u, \
                                                           OUT *o, uint32_t *c)                      \
    {                                                                                                 \
        const uint32_t t0 = MDR_PORT_SYST_CVR;                                                        \
        const mdr_status st = f(e, u, o);                                                             \
        const uint32_t t1 = MDR_PORT_SYST_CVR;                                                        \
        *c = counts(t0, t1);                                                                          \
        return st;                                                                                    \
    }                                                                                                 \
    __attribute__((noinline, noipa)) static mdr_status NAME##_empty(ENG *e, UT u, OUT *o)            \
    {                                                                                                 \
        (void)e, (void)u, (void)o;                                                                    \
        return 0;                                                                                     \
    }                                                                                                 \
    static uint32_t NAME##_base(void)                                                                 \
    {                                                                                                 \
        static ENG e;                                                                                 \
        static OUT o;                                                                                 \
        uint32_t c, best = 0xFFFFFFFFu;                                                               \
        for (int i = 0; i < 16; i++) {                                                                \
            (void)NAME(NAME##_empty, &e, (UT)1, &o, &c);                                              \
            best = c < best ? c : best;                                                               \
        }                                                                                             \
        return best;                                                                                  \
    }

TIMED(timed_spring_f32, mdr_engine_f32, float, mdr_step_f32)
TIMED(timed_spring_q31, mdr_engine_q31, int32_t, mdr_step_q31)
TIMED(timed_scene_f32, mdr_scene_f32, float, mdr_step_f32)
TIMED(timed_scene_q31, mdr_scene_q31, int32_t, mdr_step_q31)

/* SysTick counts of n turns of a 2-instruction loop */
static uint32_t loop_counts(uint32_t n)
{
    uint32_t t0 = MDR_PORT_SYST_CVR, t1;
    __asm__ volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(n) : : "cc");
    t1 = MDR_PORT_SYST_CVR;
    return counts(t0, t1);
}

/* counts per instruction: the difference of 2^20 and 2^19 turns (the
 * reads around the loop cancel), to 1e-4: 2^shift ns at the SysTick's
 * 25 MHz is 3.2 exactly, and the measurement is within 2e-6 of it */
static double calibrate(void)
{
    const uint32_t c1 = loop_counts(1u << 19), c2 = loop_counts(1u << 20);
    const double v = (double)(c2 - c1) / (2.0 * (double)(1u << 19));
    return (double)(long)(v * 1e4 + 0.5) / 1e4;
}

/* the instructions k between two reads c counts apart: the SysTick counts
 * whole periods of its clock, so c is floor(scale k) or one more, whatever
 * the phase of the first read: scale k in [c - 1, c + 1), an interval of
 * 2/scale < 1 instruction, which holds one integer */
static uint32_t decode(uint32_t c)
{
    const double lo = ((double)c - 1.0) / scale;
    uint32_t k = lo > 0 ? (uint32_t)lo : 0;
    return (double)k < lo ? k + 1 : k;
}

/* instructions of a step: the timing function's instructions around it
 * less those around the empty step (base), plus the empty step's two */
static uint32_t instr(uint32_t c, uint32_t base)
{
    return decode(c) - decode(base) + 2u;
}

static void note(stats *s, uint32_t c, uint32_t base, int cls)
{
    uint32_t k = instr(c, base);
#ifdef STEP_TRACE
    printf("tick,%ld,%lu,%d\n", s->n + 1, (unsigned long)k, cls);
#endif
    s->sum += k;
    s->n++;
    s->cls_sum[cls] += k;
    s->cls_n[cls]++;
    if (k > s->max) {
        s->max = k;
        s->imax = s->n;
    }
}

static void print(const char *engine, const char *arith, const char *cycle, const stats *s)
{
    int i;
    if (s->n == 0) {
        return; /* (not run: STEP_TRACE) */
    }
    printf("%s,%s,%s,%s,%.1f,%lu", engine, arith, BENCH_CORE, cycle, s->sum / (double)s->n,
           (unsigned long)s->max);
    for (i = 0; i < 3; i++) {
        if (s->cls_n[i] > 0) {
            printf(",%.1f", s->cls_sum[i] / (double)s->cls_n[i]);
        } else {
            printf(",");
        }
    }
    printf("\n");
    printf("# %s %s %s ticks: %ld separated, %ld pinned, %ld moving; the worst is tick %ld\n", engine, arith,
           cycle, s->cls_n[0], s->cls_n[1], s->cls_n[2], s->imax);
}

enum { SEPARATED, PINNED, MOVING };

/* the spring engine in f32 / q31 and the scene in f32 over n ticks of
 * control ctl; cls from the state before and after each tick */
#define RUN_SPRING(NAME, SFX, IN, STEP)                                              \
    static int NAME(mdr_engine_##SFX *e, long n, stats *s)                           \
    {                                                                                \
        const uint32_t base = timed_spring_##SFX##_base();                           \
        long i;                                                                      \
        mdr_step_##SFX o;                                                            \
        mdr_status st;                                                               \
        for (i = 1; i <= n; i++) {                                                   \
            uint32_t c;                                                              \
            int was = e->contact;                                                    \
            uint16_t k0 = e->k;                                                      \
            __typeof__(e->a) a0 = e->a;                                              \
            st = timed_spring_##SFX(STEP, e, IN[i], &o, &c);                          \
            if (st != MDR_OK) {                                                      \
                printf("step-cost: tick %ld refused (%d)\n", i, st);                 \
                return 1;                                                            \
            }                                                                        \
            note(s, c, base, !was && !e->contact ? SEPARATED                         \
                       : was && e->contact && e->a == a0 && e->k == k0 && o.event == 0 \
                           ? PINNED                                                  \
                           : MOVING);                                                \
        }                                                                            \
        return 0;                                                                    \
    }

RUN_SPRING(run_spring_f32, f32, in_f32, mdr_engine_step_d_f32)
RUN_SPRING(run_spring_q31, q31, in_q31, mdr_engine_step_d_q31)
RUN_SPRING(run_spring_z_f32, f32, in_f32, mdr_engine_step_z_f32)
RUN_SPRING(run_spring_z_q31, q31, in_q31, mdr_engine_step_z_q31)

/* a scene in f32 / q31 over n ticks of fixed grips or (machine) the base */
#define RUN_SCENE(NAME, SFX, IN)                                                                       \
    static int NAME(mdr_scene_##SFX *e, long n, int machine, stats *s)                                 \
    {                                                                                                  \
        const uint32_t base = timed_scene_##SFX##_base();                                              \
        long i;                                                                                        \
        mdr_step_##SFX o;                                                                              \
        mdr_status st;                                                                                 \
        for (i = 1; i <= n; i++) {                                                                     \
            uint32_t c;                                                                                \
            int was = e->contact;                                                                      \
            __typeof__(e->tau) t0 = e->tau;                                                            \
            st = timed_scene_##SFX(machine ? mdr_scene_step_z_##SFX : mdr_scene_step_d_##SFX, e, IN[i], \
                                   &o, &c);                                                            \
            if (st != MDR_OK) {                                                                        \
                printf("step-cost: scene %s tick %ld refused (%d)\n", #SFX, i, st);                   \
                return 1;                                                                              \
            }                                                                                          \
            note(s, c, base, !was && !e->contact ? SEPARATED : was && e->contact && e->tau == t0 ? PINNED : MOVING); \
        }                                                                                              \
        return 0;                                                                                      \
    }

RUN_SCENE(run_scene_f32, f32, in_f32)
RUN_SCENE(run_scene_q31, q31, in_q31)

/* the line to run: every one, or STEP_TRACE's alone */
static int want(const char *engine, const char *arith, const char *cycle)
{
#ifdef STEP_TRACE
    char line[48];
    snprintf(line, sizeof line, "%s,%s,%s", engine, arith, cycle);
    return strcmp(line, STEP_TRACE) == 0;
#else
    (void)engine, (void)arith, (void)cycle;
    return 1;
#endif
}

/* the afm cycle's base position at tick i (1 ... AFM_TICKS), metres */
static double afm_path(long i)
{
    long h = AFM_TICKS / 2;
    return i <= h ? -10e-9 + 60e-9 * (double)i / (double)h : 50e-9 - 110e-9 * (double)(i - h) / (double)h;
}

int main(void)
{
    const float sph[3] = {1e-6f, 0, 0}, tip[3] = {20e-9f, 0, 0};
    const float Eafm = 3.8e9f, wafm = 0.066f, km = 0.2f;
    mdr_contact_f32 c;
    mdr_table_f32 t;
    mdr_table_q31 tq;
    long i;
    mdr_port_cycles_init();
    scale = calibrate();
    printf("# %s (QEMU -icount shift=7): %.4f SysTick counts per instruction (measured), "
           "timing function %.0f instructions around the step\n",
           BENCH_CORE, scale, (double)decode(timed_spring_f32_base()) - 2.0);
    /* grips: the exact sphere, N = 1024, the README's cycle */
    for (i = 1; i <= STEPS; i++) {
        in_f32[i] = (float)bench_path(i);
    }
    if (mdr_contact_init_f32(&c, MDR_PROFILE_SPHERE, sph, 1e6f, 0.05f) != MDR_OK ||
        mdr_table_init_profile_f32(&t, n32, 1024, &c, 0.7e-6f) != MDR_OK ||
        mdr_table_q31_from_f32(&tq, nq, &t) != MDR_OK) {
        printf("step-cost: setup failed\n");
        return 1;
    }
    {
        mdr_engine_f32 e;
        mdr_engine_q31 q;
        mdr_scene_f32 s;
        mdr_scene_q31 sq;
        stats a = {0}, b = {0}, d = {0}, dq = {0};
        if (mdr_engine_init_f32(&e, &t, 1e6f, 0.05f, 0.02f, 0) != MDR_OK ||
            mdr_engine_outputs_f32(&e, MDR_OUT_FORCE) != MDR_OK ||
            mdr_engine_init_q31_f32(&q, &tq, 1e6f, 0.05f, 0.02f, 0) != MDR_OK ||
            mdr_engine_outputs_q31(&q, MDR_OUT_FORCE) != MDR_OK ||
            mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.02f, 0.0f, MDR_OUT_FORCE, NULL) !=
                MDR_OK ||
            mdr_scene_init_q31_f32(&sq, &s, 0.7e-6f) != MDR_OK) {
            printf("step-cost: init failed\n");
            return 1;
        }
        for (i = 1; i <= STEPS; i++) {
            in_q31[i] = mdr_q31_in(&q, MDR_Q_D, in_f32[i]);
        }
        if ((want("spring", "f32", "grips") && run_spring_f32(&e, STEPS, &a)) ||
            (want("spring", "q31", "grips") && run_spring_q31(&q, STEPS, &b)) ||
            (want("scene", "f32", "grips") && run_scene_f32(&s, STEPS, 0, &d))) {
            return 1;
        }
        for (i = 1; i <= STEPS; i++) { /* (the q31 scene's own depth unit) */
            if (mdr_scene_q31_from_si(&sq, MDR_Q_D, in_f32[i], &in_q31[i]) != MDR_OK) {
                printf("step-cost: q31 scene input %ld\n", i);
                return 1;
            }
        }
        if (want("scene", "q31", "grips") && run_scene_q31(&sq, STEPS, 0, &dq)) {
            return 1;
        }
        printf("engine,arith,core,cycle,mean,max,separated,pinned,moving\n");
        print("spring", "f32", "grips", &a);
        print("spring", "q31", "grips", &b);
        print("scene", "f32", "grips", &d);
        print("scene", "q31", "grips", &dq);
    }
    /* afm: a 20 nm paraboloid through a 0.2 N/m cantilever */
    for (i = 1; i <= AFM_TICKS; i++) {
        in_f32[i] = (float)afm_path(i);
    }
    if (mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, tip, Eafm, wafm) != MDR_OK ||
        mdr_table_init_profile_f32(&t, n32, 1024, &c, 12e-9f) != MDR_OK ||
        mdr_table_q31_from_f32(&tq, nq, &t) != MDR_OK) {
        printf("step-cost: afm setup failed\n");
        return 1;
    }
    {
        mdr_engine_f32 e;
        mdr_engine_q31 q;
        mdr_scene_f32 s;
        mdr_scene_q31 sq;
        stats a = {0}, b = {0}, d = {0}, dq = {0};
        if (mdr_engine_init_f32(&e, &t, Eafm, wafm, 0.5f * wafm, km) != MDR_OK ||
            mdr_engine_outputs_f32(&e, MDR_OUT_FORCE) != MDR_OK ||
            mdr_engine_init_q31_f32(&q, &tq, Eafm, wafm, 0.5f * wafm, km) != MDR_OK ||
            mdr_engine_outputs_q31(&q, MDR_OUT_FORCE) != MDR_OK ||
            mdr_scene_init_paraboloid_f32(&s, 20e-9f, Eafm, wafm, 0.5f * wafm, km, MDR_OUT_FORCE, NULL) !=
                MDR_OK ||
            mdr_scene_init_q31_f32(&sq, &s, 12e-9f) != MDR_OK) {
            printf("step-cost: afm init failed\n");
            return 1;
        }
        for (i = 1; i <= AFM_TICKS; i++) {
            in_q31[i] = mdr_q31_in(&q, MDR_Q_Z, in_f32[i]);
        }
        if ((want("spring", "f32", "afm") && run_spring_z_f32(&e, AFM_TICKS, &a)) ||
            (want("spring", "q31", "afm") && run_spring_z_q31(&q, AFM_TICKS, &b)) ||
            (want("scene", "f32", "afm") && run_scene_f32(&s, AFM_TICKS, 1, &d))) {
            return 1;
        }
        for (i = 1; i <= AFM_TICKS; i++) {
            if (mdr_scene_q31_from_si(&sq, MDR_Q_Z, in_f32[i], &in_q31[i]) != MDR_OK) {
                printf("step-cost: q31 scene afm input %ld\n", i);
                return 1;
            }
        }
        if (want("scene", "q31", "afm") && run_scene_q31(&sq, AFM_TICKS, 1, &dq)) {
            return 1;
        }
        print("spring", "f32", "afm", &a);
        print("spring", "q31", "afm", &b);
        print("scene", "f32", "afm", &d);
        print("scene", "q31", "afm", &dq);
    }
    return 0;
}
