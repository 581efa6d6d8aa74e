/* SPDX-License-Identifier: MIT */
/*
 * mdr_fit.h: from a measured force curve to E*, w, the contact point and the
 * force baseline (Levenberg-Marquardt on the library's quasi-static model),
 * the two-point JKR method, and the adhesion regime (Tabor parameter).
 * One set of functions per arithmetic: _f32 (float, firmware) and _f64
 * (double, host). See mdr_fit_t.h for the contract, written once for both.
 * Built when MDR_CFG_FIT is 1 (the default, mdr_options.h).
 */
#ifndef MDR_FIT_H
#define MDR_FIT_H

#include <stddef.h>

#include "mdr_contact.h"

#if MDR_CFG_FIT

/** Methods of mdr_fit_curve_<type>(). */
#define MDR_FIT_FULL 1u      /**< Levenberg-Marquardt over every retract point */
#define MDR_FIT_TWO_POINT 2u /**< pull-off force and zero-force point only */

/** Branches of mdr_fit_model_<type>(). */
#define MDR_FIT_RETRACT 1u  /**< z decreasing; separates at the fold */
#define MDR_FIT_APPROACH 2u /**< z increasing; touches (and jumps in) at z - z0 = 0 */

/** Adhesion regimes by the Tabor parameter mu (mdr_tabor_<type>()). */
#define MDR_REGIME_JKR 1u        /**< mu >= MDR_MU_JKR */
#define MDR_REGIME_TRANSITION 2u /**< MDR_MU_DMT < mu < MDR_MU_JKR */
#define MDR_REGIME_DMT 3u        /**< mu <= MDR_MU_DMT */
#define MDR_MU_JKR 5.0
#define MDR_MU_DMT 0.1

/** Default equilibrium distance z_e of the Tabor parameter [m]. */
#define MDR_FIT_Z_E_DEFAULT 0.3e-9

/** Cap on Levenberg-Marquardt iterations (each one model evaluation over
 *  the curve); reaching it gives MDR_E_FITCAP. */
#define MDR_FIT_ITER_MAX 100
/** Fewest points in the retract (from the largest z on). */
#define MDR_FIT_MIN_POINTS 8
/** Fewest retract points in contact (up to and with the pull-off point). */
#define MDR_FIT_MIN_CONTACT 4
/** Fewest receding points in contact after a pinned top (from its end up
 *  to and with the pull-off point): near the fold F goes as the square
 *  root of z - z_fold, and fewer points fitted there answered E* and w up
 *  to 23 reported errors off (docs/fitting.md). */
#define MDR_FIT_MIN_RECEDE 16
/** Fewest free points after the pull-off (they give the baseline). */
#define MDR_FIT_MIN_FREE 3
/** A step (pull-off jump) or a force (contact) counts when it exceeds this
 *  many standard deviations of the noise of the free part. */
#define MDR_FIT_NOISE_SIGMAS 6.0
/** The full fit's answer must reproduce the curve: an rms residual above
 *  what counts as a force (MDR_FIT_NOISE_SIGMAS noise widths and the
 *  forces' rounding) plus this fraction of the retract's largest force is
 *  refused (MDR_E_MISFIT). 1e-3: ten times the worst relative error the
 *  fit documents for its own arithmetic (f32, 1e-4), so no rounding or
 *  resolution of the model reaches it. */
#define MDR_FIT_MISFIT_REL 1e-3

/** Workspace of mdr_fit_curve_<type>() for a curve of n points, in elements
 *  of the arithmetic's type (float or double): the contact radius of every
 *  point at the last accepted and at the trial parameters. */
#define MDR_FIT_WORK_LEN(n) (2u * (size_t)(n))

/** Name of a regime ("JKR", "transition", "DMT"); "none" for 0 and unknown
 *  values. Never NULL. */
MDR_BEGIN_DECLS
const char *mdr_regime_str(uint8_t regime);
MDR_END_DECLS

/* the declarations per arithmetic, written out from mdr_fit_t.h by
 * mk/gen_headers.py (make headers) */
#include "mdr_fit_f32.h"
#include "mdr_fit_f64.h"

#endif /* MDR_CFG_FIT */

#endif /* MDR_FIT_H */
