/* SPDX-License-Identifier: MIT */
/*
 * port/riscv/startup.c: reset and trap entry of an RV32 program linked
 * with port/riscv/virt.ld, in machine mode on one hart. _start sets the
 * global pointer (gp, for the linker's relaxation), the stack pointer (top
 * of RAM), the thread pointer (tp: the TLS block, picolibc's errno) and the
 * trap vector, and turns the FPU on where the build uses one
 * (mstatus.FS); mdr_reset then copies .data and .tdata from flash, zeroes
 * .tbss and .bss, runs main() and ends the QEMU run with main's return
 * value as its exit status (mdr_sh_exit). A trap (illegal instruction,
 * access fault, misaligned access, ...) prints its cause and addresses and
 * exits with status 3, so a crashing test fails instead of hanging.
 */
#include <stddef.h>
#include <stdint.h>

#include "../target.h"

extern int main(void);

void mdr_reset(void) __attribute__((noreturn));
void mdr_trap(void) __attribute__((noreturn, aligned(4)));

__asm__(".section .text.mdr_start, \"ax\", @progbits\n"
        ".globl _start\n"
        "_start:\n"
        ".option push\n"
        ".option norelax\n"
        ".option arch, +zicsr\n"
        "    la gp, __global_pointer$\n"
        "    la sp, mdr_ld_estack\n"
        "    la tp, mdr_ld_tls\n"
        "    la t0, mdr_trap\n"
        "    csrw mtvec, t0\n"
#if defined(__riscv_flen)
        "    li t0, 0x2000\n" /* mstatus.FS = Initial: F/D instructions allowed */
        "    csrs mstatus, t0\n"
        "    csrw fcsr, zero\n"
#endif
        "    j mdr_reset\n"
        ".option pop\n"
        ".text\n");

void mdr_reset(void)
{
    mdr_ram_init();
    mdr_sh_exit(main());
}

/* "target: trap, mcause 0x..., mepc 0x..., mtval 0x...", no library call */
void mdr_trap(void)
{
    static const char hex[] = "0123456789abcdef";
    static const char *const name[3] = {"target: trap, mcause 0x", ", mepc 0x", ", mtval 0x"};
    char msg[96];
    uint32_t cause, epc, tval;
    size_t n = 0, k, j;
    /* the CSR instructions: Zicsr, which binutils >= 2.38 wants named */
    __asm__ volatile(".option push\n.option arch, +zicsr\ncsrr %0, mcause\n"
                     "csrr %1, mepc\ncsrr %2, mtval\n.option pop"
                     : "=r"(cause), "=r"(epc), "=r"(tval));
    const uint32_t v[3] = {cause, epc, tval};
    for (k = 0; k < 3; k++) {
        for (j = 0; name[k][j] != '\0'; j++) {
            msg[n++] = name[k][j];
        }
        for (j = 8; j-- > 0;) {
            msg[n++] = hex[(v[k] >> (4 * j)) & 0xfu];
        }
    }
    msg[n++] = '\n';
    msg[n] = '\0';
    mdr_sh_write0(msg);
    mdr_sh_exit(3);
}
