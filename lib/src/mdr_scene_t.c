/*
 * mdr_scene_t.c: the table-free scene engine (mdr_scene_t.h), one
 * arithmetic per inclusion (after mdr_engine_t.c, whose material check,
 * Kahan sum and iteration cap it shares).
 *
 * g(x) = C x^n. In the scene's units (tau = sqrt(a/a_s), depths by
 * D_s = C a_s^n, u by the unit of its control) with q = tau^(2n-1):
 *   g = q tau,  G = q tau^3/(n+1),  dl = gamma tau            (4.19, 4.20)
 *   pinned:  d = (u + ka G)/(al + ka tau^2),  F = tau^2 d - G  (F = u: load)
 *   branch:  U(tau) = tau [al (q - gamma) + ka tau^2 (nu q - gamma)],
 *            nu = n/(n+1)
 *            U'(tau) = al (2n q - gamma) + ka tau^2 (2n q - 3 gamma)
 * with (al, ka) = (1, 0) fixed grips (u = d), (0, 1) fixed load
 * (u = F/(2E*)), (1, kap) machine (u = z). U' has one zero tau_f on
 * tau > 0 (the fold; at 0 when gamma = 0); U is increasing and convex on
 * [tau_f, inf) (U'' >= 0 there), so Newton from either side converges to
 * the stable root, from the right monotonically (the bracketed,
 * bisection-backed form of mdr_e_root, Numerical Recipes 9.4; mdr_s_root
 * bounds the iterations by MDR_ENG_ITER plus the doublings of its climb). The root is accepted within 4 eps of tau:
 * a relative error of 8 eps in a, below the rounding of the F and d it
 * gives. The fold of the retraction branch is found once at init for each
 * control. Below it U rises back to U(0) = 0, so a fold reached on
 * retraction is the pull-off (no landing: the profile is convex).
 */

#if MDR_CFG_SCENE /* to the end of the file */

/* The exponent n of g = C x^n: a build whose only scene profile is the
 * paraboloid (mdr_options.h) knows it is 2, and its powers and quotients
 * of n fold to constants. */
#if MDR_CFG_PROFILE_PARABOLOID && !MDR_CFG_PROFILE_CONE && !MDR_CFG_PROFILE_POWERLAW
#define MDR_S_N(n) ((void)(n), (uint8_t)2)
#else
#define MDR_S_N(n) (n)
#endif

/* A branch of the controlled variable: control constants and gamma. */
typedef struct {
    MDR_T al, ka, gam, nu, n2; /* n2 = 2n */
    uint8_t n;
} MDR_SFX(mdr_s_br);

/* tau^(2n-1) */
static MDR_STEP_FN MDR_T MDR_SFX(mdr_s_q)(uint8_t n, MDR_T tau)
{
    MDR_T q = tau, t2 = tau * tau;
    uint8_t i;
    for (i = 1; i < MDR_S_N(n); i++) {
        q *= t2;
    }
    return q;
}

/* U and U' at tau (see the top of this file). */
static MDR_STEP_FN MDR_T MDR_SFX(mdr_s_U)(const MDR_SFX(mdr_s_br) *b, MDR_T tau, MDR_T *dU)
{
    MDR_T q = MDR_SFX(mdr_s_q)(b->n, tau), t2 = tau * tau;
    *dU = b->al * (b->n2 * q - b->gam) + b->ka * t2 * (b->n2 * q - MDR_K(3.0) * b->gam);
    return tau * (b->al * (q - b->gam) + b->ka * t2 * (b->nu * q - b->gam));
}

/* The root of U(tau) = v above lo, where U(lo) < v and U is increasing
 * and convex from the fold on: Newton from `start`, bisection where Newton
 * leaves the bracket (lo, hi] or does not halve the residual. hi = 0: no
 * upper bound known yet (advancing edge): the iterate climbs by Newton
 * steps (which pass the root where U is convex) or, below the fold,
 * doublings, until U >= v gives one. MDR_OK; MDR_E_OVERFLOW when U stays
 * below v in the arithmetic's range; MDR_E_NOCONV at the cap. */
