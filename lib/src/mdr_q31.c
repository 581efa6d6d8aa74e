/*
 * mdr_q31.c: the step of the fixed-point spring engine. Integer arithmetic
 * only (int32 values, int64 products and quotients): no float type appears
 * in this file, so a build of it calls no soft-float helper (checked by
 * `make cross`). Contract and formats: lib/include/mdr_q31.h; model and
 * state machine: lib/include/mdr_engine_t.h and lib/src/mdr_engine_t.c,
 * whose algorithm this file follows step for step in normalised units:
 *
 *   x = a/L = t^2, D = g(x) - c t, F/F0 = x D - G, and along an edge branch
 *   U = al D + ka (x D - G) with (al, ka) = (1, 0) fixed grips (U = d/D0),
 *   (0, 1) fixed load (U = F/F0) and (1, kappa)/(1 + kappa) for the machine
 *   (U = z/((1 + kappa) D0)): every control lies in |U| <= 2.
 *
 * Inside spring k, with e = (x - x_k) n in [0, 1] (seed 4.46 tabulated, see
 * mdr_node_q31): g = g_k + e dg + b e (1 - e), dg = s_k / n (the spring's
 * mean slope, stored), G = G_k + (e/n) (g_k + e (dg/2 + b (1/2 - e/3))),
 * g' = s_k + n b (1 - 2e) (per unit x = a/L). dU/dt = al (2 t g' - c)
 * + ka x (2 t g' - 3 c) (seed 4.25/4.26 with da/dt = 2t); the Newton step is
 * dt = (U - u) / (dU/dt).
 *
 * Rounding: every rescaling of a product rounds to nearest (mdr_q_rs);
 * quotients truncate. Error per evaluation of g, G, U: a few units in the
 * last place of Q2.29 (2^-29 of D0, F0); the root is located to one ulp of
 * t (Q1.30) or where the Newton correction rounds to zero.
 */
#include <stddef.h>

#include "mdr.h"
#include "mdr_hooks.h"

#if MDR_CFG_Q31 /* to the end of the file */

#define MDR_Q_ITER 64 /* root / fold iteration cap (bisection alone needs 31) */
#define MDR_Q_UTOL 4  /* rounding bound of mdr_q_U, LSB of Q2.29 */

/* v / 2^s rounded to nearest (ties toward +inf), s >= 1, |v| < 2^62 (0 for
 * s >= 63). Written without >> of a negative value (implementation-defined
 * in C99): for r < 0, ~(~r >> s) is floor(r / 2^s). */
MDR_INLINE MDR_STEP_FN int64_t mdr_q_rs(int64_t v, unsigned s)
{
    int64_t r;
    if (s >= 63u) {
        return 0;
    }
    r = v + ((int64_t)1 << (s - 1u));
    return r >= 0 ? r >> s : ~(~r >> s);
}

/* v = h 2^s + l with 0 <= l < 2^s (floor division, no shift of a negative
 * value), so that mdr_q_rs(a v, s) = a h + mdr_q_rs(a l, s) exactly: a
 * product rescaled without forming a v, which overflows int64 where |v| is
 * large (dU/dt of a strongly curved table: mdr_q_dU). */
MDR_INLINE MDR_STEP_FN void mdr_q_split(int64_t v, unsigned s, int64_t *h, int64_t *l)
{
    const int64_t d = (int64_t)1 << s;
    int64_t q = v / d, r = v - q * d;
    if (r < 0) {
        r += d;
        q -= 1;
    }
    *h = q;
    *l = r;
}

/* mdr_q_rs(a v, s) for |a| <= 2^31, 1 <= s <= 31 and |v| up to 2^62 / |a|
 * 2^s of its own size: the product through mdr_q_split */
MDR_INLINE MDR_STEP_FN int64_t mdr_q_mulrs(int64_t a, int64_t v, unsigned s)
{
    int64_t h, l;
    mdr_q_split(v, s, &h, &l);
    return a * h + mdr_q_rs(a * l, s);
}

/* v * 2^s without a left shift of a negative value; |v| 2^s < 2^63 */
MDR_INLINE MDR_STEP_FN int64_t mdr_q_ls(int64_t v, unsigned s)
{
    return v * ((int64_t)1 << s);
}

