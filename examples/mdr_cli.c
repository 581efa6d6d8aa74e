/*
 * mdr: command-line front end of libmdr (host only; uses stdio).
 *
 *   mdr eq       <profile> <material> [--arith f32|f64] --a A [--d D]
 *                (without --d the equilibrium state at radius A; with it
 *                the state (A, D) as given, pinned or not: F of that state,
 *                its K_I and G; d_eq, F_eq the equilibrium's)
 *   mdr critical <profile> <material> --control load|grips|machine
 *                [--k-machine K] [--a-start A]
 *                (+ max_tensile_F, max_tensile_d: the most tensile force
 *                of the quasi-static path to the pull-off, and its depth)
 *   mdr curve    <profile> <material> --a-max A --n N
 *   mdr stress   <profile> <material> --a A [--d D] --r R
 *   mdr stress   <profile> <material> --control MODE [--k-machine K] --r S
 *                (at the critical state, r = S * a_c with 0 <= S < 1)
 *   mdr cycle    <profile> <material> --control load|grips|machine
 *                [--k-machine K] [--springs N] [--w-adv W] [--a-max A]
 *                --path V1,V2,... --steps-per-segment S
 *                drives the spring engine along the piecewise-linear path of
 *                the controlled variable (d [m], F [N] or z [m]); CSV
 *                step,z,d,F,a,event on stdout, one JSON summary on stderr:
 *                pull_off_F pull_off_d events dissipated (+ cycles, jumps,
 *                springs, a_max, max_tensile_F, max_tensile_d: the most
 *                tensile force of the path, before or after any jump, and
 *                its depth; null if none was tensile, event_list)
 *   mdr table    <profile> [--springs N] --a-max A [--name NAME]
 *                prints the spring table as const C arrays (for flash)
 *
 *   cycle and table take --arith f32|f64|q31 (default f32). q31: the
 *   fixed-point engine (lib/include/mdr_q31.h) on the table converted from
 *   the f64 one, constants by the double init; cycle still reads and prints
 *   SI values (converted in double), table prints the q31 nodes (N must be
 *   a power of two).
 *
 *   <profile> also: --profile table --file FILE (CSV r,f in metres, r from
 *               0 strictly increasing; every command; the profile ends at
 *               the last r; slopes formed in double, then converted)
 *   --springs N  springs of the table (default 1024, up to MDR_SPRINGS_MAX)
 *   --a-max A    table extent (cycle: default 1.25 x the largest radius the
 *                path can reach, from the closed-form equilibrium)
 *
 *   <profile>:  --profile paraboloid --R R | cone --theta RAD |
 *               powerlaw --C C --n N | flatpunch --a0 A0 | sphere --R R |
 *               flattip --R R --b B | wavy --R R --h H --lambda L
 *   <material>: --E ESTAR [Pa] --w W [J/m^2, work of adhesion]
 *
 * eq, critical and stress print one JSON object, curve prints CSV a,d,F.
 * Bad arguments: one line on stderr naming the problem, exit status 2.
 * A computation that fails (iteration cap) exits with 1.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mdr.h"
#include "mdr_host.h"
#include "tip_csv.h"

enum { CMD_EQ, CMD_CRITICAL, CMD_CURVE, CMD_STRESS, CMD_CYCLE, CMD_TABLE };

/* --profile table */
#define KIND_TABLE MDR_PROFILE_TABLE

struct cli_args {
    int cmd;
    uint8_t kind, control;
    double p[3], E, w, a, r, a_max, a_start, k_m, w_adv, d;
    long n, springs, steps;
    int f64, q31, have_control, have_a_start, have_amax, have_d;
    double *path; /* --path values */
    long npath;
    double *tr, *tf, *ts; /* --file samples, and their slopes (double) */
    long ntab;
    const char *name, *file;
};

static int usage_error(const char *msg, const char *what)
{
    fprintf(stderr, "mdr: %s%s%s\n", msg, what ? ": " : "", what ? what : "");
    return 2;
}

static int cli_fail(const char *what, mdr_status st)
{
    fprintf(stderr, "mdr: %s: %s (status %d)\n", what, mdr_status_str(st), (int)st);
    return st == MDR_E_NOCONV ? 1 : 2;
}

