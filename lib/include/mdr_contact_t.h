/* SPDX-License-Identifier: MIT */
/*
 * mdr_contact_t.h: declarations of one arithmetic of the contact module.
 *
 * Not a header to include directly: mdr_contact.h includes it once per
 * arithmetic with MDR_T (float or double) and MDR_SFX(name) (name ## _f32 or
 * name ## _f64) defined, so that every arithmetic has the same, once-written
 * contract. Read it with T = float and suffix _f32.
 *
 * Model (chapter 4 of Popov, Hess & Willert, Handbook of Contact Mechanics,
 * 2019, whose equation numbers these comments give): a rigid axisymmetric
 * profile f(r) against an elastic half-space of effective modulus E* with
 * work of adhesion w. MDR maps it to a
 * row of springs of stiffness E* per unit length pressed by the equivalent
 * profile g(x) (eq. 4.46); the contact state is parameterised by its
 * radius a:
 *   dl(a) = sqrt(2*pi*a*w/E*)            rule of Hess, 4.1 / 4.21
 *   d(a)  = g(a) - dl(a)                  4.25
 *   F(a)  = 2*E*(a*d(a) - G(a)), G = int_0^a g dx           4.26
 *   dd/da = g'(a) - dl/(2a),  dF/da = 2*E*(a*g'(a) - 1.5*dl)
 *   K_I   = E*(g(a) - d)/sqrt(pi*a)       4.17 (= sqrt(2 E* w) at equilibrium)
 *   G_rel = K_I^2/(2E*)                   4.14 (energy release rate)
 */

/** One contact scene: profile + material, with constants derived at init.
 *  Caller-owned; fill it with mdr_contact_init_<type>() only. */
typedef struct {
    MDR_T E;     /**< effective modulus E* [Pa] */
    MDR_T w;     /**< work of adhesion w [J/m^2] */
    MDR_T p[3];  /**< profile parameters as given (see MDR_PROFILE_*) */
    MDR_T c_dl;  /**< sqrt(2*pi*w/E*) [m^0.5]: dl(a) = c_dl*sqrt(a) */
    MDR_T k[3];  /**< per-profile derived constants (see profile/mdr_profile.inc) */
    const MDR_T *tr; /**< MDR_PROFILE_TABLE: the caller's radii r[0..tm-1]; NULL otherwise */
    const MDR_T *ts; /**< MDR_PROFILE_TABLE: the caller's interval slopes s[0..tm-2]; NULL otherwise */
    uint16_t tm;  /**< MDR_PROFILE_TABLE: number of samples; 0 otherwise */
    uint8_t kind; /**< MDR_PROFILE_* */
} MDR_SFX(mdr_contact);

/** Equilibrium state at a given contact radius (all SI). */
typedef struct {
    MDR_T a;     /**< contact radius [m] */
    MDR_T d;     /**< indentation depth [m], positive into the surface */
    MDR_T F;     /**< normal force [N], compressive positive */
    MDR_T dd_da; /**< dd/da [1] */
    MDR_T dF_da; /**< dF/da [N/m] */
    MDR_T dl;    /**< critical spring stretch dl(a) = sqrt(2 pi a w/E*) [m] */
    MDR_T K_I;   /**< mode-I stress intensity factor [Pa m^0.5] */
    MDR_T G;     /**< energy release rate K_I^2/(2E*) [J/m^2] (= w at equilibrium) */
    bool stable_load;  /**< stable under fixed load: dF/da > 0 (4.23, k = 2/3) */
    bool stable_grips; /**< stable under fixed grips: dd/da > 0 (4.23, k = 2) */
} MDR_SFX(mdr_eqstate);