/* v * 2^-s for any s in -62..62 (rounded when s > 0) */
MDR_INLINE MDR_STEP_FN int64_t mdr_q_sh(int64_t v, int s)
{
    return s > 0 ? mdr_q_rs(v, (unsigned)s) : s < 0 ? mdr_q_ls(v, (unsigned)-s) : v;
}

/* int64 -> int32, saturating; sets MDR_FLAG_SAT in *flags when it does */
MDR_INLINE MDR_STEP_FN int32_t mdr_q_sat(int64_t v, uint8_t *flags)
{
    if (v > INT32_MAX) {
        *flags |= MDR_FLAG_SAT;
        return INT32_MAX;
    }
    if (v < INT32_MIN) {
        *flags |= MDR_FLAG_SAT;
        return INT32_MIN;
    }
    return (int32_t)v;
}

/* a + b in int64, saturating (energy sums) */
MDR_INLINE MDR_STEP_FN int64_t mdr_q_add(int64_t a, int64_t b, uint8_t *flags)
{
    if (b > 0 && a > INT64_MAX - b) {
        *flags |= MDR_FLAG_SAT;
        return INT64_MAX;
    }
    if (b < 0 && a < INT64_MIN - b) {
        *flags |= MDR_FLAG_SAT;
        return INT64_MIN;
    }
    return a + b;
}

/* ------------------------------------------------------------ the branch */

typedef struct {
    const mdr_table_q31 *tab;
    int32_t al, ka; /* Q1.30 */
    int32_t c;      /* Q2.29 of D0 (c_adv or c_w: dl(L)/D0) */
    uint8_t sh, m;  /* table -> engine shift; log2 n */
} mdr_qb;

typedef struct {
    int32_t t, x; /* Q1.30 */
    int32_t g;    /* Q2.29 of D0 */
    int32_t G;    /* Q2.29 of L D0 */
    int64_t dg;   /* slope g' L / D0, Q29: s + n b (1 - 2e), up to ~8 + 2n within a spring */
    uint16_t k;
} mdr_qp;

/* a table value (Q1.30 of Dg or L Dg) in engine units (Q2.29 of D0, L D0) */
MDR_INLINE MDR_STEP_FN int32_t mdr_q_tv(const mdr_qb *b, int32_t v)
{
    return (int32_t)mdr_q_rs(v, b->sh);
}

/* g, G, g' at t in spring k. The spring's mean slope s_k (Q3.28 of Dg/L)
 * and its curvature term b_k (Q(fb) of Dg, fb >= 30 chosen per table) enter
 * g and g' directly, not as differences of rounded node values: at
 * n = 1024 g' keeps ~2^-28 of Dg/L where node differences would leave 2^-20. */
static MDR_STEP_FN mdr_qp mdr_q_at(const mdr_qb *b, uint16_t k, int32_t t)
{
    const mdr_node_q31 *n0 = &b->tab->node[k];
    const int32_t one = MDR_Q30_ONE;
    const unsigned sk = b->sh - 1u;                  /* D0 = 2^sk Dg */
    const unsigned sb = b->tab->fb + 1u + sk;        /* Q(fb+30) of Dg -> Q29 of D0 */
    int32_t g0 = mdr_q_tv(b, n0->g);
    uint64_t t2 = (uint64_t)(uint32_t)t * (uint32_t)t; /* Q2.60 */
    int32_t e = (int32_t)mdr_q_rs((int64_t)t2 - (int64_t)((uint64_t)k << (60u - b->m)),
                                  30u - b->m);          /* Q1.30 */
    int32_t e23 = (int32_t)mdr_q_rs((int64_t)e * 715827883, 30); /* 2e/3 */
    /* dg = g_{k+1} - g_k (Q2.29 of D0, for G), e dg, b (1 - e), b (1 - 2e/3) */
    int64_t dg = mdr_q_sh(n0->s, (int)(b->m + sk) - 1);
    int64_t edg = mdr_q_rs((int64_t)e * n0->s, 29u + b->m + sk);
    int64_t b1 = mdr_q_rs((int64_t)n0->b * (one - e), sb);
    int64_t s2 = dg + mdr_q_rs((int64_t)n0->b * (one - e23), sb);
    int64_t s1 = g0 + mdr_q_rs(e * s2, 31);
    mdr_qp p;
    p.t = t;
    p.x = (int32_t)mdr_q_rs((int64_t)t2, 30);
    p.k = k;
    p.g = g0 + (int32_t)(edg + mdr_q_rs(e * b1, 30));
    /* g' L/D0 = s_k Dg/D0 + n b (1 - 2e) */
    p.dg = mdr_q_sh(n0->s, (int)sk - 1) +
           mdr_q_sh((int64_t)n0->b * ((int64_t)one - 2 * (int64_t)e), (int)sb - (int)b->m);
    p.G = mdr_q_tv(b, n0->G) + (int32_t)mdr_q_rs(e * s1, 30u + b->m);
    return p;
}

