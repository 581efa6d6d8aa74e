/* SPDX-License-Identifier: MIT */
/*
 * mdr_scene_q31.h: the table-free scene (mdr_scene_t.h) in fixed point, for
 * cores without an FPU. The same solver as the float scenes (one source:
 * lib/src/engine/mdr_edge_mono.inc) over integer kernels; the step uses
 * 32-bit integers with 32x32->64 products and one normalised 32-bit
 * division per Newton step (no float, no 64-bit division, no soft-float
 * call), so the same inputs give bit-identical outputs on every compiler and
 * core. Same state machine, events and energy bookkeeping as the q31 spring
 * engine (mdr_q31.h), same step struct, same Q formats of its inputs and
 * outputs.
 *
 * Units. A q31 scene is made at init (float, or double on the host) from an
 * initialised float scene of g(x) = C x^n and the largest contact radius
 * the cycle reaches, a_max:
 *   L   = a_s 4^k, the least such >= a_max (a_s: the float scene's radius
 *         unit, so that sqrt(a/L) is the float scene's tau / 2^k exactly)
 *   D0  = a power of two >= g(L) + c_w sqrt(L) [m] (every equilibrium
 *         depth with a <= L lies in |d| <= D0)
 *   F0  = 2 E* L D0 [N],  Z0 = 2^sz D0 [m], sz = floor(log2(1 + kappa)),
 *         kappa = 2 E* L / k_m,  W0 = F0 D0 [J]
 * as the q31 spring engine's with L in place of its table's x_max.
 *
 * Formats ("Qm.f": value = raw * unit * 2^-f):
 *   the edge tau = sqrt(a/L)  int32 Q1.30 (0 ... 2^30)
 *   a (outputs)               int32 Q1.30 of L
 *   d, F, z                   int32 Q2.29 of D0, F0, Z0
 *   work, dissipated          int64 Q15.48 of W0
 *   inside: g(L)/D0 Q1.30; c_w sqrt(L)/D0, the branch U and its slope
 *   Q2.29 (int64); U'' Q2.29 per unit tau^2.
 * Documented input range of every step: |d|, |F|, |z| <= 2 units (raw
 * +-2^30); beyond it the input saturates to +-2^30 and sets the sticky
 * MDR_FLAG_SAT; a result that does not fit its format saturates and sets
 * the same flag. Nothing wraps. An edge that would pass a = L is refused
 * (MDR_E_OUTSIDE, MDR_FLAG_OUTSIDE, state unchanged): L is the scene's
 * range as x_max is a table's.
 *
 * Accuracy: the Newton root is exact to half an LSB of tau (the quadratic
 * stopping rule) plus U's rounding (a few LSB of Q2.29); d and F within a
 * few LSB of the f64 scene at the same control over whole cycles (the
 * tolerances measured by host_tests/test_scene.c) whose approach goes
 * deeper than a few hundred LSB of d: a shallower contact's radius is
 * resolved only to the rounding of g there, ~1 LSB / (a g'(a)) relative,
 * and a contact pinned at it keeps that error to its pull-off
 * (docs/fixed-point.md, "Resolution of the profile near the apex").
 */
#ifndef MDR_SCENE_Q31_H
#define MDR_SCENE_Q31_H

#include <stdint.h>

#include "mdr_q31.h"
#include "mdr_scene.h"

#if MDR_CFG_Q31 && MDR_CFG_SCENE
MDR_BEGIN_DECLS

/** A q31 scene: units, constants and state. Caller-owned; fill it with
 *  mdr_scene_init_q31_f32() or _f64(), change it only through the step
 *  functions. */
