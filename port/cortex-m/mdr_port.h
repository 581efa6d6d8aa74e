/*
 * port/cortex-m/mdr_port.h: hooks for Arm Cortex-M (arm-none-eabi-gcc).
 * Chosen by -Iport/cortex-m. With a single-precision FPU (M4F, M7:
 * __ARM_FP bit 2) the float square root is the VSQRT.F32 instruction
 * (needs -fno-math-errno, which the Makefile sets); without one (M0, M3)
 * lib/ uses its own Newton routine (lib/src/mdr_math_t.c).
 */
#ifndef MDR_PORT_H
#define MDR_PORT_H

#if defined(__ARM_FP) && (__ARM_FP & 4)
#define MDR_PORT_SQRT_F32(x) __builtin_sqrtf(x)
#endif

/* internal invariants: compiled out by default on targets */
#define MDR_ASSERT(cond) ((void)0)

#endif /* MDR_PORT_H */
