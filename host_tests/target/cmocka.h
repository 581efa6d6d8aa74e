/* SPDX-License-Identifier: MIT */
/*
 * host_tests/target/cmocka.h: the part of the cmocka API the host tests use
 * (cmocka_unit_test, cmocka_run_group_tests[_name], assert_true,
 * assert_false, assert_int_equal, assert_memory_equal, assert_string_equal,
 * fail, fail_msg, print_message, print_error), for the target builds, where the
 * Debian cmocka library does not exist. On the include path before the
 * system's only in target builds (make target-test). It prints the lines
 * cmocka prints ([ RUN ], [ OK ], [ FAILED ], the summary), so host and
 * target runs read and compare the same; main's return value is the
 * number of failed tests, as with cmocka.
 *
 * A failed assertion prints where and why, then longjmps out of the test
 * (tests run one after another, each after its setup where it has one; no
 * teardown or group state, which the host tests do not use). A build may
 * leave tests out by name (MDR_TARGET_SKIP, below).
 */
#ifndef MDR_TARGET_CMOCKA_H
#define MDR_TARGET_CMOCKA_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef void (*CMUnitTestFunction)(void **state);
typedef int (*CMFixtureFunction)(void **state);

struct CMUnitTest {
    const char *name;
    CMUnitTestFunction test_func;
    CMFixtureFunction setup_func; /* run before the test (NULL: none), as cmocka's */
};

#define cmocka_unit_test(f) {#f, f, NULL}
#define cmocka_unit_test_setup(f, setup) {#f, f, setup}

static jmp_buf mdr_cm_jmp;

static inline void mdr_cm_fail(const char *file, int line, const char *what)
{
    printf("[  ERROR   ] --- %s\n[   LINE   ] --- %s:%d: error: Failure!\n", what, file, line);
    longjmp(mdr_cm_jmp, 1);
}

static inline void mdr_cm_int(long long a, long long b, const char *file, int line)
{
    char msg[64];
    if (a != b) {
        /* in 32-bit halves: newlib-nano's printf (the Cortex-M0's) has no
         * long long conversion */
        unsigned long long ua = (unsigned long long)a, ub = (unsigned long long)b;
        snprintf(msg, sizeof msg, "0x%08lx%08lx != 0x%08lx%08lx", (unsigned long)(ua >> 32),
                 (unsigned long)(ua & 0xFFFFFFFFu), (unsigned long)(ub >> 32), (unsigned long)(ub & 0xFFFFFFFFu));
        mdr_cm_fail(file, line, msg);
    }
}

#define assert_true(c) ((c) ? (void)0 : mdr_cm_fail(__FILE__, __LINE__, #c))
#define assert_false(c) (!(c) ? (void)0 : mdr_cm_fail(__FILE__, __LINE__, "!(" #c ")"))
#define assert_int_equal(a, b) mdr_cm_int((long long)(a), (long long)(b), __FILE__, __LINE__)
#define assert_memory_equal(a, b, n) \
    (memcmp((a), (b), (n)) == 0 ? (void)0 : mdr_cm_fail(__FILE__, __LINE__, "memory differs"))
#define assert_string_equal(a, b) \
    (strcmp((a), (b)) == 0 ? (void)0 : mdr_cm_fail(__FILE__, __LINE__, "strings differ"))
#define fail() mdr_cm_fail(__FILE__, __LINE__, "fail()")
/* cmocka's: the message (a format and its arguments), then fail() */
#define fail_msg(...) (print_error("ERROR: " __VA_ARGS__), print_error("\n"), mdr_cm_fail(__FILE__, __LINE__, "fail_msg()"))

static inline void print_message(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

static inline void print_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

/* The tests a target build leaves out: MDR_TARGET_SKIP, a string of
 * comma-separated test names (exact), set per core and program by
 * mk/target.mk (TGT_SKIP_<core>_<program>: sweeps in soft double that take
 * minutes of QEMU; TARGET_TEST=full sets none). Whether name is one. */
#ifndef MDR_TARGET_SKIP
#define MDR_TARGET_SKIP ""
#endif
static inline int mdr_cm_skipped(const char *name)
{
    const char *list = MDR_TARGET_SKIP;
    const size_t k = strlen(name);
    while (*list != '\0') {
        const size_t m = strcspn(list, ",");
        if (m == k && strncmp(list, name, k) == 0) {
            return 1;
        }
        list += m;
        if (*list == ',') {
            list++;
        }
    }
    return 0;
}

static inline int mdr_cm_run(const struct CMUnitTest *t, const size_t total)
{
    volatile size_t i, failed = 0, left = 0, n;
    static const char *failed_name[64];
    for (i = 0; i < total; i++) {
        left += (size_t)mdr_cm_skipped(t[i].name);
    }
    if (left > 0) {
        /* (as the host's MDR_SKIP_TESTS line, host_tests/applies.h) */
        printf("MDR_TARGET_SKIP=%s: %u of %u tests left out (TARGET_TEST=full runs them)\n", MDR_TARGET_SKIP,
               (unsigned)left, (unsigned)total);
    }
    {
        /* every name of the list is a test's (a renamed test fails here) */
        const char *c = MDR_TARGET_SKIP;
        size_t names = *c != '\0' ? 1u : 0u;
        for (; *c != '\0'; c++) {
            names += (size_t)(*c == ',');
        }
        if (names != left) {
            printf("MDR_TARGET_SKIP=%s: %u names, %u of them tests of this program\n", MDR_TARGET_SKIP,
                   (unsigned)names, (unsigned)left);
            return 1;
        }
    }
    n = total - left;
    printf("[==========] Running %u test(s).\n", (unsigned)n);
    for (i = 0; i < total; i++) {
        if (mdr_cm_skipped(t[i].name)) {
            continue;
        }
        printf("[ RUN      ] %s\n", t[i].name);
        if (setjmp(mdr_cm_jmp) == 0) {
            if (t[i].setup_func != NULL && t[i].setup_func(NULL) != 0) {
                mdr_cm_fail(__FILE__, __LINE__, "setup failed");
            }
            t[i].test_func(NULL);
            printf("[       OK ] %s\n", t[i].name);
        } else {
            printf("[  FAILED  ] %s\n", t[i].name);
            if (failed < 64) {
                failed_name[failed] = t[i].name;
            }
            failed++;
        }
    }
    printf("[==========] %u test(s) run.\n", (unsigned)n);
    printf("[  PASSED  ] %u test(s).\n", (unsigned)(n - failed));
    if (failed > 0) {
        printf("[  FAILED  ] %u test(s), listed below:\n", (unsigned)failed);
        for (i = 0; i < failed && i < 64; i++) {
            printf("[  FAILED  ] %s\n", failed_name[i]);
        }
        printf("\n %u FAILED TEST(S)\n", (unsigned)failed);
    }
    return (int)failed;
}

#define cmocka_run_group_tests(tests, setup, teardown) \
    ((void)(setup), (void)(teardown), mdr_cm_run((tests), sizeof(tests) / sizeof((tests)[0])))
#define cmocka_run_group_tests_name(name, tests, setup, teardown) \
    ((void)(name), cmocka_run_group_tests(tests, setup, teardown))

#endif /* MDR_TARGET_CMOCKA_H */
