/* SPDX-License-Identifier: MIT */
/*
 * crit_sweep.c: mdr_critical against closed forms worked out here, in long
 * double, independently of the library (issue 16). Part of make stress: the
 * short grid in make test, `make stress STRESS=long` the dense one.
 *
 * Swept, in f32 and f64, under fixed load, fixed grips and a machine
 * (k_m = 2E* a_c times 1e-3, 1, 1e3):
 *   power law f = C r^n, n continuous in (1/2, 8] (a fixed set plus
 *     n = 1/2 + 10^-k, k = 1..6), two ways: C = L^(1-n) with L over 12
 *     decades (1 nm .. 1 km), and C chosen so that the fixed-load critical
 *     radius is a target radius over 12 decades (the only way n -> 1/2+
 *     stays in range: the radius is (3c/(2 n kappa_n C))^(1/(n-1/2)));
 *   paraboloid and cone (R, theta);
 *   exact sphere (Maugis), R over 12 decades, E* R/(pi w) from 1e-15 to 1e21
 *     (a_c -> R included);
 *   flattened tip, b = 0.3 .. 3 times its threshold, both sides of
 *     0.7475 a* (load) and of the same ratio of the grips radius (grips);
 * E* over 12 decades (1 Pa .. 1 TPa), w over 12 decades (1e-6 .. 1e6 J/m^2).
 * Each scene from the default start and from starts on the unstable branch
 * (1e-3 and 0.5 of the critical radius) and far out (1e3): a start is a
 * hint, the answer may not depend on it.
 *
 * Expected values (long double):
 *   kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma((n + 1)/2) (tgammal); the
 *   critical radius from s(a) = sqrt(a) g'(a) = k c (4.23: k = 3/2 load,
 *   1/2 grips), for the power law in closed form (4.70), for the sphere and
 *   the flattened tip by bisection of s on its monotonic pieces (s of the
 *   flattened tip falls on (b, y_m b], y_m^2 = (9 + sqrt 57)/12, and rises
 *   above); under a machine the roots of dz/da on a 400-point grid between
 *   the grips and the load radii, bisected, and the lowest local minimum of
 *   z; d and F from 4.66/4.68 (power law), 4.75/4.77 (sphere; 4.77 as its
 *   series sum_k 4k/(4k^2 - 1) t^(2k+1) below t = 1/2, where it cancels),
 *   4.82/4.83 and Kendall (4.61-4.63) at a = b for the flattened tip. The
 *   flattened tip separates at a = b iff b >= (2/F_m)^(2/3) a_k (a_k the
 *   paraboloid's critical radius, F_m = sqrt(y_m)(2y_m^2-1)/sqrt(y_m^2-1)):
 *   0.747526 a* (seed: 0.7475), otherwise at the lower of F (d) at a = b
 *   and at the window's upper root.
 *   Also the most tensile force of the path (mdr_critstate.F_min): the
 *   load's critical force under grips and machine for the power laws,
 *   paraboloid, cone and sphere (their F falls to the load root, then rises).
 *
 * Errors: |da|/a, |dF|/|F|, |dd|/max(|d|, dl(a)) (depths cross 0: n = 1.5).
 * As n -> 1/2 the critical radius is ill-conditioned: a relative error e of
 * s moves it by e/(n - 1/2); the bounds below are scaled by cond =
 * max(1, 1/(n - 1/2)) for every profile (1 for the others).
 *
 * Asserted (exit status 1 otherwise): every result within TOL * cond
 * (TOL32, TOL64 below, each within 10x of the worst error measured); no
 * status but MDR_OK where the expected state and the scene's scales lie in
 * the arithmetic's normal range with a margin (1e-30 .. 1e30 in f32,
 * 1e-290 .. 1e290 in f64), and there any other status named (MDR_E_OVERFLOW,
 * MDR_E_RADIUS: a critical radius within rounding of R, MDR_E_NONFINITE /
 * MDR_E_PARAM from an init whose constants leave the range); the same
 * answer from every start.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fl.h"
#include "mdr.h"

/* 10x the worst errors measured (make stress STRESS=long, 1 985 541 calls,
 * README): f64 2.3e-15 (a cone under a machine), f32 3.0e-6 (a power law,
 * n = 0.9, under a machine), both times cond */
#define TOL64 2.5e-14
#define TOL32 3e-5

typedef long double ld;

