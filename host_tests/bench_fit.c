/* SPDX-License-Identifier: MIT */
/*
 * bench_fit.c: the cost of fitting force curves (lib/include/mdr_fit.h), in
 * one run: curves per second per core for 1 000-point retract curves of a
 * paraboloid tip (f64 and f32, the full Levenberg-Marquardt fit and the
 * two-point method), the forward model's cost per point, and their ratio.
 *
 *   bench_fit time [--md FILE]
 *       CPU time of this process (clock(): one core, whatever else runs on
 *       the machine) over NCURVES distinct noisy curves, REPEAT times each,
 *       the median of REPEAT passes; a Markdown table on stdout (and FILE)
 *   bench_fit callgrind
 *       each row once between CALLGRIND_ZERO_STATS and CALLGRIND_DUMP_STATS_AT
 *       (run under valgrind --tool=callgrind: instructions per curve and per
 *       model point, independent of the machine's load; make bench-fit)
 *
 * The scene: R = 20 nm, E* = 1 GPa, w = 0.05 J/m^2 (Tabor mu = 1.2), a
 * cantilever of 0.2 N/m, the retract from 2|z'_fold| + z'(2.5 a_fold) to
 * 0.4 of that range below the fold (70 % of the points in contact),
 * Gaussian noise of 1 % of the pull-off force, offsets z0 = 1 um and
 * F_b = 0.1 nN. At that noise the two-point method refuses most curves
 * (MDR_E_DEGENERATE: its standard errors cannot hold, docs/fitting.md);
 * its row times what it does either way and says how many it answered.
 * Any other failure stops the bench.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <valgrind/callgrind.h>

#include "mdr.h"
#include "noise.h"

#define NPTS 1000
#define NCURVES 32
#define REPEAT 5

static double z64[NCURVES][NPTS], F64[NCURVES][NPTS], work64[MDR_FIT_WORK_LEN(NPTS)], Fm64[NPTS];
static float z32[NCURVES][NPTS], F32[NCURVES][NPTS], work32[MDR_FIT_WORK_LEN(NPTS)], Fm32[NPTS];
static mdr_contact_f64 tip64, c64;
static mdr_contact_f32 tip32, c32;
static volatile double sink;

static const double R = 20e-9, E = 1e9, W = 0.05, KM = 0.2, Z0 = 1e-6, FB = 1e-10;


static void setup(void)
{
    double p[3] = {R, 0, 0}, as, zf, ztop, zbot, Fclean[NPTS], z[NPTS];
    float pf[3] = {(float)R, 0.0f, 0.0f};
    mdr_critstate_f64 cs;
    mdr_eqstate_f64 e;
    int i, k;
    if (mdr_contact_init_f64(&c64, MDR_PROFILE_PARABOLOID, p, E, W) != MDR_OK ||
        mdr_contact_init_f64(&tip64, MDR_PROFILE_PARABOLOID, p, 1.0, 0.0) != MDR_OK ||
        mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pf, (float)E, (float)W) != MDR_OK ||
        mdr_contact_init_f32(&tip32, MDR_PROFILE_PARABOLOID, pf, 1.0f, 0.0f) != MDR_OK ||
        mdr_default_start_f64(&c64, &as) != MDR_OK ||
        mdr_critical_f64(&c64, MDR_CONTROL_MACHINE, KM, as, &cs) != MDR_OK ||
        mdr_eq_f64(&c64, 2.5 * cs.a, &e) != MDR_OK) {
        fprintf(stderr, "bench_fit: setup failed\n");
        exit(1);
    }
    zf = cs.d + cs.F / KM;
    ztop = 2 * fabs(zf) + e.d + e.F / KM;
    zbot = zf - 0.4 * (ztop - zf);
    for (i = 0; i < NPTS; i++) {
        z[i] = Z0 + ztop + (zbot - ztop) * i / (NPTS - 1);
    }
    if (mdr_fit_model_f64(&c64, KM, Z0, FB, MDR_FIT_RETRACT, z, NPTS, Fclean) != MDR_OK) {
        fprintf(stderr, "bench_fit: model failed\n");
        exit(1);
    }
    for (k = 0; k < NCURVES; k++) {
        for (i = 0; i < NPTS; i++) {
            z64[k][i] = z[i];
            F64[k][i] = Fclean[i] + 0.01 * fabs(cs.F) * gauss();
            z32[k][i] = (float)z64[k][i];
            F32[k][i] = (float)F64[k][i];
        }
    }
}

/* curves the two-point method refused (MDR_E_DEGENERATE) */
static int tp_refused[NCURVES];

