/* SPDX-License-Identifier: MIT */
/*
 * mdr_engine_t.h: declarations of one arithmetic of the spring engine.
 * Included by mdr_engine.h once per arithmetic (MDR_T, MDR_SFX defined); read
 * it with T = float and suffix _f32.
 *
 * The table. The equivalent profile g(x) (eq. 4.46) is held at the n+1
 * spring boundaries x_i = i*h, 0 <= x_i <= x_max = n*h, as g_i, the prefix
 * integral G_i = int_0^{x_i} g, t_i = sqrt(x_i) and, per spring, the excess
 * q_i = int_{x_i}^{x_{i+1}} g - h*(g_i + g_{i+1})/2 of its integral over the
 * trapezoid. After node n, two nodes per block of MDR_TABLE_BLOCK springs
 * hold bounds over the block (interpolant included): node n+1+2b =
 * {g: min g, G: min G, t: max g, q: max G}, node n+2+2b = {g: min g', 0, 0,
 * 0} (g' per unit x); the builders write them, the engine uses them to pass
 * blocks where the edge cannot stop (MDR_TABLE_NODES sizes the storage). Between nodes g is the quadratic through g_i, g_{i+1} whose
 * integral is exact (q_i), and G its exact integral, so G is continuous,
 * G' = g, and g is reproduced exactly for the paraboloid and the cone; for a
 * smooth g the interpolation error is O(h^3) (measured: README, "Spring
 * engine"). dl(a) = c*sqrt(a) is never interpolated: the engine solves in
 * t = sqrt(a), where every branch is a polynomial of degree <= 4.
 *
 * The state machine (the rule of Hess, eqs. 4.1 and 4.21). With the edge at a
 * and dl_w(a) = sqrt(2 pi a w/E*), dl_adv(a) = sqrt(2 pi a w_adv/E*):
 *   advance while d > g(a) - dl_adv(a);  recede while d < g(a) - dl_w(a);
 *   otherwise the edge is pinned and F = 2E*(a d - G(a)) follows d.
 * The controlled variable u is d (fixed grips), F (fixed load) or
 * z = d + F/k_m (machine of stiffness k_m). Along an advancing or receding
 * edge u is a function U(a); the edge follows U while dU/da > 0 and jumps at
 * constant u where dU/da changes sign (a fold): to the next a with the same
 * U, or to separation (pull-off) when there is none.
 */

/** One spring boundary of a table (see above). */
typedef struct {
    MDR_T g; /**< g(x_i) [m] */
    MDR_T G; /**< int_0^{x_i} g dx [m^2] */
    MDR_T t; /**< sqrt(x_i) [m^0.5] */
    MDR_T q; /**< integral excess of spring i over its trapezoid [m^2]; 0 at i = n */
} MDR_SFX(mdr_node);

/** A spring table: geometry only (no material), so it can live in flash. */
typedef struct {
    const MDR_SFX(mdr_node) *node; /**< n+1 nodes */
    MDR_T h;                       /**< spring width [m]: x_i = i*h */
    uint16_t n;                    /**< number of springs */
    uint8_t wall;                  /**< 1: g = +inf beyond x_n (flat punch: the edge stops there) */
    uint8_t rim0;                  /**< 1: a flat's rim (the flattened tip's b, a sampled profile's
                                        first kink: g' infinite above it) lies inside spring 0,
                                        0 < rim < h, where no quadratic spring resolves it; the
                                        engines' inits refuse an adhesion whose pull-off may lie
                                        there (MDR_E_PARAM). 2: a power law C x^n, n not 1 or 2,
                                        which spring 0's quadratic is not: the inits refuse an
                                        adhesion whose pull-off the table puts in spring 0 or 1
                                        (MDR_E_PARAM). 0: neither. Set by the table builders. */
} MDR_SFX(mdr_table);

