/* SPDX-License-Identifier: MIT */
/*
 * mdr: command-line front end of libmdr (host only; uses stdio).
 * `mdr --help` and `mdr CMD --help` print the usage (the texts below).
 *
 * Results on stdout, errors on stderr (one line naming the problem). Exit
 * status: 0 ok, 1 a computation that fails (iteration cap, the edge beyond
 * the table), 2 bad arguments or input files. Every flag is --flag VALUE or
 * --flag=VALUE, given once; a flag the command does not use is refused.
 * Every JSON object carries "input" (the inputs it was computed from) and
 * "units" (the SI unit of each quantity key).
 */
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mdr.h"
#include "mdr_host.h"
#include "tip_csv.h"

enum { CMD_EQ, CMD_CRITICAL, CMD_CURVE, CMD_STRESS, CMD_CYCLE, CMD_TABLE, CMD_FIT, NCMD };

static const char *const cmd_names[NCMD] = {"eq", "critical", "curve", "stress", "cycle", "table", "fit"};

/* --profile table */
#define KIND_TABLE MDR_PROFILE_TABLE

/* the bounds of a tip file (--file): the points the table takes, the bytes
 * of as many lines of TIP_CSV_LINE_MAX characters */
#define TIP_POINTS_MAX 65535L
#define TIP_BYTES_MAX ((size_t)TIP_POINTS_MAX * TIP_CSV_LINE_MAX)

struct cli_args {
    int cmd;
    uint8_t kind, control;
    double p[3], E, w, a, r, a_max, a_start, k_m, w_adv, d;
    long n, springs, steps;
    int f64, q31, have_control, have_a_start, have_amax, have_d, have_k, have_w_adv, pi;
    double *path; /* --path values */
    long npath;
    double *tr, *tf, *ts; /* --file samples, and their slopes (double) */
    long *tline;          /* the file line of each sample */
    long ntab;
    const char *name, *file, *summary, *header, *output;
};

/* one line on stderr, "mdr: " and the formatted message; returns 2. A
 * value given with a line break in it (--E $'1e9\n') is echoed with the
 * break written as \n, so that the message stays one line. */
static int usage_errf(const char *fmt, ...)
{
    char buf[4096];
    const char *c;
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    fputs("mdr: ", stderr);
    for (c = buf; *c; c++) {
        const unsigned char ch = (unsigned char)*c;
        if (ch == '\n' || ch == '\r') {
            fputs(ch == '\n' ? "\\n" : "\\r", stderr);
        } else if (ch < 0x20 && ch != '\t') {
            fprintf(stderr, "\\x%02x", ch);
        } else {
            fputc(ch, stderr);
        }
    }
    fputc('\n', stderr);
    return 2;
}

static int usage_error(const char *msg, const char *what)
{
    return usage_errf("%s%s%s", msg, what ? ": " : "", what ? what : "");
}

/* A file that could not be opened, read or written: the line gives the
 * system's reason (errno, read right after the failing call; a bare
 * "cannot open" left a user guessing, helper-22 at stop 54); returns 2 */
static int usage_sys(const char *msg, const char *what)
{
    const int e = errno;
    if (e == 0) {
        return usage_error(msg, what);
    }
    return usage_errf("%s: %s (%s)", msg, what, strerror(e));
}

/* a status's name (lib/include/mdr_types.h), as the Python package's
 * exceptions give it: the line names the status as well as its number.
 * Each entry is placed by its code and named by its own macro (CLI_ST), so
 * neither the order nor a name can be wrong; test_cli.sh checks that every
 * MDR_E_* of the header has one. */
#define CLI_ST(s) [-(s)] = #s
static const char *cli_stname(mdr_status st)
{
    static const char *const names[] = {
        CLI_ST(MDR_OK),          CLI_ST(MDR_E_NULL),      CLI_ST(MDR_E_NONFINITE), CLI_ST(MDR_E_PARAM),
        CLI_ST(MDR_E_KIND),      CLI_ST(MDR_E_RADIUS),    CLI_ST(MDR_E_POSITION),  CLI_ST(MDR_E_CONTROL),
        CLI_ST(MDR_E_NOCONV),    CLI_ST(MDR_E_SINGULAR),  CLI_ST(MDR_E_OVERFLOW),  CLI_ST(MDR_E_OUTSIDE),
        CLI_ST(MDR_E_TABLE),     CLI_ST(MDR_E_SIZE),      CLI_ST(MDR_E_DISABLED),  CLI_ST(MDR_E_FEW),
        CLI_ST(MDR_E_ORDER),     CLI_ST(MDR_E_NOCONTACT), CLI_ST(MDR_E_NOPULLOFF), CLI_ST(MDR_E_FITCAP),
        CLI_ST(MDR_E_DEGENERATE), CLI_ST(MDR_E_JUMPS),    CLI_ST(MDR_E_PINNED),    CLI_ST(MDR_E_MISFIT)};
    const int i = -(int)st;
    return i >= 0 && i < (int)(sizeof names / sizeof names[0]) && names[i] != NULL ? names[i] : "unknown status";
}
#undef CLI_ST

static int cli_fail(const char *what, mdr_status st)
{
    /* (through usage_errf: a tip file named with a line break stays one line) */
    (void)usage_errf("%s: %s (%s, status %d)", what, mdr_status_str(st), cli_stname(st), (int)st);
    return st == MDR_E_NOCONV ? 1 : 2;
}

static int is_finite(double v)
{
    return v - v == 0.0; /* NaN - NaN and inf - inf are NaN */
}

/* a whole string as a finite number (strtod: decimal or hex; not nan, inf,
 * nor a nonzero number below double's normal range: tip_csv_strtod), with
 * no white space around it (strtod skipped a leading one, a trailing one
 * was "not a finite number": --E ' 1e9' ran, --E '1e9 ' was refused) */
static int parse_num(const char *s, double *v)
{
    char *end;
    if (s == NULL || *s == '\0' || isspace((unsigned char)*s)) {
        return 0;
    }
    *v = tip_csv_strtod(s, &end);
    return *end == '\0' && is_finite(*v);
}

/* why a number did not parse (parse_num, parse_list's value s): a nonzero
 * number below double's range (tip_csv_strtod), or not a finite number */
static const char *num_problem(const char *s)
{
    char *end;
    const int e0 = errno;
    const size_t len = strcspn(s, ",");
    double v;
    if (len > 0 && (isspace((unsigned char)s[0]) || isspace((unsigned char)s[len - 1]))) {
        return "white space around the number (give the number alone)";
    }
    errno = 0;
    v = strtod(s, &end);
    const int under = end != s && errno == ERANGE && v == 0.0;
    errno = e0;
    return under ? "a nonzero number below double's range (it underflows to 0)" : "not a finite number";
}

/* A subnormal double (nonzero, below DBL_MIN): it holds fewer than 17
 * digits (1e-310 is read as 9.9999999999999694e-311) and, as a physical
 * input, takes the library outside the range it computes in (--E 1e-310
 * made w/E* overflow and the line blamed --w; --w and --a 1e-310 ran with
 * exit 0 on numbers that had lost digits). Refused for every value given
 * in any arithmetic (f32 refuses more: outside_f32). */
