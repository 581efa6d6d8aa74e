/* mdr_q31.c: the integer step of the fixed-point spring engine
 * (engine/mdr_q31_step.inc); its init and tables are float and live in
 * mdr_f32.c / mdr_f64.c. No float type appears in this unit (checked by
 * make cross). Empty when MDR_CFG_Q31 is 0 (mdr_options.h). */
#include <stddef.h>

#include "mdr.h"
#include "mdr_hooks.h"

#if MDR_CFG_Q31
#include "engine/mdr_q31_step.inc"
#else
/* ISO C: a translation unit declares something */
typedef int mdr_q31_not_built;
#endif
