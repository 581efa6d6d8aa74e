/* SPDX-License-Identifier: MIT */
/*
 * mdr_ref.c: the GSL double-precision reference (see mdr_ref.h).
 * Host only; uses libm and GSL. Tolerances: every quadrature asks for
 * 1e-13 relative; the self-test (host_tests/test_ref.c) shows what results.
 */
#include "mdr_ref.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stddef.h>

#include "mdr_types.h"

#define REF_LIMIT 4000
#define REF_EPSREL 1e-13

static gsl_integration_workspace *ws_for(int level)
{
    /* one workspace per nesting level: G -> g -> f' and sigma -> g' */
    static gsl_integration_workspace *ws[4];
    if (ws[level] == NULL) {
        gsl_set_error_handler_off();
        ws[level] = gsl_integration_workspace_alloc(REF_LIMIT);
    }
    return ws[level];
}

/* Diagnostics: quadratures that GSL reports as failed with an error estimate
 * above REF_ACCEPT relative. Printed by the tests, not asserted: such
 * quadratures are inner parts of a sum (the phi integral of g' next to the
 * flattened tip's point term) whose absolute error estimates (1e-15) do not
 * reach the results, which test_ref.c proves against the closed forms. */
#define REF_ACCEPT 1e-10
static int failures;

static void note_status(int st, double err, double r)
{
    if (st != GSL_SUCCESS && !(err <= REF_ACCEPT * fabs(r))) {
        failures++;
    }
}

int ref_failures(void)
{
    return failures;
}

static double qaws(gsl_function *F, double a, double b, double alpha, double beta, int level)
{
    double r = 0.0, err;
    gsl_integration_qaws_table *t = gsl_integration_qaws_table_alloc(alpha, beta, 0, 0);
    int st = gsl_integration_qaws(F, a, b, t, 0.0, REF_EPSREL, REF_LIMIT, ws_for(level), &r, &err);
    note_status(st, err, r);
    gsl_integration_qaws_table_free(t);
    return r;
}

static double qag(gsl_function *F, double a, double b, int level)
{
    double r = 0.0, err;
    int st = gsl_integration_qag(F, a, b, 0.0, REF_EPSREL, REF_LIMIT, GSL_INTEG_GAUSS61, ws_for(level),
                                 &r, &err);
    note_status(st, err, r);
    return r;
}

/* ---- the gap profile f and its derivatives, from the seed's definitions ---- */

double ref_f(const ref_scene *s, double r)
{
    const double *p = s->p;
    switch (s->kind) {
    case MDR_PROFILE_PARABOLOID: return r * r / (2 * p[0]);
    case MDR_PROFILE_CONE: return tan(p[0]) * r;
    case MDR_PROFILE_POWERLAW: return p[0] * pow(r, p[1]);
    case MDR_PROFILE_SPHERE: return p[0] - sqrt(p[0] * p[0] - r * r);
    case MDR_PROFILE_FLATTIP: return r < p[1] ? 0.0 : (r * r - p[1] * p[1]) / (2 * p[0]);
    case MDR_PROFILE_WAVY: return r * r / (2 * p[0]) + p[1] * (1 - cos(2 * M_PI * r / p[2]));
    default: return 0.0;
    }
}

static double fp(const ref_scene *s, double r)
{
    const double *p = s->p;
    switch (s->kind) {
    case MDR_PROFILE_PARABOLOID: return r / p[0];
    case MDR_PROFILE_CONE: return tan(p[0]);
    case MDR_PROFILE_POWERLAW: return p[0] * p[1] * pow(r, p[1] - 1);
    case MDR_PROFILE_SPHERE: return r / sqrt(p[0] * p[0] - r * r);
    case MDR_PROFILE_FLATTIP: return r < p[1] ? 0.0 : r / p[0];
    case MDR_PROFILE_WAVY: return r / p[0] + p[1] * 2 * M_PI / p[2] * sin(2 * M_PI * r / p[2]);
    default: return 0.0;
    }
}

