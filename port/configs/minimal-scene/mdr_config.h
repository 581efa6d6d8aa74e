/* SPDX-License-Identifier: MIT */
/*
 * mdr_config.h of the minimal scene (make size: m4f-scene): a gripper
 * finger that needs the force on a paraboloid, in float, and nothing else.
 * Everything not listed keeps its default (lib/include/mdr_options.h).
 */
#ifndef MDR_CONFIG_H
#define MDR_CONFIG_H

#define MDR_CFG_F64 0    /* float only */
#define MDR_CFG_Q31 0
#define MDR_CFG_ENGINE 0 /* table-free: no spring tables */
#define MDR_CFG_STRESS 0
#define MDR_CFG_EVENTS 0 /* force (and radius) only */
#define MDR_CFG_PROFILE_CONE 0
#define MDR_CFG_PROFILE_POWERLAW 0
#define MDR_CFG_PROFILE_FLATPUNCH 0
#define MDR_CFG_PROFILE_SPHERE 0
#define MDR_CFG_PROFILE_FLATTIP 0
#define MDR_CFG_PROFILE_WAVY 0
#define MDR_CFG_PROFILE_TABLE 0

#endif /* MDR_CONFIG_H */
