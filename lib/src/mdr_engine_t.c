/*
 * mdr_engine_t.c: spring tables and the real-time approach-retract engine,
 * written once for every floating arithmetic (see mdr_arith.h). Contract and
 * model: lib/include/mdr_engine_t.h.
 *
 * Notation inside: the controlled variable along an edge branch is
 *   U(t) = al*D + ka*(x*D - G),  D = g(x) - c*t,  x = t^2 = a,
 * with (al, ka) = (1, 0) for fixed grips (U = d), (0, 1) for fixed load
 * (U = F/(2E*)) and (1, 2E* /k_m) for the machine (U = z); c = c_adv on an
 * advancing edge, c_w on a receding one. dU/dt = al*(2t g' - c)
 * + ka*(2t x g' - 3c x) (from dd/da and dF/da of seed 4.25/4.26 with
 * da/dt = 2t). A branch is stable where dU/dt > 0, in either direction of
 * motion. A scan walks the nodes from the edge in the direction of motion
 * with W = dir*U: the edge lands at the first W >= dir*u; a W that drops
 * below its predecessor first marks a fold (a local maximum of W).
 */

#define MDR_GAUSS2_A MDR_K(0.211324865405187117745425609748689) /* (1 - 1/sqrt3)/2 */
#define MDR_GAUSS2_B MDR_K(0.788675134594812882254574390251311) /* (1 + 1/sqrt3)/2 */
/* Root / fold iteration cap: exponent bisection where a bracket spans
 * orders of magnitude (spring 0; <= log2 of the exponent range, < 12), then
 * halving to 4 eps in t (<= MANT_BITS + 2), each halving possibly beside
 * one Newton step (mdr_e_root forces a bisection after a Newton step that
 * did not at least halve the residual) */
#define MDR_ENG_ITER (2 * (MDR_MANT_BITS + 16))

/* Kahan accumulation: *s + *cmp holds the sum to ~eps relative. */
MDR_INLINE MDR_STEP_FN void MDR_SFX(mdr_e_kahan)(MDR_T *s, MDR_T *cmp, MDR_T v)
{
    MDR_T y = v - *cmp;
    MDR_T tt = *s + y;
    *cmp = (tt - *s) - y;
    *s = tt;
}

#if MDR_CFG_ENGINE || MDR_CFG_SCENE
/* The material and machine checks of every engine init (f32, f64, q31). */
static mdr_status MDR_SFX(mdr_e_material)(MDR_T E, MDR_T w, MDR_T w_adv, MDR_T k_m)
{
    if (!MDR_SFX(mdr_m_isfinite)(E) || !MDR_SFX(mdr_m_isfinite)(w) ||
        !MDR_SFX(mdr_m_isfinite)(w_adv) || !MDR_SFX(mdr_m_isfinite)(k_m)) {
        return MDR_E_NONFINITE;
    }
    if (!(E > MDR_K(0.0)) || !(w >= MDR_K(0.0)) || !(w_adv >= MDR_K(0.0)) || w_adv > w) {
        return MDR_E_PARAM;
    }
    if (k_m < MDR_K(0.0)) {
        return MDR_E_CONTROL;
    }
    return MDR_OK;
}
#endif

#if MDR_CFG_ENGINE /* to the end of the file */

/* ---------------------------------------------------------------- tables */

/* Prefix sums G_i and the square roots t_i of a table whose g_i and q_i are
 * set: G_{i+1} = G_i + h (g_i + g_{i+1})/2 + q_i, compensated; then the
 * header is filled (only now: a failed build leaves it untouched). */
static mdr_status MDR_SFX(mdr_e_finish)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                        uint16_t n, MDR_T h, bool wall)
{
    MDR_T s = MDR_K(0.0), cmp = MDR_K(0.0);
    uint16_t i;
    node[0].G = MDR_K(0.0);
    node[0].t = MDR_K(0.0);
    node[n].q = MDR_K(0.0);
    for (i = 0; i < n; i++) {
        MDR_SFX(mdr_e_kahan)(&s, &cmp, MDR_K(0.5) * h * (node[i].g + node[i + 1].g) + node[i].q);
        node[i + 1].G = s;
        node[i + 1].t = MDR_SQRT(h * (MDR_T)(i + 1));
    }
    /* finite inputs can still overflow the arithmetic (a gap of 1e306 m
     * in one sample of a tip file: fuzz_table) */
    for (i = 0; i <= n; i++) {
        if (!MDR_SFX(mdr_m_isfinite)(node[i].g) || !MDR_SFX(mdr_m_isfinite)(node[i].G) ||
            !MDR_SFX(mdr_m_isfinite)(node[i].q)) {
            return MDR_E_OVERFLOW;
        }
    }
    tab->node = node;
    tab->h = h;
    tab->n = n;
    tab->wall = (uint8_t)wall;
    return MDR_OK;
}

static bool MDR_SFX(mdr_e_size_ok)(uint16_t n)
{
    return n >= MDR_SPRINGS_MIN && n <= MDR_SPRINGS_MAX;
}

/* The checks every table builder starts with: pointers, then N. */
static mdr_status MDR_SFX(mdr_e_args)(const void *tab, const void *node, const void *src,
                                      uint16_t n)
{
    if (tab == NULL || node == NULL || src == NULL) {
        return MDR_E_NULL;
    }
    return MDR_SFX(mdr_e_size_ok)(n) ? MDR_OK : MDR_E_SIZE;
}