static double fpp(const ref_scene *s, double r)
{
    const double *p = s->p;
    double k;
    switch (s->kind) {
    case MDR_PROFILE_PARABOLOID: return 1 / p[0];
    case MDR_PROFILE_POWERLAW: return p[0] * p[1] * (p[1] - 1) * pow(r, p[1] - 2);
    case MDR_PROFILE_SPHERE: return p[0] * p[0] / pow(p[0] * p[0] - r * r, 1.5);
    case MDR_PROFILE_FLATTIP: return r < p[1] ? 0.0 : 1 / p[0];
    case MDR_PROFILE_WAVY:
        k = 2 * M_PI / p[2];
        return 1 / p[0] + p[1] * k * k * cos(k * r);
    default: return 0.0;
    }
}

/* ---- g: Abel transform 4.46 by QAWS ------------------------------------ */

struct gctx {
    const ref_scene *s;
    double x;
};

static double g_integrand(double r, void *v)
{
    const struct gctx *c = v;
    return fp(c->s, r) / sqrt(c->x + r);
}

static double g_integrand_regular(double r, void *v)
{
    const struct gctx *c = v; /* away from r = x: f'(r)/sqrt(x^2 - r^2) */
    return fp(c->s, r) / sqrt((c->x - r) * (c->x + r));
}

static double g_integrand_pow(double r, void *v)
{
    const struct gctx *c = v; /* f' = nC r^(n-1): r^(n-1) is the QAWS weight */
    return c->s->p[0] * c->s->p[1] / sqrt(c->x + r);
}

/* Where g is not identically zero on [0, x]: returns 0 if it is (flat
 * punch; flattened tip up to b), else 1 with *lo the start of its support. */
static int g_support(const ref_scene *s, double x, double *lo)
{
    *lo = 0.0;
    if (s->kind == MDR_PROFILE_FLATPUNCH) {
        return 0;
    }
    if (s->kind == MDR_PROFILE_FLATTIP) {
        *lo = s->p[1];
        return x > s->p[1];
    }
    return 1;
}

static double ref_g_level(const ref_scene *s, double x, int level)
{
    struct gctx c = {s, x};
    gsl_function F = {g_integrand, &c};
    double lo, alpha = 0.0;
    if (!g_support(s, x, &lo)) {
        return 0.0;
    }
    if (s->kind == MDR_PROFILE_POWERLAW) {
        F.function = g_integrand_pow;
        alpha = s->p[1] - 1;
    }
    if (s->kind == MDR_PROFILE_WAVY && x > 2 * s->p[2]) {
        /* many oscillations of f': one panel per wavelength, the last one
         * (with the 1/sqrt(x - r) end point) by QAWS */
        gsl_function Fr = {g_integrand_regular, &c};
        double lam = s->p[2], sum = 0.0, r0 = 0.0, end = x - lam;
        while (r0 < end) {
            double r1 = r0 + lam < end ? r0 + lam : end;
            sum += qag(&Fr, r0, r1, level);
            r0 = r1;
        }
        return x * (sum + qaws(&F, end, x, 0.0, -0.5, level));
    }
    return x * qaws(&F, lo, x, alpha, -0.5, level);
}

double ref_g(const ref_scene *s, double x)
{
    return ref_g_level(s, x, 1);
}

/* ---- g': phi form ------------------------------------------------------- */

static double dg_integrand(double phi, void *v)
{
    const struct gctx *c = v;
    double sn = sin(phi), r = c->x * sn;
    return fp(c->s, r) + r * fpp(c->s, r);
}

static double dg_integrand_pow(double phi, void *v)
{
    /* f' + r f'' = n^2 C r^(n-1); weight phi^(n-1), integrand (sin phi/phi)^(n-1) */
    const struct gctx *c = v;
    double n = c->s->p[1], q = phi > 0 ? sin(phi) / phi : 1.0;
    return n * n * c->s->p[0] * pow(c->x, n - 1) * pow(q, n - 1);
}

