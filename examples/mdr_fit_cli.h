/* SPDX-License-Identifier: MIT */
/*
 * mdr_fit_cli.h: `mdr fit`, measured force curves to E*, w, contact point,
 * baseline and regime (lib/include/mdr_fit.h). Included once by mdr_cli.c,
 * after its profile table and argument helpers; mdr_cli.c's main() hands
 * argv to fit_main() when the command is "fit".
 *
 *   mdr fit --curve curve.csv <profile> --k-machine K [--method full|two-point]
 *           [--z-e ZE] [--arith f32|f64] [--E0 E --w0 W] [--approach] [--unpinned]
 *           [--flat-baseline]
 *   mdr fit --map map.csv <profile> --k-machine K [--jobs J] [same options]
 *
 *   <profile>  --profile paraboloid --R R | cone --theta RAD | powerlaw --C C
 *              --n N | sphere --R R | flattip --R R --b B | wavy --R R --h H
 *              --lambda L (the flat punch cannot be fitted: mdr_fit_t.h)
 *   curve.csv  a header line (optional: a first field that does not
 *              start as a number would), then z,F rows in time order (z
 *              the base position [m], increasing toward the sample; F the
 *              force [N], compressive positive); the retract is the part
 *              from the largest z on. Lines starting with '#' and empty
 *              lines are skipped; a UTF-8 byte order mark is dropped.
 *   map.csv    a header line (optional, the same), then curve,z,F rows,
 *              each curve's rows contiguous and in time order (curve: any
 *              label without a comma or a double quote, not starting with
 *              '#'). A bad row stops the map (exit 2) after the rows of the
 *              curves before the one it stops, whatever --jobs.
 *   --arith    f64 (default) or f32
 *   --method   full (default: Levenberg-Marquardt) or two-point
 *   --z-e      equilibrium distance of the Tabor parameter [m], 0.3e-9
 *   --E0 --w0  first guesses (default: the two-point method)
 *   --approach also fit w_adv to the approach part (JSON w_adv, w_adv_err)
 *   --unpinned the retract recedes from its top (no adhesion hysteresis):
 *              no pinned top is looked for (every sample fitted), and a
 *              retract straight within its noise to the pull-off is
 *              fitted instead of refused (MDR_E_PINNED)
 *   --flat-baseline  the force baseline is flat (its slope subtracted
 *              already): F_slope held at 0 (default: the baseline
 *              F_base + F_slope (z - z0) is fitted, slope and all)
 *   --jobs     threads for a map (default: every core)
 *   --model F  (with --curve) also write the fitted model: CSV z,F,F_model,
 *              branch (approach with w_adv, or w without --approach;
 *              retract), for plots and residuals
 *
 * --curve prints one JSON object: E w z0 F_base E_err w_err z0_err
 * F_base_err F_slope F_slope_err mu R_mu z_e regime rms pull_off_F pull_off_z a_pull_off n
 * n_pinned method iterations arith status (+ w_adv w_adv_err n_approach); exit 0.
 * A fit that fails prints {"status": ..., "message": ...} (and "hint" for
 * MDR_E_DEGENERATE of the full fit with the slope fitted, and for
 * MDR_E_PINNED with --unpinned or --approach) and exits 1. With --arith f32
 * each answer is checked against f64's fit of the same samples
 * (fit_check_f32): refused with f64's status where f64 refuses them, and
 * with MDR_E_PARAM where E*, w or w_adv lies further from f64's than
 * MDR_HOST_F32_FIT_MAX and 3 of its reported errors, or reports an error
 * below f64's by more than MDR_HOST_F32_FIT_ERR (a "hint" names it).
 * --map prints CSV curve,E,w,z0,F_base,mu,rms,status,E_err,w_err,F_slope
 * (the last three appended at stop 40: the columns before keep their
 * places), one row per curve in the input's order (status "ok" or the
 * library's status name; the other fields empty when the fit failed), a progress bar on stderr when stderr
 * is a terminal; exit 0 when every curve was fitted, 1 when some failed.
 * Bad arguments or a bad file: exit 2, one line on stderr (file:line: why).
 */
#include <limits.h>
#include <pthread.h>
#include <time.h>
#include <unistd.h>

struct fit_args {
    const char *file, *model, *tipfile;
    int map, f64, approach, unpinned, flat, jobs, pi, have_E0; /* pi: -1 for --profile table */
    uint8_t kind, method;
    double p[3], k_m, z_e, E0, w0;
    /* --profile table: the samples as each arithmetic's contact takes them
     * (radii, then slopes formed in double: mdr_host_tip_contact) */
    uint16_t tm;
    float *tip_f32;
    double *tip_f64;
};

/* one result in double, whatever the arithmetic */
typedef struct {
    mdr_status st;
    double E, w, z0, F_base, E_err, w_err, z0_err, F_base_err, F_slope, F_slope_err, rms, pull_off_F, pull_off_z;
    double a_pull_off;
    double mu, R_mu, w_adv, w_adv_err;
    uint32_t n, n_approach, n_pinned;
    uint16_t iterations;
    uint8_t regime, method;
    /* --arith f32 refused against f64's fit of the same samples
     * (fit_check_f32): f32_which 0 E*, 1 w, 2 w_adv (f32_off: how far),
     * 3 + those: its reported error too small (f32_off: f64's over it),
     * -2 f64 refuses them (st: f64's status); -1 not refused */
    int f32_which;
    double f32_off;
} fit_res;

/* a thread's buffer for one curve in an arithmetic: z, F and the workspace */
typedef struct {
    void *buf;
    size_t bytes;
} fit_scratch;

static int fit_scratch_grow(fit_scratch *s, size_t n, size_t elem)
{
    size_t need = (2 * n + MDR_FIT_WORK_LEN(n)) * elem;
    if (need > s->bytes) {
        void *b = realloc(s->buf, need);
        if (b == NULL) {
            return 1;
        }
        s->buf = b;
        s->bytes = need;
    }
    return 0;
}

#define FIT_T float
#define FIT_SFX(name) name##_f32
#include "mdr_fit_cli_t.h"
#undef FIT_T
#undef FIT_SFX
#define FIT_T double
#define FIT_SFX(name) name##_f64
#include "mdr_fit_cli_t.h"
#undef FIT_T
#undef FIT_SFX

/* An f32 fit's answer (o, MDR_OK) against f64's fit of the same samples,
 * as the CLI's other f32 answers are checked against f64's: refused where
 * f64 refuses the samples (o->st: f64's status) or where E*, w or w_adv
 * lies further from f64's than MDR_HOST_F32_FIT_MAX and 3 of its own
 * reported errors, or its reported error lies below f64's by more than
 * MDR_HOST_F32_FIT_ERR (mdr_host_f32_fit_check): then MDR_E_PARAM */