static MDR_STEP_FN mdr_status MDR_SFX(mdr_s_root)(const MDR_SFX(mdr_s_br) *b, MDR_T v, MDR_T lo,
                                                  MDR_T hi, MDR_T start, MDR_T *out)
{
    MDR_T t = start, fprev = MDR_MAXV;
    int it;
    for (it = 0; it < MDR_ENG_ITER + 2 * MDR_EXP_MAX; it++) {
        MDR_T dU, f = MDR_SFX(mdr_s_U)(b, t, &dU) - v, tn;
        if (f < MDR_K(0.0)) {
            lo = t;
        } else {
            hi = t;
        }
        tn = t - f / dU;
        if (!(hi > MDR_K(0.0))) { /* climbing */
            if (!(dU > MDR_K(0.0)) || !(tn > t)) { /* below the fold, or rounding */
                tn = t > MDR_K(0.0) ? MDR_K(2.0) * t : MDR_K(1.0);
            }
            if (!(tn <= MDR_MAXV)) {
                return MDR_E_OVERFLOW;
            }
            t = tn;
            continue;
        }
        if (f == MDR_K(0.0) || hi - lo <= MDR_K(4.0) * MDR_EPS * hi) {
            *out = hi;
            return MDR_OK;
        }
        if (!(dU > MDR_K(0.0)) || !(tn > lo && tn < hi) ||
            MDR_SFX(mdr_m_fabs)(f) > MDR_K(0.5) * MDR_SFX(mdr_m_fabs)(fprev)) {
            tn = MDR_K(0.5) * (lo + hi);
        } else if (MDR_SFX(mdr_m_fabs)(tn - t) <= MDR_K(2.0) * MDR_EPS * t) {
            *out = tn;
            return MDR_OK;
        }
        fprev = f;
        t = tn;
    }
    return MDR_E_NOCONV;
}

/* The branch of a control on the retraction (dir < 0) or approach side. */
static MDR_STEP_FN MDR_SFX(mdr_s_br) MDR_SFX(mdr_s_branch)(const MDR_SFX(mdr_scene) *s, MDR_T al,
                                                          MDR_T ka, int dir)
{
    MDR_SFX(mdr_s_br) b;
    b.al = al;
    b.ka = ka;
    b.gam = dir < 0 ? s->gw : s->ga;
    b.n = MDR_S_N(s->n);
    b.n2 = MDR_K(2.0) * (MDR_T)b.n;
    b.nu = (MDR_T)b.n / ((MDR_T)b.n + MDR_K(1.0));
    return b;
}

/* G = q tau^3/(n+1) at tau, from q = tau^(2n-1). */
static MDR_STEP_FN MDR_T MDR_SFX(mdr_s_G)(uint8_t n, MDR_T q, MDR_T tau)
{
    return q * tau * tau * tau / ((MDR_T)MDR_S_N(n) + MDR_K(1.0));
}

/* d and F of the pinned relation with the edge at tau and the control u;
 * returns q = tau^(2n-1) for the caller's branch tests. */
static MDR_STEP_FN MDR_T MDR_SFX(mdr_s_state)(const MDR_SFX(mdr_s_br) *b, MDR_T tau, MDR_T u, MDR_T *d,
                                              MDR_T *F)
{
    MDR_T q = MDR_SFX(mdr_s_q)(b->n, tau), t2 = tau * tau, G = MDR_SFX(mdr_s_G)(b->n, q, tau);
    *d = (u + b->ka * G) / (b->al + b->ka * t2);
    *F = b->al == MDR_K(0.0) ? u : t2 * *d - G;
    return q;
}

/* ------------------------------------------------------------------- init */

/* The fold of the retraction branch (al, ka): the zero of U' in (0, inf)
 * (U' < 0 below it, > 0 above), by doubling from 1 until U' > 0, then
 * bisection to the resolution of the arithmetic. */
static MDR_T MDR_SFX(mdr_s_fold)(const MDR_SFX(mdr_s_br) *b)
{
    MDR_T lo = MDR_K(0.0), hi = MDR_K(0.0), t = MDR_K(1.0), dU;
    int it;
    for (it = 0; it < 2 * MDR_EXP_MAX + MDR_ENG_ITER && b->gam > MDR_K(0.0); it++) {
        (void)MDR_SFX(mdr_s_U)(b, t, &dU);
        if (dU > MDR_K(0.0)) {
            hi = t;
        } else {
            lo = t;
        }
        t = hi > MDR_K(0.0) ? MDR_K(0.5) * (lo + hi) : MDR_K(2.0) * t;
        if (hi > MDR_K(0.0) && !(t > lo && t < hi)) {
            break;
        }
    }
    return hi;
}

