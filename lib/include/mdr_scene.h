/*
 * mdr_scene.h: table-free scenes. Profiles whose equivalent profile is a
 * monomial (paraboloid, cone, power laws with integer n) stepped like the
 * spring engine with no spring table, computing only the outputs a scene
 * asks for. One set of functions per arithmetic (_f32; _f64 on the host);
 * the contract is written once in mdr_scene_t.h.
 */
#ifndef MDR_SCENE_H
#define MDR_SCENE_H

#include "mdr_engine.h"

/** Output groups of a scene (the outputs argument of mdr_scene_init_*()).
 *  The step always solves for d and F; the rest is computed only when asked. */
#define MDR_OUT_FORCE 0u  /**< out->F and out->d only */
#define MDR_OUT_RADIUS 1u /**< + out->a */
#define MDR_OUT_EVENTS 2u /**< + out->z, event, jumps, a0/d0/F0, a1/d1/F1 */
#define MDR_OUT_ALL 3u    /**< every field of mdr_step_<type> */

#define MDR_TEMPLATE "mdr_scene_t.h"
#include "mdr_each_arith.h"

#endif /* MDR_SCENE_H */