static void fit_check_f32(const struct fit_args *A, const double *z, const double *F, size_t n, fit_scratch *s,
                          fit_res *o)
{
    fit_res r;
    const double p32[3] = {o->E, o->w, o->w_adv}, e32[3] = {o->E_err, o->w_err, o->w_adv_err};
    int which, k;
    double x;
    mdr_status st;
    memset(&r, 0, sizeof r);
    /* (the status from the return: an early refusal, the tip's or the
     * scratch's, leaves r.st unset) */
    st = fit_run_f64(A, z, F, n, s, &r);
    if (st != MDR_OK) {
        o->st = st;
        o->f32_which = -2;
        return;
    }
    {
        const double p64[3] = {r.E, r.w, r.w_adv}, e64[3] = {r.E_err, r.w_err, r.w_adv_err};
        k = mdr_host_f32_fit_check(p32, e32, p64, e64, A->approach ? 3 : 2, &which, &x);
    }
    if (k != 0) {
        o->st = MDR_E_PARAM;
        o->f32_which = k == 2 ? 3 + which : which;
        o->f32_off = x;
    }
}

static mdr_status fit_one(const struct fit_args *A, const double *z, const double *F, size_t n, fit_scratch *s,
                          fit_res *o)
{
    memset(o, 0, sizeof *o);
    o->f32_which = -1;
    if (n > UINT32_MAX / 2) {
        o->st = MDR_E_SIZE;
        return o->st;
    }
    if (A->f64) {
        o->st = fit_run_f64(A, z, F, n, s, o);
    } else if ((o->st = fit_run_f32(A, z, F, n, s, o)) == MDR_OK) {
        fit_check_f32(A, z, F, n, s, o);
    }
    return o->st;
}

/* The library's status as its C name (for JSON and CSV). */
static const char *fit_status_name(mdr_status st)
{
    switch (st) {
    case MDR_OK: return "ok";
    case MDR_E_NULL: return "MDR_E_NULL";
    case MDR_E_NONFINITE: return "MDR_E_NONFINITE";
    case MDR_E_PARAM: return "MDR_E_PARAM";
    case MDR_E_KIND: return "MDR_E_KIND";
    case MDR_E_RADIUS: return "MDR_E_RADIUS";
    case MDR_E_POSITION: return "MDR_E_POSITION";
    case MDR_E_CONTROL: return "MDR_E_CONTROL";
    case MDR_E_NOCONV: return "MDR_E_NOCONV";
    case MDR_E_SINGULAR: return "MDR_E_SINGULAR";
    case MDR_E_OVERFLOW: return "MDR_E_OVERFLOW";
    case MDR_E_OUTSIDE: return "MDR_E_OUTSIDE";
    case MDR_E_TABLE: return "MDR_E_TABLE";
    case MDR_E_SIZE: return "MDR_E_SIZE";
    case MDR_E_DISABLED: return "MDR_E_DISABLED";
    case MDR_E_FEW: return "MDR_E_FEW";
    case MDR_E_ORDER: return "MDR_E_ORDER";
    case MDR_E_NOCONTACT: return "MDR_E_NOCONTACT";
    case MDR_E_NOPULLOFF: return "MDR_E_NOPULLOFF";
    case MDR_E_FITCAP: return "MDR_E_FITCAP";
    case MDR_E_DEGENERATE: return "MDR_E_DEGENERATE";
    case MDR_E_JUMPS: return "MDR_E_JUMPS";
    case MDR_E_PINNED: return "MDR_E_PINNED";
    case MDR_E_MISFIT: return "MDR_E_MISFIT";
    default: return "MDR_E_OTHER";
    }
}

/* ---- reading CSV with line numbers ------------------------------------ */

typedef struct {
    FILE *fp;
    const char *name;
    char *buf;
    size_t cap;
    long line;
    double vmax; /* the largest |value| of the arithmetic (--arith f32: FLT_MAX) */
    long off;    /* the bytes of the lines read (a NUL byte on the last line) */
} fit_reader;

/* the longest line and the most points of one curve that mdr fit reads */
#define FIT_LINE_MAX 65536
#define FIT_POINTS_MAX ((size_t)1 << 24)

static int fit_bad_line(const fit_reader *r, const char *why);

/* at the end of the file, a last line of got characters that ends before
 * the file does (where it has positions): a NUL byte cut it short */
static int fit_short_end(const fit_reader *r, size_t got)
{
    const long pos = ftell(r->fp);
    return pos >= 0 && pos != r->off + (long)got;
}

/* the next line (newline removed) in r->buf: its length, -1 at the end of
 * the file, on a read error (ferror tells) or out of memory, or -2 after a
 * message naming the line: a NUL byte (not a text file: /dev/zero is
 * refused at once), a line longer than FIT_LINE_MAX - 2 characters */
static long fit_getline(fit_reader *r)
{
    size_t len = 0;
    for (;;) {
        size_t room, got;
        if (r->cap - len < 2) {
            size_t nc = r->cap ? 2 * r->cap : 4096;
            char *b = nc > FIT_LINE_MAX ? NULL : realloc(r->buf, nc);
            if (b == NULL) {
                if (nc > FIT_LINE_MAX) {
                    r->line++;
                    (void)fit_bad_line(r, "line longer than 65534 characters");
                    return -2;
                }
                return -1;
            }
            r->buf = b;
            r->cap = nc;
        }
        room = r->cap - len;
        if (fgets(r->buf + len, (int)(room > INT_MAX ? INT_MAX : room), r->fp) == NULL) {
            if (len == 0) {
                return -1;
            }
            break;
        }
        got = strlen(r->buf + len);
        /* fgets stops at a newline, at the end of the file or with the
         * buffer full: anything else is a NUL byte in the text; on a last
         * line without a newline (the end of the file) the bytes read
         * tell, where the file has positions (a NUL there cut the line
         * short unseen: helper-36, stop 59) */
        if ((got == 0 || r->buf[len + got - 1] != '\n') && got + 1 < room && (!feof(r->fp) || fit_short_end(r, got))) {
            r->line++;
            (void)fit_bad_line(r, "a NUL byte (not a text file)");
            return -2;
        }
        r->off += (long)got;
        len += got;
        if (len > 0 && r->buf[len - 1] == '\n') {
            len--;
            break;
        }
    }
    if (len > 0 && r->buf[len - 1] == '\r') {
        len--;
    }
    /* a UTF-8 byte order mark before the first line (a spreadsheet's
     * export): without a header it made the first row the header (--curve)
     * or a label of its own (--map); helper-36, stop 59 */
    if (r->line == 0 && len >= 3 && memcmp(r->buf, "\xEF\xBB\xBF", 3) == 0) {
        memmove(r->buf, r->buf + 3, len - 3);
        len -= 3;
    }
    r->buf[len] = '\0';
    r->line++;
    return (long)len;
}

static int fit_bad_line(const fit_reader *r, const char *why)
{
    return usage_errf("%s:%ld: %s", r->name, r->line, why); /* (a name with a line break stays one line) */
}

/* a blank line or a comment */
static int fit_skip(const char *s)
{
    while (*s == ' ' || *s == '\t') {
        s++;
    }
    return *s == '\0' || *s == '#';
}

/* a header's field [s, e): text that does not start as a number would (a
 * first data row with a typo, "1.9e-O6,1e-12", was taken for the header
 * and dropped, exit 0; helper-36, stop 59) */
static int fit_header_field(const char *s, const char *e)
{
    while (s < e && (*s == ' ' || *s == '\t')) {
        s++;
    }
    return s < e && strchr("0123456789+-.", *s) == NULL;
}

