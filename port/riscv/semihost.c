/* SPDX-License-Identifier: MIT */
/*
 * port/riscv/semihost.c: the semihosting trap of RISC-V ("RISC-V
 * Semihosting" v0.2; port/target.h): the sequence slli zero, zero, 0x1f;
 * ebreak; srai zero, zero, 7, uncompressed and on one page (QEMU reads the
 * EBREAK's neighbours), here a 16-byte aligned function of its own:
 * operation in a0, parameter in a1, result in a0.
 */
#include <stdint.h>

#include "../target.h"

__asm__(".section .text.mdr_sh_call, \"ax\", @progbits\n"
        ".balign 16\n"
        ".globl mdr_sh_call\n"
        "mdr_sh_call:\n"
        ".option push\n"
        ".option norvc\n"
        "    slli zero, zero, 0x1f\n"
        "    ebreak\n"
        "    srai zero, zero, 7\n"
        ".option pop\n"
        "    ret\n"
        ".text\n");