/** Energy bookkeeping of every engine of this arithmetic: embedded in a
 *  spring engine (.en), caller-owned for a scene. The work of the contact
 *  force, int F dd, is summed per cycle (a cycle ends with a complete
 *  separation), so its rounding does not grow with the number of cycles.
 *  Each tick's work is exact whatever the tick, to the arithmetic's
 *  rounding of the states: on a moving edge the change of the elastic
 *  energy less the work of adhesion (eq. 4.21), not a quadrature of F
 *  over d; a jump at constant control and a pinned stretch by the
 *  trapezoid, exact there.
 *  What a cycle dissipates (last_cycle, dissipated) is not that sum of
 *  work, whose terms carry the stored elastic energy there and back (a
 *  hard sphere under a large load stores ~1e6 times what its cycle
 *  dissipates, which the rounding of the states' work, ~eps times that,
 *  swamped: 5 % in f32, a negative loop in f64 at E* = 1e35), but the sum
 *  `loss` of what each part of the cycle dissipates where it arises: the
 *  work less the change of the elastic energy E* int_0^a (d - g)^2 dx of
 *  the springs in contact. That is 0 on a pinned edge, the work of
 *  adhesion -w pi (a1^2 - a0^2) on a moving one (w_adv advancing, w
 *  receding), and at a jump between the states (a0, d0) and (a1, d1)
 *  -E* int_a0^a1 (d0 - g)(d1 - g) dx; over a whole cycle the elastic
 *  energy returns to 0, so the two sums agree but for rounding, and the
 *  loss is resolved to the arithmetic's rounding of the contact's size,
 *  not of its stored energy. */
typedef struct {
    MDR_T work;         /**< int F dd since the last complete separation [J] */
    MDR_T work_c;       /**< compensation term of that sum (Kahan) */
    MDR_T dissipated;   /**< energy dissipated over completed cycles [J] */
    MDR_T dissipated_c; /**< compensation term of that sum (Kahan) */
    MDR_T last_cycle;   /**< energy dissipated in the last completed cycle [J]: `loss` at its end */
    uint32_t cycles;    /**< completed cycles (approach, then complete separation) */
    MDR_T loss;         /**< the work since the last complete separation less the elastic
                             energy stored now, E* int_0^a (d - g)^2 dx [J], summed where it
                             arises (a moving edge: its work of adhesion; a jump): at a complete
                             separation, what the cycle dissipated (last_cycle) */
    MDR_T loss_c;       /**< compensation term of that sum (Kahan) */
} MDR_SFX(mdr_energy);

/** The pinned edge of an engine for one control mode (internal: what a tick
 *  that leaves the edge where it is needs). u in the SI units of that
 *  control (d, F or z). */
typedef struct {
    MDR_T u_lo, u_hi; /**< the edge stays while u_lo <= u <= u_hi */
    MDR_T kd, d0;     /**< then d = kd u + d0 */
    MDR_T kF, F0;     /**< and F = kF u + F0 */
    MDR_T s_lo, s_hi; /**< the solver's edge coordinate per unit of u along the receding
                           (u < u_lo) and the advancing branch (u > u_hi) at the edge: the
                           first step of the next move; 0 where there is none (a fold). A
                           scene keeps, after a move, the other branch's slope at an earlier
                           edge: only a start for Newton */
} MDR_SFX(mdr_pinned);

/** The engine: material, control constants and the contact state.
 *  Caller-owned; fill it with mdr_engine_init_<type>() only, then read it
 *  freely and change it only through the step functions. */
