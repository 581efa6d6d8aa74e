/*
 * mdr_math_t.c: libmdr's own elementary and special functions (no libm),
 * written once for every floating arithmetic (see mdr_arith.h).
 *
 * Layout of each routine (after musl): special cases, reduction, core.
 * "eps" below is the unit roundoff of the arithmetic (2^-24 or 2^-53); error
 * bounds are for the core approximation; the final roundings add a few eps.
 * Truncation lengths differ per arithmetic and are chosen so that the
 * truncation error is below eps/4.
 */
#include "mdr_tables.h"

#if defined(MDR_ARITH_F32)
#define MDR_LOG_TERMS 6     /* |s|^13/13 < 2^-27 for |s| <= 0.1716 */
#define MDR_EXP_DEG 8       /* 0.347^9/9! = 2.0e-10 */
#define MDR_SIN_DEG 11      /* (pi/4)^13/13! = 6.0e-12 */
#define MDR_SQRT_NEWTON 3
#define MDR_POW_SPLIT 0xFFFFF000u /* keep 12 significant bits of y */
#define MDR_PIO2_1 MDR_K(1.5703125)                 /* 12 bits: k*P1 exact for |k| < 2^12 */
#define MDR_PIO2_2 MDR_K(4.837512969970703125e-4)   /* next 12 bits */
#define MDR_PIO2_3 MDR_K(7.549789954891882e-8)      /* rest */
#define MDR_LN2_HI MDR_K(0.693145751953125)         /* 13 bits */
#define MDR_LN2_LO MDR_K(1.428606765330187e-06)
#define MDR_STRUVE_ZMAX MDR_K(18.0) /* K_nu series error ~ e^-z: 1e-9 relative at 18 */
#define MDR_GL_N MDR_GL32_N
#define MDR_GL_TABLE MDR_GL32_TABLE
#define MDR_SPLIT MDR_K(4097.0)   /* 2^12 + 1, Veltkamp split */
#define MDR_2PI_HI MDR_K(6.28318548202514648)      /* fl(2 pi) */
#define MDR_2PI_LO MDR_K(-1.7484555314695172e-7)  /* 2 pi - fl(2 pi) */
#define MDR_WAVY_QMAX MDR_K(7.0368744177664e13) /* 2^46: x/lambda limit, mdr_m_struve01_wave */
#define MDR_GAMMA_M MDR_K(6.0)  /* Stirling remainder 1/(1188 x^9) < 1e-10 at x >= 6 */
#else
#define MDR_LOG_TERMS 12    /* |s|^25/25 < 2^-57 */
#define MDR_EXP_DEG 13      /* 0.347^14/14! = 4.3e-18 */
#define MDR_SIN_DEG 19      /* (pi/4)^21/21! = 3.2e-22 */
#define MDR_SQRT_NEWTON 5
#define MDR_POW_SPLIT 0xFFFFFFFFF8000000u /* keep 26 significant bits of y */
#define MDR_PIO2_1 MDR_K(1.570796325802803)         /* 30 bits */
#define MDR_PIO2_2 MDR_K(9.920935791635221e-10)     /* next 30 bits */
#define MDR_PIO2_3 MDR_K(5.170182981794105e-19)
#define MDR_LN2_HI MDR_K(6.93147180369123816490e-01) /* fdlibm ln2_hi, 32 bits */
#define MDR_LN2_LO MDR_K(1.90821492927058770002e-10)
#define MDR_STRUVE_ZMAX MDR_K(40.0) /* K_nu series error ~ e^-z: 3e-20 at 40 */
#define MDR_GL_N MDR_GL64_N
#define MDR_GL_TABLE MDR_GL64_TABLE
#define MDR_SPLIT MDR_K(134217729.0) /* 2^27 + 1, Veltkamp split */
#define MDR_2PI_HI MDR_K(6.283185307179586232)     /* fl(2 pi) */
#define MDR_2PI_LO MDR_K(2.4492935982947064e-16)   /* 2 pi - fl(2 pi) */
#define MDR_WAVY_QMAX MDR_K(2.028240960365167e31) /* 2^104: x/lambda limit, mdr_m_struve01_wave */
#define MDR_GAMMA_M MDR_K(20.0) /* Stirling remainder < 2e-15 at x >= 20 */
#endif

typedef union {
    MDR_T f;
    MDR_UINT u;
} MDR_SFX(mdr_m_bits);

#define MDR_EXP_MASK ((((MDR_UINT)1 << (sizeof(MDR_T) * 8u - 1u - MDR_MANT_BITS)) - 1u))

MDR_T MDR_SFX(mdr_m_fabs)(MDR_T x)
{
    return x < MDR_K(0.0) ? -x : x;
}