/* the profile exactly at node j */
static MDR_STEP_FN mdr_qp mdr_q_node(const mdr_qb *b, uint16_t j)
{
    const mdr_node_q31 *nj = &b->tab->node[j];
    mdr_qp p;
    p.t = nj->t;
    p.x = (int32_t)((uint32_t)j << (30u - b->m));
    p.g = mdr_q_tv(b, nj->g);
    p.G = mdr_q_tv(b, nj->G);
    p.dg = 0;
    p.k = j < b->tab->n ? j : (uint16_t)(j - 1u);
    return p;
}

/* U at p, Q2.29 (int64: |U| <= 3 units on the table) */
static MDR_STEP_FN int64_t mdr_q_U(const mdr_qb *b, const mdr_qp *p)
{
    int64_t D = p->g - mdr_q_rs((int64_t)b->c * p->t, 30);
    int64_t phi = mdr_q_rs(p->x * D, 30) - p->G;
    return mdr_q_rs(b->al * D + b->ka * phi, 30);
}

/* dU/dt at p, Q2.29 (int64): al (2 t g' - c) + ka x (2 t g' - 3 c) */
/* (the same value as mdr_q_rs(al (tg - c) + ka mdr_q_rs(x (tg - 3c), 30),
 * 30), without its int64 overflow: |g'| L/D0 is not bounded by the slopes'
 * 8 within a spring, where n b (1 - 2e) adds up to 2n, and a sphere
 * tabulated to 0.99 R overflowed al (tg - c), fuzz_step) */
static MDR_STEP_FN int64_t mdr_q_dU(const mdr_qb *b, const mdr_qp *p)
{
    int64_t tg = mdr_q_mulrs(p->t, p->dg, 29), Ah, Al, Ph, Pl;
    mdr_q_split(tg - b->c, 30, &Ah, &Al);
    mdr_q_split(mdr_q_mulrs(p->x, tg - 3 * (int64_t)b->c, 30), 30, &Ph, &Pl);
    return (b->al * Ah + b->ka * Ph) + mdr_q_rs(b->al * Al + b->ka * Pl, 30);
}

/* dU/dt >= 0 at p (stable), read from the sign of mdr_q_dU, and where that
 * rounds to 0 from the sign of its terms al (tg - c) + ka x (tg - 3c): the
 * first if not 0, else tg - 3c (x > 0 for t > 0). Under fixed load
 * (al = 0) x (tg - 3c) rescaled by 2^-30 is 0 for t < 2^-15 (x < 2^-30),
 * and the fold search took that for stable ground down to t = 0 (fuzz_step:
 * a q31 load step to F = 0 landed on a = 0 in contact, d saturated). */
static MDR_STEP_FN bool mdr_q_stable(const mdr_qb *b, const mdr_qp *p)
{
    int64_t d = mdr_q_dU(b, p), tg;
    if (d != 0) {
        return d > 0;
    }
    tg = mdr_q_mulrs(p->t, p->dg, 29);
    if (b->al != 0 && tg != b->c) { /* al >= 0: the sign of al (tg - c) */
        return tg > b->c;
    }
    return b->ka == 0 || tg - 3 * (int64_t)b->c >= 0;
}

/* Root of dir (U - u) in spring k between ta (< 0) and tb (>= 0): Newton
 * from the secant point, bisection whenever it leaves the bracket. */
