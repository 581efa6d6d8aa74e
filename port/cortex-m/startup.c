/*
 * port/cortex-m/startup.c: reset and fault handlers, vector table for a
 * Cortex-M program linked with port/cortex-m/mps2.ld. Reset copies .data
 * (and .ramfunc) from flash, zeroes .bss, enables the FPU where the build
 * uses it, opens the semihosting console (newlib's librdimon) and runs
 * main(); main's return value becomes the exit status of the QEMU run
 * (mdr_sh_exit). A fault prints its name and exits with status 3, so a
 * crashing test fails instead of hanging.
 */
#include <stddef.h>
#include <stdint.h>

#include "semihost.h"

extern uint32_t mdr_ld_sidata[], mdr_ld_sdata[], mdr_ld_edata[], mdr_ld_sbss[], mdr_ld_ebss[], mdr_ld_estack[];
extern void initialise_monitor_handles(void);
extern int main(void);

void Reset_Handler(void);
void mdr_fault_handler(void);

void Reset_Handler(void)
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
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11 (the FPU) before any float code */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    initialise_monitor_handles();
    mdr_sh_exit(main());
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