/* one number field [s, e) */
static int fit_num(const char *s, const char *e, double *v)
{
    char *end;
    while (s < e && (*s == ' ' || *s == '\t')) {
        s++;
    }
    while (e > s && (e[-1] == ' ' || e[-1] == '\t')) {
        e--;
    }
    if (s == e) {
        return 0;
    }
    *v = tip_csv_strtod(s, &end);
    return end == e;
}

/* Split the line at commas into at most 3 fields: their count (4: more);
 * starts and ends in f[][2]. A line without a comma is split at runs of
 * tabs and spaces instead (a tab- or space-separated export, as a tip
 * file is read: refused as one field before, helper-56). */
static int fit_fields(char *s, char *f[3][2])
{
    int n = 0;
    if (strchr(s, ',') == NULL) {
        for (;;) {
            while (*s == ' ' || *s == '\t') {
                s++;
            }
            if (*s == '\0') {
                return n;
            }
            if (n == 3) {
                return 4;
            }
            f[n][0] = s;
            while (*s != '\0' && *s != ' ' && *s != '\t') {
                s++;
            }
            f[n][1] = s;
            n++;
        }
    }
    for (;;) {
        char *c = strchr(s, ',');
        if (n == 3) {
            return 4;
        }
        f[n][0] = s;
        f[n][1] = c != NULL ? c : s + strlen(s);
        n++;
        if (c == NULL) {
            return n;
        }
        s = c + 1;
    }
}

/* the z,F of a data line (fields k0, k0 + 1); 0 ok, else 2 after the message */
static int fit_row(const fit_reader *r, char *f[3][2], int k0, double *z, double *F)
{
    if (!fit_num(f[k0][0], f[k0][1], z) || !fit_num(f[k0 + 1][0], f[k0 + 1][1], F)) {
        return fit_bad_line(r, "not a number");
    }
    if (*z != *z || *F != *F || *z - *z != 0.0 || *F - *F != 0.0) {
        return fit_bad_line(r, "not a finite number (NaN or inf)");
    }
    if (*z > r->vmax || *z < -r->vmax || *F > r->vmax || *F < -r->vmax) {
        /* (the fit refused it as MDR_E_NONFINITE, no line named) */
        return fit_bad_line(r, "outside the range of --arith f32");
    }
    return 0;
}

/* a curve's samples and the file line of each */
typedef struct {
    double *z, *F;
    long *line;
    size_t n, cap;
    char *label;
    fit_res res;
} fit_curve;

/* why fit_push() failed */
static const char *fit_push_why(const fit_curve *c)
{
    return c->n >= FIT_POINTS_MAX ? "more than 16777216 points in one curve" : "out of memory";
}

static int fit_push(fit_curve *c, double z, double F, long line)
{
    if (c->n >= FIT_POINTS_MAX) {
        return 1;
    }
    if (c->n == c->cap) {
        /* (from 64 points: a map's buffers are 64 x --jobs curves, and
         * from 1 024 a 70 000-curve map of 3-row curves took 824 MB at
         * --jobs 1024; helper-36, stop 59) */
        size_t nc = c->cap ? 2 * c->cap : 64;
        double *zz = realloc(c->z, nc * sizeof *zz);
        double *ff;
        long *ll;
        if (zz == NULL) {
            return 1;
        }
        c->z = zz;
        ff = realloc(c->F, nc * sizeof *ff);
        if (ff == NULL) {
            return 1;
        }
        c->F = ff;
        ll = realloc(c->line, nc * sizeof *ll);
        if (ll == NULL) {
            return 1;
        }
        c->line = ll;
        c->cap = nc;
    }
    c->z[c->n] = z;
    c->F[c->n] = F;
    c->line[c->n] = line;
    c->n++;
    return 0;
}

static void fit_curve_free(fit_curve *c)
{
    free(c->z);
    free(c->F);
    free(c->line);
    free(c->label);
    memset(c, 0, sizeof *c);
}

/* The first line of the retract whose z increases (a bad file), or 0. */
/* where the retract begins: the last row at the largest z (0 for no rows) */
static size_t fit_top(const fit_curve *c)
{
    size_t i, top = 0;
    for (i = 0; i < c->n; i++) {
        top = c->z[i] >= c->z[top] ? i : top;
    }
    return top;
}

static long fit_order_line(const fit_curve *c)
{
    size_t i;
    for (i = fit_top(c) + 1; i < c->n; i++) {
        if (c->z[i] > c->z[i - 1]) {
            return c->line[i];
        }
    }
    return 0;
}

/* ---- one curve ------------------------------------------------------------ */

/* --model: the data with the fitted model (f64) beside them, written (and
 * closed) before the JSON goes to stdout, so that a model that fails
 * (exit 1), a file that cannot be opened (exit 2) or written (exit 1)
 * leaves stdout empty */
static int fit_write_model(const struct fit_args *A, const fit_curve *c)
{
    mdr_contact_f64 tip;
    double *Fm = malloc(c->n * sizeof *Fm);
    const size_t top = fit_top(c);
    size_t i;
    mdr_status st = fit_tip_f64(A, &tip);
    FILE *fp;
    int werr;
    if (Fm == NULL) {
        return usage_error("out of memory", NULL);
    }
    if (st == MDR_OK) {
        st = mdr_contact_material_f64(&tip, c->res.E, A->approach ? c->res.w_adv : c->res.w);
    }
    if (st == MDR_OK && top > 0) {
        st = mdr_fit_model_f64(&tip, A->k_m, c->res.z0, c->res.F_base, MDR_FIT_APPROACH, c->z, (uint32_t)top, Fm);
    }
    if (st == MDR_OK) {
        st = mdr_contact_material_f64(&tip, c->res.E, c->res.w);
    }
    if (st == MDR_OK) {
        st = mdr_fit_model_f64(&tip, A->k_m, c->res.z0, c->res.F_base, MDR_FIT_RETRACT, c->z + top,
                               (uint32_t)(c->n - top), Fm + top);
    }
    if (st != MDR_OK) {
        free(Fm);
        (void)cli_fail("--model", st);
        return 1;
    }
    fp = fopen(A->model, "w");
    if (fp == NULL) {
        free(Fm);
        return usage_sys("cannot write", A->model);
    }
    fprintf(fp, "z,F,F_model,branch\n");
    for (i = 0; i < c->n; i++) {
        /* the model over the baseline F_base + F_slope (z - z0) */
        const double Fmi = Fm[i] + c->res.F_slope * (c->z[i] - c->res.z0);
        fprintf(fp, "%.17g,%.17g,%.17g,%s\n", c->z[i], c->F[i], Fmi, i < top ? "approach" : "retract");
    }
    free(Fm);
    werr = ferror(fp);
    if (fclose(fp) != 0 || werr) {
        perror("mdr: --model");
        return 1;
    }
    return 0;
}

