/* SPDX-License-Identifier: MIT */
/*
 * mdr_each_arith.h: includes the contract template named by MDR_TEMPLATE
 * once per floating arithmetic the build has (mdr_options.h), with
 * MDR_T = float, MDR_SFX(name) = name##_f32, then MDR_T = double,
 * MDR_SFX(name) = name##_f64. The public headers include the generated
 * per-arithmetic ones (mdr_scene_f32.h, ..., written out by
 * mk/gen_headers.py); this file serves code written once for both
 * arithmetics outside lib/ (the Python package's python/src):
 *     #define MDR_TEMPLATE "mdr_py_t.h"
 *     #include "mdr_each_arith.h"
 * No include guard: it is meant to be included once per template.
 */
#if MDR_CFG_F32
#define MDR_T float
#define MDR_SFX(name) name##_f32
#include MDR_TEMPLATE
#undef MDR_T
#undef MDR_SFX
#endif

#if MDR_CFG_F64
#define MDR_T double
#define MDR_SFX(name) name##_f64
#include MDR_TEMPLATE
#undef MDR_T
#undef MDR_SFX
#endif

#undef MDR_TEMPLATE
