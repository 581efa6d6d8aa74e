/* SPDX-License-Identifier: MIT */
/*
 * applies.h: which configurations a test suite applies to. A suite that
 * needs parts of the library a configuration removes (build matrix, make
 * matrix; options: lib/include/mdr_options.h) compiles to a main() that
 * says so and exits 0; make matrix counts it as not applicable.
 * Include after mdr.h.
 */
#ifndef MDR_APPLIES_H
#define MDR_APPLIES_H

#include <stdio.h>

#define MDR_CFG_ALL_PROFILES                                                                       \
    (MDR_CFG_PROFILE_PARABOLOID && MDR_CFG_PROFILE_CONE && MDR_CFG_PROFILE_POWERLAW &&             \
     MDR_CFG_PROFILE_FLATPUNCH && MDR_CFG_PROFILE_SPHERE && MDR_CFG_PROFILE_FLATTIP &&             \
     MDR_CFG_PROFILE_WAVY && MDR_CFG_PROFILE_TABLE)

/* the fit (MDR_CFG_FIT) stands on the contact module of a float arithmetic */
#define MDR_CFG_HAS_FIT (MDR_CFG_FIT && (MDR_CFG_F32 || MDR_CFG_F64))

#define MDR_TEST_NOT_APPLICABLE(needs)                                                             \
    int main(void)                                                                                 \
    {                                                                                              \
        printf("not applicable: the suite needs %s\n", needs);                                    \
        return 0;                                                                                  \
    }

/* A suite's run, leaving out the tests whose names match a pattern of
 * MDR_SKIP_TESTS (comma-separated; fnmatch's * ? and [...]): make matrix
 * leaves out each suite's long sweeps, which make test's host, sanitizer
 * and mutation suites run (host_tests/matrix.sh says which and why). The
 * suite prints how many it left out. On a target: every test. */
#ifdef MDR_TARGET_TEST
#define MDR_RUN_TESTS_NAME(name, tests) cmocka_run_group_tests_name(name, tests, NULL, NULL)
#else
#include <fnmatch.h>
#include <stdlib.h>
#include <string.h>
/* whether name matches one of the comma-separated patterns of list */
static inline int mdr_skipped_(const char *list, const char *name)
{
    char pat[128];
    while (*list != '\0') {
        size_t k = strcspn(list, ",");
        if (k > 0 && k < sizeof pat) {
            memcpy(pat, list, k);
            pat[k] = '\0';
            if (fnmatch(pat, name, 0) == 0) {
                return 1;
            }
        }
        list += k;
        if (*list == ',') {
            list++;
        }
    }
    return 0;
}
static inline int mdr_run_tests_(const char *group, const struct CMUnitTest *t, size_t n)
{
    static struct CMUnitTest kept[512];
    const char *skip = getenv("MDR_SKIP_TESTS");
    size_t i, m = 0;
    if (skip == NULL || *skip == '\0') {
        return _cmocka_run_group_tests(group, t, n, NULL, NULL);
    }
    if (n > sizeof kept / sizeof kept[0]) {
        printf("MDR_SKIP_TESTS: %u tests, more than applies.h's %u\n", (unsigned)n,
               (unsigned)(sizeof kept / sizeof kept[0]));
        return 1;
    }
    for (i = 0; i < n; i++) {
        if (!mdr_skipped_(skip, t[i].name)) {
            kept[m++] = t[i];
        }
    }
    printf("MDR_SKIP_TESTS=%s: %u of %u tests left out\n", skip, (unsigned)(n - m), (unsigned)n);
    return _cmocka_run_group_tests(group, kept, m, NULL, NULL);
}
#define MDR_RUN_TESTS_NAME(name, tests) mdr_run_tests_(name, tests, sizeof(tests) / sizeof((tests)[0]))
#endif
#define MDR_RUN_TESTS(tests) MDR_RUN_TESTS_NAME(#tests, tests)

#endif /* MDR_APPLIES_H */
