/* SPDX-License-Identifier: MIT */
/*
 * fuzz_table.c: the tabulated-profile parser (examples/tip_csv.h, the mdr
 * CLI's reader of measured tips) and mdr_table_init_gap on what it accepts.
 * Bytes: springs (2 ... 4096, a power of two), E*, w, then the CSV text.
 * The pairs go to mdr_table_init_gap_f64 and _f32; a table they accept must
 * be finite, and carries an f32, f64 and q31 engine through a fixed
 * approach and retraction under fixed grips (0 -> the table's largest
 * depth -> twice the adhesive reach below 0), checked as fuzz.h says.
 * The same samples, as slopes formed in double (tip_slopes), make a contact
 * of the contact module (mdr_contact_init_table, f32 and f64): equilibrium
 * at radii across the table and, for up to 512 samples, the critical state
 * from the default start under fixed load and grips; named statuses,
 * nothing written on refusal, finite results.
 */
#include "fuzz.h"
#include "tip_csv.h"

#define PMAX 4096
#define NMAX 4096
static double r[PMAX], f[PMAX];
static float r32[PMAX], f32[PMAX];
static mdr_node_f64 n64[MDR_TABLE_NODES(NMAX)];
static mdr_node_f32 n32[MDR_TABLE_NODES(NMAX)];
static mdr_node_q31 nq[MDR_TABLE_NODES(NMAX)];
static double sl[PMAX];
static float sl32[PMAX];

/* the contact module on the samples (see the top) */
static void contact_checks(long m, double E, double w)
{
    mdr_contact_f64 c;
    mdr_contact_f32 cf;
    long i;
    mdr_status st;
    if (tip_slopes(r, f, m, sl, NULL) == -1) {
        return; /* (a falling f, -2, the library takes: its slopes are all written) */
    }
    for (i = 0; i + 1 < m; i++) {
        sl32[i] = (float)sl[i];
    }
    memset(&c, 0x5a, sizeof c);
    {
        mdr_contact_f64 c0 = c;
        st = mdr_contact_init_table_f64(&c, r, sl, (uint16_t)m, E, w);
        fz_status(st);
        FZ_CHECK(st == MDR_OK || memcmp(&c, &c0, sizeof c) == 0);
    }
    if (st == MDR_OK) {
        mdr_critstate_f64 k, k0;
        double a0;
        for (i = 1; i <= 8; i++) {
            mdr_eqstate_f64 q;
            st = mdr_eq_f64(&c, c.p[0] * (double)i / 8.0, &q);
            fz_status(st);
            FZ_CHECK(st != MDR_OK || (fz_fin(q.d) && fz_fin(q.F) && fz_fin(q.dF_da) && fz_fin(q.dd_da)));
        }
        if (m <= 512 && mdr_default_start_f64(&c, &a0) == MDR_OK) {
            for (uint8_t ctl = 1; ctl <= 2; ctl++) {
                memset(&k, 0x5a, sizeof k);
                k0 = k;
                st = mdr_critical_f64(&c, ctl, 0.0, a0, &k);
                fz_status(st);
                FZ_CHECK(st == MDR_OK ? fz_fin(k.a) && fz_fin(k.d) && fz_fin(k.F) && fz_fin(k.F_min)
                                      : memcmp(&k, &k0, sizeof k) == 0);
            }
        }
    }
    st = mdr_contact_init_table_f32(&cf, r32, sl32, (uint16_t)m, (float)E, (float)w);
    fz_status(st);
    if (st == MDR_OK && m <= 512) {
        mdr_critstate_f32 k;
        float a0;
        if (mdr_default_start_f32(&cf, &a0) == MDR_OK) {
            st = mdr_critical_f32(&cf, MDR_CONTROL_LOAD, 0.0f, a0, &k);
            fz_status(st);
            FZ_CHECK(st != MDR_OK || (fz_fin((double)k.a) && fz_fin((double)k.F) && fz_fin((double)k.d)));
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    uint16_t n = (uint16_t)(2u << fz_u8(&in) % 12);
    double E = pow(10.0, 3 + 9 * fz_u8(&in) / 255.0), w = pow(10.0, -6 + 7 * fz_u8(&in) / 255.0);
    long m = tip_csv_parse((const char *)in.p, in.n, r, f, PMAX), i;
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    mdr_table_q31 tq;
    mdr_engine_f64 e64;
    mdr_engine_f32 e32;
    mdr_engine_q31 eq;
    mdr_status st;
    int ok32 = 0, okq = 0;
    double gmax = 0, dmax, dmin;
    FZ_CHECK(m >= -2 && m <= PMAX);
    if (m < 0 || m > 65535) {
        return 0;
    }
    for (i = 0; i < m; i++) {
        r32[i] = (float)r[i];
        f32[i] = (float)f[i];
    }
    contact_checks(m, E, w);
    st = mdr_table_init_gap_f32(&t32, n32, n, r32, f32, (uint16_t)m);
    fz_status(st);
    if (st == MDR_OK) {
        for (i = 0; i <= n; i++) {
            FZ_CHECK(fz_fin((double)n32[i].g) && fz_fin((double)n32[i].G) && fz_fin((double)n32[i].q));
        }
        ok32 = mdr_engine_init_f32(&e32, &t32, (float)E, (float)w, (float)w, 0.0f) == MDR_OK;
    }
    st = mdr_table_init_gap_f64(&t64, n64, n, r, f, (uint16_t)m);
    fz_status(st);
    if (st != MDR_OK || mdr_engine_init_f64(&e64, &t64, E, w, w, 0.0) != MDR_OK) {
        return 0;
    }
    for (i = 0; i <= n; i++) {
        FZ_CHECK(fz_fin(n64[i].g) && fz_fin(n64[i].G) && fz_fin(n64[i].q));
        gmax = fmax(gmax, n64[i].g);
    }
    okq = mdr_table_q31_from_f64(&tq, nq, &t64) == MDR_OK && mdr_engine_init_q31_f64(&eq, &tq, E, w, w, 0.0) == MDR_OK;
    dmax = gmax;
    dmin = -2 * e64.c_w * sqrt(n * t64.h);
    for (i = 1; i <= 96; i++) {
        double d = i <= 32 ? dmax * i / 32.0 : dmax + (dmin - dmax) * (i - 32) / 64.0;
        mdr_step_f64 o64;
        mdr_step_f32 o32;
        mdr_step_q31 oq;
        fz_step_f64(&e64, FZ_D, d, &o64);
        if (ok32) {
            fz_step_f32(&e32, FZ_D, (float)d, &o32);
        }
        if (okq) {
            double dq = d / (double)eq.D0 * 536870912.0;
            fz_step_q31(&eq, FZ_D, (int32_t)fmax(-2147483648.0, fmin(2147483647.0, dq)), &oq);
        }
    }
    return 0;
}