static MDR_STEP_FN bool mdr_q_root(const mdr_qb *b, int dir, int64_t u, uint16_t k, int32_t ta, int64_t fa,
                       int32_t tb, int64_t fb, mdr_qp *out)
{
    int32_t lo = ta, hi = tb, t;
    int it;
    /* secant point, or the midpoint when ta is at the target (mdr_e_root) */
    t = fa < 0 && fb > fa ? ta + (int32_t)(((int64_t)(tb - ta) * -fa) / (fb - fa)) : lo + (hi - lo) / 2;
    for (it = 0; it < MDR_Q_ITER; it++) {
        mdr_qp p = mdr_q_at(b, k, t);
        int64_t fv = dir * (mdr_q_U(b, &p) - u);
        int64_t df = dir * mdr_q_dU(b, &p);
        int64_t tn, dt;
        if (fv < 0) {
            lo = t;
        } else {
            hi = t;
        }
        if (fv == 0 || (hi > lo ? hi - lo : lo - hi) <= 1) {
            *out = p;
            return true;
        }
        dt = df != 0 ? mdr_q_ls(fv, 30) / df : 0;
        if (df != 0 && dt == 0) { /* the correction is below one ulp of t */
            *out = p;
            return true;
        }
        tn = t - dt;
        if (df == 0 || !(lo < hi ? tn > lo && tn < hi : tn < lo && tn > hi)) {
            tn = lo + (hi - lo) / 2;
        }
        t = (int32_t)tn;
    }
    *out = mdr_q_at(b, k, hi);
    return false;
}

/* Fold in spring k between ta (dU/dt >= 0) and tb (< 0): bisection */
static MDR_STEP_FN mdr_qp mdr_q_fold(const mdr_qb *b, uint16_t k, int32_t ta, int32_t tb)
{
    int it;
    for (it = 0; it < MDR_Q_ITER; it++) {
        int32_t tm = ta + (tb - ta) / 2;
        mdr_qp p;
        if (tm == ta || tm == tb) {
            break;
        }
        p = mdr_q_at(b, k, tm);
        if (mdr_q_stable(b, &p)) {
            ta = tm;
        } else {
            tb = tm;
        }
    }
    return mdr_q_at(b, k, ta);
}

enum { MDR_Q_SCAN_ROOT, MDR_Q_SCAN_FOLD, MDR_Q_SCAN_END, MDR_Q_SCAN_NOCONV };

/* Walk from p0 in direction dir to the first dir*U >= dir*u (> when
 * !folds), or with folds to the first fold (mdr_e_scan in mdr_engine_t.c). */
static MDR_STEP_FN int mdr_q_scan(const mdr_qb *b, int dir, int64_t u, bool folds, const mdr_qp *p0,
                      mdr_qp *out)
{
    const int64_t su = dir * u;
    const uint16_t n = b->tab->n;
    int32_t tq = p0->t, tpp = p0->t;
    int64_t Wq = dir * mdr_q_U(b, p0);
    bool q_is_node = false;
    long j = dir > 0 ? (long)p0->k + 1 : (long)p0->k;
    if (folds && !mdr_q_stable(b, p0)) {
        *out = *p0;
        return MDR_Q_SCAN_FOLD;
    }
    for (; j >= 0 && j <= (long)n; j += dir) {
        uint16_t seg = (uint16_t)(dir > 0 ? j - 1 : j);
        mdr_qp pj = mdr_q_node(b, (uint16_t)j);
        int64_t Wj = dir * mdr_q_U(b, &pj);
        /* spring 0 of an adhesive branch holds a fold (mdr_e_scan) */
        const bool fold0 = folds && dir < 0 && j == 0 && b->c > 0;
        if (pj.t == tq) {
            Wq = Wj;
            q_is_node = true;
            continue;
        }
        if (!fold0 && (folds ? Wj >= su : Wj > su)) {
            return mdr_q_root(b, dir, u, seg, tq, Wq - su, pj.t, Wj - su, out) ? MDR_Q_SCAN_ROOT
                                                                               : MDR_Q_SCAN_NOCONV;
        }
        if (folds && (Wj < Wq || fold0)) {
            mdr_qp pq = mdr_q_at(b, seg, tq), pf;
            int64_t Wf, fa = Wq - su;
            uint16_t fseg = seg;
            int32_t ta = tq, tb = pj.t;
            if (!mdr_q_stable(b, &pq)) {
                if (!q_is_node) {
                    *out = pq;
                    return MDR_Q_SCAN_FOLD;
                }
                fseg = (uint16_t)(dir > 0 ? seg - 1 : seg + 1);
                pq = mdr_q_at(b, fseg, tq);
                if (mdr_q_stable(b, &pq)) {
                    *out = pq;
                    return MDR_Q_SCAN_FOLD;
                }
                ta = tpp;
                tb = tq;
                {
                    mdr_qp pa = mdr_q_at(b, fseg, tpp);
                    fa = dir * mdr_q_U(b, &pa) - su;
                }
            }
            pf = mdr_q_fold(b, fseg, ta, tb);
            Wf = dir * mdr_q_U(b, &pf);
            if (Wf >= su) {
                return mdr_q_root(b, dir, u, fseg, ta, fa, pf.t, Wf - su, out) ? MDR_Q_SCAN_ROOT
                                                                                : MDR_Q_SCAN_NOCONV;
            }
            *out = pf;
            return MDR_Q_SCAN_FOLD;
        }
        tpp = tq;
        tq = pj.t;
        Wq = Wj;
        q_is_node = true;
    }
    return MDR_Q_SCAN_END;
}