typedef struct {
    int kind;
    ld p0, p1; /* R | theta | C, n | R, b */
    ld E, w, km;
    int ctl;
    ld k0; /* power law: kappa_n C (set by run()) */
} scene;

typedef struct {
    ld a, d, F, Fmin;
    int jumps;
    int have_fmin;
} expect_t;

static const ld PI_L = 3.141592653589793238462643383279502884L;

/* ---- closed forms (long double) ------------------------------------------ */

static ld kappa(ld n)
{
    return sqrtl(PI_L) * tgammal(n / 2 + 1) / tgammal((n + 1) / 2);
}

/* (R^2 + a^2)/2 ln((R+a)/(R-a)) - R a over R^2 (4.77) at t = a/R, as its
 * series below 1/2 */
static ld sphere_fna(ld t)
{
    if (t < 0.5L) {
        ld s = 0, tp = t * t * t;
        for (int k = 1; k < 200; k++) {
            ld term = 4.0L * k / (4.0L * k * k - 1) * tp;
            s += term;
            if (term < s * 1e-22L) {
                break;
            }
            tp *= t * t;
        }
        return s;
    }
    return (1 + t * t) * atanhl(t) - t;
}

/* g, g', F_na/(2E*) at a */
static void prof(const scene *s, ld a, ld *g, ld *dg, ld *fna)
{
    switch (s->kind) {
    case MDR_PROFILE_POWERLAW: {
        ld n = s->p1, k0 = s->k0;
        *g = k0 * powl(a, n);
        *dg = n * *g / a;
        *fna = n / (n + 1) * a * *g; /* a (g - hbar) ... F_na = 2E* a hbar */
        break;
    }
    case MDR_PROFILE_PARABOLOID:
        *g = a * a / s->p0;
        *dg = 2 * a / s->p0;
        *fna = 2.0L / 3 * a * a * a / s->p0;
        break;
    case MDR_PROFILE_CONE: {
        ld k0 = PI_L / 2 * tanl(s->p0);
        *g = k0 * a;
        *dg = k0;
        *fna = 0.5L * k0 * a * a;
        break;
    }
    case MDR_PROFILE_SPHERE: {
        ld R = s->p0, t = a / R;
        *g = a * atanhl(t);
        *dg = atanhl(t) + t / ((1 - t) * (1 + t));
        *fna = 0.5L * R * R * sphere_fna(t);
        break;
    }
    default: { /* flattened tip */
        ld R = s->p0, b = s->p1;
        if (a <= b) {
            *g = *dg = *fna = 0;
        } else {
            ld q = sqrtl((a - b) * (a + b));
            *g = a * q / R;
            *dg = (2 * a * a - b * b) / (R * q);
            *fna = (2 * a * a + b * b) * q / (3 * R);
        }
        break;
    }
    }
}

/* the control's value, its slope, d, F at a (the flattened tip at a = b:
 * the limit from the flat) */
static void state(const scene *s, ld a, ld *v, ld *q, ld *d, ld *F)
{
    ld g, dg, fna, c = sqrtl(2 * PI_L * s->w / s->E), dl = c * sqrtl(a);
    prof(s, a, &g, &dg, &fna);
    *d = g - dl;
    *F = 2 * s->E * (fna - a * dl);
    {
        ld dd = dg - dl / (2 * a), dF = 2 * s->E * (a * dg - 1.5L * dl);
        if (s->ctl == MDR_CONTROL_LOAD) {
            *v = *F;
            *q = dF;
        } else if (s->ctl == MDR_CONTROL_GRIPS) {
            *v = *d;
            *q = dd;
        } else {
            *v = *d + *F / s->km;
            *q = dd + dF / s->km;
        }
    }
}

