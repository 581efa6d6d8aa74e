/*
 * port/cortex-m/semihost.h: the two Arm semihosting calls the target
 * programs need besides newlib's console (librdimon): write a string to
 * the debugger's console, and exit with a status. Semihosting traps with
 * BKPT 0xAB on M-profile cores; without a debugger or QEMU attached the
 * BKPT faults, so only test and benchmark programs link this.
 */
#ifndef MDR_SEMIHOST_H
#define MDR_SEMIHOST_H

void mdr_sh_write0(const char *s);
void mdr_sh_exit(int status) __attribute__((noreturn));

#endif /* MDR_SEMIHOST_H */
