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

/* A suite's run, leaving out the tests that match MDR_SKIP_TESTS
 * (cmocka's pattern: * and ?): make matrix leaves out each suite's long
 * sweeps, which make test's host, sanitizer and mutation suites run
 * (host_tests/matrix.sh says which and why). On a target: every test. */
#ifdef MDR_TARGET_TEST
#define MDR_RUN_TESTS(tests) cmocka_run_group_tests(tests, NULL, NULL)
#else
#include <stdlib.h>
#define MDR_RUN_TESTS(tests)                                                                       \
    (getenv("MDR_SKIP_TESTS") != NULL ? cmocka_set_skip_filter(getenv("MDR_SKIP_TESTS")) : (void)0, \
     cmocka_run_group_tests(tests, NULL, NULL))
#endif

#endif /* MDR_APPLIES_H */
