/*
 * port/cortex-m/semihost.c: semihosting calls (Arm "Semihosting for
 * AArch32 and AArch64", v2.0): SYS_WRITE0 (0x04) and SYS_EXIT_EXTENDED
 * (0x20), whose parameter block {ADP_Stopped_ApplicationExit, status}
 * makes QEMU (-semihosting-config enable=on) exit with that status.
 */
#include <stdint.h>
#include <stdio.h>

#include "semihost.h"

static uintptr_t mdr_sh_call(uintptr_t op, uintptr_t arg)
{
    register uintptr_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void mdr_sh_write0(const char *s)
{
    (void)mdr_sh_call(0x04u, (uintptr_t)s);
}

void mdr_sh_exit(int status)
{
    uintptr_t block[2];
    (void)fflush(stdout); /* exiting: nothing to do about a failure */
    (void)fflush(stderr);
    block[0] = 0x20026u; /* ADP_Stopped_ApplicationExit */
    block[1] = (uintptr_t)(uint32_t)status;
    (void)mdr_sh_call(0x20u, (uintptr_t)block);
    for (;;) {
    }
}
