/*
 * mdr_q31init_t.c: the init-time (floating point) half of the q31 engine:
 * q31 tables from the tables of each floating arithmetic, the engine init
 * in each, and (f32 only) the SI conversions. Contract: lib/include/mdr_q31.h.
 * The step (integer only) is lib/src/mdr_q31.c.
 */

#if MDR_CFG_Q31 /* to the end of the file */

/* v rounded to nearest (ties away from zero); |v| <= 2^31 - 2^8 (int32
 * conversions only: a float -> int64 conversion would call a double
 * helper on some cores) */
static int32_t MDR_SFX(mdr_q_round)(MDR_T v)
{
    return v >= MDR_K(0.0) ? (int32_t)(v + MDR_K(0.5)) : -(int32_t)(MDR_K(0.5) - v);
}

/* v * f as Q(31-f).f (f = 2^bits), or false when it does not fit */
static bool MDR_SFX(mdr_q_fmt)(MDR_T v, MDR_T f, int32_t *out)
{
    MDR_T s = v * f;
    if (!(s > MDR_K(-2147483520.0) && s < MDR_K(2147483520.0))) {
        return false;
    }
    *out = MDR_SFX(mdr_q_round)(s);
    return true;
}

/* The least e with 2^e >= v, v > 0 finite (from mdr_m_frexp: v = f 2^x,
 * f in [1, 2), so 2^x <= v < 2^(x+1), equality only for f = 1). */
static int MDR_SFX(mdr_q_log2_ceil)(MDR_T v)
{
    int x;
    MDR_T f = MDR_SFX(mdr_m_frexp)(v, &x);
    return f == MDR_K(1.0) ? x : x + 1;
}

mdr_status MDR_SFX(mdr_table_q31_from)(mdr_table_q31 *tab, mdr_node_q31 *node,
                                       const MDR_SFX(mdr_table) *src)
{
    const MDR_T Q30 = MDR_K(1073741824.0), Q28 = MDR_K(268435456.0);
    MDR_T gmax = MDR_K(0.0), Dg, L, LD, bs, Qb;
    uint8_t fb = 30;
    int32_t gq = 0;
    uint16_t i, n;
    uint8_t m = 0;
    if (tab == NULL || node == NULL || src == NULL || src->node == NULL) {
        return MDR_E_NULL;
    }
    n = src->n;
    while (m < 15 && ((uint16_t)1u << m) < n) {
        m++;
    }
    if (n < MDR_SPRINGS_MIN || n > MDR_SPRINGS_MAX || ((uint16_t)1u << m) != n) {
        return MDR_E_SIZE;
    }
    L = src->h * (MDR_T)n;
    for (i = 0; i <= n; i++) {
        MDR_T ag = MDR_SFX(mdr_m_fabs)(src->node[i].g);
        gmax = ag > gmax ? ag : gmax;
    }
    /* Dg: the least power of two >= max|g| (>= L/1024 for an all-flat g) */
    Dg = MDR_SFX(mdr_m_ldexp)(
        MDR_K(1.0), MDR_SFX(mdr_q_log2_ceil)(gmax > MDR_K(0.0) ? gmax : L * MDR_K(0.0009765625)));
    LD = L * Dg;
    bs = MDR_K(6.0) * (MDR_T)n / LD;
    /* fb: the most fractional bits (30..40) that hold every b_i with a bit
     * to spare; |b_i| >= 2 Dg does not fit even Q1.30 */
    {
        MDR_T bmax = MDR_K(0.0);
        for (i = 0; i < n; i++) {
            MDR_T ab = MDR_SFX(mdr_m_fabs)(src->node[i].q * bs);
            bmax = ab > bmax ? ab : bmax;
        }
        Qb = Q30;
        while (fb < 40 && bmax * Qb * MDR_K(4.0) < MDR_K(2147483648.0)) {
            Qb *= MDR_K(2.0);
            fb++;
        }
    }
    for (i = 0; i <= n; i++) {
        const MDR_SFX(mdr_node) *s = &src->node[i];
        /* t_i = floor(sqrt(i/n) 2^30) exactly: isqrt(i 2^(60-m)) */
        uint64_t v = (uint64_t)i << (60u - m), r = 0, bit = (uint64_t)1 << 62;
        while (bit > v) {
            bit >>= 2;
        }
        while (bit != 0) {
            if (v >= r + bit) {
                v -= r + bit;
                r = (r >> 1) + bit;
            } else {
                r >>= 1;
            }
            bit >>= 2;
        }
        node[i].t = (int32_t)r;
        if (!MDR_SFX(mdr_q_fmt)(s->g / Dg, Q30, &node[i].g) ||
            !MDR_SFX(mdr_q_fmt)(s->G / LD, Q30, &node[i].G) ||
            !MDR_SFX(mdr_q_fmt)(s->q * bs, Qb, &node[i].b) ||
            !MDR_SFX(mdr_q_fmt)(i < n ? (s[1].g - s->g) * (MDR_T)n / Dg : MDR_K(0.0), Q28,
                                &node[i].s)) {
            return MDR_E_OVERFLOW;
        }
        gq = node[i].g > gq ? node[i].g : (-node[i].g > gq ? -node[i].g : gq);
    }
    tab->node = node;
    tab->L = (float)L;
    tab->L_lo = (float)(L - (MDR_T)tab->L);
    tab->Dg = (float)Dg;
    tab->gmax = gq;
    tab->n = n;
    tab->m = m;
    tab->fb = fb;
    tab->wall = src->wall;
    return MDR_OK;
}