mdr_status MDR_SFX(mdr_table_init_profile)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                           uint16_t n, const MDR_SFX(mdr_contact) *c, MDR_T x_max)
{
    MDR_T h;
    uint16_t i;
    mdr_status st = MDR_SFX(mdr_e_args)(tab, node, c, n);
    if (st != MDR_OK) {
        return st;
    }
    if (!MDR_SFX(mdr_m_isfinite)(x_max)) {
        return MDR_E_NONFINITE;
    }
    if (!(x_max > MDR_K(0.0))) {
        return MDR_E_RADIUS;
    }
    h = x_max / (MDR_T)n;
    if (!(h > MDR_K(0.0))) {
        return MDR_E_RADIUS;
    }
    node[0].g = MDR_K(0.0);
    for (i = 1; i <= n; i++) {
        MDR_T x = i == n ? x_max : h * (MDR_T)i;
        st = MDR_SFX(mdr_profile_eval)(c, x, &node[i].g, NULL, NULL);
        if (st != MDR_OK) {
            return st;
        }
    }
    for (i = 0; i < n; i++) {
        MDR_T x0 = h * (MDR_T)i, ga, gb;
        st = MDR_SFX(mdr_profile_eval)(c, x0 + MDR_GAUSS2_A * h, &ga, NULL, NULL);
        if (st == MDR_OK) {
            st = MDR_SFX(mdr_profile_eval)(c, x0 + MDR_GAUSS2_B * h, &gb, NULL, NULL);
        }
        if (st != MDR_OK) {
            return st;
        }
        /* 2-point Gauss-Legendre minus the trapezoid: error O(h^5 g'''') */
        node[i].q = MDR_K(0.5) * h * ((ga + gb) - (node[i].g + node[i + 1].g));
    }
    return MDR_SFX(mdr_e_finish)(tab, node, n, h,
                                 c->kind == MDR_PROFILE_FLATPUNCH && x_max == c->p[0]);
}

/* Slope (f_{j+1} - f_j)/(r_{j+1} - r_j) of sample interval j. */
static MDR_T MDR_SFX(mdr_e_slope)(const MDR_T *r, const MDR_T *f, uint16_t j)
{
    return (f[j + 1] - f[j]) / (r[j + 1] - r[j]);
}

/* Curvature of interval j: difference of the neighbouring slopes over the
 * distance of their midpoints (centred inside, one-sided at the two ends);
 * needs m >= 3. */
static MDR_T MDR_SFX(mdr_e_curv)(const MDR_T *r, const MDR_T *f, uint16_t m, uint16_t j)
{
    uint16_t lo = j == 0 ? 0 : (uint16_t)(j - 1);
    uint16_t hi = j + 1 > m - 2 ? (uint16_t)(m - 2) : (uint16_t)(j + 1);
    return (MDR_SFX(mdr_e_slope)(r, f, hi) - MDR_SFX(mdr_e_slope)(r, f, lo)) /
           (MDR_K(0.5) * ((r[hi] + r[hi + 1]) - (r[lo] + r[lo + 1])));
}

/* g(x) of the piecewise-quadratic f of the samples: exact Abel integral of
 * each linear piece of f' (see mdr_table_init_gap()). x >= 0. */
static MDR_T MDR_SFX(mdr_e_abel)(const MDR_T *r, const MDR_T *f, uint16_t m, MDR_T x)
{
    MDR_T sum = MDR_K(0.0), cmp = MDR_K(0.0);
    MDR_T s0 = x; /* sqrt(x^2 - r_0^2) with r_0 = 0 */
    uint16_t j;
    if (!(x > MDR_K(0.0))) {
        return MDR_K(0.0);
    }
    for (j = 0; j + 1 < m && r[j] < x; j++) {
        MDR_T r0 = r[j], r1 = r[j + 1] < x ? r[j + 1] : x;
        MDR_T s1 = r1 < x ? MDR_SQRT((x - r1) * (x + r1)) : MDR_K(0.0);
        MDR_T mj = MDR_SFX(mdr_e_slope)(r, f, j);
        MDR_T bj = MDR_SFX(mdr_e_curv)(r, f, m, j);
        MDR_T rm = MDR_K(0.5) * (r[j] + r[j + 1]);
        /* S0 - S1 and the asin difference without cancellation */
        MDR_T ds = (r1 - r0) * (r1 + r0) / (s0 + s1);
        MDR_T num = (r1 - r0) * s0 + r0 * ds;
        MDR_T dth = MDR_SFX(mdr_m_atan2p)(num, s0 * s1 + r0 * r1);
        /* int (mj + bj (r - rm)) / sqrt(x^2 - r^2) dr over [r0, r1] */
        MDR_SFX(mdr_e_kahan)(&sum, &cmp, mj * dth + bj * (ds - rm * dth));
        s0 = s1;
    }
    return x * sum;
}

mdr_status MDR_SFX(mdr_table_init_gap)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                       uint16_t n, const MDR_T *r, const MDR_T *f, uint16_t m)
{
    MDR_T h;
    uint16_t i;
    mdr_status st = MDR_SFX(mdr_e_args)(tab, node, r, n);
    if (st != MDR_OK) {
        return st;
    }
    if (f == NULL) {
        return MDR_E_NULL;
    }
    if (m < MDR_TABLE_MIN_POINTS) {
        return MDR_E_TABLE;
    }
    for (i = 0; i < m; i++) {
        if (!MDR_SFX(mdr_m_isfinite)(r[i]) || !MDR_SFX(mdr_m_isfinite)(f[i])) {
            return MDR_E_NONFINITE;
        }
    }
    if (r[0] != MDR_K(0.0)) {
        return MDR_E_TABLE;
    }
    for (i = 1; i < m; i++) {
        if (!(r[i] > r[i - 1])) {
            return MDR_E_TABLE;
        }
    }
    h = r[m - 1] / (MDR_T)n;
    if (!(h > MDR_K(0.0))) {
        return MDR_E_TABLE;
    }
    for (i = 0; i <= n; i++) {
        MDR_T x = i == n ? r[m - 1] : h * (MDR_T)i;
        node[i].g = MDR_SFX(mdr_e_abel)(r, f, m, x);
    }
    for (i = 0; i < n; i++) {
        MDR_T x0 = h * (MDR_T)i;
        MDR_T ga = MDR_SFX(mdr_e_abel)(r, f, m, x0 + MDR_GAUSS2_A * h);
        MDR_T gb = MDR_SFX(mdr_e_abel)(r, f, m, x0 + MDR_GAUSS2_B * h);
        node[i].q = MDR_K(0.5) * h * ((ga + gb) - (node[i].g + node[i + 1].g));
    }
    return MDR_SFX(mdr_e_finish)(tab, node, n, h, false);
}

