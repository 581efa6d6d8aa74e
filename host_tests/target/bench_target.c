/* SPDX-License-Identifier: MIT */
/*
 * host_tests/target/bench_target.c: instructions per engine step on the
 * emulated Cortex-M4F and Cortex-M3 (make bench: QEMU mps2-an386 and
 * mps2-an385 with -icount shift=0; BENCH_CORE names the build's core).
 *
 * With -icount shift=0 QEMU advances its virtual clock by 1 ns per guest
 * instruction, and the SysTick (port/cortex-m/mdr_port.h,
 * MDR_PORT_CYCLES_SYSTICK: QEMU does not model the DWT) counts that clock
 * at the board's 25 MHz: one tick per 40 instructions. The scale is not
 * assumed but measured: a loop of two instructions per turn
 * (SUBS, BNE) runs 2^20 turns first. A step's count is then the ticks of a
 * whole approach-retract cycle of STEPS steps times instructions per tick,
 * divided by STEPS: exact to ~40/STEPS instructions per step, and exactly
 * reproducible (instructions, not time; a real M4F spends more cycles per
 * instruction on loads, divides and branches).
 *
 * Scene and path (host_tests/bench_scene.h, as the host bench): exact sphere R = 1 um,
 * E* = 1 MPa, w = 0.05, w_adv = 0.02, table to 0.7 R, fixed grips, d from 0
 * to 0.1 um and back to -0.3 um (past pull-off). f32 engine and q31 engine
 * (table from the f32 one, float init, raw Q2.29 inputs converted before
 * counting), N = 64 ... 4096.
 *
 * Also measured: the stack a step uses (the region below the caller's
 * stack pointer is filled with a pattern before the cycle; the deepest
 * overwritten word after it), libgcc helpers included.
 */
#include <stdint.h>
#include <stdio.h>

#include "mdr.h"
#include "../bench_scene.h"
#include "mdr_port.h"
#ifdef BENCH_MATRIX
#include "../bench_matrix.h"
#endif

#ifndef BENCH_CORE
#define BENCH_CORE "Cortex-M4F"
#endif
#define PAINT 4096 /* bytes of stack painted below the caller's frame */

static mdr_node_f32 n32[MDR_TABLE_NODES(4096)];
static mdr_node_q31 nq[MDR_TABLE_NODES(4096)];
static float in_f32[STEPS + 1];
static int32_t in_q31[STEPS + 1];

static uint32_t ticks_since(uint32_t t0)
{
    return (mdr_port_cycles() - t0) & MDR_PORT_CYCLES_MASK;
}

/* instructions per SysTick tick: 2^20 turns of a 2-instruction loop */
static double calibrate(void)
{
    uint32_t n = 1u << 20, t0 = mdr_port_cycles();
    __asm__ volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(n) : : "cc");
    return 2.0 * (double)(1u << 20) / (double)ticks_since(t0);
}

/* Fill the PAINT bytes below the stack pointer with a pattern, with no
 * call in between (the region is free: nothing below sp is live, and the
 * SysTick raises no interrupt); painted_used() then finds the deepest
 * overwritten word. */
#define PAINT_BELOW_SP(top)                                 \
    do {                                                    \
        uint32_t *p_;                                       \
        __asm__ volatile("mov %0, sp" : "=r"(top));         \
        for (p_ = (top) - PAINT / 4; p_ < (top); p_++) {    \
            *(volatile uint32_t *)p_ = 0xA5A5A5A5u;         \
        }                                                   \
    } while (0)
static uint32_t painted_used(uint32_t *top)
{
    uint32_t *p = top - PAINT / 4;
    while (p < top && *(volatile uint32_t *)p == 0xA5A5A5A5u) {
        p++;
    }
    return (uint32_t)((uintptr_t)top - (uintptr_t)p);
}

/* one cycle of an engine (inputs in_##SFX); returns ticks, *stack the
 * measured depth. The outputs are folded into acc (type T, operator OP=)
 * so that no step is optimised away, at one instruction per step. */
