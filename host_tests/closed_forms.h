/* SPDX-License-Identifier: MIT */
/*
 * closed_forms.h: g, g' and G of the seed's profiles (but the wavy one)
 * written out in long double with libm, independently of lib/, for the
 * tests (test_unit.c, test_config.c). Include after <math.h> and mdr.h.
 */
#ifndef MDR_CLOSED_FORMS_H
#define MDR_CLOSED_FORMS_H

/* g(a), g'(a) and G(a) of a profile from closed forms written here in long
 * double (seed 4.28, 4.55, 4.65, 4.63, 4.74-4.77, 4.81; G = int_0^a g:
 * sphere ((a^2 - R^2)/2) atanh(a/R) + R a/2, flattened tip
 * (a^2 - b^2)^(3/2)/(3R)); not the wavy profile (its Struve terms are checked
 * against GSL in test_gsl.c and test_vectors.c) */
__attribute__((unused)) static void profile_cf(uint8_t k, const double p[3], double a, double *g, double *dg, double *G)
{
    long double x = a, r;
    switch (k) {
    case MDR_PROFILE_PARABOLOID:
        *g = (double)(x * x / p[0]), *dg = (double)(2 * x / p[0]), *G = (double)(x * x * x / (3 * p[0]));
        break;
    case MDR_PROFILE_CONE: {
        long double k0 = M_PI / 2 * tanl(p[0]);
        *g = (double)(k0 * x), *dg = (double)k0, *G = (double)(k0 * x * x / 2);
        break;
    }
    case MDR_PROFILE_POWERLAW: {
        long double n = p[1], kap = sqrtl(M_PI) * expl(lgammal(n / 2 + 1) - lgammal((n + 1) / 2));
        long double gv = kap * p[0] * powl(x, n);
        *g = (double)gv, *dg = (double)(n * gv / x), *G = (double)(gv * x / (n + 1));
        break;
    }
    case MDR_PROFILE_FLATPUNCH:
        *g = *dg = *G = 0;
        break;
    case MDR_PROFILE_SPHERE:
        r = p[0];
        *g = (double)(x * atanhl(x / r));
        *dg = (double)(atanhl(x / r) + (x / r) / (1 - (x / r) * (x / r)));
        *G = (double)((x * x - r * r) / 2 * atanhl(x / r) + r * x / 2);
        break;
    default: { /* flattened tip: 0 on the flat (a <= b), 4.81 beyond */
        long double b = p[1], s2 = (x - b) * (x + b);
        if (x <= b) {
            *g = *dg = *G = 0;
            break;
        }
        *g = (double)(x * sqrtl(s2) / p[0]);
        *dg = (double)((2 * s2 + b * b) / (p[0] * sqrtl(s2)));
        *G = (double)(s2 * sqrtl(s2) / (3 * p[0]));
        break;
    }
    }
}

/* The work int F dd of one JKR cycle of the paraboloid (g = x^2/R, seed
 * 4.28) with w_adv on approach and w on retraction, under fixed load or
 * fixed grips (ctl), up to the radius a_max and back past the pull-off.
 * Along a branch of c = sqrt(2 pi w/E*) (dl = c sqrt(a), 4.21), with
 * s = sqrt(a): d = s^4/R - c s and F = 2E*(a d - a^3/(3R))
 * = 4E* s^6/(3R) - 2E* c s^3 (JKR), so that F dd = F d'(s) ds and
 *   int F dd = P(s_B) - P(s_A),
 *   P(s) = 8E* s^10/(15 R^2) - 4E* c s^7/(3R) + E* c^2 s^4/2.
 * The cycle: the jump-in at the touch (constant control: no work) onto the
 * approach branch where the control is 0 (load: s^3 = 3R c_adv/2; grips:
 * s^3 = R c_adv), along it to a_max, pinned there down to the retraction
 * branch (F linear in d: the trapezoid), along that to its fold (load:
 * s^3 = 3R c_w/4; grips: s^3 = R c_w/4) and the pull-off (constant
 * control: no work). Also: the gross work (the sum of |int F dd| over the
 * pieces), the peak control and the pull-off's control. */
__attribute__((unused)) static double jkr_P(double E_, double R, double c, double s)
{
    const double s3 = s * s * s;
    return s3 * s * (8 * E_ * s3 * s3 / (15 * R * R) - 4 * E_ * c * s3 / (3 * R) + E_ * c * c / 2);
}

