/* SPDX-License-Identifier: MIT */
/*
 * mdr_engine.h: the real-time spring engine. A fixed-size table of springs
 * (caller-owned, or a const array generated on the host by `mdr table`) and
 * a caller-owned contact state that is stepped once per control tick with
 * the indentation d, the force F or the base position z of a compliant
 * machine. One set of functions per arithmetic (_f32; _f64 on the host); the
 * contract is written once in mdr_engine_t.h. The table-free scenes
 * (mdr_scene.h) and the fixed-point engine (mdr_q31.h) are the same state
 * machine with another edge solver or arithmetic: the events, flags, output
 * groups and energy bookkeeping below are theirs too.
 */
#ifndef MDR_ENGINE_H
#define MDR_ENGINE_H

#include <stddef.h>

#include "mdr_contact.h"

/** Fewest and most springs of a table. The upper limit keeps node indices
 *  in uint16_t and the node abscissae i*h exact to an ulp. */
#define MDR_SPRINGS_MIN 2
#define MDR_SPRINGS_MAX 16384
/** The fewest springs per wavelength at which a table of the wavy profile
 *  (MDR_PROFILE_WAVY) resolves its waves (docs/engine.md): with fewer its
 *  folds and jumps are the table's, not the profile's (the CLI's and the
 *  Python package's warnings). */
#define MDR_WAVY_SPRINGS_PER_WAVELENGTH 8
/** Springs per block of a table: after its n+1 nodes a table stores, per
 *  block of MDR_TABLE_BLOCK springs, bounds of g, G and g' over the block
 *  (two nodes each), so that the engine passes a block in one comparison
 *  where the edge cannot stop inside it (a jump across half the table
 *  costs O(n/32) comparisons, not O(n)). */
#define MDR_TABLE_BLOCK 32u
/** Blocks of a table of n springs. */
#define MDR_TABLE_BLOCKS(n) (((size_t)(n) + MDR_TABLE_BLOCK - 1u) / MDR_TABLE_BLOCK)
/** Nodes of storage for a table of n springs: its n+1 spring boundaries
 *  x_i = i*h, then two nodes of block bounds per MDR_TABLE_BLOCK springs.
 *  Size every node array with this macro. */
#define MDR_TABLE_NODES(n) ((size_t)(n) + 1u + 2u * MDR_TABLE_BLOCKS(n))
/** Bytes of node storage for n springs, per arithmetic. */
#define MDR_TABLE_BYTES_F32(n) (MDR_TABLE_NODES(n) * sizeof(mdr_node_f32))
#define MDR_TABLE_BYTES_F64(n) (MDR_TABLE_NODES(n) * sizeof(mdr_node_f64))
/** The adhesion a float engine resolves (f32, f64; w > 0): init refuses
 *  (MDR_E_PARAM) a table on which a pull-off lies so deep inside the first
 *  spring that the spring's quadratic gives g there only to a relative
 *  rounding bound above 1/MDR_ENGINE_ADH_COND (on a profile flat at 0,
 *  2 eps/e at the fraction e of the spring: a first spring more than
 *  about 2^10 / eps pull-off radii wide; the pull-off force is off by 0.3
 *  to 0.6 of that bound). More springs or a smaller table length resolve
 *  it; q31's own limit is MDR_Q31_ADH_LSB. */
#define MDR_ENGINE_ADH_COND 1024
/** Fewest points of a tabulated gap profile r_i, f(r_i). */
#define MDR_TABLE_MIN_POINTS 3

/** Events of a step (mdr_step_<type>.event). When several happen in one
 *  step, the last one is reported and mdr_step.jumps counts the jumps. */
#define MDR_EV_NONE 0u       /**< quasi-static: edge pinned or moving smoothly */
#define MDR_EV_CONTACT 1u    /**< first touch of this instance, without a jump (w_adv = 0) */
#define MDR_EV_JUMP_IN 2u    /**< touch followed by a jump into contact (w_adv > 0; or a fold of a wavy profile in the touch's tick) */
#define MDR_EV_JUMP 3u       /**< jump of the edge inside contact (wavy profile) */
#define MDR_EV_PULL_OFF 4u   /**< jump to complete separation (an unstable end of the branch) */
#define MDR_EV_RECONTACT 5u  /**< touch after a separation, without a jump */
#define MDR_EV_SEPARATION 6u /**< contact shrank smoothly to a = 0 (no adhesion hysteresis left) */

/** Sticky flags (.flags of every engine): set by a step, cleared only by
 *  the engine's clear-flags function. */
#define MDR_FLAG_OUTSIDE 1u  /**< a step was refused: the edge would leave the table */
#define MDR_FLAG_NOCONV 2u   /**< a root or fold search hit its iteration cap */

/** Output groups of every engine (spring, scene, q31): what a step writes
 *  into its mdr_step_<type> besides F and d, and what it keeps. A step
 *  computes only what is asked for. Spring engines start with
 *  MDR_OUT_ALL | MDR_OUT_ENERGY (mdr_engine_outputs_<type>() changes it);
 *  scenes take theirs at init. */
#define MDR_OUT_FORCE 0u  /**< out->F and out->d only */
#define MDR_OUT_RADIUS 1u /**< + out->a */
#define MDR_OUT_EVENTS 2u /**< + out->z, event, jumps, a0/d0/F0, a1/d1/F1 */
#define MDR_OUT_ALL 3u    /**< every field of mdr_step_<type> */
#define MDR_OUT_ENERGY 4u /**< keep the energy bookkeeping (spring engines; a scene keeps
                               it in the mdr_energy_<type> given to its init) */

/** Short English name of an event code ("pull-off", ...). Never NULL. */
MDR_BEGIN_DECLS
const char *mdr_event_str(uint8_t event);
MDR_END_DECLS

/* the declarations per arithmetic, written out from mdr_engine_t.h by
 * mk/gen_headers.py (make headers) */
#include "mdr_engine_f32.h"
#include "mdr_engine_f64.h"

#endif /* MDR_ENGINE_H */