bool MDR_SFX(mdr_m_isfinite)(MDR_T x)
{
    MDR_SFX(mdr_m_bits) b;
    b.f = x;
    return ((b.u >> MDR_MANT_BITS) & MDR_EXP_MASK) != MDR_EXP_MASK;
}

/* 2^e for e in the normal exponent range [1 - bias, MDR_EXP_MAX]. Exact. */
static MDR_T MDR_SFX(mdr_m_pow2)(int e)
{
    MDR_SFX(mdr_m_bits) b;
    b.u = (MDR_UINT)(e + MDR_EXP_BIAS) << MDR_MANT_BITS;
    return b.f;
}

/* x * 2^e, exact unless the result leaves the normal range (then it rounds or
 * saturates like repeated multiplication). Any int e. */
MDR_T MDR_SFX(mdr_m_ldexp)(MDR_T x, int e)
{
    while (e > MDR_EXP_MAX) {
        x *= MDR_SFX(mdr_m_pow2)(MDR_EXP_MAX);
        e -= MDR_EXP_MAX;
        if (!MDR_SFX(mdr_m_isfinite)(x)) {
            return x;
        }
    }
    while (e < 1 - MDR_EXP_BIAS) {
        x *= MDR_SFX(mdr_m_pow2)(1 - MDR_EXP_BIAS); /* smallest normal */
        e += MDR_EXP_BIAS - 1;
        if (x == MDR_K(0.0)) {
            return x;
        }
    }
    return x * MDR_SFX(mdr_m_pow2)(e);
}

/* x = m * 2^e with m in [1, 2) for finite x > 0 (subnormals included).
 * Returns m; x <= 0 or non-finite returns x and e = 0. Exact. */
MDR_T MDR_SFX(mdr_m_frexp)(MDR_T x, int *e)
{
    MDR_SFX(mdr_m_bits) b;
    int bias = 0;
    *e = 0;
    if (!(x > MDR_K(0.0)) || !MDR_SFX(mdr_m_isfinite)(x)) {
        return x;
    }
    if (x < MDR_MINV) {
        x = MDR_SFX(mdr_m_ldexp)(x, MDR_MANT_BITS + 1);
        bias = MDR_MANT_BITS + 1;
    }
    b.f = x;
    *e = (int)((b.u >> MDR_MANT_BITS) & MDR_EXP_MASK) - MDR_EXP_BIAS - bias;
    b.u = (b.u & (((MDR_UINT)1 << MDR_MANT_BITS) - 1u)) | ((MDR_UINT)MDR_EXP_BIAS << MDR_MANT_BITS);
    return b.f;
}

/* sqrt(x), x >= 0. Reduction x = m 4^k, m in [1, 4); initial guess
 * (m + 2)/3, the chord of sqrt on [1, 4] (relative error <= 5.7 %), then
 * Newton y <- (y + m/y)/2, whose relative error after a step is about half
 * the square of the one before: 5.7e-2, 1.6e-3, 1.3e-6, 8e-13, 3e-25; so 3
 * steps (f32) or 5 (f64) reach the rounding level. Error <= 1 ulp.
 * Negative x returns 0 (callers never pass it). */
MDR_T MDR_SFX(mdr_m_sqrt)(MDR_T x)
{
    int e, i;
    MDR_T m, y;
    if (!(x > MDR_K(0.0))) {
        return MDR_K(0.0);
    }
    if (!MDR_SFX(mdr_m_isfinite)(x)) {
        return x;
    }
    m = MDR_SFX(mdr_m_frexp)(x, &e);
    if (e & 1) {
        m *= MDR_K(2.0);
        e -= 1;
    }
    y = (m + MDR_K(2.0)) / MDR_K(3.0);
    y = MDR_K(0.5) * (y + m / y);
    for (i = 1; i < MDR_SQRT_NEWTON; i++) {
        y = MDR_K(0.5) * (y + m / y);
    }
    return MDR_SFX(mdr_m_ldexp)(y, e / 2);
}

/* log(m) for m in [sqrt(1/2), sqrt(2)): 2 atanh(s), s = (m-1)/(m+1),
 * |s| <= 0.1716, Taylor series of atanh; truncation < eps/4 relative. */
static MDR_T MDR_SFX(mdr_m_logm)(MDR_T m)
{
    MDR_T s = (m - MDR_K(1.0)) / (m + MDR_K(1.0));
    MDR_T s2 = s * s, p = MDR_K(0.0);
    int k;
    for (k = MDR_LOG_TERMS - 1; k >= 1; k--) {
        p = (p + MDR_K(1.0) / (MDR_T)(2 * k + 1)) * s2;
    }
    return MDR_K(2.0) * s * (MDR_K(1.0) + p);
}