/** A state on the equilibrium curve reached by quasi-static retraction. */
typedef struct {
    MDR_T a;        /**< contact radius [m]; 0 when the contact peels off continuously */
    MDR_T d;        /**< indentation depth [m] */
    MDR_T F;        /**< normal force [N] */
    uint16_t jumps; /**< intermediate jumps (to a smaller stable radius) before this state */
    MDR_T F_min;    /**< the most tensile (lowest) force of the equilibrium states the
                         quasi-static path passes from the start to this one [N]: under
                         fixed load F itself; under fixed grips of a paraboloid -1.5 pi w R
                         (F at the load's fold) while F = -5/6 pi w R; 0 or more when
                         nothing along the path is tensile */
    MDR_T d_F_min;  /**< the depth of that state [m] */
} MDR_SFX(mdr_critstate);

/**
 * @brief Validate a scene and derive its constants.
 * @param[out] c     instance to fill; untouched unless MDR_OK is returned
 * @param[in]  kind  MDR_PROFILE_*
 * @param[in]  p     profile parameters, SI; meaning per kind (MDR_PROFILE_*):
 *                   R > 0 [m]; theta in (0, pi/2) [rad]; C > 0 [m^(1-n)] and
 *                   0 < n <= MDR_POWERLAW_N_MAX; a0 > 0 [m]; flattened tip
 *                   R > 0, 0 <= b [m]; wavy R > 0, h >= 0, lambda > 0 [m].
 *                   Unused entries are ignored (they may be anything).
 * @param[in]  E     effective modulus E* > 0 [Pa]
 * @param[in]  w     work of adhesion w >= 0 [J/m^2]; w = 0 is the
 *                   non-adhesive contact exactly (dl = 0)
 * @return MDR_OK, MDR_E_NULL, MDR_E_KIND (also for MDR_PROFILE_TABLE: use
 *         mdr_contact_init_table()), MDR_E_DISABLED (a profile removed by
 *         MDR_CFG_PROFILE_<KIND>, mdr_options.h), MDR_E_NONFINITE, MDR_E_PARAM
 */
mdr_status MDR_SFX(mdr_contact_init)(MDR_SFX(mdr_contact) *c, uint8_t kind,
                                     const MDR_T p[3], MDR_T E, MDR_T w);

/**
 * @brief A contact whose gap profile is sampled (a measured or worn tip):
 *        kind MDR_PROFILE_TABLE, the same model as the spring tables of
 *        mdr_table_init_gap(), evaluated exactly at any radius.
 *
 * f' is linear on each interval [r_j, r_j+1] with mean slope s_j exactly and
 * a curvature estimated from the neighbouring slopes; at a node where the
 * slope jumps (a kink: a worn flat's rim, the leading samples equal) the
 * curvature is taken from one side only, so the kink stays at that node
 * (a node is a kink where its slope change per unit length exceeds 4x both
 * neighbours' and its slope jump the slopes' rounding, eps r/h of them).
 * g, g' and G = int g are then the exact Abel integrals of
 * that f' (g' is +-inf just above a kink: MDR_E_OVERFLOW from
 * mdr_profile_eval() there when dg is asked for, like the flattened tip's
 * rim). Accuracy: order 2.5 in the sample spacing for a smooth f
 * (docs/profiles.md, "Tabulated tips"); a paraboloid, and a paraboloid with a flat
 * ending at a node, are reproduced to rounding. Cost of one evaluation
 * O(m); mdr_critical() on a table O(m^2).
 *
 * Why slopes, not f: the model needs only f', and forming f_j+1 - f_j in
 * float loses the samples' height (a 1 m offset on a 10 um sphere moved
 * the f32 pull-off by 46 %). Difference the samples where they are exact
 * (in double on the host: tip_slopes() in examples/tip_csv.h, the mdr CLI,
 * or your own code: s_j = (f_j+1 - f_j)/(r_j+1 - r_j)), then convert r and
 * s to float. The f32 library never calls a double helper.
 *
 * @param[out] c  filled only on MDR_OK; it keeps the pointers r and s (the
 *                arrays are the caller's and must outlive the contact)
 * @param[in]  r  radii [m], r[0] = 0, strictly increasing, finite
 * @param[in]  s  slopes s[j] = (f(r_j+1) - f(r_j))/(r_j+1 - r_j), j = 0..m-2
 *                [1], finite
 * @param[in]  m  samples, MDR_TABLE_MIN_POINTS (3) .. 65535
 * @param[in]  E  effective modulus E* > 0 [Pa]
 * @param[in]  w  work of adhesion w >= 0 [J/m^2]
 * @return MDR_OK, MDR_E_NULL, MDR_E_DISABLED (MDR_CFG_PROFILE_TABLE = 0),
 *         MDR_E_NONFINITE, MDR_E_PARAM (E, w), MDR_E_TABLE (m, r),
 *         MDR_E_OVERFLOW (g or G at r[m-1] beyond the arithmetic's range)
 */
