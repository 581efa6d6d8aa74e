/* SPDX-License-Identifier: MIT */
/*
 * contact_util.h: what test_unit.c and test_critical.c share (include after
 * <cmocka.h>, <math.h>, mdr.h and test_util.h): contacts made or the test
 * fails, a guard pattern to see that a refused call wrote nothing, and the
 * critical state from the default start in both arithmetics against
 * expected values.
 */
#define GUARD 0x5Au

static inline mdr_contact_f64 mk64(uint8_t kind, double p0, double p1, double p2, double E, double w)
{
    mdr_contact_f64 c;
    double p[3] = {p0, p1, p2};
    assert_int_equal(mdr_contact_init_f64(&c, kind, p, E, w), MDR_OK);
    return c;
}

static inline mdr_contact_f32 mk32(uint8_t kind, double p0, double p1, double p2, double E, double w)
{
    mdr_contact_f32 c;
    float p[3] = {(float)p0, (float)p1, (float)p2};
    assert_int_equal(mdr_contact_init_f32(&c, kind, p, (float)E, (float)w), MDR_OK);
    return c;
}

static inline int untouched(const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) {
        if (b[i] != GUARD) {
            return 0;
        }
    }
    return 1;
}

/* the critical state from mdr_default_start in both arithmetics against
 * (a, d, F): a relative to a, F to |F|, d to max(|d|, dl(a)); tol64 for
 * f64, tol32 for f32 */
static inline void crit_both(uint8_t kind, double p0, double p1, double p2, double E, double w, uint8_t ctl,
                             double km, double a, double d, double F, double tol64, double tol32, const char *what)
{
    mdr_contact_f64 c64 = mk64(kind, p0, p1, p2, E, w);
    mdr_contact_f32 c32 = mk32(kind, p0, p1, p2, E, w);
    mdr_critstate_f64 o64;
    mdr_critstate_f32 o32;
    double s64;
    float s32;
    double dl = sqrt(2 * M_PI * a * w / E), ds = fabs(d) > dl ? fabs(d) : dl;
    assert_int_equal(mdr_default_start_f64(&c64, &s64), MDR_OK);
    assert_int_equal(mdr_default_start_f32(&c32, &s32), MDR_OK);
    assert_int_equal(mdr_critical_f64(&c64, ctl, km, s64, &o64), MDR_OK);
    assert_int_equal(mdr_critical_f32(&c32, ctl, (float)km, s32, &o32), MDR_OK);
    print_message("%-34s f64 rel a %.1e F %.1e d %.1e | f32 rel a %.1e F %.1e d %.1e\n", what,
                  fabs(o64.a - a) / a, fabs(o64.F - F) / fabs(F), fabs(o64.d - d) / ds,
                  fabs(o32.a - a) / a, fabs(o32.F - F) / fabs(F), fabs(o32.d - d) / ds);
    {
        char w64[160], w32[160];
        snprintf(w64, sizeof w64, "critical state (f64, tol %.1e) [%s]", tol64, what);
        snprintf(w32, sizeof w32, "critical state (f32, tol %.1e) [%s]", tol32, what);
        rel_le(o64.a, a, 0, tol64, w64);
        rel_le(o64.F, F, 0, tol64, w64);
        rel_le(o64.d, d, ds, tol64, w64);
        rel_le(o32.a, a, 0, tol32, w32);
        rel_le(o32.F, F, 0, tol32, w32);
        rel_le(o32.d, d, ds, tol32, w32);
    }
}