static int parse_num(const char *s, double *v)
{
    char *end;
    if (s == NULL || *s == '\0') {
        return 0;
    }
    *v = strtod(s, &end);
    return *end == '\0';
}

/* "V1,V2,..." -> malloc'd array; 0 on a malformed list */
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
        v[i++] = strtod(s, &end);
        if (end == s || (*end != ',' && *end != '\0')) {
            free(v);
            return 0;
        }
        s = end + 1;
    }
    *out = v;
    return n;
}

/* CSV of r,f (examples/tip_csv.h) -> malloc'd arrays; count or -1 */
static long read_table(const char *file, double **r, double **f)
{
    FILE *fp = fopen(file, "rb");
    char *text = NULL;
    size_t len = 0, cap = 0, got;
    long n = -1;
    if (fp == NULL) {
        return -1;
    }
    do {
        if (len == cap) {
            char *t = realloc(text, cap = cap ? 2 * cap : 65536);
            if (t == NULL) {
                break;
            }
            text = t;
        }
        got = fread(text + len, 1, cap - len, fp);
        len += got;
    } while (got > 0);
    if (!ferror(fp) && feof(fp)) {
        size_t lines = tip_csv_lines(text, len) + 1;
        *r = malloc(lines * sizeof **r);
        *f = malloc(lines * sizeof **f);
        if (*r != NULL && *f != NULL) {
            n = tip_csv_parse(text, len, *r, *f, lines);
        }
        if (n < 0) {
            free(*r);
            free(*f);
            *r = *f = NULL;
            n = -1;
        }
    }
    (void)fclose(fp); /* read only: nothing to lose */
    free(text);
    return n;
}

#define CLI_T float
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
#undef CLI_SFX
#undef CLI_FMT
#undef CLI_EFMT
#undef CLI_NAME
#undef CLI_LIT
#define CLI_T double
#define CLI_SFX(name) name##_f64
#define CLI_NAME "f64"
#define CLI_LIT ""
#define CLI_FMT "%.17g"
#define CLI_EFMT "%.16e"
#include "mdr_host_t.h"
#include "mdr_cli_t.h"

/* profile name -> kind and the flags of its parameters */
static const struct {
    const char *name;
    uint8_t kind;
    const char *flags[3];
} profiles[] = {
    {"paraboloid", MDR_PROFILE_PARABOLOID, {"--R", NULL, NULL}},
    {"cone", MDR_PROFILE_CONE, {"--theta", NULL, NULL}},
    {"powerlaw", MDR_PROFILE_POWERLAW, {"--C", "--n", NULL}},
    {"flatpunch", MDR_PROFILE_FLATPUNCH, {"--a0", NULL, NULL}},
    {"sphere", MDR_PROFILE_SPHERE, {"--R", NULL, NULL}},
    {"flattip", MDR_PROFILE_FLATTIP, {"--R", "--b", NULL}},
    {"wavy", MDR_PROFILE_WAVY, {"--R", "--h", "--lambda"}},
};

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

#include "mdr_fit_cli.h"