/* Common init: g = C x^n, material checked by the caller's path. */
static mdr_status MDR_SFX(mdr_s_init)(MDR_SFX(mdr_scene) *s, MDR_T C, uint8_t n, MDR_T E, MDR_T w,
                                      MDR_T w_adv, MDR_T k_m, uint8_t outputs, MDR_SFX(mdr_energy) *en)
{
    MDR_SFX(mdr_scene) z;
    MDR_T cw, ca, ts = MDR_K(1.0);
    int i;
    mdr_status st;
    if (s == NULL) {
        return MDR_E_NULL;
    }
    st = MDR_SFX(mdr_e_material)(E, w, w_adv, k_m);
    if (st != MDR_OK) {
        return st;
    }
    if (outputs > MDR_OUT_ALL) {
        return MDR_E_PARAM;
    }
    if (!MDR_CFG_EVENTS && ((outputs & MDR_OUT_EVENTS) != 0u || en != NULL)) {
        return MDR_E_DISABLED;
    }
    cw = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w / E));
    ca = MDR_SQRT(MDR_K(2.0) * MDR_PI * (w_adv / E));
    /* a_s = ts^2, ts a power of two with ts^(2n-1) within a factor
     * P = 2^(2n-1) of c_w/C, so that gamma_w ~ 1 (exact doublings) */
    if (cw > MDR_K(0.0)) {
        MDR_T r = cw / C, P = MDR_SFX(mdr_s_q)(n, MDR_K(2.0));
        if (!(r > MDR_K(0.0)) || !MDR_SFX(mdr_m_isfinite)(r)) {
            return MDR_E_OVERFLOW;
        }
        while (r > P) {
            r /= P;
            ts *= MDR_K(2.0);
        }
        while (r * P < MDR_K(1.0)) {
            r *= P;
            ts *= MDR_K(0.5);
        }
    }
    z.as = ts * ts;
    z.Ds = C;
    for (i = 0; i < (int)MDR_S_N(n); i++) {
        z.Ds *= z.as;
    }
    z.Fs = MDR_K(2.0) * E * z.as * z.Ds;
    z.gw = cw * ts / z.Ds;
    z.ga = ca * ts / z.Ds;
    z.kap = k_m > MDR_K(0.0) ? MDR_K(2.0) * E * z.as / k_m : MDR_K(0.0);
    /* finite and > 0 (gw, ga >= 0): comparisons, false for NaN */
    if (!(z.as > MDR_K(0.0) && z.as <= MDR_MAXV) || !(z.Ds > MDR_K(0.0) && z.Ds <= MDR_MAXV) ||
        !(z.Fs > MDR_K(0.0) && z.Fs <= MDR_MAXV) || !(z.gw <= MDR_MAXV) || !(z.ga <= MDR_MAXV)) {
        return MDR_E_OVERFLOW;
    }
    if (!(z.kap <= MDR_MAXV)) {
        return MDR_E_CONTROL;
    }
    z.n = n;
    {
        static const MDR_T al[3] = {MDR_K(0.0), MDR_K(1.0), MDR_K(1.0)};
        const MDR_T ka[3] = {MDR_K(1.0), MDR_K(0.0), z.kap};
        for (i = 0; i < 3; i++) {
            MDR_SFX(mdr_s_br) b = MDR_SFX(mdr_s_branch)(&z, al[i], ka[i], -1);
            z.tf[i] = MDR_SFX(mdr_s_fold)(&b);
        }
    }
    z.tau = z.dh = MDR_K(0.0);
    z.en = en;
    z.outputs = outputs;
    z.contact = z.touched = z.flags = 0;
    if (MDR_CFG_EVENTS && en != NULL) {
        en->work = en->work_c = en->work_sep = en->dissipated = en->last_cycle = MDR_K(0.0);
        en->cycles = 0;
    }
    *s = z;
    return MDR_OK;
}

