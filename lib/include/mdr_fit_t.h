/* SPDX-License-Identifier: MIT */
/*
 * mdr_fit_t.h: declarations of one arithmetic of the fit module.
 *
 * Not a header to include directly: mdr_fit.h includes it once per
 * arithmetic with MDR_T (float or double) and MDR_SFX(name) defined. Read it
 * with T = float and suffix _f32.
 *
 * The measurement. A force curve (z_i, F_i) in time order: z the base
 * (piezo) position [m], increasing toward the sample; F the force [N] read
 * from the cantilever of stiffness k_m, compressive positive (k_m times the
 * deflection). The curve may hold the approach and the retract; the retract
 * is the part from the largest z on (from its last occurrence).
 *
 * The model (quasi-static, the one the engines follow). The tip (any profile
 * of the contact module) touches the sample at base position z0 with zero
 * force; the model's base position is z' = z - z0 and the contact obeys
 *     z' = d(a) + F(a)/k_m                  (machine of stiffness k_m)
 * with d(a), F(a) the equilibrium of mdr_eq_<type>(). On the retract the
 * contact shrinks along the stable branch (dz'/da > 0) until the fold
 * (dz'/da = 0, found by mdr_critical_<type>() under MDR_CONTROL_MACHINE),
 * then jumps off to F = 0. On the approach (work of adhesion w_adv) the tip
 * touches at z' = 0 and (w_adv > 0) jumps in to the stable branch. The
 * measured force is the model's plus a baseline: F_i = F_model(z_i - z0) +
 * F_b. A retract that starts pinned (w_adv < w: the contact radius held at
 * the approach's largest while the force falls along a straight line, until
 * it meets the receding branch) is fitted from below that part, which the
 * fit finds and leaves out (n_pinned; docs/fitting.md says how, and what it
 * cannot find: a retract pinned all the way to its rupture).
 *
 * Not fitted by this model: profiles whose retract jumps to a smaller
 * stable contact before the pull-off (the wavy profile where it does:
 * MDR_E_JUMPS) and the flat punch (its contact stays pinned at the rim
 * until it ruptures, so there is no equilibrium branch to follow:
 * MDR_E_KIND; its pull-off is Kendall's closed form).
 */

/** Options of a fit; fill with mdr_fit_defaults_<type>() and change fields. */
typedef struct {
    MDR_T k_m;     /**< cantilever (machine) stiffness [N/m], finite > 0 */
    MDR_T z_e;     /**< equilibrium distance of the Tabor parameter [m], > 0
                        (default MDR_FIT_Z_E_DEFAULT) */
    MDR_T E0, w0;  /**< first guesses of E* [Pa] and w [J/m^2]; both > 0 to use
                        them (MDR_FIT_TWO_POINT: where its search starts),
                        both 0 (default) for the two-point guess */
    uint8_t method;   /**< MDR_FIT_FULL (default) or MDR_FIT_TWO_POINT */
    uint8_t approach; /**< 1: also fit w_adv to the approach part (E*, z0, F_b
                           held at the retract's values); default 0 */
    uint8_t unpinned; /**< 1: the caller knows the retract recedes from its top
                           (no adhesion hysteresis: w_adv = w, no pinned top):
                           no pinned top is looked for, every retract sample
                           is fitted (n_pinned = 0), and a retract straight
                           within its noise to the pull-off is fitted as a
                           receding branch instead of refused as one a pinned
                           top could hide in (MDR_E_PINNED; a line that
                           explains it better than the branch is still
                           refused); MDR_FIT_TWO_POINT: a retract straight
                           past its zero-force point is answered; default 0 */
    uint8_t flat;     /**< 1: the caller knows the force baseline is flat (its
                           slope subtracted): F_slope held at 0, one parameter
                           fewer; default 0: the baseline F_base + F_slope
                           (z - z0) is fitted, slope and all (an interferometric
                           or virtual-deflection tilt, as raw AFM data carry) */
} MDR_SFX(mdr_fit_opts);

