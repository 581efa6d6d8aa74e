/* SPDX-License-Identifier: MIT */
/*
 * fl.h: x rounded to float and back, the value a float caller passes, for
 * tests that compare f32 against f64 at the same inputs (test_vectors.c,
 * stress.c). Through a volatile: GCC 12.2 -O2 (x86-64) dropped the rounding
 * of {(double)(float)v[2], (double)(float)v[3], ...} when its SLP vectoriser
 * paired it with the float conversions of the same values (seen in
 * test_vectors, and in stress.c's float-rounded parameters; with
 * -fno-tree-slp-vectorize the rounding is kept).
 */
#ifndef FL_H
#define FL_H

static inline double fl(double x)
{
    volatile float f = (float)x;
    return f;
}

#endif /* FL_H */
