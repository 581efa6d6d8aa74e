/* SPDX-License-Identifier: MIT */
/*
 * scenes.h: the scenes of the engine's whole-cycle tests and benchmarks
 * (test_q31.c, bench_matrix.c, target/bench_target.c): every profile of the
 * seed and a tabulated tip, each with its table extent, and the control path
 * of one approach-retract cycle through pull-off under each control mode.
 * GSL-free: the target benchmark includes it too; the residual against the
 * reference (scene_residual) needs ref/: it is there with SCENES_REF.
 */
#ifndef SCENES_H
#define SCENES_H

#include <math.h>
#include <stdint.h>

#include "mdr.h"
#include "mdr_ref.h"

/* not every includer uses every helper */
#define SCENE_FN static __attribute__((unused))

typedef struct {
    const char *name; /* for people */
    const char *key;  /* for CSV: no spaces or commas */
    ref_scene s;
    double L;    /* table extent */
    int gap;     /* 1: tabulated tip (GAP_SAMPLES samples of s's gap profile) */
    double goal; /* the accuracy goal of test_q31's e_curve and e_po against ref */
    double table; /* test_q31: tolerance of the f64 engine's e_curve at N = 1024
                   * against ref, the table's own error (about 4x the worst
                   * measured over the three controls; exact tables: rounding) */
} scene;

#define GOAL_SMOOTH 1e-4
/* the flattened tip's table limits the force curve just above its rim
 * (test_q31.c); its pull-offs meet GOAL_SMOOTH since the rim is a node */
#define GOAL_FLATTIP 1e-3
#define GAP_SAMPLES 600

static const scene scenes[] = {
    {"paraboloid", "paraboloid", {MDR_PROFILE_PARABOLOID, {1e-6, 0, 0}, 1e6, 0.01}, 0.9e-6, 0, GOAL_SMOOTH, 4e-14},
    {"cone", "cone", {MDR_PROFILE_CONE, {0.5, 0, 0}, 1e6, 0.01}, 1e-6, 0, GOAL_SMOOTH, 4e-14},
    {"power law n=3", "powerlaw", {MDR_PROFILE_POWERLAW, {5e11, 3, 0}, 1e6, 0.01}, 1e-6, 0, GOAL_SMOOTH, 1.5e-9},
    {"flat punch", "flatpunch", {MDR_PROFILE_FLATPUNCH, {1e-6, 0, 0}, 1e6, 0.01}, 1e-6, 0, GOAL_SMOOTH, 5e-16},
    {"exact sphere", "sphere", {MDR_PROFILE_SPHERE, {1e-6, 0, 0}, 1e6, 0.01}, 0.9e-6, 0, GOAL_SMOOTH, 4e-9},
    {"flattened tip", "flattip", {MDR_PROFILE_FLATTIP, {1e-6, 0.2e-6, 0}, 1e6, 0.01}, 0.9e-6, 0, GOAL_FLATTIP, 2.5e-3},
    {"wavy (4.54)", "wavy", {MDR_PROFILE_WAVY, {100e-6, 0.15e-6, 5e-6}, 1e6, 0.7957747154594767}, 80e-6, 0,
     GOAL_SMOOTH, 8e-6},
    {"tabulated sphere", "table", {MDR_PROFILE_SPHERE, {1e-6, 0, 0}, 1e6, 0.01}, 0.9e-6, 1, GOAL_SMOOTH, 4e-7},
};
#define NSCENES (sizeof scenes / sizeof scenes[0])

/* the tabulated tip's samples: r_i = L i/(GAP_SAMPLES-1) and the gap of the
 * exact sphere, f = R - sqrt(R^2 - r^2) (as ref_f) */
SCENE_FN void scene_gap(const scene *sc, double *r, double *f)
{
    int i;
    double R = sc->s.p[0];
    for (i = 0; i < GAP_SAMPLES; i++) {
        r[i] = sc->L * i / (GAP_SAMPLES - 1.0);
        f[i] = R - sqrt(R * R - r[i] * r[i]);
    }
}

/* The f64 table of a scene with n springs into nodes[n + 1]. */
SCENE_FN mdr_status scene_table_f64(const scene *sc, mdr_table_f64 *t, mdr_node_f64 *nodes, uint16_t n)
{
    mdr_contact_f64 c;
    mdr_status st = mdr_contact_init_f64(&c, (uint8_t)sc->s.kind, sc->s.p, sc->s.E, sc->s.w);
    if (st != MDR_OK) {
        return st;
    }
    if (sc->gap) {
        static double r[GAP_SAMPLES], f[GAP_SAMPLES];
        scene_gap(sc, r, f);
        return mdr_table_init_gap_f64(t, nodes, n, r, f, GAP_SAMPLES);
    }
    return mdr_table_init_profile_f64(t, nodes, n, &c, sc->L);
}