/* natural log, x > 0 finite (else returns 0; callers validate).
 * Reduction x = m 2^e, m in [sqrt(1/2), sqrt(2)); log x = e ln2 + log m with
 * ln2 split in hi + lo so e*ln2_hi is exact. Error <= 2 ulp (absolute 2 eps
 * near x = 1). */
MDR_T MDR_SFX(mdr_m_log)(MDR_T x)
{
    int e;
    MDR_T m;
    if (!(x > MDR_K(0.0)) || !MDR_SFX(mdr_m_isfinite)(x)) {
        return MDR_K(0.0);
    }
    m = MDR_SFX(mdr_m_frexp)(x, &e);
    if (m > MDR_K(1.41421356237309504880)) {
        m *= MDR_K(0.5);
        e += 1;
    }
    return (MDR_T)e * MDR_LN2_HI + ((MDR_T)e * MDR_LN2_LO + MDR_SFX(mdr_m_logm)(m));
}

/* exp(x) for finite x (overflow gives +inf, underflow 0 or a subnormal).
 * Cody-Waite reduction x = k ln2 + r, |r| <= ln2/2; Taylor polynomial of
 * degree MDR_EXP_DEG in Horner form (truncation < eps/4); scaling by 2^k
 * exact. Error <= 2 ulp. */
MDR_T MDR_SFX(mdr_m_exp)(MDR_T x)
{
    MDR_T kf, r, p;
    int k, i;
    if (x != x) {
        return x; /* NaN: no conversion to int (found by fuzz_init: a power law with n = 1e-10) */
    }
    if (x > MDR_K(1.5) * (MDR_T)MDR_EXP_MAX * MDR_LN2) {
        return MDR_MAXV * MDR_K(2.0);
    }
    if (x < MDR_K(-1.5) * (MDR_T)MDR_EXP_MAX * MDR_LN2) {
        return MDR_K(0.0);
    }
    kf = x / MDR_LN2;
    k = (int)(kf < MDR_K(0.0) ? kf - MDR_K(0.5) : kf + MDR_K(0.5));
    r = (x - (MDR_T)k * MDR_LN2_HI) - (MDR_T)k * MDR_LN2_LO;
    p = MDR_K(1.0);
    for (i = MDR_EXP_DEG; i >= 1; i--) {
        p = MDR_K(1.0) + p * r / (MDR_T)i;
    }
    return MDR_SFX(mdr_m_ldexp)(p, k);
}

/* c * x^y for c > 0, x > 0, finite y with |y| <= 64, without intermediate
 * over/underflow (only the result may leave the range).
 * x = m 2^e (m in [sqrt(1/2), sqrt(2))); y = yh + yl with yh of 12 (f32) or
 * 26 (f64) bits so yh*e is exact; yh*e = k + f (k integer, f exact);
 * x^y = 2^k * exp(ln2*(f + yl*e) + y*log m). The exponent argument is O(|y|)
 * with absolute error ~ (|y|+1) eps, so the relative error is <= (|y|+3) eps,
 * independent of the magnitude of x (a plain exp(y log x) loses |y log x| eps).
 * Integer and half-integer y <= 16 take an exact-exponent product path. */
MDR_T MDR_SFX(mdr_m_powscaled)(MDR_T c, MDR_T x, MDR_T y)
{
    int e, ec, k;
    MDR_T m, mc, yh, yl, p, f, arg;
    MDR_SFX(mdr_m_bits) b;
    m = MDR_SFX(mdr_m_frexp)(x, &e);
    if (m > MDR_K(1.41421356237309504880)) {
        m *= MDR_K(0.5);
        e += 1;
    }
    mc = MDR_SFX(mdr_m_frexp)(c, &ec);
    if (y > MDR_K(0.0) && y <= MDR_K(16.0) && (MDR_T)(int)(y * MDR_K(2.0)) == y * MDR_K(2.0)) {
        /* y = k or k + 1/2 (k <= 16): m^k by repeated products (m^16 < 2^8)
         * and one sqrt; error <= (k + 1) / 2 ulp. */
        int kk = (int)y, i, eh = e;
        MDR_T r = mc;
        for (i = 0; i < kk; i++) {
            r *= m;
        }
        if (y != (MDR_T)kk) {
            MDR_T mh = m;
            if (eh & 1) { /* sqrt(m 2^e) = sqrt(2m) 2^((e-1)/2) */
                mh *= MDR_K(2.0);
                eh -= 1;
            }
            r *= MDR_SQRT(mh);
            return MDR_SFX(mdr_m_ldexp)(r, ec + kk * e + eh / 2);
        }
        return MDR_SFX(mdr_m_ldexp)(r, ec + kk * e);
    }
    b.f = y;
    b.u &= MDR_POW_SPLIT;
    yh = b.f;
    yl = y - yh;
    p = yh * (MDR_T)e; /* exact */
    k = (int)(p < MDR_K(0.0) ? p - MDR_K(0.5) : p + MDR_K(0.5));
    f = p - (MDR_T)k; /* exact, |f| <= 1/2 */
    arg = MDR_LN2 * (f + yl * (MDR_T)e) + y * MDR_SFX(mdr_m_logm)(m);
    return MDR_SFX(mdr_m_ldexp)(mc * MDR_SFX(mdr_m_exp)(arg), k + ec);
}

