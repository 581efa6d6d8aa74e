/* SPDX-License-Identifier: MIT */
/*
 * mdr_py.c: the C side of the Python package (see mdr_py.h). The loops
 * over points are instantiated per floating arithmetic from mdr_py_t.inc;
 * the engines of the three arithmetics share one tick loop, which steps
 * exactly as `mdr cycle` does (the same path values, conversions and q31
 * units: examples/mdr_host.h).
 */
#include <float.h>
#include <stdlib.h>

#include "mdr_py.h"
#include "tip_csv.h"

#define MDR_TEMPLATE "mdr_py_t.inc"
#include "mdr_each_arith.h"

size_t mdrpy_fit_work_len(size_t n)
{
    const size_t max = (size_t)-1;
    if (n > max / 4u) {
        return 0;
    }
    return 2u * n + MDR_FIT_WORK_LEN(n);
}

double mdrpy_f32_eq_max(void)
{
    return MDR_HOST_F32_EQ_MAX;
}

double mdrpy_f32_answer_max(void)
{
    return MDR_HOST_F32_ANSWER_MAX;
}

double mdrpy_f32_slope_max(void)
{
    return MDR_HOST_F32_SLOPE_MAX;
}

double mdrpy_f32_crit_max(void)
{
    return MDR_HOST_F32_CRIT_MAX;
}

double mdrpy_f32_fit_max(void)
{
    return MDR_HOST_F32_FIT_MAX;
}

double mdrpy_f32_fit_err(void)
{
    return MDR_HOST_F32_FIT_ERR;
}

int mdrpy_f32_fit_check(const double p32[3], const double e32[3], const double p64[3], const double e64[3], int n,
                        int *which, double *x)
{
    return mdr_host_f32_fit_check(p32, e32, p64, e64, n, which, x);
}

const char *mdrpy_f32_fit_which(int which)
{
    return mdr_host_f32_fit_which(which);
}

/* v held by float exactly (its rounding is v): where every input is, the
 * roundings are the values and mdr_host_f32_eq_change() is 0 */
static int mdrpy_is_float(double v)
{
    return mdr_host_in_float(v) && mdr_host_f32_round(v) == v;
}

/* The pair of the f32 checks: a sampled tip's (r not NULL: m radii, the
 * slopes s, their conversions in *rd, malloc'd here, the caller frees it)
 * or an analytic profile's (kind, p). -1: no memory; 0: no check (a value
 * beyond float); 1: made. */
static int mdrpy_f32_pair(mdr_host_f32_eq_pair *x, uint8_t kind, const double p[3], const double *r, const double *s,
                          uint16_t m, double E, double w, double **rd)
{
    *rd = NULL;
    if (r == NULL) {
        return mdr_host_f32_eq_pair_init(x, kind, p, E, w);
    }
    *rd = malloc(2 * (size_t)m * sizeof **rd);
    if (*rd == NULL) {
        return -1;
    }
    return mdr_host_f32_eq_pair_init_tip(x, r, s, m, E, w, *rd);
}

/* every input but the points already a float (their roundings are the
 * values: mdr_host_f32_eq_change() is 0 at a point that is one too) */
static int mdrpy_f32_inputs_exact(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m,
                                  double E, double w)
{
    int exact = mdrpy_is_float(E) && mdrpy_is_float(w);
    uint16_t i;
    (void)kind;
    if (r == NULL) {
        return exact && mdrpy_is_float(p[0]) && mdrpy_is_float(p[1]) && mdrpy_is_float(p[2]);
    }
    for (i = 0; i < m; i++) {
        exact = exact && mdrpy_is_float(r[i]) && (i + 1 == m || mdrpy_is_float(s[i]));
    }
    return exact;
}

