/* SPDX-License-Identifier: MIT */
/*
 * port/target.h: what the ports' startup code shares (the bare-metal test
 * and benchmark programs of make target-test and make bench; not part of a
 * firmware's build of lib/).
 *
 * Semihosting (Arm "Semihosting for AArch32 and AArch64" v2.0, which
 * "RISC-V Semihosting" carries unchanged): port/semihost.c makes the two
 * calls the startup code needs besides the C library's console, over the
 * port's trap mdr_sh_call() (port/cortex-m/semihost.c: BKPT 0xAB;
 * port/riscv/semihost.c: the EBREAK sequence). Without a debugger or QEMU
 * attached the trap faults, so only test programs link these.
 *
 * RAM setup: the linker scripts (port/cortex-m/sections.ld,
 * port/riscv/virt.ld) name the initialised data's image in flash
 * (mdr_ld_sidata) and place (mdr_ld_sdata .. mdr_ld_edata), and the zeroed
 * part (mdr_ld_sbss .. mdr_ld_ebss), all word-aligned.
 */
#ifndef MDR_TARGET_H
#define MDR_TARGET_H

#include <stddef.h>
#include <stdint.h>

/** the port's semihosting trap: operation op, parameter arg; the result */
uintptr_t mdr_sh_call(uintptr_t op, uintptr_t arg);
/** SYS_WRITE0: a NUL-terminated string to the debugger's console */
void mdr_sh_write0(const char *s);
/** flush stdout and stderr, then SYS_EXIT_EXTENDED: end the run (QEMU exits
 *  with this status) */
void mdr_sh_exit(int status) __attribute__((noreturn));

extern uint32_t mdr_ld_sidata[], mdr_ld_sdata[], mdr_ld_edata[], mdr_ld_sbss[], mdr_ld_ebss[];

/** copy the initialised data from flash, zero the rest (before any C code
 *  that uses static storage) */
static inline void mdr_ram_init(void)
{
    /* word counts from addresses: the symbols are distinct objects to C */
    size_t i, nd = ((uintptr_t)mdr_ld_edata - (uintptr_t)mdr_ld_sdata) / sizeof(uint32_t);
    size_t nb = ((uintptr_t)mdr_ld_ebss - (uintptr_t)mdr_ld_sbss) / sizeof(uint32_t);
    for (i = 0; i < nd; i++) {
        mdr_ld_sdata[i] = mdr_ld_sidata[i];
    }
    for (i = 0; i < nb; i++) {
        mdr_ld_sbss[i] = 0;
    }
}

#endif /* MDR_TARGET_H */
