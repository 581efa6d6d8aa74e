/*
 * port/riscv/mdr_port.h: hooks for RV32 (riscv64-unknown-elf-gcc, -march=rv32...).
 * Chosen by -Iport/riscv. With the F extension the float square root is
 * FSQRT.S (needs -fno-math-errno); otherwise lib/'s own routine.
 */
#ifndef MDR_PORT_H
#define MDR_PORT_H

#if defined(__riscv_flen) && __riscv_flen >= 32
#define MDR_PORT_SQRT_F32(x) __builtin_sqrtf(x)
#endif

#define MDR_ASSERT(cond) ((void)0)

#endif /* MDR_PORT_H */
