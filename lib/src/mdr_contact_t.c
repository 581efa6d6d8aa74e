/*
 * mdr_contact_t.c: the contact module, written once for every floating
 * arithmetic (see mdr_arith.h). Equation numbers refer to the seed chapter
 * (Popov, Hess, Willert: Handbook of Contact Mechanics, ch. 4).
 *
 * Derived constants in c->k[] per profile:
 *   paraboloid, sphere: k = {R}
 *   cone:      k = {(pi/2) tan(theta)}                 g = k0 x           (4.55)
 *   powerlaw:  k = {kappa_n C, n}                       g = k0 x^n         (4.65)
 *   flatpunch: k = {a0}                                 g = 0
 *   flattip:   k = {R, b}                               g = x sqrt(x^2-b^2)/R (4.81)
 *   wavy:      k = {pi^2 h/lambda, 2 pi/lambda, pi h/2}, R = p[0] (4.47, 4.51)
 *
 * Cancellation. F(a) = 2E*(a d - G) is evaluated as 2E* a (hbar - dl) with
 * hbar(a) = (a g(a) - G(a))/a = (1/a) int_0^a x g'(x) dx written in closed
 * form per profile, so no profile term cancels: for the exact sphere
 * hbar = (R/2)(t atanh t + (atanh t - t)/t), t = a/R, where atanh t - t is
 * summed as a series (mdr_m_atanh_m) instead of subtracting R a from
 * (R^2+a^2) atanh(a/R) as in 4.77 (which keeps no digit at a/R = 1e-3 in
 * float). The remaining subtraction hbar - dl is the physics (F changes sign)
 * and its error is relative to the scale 2E* a dl, not to F.
 * Lengths enter as ratios (a/R) before being multiplied, so no a^3 or a^n is
 * formed that could underflow in float for nanometre contacts.
 */
#include "mdr_tables.h"

/* g(x), g'(x) and hbar(x) = (x g(x) - G(x))/x for x in the profile's domain
 * (checked by the caller). dg may come back +inf (flattened tip at x = b).
 * Wavy profile: k = {pi^2 h/lambda, 2 pi/lambda, pi h/2}, R = p[0]. */
static void MDR_SFX(mdr_c_profile)(const MDR_SFX(mdr_contact) *c, MDR_T x, MDR_T *g, MDR_T *dg,
                                   MDR_T *hbar)
{
    const MDR_T *k = c->k;
    switch (c->kind) {
#if MDR_CFG_PROFILE_PARABOLOID
    case MDR_PROFILE_PARABOLOID: {
        MDR_T t = x / k[0];
        *g = x * t;
        *dg = MDR_K(2.0) * t;
        *hbar = MDR_K(2.0) / MDR_K(3.0) * x * t;
        break;
    }
#endif
#if MDR_CFG_PROFILE_CONE
    case MDR_PROFILE_CONE:
        *g = k[0] * x;
        *dg = k[0];
        *hbar = MDR_K(0.5) * k[0] * x;
        break;
#endif
#if MDR_CFG_PROFILE_POWERLAW
    case MDR_PROFILE_POWERLAW: {
        MDR_T gv = MDR_SFX(mdr_m_powscaled)(k[0], x, k[1]);
        *g = gv;
        *dg = k[1] * (gv / x);
        *hbar = k[1] / (k[1] + MDR_K(1.0)) * gv;
        break;
    }
#endif
#if MDR_CFG_PROFILE_SPHERE
    case MDR_PROFILE_SPHERE: {
        /* 1 - t from R - x (exact for x >= R/2): accurate as a -> R */
        MDR_T t = x / k[0], omt = (k[0] - x) / k[0];
        MDR_T am = MDR_SFX(mdr_m_atanh_m2)(t, omt), at = t + am;
        *g = x * at;
        *dg = at + t / (omt * (MDR_K(1.0) + t));
        *hbar = MDR_K(0.5) * k[0] * (t * at + am / t);
        break;
    }
#endif
#if MDR_CFG_PROFILE_FLATTIP
    case MDR_PROFILE_FLATTIP: {
        MDR_T b = k[1];
        if (x <= b) {
            *g = MDR_K(0.0);
            *dg = (x < b) ? MDR_K(0.0) : MDR_MAXV * MDR_K(2.0);
            *hbar = MDR_K(0.0);
        } else {
            MDR_T s2 = (x - b) * (x + b), s = MDR_SQRT(s2);
            *g = x / k[0] * s;
            *dg = (MDR_K(2.0) * s2 + b * b) / (k[0] * s);
            *hbar = s / (MDR_K(3.0) * k[0]) * (MDR_K(2.0) * x + b * (b / x));
        }
        break;
    }
#endif
#if MDR_CFG_PROFILE_WAVY
    case MDR_PROFILE_WAVY: {
        MDR_T h0, h1, h0p, zh, z;
        MDR_T t = x / c->p[0];
        /* z = 2 pi x/lambda; phase exact to eps^2 for any x/lambda */
        MDR_SFX(mdr_m_struve01_wave)(x, c->p[2], &z, &h0, &h1, &h0p, &zh);
        *g = x * t + k[0] * x * h0;                      /* 4.47 */
        *dg = MDR_K(2.0) * t + k[0] * (h0 + z * h0p);    /* d/dx [x H0(kx)] */
        *hbar = MDR_K(2.0) / MDR_K(3.0) * x * t + k[2] * zh; /* 4.51 / (2E* a) */
        break;
    }
#endif
    default: /* MDR_PROFILE_FLATPUNCH: g = 0 on 0 <= x <= a0 (init admits no
              * other kind: the cases above are those built) */
        *g = MDR_K(0.0);
        *dg = MDR_K(0.0);
        *hbar = MDR_K(0.0);
        break;
    }
}

