/* SPDX-License-Identifier: MIT */
/*
 * mdr.h: umbrella header of libmdr. Include this one.
 * Freestanding C99: needs only <stdint.h>, <stdbool.h> and <stddef.h>.
 */
#ifndef MDR_H
#define MDR_H

#include "mdr_types.h"
#include "mdr_contact.h"
#include "mdr_engine.h"
#include "mdr_scene.h"
#include "mdr_q31.h"
#include "mdr_scene_q31.h"
#include "mdr_fit.h"

#define MDR_VERSION_MAJOR 0
#define MDR_VERSION_MINOR 1

#endif /* MDR_H */
