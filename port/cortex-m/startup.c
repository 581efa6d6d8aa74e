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
 * The board's stack reserve (_stack_size, which the linker checks against
 * data + bss) is kept: Reset sets newlib's heap limit at its lower end, so
 * a malloc that would enter it fails instead of handing out the stack's
 * words, and a run whose painted stack went below it fails (exit status 4)
 * even where every test passed: a stack that grew into the heap may have
 * overwritten what the heap held (stop 45: the q31 step's -O2 build on the
 * microbit corrupted printf's big-number freelist that way).
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
/* the board script's stack reserve: an absolute symbol, its address is its value */
extern char _stack_size[]; /* NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp) */
/* newlib's system call and heap limit (librdimon, 0xcafedead: none): the
 * reserved names are the C library's own */
extern void *_sbrk(ptrdiff_t incr);   /* NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp) */
extern char *__heap_limit;           /* NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp) */

/* the top of the painted region (a little below Reset_Handler's frame) */
static const uint32_t *mdr_paint_top;

/* the report; 0, or 4 where the stack went below its reserve */
static int mdr_ram_report(void)
{
    uintptr_t brk = ((uintptr_t)_sbrk(0) + 3u) & ~(uintptr_t)3u;
    const uint32_t *p = end + (brk - (uintptr_t)end) / sizeof(uint32_t);
    uintptr_t deepest, ram = (uintptr_t)mdr_ld_estack - (uintptr_t)mdr_ld_sram;
    uintptr_t reserve = (uintptr_t)_stack_size;
    while (p < mdr_paint_top && *(const volatile uint32_t *)p == MDR_PAINT) {
        p++;
    }
    deepest = (uintptr_t)p;
    printf("target RAM %u B: data+bss %u, heap %u, stack %u (painted), never used %u\n", (unsigned)ram,
           (unsigned)((uintptr_t)end - (uintptr_t)mdr_ld_sram), (unsigned)(brk - (uintptr_t)end),
           (unsigned)((uintptr_t)mdr_ld_estack - deepest), (unsigned)(deepest - brk));
    if ((uintptr_t)mdr_ld_estack - deepest > reserve) {
        printf("target: the stack (%u B) overran its reserve (_stack_size %u B): raise it in the board script "
               "or use less stack\n",
               (unsigned)((uintptr_t)mdr_ld_estack - deepest), (unsigned)reserve);
        return 4;
    }
    return 0;
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
        __heap_limit = (char *)mdr_ld_estack - (uintptr_t)_stack_size;
        for (p = end; p < mdr_paint_top; p++) {
            *(volatile uint32_t *)p = MDR_PAINT;
        }
    }
    initialise_monitor_handles();
    {
        int status = main();
        int ram = mdr_ram_report();
        mdr_sh_exit(status != 0 ? status : ram);
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
