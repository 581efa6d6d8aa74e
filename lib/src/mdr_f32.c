/* SPDX-License-Identifier: MIT */
/* mdr_f32.c: the float arithmetic of every template (math, profiles, tables,
 * equilibrium, engines, q31 init); empty when MDR_CFG_F32 is 0 (mdr_options.h). */
#define MDR_ARITH_F32
#include <stddef.h>

#include "mdr.h"

#if MDR_CFG_F32
#include "mdr_float.inc"
#else
/* ISO C: a translation unit declares something */
typedef int mdr_f32_not_built;
#endif
