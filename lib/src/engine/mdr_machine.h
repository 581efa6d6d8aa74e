/* SPDX-License-Identifier: MIT */
/*
 * mdr_machine.h: what every instance of the state machine shares, whatever
 * its arithmetic (included once per translation unit by the engines'
 * common files).
 */
#ifndef MDR_MACHINE_H
#define MDR_MACHINE_H

/* what an edge solver's move and land return (mdr_machine.inc), besides
 * refusals (negative statuses) */
enum { MDR_M_ROOT, MDR_M_FOLD, MDR_M_END };

#endif /* MDR_MACHINE_H */
