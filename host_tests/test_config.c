/* SPDX-License-Identifier: MIT */
/*
 * test_config.c: the test every configuration of the build matrix runs
 * (make matrix; options: lib/include/mdr_options.h). Compiled with the
 * configuration's options, it checks that what the configuration keeps
 * works and that what it removes is gone: removed profiles and output
 * groups answer MDR_E_DISABLED and leave the instance unchanged, removed
 * functions are not declared (their checks are compiled out with them).
 *
 * Tolerances:
 *   TOL_MIN = 5e-6: the smallest force along a fixed-grips cycle of a
 *     paraboloid (4000 ticks) against JKR's -1.5 pi w R (seed 4.36): the
 *     minimum is smooth in d, so the tick spacing (1/400 of the path's
 *     depth scale) leaves ~1e-6; f32 rounding ~1e-6; scenes and the spring
 *     engine (256 springs, a table exact for g quadratic in x) alike;
 *   TOL_MIN_Q31_LSB = 3: the q31 engine's smallest force on the same
 *     depths against the float engine's, in LSB of its force format
 *     (2^-29 F0, 7e-7 of this minimum: the format's rounding of F and the
 *     state's few LSB, README "Fixed point"; measured 0.41 LSB);
 *   the force and depth of a force-only scene equal those of an
 *     all-outputs scene bit for bit;
 *   every profile kept: d and F at one radius against the closed forms of
 *     host_tests/closed_forms.h, TC_TOL32 = 5e-7 and TC_TOL64 = 1e-15 of
 *     the size of their terms; the paraboloid's stress against 4.42, the
 *     same tolerances (the wavy profile: test_vectors.c against GSL).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mdr.h"
#include "test_util.h"
#include "closed_forms.h"

#define TOL_MIN 5e-6
#define TOL_MIN_Q31_LSB 3.0
#define NTICK 4000
#define NSPR 256
#define AMAX 3e-6

/* the paraboloid of the cycles: R [m], E* [Pa], w [J/m^2] */
#define TC_TOL32 5e-7
#define TC_TOL64 1e-15
#define TC_R 1e-6
#define TC_E 1e6
#define TC_W 0.05

#if (MDR_CFG_SCENE || MDR_CFG_ENGINE) && MDR_CFG_PROFILE_PARABOLOID
/* The smallest force along a fixed-grips cycle of the paraboloid is JKR's
 * -1.5 pi w R (the fixed-load pull-off, passed by the grips path). */
#define JKR_F (-1.5 * M_PI * TC_W * TC_R)

/* a grips path 0 -> 4 d_c -> -2 d_c (d_c = (pi^2 w^2 R/E*^2)^(1/3), the
 * depth scale of JKR): tick i of NTICK */
static double grips_d(int i)
{
    double dc = pow(M_PI * M_PI * TC_W * TC_W * TC_R / (TC_E * TC_E), 1.0 / 3.0);
    double u = (double)i / NTICK;
    return u < 0.4 ? 10.0 * dc * u : 4.0 * dc - 10.0 * dc * (u - 0.4);
}
#endif

#if MDR_CFG_F32
#define T float
#define SFX(name) name##_f32
#include "test_config_t.h"
#undef T
#undef SFX
#endif
#if MDR_CFG_F64
#define T double
#define SFX(name) name##_f64
#include "test_config_t.h"
#undef T
#undef SFX
#endif

/* the configuration, as the library sees it */
static void print_config(void)
{
    printf("config: f32 %d f64 %d q31 %d engine %d scene %d stress %d events %d profiles %d%d%d%d%d%d%d\n",
           MDR_CFG_F32, MDR_CFG_F64, MDR_CFG_Q31, MDR_CFG_ENGINE, MDR_CFG_SCENE, MDR_CFG_STRESS,
           MDR_CFG_EVENTS, MDR_CFG_PROFILE_PARABOLOID, MDR_CFG_PROFILE_CONE, MDR_CFG_PROFILE_POWERLAW,
           MDR_CFG_PROFILE_FLATPUNCH, MDR_CFG_PROFILE_SPHERE, MDR_CFG_PROFILE_FLATTIP,
           MDR_CFG_PROFILE_WAVY);
}

static void status_names(void **state)
{
    (void)state;
    assert_string_equal(mdr_status_str(MDR_E_DISABLED), "removed from this build (mdr_options.h)");
}

#if MDR_CFG_F32
static void f32_profiles(void **state)
{
    (void)state;
    profiles_f32();
}
#endif
#if MDR_CFG_F64
static void f64_profiles(void **state)
{
    (void)state;
    profiles_f64();
}
#endif
#if MDR_CFG_SCENE && MDR_CFG_PROFILE_PARABOLOID
static void scenes(void **state)
{
    (void)state;
#if MDR_CFG_F32
    scene_f32();
#endif
#if MDR_CFG_F64
    scene_f64();
#endif
}
#endif
#if MDR_CFG_ENGINE && MDR_CFG_PROFILE_PARABOLOID
static void engines(void **state)
{
    (void)state;
#if MDR_CFG_F32
    engine_f32();
#endif
#if MDR_CFG_F64
    engine_f64();
#endif
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(status_names),
#if MDR_CFG_F32
        cmocka_unit_test(f32_profiles),
#endif
#if MDR_CFG_F64
        cmocka_unit_test(f64_profiles),
#endif
#if MDR_CFG_SCENE && MDR_CFG_PROFILE_PARABOLOID
        cmocka_unit_test(scenes),
#endif
#if MDR_CFG_ENGINE && MDR_CFG_PROFILE_PARABOLOID
        cmocka_unit_test(engines),
#endif
    };
    print_config();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
