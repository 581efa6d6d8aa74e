/* SPDX-License-Identifier: MIT */
/*
 * mdr_arith_q31.h: the q31 arithmetic of the templates written once for
 * every arithmetic (the state machine engine/mdr_machine.inc and the spring
 * solver engine/mdr_edge_table.inc), for lib/src/mdr_q31.c: int32_t values
 * in Q formats (lib/include/mdr_q31.h), 64-bit products, no float type.
 *
 *   MDR_T          int32_t: a state value (d, F, z raw; t, x Q1.30)
 *   MDR_SFX(n)     n_q31
 *   MDR_ZERO       0
 *   MDR_TINY       1, the smallest positive raw value
 *   MDR_MAXV       INT32_MAX
 *   MDR_FINITE(x)  1: every integer is a value (the overflow policy of q31
 *                  is to saturate and set MDR_FLAG_SAT, never to refuse)
 */
#ifndef MDR_ARITH_Q31_H
#define MDR_ARITH_Q31_H

#include <stdint.h>

#include "mdr_hooks.h"

#define MDR_ARITH_Q31 1
#define MDR_T int32_t
#define MDR_SFX(name) name##_q31
#define MDR_ZERO 0
#define MDR_TINY 1
#define MDR_MAXV INT32_MAX
/* the lowest control a step takes as it is (beyond: saturated, MDR_FLAG_SAT) */
#define MDR_UMIN (-2 * MDR_Q29_ONE)
#define MDR_FINITE(x) ((void)(x), 1)
#define MDR_FINITE4(a, b, c, d) ((void)(a), (void)(b), (void)(c), (void)(d), 1)

#endif /* MDR_ARITH_Q31_H */
