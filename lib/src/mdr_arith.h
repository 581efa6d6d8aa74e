/* SPDX-License-Identifier: MIT */
/*
 * mdr_arith.h: the macros that make one template source serve every floating
 * arithmetic. A translation unit defines MDR_ARITH_F32 or MDR_ARITH_F64 and
 * then includes this file and the *_t.h / *.inc templates (mdr_float.inc).
 *
 *   MDR_T          the real type
 *   MDR_SFX(n)     n_f32 / n_f64 (public and internal names)
 *   MDR_K(x)       a literal of type MDR_T: write every literal with a decimal
 *                  point or exponent (MDR_K(2.0), MDR_K(1e-3)), never MDR_K(2)
 *   MDR_UINT       unsigned integer of the same width (bit access)
 *   MDR_MANT_BITS  stored mantissa bits; MDR_EXP_BIAS exponent bias
 *   MDR_EPS        unit roundoff 2^-p (half an ulp of 1)
 *   MDR_SQRT_EPS   its square root, rounded to a power of two
 *   MDR_MAXV, MDR_MINV, MDR_TINY  the largest, the smallest normal and the
 *                  smallest subnormal positive number
 *   MDR_SQRT(x)    the port's square-root hook, or our own routine
 *   MDR_FMA(a, b, c)  a b + c, rounded once where the port fuses it
 *                  (f32: MDR_PORT_FMA_F32, mdr_hooks.h; f64: never, so the
 *                  f64 results are the host's on every core), else twice
 */
#ifndef MDR_ARITH_H
#define MDR_ARITH_H

#include <float.h>
#include <stdint.h>

#include "mdr_hooks.h"

#if defined(MDR_ARITH_F32)
#define MDR_T float
#define MDR_SFX(name) name##_f32
#define MDR_K(x) x##f
#define MDR_UINT uint32_t
#define MDR_MANT_BITS 23
#define MDR_EXP_BIAS 127
#define MDR_EXP_MAX 127
#define MDR_EPS MDR_K(5.9604644775390625e-8)
#define MDR_SQRT_EPS MDR_K(2.44140625e-4) /* 2^-12 */
#define MDR_MAXV FLT_MAX
#define MDR_MINV FLT_MIN
#define MDR_TINY MDR_K(1.40129846432481707e-45) /* the smallest subnormal, 2^-149 */
#ifdef MDR_PORT_SQRT_F32
#define MDR_SQRT(x) MDR_PORT_SQRT_F32(x)
#else
#define MDR_SQRT(x) mdr_m_sqrt_f32(x)
#endif
#ifdef MDR_PORT_FMA_F32
#define MDR_FMA(a, b, c) MDR_PORT_FMA_F32(a, b, c)
#endif
#elif defined(MDR_ARITH_F64)
#define MDR_T double
#define MDR_SFX(name) name##_f64
#define MDR_K(x) x
#define MDR_UINT uint64_t
#define MDR_MANT_BITS 52
#define MDR_EXP_BIAS 1023
#define MDR_EXP_MAX 1023
#define MDR_EPS MDR_K(1.1102230246251565e-16)
#define MDR_SQRT_EPS MDR_K(1.490116119384765625e-8) /* 2^-26 */
#define MDR_MAXV DBL_MAX
#define MDR_MINV DBL_MIN
#define MDR_TINY MDR_K(4.94065645841246544e-324) /* the smallest subnormal, 2^-1074 */
#ifdef MDR_PORT_SQRT_F64
#define MDR_SQRT(x) MDR_PORT_SQRT_F64(x)
#else
#define MDR_SQRT(x) mdr_m_sqrt_f64(x)
#endif
#else
#error "define MDR_ARITH_F32 or MDR_ARITH_F64 before including mdr_arith.h"
#endif

#ifndef MDR_FMA
#define MDR_FMA(a, b, c) ((a) * (b) + (c))
#endif

/* what the engines' state machine (engine/mdr_machine.inc) needs of an
 * arithmetic: zero; finiteness (x - x is 0 unless x is inf or NaN; a sum of
 * finite terms is finite or overflows) */
#define MDR_ZERO MDR_K(0.0)
/* the lowest control a step takes (below: -inf, refused) */
#define MDR_UMIN (-MDR_MAXV)
#define MDR_FINITE(x) ((x) - (x) == MDR_K(0.0))
#define MDR_FINITE4(a, b, c, d) MDR_FINITE((a) + (b) + (c) + (d))

#define MDR_PI MDR_K(3.14159265358979323846264338327950288)
#define MDR_LN2 MDR_K(0.693147180559945309417232121458176568)

#endif /* MDR_ARITH_H */
