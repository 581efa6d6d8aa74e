/* SPDX-License-Identifier: MIT */
/*
 * fuzz_init.c: the init functions with arbitrary parameters, and the
 * closed-form calls on every scene they accept. From the fuzzer's bytes: a
 * profile kind (0 ... 8: two of them unknown), p[0..2], E*, w (fz_val: any
 * magnitude, zero, negative, NaN, inf, raw float bits), radii and positions,
 * a control mode (0 ... 4) and k_m; then, in f32 and f64 from the same
 * values: mdr_contact_init, mdr_profile_eval, mdr_eq, mdr_stress_intensity,
 * mdr_stress / mdr_stress_at, mdr_default_start, mdr_critical, a spring
 * table of the scene (mdr_table_init_profile, springs 0 ... 600) with its
 * engine (mdr_engine_init, any w_adv and k_m), and the q31 table and engine
 * inits from it. Checked as fuzz.h says: named statuses, nothing written on
 * a refusal, finite results on MDR_OK.
 */
#include "fuzz.h"

#define NMAX 600

/* one arithmetic, written once */
#define FZ_T float
#define FZ_SFX(name) name##_f32
#include "fuzz_init_t.h"
#undef FZ_T
#undef FZ_SFX
#define FZ_T double
#define FZ_SFX(name) name##_f64
#include "fuzz_init_t.h"
#undef FZ_T
#undef FZ_SFX

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    fz_scene s;
    int i;
    s.kind = (uint8_t)(fz_u8(&in) % 9);
    s.p[0] = fz_val(&in, -10, 1);
    s.p[1] = fz_val(&in, -10, 1);
    s.p[2] = fz_val(&in, -10, 1);
    s.E = fz_val(&in, 2, 13);
    s.w = fz_val(&in, -7, 2);
    for (i = 0; i < 4; i++) {
        s.a[i] = fz_val(&in, -12, 1);
        s.r[i] = fz_u8(&in) / 200.0; /* fraction of a: past 1 is outside */
        s.d[i] = fz_val(&in, -12, 1);
    }
    s.control = (uint8_t)(fz_u8(&in) % 5);
    s.k_m = fz_val(&in, -6, 9);
    s.springs = (uint16_t)(fz_u8(&in) * 600u / 255u);
    s.x_frac = fz_val(&in, -3, 1);
    s.w_adv = fz_val(&in, -7, 2);
    s.k_m2 = fz_val(&in, -6, 9);
#ifdef FZ_DEBUG
    fprintf(stderr, "kind %u p %.17g %.17g %.17g E %.17g w %.17g a %.17g %.17g %.17g %.17g control %u k_m %.17g "
            "springs %u x_frac %.17g w_adv %.17g k_m2 %.17g\n", (unsigned)s.kind, s.p[0], s.p[1], s.p[2], s.E, s.w,
            s.a[0], s.a[1], s.a[2], s.a[3], (unsigned)s.control, s.k_m, (unsigned)s.springs, s.x_frac, s.w_adv, s.k_m2);
#endif
    fz_init_f64(&s);
    fz_init_f32(&s);
    return 0;
}
