/* mdr_f64.c: the double arithmetic (host builds only) of every template (math, contact). */
#define MDR_ARITH_F64
#include <stddef.h>

#include "mdr.h"
#include "mdr_arith.h"
#include "mdr_math_t.h"

#include "mdr_math_t.c"
#include "mdr_contact_t.c"
#include "mdr_engine_t.c"
#include "mdr_scene_t.c"
#include "mdr_q31init_t.c"