static int is_subnormal(double v)
{
    const double m = v < 0 ? -v : v;
    return m != 0.0 && m < DBL_MIN;
}
#define SUBNORMAL_WHY "a subnormal number (nonzero, below double's normal range 2.2250738585072014e-308: it loses digits); give 0 or a value of larger magnitude"

/* "V1,V2,..." -> malloc'd array of finite numbers: the count, 0 out of
 * memory, or -(1 + i) when value i (from 0) is not a finite number */
static long parse_list(const char *s, double **out)
{
    long n = 1, i = 0;
    const char *c;
    double *v;
    for (c = s; *c; c++) {
        n += *c == ',';
    }
    v = malloc((size_t)n * sizeof *v);
    if (v == NULL) {
        return 0;
    }
    while (i < n) {
        char *end;
        v[i] = tip_csv_strtod(s, &end);
        if (end == s || (*end != ',' && *end != '\0') || !is_finite(v[i]) || isspace((unsigned char)*s)) {
            free(v);
            return -(1 + i);
        }
        i++;
        s = end + 1;
    }
    *out = v;
    return n;
}

/* A tip file (examples/tip_csv.h) -> malloc'd r, f and the file line of
 * each pair, at most TIP_POINTS_MAX pairs and TIP_BYTES_MAX bytes (a device
 * that never ends, /dev/zero, is refused at its first NUL byte). Returns the
 * count, or 2 after one line on stderr naming file:line. */
static long read_table(const char *file, double **r, double **f, long **lines)
{
    FILE *fp = fopen(file, "rb");
    char *text = NULL;
    size_t len = 0, cap = 0, got;
    long n = -4, line = 0; /* -4: out of memory */
    *r = *f = NULL;
    *lines = NULL;
    if (fp == NULL) {
        return -usage_sys("cannot open", file);
    }
    do {
        const char *nul;
        if (len == cap) {
            char *t = cap >= TIP_BYTES_MAX ? NULL : realloc(text, cap = cap ? 2 * cap : 65536);
            if (t == NULL) {
                (void)fclose(fp);
                free(text);
                if (cap > TIP_BYTES_MAX) {
                    return -usage_errf("%s: larger than %lu bytes (%ld lines of %d characters)", file,
                                       (unsigned long)TIP_BYTES_MAX, TIP_POINTS_MAX, TIP_CSV_LINE_MAX - 1);
                }
                return -usage_error("out of memory reading", file);
            }
            text = t;
        }
        got = fread(text + len, 1, cap - len, fp);
        nul = memchr(text + len, '\0', got);
        len += got;
        if (nul != NULL) {
            (void)fclose(fp);
            line = (long)tip_csv_lines(text, (size_t)(nul - text) + 1);
            free(text);
            return -usage_errf("%s:%ld: a NUL byte (not a text file)", file, line);
        }
    } while (got > 0);
    if (ferror(fp)) {
        (void)fclose(fp);
        free(text);
        return -usage_sys("read error in", file);
    }
    (void)fclose(fp); /* read only: nothing to lose */
    {
        size_t m = tip_csv_lines(text, len);
        m = m > (size_t)TIP_POINTS_MAX ? (size_t)TIP_POINTS_MAX : m < 1 ? 1 : m;
        *r = malloc(m * sizeof **r);
        *f = malloc(m * sizeof **f);
        *lines = malloc(m * sizeof **lines);
        if (*r != NULL && *f != NULL && *lines != NULL) {
            n = tip_csv_parse_at(text, len, *r, *f, m, *lines, &line);
        }
        free(text);
        if (n < 0) {
            free(*r);
            free(*f);
            free(*lines);
            *r = *f = NULL;
            *lines = NULL;
            if (n == -1) {
                return -usage_errf("%s:%ld: %s", file, line,
                                   "expected two numbers r f (separated by a comma, tabs or spaces), "
                                   "a comment (#) or a header");
            }
            if (n == -2) {
                return -usage_errf("%s:%ld: more than %ld points", file, line, TIP_POINTS_MAX);
            }
            if (n == -3) {
                return -usage_errf("%s:%ld: line longer than %d characters", file, line, TIP_CSV_LINE_MAX - 1);
            }
            return -usage_error("out of memory reading", file);
        }
    }
    return n;
}

/* A tip file (r,f rows) read, checked and differenced: the radii, heights,
 * interval slopes formed in double (tip_slopes) and each row's line, all
 * malloc'd (the caller frees them, also on failure); the count, or -1 after
 * the line naming the file, line and problem. */
static long load_tip(const char *file, double **r, double **f, double **s, long **lines)
{
    long k, n = read_table(file, r, f, lines);
    *s = NULL;
    if (n < 0 || *r == NULL || *f == NULL || *lines == NULL) {
        return -1; /* named by read_table() */
    }
    if (n < MDR_TABLE_MIN_POINTS) { /* (the library's MDR_E_TABLE named no count: helper-24) */
        (void)usage_errf("%s: %ld points; a tip needs at least %d rows r,f (r from 0)", file, n,
                         MDR_TABLE_MIN_POINTS);
        return -1;
    }
    *s = malloc((size_t)(n - 1) * sizeof **s); /* (n >= 3: above) */
    if (*s == NULL) {
        (void)usage_error("out of memory reading", file);
        return -1;
    }
    for (k = 0; k < n; k++) {
        if (!is_finite((*r)[k]) || !is_finite((*f)[k])) {
            (void)usage_errf("%s:%ld: not a finite number", file, (*lines)[k]);
            return -1;
        }
        if (is_subnormal((*r)[k]) || is_subnormal((*f)[k])) {
            (void)usage_errf("%s:%ld: %s", file, (*lines)[k], SUBNORMAL_WHY);
            return -1;
        }
    }
    if ((*r)[0] != 0.0) { /* (the library's MDR_E_TABLE named neither line nor rule: helper-66, stop 71) */
        (void)usage_errf("%s:%ld: the first radius must be 0 (r = %.17g): a tip's samples start on its axis", file,
                         (*lines)[0], (*r)[0]);
        return -1;
    }
    switch (tip_slopes(*r, *f, n, *s, &k)) {
    case -1:
        (void)usage_errf("%s:%ld: r must increase strictly (r = %.17g after %.17g)", file, (*lines)[k], (*r)[k],
                         (*r)[k - 1]);
        return -1;
    case -2: /* (taken with exit 0: an attack after stop 59) */
        (void)usage_errf("%s:%ld: f must not decrease with r (f = %.17g after %.17g): the gap of a tip "
                         "grows with the radius", file, (*lines)[k], (*f)[k], (*f)[k - 1]);
        return -1;
    default:
        return n;
    }
}

