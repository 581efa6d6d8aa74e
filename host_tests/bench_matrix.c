/* SPDX-License-Identifier: MIT */
/*
 * bench_matrix.c: run time against error for every scene, method,
 * arithmetic and N (make bench; the configurations: bench_matrix.h).
 *
 *   bench_matrix time [--host-instr F] [--m4 F] [--csv F] [--md F] [--plot F]
 *       times every row (median of REPEAT runs of the whole cycle, ns per
 *       evaluation), measures its largest error against the GSL reference
 *       over the cycle, joins the instruction counts of F (lines
 *       scene,method,arith,N,instructions per evaluation; from the
 *       callgrind mode and from the target, target/bench_target.c), and
 *       writes the CSV, the Markdown tables (summary, goals, every row) and
 *       the plot's data; the summary and goals also on stdout.
 *   bench_matrix callgrind
 *       run under valgrind --tool=callgrind --collect-atstart=yes: each row
 *       runs once between CALLGRIND_ZERO_STATS and CALLGRIND_DUMP_STATS_AT
 *       whose label is the row's key and its number of evaluations (the
 *       Makefile divides the dump's instruction total by it).
 *
 * Error of a row: the largest residual of its states (a, d, F) against the
 * reference curve (scenes.h: max(|F - 2E*(a d - G_ref(a))|, 2E* a |d -
 * g_ref(a) + sqrt(2 pi a w/E*)|), relative to the largest |F| of the cycle,
 * over NCHECK evenly spaced ticks and every tick with a jump; for
 * closed_form the same residual of the mdr_eq state at NCHECK of its radii;
 * gsl_ref is the reference (no error). All figures of one table come from
 * one run: the machine is shared and noisy, the ratios are the claim.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <valgrind/callgrind.h>

#define SCENES_REF
#include "bench_matrix.h"
#include "naive_sum.h"

#define REPEAT 5
#define NCHECK 64
#define REF_PTS 16
#define MAXROWS 600

enum { M_CLOSED, M_ENGINE, M_NAIVE, M_REF };

typedef struct {
    const scene *sc;
    char method[16];
    int arith; /* -1: none (gsl_ref) */
    int n;     /* 0: none */
    double ns, err, host_instr, m4_instr;
} row;

