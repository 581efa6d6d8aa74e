/* SPDX-License-Identifier: MIT */
/*
 * mdr_py_t.h: the array loops over a contact, for one floating arithmetic.
 * Included by mdr_py.h through the library's mdr_each_arith.h (MDR_T,
 * MDR_SFX defined). Arrays as described in mdr_py.h; *fail is the index of
 * the element the library refused (written only then).
 */

/**
 * @brief mdr_eq() at n radii a[i] [m].
 * @param out    [MDRPY_EQ_N][n]: a, d, F, dd/da, dF/da, dl, K_I, G
 * @param flags  [MDRPY_EQ_NFLAGS][n]: stable_load, stable_grips (0/1)
 * @return MDR_OK or the status of the first refused element
 */
mdr_status MDR_SFX(mdrpy_eq)(const MDR_SFX(mdr_contact) *c, size_t n, const double *a, double *out,
                             uint8_t *flags, size_t *fail);

/**
 * @brief Any state (a[i], d[i]), pinned or not, as `mdr eq --d` gives it:
 *        F = F_eq + 2E* a (d - d_eq) (= 2E*(a d - G(a)), 4.26) from
 *        mdr_eq() at a, K_I and G from mdr_stress_intensity().
 * @param out  [MDRPY_ST_N][n]: a, d, F, K_I, G
 * @return MDR_OK, the library's status, MDR_E_OVERFLOW (F beyond range)
 */
mdr_status MDR_SFX(mdrpy_state)(const MDR_SFX(mdr_contact) *c, size_t n, const double *a,
                                const double *d, double *out, size_t *fail);

/**
 * @brief sigma_zz(r[i]) in the contact of radius a[i]: held at depth d[i]
 *        (mdr_stress_at()), or in equilibrium when d is NULL (mdr_stress()).
 * @param sigma  n values [Pa]
 */
mdr_status MDR_SFX(mdrpy_stress)(const MDR_SFX(mdr_contact) *c, size_t n, const double *a,
                                 const double *d, const double *r, double *sigma, size_t *fail);

/**
 * @brief The equivalent profile at x[i] (mdr_profile_eval()).
 * @param out  [MDRPY_PR_N][n]: g [m], g' [1], G = int_0^x g [m^2]
 */
mdr_status MDR_SFX(mdrpy_profile)(const MDR_SFX(mdr_contact) *c, size_t n, const double *x,
                                  double *out, size_t *fail);

/**
 * @brief Contact of a sampled gap profile f(r_i) [m] at radii r_i [m], m
 *        points, as `mdr cycle/fit --profile table` builds it: the interval
 *        slopes formed in double (tip_slopes(), examples/tip_csv.h), the
 *        radii and slopes converted into buf (mdr_host_tip_contact(),
 *        mdr_contact_init_table_*).
 * @param s    caller scratch of max(m - 1, 1) doubles (the slopes)
 * @param buf  caller storage of max(2 m, 1) values; the contact points into
 *             it: it must outlive the contact
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE (an r or f not finite),
 *         MDR_E_TABLE (r not strictly increasing, or m), MDR_E_OVERFLOW (a
 *         radius or slope beyond the arithmetic), or the status of
 *         mdr_contact_init_table_* (c untouched unless MDR_OK)
 */
mdr_status MDR_SFX(mdrpy_contact_tip)(MDR_SFX(mdr_contact) *c, const double *r, const double *f,
                                      uint16_t m, double E, double w, double *s, MDR_T *buf);

/**
 * @brief mdr_fit_curve() on n samples (z[i] [m], F[i] [N]) given in
 *        double: converted to the arithmetic (a finite value beyond it is
 *        MDR_E_OVERFLOW, *fail its index), the options set as documented in
 *        mdr_fit_t.h (mdr_fit_defaults(), then k_m, z_e, E0, w0, method,
 *        approach, unpinned, flat), the result widened into *o.
 * @param tip   the profile (its E*, w unused)
 * @param work  mdrpy_fit_work_len(n) elements, caller's
 * @param[out] fail  index of the sample refused in the conversion (written
 *             only then)
 * @return MDR_OK or the status of mdr_fit_curve() (o written only on MDR_OK)
 */
mdr_status MDR_SFX(mdrpy_fit)(const MDR_SFX(mdr_contact) *tip, double k_m, double z_e, double E0,
                              double w0, uint8_t method, uint8_t approach, uint8_t unpinned, uint8_t flat,
                              const double *z, const double *F, uint32_t n, MDR_T *work, size_t work_len,
                              mdrpy_fit_res *o, size_t *fail);

/**
 * @brief The fitted model beside the data, as `mdr fit --model`: up to the
 *        last largest z the approach branch with w_approach (w_adv when it
 *        was fitted, else w), from there the retract with w, both with E*,
 *        z0 and the baseline F_base + F_slope (z - z0) of *res
 *        (mdr_fit_model(), the slope added in double).
 * @param tip   the profile (copied: its material is changed on the copy)
 * @param work  mdrpy_fit_work_len(n) elements, caller's
 * @param Fm    n model forces [N]; written only on MDR_OK
 * @param[out] top  index of the first retract sample
 * @return MDR_OK, MDR_E_OVERFLOW (a sample beyond the arithmetic), or the
 *         status of mdr_contact_material() or mdr_fit_model()
 */
mdr_status MDR_SFX(mdrpy_fit_model)(const MDR_SFX(mdr_contact) *tip, double k_m, const mdrpy_fit_res *res,
                                    double w_approach, const double *z, uint32_t n, MDR_T *work,
                                    size_t work_len, double *Fm, uint32_t *top);