/* ------------------------------------------------------------ the step */

/* Trapezoid of F dd into the work sum: ((F0+F1)/2) (d1-d0), Q2.58 -> Q15.48 */
static MDR_STEP_FN void mdr_q_work(mdr_engine_q31 *s, int32_t d0, int32_t F0, int32_t d1, int32_t F1)
{
    int64_t avg = mdr_q_rs((int64_t)F0 + F1, 1);
    s->work = mdr_q_add(s->work, mdr_q_rs(avg * ((int64_t)d1 - d0), 10), &s->flags);
}

/* d and F with the edge at p and the control at u (pinned relation):
 * d = (u + ka G)/(al + ka x) (one int64 division unless ka = 0),
 * F = x d - G (= u exactly at fixed load). */
static MDR_STEP_FN void mdr_q_state(const mdr_qb *b, int64_t u, const mdr_qp *p, int32_t *d, int32_t *F,
                        uint8_t *flags)
{
    if (b->ka == 0) {
        *d = mdr_q_sat(u, flags);
    } else {
        int64_t den = b->al + mdr_q_rs((int64_t)b->ka * p->x, 30); /* Q1.30, > 0 in contact */
        int64_t num = mdr_q_ls(u, 30) + (int64_t)b->ka * p->G;     /* Q2.59 */
        *d = mdr_q_sat(den > 0 ? num / den : (num >= 0 ? INT64_MAX : INT64_MIN), flags);
    }
    *F = b->al == 0 ? mdr_q_sat(u, flags)
                    : mdr_q_sat(mdr_q_rs((int64_t)p->x * *d, 30) - p->G, flags);
}

/* d + kappa F in D0 units (the base position of the machine as a depth) */
static MDR_STEP_FN int32_t mdr_q_zd(const mdr_engine_q31 *e, int32_t d, int32_t F, uint8_t *flags)
{
    return mdr_q_sat(d + mdr_q_rs((int64_t)e->z_k * F, 30u - e->sz), flags);
}

static MDR_STEP_FN mdr_status mdr_q_refuse(mdr_engine_q31 *e, uint8_t flag, mdr_status st)
{
    e->flags |= flag;
    return st;
}

/* One step with the control u (Q2.29) on the branch family (al, ka) of
 * control mode ctl; zr is the raw z input of the machine. */
