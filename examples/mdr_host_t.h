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

/** The force of the state (e->a, d), e the equilibrium state at that
 *  radius: mdr_host_state_F() with G(a) from the profile (into *F). */
static inline mdr_status HOST_SFX(mdr_host_state_F)(const HOST_SFX(mdr_contact) *c, const HOST_SFX(mdr_eqstate) *e,
                                                    HOST_T d, HOST_T *F)
{
    HOST_T G;
    const mdr_status st = HOST_SFX(mdr_profile_eval)(c, e->a, NULL, NULL, &G);
    if (st == MDR_OK) {
        const double v = mdr_host_state_F((double)c->E, (double)e->a, (double)d, (double)G, (double)e->F, (double)e->d,
                                          HOST_SFX(mdr_host_tmin)());
        /* (beyond the arithmetic's range: infinite, which the callers
         * refuse; the conversion itself would be undefined) */
        *F = (HOST_T)(!(fabs(v) <= HOST_SFX(mdr_host_tmax)()) ? v * HUGE_VAL : v);
    }
    return st;
}

/** The controlled variable on the equilibrium curve at radius a (into *v). */
static inline mdr_status HOST_SFX(mdr_host_control_at)(const HOST_SFX(mdr_contact) *c, uint8_t control,
                                                       double k_m, HOST_T a, HOST_T *v)
{
    HOST_SFX(mdr_eqstate) e;
    mdr_status st = HOST_SFX(mdr_eq)(c, a, &e);
    if (st == MDR_OK) {
        *v = HOST_SFX(mdr_host_control_of)(control, k_m, &e);
    }
    return st;
}

/** Bisect c(lo) < umax <= c(hi) to hi - lo <= 2^-20 hi (at most 64
 *  halvings); returns the bracket's upper end (an evaluation that fails
 *  stops there: hi stays a radius where the curve is at or above umax). */
