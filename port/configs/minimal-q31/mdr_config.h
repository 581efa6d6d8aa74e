/* SPDX-License-Identifier: MIT */
/*
 * mdr_config.h of the minimal q31 scene (make size: m0-q31min): a
 * Cortex-M0 steps a paraboloid finger in fixed point on a const spring
 * table generated on the host (`mdr table --arith q31`), initialised once
 * in float. Everything not listed keeps its default
 * (lib/include/mdr_options.h).
 */
#ifndef MDR_CONFIG_H
#define MDR_CONFIG_H

#define MDR_CFG_F64 0   /* the init in float only */
#define MDR_CFG_SCENE 0 /* the table-free scenes are float */
#define MDR_CFG_STRESS 0
#define MDR_CFG_PROFILE_CONE 0
#define MDR_CFG_PROFILE_POWERLAW 0
#define MDR_CFG_PROFILE_FLATPUNCH 0
#define MDR_CFG_PROFILE_SPHERE 0
#define MDR_CFG_PROFILE_FLATTIP 0
#define MDR_CFG_PROFILE_WAVY 0
#define MDR_CFG_PROFILE_TABLE 0

#endif /* MDR_CONFIG_H */
