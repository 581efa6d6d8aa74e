/* SPDX-License-Identifier: MIT */
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

/* Output groups of a scene: MDR_OUT_* of mdr_engine.h (the outputs
 * argument of mdr_scene_init_*(); MDR_OUT_ENERGY is not used: a scene keeps
 * its energy in the mdr_energy_<type> given to its init). */

/* the declarations per arithmetic, written out from mdr_scene_t.h by
 * mk/gen_headers.py (make headers) */
#include "mdr_scene_f32.h"
#include "mdr_scene_f64.h"

#endif /* MDR_SCENE_H */
