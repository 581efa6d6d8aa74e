/* SPDX-License-Identifier: MIT */
/*
 * fuzz_step.c: the step functions with arbitrary input sequences. The first
 * bytes choose a valid scene (profile and size, material, w_adv, machine,
 * springs 2 ... 4096, table extent) and build the f64, f32 and q31 tables
 * and engines on it; every following 5 bytes are one tick: a byte choosing
 * the control (d, F, z, or clear the flags) and 32 bits of value, a signed
 * Q2.29 number of the scene's units (up to +-4 units: past the table's end,
 * and for q31 past its documented +-2 input range into saturation), or with
 * the top bit of the control byte raw float bits for the float engines
 * (NaN, inf). The three engines take the same physical input; every step is
 * checked as fuzz.h describes. Where the profile is a monomial (paraboloid,
 * cone, integer power law) the f64 and f32 table-free scenes take the same
 * inputs (all outputs, energy kept; fz_scene_step), and the q31 scene made
 * from the f64 one with a_max = x_max takes the same raw q31 values (in its
 * own units; fz_scene_step_q31).
 */
#include "fuzz.h"

#define NMAX 4096
static mdr_node_f32 n32[MDR_TABLE_NODES(NMAX)];
static mdr_node_f64 n64[MDR_TABLE_NODES(NMAX)];
static mdr_node_q31 nq[MDR_TABLE_NODES(NMAX)];

