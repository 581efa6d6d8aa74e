/* SPDX-License-Identifier: MIT */
/*
 * mdr_refgen.c: writes the reference vectors that host tests compare lib/
 * against (committed as text; `make ref-check` regenerates and diffs them).
 *
 *   mdr_refgen critical   scene,kind,p0,p1,p2,E,w,control,k_m,a_start,a,d,F,jumps
 *   mdr_refgen curves     scene,kind,p0,p1,p2,E,w,a,d,F,dd_da,dF_da,g,dg
 *
 * Scenes: every profile over grids at AFM scale (R = 5 nm .. 1 um,
 * E* = 1 MPa .. 200 GPa, w = 0.01 .. 1 J/m^2) and gripper scale
 * (R = 0.1 .. 10 mm, E* = 0.1 .. 10 MPa), plus the seed's wavy examples.
 * Curves: 200 radii, geometric from 1e-4 a_c to 10 a_c (a_c: fixed-load
 * critical radius), capped at a0 (flat punch) and 0.99 R (sphere).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mdr_ref.h"
#include "mdr_types.h"

#define MAXS 400

static ref_scene scenes[MAXS];
static int nscenes;

static void add(int kind, double p0, double p1, double p2, double E, double w)
{
    ref_scene s = {kind, {p0, p1, p2}, E, w};
    scenes[nscenes++] = s;
}

static void build(void)
{
    static const double afmR[] = {5e-9, 1e-7, 1e-6}, afmE[] = {1e6, 1e9, 2e11};
    static const double grR[] = {1e-4, 1e-2}, grE[] = {1e5, 1e7}, ws[] = {0.01, 1.0};
    for (int scale = 0; scale < 2; scale++) {
        const double *Rs = scale ? grR : afmR, *Es = scale ? grE : afmE;
        int nR = scale ? 2 : 3, nE = scale ? 2 : 3;
        for (int ie = 0; ie < nE; ie++) {
            for (int iw = 0; iw < 2; iw++) {
                double E = Es[ie], w = ws[iw];
                add(MDR_PROFILE_CONE, scale ? 0.1 : 1.2, 0, 0, E, w);
                for (int ir = 0; ir < nR; ir++) {
                    double R = Rs[ir];
                    double astar = cbrt(9 * M_PI * R * R * w / (8 * E));
                    add(MDR_PROFILE_PARABOLOID, R, 0, 0, E, w);
                    add(MDR_PROFILE_SPHERE, R, 0, 0, E, w);
                    add(MDR_PROFILE_POWERLAW, 0.5 / pow(R, 0.75 - 1), 0.75, 0, E, w);
                    add(MDR_PROFILE_POWERLAW, 0.5 / pow(R, 1.5 - 1), 1.5, 0, E, w);
                    add(MDR_PROFILE_POWERLAW, 0.5 / pow(R, 3.0 - 1), 3.0, 0, E, w);
                    add(MDR_PROFILE_FLATPUNCH, R, 0, 0, E, w);
                    add(MDR_PROFILE_FLATTIP, R, 0.3 * astar, 0, E, w);
                    add(MDR_PROFILE_FLATTIP, R, 0.9 * astar, 0, E, w);
                    add(MDR_PROFILE_WAVY, R, 0.005 * astar / 6, astar / 6, E, w);
                    add(MDR_PROFILE_WAVY, R, 0.03 * astar / 6, astar / 6, E, w);
                }
            }
        }
    }
    /* the seed's wavy examples (4.54, Fig. 4.9) and CHECK_VALUES scenes */
    add(MDR_PROFILE_WAVY, 1, 0.005 * 0.05, 0.05, 1, 0.05 / (2 * M_PI));
    add(MDR_PROFILE_WAVY, 1, 0.03 * 0.05, 0.05, 1, 0.05 / (2 * M_PI));
    add(MDR_PROFILE_SPHERE, 1, 0, 0, 1, 0.001);
    add(MDR_PROFILE_POWERLAW, 1, 4, 0, 1, 1);
}

