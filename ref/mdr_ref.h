/* SPDX-License-Identifier: MIT */
/*
 * mdr_ref.h: double-precision reference for libmdr, built on GSL and
 * numerically independent of lib/: it never uses the closed forms of g, G or
 * the Struve functions that lib/ evaluates. It starts from the gap profile
 * f(r) of the seed's problem statements and computes
 *   g(x)  = x int_0^x f'(r)/sqrt(x^2-r^2) dr   (4.46) with gsl_integration_qaws
 *           (the 1/sqrt(x-r) end point is the weight);
 *   g'(x) = int_0^{pi/2} [f'(x s) + x s f''(x s)] dphi, s = sin(phi)
 *           (differentiating g = x int_0^{pi/2} f'(x sin phi) dphi), with the
 *           jump of f' at r = b of the flattened tip as a point term;
 *   G(a)  = int_0^a g(x) dx by adaptive Gauss-Kronrod over the g above;
 *   d, F, derivatives from 4.25/4.26; sigma from 4.27 with qaws;
 *   critical states by the same quasi-static path definition as lib/
 *   (mdr_contact_t.h) with a finer scan and Brent's method (gsl_root);
 *   Struve H0, H1 from their integral representations (DLMF 11.5.2, 11.5.1).
 * It is proved against the seed's closed forms in host_tests/test_ref.c.
 */
#ifndef MDR_REF_H
#define MDR_REF_H

typedef struct {
    int kind;      /* MDR_PROFILE_* */
    double p[3];   /* as in lib/ */
    double E, w;   /* E* [Pa], work of adhesion [J/m^2] */
} ref_scene;

typedef struct {
    double a, d, F, dd_da, dF_da, dl;
} ref_eq;

typedef struct {
    double a, d, F;
    int jumps;
} ref_crit;

double ref_f(const ref_scene *s, double r);
double ref_g(const ref_scene *s, double x);
double ref_dg(const ref_scene *s, double x);
double ref_G(const ref_scene *s, double a);
int ref_eq_at(const ref_scene *s, double a, ref_eq *out);
double ref_stress(const ref_scene *s, double a, double r);
int ref_critical(const ref_scene *s, int control, double k_m, double a_start, ref_crit *out);
double ref_struve_h0(double z);
double ref_struve_h1(double z);
/* number of quadratures GSL reported as failed with an error estimate above
 * 1e-10 relative since start (diagnostics; see mdr_ref.c) */
int ref_failures(void);

#endif /* MDR_REF_H */