static inline HOST_T HOST_SFX(mdr_host_bisect)(const HOST_SFX(mdr_contact) *c, uint8_t control, double k_m,
                                               HOST_T umax, HOST_T lo, HOST_T hi)
{
    int i;
    for (i = 0; i < 64 && hi - lo > hi * (HOST_T)9.5367431640625e-7; i++) {
        const HOST_T mid = lo + (hi - lo) / (HOST_T)2;
        HOST_T v;
        if (HOST_SFX(mdr_host_control_at)(c, control, k_m, mid, &v) != MDR_OK) {
            break;
        }
        if (v >= umax) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return hi;
}

/**
 * @brief Default table extent for a cycle along a path of the controlled
 *        variable: 1.25 x the radius a* where the equilibrium curve (work
 *        w, the widest of every approach branch: w_adv <= w gives a larger
 *        d, F and z at every radius) reaches the path's largest value,
 *        umax. No approach, jump or re-approach along the path takes the
 *        edge beyond a*. a* is bracketed from mdr_default_start() by
 *        doubling while the curve lies below umax (at most 200 doublings)
 *        or halving while it lies at or above it (at most 60 halvings),
 *        then bisected to a relative width of 2^-20: the extent is 1.25 a*
 *        to within 1e-6 (above it: the bracket's upper end). The wavy
 *        curve, which may cross umax several times, is scanned below that
 *        crossing at eight cells per wavelength (at most 65536 cells) for
 *        its first crossing after it has been below umax. Capped by the profile's domain
 *        (flat punch: a0, sphere: 0.999 R). A path that never reaches the
 *        curve's rising branch (nothing below umax within 2^-60 of the
 *        start: the body stays apart) gets 1.25 x the start.
 * @param c        an initialised contact
 * @param control  MDR_CONTROL_* of the path
 * @param k_m      machine stiffness [N/m] (MDR_CONTROL_MACHINE)
 * @param path     npath >= 1 values of the controlled variable [m or N]
 * @param[out] a_max  [m], written on MDR_OK only
 * @return MDR_OK or the status of mdr_default_start() / mdr_eq() (above
 *         the start)
 */
static inline mdr_status HOST_SFX(mdr_host_extent)(const HOST_SFX(mdr_contact) *c, uint8_t control,
                                                   double k_m, const double *path, long npath,
                                                   HOST_T *a_max)
{
    HOST_T a, lo, hi, v, cap = (HOST_T)1e30, umax = (HOST_T)path[0];
    long i;
    int found = 0;
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
    a = a < cap ? a : cap;
    st = HOST_SFX(mdr_host_control_at)(c, control, k_m, a, &v);
    if (st != MDR_OK) {
        return st;
    }
    lo = hi = a;
    if (v < umax) {
        /* up: double until the curve reaches umax (or the cap) */
        for (i = 0; i < 200 && !found; i++) {
            hi = (HOST_T)2 * lo < cap ? (HOST_T)2 * lo : cap;
            st = HOST_SFX(mdr_host_control_at)(c, control, k_m, hi, &v);
            if (st != MDR_OK) {
                return st;
            }
            if (v >= umax) {
                found = 1;
            } else if (hi >= cap) {
                *a_max = cap; /* the path goes beyond the domain's end */
                return MDR_OK;
            } else {
                lo = hi;
            }
        }
        if (!found) {
            a = (HOST_T)1.25 * hi;
            *a_max = a < cap ? a : cap;
            return MDR_OK;
        }
    } else {
        /* down: halve until the curve lies below umax */
        for (i = 0; i < 60 && !found; i++) {
            lo = hi / (HOST_T)2;
            if (HOST_SFX(mdr_host_control_at)(c, control, k_m, lo, &v) != MDR_OK) {
                break;
            }
            if (v < umax) {
                found = 1;
            } else {
                hi = lo;
            }
        }
        if (!found) {
            a = (HOST_T)1.25 * a;
            *a_max = a < cap ? a : cap;
            return MDR_OK;
        }
    }
    hi = HOST_SFX(mdr_host_bisect)(c, control, k_m, umax, lo, hi);
    if (c->kind == MDR_PROFILE_WAVY && c->p[1] > (HOST_T)0) {
        /* the wavy curve may cross umax several times below hi: the first
         * crossing after the curve has been below umax, from a scan of
         * eight cells per wavelength (at most 65536 cells: a narrower
         * excursion above umax that the scan steps over leaves a later
         * crossing, a larger extent) */
        const HOST_T cell = c->p[2] / (HOST_T)8 > hi / (HOST_T)65536 ? c->p[2] / (HOST_T)8 : hi / (HOST_T)65536;
        HOST_T prev = (HOST_T)0;
        int below = 0;
        for (i = 1; (HOST_T)i * cell < hi; i++) {
            const HOST_T x = (HOST_T)i * cell;
            if (HOST_SFX(mdr_host_control_at)(c, control, k_m, x, &v) != MDR_OK) {
                break;
            }
            if (v < umax) {
                below = 1;
                prev = x;
            } else if (below) {
                hi = HOST_SFX(mdr_host_bisect)(c, control, k_m, umax, prev, x);
                break;
            }
        }
    }
    a = (HOST_T)1.25 * hi;
    *a_max = a < cap ? a : cap;
    return MDR_OK;
}

/**
 * @brief Whether a q31 engine exists on a float table and takes a whole path
 *        as its steps would: the q31 table (mdr_table_q31_from()), the
 *        engine (mdr_engine_init_q31()) and its SI units in *q, then every
 *        tick's value (mdr_host_path_value()) converted as the step converts
 *        it (mdr_host_q31_raw(): within +-2 units of D0, F0 or Z0) and, under
 *        a machine, at or above the engine's z_min (a separated machine's
 *        depth d = z 2^sz, Q2.29 of D0, fits the step's int32 there; below
 *        it, the free body's depth saturates).
 * @param tab     the float table; qnodes: MDR_TABLE_NODES(tab->n) nodes
 * @param steps   ticks per segment of the path (>= 1)
 * @return MDR_OK (q is ready); the status of mdr_table_q31_from() or
 *         mdr_engine_init_q31(); MDR_E_OVERFLOW (a tick beyond the range);
 *         MDR_E_NONFINITE (a tick NaN or inf)
 */
static inline mdr_status HOST_SFX(mdr_host_q31_fits)(const HOST_SFX(mdr_table) *tab, mdr_node_q31 *qnodes,
                                                     mdr_host_q31 *q, double E, double w, double w_adv,
                                                     double k_m, uint8_t control, const double *path,
                                                     long npath, long steps)
{
    const int machine = control != MDR_CONTROL_GRIPS && control != MDR_CONTROL_LOAD;
    long seg, tick;
    mdr_status st = HOST_SFX(mdr_table_q31_from)(&q->t, qnodes, tab);
    if (st == MDR_OK) {
        st = HOST_SFX(mdr_engine_init_q31)(&q->e, &q->t, (HOST_T)E, (HOST_T)w, (HOST_T)w_adv, (HOST_T)k_m);
    }
    if (st != MDR_OK) {
        return st;
    }
    mdr_host_q31_units(q, E);
    return mdr_host_q31_path(path, npath, steps, mdr_host_q31_unit(q, control),
                             machine && q->e.machine ? q->e.z_min : INT32_MIN, &seg, &tick);
}

/** The number of doublings of the default extent the q31 rule tries. */
#define MDR_HOST_Q31_WIDEN 8

/**
 * @brief Default table extent of a q31 cycle: mdr_host_extent(), doubled
 *        (at most MDR_HOST_Q31_WIDEN times) until the q31 form of the table
 *        of n springs to that extent exists and the whole path fits its
 *        ranges (mdr_host_q31_fits()). The q31 units grow with the table
 *        (D0 with max|g|, F0 = 2 E* L D0, Z0 = 2^sz D0): a table tight
 *        around the path can have a profile too steep for its q31 form (a
 *        strongly wavy one) or units too small for a path driven far past
 *        the pull-off. The doublings stay within the profile's domain (flat
 *        punch: none; sphere: below 0.999 R) and stop at the first refusal
 *        other than MDR_E_OVERFLOW (a table or engine init, e.g. an adhesion
 *        below MDR_Q31_ADH_LSB of a wider table's force unit). When no
 *        extent fits, the undoubled one (the caller's checks then name why).
 *        An explicit extent is the caller's and is never changed.
 * @param nodes   scratch of MDR_TABLE_NODES(n) float nodes; qnodes of as
 *                many q31 nodes; q: scratch engine (all overwritten)
 * @param[out] a_max  [m], written on MDR_OK only
 * @return MDR_OK or the status of mdr_host_extent()
 */
static inline mdr_status HOST_SFX(mdr_host_extent_q31)(const HOST_SFX(mdr_contact) *c, uint16_t n, double E,
                                                       double w, double w_adv, double k_m, uint8_t control,
                                                       const double *path, long npath, long steps,
                                                       HOST_SFX(mdr_node) *nodes, mdr_node_q31 *qnodes,
                                                       mdr_host_q31 *q, HOST_T *a_max)
{
    HOST_T a0, a;
    int k;
    mdr_status st = HOST_SFX(mdr_host_extent)(c, control, k_m, path, npath, &a0);
    if (st != MDR_OK) {
        return st;
    }
    a = a0;
    for (k = 0; k <= MDR_HOST_Q31_WIDEN; k++) {
        HOST_SFX(mdr_table) tab;
        a = k > 0 ? (HOST_T)2 * a : a; /* a0 2^k (exact) */
        if (k > 0 && (c->kind == MDR_PROFILE_FLATPUNCH ||
                      (c->kind == MDR_PROFILE_SPHERE && !(a < (HOST_T)0.999 * c->p[0])))) {
            break;
        }
        st = HOST_SFX(mdr_table_init_profile)(&tab, nodes, n, c, a);
        if (st != MDR_OK) {
            break;
        }
        st = HOST_SFX(mdr_host_q31_fits)(&tab, qnodes, q, E, w, w_adv, k_m, control, path, npath, steps);
        if (st == MDR_OK) {
            *a_max = a;
            return MDR_OK;
        }
        if (st != MDR_E_OVERFLOW) {
            break;
        }
    }
    *a_max = a0;
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
