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

#endif /* MDR_CLOSED_FORMS_H */
