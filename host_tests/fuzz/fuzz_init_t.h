/* SPDX-License-Identifier: MIT */
/*
 * fuzz_init_t.h: one arithmetic of fuzz_init.c (FZ_T float or double,
 * FZ_SFX _f32 or _f64). fz_scene is defined once, before the first use.
 */
#ifndef FZ_SCENE_DEFINED
#define FZ_SCENE_DEFINED
typedef struct {
    uint8_t kind, control;
    double p[3], E, w, a[4], r[4], d[4], k_m, x_frac, w_adv, k_m2;
    uint16_t springs;
} fz_scene;
#endif

/* a call with an output struct: on refusal the output must be untouched */
#define FZ_OUT(call, out)                              \
    do {                                               \
        unsigned char fz_sav[sizeof(out)];             \
        memset(&(out), 0x5a, sizeof(out));             \
        memcpy(fz_sav, &(out), sizeof(out));           \
        st = (call);                                   \
        fz_status(st);                                 \
        if (st != MDR_OK) {                            \
            FZ_CHECK(memcmp(fz_sav, &(out), sizeof(out)) == 0); \
        }                                              \
    } while (0)

static void FZ_SFX(fz_init)(const fz_scene *s)
{
    static FZ_SFX(mdr_node) nodes[MDR_TABLE_NODES(NMAX)];
    static mdr_node_q31 nq[MDR_TABLE_NODES(NMAX)];
    const FZ_T p[3] = {(FZ_T)s->p[0], (FZ_T)s->p[1], (FZ_T)s->p[2]};
    FZ_SFX(mdr_contact) c;
    FZ_SFX(mdr_table) tab;
    FZ_SFX(mdr_engine) e;
    mdr_table_q31 tq;
    mdr_engine_q31 eq;
    FZ_T a0 = 0;
    mdr_status st;
    int i;
    FZ_OUT(FZ_SFX(mdr_contact_init)(&c, s->kind, p, (FZ_T)s->E, (FZ_T)s->w), c);
    if (st != MDR_OK) {
        return;
    }
    for (i = 0; i < 4; i++) {
        FZ_T a = (FZ_T)s->a[i], g = 0, dg = 0, G = 0, K = 0, Gr = 0, sg = 0;
        FZ_SFX(mdr_eqstate) q;
        st = FZ_SFX(mdr_profile_eval)(&c, a, &g, &dg, &G);
        fz_status(st);
        FZ_CHECK(st != MDR_OK || (fz_fin((double)g) && fz_fin((double)dg) && fz_fin((double)G)));
        FZ_OUT(FZ_SFX(mdr_eq)(&c, a, &q), q);
        if (st == MDR_OK) {
            FZ_CHECK(fz_fin((double)q.d) && fz_fin((double)q.F) && fz_fin((double)q.dd_da) &&
                     fz_fin((double)q.dF_da) && fz_fin((double)q.dl) && fz_fin((double)q.K_I) &&
                     fz_fin((double)q.G));
            FZ_OUT(FZ_SFX(mdr_stress)(&c, a, (FZ_T)s->r[i] * a, &sg), sg);
            FZ_CHECK(st != MDR_OK || fz_fin((double)sg));
        }
        FZ_OUT(FZ_SFX(mdr_stress_intensity)(&c, a, (FZ_T)s->d[i], &K, &Gr), K);
        FZ_CHECK(st != MDR_OK || (fz_fin((double)K) && fz_fin((double)Gr)));
        FZ_OUT(FZ_SFX(mdr_stress_at)(&c, a, (FZ_T)s->d[i], (FZ_T)s->r[i] * a, &sg), sg);
        FZ_CHECK(st != MDR_OK || fz_fin((double)sg));
    }
    FZ_OUT(FZ_SFX(mdr_default_start)(&c, &a0), a0);
    if (st == MDR_OK) {
        FZ_SFX(mdr_critstate) k;
        FZ_CHECK(fz_fin((double)a0) && a0 > 0);
        FZ_OUT(FZ_SFX(mdr_critical)(&c, s->control, (FZ_T)s->k_m, a0, &k), k);
        FZ_CHECK(st != MDR_OK || (fz_fin((double)k.a) && fz_fin((double)k.d) && fz_fin((double)k.F)));
    }
    /* a table of the scene, its engine, the q31 table and engine */
    FZ_OUT(FZ_SFX(mdr_table_init_profile)(&tab, nodes, s->springs, &c, (FZ_T)(s->x_frac * s->a[0])), tab);
    if (st != MDR_OK) {
        return;
    }
    for (i = 0; i <= tab.n; i++) {
        FZ_CHECK(fz_fin((double)nodes[i].g) && fz_fin((double)nodes[i].G) && fz_fin((double)nodes[i].t) &&
                 fz_fin((double)nodes[i].q));
    }
    FZ_OUT(FZ_SFX(mdr_engine_init)(&e, &tab, (FZ_T)s->E, (FZ_T)s->w, (FZ_T)s->w_adv, (FZ_T)s->k_m2), e);
    FZ_OUT(FZ_SFX(mdr_table_q31_from)(&tq, nq, &tab), tq);
    if (st == MDR_OK) {
        FZ_OUT(FZ_SFX(mdr_engine_init_q31)(&eq, &tq, (FZ_T)s->E, (FZ_T)s->w, (FZ_T)s->w_adv, (FZ_T)s->k_m2),
               eq);
    }
}
#undef FZ_OUT
