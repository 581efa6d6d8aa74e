/* SPDX-License-Identifier: MIT */
/*
 * first_eq.h: the oracle of the first equilibrium on the way (test_engine's
 * first_equilibrium_coarse_tables, test_q31's coarse_tables_first_eq),
 * written from the model of lib/include/mdr_engine_t.h, not from the
 * engine's code: U(t) of a branch on a table's interpolant (nodes as
 * doubles), sampled ORACLE_M times per spring from the edge in the
 * direction of motion; the first sample past the control is a root
 * (refined by bisection), a sample below the one before it, before any
 * root, is a fold (a jump). Ticks where the branch's highest point before
 * the answer comes within TOL_FIRST_TIE of the control (relative to the
 * range of U on the table) are ties: the sampling cannot tell.
 */
#ifndef FIRST_EQ_H
#define FIRST_EQ_H

#include <math.h>
#include <stdint.h>

#include "mdr.h"

#define ORACLE_M 400
#define TOL_FIRST_TIE 1e-5

typedef struct {
    double al, ka, c;
} or_branch;

/* U and dU/dt of a branch at x on the interpolant of t (nodes as doubles) */
static double or_U(const mdr_node_f64 *node, uint16_t n, double h, const or_branch *b, double x, double *dU)
{
    int k = (int)(x / h);
    double e, Dg, B, g, G, dg, tt = sqrt(x), D;
    k = k < 0 ? 0 : k >= (int)n ? (int)n - 1 : k;
    e = (x - h * k) / h;
    Dg = node[k + 1].g - node[k].g;
    B = 6.0 * node[k].q / h;
    g = node[k].g + e * (Dg + B * (1.0 - e));
    dg = (Dg + B * (1.0 - 2.0 * e)) / h;
    G = node[k].G + h * e * (node[k].g + e * (0.5 * Dg + B * (0.5 - e / 3.0)));
    D = g - b->c * tt;
    if (dU) {
        *dU = b->al * (2 * tt * dg - b->c) + b->ka * x * (2 * tt * dg - 3 * b->c);
    }
    return b->al * D + b->ka * (x * D - G);
}

enum { OR_PINNED, OR_ROOT, OR_FOLD, OR_END, OR_TIE };

/* the oracle's answer for a tick from the edge at x0 to the control u;
 * *xr the root's x; span: the range of U on the table (the tie margin) */
static int or_tick(const mdr_node_f64 *node, uint16_t n, double h, double al, double ka, double cadv,
                   double cw, double x0, double u, double span, double *xr)
{
    const or_branch adv = {al, ka, cadv}, rec = {al, ka, cw};
    const or_branch *b;
    const double dx = h / ORACLE_M, tie = TOL_FIRST_TIE * span, xn = h * n;
    double x = x0, W, Wmax;
    int dir;
    if (or_U(node, n, h, &adv, x0, NULL) < u) {
        dir = 1, b = &adv;
    } else if (or_U(node, n, h, &rec, x0, NULL) > u) {
        dir = -1, b = &rec;
    } else {
        return OR_PINNED;
    }
    W = dir * (or_U(node, n, h, b, x0, NULL) - u);
    Wmax = W;
    for (;;) {
        double xn1 = x + dir * dx, Wn;
        if (xn1 <= 0 || xn1 >= xn) {
            return OR_END;
        }
        Wn = dir * (or_U(node, n, h, b, xn1, NULL) - u);
        if (Wn >= 0) {
            double lo = x, hi = xn1;
            int i;
            if (Wmax > -tie) {
                return OR_TIE;
            }
            for (i = 0; i < 200 && lo != hi; i++) {
                double m = 0.5 * (lo + hi);
                if (m == lo || m == hi) {
                    break;
                }
                if (dir * (or_U(node, n, h, b, m, NULL) - u) >= 0) {
                    hi = m;
                } else {
                    lo = m;
                }
            }
            *xr = hi;
            return OR_ROOT;
        }
        if (Wn < W) { /* W turned: a fold at or before x */
            return Wmax > -tie || Wn > W - 1e-12 * span ? OR_TIE : OR_FOLD;
        }
        Wmax = Wn > Wmax ? Wn : Wmax;
        W = Wn;
        x = xn1;
    }
}

#endif /* FIRST_EQ_H */