static double ref_dg_level(const ref_scene *s, double x, int level)
{
    struct gctx c = {s, x};
    gsl_function F = {dg_integrand, &c};
    if (s->kind == MDR_PROFILE_FLATPUNCH) {
        return 0.0;
    }
    if (s->kind == MDR_PROFILE_POWERLAW) {
        F.function = dg_integrand_pow;
        return qaws(&F, 0.0, M_PI / 2, s->p[1] - 1, 0.0, level);
    }
    if (s->kind == MDR_PROFILE_FLATTIP) {
        double b = s->p[1];
        if (x <= b) {
            return 0.0;
        }
        /* jump of f' by b/R at r = b: x sin(phi_b) (b/R) / (x cos(phi_b)) */
        return qag(&F, asin(b / x), M_PI / 2, level) + b * b / (s->p[0] * sqrt((x - b) * (x + b)));
    }
    return qag(&F, 0.0, M_PI / 2, level);
}

double ref_dg(const ref_scene *s, double x)
{
    return ref_dg_level(s, x, 1);
}

/* ---- G = int g -------------------------------------------------------- */

static double G_integrand(double x, void *v)
{
    return ref_g_level(v, x, 1);
}

double ref_G(const ref_scene *s, double a)
{
    gsl_function F = {G_integrand, (void *)s};
    double lo;
    if (!g_support(s, a, &lo)) {
        return 0.0;
    }
    if (s->kind == MDR_PROFILE_WAVY) {
        /* one panel per wavelength of the oscillating g */
        double sum = 0.0, x0 = 0.0;
        while (x0 < a) {
            double x1 = x0 + s->p[2] < a ? x0 + s->p[2] : a;
            sum += qag(&F, x0, x1, 0);
            x0 = x1;
        }
        return sum;
    }
    return qag(&F, lo, a, 0);
}

int ref_eq_at(const ref_scene *s, double a, ref_eq *o)
{
    double g = ref_g(s, a), dg = ref_dg(s, a), G = ref_G(s, a);
    o->a = a;
    o->dl = sqrt(2 * M_PI * a * s->w / s->E);
    o->d = g - o->dl;
    o->F = 2 * s->E * (a * o->d - G);
    o->dd_da = dg - o->dl / (2 * a);
    o->dF_da = 2 * s->E * (a * dg - 1.5 * o->dl);
    return 0;
}

/* ---- stress 4.27 -------------------------------------------------------- */

struct sctx {
    const ref_scene *s;
    double r, b;
};

static double s_integrand(double x, void *v)
{
    const struct sctx *c = v;
    return ref_dg_level(c->s, x, 1) / sqrt(x + c->r);
}

static double s_integrand_center(double x, void *v)
{
    const struct sctx *c = v;
    return ref_dg_level(c->s, x, 1) / x;
}

static double s_integrand_flat(double x, void *v)
{
    /* flattened tip, r < b: weight (x-b)^(-1/2), integrand g'(x) sqrt(x-b)/sqrt(x^2-r^2),
     * with g' sqrt(x-b) = (regular part) sqrt(x-b) + b^2/(R sqrt(x+b)) so that
     * the end point x = b (where Clenshaw-Curtis evaluates) has its limit */
    const struct sctx *c = v;
    double b = c->b, reg = 0.0;
    if (x > b) {
        struct gctx gc = {c->s, x};
        gsl_function F = {dg_integrand, &gc};
        reg = qag(&F, asin(b / x), M_PI / 2, 1) * sqrt(x - b);
    }
    return (reg + b * b / (c->s->p[0] * sqrt(x + b))) / sqrt(x * x - c->r * c->r);
}