mdr_status MDR_SFX(mdr_contact_init_table)(MDR_SFX(mdr_contact) *c, const MDR_T *r,
                                           const MDR_T *s, uint16_t m, MDR_T E, MDR_T w);

/**
 * @brief Give an initialised contact another material: same profile, new E*
 *        and w (the derived constants that depend on them are updated). The
 *        fit (mdr_fit.h) varies E* and w of a tip this way, whatever its kind.
 * @param[in,out] c  from mdr_contact_init_<type>() or
 *                  mdr_contact_init_table_<type>(); untouched unless MDR_OK
 * @param[in]     E  effective modulus E* > 0 [Pa]
 * @param[in]     w  work of adhesion w >= 0 [J/m^2]
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_PARAM (also when
 *         sqrt(2 pi w/E*) is beyond the arithmetic's range)
 */
mdr_status MDR_SFX(mdr_contact_material)(MDR_SFX(mdr_contact) *c, MDR_T E, MDR_T w);

/**
 * @brief Equivalent 1D profile at x: g(x), g'(x) and G(x) = int_0^x g.
 * @param[in]  c   from mdr_contact_init_<type>() or mdr_contact_init_table_<type>()
 * @param[in]  x   0 < x, and x < R (sphere), x <= a0 (flat punch),
 *                 x/lambda < 2^46 (wavy, f32; 2^104 in f64: beyond, the
 *                 phase 2 pi x/lambda has no correct digit) [m]
 * @param[out] g   g(x) [m] (may be NULL)
 * @param[out] dg  g'(x) [1] (may be NULL); +inf slopes (power law n < 1 at
 *                 small x, flattened tip at x = b) give MDR_E_OVERFLOW
 * @param[out] G   int_0^x g(s) ds [m^2] (may be NULL)
 * @return MDR_OK, MDR_E_NULL (c), MDR_E_NONFINITE, MDR_E_RADIUS, MDR_E_OVERFLOW
 */
mdr_status MDR_SFX(mdr_profile_eval)(const MDR_SFX(mdr_contact) *c, MDR_T x,
                                     MDR_T *g, MDR_T *dg, MDR_T *G);

/**
 * @brief Equilibrium (Griffith) state at contact radius a: eq. 4.19-4.26.
 * @param[in]  c    from mdr_contact_init_<type>() or mdr_contact_init_table_<type>()
 * @param[in]  a    contact radius, same domain as mdr_profile_eval() [m]
 * @param[out] out  filled only on MDR_OK
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_RADIUS, MDR_E_OVERFLOW
 *         (e.g. g' infinite at a = b of the flattened tip)
 */
mdr_status MDR_SFX(mdr_eq)(const MDR_SFX(mdr_contact) *c, MDR_T a,
                           MDR_SFX(mdr_eqstate) *out);

#if MDR_CFG_STRESS
/**
 * @brief Stress intensity and energy release rate of any state (a, d),
 *        pinned or in equilibrium: K_I = E*(g(a) - d)/sqrt(pi a) (4.17),
 *        G = K_I^2/(2E*) (4.14).
 * @param[in]  c    from mdr_contact_init_<type>() or mdr_contact_init_table_<type>()
 * @param[in]  a    contact radius [m]
 * @param[in]  d    indentation depth [m] (any finite value)
 * @param[out] K_I  [Pa m^0.5]; negative when the edge is compressed
 * @param[out] G    [J/m^2] (may be NULL)
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_RADIUS, MDR_E_OVERFLOW
 */