mdr_status MDR_SFX(mdr_scene_init_paraboloid)(MDR_SFX(mdr_scene) *s, MDR_T R, MDR_T E, MDR_T w,
                                              MDR_T w_adv, MDR_T k_m, uint8_t outputs,
                                              MDR_SFX(mdr_energy) *en)
{
    if (!MDR_SFX(mdr_m_isfinite)(R)) {
        return s == NULL ? MDR_E_NULL : MDR_E_NONFINITE;
    }
    if (!(R > MDR_K(0.0))) {
        return s == NULL ? MDR_E_NULL : MDR_E_PARAM;
    }
    if (!MDR_CFG_PROFILE_PARABOLOID) {
        return s == NULL ? MDR_E_NULL : MDR_E_DISABLED;
    }
    return MDR_SFX(mdr_s_init)(s, MDR_K(1.0) / R, 2, E, w, w_adv, k_m, outputs, en);
}

mdr_status MDR_SFX(mdr_scene_init_contact)(MDR_SFX(mdr_scene) *s, const MDR_SFX(mdr_contact) *c,
                                           MDR_T w_adv, MDR_T k_m, uint8_t outputs,
                                           MDR_SFX(mdr_energy) *en)
{
    if (c == NULL) {
        return MDR_E_NULL;
    }
    switch (c->kind) {
    case MDR_PROFILE_PARABOLOID:
        return MDR_SFX(mdr_s_init)(s, MDR_K(1.0) / c->k[0], 2, c->E, c->w, w_adv, k_m, outputs, en);
    case MDR_PROFILE_CONE:
        return MDR_SFX(mdr_s_init)(s, c->k[0], 1, c->E, c->w, w_adv, k_m, outputs, en);
    case MDR_PROFILE_POWERLAW:
        if (c->k[1] >= MDR_K(1.0) && c->k[1] == (MDR_T)(uint8_t)c->k[1]) {
            return MDR_SFX(mdr_s_init)(s, c->k[0], (uint8_t)c->k[1], c->E, c->w, w_adv, k_m, outputs,
                                       en);
        }
        return MDR_E_KIND;
    default:
        return MDR_E_KIND;
    }
}

/* ------------------------------------------------------------------- step */

/* Trapezoid of F dd into the energy sums (SI). */
static MDR_STEP_FN void MDR_SFX(mdr_s_work)(MDR_SFX(mdr_energy) *en, MDR_T d0, MDR_T F0, MDR_T d1, MDR_T F1)
{
    MDR_SFX(mdr_e_kahan)(&en->work, &en->work_c, MDR_K(0.5) * (F0 + F1) * (d1 - d0));
}

/* A refused step: the state is left as it was; an iteration cap is
 * remembered in the sticky flags. */
static MDR_STEP_FN mdr_status MDR_SFX(mdr_s_refuse)(MDR_SFX(mdr_scene) *s, mdr_status st)
{
    if (st == MDR_E_NOCONV) {
        s->flags |= MDR_FLAG_NOCONV;
    }
    return st;
}

/* One step with the control u (scene units) under (al, ka); ctl indexes
 * tf[] (0 load, 1 grips, 2 machine). */