typedef struct {
    float L, D0, F0, Z0;  /**< units [m, m, N, m] as float (conversions; not used by the step) */
    int32_t gc;           /**< g(L)/D0 = C L^n/D0, Q1.30 */
    int32_t c_w, c_adv;   /**< dl(L)/D0 on retraction / approach, Q2.29 */
    int32_t al_z, ka_z;   /**< machine branch weights 1/(1+kappa), kappa/(1+kappa), Q1.30 */
    int32_t z_in;         /**< 2^sz/(1+kappa), Q1.30: internal control = z * z_in */
    int32_t z_k;          /**< kappa/2^sz, Q1.30: z = d/2^sz + z_k F */
    int32_t z_min;        /**< the least raw z a separated step_z answers without its full tick:
                               max(-2^30, -2^(31-sz)), so that z 2^sz fits (INT32_MAX without a machine) */
    int32_t z_mul;        /**< 2^sz: a separated machine's depth d = z 2^sz (Q2.29 of D0) */
    int32_t nu, in1;      /**< n/(n+1), 1/(n+1), Q1.30 */
    int32_t kn_z;         /**< ka_z nu rounded, Q1.30: the machine branch's weight of nu g x */
    int32_t t1;           /**< sqrt(a_s/L), Q1.30: where a root search from a = 0 starts */
    int32_t tf[3];        /**< the retraction branch's fold, tau Q1.30: load, grips, machine */
    int32_t uf[3];        /**< the branch there, Q2.29 (rounded up: below it a receding
                               tick takes the slow path) */
    int32_t tau;          /**< the edge sqrt(a/L), Q1.30; 0 when separated */
    int32_t d;            /**< indentation, Q2.29 of D0 */
    int32_t F;            /**< force, Q2.29 of F0 */
    mdr_pinned_q31 pin;   /**< the pinned edge for control mode `mode` */
    mdr_energy_q31 en;    /**< energy bookkeeping (with MDR_OUT_ENERGY), Q15.48 of W0 */
    uint8_t n;            /**< exponent of g = C x^n */
    uint8_t sz;           /**< Z0 = 2^sz D0 */
    uint8_t machine;      /**< 1 if k_m > 0 */
    uint8_t contact;      /**< 1 in contact, 0 separated */
    uint8_t touched;      /**< 1 once the scene has been in contact */
    uint8_t flags;        /**< sticky MDR_FLAG_* (MDR_FLAG_SAT, MDR_FLAG_OUTSIDE, MDR_FLAG_NOCONV) */
    uint8_t outputs;      /**< MDR_OUT_* of the float scene (MDR_OUT_ENERGY: en kept) */
    uint8_t mode;         /**< control mode (MDR_CONTROL_*) of the pinned edge, bit 7 set while a move has left its linear coefficients (pin) to the next pinned tick; 0 exactly when separated */
    int32_t mv_c, mv_d; /**< internal: where the step's last fast move began (the edge's
                             coordinate, d raw), for its work (MDR_OUT_ENERGY) */
} mdr_scene_q31;

#if MDR_CFG_F32
/**
 * @brief A q31 scene from a float scene (init time, float arithmetic; the
 *        _f64 version from a double scene to ~2^-30), separated. Takes the
 *        float scene's profile, material, machine and outputs (an energy
 *        struct given to it: the q31 scene keeps its own, MDR_OUT_ENERGY),
 *        not its state. Chooses L, D0, F0, Z0 (top of this file) and the
 *        constants, rounded to nearest; the retraction folds from the float
 *        scene's (to its precision: the fold's position enters U at second
 *        order).
 * @param[out] q     the q31 scene; untouched unless MDR_OK
 * @param[in]  s     an initialised float scene (mdr_scene_init_*_f32)
 * @param[in]  a_max the largest contact radius the scene must reach [m],
 *                   finite > 0; its L (above, the least a_s 4^k >= a_max)
 *                   must reach the fold radius of the retraction branch
 *                   under every control (the JKR pull-off radius under
 *                   fixed load, a little above the float scene's
 *                   a_s tf[0]^2): an a_max below that fold is accepted
 *                   where its L reaches it
 * @return MDR_OK, MDR_E_NULL, MDR_E_NONFINITE (a_max), MDR_E_PARAM (a_max
 *         <= 0, L below a retraction fold, or so far above it that the
 *         pull-off force is below MDR_Q31_ADH_LSB LSB of F: with w > 0;
 *         the adhesion unresolved), MDR_E_CONTROL (kappa =
 *         2 E* L/k_m > 2^16), MDR_E_OVERFLOW (a unit beyond float range,
 *         or g(L)/D0 below 2^-30: a_max far below the adhesive range)
 */
