/*
 * port/host/mdr_port.h: hooks for host builds (x86-64, aarch64 with an FPU).
 * Chosen by the include path (-Iport/host). Every hook has a default in
 * lib/src/mdr_arith.h; define one here to override it.
 *
 *  MDR_PORT_SQRT_F32/F64(x)  square root; the compiler builtin becomes one
 *                            instruction with -fno-math-errno (the Makefile
 *                            sets it), otherwise our own Newton routine.
 *  MDR_ASSERT(cond)          internal invariants; trap on the host.
 */
#ifndef MDR_PORT_H
#define MDR_PORT_H

#ifndef MDR_PORT_OWN_SQRT
#define MDR_PORT_SQRT_F32(x) __builtin_sqrtf(x)
#define MDR_PORT_SQRT_F64(x) __builtin_sqrt(x)
#endif

#define MDR_ASSERT(cond) ((cond) ? (void)0 : __builtin_trap())

#endif /* MDR_PORT_H */
