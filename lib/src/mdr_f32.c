/* mdr_f32.c: the float arithmetic of every template (math, contact). */
#define MDR_ARITH_F32
#include <stddef.h>

#include "mdr.h"
#include "mdr_arith.h"
#include "mdr_math_t.h"

#include "mdr_math_t.c"
#include "mdr_contact_t.c"
#include "mdr_engine_t.c"
#include "mdr_scene_t.c"
#include "mdr_q31init_t.c"