int main(int argc, char **argv)
{
    static const char *cmds[] = {"eq", "critical", "curve", "stress", "cycle", "table"};
    struct cli_args A;
    const char *profile = NULL;
    const char *names[32];
    double vals[32];
    int nflag = 0, i, k, rc;
    int have_E = 0, have_w = 0, have_a = 0, have_r = 0, have_n = 0, have_steps = 0;
    int used[32] = {0};

    if (argc >= 2 && strcmp(argv[1], "fit") == 0) {
        return fit_main(argc, argv);
    }
    memset(&A, 0, sizeof A);
    A.springs = 1024;
    A.name = "mdr_tip";
    if (argc < 2) {
        return usage_error("missing command (eq, critical, curve, stress, cycle, table)", NULL);
    }
    A.cmd = -1;
    for (k = 0; k < (int)(sizeof cmds / sizeof cmds[0]); k++) {
        if (strcmp(argv[1], cmds[k]) == 0) {
            A.cmd = k;
        }
    }
    if (A.cmd < 0) {
        return usage_error("unknown command", argv[1]);
    }
    for (i = 2; i < argc; i++) {
        const char *f = argv[i];
        if (strncmp(f, "--", 2) != 0) {
            return usage_error("expected a flag", f);
        }
        if (i + 1 >= argc) {
            return usage_error("flag needs a value", f);
        }
        if (strcmp(f, "--profile") == 0) {
            profile = argv[++i];
            continue;
        }
        if (strcmp(f, "--arith") == 0) {
            const char *v = argv[++i];
            if (strcmp(v, "f32") == 0) {
                A.f64 = 0;
            } else if (strcmp(v, "f64") == 0) {
                A.f64 = 1;
            } else if (strcmp(v, "q31") == 0) {
                A.f64 = 1; /* the q31 table and constants are set up in double */
                A.q31 = 1;
            } else {
                return usage_error("--arith takes f32, f64 or q31", v);
            }
            continue;
        }
        if (strcmp(f, "--control") == 0) {
            const char *v = argv[++i];
            if (strcmp(v, "load") == 0) {
                A.control = MDR_CONTROL_LOAD;
            } else if (strcmp(v, "grips") == 0) {
                A.control = MDR_CONTROL_GRIPS;
            } else if (strcmp(v, "machine") == 0) {
                A.control = MDR_CONTROL_MACHINE;
            } else {
                return usage_error("--control takes load, grips or machine", v);
            }
            A.have_control = 1;
            continue;
        }
        if (strcmp(f, "--path") == 0 && A.cmd == CMD_CYCLE) {
            free(A.path);
            A.npath = parse_list(argv[++i], &A.path);
            if (A.npath < 2) {
                return usage_error("--path takes two or more numbers V1,V2,...", argv[i]);
            }
            continue;
        }
        if (strcmp(f, "--file") == 0) {
            A.file = argv[++i];
            continue;
        }
        if (strcmp(f, "--name") == 0 && A.cmd == CMD_TABLE) {
            const char *v = argv[++i];
            size_t j;
            for (j = 0; v[j]; j++) {
                char ch = v[j];
                if (!(ch == '_' || (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (j > 0 && ch >= '0' && ch <= '9'))) {
                    return usage_error("--name must be a C identifier", v);
                }
            }
            if (j == 0) {
                return usage_error("--name must be a C identifier", v);
            }
            A.name = v;
            continue;
        }
        if (nflag == 32) {
            return usage_error("too many flags", f);
        }
        names[nflag] = f;
        if (!parse_num(argv[++i], &vals[nflag])) {
            return usage_error("not a number", f);
        }
        nflag++;
    }
    if (profile == NULL) {
        return usage_error("missing --profile", NULL);
    }
    if (strcmp(profile, "table") == 0) {
        if (A.file == NULL) {
            return usage_error("--profile table needs --file FILE", NULL);
        }
        A.kind = KIND_TABLE;
    } else {
        int pi = -1;
        for (k = 0; k < (int)(sizeof profiles / sizeof profiles[0]); k++) {
            if (strcmp(profiles[k].name, profile) == 0) {
                pi = k;
            }
        }
        if (pi < 0) {
            return usage_error("unknown profile", profile);
        }
        A.kind = profiles[pi].kind;
        {
            const char *missing = profile_params(pi, names, vals, nflag, used, A.p);
            if (missing != NULL) {
                return usage_error("missing profile parameter", missing);
            }
        }
    }
    for (i = 0; i < nflag; i++) {
        const char *f = names[i];
        int c = A.cmd;
        if (used[i]) {
            continue;
        }
        if (strcmp(f, "--E") == 0 && c != CMD_TABLE) {
            A.E = vals[i];
            have_E = 1;
        } else if (strcmp(f, "--w") == 0 && c != CMD_TABLE) {
            A.w = vals[i];
            have_w = 1;
        } else if (strcmp(f, "--a") == 0 && (c == CMD_EQ || c == CMD_STRESS)) {
            A.a = vals[i];
            have_a = 1;
        } else if (strcmp(f, "--d") == 0 && (c == CMD_EQ || c == CMD_STRESS)) {
            A.d = vals[i];
            A.have_d = 1;
        } else if (strcmp(f, "--r") == 0 && c == CMD_STRESS) {
            A.r = vals[i];
            have_r = 1;
        } else if (strcmp(f, "--a-max") == 0 && (c == CMD_CURVE || c == CMD_CYCLE || c == CMD_TABLE)) {
            A.a_max = vals[i];
            A.have_amax = 1;
        } else if (strcmp(f, "--n") == 0 && c == CMD_CURVE) {
            if (!parse_count(vals[i], 1, 10000000, &A.n)) {
                return usage_error("--n must be an integer in [1, 1e7]", NULL);
            }
            have_n = 1;
        } else if (strcmp(f, "--springs") == 0 && (c == CMD_CYCLE || c == CMD_TABLE)) {
            if (!parse_count(vals[i], MDR_SPRINGS_MIN, MDR_SPRINGS_MAX, &A.springs)) {
                return usage_error("--springs must be an integer in [2, 16384]", NULL);
            }
        } else if (strcmp(f, "--steps-per-segment") == 0 && c == CMD_CYCLE) {
            if (!parse_count(vals[i], 1, 10000000, &A.steps)) {
                return usage_error("--steps-per-segment must be an integer in [1, 1e7]", NULL);
            }
            have_steps = 1;
        } else if (strcmp(f, "--w-adv") == 0 && c == CMD_CYCLE) {
            A.w_adv = vals[i];
        } else if (strcmp(f, "--k-machine") == 0 &&
                   (c == CMD_CRITICAL || c == CMD_STRESS || c == CMD_CYCLE)) {
            A.k_m = vals[i];
        } else if (strcmp(f, "--a-start") == 0 && c == CMD_CRITICAL) {
            A.a_start = vals[i];
            A.have_a_start = 1;
        } else {
            return usage_error("unknown or misplaced flag", f);
        }
    }
    if (A.cmd == CMD_TABLE) {
        A.E = 1.0; /* geometry only: any valid material */
    } else {
        if (!have_E) {
            return usage_error("missing --E", NULL);
        }
        if (!have_w) {
            return usage_error("missing --w", NULL);
        }
    }
    switch (A.cmd) {
    case CMD_EQ:
        if (!have_a) {
            return usage_error("missing --a", NULL);
        }
        break;
    case CMD_CURVE:
        if (!A.have_amax || !have_n) {
            return usage_error("curve needs --a-max and --n", NULL);
        }
        break;
    case CMD_CRITICAL:
        if (!A.have_control) {
            return usage_error("missing --control", NULL);
        }
        break;
    case CMD_CYCLE:
        if (!A.have_control) {
            return usage_error("missing --control", NULL);
        }
        if (A.path == NULL || !have_steps) {
            return usage_error("cycle needs --path V1,V2,... and --steps-per-segment S", NULL);
        }
        break;
    case CMD_TABLE:
        if (!A.have_amax && A.kind != KIND_TABLE) {
            return usage_error("table needs --a-max", NULL);
        }
        break;
    default:
        if (!have_r || (have_a == A.have_control)) {
            return usage_error("stress needs --r and either --a or --control", NULL);
        }
        if (A.have_d && !have_a) {
            return usage_error("--d needs --a (a state (a, d) as given)", NULL);
        }
        break;
    }
    if (A.have_control && A.control == MDR_CONTROL_MACHINE && !(A.k_m > 0.0)) {
        return usage_error("--control machine needs --k-machine > 0", NULL);
    }
    if (A.kind == KIND_TABLE) {
        A.ntab = read_table(A.file, &A.tr, &A.tf);
        if (A.ntab < 0) {
            return usage_error("cannot read r,f pairs from", A.file);
        }
        if (A.ntab > 65535) {
            free(A.tr);
            free(A.tf);
            return usage_error("more than 65535 points in", A.file);
        }
        A.ts = malloc((size_t)(A.ntab > 1 ? A.ntab - 1 : 1) * sizeof *A.ts);
        if (A.ts == NULL || tip_slopes(A.tr, A.tf, A.ntab, A.ts) != 0) {
            free(A.tr);
            free(A.tf);
            free(A.ts);
            return usage_error("r must increase strictly in", A.file);
        }
    }
    if (A.q31 && A.cmd != CMD_CYCLE && A.cmd != CMD_TABLE) {
        free(A.path);
        free(A.tr);
        free(A.tf);
        free(A.ts);
        return usage_error("--arith q31 works with cycle and table only", NULL);
    }
    rc = A.f64 ? run_f64(&A) : run_f32(&A);
    free(A.path);
    free(A.tr);
    free(A.tf);
    free(A.ts);
    /* the results are on stdout: a write error (a full disk) fails the run */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        perror("mdr: stdout");
        return 1;
    }
    return rc;
}