/* The profile's domain for a contact radius or an abscissa x. */
static mdr_status MDR_SFX(mdr_c_domain)(const MDR_SFX(mdr_contact) *c, MDR_T x)
{
    if (!MDR_SFX(mdr_m_isfinite)(x)) {
        return MDR_E_NONFINITE;
    }
    if (!(x > MDR_K(0.0))) {
        return MDR_E_RADIUS;
    }
    if (c->kind == MDR_PROFILE_SPHERE && !(x < c->p[0])) {
        return MDR_E_RADIUS;
    }
    if (c->kind == MDR_PROFILE_FLATPUNCH && x > c->p[0]) {
        return MDR_E_RADIUS;
    }
    if (c->kind == MDR_PROFILE_WAVY && !(x / c->p[2] < MDR_WAVY_QMAX)) {
        return MDR_E_RADIUS; /* the phase 2 pi x/lambda has no correct digit */
    }
    return MDR_OK;
}

mdr_status MDR_SFX(mdr_contact_init)(MDR_SFX(mdr_contact) *c, uint8_t kind, const MDR_T p[3],
                                     MDR_T E, MDR_T w)
{
    MDR_SFX(mdr_contact) t;
    int i, np;
    if (c == NULL || p == NULL) {
        return MDR_E_NULL;
    }
    switch (kind) {
    case MDR_PROFILE_PARABOLOID:
    case MDR_PROFILE_CONE:
    case MDR_PROFILE_FLATPUNCH:
    case MDR_PROFILE_SPHERE:
        np = 1;
        break;
    case MDR_PROFILE_POWERLAW:
    case MDR_PROFILE_FLATTIP:
        np = 2;
        break;
    case MDR_PROFILE_WAVY:
        np = 3;
        break;
    default:
        return MDR_E_KIND;
    }
    if (!MDR_CFG_HAS_PROFILE(kind)) {
        return MDR_E_DISABLED;
    }
    if (!MDR_SFX(mdr_m_isfinite)(E) || !MDR_SFX(mdr_m_isfinite)(w)) {
        return MDR_E_NONFINITE;
    }
    for (i = 0; i < np; i++) {
        if (!MDR_SFX(mdr_m_isfinite)(p[i])) {
            return MDR_E_NONFINITE;
        }
    }
    if (!(E > MDR_K(0.0)) || !(w >= MDR_K(0.0))) {
        return MDR_E_PARAM;
    }
    t.kind = (uint8_t)kind;
    t.E = E;
    t.w = w;
    for (i = 0; i < 3; i++) {
        t.p[i] = (i < np) ? p[i] : MDR_K(0.0);
        t.k[i] = MDR_K(0.0);
    }
    t.c_dl = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w / E));
    switch (kind) {
#if MDR_CFG_PROFILE_CONE
    case MDR_PROFILE_CONE: {
        MDR_T sv, cv;
        if (!(p[0] > MDR_K(0.0)) || !(p[0] < MDR_PI * MDR_K(0.5))) {
            return MDR_E_PARAM;
        }
        MDR_SFX(mdr_m_sincos)(p[0], &sv, &cv);
        t.k[0] = MDR_PI * MDR_K(0.5) * (sv / cv); /* kappa_1 tan(theta), 4.55 */
        break;
    }
#endif
#if MDR_CFG_PROFILE_POWERLAW
    case MDR_PROFILE_POWERLAW:
        if (!(p[0] > MDR_K(0.0)) || !(p[1] > MDR_K(0.0)) || p[1] > (MDR_T)MDR_POWERLAW_N_MAX) {
            return MDR_E_PARAM;
        }
        /* kappa_n = sqrt(pi) Gamma(n/2+1)/Gamma((n+1)/2)   (4.65) */
        t.k[0] = MDR_K(1.772453850905516027298167483341145183) *
                 MDR_SFX(mdr_m_gamma_ratio_half)((p[1] + MDR_K(1.0)) * MDR_K(0.5)) * p[0];
        t.k[1] = p[1];
        break;
#endif
    case MDR_PROFILE_FLATTIP:
        if (!(p[0] > MDR_K(0.0)) || !(p[1] >= MDR_K(0.0))) {
            return MDR_E_PARAM;
        }
        t.k[0] = p[0];
        t.k[1] = p[1];
        break;
#if MDR_CFG_PROFILE_WAVY
    case MDR_PROFILE_WAVY:
        if (!(p[0] > MDR_K(0.0)) || !(p[1] >= MDR_K(0.0)) || !(p[2] > MDR_K(0.0))) {
            return MDR_E_PARAM;
        }
        t.k[0] = MDR_PI * MDR_PI * (p[1] / p[2]);
        t.k[1] = MDR_K(2.0) * MDR_PI / p[2];
        t.k[2] = MDR_PI * MDR_K(0.5) * p[1];
        break;
#endif
    default: /* paraboloid, sphere, flat punch: one length > 0 */
        if (!(p[0] > MDR_K(0.0))) {
            return MDR_E_PARAM;
        }
        t.k[0] = p[0];
        break;
    }
    for (i = 0; i < 3; i++) {
        if (!MDR_SFX(mdr_m_isfinite)(t.k[i])) {
            return MDR_E_PARAM;
        }
    }
    if (!MDR_SFX(mdr_m_isfinite)(t.c_dl)) {
        return MDR_E_PARAM;
    }
    *c = t;
    return MDR_OK;
}