typedef struct {
    const MDR_SFX(mdr_table) *tab;
    MDR_T E;      /**< E* [Pa] */
    MDR_T c_w;    /**< sqrt(2 pi w/E*) [m^0.5]: dl_w(a) = c_w sqrt(a) */
    MDR_T c_adv;  /**< sqrt(2 pi w_adv/E*) [m^0.5] */
    MDR_T k_m;    /**< machine stiffness [N/m]; 0: no machine (step_z refused) */
    MDR_T kappa;  /**< 2E* /k_m [1/m]; 0 without machine */
    /* state of the edge */
    MDR_T a;      /**< contact radius [m]; 0 when separated */
    MDR_T t;      /**< sqrt(a) [m^0.5] */
    MDR_T g;      /**< g(a) [m] */
    MDR_T Ga;     /**< G(a) [m^2] */
    MDR_T d;      /**< indentation [m] after the last step */
    MDR_T F;      /**< force [N] after the last step */
    MDR_SFX(mdr_pinned) pin; /**< the pinned edge for control mode `mode` */
    MDR_T ik_m;   /**< 1/k_m [m/N] (z = d + F/k_m); 0 without machine */
    MDR_T ih;     /**< 1/h of the table [1/m] */
    MDR_T iE2;    /**< 1/(2E*) [1/Pa] */
    MDR_T z_min;  /**< the least z [m] a separated step_z answers without its full tick:
                       minus the largest finite value of the type with a machine, the largest
                       without one (no z qualifies) */
    /* the two jumps that cross the table, known from init (per control
     * mode, index MDR_CONTROL_* - 1; the step's units: d, F/(2E*), z) */
    MDR_T u_min[3]; /**< the least U of the receding branch over the table's nodes and the
                         turns inside its springs: a fold whose landing aims below it pulls
                         off (no scan) */
    MDR_T t_in[3];  /**< sqrt(a) of the landing of a jump-in from a = 0 */
    MDR_T t_fold[3]; /**< sqrt(a) of the outermost fold of the receding branch */
    MDR_T u_fold[3]; /**< its U less U's rounding bound there: a move toward a control
                          below it from above the fold stops at the fold (no scan) */
    MDR_SFX(mdr_energy) en; /**< energy bookkeeping (with MDR_OUT_ENERGY) */
    uint16_t k;   /**< spring holding the edge: x_k <= a <= x_{k+1} */
    uint16_t k_in[3]; /**< the spring of t_in; 0xFFFF where none is known (the step scans) */
    uint16_t k_fold[3]; /**< the spring of t_fold; 0xFFFF where none is known */
    uint16_t k_sure[3][2]; /**< per control mode and direction (0 receding, 1 advancing): the
                                first spring from which every spring has its branch stable at
                                both ends, so all through (the step tests the ends of the
                                springs below it where it passes them) */
    uint8_t contact; /**< 1 in contact, 0 separated */
    uint8_t touched; /**< 1 once the instance has been in contact */
    uint8_t flags;   /**< sticky MDR_FLAG_* */
    uint8_t outputs; /**< MDR_OUT_* (init: MDR_OUT_ALL | MDR_OUT_ENERGY) */
    uint8_t mode;    /**< control mode (MDR_CONTROL_*) of the pinned edge, bit 7 set while a move has left its linear coefficients (pin) to the next pinned tick; 0 exactly when separated */
    MDR_T mv_c, mv_d; /**< internal: where the step's last fast move began (the edge's
                           coordinate in the engine's units, d [m]), for its work (MDR_OUT_ENERGY) */
} MDR_SFX(mdr_engine);

/** What one step did. All SI; "before"/"after" describe the last jump of
 *  the step and equal the final state when there was none. */
typedef struct {
    MDR_T z;       /**< d + F/k_m (d without a machine; the control as given by a step_z) [m] */
    MDR_T d;       /**< indentation [m] */
    MDR_T F;       /**< force [N]; 0 when separated */
    MDR_T a;       /**< contact radius [m]; 0 when separated */
    MDR_T a0, d0, F0; /**< last stable state before the jump (the fold) */
    MDR_T a1, d1, F1; /**< state right after the jump, same control value */
    uint8_t event; /**< MDR_EV_* */
    uint8_t jumps; /**< jumps in this step (saturates at 255) */
} MDR_SFX(mdr_step);

