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
 * @brief Any state (a[i], d[i]), pinned or not: F = 2E*(a d - G(a)) with
 *        G(a) from mdr_profile_eval(), K_I and G from
 *        mdr_stress_intensity().
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