/* profile name -> kind and the flags of its parameters */
static const struct {
    const char *name;
    uint8_t kind;
    const char *flags[3];
    const char *range; /* what mdr_contact_init takes (named in its refusal: helper-66, stop 71) */
} profiles[] = {
    {"paraboloid", MDR_PROFILE_PARABOLOID, {"--R", NULL, NULL}, "R > 0"},
    {"cone", MDR_PROFILE_CONE, {"--theta", NULL, NULL}, "0 < theta < pi/2 rad"},
    {"powerlaw", MDR_PROFILE_POWERLAW, {"--C", "--n", NULL}, "C > 0, 0 < n <= 8"},
    {"flatpunch", MDR_PROFILE_FLATPUNCH, {"--a0", NULL, NULL}, "a0 > 0"},
    {"sphere", MDR_PROFILE_SPHERE, {"--R", NULL, NULL}, "R > 0"},
    {"flattip", MDR_PROFILE_FLATTIP, {"--R", "--b", NULL}, "R > 0, b >= 0"},
    {"wavy", MDR_PROFILE_WAVY, {"--R", "--h", "--lambda"}, "R > 0, h >= 0, lambda > 0"},
};
#if MDR_POWERLAW_N_MAX != 8
#error "profiles[]: the power law's range names n <= 8"
#endif

/* ---- JSON: the inputs and units every object carries -------------------- */

/* the SI unit of each quantity key (counts, flags and names have none) */
static const struct {
    const char *key, *unit;
} unit_of[] = {
    {"a", "m"}, {"d", "m"}, {"F", "N"}, {"z", "m"}, {"r", "m"}, {"dd_da", "1"}, {"dF_da", "N/m"},
    {"dl", "m"}, {"K_I", "Pa m^0.5"}, {"G_rel", "J/m^2"}, {"G", "J/m^2"}, {"d_eq", "m"}, {"F_eq", "N"},
    {"a_start", "m"}, {"max_tensile_F", "N"}, {"max_tensile_d", "m"}, {"sigma", "Pa"},
    {"r_over_a_c", "1"}, {"pull_off_F", "N"}, {"pull_off_d", "m"}, {"dissipated", "J"},
    {"a_max", "m"}, {"a0", "m"}, {"d0", "m"}, {"F0", "N"}, {"a1", "m"}, {"d1", "m"}, {"F1", "N"},
    {"R", "m"}, {"theta", "rad"}, {"C", "m^(1-n)"}, {"n", "1"}, {"b", "m"}, {"h", "m"},
    {"lambda", "m"}, {"E", "Pa"}, {"w", "J/m^2"}, {"w_adv", "J/m^2"}, {"k_m", "N/m"},
    {"E_err", "Pa"}, {"w_err", "J/m^2"}, {"w_adv_err", "J/m^2"}, {"z0", "m"}, {"z0_err", "m"},
    {"F_base", "N"}, {"F_base_err", "N"}, {"F_slope", "N/m"}, {"F_slope_err", "N/m"}, {"mu", "1"}, {"R_mu", "m"}, {"z_e", "m"}, {"rms", "N"},
    {"pull_off_z", "m"}, {"a_pull_off", "m"}, {"E0", "Pa"}, {"w0", "J/m^2"},
};

/* a JSON writer that remembers the keys it wrote, for the units object */
typedef struct {
    FILE *fp;
    const char *keys[52];
    int nk, first, f64; /* f64: 17 digits, else 9 (a float's round trip) */
} cli_json;

static void json_begin(cli_json *j, FILE *fp, int f64)
{
    j->fp = fp;
    j->nk = 0;
    j->first = 1;
    j->f64 = f64;
    fputc('{', fp);
}

/* remember a key (for the units object) without writing it */
static void json_key_only(cli_json *j, const char *key)
{
    int i;
    for (i = 0; i < j->nk; i++) {
        if (strcmp(j->keys[i], key) == 0) {
            return;
        }
    }
    if (j->nk < (int)(sizeof j->keys / sizeof j->keys[0])) {
        j->keys[j->nk++] = key;
    }
}

static void json_key(cli_json *j, const char *key)
{
    fprintf(j->fp, "%s\"%s\": ", j->first ? "" : ", ", key);
    j->first = 0;
    json_key_only(j, key);
}

static void json_num(cli_json *j, const char *key, double v)
{
    json_key(j, key);
    fprintf(j->fp, j->f64 ? "%.17g" : "%.9g", v);
}

/* a JSON string value (no key) */
static void json_strv(FILE *fp, const char *v)
{
    fputc('"', fp);
    for (; *v; v++) {
        unsigned char ch = (unsigned char)*v;
        if (ch == '"' || ch == '\\') {
            fprintf(fp, "\\%c", ch);
        } else if (ch < 0x20) {
            fprintf(fp, "\\u%04x", ch);
        } else {
            fputc(ch, fp);
        }
    }
    fputc('"', fp);
}

static void json_str(cli_json *j, const char *key, const char *v)
{
    json_key(j, key);
    json_strv(j->fp, v);
}

/* The warning of a table of spring width h [m] for profile A, written into
 * buf (empty: none): a wavy profile's springs per wavelength below
 * MDR_WAVY_SPRINGS_PER_WAVELENGTH, which `cycle` (the summary's
 * "warnings") and `table` report (helper-63, stop 70: 6.4 springs per
 * wavelength put an approach fold 8 % below the profile's, 0.9 reported 56
 * of 198 jumps and a pull-off 4 % off, exit 0 and silent). */
static void table_warning(const struct cli_args *A, double h, char *buf, size_t len)
{
    const double spw = A->kind == MDR_PROFILE_WAVY && h > 0 ? A->p[2] / h : MDR_WAVY_SPRINGS_PER_WAVELENGTH;
    buf[0] = '\0';
    if (spw < MDR_WAVY_SPRINGS_PER_WAVELENGTH) {
        (void)snprintf(buf, len,
                       "%.3g springs per wavelength (--lambda %.9g m, spring width %.9g m): below %d the waves "
                       "are not resolved; more --springs or a lower --a-max",
                       spw, A->p[2], h, MDR_WAVY_SPRINGS_PER_WAVELENGTH);
    }
}

static const char *control_name(uint8_t c)
{
    return c == MDR_CONTROL_LOAD ? "load" : c == MDR_CONTROL_GRIPS ? "grips" : "machine";
}

/* The "units" object of the keys written by j (the result) and in (its
 * input object; "path" in pu), and the end of the object. */
static void json_units(cli_json *j, const cli_json *in, const char *pu)
{
    json_key(j, "units");
    fputc('{', j->fp);
    {
        int first = 1, i, k;
        for (k = 0; k < j->nk + in->nk; k++) {
            const char *key = k < j->nk ? j->keys[k] : in->keys[k - j->nk];
            const char *u = NULL;
            if (strcmp(key, "path") == 0) {
                u = pu;
            }
            for (i = 0; u == NULL && i < (int)(sizeof unit_of / sizeof unit_of[0]); i++) {
                if (strcmp(unit_of[i].key, key) == 0) {
                    u = unit_of[i].unit;
                }
            }
            for (i = 0; u != NULL && i < k && i < j->nk; i++) {
                u = strcmp(j->keys[i], key) == 0 ? NULL : u; /* listed once */
            }
            if (u != NULL) {
                fprintf(j->fp, "%s\"%s\": \"%s\"", first ? "" : ", ", key, u);
                first = 0;
            }
        }
    }
    fputs("}}\n", j->fp);
}

/* The "input" object of a command's JSON (the values as given, in double)
 * and its "units" for those keys and the result's (j: the result object's
 * writer, whose keys are in it); ends the object. */
