/* mdr_f64.c: the double arithmetic (host builds only) of every template;
 * empty when MDR_CFG_F64 is 0 (mdr_options.h). */
#define MDR_ARITH_F64
#include <stddef.h>

#include "mdr.h"

#if MDR_CFG_F64
#include "mdr_arith.h"
#include "mdr_math_t.h"

#include "mdr_math_t.c"
#include "mdr_contact_t.c"
#include "mdr_engine_t.c"
#include "mdr_scene_t.c"
#include "mdr_q31init_t.c"
#else
/* ISO C: a translation unit declares something */
typedef int mdr_f64_not_built;
#endif
