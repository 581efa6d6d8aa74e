/* SPDX-License-Identifier: MIT */
/*
 * fuzz_engine_t.h: the checks of one float engine step (fuzz.h, top), for
 * FZ_T float (_f32) and double (_f64). Rounding allowance of the Hess band:
 * FZ_BAND_ULPS ulps of the size of its terms |g| + dl_w + |d|, plus what
 * the edge's tolerance of 4 eps in t makes of D = g - c t, plus the
 * arithmetic's subnormal spacing.
 */
#define FZ_BAND_ULPS 512

static inline void FZ_SFX(fz_check)(const FZ_SFX(mdr_engine) *e, const FZ_SFX(mdr_engine) *before,
                             mdr_status st, const FZ_SFX(mdr_step) *out,
                             const FZ_SFX(mdr_step) *out0)
{
    const FZ_SFX(mdr_table) *tab = e->tab;
    const double eps = sizeof(FZ_T) == sizeof(float) ? (double)FLT_EPSILON : DBL_EPSILON;
    fz_status(st);
    FZ_CHECK(st != MDR_E_NOCONV); /* "not expected" (mdr_engine_t.h) */
    if (st != MDR_OK) {
        FZ_SFX(mdr_engine) x = *e;
        x.flags = before->flags;
        FZ_CHECK(memcmp(&x, before, sizeof x) == 0);
        FZ_CHECK(memcmp(out, out0, sizeof *out) == 0);
        return;
    }
    FZ_CHECK(fz_fin((double)out->z) && fz_fin((double)out->d) && fz_fin((double)out->F) &&
             fz_fin((double)out->a));
    FZ_CHECK(fz_fin((double)out->a0) && fz_fin((double)out->d0) && fz_fin((double)out->F0));
    FZ_CHECK(fz_fin((double)out->a1) && fz_fin((double)out->d1) && fz_fin((double)out->F1));
    FZ_CHECK(fz_fin((double)e->en.work) && fz_fin((double)e->en.dissipated) && fz_fin((double)e->en.last_cycle));
    FZ_CHECK(e->a >= 0 && (double)e->a <= (double)tab->n * (double)tab->h * (1 + 4 * eps));
    /* the edge lives in t: a = t^2 underflows to 0 for radii below the
     * smallest subnormal (f32 re-contact at d = 1.4e-45 m) */
    FZ_CHECK(e->contact ? e->t > 0 : e->a == 0 && e->t == 0 && e->F == 0);
    FZ_CHECK(e->k < tab->n);
    if (e->contact) {
        double a = (double)e->a, t = (double)e->t, g = (double)e->g, d = (double)e->d;
        double dlw = (double)e->c_w * t, dla = (double)e->c_adv * t;
        /* g'(a) of the table's quadratic in spring k (mdr_e_at): the edge
         * is solved to 4 eps in t, which moves D = g - c t by
         * 4 eps t |2 t g' - c| (steep next to a flattened tip's rim) */
        double h = (double)tab->h, xk = (double)e->k * h, ex = a - xk;
        double sl = ((double)tab->node[e->k + 1].g - (double)tab->node[e->k].g) / h;
        double dg = sl + 6.0 * (double)tab->node[e->k].q / (h * h * h) * (h - 2 * ex);
        /* ... and the subnormal spacing of the arithmetic (radii, depths
         * below its smallest normal number: mdr_e_root stops when x = t^2
         * spans 16 eps MINV, which moves g by g' times that) */
        const double minv = sizeof(FZ_T) == sizeof(float) ? (double)FLT_MIN : DBL_MIN;
        double tol = FZ_BAND_ULPS * eps * (fabs(g) + dlw + fabs(d)) +
                     8 * eps * t * (2 * t * fabs(dg) + (double)e->c_w) + 16 * eps * minv * (1 + fabs(dg));
        if (e->k == 0 && a > 0) {
            /* spring 0 accepts a root with U within mdr_e_Utol0 of the
             * target: in depth 8 eps (Dm + Gm/x), Dm, Gm its magnitudes */
            double b6 = 6.0 * fabs((double)tab->node[0].q) / (h * h * h), as = fabs(sl);
            double Dm = a * (as + b6 * (h + a)) + (double)e->c_w * t, Gm = a * a * (0.5 * as + b6 * (0.5 * h + a));
            tol += 16 * eps * (Dm + Gm / a);
        }
        FZ_CHECK(a >= xk * (1 - 4 * eps) && a <= (xk + (double)tab->h) * (1 + 4 * eps));
        if (!(d >= g - dlw - tol && (d <= g - dla + tol || (tab->wall && e->k == tab->n - 1u)))) {
            fprintf(stderr, "Hess band: d %.17g, g - dl_w %.17g, g - dl_adv %.17g, tol %.3g (a %.17g, k %u)\n", d,
                    g - dlw, g - dla, tol, a, (unsigned)e->k);
        }
        /* at a wall (flat punch rim) the edge is held: d may pass the approach side */
        FZ_CHECK(d >= g - dlw - tol && (d <= g - dla + tol || (tab->wall && e->k == tab->n - 1u)));
    }
    FZ_CHECK(out->F == e->F && out->d == e->d && out->a == e->a);
}