size_t mdrpy_f32_eq_check(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m, double E,
                          double w, size_t n, const double *a, const double *d, size_t k, const double *d32,
                          const double *F32, const double *dd32, const double *dF32, const double *K32, int *what,
                          double *value)
{
    mdr_host_f32_eq_pair x;
    double *rd;
    size_t i;
    const int exact = mdrpy_f32_inputs_exact(kind, p, r, s, m, E, w);
    const int ok = mdrpy_f32_pair(&x, kind, p, r, s, m, E, w, &rd);
    if (ok < 0) {
        *what = 0;
        *value = DBL_MAX;
        return 0; /* (refused: the check cannot be made) */
    }
    for (i = 0; ok && i < n && i <= k; i++) {
        /* (where every input is a float the change is 0: not computed) */
        const int rounded = !(exact && mdrpy_is_float(a[i]) && (d == NULL || mdrpy_is_float(d[i])));
        const double ans[2] = {i < k ? d32[i] : 0.0, i < k ? F32[i] : 0.0};
        const double dv[2] = {dd32 != NULL && i < k ? dd32[i] : 0.0, dF32 != NULL && i < k ? dF32[i] : 0.0};
        double ch = 0.0, er = 0.0;
        int q = 0;
        mdr_host_f32_eq_pair_check(&x, a[i], d != NULL ? &d[i] : NULL, rounded ? &ch : NULL, ans,
                                   dd32 != NULL ? dv : NULL, K32 != NULL && i < k ? &K32[i] : NULL,
                                   i < k ? &er : NULL, &q);
        if (ch > MDR_HOST_F32_EQ_MAX || er > mdr_host_f32_max(q)) {
            /* (the rounding's first, as the CLI's order; an answer's d or
             * F: 1, its dd/da 2, dF/da 3) */
            *what = ch > MDR_HOST_F32_EQ_MAX ? 0 : q < 2 ? 1 : q; /* (4: a state's K_I) */
            *value = *what == 0 ? ch : er;
            break;
        }
        if (i == k) {
            i = n; /* (not answered: the library's refusal at k stands) */
            break;
        }
    }
    free(rd);
    return ok && i < n ? i : n;
}

/* the f32 stresses s32[i] at rr[i] in the states (a[i], d[i]) */
size_t mdrpy_f32_stress_wrong(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m,
                              double E, double w, size_t n, const double *a, const double *d, const double *rr,
                              const double *s32, double *err)
{
    mdr_host_f32_eq_pair x;
    double *rd;
    size_t i = n;
    const int ok = mdrpy_f32_pair(&x, kind, p, r, s, m, E, w, &rd);
    if (ok < 0) {
        *err = DBL_MAX;
        return 0; /* (refused: the check cannot be made) */
    }
    if (ok) {
        for (i = 0; i < n; i++) {
            const double er = mdr_host_f32_stress_err(&x, a[i], d != NULL ? &d[i] : NULL, rr[i], s32[i]);
            if (er > MDR_HOST_F32_ANSWER_MAX) {
                *err = er;
                break;
            }
        }
    }
    free(rd);
    return i;
}

double mdrpy_f32_crit_wrong(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m, double E,
                            double w, uint8_t control, double k_m, const double *a0, double a32, double d32, double F32,
                            double Fm32)
{
    mdr_host_f32_eq_pair x;
    double *rd, er = 0.0;
    const int ok = mdrpy_f32_pair(&x, kind, p, r, s, m, E, w, &rd);
    if (ok < 0) {
        return DBL_MAX; /* (refused: the check cannot be made) */
    }
    if (ok) {
        er = mdr_host_f32_crit_err(&x, control, k_m, a0, a32, d32, F32, Fm32);
    }
    free(rd);
    return er;
}

/* the q31 table from the f64 one and the double init, as `mdr cycle` */
static mdr_status mdrpy_init(mdrpy_engine *x, mdr_node_q31 *nq)
{
    mdr_status st;
    if (x->arith == MDRPY_F32) {
        return mdrpy_engine_init_f32(x);
    }
    if (x->arith == MDRPY_F64) {
        return mdrpy_engine_init_f64(x);
    }
    if (nq != NULL) {
        st = mdr_table_q31_from_f64(&x->q.t, nq, &x->table_f64);
        if (st != MDR_OK) {
            return st;
        }
    }
    st = mdr_engine_init_q31_f64(&x->q.e, &x->q.t, x->E, x->w, x->w_adv, x->k_m);
    if (st == MDR_OK) {
        mdr_host_q31_units(&x->q, x->E);
    }
    return st;
}

