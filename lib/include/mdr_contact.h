/* SPDX-License-Identifier: MIT */
/*
 * mdr_contact.h: equilibrium, stability, critical states and stress of an
 * adhesive axisymmetric contact (closed forms of the equivalent profile).
 * One set of functions per arithmetic: _f32 (float, for FPU cores) and _f64
 * (double, host builds; not compiled for targets). See mdr_contact_t.h for the
 * contract, written once for both.
 */
#ifndef MDR_CONTACT_H
#define MDR_CONTACT_H

#include "mdr_types.h"

/* the declarations per arithmetic, written out from mdr_contact_t.h by
 * mk/gen_headers.py (make headers) */
#include "mdr_contact_f32.h"
#include "mdr_contact_f64.h"

/** Cap on the cells walked by mdr_critical_<type>() (beyond:
 *  MDR_E_NOCONV): the wavy profile takes four per wavelength below the
 *  radius above which it is stable under every control (65536 wavelengths),
 *  a table two per sample interval (every table fits). */
#define MDR_CRIT_SCAN_MAX 262144

/** The band around n = 1/2 in which mdr_critical_<type>() refuses a power
 *  law with adhesion (MDR_E_RADIUS): |n - 1/2| <= MDR_CRIT_HALF_BAND eps,
 *  eps the arithmetic's unit roundoff (2^-53 in f64, 2^-24 in f32), where
 *  its critical radius is not resolved to 1 %. */
#define MDR_CRIT_HALF_BAND 1024

#endif /* MDR_CONTACT_H */
