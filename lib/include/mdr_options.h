/* SPDX-License-Identifier: MIT */
/*
 * mdr_options.h: every compile-time option of libmdr with its default, in
 * one place. Included by mdr_types.h (so by every header and source).
 *
 * To change an option, either
 *   - write your own mdr_config.h (any directory on your include path) with
 *     the #defines you want and compile the library AND your code with
 *     -DMDR_USE_CONFIG (lib/mdr_config.example.h is a commented template), or
 *   - give the same -D options to every compilation.
 * The library and the code that calls it must see the same options (the
 * declarations of removed functions disappear; no type changes its layout).
 *
 * Without any option everything is built; a firmware that links with
 * --gc-sections (the sources are compiled with -ffunction-sections
 * -fdata-sections) already pays only for the functions it calls: the
 * options below remove code a linker cannot see is unused (a profile behind
 * a run-time kind, the event and energy code inside the scene step), make
 * the removal explicit, and shorten the build.
 *
 * Each option is 0 (removed) or 1 (built, the default).
 *
 * Arithmetics
 *   MDR_CFG_F32      float: closed forms, stress, spring engine, scenes, the
 *                    q31 init in float and the q31 <-> SI helpers
 *   MDR_CFG_F64      double: the same in double (host-side analysis; soft
 *                    double on cores without a double FPU). MDR_NO_F64,
 *                    defined, is the older spelling of MDR_CFG_F64 = 0.
 *   MDR_CFG_Q31      the fixed-point spring engine (needs MDR_CFG_ENGINE and
 *                    a float arithmetic for its init)
 * Evaluation paths
 *   MDR_CFG_ENGINE   spring tables and the spring engine (mdr_engine_t.h)
 *   MDR_CFG_SCENE    table-free scenes (mdr_scene_t.h)
 *   MDR_CFG_FIT      fitting measured force curves (mdr_fit.h): E*, w,
 *                    contact point and baseline, two-point method, regime
 * Output groups
 *   MDR_CFG_STRESS   stress: mdr_stress(), mdr_stress_at(),
 *                    mdr_stress_intensity() and their quadrature table
 *   MDR_CFG_EVENTS   events, jump states and dissipated energy of scenes:
 *                    with 0 a scene computes F, d and a only, and its init
 *                    refuses MDR_OUT_EVENTS and an energy struct with
 *                    MDR_E_DISABLED. (The spring engines always report
 *                    events and energy: their state carries them.)
 * Profiles (closed forms, tables from a profile, scenes): a removed profile
 *   gives MDR_E_DISABLED from every init that names it, and its code (and
 *   special functions: Struve for the wavy profile, atanh for the sphere,
 *   Gamma and powers for power laws, sin/cos/log for the cone) is not built.
 *   MDR_CFG_PROFILE_PARABOLOID, _CONE, _POWERLAW, _FLATPUNCH, _SPHERE,
 *   _FLATTIP, _WAVY, _TABLE (sampled profiles in the contact module; the
 *   spring tables of sampled profiles, mdr_table_init_gap(), come with
 *   MDR_CFG_ENGINE)
 */
#ifndef MDR_OPTIONS_H
#define MDR_OPTIONS_H

#ifdef MDR_USE_CONFIG
#include "mdr_config.h"
#endif

#if defined(MDR_NO_F64) && !defined(MDR_CFG_F64)
#define MDR_CFG_F64 0
#endif

#ifndef MDR_CFG_F32
#define MDR_CFG_F32 1
#endif
#ifndef MDR_CFG_F64
#define MDR_CFG_F64 1
#endif
#ifndef MDR_CFG_Q31
#define MDR_CFG_Q31 1
#endif
#ifndef MDR_CFG_ENGINE
#define MDR_CFG_ENGINE 1
#endif
#ifndef MDR_CFG_SCENE
#define MDR_CFG_SCENE 1
#endif
#ifndef MDR_CFG_FIT
#define MDR_CFG_FIT 1
#endif
#ifndef MDR_CFG_STRESS
#define MDR_CFG_STRESS 1
#endif
#ifndef MDR_CFG_EVENTS
#define MDR_CFG_EVENTS 1
#endif
#ifndef MDR_CFG_PROFILE_PARABOLOID
#define MDR_CFG_PROFILE_PARABOLOID 1
#endif
#ifndef MDR_CFG_PROFILE_CONE
#define MDR_CFG_PROFILE_CONE 1
#endif
#ifndef MDR_CFG_PROFILE_POWERLAW
#define MDR_CFG_PROFILE_POWERLAW 1
#endif
#ifndef MDR_CFG_PROFILE_FLATPUNCH
#define MDR_CFG_PROFILE_FLATPUNCH 1
#endif
#ifndef MDR_CFG_PROFILE_SPHERE
#define MDR_CFG_PROFILE_SPHERE 1
#endif
#ifndef MDR_CFG_PROFILE_FLATTIP
#define MDR_CFG_PROFILE_FLATTIP 1
#endif
#ifndef MDR_CFG_PROFILE_WAVY
#define MDR_CFG_PROFILE_WAVY 1
#endif
#ifndef MDR_CFG_PROFILE_TABLE
#define MDR_CFG_PROFILE_TABLE 1
#endif

/* combinations that cannot work */
#if MDR_CFG_Q31 && !MDR_CFG_ENGINE
#error "MDR_CFG_Q31 needs MDR_CFG_ENGINE (the q31 engine steps a spring table)"
#endif
#if MDR_CFG_Q31 && !MDR_CFG_F32 && !MDR_CFG_F64
#error "MDR_CFG_Q31 needs MDR_CFG_F32 or MDR_CFG_F64 (its init and table conversion)"
#endif

/** 1 if profile kind k (MDR_PROFILE_*) is built (a constant expression;
 *  the kinds are defined in mdr_types.h, before any use expands it). */
#define MDR_CFG_HAS_PROFILE(k)                                                           \
    ((k) == MDR_PROFILE_PARABOLOID  ? MDR_CFG_PROFILE_PARABOLOID                         \
     : (k) == MDR_PROFILE_CONE      ? MDR_CFG_PROFILE_CONE                               \
     : (k) == MDR_PROFILE_POWERLAW  ? MDR_CFG_PROFILE_POWERLAW                           \
     : (k) == MDR_PROFILE_FLATPUNCH ? MDR_CFG_PROFILE_FLATPUNCH                          \
     : (k) == MDR_PROFILE_SPHERE    ? MDR_CFG_PROFILE_SPHERE                             \
     : (k) == MDR_PROFILE_FLATTIP   ? MDR_CFG_PROFILE_FLATTIP                            \
     : (k) == MDR_PROFILE_WAVY      ? MDR_CFG_PROFILE_WAVY                               \
     : (k) == MDR_PROFILE_TABLE     ? MDR_CFG_PROFILE_TABLE                              \
                                    : 0)

#endif /* MDR_OPTIONS_H */