#if MDR_CFG_ENGINE
/**
 * @brief Spring table of an analytic profile: g_i, G_i from the foundation's
 *        closed forms (mdr_profile_eval()), q_i by 2-point Gauss-Legendre on
 *        each spring (error O(h^5 g'''') per spring), G_i as compensated
 *        prefix sums of the spring integrals (so G is consistent with g).
 *        Where g' is smooth, g_{i+1} - g_i and q_i come from g' (Gauss
 *        on g'), not from differences of values of g, which cancel by x/h:
 *        g_i is then the compensated sum of those increments, within the
 *        rounding of the closed form's value at x_i (it is reset to it
 *        otherwise), and the engine's g' in a spring is exact but for the
 *        storage of g_i (f32: |dg'|/g' <= 2^-24 (|g_i| + |g_{i+1}|)/(h g'),
 *        which a fixed-grips pull-off feels to first order; engine.md).
 * @param[out] tab   table header; untouched unless MDR_OK
 * @param[out] node  caller storage of MDR_TABLE_NODES(n) nodes
 * @param[in]  n     springs, MDR_SPRINGS_MIN..MDR_SPRINGS_MAX
 * @param[in]  c     an initialised contact (only its profile is used)
 * @param[in]  x_max table extent [m], > 0 and inside the profile's domain
 *                   (x_max < R for the sphere). Flat punch: x_max <= a0, and
 *                   x_max == a0 makes the rim a wall (the edge stops there).
 *                   A flat's rim b (the flattened tip's; a sampled
 *                   profile's first kink) is put on a node k: the spring
 *                   width is b/k instead of x_max/n, k the whole springs
 *                   below b rounded down, so the table reaches up to one
 *                   part in k beyond x_max (or, where a sampled profile
 *                   ends first, rounded up: short of x_max by less than
 *                   one part in k). tab->h n is the extent made; rims in
 *                   spring 0 (b < x_max/n) stay where they are.
 * @return MDR_OK, MDR_E_NULL, MDR_E_KIND (a contact no init filled),
 *         MDR_E_SIZE, MDR_E_NONFINITE, MDR_E_RADIUS,
 *         MDR_E_OVERFLOW (x_max too large for the arithmetic, or so small
 *         that the table's values lose their digits, every table: a
 *         curvature term that matters, q ~ h |Dg_{i+1} - Dg_i|/12, below
 *         the smallest normal number, or max |G| below it over the unit
 *         roundoff)
 */
mdr_status MDR_SFX(mdr_table_init_profile)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                           uint16_t n, const MDR_SFX(mdr_contact) *c, MDR_T x_max);

/**
 * @brief Spring table of a tabulated gap profile f(r_i) (a measured or worn
 *        tip), x_max = r[m-1].
 *
 * f' is taken linear on each interval [r_j, r_j+1]: mean slope exactly
 * (f_j+1 - f_j)/(r_j+1 - r_j), curvature from the neighbouring slopes
 * (one-sided at the ends), so f' has error O(h_r^2) for a smooth f and the
 * piecewise quadratic f passes through every sample. The Abel transform
 * g(x) = x int_0^x f'(r)/sqrt(x^2-r^2) dr is then integrated exactly over
 * each piece: x [alpha (asin(r1/x) - asin(r0/x)) + beta (S0 - S1)],
 * S = sqrt(x^2 - r^2), with the asin difference as one atan of a
 * cancellation-free quotient. Order of accuracy in the sample spacing h_r:
 * f' has error O(h_r^2); with the integrable 1/sqrt kernel g converges at
 * order 2.5 (measured 2.47 for the exact sphere, host_tests/test_engine.c,
 * gap_table_order; docs/engine.md). Quadratic f
 * (paraboloid) is reproduced to rounding. f(0) may be any value (only f'
 * enters). The first kink of the samples (a worn flat's rim) is put on a
 * node by shortening the table by less than one part in k, k the springs
 * below it (as mdr_table_init_profile()): its flat-edge separation is then
 * Kendall's to rounding. The springs' g increments and q_i are taken from
 * the model's g' where it is smooth (as mdr_table_init_profile()). Cost
 * O(n*m) at init.
 * @param[out] tab  table header; untouched unless MDR_OK
 * @param[out] node caller storage of MDR_TABLE_NODES(n) nodes
 * @param[in] n  springs, MDR_SPRINGS_MIN..MDR_SPRINGS_MAX
 * @param[in] r  radii [m], r[0] = 0, strictly increasing, finite
 * @param[in] f  gap f(r_i) [m], finite
 * @param[in] m  points, >= MDR_TABLE_MIN_POINTS
 * @return MDR_OK, MDR_E_NULL, MDR_E_SIZE, MDR_E_NONFINITE, MDR_E_TABLE,
 *         MDR_E_OVERFLOW (a table entry beyond the arithmetic's range, at
 *         either end: as mdr_table_init_profile())
 */