/* atanh(t) - t for 0 <= t < 1 given with omt = 1 - t, without
 * cancellation: the caller forms omt from its own exact complement (the
 * sphere: (R - x)/R, R - x exact for x >= R/2), so that near t -> 1 the
 * result is not limited by the rounding of t (with omt = 1 - t from a
 * rounded t the relative error of omt is eps/omt: 6 % at omt = 1e-6 in
 * float, found by host_tests/stress.c).
 * t <= 0.6: series sum_{k>=1} t^(2k+1)/(2k+1) (term ratio <= 0.36, summed
 * until a term is below eps/4 of the sum; at most 60 terms); error <= 2 ulp.
 * t > 0.6: (1/2) log((1+t)/(1-t)) - t. At t = 0.6 atanh = 0.693 and the
 * difference 0.093, so the subtraction amplifies the log's error by at most
 * 7.5 (3 bits), less for larger t: error <= 16 ulp. */
MDR_T MDR_SFX(mdr_m_atanh_m2)(MDR_T t, MDR_T omt)
{
    if (t <= MDR_K(0.6)) {
        MDR_T t2 = t * t, term = t * t2, sum = MDR_K(0.0);
        int k;
        for (k = 1; k <= 60; k++) {
            MDR_T add = term / (MDR_T)(2 * k + 1);
            sum += add;
            if (add <= sum * MDR_EPS * MDR_K(0.25)) {
                break;
            }
            term *= t2;
        }
        return sum;
    }
    return MDR_K(0.5) * MDR_SFX(mdr_m_log)((MDR_K(1.0) + t) / omt) - t;
}

/* atanh(t) - t for 0 <= t < 1 (omt = 1 - t). */
MDR_T MDR_SFX(mdr_m_atanh_m)(MDR_T t)
{
    return MDR_SFX(mdr_m_atanh_m2)(t, MDR_K(1.0) - t);
}

/* atanh(t) for 0 <= t < 1: t + (atanh(t) - t). Error <= 3 ulp. */
MDR_T MDR_SFX(mdr_m_atanh)(MDR_T t)
{
    return t + MDR_SFX(mdr_m_atanh_m)(t);
}

/* atan2(y, x) for y >= 0, x >= 0, not both 0: the angle in [0, pi/2].
 * u = min/max in [0, 1] (the swap gives pi/2 - atan u); for u > tan(pi/12)
 * atan u = pi/6 + atan v, v = (sqrt3 u - 1)/(u + sqrt3), |v| <= tan(pi/12)
 * = 0.268 (the tangent addition formula); then the Taylor series of atan v
 * (term ratio <= 0.072, summed until a term is below eps/4 of the sum, at
 * most 40 terms). Error <= 3 ulp of the result; for tiny y/x the result
 * keeps full relative accuracy (no reduction). */
MDR_T MDR_SFX(mdr_m_atan2p)(MDR_T y, MDR_T x)
{
    const MDR_T sqrt3 = MDR_K(1.73205080756887729352744634150587237);
    MDR_T u, v, v2, term, sum, base = MDR_K(0.0);
    bool swap = y > x;
    int k;
    u = swap ? x / y : y / x;
    if (u > MDR_K(0.267949192431122706472553658494127633)) {
        v = (sqrt3 * u - MDR_K(1.0)) / (u + sqrt3);
        base = MDR_PI / MDR_K(6.0);
    } else {
        v = u;
    }
    v2 = v * v;
    term = v;
    sum = v;
    for (k = 1; k <= 40; k++) {
        MDR_T add;
        term *= -v2;
        add = term / (MDR_T)(2 * k + 1);
        sum += add;
        if (MDR_SFX(mdr_m_fabs)(add) <= MDR_SFX(mdr_m_fabs)(sum) * MDR_EPS * MDR_K(0.25)) {
            break;
        }
    }
    sum += base;
    return swap ? MDR_PI * MDR_K(0.5) - sum : sum;
}