mdr_status MDR_SFX(mdr_table_init_g)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                     uint16_t n, MDR_T h, const MDR_T *g)
{
    uint16_t i;
    mdr_status st = MDR_SFX(mdr_e_args)(tab, node, g, n);
    if (st != MDR_OK) {
        return st;
    }
    if (!MDR_SFX(mdr_m_isfinite)(h)) {
        return MDR_E_NONFINITE;
    }
    if (!(h > MDR_K(0.0)) || !MDR_SFX(mdr_m_isfinite)(h * (MDR_T)n)) {
        return MDR_E_PARAM;
    }
    for (i = 0; i <= n; i++) {
        if (!MDR_SFX(mdr_m_isfinite)(g[i])) {
            return MDR_E_NONFINITE;
        }
    }
    if (g[0] != MDR_K(0.0)) {
        return MDR_E_TABLE;
    }
    for (i = 0; i <= n; i++) {
        node[i].g = g[i];
        node[i].q = MDR_K(0.0);
    }
    return MDR_SFX(mdr_e_finish)(tab, node, n, h, false);
}

/* ---------------------------------------------------------------- engine */

mdr_status MDR_SFX(mdr_engine_init)(MDR_SFX(mdr_engine) *e, const MDR_SFX(mdr_table) *tab,
                                    MDR_T E, MDR_T w, MDR_T w_adv, MDR_T k_m)
{
    MDR_SFX(mdr_engine) z;
    mdr_status st;
    if (e == NULL || tab == NULL || tab->node == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_e_size_ok)(tab->n) || !(tab->h > MDR_K(0.0)) ||
        !MDR_SFX(mdr_m_isfinite)(tab->h)) {
        return MDR_E_SIZE;
    }
    st = MDR_SFX(mdr_e_material)(E, w, w_adv, k_m);
    if (st != MDR_OK) {
        return st;
    }
    z.tab = tab;
    z.E = E;
    z.c_w = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w / E));
    z.c_adv = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w_adv / E));
    z.k_m = k_m;
    z.kappa = k_m > MDR_K(0.0) ? MDR_K(2.0) * E / k_m : MDR_K(0.0);
    if (!MDR_SFX(mdr_m_isfinite)(z.kappa)) {
        return MDR_E_CONTROL;
    }
    z.a = z.t = z.g = z.Ga = z.d = z.F = MDR_K(0.0);
    z.k = 0;
    z.contact = 0;
    z.touched = 0;
    z.flags = 0;
    z.work = z.work_c = z.work_sep = z.dissipated = z.last_cycle = MDR_K(0.0);
    z.cycles = 0;
    *e = z;
    return MDR_OK;
}

uint8_t MDR_SFX(mdr_engine_clear_flags)(MDR_SFX(mdr_engine) *e)
{
    uint8_t f;
    if (e == NULL) {
        return 0;
    }
    f = e->flags;
    e->flags = 0;
    return f;
}

/* A branch of the controlled variable (see the top of this file). */
typedef struct {
    const MDR_SFX(mdr_table) *tab;
    MDR_T al, ka, c, ih, b6; /* ih = 1/h, b6 = 6/h^3 */
} MDR_SFX(mdr_e_branch);

/* A point of the equivalent profile inside spring k. */
typedef struct {
    MDR_T t, x, g, G, dg;
    uint16_t k;
} MDR_SFX(mdr_e_pt);

/* g, G, g' at t in spring k (t_k <= t <= t_{k+1}): the quadratic of the
 * table header, e = x - x_k. */
static MDR_STEP_FN MDR_SFX(mdr_e_pt) MDR_SFX(mdr_e_at)(const MDR_SFX(mdr_e_branch) *b, uint16_t k, MDR_T t)
{
    const MDR_SFX(mdr_node) *n0 = &b->tab->node[k];
    const MDR_SFX(mdr_node) *n1 = n0 + 1;
    MDR_T h = b->tab->h;
    MDR_SFX(mdr_e_pt) p;
    MDR_T s = (n1->g - n0->g) * b->ih;
    MDR_T be = n0->q * b->b6;
    MDR_T e;
    p.t = t;
    p.x = t * t;
    p.k = k;
    e = p.x - h * (MDR_T)k;
    p.g = n0->g + e * (s + be * (h - e));
    p.dg = s + be * (h - MDR_K(2.0) * e);
    p.G = n0->G + e * (n0->g + e * (MDR_K(0.5) * s + be * (MDR_K(0.5) * h - e / MDR_K(3.0))));
    return p;
}

/* The profile exactly at node j (no interpolation; dg unused there). */
static MDR_STEP_FN MDR_SFX(mdr_e_pt) MDR_SFX(mdr_e_node)(const MDR_SFX(mdr_e_branch) *b, uint16_t j)
{
    MDR_SFX(mdr_e_pt) p;
    p.t = b->tab->node[j].t;
    p.x = b->tab->h * (MDR_T)j;
    p.g = b->tab->node[j].g;
    p.G = b->tab->node[j].G;
    p.dg = MDR_K(0.0);
    p.k = j < b->tab->n ? j : (uint16_t)(j - 1);
    return p;
}