/** Result of a fit (SI). */
typedef struct {
    MDR_T E;          /**< effective modulus E* [Pa] */
    MDR_T w;          /**< work of adhesion w of the retract [J/m^2] */
    MDR_T z0;         /**< base position of first touch at zero force [m] */
    MDR_T F_base;     /**< force baseline at z0 [N]: the baseline is
                           F_base + F_slope (z - z0) */
    MDR_T E_err, w_err, z0_err, F_base_err; /**< one standard error each, from
                           the Jacobian at the result: s^2 (J^T J)^-1, s^2 = sum
                           of squared residuals/(n-5) (n-4 with opts->flat), with the fold's position
                           between the last contact and the first free sample
                           as a nuisance of at most that interval's spread, and
                           that spread where the result is no minimum in the
                           fold's position, and (f64) where z was written
                           to a unit, z's scale within a unit over the
                           contact's span (mdr_fit.inc, docs/fitting.md);
                           MDR_FIT_TWO_POINT: its two measurements' noise and
                           rounding and the step from the last contact sample
                           to the fold, propagated through the method */
    MDR_T rms;        /**< root mean square residual force over the n points [N] */
    MDR_T pull_off_F; /**< the model's pull-off force (at the fold), relative to
                           the baseline [N] (negative) */
    MDR_T pull_off_z; /**< base position of the model's pull-off, z0 + z'_fold [m] */
    MDR_T a_pull_off; /**< contact radius at the model's pull-off [m] */
    MDR_T mu;         /**< Tabor parameter (R w^2/(E*^2 z_e^3))^(1/3) */
    MDR_T R_mu;       /**< the tip radius R used in mu [m] (see mdr_tabor_<type>()) */
    MDR_T w_adv;      /**< work of adhesion of the approach [J/m^2] (n_approach > 0) */
    MDR_T w_adv_err;  /**< its standard error [J/m^2], the error of the
                           retract's answer the approach's fit holds (E*,
                           z0, the baseline) included */
    MDR_T F_slope;    /**< slope of the force baseline dF_b/dz [N/m]: fitted;
                           0 with opts->flat; MDR_FIT_TWO_POINT: the free
                           part's least-squares slope (0 where that line does
                           not reach the retract's top within two noise
                           widths, or with opts->flat) */
    MDR_T F_slope_err; /**< its standard error [N/m] (0 where it is 0 by the
                           rules above) */
    uint32_t n;          /**< retract points used */
    uint32_t n_approach; /**< approach points used for w_adv (0: not fitted) */
    uint32_t n_pinned;   /**< samples at the top of the retract left out as its pinned
                              part (w_adv < w: the contact radius held until the force
                              meets the receding branch; mdr_fit_curve_<type>()) */
    uint16_t iterations; /**< Levenberg-Marquardt iterations (0 for two-point) */
    uint8_t method;      /**< MDR_FIT_FULL or MDR_FIT_TWO_POINT */
    uint8_t regime;      /**< MDR_REGIME_JKR, _TRANSITION or _DMT */
} MDR_SFX(mdr_fit_result);

/**
 * @brief Default options: the given k_m, z_e = MDR_FIT_Z_E_DEFAULT, no first
 *        guess (two-point), MDR_FIT_FULL, no approach fit, the pinned top
 *        looked for, the baseline's slope fitted.
 * @param[out] o    filled (no check of k_m: mdr_fit_curve_<type>() checks it)
 * @param[in]  k_m  machine (cantilever) stiffness [N/m], copied into o->k_m
 */
void MDR_SFX(mdr_fit_defaults)(MDR_SFX(mdr_fit_opts) *o, MDR_T k_m);