/* the input and units objects of a fit's JSON; ends the object */
static void fit_json_end(cli_json *j, const struct fit_args *A)
{
    cli_json in;
    json_key(j, "input");
    json_begin(&in, j->fp, 1);
    json_str(&in, "command", "fit");
    json_str(&in, "curve", A->file);
    if (A->pi < 0) {
        json_str(&in, "profile", "table");
        json_str(&in, "file", A->tipfile);
    } else {
        int k;
        json_str(&in, "profile", profiles[A->pi].name);
        for (k = 0; k < 3 && profiles[A->pi].flags[k] != NULL; k++) {
            json_num(&in, profiles[A->pi].flags[k] + 2, A->p[k]);
        }
    }
    json_num(&in, "k_m", A->k_m);
    json_num(&in, "z_e", A->z_e);
    if (A->have_E0) {
        json_num(&in, "E0", A->E0);
        json_num(&in, "w0", A->w0);
    }
    json_str(&in, "method", A->method == MDR_FIT_FULL ? "full" : "two-point");
    json_key(&in, "approach");
    fputs(A->approach ? "true" : "false", in.fp);
    json_key(&in, "unpinned");
    fputs(A->unpinned ? "true" : "false", in.fp);
    json_key(&in, "flat_baseline");
    fputs(A->flat ? "true" : "false", in.fp);
    json_str(&in, "arith", A->f64 ? "f64" : "f32");
    fputc('}', j->fp);
    json_units(j, &in, "m");
}

/* The span of z [m] beyond which a failed fit's hint asks for SI units:
 * 1 cm, far beyond a piezo's or an indenter's travel, where a curve in nm
 * spans tens to thousands */
#define FIT_SPAN_SI 1e-2
/* a force span above which a failed fit's hint names the units: 1 N is
 * beyond an adhesive contact's forces at any tip or gripper scale this fit
 * serves (a JKR pull-off 1.5 pi w R: w = 1 J/m^2 on R = 1 cm is 47 mN); nN
 * taken for newtons gave MDR_E_DEGENERATE with a hint about the baseline's
 * slope (helper-66, stop 71) */
#define FIT_FSPAN_SI 1.0

static double fit_span(const double *z, size_t n)
{
    double lo = 0.0, hi = 0.0;
    size_t i;
    for (i = 0; i < n; i++) {
        lo = i == 0 || z[i] < lo ? z[i] : lo;
        hi = i == 0 || z[i] > hi ? z[i] : hi;
    }
    return hi - lo;
}

static int fit_curve_cmd(const struct fit_args *A)
{
    fit_reader r = {NULL, NULL, NULL, 0, 0, DBL_MAX, 0};
    fit_curve c;
    fit_scratch s = {NULL, 0};
    int rc = 0, header = 0;
    long bad;
    cli_json j;
    memset(&c, 0, sizeof c);
    r.name = A->file;
    r.vmax = A->f64 ? DBL_MAX : (double)FLT_MAX;
    r.fp = fopen(A->file, "rb");
    if (r.fp == NULL) {
        return usage_sys("cannot open", A->file);
    }
    for (;;) {
        char *f[3][2];
        double z, F;
        long got = rc == 0 ? fit_getline(&r) : -1;
        if (got < 0) {
            rc = got == -2 ? 2 : rc;
            break;
        }
        if (fit_skip(r.buf)) {
            continue;
        }
        if (fit_fields(r.buf, f) != 2) {
            rc = fit_bad_line(&r, "expected two fields z,F (separated by a comma, tabs or spaces)");
        } else if (!header && !fit_num(f[0][0], f[0][1], &z) && fit_header_field(f[0][0], f[0][1])) {
            header = 1; /* the header line */
        } else {
            header = 1;
            rc = fit_row(&r, f, 0, &z, &F);
            if (rc == 0 && fit_push(&c, z, F, r.line) != 0) {
                rc = fit_bad_line(&r, fit_push_why(&c));
            }
        }
    }
    if (rc == 0 && ferror(r.fp)) {
        rc = usage_sys("read error in", A->file);
    }
    (void)fclose(r.fp); /* read only */
    free(r.buf);
    if (rc == 0 && c.n == 0) {
        rc = usage_error("no z,F rows in", A->file);
    }
    if (rc == 0 && (bad = fit_order_line(&c)) != 0) {
        rc = usage_errf("%s:%ld: z increases within the retract (the part after the largest z)", A->file, bad);
    }
    if (rc != 0) {
        fit_curve_free(&c);
        return rc;
    }
    (void)fit_one(A, c.z, c.F, c.n, &s, &c.res);
    free(s.buf);
    /* the model file first: nothing on stdout if it fails */
    if (c.res.st == MDR_OK && A->model != NULL && (rc = fit_write_model(A, &c)) != 0) {
        fit_curve_free(&c);
        return rc;
    }
    json_begin(&j, stdout, A->f64);
    if (c.res.st != MDR_OK) {
        json_str(&j, "status", fit_status_name(c.res.st));
        json_str(&j, "message", mdr_status_str(c.res.st));
        const double span = fit_span(c.z, c.n), fspan = fit_span(c.F, c.n);
        const int zs = span > FIT_SPAN_SI; /* z's span first, as before F's was checked */
        char h[200], h2[800];
        const char *hs = NULL;
        if (c.res.f32_which >= 3) {
            (void)snprintf(h, sizeof h, "f32's reported error of %s is %.2g times below f64's for the same samples "
                                        "(more than %g): take --arith f64",
                           mdr_host_f32_fit_which(c.res.f32_which - 3), c.res.f32_off, MDR_HOST_F32_FIT_ERR);
            hs = h;
        } else if (c.res.f32_which >= 0) {
            (void)snprintf(h, sizeof h, "f32's %s is %.2g off f64's fit of the same samples (more than %g and 3 of "
                                        "its reported errors): take --arith f64",
                           mdr_host_f32_fit_which(c.res.f32_which), c.res.f32_off, MDR_HOST_F32_FIT_MAX);
            hs = h;
        } else if (zs || fspan > FIT_FSPAN_SI) {
            /* (nm or um taken for metres were refused with a diagnosis of
             * the curve's shape: MDR_E_DEGENERATE, MDR_E_PINNED; helper-56) */
            (void)snprintf(h, sizeof h, "%s spans %.3g %s: z and F must be in metres and newtons (SI), not nm, um "
                                        "or nN", zs ? "z" : "F", zs ? span : fspan, zs ? "m" : "N");
            hs = h;
        } else if ((c.res.st == MDR_E_NOCONTACT || c.res.st == MDR_E_NOPULLOFF || c.res.st == MDR_E_FEW) &&
                   c.n > 0) {
            /* where the retract begins: an outlier above the top moves it
             * (helper-56: one row at z = 5e-6 m gave MDR_E_NOCONTACT) */
            const size_t top = fit_top(&c);
            (void)snprintf(h, sizeof h, "the retract is the part from the largest z on: line %ld (z = %.9g m), "
                                        "%lu rows",
                           c.line[top], c.z[top], (unsigned long)(c.n - top));
            hs = h;
        } else if (c.res.st == MDR_E_DEGENERATE && !A->flat && A->method == MDR_FIT_FULL) {
            /* the slope's price (docs/fitting.md): what the caller can do */
            hs = "the baseline's slope is fitted too: give the whole free path of both "
                 "branches, or --flat-baseline where the slope is subtracted already";
        } else if (c.res.st == MDR_E_PINNED && A->unpinned) {
            /* the message's "state unpinned" is done: what is left */
            hs = "with --unpinned: a line to the pull-off explains the retract better than a "
                 "receding branch (a contact pinned until it ruptures, or a branch straight "
                 "within the noise)";
        } else if (c.res.st == MDR_E_PINNED && A->approach) {
            /* the message's "fit with the approach" is done: what it found */
            hs = "with --approach: the approach did not rule a pinned top out (its w_adv more "
                 "than 6 errors below w, adhesion hysteresis, or its own E* more than 3 errors "
                 "from the retract's), or the contact is pinned until it ruptures; the fit does "
                 "not model a pinned top the noise hides: a stiffer lever or less noise shows "
                 "where the retract recedes (docs/fitting.md)";
        }
        if (c.res.f32_which == -2) {
            /* f64's own refusal and its hint: f32 alone answered */
            (void)snprintf(h2, sizeof h2, "f32's fit answered, but f64's fit of the same samples refuses them (an f32 "
                                          "answer is checked against f64's)%s%s",
                           hs != NULL ? "; " : "", hs != NULL ? hs : "");
            hs = h2;
        }
        if (hs != NULL) {
            json_str(&j, "hint", hs);
        }
        json_key(&j, "status_code");
        printf("%d", (int)c.res.st);
        json_str(&j, "method", A->method == MDR_FIT_FULL ? "full" : "two-point");
        json_str(&j, "arith", A->f64 ? "f64" : "f32");
        fit_json_end(&j, A);
        fit_curve_free(&c);
        return 1;
    }
    json_num(&j, "E", c.res.E);
    json_num(&j, "w", c.res.w);
    json_num(&j, "z0", c.res.z0);
    json_num(&j, "F_base", c.res.F_base);
    json_num(&j, "E_err", c.res.E_err);
    json_num(&j, "w_err", c.res.w_err);
    json_num(&j, "z0_err", c.res.z0_err);
    json_num(&j, "F_base_err", c.res.F_base_err);
    json_num(&j, "F_slope", c.res.F_slope);
    json_num(&j, "F_slope_err", c.res.F_slope_err);
    json_num(&j, "mu", c.res.mu);
    json_num(&j, "R_mu", c.res.R_mu);
    json_num(&j, "z_e", A->z_e);
    json_str(&j, "regime", mdr_regime_str(c.res.regime));
    json_num(&j, "rms", c.res.rms);
    json_num(&j, "pull_off_F", c.res.pull_off_F);
    json_num(&j, "pull_off_z", c.res.pull_off_z);
    json_num(&j, "a_pull_off", c.res.a_pull_off);
    if (A->approach) {
        json_num(&j, "w_adv", c.res.w_adv);
        json_num(&j, "w_adv_err", c.res.w_adv_err);
        json_key(&j, "n_approach");
        printf("%lu", (unsigned long)c.res.n_approach);
    }
    json_key(&j, "n");
    printf("%lu", (unsigned long)c.res.n);
    json_key(&j, "n_pinned");
    printf("%lu", (unsigned long)c.res.n_pinned);
    json_str(&j, "method", c.res.method == MDR_FIT_FULL ? "full" : "two-point");
    json_key(&j, "iterations");
    printf("%u", (unsigned)c.res.iterations);
    json_str(&j, "arith", A->f64 ? "f64" : "f32");
    json_str(&j, "status", "ok");
    fit_json_end(&j, A);
    fit_curve_free(&c);
    return 0;
}

