/* SPDX-License-Identifier: MIT */
/*
 * mdr_each_arith.h: includes the contract template named by MDR_TEMPLATE
 * once per floating arithmetic the build has (mdr_options.h), with
 * MDR_T = float, MDR_SFX(name) = name##_f32, then MDR_T = double,
 * MDR_SFX(name) = name##_f64. Used by mdr_contact.h, mdr_engine.h and
 * mdr_scene.h:
 *     #define MDR_TEMPLATE "mdr_scene_t.h"
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
