/*
 * mdr: command-line front end of libmdr (host only; uses stdio).
 *
 *   mdr eq       <profile> <material> [--arith f32|f64] --a A
 *   mdr critical <profile> <material> --control load|grips|machine
 *                [--k-machine K] [--a-start A]
 *   mdr curve    <profile> <material> --a-max A --n N
 *   mdr stress   <profile> <material> --a A --r R
 *   mdr stress   <profile> <material> --control MODE [--k-machine K] --r S
 *                (at the critical state, r = S * a_c with 0 <= S < 1)
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

enum { CMD_EQ, CMD_CRITICAL, CMD_CURVE, CMD_STRESS };

struct cli_args {
    int cmd;
    uint8_t kind, control;
    double p[3], E, w, a, r, a_max, a_start, k_m;
    long n;
    int f64, have_control, have_a_start;
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

#define CLI_T float
#define CLI_SFX(name) name##_f32
#define CLI_FMT "%.9g"
#include "mdr_cli_t.h"
#undef CLI_T
#undef CLI_SFX
#undef CLI_FMT
#define CLI_T double
#define CLI_SFX(name) name##_f64
#define CLI_FMT "%.17g"
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

int main(int argc, char **argv)
{
    struct cli_args A;
    const char *profile = NULL;
    const char *names[32];
    double vals[32];
    int nflag = 0, i, k, pi = -1;
    int have_E = 0, have_w = 0, have_a = 0, have_r = 0, have_amax = 0, have_n = 0;
    int used[32] = {0};

    memset(&A, 0, sizeof A);
    if (argc < 2) {
        return usage_error("missing command (eq, critical, curve, stress)", NULL);
    }
    if (strcmp(argv[1], "eq") == 0) {
        A.cmd = CMD_EQ;
    } else if (strcmp(argv[1], "critical") == 0) {
        A.cmd = CMD_CRITICAL;
    } else if (strcmp(argv[1], "curve") == 0) {
        A.cmd = CMD_CURVE;
    } else if (strcmp(argv[1], "stress") == 0) {
        A.cmd = CMD_STRESS;
    } else {
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
            } else {
                return usage_error("--arith takes f32 or f64", v);
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
    for (k = 0; k < (int)(sizeof profiles / sizeof profiles[0]); k++) {
        if (strcmp(profiles[k].name, profile) == 0) {
            pi = k;
        }
    }
    if (pi < 0) {
        return usage_error("unknown profile", profile);
    }
    A.kind = profiles[pi].kind;
    for (k = 0; k < 3 && profiles[pi].flags[k] != NULL; k++) {
        int found = 0;
        for (i = 0; i < nflag; i++) {
            if (strcmp(names[i], profiles[pi].flags[k]) == 0) {
                A.p[k] = vals[i];
                used[i] = found = 1;
            }
        }
        if (!found) {
            return usage_error("missing profile parameter", profiles[pi].flags[k]);
        }
    }
    for (i = 0; i < nflag; i++) {
        const char *f = names[i];
        if (used[i]) {
            continue;
        }
        if (strcmp(f, "--E") == 0) {
            A.E = vals[i];
            have_E = 1;
        } else if (strcmp(f, "--w") == 0) {
            A.w = vals[i];
            have_w = 1;
        } else if (strcmp(f, "--a") == 0 && (A.cmd == CMD_EQ || A.cmd == CMD_STRESS)) {
            A.a = vals[i];
            have_a = 1;
        } else if (strcmp(f, "--r") == 0 && A.cmd == CMD_STRESS) {
            A.r = vals[i];
            have_r = 1;
        } else if (strcmp(f, "--a-max") == 0 && A.cmd == CMD_CURVE) {
            A.a_max = vals[i];
            have_amax = 1;
        } else if (strcmp(f, "--n") == 0 && A.cmd == CMD_CURVE) {
            if (vals[i] < 1 || vals[i] > 10000000 || vals[i] != (double)(long)vals[i]) {
                return usage_error("--n must be an integer in [1, 1e7]", NULL);
            }
            A.n = (long)vals[i];
            have_n = 1;
        } else if (strcmp(f, "--k-machine") == 0 && (A.cmd == CMD_CRITICAL || A.cmd == CMD_STRESS)) {
            A.k_m = vals[i];
        } else if (strcmp(f, "--a-start") == 0 && A.cmd == CMD_CRITICAL) {
            A.a_start = vals[i];
            A.have_a_start = 1;
        } else {
            return usage_error("unknown or misplaced flag", f);
        }
    }
    if (!have_E) {
        return usage_error("missing --E", NULL);
    }
    if (!have_w) {
        return usage_error("missing --w", NULL);
    }
    switch (A.cmd) {
    case CMD_EQ:
        if (!have_a) {
            return usage_error("missing --a", NULL);
        }
        break;
    case CMD_CURVE:
        if (!have_amax || !have_n) {
            return usage_error("curve needs --a-max and --n", NULL);
        }
        break;
    case CMD_CRITICAL:
        if (!A.have_control) {
            return usage_error("missing --control", NULL);
        }
        break;
    default:
        if (!have_r || (have_a == A.have_control)) {
            return usage_error("stress needs --r and either --a or --control", NULL);
        }
        break;
    }
    if (A.have_control && A.control == MDR_CONTROL_MACHINE && !(A.k_m > 0.0)) {
        return usage_error("--control machine needs --k-machine > 0", NULL);
    }
    return A.f64 ? run_f64(&A) : run_f32(&A);
}