/* ---- a map: curves on threads, in the input's order -------------------- */

/* A pool of worker threads fitting the curves of one chunk (a batch of
 * curves read from the file) while the main thread reads the next. */
typedef struct {
    pthread_mutex_t mu;
    pthread_cond_t go, done;
    fit_curve *jobs;
    size_t njobs, next, finished;
    int quit;
    const struct fit_args *A;
} fit_pool;

static void *fit_worker(void *arg)
{
    fit_pool *P = arg;
    fit_scratch s = {NULL, 0};
    (void)pthread_mutex_lock(&P->mu);
    for (;;) {
        size_t i;
        while (!P->quit && P->next >= P->njobs) {
            (void)pthread_cond_wait(&P->go, &P->mu);
        }
        if (P->quit) {
            break;
        }
        i = P->next++;
        (void)pthread_mutex_unlock(&P->mu);
        (void)fit_one(P->A, P->jobs[i].z, P->jobs[i].F, P->jobs[i].n, &s, &P->jobs[i].res);
        (void)pthread_mutex_lock(&P->mu);
        if (++P->finished == P->njobs) {
            (void)pthread_cond_signal(&P->done);
        }
    }
    (void)pthread_mutex_unlock(&P->mu);
    free(s.buf);
    return NULL;
}

static void fit_pool_submit(fit_pool *P, fit_curve *jobs, size_t n)
{
    (void)pthread_mutex_lock(&P->mu);
    P->jobs = jobs;
    P->njobs = n;
    P->next = 0;
    P->finished = 0;
    (void)pthread_cond_broadcast(&P->go);
    (void)pthread_mutex_unlock(&P->mu);
}

static void fit_pool_wait(fit_pool *P)
{
    (void)pthread_mutex_lock(&P->mu);
    while (P->finished < P->njobs) {
        (void)pthread_cond_wait(&P->done, &P->mu);
    }
    (void)pthread_mutex_unlock(&P->mu);
}

/* The labels of the curves seen so far (open addressing on a string hash),
 * to refuse a curve whose rows are not contiguous. */
typedef struct {
    char **slot;
    size_t cap, n;
} fit_seen;

static size_t fit_hash(const char *s)
{
    size_t h = 1469598103u;
    while (*s) {
        h = (h ^ (unsigned char)*s++) * 16777619u;
    }
    return h;
}

/* 1 if label was already there, 0 if added, -1 out of memory */
static int fit_seen_add(fit_seen *t, const char *label)
{
    size_t i;
    if (2 * (t->n + 1) > t->cap) {
        size_t nc = t->cap ? 2 * t->cap : 1024, k;
        char **ns = calloc(nc, sizeof *ns);
        if (ns == NULL) {
            return -1;
        }
        for (k = 0; k < t->cap; k++) {
            if (t->slot[k] != NULL) {
                for (i = fit_hash(t->slot[k]) & (nc - 1); ns[i] != NULL; i = (i + 1) & (nc - 1)) {
                }
                ns[i] = t->slot[k];
            }
        }
        free(t->slot);
        t->slot = ns;
        t->cap = nc;
    }
    for (i = fit_hash(label) & (t->cap - 1); t->slot[i] != NULL; i = (i + 1) & (t->cap - 1)) {
        if (strcmp(t->slot[i], label) == 0) {
            return 1;
        }
    }
    {
        size_t len = strlen(label) + 1;
        t->slot[i] = malloc(len);
        if (t->slot[i] == NULL) {
            return -1;
        }
        memcpy(t->slot[i], label, len);
    }
    t->n++;
    return 0;
}

static void fit_seen_free(fit_seen *t)
{
    size_t i;
    for (i = 0; i < t->cap; i++) {
        free(t->slot[i]);
    }
    free(t->slot);
}

/* the label field, trimmed, into a new string */
static char *fit_label(const char *s, const char *e)
{
    char *l;
    while (s < e && (*s == ' ' || *s == '\t')) {
        s++;
    }
    while (e > s && (e[-1] == ' ' || e[-1] == '\t')) {
        e--;
    }
    l = malloc((size_t)(e - s) + 1);
    if (l != NULL) {
        memcpy(l, s, (size_t)(e - s));
        l[e - s] = '\0';
    }
    return l;
}

