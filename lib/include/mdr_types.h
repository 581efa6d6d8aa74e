/* SPDX-License-Identifier: MIT */
/*
 * libmdr: adhesive (JKR-type) normal contact of axisymmetric bodies by the
 * Method of Dimensionality Reduction.
 *
 * mdr_types.h: status codes, profile kinds and control modes shared by every
 * arithmetic. Needs only <stdint.h> and <stdbool.h>.
 *
 * Conventions used throughout the library (SI units everywhere):
 *   - compressive normal force F is positive, adhesive (tensile) force negative;
 *   - indentation depth d is positive into the surface;
 *   - normal stress sigma is negative in compression (eq. 4.42);
 *   - w is the WORK of adhesion (Dupre energy, eq. 4.5), not the surface
 *     energy of one body: a paraboloid pulls off at F = -1.5*pi*w*R.
 */
#ifndef MDR_TYPES_H
#define MDR_TYPES_H

#include <stdbool.h>
#include <stdint.h>

#include "mdr_options.h"

/** The public functions have C linkage in a C++ translation unit too
 *  (firmware written in C++ includes these headers as they are). */
#ifdef __cplusplus
#define MDR_BEGIN_DECLS extern "C" {
#define MDR_END_DECLS }
#else
#define MDR_BEGIN_DECLS
#define MDR_END_DECLS
#endif

/** Status code of every fallible call: MDR_OK or a negative named error.
 *  int8_t, not an enum, so that its size is the same on every ABI. */
typedef int8_t mdr_status;

#define MDR_OK 0
/** A required pointer argument is NULL. */
#define MDR_E_NULL (-1)
/** An input is NaN or +-inf. */
#define MDR_E_NONFINITE (-2)
/** A material or profile parameter is outside its documented range. */
#define MDR_E_PARAM (-3)
/** Unknown profile kind. */
#define MDR_E_KIND (-4)
/** Contact radius a outside the profile's domain (a <= 0, a >= R for the
 *  exact sphere, a > a0 for the flat punch, a > r[m-1] for a tabulated
 *  profile, a/lambda >= 2^46 (f32) or 2^104 (f64) for the wavy profile);
 *  from mdr_critical(): no stable state at or above the start (the contact
 *  would grow without bound when pressed there, or the stable branch lies
 *  beyond the last sample of a table), or a critical radius beyond the
 *  arithmetic's resolution (the sphere's within one ulp of R, a power
 *  law's with n within 2^10 eps of 1/2, mdr_critical_<type>()). */
#define MDR_E_RADIUS (-5)
/** Radial position r outside [0, a). */
#define MDR_E_POSITION (-6)
/** Unknown control mode, or machine stiffness k_m not finite and > 0, or
 *  out of the engine's range (q31: kappa = 2 E* L / k_m above 2^16, a lever
 *  far softer than the contact; float: (2 E*) / k_m not finite). */
#define MDR_E_CONTROL (-7)
/** An iteration reached its fixed cap without converging. */
#define MDR_E_NOCONV (-8)
/** The requested quantity is infinite at this point (stress at the tip of a
 *  cone or of a power law with n <= 1, at the rim r = b of a flattened tip). */
#define MDR_E_SINGULAR (-9)
/** A result would overflow the arithmetic's range (no inf or NaN escapes),
 *  or a spring table lies so far below it that its values lose their
 *  digits (curvature terms or integrals not normal numbers). */
#define MDR_E_OVERFLOW (-10)
/** The contact edge would move past the last spring of the table (the
 *  engine's state is left as it was and MDR_FLAG_OUTSIDE is set). */
#define MDR_E_OUTSIDE (-11)
/** A tabulated profile is unusable: r not strictly increasing from r = 0,
 *  fewer than MDR_TABLE_MIN_POINTS points, or g(0) != 0. */
#define MDR_E_TABLE (-12)
/** Number of springs outside [MDR_SPRINGS_MIN, MDR_SPRINGS_MAX]. */
#define MDR_E_SIZE (-13)
/** The profile, output group or feature asked for was removed from this
 *  build by a compile-time option (mdr_options.h). */