/* Every entry of the table zero (g, G, slopes, curvature): O(n), init only. */
static bool MDR_SFX(mdr_q_table_zero)(const mdr_table_q31 *tab)
{
    uint16_t i;
    if (tab->gmax != 0) {
        return false;
    }
    for (i = 0; i <= tab->n; i++) {
        const mdr_node_q31 *q = &tab->node[i];
        if (q->g != 0 || q->G != 0 || q->s != 0 || q->b != 0) {
            return false;
        }
    }
    return true;
}

mdr_status MDR_SFX(mdr_engine_init_q31)(mdr_engine_q31 *e, const mdr_table_q31 *tab, MDR_T E,
                                        MDR_T w, MDR_T w_adv, MDR_T k_m)
{
    const MDR_T Q29 = MDR_K(536870912.0), Q30 = MDR_K(1073741824.0);
    mdr_engine_q31 z;
    MDR_T L, cw, ca, M, D0;
    uint8_t k = 0;
    mdr_status st;
    if (e == NULL || tab == NULL || tab->node == NULL) {
        return MDR_E_NULL;
    }
    L = (MDR_T)tab->L + (MDR_T)tab->L_lo;
    if (tab->n < MDR_SPRINGS_MIN || tab->n > MDR_SPRINGS_MAX || tab->m > 14 ||
        ((uint16_t)1u << tab->m) != tab->n || tab->fb < 30 || tab->fb > 40 || !(L > MDR_K(0.0)) ||
        !(tab->Dg > 0.0f) || !MDR_SFX(mdr_m_isfinite)(L) || !MDR_SFX(mdr_m_isfinite)((MDR_T)tab->Dg) ||
        tab->gmax < 0) {
        return MDR_E_SIZE;
    }
    st = MDR_SFX(mdr_e_material)(E, w, w_adv, k_m);
    if (st != MDR_OK) {
        return st;
    }
    /* dl(L) = sqrt(2 pi w L / E*) on retraction, approach */
    cw = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w / E) * L);
    ca = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w_adv / E) * L);
    M = (MDR_T)tab->gmax * ((MDR_T)tab->Dg / Q30) + cw;
    /* D0 = 2^k Dg, the least k >= 0 with D0 >= M (Dg is a power of two).
     * An all-zero table (the flat punch: g, G, slopes and curvature 0) has
     * no depth scale of its own (its Dg is L/1024): there D0 is the least
     * power of two >= dl_w(L), whatever Dg, and the shift from the table's
     * unit (sh) acts on zeros only. With D0 >= Dg instead, a cycle whose
     * dl_w(L) is far below L/1024 used a sliver of Q2.29 (make stress:
     * 3.6e-4 of max|F| for a 1 m punch with w/E* = 1e-18 m). */
    if (M > MDR_K(0.0) && MDR_SFX(mdr_q_table_zero)(tab)) {
        D0 = MDR_SFX(mdr_m_ldexp)(MDR_K(1.0), MDR_SFX(mdr_q_log2_ceil)(M));
    } else {
        if (M > (MDR_T)tab->Dg) {
            int kk = MDR_SFX(mdr_q_log2_ceil)(M) - MDR_SFX(mdr_q_log2_ceil)((MDR_T)tab->Dg);
            if (kk > 60) {
                return MDR_E_OVERFLOW;
            }
            k = (uint8_t)kk;
        }
        D0 = MDR_SFX(mdr_m_ldexp)((MDR_T)tab->Dg, k);
    }
    z.tab = tab;
    z.L = tab->L;
    z.D0 = (float)D0;
    z.F0 = (float)(MDR_K(2.0) * E * L * D0);
    /* the units as float: finite and > 0 (dl_w(L) enormous for w/E* huge,
     * e.g. E* = 9e-42 Pa: fuzz_init) */
    if (!MDR_SFX(mdr_m_isfinite)(M) || !MDR_SFX(mdr_m_isfinite)((MDR_T)z.D0) || !(z.D0 > 0.0f) ||
        !MDR_SFX(mdr_m_isfinite)((MDR_T)z.F0) || !(z.F0 > 0.0f)) {
        return MDR_E_OVERFLOW;
    }
    z.sh = (uint8_t)(k + 1u);
    z.c_w = MDR_SFX(mdr_q_round)(cw / D0 * Q29);
    z.c_adv = MDR_SFX(mdr_q_round)(ca / D0 * Q29);
    z.machine = k_m > MDR_K(0.0);
    z.sz = 0;
    z.al_z = MDR_Q30_ONE;
    z.ka_z = 0;
    z.z_in = MDR_Q30_ONE;
    z.z_k = 0;
    if (z.machine) {
        MDR_T kap = MDR_K(2.0) * E * L / k_m, sc;
        if (!MDR_SFX(mdr_m_isfinite)(kap) || kap > MDR_K(65536.0)) {
            return MDR_E_CONTROL;
        }
        z.al_z = MDR_SFX(mdr_q_round)(Q30 / (MDR_K(1.0) + kap));
        z.ka_z = MDR_Q30_ONE - z.al_z;
        /* sz = floor(log2(1 + kap)): 1 + kap = f 2^x, f in [1, 2), sz = x */
        {
            int x;
            (void)MDR_SFX(mdr_m_frexp)(MDR_K(1.0) + kap, &x);
            z.sz = (uint8_t)x;
        }
        sc = MDR_SFX(mdr_m_ldexp)(MDR_K(1.0), z.sz);
        z.z_in = MDR_SFX(mdr_q_round)(Q30 * (sc / (MDR_K(1.0) + kap)));
        z.z_k = MDR_SFX(mdr_q_round)(Q30 * (kap / sc));
    }
    z.Z0 = z.D0 * (float)(1UL << z.sz);
    z.a = z.t = z.g = z.Ga = z.d = z.F = 0;
    z.k = 0;
    z.contact = z.touched = z.flags = 0;
    z.work = z.work_sep = z.dissipated = z.last_cycle = 0;
    z.cycles = 0;
    *e = z;
    return MDR_OK;
}