static MDR_STEP_FN MDR_T MDR_SFX(mdr_e_U)(const MDR_SFX(mdr_e_branch) *b, const MDR_SFX(mdr_e_pt) *p)
{
    MDR_T D = p->g - b->c * p->t;
    return b->al * D + b->ka * (p->x * D - p->G);
}

static MDR_STEP_FN MDR_T MDR_SFX(mdr_e_dU)(const MDR_SFX(mdr_e_branch) *b, const MDR_SFX(mdr_e_pt) *p)
{
    MDR_T tg = MDR_K(2.0) * p->t * p->dg;
    return b->al * (tg - b->c) + b->ka * p->x * (tg - MDR_K(3.0) * b->c);
}

/* Bound on the rounding error of mdr_e_U at p: 8 eps times the sum of the
 * magnitudes of its terms (U = al D + ka (x D - G), D = g - c t). Near a
 * fold U is flat, and values within this bound of each other are not
 * ordered by the arithmetic. */
static MDR_STEP_FN MDR_T MDR_SFX(mdr_e_Utol)(const MDR_SFX(mdr_e_branch) *b, const MDR_SFX(mdr_e_pt) *p)
{
    MDR_T Dm = MDR_SFX(mdr_m_fabs)(p->g) + MDR_SFX(mdr_m_fabs)(b->c * p->t);
    return MDR_K(8.0) * MDR_EPS *
           (MDR_SFX(mdr_m_fabs)(b->al) * Dm +
            MDR_SFX(mdr_m_fabs)(b->ka) * (MDR_SFX(mdr_m_fabs)(p->x) * Dm + MDR_SFX(mdr_m_fabs)(p->G)) +
            MDR_K(2.0) * MDR_MINV); /* U's absolute floor: 8x the one mdr_e_root accepts as 0 */
}

/* The bisection point of [lo, hi] (either order; t >= 0): their mean, or,
 * where they span more than a factor of 4 (only spring 0 can: its low end
 * is t = 0), the power of two halfway between their exponents, so that a
 * root or fold at any t > 0 is reached in ~log2(exponent span) + MANT_BITS
 * halvings, not log2(hi/t) + MANT_BITS, which has no bound (the cap was hit
 * by a landing 1e-4 of the spring's width from t = 0, fuzz_step). No sqrt:
 * frexp/ldexp. */
static MDR_STEP_FN bool MDR_SFX(mdr_e_wide)(MDR_T lo, MDR_T hi)
{
    return lo < hi ? hi > MDR_K(4.0) * lo : lo > MDR_K(4.0) * hi;
}

static MDR_STEP_FN MDR_T MDR_SFX(mdr_e_mid)(MDR_T lo, MDR_T hi)
{
    MDR_T a = lo < hi ? lo : hi, c = lo < hi ? hi : lo;
    int ea, ec;
    if (!MDR_SFX(mdr_e_wide)(lo, hi)) {
        return MDR_K(0.5) * (lo + hi);
    }
    /* below t = 2^-63 (f32) resp. 2^-511 (f64) x = t^2 leaves the normal
     * range and dU/dt, a multiple of x under load, reads 0 (stable): the
     * lowest bisection point is there */
    (void)MDR_SFX(mdr_m_frexp)(a, &ea);
    if (!(a > MDR_K(0.0)) || ea < -MDR_EXP_BIAS / 2) {
        ea = -MDR_EXP_BIAS / 2;
    }
    (void)MDR_SFX(mdr_m_frexp)(c, &ec);
    if (ec - ea < 2) { /* c is itself that small */
        return MDR_K(0.5) * (lo + hi);
    }
    return MDR_SFX(mdr_m_ldexp)(MDR_K(1.0), (ea + ec) / 2); /* strictly inside (a, c) */
}

/* The rounding bound of mdr_e_U at p in spring 0, from the magnitudes of
 * the terms of the interpolation itself: there g = e (s + b (h - e)) and
 * G = e^2 (s/2 + b (h/2 - e/3)) are small differences of terms of size
 * e |s| (s + b h ~ g'(0) cancels for a profile flat at 0), so the error of
 * U is ~eps e |s|, far above mdr_e_Utol's eps |g| (measured: residuals of
 * ~1e3 eps |g| that Newton crept through past the iteration cap). */
static MDR_STEP_FN MDR_T MDR_SFX(mdr_e_Utol0)(const MDR_SFX(mdr_e_branch) *b, const MDR_SFX(mdr_e_pt) *p)
{
    const MDR_SFX(mdr_node) *n0 = &b->tab->node[0];
    MDR_T x = p->x, h = b->tab->h;
    MDR_T as = MDR_SFX(mdr_m_fabs)((n0[1].g - n0->g) * b->ih), ab = MDR_SFX(mdr_m_fabs)(n0->q * b->b6);
    MDR_T Dm = MDR_SFX(mdr_m_fabs)(n0->g) + x * (as + ab * (h + x)) + MDR_SFX(mdr_m_fabs)(b->c * p->t);
    MDR_T Gm = x * x * (MDR_K(0.5) * as + ab * (MDR_K(0.5) * h + x));
    return MDR_K(8.0) * MDR_EPS *
           (MDR_SFX(mdr_m_fabs)(b->al) * Dm + MDR_SFX(mdr_m_fabs)(b->ka) * (x * Dm + Gm));
}