mdr_status MDR_SFX(mdr_table_init_gap)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                       uint16_t n, const MDR_T *r, const MDR_T *f, uint16_t m);

/**
 * @brief Spring table of a tabulated equivalent profile g given directly at
 *        x_i = i*h, i = 0..n (g[0] must be 0). Between nodes g is linear
 *        (q_i = 0) and G the trapezoidal prefix sums, exact for that g.
 * @param[out] tab  table header; untouched unless MDR_OK
 * @param[out] node caller storage of MDR_TABLE_NODES(n) nodes
 * @param[in] n  springs, MDR_SPRINGS_MIN..MDR_SPRINGS_MAX
 * @param[in] h  spring width [m], finite > 0
 * @param[in] g  n+1 values [m], finite
 * @return MDR_OK, MDR_E_NULL, MDR_E_SIZE, MDR_E_NONFINITE, MDR_E_PARAM (h),
 *         MDR_E_TABLE (g[0] != 0), MDR_E_OVERFLOW (G beyond the range, at
 *         either end: as mdr_table_init_profile())
 */
mdr_status MDR_SFX(mdr_table_init_g)(MDR_SFX(mdr_table) *tab, MDR_SFX(mdr_node) *node,
                                     uint16_t n, MDR_T h, const MDR_T *g);

/**
 * @brief Start an engine on a table, separated (a = 0, d = 0, F = 0).
 * @param[out] e     the engine; untouched unless MDR_OK
 * @param[in] tab    a table from mdr_table_init_*() or a generated const
 *                   table; must outlive the engine and stay as it was: the
 *                   engine keeps what init found on it (the pull-off's and
 *                   the landings' springs, the fold's control); a table
 *                   rebuilt in place (another tip in the same storage) needs
 *                   the engine initialised again (else a 40 um tip written
 *                   over a 10 um one pulled off at 0.29 of its force,
 *                   MDR_OK: helper-32, stop 58)
 * @param[in] E      E* > 0 [Pa]
 * @param[in] w      work of adhesion on retraction, w >= 0 [J/m^2]
 * @param[in] w_adv  work of adhesion on approach, 0 <= w_adv <= w [J/m^2]
 *                   (0: non-adhesive loading; w: reversible JKR)
 * @param[in] k_m    machine stiffness [N/m]: finite > 0, or 0 for none
 *                   (then mdr_engine_step_z() returns MDR_E_CONTROL)
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE, MDR_E_PARAM (E, w, w_adv;
 *         or, with w > 0, a pull-off so deep inside the table's first
 *         spring that it is not resolved: MDR_ENGINE_ADH_COND; or, on a
 *         table whose flat's rim lies inside spring 0 (rim0 = 1), a pull-off
 *         that may lie there, docs/accuracy.md; on a power law's table
 *         (rim0 = 2), a pull-off in spring 0 or 1 or none found,
 *         docs/engine.md),
 *         MDR_E_CONTROL (k_m < 0, or (2 E*) / k_m or 1/k_m not
 *         finite in the arithmetic: 2 E* is formed first, so with a machine
 *         E* above half the largest value is refused), MDR_E_SIZE (table
 *         header invalid)
 */
mdr_status MDR_SFX(mdr_engine_init)(MDR_SFX(mdr_engine) *e, const MDR_SFX(mdr_table) *tab,
                                    MDR_T E, MDR_T w, MDR_T w_adv, MDR_T k_m);

