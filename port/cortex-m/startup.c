/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/startup.c: reset and fault handlers, vector table for a
 * Cortex-M program linked with a board script of port/cortex-m (mps2.ld,
 * microbit.ld). Reset copies .data (and .ramfunc) from flash, zeroes .bss
 * (port/target.h), enables the FPU where the build uses it, opens the
 * semihosting console (newlib's librdimon) and runs main(); main's return
 * value becomes the exit status of the QEMU run (mdr_sh_exit). A fault prints its name and exits with status 3, so a
 * crashing test fails instead of hanging.
 *
 * With MDR_RAM_REPORT (boards with little RAM: the microbit's 16 KB) the
 * program also says how much RAM it used: Reset paints the free RAM
 * between the heap's start (`end`) and the stack pointer with a pattern;
 * after main the heap's top (newlib's _sbrk(0)) and the deepest
 * overwritten word above it give the heap and the stack the run used, and
 * the bytes between them that nothing ever wrote. The stack figure counts
 * the 256 bytes below Reset's frame, which are not painted, as used, and
 * can miss only words a frame reserved but never wrote, at its deepest end.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "../target.h"

extern uint32_t mdr_ld_estack[];
extern void initialise_monitor_handles(void);
extern int main(void);

void Reset_Handler(void);
void mdr_fault_handler(void);

#ifdef MDR_RAM_REPORT
#define MDR_PAINT 0xA5A5A5A5u
extern uint32_t mdr_ld_sram[], end[];
/* newlib's system call (librdimon): the reserved name is the C library's own */
extern void *_sbrk(ptrdiff_t incr); /* NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp) */

/* the top of the painted region (a little below Reset_Handler's frame) */
static const uint32_t *mdr_paint_top;

static void mdr_ram_report(void)
{
    uintptr_t brk = ((uintptr_t)_sbrk(0) + 3u) & ~(uintptr_t)3u;
    const uint32_t *p = end + (brk - (uintptr_t)end) / sizeof(uint32_t);
    uintptr_t deepest, ram = (uintptr_t)mdr_ld_estack - (uintptr_t)mdr_ld_sram;
    while (p < mdr_paint_top && *(const volatile uint32_t *)p == MDR_PAINT) {
        p++;
    }
    deepest = (uintptr_t)p;
    printf("target RAM %u B: data+bss %u, heap %u, stack %u (painted), never used %u\n", (unsigned)ram,
           (unsigned)((uintptr_t)end - (uintptr_t)mdr_ld_sram), (unsigned)(brk - (uintptr_t)end),
           (unsigned)((uintptr_t)mdr_ld_estack - deepest), (unsigned)(deepest - brk));
}
#endif

void Reset_Handler(void)
{
    mdr_ram_init();
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11 (the FPU) before any float code */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
#ifdef MDR_RAM_REPORT
    {
        uint32_t *p;
        const uint32_t *sp;
        __asm__ volatile("mov %0, sp" : "=r"(sp));
        mdr_paint_top = sp - 64; /* 256 bytes below this frame */
        for (p = end; p < mdr_paint_top; p++) {
            *(volatile uint32_t *)p = MDR_PAINT;
        }
    }
    initialise_monitor_handles();
    {
        int status = main();
        mdr_ram_report();
        mdr_sh_exit(status);
    }
#else
    initialise_monitor_handles();
    mdr_sh_exit(main());
#endif
}

void mdr_fault_handler(void)
{
    mdr_sh_write0("target: fault (hard fault, NMI or unexpected exception)\n");
    mdr_sh_exit(3);
}

typedef void (*mdr_vector)(void);

/* initial stack pointer, reset, then NMI .. SysTick (15 entries) */
__attribute__((section(".isr_vector"), used)) static const mdr_vector mdr_vectors[16] = {
    /* the initial stack pointer is an address, not a function */
    (mdr_vector)(uintptr_t)mdr_ld_estack, /* NOLINT(performance-no-int-to-ptr) */
    Reset_Handler, mdr_fault_handler, mdr_fault_handler,
    mdr_fault_handler, mdr_fault_handler, mdr_fault_handler, 0, 0, 0, 0,
    mdr_fault_handler, mdr_fault_handler, 0, mdr_fault_handler, mdr_fault_handler,
};
