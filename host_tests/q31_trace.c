/* SPDX-License-Identifier: MIT */
/*
 * q31_trace.c: a fingerprint of the q31 engine's outputs. Runs approach-
 * retract cycles of four scenes (paraboloid, exact sphere, flat punch, seed
 * wavy) under each control, 256 springs, and hashes every raw output of every
 * step (status, a, d, F, z, the jump states, event, jumps) and the final
 * energy sums with 64-bit FNV-1a. `make q31-exact` builds it with several
 * compilers and optimisation levels and requires one hash: the step is
 * integer arithmetic, so any difference is a bug (undefined or
 * implementation-defined behaviour). Tables and engine constants are set up
 * in double on the host, identically for every build (IEEE, no contraction).
 * The q31 table-free scene (mdr_scene_q31.h) is traced the same way: the
 * paraboloid, the cone and the power law n = 3, each under every control
 * over the same raw path, its constants made in double from an f64 scene.
 *
 * `q31_trace --tables` prints the four q31 tables (nodes and headers) as
 * const C (build/host/q31_trace_tables.h); a build with -DQ31_TRACE_TABLES
 * reads them from there instead of computing them, as a firmware on a core
 * with little RAM does (`mdr table --arith q31`): the Cortex-M0 of make
 * target-test, whose 16 KB do not hold the 256-spring f64 and q31 tables.
 * The hash covers the same nodes and steps, so it prints the same
 * fingerprint; the engine is still set up on the core (the double init).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mdr.h"

#ifdef Q31_TRACE_TABLES
#include "q31_trace_tables.h"
#endif

#define TRACE_SPRINGS 256

static uint64_t h = 14695981039346656037ull;

static void mix(int64_t v)
{
    int i;
    for (i = 0; i < 8; i++) {
        h ^= (uint64_t)((v >> (8 * i)) & 0xff);
        h *= 1099511628211ull;
    }
}

static const struct {
    uint8_t kind;
    double p[3], E, w, L;
} sc[] = {
    {MDR_PROFILE_PARABOLOID, {1e-6, 0, 0}, 1e6, 0.01, 0.9e-6},
    {MDR_PROFILE_SPHERE, {1e-6, 0, 0}, 1e6, 0.01, 0.9e-6},
    {MDR_PROFILE_FLATPUNCH, {1e-6, 0, 0}, 1e6, 0.01, 1e-6},
    {MDR_PROFILE_WAVY, {100e-6, 0.15e-6, 5e-6}, 1e6, 0.7957747154594767, 80e-6},
};
#define NSCENES (sizeof sc / sizeof sc[0])

#ifndef Q31_TRACE_TABLES
static mdr_node_q31 nq[MDR_TABLE_NODES(TRACE_SPRINGS)];

/* the q31 table of scene k, made in double from the f64 one (nodes in nq) */
static int table(unsigned k, mdr_table_q31 *tq)
{
    static mdr_node_f64 nf[MDR_TABLE_NODES(TRACE_SPRINGS)];
    mdr_contact_f64 c;
    mdr_table_f64 t;
    return mdr_contact_init_f64(&c, sc[k].kind, sc[k].p, sc[k].E, sc[k].w) != MDR_OK ||
           mdr_table_init_profile_f64(&t, nf, TRACE_SPRINGS, &c, sc[k].L) != MDR_OK ||
           mdr_table_q31_from_f64(tq, nq, &t) != MDR_OK;
}
#endif

/* the same cycle's control at tick i (raw Q2.29 units) */
static int32_t path_u(int i)
{
    return i <= 600    ? (int32_t)(i * (MDR_Q29_ONE / 3000))
           : i <= 2400 ? (int32_t)((600 - 3600 * (i - 600) / 1800) * (MDR_Q29_ONE / 3000))
                       : (int32_t)((-3000 + 6 * (i - 2400)) * (MDR_Q29_ONE / 3000));
}

static void mix_step(mdr_status st, const mdr_step_q31 *o)
{
    mix(st);
    mix(o->a);
    mix(o->d);
    mix(o->F);
    mix(o->z);
    mix(o->a0);
    mix(o->d0);
    mix(o->F0);
    mix(o->a1);
    mix(o->d1);
    mix(o->F1);
    mix(o->event);
    mix(o->jumps);
}

#if MDR_CFG_SCENE
/* the q31 scenes: every monomial under every control */
static int trace_scenes(long *steps, long *events, long *refused)
{
    static const struct {
        uint8_t kind;
        double p[3], a_max;
    } ms[] = {
        {MDR_PROFILE_PARABOLOID, {1e-6, 0, 0}, 0.9e-6},
        {MDR_PROFILE_CONE, {0.3, 0, 0}, 2e-6},
        {MDR_PROFILE_POWERLAW, {1e12, 3, 0}, 1e-6},
    };
    unsigned k;
    int ctl, i;
    for (k = 0; k < sizeof ms / sizeof ms[0]; k++) {
        for (ctl = 1; ctl <= 3; ctl++) {
            mdr_contact_f64 c;
            mdr_scene_f64 s;
            mdr_energy_f64 en;
            mdr_scene_q31 q;
            if (mdr_contact_init_f64(&c, ms[k].kind, ms[k].p, 1e6, 0.01) != MDR_OK ||
                mdr_scene_init_contact_f64(&s, &c, 0.005, ctl == MDR_CONTROL_MACHINE ? 0.5 : 0.0, MDR_OUT_ALL,
                                           &en) != MDR_OK ||
                mdr_scene_init_q31_f64(&q, &s, ms[k].a_max) != MDR_OK) {
                printf("q31 trace: scene init failed\n");
                return 1;
            }
            mix(q.gc);
            mix(q.c_w);
            mix(q.c_adv);
            mix(q.z_in);
            mix(q.tf[ctl - 1]);
            mix(q.uf[ctl - 1]);
            for (i = 1; i <= 3000; i++) {
                const int32_t u = path_u(i);
                mdr_step_q31 o = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
                mdr_status st = ctl == MDR_CONTROL_GRIPS ? mdr_scene_step_d_q31(&q, u, &o)
                                : ctl == MDR_CONTROL_LOAD ? mdr_scene_step_F_q31(&q, u / 64, &o)
                                                          : mdr_scene_step_z_q31(&q, u / 8, &o);
                mix_step(st, &o);
                *events += o.event != MDR_EV_NONE;
                *refused += st != MDR_OK;
                ++*steps;
            }
            mix(q.en.work);
            mix(q.en.dissipated);
            mix((int64_t)q.en.cycles);
            mix(q.flags);
        }
    }
    return 0;
}
#endif