/* sin and cos of x, |x| <= MDR_SINCOS_XMAX (asserted: the callers reduce
 * larger phases themselves, mdr_m_struve01_wave). Reduction by pi/2 with a
 * three-part Cody-Waite constant (k*P1 and k*P2 exact for |k| < 2^12 in
 * f32, 2^30 in f64, i.e. |x| < 6400 resp. 1.6e9; beyond, the reduction
 * error grows like |x| eps); Taylor polynomials of sin (degree MDR_SIN_DEG)
 * and cos (degree MDR_SIN_DEG-1) on |r| <= pi/4: truncation < eps/4.
 * Error <= 2 ulp for |x| < 6400. */
#define MDR_SINCOS_XMAX MDR_K(1.0e9)
void MDR_SFX(mdr_m_sincos)(MDR_T x, MDR_T *s, MDR_T *c)
{
    const bool in = x <= MDR_SINCOS_XMAX && x >= -MDR_SINCOS_XMAX;
    MDR_T kf = in ? x * MDR_K(0.636619772367581343075535053490057448) : MDR_K(0.0);
    long k;
    MDR_ASSERT(in); /* compiled out, an x outside gives garbage, not UB */
    k = (long)(kf < MDR_K(0.0) ? kf - MDR_K(0.5) : kf + MDR_K(0.5));
    MDR_T r = ((x - (MDR_T)k * MDR_PIO2_1) - (MDR_T)k * MDR_PIO2_2) - (MDR_T)k * MDR_PIO2_3;
    MDR_T r2 = r * r, ps = MDR_K(0.0), pc = MDR_K(0.0), sr, cr;
    int i;
    /* sin r = r (1 - r^2/(2*3) (1 - r^2/(4*5) (...))) */
    for (i = MDR_SIN_DEG; i >= 3; i -= 2) {
        ps = r2 / (MDR_T)((i - 1) * i) * (MDR_K(1.0) - ps);
    }
    sr = r * (MDR_K(1.0) - ps);
    for (i = MDR_SIN_DEG - 1; i >= 2; i -= 2) {
        pc = r2 / (MDR_T)((i - 1) * i) * (MDR_K(1.0) - pc);
    }
    cr = MDR_K(1.0) - pc;
    switch ((unsigned long)k & 3u) {
    case 0u:
        *s = sr;
        *c = cr;
        break;
    case 1u:
        *s = cr;
        *c = -sr;
        break;
    case 2u:
        *s = -sr;
        *c = -cr;
        break;
    default:
        *s = -cr;
        *c = sr;
        break;
    }
}

/* Rounding error of p = fl(x y): x y - p exactly, by Veltkamp splitting
 * (Dekker 1971), valid without FMA and without overflow for |x|,|y| < 1e15
 * in f32 (< 1e150 in f64). */
static MDR_T MDR_SFX(mdr_m_two_prod_err)(MDR_T x, MDR_T y, MDR_T p)
{
    MDR_T tx = MDR_SPLIT * x, ty = MDR_SPLIT * y;
    MDR_T xh = tx - (tx - x), xl = x - xh;
    MDR_T yh = ty - (ty - y), yl = y - yh;
    return ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
}

/* 2 pi (qh + ql) as an unevaluated sum zh + zl, |zl| <= ulp(zh), error
 * ~eps^2 (two-product with 2 pi = hi + lo). */
static void MDR_SFX(mdr_m_two_pi)(MDR_T qh, MDR_T ql, MDR_T *zh, MDR_T *zl)
{
    MDR_T h = MDR_2PI_HI * qh;
    *zl = MDR_SFX(mdr_m_two_prod_err)(MDR_2PI_HI, qh, h) + (MDR_2PI_HI * ql + MDR_2PI_LO * qh);
    *zh = h;
}

/* x / lambda as qh + ql to ~eps^2: compensated division (the residual
 * x - qh lambda is exact by two-product and Sterbenz). */
static void MDR_SFX(mdr_m_turns)(MDR_T x, MDR_T lambda, MDR_T *qh, MDR_T *ql)
{
    MDR_T q = x / lambda, p = q * lambda;
    *ql = ((x - p) - MDR_SFX(mdr_m_two_prod_err)(q, lambda, p)) / lambda;
    *qh = q;
}

/* log(1+u) - u for |u| <= 1/40: alternating series -u^2/2 + u^3/3 - ...
 * (ratio <= 1/40; 12 terms leave < 1e-21). */
static MDR_T MDR_SFX(mdr_m_log1pm)(MDR_T u)
{
    MDR_T p = MDR_K(0.0);
    int k;
    for (k = 13; k >= 2; k--) {
        p = u * (MDR_K(1.0) / (MDR_T)k * ((k & 1) ? MDR_K(1.0) : MDR_K(-1.0)) + p);
    }
    return u * p;
}

