/* SPDX-License-Identifier: MIT */
/*
 * naive_sum.h: the naive O(N) force of a spring table, the oracle of
 * test_engine.c and the baseline of bench_engine.c. Each full spring j
 * below the edge carries 2E*(d h - int_spring g) (its trapezoid plus the
 * stored excess q_j), the edge spring the part up to a, integrated over the
 * same quadratic as the engine (lib/include/mdr_engine_t.h); summed in
 * double, one spring at a time, without the prefix sums G_i.
 */
#define NAIVE_SUM(SFX)                                                                     \
    static inline double naive_F_##SFX(const mdr_table_##SFX *t, double E, double a, double d)    \
    {                                                                                      \
        double sum = 0, h = t->h;                                                          \
        long j, k = (long)(a / h);                                                         \
        const mdr_node_##SFX *p;                                                           \
        if (k >= (long)t->n) {                                                             \
            k = (long)t->n - 1;                                                            \
        }                                                                                  \
        for (j = 0; j < k; j++) {                                                          \
            p = &t->node[j];                                                               \
            sum += d * h - (0.5 * h * ((double)p->g + (double)p[1].g) + (double)p->q);     \
        }                                                                                  \
        p = &t->node[k];                                                                   \
        {                                                                                  \
            double e = a - h * (double)k, s = ((double)p[1].g - (double)p->g) / h;         \
            double be = 6 * (double)p->q / (h * h * h);                                    \
            sum += d * e - e * ((double)p->g + e * (0.5 * s + be * (0.5 * h - e / 3)));    \
        }                                                                                  \
        return 2 * E * sum;                                                                \
    }
NAIVE_SUM(f32)
NAIVE_SUM(f64)

/* g(a) of a table's quadratic spring interpolant (mdr_engine_t.h),
 * recomputed here in double from the nodes: the band of the rule of Hess
 * checked against something the engine did not compute */
#define TABLE_G(SFX)                                                                       \
    static inline double table_g_##SFX(const mdr_table_##SFX *t, double a)                        \
    {                                                                                      \
        double h = t->h, e, s, be;                                                         \
        long k = (long)(a / h);                                                            \
        const mdr_node_##SFX *p;                                                           \
        if (k >= (long)t->n) {                                                             \
            k = (long)t->n - 1;                                                            \
        }                                                                                  \
        p = &t->node[k];                                                                   \
        e = a - h * (double)k;                                                             \
        s = ((double)p[1].g - (double)p->g) / h;                                           \
        be = 6 * (double)p->q / (h * h * h);                                               \
        return (double)p->g + e * (s + be * (h - e));                                      \
    }
TABLE_G(f32)
TABLE_G(f64)