mdr_status MDR_SFX(mdr_stress_intensity)(const MDR_SFX(mdr_contact) *c, MDR_T a,
                                         MDR_T d, MDR_T *K_I, MDR_T *G);

/**
 * @brief Normal stress sigma_zz(r) inside a contact of radius a held at depth
 *        d (4.27): sigma = -(E* /pi) int_r^a g'(x)/sqrt(x^2-r^2) dx
 *                          + E*(g(a)-d)/(pi sqrt(a^2-r^2)).
 *        Negative in compression; the second term is the adhesive (tensile)
 *        edge singularity. Paraboloid, cone, flat punch: closed forms;
 *        other profiles: tanh-sinh quadrature (see mdr_contact_t.c); measured
 *        against GSL within 3e-7 (f32) and 3e-12 (f64) of the size of the two
 *        terms, except within 1e-3 a of the rim r = b of the flattened tip.
 * @param[in] c      from mdr_contact_init_<type>() or mdr_contact_init_table_<type>()
 * @param[in] a      contact radius [m], same domain as mdr_profile_eval()
 * @param[in] d      indentation depth [m] (any finite value)
 * @param[in] r      radial position, 0 <= r < a [m]; r > 0 for the cone, the
 *                   power law with n <= 1 and a sampled tip whose f'(0+) is
 *                   not 0 (a sampled cone); r != b for the flattened tip and
 *                   r not at a kink of a sampled tip (MDR_E_SINGULAR)
 * @param[out] sigma sigma_zz(r) [Pa], compressive negative; untouched unless MDR_OK
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_RADIUS, MDR_E_POSITION,
 *         MDR_E_SINGULAR, MDR_E_OVERFLOW
 */
mdr_status MDR_SFX(mdr_stress_at)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_T d,
                                  MDR_T r, MDR_T *sigma);

/** @brief sigma_zz(r) in the equilibrium state of radius a (d = g(a) - dl(a),
 *         4.25; also at a flat's rim, a = b, where mdr_eq()'s dd/da is
 *         infinite); see mdr_stress_at(). Same errors. */
mdr_status MDR_SFX(mdr_stress)(const MDR_SFX(mdr_contact) *c, MDR_T a, MDR_T r,
                               MDR_T *sigma);
#endif /* MDR_CFG_STRESS */