/**
 * @brief The material and machine checks of mdr_engine_init() (and of the
 *        q31 engine's init from this arithmetic) alone, before a table is
 *        built: a front end refuses bad settings where they are given.
 * @param E, w, w_adv, k_m  as mdr_engine_init()
 * @return MDR_OK, MDR_E_NONFINITE, MDR_E_PARAM (E* not > 0, w < 0, w_adv
 *         < 0 or above w, or w/E* beyond the arithmetic), MDR_E_CONTROL (k_m < 0, or (2 E*) / k_m or
 *         1/k_m not finite in the arithmetic): the status mdr_engine_init()
 *         returns for these on a valid table (a pull-off the table does not
 *         resolve is the init's to find)
 */
mdr_status MDR_SFX(mdr_engine_check)(MDR_T E, MDR_T w, MDR_T w_adv, MDR_T k_m);

/**
 * @brief One control tick with the indentation d held (fixed grips).
 * @param[in,out] e  the engine; unchanged unless MDR_OK (but for its sticky flags)
 * @param[in]  d    indentation [m], finite (negative: a gap)
 * @param[out] out  what happened; written only on MDR_OK
 * @return MDR_OK; MDR_E_NULL, MDR_E_NONFINITE; MDR_E_OUTSIDE (state
 *         unchanged, MDR_FLAG_OUTSIDE set); MDR_E_OVERFLOW (d, F, z or the
 *         energy sums would leave the arithmetic's range: state unchanged);
 *         MDR_E_NOCONV (not expected: bisection backs every iteration;
 *         state unchanged, flag set)
 *
 * Cost: O(1) when the edge is pinned (under load and through a machine the
 * first pinned tick after a move computes the pinned relation once: a few
 * divisions); otherwise O(1) plus one comparison per node the edge passes
 * (it moves from where it was) and a safeguarded Newton solve (typically
 * 2-4 iterations, capped) in the spring where it stops; a fold adds a
 * bisection to locate it.
 */
mdr_status MDR_SFX(mdr_engine_step_d)(MDR_SFX(mdr_engine) *e, MDR_T d, MDR_SFX(mdr_step) *out);

/** @brief One tick with the force F [N] held (fixed load); see step_d().
 *  While separated the contact carries no force: out.F = 0, and d keeps the
 *  depth at which contact was lost (the body is free). */
mdr_status MDR_SFX(mdr_engine_step_F)(MDR_SFX(mdr_engine) *e, MDR_T F, MDR_SFX(mdr_step) *out);

/** @brief One tick with the base position z = d + F/k_m [m] held through
 *  the machine stiffness given at init; see step_d(). MDR_E_CONTROL when
 *  the engine has no machine (k_m = 0). */
mdr_status MDR_SFX(mdr_engine_step_z)(MDR_SFX(mdr_engine) *e, MDR_T z, MDR_SFX(mdr_step) *out);

/** @brief Clear the sticky flags; returns the flags that were set. */
uint8_t MDR_SFX(mdr_engine_clear_flags)(MDR_SFX(mdr_engine) *e);

/**
 * @brief Choose what the steps compute: MDR_OUT_* bits (MDR_OUT_FORCE: F and
 *        d only; MDR_OUT_RADIUS, MDR_OUT_EVENTS, MDR_OUT_ENERGY add a, the
 *        event fields and z, the energy sums). Fields not asked for are not
 *        written (out) resp. not updated (e->en); turning MDR_OUT_ENERGY
 *        back on restarts the sums from zero (in contact: the cycle's loss
 *        then ends, at the next complete separation, with the elastic
 *        energy stored at the restart counted as dissipated). A step costs
 *        less the less it is asked for (README, step cost).
 * @return MDR_OK, MDR_E_NULL, MDR_E_PARAM (unknown bits)
 */
mdr_status MDR_SFX(mdr_engine_outputs)(MDR_SFX(mdr_engine) *e, uint8_t outputs);
#endif /* MDR_CFG_ENGINE */