#ifdef MDR_ARITH_F32
static float mdr_q_unit(const mdr_engine_q31 *e, uint8_t q)
{
    switch (q) {
    case MDR_Q_A:
        return e->L / 1073741824.0f;
    case MDR_Q_D:
        return e->D0 / 536870912.0f;
    case MDR_Q_F:
        return e->F0 / 536870912.0f;
    case MDR_Q_Z:
        return e->Z0 / 536870912.0f;
    default:
        return 0.0f;
    }
}

int32_t mdr_q31_in(const mdr_engine_q31 *e, uint8_t q, float v)
{
    float u, s;
    if (e == NULL || !(mdr_q_unit(e, q) > 0.0f)) {
        return 0;
    }
    u = mdr_q_unit(e, q);
    s = v / u;
    if (!(s < 2147483520.0f)) { /* also NaN: the largest float below 2^31 */
        return s != s ? 0 : INT32_MAX;
    }
    if (!(s > -2147483648.0f)) {
        return INT32_MIN;
    }
    return mdr_q_round_f32(s);
}

float mdr_q31_out(const mdr_engine_q31 *e, uint8_t q, int32_t v)
{
    return e == NULL ? 0.0f : (float)v * mdr_q_unit(e, q);
}

float mdr_q31_energy(const mdr_engine_q31 *e, int64_t v)
{
    /* W0 2^-48; the int64 is first reduced to int32 range (a float -> int64
     * conversion would pull a double helper into soft-float builds) */
    float scale = (e == NULL ? 0.0f : e->F0 / 16777216.0f) * (e == NULL ? 0.0f : e->D0 / 16777216.0f);
    while (v >= 2147483648 || v <= -2147483648) {
        v /= 2;
        scale *= 2.0f;
    }
    return (float)(int32_t)v * scale;
}
#endif
#endif /* MDR_CFG_Q31 */
