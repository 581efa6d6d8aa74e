/* SPDX-License-Identifier: MIT */
/*
 * port/host/mdr_port.h: hooks for host builds (x86-64, aarch64 with an FPU).
 * Chosen by the include path (-Iport/host). The hooks lib/ uses and their
 * defaults: lib/src/mdr_hooks.h.
 *
 *  MDR_PORT_SQRT_F32/F64(x)  the compiler builtin: one instruction with
 *                            -fno-math-errno (the Makefile sets it). Define
 *                            MDR_PORT_OWN_SQRT to test lib/'s own routine.
 *  MDR_PORT_FMA_F32(a, b, c)  the default (mdr_hooks.h: fused where the
 *                            compiler says fmaf is one instruction; not on
 *                            x86-64 without -mfma). Define MDR_PORT_FUSED
 *                            to fuse with __builtin_fmaf anyway (a call of
 *                            libm's fmaf, correctly rounded: the result of
 *                            the Cortex-M4F's vfma), which is how the host
 *                            tests the f32 step of the FPU cores.
 *  MDR_STEP_FN               the default (lib/src/mdr_hooks.h).
 *  MDR_ASSERT(cond)          internal invariants: trap on the host (the
 *                            tests and sanitizer builds see any violation).
 *  mdr_port_cycles()         a free-running counter for benchmarks (not used
 *                            by lib/): the time-stamp counter on x86, the
 *                            virtual counter on aarch64, else 0.
 */
#ifndef MDR_PORT_H
#define MDR_PORT_H

#include <stdint.h>

#ifndef MDR_PORT_OWN_SQRT
#define MDR_PORT_SQRT_F32(x) __builtin_sqrtf(x)
#define MDR_PORT_SQRT_F64(x) __builtin_sqrt(x)
#define MDR_PORT_SQRT_BUILTIN 1 /* needs -fno-math-errno (mdr_hooks.h) */
#endif

#ifdef MDR_PORT_FUSED
#define MDR_PORT_FMA_F32(a, b, c) __builtin_fmaf(a, b, c)
#endif

#define MDR_ASSERT(cond) ((cond) ? (void)0 : __builtin_trap())

/* counter ticks per mdr_port_cycles() unit are the machine's; 64 bits */
static inline uint64_t mdr_port_cycles(void)
{
#if defined(__x86_64__) || defined(__i386__)
    return (uint64_t)__builtin_ia32_rdtsc();
#elif defined(__aarch64__)
    uint64_t v;
    __asm__ volatile("mrs %0, cntvct_el0" : "=r"(v));
    return v;
#else
    return 0;
#endif
}

#endif /* MDR_PORT_H */