static void json_end(cli_json *j, const struct cli_args *A)
{
    cli_json in;
    const char *arith = A->q31 ? "q31" : A->f64 ? "f64" : "f32";
    json_key(j, "input");
    json_begin(&in, j->fp, 1);
    json_str(&in, "command", cmd_names[A->cmd]);
    if (A->kind == KIND_TABLE) {
        json_str(&in, "profile", "table");
        json_str(&in, "file", A->file);
        json_num(&in, "points", (double)A->ntab);
    } else {
        int k;
        json_str(&in, "profile", profiles[A->pi].name);
        for (k = 0; k < 3 && profiles[A->pi].flags[k] != NULL; k++) {
            json_num(&in, profiles[A->pi].flags[k] + 2, A->p[k]);
        }
    }
    if (A->cmd != CMD_TABLE) {
        json_num(&in, "E", A->E);
        json_num(&in, "w", A->w);
    }
    json_str(&in, "arith", arith);
    if (A->have_control) {
        json_str(&in, "control", control_name(A->control));
    }
    if (A->have_k || A->cmd == CMD_CYCLE) {
        json_num(&in, "k_m", A->k_m);
    }
    switch (A->cmd) {
    case CMD_EQ:
    case CMD_STRESS:
        if (!A->have_control) {
            json_num(&in, "a", A->a);
        }
        if (A->have_d) {
            json_num(&in, "d", A->d);
        }
        if (A->cmd == CMD_STRESS) {
            json_num(&in, A->have_control ? "r_over_a_c" : "r", A->r);
        }
        break;
    case CMD_CURVE:
        json_num(&in, "a_max", A->a_max);
        json_num(&in, "n", (double)A->n);
        break;
    case CMD_CYCLE:
        json_num(&in, "w_adv", A->w_adv);
        json_num(&in, "springs", (double)A->springs);
        if (A->have_amax) {
            json_num(&in, "a_max", A->a_max);
        }
        json_num(&in, "steps_per_segment", (double)A->steps);
        json_key(&in, "path");
        {
            long i;
            for (i = 0; i < A->npath; i++) {
                fprintf(j->fp, "%s%.17g", i ? ", " : "[", A->path[i]);
            }
        }
        fputc(']', j->fp);
        break;
    case CMD_TABLE:
        json_num(&in, "springs", (double)A->springs);
        if (A->have_amax) {
            json_num(&in, "a_max", A->a_max);
        }
        break;
    default:
        break;
    }
    if ((A->cmd == CMD_CRITICAL || A->cmd == CMD_STRESS) && A->have_a_start) {
        json_num(&in, "a_start", A->a_start);
    }
    fputc('}', j->fp);
    json_units(j, &in, A->control == MDR_CONTROL_LOAD ? "N" : "m");
}

/* mdr table's header declaring the table (--header FILE, or FILE.h next
 * to --output FILE.c): 0, or 2 after one line on stderr; inc (cap bytes)
 * gets the name the .c includes it by. */
static int write_table_header(const struct cli_args *A, const char *sfx, unsigned n, char *inc, size_t cap)
{
    char hpath[1024], guard[256];
    const char *base, *src = A->header != NULL ? A->header : A->output;
    size_t l = strlen(src), i;
    FILE *out;
    if (l >= sizeof hpath || l >= cap) {
        return usage_error("path too long", src);
    }
    memcpy(hpath, src, l + 1);
    if (A->header == NULL) {
        hpath[l - 1] = 'h'; /* FILE.c -> FILE.h */
    }
    base = strrchr(hpath, '/');
    base = base != NULL ? base + 1 : hpath;
    memcpy(inc, base, strlen(base) + 1);
    (void)snprintf(guard, sizeof guard, "MDR_TABLE_%s_H", A->name);
    for (i = 0; guard[i]; i++) {
        if (guard[i] >= 'a' && guard[i] <= 'z') {
            guard[i] = (char)(guard[i] - ('a' - 'A'));
        }
    }
    out = fopen(hpath, "w");
    if (out == NULL) {
        return usage_sys("cannot write", hpath);
    }
    fprintf(out,
            "/* spring table generated by `mdr table` (libmdr %d.%d): the declaration of\n"
            " * %s (%u springs, %s); its definition is in the generated .c. */\n"
            "#ifndef %s\n#define %s\n\n#include \"mdr.h\"\n\n"
            "/** springs of %s */\n#define %.*s_SPRINGS %uu\n\n"
            "extern const mdr_table_%s %s;\n\n#endif /* %s */\n",
            MDR_VERSION_MAJOR, MDR_VERSION_MINOR, A->name, n, sfx, guard, guard, A->name,
            (int)strlen(guard) - 2, guard, n, sfx, A->name, guard);
    if (fclose(out) != 0) {
        return usage_sys("cannot write", hpath);
    }
    return 0;
}

#define CLI_T float
#define CLI_F64 0
#define CLI_SFX(name) name##_f32
#define CLI_NAME "f32"
#define CLI_LIT "f"
#define CLI_FMT "%.9g"
#define CLI_EFMT "%.8e"
#define HOST_T CLI_T
#define HOST_SFX CLI_SFX
#include "mdr_host_t.h"
#include "mdr_cli_t.h"
#undef CLI_T
#undef CLI_F64
#undef CLI_SFX
#undef CLI_FMT
#undef CLI_EFMT
#undef CLI_NAME
#undef CLI_LIT
#define CLI_T double
#define CLI_F64 1
#define CLI_SFX(name) name##_f64
#define CLI_NAME "f64"
#define CLI_LIT ""
#define CLI_FMT "%.17g"
#define CLI_EFMT "%.16e"
#include "mdr_host_t.h"
#include "mdr_cli_t.h"

/* The parameters of profile pi (profiles[pi].flags, in order) from the n
 * flags given (names, vals) into p[]; used[i] set for each flag taken.
 * Returns NULL, or the name of a parameter not given. */
static const char *profile_params(int pi, const char *const *names, const double *vals, int n,
                                  int *used, double p[3])
{
    int k, i;
    for (k = 0; k < 3 && profiles[pi].flags[k] != NULL; k++) {
        int found = 0;
        for (i = 0; i < n; i++) {
            if (strcmp(names[i], profiles[pi].flags[k]) == 0) {
                p[k] = vals[i];
                used[i] = found = 1;
            }
        }
        if (!found) {
            return profiles[pi].flags[k];
        }
    }
    return NULL;
}

static int parse_count(double v, long lo, long hi, long *out)
{
    if (!(v >= (double)lo && v <= (double)hi) || v != (double)(long)v) {
        return 0;
    }
    *out = (long)v;
    return 1;
}

/* ---- the command line: flags, help -------------------------------------- */

#define CLI_MAX_FLAGS 40

/* one flag and its value (NULL for a flag that takes none) */
struct cli_kv {
    char name[40];
    const char *val;
};

/* argv[first..] -> flag/value pairs: "--flag VALUE" or "--flag=VALUE"; the
 * flags listed in bools take no value. Returns 0, 3 when --help or -h is
 * among them, or 2 after one line on stderr (not a flag, a missing value, a
 * flag given twice, too many flags). */