/**
 * @brief Fit E*, w, z0 and the baseline F_b + F_slope (z - z0) to a measured
 *        force curve.
 *
 * Steps: (1) the curve is checked and read: the retract from the largest z,
 * its pull-off (the largest rise of F after the force minimum, followed by at
 * least MDR_FIT_MIN_FREE free points), the baseline (mean of the free
 * points) and the noise (from their successive differences, leaving out
 * those beyond 6 of their standard deviation: a tether's step or a glitch
 * in the free tail is no noise, and its samples are then the model's
 * misfit), the zero-force point. (2) First guess, and the whole answer of MDR_FIT_TWO_POINT: the
 * two-point method (E*, w such that the model's fold force under k_m is the
 * measured pull-off force and the depth d = z - F/k_m between the zero-force
 * point and the pull-off is the measured one; exact for the model with the
 * given k_m and any profile; z0 from the zero-force point, F_b the
 * baseline), or opts->E0, w0. (3) MDR_FIT_FULL: Levenberg-Marquardt over
 * every retract point in (ln E*, ln w, z0, F_b, F_slope; F_slope held at 0
 * with opts->flat), analytic Jacobian,
 * Marquardt scaling, at most MDR_FIT_ITER_MAX iterations. (4) Standard
 * errors, the model's pull-off, the Tabor parameter and the regime.
 * MDR_FIT_FULL answers only where the model reproduces the curve (rms
 * residual at most MDR_FIT_NOISE_SIGMAS noise widths plus
 * MDR_FIT_MISFIT_REL of the largest retract force, else MDR_E_MISFIT) and
 * the data determine E* and w (relative standard errors below 1, and for
 * E* the sum of squares' profile bounding it within a factor 20, else
 * MDR_E_DEGENERATE): a minimum Levenberg-Marquardt converges to from a
 * poor first guess, z not in metres, or E* run off toward the rigid limit
 * is refused, never answered. (5) opts->approach: w_adv >= 0 fitted to
 * the approach points.
 *
 * @param[in]  tip   the profile, from mdr_contact_init_<type>() (its E* and w
 *                   are not used); every kind but the flat punch
 * @param[in]  opts  options (mdr_fit_defaults_<type>())
 * @param[in]  z,F   n samples in time order [m], [N] (see above)
 * @param[in]  n     number of samples
 * @param      work  caller's workspace of work_len >= MDR_FIT_WORK_LEN(n)
 *                   elements (contents on return unspecified)
 * @param[in]  work_len  number of elements of work
 * @param[out] out   written only on MDR_OK
 * @return MDR_OK;
 *   bad arguments: MDR_E_NULL, MDR_E_NONFINITE (a NaN or infinite sample or
 *   option), MDR_E_PARAM (k_m, z_e, E0/w0, method, approach, unpinned or
 *   flat out of range),
 *   MDR_E_KIND (flat punch), MDR_E_SIZE (work_len too small, or n beyond
 *   UINT32_MAX/2);
 *   curves the fit cannot read: MDR_E_FEW (fewer than MDR_FIT_MIN_POINTS
 *   retract points, or fewer than MDR_FIT_MIN_CONTACT in contact, or, the
 *   full fit past a pinned top, fewer than MDR_FIT_MIN_RECEDE receding
 *   points in contact after it, or, where the retract's straight start
 *   leaves fewer, the retract fitted from its top missing the samples),
 *   or, with opts->approach, fewer than
 *   MDR_FIT_MIN_POINTS approach points),
 *   MDR_E_ORDER (the samples not in time order: z not monotonic within
 *   the retract, or within the approach when it is fitted; z rising to the
 *   last sample, no retract: an approach alone, or a retract reversed; the
 *   approach in contact (a force off the baseline by 6 noise widths and a
 *   tenth of the pull-off force) a sampling step or more below the
 *   retract's last contact sample, though the fold lies below first touch:
 *   the curve reversed; docs/fitting.md),
 *   MDR_E_NOCONTACT (no retract force above the baseline
 *   by more than the noise), MDR_E_NOPULLOFF (the curve never separates: no
 *   pull-off jump above the noise followed by MDR_FIT_MIN_FREE free points,
 *   or no adhesion);
 *   fits that fail: MDR_E_FITCAP (iteration cap, or a pinned top's end not
 *   settled in 8 refits), MDR_E_DEGENERATE (the
 *   data do not determine the parameters: singular equations (also the
 *   approach's, opts->approach: no error of w_adv), or a
 *   relative standard error of E* or w of 1 or more, or (full fit, E*'s
 *   above 0.1) a profile of the sum of squares in ln E* that does not rise
 *   by 3 errors within a factor 20 either way; or the two-point
 *   equations have no solution, for MDR_FIT_TWO_POINT also not 3 noise
 *   errors from its measurements, or its noise alone gives ln E* an error
 *   above 0.5), MDR_E_MISFIT (the full fit: the
 *   fitted model does not reproduce the curve, its rms residual beyond
 *   MDR_FIT_NOISE_SIGMAS noise widths plus MDR_FIT_MISFIT_REL of the
 *   force scale; or the retract's adhesive end, its contact samples at or
 *   below the baseline, not met within its noise by the model's square-root
 *   approach to the fold: a pull-off that is no fold, as the end of an
 *   approach passed in reversed time order; either method: the retract's
 *   free part next to the pull-off off its line (the sum of its first m
 *   residuals beyond MDR_FIT_NOISE_SIGMAS noise widths times sqrt(m),
 *   m = 1, 2, 4, ...: a long-range attraction after the jump); the approach
 *   leaving the baseline a sampling step or more below the retract's last
 *   contact sample, where the model holds it free: drift, a glitch,
 *   correlated noise, or a curve reversed; opts->approach: the approach's
 *   free part curved beyond its noise where it gets its own baseline
 *   (an offset off the free tail's, or a slope that disagrees with it): a
 *   baseline the model's line does not describe; docs/fitting.md),
 *   MDR_E_JUMPS (the retract jumps before the pull-off),
 *   MDR_E_PINNED (the full fit: the retract straight to its pull-off
 *   and a line explains it better than the receding branch: a contact
 *   pinned until it ruptures; or, in noisy data, straight within its noise
 *   to the pull-off, or from its top to fewer than MDR_FIT_MIN_RECEDE
 *   samples above it, where a pinned top could hide, and neither
 *   opts->unpinned nor the approach (opts->approach: w_adv within
 *   MDR_FIT_NOISE_SIGMAS reported errors of w) rules it out;
 *   MDR_FIT_TWO_POINT: the retract straight within its noise from its top
 *   to past its zero-force point, which a pinned top would move, and
 *   neither rules it out; docs/fitting.md),
 *   MDR_E_RADIUS (the indentation needs a contact beyond the profile's
 *   domain, e.g. a >= R of the sphere), MDR_E_NOCONV, MDR_E_OVERFLOW (from
 *   the contact module).
 */
