/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/semihost.c: the semihosting trap of M-profile cores
 * (port/target.h): BKPT 0xAB with the operation in r0 and the parameter in
 * r1; the result comes back in r0.
 */
#include <stdint.h>

#include "../target.h"

uintptr_t mdr_sh_call(uintptr_t op, uintptr_t arg)
{
    register uintptr_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}
