/*
 * afm_demo.c: an AFM pull-off scene with libmdr (f32, as on the target).
 *
 * A silicon-nitride tip of radius R = 20 nm against PDMS and against a stiff
 * polymer (polystyrene). For each, the pull-off state under fixed load,
 * fixed grips and through the cantilever (k_m = 0.2 N/m), for the exact
 * sphere and its paraboloid (JKR) approximation, beside the JKR closed forms
 * -1.5 pi w R and -(5/6) pi w R. Writes the retraction branch F(d) of both
 * substrates as CSV to OUTDIR/afm_fd.csv and, when gnuplot is installed,
 * a plot OUTDIR/afm_fd.png (normalised: F/(pi w R) against d/(pi^2 w^2 R/E*^2)^(1/3)).
 *
 * Usage: afm_demo [OUTDIR]   (default build/demo)
 */
#define _DEFAULT_SOURCE /* M_PI, mkdir */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "mdr.h"

struct substrate {
    const char *name;
    double E, nu, w; /* Young's modulus [Pa], Poisson ratio, work of adhesion [J/m^2] */
};

static const double R_TIP = 20e-9, E_TIP = 250e9, NU_TIP = 0.23, K_CANTILEVER = 0.2;

/* 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 */
static double e_star(const struct substrate *s)
{
    return 1.0 / ((1 - s->nu * s->nu) / s->E + (1 - NU_TIP * NU_TIP) / E_TIP);
}

int main(int argc, char **argv)
{
    static const struct substrate subs[2] = {
        {"PDMS", 2.0e6, 0.5, 0.045},
        {"polystyrene", 3.4e9, 0.34, 0.066},
    };
    static const char *ctl_name[4] = {"", "fixed load", "fixed grips", "cantilever"};
    const char *outdir = argc > 1 ? argv[1] : "build/demo";
    char path[512];
    FILE *csv;
    int i;

    mkdir("build", 0777);
    mkdir(outdir, 0777);
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
                double jkr = ctl == MDR_CONTROL_LOAD    ? -1.5 * M_PI * s->w * R_TIP
                             : ctl == MDR_CONTROL_GRIPS ? -5.0 / 6.0 * M_PI * s->w * R_TIP
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

    /* equilibrium curve of the exact sphere, both substrates, normalised */
    snprintf(path, sizeof path, "%s/afm_fd.csv", outdir);
    csv = fopen(path, "w");
    if (csv == NULL) {
        perror(path);
        return 1;
    }
    fprintf(csv, "substrate,a,d,F,d_norm,F_norm\n");
    for (i = 0; i < 2; i++) {
        const struct substrate *s = &subs[i];
        double Es = e_star(s), dn = cbrt(M_PI * M_PI * s->w * s->w * R_TIP / (Es * Es));
        float p[3] = {(float)R_TIP, 0.0f, 0.0f};
        mdr_contact_f32 c;
        float a0;
        int j;
        mdr_critstate_f32 o;
        mdr_contact_init_f32(&c, MDR_PROFILE_SPHERE, p, (float)Es, (float)s->w);
        mdr_default_start_f32(&c, &a0);
        /* up to 2.5 a_c (fixed load), inside the sphere */
        if (mdr_critical_f32(&c, MDR_CONTROL_LOAD, 0.0f, a0, &o) == MDR_OK) {
            a0 = fminf(2.5f * o.a, 0.95f * (float)R_TIP);
        }
        for (j = 1; j <= 400; j++) {
            float a = a0 * (float)j / 400.0f;
            mdr_eqstate_f32 e;
            if (mdr_eq_f32(&c, a, &e) == MDR_OK) {
                fprintf(csv, "%s,%.9g,%.9g,%.9g,%.6g,%.6g\n", s->name, (double)e.a, (double)e.d,
                        (double)e.F, (double)e.d / dn, (double)e.F / (M_PI * s->w * R_TIP));
            }
        }
    }
    fclose(csv);
    printf("equilibrium F-d curves (exact sphere): %s\n", path);
    if (system("command -v gnuplot >/dev/null 2>&1") == 0) {
        char cmd[2048];
        snprintf(cmd, sizeof cmd,
                 "gnuplot -e \"set terminal pngcairo size 800,560 noenhanced; set output '%s/afm_fd.png';"
                 " set datafile separator ','; set key bottom right; set grid;"
                 " set xlabel 'd / (pi^2 w^2 R / E*^2)^(1/3)'; set ylabel 'F / (pi w R)';"
                 " set title 'Si3N4 tip R = 20 nm, exact sphere (libmdr f32)';"
                 " plot '%s' using (strcol(1) eq 'PDMS' ? \\$5 : 1/0):6 with lines lw 2 title 'PDMS',"
                 " '' using (strcol(1) eq 'polystyrene' ? \\$5 : 1/0):6 with lines lw 2 title 'polystyrene',"
                 " -1.5 with lines dt 2 title 'JKR -1.5'\" 2>/dev/null",
                 outdir, path);
        if (system(cmd) == 0) {
            printf("plot: %s/afm_fd.png\n", outdir);
        } else {
            printf("plot: gnuplot failed (no pngcairo terminal?); CSV written\n");
        }
    } else {
        printf("plot: install gnuplot for a PNG\n");
    }
    return 0;
}