/* the material of an engine, then its init (the engine points to the
 * table inside x: x is built in place, never copied) */
static mdr_status mdrpy_finish(mdrpy_engine *x, double E, double w, double w_adv, double k_m,
                               mdr_node_q31 *nq)
{
    x->E = E;
    x->w = w;
    x->w_adv = w_adv;
    x->k_m = k_m;
    return mdrpy_init(x, nq);
}

mdr_status mdrpy_extent(uint8_t arith, uint8_t kind, const double p[3], double E, double w,
                        uint8_t control, double k_m, const double *path, size_t npath,
                        double *a_max)
{
    if (p == NULL || path == NULL || a_max == NULL || npath == 0) {
        return MDR_E_NULL;
    }
    if (arith == MDRPY_F32) {
        return mdrpy_extent_f32(kind, p, E, w, control, k_m, path, npath, a_max);
    }
    return mdrpy_extent_f64(kind, p, E, w, control, k_m, path, npath, a_max);
}

mdr_status mdrpy_extent_q31(uint8_t kind, const double p[3], double E, double w, double w_adv,
                            uint8_t control, double k_m, uint16_t springs, const double *path,
                            size_t npath, long steps, double *a_max)
{
    mdr_contact_f64 c;
    mdr_node_f64 *nodes;
    mdr_node_q31 *qnodes;
    mdr_host_q31 *q;
    mdr_status st;
    if (p == NULL || path == NULL || a_max == NULL || npath < 2) {
        return MDR_E_NULL;
    }
    if (steps < 1) {
        return MDR_E_PARAM;
    }
    st = mdrpy_contact_f64(&c, kind, p, E, w);
    if (st != MDR_OK) {
        return st;
    }
    nodes = malloc(MDR_TABLE_NODES(springs) * sizeof *nodes);
    qnodes = malloc(MDR_TABLE_NODES(springs) * sizeof *qnodes);
    q = malloc(sizeof *q);
    st = MDR_E_SIZE;
    if (nodes != NULL && qnodes != NULL && q != NULL) {
        st = mdr_host_extent_q31_f64(&c, springs, E, w, w_adv, k_m, control, path, (long)npath, steps, nodes,
                                     qnodes, q, a_max);
    }
    free(q);
    free(qnodes);
    free(nodes);
    return st;
}

mdr_status mdrpy_engine_profile(mdrpy_engine *x, uint8_t arith, uint8_t kind, const double p[3],
                                double E, double w, double w_adv, double k_m, uint16_t springs,
                                double a_max, mdr_node_f32 *n32, mdr_node_f64 *n64,
                                mdr_node_q31 *nq)
{
    mdr_status st;
    if (x == NULL || p == NULL || arith > MDRPY_Q31 || (arith == MDRPY_F32 ? n32 == NULL : n64 == NULL) ||
        (arith == MDRPY_Q31 && nq == NULL)) {
        return MDR_E_NULL;
    }
    x->arith = arith;
    if (arith == MDRPY_F32) {
        st = mdrpy_table_profile_f32(x, kind, p, E, w, springs, a_max, n32);
    } else {
        st = mdrpy_table_profile_f64(x, kind, p, E, w, springs, a_max, n64);
    }
    if (st != MDR_OK) {
        return st;
    }
    return mdrpy_finish(x, E, w, w_adv, k_m, nq);
}