mdr_status MDR_SFX(mdr_profile_eval)(const MDR_SFX(mdr_contact) *c, MDR_T x, MDR_T *g, MDR_T *dg,
                                     MDR_T *G)
{
    MDR_T gv, dgv, hb, Gv;
    mdr_status st;
    if (c == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_c_domain)(c, x);
    if (st != MDR_OK) {
        return st;
    }
    MDR_SFX(mdr_c_profile)(c, x, &gv, &dgv, &hb);
    Gv = x * (gv - hb); /* G = x g - H = x (g - hbar); g - hbar >= g/3 for every profile here */
    if (!MDR_SFX(mdr_m_isfinite)(gv) || !MDR_SFX(mdr_m_isfinite)(Gv) ||
        (dg != NULL && !MDR_SFX(mdr_m_isfinite)(dgv))) {
        return MDR_E_OVERFLOW;
    }
    if (g != NULL) {
        *g = gv;
    }
    if (dg != NULL) {
        *dg = dgv;
    }
    if (G != NULL) {
        *G = Gv;
    }
    return MDR_OK;
}

/* Equilibrium state without argument checks (a in the domain). Returns
 * MDR_E_OVERFLOW if anything is not finite. */
static mdr_status MDR_SFX(mdr_c_eq)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_SFX(mdr_eqstate) *o)
{
    MDR_T g, dg, hb, dl, twoEa;
    MDR_SFX(mdr_c_profile)(c, a, &g, &dg, &hb);
    dl = c->c_dl * MDR_SQRT(a);              /* 4.21 */
    twoEa = MDR_K(2.0) * c->E * a;
    o->a = a;
    o->dl = dl;
    o->d = g - dl;                           /* 4.25 */
    o->F = twoEa * (hb - dl);                /* 4.26 = 2E*(a d - G) */
    o->dd_da = dg - MDR_K(0.5) * dl / a;
    o->dF_da = MDR_K(2.0) * c->E * (a * dg - MDR_K(1.5) * dl);
    /* K_I = dF/(2a sqrt(pi a)) with dF = 2E* a dl (4.17, 4.18) */
    o->K_I = c->E * dl / MDR_SQRT(MDR_PI * a);
    o->G = o->K_I * (o->K_I / (MDR_K(2.0) * c->E));
    o->stable_load = o->dF_da > MDR_K(0.0);
    o->stable_grips = o->dd_da > MDR_K(0.0);
    if (!MDR_SFX(mdr_m_isfinite)(o->d) || !MDR_SFX(mdr_m_isfinite)(o->F) ||
        !MDR_SFX(mdr_m_isfinite)(o->dd_da) || !MDR_SFX(mdr_m_isfinite)(o->dF_da) ||
        !MDR_SFX(mdr_m_isfinite)(o->K_I) || !MDR_SFX(mdr_m_isfinite)(o->G)) {
        return MDR_E_OVERFLOW;
    }
    return MDR_OK;
}