#define CYCLE(SFX, T, OP)                                                              \
    __attribute__((noinline)) static uint32_t cycle_##SFX(mdr_engine_##SFX *e,         \
                                                          uint32_t *stack)              \
    {                                                                                   \
        mdr_step_##SFX o;                                                               \
        uint32_t *top, t0;                                                              \
        long i;                                                                         \
        T acc = 0;                                                                      \
        PAINT_BELOW_SP(top);                                                            \
        t0 = mdr_port_cycles();                                                         \
        for (i = 1; i <= STEPS; i++) {                                                  \
            if (mdr_engine_step_d_##SFX(e, in_##SFX[i], &o) != MDR_OK) {                \
                return 0;                                                               \
            }                                                                           \
            acc OP o.F;                                                                 \
        }                                                                               \
        t0 = ticks_since(t0);                                                           \
        sink_##SFX = acc;                                                               \
        *stack = painted_used(top);                                                     \
        return t0;                                                                      \
    }
static volatile float sink_f32;
static volatile int32_t sink_q31;
CYCLE(f32, float, +=)
CYCLE(q31, int32_t, ^=)

/* one cycle of a table-free scene (paraboloid R = 1 um, same path) */
__attribute__((noinline)) static uint32_t cycle_scene(mdr_scene_f32 *s)
{
    mdr_step_f32 o;
    uint32_t t0;
    long i;
    float acc = 0;
    t0 = mdr_port_cycles();
    for (i = 1; i <= STEPS; i++) {
        if (mdr_scene_step_d_f32(s, in_f32[i], &o) != MDR_OK) {
            return 0;
        }
        acc += o.F;
    }
    t0 = ticks_since(t0);
    sink_f32 = acc;
    return t0;
}

/* instructions per step of the paraboloid scene, force only and with every
 * output and the energy (issue 7) */
static int scene_rows(double ipt)
{
    mdr_scene_f32 s;
    mdr_energy_f32 en;
    uint32_t kf, ka;
    if (mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.02f, 0.0f, MDR_OUT_FORCE, NULL) != MDR_OK) {
        return 1;
    }
    kf = cycle_scene(&s);
    if (mdr_scene_init_paraboloid_f32(&s, 1e-6f, 1e6f, 0.05f, 0.02f, 0.0f, MDR_OUT_ALL, &en) != MDR_OK) {
        return 1;
    }
    ka = cycle_scene(&s);
    if (kf == 0 || ka == 0) {
        printf("bench: a scene step failed\n");
        return 1;
    }
    printf("scene (paraboloid R = 1 um, table-free, f32): force only %.1f instr/step, all outputs + "
           "energy %.1f, ratio %.2f\n",
           (double)kf * ipt / STEPS, (double)ka * ipt / STEPS, (double)ka / (double)kf);
    return 0;
}

#ifdef BENCH_MATRIX
/* The benchmark matrix's rows that run on the target (bench_matrix.h:
 * engine rows in f32, f64 (soft double) and q31, closed-form rows in f32
 * and f64): one line "M4,scene,method,arith,N,instructions per evaluation"
 * each, joined to the host's rows by bench_matrix.c. */
static int matrix(double ipt)
{
    static bm_scene b;
    size_t k;
    int j, ctl, a;
    for (k = 0; k < NSCENES; k++) {
        if (bm_scene_init(&b, &scenes[k]) != MDR_OK) {
            printf("bench: scene %s failed\n", scenes[k].key);
            return 1;
        }
        for (a = 0; a < 2 && !scenes[k].gap; a++) {
            double acc = 0;
            uint32_t t0 = mdr_port_cycles();
            mdr_status st = a ? bm_closed_f64(&b, &acc) : bm_closed_f32(&b, &acc);
            uint32_t dt = ticks_since(t0);
            sink_f32 = (float)acc;
            if (st != MDR_OK) {
                return 1;
            }
            printf("M4,%s,closed_form,%s,0,%.1f\n", scenes[k].key, a ? "f64" : "f32",
                   (double)dt * ipt / (double)b.nradii);
        }
        for (j = 0; j < BM_NSIZES; j++) {
            if (bm_tables(&b, bm_sizes[j]) != MDR_OK) {
                return 1;
            }
            for (ctl = (int)MDR_CONTROL_LOAD; ctl <= (int)MDR_CONTROL_MACHINE; ctl++) {
                if (bm_engines(&b, ctl) != MDR_OK) {
                    return 1;
                }
                for (a = 0; a < BM_NARITH; a++) {
                    double acc = 0;
                    uint32_t t0 = mdr_port_cycles(), dt;
                    mdr_status st = a == BM_F32            ? bm_cycle_f32(&b.e32, ctl, &acc)
                                    : a == BM_F64          ? bm_cycle_f64(&b.e64, ctl, &acc)
                                    : b.tq_st != MDR_OK    ? b.tq_st /* the q31 table was refused */
                                                           : bm_cycle_q31(&b.eq, ctl, &acc);
                    dt = ticks_since(t0);
                    sink_f32 = (float)acc;
                    if (st == MDR_OK) {
                        printf("M4,%s,%s,%s,%u,%.1f\n", scenes[k].key, bm_engine[ctl], bm_arith[a],
                               (unsigned)bm_sizes[j], (double)dt * ipt / BM_STEPS);
                    } else {
                        printf("bench: %s %s %s N = %u: %s\n", scenes[k].key, bm_engine[ctl], bm_arith[a],
                               (unsigned)bm_sizes[j], mdr_status_str(st));
                    }
                }
            }
        }
    }
    return 0;
}
#endif

