/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/mdr_port.h: hooks for Arm Cortex-M (arm-none-eabi-gcc).
 * Chosen by -Iport/cortex-m; compiler flags per core: port/cortex-m/port.mk.
 * The hooks lib/ uses and their defaults: lib/src/mdr_hooks.h.
 *
 *  MDR_PORT_SQRT_F32(x)  VSQRT.F32 where there is a single-precision FPU
 *                        (M4F, M7: __ARM_FP bit 2; needs -fno-math-errno);
 *                        without one (M0, M0+, M3) lib/'s own Newton
 *                        routine. Double precision: always lib/'s routine
 *                        (no Cortex-M4/M7-SP core has a double FPU; the
 *                        M7-DP's VSQRT.F64 via MDR_PORT_SQRT_F64 if wanted).
 *  MDR_STEP_FN, MDR_ASSERT  the defaults of lib/src/mdr_hooks.h: the step
 *                        path in section MDR_STEP_SECTION when the build
 *                        defines it, e.g. -DMDR_STEP_SECTION='".ramfunc"'
 *                        (RAM, copied by the startup code with .data:
 *                        port/cortex-m/mps2.ld) or '".itcm"' on an M7 whose
 *                        linker script has one; asserts compiled out unless
 *                        MDR_PORT_ASSERT_HOOK.
 *  mdr_port_cycles_init(), mdr_port_cycles()
 *                        a cycle counter for benchmarks (not used by lib/):
 *                        DWT CYCCNT (32 bits) on ARMv7-M/ARMv8-M mainline;
 *                        SysTick (24 bits, counting up here) on ARMv6-M or
 *                        when MDR_PORT_CYCLES_SYSTICK is defined (QEMU does
 *                        not model the DWT). Differences modulo
 *                        MDR_PORT_CYCLES_MASK + 1.
 */
#ifndef MDR_PORT_H
#define MDR_PORT_H

#include <stdint.h>

#if defined(__ARM_FP) && (__ARM_FP & 4)
#define MDR_PORT_SQRT_F32(x) __builtin_sqrtf(x)
#define MDR_PORT_SQRT_BUILTIN 1 /* needs -fno-math-errno (mdr_hooks.h) */
#endif

/* memory-mapped registers of the System Control Space (ARMv6-M/v7-M ARM) */
#define MDR_PORT_REG(a) (*(volatile uint32_t *)(uintptr_t)(a))
#define MDR_PORT_SYST_CSR MDR_PORT_REG(0xE000E010u)
#define MDR_PORT_SYST_RVR MDR_PORT_REG(0xE000E014u)
#define MDR_PORT_SYST_CVR MDR_PORT_REG(0xE000E018u)
#define MDR_PORT_DEMCR MDR_PORT_REG(0xE000EDFCu)
#define MDR_PORT_DWT_CTRL MDR_PORT_REG(0xE0001000u)
#define MDR_PORT_DWT_CYCCNT MDR_PORT_REG(0xE0001004u)

#if (defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__) || \
     defined(__ARM_ARCH_8M_MAIN__)) && !defined(MDR_PORT_CYCLES_SYSTICK)
#define MDR_PORT_CYCLES_MASK 0xFFFFFFFFu
static inline void mdr_port_cycles_init(void)
{
    MDR_PORT_DEMCR |= 1u << 24; /* TRCENA */
    MDR_PORT_DWT_CYCCNT = 0;
    MDR_PORT_DWT_CTRL |= 1u; /* CYCCNTENA */
}
static inline uint32_t mdr_port_cycles(void)
{
    return MDR_PORT_DWT_CYCCNT;
}
#else
#define MDR_PORT_CYCLES_MASK 0x00FFFFFFu
/* SysTick free-running from the processor clock, no interrupt. A firmware
 * whose RTOS owns SysTick reads its own timer instead. */
static inline void mdr_port_cycles_init(void)
{
    MDR_PORT_SYST_CSR = 0;
    MDR_PORT_SYST_RVR = MDR_PORT_CYCLES_MASK;
    MDR_PORT_SYST_CVR = 0;
    MDR_PORT_SYST_CSR = 5u; /* ENABLE | CLKSOURCE = processor clock */
}
static inline uint32_t mdr_port_cycles(void)
{
    return MDR_PORT_CYCLES_MASK - MDR_PORT_SYST_CVR; /* counts down */
}
#endif

#endif /* MDR_PORT_H */
