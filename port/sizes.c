/* SPDX-License-Identifier: MIT */
/*
 * port/sizes.c: sizeof of every instance type on a target, read back by
 * `make size` with `nm -S` (each array's size is the type's size). Compiled,
 * never linked.
 */
#include "mdr.h"

#define MDR_SIZEOF(t) const unsigned char mdr_sizeof_##t[sizeof(t)] = {0}
MDR_SIZEOF(mdr_contact_f32);
MDR_SIZEOF(mdr_engine_f32);
MDR_SIZEOF(mdr_node_f32);
MDR_SIZEOF(mdr_table_f32);
MDR_SIZEOF(mdr_engine_q31);
MDR_SIZEOF(mdr_node_q31);
MDR_SIZEOF(mdr_table_q31);
MDR_SIZEOF(mdr_scene_f32);