#define MDR_E_DISABLED (-14)
/** Fit (mdr_fit.h): too few points in the curve's retract, or in contact. */
#define MDR_E_FEW (-15)
/** Fit: the base position z is not monotonic within the retract (or within
 *  the approach when it is fitted). */
#define MDR_E_ORDER (-16)
/** Fit: no contact in the curve (no retract force above the baseline by
 *  more than the noise). */
#define MDR_E_NOCONTACT (-17)
/** Fit: the curve never separates (no pull-off jump back to the baseline
 *  followed by free points), or shows no adhesion. */
#define MDR_E_NOPULLOFF (-18)
/** Fit: Levenberg-Marquardt reached its iteration cap (MDR_FIT_ITER_MAX). */
#define MDR_E_FITCAP (-19)
/** Fit: the data do not determine the parameters (singular normal
 *  equations, or the two-point equations have no solution). */
#define MDR_E_DEGENERATE (-20)
/** Fit: the model's retract jumps to a smaller stable contact before the
 *  pull-off (wavy profiles): the one-branch model does not apply. */
#define MDR_E_JUMPS (-21)
/** Fit: the retract's contact part is straight down to its pull-off, and a
 *  straight line explains it better than the receding branch: a contact
 *  pinned at one radius until it ruptures (w_adv < w), which does not
 *  determine E* and w; or, in noisy data, a pinned top could hide in it
 *  (a receding branch with a larger E* meets the samples as well) and
 *  neither the caller (opts.unpinned) nor the approach (w_adv within
 *  MDR_FIT_NOISE_SIGMAS errors of w) rules it out. */
#define MDR_E_PINNED (-22)
/** Fit: the fitted model does not reproduce the curve: its rms residual
 *  exceeds what counts as a force in the data (MDR_FIT_NOISE_SIGMAS noise
 *  widths) by more than MDR_FIT_MISFIT_REL of the curve's force scale. A
 *  minimum away from the answer (a poor first guess), units that are not
 *  SI (z in nm), or a curve the model does not describe. */
#define MDR_E_MISFIT (-23)

/** Profile kinds (uint8_t values; the meaning of p[0..2] for each). */
#define MDR_PROFILE_PARABOLOID 1u /**< f = r^2/(2R);          p = {R}            */
#define MDR_PROFILE_CONE 2u       /**< f = tan(theta)*r;      p = {theta [rad]}  */
#define MDR_PROFILE_POWERLAW 3u   /**< f = C*r^n;             p = {C [m^(1-n)], n} */
#define MDR_PROFILE_FLATPUNCH 4u  /**< flat cylinder radius a0; p = {a0}          */
#define MDR_PROFILE_SPHERE 5u     /**< f = R - sqrt(R^2-r^2); p = {R}            */
#define MDR_PROFILE_FLATTIP 6u    /**< paraboloid, flat for r<b; p = {R, b}      */
#define MDR_PROFILE_WAVY 7u       /**< r^2/(2R)+h(1-cos(2 pi r/lambda)); p = {R, h, lambda} */
#define MDR_PROFILE_TABLE 8u      /**< sampled f(r_i) (a measured or worn tip): mdr_contact_init_table() */

/** Control modes: what the device holds fixed while the contact evolves. */
#define MDR_CONTROL_LOAD 1u    /**< force F controlled (fixed load, k = 2/3 in 4.23)  */
#define MDR_CONTROL_GRIPS 2u   /**< depth d controlled (fixed grips, k = 2 in 4.23)  */
#define MDR_CONTROL_MACHINE 3u /**< base z = d + F/k_m controlled through stiffness k_m */

/** Largest power-law exponent accepted (keeps a^n inside float range for
 *  every contact radius between 1e-12 m and 1 m). */
#define MDR_POWERLAW_N_MAX 8

/** Short English name of a status code ("ok", "null pointer", ...).
 *  Never returns NULL; unknown codes give "unknown status". */
MDR_BEGIN_DECLS
const char *mdr_status_str(mdr_status s);
MDR_END_DECLS

#endif /* MDR_TYPES_H */
