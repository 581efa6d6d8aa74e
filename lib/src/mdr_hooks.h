/*
 * mdr_hooks.h: the port hooks lib/ uses, with their defaults. The port's
 * mdr_port.h (port/host, port/cortex-m, port/riscv, or a firmware's own,
 * found on the include path) may define any of them first:
 *
 *   MDR_PORT_SQRT_F32(x), MDR_PORT_SQRT_F64(x)
 *                  square root (the FPU instruction); default: lib/'s own
 *                  Newton routine (lib/src/mdr_math_t.c, correctly rounded
 *                  to 1 ulp)
 *   MDR_INLINE     qualifiers of the small helpers of the step (default
 *                  `static inline`)
 *   MDR_STEP_FN    attribute of every function on the step path (the public
 *                  step functions and what they call): a section such as
 *                  ".ramfunc" or ".itcm" to run the step from RAM; default
 *                  none. The port headers set it from MDR_STEP_SECTION.
 *   MDR_ASSERT(c)  internal invariants (never input checks: bad input is a
 *                  status code); default compiled out.
 */
#ifndef MDR_HOOKS_H
#define MDR_HOOKS_H

#include "mdr_port.h"

#ifndef MDR_INLINE
#define MDR_INLINE static inline
#endif

#ifndef MDR_STEP_FN
#define MDR_STEP_FN
#endif

#ifndef MDR_ASSERT
#define MDR_ASSERT(cond) ((void)0)
#endif

#endif /* MDR_HOOKS_H */