static int cli_collect(int argc, char **argv, int first, const char *const *bools, struct cli_kv *kv,
                       int *n)
{
    int i, k;
    *n = 0;
    for (i = first; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            return 3;
        }
    }
    for (i = first; i < argc; i++) {
        const char *f = argv[i], *eq = strchr(f, '=');
        size_t len = eq != NULL ? (size_t)(eq - f) : strlen(f);
        int is_bool = 0;
        if (strncmp(f, "--", 2) != 0 || len <= 2) {
            return usage_error("expected a flag --NAME, found", f);
        }
        if (len >= sizeof kv[0].name) {
            return usage_errf("unknown flag: %.*s", (int)len, f);
        }
        if (*n == CLI_MAX_FLAGS) {
            return usage_error("too many flags", f);
        }
        memcpy(kv[*n].name, f, len);
        kv[*n].name[len] = '\0';
        for (k = 0; bools != NULL && bools[k] != NULL; k++) {
            is_bool |= strcmp(kv[*n].name, bools[k]) == 0;
        }
        for (k = 0; k < *n; k++) {
            if (strcmp(kv[k].name, kv[*n].name) == 0) {
                return usage_error("flag given twice", kv[*n].name);
            }
        }
        if (is_bool) {
            if (eq != NULL) {
                return usage_error("flag takes no value", kv[*n].name);
            }
            kv[*n].val = NULL;
        } else if (eq != NULL) {
            kv[*n].val = eq + 1;
        } else if (i + 1 < argc && strncmp(argv[i + 1], "--", 2) == 0 && argv[i + 1][2] != '\0') {
            /* (--a --d 0: --a's value missing, not "0" a stray word; a value
             * that starts with -- goes as --a=VALUE) */
            return usage_errf("flag needs a value: %s (found the flag %s)", kv[*n].name, argv[i + 1]);
        } else if (i + 1 < argc) {
            kv[*n].val = argv[++i];
        } else {
            return usage_error("flag needs a value", kv[*n].name);
        }
        (*n)++;
    }
    return 0;
}

static const char usage_main[] =
    "usage: mdr COMMAND <profile> <material> [flags]     (mdr COMMAND --help for one)\n"
    "\n"
    "  eq        the equilibrium state at contact radius --a (or the state (a, d))\n"
    "  critical  the critical (pull-off) state under --control load|grips|machine\n"
    "  curve     the equilibrium curve a,d,F (CSV) up to --a-max\n"
    "  stress    the normal stress sigma(r) in the contact\n"
    "  cycle     the real-time spring engine along a path (CSV + JSON summary)\n"
    "  table     the spring table as C source (for flash), and its header\n"
    "  fit       E*, w of a measured force curve (or a map of curves)\n"
    "  help      this text (mdr help COMMAND: the command's)\n"
    "\n"
    "  <profile>:  --profile paraboloid --R R | cone --theta RAD | powerlaw --C C --n N |\n"
    "              flatpunch --a0 A0 | sphere --R R | flattip --R R --b B |\n"
    "              wavy --R R --h H --lambda L | table --file FILE\n"
    "              (cone: theta is the flank's angle to the sample surface, f = tan(theta) r,\n"
    "              pi/2 minus a tip's half-angle)\n"
    "  <material>: --E ESTAR [Pa, effective modulus] --w W [J/m^2, work of adhesion]\n"
    "  --arith f32|f64 (default f32, fit f64; cycle and table also q31)\n"
    "\n"
    "Every flag is --flag VALUE or --flag=VALUE, given once; SI units (m, N, Pa, J/m^2).\n"
    "Results on stdout, errors on stderr (one line). Exit status: 0 ok, 1 a computation\n"
    "that fails (iteration cap, edge beyond the table, q31 results saturated, results\n"
    "that cannot be written), 2 bad arguments or input, including input the library\n"
    "refuses by name (in f32 a state beyond float's range: MDR_E_OVERFLOW, take f64).\n"
    "In f32, eq, curve, stress and critical refuse (exit 2) a state that the rounding\n"
    "of its inputs to float moves, or that f32's answer misses, by more than f32's goal\n"
    "against f64: take --arith f64.\n"
    "mdr --version: the library's version.\n";

static const char *const usage_cmd[NCMD] = {
    /* eq */
    "usage: mdr eq <profile> <material> --a A [--d D] [--arith f32|f64]\n"
    "  the equilibrium state at contact radius A [m]: JSON a, d, F, dd_da, dF_da, dl,\n"
    "  K_I [Pa m^0.5], G_rel [J/m^2] (energy release rate K_I^2/(2E*); \"G\" is its old\n"
    "  name, kept), stable_load, stable_grips. With --d D [m]: the state (A, D) as\n"
    "  given, pinned or not (F, K_I, G_rel of that state; d_eq, F_eq the equilibrium's).\n",
    /* critical */
    "usage: mdr critical <profile> <material> --control load|grips|machine\n"
    "                    [--k-machine K] [--a-start A] [--arith f32|f64]\n"
    "  the critical state (the pull-off): JSON a, d, F, jumps, a_start, max_tensile_F,\n"
    "  max_tensile_d (the most tensile force of the quasi-static path to the pull-off).\n"
    "  --k-machine K [N/m]: the machine stiffness, with --control machine only.\n",
    /* curve */
    "usage: mdr curve <profile> <material> --a-max A --n N [--arith f32|f64]\n"
    "  CSV a,d,F of N equilibrium states at a = A i/N, i = 1..N. With --profile\n"
    "  powerlaw (whose exponent is --n) give the count as --points N.\n",
    /* stress */
    "usage: mdr stress <profile> <material> --a A [--d D] --r R [--arith f32|f64]\n"
    "       mdr stress <profile> <material> --control MODE [--k-machine K] [--a-start A] --r S\n"
    "  JSON sigma [Pa] at radius R [m] of the equilibrium (or the state (A, D)); with\n"
    "  --control at the critical state, r = S a_c with 0 <= S < 1.\n",
    /* cycle */
    "usage: mdr cycle <profile> <material> --control load|grips|machine --path V1,V2,...\n"
    "                 --steps-per-segment S [--k-machine K] [--w-adv W] [--springs N]\n"
    "                 [--a-max A] [--arith f32|f64|q31] [--summary FILE]\n"
    "  drives the spring engine along the piecewise-linear path of the controlled\n"
    "  variable (d [m], F [N] or z [m]). CSV step,z,d,F,a,event on stdout; the JSON\n"
    "  summary (pull_off_F, pull_off_d, events, dissipated, cycles, jumps, springs,\n"
    "  a_max, max_tensile_F, max_tensile_d, event_list, warnings, input, units) on\n"
    "  stderr, or in FILE with --summary FILE (a run that fails, exit 1: its one line\n"
    "  on stderr, the summary up to the failure in FILE only). pull_off_F, pull_off_d:\n"
    "  the last pull-off's state (each one is in event_list; max_tensile_F is the most\n"
    "  tensile force of the whole run). A body that has pulled off under --control load\n"
    "  carries no force (F = 0) at the depth it left from, whatever the load asked,\n"
    "  until it touches again. warnings: a wavy profile's table with fewer than 8\n"
    "  springs per wavelength, whose folds and jumps it does not resolve (also a line\n"
    "  on stderr with --summary FILE). --k-machine K [N/m]: the machine stiffness,\n"
    "  needed by --control machine; under grips or load it sets the CSV's z = d + F/K\n"
    "  (without it z = d) and nothing else. --w-adv W: work of adhesion on approach\n"
    "  (default 0, echoed in the summary). --springs N: default 1024 (2..16384; q31: a\n"
    "  power of two). --a-max: the table extent, default 1.25 x the largest radius the\n"
    "  path can reach (to 1e-6: where the equilibrium curve of w first reaches the\n"
    "  path's largest value; the sphere: at most 0.999 R). q31: the fixed-point engine\n"
    "  on the table converted from the f64 one; the path must stay within its input\n"
    "  range (+-2 units of D0, F0 or Z0; machine: z >= z_min, where the free body's\n"
    "  depth fits), else it is refused. The q31 default extent is that one doubled, at\n"
    "  most 8 times, until the q31 table exists and the whole path fits (the units grow\n"
    "  with the table); an explicit --a-max is kept.\n",
    /* table */
    "usage: mdr table <profile> [--springs N] --a-max A [--name NAME] [--arith f32|f64|q31]\n"
    "                 [--output FILE.c] [--header FILE.h]\n"
    "  the spring table as const C arrays (for flash), on stdout or in FILE.c; the\n"
    "  header declaring it goes to FILE.h (--header), or next to FILE.c (--output,\n"
    "  FILE.h); the .c then includes it. q31: N must be a power of two. A wavy profile's\n"
    "  table with fewer than 8 springs per wavelength: a warning line on stderr.\n",
    /* fit */
    "usage: mdr fit (--curve FILE | --map FILE) <profile> --k-machine K [--arith f32|f64]\n"
    "               [--method full|two-point] [--approach] [--unpinned] [--z-e ZE] [--E0 E --w0 W]\n"
    "               [--flat-baseline] [--model FILE] [--jobs N]\n"
    "  fits E*, w (and the base offset z0, force baseline F_base and its slope\n"
    "  F_slope, held at 0 with --flat-baseline) to a measured\n"
    "  force curve z,F (CSV, --curve: JSON on stdout) or to every curve of a map\n"
    "  (curve,z,F, --map: CSV on stdout); tab- or space-separated files too. --jobs:\n"
    "  a map's threads. --arith: default f64; an f32 answer is refused where f64's fit of\n"
    "  the same samples refuses them, lies further from it than f32's goal and 3 of its errors,\n"
    "  or reports an error 3 times below f64's (MDR_E_PARAM). See docs/fitting.md.\n",
};

