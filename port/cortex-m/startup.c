/*
 * port/cortex-m/startup.c: reset and fault handlers, vector table for a
 * Cortex-M program linked with port/cortex-m/mps2.ld. Reset copies .data
 * (and .ramfunc) from flash, zeroes .bss, enables the FPU where the build
 * uses it, opens the semihosting console (newlib's librdimon) and runs
 * main(); main's return value becomes the exit status of the QEMU run
 * (mdr_sh_exit). A fault prints its name and exits with status 3, so a
 * crashing test fails instead of hanging.
 */
#include <stdint.h>

#include "semihost.h"

extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[], _estack[];
extern void initialise_monitor_handles(void);
extern int main(void);

void Reset_Handler(void);
void mdr_fault_handler(void);

void Reset_Handler(void)
{
    uint32_t *s = _sidata, *d = _sdata;
    while (d < _edata) {
        *d++ = *s++;
    }
    for (d = _sbss; d < _ebss; d++) {
        *d = 0;
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
    (mdr_vector)(uintptr_t)_estack, Reset_Handler, mdr_fault_handler, mdr_fault_handler,
    mdr_fault_handler, mdr_fault_handler, mdr_fault_handler, 0, 0, 0, 0,
    mdr_fault_handler, mdr_fault_handler, 0, mdr_fault_handler, mdr_fault_handler,
};