/**
 * @brief Critical (pull-off) state of quasi-static retraction.
 *
 * Starting in equilibrium at radius a_start, the controlled variable
 * (F, d or z = d + F/k_m) is decreased slowly. The contact follows the stable
 * branch; where the branch ends (dc/da = 0) it jumps at constant control to
 * the next stable equilibrium with a smaller radius (counted in jumps). The
 * result is the last stable state before complete separation: for a smooth
 * paraboloid the JKR pull-off, for the flat punch Kendall's rupture (4.63),
 * for the flattened tip with b > 0.7475 a* the state at a = b (a* the
 * paraboloid's critical radius under the same control). If the branch
 * peels stably all the way to a -> 0 (w = 0, or a power law with n < 1/2),
 * the result is a = d = F = 0.
 *
 * Equivalently, the result is the minimum of the control's equilibrium
 * value c(a) over (0, a_start] (F, d or z), and the jumps are the other
 * local minima of c lower than everything above them. The search finds
 * every local minimum by construction from the profile's structure
 * (closed-form or bracketed stability roots, kinks, the wavy profile's
 * asymptotic envelope; equilibrium/mdr_critical.inc), not by a scan of
 * fixed step.
 *
 * a_start is a hint that cannot make the answer wrong: if the contact at
 * a_start is unstable under the control, it first jumps in (as when pressed
 * there) to the smallest larger radius with the same control value, and
 * retracts from there. For every profile but the wavy one (whose jumps
 * depend on where retraction starts) the result is then the same for every
 * start at or above the outermost fold (mdr_default_start() is one).
 *
 * Work: a few dozen evaluations for the closed-form profiles; the wavy
 * profile four per wavelength below the radius where every control is
 * stable (from its asymptotic envelope) plus ~100 per fold; a table O(m^2)
 * (two cells per sample interval, O(m) each). Fixed caps:
 * MDR_CRIT_SCAN_MAX cells, 200 bisection and 160 golden-section steps.
 *
 * @param[in]  c        from mdr_contact_init_<type>() or mdr_contact_init_table_<type>()
 * @param[in]  control  MDR_CONTROL_LOAD, _GRIPS or _MACHINE
 * @param[in]  k_m      machine stiffness [N/m], finite > 0; used only for
 *                      MDR_CONTROL_MACHINE (ignored otherwise)
 * @param[in]  a_start  starting radius [m] in the profile's domain (see
 *                      mdr_default_start())
 * @param[out] out      filled only on MDR_OK
 * @return MDR_OK, MDR_E_NULL, MDR_E_KIND (a contact no init filled),
 *         MDR_E_NONFINITE, MDR_E_CONTROL, MDR_E_RADIUS
 *         (a_start outside the domain; no stable state at or above it: a
 *         power law with n < 1/2 beyond its fold, a table that ends on an
 *         unstable branch; a critical radius the arithmetic does not
 *         resolve: the sphere's within rounding of R, a power law's with
 *         adhesion where |n - 1/2| <= 2^10 eps, eps the unit roundoff
 *         (1.1e-13 in f64, 6.1e-5 in f32; n = 1/2 included), whose radius
 *         (k c/(n kappa C))^(1/(n - 1/2)) moves by e/|n - 1/2| for a
 *         relative error e of the profile's slope, more than 1 % there:
 *         at 1 ulp above 1/2 it was answered as 0), MDR_E_OVERFLOW (a critical radius or state beyond the
 *         arithmetic's range, more than 65535 jumps), MDR_E_NOCONV (more
 *         than MDR_CRIT_SCAN_MAX cells: a wavy contact of more than ~65536
 *         wavelengths below its stable radius)
 */
mdr_status MDR_SFX(mdr_critical)(const MDR_SFX(mdr_contact) *c, uint8_t control,
                                 MDR_T k_m, MDR_T a_start,
                                 MDR_SFX(mdr_critstate) *out);

/**
 * @brief A starting radius for mdr_critical() on the last stable branch of
 *        every control: above the outermost root of dF/da = 0 (found
 *        exactly: above it every control is stable), 3 x the radius a_x
 *        where g(a_x) = dl(a_x) when that lies above the root (the start
 *        before issue 16), else twice the root, and below R for the sphere
 *        (halfway from the root to R); at least 1.5 b for the flattened
 *        tip; power laws with n < 1/2: below their load root (min(a_x/3,
 *        root/2)), where they are stable; n = 1/2, whose g and dl both
 *        grow as sqrt(a) (no length sets a critical radius), and n within
 *        2^10 eps of 1/2 (see mdr_critical()): the profile's length
 *        C^(1/(1 - n)), which mdr_critical() answers with MDR_E_RADIUS
 *        (helper-33, stop 58; helper-62, stop 68); the flat punch: a0; a table: its
 *        last sample; the wavy profile (where the jumps depend on the
 *        start): 3 a_x of its smooth base; without adhesion the profile's
 *        length.
 * @param[in]  c       from mdr_contact_init_<type>() or mdr_contact_init_table_<type>()
 * @param[out] a_start [m]; untouched unless MDR_OK
 * @return MDR_OK, MDR_E_NULL, MDR_E_NOCONV, MDR_E_RADIUS (the sphere's root
 *         within rounding of R), MDR_E_OVERFLOW (the radius is beyond the
 *         arithmetic's range: w/E* enormous, or a power law near n = 1/2)
 */
mdr_status MDR_SFX(mdr_default_start)(const MDR_SFX(mdr_contact) *c, MDR_T *a_start);
