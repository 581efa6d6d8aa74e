/* mdr_f32.c: the float arithmetic of every template (math, contact, engine, scene, q31 init); empty
 * when MDR_CFG_F32 is 0 (mdr_options.h). */
#define MDR_ARITH_F32
#include <stddef.h>

#include "mdr.h"

#if MDR_CFG_F32
#include "mdr_arith.h"
#include "mdr_math_t.h"

#include "mdr_math_t.c"
#include "mdr_contact_t.c"
#include "mdr_engine_t.c"
#include "mdr_scene_t.c"
#include "mdr_q31init_t.c"
#else
/* ISO C: a translation unit declares something */
typedef int mdr_f32_not_built;
#endif