/* Root of dir*(U - u) in spring k between ta (value < 0) and tb (>= 0):
 * Newton from the secant point, safeguarded as rtsafe (Press et al.,
 * Numerical Recipes, 2nd ed., 9.4): bisection whenever Newton leaves the
 * bracket or does not at least halve the step before the last one. Near
 * the root the rounding noise of U (the cancellation in x D - G) makes
 * plain Newton wander inside the bracket with steps of a few ulps; the
 * halving rules bound the iterations by twice those of bisection
 * (MDR_ENG_ITER).
 * A point where |U - u| is below U's absolute resolution, eps MDR_MINV,
 * is a root (U near the underflow threshold: a machine base of 2e-38 m in
 * f32, fuzz_step); mdr_e_Utol, the landing shift, is at least 8x that.
 * Converged when hi - lo <= 4 eps t, or when x = t^2 across the whole
 * bracket spans a few subnormal spacings, (hi - lo) max(lo, hi) <= 8 eps
 * MDR_MINV (a contact radius below the arithmetic's smallest normal
 * number, reached by depths like 1e-39 m in f32: fuzz_step; measured at
 * the bracket's top, not at t, which near t = 0 would accept any bracket).
 * In spring 0 a point on the target side of u by at most U's rounding
 * bound there (mdr_e_Utol0) is a root to working precision (not one below
 * it: a landing aims past the fold, and would take the fold for its
 * landing again): the bracket's low end is t = 0, so bisection to 4 eps
 * in t has no bound as the root approaches 0, and Newton crept through
 * U's noise ulp by ulp past the cap (f32 jump-ins of a 1 m sphere and of
 * a 1 cm sphere on 64 springs, make stress). */
static MDR_STEP_FN bool MDR_SFX(mdr_e_root)(const MDR_SFX(mdr_e_branch) *b, int dir, MDR_T u, uint16_t k,
                                MDR_T ta, MDR_T fa, MDR_T tb, MDR_T fb, MDR_SFX(mdr_e_pt) *out)
{
    MDR_T lo = ta, hi = tb, t, dx = tb - ta, dxold = dx, fprev = MDR_K(0.0);
    int it;
    /* the secant point; the midpoint when ta is itself at the target
     * (fa = 0: the landing of a jump-in at t = 0, where mdr_e_Utol is 0, or
     * any fold whose U equals the target exactly): the secant would return
     * ta, the fold, and the step would fold there again until
     * MDR_E_NOCONV (found with an 8-spring table, test_engine) */
    t = fa < MDR_K(0.0) && fb - fa > MDR_K(0.0) ? ta + (tb - ta) * (-fa / (fb - fa)) : MDR_SFX(mdr_e_mid)(ta, tb);
    if (!((t - ta) * (t - tb) < MDR_K(0.0))) {
        /* the secant point rounded onto or past an end (a bracket from 0.014
         * to 1.2e-11 gave t = 0, the trivial root U(0) = 0: fuzz_step) */
        t = MDR_SFX(mdr_e_mid)(ta, tb);
    }
    for (it = 0; it < MDR_ENG_ITER; it++) {
        MDR_SFX(mdr_e_pt) p = MDR_SFX(mdr_e_at)(b, k, t);
        MDR_T fv = (MDR_T)dir * (MDR_SFX(mdr_e_U)(b, &p) - u);
        MDR_T df = (MDR_T)dir * MDR_SFX(mdr_e_dU)(b, &p);
        MDR_T tn;
        if (fv < MDR_K(0.0)) {
            lo = t;
        } else {
            hi = t;
        }
        tn = df != MDR_K(0.0) ? t - fv / df : t;
        if ((k == 0u && fv >= MDR_K(0.0) && fv <= MDR_SFX(mdr_e_Utol0)(b, &p)) ||
            MDR_SFX(mdr_m_fabs)(fv) <= MDR_K(2.0) * MDR_EPS * MDR_MINV || /* below U's resolution */
            MDR_SFX(mdr_m_fabs)(hi - lo) <= MDR_K(4.0) * MDR_EPS * t ||
            MDR_SFX(mdr_m_fabs)(hi - lo) * (lo > hi ? lo : hi) <= MDR_K(8.0) * MDR_EPS * MDR_MINV) {
            *out = p;
            return true;
        }
        if (!((tn - lo) * (tn - hi) < MDR_K(0.0)) ||
            MDR_SFX(mdr_m_fabs)(MDR_K(2.0) * fv) > MDR_SFX(mdr_m_fabs)(dxold * df) ||
            MDR_SFX(mdr_e_wide)(lo, hi) ||
            (it > 0 && (fv < MDR_K(0.0)) == (fprev < MDR_K(0.0)) &&
             MDR_SFX(mdr_m_fabs)(fv) > MDR_K(0.5) * MDR_SFX(mdr_m_fabs)(fprev))) {
            /* out of the bracket, a step not half the one before last,
             * a bracket spanning orders of magnitude, or a residual that
             * did not halve on the same side: Newton is not converging
             * (it crept ulp by ulp where U's computed value and slope
             * disagree: U's noise in spring 0, terms underflowing) */
            tn = MDR_SFX(mdr_e_mid)(lo, hi);
        } else if (MDR_SFX(mdr_m_fabs)(tn - t) <= MDR_EPS * MDR_SFX(mdr_m_fabs)(t)) {
            *out = MDR_SFX(mdr_e_at)(b, k, tn);
            return true;
        }
        dxold = dx;
        dx = tn - t;
        fprev = fv;
        t = tn;
    }
    *out = MDR_SFX(mdr_e_at)(b, k, hi);
    return false;
}

/* Fold in spring k between ta (dU/dt >= 0 side, reached first) and tb
 * (dU/dt < 0): bisection on the sign of dU/dt. */
