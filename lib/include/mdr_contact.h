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

#define MDR_TEMPLATE "mdr_contact_t.h"
#include "mdr_each_arith.h"

/** Cap on the downward scan of mdr_critical_<type>() (grid steps). */
#define MDR_CRIT_SCAN_MAX 8192

#endif /* MDR_CONTACT_H */