/* The control path of a scene's cycle: the controlled value rises from 0
 * to top[ctl] in NUP ticks and falls to bot[ctl] in NDOWN ticks (ctl =
 * MDR_CONTROL_LOAD, _GRIPS, _MACHINE; the machine's stiffness km). Set from
 * a fixed-grips run of the f64 engine on t64 (w_adv = w): depth up to 90 %
 * of the equilibrium depth at 0.8 L, down to 1.2 c sqrt(L) below contact
 * (past every pull-off); the force range Ftop (at the top), Fmin (the most
 * adhesive) of that run: load from 0 to 0.8 Ftop down to 1.3 Fmin; the
 * machine (km = 2E* L/3, about a third of the stiffest contact) over the
 * same depths plus those forces through km. */
typedef struct {
    double top[4], bot[4], km;
} scene_path;

SCENE_FN mdr_status scene_path_of(const scene *sc, const mdr_table_f64 *t64, int nup, int ndown,
                                scene_path *P)
{
    mdr_engine_f64 e;
    mdr_step_f64 o;
    mdr_contact_f64 c;
    double E = sc->s.E, w = sc->s.w, L = sc->L, cL = sqrt(2 * M_PI * w * L / E);
    double g8, dmax, dmin, Ftop = 0, Fmin = 0, km = 2 * E * L / 3;
    mdr_status st;
    int i;
    *P = (scene_path){{0, 0, 0, 0}, {0, 0, 0, 0}, 0};
    if ((st = mdr_contact_init_f64(&c, (uint8_t)sc->s.kind, sc->s.p, E, w)) != MDR_OK ||
        (st = mdr_profile_eval_f64(&c, 0.8 * L, &g8, NULL, NULL)) != MDR_OK ||
        (st = mdr_engine_init_f64(&e, t64, E, w, w, 0)) != MDR_OK) {
        return st;
    }
    dmax = 0.9 * (g8 - sqrt(2 * M_PI * w * 0.8 * L / E));
    dmax = dmax > 0 ? dmax : 0.3 * cL;
    dmin = -1.2 * cL;
    for (i = 1; i <= nup + ndown; i++) {
        double d = i <= nup ? dmax * i / nup : dmax + (dmin - dmax) * (i - nup) / ndown;
        if ((st = mdr_engine_step_d_f64(&e, d, &o)) != MDR_OK) {
            return st;
        }
        Fmin = fmin(Fmin, o.F);
        if (i == nup) {
            Ftop = o.F;
        }
    }
    if (!(Ftop > 0)) {
        return MDR_E_PARAM;
    }
    P->km = km;
    P->top[MDR_CONTROL_GRIPS] = dmax;
    P->bot[MDR_CONTROL_GRIPS] = dmin;
    P->top[MDR_CONTROL_LOAD] = 0.8 * Ftop;
    P->bot[MDR_CONTROL_LOAD] = 1.3 * Fmin;
    P->top[MDR_CONTROL_MACHINE] = dmax + 0.8 * Ftop / km;
    P->bot[MDR_CONTROL_MACHINE] = dmin + 1.3 * Fmin / km;
    return MDR_OK;
}

/* the controlled value at tick i = 1 ... nup + ndown */
SCENE_FN double scene_u(const scene_path *P, int ctl, int nup, int ndown, long i)
{
    double top = P->top[ctl], bot = P->bot[ctl];
    return i <= nup ? top * (double)i / nup : top + (bot - top) * (double)(i - nup) / ndown;
}

/* g and G of an f64 table's interpolant at a (lib/include/mdr_engine_t.h:
 * the quadratic through g_k, g_k+1 with the spring integral q_k) */
SCENE_FN void scene_tab_gG(const mdr_table_f64 *t, double a, double *g, double *G)
{
    int k = (int)(a / t->h);
    const mdr_node_f64 *n0;
    double e, s, be, h = t->h;
    k = k < 0 ? 0 : k >= t->n ? t->n - 1 : k;
    n0 = &t->node[k];
    e = a - h * k;
    s = (n0[1].g - n0->g) / h;
    be = 6 * n0->q / (h * h * h);
    *g = n0->g + e * (s + be * (h - e));
    *G = n0->G + e * (n0->g + e * (0.5 * s + be * (0.5 * h - e / 3)));
}

#ifdef SCENES_REF
/* Distance of a contact state (a, d, F) from the equilibrium curve of the
 * reference (t64 NULL) or of an f64 table's interpolant:
 * max(|F - 2E*(a d - G(a))|, 2E* a |d - (g(a) - sqrt(2 pi a w/E*))|); the
 * second term (the depth error as a force through the contact stiffness)
 * is omitted at a wall (the flat punch's rim), where the edge is pinned. */
SCENE_FN double scene_residual(const scene *sc, const mdr_table_f64 *t64, double a, double d, double F,
                             int wall)
{
    double E = sc->s.E, g, G, r;
    if (t64 != NULL) {
        scene_tab_gG(t64, a, &g, &G);
    } else {
        g = wall ? 0 : ref_g(&sc->s, a);
        G = ref_G(&sc->s, a);
    }
    r = fabs(F - 2 * E * (a * d - G));
    if (!wall) {
        r = fmax(r, 2 * E * a * fabs(d - (g - sqrt(2 * M_PI * a * sc->s.w / E))));
    }
    return r;
}
#endif

#endif /* SCENES_H */
