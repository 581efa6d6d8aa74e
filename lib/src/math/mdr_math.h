/* SPDX-License-Identifier: MIT */
/*
 * mdr_math.h: declarations of libmdr's own freestanding math (no libm), one
 * set per arithmetic (include after mdr_arith.h). Internal: not installed.
 * Domains and error bounds are stated above each definition in mdr_math.inc;
 * callers validate arguments, these kernels do not return statuses.
 */
#include <stdbool.h>

MDR_T MDR_SFX(mdr_m_sqrt)(MDR_T x);
MDR_T MDR_SFX(mdr_m_ldexp)(MDR_T x, int e);
MDR_T MDR_SFX(mdr_m_frexp)(MDR_T x, int *e);
MDR_T MDR_SFX(mdr_m_fabs)(MDR_T x);
bool MDR_SFX(mdr_m_isfinite)(MDR_T x);
MDR_T MDR_SFX(mdr_m_log)(MDR_T x);
MDR_T MDR_SFX(mdr_m_exp)(MDR_T x);
MDR_T MDR_SFX(mdr_m_powscaled)(MDR_T c, MDR_T x, MDR_T y);
MDR_T MDR_SFX(mdr_m_atanh)(MDR_T t);
MDR_T MDR_SFX(mdr_m_atan2p)(MDR_T y, MDR_T x);
MDR_T MDR_SFX(mdr_m_atanh_m)(MDR_T t);
MDR_T MDR_SFX(mdr_m_atanh_m2)(MDR_T t, MDR_T omt);
void MDR_SFX(mdr_m_sincos)(MDR_T x, MDR_T *s, MDR_T *c);
MDR_T MDR_SFX(mdr_m_gamma_ratio_half)(MDR_T m);
void MDR_SFX(mdr_m_struve01)(MDR_T z, MDR_T zl, MDR_T *h0, MDR_T *h1, MDR_T *h0p, MDR_T *zh0_h1);
void MDR_SFX(mdr_m_struve01_wave)(MDR_T x, MDR_T lambda, MDR_T *z, MDR_T *h0, MDR_T *h1, MDR_T *h0p,
                                  MDR_T *zh0_h1);