double ref_stress(const ref_scene *s, double a, double r)
{
    struct sctx c = {s, r, 0.0};
    gsl_function F = {s_integrand, &c};
    double S, g = ref_g(s, a), dl = sqrt(2 * M_PI * a * s->w / s->E);
    if (s->kind == MDR_PROFILE_FLATPUNCH) {
        S = 0.0;
    } else if (s->kind == MDR_PROFILE_FLATTIP && r < s->p[1]) {
        c.b = s->p[1];
        F.function = s_integrand_flat;
        S = qaws(&F, s->p[1], a, -0.5, 0.0, 0);
    } else if (r == 0.0) {
        /* int_0^a g'(x)/x dx: QAGS (interior nodes only; x = 0 is 0/0) */
        double err;
        F.function = s_integrand_center;
        int st = gsl_integration_qags(&F, 0.0, a, 0.0, REF_EPSREL, REF_LIMIT, ws_for(0), &S, &err);
        note_status(st, err, S);
    } else {
        S = qaws(&F, r, a, -0.5, 0.0, 0);
    }
    (void)g;
    return s->E / M_PI * (dl / sqrt(a * a - r * r) - S);
}

/* ---- Struve from integral representations ------------------------------ */

struct zctx {
    double z;
};

static double h0_integrand(double t, void *v)
{
    return sin(((struct zctx *)v)->z * cos(t));
}

static double h1_integrand(double t, void *v)
{
    double st = sin(t);
    return st * st * sin(((struct zctx *)v)->z * cos(t));
}

double ref_struve_h0(double z)
{
    struct zctx c = {z};
    gsl_function F = {h0_integrand, &c};
    return 2 / M_PI * qag(&F, 0, M_PI / 2, 2);
}

double ref_struve_h1(double z)
{
    struct zctx c = {z};
    gsl_function F = {h1_integrand, &c};
    return 2 * z / M_PI * qag(&F, 0, M_PI / 2, 2);
}

/* ---- critical states: the path of mdr_critical with a finer scan ---------- */

struct cctx {
    const ref_scene *s;
    int control;
    double km, target;
};

/* slope of the controlled variable: needs g' only */
static double c_slope(double a, void *v)
{
    const struct cctx *c = v;
    double dg = ref_dg(c->s, a), dl = sqrt(2 * M_PI * a * c->s->w / c->s->E);
    double dd = dg - dl / (2 * a), dF = 2 * c->s->E * (a * dg - 1.5 * dl);
    if (c->control == MDR_CONTROL_LOAD) {
        return dF;
    }
    if (c->control == MDR_CONTROL_GRIPS) {
        return dd;
    }
    return dd + dF / c->km;
}

/* controlled variable minus a target: F needs G, d does not */
static double c_value(double a, void *v)
{
    const struct cctx *c = v;
    double g = ref_g(c->s, a), dl = sqrt(2 * M_PI * a * c->s->w / c->s->E), d = g - dl;
    if (c->control == MDR_CONTROL_GRIPS) {
        return d - c->target;
    }
    {
        double F = 2 * c->s->E * (a * d - ref_G(c->s, a));
        if (c->control == MDR_CONTROL_LOAD) {
            return F - c->target;
        }
        return d + F / c->km - c->target;
    }
}

static double brent(double (*fn)(double, void *), void *ctx, double lo, double hi)
{
    gsl_function F = {fn, ctx};
    gsl_root_fsolver *so = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double x = 0.5 * (lo + hi);
    int it;
    gsl_root_fsolver_set(so, &F, lo, hi);
    for (it = 0; it < 300; it++) {
        gsl_root_fsolver_iterate(so);
        x = gsl_root_fsolver_root(so);
        lo = gsl_root_fsolver_x_lower(so);
        hi = gsl_root_fsolver_x_upper(so);
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) {
            break;
        }
    }
    gsl_root_fsolver_free(so);
    return x;
}

static double step_down(const ref_scene *s, double a, double rel)
{
    double h = a * rel;
    if (s->kind == MDR_PROFILE_WAVY && s->p[1] > 0 && h > s->p[2] / 64) {
        h = s->p[2] / 64;
    }
    return a - h;
}

/* Domain end for the jump-in scan: R for the sphere (exclusive), a0 for the
 * flat punch (a wall: the edge stops there); 0 for none. */