/* --help anywhere, `mdr help [CMD]`, --version: 0, or -1 to go on */
static int cli_help(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
        if (argc > 2) {
            return usage_error("--version takes no arguments", argv[2]);
        }
        printf("mdr (libmdr %d.%d)\n", MDR_VERSION_MAJOR, MDR_VERSION_MINOR);
        return 0;
    }
    if (argc >= 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
                      strcmp(argv[1], "help") == 0)) {
        if (argc > 2 && strcmp(argv[1], "help") != 0) {
            return usage_error("--help takes no arguments (mdr help COMMAND)", argv[2]);
        }
        if (argc == 3 && (strcmp(argv[2], "help") == 0 || strcmp(argv[2], "--help") == 0 ||
                          strcmp(argv[2], "-h") == 0)) {
            fputs(usage_main, stdout); /* (help on help: the commands) */
            return 0;
        }
        if (argc == 3 && strcmp(argv[1], "help") == 0) {
            int k;
            for (k = 0; k < NCMD; k++) {
                if (strcmp(argv[2], cmd_names[k]) == 0) {
                    fputs(usage_cmd[k], stdout);
                    return 0;
                }
            }
            return usage_error("help: unknown command", argv[2]);
        }
        if (argc > 2 && strcmp(argv[1], "help") == 0) {
            return usage_error("help takes one command", argv[3]);
        }
        fputs(usage_main, stdout);
        return 0;
    }
    return -1;
}

/* the arithmetic's range: a value float cannot hold (beyond FLT_MAX, or
 * nonzero below FLT_MIN where it would lose digits or become 0) */
static int outside_f32(double v)
{
    double m = v < 0 ? -v : v;
    return m > (double)FLT_MAX || (m != 0.0 && m < (double)FLT_MIN);
}

/* C's keywords (C99 and C11), which no --name may be */
static const char *const c_keywords[] = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
    "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short", "signed",
    "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile", "while", "_Bool",
    "_Complex", "_Imaginary", "_Alignas", "_Alignof", "_Atomic", "_Generic", "_Noreturn", "_Static_assert",
    "_Thread_local"};

/* the commands that take a flag (bits of CMD_*) */
#define C_(c) (1u << (c))
#define C_ALL (C_(CMD_EQ) | C_(CMD_CRITICAL) | C_(CMD_CURVE) | C_(CMD_STRESS) | C_(CMD_CYCLE) | C_(CMD_TABLE))
static const struct {
    const char *name;
    unsigned cmds;
} flag_cmds[] = {
    {"--profile", C_ALL},
    {"--arith", C_ALL},
    {"--file", C_ALL},
    {"--control", C_(CMD_CRITICAL) | C_(CMD_STRESS) | C_(CMD_CYCLE)},
    {"--path", C_(CMD_CYCLE)},
    {"--summary", C_(CMD_CYCLE)},
    {"--name", C_(CMD_TABLE)},
    {"--header", C_(CMD_TABLE)},
    {"--output", C_(CMD_TABLE)},
    {"--E", C_ALL & ~C_(CMD_TABLE)},
    {"--w", C_ALL & ~C_(CMD_TABLE)},
    {"--a", C_(CMD_EQ) | C_(CMD_STRESS)},
    {"--d", C_(CMD_EQ) | C_(CMD_STRESS)},
    {"--r", C_(CMD_STRESS)},
    {"--a-max", C_(CMD_CURVE) | C_(CMD_CYCLE) | C_(CMD_TABLE)},
    {"--n", C_(CMD_CURVE)},
    {"--points", C_(CMD_CURVE)},
    {"--springs", C_(CMD_CYCLE) | C_(CMD_TABLE)},
    {"--steps-per-segment", C_(CMD_CYCLE)},
    {"--w-adv", C_(CMD_CYCLE)},
    {"--k-machine", C_(CMD_CRITICAL) | C_(CMD_STRESS) | C_(CMD_CYCLE)},
    {"--a-start", C_(CMD_CRITICAL) | C_(CMD_STRESS)},
};

/* 1: f is a flag of command c's own (not only a profile parameter) */
static int cmd_has(const char *f, int c)
{
    int k;
    for (k = 0; k < (int)(sizeof flag_cmds / sizeof flag_cmds[0]); k++) {
        if (strcmp(f, flag_cmds[k].name) == 0) {
            return (flag_cmds[k].cmds & C_(c)) != 0;
        }
    }
    return 0;
}

/* 1: a flag of command c (its own, or a profile parameter) */
static int flag_known(const char *f, int c, int *of_profile)
{
    int k, i;
    *of_profile = 0;
    for (k = 0; k < (int)(sizeof profiles / sizeof profiles[0]); k++) {
        for (i = 0; i < 3 && profiles[k].flags[i] != NULL; i++) {
            *of_profile |= strcmp(f, profiles[k].flags[i]) == 0;
        }
    }
    for (k = 0; k < (int)(sizeof flag_cmds / sizeof flag_cmds[0]); k++) {
        if (strcmp(f, flag_cmds[k].name) == 0) {
            return (flag_cmds[k].cmds & C_(c)) != 0 || *of_profile ? 1 : -1;
        }
    }
    return *of_profile ? 1 : 0;
}