/* the label field [s, e), trimmed, equals label */
static int fit_same_label(const char *label, const char *s, const char *e)
{
    size_t n;
    while (s < e && (*s == ' ' || *s == '\t')) {
        s++;
    }
    while (e > s && (e[-1] == ' ' || e[-1] == '\t')) {
        e--;
    }
    n = e > s ? (size_t)(e - s) : 0u;
    return strlen(label) == n && memcmp(label, s, n) == 0;
}

/* the first row of the next curve, read at the end of a chunk */
typedef struct {
    int have, header;
    char *label;
    double z, F;
    long line;
} fit_pending;

/* a bad row after k curves read whole: *bad set, k returned (fit_read_chunk) */
static long fit_stop(int *bad, size_t k)
{
    *bad = 1;
    return (long)k;
}

/* Read up to max curves into ch[] (reusing their buffers; the pending row
 * of the previous call first). Returns the number read; on a bad row
 * (the message printed) *bad = 1 and the number of curves read whole
 * before it (those before the curve in reading at the bad row, which is
 * not written even where the bad row would start the next), so that a map
 * stopped by a bad row writes the same curves whatever --jobs
 * (helper-36, stop 59: 32, 0 and 0 curves at --jobs 1, 2 and 4 for a bad
 * row in the 41st curve, the rows of the chunk in reading dropped). */
static long fit_read_chunk(fit_reader *r, fit_seen *seen, fit_pending *pd, fit_curve *ch, size_t max, int *bad)
{
    size_t k = 0, i;
    int active = 0;
    for (i = 0; i < max; i++) {
        ch[i].n = 0;
    }
    if (pd->have) {
        free(ch[0].label);
        ch[0].label = pd->label;
        pd->label = NULL;
        pd->have = 0;
        if (fit_push(&ch[0], pd->z, pd->F, pd->line) != 0) {
            (void)fit_bad_line(r, fit_push_why(&ch[0]));
            return fit_stop(bad, k);
        }
        active = 1;
    }
    for (;;) {
        char *f[3][2], *label;
        double z, F;
        int sn;
        long got = fit_getline(r);
        if (got == -2) {
            return fit_stop(bad, k);
        }
        if (got < 0) {
            return (long)(k + (size_t)active);
        }
        if (fit_skip(r->buf)) {
            continue;
        }
        if (fit_fields(r->buf, f) != 3) {
            (void)fit_bad_line(r, "expected three fields curve,z,F (separated by commas, tabs or spaces)");
            return fit_stop(bad, k);
        }
        if (!pd->header && !fit_num(f[1][0], f[1][1], &z) && fit_header_field(f[1][0], f[1][1])) {
            pd->header = 1; /* the header line */
            continue;
        }
        pd->header = 1;
        if (fit_row(r, f, 1, &z, &F) != 0) {
            return fit_stop(bad, k);
        }
        if (active && fit_same_label(ch[k].label, f[0][0], f[0][1])) {
            if (fit_push(&ch[k], z, F, r->line) != 0) {
                (void)fit_bad_line(r, fit_push_why(&ch[k]));
                return fit_stop(bad, k);
            }
            continue;
        }
        label = fit_label(f[0][0], f[0][1]);
        if (label == NULL) {
            (void)fit_bad_line(r, "out of memory");
            return fit_stop(bad, k);
        }
        if (strchr(label, '"') != NULL) {
            /* (written as it is, it opened a quoted field in the output
             * CSV that swallowed the rows after it; helper-36, stop 59) */
            free(label);
            (void)fit_bad_line(r, "a curve label with a double quote (the output is CSV: use a label without one)");
            return fit_stop(bad, k);
        }
        /* a new curve */
        sn = fit_seen_add(seen, label);
        if (sn != 0) {
            char msg[200];
            (void)snprintf(msg, sizeof msg, "curve %.80s%s", label,
                           sn > 0 ? " appears again: the rows of a curve must be contiguous" : ": out of memory");
            free(label);
            (void)fit_bad_line(r, msg);
            return fit_stop(bad, k);
        }
        if (active) {
            k++;
            if (k == max) {
                pd->have = 1;
                pd->label = label;
                pd->z = z;
                pd->F = F;
                pd->line = r->line;
                return (long)k;
            }
        }
        free(ch[k].label);
        ch[k].label = label;
        active = 1;
        if (fit_push(&ch[k], z, F, r->line) != 0) {
            (void)fit_bad_line(r, fit_push_why(&ch[k]));
            return fit_stop(bad, k);
        }
    }
}

static void fit_map_row(const fit_curve *c, int f64)
{
    /* the columns of stop 39, then (stop 40, appended) E_err, w_err, F_slope */
    const char *fmt = f64 ? "%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,ok,%.17g,%.17g,%.17g\n"
                          : "%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,ok,%.9g,%.9g,%.9g\n";
    if (c->res.st == MDR_OK) {
        printf(fmt, c->label, c->res.E, c->res.w, c->res.z0, c->res.F_base, c->res.mu, c->res.rms, c->res.E_err,
               c->res.w_err, c->res.F_slope);
    } else {
        printf("%s,,,,,,,%s,,,\n", c->label, fit_status_name(c->res.st));
    }
}

/* seconds on a monotonic clock */
static double fit_now(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) {
        return 0.0;
    }
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void fit_progress(long done_bytes, long total, unsigned long curves, double t0)
{
    char bar[41];
    double f = total > 0 ? (double)done_bytes / (double)total : 0.0;
    double dt = fit_now() - t0;
    int i, k = (int)(f * 40.0);
    for (i = 0; i < 40; i++) {
        bar[i] = i < k ? '=' : ' ';
    }
    bar[40] = '\0';
    fprintf(stderr, "\rmdr fit: [%s] %3d%%  %lu curves  %.0f curves/s ", bar, (int)(f * 100.0), curves,
            dt > 0 ? (double)curves / dt : 0.0);
}

