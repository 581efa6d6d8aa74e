/* SPDX-License-Identifier: MIT */
/*
 * mdr_fit_cli_t.h: one arithmetic of `mdr fit` (examples/mdr_fit_cli.h
 * includes it twice, with FIT_T float/double and FIT_SFX(name) name##_f32 /
 * name##_f64): the tip, the options and one fit in that arithmetic, the
 * result back in double.
 */

/* the profile as a contact of the arithmetic (its E* and w unused) */
static mdr_status FIT_SFX(fit_tip)(const struct fit_args *A, FIT_SFX(mdr_contact) *tip)
{
    FIT_T p[3] = {(FIT_T)A->p[0], (FIT_T)A->p[1], (FIT_T)A->p[2]};
    if (A->kind == MDR_PROFILE_TABLE) { /* samples converted and checked by fit_tip_samples() */
        const FIT_T *b = FIT_SFX(A->tip);
        return FIT_SFX(mdr_contact_init_table)(tip, b, b + A->tm, A->tm, (FIT_T)1.0, (FIT_T)0.0);
    }
    return FIT_SFX(mdr_contact_init)(tip, A->kind, p, (FIT_T)1.0, (FIT_T)0.0);
}

/* One curve (n samples in double) fitted in the arithmetic; the scratch
 * grows to n. */
static mdr_status FIT_SFX(fit_run)(const struct fit_args *A, const double *z, const double *F, size_t n,
                                   fit_scratch *s, fit_res *o)
{
    FIT_SFX(mdr_contact) tip;
    FIT_SFX(mdr_fit_opts) opt;
    FIT_SFX(mdr_fit_result) r;
    FIT_T *zt, *Ft, *wk;
    size_t i;
    mdr_status st = FIT_SFX(fit_tip)(A, &tip);
    if (st != MDR_OK) {
        return st;
    }
    if (fit_scratch_grow(s, n, sizeof(FIT_T)) != 0) {
        return MDR_E_SIZE;
    }
    zt = (FIT_T *)s->buf;
    Ft = zt + n;
    wk = Ft + n;
    for (i = 0; i < n; i++) {
        zt[i] = (FIT_T)z[i];
        Ft[i] = (FIT_T)F[i];
    }
    FIT_SFX(mdr_fit_defaults)(&opt, (FIT_T)A->k_m);
    opt.z_e = (FIT_T)A->z_e;
    opt.E0 = (FIT_T)A->E0;
    opt.w0 = (FIT_T)A->w0;
    opt.method = A->method;
    opt.approach = A->approach ? 1u : 0u;
    opt.unpinned = A->unpinned ? 1u : 0u;
    opt.flat = A->flat ? 1u : 0u;
    st = FIT_SFX(mdr_fit_curve)(&tip, &opt, zt, Ft, (uint32_t)n, wk, MDR_FIT_WORK_LEN(n), &r);
    o->st = st;
    if (st != MDR_OK) {
        return st;
    }
    o->E = (double)r.E;
    o->w = (double)r.w;
    o->z0 = (double)r.z0;
    o->F_base = (double)r.F_base;
    o->E_err = (double)r.E_err;
    o->w_err = (double)r.w_err;
    o->z0_err = (double)r.z0_err;
    o->F_base_err = (double)r.F_base_err;
    o->F_slope = (double)r.F_slope;
    o->F_slope_err = (double)r.F_slope_err;
    o->rms = (double)r.rms;
    o->pull_off_F = (double)r.pull_off_F;
    o->pull_off_z = (double)r.pull_off_z;
    o->a_pull_off = (double)r.a_pull_off;
    o->mu = (double)r.mu;
    o->R_mu = (double)r.R_mu;
    o->w_adv = (double)r.w_adv;
    o->w_adv_err = (double)r.w_adv_err;
    o->n = r.n;
    o->n_approach = r.n_approach;
    o->n_pinned = r.n_pinned;
    o->iterations = r.iterations;
    o->regime = r.regime;
    o->method = r.method;
    return MDR_OK;
}