mdr_status MDR_SFX(mdr_eq)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_SFX(mdr_eqstate) *out)
{
    MDR_SFX(mdr_eqstate) o;
    mdr_status st;
    if (c == NULL || out == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_c_domain)(c, a);
    if (st != MDR_OK) {
        return st;
    }
    st = MDR_SFX(mdr_c_eq)(c, a, &o);
    if (st == MDR_OK) {
        *out = o;
    }
    return st;
}

#if MDR_CFG_STRESS
mdr_status MDR_SFX(mdr_stress_intensity)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_T d, MDR_T *K_I,
                                         MDR_T *G)
{
    MDR_T g, dg, hb, k, gr;
    mdr_status st;
    if (c == NULL || K_I == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_c_domain)(c, a);
    if (st != MDR_OK) {
        return st;
    }
    if (!MDR_SFX(mdr_m_isfinite)(d)) {
        return MDR_E_NONFINITE;
    }
    MDR_SFX(mdr_c_profile)(c, a, &g, &dg, &hb);
    /* K_I = dF/(2a sqrt(pi a)), dF = F_na - F = 2E* a (g(a) - d)   (4.16, 4.17) */
    k = c->E * (g - d) / MDR_SQRT(MDR_PI * a);
    gr = k * (k / (MDR_K(2.0) * c->E));
    if (!MDR_SFX(mdr_m_isfinite)(k) || !MDR_SFX(mdr_m_isfinite)(gr)) {
        return MDR_E_OVERFLOW;
    }
    *K_I = k;
    if (G != NULL) {
        *G = gr;
    }
    return MDR_OK;
}

/*
 * S(r, a) = int_r^a g'(x)/sqrt(x^2 - r^2) dx, the Abel integral of 4.27.
 *
 * Closed forms: paraboloid (2/R) sqrt(a^2-r^2) (4.41); cone
 * k0 acosh(a/r); flat punch 0. Other profiles: tanh-sinh quadrature
 * (Takahasi & Mori 1974; h = 1/8, 57 nodes from mdr_tables.h) over
 *   u in [0, a - r], x = r + u, integrand g'(x)/sqrt(u (2r + u)),
 * whose only singularity (algebraic, at u = 0) the double-exponential rule
 * integrates at full rate; the flattened tip with r < b uses
 *   s in [0, sqrt(a^2 - b^2)], x = sqrt(b^2 + s^2),
 *   integrand (2x^2 - b^2)/(R x sqrt(s^2 + b^2 - r^2))
 * (from x^2 = b^2 + s^2, which removes the 1/sqrt(x - b) of g').
 * The wavy profile's g' oscillates with period lambda: the u range is cut
 * into panels of at most lambda/4 (at most 512; beyond a = 128 lambda the
 * accuracy degrades), each integrated by the same rule.
 * Error of the rule: measured against ref/ (host_tests/test_gsl.c), see the
 * README; not guaranteed within 1e-3 a of a singular point (r -> b).
 */
static MDR_T MDR_SFX(mdr_c_stress_integrand)(const MDR_SFX(mdr_contact) *c, MDR_T r, MDR_T u,
                                             bool flat_s)
{
    MDR_T g, dg, hb;
    if (flat_s) {
        MDR_T b = c->k[1], x = MDR_SQRT(b * b + u * u); /* u = 0 is regular here */
        return (MDR_K(2.0) * x * x - b * b) /
               (c->k[0] * x * MDR_SQRT(u * u + (b - r) * (b + r)));
    }
    if (u == MDR_K(0.0)) {
        return MDR_K(0.0); /* a node that underflowed onto the end point: weight < 1e-22 */
    }
    MDR_SFX(mdr_c_profile)(c, r + u, &g, &dg, &hb);
    /* sqrt(u) sqrt(2r + u), not sqrt(u (2r + u)): the product underflows in
     * float for nodes within 1e-30 of the end point */
    return dg / (MDR_SQRT(u) * MDR_SQRT(MDR_K(2.0) * r + u));
}

