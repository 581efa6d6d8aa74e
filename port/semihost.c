/* SPDX-License-Identifier: MIT */
/*
 * port/semihost.c: the semihosting calls of port/target.h over the port's
 * trap mdr_sh_call(): SYS_WRITE0 (0x04), and SYS_EXIT_EXTENDED (0x20),
 * whose parameter block {ADP_Stopped_ApplicationExit, status} makes QEMU
 * (-semihosting-config enable=on) exit with that status.
 */
#include <stdint.h>
#include <stdio.h>

#include "target.h"

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