mdr_status mdr_scene_init_q31_f32(mdr_scene_q31 *q, const mdr_scene_f32 *s, float a_max);
#endif
#if MDR_CFG_F64
/** @brief As mdr_scene_init_q31_f32(), from a double scene (host). */
mdr_status mdr_scene_init_q31_f64(mdr_scene_q31 *q, const mdr_scene_f64 *s, double a_max);
#endif

/**
 * @brief One tick at fixed grips: d, Q2.29 of D0, documented |d| <= 2^30.
 *        Integer arithmetic only.
 * @param[in,out] s  the scene; unchanged unless MDR_OK (but for its sticky flags)
 * @param[in]  d    indentation, Q2.29 of D0; beyond +-2^30 saturated, MDR_FLAG_SAT
 * @param[out] out  what happened (formats above); only the fields of
 *                  s->outputs are written (d and F always), only on MDR_OK
 * @return MDR_OK; MDR_E_NULL; MDR_E_OUTSIDE (the edge would pass a = L:
 *         state unchanged, MDR_FLAG_OUTSIDE); MDR_E_NOCONV (not expected:
 *         bisection backs every iteration; MDR_FLAG_NOCONV)
 *
 * Cost: pinned edge, two comparisons and two products (the first pinned
 * tick after a move computes the pinned relation once: a few normalised
 * 32-bit divisions); moving edge, Newton from the tangent at the edge (one
 * normalised 32-bit division per step, usually one step).
 */
mdr_status mdr_scene_step_d_q31(mdr_scene_q31 *s, int32_t d, mdr_step_q31 *out);
/** @brief One tick at fixed load: F, Q2.29 of F0; see step_d. While
 *  separated out->F = 0 and d keeps the depth at which contact was lost. */
mdr_status mdr_scene_step_F_q31(mdr_scene_q31 *s, int32_t F, mdr_step_q31 *out);
/** @brief One tick of the machine base: z, Q2.29 of Z0; see step_d.
 *  MDR_E_CONTROL without a machine. */
mdr_status mdr_scene_step_z_q31(mdr_scene_q31 *s, int32_t z, mdr_step_q31 *out);
/** @brief Clear the sticky flags; returns those that were set (0 for NULL). */
uint8_t mdr_scene_clear_flags_q31(mdr_scene_q31 *s);

#if MDR_CFG_F32
/**
 * @brief SI value -> raw q31 value of quantity q (MDR_Q_A/D/F/Z) in the
 *        scene's units, rounded to nearest (float; as mdr_q31_from_si()).
 * @return MDR_OK, MDR_E_NULL (s or raw), MDR_E_PARAM (an unknown q),
 *         MDR_E_NONFINITE (v NaN or infinite), MDR_E_OVERFLOW (v / unit
 *         outside the int32 range); *raw untouched unless MDR_OK
 */
mdr_status mdr_scene_q31_from_si(const mdr_scene_q31 *s, uint8_t q, float v, int32_t *raw);
/** @brief Raw q31 value of quantity q -> SI (float); 0 for NULL. */
float mdr_scene_q31_out(const mdr_scene_q31 *s, uint8_t q, int32_t v);
/** @brief Raw Q15.48 energy -> J (float); 0 for NULL. */
float mdr_scene_q31_energy(const mdr_scene_q31 *s, int64_t v);
#endif

MDR_END_DECLS
#endif /* MDR_CFG_Q31 && MDR_CFG_SCENE */
#endif /* MDR_SCENE_Q31_H */