/* tanh-sinh over u in [u0, u0 + U] of the stress integrand */
static MDR_T MDR_SFX(mdr_c_de)(const MDR_SFX(mdr_contact) *c, MDR_T r, MDR_T u0, MDR_T U, bool flat_s)
{
    static const MDR_T de[MDR_DE_N][2] = {MDR_DE_TABLE};
    MDR_T half = MDR_K(0.5) * U, sum;
    int j;
    sum = de[0][1] * MDR_SFX(mdr_c_stress_integrand)(c, r, u0 + half, flat_s);
    for (j = 1; j < MDR_DE_N; j++) {
        MDR_T off = half * de[j][0];
        sum += de[j][1] * (MDR_SFX(mdr_c_stress_integrand)(c, r, u0 + off, flat_s) +
                           MDR_SFX(mdr_c_stress_integrand)(c, r, u0 + (U - off), flat_s));
    }
    return half * sum;
}

#define MDR_ABEL_PANELS_MAX 512

static MDR_T MDR_SFX(mdr_c_abel)(const MDR_SFX(mdr_contact) *c, MDR_T r, MDR_T a)
{
    MDR_T U, sum;
    int np = 1, i;
    switch (c->kind) {
    case MDR_PROFILE_PARABOLOID:
        return MDR_K(2.0) / c->k[0] * MDR_SQRT((a - r) * (a + r));
#if MDR_CFG_PROFILE_CONE
    case MDR_PROFILE_CONE:
        return c->k[0] * MDR_SFX(mdr_m_log)((a + MDR_SQRT((a - r) * (a + r))) / r);
#endif
    case MDR_PROFILE_FLATPUNCH:
        return MDR_K(0.0);
    default:
        break;
    }
    if (c->kind == MDR_PROFILE_FLATTIP && a <= c->k[1]) {
        return MDR_K(0.0); /* the contact lies on the flat: g' = 0 on [0, a] (found by make stress) */
    }
    if (c->kind == MDR_PROFILE_FLATTIP && r < c->k[1]) {
        return MDR_SFX(mdr_c_de)(c, r, MDR_K(0.0), MDR_SQRT((a - c->k[1]) * (a + c->k[1])), true);
    }
    U = a - r;
    if (c->kind == MDR_PROFILE_WAVY && c->p[1] > MDR_K(0.0)) {
        /* g' oscillates with period lambda: panels of at most lambda/4 */
        MDR_T q = U / (c->p[2] * MDR_K(0.25));
        np = q >= (MDR_T)MDR_ABEL_PANELS_MAX ? MDR_ABEL_PANELS_MAX : (int)q + 1;
    }
    /* panel 0 holds the 1/sqrt end point; the others are regular */
    sum = MDR_K(0.0);
    for (i = 0; i < np; i++) {
        /* U times a fraction: U * i overflows float for U > FLT_MAX/512
         * (fuzz_init: a wavy contact of a = 3e36 m) */
        MDR_T u0 = U * ((MDR_T)i / (MDR_T)np), u1 = U * ((MDR_T)(i + 1) / (MDR_T)np);
        sum += MDR_SFX(mdr_c_de)(c, r, u0, u1 - u0, false);
    }
    return sum;
}

mdr_status MDR_SFX(mdr_stress_at)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_T d, MDR_T r,
                                  MDR_T *sigma)
{
    MDR_T g, dg, hb, s;
    mdr_status st;
    if (c == NULL || sigma == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_c_domain)(c, a);
    if (st != MDR_OK) {
        return st;
    }
    if (!MDR_SFX(mdr_m_isfinite)(d) || !MDR_SFX(mdr_m_isfinite)(r)) {
        return MDR_E_NONFINITE;
    }
    if (!(r >= MDR_K(0.0)) || !(r < a)) {
        return MDR_E_POSITION;
    }
    if (r == MDR_K(0.0) && (c->kind == MDR_PROFILE_CONE ||
                            (c->kind == MDR_PROFILE_POWERLAW && c->k[1] <= MDR_K(1.0)))) {
        return MDR_E_SINGULAR;
    }
    if (c->kind == MDR_PROFILE_FLATTIP && r == c->k[1]) {
        return MDR_E_SINGULAR;
    }
    MDR_SFX(mdr_c_profile)(c, a, &g, &dg, &hb);
    /* 4.27 with q = E*(d - g): q' = -E* g', q(a) = E*(d - g(a)) */
    s = c->E / MDR_PI *
        ((g - d) / MDR_SQRT((a - r) * (a + r)) - MDR_SFX(mdr_c_abel)(c, r, a));
    if (!MDR_SFX(mdr_m_isfinite)(s)) {
        return MDR_E_OVERFLOW;
    }
    *sigma = s;
    return MDR_OK;
}