static MDR_STEP_FN mdr_status mdr_q_step(mdr_engine_q31 *e, uint8_t ctl, int32_t al, int32_t ka, int32_t u,
                             int32_t zr, mdr_step_q31 *out)
{
    const mdr_table_q31 *tab = e->tab;
    mdr_engine_q31 s = *e;
    mdr_qb b;
    mdr_qp p;
    mdr_step_q31 o;
    int32_t dprev = e->d, Fprev = e->F, d = 0, F = 0;
    int dir = 0;
    bool from_sep = !e->contact;
    unsigned iter;

    b.tab = tab;
    b.al = al;
    b.ka = ka;
    b.c = 0;
    b.sh = s.sh;
    b.m = tab->m;
    p.t = s.t;
    p.x = s.a;
    p.g = s.g;
    p.G = s.Ga;
    p.dg = 0;
    p.k = s.k;
    o.event = MDR_EV_NONE;
    o.jumps = 0;

    if (s.contact) {
        mdr_q_state(&b, u, &p, &d, &F, &s.flags);
        if (d > p.g - mdr_q_rs((int64_t)s.c_adv * p.t, 30)) {
            dir = 1;
        } else if (d < p.g - mdr_q_rs((int64_t)s.c_w * p.t, 30)) {
            dir = -1;
        }
    } else if (u > 0) {
        dir = 1;
        dprev = Fprev = 0;
    }
    if (dir != 0) {
        b.c = dir > 0 ? s.c_adv : s.c_w;
        p = mdr_q_at(&b, s.k, s.t);
    }
    for (iter = 0; dir != 0; iter++) {
        mdr_qp pf, pl;
        int64_t uf;
        int32_t df, Ff, dl, Fl;
        int r;
        if (iter > (unsigned)tab->n + 1u) {
            return mdr_q_refuse(e, MDR_FLAG_NOCONV, MDR_E_NOCONV);
        }
        if (dir > 0 && s.contact && tab->wall && p.k == tab->n - 1 && p.t >= tab->node[tab->n].t) {
            break;
        }
        r = mdr_q_scan(&b, dir, u, true, &p, &pf);
        if (r == MDR_Q_SCAN_NOCONV) {
            return mdr_q_refuse(e, MDR_FLAG_NOCONV, MDR_E_NOCONV);
        }
        if (r == MDR_Q_SCAN_ROOT) {
            p = pf;
            s.contact = 1;
            break;
        }
        if (r == MDR_Q_SCAN_END) {
            if (dir > 0) {
                if (!tab->wall) {
                    return mdr_q_refuse(e, MDR_FLAG_OUTSIDE, MDR_E_OUTSIDE);
                }
                p = mdr_q_node(&b, tab->n);
                s.contact = 1;
                break;
            }
            o.event = MDR_EV_SEPARATION;
            s.contact = 0;
            break;
        }
        uf = mdr_q_U(&b, &pf);
        if (pf.x == 0) { /* fold at first touch: no pinned relation there */
            df = 0;
            Ff = 0;
        } else {
            mdr_q_state(&b, uf, &pf, &df, &Ff, &s.flags);
        }
        mdr_q_work(&s, dprev, Fprev, df, Ff);
        o.a0 = pf.x;
        o.d0 = df;
        o.F0 = Ff;
        if (o.jumps < 255u) {
            o.jumps++;
        }
        /* the landing aims past the rounding error of U (5 rounded terms,
         * <= MDR_Q_UTOL LSB), so that a point next to the fold whose U
         * equals uf but for rounding is not taken for the landing (it folds
         * again there without end: a q31 load step on the wavy profile hit
         * the jump cap, fuzz_step; mdr_e_Utol in the float engine) */
        r = mdr_q_scan(&b, dir, uf + (int64_t)dir * MDR_Q_UTOL, false, &pf, &pl);
        if (r == MDR_Q_SCAN_NOCONV) {
            return mdr_q_refuse(e, MDR_FLAG_NOCONV, MDR_E_NOCONV);
        }
        if (r == MDR_Q_SCAN_END && dir < 0) {
            o.event = MDR_EV_PULL_OFF;
            o.a1 = 0;
            o.d1 = ctl == MDR_CONTROL_GRIPS     ? mdr_q_sat(uf, &s.flags)
                   : ctl == MDR_CONTROL_MACHINE ? mdr_q_zd(e, df, Ff, &s.flags)
                                                : df;
            o.F1 = 0;
            mdr_q_work(&s, df, Ff, o.d1, 0);
            dprev = o.d1;
            Fprev = 0;
            s.contact = 0;
            break;
        }
        if (r == MDR_Q_SCAN_END) {
            if (!tab->wall) {
                return mdr_q_refuse(e, MDR_FLAG_OUTSIDE, MDR_E_OUTSIDE);
            }
            pl = mdr_q_node(&b, tab->n);
        }
        mdr_q_state(&b, uf, &pl, &dl, &Fl, &s.flags);
        mdr_q_work(&s, df, Ff, dl, Fl);
        o.a1 = pl.x;
        o.d1 = dl;
        o.F1 = Fl;
        o.event = from_sep && o.jumps == 1u ? MDR_EV_JUMP_IN : MDR_EV_JUMP;
        dprev = dl;
        Fprev = Fl;
        p = pl;
        s.contact = 1;
    }

    if (s.contact) {
        if (dir != 0) {
            mdr_q_state(&b, u, &p, &d, &F, &s.flags);
        }
        s.a = p.x;
        s.t = p.t;
        s.g = p.g;
        s.Ga = p.G;
        s.k = p.k;
        if (from_sep && o.jumps == 0) {
            o.event = s.touched ? MDR_EV_RECONTACT : MDR_EV_CONTACT;
        }
        s.touched = 1;
    } else {
        F = 0;
        d = ctl == MDR_CONTROL_GRIPS     ? u
            : ctl == MDR_CONTROL_MACHINE ? mdr_q_sat(mdr_q_ls(zr, s.sz), &s.flags)
            : o.event == MDR_EV_PULL_OFF ? dprev
            : o.event == MDR_EV_SEPARATION ? 0
                                           : e->d;
        s.a = s.t = s.g = s.Ga = 0;
        s.k = 0;
    }
    if (o.event == MDR_EV_SEPARATION) {
        mdr_q_work(&s, dprev, Fprev, 0, 0);
    } else if (s.contact) {
        mdr_q_work(&s, dprev, Fprev, d, F);
    }
    if (!s.contact && e->contact) {
        int64_t cyc = mdr_q_add(s.work, -s.work_sep, &s.flags);
        s.work_sep = s.work;
        s.last_cycle = cyc;
        s.dissipated = mdr_q_add(s.dissipated, cyc, &s.flags);
        s.cycles++;
    }
    s.d = d;
    s.F = F;
    o.a = s.a;
    o.d = d;
    o.F = F;
    o.z = s.machine ? mdr_q_sat(mdr_q_rs(mdr_q_ls(d, 30u - s.sz) + (int64_t)s.z_k * F, 30), &s.flags)
                    : d;
    if (o.jumps == 0) {
        o.a0 = o.a1 = o.a;
        o.d0 = o.d1 = d;
        o.F0 = o.F1 = F;
    }
    MDR_ASSERT(s.k < tab->n); /* the edge lies in spring k: x_k <= a <= x_{k+1} */
    *e = s;
    *out = o;
    return MDR_OK;
}