static MDR_STEP_FN mdr_status MDR_SFX(mdr_s_step)(MDR_SFX(mdr_scene) *s, int ctl, MDR_T al, MDR_T ka,
                                                  MDR_T u, MDR_SFX(mdr_step) *out)
{
    MDR_SFX(mdr_scene) z = *s; /* a refused step changes nothing */
    MDR_SFX(mdr_energy) en = {MDR_K(0.0), MDR_K(0.0), MDR_K(0.0), MDR_K(0.0), MDR_K(0.0), 0u};
    /* constant false without MDR_CFG_EVENTS: their code is not built */
    const bool ev = MDR_CFG_EVENTS && (z.outputs & MDR_OUT_EVENTS) != 0u;
    const bool wk = MDR_CFG_EVENTS && z.en != NULL;
    MDR_T d = MDR_K(0.0), F = MDR_K(0.0), dprev, Fprev;
    MDR_T a0 = MDR_K(0.0), d0 = MDR_K(0.0), F0 = MDR_K(0.0), a1 = MDR_K(0.0), d1 = MDR_K(0.0), F1 = MDR_K(0.0);
    uint8_t event = MDR_EV_NONE, jumps = 0;
    int dir = 0;
    mdr_status st;
    const bool from_sep = !z.contact;
    MDR_SFX(mdr_s_br) b = MDR_SFX(mdr_s_branch)(&z, al, ka, 1);

    if (wk) {
        en = *z.en;
    }
    /* the previous state (energy; its force only when the energy is kept) */
    dprev = z.dh;
    Fprev = MDR_K(0.0);
    if (z.contact) {
        MDR_T q = MDR_SFX(mdr_s_state)(&b, z.tau, u, &d, &F);
        if (wk) {
            Fprev = z.tau * z.tau * z.dh - MDR_SFX(mdr_s_G)(z.n, q, z.tau);
        }
        if (d > z.tau * (q - z.ga)) {
            dir = 1;
        } else if (d < z.tau * (q - z.gw)) {
            dir = -1;
        }
    } else if (u > MDR_K(0.0)) {
        dir = 1;
        dprev = Fprev = MDR_K(0.0); /* the touch point */
    }

    if (dir > 0) { /* advance on the approach branch */
        MDR_T dU, U0 = MDR_SFX(mdr_s_U)(&b, z.tau, &dU), t;
        if (!(dU > MDR_K(0.0)) && b.gam > MDR_K(0.0)) {
            /* on the unstable side of the approach fold (the touch point
             * of an adhesive approach): jump at constant U0 to the stable
             * branch (jump-in) */
            MDR_T tol = MDR_K(8.0) * MDR_EPS * (MDR_SFX(mdr_m_fabs)(U0) + MDR_MINV), dl, Fl;
            st = MDR_SFX(mdr_s_root)(&b, U0 + tol, z.tau, MDR_K(0.0), z.tau, &t);
            if (st != MDR_OK) {
                return MDR_SFX(mdr_s_refuse)(s, st);
            }
            if (ev || wk) { /* the states before and after the jump */
                if (z.contact) {
                    MDR_SFX(mdr_s_state)(&b, z.tau, U0, &d0, &F0);
                }
                a0 = z.tau;
                MDR_SFX(mdr_s_state)(&b, t, U0, &dl, &Fl);
                if (wk) {
                    MDR_SFX(mdr_s_work)(&en, dprev * z.Ds, Fprev * z.Fs, d0 * z.Ds, F0 * z.Fs);
                    MDR_SFX(mdr_s_work)(&en, d0 * z.Ds, F0 * z.Fs, dl * z.Ds, Fl * z.Fs);
                }
                a1 = t;
                d1 = dl;
                F1 = Fl;
                dprev = dl;
                Fprev = Fl;
            }
            event = from_sep ? MDR_EV_JUMP_IN : MDR_EV_JUMP;
            jumps = 1;
            z.tau = t;
            U0 = MDR_SFX(mdr_s_U)(&b, t, &dU);
        }
        if (U0 < u) {
            st = MDR_SFX(mdr_s_root)(&b, u, z.tau, MDR_K(0.0), z.tau, &t);
            if (st != MDR_OK) {
                return MDR_SFX(mdr_s_refuse)(s, st); /* MDR_E_OVERFLOW: the edge would leave the range */
            }
            z.tau = t;
        }
        z.contact = 1;
    } else if (dir < 0) { /* recede on the retraction branch */
        MDR_T tf = z.tf[ctl], dU, t;
        b.gam = z.gw;
        if (z.tau > tf && MDR_SFX(mdr_s_U)(&b, tf, &dU) < u) {
            st = MDR_SFX(mdr_s_root)(&b, u, tf, z.tau, z.tau, &t);
            if (st != MDR_OK) {
                return MDR_SFX(mdr_s_refuse)(s, st);
            }
            z.tau = t;
        } else if (b.gam == MDR_K(0.0)) {
            /* no adhesion: the contact shrinks smoothly to a = 0 */
            event = MDR_EV_SEPARATION;
            z.contact = 0;
        } else {
            /* the fold (or the edge itself, if past it): pull-off */
            MDR_T tp = z.tau < tf ? z.tau : tf;
            MDR_T uf = MDR_SFX(mdr_s_U)(&b, tp, &dU);
            MDR_SFX(mdr_s_state)(&b, tp, uf, &d0, &F0);
            a0 = tp;
            d1 = al != MDR_K(0.0) ? uf : d0;
            if (wk) {
                MDR_SFX(mdr_s_work)(&en, dprev * z.Ds, Fprev * z.Fs, d0 * z.Ds, F0 * z.Fs);
                MDR_SFX(mdr_s_work)(&en, d0 * z.Ds, F0 * z.Fs, d1 * z.Ds, MDR_K(0.0));
            }
            dprev = d1;
            Fprev = MDR_K(0.0);
            event = MDR_EV_PULL_OFF;
            jumps = 1;
            z.contact = 0;
        }
    }

    if (z.contact) {
        if (dir != 0) {
            MDR_SFX(mdr_s_state)(&b, z.tau, u, &d, &F);
        }
        if (from_sep && jumps == 0) {
            event = z.touched ? MDR_EV_RECONTACT : MDR_EV_CONTACT;
        }
        z.touched = 1;
        if (wk) {
            MDR_SFX(mdr_s_work)(&en, dprev * z.Ds, Fprev * z.Fs, d * z.Ds, F * z.Fs);
        }
    } else {
        F = MDR_K(0.0);
        d = al != MDR_K(0.0) ? u : event == MDR_EV_PULL_OFF ? dprev : event == MDR_EV_SEPARATION ? MDR_K(0.0) : z.dh;
        z.tau = MDR_K(0.0);
        if (wk && event == MDR_EV_SEPARATION) {
            MDR_SFX(mdr_s_work)(&en, dprev * z.Ds, Fprev * z.Fs, MDR_K(0.0), MDR_K(0.0));
        }
    }
    if (wk && !z.contact && s->contact) { /* a cycle ends */
        MDR_T w0 = en.work - en.work_c;
        en.last_cycle = w0 - en.work_sep;
        en.work_sep = w0;
        en.dissipated += en.last_cycle;
        en.cycles++;
    }
    z.dh = d;
    d *= z.Ds;
    F *= z.Fs;
    if (!MDR_SFX(mdr_m_isfinite)(d) || !MDR_SFX(mdr_m_isfinite)(F) ||
        (wk && (!MDR_SFX(mdr_m_isfinite)(en.work) || !MDR_SFX(mdr_m_isfinite)(en.dissipated)))) {
        return MDR_E_OVERFLOW;
    }
    out->d = d;
    out->F = F;
    if ((z.outputs & MDR_OUT_RADIUS) != 0u) {
        out->a = z.tau * z.tau * z.as;
    }
    if (ev) {
        out->z = z.kap > MDR_K(0.0) ? (z.dh + z.kap * F / z.Fs) * z.Ds : d;
        out->event = event;
        out->jumps = jumps;
        if (jumps == 0) {
            out->a0 = out->a1 = z.tau * z.tau * z.as;
            out->d0 = out->d1 = d;
            out->F0 = out->F1 = F;
        } else {
            out->a0 = a0 * a0 * z.as;
            out->d0 = d0 * z.Ds;
            out->F0 = F0 * z.Fs;
            out->a1 = a1 * a1 * z.as;
            out->d1 = d1 * z.Ds;
            out->F1 = F1 * z.Fs;
        }
    }
    if (wk) {
        *z.en = en;
    }
    *s = z;
    return MDR_OK;
}