static int trace(void)
{
    long steps = 0, events = 0, refused = 0;
    unsigned k;
    int ctl, i;
    for (k = 0; k < NSCENES; k++) {
        mdr_table_q31 tq;
        const mdr_node_q31 *n;
#ifdef Q31_TRACE_TABLES
        tq = q31_trace_tab[k];
#else
        if (table(k, &tq) != 0) {
            printf("q31 trace: setup failed\n");
            return 1;
        }
#endif
        n = tq.node;
        for (i = 0; i <= TRACE_SPRINGS; i++) {
            mix(n[i].g);
            mix(n[i].G);
            mix(n[i].t);
            mix(n[i].s);
            mix(n[i].b);
        }
        for (ctl = 1; ctl <= 3; ctl++) {
            mdr_engine_q31 e;
            double km = ctl == MDR_CONTROL_MACHINE ? 2 * sc[k].E * sc[k].L / 3 : 0;
            if (mdr_engine_init_q31_f64(&e, &tq, sc[k].E, sc[k].w, sc[k].w, km) != MDR_OK) {
                printf("q31 trace: init failed\n");
                return 1;
            }
            /* 0 -> +0.2 -> -1.0 units and back up to 0.2: approach, pull-off, re-contact */
            for (i = 1; i <= 3000; i++) {
                const int32_t u = path_u(i);
                mdr_step_q31 o = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
                mdr_status st = ctl == MDR_CONTROL_GRIPS ? mdr_engine_step_d_q31(&e, u, &o)
                                : ctl == MDR_CONTROL_LOAD ? mdr_engine_step_F_q31(&e, u / 64, &o)
                                                          : mdr_engine_step_z_q31(&e, u, &o);
                mix_step(st, &o);
                events += o.event != MDR_EV_NONE;
                refused += st != MDR_OK;
                steps++;
            }
            mix(e.en.work);
            mix(e.en.dissipated);
            mix((int64_t)e.en.cycles);
            mix(e.flags);
        }
    }
#if MDR_CFG_SCENE
    if (trace_scenes(&steps, &events, &refused) != 0) {
        return 1;
    }
#endif
    /* the hash in two 32-bit halves: newlib-nano's printf (the Cortex-M0's)
     * has no long long conversion */
    printf("q31 trace: %08lx%08lx (%ld steps, %ld events, %ld refused)\n", (unsigned long)(h >> 32),
           (unsigned long)(h & 0xFFFFFFFFu), steps, events, refused);
    return 0;
}

#ifdef MDR_TARGET_TEST
int main(void)
{
    return trace();
}
#else
/* the tables as const C, in the layout of `mdr table --arith q31` (floats
 * as hexadecimal literals: exact) */
static int print_tables(void)
{
    mdr_table_q31 tq[NSCENES];
    unsigned k;
    int i;
    printf("/* q31 tables of host_tests/q31_trace.c, made by `q31_trace --tables`: do not edit */\n");
    for (k = 0; k < NSCENES; k++) {
        if (table(k, &tq[k]) != 0) {
            fprintf(stderr, "q31 trace: setup failed\n");
            return 1;
        }
        /* the n + 1 nodes and the block bounds after them */
        printf("static const mdr_node_q31 q31_trace_node%u[%d] = {\n", k, (int)MDR_TABLE_NODES(TRACE_SPRINGS));
        for (i = 0; i < (int)MDR_TABLE_NODES(TRACE_SPRINGS); i++) {
            printf("    {%ld, %ld, %ld, %ld, %ld},\n", (long)nq[i].g, (long)nq[i].G, (long)nq[i].t,
                   (long)nq[i].s, (long)nq[i].b);
        }
        printf("};\n");
    }
    printf("static const mdr_table_q31 q31_trace_tab[%u] = {\n", (unsigned)NSCENES);
    for (k = 0; k < NSCENES; k++) {
        printf("    {q31_trace_node%u, %af, %af, %af, %ld, %u, %u, %u, %u, %u},\n", k, (double)tq[k].L,
               (double)tq[k].L_lo, (double)tq[k].Dg, (long)tq[k].gmax, (unsigned)tq[k].n,
               (unsigned)tq[k].m, (unsigned)tq[k].fb, (unsigned)tq[k].wall, (unsigned)tq[k].rim0);
    }
    printf("};\n");
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--tables") == 0) {
        return print_tables();
    }
    if (argc != 1) {
        fprintf(stderr, "usage: q31_trace [--tables]\n");
        return 2;
    }
    return trace();
}
#endif
