/* SPDX-License-Identifier: MIT */
/*
 * mdr_hooks.h: the port hooks lib/ uses, with their defaults. The port's
 * mdr_port.h (port/host, port/cortex-m, port/riscv, or a firmware's own,
 * found on the include path) may define any of them first:
 *
 *   MDR_PORT_SQRT_F32(x), MDR_PORT_SQRT_F64(x)
 *                  square root (the FPU instruction); default: lib/'s own
 *                  Newton routine (lib/src/math/mdr_math.inc, correctly rounded
 *                  to 1 ulp)
 *   MDR_PORT_SQRT_BUILTIN  defined by a port whose square root is the
 *                  compiler's __builtin_sqrt(f): GCC and Clang make it one
 *                  instruction only with -fno-math-errno (otherwise a call
 *                  of sqrtf/sqrt that a freestanding link cannot resolve),
 *                  so such a build without that flag stops here with an
 *                  #error (the compilers define __NO_MATH_ERRNO__ with it)
 *   MDR_PORT_FMA_F32(a, b, c)
 *                  a b + c rounded once (fused multiply-add), used by the
 *                  f32 step's kernels where one instruction does it;
 *                  default: __builtin_fmaf where the compiler says it is
 *                  one instruction (GCC's __FP_FAST_FMAF: Cortex-M4F/M7,
 *                  RV32F, aarch64, x86-64 with -mfma), else undefined: the
 *                  kernels then round a b and the sum separately. A port
 *                  may define it (e.g. Clang, which does not define
 *                  __FP_FAST_FMAF, with -fno-math-errno), or define it as
 *                  ((a) * (b) + (c)) to keep the two roundings.
 *   MDR_INLINE     qualifiers of the small helpers of the step (default
 *                  `static inline`)
 *   MDR_FORCE_INLINE  qualifiers of the step's fast paths, which the public
 *                  step functions inline per control mode to specialise
 *                  them (default `static inline` with GCC's and Clang's
 *                  always_inline)
 *   MDR_NOINLINE   keeps a function out of line (the per-control ticks, so
 *                  that the step's pinned path has no prologue)
 *   MDR_STEP_FN    attribute of every function on the step path (the public
 *                  step functions and what they call); default: section
 *                  MDR_STEP_SECTION when the build defines it (a string
 *                  literal such as ".ramfunc" or ".itcm", to run the step
 *                  from RAM), else none.
 *   MDR_ASSERT(c)  internal invariants (never input checks: bad input is a
 *                  status code); default: compiled out, or, when
 *                  MDR_PORT_ASSERT_HOOK is defined, a call of the firmware's
 *                  void mdr_port_assert_failed(const char *file, int line).
 */
#ifndef MDR_HOOKS_H
#define MDR_HOOKS_H

#include "mdr_port.h"

#if defined(MDR_PORT_SQRT_BUILTIN) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(__NO_MATH_ERRNO__)
#error "libmdr: this port maps sqrt to __builtin_sqrt(f), which needs -fno-math-errno (MDR_REQUIRED_CFLAGS of lib/Filelists.mk); without it the objects call sqrtf/sqrt from libm"
#endif

#if !defined(MDR_PORT_FMA_F32) && defined(__GNUC__) && defined(__FP_FAST_FMAF)
#define MDR_PORT_FMA_F32(a, b, c) __builtin_fmaf(a, b, c)
#endif

#ifndef MDR_INLINE
#define MDR_INLINE static inline
#endif

#ifndef MDR_FORCE_INLINE
#if defined(__GNUC__)
#define MDR_FORCE_INLINE static inline __attribute__((always_inline))
#else
#define MDR_FORCE_INLINE static inline
#endif
#endif

#ifndef MDR_NOINLINE
#if defined(__GNUC__)
#define MDR_NOINLINE __attribute__((noinline))
#else
#define MDR_NOINLINE
#endif
#endif

#ifndef MDR_STEP_FN
#ifdef MDR_STEP_SECTION
#define MDR_STEP_FN __attribute__((section(MDR_STEP_SECTION)))
#else
#define MDR_STEP_FN
#endif
#endif

#ifndef MDR_ASSERT
#ifdef MDR_PORT_ASSERT_HOOK
void mdr_port_assert_failed(const char *file, int line);
#define MDR_ASSERT(cond) ((cond) ? (void)0 : mdr_port_assert_failed(__FILE__, __LINE__))
#else
#define MDR_ASSERT(cond) ((void)0)
#endif
#endif

#endif /* MDR_HOOKS_H */
