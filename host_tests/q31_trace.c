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
 */
#include <stdint.h>
#include <stdio.h>

#include "mdr.h"

static uint64_t h = 14695981039346656037ull;

static void mix(int64_t v)
{
    int i;
    for (i = 0; i < 8; i++) {
        h ^= (uint64_t)((v >> (8 * i)) & 0xff);
        h *= 1099511628211ull;
    }
}

int main(void)
{
    static mdr_node_f64 nf[MDR_TABLE_NODES(256)];
    static mdr_node_q31 nq[MDR_TABLE_NODES(256)];
    static const struct {
        uint8_t kind;
        double p[3], E, w, L;
    } sc[] = {
        {MDR_PROFILE_PARABOLOID, {1e-6, 0, 0}, 1e6, 0.01, 0.9e-6},
        {MDR_PROFILE_SPHERE, {1e-6, 0, 0}, 1e6, 0.01, 0.9e-6},
        {MDR_PROFILE_FLATPUNCH, {1e-6, 0, 0}, 1e6, 0.01, 1e-6},
        {MDR_PROFILE_WAVY, {100e-6, 0.15e-6, 5e-6}, 1e6, 0.7957747154594767, 80e-6},
    };
    long steps = 0, events = 0, refused = 0;
    unsigned k;
    int ctl, i;
    for (k = 0; k < sizeof sc / sizeof sc[0]; k++) {
        mdr_contact_f64 c;
        mdr_table_f64 t;
        mdr_table_q31 tq;
        if (mdr_contact_init_f64(&c, sc[k].kind, sc[k].p, sc[k].E, sc[k].w) != MDR_OK ||
            mdr_table_init_profile_f64(&t, nf, 256, &c, sc[k].L) != MDR_OK ||
            mdr_table_q31_from_f64(&tq, nq, &t) != MDR_OK) {
            printf("q31 trace: setup failed\n");
            return 1;
        }
        for (i = 0; i <= 256; i++) {
            mix(nq[i].g);
            mix(nq[i].G);
            mix(nq[i].t);
            mix(nq[i].s);
            mix(nq[i].b);
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
                int32_t u = i <= 600    ? (int32_t)(i * (MDR_Q29_ONE / 3000))
                            : i <= 2400 ? (int32_t)((600 - 3600 * (i - 600) / 1800) * (MDR_Q29_ONE / 3000))
                                        : (int32_t)((-3000 + 6 * (i - 2400)) * (MDR_Q29_ONE / 3000));
                mdr_step_q31 o = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
                mdr_status st = ctl == MDR_CONTROL_GRIPS ? mdr_engine_step_d_q31(&e, u, &o)
                                : ctl == MDR_CONTROL_LOAD ? mdr_engine_step_F_q31(&e, u / 64, &o)
                                                          : mdr_engine_step_z_q31(&e, u, &o);
                mix(st);
                events += o.event != MDR_EV_NONE;
                refused += st != MDR_OK;
                mix(o.a);
                mix(o.d);
                mix(o.F);
                mix(o.z);
                mix(o.a0);
                mix(o.d0);
                mix(o.F0);
                mix(o.a1);
                mix(o.d1);
                mix(o.F1);
                mix(o.event);
                mix(o.jumps);
                steps++;
            }
            mix(e.en.work);
            mix(e.en.dissipated);
            mix((int64_t)e.en.cycles);
            mix(e.flags);
        }
    }
    printf("q31 trace: %016llx (%ld steps, %ld events, %ld refused)\n", (unsigned long long)h, steps,
           events, refused);
    return 0;
}