static row rows[MAXROWS];
static int nrows;
static int cg_mode;
static volatile double sink;

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* the fixed-grips cycle with the naive O(N) force after every step */
#define NAIVE_CYCLE(SFX, EF, TF, IN)                                                                \
    static mdr_status naive_cycle_##SFX(const bm_scene *b, double *acc)                         \
    {                                                                                            \
        mdr_engine_##SFX e = b->EF;                                                              \
        mdr_step_##SFX o;                                                                        \
        mdr_status st;                                                                           \
        double s = 0;                                                                            \
        long i;                                                                                  \
        for (i = 1; i <= BM_STEPS; i++) {                                                        \
            if ((st = mdr_engine_step_d_##SFX(&e, IN[i], &o)) != MDR_OK) {                       \
                return st;                                                                       \
            }                                                                                    \
            s += e.contact ? naive_F_##SFX(&b->TF, (double)e.E, (double)e.a, (double)e.d) : 0; \
        }                                                                                        \
        *acc += s;                                                                               \
        return MDR_OK;                                                                           \
    }
NAIVE_CYCLE(f32, e32, t32, bm_in32)
NAIVE_CYCLE(f64, e64, t64, bm_in64)

/* the reference at REF_PTS radii of the scene */
static mdr_status ref_run(const bm_scene *b, double *acc)
{
    int i;
    for (i = 0; i < REF_PTS; i++) {
        ref_eq q;
        if (ref_eq_at(&b->sc->s, bm_a64[(long)i * (b->nradii - 1) / (REF_PTS - 1)], &q) != 0) {
            return MDR_E_NOCONV;
        }
        *acc += q.F;
    }
    return MDR_OK;
}

static mdr_status run_once(const bm_scene *b, int method, int arith, double *acc)
{
    switch (method) {
    case M_CLOSED: return arith == BM_F32 ? bm_closed_f32(b, acc) : bm_closed_f64(b, acc);
    case M_ENGINE:
        return arith == BM_F32   ? bm_cycle_f32(&b->e32, b->ctl, acc)
               : arith == BM_F64 ? bm_cycle_f64(&b->e64, b->ctl, acc)
                                 : bm_cycle_q31(&b->eq, b->ctl, acc);
    case M_NAIVE: return arith == BM_F32 ? naive_cycle_f32(b, acc) : naive_cycle_f64(b, acc);
    default: return ref_run(b, acc);
    }
}

/* A row's time per evaluation (median of REPEAT runs), or in callgrind mode
 * one run between zeroed and dumped counters. NAN if a run fails. */
static double measure(const bm_scene *b, int method, int arith, long evals, const char *key)
{
    double t[REPEAT], acc = 0;
    int r;
    if (cg_mode) {
        char label[160];
        mdr_status st;
        CALLGRIND_ZERO_STATS;
        st = run_once(b, method, arith, &acc);
        snprintf(label, sizeof label, "%s,%ld", key, evals);
        CALLGRIND_DUMP_STATS_AT(label);
        sink = acc;
        return st == MDR_OK ? 0 : NAN;
    }
    for (r = 0; r < REPEAT; r++) {
        double t0 = now_ns();
        if (run_once(b, method, arith, &acc) != MDR_OK) {
            return NAN;
        }
        t[r] = (now_ns() - t0) / (double)evals;
    }
    sink = acc;
    return median(t, REPEAT);
}

/* ---- errors against the reference over one cycle --------------------------- */

/* one tick of the engine of an arithmetic under the scene's control mode,
 * the state in SI; returns the status */
typedef struct {
    double a, d, F;
    int jumps, contact, wall;
} si_state;

#define STEP_SI(SFX)                                                                            \
    static mdr_status step_si_##SFX(bm_scene *b, mdr_engine_##SFX *e, long i, si_state *s)      \
    {                                                                                           \
        mdr_step_##SFX o;                                                                       \
        mdr_status st = b->ctl == MDR_CONTROL_GRIPS  ? mdr_engine_step_d_##SFX(e, BM_IN_##SFX[i], &o) \
                        : b->ctl == MDR_CONTROL_LOAD ? mdr_engine_step_F_##SFX(e, BM_IN_##SFX[i], &o) \
                                                     : mdr_engine_step_z_##SFX(e, BM_IN_##SFX[i], &o); \
        s->a = (double)o.a;                                                                     \
        s->d = (double)o.d;                                                                     \
        s->F = (double)o.F;                                                                     \
        s->jumps = o.jumps;                                                                     \
        s->contact = e->contact;                                                                \
        return st;                                                                              \
    }
STEP_SI(f32)
STEP_SI(f64)
STEP_SI(q31)

static double cycle_error(bm_scene *b, int method, int arith)
{
    mdr_engine_f32 e32 = b->e32;
    mdr_engine_f64 e64 = b->e64;
    mdr_engine_q31 eq = b->eq;
    const double Lq = (double)b->tq.L + (double)b->tq.L_lo, D0 = (double)eq.D0;
    const double Fq = 2 * b->sc->s.E * Lq * D0;
    double worst = 0, Fmax = 0;
    long i;
    for (i = 1; i <= BM_STEPS; i++) {
        si_state s;
        mdr_status st = arith == BM_F32   ? step_si_f32(b, &e32, i, &s)
                        : arith == BM_F64 ? step_si_f64(b, &e64, i, &s)
                                          : step_si_q31(b, &eq, i, &s);
        if (st != MDR_OK) {
            return NAN;
        }
        if (arith == BM_Q31) {
            s.a *= Lq / 1073741824.0;
            s.d *= D0 / 536870912.0;
            s.F *= Fq / 536870912.0;
        }
        if (method == M_NAIVE && s.contact) {
            s.F = arith == BM_F32 ? naive_F_f32(&b->t32, (double)e32.E, (double)e32.a, (double)e32.d)
                                  : naive_F_f64(&b->t64, e64.E, e64.a, e64.d);
        }
        Fmax = fmax(Fmax, fabs(s.F));
        if (s.contact && (i % (BM_STEPS / NCHECK) == 0 || s.jumps)) {
            int wall = b->t64.wall && s.a >= b->sc->L * (1 - 1e-6);
            worst = fmax(worst, scene_residual(b->sc, NULL, s.a, s.d, s.F, wall));
        }
    }
    return worst / Fmax;
}

static double closed_error(const bm_scene *b, int arith)
{
    double worst = 0, Fmax = 0;
    long i, every = b->nradii / NCHECK;
    for (i = 0; i < b->nradii; i++) {
        double d, F;
        if (arith == BM_F32) {
            mdr_eqstate_f32 q;
            mdr_eq_f32(&b->c32, bm_a32[i], &q);
            d = q.d;
            F = q.F;
        } else {
            mdr_eqstate_f64 q;
            mdr_eq_f64(&b->c64, bm_a64[i], &q);
            d = q.d;
            F = q.F;
        }
        Fmax = fmax(Fmax, fabs(F));
        if (i % every == 0) {
            worst = fmax(worst, scene_residual(b->sc, NULL, arith == BM_F32 ? (double)bm_a32[i] : bm_a64[i], d,
                                               F, b->sc->s.kind == MDR_PROFILE_FLATPUNCH));
        }
    }
    return worst / Fmax;
}

static row *add_row(const scene *sc, const char *method, int arith, int n)
{
    row *r = &rows[nrows++];
    memset(r, 0, sizeof *r);
    r->sc = sc;
    snprintf(r->method, sizeof r->method, "%s", method);
    r->arith = arith;
    r->n = n;
    r->err = r->host_instr = r->m4_instr = NAN;
    return r;
}

static void row_key(const row *r, char *buf, size_t len)
{
    snprintf(buf, len, "%s,%s,%s,%d", r->sc->key, r->method, r->arith >= 0 ? bm_arith[r->arith] : "-", r->n);
}

/* one row: time (or callgrind dump) and, in time mode, the error */
static void do_row(bm_scene *b, const char *method_name, int method, int arith, int n, long evals)
{
    row *r = add_row(b->sc, method_name, arith, n);
    char key[128];
    row_key(r, key, sizeof key);
    if (method == M_ENGINE && arith == BM_Q31 && b->tq_st != MDR_OK) {
        /* no q31 table: no time, no callgrind dump, no error; "-" in the tables */
        r->ns = NAN;
        fprintf(stderr, "bench_matrix: %s: the q31 table is refused (%s)\n", key, mdr_status_str(b->tq_st));
        return;
    }
    r->ns = measure(b, method, arith, evals, key);
    if (!cg_mode && method != M_REF && !isnan(r->ns)) {
        r->err = method == M_CLOSED ? closed_error(b, arith) : cycle_error(b, method, arith);
    }
    if (isnan(r->ns)) {
        fprintf(stderr, "bench_matrix: %s failed\n", key);
    }
}

static void run_all(void)
{
    static bm_scene b;
    size_t k;
    int j, ctl, a;
    for (k = 0; k < NSCENES; k++) {
        const scene *sc = &scenes[k];
        if (bm_scene_init(&b, sc) != MDR_OK) {
            fprintf(stderr, "bench_matrix: scene %s failed\n", sc->key);
            exit(1);
        }
        fprintf(stderr, "  %s\n", sc->name);
        if (!sc->gap) {
            do_row(&b, "closed_form", M_CLOSED, BM_F32, 0, b.nradii);
            do_row(&b, "closed_form", M_CLOSED, BM_F64, 0, b.nradii);
        }
        do_row(&b, "gsl_ref", M_REF, -1, 0, REF_PTS);
        for (j = 0; j < BM_NSIZES; j++) {
            if (bm_tables(&b, bm_sizes[j]) != MDR_OK) {
                fprintf(stderr, "bench_matrix: tables of %s at N = %u failed\n", sc->key, bm_sizes[j]);
                exit(1);
            }
            for (ctl = (int)MDR_CONTROL_LOAD; ctl <= (int)MDR_CONTROL_MACHINE; ctl++) {
                if (bm_engines(&b, ctl) != MDR_OK) {
                    fprintf(stderr, "bench_matrix: engines of %s failed\n", sc->key);
                    exit(1);
                }
                for (a = 0; a < BM_NARITH; a++) {
                    do_row(&b, bm_engine[ctl], M_ENGINE, a, bm_sizes[j], BM_STEPS);
                }
                if (ctl == MDR_CONTROL_GRIPS) {
                    do_row(&b, "naive", M_NAIVE, BM_F32, bm_sizes[j], BM_STEPS);
                    do_row(&b, "naive", M_NAIVE, BM_F64, bm_sizes[j], BM_STEPS);
                }
            }
        }
    }
}

/* ---- joining instruction counts, tables, plot data -------------------------- */

static void join(const char *file, int m4)
{
    FILE *fp = fopen(file, "r");
    char line[256];
    if (fp == NULL) {
        fprintf(stderr, "bench_matrix: cannot read %s\n", file);
        exit(1);
    }
    while (fgets(line, sizeof line, fp) != NULL) {
        char *c = strrchr(line, ',');
        int i;
        if (c == NULL) {
            continue;
        }
        *c = '\0';
        for (i = 0; i < nrows; i++) {
            char key[128];
            row_key(&rows[i], key, sizeof key);
            if (strcmp(key, line) == 0) {
                *(m4 ? &rows[i].m4_instr : &rows[i].host_instr) = atof(c + 1);
            }
        }
    }
    fclose(fp);
}

static int smooth(const scene *sc)
{
    return sc->s.kind != MDR_PROFILE_FLATTIP && sc->s.kind != MDR_PROFILE_FLATPUNCH;
}

/* the summary: per method, arithmetic and N the median over scenes of time
 * and instructions, the worst error over the smooth scenes and over the
 * others (flat punch, flattened tip) */
typedef struct {
    char method[16];
    int arith, n;
    double ns, host_instr, m4_instr, err_smooth, err_other;
} sumrow;

static sumrow sums[64];
static int nsums;

static double med_of(const sumrow *s, int what)
{
    double v[NSCENES];
    int i, m = 0;
    for (i = 0; i < nrows; i++) {
        const row *r = &rows[i];
        if (strcmp(r->method, s->method) == 0 && r->arith == s->arith && r->n == s->n) {
            double x = what == 0 ? r->ns : what == 1 ? r->host_instr : r->m4_instr;
            if (!isnan(x)) {
                v[m++] = x;
            }
        }
    }
    return m ? median(v, m) : NAN;
}

/* summary order: methods as below, then arithmetic, then N */
static int method_rank(const char *m)
{
    static const char *const order[] = {"closed_form", "gsl_ref", "engine_d", "engine_F", "engine_z", "naive"};
    int i;
    for (i = 0; i < 6 && strcmp(order[i], m) != 0; i++) {
    }
    return i;
}

static int cmp_sum(const void *x, const void *y)
{
    const sumrow *a = x, *b = y;
    int d = method_rank(a->method) - method_rank(b->method);
    return d ? d : a->arith != b->arith ? a->arith - b->arith : a->n - b->n;
}

static void summarise(void)
{
    int i, j;
    for (i = 0; i < nrows; i++) {
        const row *r = &rows[i];
        sumrow *s = NULL;
        for (j = 0; j < nsums; j++) {
            if (strcmp(sums[j].method, r->method) == 0 && sums[j].arith == r->arith && sums[j].n == r->n) {
                s = &sums[j];
            }
        }
        if (s == NULL) {
            s = &sums[nsums++];
            memset(s, 0, sizeof *s);
            snprintf(s->method, sizeof s->method, "%s", r->method);
            s->arith = r->arith;
            s->n = r->n;
        }
        if (smooth(r->sc)) {
            s->err_smooth = fmax(s->err_smooth, r->err);
        } else {
            s->err_other = fmax(s->err_other, r->err);
        }
    }
    qsort(sums, (size_t)nsums, sizeof sums[0], cmp_sum);
    for (j = 0; j < nsums; j++) {
        sums[j].ns = med_of(&sums[j], 0);
        sums[j].host_instr = med_of(&sums[j], 1);
        sums[j].m4_instr = med_of(&sums[j], 2);
    }
}

static const sumrow *find_sum(const char *method, int arith, int n)
{
    int j;
    for (j = 0; j < nsums; j++) {
        if (strcmp(sums[j].method, method) == 0 && sums[j].arith == arith && sums[j].n == n) {
            return &sums[j];
        }
    }
    return NULL;
}

static void fmt(char *buf, size_t len, const char *f, double v)
{
    if (isnan(v)) {
        snprintf(buf, len, "-");
    } else {
        snprintf(buf, len, f, v);
    }
}

static void write_summary(FILE *o)
{
    int j;
    fprintf(o, "| method | arith | N | ns/eval (host) | instr/eval (host) | instr/eval (M4F) | "
               "max error, smooth | max error, flat punch + flattened tip |\n"
               "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (j = 0; j < nsums; j++) {
        const sumrow *s = &sums[j];
        char ns[32], hi[32], mi[32], es[32], eo[32], n[16];
        fmt(ns, sizeof ns, s->ns < 1e4 ? "%.1f" : "%.3g", s->ns);
        fmt(hi, sizeof hi, "%.0f", s->host_instr);
        fmt(mi, sizeof mi, "%.0f", s->m4_instr);
        fmt(es, sizeof es, "%.1e", s->method[0] == 'g' ? NAN : s->err_smooth);
        fmt(eo, sizeof eo, "%.1e", s->method[0] == 'g' ? NAN : s->err_other);
        fmt(n, sizeof n, "%.0f", s->n ? (double)s->n : NAN);
        fprintf(o, "| %s | %s | %s | %s | %s | %s | %s | %s |\n", s->method, s->arith >= 0 ? bm_arith[s->arith] : "double",
                n, ns, hi, mi, es, eo);
    }
}

/* the goals of the issue, from the summary (medians over scenes) and from
 * the rows (worst case over scenes) */
static void write_goals(FILE *o)
{
    const char *eng[3] = {"engine_d", "engine_F", "engine_z"};
    double worst_ratio_t = 0, worst_ratio_i = 0, worst_cf = 0, least_ref = INFINITY, worst_err = 0;
    int c, i;
    for (c = 0; c < 3; c++) {
        const sumrow *s64 = find_sum(eng[c], BM_F32, 64), *s4k = find_sum(eng[c], BM_F32, 4096);
        const sumrow *s1k = find_sum(eng[c], BM_F32, 1024), *cf = find_sum("closed_form", BM_F32, 0);
        const sumrow *ref = find_sum("gsl_ref", -1, 0);
        if (s64 && s4k && s1k && cf && ref) {
            worst_ratio_t = fmax(worst_ratio_t, s4k->ns / s64->ns);
            worst_ratio_i = fmax(worst_ratio_i, s4k->host_instr / s64->host_instr);
            worst_cf = fmax(worst_cf, s1k->ns / cf->ns);
            least_ref = fmin(least_ref, ref->ns / s1k->ns);
        }
    }
    for (i = 0; i < nrows; i++) {
        const row *r = &rows[i];
        if (r->arith == BM_F32 && r->n == 1024 && strncmp(r->method, "engine", 6) == 0 && smooth(r->sc)) {
            worst_err = fmax(worst_err, r->err);
        }
    }
    fprintf(o, "| goal | measured (f32 engine, median over scenes; largest over d, F, z control) | met |\n"
               "| --- | --- | --- |\n");
    fprintf(o, "| step time at N = 4096 within 1.2x of N = 64 | %.2fx (time), %.2fx (host instructions) | %s |\n",
            worst_ratio_t, worst_ratio_i, worst_ratio_t <= 1.2 && worst_ratio_i <= 1.2 ? "yes" : "no");
    fprintf(o, "| step at most 2x one closed-form F(a) (`mdr_eq_f32`) | %.2fx at N = 1024 | %s |\n", worst_cf,
            worst_cf <= 2 ? "yes" : "no");
    fprintf(o, "| at least 10^4x faster than the GSL reference per equilibrium point | %.3gx at N = 1024 | %s |\n",
            least_ref, least_ref >= 1e4 ? "yes" : "no");
    fprintf(o, "| f32 error below 1e-5 of peak abs(F) at N = 1024, smooth profiles | %.2e (worst scene and control) | %s |\n",
            worst_err, worst_err < 1e-5 ? "yes" : "no");
}

static void write_rows(FILE *o, int csv)
{
    int i;
    if (csv) {
        fprintf(o, "scene,method,arith,N,ns_per_eval,host_instr_per_eval,m4_instr_per_eval,max_error\n");
    } else {
        fprintf(o, "| scene | method | arith | N | ns/eval | instr/eval (host) | instr/eval (M4F) | max error |\n"
                   "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    }
    for (i = 0; i < nrows; i++) {
        const row *r = &rows[i];
        char ns[32], hi[32], mi[32], er[32], n[16];
        fmt(ns, sizeof ns, csv ? "%.4g" : (r->ns < 1e4 ? "%.1f" : "%.3g"), r->ns);
        fmt(hi, sizeof hi, "%.1f", r->host_instr);
        fmt(mi, sizeof mi, "%.1f", r->m4_instr);
        fmt(er, sizeof er, "%.2e", r->err);
        fmt(n, sizeof n, "%.0f", r->n ? (double)r->n : NAN);
        fprintf(o, csv ? "%s,%s,%s,%s,%s,%s,%s,%s\n" : "| %s | %s | %s | %s | %s | %s | %s | %s |\n",
                csv ? r->sc->key : r->sc->name, r->method, r->arith >= 0 ? bm_arith[r->arith] : "double", n, ns,
                hi, mi, er);
    }
}

/* gnuplot data: one block per method and arithmetic (N, ns, error), and the
 * reference's time; a fourth column is the point's label */
static void write_plot(FILE *o)
{
    const char *methods[] = {"engine_d", "engine_F", "engine_z", "naive", "closed_form"};
    int m, a, j;
    for (m = 0; m < 5; m++) {
        for (a = 0; a < BM_NARITH; a++) {
            int any = 0;
            for (j = 0; j < nsums; j++) {
                const sumrow *s = &sums[j];
                if (strcmp(s->method, methods[m]) == 0 && s->arith == a && !isnan(s->ns)) {
                    if (!any) {
                        fprintf(o, "\"%s %s\"\n", methods[m], bm_arith[a]);
                        any = 1;
                    }
                    /* N as a label on the f32 engine_d and naive lines only (the
                     * others lie on top of them) */
                    if (s->n && a == BM_F32 && (m == 0 || m == 3)) {
                        fprintf(o, "%d %.6g %.6g \"%d\"\n", s->n, s->ns, s->err_smooth, s->n);
                    } else {
                        fprintf(o, "%d %.6g %.6g \"\"\n", s->n, s->ns, s->err_smooth);
                    }
                }
            }
            if (any) {
                fprintf(o, "\n\n");
            }
        }
    }
    {
        const sumrow *ref = find_sum("gsl_ref", -1, 0);
        fprintf(o, "\"gsl_ref\"\n0 %.6g 0 \"\"\n", ref ? ref->ns : NAN);
    }
}

static FILE *open_out(const char *f)
{
    FILE *o = fopen(f, "w");
    if (o == NULL) {
        fprintf(stderr, "bench_matrix: cannot write %s\n", f);
        exit(1);
    }
    return o;
}

int main(int argc, char **argv)
{
    const char *hi = NULL, *m4 = NULL, *csv = NULL, *md = NULL, *plot = NULL;
    int i;
    if (argc < 2 || (strcmp(argv[1], "time") != 0 && strcmp(argv[1], "callgrind") != 0)) {
        fprintf(stderr, "usage: bench_matrix time [--host-instr F] [--m4 F] [--csv F] [--md F] [--plot F]\n"
                        "       bench_matrix callgrind   (under valgrind --tool=callgrind)\n");
        return 2;
    }
    cg_mode = strcmp(argv[1], "callgrind") == 0;
    for (i = 2; i + 1 < argc; i += 2) {
        const char **dst = strcmp(argv[i], "--host-instr") == 0 ? &hi
                           : strcmp(argv[i], "--m4") == 0       ? &m4
                           : strcmp(argv[i], "--csv") == 0      ? &csv
                           : strcmp(argv[i], "--md") == 0       ? &md
                           : strcmp(argv[i], "--plot") == 0     ? &plot
                                                                : NULL;
        if (dst == NULL) {
            fprintf(stderr, "bench_matrix: unknown option %s\n", argv[i]);
            return 2;
        }
        *dst = argv[i + 1];
    }
    fprintf(stderr, "bench_matrix %s:\n", argv[1]);
    run_all();
    if (cg_mode) {
        return 0;
    }
    if (hi != NULL) {
        join(hi, 0);
    }
    if (m4 != NULL) {
        join(m4, 1);
    }
    summarise();
    printf("Run time against error (medians over the %d scenes; errors: worst scene)\n\n", (int)NSCENES);
    write_summary(stdout);
    printf("\n");
    write_goals(stdout);
    if (csv != NULL) {
        FILE *o = open_out(csv);
        write_rows(o, 1);
        fclose(o);
    }
    if (md != NULL) {
        FILE *o = open_out(md);
        fprintf(o, "# Benchmark matrix (`make bench`)\n\nGenerated by `host_tests/bench_matrix.c`; "
                   "methods, error and instruction counts are defined there and in `host_tests/bench_matrix.h`.\n\n"
                   "## Summary (medians over the scenes; errors: worst scene)\n\n");
        write_summary(o);
        fprintf(o, "\n## Goals\n\n");
        write_goals(o);
        fprintf(o, "\n## Every row\n\n");
        write_rows(o, 0);
        fclose(o);
    }
    if (plot != NULL) {
        FILE *o = open_out(plot);
        write_plot(o);
        fclose(o);
    }
    return 0;
}