mdr_status MDR_SFX(mdr_stress)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_T r, MDR_T *sigma)
{
    MDR_SFX(mdr_eqstate) e;
    mdr_status st;
    if (c == NULL || sigma == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_eq)(c, a, &e);
    if (st != MDR_OK) {
        return st;
    }
    return MDR_SFX(mdr_stress_at)(c, a, e.d, r, sigma);
}
#endif /* MDR_CFG_STRESS */

/* ---- critical states ---------------------------------------------------- */

/* Controlled variable c(a) and its slope for a control mode. */
static mdr_status MDR_SFX(mdr_c_ctrl)(const MDR_SFX(mdr_contact) *c, uint8_t control, MDR_T km, MDR_T a,
                                      MDR_T *v, MDR_T *dv, MDR_SFX(mdr_eqstate) *e)
{
    mdr_status st = MDR_SFX(mdr_c_eq)(c, a, e);
    /* the rim of the flattened tip, a = b: only the slopes are infinite (g'
     * = +inf); d and F are set and finite (g(b) = G(b) = 0). The search takes
     * the limit from above: stable, slope +inf. */
    bool rim = st == MDR_E_OVERFLOW && c->kind == MDR_PROFILE_FLATTIP && a == c->k[1];
    if (st != MDR_OK && !rim) {
        return st;
    }
    if (control == MDR_CONTROL_LOAD) {
        *v = e->F;
        *dv = e->dF_da;
    } else if (control == MDR_CONTROL_GRIPS) {
        *v = e->d;
        *dv = e->dd_da;
    } else {
        *v = e->d + e->F / km;
        *dv = e->dd_da + e->dF_da / km;
    }
    if (rim) {
        *dv = MDR_MAXV;
    }
    return MDR_OK;
}

#define MDR_CRIT_STEP MDR_K(0.015)
#define MDR_CRIT_AMIN MDR_K(1e-9)
#define MDR_CRIT_BISECT 200

/* Next grid point below a: geometric step, at most lambda/16 (wavy). */
static MDR_T MDR_SFX(mdr_c_step)(const MDR_SFX(mdr_contact) *c, MDR_T a)
{
    MDR_T h = a * MDR_CRIT_STEP;
    if (c->kind == MDR_PROFILE_WAVY && c->p[1] > MDR_K(0.0)) {
        MDR_T hw = c->p[2] * MDR_K(0.0625);
        h = h < hw ? h : hw;
    }
    return a - h;
}

/* Bisection of [lo, hi] to machine precision (at most MDR_CRIT_BISECT
 * halvings, then MDR_E_NOCONV). level = false: keeps hi on the stable side
 * (dc/da > 0), the end of a stable branch; level = true: keeps lo with
 * c(lo) < cstar, the landing radius of a jump at constant control. */
static mdr_status MDR_SFX(mdr_c_bisect)(const MDR_SFX(mdr_contact) *c, uint8_t control, MDR_T km,
                                        bool level, MDR_T cstar, MDR_T *lo, MDR_T *hi)
{
    int it;
    for (it = 0; it < MDR_CRIT_BISECT; it++) {
        MDR_T mid = MDR_K(0.5) * (*lo + *hi), vm, dvm;
        MDR_SFX(mdr_eqstate) em;
        mdr_status st;
        if (!(mid > *lo && mid < *hi)) {
            return MDR_OK;
        }
        st = MDR_SFX(mdr_c_ctrl)(c, control, km, mid, &vm, &dvm, &em);
        if (st != MDR_OK) {
            return st;
        }
        if (level ? !(vm < cstar) : (dvm > MDR_K(0.0))) {
            *hi = mid;
        } else {
            *lo = mid;
        }
    }
    return MDR_E_NOCONV;
}