static MDR_STEP_FN MDR_SFX(mdr_e_pt) MDR_SFX(mdr_e_fold)(const MDR_SFX(mdr_e_branch) *b, uint16_t k,
                                             MDR_T ta, MDR_T tb)
{
    int it;
    for (it = 0; it < MDR_ENG_ITER; it++) {
        MDR_T tm = MDR_SFX(mdr_e_mid)(ta, tb);
        MDR_SFX(mdr_e_pt) p;
        if (tm == ta || tm == tb) {
            break;
        }
        p = MDR_SFX(mdr_e_at)(b, k, tm);
        if (MDR_SFX(mdr_e_dU)(b, &p) >= MDR_K(0.0)) {
            ta = tm;
        } else {
            tb = tm;
        }
    }
    return MDR_SFX(mdr_e_at)(b, k, ta);
}

enum { MDR_E_SCAN_ROOT, MDR_E_SCAN_FOLD, MDR_E_SCAN_END, MDR_E_SCAN_NOCONV };

/* Walk from the point p0 in direction dir (+1: a grows) to the first
 * dir*U >= dir*u (strictly > when !folds: the landing of a jump that left a
 * fold where U = u). With folds, stop at the first fold instead. */
static MDR_STEP_FN int MDR_SFX(mdr_e_scan)(const MDR_SFX(mdr_e_branch) *b, int dir, MDR_T u, bool folds,
                               const MDR_SFX(mdr_e_pt) *p0, MDR_SFX(mdr_e_pt) *out)
{
    const MDR_T su = (MDR_T)dir * u;
    const uint16_t n = b->tab->n;
    MDR_T tq = p0->t, Wq = (MDR_T)dir * MDR_SFX(mdr_e_U)(b, p0); /* previous point */
    MDR_T tpp = tq;                                               /* the one before */
    bool q_is_node = false;
    long j = dir > 0 ? (long)p0->k + 1 : (long)p0->k;
    if (folds && MDR_SFX(mdr_e_dU)(b, p0) < MDR_K(0.0)) {
        *out = *p0;
        return MDR_E_SCAN_FOLD;
    }
    for (; j >= 0 && j <= (long)n; j += dir) {
        uint16_t seg = (uint16_t)(dir > 0 ? j - 1 : j); /* spring between tq and t_j */
        MDR_SFX(mdr_e_pt) pj = MDR_SFX(mdr_e_node)(b, (uint16_t)j);
        MDR_T Wj = (MDR_T)dir * MDR_SFX(mdr_e_U)(b, &pj);
        /* Spring 0 of an adhesive branch (c > 0) holds a fold whatever its
         * node values say: U(0) = 0, and just above t = 0 dl = c t beats g
         * (and G), so U < 0 there and U has its minimum inside the spring.
         * Its end node t = 0 is not a root to land on: a receding edge
         * looks for the fold first (found by fuzz_step: a coarse table
         * whose pull-off radius lies inside spring 0 landed on a = 0 in
         * contact at d = 0, and peeled "smoothly" for d < 0). */
        const bool fold0 = folds && dir < 0 && j == 0 && b->c > MDR_K(0.0);
        if (pj.t == tq) { /* the start is this node: nothing between */
            Wq = Wj;
            q_is_node = true;
            continue;
        }
        if (!fold0 && (folds ? Wj >= su : Wj > su)) {
            return MDR_SFX(mdr_e_root)(b, dir, u, seg, tq, Wq - su, pj.t, Wj - su, out)
                       ? MDR_E_SCAN_ROOT
                       : MDR_E_SCAN_NOCONV;
        }
        if (folds && (Wj < Wq || fold0)) {
            /* the maximum of W lies around tq: in this spring if W still
             * rises there, else in the spring before it (or tq itself) */
            MDR_SFX(mdr_e_pt) pq = MDR_SFX(mdr_e_at)(b, seg, tq);
            MDR_SFX(mdr_e_pt) pf;
            MDR_T Wf;
            uint16_t fseg = seg;
            MDR_T ta = tq, tb = pj.t, fa = Wq - su;
            if (MDR_SFX(mdr_e_dU)(b, &pq) < MDR_K(0.0)) {
                if (!q_is_node) {
                    *out = pq;
                    return MDR_E_SCAN_FOLD;
                }
                fseg = (uint16_t)(dir > 0 ? seg - 1 : seg + 1);
                pq = MDR_SFX(mdr_e_at)(b, fseg, tq);
                if (MDR_SFX(mdr_e_dU)(b, &pq) >= MDR_K(0.0)) {
                    *out = pq; /* a kink at the node */
                    return MDR_E_SCAN_FOLD;
                }
                ta = tpp;
                tb = tq;
                {
                    MDR_SFX(mdr_e_pt) pa = MDR_SFX(mdr_e_at)(b, fseg, tpp);
                    fa = (MDR_T)dir * MDR_SFX(mdr_e_U)(b, &pa) - su;
                }
            }
            pf = MDR_SFX(mdr_e_fold)(b, fseg, ta, tb);
            Wf = (MDR_T)dir * MDR_SFX(mdr_e_U)(b, &pf);
            if (Wf >= su) { /* the branch reaches u between the samples */
                return MDR_SFX(mdr_e_root)(b, dir, u, fseg, ta, fa, pf.t, Wf - su, out)
                           ? MDR_E_SCAN_ROOT
                           : MDR_E_SCAN_NOCONV;
            }
            *out = pf;
            return MDR_E_SCAN_FOLD;
        }
        tpp = tq;
        tq = pj.t;
        Wq = Wj;
        q_is_node = true;
    }
    return MDR_E_SCAN_END;
}

