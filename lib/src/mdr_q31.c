/* SPDX-License-Identifier: MIT */
/* mdr_q31.c: the integer step of the fixed-point engines: the state machine
 * and the spring solver written once for every arithmetic
 * (engine/mdr_machine.inc, engine/mdr_edge_table.inc) over the q31
 * arithmetic (mdr_arith_q31.h, engine/mdr_engine_q31.inc,
 * engine/mdr_table_int.inc), and the table-free scene's solver
 * (engine/mdr_edge_mono.inc) over its integer kernels
 * (engine/mdr_mono_int.inc); their init and tables are float and live in
 * mdr_f32.c / mdr_f64.c. No float type appears in this unit (checked by
 * make cross). Empty when MDR_CFG_Q31 is 0 (mdr_options.h). */
#include <stdbool.h>
#include <stddef.h>

#include "mdr.h"
#include "mdr_arith_q31.h"

#if MDR_CFG_Q31
#include "engine/mdr_engine_q31.inc"
#include "engine/mdr_table_int.inc"
#include "engine/mdr_edge_table.inc"
#include "engine/mdr_mono_int.inc"
#include "engine/mdr_edge_mono.inc"
#else
/* ISO C: a translation unit declares something */
typedef int mdr_q31_not_built;
#endif