/* Stirling series of log Gamma(x) without the leading terms:
 * S(x) = 1/(12x) - 1/(360x^3) + 1/(1260x^5) - 1/(1680x^7) (DLMF 5.11.1);
 * truncation < 1/(1188 x^9). */
static MDR_T MDR_SFX(mdr_m_stirling)(MDR_T x)
{
    MDR_T r = MDR_K(1.0) / x, r2 = r * r;
    return r * (MDR_K(1.0) / MDR_K(12.0) -
                r2 * (MDR_K(1.0) / MDR_K(360.0) -
                      r2 * (MDR_K(1.0) / MDR_K(1260.0) - r2 / MDR_K(1680.0))));
}

/* Gamma(m + 1/2)/Gamma(m) for m > 0 (kappa_n = sqrt(pi) * this at
 * m = (n+1)/2, seed 4.65). Upward recurrence ratio(m) = m/(m+1/2) ratio(m+1)
 * to M >= 6 (f32) or 20 (f64), then ratio(M) = sqrt(M) exp(M (log1p(u) - u) + S(M+1/2) - S(M)),
 * u = 1/(2M), from Stirling's series (no cancellation: every part is small).
 * Error <= (number of recurrence steps + 4) eps: < 10 eps (f32), 24 eps (f64). */
MDR_T MDR_SFX(mdr_m_gamma_ratio_half)(MDR_T m)
{
    MDR_T prod = MDR_K(1.0), M = m, u;
    while (M < MDR_GAMMA_M) {
        prod *= M / (M + MDR_K(0.5));
        M += MDR_K(1.0);
    }
    u = MDR_K(0.5) / M;
    return prod * MDR_SQRT(M) *
           MDR_SFX(mdr_m_exp)(M * MDR_SFX(mdr_m_log1pm)(u) + MDR_SFX(mdr_m_stirling)(M + MDR_K(0.5)) -
                              MDR_SFX(mdr_m_stirling)(M));
}

/*
 * Struve functions H0(z), H1(z), H0'(z) and z*H0(z) - H1(z) for z >= 0, the
 * argument given as z + zl (zl: the low part of an exactly formed phase, or
 * 0; it enters the phases only, amplitudes use z).
 *
 * z <= ZMAX (18 in f32, 40 in f64): Gauss-Legendre quadrature (32 nodes in
 *   f32, 64 in f64) of
 *   H0 = (2/pi) int_0^{pi/2} sin(z cos t) dt,
 *   H1 = (2z/pi) int_0^{pi/2} sin^2 t sin(z cos t) dt,
 *   z H0 - H1 = (2z/pi) int_0^{pi/2} cos^2 t sin(z cos t) dt,
 *   H0' = 2/pi - H1 = (2/pi) int_0^{pi/2} cos t cos(z cos t) dt
 *   (DLMF 11.5.1/11.5.2, 11.4.27). The integrands are entire; the Gauss
 *   remainder (pi/2)^(2n+1) (n!)^4 z^(2n) / ((2n+1) ((2n)!)^3) is < 1e-15 for
 *   n = 32, z = 18 and < 1e-30 for n = 64, z = 40. No cancellation: small z
 *   scales every node value by z. The argument z cos t is formed exactly
 *   (two-product) and the sums are compensated.
 * z > ZMAX: H_n = Y_n + K_n with the asymptotic expansions of K_n
 *   (DLMF 11.6.1) and of Y_n (Hankel, DLMF 10.17.4), each summed until its
 *   terms stop decreasing or fall below eps/4. The smallest term of the K_n
 *   series, (1/pi^2) Gamma(k+1/2)^2 (2/z)^(2k+1) at k ~ z/2, is ~ e^-z:
 *   1e-9 at z = 18 (f32), 3e-20 at z = 40 (f64); Hankel's is ~ e^-2z.
 */
static void MDR_SFX(mdr_m_hankel_pq)(MDR_T nu4, MDR_T z, MDR_T *P, MDR_T *Q)
{
    /* P = sum_k (-1)^k a_2k / z^2k, Q = sum_k (-1)^k a_(2k+1) / z^(2k+1),
     * a_k = prod_{j=1..k} (4nu^2 - (2j-1)^2) / (k! 8^k) */
    MDR_T term = MDR_K(1.0), p = MDR_K(0.0), q = MDR_K(0.0), prev = MDR_MAXV;
    int k;
    for (k = 0; k < 60; k++) {
        MDR_T at = MDR_SFX(mdr_m_fabs)(term);
        if (at > prev) {
            break;
        }
        switch (k & 3) {
        case 0: p += term; break;
        case 1: q += term; break;
        case 2: p -= term; break;
        default: q -= term; break;
        }
        if (at < MDR_EPS * MDR_K(0.25)) {
            break;
        }
        prev = at;
        term *= (nu4 - (MDR_T)((2 * k + 1) * (2 * k + 1))) / ((MDR_T)(k + 1) * MDR_K(8.0) * z);
    }
    *P = p;
    *Q = q;
}