/* a log-uniform value from one byte, 10^lo ... 10^hi */
static double fz_log8(fz_in *in, double lo, double hi)
{
    return pow(10.0, lo + (hi - lo) * fz_u8(in) / 255.0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    uint8_t kind = (uint8_t)(1 + fz_u8(&in) % 7);
    double L = fz_log8(&in, -9, 0), u = fz_u8(&in) / 255.0, p[3] = {L, 0, 0};
    double E = fz_log8(&in, 3, 12), w = fz_log8(&in, -6, 1), w_adv = w * fz_u8(&in) / 255.0;
    uint8_t mb = fz_u8(&in);
    uint16_t n = (uint16_t)(2u << fz_u8(&in) % 12);
    double xf = 0.05 + 1.95 * fz_u8(&in) / 255.0, x_max, k_m, unit[3];
    mdr_contact_f64 c64;
    mdr_contact_f32 c32;
    mdr_table_f64 t64;
    mdr_table_f32 t32;
    mdr_table_q31 tq;
    mdr_engine_f64 e64;
    mdr_engine_f32 e32;
    mdr_engine_q31 eq;
    mdr_scene_f64 s64;
    mdr_scene_f32 s32;
    mdr_scene_q31 sq;
    mdr_energy_f64 en64;
    mdr_energy_f32 en32;
    int ok32, okq, ops, oks64, oks32, oksq;
    switch (kind) {
    case MDR_PROFILE_CONE:
        p[0] = 0.01 + 1.55 * u;
        break;
    case MDR_PROFILE_POWERLAW:
        p[1] = 0.5 + 7.5 * u;
        p[0] = 0.1 * pow(L, 1 - p[1]);
        break;
    case MDR_PROFILE_SPHERE:
        xf = fmin(xf, 0.99);
        break;
    case MDR_PROFILE_FLATPUNCH:
        xf = fmin(xf, 1.0);
        break;
    case MDR_PROFILE_FLATTIP:
        p[1] = 0.5 * L * u;
        break;
    case MDR_PROFILE_WAVY:
        p[2] = L / 20 * pow(5.0, 2 * u - 1);         /* lambda: R/100 ... R/4 */
        p[1] = p[2] * p[2] / (fz_log8(&in, 0.2, 1.3) * L); /* alpha 1.6 ... 20 */
        break;
    default:
        break;
    }
    x_max = xf * L;
    /* machine: none, or kappa = 2E* x_max/k_m from 2^-4 to 2^16 */
    k_m = mb < 32 ? 0 : 2 * E * x_max / pow(2.0, -4 + 20 * (mb - 32) / 223.0);
    if (mdr_contact_init_f64(&c64, kind, p, E, w) != MDR_OK ||
        mdr_table_init_profile_f64(&t64, n64, n, &c64, x_max) != MDR_OK ||
        mdr_engine_init_f64(&e64, &t64, E, w, w_adv, k_m) != MDR_OK) {
        return 0;
    }
    {
        const float p32[3] = {(float)p[0], (float)p[1], (float)p[2]};
        ok32 = mdr_contact_init_f32(&c32, kind, p32, (float)E, (float)w) == MDR_OK &&
               mdr_table_init_profile_f32(&t32, n32, n, &c32, (float)x_max) == MDR_OK &&
               mdr_engine_init_f32(&e32, &t32, (float)E, (float)w, (float)w_adv, (float)k_m) == MDR_OK;
    }
    oks64 = mdr_scene_init_contact_f64(&s64, &c64, w_adv, k_m, MDR_OUT_ALL, &en64) == MDR_OK;
    oks32 = ok32 && mdr_scene_init_contact_f32(&s32, &c32, (float)w_adv, (float)k_m, MDR_OUT_ALL, &en32) == MDR_OK;
    oksq = oks64 && mdr_scene_init_q31_f64(&sq, &s64, x_max) == MDR_OK;
    okq = mdr_table_q31_from_f64(&tq, nq, &t64) == MDR_OK &&
          mdr_engine_init_q31_f64(&eq, &tq, E, w, w_adv, k_m) == MDR_OK;
#ifdef FZ_DEBUG
    fprintf(stderr, "kind %u p %.17g %.17g %.17g E %.17g w %.17g w_adv %.17g k_m %.17g n %u x_max %.17g f32 %d q31 %d\n",
            (unsigned)kind, p[0], p[1], p[2], E, w, w_adv, k_m, (unsigned)n, x_max, ok32, okq);
#endif
    /* the units of one input: the q31 engine's, or the same sizes */
    if (okq) {
        unit[0] = eq.D0;
        unit[1] = 2 * E * ((double)tq.L + (double)tq.L_lo) * eq.D0;
        unit[2] = eq.Z0;
    } else {
        double gmax = 0;
        int i;
        for (i = 0; i <= n; i++) {
            gmax = fmax(gmax, fabs(n64[i].g));
        }
        unit[0] = gmax + e64.c_w * sqrt(x_max);
        unit[1] = 2 * E * x_max * unit[0];
        unit[2] = unit[0] + (k_m > 0 ? unit[1] / k_m : 0);
    }
    for (ops = 0; ops < 400 && in.n > 0; ops++) {
        uint8_t op = fz_u8(&in), ctl = op & 3u; /* FZ_D, FZ_F, FZ_Z, or 3: clear the flags */
        uint32_t bits = fz_u32(&in);
        int32_t raw = (int32_t)bits;
        double v = raw / 536870912.0 * unit[ctl < 3 ? ctl : 0];
        float vf;
        if (op & 0x80u) {
            memcpy(&vf, &bits, sizeof vf);
            v = (double)vf;
        } else {
            vf = (float)v;
        }
        if (ctl == 3) {
            mdr_engine_clear_flags_f64(&e64);
            mdr_engine_clear_flags_f32(&e32);
            mdr_engine_clear_flags_q31(&eq);
            s64.flags = 0;
            s32.flags = 0;
            (void)mdr_scene_clear_flags_q31(&sq);
            continue;
        }
        {
            mdr_step_f64 o;
            mdr_status st = fz_step_f64(&e64, ctl, v, &o);
#ifdef FZ_DEBUG
            fprintf(stderr, "f64 ctl %u v %.17g: st %d a %.9g d %.9g F %.9g contact %u event %u\n", (unsigned)ctl, v,
                    (int)st, e64.a, e64.d, e64.F, (unsigned)e64.contact, (unsigned)o.event);
#else
            (void)st;
#endif
        }
        if (ok32) {
            mdr_step_f32 o;
            fz_step_f32(&e32, ctl, vf, &o);
        }
        if (oks64) {
            fz_scene_step_f64(&s64, ctl, v);
        }
        if (oks32) {
            fz_scene_step_f32(&s32, ctl, vf);
        }
        if (okq && !(op & 0x80u)) {
            mdr_step_q31 o;
            fz_step_q31(&eq, ctl, raw, &o);
        }
        if (oksq && !(op & 0x80u)) {
            fz_scene_step_q31(&sq, ctl, raw);
        }
    }
    return 0;
}
