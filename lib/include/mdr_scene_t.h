/* SPDX-License-Identifier: MIT */
/*
 * mdr_scene_t.h: declarations of one arithmetic of the table-free scene
 * engine. Included by mdr_scene.h once per arithmetic (MDR_T, MDR_SFX
 * defined); read it with T = float and suffix _f32.
 *
 * A scene is a profile whose equivalent profile is a monomial,
 * g(x) = C x^n with integer n (paraboloid n = 2, C = 1/R; cone n = 1,
 * C = (pi/2) tan(theta); power law C r^n with integer n, C = kappa_n C),
 * stepped like the spring engine (same state machine, events, energy,
 * mdr_engine_t.h) with no table: in t = sqrt(a) every branch U(t) of the
 * controlled variable is a polynomial, convex where the edge is stable, so
 * the step is a Newton solve from where the edge was, and the fold of the
 * retraction branch under each control is found once, at init. 0 bytes of
 * spring storage; the instance is the whole state.
 *
 * Units inside the instance are normalised by powers of two chosen at init
 * (exact scaling: no rounding, no overflow for any scene whose results fit
 * the arithmetic): radius a_s, depth D_s = C a_s^n, force 2E* a_s D_s;
 * a_s near the adhesive length where c_w sqrt(a) ~ g(a), without adhesion
 * (w = 0, n >= 2) near the profile's own length where g(a) ~ a (the
 * paraboloid's R), the cone's 1 m.
 *
 * Outputs (the `outputs` argument of init, MDR_OUT_* bits): the step always
 * solves for d and F and writes out->d and out->F; MDR_OUT_RADIUS adds
 * out->a, MDR_OUT_EVENTS adds out->z, out->event, out->jumps and the states
 * before and after a jump (a0, d0, F0, a1, d1, F1). Fields not asked for are
 * not written. Energy (work, dissipated energy per cycle) is kept only in a
 * caller-owned mdr_energy_<type> (mdr_engine_t.h) given to init (NULL: not
 * computed).
 */

/** A table-free scene. Caller-owned; fill it with an mdr_scene_init_*()
 *  function only, then read it freely and change it only through the step
 *  functions. Its energy bookkeeping is the mdr_energy_<type> of
 *  mdr_engine_t.h, caller-owned and optional, held by pointer: a struct
 *  copy of a scene shares it with the original (both count their cycles
 *  into it), so give a copy that steps on its own an init of its own (or
 *  none); the spring engine embeds its energy and copies it. */
typedef struct {
    MDR_T Ds;      /**< depth unit D_s = C a_s^n [m] */
    MDR_T Fs;      /**< force unit 2 E* a_s D_s [N] */
    MDR_T as;      /**< radius unit a_s [m] (a power of two) */
    MDR_T iDs, iFs; /**< 1/D_s, 1/F_s */
    MDR_T FsDs;    /**< F_s/D_s */
    MDR_T gw;      /**< dl_w(a)/D_s at a = a_s: sqrt(2 pi w a_s/E*)/D_s */
    MDR_T ga;      /**< the same with w_adv */
    MDR_T kap;     /**< 2E* a_s/k_m, 0 without a machine */
    MDR_T z_min;   /**< the least z [m] a separated step_z answers without its full tick:
                        minus the largest finite value of the type with a machine, the largest
                        without one (no z qualifies) */
    MDR_T tlo;     /**< the least edge tau a contact may have where F_s > 1 N or D_s > 1 m:
                        tau^(2n+2) (F's scale) at least 2^(2n+2) times the smallest normal
                        value of the type (a smaller edge, a contact absurdly small against
                        a_s, is refused: MDR_E_OVERFLOW); 0 with smaller units (below that
                        edge d and F keep an absolute floor of 2^(2n+2) FLT_MIN (f32) in m
                        and N) */
    MDR_T tf[3];   /**< sqrt(a_fold/a_s) of the retraction branch: load, grips, machine (without
                        adhesion, tlo: the contact ends at u = 0, and a control between 0 and
                        that of tlo is refused) */
    MDR_T uf[3];   /**< the control at that fold, in scene units (below it: pull-off) */
    MDR_T nu;      /**< n/(n+1) */
    MDR_T in1;     /**< 1/(n+1) */
    MDR_T bD, bF;  /**< (gw - ga) D_s, (gw - ga) F_s: the pinned band's width per tau [m], [N] */
    MDR_T GD, GF;  /**< D_s/(n+1), F_s/(n+1): G's scale [m], [N] */
    MDR_T tau;     /**< edge: sqrt(a/a_s); 0 when separated */
    MDR_T d, F;    /**< indentation [m], force [N] after the last step */
    MDR_SFX(mdr_pinned) pin; /**< the pinned edge for control mode `mode` (mdr_engine_t.h) */
    MDR_SFX(mdr_energy) *en; /**< energy bookkeeping, or NULL */
    uint8_t n;       /**< exponent of g = C x^n, 1..MDR_POWERLAW_N_MAX */
    uint8_t outputs; /**< MDR_OUT_* of init, with MDR_OUT_ENERGY when en is kept */
    uint8_t mode;    /**< control mode (MDR_CONTROL_*) of the pinned edge, bit 7 set while a move has left its linear coefficients (pin) to the next pinned tick; 0 exactly when separated */
    uint8_t contact; /**< 1 in contact, 0 separated */
    uint8_t touched; /**< 1 once the scene has been in contact */
    uint8_t flags;   /**< sticky MDR_FLAG_* (MDR_FLAG_NOCONV) */
    MDR_T mv_c, mv_d; /**< internal: where the step's last fast move began (the edge's
                           coordinate in the engine's units, d [m]), for its work (MDR_OUT_ENERGY) */
} MDR_SFX(mdr_scene);