mdr_status MDR_SFX(mdr_fit_curve)(const MDR_SFX(mdr_contact) *tip, const MDR_SFX(mdr_fit_opts) *opts,
                                  const MDR_T *z, const MDR_T *F, uint32_t n, MDR_T *work,
                                  size_t work_len, MDR_SFX(mdr_fit_result) *out);

/**
 * @brief The model force curve at given parameters (the forward model the fit
 *        uses): F_out[i] = F_model(z[i] - z0) + F_b.
 * @param[in]  c       profile and material (E*, and w of this branch: w for
 *                     the retract, w_adv for the approach); not a flat punch
 * @param[in]  k_m     machine stiffness [N/m], finite > 0
 * @param[in]  z0,F_b  contact point [m] and baseline [N]
 * @param[in]  branch  MDR_FIT_RETRACT (z non-increasing: the contact starts
 *                     on the stable branch at z[0] and separates at the fold)
 *                     or MDR_FIT_APPROACH (z non-decreasing)
 * @param[in]  z       n base positions [m]
 * @param[in]  n       number of positions
 * @param[out] F_out   n forces [N]; written only on MDR_OK
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_PARAM (k_m, branch),
 *         MDR_E_KIND (flat punch), MDR_E_ORDER (z not monotonic in the
 *         branch's direction), MDR_E_JUMPS, MDR_E_RADIUS, MDR_E_NOCONV,
 *         MDR_E_OVERFLOW
 */
mdr_status MDR_SFX(mdr_fit_model)(const MDR_SFX(mdr_contact) *c, MDR_T k_m, MDR_T z0, MDR_T F_b,
                                  uint8_t branch, const MDR_T *z, uint32_t n, MDR_T *F_out);

/**
 * @brief Tabor parameter mu = (R w^2/(E*^2 z_e^3))^(1/3) and the regime.
 *
 * R is the tip's radius of curvature at its apex where the profile has one:
 * R (paraboloid, sphere, and the flattened tip's paraboloid), 1/(2C)
 * (power law with n = 2), 1/(1/R + 4 pi^2 h/lambda^2) (wavy), and for a
 * sampled tip (MDR_PROFILE_TABLE) 1/f''(0) of the samples' model (f'
 * linear on each interval, lib/src/profile/mdr_abel.inc: the curvature of
 * the first interval) where that model starts smooth, |f'(0)| <= f''(0)
 * r_1/8 (exact for a sampled paraboloid). Profiles without a finite,
 * nonzero apex curvature (cone, other power laws; a sampled tip with a
 * flat or a pointed apex) take the radius of the paraboloid with the same
 * equivalent profile at the contact radius a_c: R = a_c^2/g(a_c) (exact
 * for a paraboloid).
 *
 * @param[in]  c       profile and material (E* > 0, w >= 0)
 * @param[in]  z_e     equilibrium distance [m], finite > 0
 * @param[in]  a_c     contact radius for the equivalent radius [m] (the
 *                     pull-off radius in mdr_fit_curve_<type>()); used only
 *                     by profiles without an apex radius
 * @param[out] mu      Tabor parameter (0 for w = 0)
 * @param[out] R       the radius used [m] (may be NULL)
 * @param[out] regime  MDR_REGIME_* (may be NULL)
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_PARAM (z_e <= 0),
 *         MDR_E_RADIUS (a_c outside the profile's domain, when it is used),
 *         MDR_E_OVERFLOW
 */
mdr_status MDR_SFX(mdr_tabor)(const MDR_SFX(mdr_contact) *c, MDR_T z_e, MDR_T a_c, MDR_T *mu, MDR_T *R,
                              uint8_t *regime);