/* a_start = 3 a_x with ref d(a_x) = 0 (capped as documented in lib/) */
static double start_of(const ref_scene *s)
{
    double lo, hi;
    if (s->kind == MDR_PROFILE_FLATPUNCH) {
        return s->p[0];
    }
    lo = hi = (s->kind == MDR_PROFILE_CONE) ? 1.0 : (s->kind == MDR_PROFILE_SPHERE ? 0.5 * s->p[0] : s->p[0]);
    if (s->kind == MDR_PROFILE_POWERLAW) {
        lo = hi = 1e-6;
    }
    if (s->kind == MDR_PROFILE_WAVY) {
        /* smooth base */
        return 3 * cbrt(pow(sqrt(2 * M_PI * s->w / s->E) * s->p[0], 2));
    }
    while (ref_g(s, lo) - sqrt(2 * M_PI * lo * s->w / s->E) > 0) {
        lo *= 0.5;
    }
    while (ref_g(s, hi) - sqrt(2 * M_PI * hi * s->w / s->E) <= 0) {
        hi = (s->kind == MDR_PROFILE_SPHERE) ? 0.5 * (hi + s->p[0]) : 2 * hi;
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; i++) {
        double m = 0.5 * (lo + hi);
        if (ref_g(s, m) - sqrt(2 * M_PI * m * s->w / s->E) > 0) {
            hi = m;
        } else {
            lo = m;
        }
    }
    {
        double a = 3 * hi;
        if (s->kind == MDR_PROFILE_SPHERE && a > 0.9 * s->p[0]) {
            a = 0.9 * s->p[0];
        }
        if (s->kind == MDR_PROFILE_FLATTIP && a < 1.5 * s->p[1]) {
            a = 1.5 * s->p[1];
        }
        return a;
    }
}

static void head(const ref_scene *s, int i)
{
    printf("%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g", i, s->kind, s->p[0], s->p[1], s->p[2], s->E, s->w);
}

int main(int argc, char **argv)
{
    int crit = argc > 1 && strcmp(argv[1], "critical") == 0;
    build();
    if (crit) {
        printf("scene,kind,p0,p1,p2,E,w,control,k_m,a_start,a,d,F,jumps\n");
    } else {
        printf("scene,kind,p0,p1,p2,E,w,a,d,F,dd_da,dF_da,g,dg\n");
    }
    for (int i = 0; i < nscenes; i++) {
        const ref_scene *s = &scenes[i];
        double a0 = start_of(s);
        ref_crit cl;
        ref_critical(s, MDR_CONTROL_LOAD, 0, a0, &cl);
        if (crit) {
            for (int ctl = 1; ctl <= 3; ctl++) {
                /* machine: stiffness 2 E* a_c, comparable to the contact's */
                double km = ctl == 3 ? 2 * s->E * (cl.a > 0 ? cl.a : a0) : 0.0;
                ref_crit c;
                if (ctl == 1) {
                    c = cl;
                } else {
                    ref_critical(s, ctl, km, a0, &c);
                }
                head(s, i);
                printf(",%d,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", ctl, km, a0, c.a, c.d, c.F, c.jumps);
            }
        } else {
            double ac = cl.a > 0 ? cl.a : a0, lo = 1e-4 * ac, hi = 10 * ac;
            if (s->kind == MDR_PROFILE_FLATPUNCH && hi > s->p[0]) {
                hi = s->p[0];
            }
            if (s->kind == MDR_PROFILE_SPHERE && hi > 0.99 * s->p[0]) {
                hi = 0.99 * s->p[0];
            }
            for (int k = 0; k < 200; k++) {
                double a = lo * pow(hi / lo, k / 199.0);
                ref_eq e;
                if (s->kind == MDR_PROFILE_FLATTIP && fabs(a - s->p[1]) < 1e-6 * s->p[1]) {
                    continue; /* g' infinite at a = b */
                }
                ref_eq_at(s, a, &e);
                head(s, i);
                printf(",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", a, e.d, e.F, e.dd_da, e.dF_da,
                       ref_g(s, a), ref_dg(s, a));
            }
        }
        if (fflush(stdout) != 0) {
            perror("mdr_refgen");
            return 1;
        }
    }
    return 0;
}