#if MDR_CFG_SCENE
/**
 * @brief A paraboloid scene, f = r^2/(2R), g = x^2/R (eq. 4.28), table-free.
 *        Links nothing of the other profiles.
 * @param[out] s      instance; untouched unless MDR_OK
 * @param[in]  R      radius [m], finite > 0
 * @param[in]  E      E* > 0 [Pa]
 * @param[in]  w      work of adhesion on retraction, w >= 0 [J/m^2]
 * @param[in]  w_adv  on approach, 0 <= w_adv <= w [J/m^2]
 * @param[in]  k_m    machine stiffness [N/m], finite > 0, or 0 for none
 * @param[in]  outputs MDR_OUT_* bits (MDR_OUT_FORCE = 0: F and d only)
 * @param[in]  en     energy bookkeeping to keep (zeroed here), or NULL
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_PARAM (R, E, w, w_adv,
 *         outputs), MDR_E_CONTROL (k_m < 0, or (2 E*) / k_m or 1/k_m not finite),
 *         MDR_E_OVERFLOW (the scene's units leave the arithmetic's range),
 *         MDR_E_DISABLED (MDR_OUT_EVENTS or an energy struct in a build
 *         without MDR_CFG_EVENTS; the paraboloid removed: mdr_options.h)
 */
mdr_status MDR_SFX(mdr_scene_init_paraboloid)(MDR_SFX(mdr_scene) *s, MDR_T R, MDR_T E, MDR_T w,
                                              MDR_T w_adv, MDR_T k_m, uint8_t outputs,
                                              MDR_SFX(mdr_energy) *en);

/**
 * @brief A scene from an initialised contact whose g is a monomial: the
 *        paraboloid, the cone, a power law with integer n (w from the
 *        contact). Other profiles need a spring table (mdr_engine_t.h):
 *        MDR_E_KIND.
 * @param[out] s  the scene; untouched unless MDR_OK
 * @param[in] c  an initialised contact (mdr_contact_init_<type>())
 * @param[in] w_adv  work of adhesion on approach, 0 <= w_adv <= w [J/m^2]
 * @param[in] k_m    machine stiffness [N/m], 0 for none
 * @param[in] outputs  MDR_OUT_* groups the steps compute
 * @param[in] en     energy bookkeeping to keep (zeroed here), or NULL
 * @return as mdr_scene_init_paraboloid(); MDR_E_KIND for profiles without a
 *         table-free path
 */
mdr_status MDR_SFX(mdr_scene_init_contact)(MDR_SFX(mdr_scene) *s, const MDR_SFX(mdr_contact) *c,
                                           MDR_T w_adv, MDR_T k_m, uint8_t outputs,
                                           MDR_SFX(mdr_energy) *en);

/**
 * @brief One control tick with the indentation d [m] held (fixed grips).
 * @param[in,out] s  the scene; unchanged unless MDR_OK (but for its sticky flags)
 * @param[in]  d    indentation [m], finite
 * @param[out] out  what happened; only the fields of s->outputs are written
 *                  (d and F always), and only on MDR_OK
 * @return MDR_OK; MDR_E_NULL, MDR_E_NONFINITE; MDR_E_OVERFLOW (a result or
 *         energy sum would leave the arithmetic's range, or the contact
 *         would be too small against a_s for it (tau below tlo): state
 *         unchanged);
 *         MDR_E_NOCONV (not expected: bisection backs every iteration;
 *         state unchanged, MDR_FLAG_NOCONV set)
 *
 * Cost: pinned edge, a few products (under load and through a machine the
 * first pinned tick after a move computes the pinned relation once: a few
 * divisions); moving edge, a Newton solve of a polynomial in t from the
 * tangent at the edge (usually one evaluation; one evaluation is about
 * 2n + 10 flops); no sqrt, log or table access.
 */
mdr_status MDR_SFX(mdr_scene_step_d)(MDR_SFX(mdr_scene) *s, MDR_T d, MDR_SFX(mdr_step) *out);

/** @brief One tick with the force F [N] held (fixed load); see step_d().
 *  While separated out->F = 0 and d keeps the depth at which contact was
 *  lost. */
mdr_status MDR_SFX(mdr_scene_step_F)(MDR_SFX(mdr_scene) *s, MDR_T F, MDR_SFX(mdr_step) *out);

/** @brief One tick with the base position z = d + F/k_m [m] held; see
 *  step_d(). MDR_E_CONTROL when the scene has no machine (k_m = 0). */
mdr_status MDR_SFX(mdr_scene_step_z)(MDR_SFX(mdr_scene) *s, MDR_T z, MDR_SFX(mdr_step) *out);

/** @brief Clear the sticky flags; returns the flags that were set (0 for a
 *  NULL scene). */
uint8_t MDR_SFX(mdr_scene_clear_flags)(MDR_SFX(mdr_scene) *s);
#endif /* MDR_CFG_SCENE */