/* (the work from the touch to the retraction branch's state at radius a,
 * a_f <= a <= a_max; a < 0: to its fold a_f, the whole cycle's) */
__attribute__((unused)) static double jkr_work_to(double E_, double R, double w, double wa, uint8_t ctl,
                                                  double a_max, double a, double *gross, double *u_max,
                                                  double *u_off)
{
    const double cw = sqrt(2 * M_PI * w / E_), ca = sqrt(2 * M_PI * wa / E_), sm = sqrt(a_max);
    const double sin = cbrt(ctl == MDR_CONTROL_LOAD ? 1.5 * R * ca : R * ca);
    const double sf = cbrt(ctl == MDR_CONTROL_LOAD ? 0.75 * R * cw : 0.25 * R * cw);
    const double da = a_max * a_max / R - ca * sm, dw = a_max * a_max / R - cw * sm;
    const double Fa = 2 * E_ * (a_max * da - a_max * a_max * a_max / (3 * R));
    const double Fw = 2 * E_ * (a_max * dw - a_max * a_max * a_max / (3 * R));
    const double w1 = jkr_P(E_, R, ca, sm) - jkr_P(E_, R, ca, sin), w2 = 0.5 * (Fa + Fw) * (dw - da);
    const double w3 = jkr_P(E_, R, cw, a < 0 ? sf : sqrt(a)) - jkr_P(E_, R, cw, sm);
    const double af = sf * sf, df = af * af / R - cw * sf;
    *gross = fabs(w1) + fabs(w2) + fabs(w3);
    *u_max = ctl == MDR_CONTROL_LOAD ? Fa : da;
    *u_off = ctl == MDR_CONTROL_LOAD ? 2 * E_ * (af * df - af * af * af / (3 * R)) : df;
    return w1 + w2 + w3;
}

__attribute__((unused)) static double jkr_cycle_work(double E_, double R, double w, double wa, uint8_t ctl,
                                                     double a_max, double *gross, double *u_max, double *u_off)
{
    return jkr_work_to(E_, R, w, wa, ctl, a_max, -1, gross, u_max, u_off);
}

/* The same cycle's dissipation as the sum of what each part dissipates
 * where it arises, which no stored energy swamps (mdr_energy's comment):
 * the work less the change of the elastic energy
 * Psi(a, d) = E* int_0^a (d - x^2/R)^2 dx = E* (a d^2 - 2 d a^3/(3R) + a^5/(5R^2)).
 * Along a branch that is the work of adhesion, -w_adv pi (a_max^2 - a_in^2)
 * on the approach and w pi (a_max^2 - a_f^2) on the retraction; pinned,
 * nothing; the jump-in from (a, d) = (0, 0) to (a_in, d_in) at its
 * constant control, whose work (F = 0 or d = 0 throughout) is 0, less
 * Psi(a_in, d_in); the pull-off from the fold (a_f, d_f) at d = d_f (load:
 * F = 0 after it, d where contact was lost; grips), whose work is 0, less
 * -Psi(a_f, d_f). Worked out here from the JKR branches, independently of
 * jkr_cycle_work (the loop's area), which it equals in exact arithmetic. */
__attribute__((unused)) static double jkr_psi(double E_, double R, double a, double d)
{
    return E_ * a * (d * d - 2 * d * a * a / (3 * R) + a * a * a * a / (5 * R * R));
}

__attribute__((unused)) static double jkr_cycle_loss(double E_, double R, double w, double wa, uint8_t ctl,
                                                     double a_max)
{
    const double cw = sqrt(2 * M_PI * w / E_), ca = sqrt(2 * M_PI * wa / E_);
    const double sin = cbrt(ctl == MDR_CONTROL_LOAD ? 1.5 * R * ca : R * ca);
    const double sf = cbrt(ctl == MDR_CONTROL_LOAD ? 0.75 * R * cw : 0.25 * R * cw);
    const double ain = sin * sin, af = sf * sf;
    const double din = ain * ain / R - ca * sin, df = af * af / R - cw * sf;
    return -wa * M_PI * (a_max * a_max - ain * ain) + w * M_PI * (a_max * a_max - af * af) -
           jkr_psi(E_, R, ain, din) + jkr_psi(E_, R, af, df);
}

