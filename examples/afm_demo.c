/* SPDX-License-Identifier: MIT */
/*
 * afm_demo.c: an AFM pull-off scene with libmdr (f32, as on the target).
 *
 * A silicon-nitride tip of radius R = 20 nm against PDMS and against a stiff
 * polymer (polystyrene). For each, the pull-off state under fixed load,
 * fixed grips and through the cantilever (k_m = 0.2 N/m), for the exact
 * sphere and its paraboloid (JKR) approximation, beside the JKR closed forms
 * -1.5 pi w R and -(5/6) pi w R. Writes the retraction branch F(d) of both
 * substrates as CSV to OUTDIR/afm_fd.csv (SI, and normalised: F/(pi w R)
 * against d/(pi^2 w^2 R/E*^2)^(1/3)).
 *
 * Then the real-time part, as firmware would run it: a force-spectroscopy
 * cycle through the cantilever with the spring engine (512 springs of the
 * exact sphere, w_adv = w/2): the base z approaches in 0.01 nm ticks until
 * the force reaches a 2 nN trigger, then retracts until the tip is free.
 * Prints the jump-in, the trigger, the pull-off (beside mdr_critical's
 * cantilever value) and the energy dissipated in the cycle; writes every
 * tick to OUTDIR/afm_cycle.csv (phase: approach or retract).
 *
 * The states to mark on plots go to OUTDIR/afm_marks.csv, one per line:
 * substrate, mark, x, F_before, F_after (SI): the fixed-load pull-off of the
 * equilibrium curve (x = d), the JKR closed form -1.5 pi w R (x = 0), and
 * the cycle's jump-in and pull-off (x = z; the force before and after the
 * jump). make demo plots them (examples/afm_demo.gp, gnuplot).
 *
 * Usage: afm_demo [OUTDIR]   (default build/demo)
 */
/* POSIX: mkdir (a feature-test macro: reserved by design) */
#define _POSIX_C_SOURCE 200809L /* NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp) */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "mdr.h"

struct substrate {
    const char *name;
    double E, nu, w; /* Young's modulus [Pa], Poisson ratio, work of adhesion [J/m^2] */
};

static const struct substrate subs[2] = {
    {"PDMS", 2.0e6, 0.5, 0.045},
    {"polystyrene", 3.4e9, 0.34, 0.066},
};

static const double PI = 3.14159265358979323846;
static const double R_TIP = 20e-9, E_TIP = 250e9, NU_TIP = 0.23, K_CANTILEVER = 0.2;

/* 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 */
static double e_star(const struct substrate *s)
{
    return 1.0 / ((1 - s->nu * s->nu) / s->E + (1 - NU_TIP * NU_TIP) / E_TIP);
}

/* OUTDIR/name opened for writing with its CSV header, or NULL (reported). */
static FILE *open_csv(const char *outdir, const char *name, const char *header, char *path,
                      size_t len)
{
    FILE *f;
    int n = snprintf(path, len, "%s/%s", outdir, name);
    if (n < 0 || (size_t)n >= len) {
        fprintf(stderr, "afm_demo: output path too long: %s\n", outdir);
        return NULL;
    }
    f = fopen(path, "w");
    if (f == NULL) {
        perror(path);
        return NULL;
    }
    fprintf(f, "%s\n", header);
    return f;
}

/* Closes a CSV written with open_csv; 0, or 1 if a write failed (reported). */
static int close_csv(FILE *f, const char *path)
{
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "afm_demo: writing %s failed\n", path);
        return 1;
    }
    return 0;
}

/* mkdir -p: every directory of path, existing ones accepted. 0 or -1. */
static int make_dirs(const char *path)
{
    char buf[512];
    size_t i, n = strlen(path);
    if (n == 0 || n >= sizeof buf) {
        return -1;
    }
    memcpy(buf, path, n + 1);
    for (i = 1; i <= n; i++) {
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
                perror(buf);
                return -1;
            }
            buf[i] = c;
        }
    }
    return 0;
}