/* Trapezoid of F dd from (d0, F0) to (d1, F1) into the work sum. */
static MDR_STEP_FN void MDR_SFX(mdr_e_work)(MDR_SFX(mdr_engine) *s, MDR_T d0, MDR_T F0, MDR_T d1, MDR_T F1)
{
    MDR_SFX(mdr_e_kahan)(&s->work, &s->work_c, MDR_K(0.5) * (F0 + F1) * (d1 - d0));
}

/* The state with the edge at p and the control at u: d from u (pinned
 * relation), F = 2E*(a d - G). For fixed load F is u exactly. */
static MDR_STEP_FN void MDR_SFX(mdr_e_state)(const MDR_SFX(mdr_e_branch) *b, MDR_T E, MDR_T u,
                                 const MDR_SFX(mdr_e_pt) *p, MDR_T *d, MDR_T *F)
{
    *d = (u + b->ka * p->G) / (b->al + b->ka * p->x);
    *F = b->al == MDR_K(0.0) ? MDR_K(2.0) * E * u : MDR_K(2.0) * E * (p->x * *d - p->G);
}

/* A refused step: set the sticky flag, leave the state, return the status. */
static MDR_STEP_FN mdr_status MDR_SFX(mdr_e_refuse)(MDR_SFX(mdr_engine) *e, uint8_t flag, mdr_status st)
{
    e->flags |= flag;
    return st;
}

/* One step with the control u on the branch family (al, ka). */
static MDR_STEP_FN mdr_status MDR_SFX(mdr_e_step)(MDR_SFX(mdr_engine) *e, MDR_T al, MDR_T ka, MDR_T u,
                                      MDR_SFX(mdr_step) *out)
{
    const MDR_SFX(mdr_table) *tab = e->tab;
    MDR_SFX(mdr_engine) s = *e; /* work on a copy: a refused step changes nothing */
    MDR_SFX(mdr_e_branch) b;
    MDR_SFX(mdr_e_pt) p;
    MDR_SFX(mdr_step) o;
    MDR_T dprev = e->d, Fprev = e->F, d, F;
    int dir = 0;
    bool from_sep = !e->contact;
    unsigned iter;

    b.tab = tab;
    b.al = al;
    b.ka = ka;
    b.c = b.ih = b.b6 = MDR_K(0.0); /* set below if the edge moves */
    p.t = s.t;
    p.x = s.a;
    p.g = s.g;
    p.G = s.Ga;
    p.dg = MDR_K(0.0);
    p.k = s.k;
    o.event = MDR_EV_NONE;
    o.jumps = 0;

    if (s.contact) { /* the pinned state; kept if the edge stays */
        MDR_SFX(mdr_e_state)(&b, s.E, u, &p, &d, &F);
        if (d > p.g - s.c_adv * p.t) {
            dir = 1;
        } else if (d < p.g - s.c_w * p.t) {
            dir = -1;
        }
    } else if (u > MDR_K(0.0)) {
        dir = 1; /* U(0) = 0 on every branch */
        dprev = Fprev = MDR_K(0.0); /* the touch point */
    }
    if (dir != 0) { /* the edge moves: interpolation constants, g' for the fold test */
        b.c = dir > 0 ? s.c_adv : s.c_w;
        b.ih = MDR_K(1.0) / tab->h;
        b.b6 = MDR_K(6.0) * b.ih * b.ih * b.ih;
        p = MDR_SFX(mdr_e_at)(&b, s.k, s.t);
    }
    for (iter = 0; dir != 0; iter++) {
        MDR_SFX(mdr_e_pt) pf, pl;
        MDR_T uf, df, Ff, dl, Fl;
        int r;
        if (iter > (unsigned)tab->n + 1u) {
            return MDR_SFX(mdr_e_refuse)(e, MDR_FLAG_NOCONV, MDR_E_NOCONV);
        }
        if (dir > 0 && s.contact && tab->wall && p.k == tab->n - 1 && p.t >= tab->node[tab->n].t) {
            break; /* held at the wall */
        }
        r = MDR_SFX(mdr_e_scan)(&b, dir, u, true, &p, &pf);
        if (r == MDR_E_SCAN_NOCONV) {
            return MDR_SFX(mdr_e_refuse)(e, MDR_FLAG_NOCONV, MDR_E_NOCONV);
        }
        if (r == MDR_E_SCAN_ROOT) {
            p = pf;
            s.contact = 1;
            break;
        }
        if (r == MDR_E_SCAN_END) {
            if (dir > 0) {
                if (!tab->wall) {
                    return MDR_SFX(mdr_e_refuse)(e, MDR_FLAG_OUTSIDE, MDR_E_OUTSIDE);
                }
                p = MDR_SFX(mdr_e_node)(&b, tab->n);
                s.contact = 1;
                break;
            }
            o.event = MDR_EV_SEPARATION; /* peeled smoothly to a = 0 */
            s.contact = 0;
            break;
        }
        /* a fold at pf: the last stable state; jump at constant u there */
        uf = MDR_SFX(mdr_e_U)(&b, &pf);
        MDR_SFX(mdr_e_state)(&b, s.E, uf, &pf, &df, &Ff);
        if (pf.x == MDR_K(0.0)) { /* fold at first touch */
            df = MDR_K(0.0);
            Ff = MDR_K(0.0);
        }
        MDR_SFX(mdr_e_work)(&s, dprev, Fprev, df, Ff);
        o.a0 = pf.x;
        o.d0 = df;
        o.F0 = Ff;
        if (o.jumps < 255u) {
            o.jumps++;
        }
        /* the landing: the first point past the fold where the branch is
         * back at uf. Past the fold U first moves away from uf; the
         * target is uf shifted beyond the rounding error of U (mdr_e_Utol),
         * so that a node next to the fold whose U equals uf but for
         * rounding is not taken for a landing at the fold itself (which
         * would fold again there, without end: seen in f32 at N = 4096
         * in bench_matrix). */
        r = MDR_SFX(mdr_e_scan)(&b, dir, uf + (MDR_T)dir * MDR_SFX(mdr_e_Utol)(&b, &pf), false, &pf, &pl);
        if (r == MDR_E_SCAN_NOCONV) {
            return MDR_SFX(mdr_e_refuse)(e, MDR_FLAG_NOCONV, MDR_E_NOCONV);
        }
        if (r == MDR_E_SCAN_END && dir < 0) {
            /* pull-off: every spring lets go at (df, Ff); the contact
             * force drops along the control line (grips: at d = df;
             * machine: to d = z; load: at d = df, the body is then free) */
            o.event = MDR_EV_PULL_OFF;
            o.a1 = MDR_K(0.0);
            o.d1 = al != MDR_K(0.0) ? uf : df;
            o.F1 = MDR_K(0.0);
            MDR_SFX(mdr_e_work)(&s, df, Ff, o.d1, MDR_K(0.0));
            dprev = o.d1;
            Fprev = MDR_K(0.0);
            s.contact = 0;
            break;
        }
        if (r == MDR_E_SCAN_END) {
            if (!tab->wall) {
                return MDR_SFX(mdr_e_refuse)(e, MDR_FLAG_OUTSIDE, MDR_E_OUTSIDE);
            }
            pl = MDR_SFX(mdr_e_node)(&b, tab->n);
        }
        MDR_SFX(mdr_e_state)(&b, s.E, uf, &pl, &dl, &Fl);
        MDR_SFX(mdr_e_work)(&s, df, Ff, dl, Fl);
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
            MDR_SFX(mdr_e_state)(&b, s.E, u, &p, &d, &F);
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
        /* separated: no force; d follows the control where it defines d,
         * under fixed load it stays where contact was lost */
        F = MDR_K(0.0);
        d = al != MDR_K(0.0) ? u
            : o.event == MDR_EV_PULL_OFF ? dprev
            : o.event == MDR_EV_SEPARATION ? MDR_K(0.0) : e->d;
        s.a = s.t = s.g = s.Ga = MDR_K(0.0);
        s.k = 0;
    }
    if (o.event == MDR_EV_SEPARATION) { /* the branch ends at (0, 0) */
        MDR_SFX(mdr_e_work)(&s, dprev, Fprev, MDR_K(0.0), MDR_K(0.0));
    } else if (s.contact) {
        MDR_SFX(mdr_e_work)(&s, dprev, Fprev, d, F);
    }
    if (!s.contact && e->contact) { /* a cycle ends */
        MDR_T wk = s.work - s.work_c;
        MDR_T cyc = wk - s.work_sep;
        s.work_sep = wk;
        s.last_cycle = cyc;
        s.dissipated += cyc;
        s.cycles++;
    }
    s.d = d;
    s.F = F;
    o.a = s.a;
    o.d = d;
    o.F = F;
    o.z = s.k_m > MDR_K(0.0) ? d + F / s.k_m : d;
    if (o.jumps == 0) {
        o.a0 = o.a1 = o.a;
        o.d0 = o.d1 = d;
        o.F0 = o.F1 = F;
    }
    /* the energy sums too: F dd of a flat punch driven 1e19 m deep is
     * finite in F and d and not in float (fuzz_step) */
    if (!MDR_SFX(mdr_m_isfinite)(d) || !MDR_SFX(mdr_m_isfinite)(F) || !MDR_SFX(mdr_m_isfinite)(o.z) ||
        !MDR_SFX(mdr_m_isfinite)(s.work) || !MDR_SFX(mdr_m_isfinite)(s.work_c) ||
        !MDR_SFX(mdr_m_isfinite)(s.dissipated)) {
        return MDR_E_OVERFLOW;
    }
    MDR_ASSERT(s.k < tab->n); /* the edge lies in spring k: x_k <= a <= x_{k+1} */
    *e = s;
    *out = o;
    return MDR_OK;
}

