/* SPDX-License-Identifier: MIT */
/*
 * bench_scene.h: the control path of the engine benchmarks, shared by the
 * host (bench_engine.c) and the target (target/bench_target.c) so that
 * their figures are of the same cycle: STEPS ticks under fixed grips, the
 * depth from 0 up to 0.1 um in STEPS/4 ticks, then down to -0.3 um (past
 * the sphere's pull-off). Scene: exact sphere R = 1 um, E* = 1 MPa,
 * w = 0.05 J/m^2, w_adv = 0.02, table to 0.7 R.
 */
#define STEPS 20000

/* depth at tick i (1 ... STEPS), metres */
static double bench_path(long i)
{
    long q = STEPS / 4;
    return i <= q ? 0.1e-6 * (double)i / (double)q : 0.1e-6 - 0.4e-6 * (double)(i - q) / (double)(STEPS - q);
}