#include "mdr_fit_cli.h"

static void free_args(struct cli_args *A)
{
    free(A->path);
    free(A->tr);
    free(A->tf);
    free(A->ts);
    free(A->tline);
}

static int parse_args(struct cli_args *A, const struct cli_kv *kv, int nkv)
{
    const char *profile = NULL;
    const char *names[CLI_MAX_FLAGS];
    double vals[CLI_MAX_FLAGS];
    int nflag = 0, i;
    int have_E = 0, have_w = 0, have_a = 0, have_r = 0, have_n = 0, have_steps = 0;
    int used[CLI_MAX_FLAGS] = {0};
    const char *path_arg = NULL;

    for (i = 0; i < nkv; i++) {
        const char *f = kv[i].name, *v = kv[i].val;
        int of_profile, known = flag_known(f, A->cmd, &of_profile);
        if (known == 0) {
            return usage_error("unknown flag", f);
        }
        if (known < 0) {
            return usage_errf("%s: not a flag of mdr %s (mdr %s --help)", f, cmd_names[A->cmd],
                              cmd_names[A->cmd]);
        }
        if (strcmp(f, "--profile") == 0) {
            profile = v;
        } else if (strcmp(f, "--arith") == 0) {
            if (strcmp(v, "f32") == 0) {
                A->f64 = 0;
            } else if (strcmp(v, "f64") == 0) {
                A->f64 = 1;
            } else if (strcmp(v, "q31") == 0) {
                A->f64 = 1; /* the q31 table and constants are set up in double */
                A->q31 = 1;
            } else {
                return usage_error("--arith takes f32, f64 or q31", v);
            }
        } else if (strcmp(f, "--control") == 0) {
            if (strcmp(v, "load") == 0) {
                A->control = MDR_CONTROL_LOAD;
            } else if (strcmp(v, "grips") == 0) {
                A->control = MDR_CONTROL_GRIPS;
            } else if (strcmp(v, "machine") == 0) {
                A->control = MDR_CONTROL_MACHINE;
            } else {
                return usage_error("--control takes load, grips or machine", v);
            }
            A->have_control = 1;
        } else if (strcmp(f, "--path") == 0) {
            path_arg = v;
        } else if (strcmp(f, "--file") == 0) {
            A->file = v;
        } else if (strcmp(f, "--summary") == 0) {
            A->summary = v;
        } else if (strcmp(f, "--header") == 0) {
            A->header = v;
        } else if (strcmp(f, "--output") == 0) {
            A->output = v;
        } else if (strcmp(f, "--name") == 0) {
            size_t j;
            for (j = 0; v[j]; j++) {
                char ch = v[j];
                if (!(ch == '_' || (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (j > 0 && ch >= '0' && ch <= '9')) || j > 200) {
                    return usage_error("--name must be a C identifier", v);
                }
            }
            if (j == 0) {
                return usage_error("--name must be a C identifier", v);
            }
            for (j = 0; j < sizeof c_keywords / sizeof c_keywords[0]; j++) {
                if (strcmp(v, c_keywords[j]) == 0) { /* (the table's .c did not compile: helper-24, stop 56) */
                    return usage_error("--name must be a C identifier, not a keyword", v);
                }
            }
            A->name = v;
        } else {
            names[nflag] = f;
            if (!parse_num(v, &vals[nflag])) {
                return usage_errf("%s: %s: %s", f, num_problem(v), v);
            }
            if (is_subnormal(vals[nflag])) {
                return usage_errf("%s: %s: %s", f, SUBNORMAL_WHY, v);
            }
            nflag++;
        }
    }
    if (path_arg != NULL) {
        A->npath = parse_list(path_arg, &A->path);
        if (A->npath < 0) {
            const char *val = path_arg; /* value -npath (from 1) */
            long k;
            for (k = 1; k < -A->npath; k++) {
                val = strchr(val, ',') + 1;
            }
            /* (white space named as such; else the words of before) */
            return usage_errf("--path: value %ld is %s: %s", -A->npath,
                              num_problem(val)[0] == 'w' ? num_problem(val) : "not a finite number", path_arg);
        }
        if (A->npath == 0) {
            return usage_error("out of memory", NULL);
        }
        if (A->npath < 2) {
            return usage_error("--path takes two or more numbers V1,V2,...", path_arg);
        }
        for (i = 0; i < A->npath; i++) {
            if (is_subnormal(A->path[i])) {
                return usage_errf("--path: value %ld (%.17g) is %s", (long)i + 1, A->path[i], SUBNORMAL_WHY);
            }
        }
    }
    if (profile == NULL) {
        return usage_error("missing --profile", NULL);
    }
    if (strcmp(profile, "table") == 0) {
        if (A->file == NULL) {
            return usage_error("--profile table needs --file FILE", NULL);
        }
        A->kind = KIND_TABLE;
    } else {
        int pi = -1, k;
        if (A->file != NULL) {
            return usage_error("--file goes with --profile table", A->file);
        }
        for (k = 0; k < (int)(sizeof profiles / sizeof profiles[0]); k++) {
            if (strcmp(profiles[k].name, profile) == 0) {
                pi = k;
            }
        }
        if (pi < 0) {
            return usage_error("unknown profile", profile);
        }
        A->kind = profiles[pi].kind;
        A->pi = pi;
        {
            const char *missing = profile_params(pi, names, vals, nflag, used, A->p);
            if (missing != NULL) {
                return usage_error("missing profile parameter", missing);
            }
        }
    }
    for (i = 0; i < nflag; i++) {
        const char *f = names[i];
        int c = A->cmd, of_profile, known = flag_known(f, c, &of_profile);
        if (used[i]) {
            continue;
        }
        if (known <= 0 || (of_profile && !cmd_has(f, c))) {
            return usage_errf("%s: not a parameter of --profile %s", f, profile);
        }
        if (strcmp(f, "--E") == 0) {
            A->E = vals[i];
            have_E = 1;
        } else if (strcmp(f, "--w") == 0) {
            A->w = vals[i];
            have_w = 1;
        } else if (strcmp(f, "--a") == 0) {
            A->a = vals[i];
            have_a = 1;
        } else if (strcmp(f, "--d") == 0) {
            A->d = vals[i];
            A->have_d = 1;
        } else if (strcmp(f, "--r") == 0) {
            A->r = vals[i];
            have_r = 1;
        } else if (strcmp(f, "--a-max") == 0) {
            A->a_max = vals[i];
            A->have_amax = 1;
        } else if (strcmp(f, "--n") == 0 || strcmp(f, "--points") == 0) {
            if (have_n) {
                return usage_error("give the count once (--n or --points)", f);
            }
            if (!parse_count(vals[i], 1, 10000000, &A->n)) {
                return usage_errf("%s must be an integer in [1, 1e7]", f);
            }
            have_n = 1;
        } else if (strcmp(f, "--springs") == 0) {
            if (!parse_count(vals[i], MDR_SPRINGS_MIN, MDR_SPRINGS_MAX, &A->springs)) {
                return usage_errf("--springs must be an integer in [%d, %d]", (int)MDR_SPRINGS_MIN,
                                  (int)MDR_SPRINGS_MAX);
            }
        } else if (strcmp(f, "--steps-per-segment") == 0) {
            if (!parse_count(vals[i], 1, 10000000, &A->steps)) {
                return usage_error("--steps-per-segment must be an integer in [1, 1e7]", NULL);
            }
            have_steps = 1;
        } else if (strcmp(f, "--w-adv") == 0) {
            A->w_adv = vals[i];
            A->have_w_adv = 1;
        } else if (strcmp(f, "--k-machine") == 0) {
            A->k_m = vals[i];
            A->have_k = 1;
        } else {
            A->a_start = vals[i];
            A->have_a_start = 1;
        }
    }
    /* a value the arithmetic cannot hold is refused here, by name, not
     * turned into 0 or inf by the conversion */
    if (!A->f64) {
        for (i = 0; i < nflag; i++) {
            if (outside_f32(vals[i])) {
                return usage_errf("%s %.9g: outside the range of --arith f32 (0 or |v| in [%.9g, %.9g])",
                                  names[i], vals[i], (double)FLT_MIN, (double)FLT_MAX);
            }
        }
        for (i = 0; i < A->npath; i++) {
            if (outside_f32(A->path[i])) {
                return usage_errf("--path value %ld (%.9g): outside the range of --arith f32", i + 1,
                                  A->path[i]);
            }
        }
    }
    /* the path's interpolation a + (b - a) j / S (mdr_host_path_value())
     * stays finite, between a and b, when (b - a) S is finite */
    for (i = 0; i + 1 < A->npath; i++) {
        if (!is_finite((A->path[i + 1] - A->path[i]) * (double)(A->steps > 0 ? A->steps : 1))) {
            return usage_errf("--path segment %ld (%.9g to %.9g): the interpolation overflows", i + 1,
                              A->path[i], A->path[i + 1]);
        }
    }
    if (A->cmd == CMD_TABLE) {
        A->E = 1.0; /* geometry only: any valid material */
    } else {
        if (!have_E) {
            return usage_error("missing --E", NULL);
        }
        if (!have_w) {
            return usage_error("missing --w", NULL);
        }
    }
    switch (A->cmd) {
    case CMD_EQ:
        if (!have_a) {
            return usage_error("missing --a", NULL);
        }
        break;
    case CMD_CURVE:
        if (!A->have_amax || !have_n) {
            return usage_error("curve needs --a-max and --n (--points with --profile powerlaw)", NULL);
        }
        break;
    case CMD_CRITICAL:
        if (!A->have_control) {
            return usage_error("missing --control", NULL);
        }
        break;
    case CMD_CYCLE:
        if (!A->have_control) {
            return usage_error("missing --control", NULL);
        }
        if (A->path == NULL || !have_steps) {
            return usage_error("cycle needs --path V1,V2,... and --steps-per-segment S", NULL);
        }
        if (A->have_w_adv && A->w >= 0.0 && is_finite(A->w) && !(A->w_adv >= 0.0 && A->w_adv <= A->w)) {
            /* (named, not the engine's "parameter out of range": helper-56) */
            return usage_errf("--w-adv %.9g: outside [0, --w] = [0, %.9g] (the approach's work of adhesion is at "
                              "most the retraction's)",
                              A->w_adv, A->w);
        }
        break;
    case CMD_TABLE:
        if (!A->have_amax && A->kind != KIND_TABLE) {
            return usage_error("table needs --a-max", NULL);
        }
        break;
    default:
        if (!have_r || (have_a == A->have_control)) {
            return usage_error("stress needs --r and either --a or --control", NULL);
        }
        if (A->have_d && !have_a) {
            return usage_error("--d needs --a (a state (a, d) as given)", NULL);
        }
        if (A->have_a_start && !A->have_control) {
            return usage_error("--a-start goes with --control (the critical state)", NULL);
        }
        break;
    }
    if (A->have_control && A->control == MDR_CONTROL_MACHINE && !(A->k_m > 0.0)) {
        return usage_error("--control machine needs --k-machine > 0", NULL);
    }
    if (A->have_k && A->cmd != CMD_CYCLE && A->control != MDR_CONTROL_MACHINE) {
        return usage_error("--k-machine goes with --control machine", NULL);
    }
    if (A->q31 && A->cmd != CMD_CYCLE && A->cmd != CMD_TABLE) {
        return usage_error("--arith q31 works with cycle and table only", NULL);
    }
    if (A->output != NULL && A->header != NULL && strcmp(A->output, A->header) == 0) {
        /* (the .c overwrote the header and included itself; helper-37, stop 59) */
        return usage_error("--output and --header name the same file", A->output);
    }
    if (A->output != NULL && A->header == NULL) {
        size_t l = strlen(A->output);
        if (l < 3 || strcmp(A->output + l - 2, ".c") != 0) {
            return usage_error("--output names a .c file (the header goes next to it)", A->output);
        }
    }
    if (A->kind == KIND_TABLE) {
        A->ntab = load_tip(A->file, &A->tr, &A->tf, &A->ts, &A->tline);
        if (A->ntab < 0) {
            return 2; /* named by load_tip() */
        }
    }
    return 0;
}

/* rc of a command whose results are on stdout: a write error there (a full
 * disk, a closed stdout) fails the run, 1 with one line */
static int stdout_written(int rc)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        perror("mdr: stdout");
        return 1;
    }
    return rc;
}