/* One step of control ctl (FZ_D, FZ_F or FZ_Z) to v, checked as above; the
 * step's output in *out (a 0x5a pattern where the step wrote nothing). */
static inline mdr_status FZ_SFX(fz_step)(FZ_SFX(mdr_engine) *e, int ctl, FZ_T v, FZ_SFX(mdr_step) *out)
{
    const FZ_SFX(mdr_engine) before = *e;
    FZ_SFX(mdr_step) o0;
    mdr_status st;
    memset(out, 0x5a, sizeof *out);
    o0 = *out;
    st = ctl == FZ_D ? FZ_SFX(mdr_engine_step_d)(e, v, out)
         : ctl == FZ_F ? FZ_SFX(mdr_engine_step_F)(e, v, out)
                       : FZ_SFX(mdr_engine_step_z)(e, v, out);
    FZ_SFX(fz_check)(e, &before, st, out, &o0);
    if (st == MDR_E_OUTSIDE) {
        /* refused only where the target lies beyond the last node: the
         * approach branch's control there, U(x_n) = al D + ka (x D - G),
         * D = g - c_adv t, is below the target (a fold on the way lands
         * still lower), to the rounding of U's terms */
        const FZ_SFX(mdr_table) *tab = e->tab;
        const FZ_SFX(mdr_node) *nn = &tab->node[tab->n];
        const double eps = sizeof(FZ_T) == sizeof(float) ? (double)FLT_EPSILON : DBL_EPSILON;
        double x = (double)tab->n * (double)tab->h, g = (double)nn->g, G = (double)nn->G;
        double ct = (double)e->c_adv * (double)nn->t, D = g - ct;
        double al = ctl == FZ_F ? 0 : 1, ka = ctl == FZ_D ? 0 : ctl == FZ_F ? 1 : (double)e->kappa;
        double U = al * D + ka * (x * D - G);
        double u = ctl == FZ_F ? (double)v / (2 * (double)e->E) : (double)v;
        double tol = 16 * eps * (al * (fabs(g) + ct) + ka * (x * (fabs(g) + ct) + fabs(G)) + fabs(u));
        FZ_CHECK(!tab->wall && U < u + tol);
    }
    return st;
}

/* One step of a table-free scene (MDR_OUT_ALL, energy kept): never
 * MDR_E_NOCONV; a refused step changes nothing (the sticky flags aside)
 * and writes no output; an accepted one gives finite outputs and energy,
 * F = 0 and a = 0 when separated, and the edge inside the Hess band of the
 * monomial g = q tau (scene units, to FZ_BAND_ULPS ulps of its terms). */
static inline void FZ_SFX(fz_scene_step)(FZ_SFX(mdr_scene) *s, int ctl, FZ_T v)
{
    const FZ_SFX(mdr_scene) before = *s;
    const FZ_SFX(mdr_energy) en0 = *s->en;
    const double eps = sizeof(FZ_T) == sizeof(float) ? (double)FLT_EPSILON : DBL_EPSILON;
    FZ_SFX(mdr_step) o, o0;
    mdr_status st;
    memset(&o, 0x5a, sizeof o);
    o0 = o;
    st = ctl == FZ_D ? FZ_SFX(mdr_scene_step_d)(s, v, &o)
         : ctl == FZ_F ? FZ_SFX(mdr_scene_step_F)(s, v, &o)
                       : FZ_SFX(mdr_scene_step_z)(s, v, &o);
    fz_status(st);
    FZ_CHECK(st != MDR_E_NOCONV);
    if (st != MDR_OK) {
        FZ_SFX(mdr_scene) x = *s;
        x.flags = before.flags;
        FZ_CHECK(memcmp(&x, &before, sizeof x) == 0);
        FZ_CHECK(memcmp(s->en, &en0, sizeof en0) == 0);
        FZ_CHECK(memcmp(&o, &o0, sizeof o) == 0);
        return;
    }
    FZ_CHECK(fz_fin((double)o.z) && fz_fin((double)o.d) && fz_fin((double)o.F) && fz_fin((double)o.a));
    FZ_CHECK(fz_fin((double)o.a0) && fz_fin((double)o.F0) && fz_fin((double)o.a1) && fz_fin((double)o.F1));
    FZ_CHECK(fz_fin((double)s->en->work) && fz_fin((double)s->en->dissipated));
    FZ_CHECK(s->contact ? s->tau > 0 && o.a >= 0 : s->tau == 0 && o.F == 0 && o.a == 0);
    if (s->contact) {
        double t = (double)s->tau, q = pow(t, 2.0 * s->n - 1.0), d = (double)s->d / (double)s->Ds;
        double gw = t * (q - (double)s->gw), ga = t * (q - (double)s->ga);
        double tol = FZ_BAND_ULPS * eps * (t * q + t * (double)s->gw + fabs(d)) + 16 * eps * (2.0 * s->n * t * q);
        FZ_CHECK(d >= gw - tol && d <= ga + tol);
    }
}
#undef FZ_BAND_ULPS