/* root of s(a) = k c on a rising piece [lo, hi] (bisection in long double) */
static ld sroot(const scene *s, ld k, ld lo, ld hi, int rising)
{
    ld c = sqrtl(2 * PI_L * s->w / s->E);
    for (int i = 0; i < 400; i++) {
        ld mid = lo > 0 && hi > 2 * lo ? sqrtl(lo) * sqrtl(hi) : (lo + hi) / 2, g, dg, fna;
        if (!(mid > lo && mid < hi)) {
            break;
        }
        prof(s, mid, &g, &dg, &fna);
        if ((sqrtl(mid) * dg > k * c) == (rising != 0)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return rising ? hi : lo;
}

/* load (k = 3/2) or grips (k = 1/2) critical radius of the profiles with
 * rising s */
static ld kroot(const scene *s, ld k)
{
    ld c = sqrtl(2 * PI_L * s->w / s->E);
    switch (s->kind) {
    case MDR_PROFILE_POWERLAW: {
        ld n = s->p1;
        return powl(k * c / (n * s->k0), 1 / (n - 0.5L)); /* 4.70 */
    }
    case MDR_PROFILE_PARABOLOID:
        return powl(k * c * s->p0 / 2, 2.0L / 3); /* 4.34 */
    case MDR_PROFILE_CONE:
        return powl(k * c / (PI_L / 2 * tanl(s->p0)), 2); /* 4.58 */
    default: /* sphere: rising s on (0, R) */
        return sroot(s, k, 0, s->p0, 1);
    }
}

/* the most tensile force of a path from above the load root: F there */
static ld load_Fc(const scene *s)
{
    scene l = *s;
    ld v, q, d, F;
    l.ctl = MDR_CONTROL_LOAD;
    state(&l, kroot(s, 1.5L), &v, &q, &d, &F);
    return F;
}

/* Expected critical state of a scene (see the top of the file). */
static void expect(const scene *s, expect_t *e)
{
    ld v, q;
    e->have_fmin = 0;
    e->jumps = 0;
    if (s->kind == MDR_PROFILE_FLATPUNCH) {
        ld a = s->p0;
        e->a = a;
        e->d = -sqrtl(2 * PI_L * a * s->w / s->E);
        e->F = -sqrtl(8 * PI_L * a * a * a * s->E * s->w);
        return;
    }
    if (s->kind == MDR_PROFILE_FLATTIP) {
        /* Kendall at b, or the window's upper root if lower (records) */
        const ld ym = sqrtl((9 + sqrtl(57.0L)) / 12), R = s->p0, b = s->p1;
        const ld Fm = sqrtl(ym) * (2 * ym * ym - 1) / sqrtl(ym * ym - 1);
        ld c = sqrtl(2 * PI_L * s->w / s->E), k = s->ctl == MDR_CONTROL_LOAD ? 1.5L : 0.5L;
        ld vb, db, Fb, vr, dr, Fr, r2;
        state(s, b, &vb, &q, &db, &Fb);
        e->a = b;
        e->d = db;
        e->F = Fb;
        if (Fm * powl(b, 1.5L) / R >= k * c) {
            return; /* no window: separation at a = b */
        }
        r2 = sroot(s, k, ym * b, 1e4L * (b + powl(k * c * R, 2.0L / 3)), 1);
        state(s, r2, &vr, &q, &dr, &Fr);
        if (vr <= vb) {
            e->a = r2;
            e->d = dr;
            e->F = Fr;
        } else {
            e->jumps = 1;
        }
        return;
    }
    if (s->ctl != MDR_CONTROL_MACHINE) {
        ld a = kroot(s, s->ctl == MDR_CONTROL_LOAD ? 1.5L : 0.5L);
        state(s, a, &v, &q, &e->d, &e->F);
        e->a = a;
    } else {
        /* roots of dz/da between the grips and the load radii; the lowest
         * local minimum of z, counting records from the top */
        /* where s = 0.99 c/2 < c/2 <= c phi: no root below */
        ld lo = kroot(s, 0.5L) * powl(0.99L, 1 / (s->kind == MDR_PROFILE_POWERLAW ? s->p1 - 0.5L : 0.5L));
        ld hi = 2 * kroot(s, 1.5L), best = 0, pa = hi, pq, pv, d, F, vfloor = 0;
        int nrec = 0, N, clamped = 0;
        if (!(lo > hi * 1e-300L)) {
            /* a grips radius below any range (n -> 1/2): the fold near it
             * has z > -dl (1 + 2E* a/k_m) at the grid's end; a lowest
             * fold above that is below every arithmetic's range */
            lo = hi * 1e-300L;
            clamped = 1;
            vfloor = -sqrtl(2 * PI_L * s->w / s->E * lo) * (1 + 2 * s->E * lo / s->km);
        }
        N = (int)fminl(4000, fmaxl(400, 20 * log10l(hi / lo)));
        state(s, hi, &pv, &pq, &d, &F);
        const ld ratio = powl(lo / hi, 1.0L / N);
        ld ag = hi;
        for (int i = 1; i <= N; i++) {
            ld a = i == N ? lo : (ag *= ratio), qa;
            state(s, a, &v, &qa, &d, &F);
            if ((qa > 0) != (pq > 0)) {
                ld l = a, h = pa;
                for (int it = 0; it < 300; it++) {
                    ld m = (l + h) / 2, vm, qm, dm, Fm;
                    if (!(m > l && m < h)) {
                        break;
                    }
                    state(s, m, &vm, &qm, &dm, &Fm);
                    if ((qm > 0) == (qa > 0)) {
                        l = m;
                    } else {
                        h = m;
                    }
                }
                if (!(qa > 0)) { /* - below, + above: a local minimum */
                    ld vr, qr, dr, Fr;
                    state(s, h, &vr, &qr, &dr, &Fr);
                    if (nrec == 0 || vr < best) {
                        best = vr;
                        e->a = h;
                        e->d = dr;
                        e->F = Fr;
                        nrec++;
                    }
                }
            }
            pa = a;
            pq = qa;
        }
        e->jumps = nrec - 1;
        if (nrec == 0 || (clamped && !(best < vfloor))) {
            e->a = 0; /* not representable: a named error is the answer */
            e->d = e->F = 0;
            e->jumps = 0;
        }
    }
    if (s->ctl != MDR_CONTROL_LOAD) {
        e->Fmin = load_Fc(s);
        e->have_fmin = 1;
    }
}

/* ---- the sweep --------------------------------------------------------------- */

typedef struct {
    char name[48];
    long n, ok, named;
    double worst;
    char where[200];
} row;

static row rows[64];
static int nrows;
static long failures;

static row *rowof(const char *name)
{
    for (int i = 0; i < nrows; i++) {
        if (strcmp(rows[i].name, name) == 0) {
            return &rows[i];
        }
    }
    memset(&rows[nrows], 0, sizeof rows[0]);
    snprintf(rows[nrows].name, sizeof rows[0].name, "%s", name);
    return &rows[nrows++];
}

static const char *pname(int kind)
{
    switch (kind) {
    case MDR_PROFILE_POWERLAW:
        return "powerlaw";
    case MDR_PROFILE_PARABOLOID:
        return "paraboloid";
    case MDR_PROFILE_CONE:
        return "cone";
    case MDR_PROFILE_SPHERE:
        return "sphere";
    case MDR_PROFILE_FLATPUNCH:
        return "flatpunch";
    default:
        return "flattip";
    }
}

static const char *const cname[4] = {"", "load", "grips", "machine"};

static int inrange(ld x, int f32)
{
    ld ax = fabsl(x), lo = f32 ? 1e-30L : 1e-290L, hi = f32 ? 1e30L : 1e290L;
    return x == 0 || (ax > lo && ax < hi);
}

/* a radius: > 0 and in range */
static int rinrange(ld x, int f32)
{
    return x > 0 && inrange(x, f32);
}

/* Does an unstable start a_s of the sphere reach a stable state by jumping
 * in below the float below R? (F and d grow without bound only
 * logarithmically as a -> R: for E* R/(pi w) small the state lies within
 * rounding of R.) */
static int sphere_reachable(const scene *s, ld as, int f32)
{
    ld v0, v1, q, d, F;
    state(s, as, &v0, &q, &d, &F);
    state(s, s->p0 * (1 - (f32 ? 1e-6L : 1e-15L)), &v1, &q, &d, &F);
    return v1 >= v0;
}

/* one scene in one arithmetic from several starts */
static void run(const scene *s, int f32, double cond)
{
    expect_t e;
    double p[3] = {0, 0, 0}, dl, err = 0, tol = (f32 ? TOL32 : TOL64) * cond;
    ld c = sqrtl(2 * PI_L * s->w / s->E);
    char rn[48], where[160];
    int rep, k;
    expect(s, &e);
    dl = (double)(c * sqrtl(e.a));
    p[0] = (double)s->p0;
    p[1] = (double)s->p1;
    snprintf(rn, sizeof rn, "%s %s %s", pname(s->kind), cname[s->ctl], f32 ? "f32" : "f64");
    snprintf(where, sizeof where, "p=%.4Lg,%.6Lg E=%.3Lg w=%.3Lg km=%.3Lg a=%.6Lg", s->p0, s->p1, s->E, s->w,
             s->km, e.a);
    /* representable: the expected state, the scales of F and d, the inputs */
    rep = rinrange(e.a, f32) && inrange(e.d, f32) && inrange(e.F, f32) && inrange(s->E, f32) &&
          inrange(s->w, f32) && inrange(c, f32) && inrange(2 * s->E * e.a * (fabsl(e.d) + dl), f32) &&
          inrange(s->p0, f32) && inrange(s->km, f32) && inrange(1e3L * e.a, f32) && inrange(1e-3L * e.a, f32);
    if (s->kind == MDR_PROFILE_POWERLAW) {
        ld k0 = s->k0;
        rep = rep && inrange(k0, f32) && inrange(k0 * powl(1e3L * e.a, s->p1), f32) &&
              inrange(k0 * powl(1e-3L * e.a, s->p1), f32);
        /* n within 2^10 eps of 1/2: the radius is not resolved to 1 %, and
         * mdr_critical refuses it (MDR_E_RADIUS) */
        rep = rep && fabsl(s->p1 - 0.5L) > 1024.0L * (f32 ? 0x1p-24L : 0x1p-53L);
    }
    if (s->kind == MDR_PROFILE_SPHERE) {
        ld omt = 1 - e.a / s->p0; /* a_c within rounding of R */
        rep = rep && omt > (f32 ? 1e-5L : 1e-14L);
    }
    if (e.have_fmin) {
        rep = rep && inrange(e.Fmin, f32);
    }
    for (k = 0; k < 4; k++) {
        /* the default start, then hints: far below (unstable), at half the
         * radius, far above */
        static const double hint[4] = {0, 1e-3, 0.5, 1e3};
        mdr_status st;
        double ga = 0, gd = 0, gF = 0, gFm = 0;
        int gj = 0;
        double a0 = hint[k] * (double)e.a;
        if (k > 0 && s->kind == MDR_PROFILE_SPHERE && !(a0 < (double)s->p0)) {
            a0 = (double)(e.a + (s->p0 - e.a) / 2);
        }
        if (k > 0) {
            /* a hint whose own state leaves the range: a named error is right */
            ld vs, qs, ds, Fs;
            state(s, (ld)a0, &vs, &qs, &ds, &Fs);
            if (!(inrange(vs, f32) && inrange(ds, f32) && inrange(Fs, f32) && inrange(qs, f32))) {
                continue;
            }
        }
        if ((k == 1 || k == 2) && s->ctl == MDR_CONTROL_MACHINE && s->kind == MDR_PROFILE_POWERLAW &&
            s->p1 < 0.5L + 0.268L) {
            continue; /* up to three roots: a start between them retracts from there (history) */
        }
        if ((k == 1 || k == 2) && s->kind == MDR_PROFILE_SPHERE && !sphere_reachable(s, (ld)a0, f32)) {
            continue; /* the jump-in target lies within rounding of R: MDR_E_RADIUS is right */
        }
        if (k == 3 && s->kind == MDR_PROFILE_FLATPUNCH) {
            continue; /* outside the punch */
        }
        if (k == 3 && s->kind == MDR_PROFILE_FLATTIP) {
            continue; /* the flattened tip's 1e3 a_c lies on the same stable branch as the default */
        }
        if (f32) {
            mdr_contact_f32 c32;
            mdr_critstate_f32 o;
            const float pf[3] = {(float)p[0], (float)p[1], 0};
            float a0f = (float)a0;
            st = mdr_contact_init_f32(&c32, (uint8_t)s->kind, pf, (float)s->E, (float)s->w);
            if (st == MDR_OK && k == 0) {
                st = mdr_default_start_f32(&c32, &a0f);
            }
            if (st == MDR_OK) {
                st = mdr_critical_f32(&c32, (uint8_t)s->ctl, (float)s->km, a0f, &o);
            }
            if (st == MDR_OK) {
                ga = (double)o.a;
                gd = (double)o.d;
                gF = (double)o.F;
                gFm = (double)o.F_min;
                gj = o.jumps;
            }
        } else {
            mdr_contact_f64 c64;
            mdr_critstate_f64 o;
            st = mdr_contact_init_f64(&c64, (uint8_t)s->kind, p, (double)s->E, (double)s->w);
            if (st == MDR_OK && k == 0) {
                st = mdr_default_start_f64(&c64, &a0);
            }
            if (st == MDR_OK) {
                st = mdr_critical_f64(&c64, (uint8_t)s->ctl, (double)s->km, a0, &o);
            }
            if (st == MDR_OK) {
                ga = o.a;
                gd = o.d;
                gF = o.F;
                gFm = o.F_min;
                gj = o.jumps;
            }
        }
        {
            row *r = rowof(rn);
            r->n++;
            if (st != MDR_OK) {
                r->named++;
                if (rep || strcmp(mdr_status_str(st), "unknown status") == 0) {
                    failures++;
                    fprintf(stderr, "crit_sweep: %s: status %s (start %d) at %s\n", rn, mdr_status_str(st), k,
                            where);
                }
                continue;
            }
            r->ok++;
            if (!rep) {
                if (!(isfinite(ga) && isfinite(gd) && isfinite(gF))) {
                    failures++;
                    fprintf(stderr, "crit_sweep: %s: non-finite result at %s\n", rn, where);
                }
                continue;
            }
            err = fabs(ga - (double)e.a) / (double)e.a;
            err = fmax(err, fabs(gF - (double)e.F) / fabs((double)e.F));
            err = fmax(err, fabs(gd - (double)e.d) / fmax(fabs((double)e.d), dl));
            if (e.have_fmin && (k == 0 || (k == 3 && a0 >= (double)kroot(s, 1.5L)))) {
                /* from a start above the load root (a start below it jumps
                 * in to a state that may lie below it: path-dependent) */
                err = fmax(err, fabs(gFm - (double)e.Fmin) / fabs((double)e.Fmin));
            }
            err /= cond;
            if (!(err <= r->worst)) {
                r->worst = err;
                snprintf(r->where, sizeof r->where, "%s (start %d)", where, k);
            }
            if (!(err <= tol / cond) || (s->kind != MDR_PROFILE_SPHERE && gj != e.jumps)) {
                failures++;
                fprintf(stderr,
                        "crit_sweep: %s: a %.9g (want %.9Lg) d %.9g (%.9Lg) F %.9g (%.9Lg) Fmin %.9g (%.9Lg) "
                        "jumps %d (%d), err %.2e x cond %.3g (start %d) at %s\n",
                        rn, ga, e.a, gd, e.d, gF, e.F, gFm, e.Fmin, gj, e.jumps, err, cond, k, where);
            }
        }
    }
}

static void run_both(const scene *s0, double cond)
{
    scene s = *s0;
    s.k0 = s.kind == MDR_PROFILE_POWERLAW ? kappa(s.p1) * s.p0 : 0;
    run(&s, 0, cond);
    run(&s, 1, cond);
}

/* a scene under the three controls; the machine at k_m = 2E* a_load x kf */
static void controls(scene s, double cond)
{
    static const double kfs[3] = {1e-3, 1.0, 1e3};
    for (int ctl = 1; ctl <= 3; ctl++) {
        s.ctl = ctl;
        if (ctl == MDR_CONTROL_MACHINE) {
            scene l = s;
            ld al;
            l.ctl = MDR_CONTROL_LOAD;
            if (s.kind == MDR_PROFILE_FLATTIP) {
                continue; /* expected values for load and grips */
            }
            l.k0 = s.kind == MDR_PROFILE_POWERLAW ? kappa(s.p1) * s.p0 : 0;
            al = s.kind == MDR_PROFILE_FLATPUNCH ? s.p0 : kroot(&l, 1.5L);
            for (int i = 0; i < 3; i++) {
                s.km = 2 * s.E * al * kfs[i];
                if (isfinite((double)s.km) && s.km > 0) {
                    run_both(&s, cond);
                }
            }
        } else {
            s.km = 0;
            run_both(&s, cond);
        }
    }
}

int main(int argc, char **argv)
{
    const int lng = argc > 1 && strcmp(argv[1], "long") == 0;
    const int ng = argc > 2 ? atoi(argv[2]) : (lng ? 13 : 4); /* points per parameter (12 decades) */
    const int nL = ng, nE = ng, nw = ng;
    static const double nfix[] = {0.6, 0.75, 0.9, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0};
    long total;
    int bad = 0;
    for (int iL = 0; iL < nL; iL++) {
        ld L = 1e-9L * powl(1e12L, (ld)iL / (nL - 1)); /* 1 nm .. 1 km */
        for (int iE = 0; iE < nE; iE++) {
            ld E = powl(1e12L, (ld)iE / (nE - 1)); /* 1 Pa .. 1 TPa */
            for (int iw = 0; iw < nw; iw++) {
                ld w = 1e-6L * powl(1e12L, (ld)iw / (nw - 1)); /* 1e-6 .. 1e6 J/m^2 */
                ld c = sqrtl(2 * PI_L * w / E);
                int sel = iL + iE + iw;
                scene s;
                memset(&s, 0, sizeof s);
                s.E = fl((double)E);
                s.w = fl((double)w);
                c = sqrtl(2 * PI_L * s.w / s.E);
                /* power laws, C = L^(1-n): every n of the fixed set in the
                 * long run, two per point in the short one */
                for (size_t i = 0; i < sizeof nfix / sizeof nfix[0]; i++) {
                    ld n = nfix[i];
                    if (!lng && (i + (size_t)sel) % 5 != 0) {
                        continue;
                    }
                    s.kind = MDR_PROFILE_POWERLAW;
                    s.p1 = n;
                    s.p0 = fl((double)powl(L, 1 - n));
                    controls(s, fmax(1.0, 1 / (double)(n - 0.5L)));
                }
                /* n continuous, and n -> 1/2+: C for a fixed-load radius L */
                for (int i = 0; i < (lng ? 12 : 2); i++) {
                    ld n = i < 6 ? 0.5L + powl(10.0L, -(ld)(1 + (i + sel) % 6))
                                 : 0.5L + 7.5L * (((i * 7919 + sel * 104729) % 1000) + 0.5L) / 1000;
                    s.kind = MDR_PROFILE_POWERLAW;
                    s.p1 = fl((double)n);
                    n = s.p1;
                    s.p0 = fl((double)(1.5L * c / (n * kappa(n) * powl(L, n - 0.5L))));
                    controls(s, fmax(1.0, 1 / (double)(n - 0.5L)));
                }
                s.kind = MDR_PROFILE_PARABOLOID;
                s.p0 = fl((double)L);
                s.p1 = 0;
                controls(s, 1);
                s.kind = MDR_PROFILE_CONE;
                s.p0 = fl(1e-4 + (1.5697963267948966 - 1e-4) * ((sel * 37) % 11) / 10.0);
                controls(s, 1);
                s.kind = MDR_PROFILE_SPHERE;
                s.p0 = fl((double)L);
                controls(s, 1);
                s.kind = MDR_PROFILE_FLATPUNCH;
                controls(s, 1);
                /* flattened tip around its thresholds (load, and grips at the
                 * same ratio of its own radius) */
                {
                    static const double ratios[] = {0.3, 0.7, 0.95, 1.05, 1.5, 3.0};
                    const ld ym = sqrtl((9 + sqrtl(57.0L)) / 12);
                    const ld Fm = sqrtl(ym) * (2 * ym * ym - 1) / sqrtl(ym * ym - 1);
                    for (size_t i = 0; i < sizeof ratios / sizeof ratios[0]; i++) {
                        if (!lng && (i + (size_t)sel) % 3 != 0) {
                            continue;
                        }
                        for (int ctl = 1; ctl <= 2; ctl++) {
                            ld k = ctl == 1 ? 1.5L : 0.5L, astar = powl(k * c * L / 2, 2.0L / 3);
                            s.kind = MDR_PROFILE_FLATTIP;
                            s.p0 = fl((double)L);
                            s.p1 = fl((double)(ratios[i] * powl(2 / Fm, 2.0L / 3) * astar));
                            s.ctl = ctl;
                            s.km = 0;
                            run_both(&s, 1);
                        }
                    }
                }
            }
        }
    }
    printf("critical-state sweep (%s): mdr_critical against closed forms (long double), f32 and f64\n",
           lng ? "long" : "short");
    printf("%-26s %7s %7s %7s  %-9s  %s\n", "profile control arith", "calls", "ok", "named", "worst/cond",
           "at");
    total = 0;
    for (int i = 0; i < nrows; i++) {
        const row *r = &rows[i];
        total += r->n;
        printf("%-26s %7ld %7ld %7ld  %.2e  %s\n", r->name, r->n, r->ok, r->named, r->worst,
               r->worst > 0 ? r->where : "");
    }
    bad = failures != 0;
    printf("%ld calls; bounds: f64 %.1e, f32 %.1e (times cond = max(1, 1/(n - 1/2))); %ld failures\n", total, TOL64,
           TOL32, failures);
    printf("crit_sweep: %d passed, %d failed\n", bad ? 0 : 1, bad);
    return bad;
}
