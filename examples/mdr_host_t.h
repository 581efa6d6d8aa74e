/* SPDX-License-Identifier: MIT */
/*
 * mdr_host_t.h: the per-arithmetic host helpers shared by the mdr CLI and
 * the Python package (see mdr_host.h). Not a header to include directly:
 * include it once per arithmetic with HOST_T (float or double) and
 * HOST_SFX(name) (name ## _f32 or name ## _f64) defined, after mdr_host.h.
 */

/** Controlled variable of an equilibrium state: F (MDR_CONTROL_LOAD), d
 *  (MDR_CONTROL_GRIPS) or z = d + F/k_m (otherwise). */
static inline HOST_T HOST_SFX(mdr_host_control_of)(uint8_t control, double k_m,
                                                   const HOST_SFX(mdr_eqstate) *e)
{
    if (control == MDR_CONTROL_LOAD) {
        return e->F;
    }
    if (control == MDR_CONTROL_GRIPS) {
        return e->d;
    }
    return e->d + e->F / (HOST_T)k_m;
}

/**
 * @brief Default table extent for a cycle along a path of the controlled
 *        variable: 1.25 x the radius where the equilibrium curve (work w,
 *        the widest of every approach branch) reaches the path's largest
 *        value, found by doubling from mdr_default_start() (at most 200
 *        doublings); capped by the profile's domain (flat punch: a0, sphere:
 *        0.999 R).
 * @param c        an initialised contact
 * @param control  MDR_CONTROL_* of the path
 * @param k_m      machine stiffness [N/m] (MDR_CONTROL_MACHINE)
 * @param path     npath >= 1 values of the controlled variable [m or N]
 * @param[out] a_max  [m], written on MDR_OK only
 * @return MDR_OK or the status of mdr_default_start() / mdr_eq()
 */
static inline mdr_status HOST_SFX(mdr_host_extent)(const HOST_SFX(mdr_contact) *c, uint8_t control,
                                                   double k_m, const double *path, long npath,
                                                   HOST_T *a_max)
{
    HOST_T a, cap = (HOST_T)1e30, umax = (HOST_T)path[0];
    long i;
    mdr_status st;
    for (i = 1; i < npath; i++) {
        umax = (HOST_T)path[i] > umax ? (HOST_T)path[i] : umax;
    }
    if (c->kind == MDR_PROFILE_FLATPUNCH) {
        *a_max = c->p[0];
        return MDR_OK;
    }
    if (c->kind == MDR_PROFILE_SPHERE) {
        cap = (HOST_T)0.999 * c->p[0];
    }
    st = HOST_SFX(mdr_default_start)(c, &a);
    if (st != MDR_OK) {
        return st;
    }
    for (i = 0; i < 200 && a < cap; i++) {
        HOST_SFX(mdr_eqstate) e;
        st = HOST_SFX(mdr_eq)(c, a, &e);
        if (st != MDR_OK) {
            return st;
        }
        if (HOST_SFX(mdr_host_control_of)(control, k_m, &e) >= umax) {
            break;
        }
        a *= 2;
    }
    a *= (HOST_T)1.25;
    *a_max = a < cap ? a : cap;
    return MDR_OK;
}

/** @brief A step record in double (exact: every field widened). */
static inline void HOST_SFX(mdr_host_widen)(const HOST_SFX(mdr_step) *s, mdr_step_f64 *o)
{
    o->z = (double)s->z;
    o->d = (double)s->d;
    o->F = (double)s->F;
    o->a = (double)s->a;
    o->a0 = (double)s->a0;
    o->d0 = (double)s->d0;
    o->F0 = (double)s->F0;
    o->a1 = (double)s->a1;
    o->d1 = (double)s->d1;
    o->F1 = (double)s->F1;
    o->event = s->event;
    o->jumps = s->jumps;
}

/**
 * @brief The contact of a sampled gap profile f(r_i) (a measured or worn
 *        tip) from radii and interval slopes given in double, as the CLI
 *        (--profile table) and the Python package (Engine.from_tip) make it,
 *        so that both build the same spring table from it: r and s converted
 *        to the arithmetic into buf (the contact points to it), then
 *        mdr_contact_init_table(). Form the slopes in double from the
 *        heights (tip_slopes(), examples/tip_csv.h): in float the difference
 *        of two heights loses their offset's digits.
 * @param r    m radii [m] (r[0] = 0, strictly increasing)
 * @param s    m - 1 interval slopes (f[j+1] - f[j])/(r[j+1] - r[j])
 * @param m    samples, MDR_TABLE_MIN_POINTS .. 65535
 * @param buf  caller storage of 2 m values, kept while the contact is used
 * @return MDR_E_OVERFLOW (a finite r or s beyond the arithmetic's range:
 *         nothing converted to inf), or the status of
 *         mdr_contact_init_table()
 */
static inline mdr_status HOST_SFX(mdr_host_tip_contact)(HOST_SFX(mdr_contact) *c, const double *r,
                                                       const double *s, uint16_t m, HOST_T E, HOST_T w,
                                                       HOST_T *buf)
{
    /* the arithmetic's largest value (the comparison is of one type with
     * itself in the f32 instance) */
    const double max = sizeof(HOST_T) == sizeof(float) ? (double)FLT_MAX : DBL_MAX; /* NOLINT(misc-redundant-expression) */
    uint16_t i;
    for (i = 0; i < m; i++) {
        const double v[2] = {r[i], i + 1 < m ? s[i] : 0.0};
        int k;
        for (k = 0; k < 2; k++) {
            if ((v[k] > max || v[k] < -max) && v[k] - v[k] == 0.0) {
                return MDR_E_OVERFLOW;
            }
        }
        buf[i] = (HOST_T)v[0];
        buf[m + i] = (HOST_T)v[1];
    }
    return HOST_SFX(mdr_contact_init_table)(c, buf, buf + m, m, E, w);
}