MDR_STEP_FN mdr_status MDR_SFX(mdr_engine_step_d)(MDR_SFX(mdr_engine) *e, MDR_T d, MDR_SFX(mdr_step) *out)
{
    if (e == NULL || out == NULL || e->tab == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_m_isfinite)(d)) {
        return MDR_E_NONFINITE;
    }
    return MDR_SFX(mdr_e_step)(e, MDR_K(1.0), MDR_K(0.0), d, out);
}

MDR_STEP_FN mdr_status MDR_SFX(mdr_engine_step_F)(MDR_SFX(mdr_engine) *e, MDR_T F, MDR_SFX(mdr_step) *out)
{
    if (e == NULL || out == NULL || e->tab == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_m_isfinite)(F)) {
        return MDR_E_NONFINITE;
    }
    return MDR_SFX(mdr_e_step)(e, MDR_K(0.0), MDR_K(1.0), F / (MDR_K(2.0) * e->E), out);
}

MDR_STEP_FN mdr_status MDR_SFX(mdr_engine_step_z)(MDR_SFX(mdr_engine) *e, MDR_T z, MDR_SFX(mdr_step) *out)
{
    if (e == NULL || out == NULL || e->tab == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_m_isfinite)(z)) {
        return MDR_E_NONFINITE;
    }
    if (!(e->k_m > MDR_K(0.0))) {
        return MDR_E_CONTROL;
    }
    return MDR_SFX(mdr_e_step)(e, MDR_K(1.0), e->kappa, z, out);
}
#endif /* MDR_CFG_ENGINE */