/* the rows: each fits (or models) curve k once; returns LM iterations */
static int fit64(int k, uint8_t method)
{
    mdr_fit_opts_f64 o;
    mdr_fit_result_f64 r;
    mdr_status st;
    mdr_fit_defaults_f64(&o, KM);
    o.unpinned = 1; /* model curves: no pinned top (at this noise the fit refuses them otherwise: MDR_E_PINNED) */
    o.method = method;
    st = mdr_fit_curve_f64(&tip64, &o, z64[k], F64[k], NPTS, work64, MDR_FIT_WORK_LEN(NPTS), &r);
    if (method == MDR_FIT_TWO_POINT && st == MDR_E_DEGENERATE) {
        tp_refused[k] = 1; /* (its errors cannot hold at this noise: a refusal is its answer, at its cost) */
        return 0;
    }
    if (st != MDR_OK) {
        fprintf(stderr, "bench_fit: f64 fit (%s) of curve %d failed: %s\n",
                method == MDR_FIT_TWO_POINT ? "two-point" : "full", k, mdr_status_str(st));
        exit(1);
    }
    sink = r.E;
    return r.iterations;
}
static int fit64_full(int k) { return fit64(k, MDR_FIT_FULL); }
static int fit64_tp(int k) { return fit64(k, MDR_FIT_TWO_POINT); }
static int fit32_full(int k)
{
    mdr_fit_opts_f32 o;
    mdr_fit_result_f32 r;
    mdr_fit_defaults_f32(&o, (float)KM);
    o.unpinned = 1;
    if (mdr_fit_curve_f32(&tip32, &o, z32[k], F32[k], NPTS, work32, MDR_FIT_WORK_LEN(NPTS), &r) != MDR_OK) {
        fprintf(stderr, "bench_fit: f32 fit of curve %d failed\n", k);
        exit(1);
    }
    sink = (double)r.E;
    return r.iterations;
}
static int model64(int k)
{
    if (mdr_fit_model_f64(&c64, KM, Z0, FB, MDR_FIT_RETRACT, z64[k], NPTS, Fm64) != MDR_OK) {
        exit(1);
    }
    sink = Fm64[NPTS / 2];
    return 0;
}
static int model32(int k)
{
    if (mdr_fit_model_f32(&c32, (float)KM, (float)Z0, (float)FB, MDR_FIT_RETRACT, z32[k], NPTS, Fm32) != MDR_OK) {
        exit(1);
    }
    sink = (double)Fm32[NPTS / 2];
    return 0;
}

static const struct {
    const char *label, *what;
    int (*run)(int);
    int per_point;
} rows[] = {
    {"fit_f64_full", "fit, f64, Levenberg-Marquardt", fit64_full, 0},
    {"fit_f32_full", "fit, f32, Levenberg-Marquardt", fit32_full, 0},
    {"fit_f64_twopoint", "fit, f64, two-point method", fit64_tp, 0},
    {"model_f64", "forward model, f64 (mdr_fit_model: 2 sweeps)", model64, 1},
    {"model_f32", "forward model, f32 (mdr_fit_model: 2 sweeps)", model32, 1},
};
#define NROWS (int)(sizeof rows / sizeof rows[0])

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    int r, k, rep;
    FILE *md = NULL;
    setup();
    if (argc >= 2 && strcmp(argv[1], "callgrind") == 0) {
        for (r = 0; r < NROWS; r++) {
            CALLGRIND_ZERO_STATS;
            for (k = 0; k < NCURVES; k++) {
                (void)rows[r].run(k);
            }
            CALLGRIND_DUMP_STATS_AT(rows[r].label);
        }
        return 0;
    }
    if (argc < 2 || strcmp(argv[1], "time") != 0) {
        fprintf(stderr, "usage: bench_fit time [--md FILE] | callgrind\n");
        return 2;
    }
    if (argc == 4 && strcmp(argv[2], "--md") == 0) {
        md = fopen(argv[3], "w");
        if (md == NULL) {
            perror(argv[3]);
            return 1;
        }
    }
    {
        double us[NROWS], it[NROWS];
        for (r = 0; r < NROWS; r++) {
            double t[REPEAT];
            long iters = 0;
            for (rep = 0; rep < REPEAT; rep++) {
                clock_t c0 = clock();
                for (k = 0; k < NCURVES; k++) {
                    iters += rows[r].run(k);
                }
                t[rep] = (double)(clock() - c0) / CLOCKS_PER_SEC / NCURVES;
            }
            qsort(t, REPEAT, sizeof t[0], cmp);
            us[r] = 1e6 * t[REPEAT / 2];
            it[r] = (double)iters / (REPEAT * NCURVES);
        }
        for (int pass = 0; pass < 2; pass++) {
            FILE *o = pass == 0 ? stdout : md;
            if (o == NULL) {
                continue;
            }
            fprintf(o, "| what (1 000-point retract, paraboloid, 1 %% noise) | time per curve | curves/s/core | "
                       "LM iterations | in model sweeps |\n| --- | ---: | ---: | ---: | ---: |\n");
            for (r = 0; r < NROWS; r++) {
                if (rows[r].per_point) {
                    fprintf(o, "| %s | %.1f ns/point | | | 1 |\n", rows[r].what, 1e3 * us[r] / (2.0 * NPTS));
                } else {
                    int m = strstr(rows[r].label, "f32") != NULL ? 4 : 3;
                    char what[160];
                    if (rows[r].run == fit64_tp) {
                        int n = 0;
                        for (k = 0; k < NCURVES; k++) {
                            n += tp_refused[k];
                        }
                        snprintf(what, sizeof what, "%s (answers %d of %d curves, the rest refused: "
                                 "MDR_E_DEGENERATE)", rows[r].what, NCURVES - n, NCURVES);
                    } else {
                        snprintf(what, sizeof what, "%s", rows[r].what);
                    }
                    fprintf(o, "| %s | %.0f us | %.0f | %.1f | %.1f |\n", what, us[r], 1e6 / us[r], it[r],
                            us[r] / (us[m] / 2.0));
                }
            }
        }
    }
    if (md != NULL && fclose(md) != 0) {
        perror("bench_fit: --md");
        return 1;
    }
    return 0;
}
