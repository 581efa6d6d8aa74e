/* SPDX-License-Identifier: MIT */
/*
 * test_util.h: the comparison every cmocka test here uses (include after
 * <cmocka.h> and <math.h>).
 *
 * With the environment variable MDR_TOL_REPORT set, a suite prints at exit,
 * for each comparison (its label up to a '[', numbers folded to '#'), the
 * largest share of its tolerance that any call used: how close each
 * tolerance sits to the error it measures (a share of 0.1 or more: within
 * 10x).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char what[96];
    double share; /* largest |got - want| / (tol * scale) */
    long n;
} mdr_tol_rec;

static mdr_tol_rec mdr_tol_recs[512];
static int mdr_tol_nrec;

static void mdr_tol_print(void)
{
    int i;
    printf("tolerance report: largest share of the tolerance used, per comparison\n");
    for (i = 0; i < mdr_tol_nrec; i++) {
        printf("  %8.3g  %6ld calls  %s\n", mdr_tol_recs[i].share, mdr_tol_recs[i].n,
               mdr_tol_recs[i].what);
    }
}

static void mdr_tol_note(const char *what, double share)
{
    static int on = -1;
    char key[96];
    size_t i = 0, j = 0;
    int r;
    if (on < 0) {
        on = getenv("MDR_TOL_REPORT") != NULL;
        if (on) {
            atexit(mdr_tol_print);
        }
    }
    if (!on) {
        return;
    }
    /* fold numbers (not those that end a name, as in f32, q31, H0): one label
     * per check, not per tick or parameter */
    while (what[i] != '\0' && what[i] != '[' && j + 1 < sizeof key) {
        char ch = what[i];
        int digit = ch >= '0' && ch <= '9';
        int named = i > 0 && ((what[i - 1] >= 'A' && what[i - 1] <= 'Z') ||
                              (what[i - 1] >= 'a' && what[i - 1] <= 'z'));
        if (digit && !named && !(j > 0 && key[j - 1] != '#' && i > 0 && what[i - 1] >= '0' &&
                                 what[i - 1] <= '9')) {
            while ((what[i] >= '0' && what[i] <= '9') || what[i] == '.' || what[i] == 'e' ||
                   what[i] == '-') {
                i++;
            }
            key[j++] = '#';
            continue;
        }
        key[j++] = ch;
        i++;
    }
    key[j] = '\0';
    for (r = 0; r < mdr_tol_nrec; r++) {
        if (strcmp(mdr_tol_recs[r].what, key) == 0) {
            break;
        }
    }
    if (r == mdr_tol_nrec) {
        if (r == (int)(sizeof mdr_tol_recs / sizeof mdr_tol_recs[0])) {
            return;
        }
        mdr_tol_nrec++;
        memcpy(mdr_tol_recs[r].what, key, j + 1);
        mdr_tol_recs[r].share = 0;
        mdr_tol_recs[r].n = 0;
    }
    mdr_tol_recs[r].n++;
    if (share > mdr_tol_recs[r].share) {
        mdr_tol_recs[r].share = share;
    }
}

/* |got - want| <= tol * scale, scale = |want| when scale <= 0; prints both
 * and the relative error on failure. */
__attribute__((unused)) static void rel_le(double got, double want, double scale, double tol, const char *what)
{
    double s = scale > 0 ? scale : fabs(want);
    mdr_tol_note(what, tol * s > 0 ? fabs(got - want) / (tol * s) : (got == want ? 0 : INFINITY));
    if (!(fabs(got - want) <= tol * s)) {
        print_error("%s: got %.17g want %.17g rel %.3g > %.3g\n", what, got, want,
                    fabs(got - want) / s, tol);
        fail();
    }
}

/* an error measured by the test (>= 0) within its tolerance */
__attribute__((unused)) static void err_le(double err, double tol, const char *what)
{
    rel_le(err, 0.0, 1.0, tol, what);
}
