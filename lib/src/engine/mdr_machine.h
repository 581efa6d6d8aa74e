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

/* the mark on an engine's mode while its pinned edge's linear
 * coefficients wait for the next pinned tick (MDR_M_LAZY) */
#define MDR_M_STALE 0x80u
/* the band end a move left open (MDR_M_LAZY_END): pin.open */
#define MDR_M_OPEN_LO 1u
#define MDR_M_OPEN_HI 2u
/* 1 where the solver's moves leave control ctl's coefficients stale */
#define MDR_M_LAZY_IN(ctl) ((MDR_M_LAZY >> (ctl)) & 1u)

/* k_in, k_fold of a control mode whose landing or fold is not known
 * (the engines' known_land, known_fold: the step scans) */
#define MDR_E_NO_LANDING 0xFFFFu

#if MDR_CFG_Q31 && MDR_CFG_ENGINE
/* the q31 engine's landings (mdr_edge_table.inc, in mdr_q31.c), which its
 * float init (engine/mdr_q31_init.inc) calls on the filled instance; false:
 * a pull-off at a rim inside spring 0 (the table's rim0) not excluded */
bool mdr_t_landings_q31(mdr_engine_q31 *s);
#endif

#endif /* MDR_MACHINE_H */