static int fit_map_cmd(const struct fit_args *A)
{
    fit_reader r = {NULL, NULL, NULL, 0, 0, DBL_MAX, 0};
    fit_seen seen = {NULL, 0, 0};
    fit_pending pd = {0, 0, NULL, 0.0, 0.0, 0};
    fit_pool P;
    pthread_t *th;
    fit_curve *buf[2];
    size_t chunk = (size_t)32 * (size_t)A->jobs, i;
    long n[2], total = 0;
    int cur = 0, rc = 0, tty = isatty(STDERR_FILENO), nth = 0, failed = 0, bad = 0;
    unsigned long curves = 0, order_n = 0;
    long order_line = 0;
    int order_first = 0;
    char order_label[128] = "";
    double t0 = fit_now();
    r.name = A->file;
    r.vmax = A->f64 ? DBL_MAX : (double)FLT_MAX;
    r.fp = fopen(A->file, "rb");
    if (r.fp == NULL) {
        return usage_sys("cannot open", A->file);
    }
    if (tty && fseek(r.fp, 0, SEEK_END) == 0) {
        total = ftell(r.fp);
        if (fseek(r.fp, 0, SEEK_SET) != 0) {
            (void)fclose(r.fp);
            return usage_error("cannot seek in", A->file);
        }
    }
    buf[0] = calloc(chunk, sizeof *buf[0]);
    buf[1] = calloc(chunk, sizeof *buf[1]);
    th = calloc((size_t)A->jobs, sizeof *th);
    if (buf[0] == NULL || buf[1] == NULL || th == NULL) {
        free(buf[0]);
        free(buf[1]);
        free(th);
        (void)fclose(r.fp);
        return usage_error("out of memory", NULL);
    }
    memset(&P, 0, sizeof P);
    (void)pthread_mutex_init(&P.mu, NULL);
    (void)pthread_cond_init(&P.go, NULL);
    (void)pthread_cond_init(&P.done, NULL);
    P.A = A;
    for (nth = 0; nth < A->jobs; nth++) {
        if (pthread_create(&th[nth], NULL, fit_worker, &P) != 0) {
            break;
        }
    }
    if (nth == 0) {
        rc = usage_error("cannot start a thread", NULL);
    }
    n[0] = rc == 0 ? fit_read_chunk(&r, &seen, &pd, buf[0], chunk, &bad) : 0;
    while (rc == 0 && n[cur] > 0) {
        fit_pool_submit(&P, buf[cur], (size_t)n[cur]);
        /* read the next chunk while the workers fit this one (none after
         * a bad row: the curves before it are written, then exit 2) */
        n[1 - cur] = bad ? 0 : fit_read_chunk(&r, &seen, &pd, buf[1 - cur], chunk, &bad);
        fit_pool_wait(&P);
        if (curves == 0) {
            /* the header with the first rows: a map refused before any
             * curve is read whole (a bad first row, no rows) leaves stdout
             * empty (the header, then exit 2 before; an attack after
             * stop 59) */
            printf("curve,E,w,z0,F_base,mu,rms,status,E_err,w_err,F_slope\n");
        }
        for (i = 0; i < (size_t)n[cur]; i++) {
            const fit_curve *c = &buf[cur][i];
            fit_map_row(c, A->f64);
            failed += c->res.st != MDR_OK;
            if (c->res.st == MDR_E_ORDER && order_n++ == 0 && c->n > 0) {
                /* the first such curve, named by its line below */
                order_line = fit_order_line(c);
                order_first = order_line == 0;
                order_line = order_line != 0 ? order_line : c->line[0];
                (void)snprintf(order_label, sizeof order_label, "%s", c->label);
            }
        }
        curves += (unsigned long)n[cur];
        if (tty) {
            fit_progress(ftell(r.fp), total, curves, t0);
        }
        cur = 1 - cur;
    }
    rc = bad ? 2 : rc;
    if (rc == 0 && ferror(r.fp)) {
        rc = usage_sys("read error in", A->file);
    }
    if (tty) {
        fputc('\n', stderr);
    }
    (void)pthread_mutex_lock(&P.mu);
    P.quit = 1;
    (void)pthread_cond_broadcast(&P.go);
    (void)pthread_mutex_unlock(&P.mu);
    for (i = 0; i < (size_t)nth; i++) {
        (void)pthread_join(th[i], NULL);
    }
    for (i = 0; i < chunk; i++) {
        fit_curve_free(&buf[0][i]);
        fit_curve_free(&buf[1][i]);
    }
    free(buf[0]);
    free(buf[1]);
    free(th);
    free(pd.label);
    free(r.buf);
    fit_seen_free(&seen);
    (void)fclose(r.fp); /* read only */
    (void)pthread_mutex_destroy(&P.mu);
    (void)pthread_cond_destroy(&P.go);
    (void)pthread_cond_destroy(&P.done);
    if (rc == 0 && curves == 0) {
        rc = usage_error("no curve,z,F rows in", A->file);
    }
    if (rc == 0 && order_n > 0) {
        /* MDR_E_ORDER named by its line, as --curve names it (the row's
         * status alone left the user searching the file): one line, the
         * first such curve */
        (void)usage_errf("%s:%ld: curve %s%s (MDR_E_ORDER; %lu curve%s of the map so)", A->file, order_line,
                         order_label,
                         order_first ? " (its first row): samples not in time order, z not monotonic within a branch "
                                       "or rising to the last sample"
                                     : ": z increases within the retract (the part after the largest z)",
                         order_n, order_n == 1 ? "" : "s");
    }
    return rc != 0 ? rc : failed > 0;
}

/* ---- arguments ----------------------------------------------------------- */

static int fit_checked(const struct fit_args *A, int have_k, int have_E0, int have_w0);

/* --profile table --file tip.csv: the samples read (r,f rows), their slopes
 * formed in double and both arithmetics' copies made and checked as the
 * contact takes them; 0, or 2 after the line naming the problem */
static int fit_tip_samples(struct fit_args *A)
{
    double *r = NULL, *fv = NULL, *sl = NULL;
    long *lines = NULL;
    long n = load_tip(A->tipfile, &r, &fv, &sl, &lines);
    int rc = 0;
    if (n < 0) {
        rc = 2; /* load_tip named the file and line */
    } else {
        mdr_contact_f64 c64;
        mdr_contact_f32 c32;
        A->tm = (uint16_t)n;
        A->tip_f64 = malloc(2 * (size_t)n * sizeof *A->tip_f64);
        A->tip_f32 = malloc(2 * (size_t)n * sizeof *A->tip_f32);
        if (A->tip_f64 == NULL || A->tip_f32 == NULL) {
            rc = usage_error("out of memory for", A->tipfile);
        } else {
            mdr_status st = mdr_host_tip_contact_f64(&c64, r, sl, A->tm, 1.0, 0.0, A->tip_f64);
            if (st == MDR_OK) {
                st = mdr_host_tip_contact_f32(&c32, r, sl, A->tm, 1.0f, 0.0f, A->tip_f32);
            }
            if (st != MDR_OK) {
                (void)cli_fail("profile", st);
                rc = 2;
            }
        }
    }
    free(r);
    free(fv);
    free(sl);
    free(lines);
    A->kind = MDR_PROFILE_TABLE;
    A->pi = -1;
    return rc;
}

/* the flags of mdr fit (numbers: its own and every profile parameter) */
static int fit_flag(const char *f)
{
    static const char *const own[] = {"--k-machine", "--z-e", "--E0", "--w0", "--jobs"};
    int k, i;
    for (k = 0; k < (int)(sizeof own / sizeof own[0]); k++) {
        if (strcmp(f, own[k]) == 0) {
            return 1;
        }
    }
    for (k = 0; k < (int)(sizeof profiles / sizeof profiles[0]); k++) {
        for (i = 0; i < 3 && profiles[k].flags[i] != NULL; i++) {
            if (strcmp(f, profiles[k].flags[i]) == 0) {
                return 1;
            }
        }
    }
    return 0;
}