mdr_status MDR_SFX(mdr_critical)(const MDR_SFX(mdr_contact) *c, uint8_t control, MDR_T k_m, MDR_T a_start,
                                 MDR_SFX(mdr_critstate) *out)
{
    MDR_SFX(mdr_eqstate) estar; /* state at a (control value vstar, slope dv) */
    MDR_T a, dv, amin, vstar;
    mdr_status st;
    int steps = 0;
    uint16_t jumps = 0;
    bool unstable_here;
    if (c == NULL || out == NULL) {
        return MDR_E_NULL;
    }
    if (control != MDR_CONTROL_LOAD && control != MDR_CONTROL_GRIPS && control != MDR_CONTROL_MACHINE) {
        return MDR_E_CONTROL;
    }
    if (control == MDR_CONTROL_MACHINE) {
        if (!MDR_SFX(mdr_m_isfinite)(k_m)) {
            return MDR_E_NONFINITE;
        }
        if (!(k_m > MDR_K(0.0))) {
            return MDR_E_CONTROL;
        }
    }
    st = MDR_SFX(mdr_c_domain)(c, a_start);
    if (st != MDR_OK) {
        return st;
    }
    amin = a_start * MDR_CRIT_AMIN;
    a = a_start;
    st = MDR_SFX(mdr_c_ctrl)(c, control, k_m, a, &vstar, &dv, &estar);
    if (st != MDR_OK) {
        return st;
    }
    unstable_here = !(dv > MDR_K(0.0));
    for (;;) {
        if (!unstable_here) {
            /* follow the stable branch down until dc/da <= 0 */
            MDR_T an = MDR_SFX(mdr_c_step)(c, a), vn, dvn;
            MDR_SFX(mdr_eqstate) en;
            if (++steps > MDR_CRIT_SCAN_MAX) {
                return MDR_E_NOCONV;
            }
            if (an <= amin) {
                /* peeled stably to a -> 0: F, d -> 0 */
                out->a = MDR_K(0.0);
                out->d = MDR_K(0.0);
                out->F = MDR_K(0.0);
                out->jumps = jumps;
                return MDR_OK;
            }
            st = MDR_SFX(mdr_c_ctrl)(c, control, k_m, an, &vn, &dvn, &en);
            if (st != MDR_OK) {
                return st;
            }
            if (dvn > MDR_K(0.0)) {
                a = an;
                continue;
            }
            /* bisection: hi stable (dc/da > 0), lo not */
            {
                MDR_T lo = an, hi = a;
                st = MDR_SFX(mdr_c_bisect)(c, control, k_m, false, MDR_K(0.0), &lo, &hi);
                if (st != MDR_OK) {
                    return st;
                }
                a = hi;
            }
            st = MDR_SFX(mdr_c_ctrl)(c, control, k_m, a, &vstar, &dv, &estar);
            if (st != MDR_OK) {
                return st;
            }
        }
        /* a: end of a stable branch (or an unstable start or landing), its
         * state in estar. Jump at constant control to the largest a' < a with
         * c(a') = c(a), if any. */
        {
            MDR_T ap = a, an, vn, dvn;
            MDR_SFX(mdr_eqstate) en;
            bool found = false;
            for (;;) {
                an = MDR_SFX(mdr_c_step)(c, ap);
                if (++steps > MDR_CRIT_SCAN_MAX) {
                    return MDR_E_NOCONV;
                }
                if (an <= amin) {
                    break;
                }
                st = MDR_SFX(mdr_c_ctrl)(c, control, k_m, an, &vn, &dvn, &en);
                if (st != MDR_OK) {
                    return st;
                }
                if (vn < vstar) {
                    found = true;
                    break;
                }
                ap = an;
            }
            if (!found) {
                /* complete separation: the state at a is the pull-off */
                out->a = estar.a;
                out->d = estar.d;
                out->F = estar.F;
                out->jumps = jumps;
                return MDR_OK;
            }
            /* bisection on c(a) - c*: lo has c < c*, hi has c >= c* (strict, so a
             * profile with c constant, e.g. the flat punch without adhesion,
             * separates instead of landing where it stands) */
            {
                MDR_T lo = an, hi = ap;
                st = MDR_SFX(mdr_c_bisect)(c, control, k_m, true, vstar, &lo, &hi);
                if (st != MDR_OK) {
                    return st;
                }
                a = lo;
            }
            jumps++;
            st = MDR_SFX(mdr_c_ctrl)(c, control, k_m, a, &vstar, &dv, &estar);
            if (st != MDR_OK) {
                return st;
            }
            unstable_here = !(dv > MDR_K(0.0));
        }
    }
}

/* Profile length used when no adhesive length exists. */
static MDR_T MDR_SFX(mdr_c_length)(const MDR_SFX(mdr_contact) *c)
{
    switch (c->kind) {
    case MDR_PROFILE_POWERLAW:
        if (MDR_CFG_PROFILE_POWERLAW && c->k[1] != MDR_K(1.0)) {
            /* C L^n = L */
            return MDR_SFX(mdr_m_powscaled)(MDR_K(1.0), c->p[0], MDR_K(1.0) / (MDR_K(1.0) - c->k[1]));
        }
        return MDR_K(1.0);
    case MDR_PROFILE_CONE:
        return MDR_K(1.0);
    case MDR_PROFILE_SPHERE:
        return MDR_K(0.5) * c->p[0];
    default:
        return c->p[0];
    }
}