/* One force-spectroscopy cycle per substrate with the real-time engine. */
static int engine_cycles(const char *outdir, FILE *marks)
{
    static mdr_node_f32 nodes[MDR_TABLE_NODES(512)];
    const float triggers[2] = {1e-9f, 5e-9f}, dz = 0.01e-9f;
    char path[512];
    FILE *csv;
    int i;
    csv = open_csv(outdir, "afm_cycle.csv", "substrate,tick,z,d,F,a,event,phase", path, sizeof path);
    if (csv == NULL) {
        return 1;
    }
    printf("\nreal-time cycle through the cantilever (spring engine, 512 springs to 0.995 R, f32, "
           "w_adv = w/2, %.2f nm ticks)\n", (double)dz * 1e9);
    for (i = 0; i < 2; i++) {
        const struct substrate *s = &subs[i];
        float E = (float)e_star(s), w = (float)s->w;
        float p[3] = {(float)R_TIP, 0.0f, 0.0f};
        mdr_contact_f32 c;
        mdr_table_f32 t;
        mdr_engine_f32 e;
        mdr_step_f32 o;
        mdr_critstate_f32 cr;
        float z = -2e-9f, a0, trigger = triggers[i];
        long tick = 0;
        int retract = 0;
        if (mdr_contact_init_f32(&c, MDR_PROFILE_SPHERE, p, E, w) != MDR_OK ||
            mdr_table_init_profile_f32(&t, nodes, 512, &c, 0.995f * (float)R_TIP) != MDR_OK ||
            mdr_engine_init_f32(&e, &t, E, w, 0.5f * w, (float)K_CANTILEVER) != MDR_OK) {
            fprintf(stderr, "afm_demo: engine init failed\n");
            (void)fclose(csv);
            return 1;
        }
        printf("%s (trigger %.0f nN):\n", s->name, (double)trigger * 1e9);
        while (tick < 10000000L) {
            mdr_status st = mdr_engine_step_z_f32(&e, z, &o);
            if (st != MDR_OK) {
                fprintf(stderr, "afm_demo: step: %s\n", mdr_status_str(st));
                (void)fclose(csv);
                return 1;
            }
            fprintf(csv, "%s,%ld,%.9g,%.9g,%.9g,%.9g,%s,%s\n", s->name, tick, (double)o.z, (double)o.d,
                    (double)o.F, (double)o.a, mdr_event_str(o.event), retract ? "retract" : "approach");
            if (o.event == MDR_EV_JUMP_IN || o.event == MDR_EV_PULL_OFF) {
                fprintf(marks, "%s,%s,%.9g,%.9g,%.9g\n", s->name, mdr_event_str(o.event), (double)o.z,
                        (double)o.F0, (double)o.F);
            }
            if (o.event != MDR_EV_NONE) {
                printf("  tick %7ld  %-10s z = %8.3f nm: F %8.4f -> %8.4f nN, d %8.4f -> %8.4f nm, "
                       "a %6.3f -> %6.3f nm\n", tick, mdr_event_str(o.event), (double)z * 1e9,
                       (double)o.F0 * 1e9, (double)o.F * 1e9, (double)o.d0 * 1e9, (double)o.d * 1e9,
                       (double)o.a0 * 1e9, (double)o.a * 1e9);
            }
            if (!retract && o.F >= trigger) {
                retract = 1;
                printf("  tick %7ld  trigger    z = %8.3f nm: F = %.4f nN, a = %.3f nm; retracting\n",
                       tick, (double)z * 1e9, (double)o.F * 1e9, (double)o.a * 1e9);
            }
            if (retract && o.event == MDR_EV_PULL_OFF) {
                break;
            }
            z += retract ? -dz : dz;
            tick++;
        }
        if (mdr_default_start_f32(&c, &a0) == MDR_OK &&
            mdr_critical_f32(&c, MDR_CONTROL_MACHINE, (float)K_CANTILEVER, a0, &cr) == MDR_OK) {
            printf("  pull-off %.4f nN (mdr_critical through the cantilever: %.4f nN); "
                   "dissipated in the cycle %.4g aJ\n",
                   (double)o.F0 * 1e9, (double)cr.F * 1e9, (double)e.en.last_cycle * 1e18);
        }
    }
    if (close_csv(csv, path) != 0) {
        return 1;
    }
    printf("every tick: %s\n", path);
    return 0;
}

