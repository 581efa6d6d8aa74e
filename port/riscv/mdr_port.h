/* SPDX-License-Identifier: MIT */
/*
 * port/riscv/mdr_port.h: hooks for RV32 (riscv64-unknown-elf-gcc,
 * -march=rv32...). Chosen by -Iport/riscv; compiler flags per core:
 * port/riscv/port.mk. The hooks lib/ uses and their defaults:
 * lib/src/mdr_hooks.h.
 *
 *  MDR_PORT_SQRT_F32(x)  FSQRT.S with the F extension (needs
 *                        -fno-math-errno), FSQRT.D with D; otherwise lib/'s
 *                        own routine.
 *  MDR_STEP_FN, MDR_ASSERT  the defaults of lib/src/mdr_hooks.h (section
 *                        MDR_STEP_SECTION if defined, e.g. a tightly coupled
 *                        memory's ".itim"; asserts off unless
 *                        MDR_PORT_ASSERT_HOOK).
 *  mdr_port_cycles()     the low 32 bits of mcycle (machine mode; user mode
 *                        code reads `cycle` instead: define
 *                        MDR_PORT_CYCLES_USER).
 */
#ifndef MDR_PORT_H
#define MDR_PORT_H

#include <stdint.h>

#if defined(__riscv_flen) && __riscv_flen >= 32
#define MDR_PORT_SQRT_F32(x) __builtin_sqrtf(x)
#define MDR_PORT_SQRT_BUILTIN 1 /* needs -fno-math-errno (mdr_hooks.h) */
#endif
#if defined(__riscv_flen) && __riscv_flen >= 64
#define MDR_PORT_SQRT_F64(x) __builtin_sqrt(x)
#endif

#define MDR_PORT_CYCLES_MASK 0xFFFFFFFFu
static inline void mdr_port_cycles_init(void)
{
}
static inline uint32_t mdr_port_cycles(void)
{
    uint32_t v;
#ifdef MDR_PORT_CYCLES_USER
    __asm__ volatile("rdcycle %0" : "=r"(v));
#else
    /* csrr v, mcycle (csrrs v, 0xB00, x0) as an encoding: binutils >= 2.38
     * with GCC >= 12's default ISA spec want Zicsr named for the mnemonic,
     * older ones do not know the name */
    __asm__ volatile(".insn i 0x73, 2, %0, x0, -1280" : "=r"(v));
#endif
    return v;
}

#endif /* MDR_PORT_H */