static mdr_status MDR_SFX(mdr_c_start)(const MDR_SFX(mdr_contact) *c, MDR_T *a_start)
{
    MDR_T lo, hi, ax, g, dg, hb;
    if (c->kind == MDR_PROFILE_FLATPUNCH) {
        *a_start = c->p[0];
        return MDR_OK;
    }
    if (c->c_dl == MDR_K(0.0) || (c->kind == MDR_PROFILE_POWERLAW && c->k[1] == MDR_K(0.5))) {
        *a_start = MDR_SFX(mdr_c_length)(c);
        return MDR_OK;
    }
    if (MDR_CFG_PROFILE_WAVY && c->kind == MDR_PROFILE_WAVY) {
        /* smooth base: a^2/R = c_dl sqrt(a)  ->  a = (c_dl R)^(2/3) */
        ax = MDR_SFX(mdr_m_powscaled)(MDR_K(1.0), c->c_dl * c->p[0], MDR_K(2.0) / MDR_K(3.0));
        *a_start = MDR_K(3.0) * ax;
        return MDR_OK;
    }
    /* bracket the zero of d(a) = g(a) - dl(a) by factors of 2 around the
     * profile length, then bisect (d changes sign exactly once for these
     * profiles: g/sqrt(a) is monotonic). */
    lo = hi = MDR_SFX(mdr_c_length)(c);
    {
        bool grows = !(c->kind == MDR_PROFILE_POWERLAW && c->k[1] < MDR_K(0.5));
        MDR_T d;
        int it;
        for (it = 0; it < 400; it++) {
            MDR_SFX(mdr_c_profile)(c, hi, &g, &dg, &hb);
            d = g - c->c_dl * MDR_SQRT(hi);
            if ((d > MDR_K(0.0)) == grows) {
                break;
            }
            lo = hi;
            hi = (c->kind == MDR_PROFILE_SPHERE) ? MDR_K(0.5) * (hi + c->p[0]) : hi * MDR_K(2.0);
        }
        if (it == 0) {
            for (it = 0; it < 400; it++) {
                lo *= MDR_K(0.5);
                MDR_SFX(mdr_c_profile)(c, lo, &g, &dg, &hb);
                d = g - c->c_dl * MDR_SQRT(lo);
                if ((d > MDR_K(0.0)) != grows) {
                    break;
                }
                hi = lo;
            }
        }
        if (it == 400) {
            return MDR_E_NOCONV;
        }
        for (it = 0; it < MDR_CRIT_BISECT; it++) {
            MDR_T mid = MDR_K(0.5) * (lo + hi);
            if (!(mid > lo && mid < hi)) {
                break;
            }
            MDR_SFX(mdr_c_profile)(c, mid, &g, &dg, &hb);
            d = g - c->c_dl * MDR_SQRT(mid);
            if ((d > MDR_K(0.0)) == grows) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        ax = hi;
        if (!grows) {
            *a_start = ax / MDR_K(3.0);
            return MDR_OK;
        }
    }
    *a_start = MDR_K(3.0) * ax;
    if (c->kind == MDR_PROFILE_SPHERE && *a_start > MDR_K(0.9) * c->p[0]) {
        *a_start = MDR_K(0.9) * c->p[0];
    }
    if (c->kind == MDR_PROFILE_FLATTIP && *a_start < MDR_K(1.5) * c->k[1]) {
        *a_start = MDR_K(1.5) * c->k[1];
    }
    return MDR_OK;
}

mdr_status MDR_SFX(mdr_default_start)(const MDR_SFX(mdr_contact) *c, MDR_T *a_start)
{
    MDR_T a = MDR_K(0.0);
    mdr_status st;
    if (c == NULL || a_start == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_c_start)(c, &a);
    if (st != MDR_OK) {
        return st;
    }
    /* 3 a_x beyond the arithmetic's range (w/E* huge: found by fuzz_init,
     * a cone with E* = 1.4e-42 Pa in f32) */
    if (!MDR_SFX(mdr_m_isfinite)(a) || !(a > MDR_K(0.0))) {
        return MDR_E_OVERFLOW;
    }
    *a_start = a;
    return MDR_OK;
}