int main(int argc, char **argv)
{
    struct cli_args A;
    struct cli_kv kv[CLI_MAX_FLAGS];
    int nkv, k, rc;

    if (argc < 2) {
        /* (one line, as every refusal; the commands: mdr --help) */
        return usage_error("no command (mdr --help lists them)", NULL);
    }
    rc = cli_help(argc, argv);
    if (rc >= 0) {
        /* (the usage or version lost to /dev/full exited 0; an attack
         * after stop 59) */
        return rc == 0 ? stdout_written(0) : rc;
    }
    memset(&A, 0, sizeof A);
    A.springs = 1024;
    A.name = "mdr_tip";
    A.cmd = -1;
    for (k = 0; k < NCMD; k++) {
        if (strcmp(argv[1], cmd_names[k]) == 0) {
            A.cmd = k;
        }
    }
    if (A.cmd < 0) {
        return usage_errf("unknown command: %s (mdr --help)", argv[1]);
    }
    if (A.cmd == CMD_FIT) {
        /* (a result JSON or map rows lost to a full disk or a closed
         * stdout exited 0; helper-36, stop 59) */
        return stdout_written(fit_main(argc, argv));
    }
    rc = cli_collect(argc, argv, 2, NULL, kv, &nkv);
    if (rc == 3) {
        fputs(usage_cmd[A.cmd], stdout);
        return stdout_written(0);
    }
    if (rc == 0) {
        rc = parse_args(&A, kv, nkv);
    }
    if (rc == 0) {
        rc = stdout_written(A.f64 ? run_f64(&A) : run_f32(&A));
    }
    free_args(&A);
    return rc;
}