static int fit_main(int argc, char **argv)
{
    static const char *const fit_bools[] = {"--approach", "--unpinned", "--flat-baseline", NULL};
    struct cli_kv kv[CLI_MAX_FLAGS];
    int nkv;
    struct fit_args A;
    const char *profile = NULL, *pname[3];
    double pval[3];
    int i, k, np = 0, have_k = 0, have_E0 = 0, have_w0 = 0, have_jobs = 0, pi = -1, used[3] = {0, 0, 0};
    long ncpu;
    memset(&A, 0, sizeof A);
    A.f64 = 1;
    A.method = MDR_FIT_FULL;
    A.z_e = MDR_FIT_Z_E_DEFAULT;
    ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    A.jobs = ncpu > 0 && ncpu < 1024 ? (int)ncpu : 1;
    i = cli_collect(argc, argv, 2, fit_bools, kv, &nkv);
    if (i == 3) {
        fputs(usage_cmd[CMD_FIT], stdout);
        return 0;
    }
    if (i != 0) {
        return i;
    }
    for (i = 0; i < nkv; i++) {
        const char *f = kv[i].name, *v = kv[i].val;
        double x = 0.0;
        if (strcmp(f, "--approach") == 0) {
            A.approach = 1;
        } else if (strcmp(f, "--unpinned") == 0) {
            A.unpinned = 1;
        } else if (strcmp(f, "--flat-baseline") == 0) {
            A.flat = 1;
        } else if (strcmp(f, "--curve") == 0 || strcmp(f, "--map") == 0) {
            if (A.file != NULL) {
                return usage_error("give one of --curve FILE or --map FILE", NULL);
            }
            A.file = v;
            A.map = f[2] == 'm';
        } else if (strcmp(f, "--profile") == 0) {
            profile = v;
        } else if (strcmp(f, "--file") == 0) {
            A.tipfile = v;
        } else if (strcmp(f, "--model") == 0) {
            A.model = v;
        } else if (strcmp(f, "--arith") == 0) {
            if (strcmp(v, "f32") != 0 && strcmp(v, "f64") != 0) {
                return usage_error("--arith takes f32 or f64", v);
            }
            A.f64 = strcmp(v, "f64") == 0;
        } else if (strcmp(f, "--method") == 0) {
            if (strcmp(v, "full") == 0) {
                A.method = MDR_FIT_FULL;
            } else if (strcmp(v, "two-point") == 0) {
                A.method = MDR_FIT_TWO_POINT;
            } else {
                return usage_error("--method takes full or two-point", v);
            }
        } else if (!fit_flag(f)) {
            int of_profile;
            if (flag_known(f, CMD_EQ, &of_profile) == 0) {
                return usage_error("unknown flag", f);
            }
            return usage_errf("%s: not a flag of mdr fit (mdr fit --help)", f);
        } else if (!parse_num(v, &x)) {
            return usage_errf("%s: %s: %s", f, num_problem(v), v);
        } else if (is_subnormal(x)) {
            return usage_errf("%s: %s: %s", f, SUBNORMAL_WHY, v);
        } else if (strcmp(f, "--k-machine") == 0) {
            A.k_m = x;
            have_k = 1;
        } else if (strcmp(f, "--z-e") == 0) {
            A.z_e = x;
        } else if (strcmp(f, "--E0") == 0) {
            A.E0 = x;
            have_E0 = 1;
        } else if (strcmp(f, "--w0") == 0) {
            A.w0 = x;
            have_w0 = 1;
        } else if (strcmp(f, "--jobs") == 0) {
            long j;
            if (!parse_count(x, 1, 1024, &j)) {
                return usage_error("--jobs must be an integer in [1, 1024]", v);
            }
            A.jobs = (int)j;
            have_jobs = 1;
        } else if (np < 3) {
            pname[np] = f; /* a profile parameter, checked below */
            pval[np++] = x;
        } else {
            return usage_error("unknown or misplaced flag", f);
        }
    }
    if (!A.f64) {
        for (k = 0; k < np; k++) {
            if (outside_f32(pval[k])) {
                return usage_errf("%s %.9g: outside the range of --arith f32", pname[k], pval[k]);
            }
        }
        /* the machine's and the start's numbers as parsed (z_e: its
         * default, within float, where not given) */
        const char *const xname[4] = {"--k-machine", "--z-e", "--E0", "--w0"};
        const double xval[4] = {A.k_m, A.z_e, A.E0, A.w0};
        for (k = 0; k < 4; k++) {
            if (outside_f32(xval[k])) {
                return usage_errf("%s %.9g: outside the range of --arith f32", xname[k], xval[k]);
            }
        }
    }
    if (A.file == NULL) {
        return usage_error("fit needs --curve FILE or --map FILE", NULL);
    }
    if (A.map && A.model != NULL) {
        return usage_error("--model goes with --curve", NULL);
    }
    if (!A.map && have_jobs) {
        /* (a flag the command does not use is refused: helper-56) */
        return usage_error("--jobs goes with --map", NULL);
    }
    if (profile == NULL) {
        return usage_error("missing --profile", NULL);
    }
    if (strcmp(profile, "table") == 0) {
        int rc;
        if (A.tipfile == NULL) {
            return usage_error("--profile table needs --file tip.csv", NULL);
        }
        if (np > 0) {
            return usage_errf("%s: not a parameter of --profile table", pname[0]);
        }
        A.have_E0 = have_E0;
        rc = fit_tip_samples(&A);
        if (rc == 0) {
            rc = fit_checked(&A, have_k, have_E0, have_w0);
        }
        free(A.tip_f32);
        free(A.tip_f64);
        return rc;
    }
    if (A.tipfile != NULL) {
        return usage_error("--file goes with --profile table", NULL);
    }
    for (k = 0; k < (int)(sizeof profiles / sizeof profiles[0]); k++) {
        if (strcmp(profiles[k].name, profile) == 0) {
            pi = k;
        }
    }
    if (pi < 0) {
        return usage_error("unknown profile", profile);
    }
    if (profiles[pi].kind == MDR_PROFILE_FLATPUNCH) {
        return usage_error("the flat punch cannot be fitted (pinned at its rim until it ruptures)", NULL);
    }
    A.kind = profiles[pi].kind;
    A.pi = pi;
    A.have_E0 = have_E0;
    {
        const char *missing = profile_params(pi, pname, pval, np, used, A.p);
        if (missing != NULL) {
            return usage_error("missing profile parameter", missing);
        }
    }
    for (k = 0; k < np; k++) {
        if (!used[k]) {
            return usage_error("unknown or misplaced flag", pname[k]);
        }
    }
    return fit_checked(&A, have_k, have_E0, have_w0);
}

/* The checks after the profile, and the command */
static int fit_checked(const struct fit_args *A, int have_k, int have_E0, int have_w0)
{
    if (!have_k || !(A->k_m > 0.0) || A->k_m - A->k_m != 0.0) {
        return usage_error("fit needs --k-machine K > 0 (N/m)", NULL);
    }
    if (!(A->z_e > 0.0) || A->z_e - A->z_e != 0.0) {
        return usage_error("--z-e must be > 0 (m)", NULL);
    }
    if (have_E0 != have_w0 || (have_E0 && !(A->E0 > 0.0 && A->w0 > 0.0))) {
        return usage_error("--E0 and --w0 go together, both > 0", NULL);
    }
    {
        mdr_contact_f64 t64;
        mdr_contact_f32 t32;
        mdr_status st = fit_tip_f64(A, &t64);
        if (st == MDR_OK && !A->f64) {
            st = fit_tip_f32(A, &t32);
        }
        if (st != MDR_OK) {
            (void)cli_fail("profile", st);
            return 2;
        }
    }
    return A->map ? fit_map_cmd(A) : fit_curve_cmd(A);
}