static double dom_of(const ref_scene *s)
{
    return s->kind == MDR_PROFILE_SPHERE || s->kind == MDR_PROFILE_FLATPUNCH ? s->p[0] : 0.0;
}

/* An unstable start (dc/da <= 0 there): the contact jumps in, as when
 * pressed there, to the smallest a > a_start with c(a) = c(a_start) (a
 * fine upward scan, then Brent). Returns the new start, the wall (flat
 * punch), or -1 when there is none (c falls for ever). */
static double jump_in(const ref_scene *s, struct cctx *c, double a_start)
{
    double cstar, a = a_start, dom = dom_of(s), rel = 0.002;
    int guard = 0;
    c->target = 0.0;
    cstar = c_value(a_start, c);
    c->target = cstar;
    for (;;) {
        double h = a * rel, an;
        rel = rel * 1.03 < 0.05 ? rel * 1.03 : 0.05;
        if (s->kind == MDR_PROFILE_WAVY && s->p[1] > 0 && h > s->p[2] / 64) {
            h = s->p[2] / 64;
        }
        an = a + h;
        if (dom > 0 && an >= dom) {
            an = s->kind == MDR_PROFILE_SPHERE ? a + 0.5 * (dom - a) : dom;
            if (!(an > a)) {
                return -1;
            }
        }
        if (++guard > 2000000) {
            return -1;
        }
        if (c_value(an, c) >= 0) {
            return brent(c_value, c, a, an);
        }
        if (s->kind == MDR_PROFILE_FLATPUNCH && an == dom) {
            return dom;
        }
        a = an;
    }
}

int ref_critical(const ref_scene *s, int control, double k_m, double a_start, ref_crit *out)
{
    struct cctx c = {s, control, k_m, 0.0};
    double a = a_start, amin = a_start * 1e-9;
    int jumps = 0, guard = 0;
    int unstable = !(c_slope(a, &c) > 0);
    if (unstable && !(s->kind == MDR_PROFILE_FLATPUNCH && a == s->p[0]) &&
        !(s->kind == MDR_PROFILE_FLATTIP && a == s->p[1])) {
        a = jump_in(s, &c, a_start);
        if (a < 0) {
            return -1;
        }
        amin = a * 1e-9;
        unstable = !(c_slope(a, &c) > 0);
    }
    for (;;) {
        if (!unstable) {
            double an = step_down(s, a, 0.005);
            if (++guard > 200000) {
                return -1;
            }
            if (an <= amin) {
                out->a = out->d = out->F = 0.0;
                out->jumps = jumps;
                return 0;
            }
            if (c_slope(an, &c) > 0) {
                a = an;
                continue;
            }
            a = brent(c_slope, &c, an, a);
            /* Brent converged onto the kink of the flattened tip at a = b,
             * where g ~ sqrt(a - b): take the limit state a = b itself */
            if (s->kind == MDR_PROFILE_FLATTIP && fabs(a - s->p[1]) <= 1e-12 * s->p[1]) {
                a = s->p[1];
            }
        }
        {
            double cstar, ap = a, an, rel = 0.005;
            int found = 0;
            c.target = 0.0;
            cstar = c_value(a, &c);
            c.target = cstar;
            for (;;) {
                an = step_down(s, ap, rel);
                rel = rel * 1.03 < 0.05 ? rel * 1.03 : 0.05;
                if (++guard > 200000) {
                    return -1;
                }
                if (an <= amin) {
                    break;
                }
                if (c_value(an, &c) < 0) {
                    found = 1;
                    break;
                }
                ap = an;
            }
            if (!found) {
                ref_eq e;
                ref_eq_at(s, a, &e);
                out->a = e.a;
                out->d = e.d;
                out->F = e.F;
                out->jumps = jumps;
                return 0;
            }
            a = brent(c_value, &c, an, ap);
            jumps++;
            unstable = !(c_slope(a, &c) > 0);
        }
    }
}