/* K_0(z), or K_1(z) - 2/pi (its leading term left out, so that
 * H0' = 2/pi - H1 = -Y1 - (K1 - 2/pi) needs no subtraction).
 * K_nu(z) ~ (1/pi) sum_k Gamma(k+1/2)/Gamma(nu+1/2-k) (z/2)^(nu-2k-1);
 * term ratio (k+1/2)(nu-1/2-k)(2/z)^2. */
static MDR_T MDR_SFX(mdr_m_struve_k)(int nu, MDR_T z)
{
    MDR_T rz2 = MDR_K(4.0) / (z * z);
    MDR_T term = (nu == 0) ? MDR_K(2.0) / (MDR_PI * z) : MDR_K(2.0) / MDR_PI * MDR_K(0.5) * MDR_K(0.5) * rz2;
    MDR_T sum = MDR_K(0.0), prev = MDR_MAXV;
    int k;
    for (k = nu; k < 60; k++) {
        MDR_T at = MDR_SFX(mdr_m_fabs)(term);
        if (at > prev) {
            break;
        }
        sum += term;
        if (at < MDR_SFX(mdr_m_fabs)(sum) * MDR_EPS * MDR_K(0.25)) {
            break;
        }
        prev = at;
        term *= ((MDR_T)k + MDR_K(0.5)) * ((MDR_T)nu - MDR_K(0.5) - (MDR_T)k) * rz2;
    }
    return sum;
}

/* The large-z branch of mdr_m_struve01 (z > MDR_STRUVE_ZMAX) given sv, cv =
 * sin z, cos z (reduced by the caller: the phase of a wave is reduced by
 * whole wavelengths, where it is exact). */
static void MDR_SFX(mdr_m_struve01_asym)(MDR_T z, MDR_T sv, MDR_T cv, MDR_T *h0, MDR_T *h1, MDR_T *h0p,
                                         MDR_T *zh0_h1)
{
    MDR_T p0, q0, p1, q1, amp, y0, y1, k1m;
    MDR_SFX(mdr_m_hankel_pq)(MDR_K(0.0), z, &p0, &q0);
    MDR_SFX(mdr_m_hankel_pq)(MDR_K(4.0), z, &p1, &q1);
    /* chi0 = z - pi/4, chi1 = z - 3pi/4: with (s, c) = sincos(z),
     * sin chi0 = (s - c)/sqrt2, cos chi0 = (c + s)/sqrt2,
     * sin chi1 = -(s + c)/sqrt2, cos chi1 = (s - c)/sqrt2. */
    amp = MDR_SQRT(MDR_K(1.0) / (MDR_PI * z)); /* sqrt(2/(pi z)) / sqrt2 */
    y0 = amp * (p0 * (sv - cv) + q0 * (cv + sv));
    y1 = amp * (-p1 * (sv + cv) + q1 * (sv - cv));
    k1m = MDR_SFX(mdr_m_struve_k)(1, z); /* K1 - 2/pi */
    *h0 = y0 + MDR_SFX(mdr_m_struve_k)(0, z);
    *h1 = y1 + (MDR_K(2.0) / MDR_PI + k1m);
    *h0p = -y1 - k1m;
    *zh0_h1 = z * *h0 - *h1;
}

/* sin and cos of zh + zl (|zh| <= MDR_SINCOS_XMAX, zl <= ulp(zh)) to first
 * order in zl. */
static void MDR_SFX(mdr_m_sincos2)(MDR_T zh, MDR_T zl, MDR_T *s, MDR_T *c)
{
    MDR_T sv, cv;
    MDR_SFX(mdr_m_sincos)(zh, &sv, &cv);
    *s = sv + zl * cv;
    *c = cv - zl * sv;
}