MDR_STEP_FN mdr_status MDR_SFX(mdr_scene_step_d)(MDR_SFX(mdr_scene) *s, MDR_T d, MDR_SFX(mdr_step) *out)
{
    if (s == NULL || out == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_m_isfinite)(d)) {
        return MDR_E_NONFINITE;
    }
    return MDR_SFX(mdr_s_step)(s, 1, MDR_K(1.0), MDR_K(0.0), d / s->Ds, out);
}

MDR_STEP_FN mdr_status MDR_SFX(mdr_scene_step_F)(MDR_SFX(mdr_scene) *s, MDR_T F, MDR_SFX(mdr_step) *out)
{
    if (s == NULL || out == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_m_isfinite)(F)) {
        return MDR_E_NONFINITE;
    }
    return MDR_SFX(mdr_s_step)(s, 0, MDR_K(0.0), MDR_K(1.0), F / s->Fs, out);
}

MDR_STEP_FN mdr_status MDR_SFX(mdr_scene_step_z)(MDR_SFX(mdr_scene) *s, MDR_T z, MDR_SFX(mdr_step) *out)
{
    if (s == NULL || out == NULL) {
        return MDR_E_NULL;
    }
    if (!MDR_SFX(mdr_m_isfinite)(z)) {
        return MDR_E_NONFINITE;
    }
    if (!(s->kap > MDR_K(0.0))) {
        return MDR_E_CONTROL;
    }
    return MDR_SFX(mdr_s_step)(s, 2, MDR_K(1.0), s->kap, z / s->Ds, out);
}
#endif /* MDR_CFG_SCENE */
