/* SPDX-License-Identifier: MIT */
/*
 * mdr_config.h template: copy it as mdr_config.h into a directory on your
 * include path, keep the lines you want, and compile the library and your
 * code with -DMDR_USE_CONFIG. Every option, its default (1) and what it
 * removes: lib/include/mdr_options.h. Options not defined here keep their
 * default. Examples: port/configs/minimal-scene, port/configs/minimal-q31.
 */
#ifndef MDR_CONFIG_H
#define MDR_CONFIG_H

/* arithmetics */
/* #define MDR_CFG_F32 0 */     /* float */
/* #define MDR_CFG_F64 0 */     /* double */
/* #define MDR_CFG_Q31 0 */     /* fixed-point spring engine */

/* evaluation paths */
/* #define MDR_CFG_ENGINE 0 */  /* spring tables and engines */
/* #define MDR_CFG_SCENE 0 */   /* table-free scenes */
/* #define MDR_CFG_FIT 0 */     /* fitting measured force curves (mdr_fit.h) */

/* output groups */
/* #define MDR_CFG_STRESS 0 */  /* stress functions */
/* #define MDR_CFG_EVENTS 0 */  /* events and energy of scenes */

/* profiles */
/* #define MDR_CFG_PROFILE_PARABOLOID 0 */
/* #define MDR_CFG_PROFILE_CONE 0 */
/* #define MDR_CFG_PROFILE_POWERLAW 0 */
/* #define MDR_CFG_PROFILE_FLATPUNCH 0 */
/* #define MDR_CFG_PROFILE_SPHERE 0 */
/* #define MDR_CFG_PROFILE_FLATTIP 0 */
/* #define MDR_CFG_PROFILE_WAVY 0 */
/* #define MDR_CFG_PROFILE_TABLE 0 */

#endif /* MDR_CONFIG_H */
