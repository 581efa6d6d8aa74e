/* SPDX-License-Identifier: MIT */
/* mdr_f64.c: the double arithmetic (host builds only) of every template; empty when MDR_CFG_F64 is 0 (mdr_options.h). */
#define MDR_ARITH_F64
#include <stddef.h>

#include "mdr.h"

#if MDR_CFG_F64
#include "mdr_float.inc"
#else
/* ISO C: a translation unit declares something */
typedef int mdr_f64_not_built;
#endif