/* The same for g = C x^n (the scenes' power laws; n = 2, C = 1/R: the
 * paraboloid above), one cycle from the touch to a_max (*u_max: its
 * control there) and back past the pull-off (*u_off: the pull-off's
 * control). On a branch of dl = c sqrt(a): d = C a^n - c sqrt(a), F/(2E*) =
 * a d - G = n/(n+1) C a^(n+1) - c a^(3/2). The jump-in at the touch lands
 * where the control is 0 (grips: C a^(n-1/2) = c_adv; load: n/(n+1)
 * C a^(n-1/2) = c_adv), from d = 0, losing E* int_0^a g (d_in - g); the
 * retraction's fold (grips: 2n C a^(n-1/2) = c_w; load: n C a^(n-1/2) =
 * 1.5 c_w) pulls off at d_f, losing Psi(a_f, d_f) = E* (a d^2 - 2 d C
 * a^(n+1)/(n+1) + C^2 a^(2n+1)/(2n+1)); the branches their works of
 * adhesion. Needs a_in, a_f < a_max. */
__attribute__((unused)) static double mono_cycle_loss(double E_, double C, int n, double w, double wa, uint8_t ctl,
                                                      double a_max, double *u_max, double *u_off)
{
    const double cw = sqrt(2 * M_PI * w / E_), ca = sqrt(2 * M_PI * wa / E_), e = 1.0 / (n - 0.5);
    const double ain = pow(ctl == MDR_CONTROL_LOAD ? ca * (n + 1) / (n * C) : ca / C, e);
    const double af = pow(ctl == MDR_CONTROL_LOAD ? 1.5 * cw / (n * C) : cw / (2 * n * C), e);
    const double din = C * pow(ain, n) - ca * sqrt(ain), df = C * pow(af, n) - cw * sqrt(af);
    const double dm = C * pow(a_max, n) - ca * sqrt(a_max);
    const double lin = E_ * (din * C * pow(ain, n + 1) / (n + 1) - C * C * pow(ain, 2 * n + 1) / (2 * n + 1));
    const double psif = E_ * (af * df * df - 2 * df * C * pow(af, n + 1) / (n + 1) + C * C * pow(af, 2 * n + 1) / (2 * n + 1));
    *u_max = ctl == MDR_CONTROL_LOAD ? 2 * E_ * (a_max * dm - C * pow(a_max, n + 1) / (n + 1)) : dm;
    *u_off = ctl == MDR_CONTROL_LOAD ? 2 * E_ * (af * df - C * pow(af, n + 1) / (n + 1)) : df;
    return -wa * M_PI * (a_max * a_max - ain * ain) + w * M_PI * (a_max * a_max - af * af) + lin + psif;
}

/* The energy tests' JKR scenes (test_engine's energy_any_tick, test_scene's,
 * test_q31's): the JKR scene of CHECK_VALUES with w_adv = 0.4 w to 8 um;
 * helper-31's 1 mm sphere of stop 58, E* = 10 GPa, w_adv = 0.99 w, to 72 um
 * (about 5 N under load), which stores some 2e6 times what it dissipates;
 * the first without adhesion */
typedef struct {
    double R, E, w, wa, a_max;
} jkr_scene;
__attribute__((unused)) static const jkr_scene jkr_scenes[3] = {
    {10e-6, 1e6, 0.05, 0.02, 8e-6}, {1e-3, 1e10, 0.05, 0.0495, 7.2e-5}, {10e-6, 1e6, 0, 0, 8e-6}};

/* jkr_cycle_work of scene sc under ctl, and the end of its path: past the
 * pull-off (1.5 times its control), without adhesion below 0 (-0.1 times
 * the peak) */
__attribute__((unused)) static double jkr_cycle(const jkr_scene *sc, uint8_t ctl, double *gross, double *u_max,
                                                double *u_end)
{
    double u_off;
    const double want = jkr_cycle_work(sc->E, sc->R, sc->w, sc->wa, ctl, sc->a_max, gross, u_max, &u_off);
    *u_end = u_off != 0 ? 1.5 * u_off : -0.1 * *u_max;
    return want;
}

#endif /* MDR_CLOSED_FORMS_H */