void MDR_SFX(mdr_m_struve01)(MDR_T z, MDR_T zl, MDR_T *h0, MDR_T *h1, MDR_T *h0p, MDR_T *zh0_h1)
{
    if (z <= MDR_STRUVE_ZMAX) {
        static const MDR_T gl[MDR_GL_N][4] = {MDR_GL_TABLE};
        /* Kahan-compensated sums: the accumulation then adds < 2 eps instead
         * of up to 32 eps (measured 8 ulp in f32 without it) */
        MDR_T s[4] = {MDR_K(0.0), MDR_K(0.0), MDR_K(0.0), MDR_K(0.0)};
        MDR_T cmp[4] = {MDR_K(0.0), MDR_K(0.0), MDR_K(0.0), MDR_K(0.0)};
        int i, j;
        for (i = 0; i < MDR_GL_N; i++) {
            MDR_T sv, cv, t[4], p, e;
            /* p + e = z cos(t_i) to ~eps^2 (Dekker's two-product of z and the
             * node's hi part, plus z times its lo part), then
             * sin(p + e) = sin p + e cos p to first order: the rounding of
             * the argument (up to 1 ulp of z) no longer reaches the result */
            p = z * gl[i][0];
            e = MDR_SFX(mdr_m_two_prod_err)(z, gl[i][0], p) + (z * gl[i][3] + zl * gl[i][0]);
            MDR_SFX(mdr_m_sincos)(p, &sv, &cv);
            {
                MDR_T s0v = sv;
                sv += e * cv;
                cv -= e * s0v;
            }
            sv *= gl[i][2];
            t[0] = sv;
            t[1] = sv * gl[i][1];
            t[2] = sv * (MDR_K(1.0) - gl[i][1]);
            t[3] = cv * gl[i][2] * gl[i][0];
            for (j = 0; j < 4; j++) {
                MDR_T y = t[j] - cmp[j], u = s[j] + y;
                cmp[j] = (u - s[j]) - y;
                s[j] = u;
            }
        }
        *h0 = s[0];
        *h1 = z * s[1];
        *h0p = s[3];
        *zh0_h1 = z * s[2];
    } else {
        MDR_T sv, cv;
        MDR_SFX(mdr_m_sincos2)(z, zl, &sv, &cv);
        MDR_SFX(mdr_m_struve01_asym)(z, sv, cv, h0, h1, h0p, zh0_h1);
    }
}

/* mdr_m_struve01 at z = 2 pi x/lambda (returned in *z) for the wavy profile:
 * the phase as zh + zl to ~eps^2 z (a phase formed in plain arithmetic is
 * off by ~3 eps z, which at z = 70 moves an oscillating term by 1e-5 of its
 * amplitude in f32), and for the large-z branch sin z, cos z from
 * the phase reduced by whole wavelengths, 2 pi ((qh - n) + ql) with n the
 * integer nearest qh (qh - n exact), so that sin and cos keep their ulp
 * accuracy for any number of wavelengths (a plain reduction of z loses
 * |z| eps, and leaves the domain of mdr_m_sincos past 1e9). */
/* The integer nearest v (ties to even), exactly: beyond 2^23 (f32) resp.
 * 2^52 (f64) every float is an integer. */
static MDR_T MDR_SFX(mdr_m_nearest_int)(MDR_T v)
{
    const MDR_T big = MDR_K(0.5) / MDR_EPS;
    if (!(v < big && v > -big)) {
        return v;
    }
    return v < MDR_K(0.0) ? (v - big) + big : (v + big) - big;
}

void MDR_SFX(mdr_m_struve01_wave)(MDR_T x, MDR_T lambda, MDR_T *z, MDR_T *h0, MDR_T *h1, MDR_T *h0p,
                                  MDR_T *zh0_h1)
{
    MDR_T qh, ql, zh, zl, rh, rl, sv, cv;
    MDR_SFX(mdr_m_turns)(x, lambda, &qh, &ql);
    MDR_SFX(mdr_m_two_pi)(qh, ql, &zh, &zl);
    *z = zh;
    if (zh <= MDR_STRUVE_ZMAX) {
        MDR_SFX(mdr_m_struve01)(zh, zl, h0, h1, h0p, zh0_h1);
        return;
    }
    /* Whole turns off twice, each step exact: f = qh - (integer nearest
     * qh); where qh's ulp is >= 1 the turns lie in ql too, so fh + fl =
     * f + ql (Fast2Sum: f is a multiple of ulp(qh) >= 2|ql|, or 0) loses
     * its nearest integer again. The callers keep x/lambda < MDR_WAVY_QMAX
     * = (2^23)^2 resp. (2^52)^2 (mdr_c_domain), so |ql| < 2^23 resp. 2^52
     * and that step is exact too; the phase keeps an error of
     * ~eps max(1, ulp(qh)) turns. */
    {
        MDR_T f = qh - MDR_SFX(mdr_m_nearest_int)(qh), fh = f + ql, fl = (f - fh) + ql;
        MDR_T r = fh - MDR_SFX(mdr_m_nearest_int)(fh);
        fh = r + fl;
        MDR_SFX(mdr_m_two_pi)(fh, (r - fh) + fl, &rh, &rl);
    }
    MDR_SFX(mdr_m_sincos2)(rh, rl, &sv, &cv);
    MDR_SFX(mdr_m_struve01_asym)(zh, sv, cv, h0, h1, h0p, zh0_h1);
}