int main(void)
{
    const float p[3] = {1e-6f, 0, 0};
    mdr_contact_f32 c;
    double ipt, base32 = 0, base31 = 0;
    uint32_t st32 = 0, st31 = 0;
    unsigned n;
    long i;
    mdr_port_cycles_init();
    ipt = calibrate();
    for (i = 1; i <= STEPS; i++) {
        in_f32[i] = (float)bench_path(i);
    }
    if (mdr_contact_init_f32(&c, MDR_PROFILE_SPHERE, p, 1e6f, 0.05f) != MDR_OK) {
        return 1;
    }
    printf("%s (QEMU -icount shift=0): instructions per step, sphere, fixed grips,\n"
           "%d-step approach-retract cycle; %.3f instructions per SysTick tick (measured)\n",
           BENCH_CORE, STEPS, ipt);
    printf("     N   f32 instr/step  ratio-to-64   q31 instr/step  ratio-to-64   q31/f32\n");
    for (n = 64; n <= 4096; n *= 2) {
        mdr_table_f32 t;
        mdr_table_q31 tq;
        mdr_engine_f32 e;
        mdr_engine_q31 q;
        uint32_t s32, s31, k32, k31;
        double i32, i31;
        if (mdr_table_init_profile_f32(&t, n32, (uint16_t)n, &c, 0.7e-6f) != MDR_OK ||
            mdr_engine_init_f32(&e, &t, 1e6f, 0.05f, 0.02f, 0) != MDR_OK ||
            mdr_table_q31_from_f32(&tq, nq, &t) != MDR_OK ||
            mdr_engine_init_q31_f32(&q, &tq, 1e6f, 0.05f, 0.02f, 0) != MDR_OK) {
            printf("bench: setup failed at N = %u\n", n);
            return 1;
        }
        for (i = 1; i <= STEPS; i++) {
            in_q31[i] = mdr_q31_in(&q, MDR_Q_D, in_f32[i]);
        }
        k32 = cycle_f32(&e, &s32);
        k31 = cycle_q31(&q, &s31);
        if (k32 == 0 || k31 == 0) {
            printf("bench: a step failed at N = %u\n", n);
            return 1;
        }
        i32 = (double)k32 * ipt / STEPS;
        i31 = (double)k31 * ipt / STEPS;
        if (n == 64) {
            base32 = i32;
            base31 = i31;
        }
        st32 = s32 > st32 ? s32 : st32;
        st31 = s31 > st31 ? s31 : st31;
        printf("  %5u  %14.1f  %11.2f  %15.1f  %11.2f  %8.2f\n", n, i32, i32 / base32, i31,
               i31 / base31, i31 / i32);
    }
    printf("stack used by a step (measured, libgcc included): f32 %u bytes, q31 %u bytes\n",
           (unsigned)st32, (unsigned)st31);
    if (scene_rows(ipt) != 0) {
        return 1;
    }
#ifdef BENCH_MATRIX
    return matrix(ipt);
#else
    return 0;
#endif
}