int main(int argc, char **argv)
{
    static const char *ctl_name[4] = {"", "fixed load", "fixed grips", "cantilever"};
    const char *outdir = argc > 1 ? argv[1] : "build/demo";
    char path[512];
    char marks_path[512];
    FILE *csv, *marks;
    int i, rc;

    if (make_dirs(outdir) != 0) {
        return 1;
    }
    printf("AFM tip: Si3N4, R = %.0f nm; cantilever k_m = %.1f N/m; libmdr f32\n\n", R_TIP * 1e9,
           K_CANTILEVER);
    printf("%-12s %-7s %-11s %10s %12s %10s %12s\n", "substrate", "tip", "control", "a_c [nm]",
           "F_c [nN]", "d_c [nm]", "JKR F [nN]");
    for (i = 0; i < 2; i++) {
        const struct substrate *s = &subs[i];
        float E = (float)e_star(s), w = (float)s->w;
        float p[3] = {(float)R_TIP, 0.0f, 0.0f};
        uint8_t kinds[2] = {MDR_PROFILE_SPHERE, MDR_PROFILE_PARABOLOID};
        int k;
        for (k = 0; k < 2; k++) {
            mdr_contact_f32 c;
            float a0;
            uint8_t ctl;
            if (mdr_contact_init_f32(&c, kinds[k], p, E, w) != MDR_OK ||
                mdr_default_start_f32(&c, &a0) != MDR_OK) {
                fprintf(stderr, "afm_demo: init failed\n");
                return 1;
            }
            for (ctl = MDR_CONTROL_LOAD; ctl <= MDR_CONTROL_MACHINE; ctl++) {
                mdr_critstate_f32 o;
                mdr_status st = mdr_critical_f32(&c, ctl, (float)K_CANTILEVER, a0, &o);
                double jkr = ctl == MDR_CONTROL_LOAD    ? -1.5 * PI * s->w * R_TIP
                             : ctl == MDR_CONTROL_GRIPS ? -5.0 / 6.0 * PI * s->w * R_TIP
                                                        : (double)NAN;
                if (st != MDR_OK) {
                    fprintf(stderr, "afm_demo: %s\n", mdr_status_str(st));
                    return 1;
                }
                printf("%-12s %-7s %-11s %10.4f %12.5f %10.4f ", k == 0 ? s->name : "",
                       k == 0 ? "sphere" : "parab.", ctl_name[ctl], (double)o.a * 1e9, (double)o.F * 1e9, (double)o.d * 1e9);
                if (isnan(jkr)) {
                    printf("%12s\n", "-");
                } else {
                    printf("%12.5f\n", jkr * 1e9);
                }
            }
        }
        printf("%-12s E* = %.4g Pa, w = %.3g J/m^2\n\n", "", e_star(s), s->w);
    }

    marks = open_csv(outdir, "afm_marks.csv", "substrate,mark,x,F_before,F_after", marks_path,
                     sizeof marks_path);
    if (marks == NULL) {
        return 1;
    }
    /* equilibrium curve of the exact sphere, both substrates, normalised */
    csv = open_csv(outdir, "afm_fd.csv", "substrate,a,d,F,d_norm,F_norm", path, sizeof path);
    if (csv == NULL) {
        (void)fclose(marks);
        return 1;
    }
    for (i = 0; i < 2; i++) {
        const struct substrate *s = &subs[i];
        double Es = e_star(s), dn = cbrt(PI * PI * s->w * s->w * R_TIP / (Es * Es));
        float p[3] = {(float)R_TIP, 0.0f, 0.0f};
        mdr_contact_f32 c;
        float a0;
        int j;
        mdr_critstate_f32 o;
        if (mdr_contact_init_f32(&c, MDR_PROFILE_SPHERE, p, (float)Es, (float)s->w) != MDR_OK ||
            mdr_default_start_f32(&c, &a0) != MDR_OK) {
            fprintf(stderr, "afm_demo: init failed\n");
            (void)fclose(csv);
            (void)fclose(marks);
            return 1;
        }
        /* up to 2.5 a_c (fixed load), inside the sphere */
        if (mdr_critical_f32(&c, MDR_CONTROL_LOAD, 0.0f, a0, &o) == MDR_OK) {
            a0 = fminf(2.5f * o.a, 0.95f * (float)R_TIP);
            fprintf(marks, "%s,fixed-load pull-off,%.9g,%.9g,%.9g\n", s->name, (double)o.d, (double)o.F,
                    (double)o.F);
        }
        fprintf(marks, "%s,JKR -1.5 pi w R,0,%.9g,%.9g\n", s->name, -1.5 * PI * s->w * R_TIP,
                -1.5 * PI * s->w * R_TIP);
        for (j = 1; j <= 400; j++) {
            float a = a0 * (float)j / 400.0f;
            mdr_eqstate_f32 e;
            if (mdr_eq_f32(&c, a, &e) == MDR_OK) {
                fprintf(csv, "%s,%.9g,%.9g,%.9g,%.6g,%.6g\n", s->name, (double)e.a, (double)e.d,
                        (double)e.F, (double)e.d / dn, (double)e.F / (PI * s->w * R_TIP));
            }
        }
    }
    if (close_csv(csv, path) != 0) {
        (void)fclose(marks);
        return 1;
    }
    printf("equilibrium F-d curves (exact sphere): %s\n", path);
    rc = engine_cycles(outdir, marks);
    if (close_csv(marks, marks_path) != 0) {
        return 1;
    }
    printf("states to mark: %s\n", marks_path);
    return rc;
}