mdr_status mdrpy_engine_tip(mdrpy_engine *x, uint8_t arith, const double *r, const double *f,
                            uint16_t m, double E, double w, double w_adv, double k_m,
                            uint16_t springs, mdr_node_f32 *n32, mdr_node_f64 *n64,
                            mdr_node_q31 *nq)
{
    mdr_status st;
    if (x == NULL || r == NULL || f == NULL || arith > MDRPY_Q31 ||
        (arith == MDRPY_F32 ? n32 == NULL : n64 == NULL) || (arith == MDRPY_Q31 && nq == NULL)) {
        return MDR_E_NULL;
    }
    x->arith = arith;
    if (arith == MDRPY_F32) {
        st = mdrpy_table_tip_f32(x, r, f, m, E, w, springs, n32);
    } else {
        st = mdrpy_table_tip_f64(x, r, f, m, E, w, springs, n64);
    }
    if (st != MDR_OK) {
        return st;
    }
    return mdrpy_finish(x, E, w, w_adv, k_m, nq);
}

mdr_status mdrpy_engine_reset(mdrpy_engine *x)
{
    if (x == NULL) {
        return MDR_E_NULL;
    }
    return mdrpy_init(x, NULL);
}

void mdrpy_engine_info(const mdrpy_engine *x, mdrpy_info *o)
{
    o->L = o->D0 = o->F0 = o->Z0 = 0;
    if (x->arith == MDRPY_F32) {
        mdrpy_info_f32(x, o);
    } else {
        mdrpy_info_f64(x, o);
    }
    if (x->arith == MDRPY_Q31) {
        const mdr_host_q31 *q = &x->q;
        o->a = q->e.a * (q->L / 1073741824.0);
        o->d = q->e.d * (q->D0 / 536870912.0);
        o->F = q->e.F * (q->F0 / 536870912.0);
        o->dissipated = mdr_host_q31_energy(q, q->e.en.dissipated);
        o->last_cycle = mdr_host_q31_energy(q, q->e.en.last_cycle);
        o->cycles = q->e.en.cycles;
        o->contact = q->e.contact;
        o->flags = q->e.flags;
        o->L = q->L;
        o->D0 = q->D0;
        o->F0 = q->F0;
        o->Z0 = q->Z0;
    }
}

mdr_status mdrpy_check_path(const mdrpy_engine *x, uint8_t control, const double *path,
                            size_t npath, size_t *bad)
{
    size_t i;
    if (path == NULL || bad == NULL) {
        return MDR_E_NULL;
    }
    if (control != MDR_CONTROL_LOAD && control != MDR_CONTROL_GRIPS && control != MDR_CONTROL_MACHINE) {
        return MDR_E_CONTROL;
    }
    for (i = 0; i < npath; i++) {
        const double v = path[i];
        mdr_status st = MDR_OK;
        if (!(v - v == 0.0)) {
            st = MDR_E_NONFINITE;
        } else if (x == NULL) {
            st = MDR_OK;
        } else if (x->arith == MDRPY_F32 && (v > (double)FLT_MAX || v < -(double)FLT_MAX)) {
            st = MDR_E_OVERFLOW;
        } else if (x->arith == MDRPY_Q31) {
            const mdr_host_q31 *q = &x->q;
            int32_t raw;
            st = mdr_host_q31_raw(v, mdr_host_q31_unit(q, control), &raw);
        }
        if (st != MDR_OK) {
            *bad = i;
            return st;
        }
    }
    if (x != NULL && x->arith == MDRPY_Q31) {
        /* a nonzero vertex that rounds to 0 LSB: the check of `mdr cycle`
         * (mdr_host_q31_lost()); it ran as a silent zero here */
        const long k = mdr_host_q31_lost(path, (long)npath, mdr_host_q31_unit(&x->q, control));
        if (k >= 0) {
            *bad = (size_t)k;
            return MDR_E_OVERFLOW;
        }
    }
    return MDR_OK;
}