/* the documented input range |v| <= 2 units: beyond it saturate and flag */
static MDR_STEP_FN int32_t mdr_q_in(mdr_engine_q31 *e, int32_t v)
{
    if (v > 2 * MDR_Q29_ONE || v < -2 * MDR_Q29_ONE) {
        e->flags |= MDR_FLAG_SAT;
        return v > 0 ? 2 * MDR_Q29_ONE : -2 * MDR_Q29_ONE;
    }
    return v;
}

MDR_STEP_FN mdr_status mdr_engine_step_d_q31(mdr_engine_q31 *e, int32_t d, mdr_step_q31 *out)
{
    if (e == NULL || out == NULL || e->tab == NULL) {
        return MDR_E_NULL;
    }
    d = mdr_q_in(e, d);
    return mdr_q_step(e, MDR_CONTROL_GRIPS, MDR_Q30_ONE, 0, d, d, out);
}

MDR_STEP_FN mdr_status mdr_engine_step_F_q31(mdr_engine_q31 *e, int32_t F, mdr_step_q31 *out)
{
    if (e == NULL || out == NULL || e->tab == NULL) {
        return MDR_E_NULL;
    }
    F = mdr_q_in(e, F);
    return mdr_q_step(e, MDR_CONTROL_LOAD, 0, MDR_Q30_ONE, F, F, out);
}

MDR_STEP_FN mdr_status mdr_engine_step_z_q31(mdr_engine_q31 *e, int32_t z, mdr_step_q31 *out)
{
    if (e == NULL || out == NULL || e->tab == NULL) {
        return MDR_E_NULL;
    }
    if (!e->machine) {
        return MDR_E_CONTROL;
    }
    z = mdr_q_in(e, z);
    return mdr_q_step(e, MDR_CONTROL_MACHINE, e->al_z, e->ka_z,
                      (int32_t)mdr_q_rs((int64_t)z * e->z_in, 30), z, out);
}

uint8_t mdr_engine_clear_flags_q31(mdr_engine_q31 *e)
{
    uint8_t f;
    if (e == NULL) {
        return 0;
    }
    f = e->flags;
    e->flags = 0;
    return f;
}
#else
/* ISO C: a translation unit declares something */
typedef int mdr_q31_not_built;
#endif /* MDR_CFG_Q31 */