mdr_status mdrpy_run(mdrpy_engine *x, uint8_t control, const double *path, size_t npath, long steps,
                     size_t tick0, size_t nticks, double *z, double *d, double *F, double *a,
                     uint8_t *event, size_t ev_cap, size_t *ev_n, size_t *ev_step,
                     uint8_t *ev_code, double *ev_val, size_t *done)
{
    const int store = z != NULL && d != NULL && F != NULL && a != NULL;
    size_t i;
    if (x == NULL || path == NULL || ev_n == NULL || done == NULL ||
        (ev_cap > 0 && (ev_step == NULL || ev_code == NULL || ev_val == NULL))) {
        return MDR_E_NULL;
    }
    if (npath < 2 || steps < 1) {
        return MDR_E_PARAM;
    }
    if (control != MDR_CONTROL_LOAD && control != MDR_CONTROL_GRIPS && control != MDR_CONTROL_MACHINE) {
        return MDR_E_CONTROL;
    }
    for (i = 0; i < nticks; i++) {
        const size_t t = tick0 + i;
        /* tick 0 is path[0]; then steps ticks per segment (j = 1 ... steps) */
        const long seg = t == 0 ? 0 : (long)((t - 1) / (size_t)steps);
        const long j = t == 0 ? 0 : (long)((t - 1) % (size_t)steps) + 1;
        mdr_step_f64 r;
        mdr_status st;
        double v;
        if ((size_t)seg + 1 >= npath) {
            *done = i;
            return MDR_E_PARAM; /* beyond the path's last tick */
        }
        if (ev_cap > 0 && *ev_n == ev_cap) {
            *done = i;
            return MDRPY_MORE;
        }
        v = mdr_host_path_value(path, steps, seg, j);
        if (x->arith == MDRPY_F32) {
            st = mdrpy_tick_f32(x, control, v, &r);
        } else if (x->arith == MDRPY_F64) {
            st = mdrpy_tick_f64(x, control, v, &r);
        } else {
            /* a tick whose results saturate is refused and undone: the
             * engine as after the last tick taken (the docstring's promise).
             * Tested per tick with the sticky flag cleared first: tested
             * against the flag as the run found it, a run after one refused
             * took every saturated tick (d 93 % off, a saturated energy sum
             * read 0 J; helper-30, stop 57) */
            const mdr_host_q31 keep = x->q;
            x->q.e.flags = (uint8_t)(x->q.e.flags & ~MDR_FLAG_SAT);
            st = mdr_host_q31_step(&x->q, control, v, 1, &r); /* values beyond the range refused */
            if (st == MDR_OK && (x->q.e.flags & MDR_FLAG_SAT)) {
                st = MDR_E_OVERFLOW; /* a result saturated (MDR_FLAG_SAT) */
            }
            if (st != MDR_OK) {
                x->q = keep;
            } else {
                x->q.e.flags = (uint8_t)(x->q.e.flags | (keep.e.flags & MDR_FLAG_SAT));
            }
        }
        if (st != MDR_OK) {
            *done = i;
            return st;
        }
        if (store) {
            z[i] = r.z;
            d[i] = r.d;
            F[i] = r.F;
            a[i] = r.a;
        }
        if (event != NULL) {
            event[i] = r.event;
        }
        if (r.event != MDR_EV_NONE && ev_cap > 0) {
            const size_t k = (*ev_n)++;
            ev_step[k] = t;
            ev_code[2 * k] = r.event;
            ev_code[2 * k + 1] = r.jumps;
            ev_val[MDRPY_EV_N * k + MDRPY_EV_A0] = r.a0;
            ev_val[MDRPY_EV_N * k + MDRPY_EV_D0] = r.d0;
            ev_val[MDRPY_EV_N * k + MDRPY_EV_F0] = r.F0;
            ev_val[MDRPY_EV_N * k + MDRPY_EV_A1] = r.a1;
            ev_val[MDRPY_EV_N * k + MDRPY_EV_D1] = r.d1;
            ev_val[MDRPY_EV_N * k + MDRPY_EV_F1] = r.F1;
        }
    }
    *done = nticks;
    return MDR_OK;
}
