/* SPDX-License-Identifier: MIT */
/*
 * test_fit.c: the fit module (lib/include/mdr_fit.h) on curves made by the
 * library's own forward model and by the JKR closed forms through a
 * cantilever written here with libm (jkr_* below, independent of lib/), with
 * noise, offsets in z and F, coarse and fine sampling, the three regimes,
 * f32 and f64; every bad input.
 *
 * On the emulated Cortex-M4F (make target-test, f64 in soft double) the
 * curves are shorter (the profiles coarse only, without the wavy one), the
 * Monte Carlo has NMC = 6 copies and the refusal sweeps are thinned
 * (NREV_SIZES and the rest below NMAX); the tolerances are the same or
 * derived from NMC; four statistical tests of f64 alone run on the host
 * only (TARGET_F64 below).
 *
 * Tolerances (relative unless said):
 *   TOL_MODEL = 1e-11: the library's forward model against the closed form,
 *     whole retract curves, relative to max|F| (both in double). Near the
 *     fold F - F_fold ~ sqrt(z' - z_fold): a rounding of z' by eps |z'|
 *     moves F there by up to ~sqrt(eps) of F (1e-9 at a sample 1e-9 a_fold
 *     above the fold); on these uniform samples measured worst 1.3e-12;
 *   TOL_RT = 5e-8: noise-free round trip (f64) of E*, w, F_b (relative to
 *     |F_po|) and z0 (relative to the z range of the contact), on curves of
 *     the forward model and of the closed form, every profile, coarse (40
 *     points) and fine (800 to 3000) sampling. The issue asks for 1e-6;
 *     measured worst 1.5e-8 (where a sample lies on the fold itself u
 *     converges linearly);
 *   TOL_RT_CF = 1e-10: the same on the closed-form curves, with and without
 *     a pinned top: measured 6.3e-12 and 3.3e-12 (the target 9.7e-12); the
 *     LM takes its last step, below sqrt(eps) in the scaled parameters
 *     (without it 1.5e-10 with a flat baseline, 8.7e-9 with its slope
 *     fitted);
 *   TOL_RT32 = 5e-5: the same in f32, measured worst 1.9e-5 (the data
 *     rounded to float: z carries ~1e-7 of itself, and E* follows from
 *     d = z - F/k_m, up to 40x smaller than z through a soft lever);
 *   noise: Monte Carlo over NMC noisy copies (Gaussian, sigma = 1 % of the
 *     pull-off force) of one closed-form curve per regime: the bias of the
 *     mean estimate within 4 standard errors of the mean (4 s/sqrt(NMC),
 *     s the larger of the copies' scatter sd and the mean reported error),
 *     the scatter sd within a factor RATIO of the mean standard error the
 *     fit reports, RATIO = 1 + 4/sqrt(2 (NMC - 1)): 4 standard deviations
 *     of a sample sd over NMC copies (1.45 for the host's 40; measured worst
 *     1.30; not checked on the target's 6, too few for a sample sd), and
 *     every single estimate within 5 reported standard errors of the truth (the reported errors
 *     carry the fold's position within the sampling step: mdr_fit_curve);
 *   TOL_TP = 1e-9: the two-point method when the zero-force point and the
 *     fold are samples (it is then exact for the model; measured 1e-12);
 *     TOL_TP_GRID = 0.5: two-point on 300 uniform samples, a first guess:
 *     it takes the last contact sample for the fold, whose force differs
 *     from the fold's by O(sqrt(step)) (measured worst 0.21 in E*);
 *   TOL_MU = 1e-13: the Tabor parameter against its formula;
 *   pinned top (w_adv < w): TOL_RT_CF on noise-free closed-form curves whose
 *     retract starts pinned (the fit leaves that part out; n_pinned the
 *     samples above the pinned part's end, or one more where the first
 *     receding sample lies on the pinned line within the rounding);
 *   coverage of the standard errors (test_cover_fold): over NCOVER
 *     closed-form curves with E*, w, R, k_m log-uniform over the sweep's
 *     ranges (test_fit_sweep), noise 1e-8 of the pull-off force (where a
 *     fit stuck at the wrong end of the sampling step, its bias about 1 %
 *     of w, shows as hundreds of errors) and the fold anywhere in the
 *     sampling step, the estimates of ln E* or ln w beyond 3 reported
 *     errors at most COVER_FRAC = 3 % of the answers (with the baseline
 *     flat, opts.flat, whose tight errors show a fold at the wrong end; then
 *     the same curves with the slope fitted: measured 4 of 449 and 3 of 390
 *     beyond 3, worst 3.64), rounded up to a
 *     whole curve (host only: TARGET_F64; at stop 38 the M4F's 24 curves
 *     met 1 of 19 answers, 3.27 errors) (a Gaussian: 0.3 to
 *     0.5 % for the two; measured 1.8 %, 8 of 448, the largest 3.3, and
 *     1.0 % over 1 500 curves), none beyond COVER_MAX = 8 (before the fix
 *     11 of 451 beyond 3, the worst 232: fits stopped with the fold at the
 *     last contact sample, mdr_fit.inc mdr_f_fold_saddle); the same over
 *     NCOVER curves with the fold within 0.1 % of a step below a sample
 *     (measured: none beyond 3, worst 2.96; 10.3 without the fold's
 *     variance of 1/4 at a saddle the search does not leave; with the
 *     fold within 1 %, a wider sweep met 6.1: a fit stopped in a valley
 *     along u where E* is barely determined, its relative error 0.2;
 *     helper, on aa8752c: the 10.3 no longer shows, without that variance
 *     the worst is 2.84 as with it, the fold's profile widening the
 *     errors there, and 4 and 3 more answers, so fit-fold-var-saddle
 *     survived this test); noise-free, where the profile does not run
 *     (test_fold_saddle_noise_free): every answer at a saddle within
 *     TOL_RT of the truth or COVER_MAX errors, a refusal passes (measured:
 *     all 28 refused; without that variance 28 answers 100 to 218 errors
 *     off);
 *   two-point errors (test_two_point_errors): over NTPCOV closed-form
 *     curves per row (16 to 1 000 samples, noise 0, 0.1 %, 1 %), every
 *     answer within COVER_MAX errors, noise-free with 40 samples or more
 *     within TP_COVER = 3.5 (measured 2.34), with noise at most COVER_FRAC
 *     beyond 3 (rounded up to a whole curve; every size, 16 samples too
 *     since the noise's upper bound refuses what 5 free samples cannot
 *     say: measured 0 of 41 answers, 4 of 3 203 over all sizes with
 *     NTPCOV = 400, compiled with -DNTPCOV=400); against a Monte Carlo
 *     (test_two_point_mc): the rms error over NMC copies within RATIO of
 *     the rms reported error (300 samples or more) or TP_MC_COARSE = 2
 *     (40 samples; measured 1.81, the errors too small there);
 *   flat valleys (test_refuse_valley): every answer within COVER_MAX,
 *     at most COVER_FRAC beyond 3 errors (rounded up to a whole curve);
 *   pinned to the rupture (a_t below the fold's radius): MDR_E_PINNED on
 *     every copy, noise-free and NMC copies with sigma = 0.1 % of the
 *     rupture force; a noisy pinned top through a 2 N/m lever (sigma 0.1 %
 *     of the pull-off force, NMC copies): every estimate of E*, w within 5
 *     reported standard errors (test_noise's rule) and n_pinned > 0;
 *   time order (test_order_*, test_reversed_baseline_step): status only,
 *     no tolerance: a curve in time order (the library's forward model,
 *     w_adv = w) never MDR_E_ORDER with its approach's baseline ORDER_STEP
 *     = 5 or ORDER_STEP_BIG = 30 noise widths (ORDER_SIG = 0.1 % of the
 *     pull-off force; 30: drag, drift) above the retract's (NORDER seeds
 *     of NORDER_PTS + NORDER_PTS samples), with a two-sample glitch (10 %
 *     of the pull-off force) on its approach's free part (noise-free, each
 *     regime), or with AR(1) noise (ORDER_RHO = 0.9, 1 %), or with white
 *     noise alone and its retract ending 3 to ORDER_TAIL_MAX = 8 samples
 *     after the pull-off, or coarse (8 to 40 samples a branch, the three
 *     regimes, E* x 0.3, 1, 3, w_adv/w = 1, 0.5, 0.25, noise-free or
 *     ORDER_SIG with the retract ending 3, 4 or 6 samples after its
 *     pull-off; test_order_coarse); the whole curve
 *     reversed, its approach's baseline ORDER_DRAG = 1 % of the pull-off
 *     force above the retract's (noise ORDER_SIG), never MDR_OK (f64 and
 *     f32, with and without opts.approach);
 *   f32 at a piezo offset, a pinned top (test_f32_pinned_offset: the
 *     transition regime and the DMT contact x 3, w_adv = 0, 100 samples,
 *     offsets z0 = 0, 0.5, 1, 2, 5 um, noise F32PIN_SIG = 0.1 % of the
 *     pull-off force, NF32PIN seeds each): every f32 answer within 5
 *     reported errors (test_noise's rule), and at least half of each
 *     row's seeds answered (measured: all 60, worst 3.7 errors; f64 on the
 *     same samples 3.8; the target's 20: 2.9). Before the fix of mdr_f_line (z's rounding) f32
 *     answered the DMT rows at 1 to 5 um 21 to 24 errors off.
 *   f64, noise-free pinned tops at piezo offsets (test_pinned_offset_clean:
 *     the three regimes, w_adv = 0 and w/2, the top at 2.5 fold radii,
 *     PINOFF_N = 112 samples, z0 = 0 to 20 um in PINOFF_STEP = 0.25 um;
 *     the host's, left out on the M4F, mk/fit.mk): every fit answered, E* and w within
 *     PINOFF_REL = 1e-8 of the truth and n_pinned the curve's (measured:
 *     486 fits, worst 6e-11; f64 only, f32's line is as it was: mdr_f_line;
 *     before stop 77's fix of mdr_f_line 65 of the
 *     40 N/m lever's refused MDR_E_MISFIT, and helper-80's closed-form
 *     curve answered E* 1.39 x, w 21 errors off at 5 um).
 *   noise-free curves as written down (test_written_digits, host only:
 *     the three regimes, w_adv = 0 and w/2, the top at 2.5 fold radii, 160
 *     samples, z0 = 2 um; z and F written with 6, 7, 9, 12 and 15
 *     significant digits and read back, F alone with 6, 9 and 15 (z's
 *     rounding, |dF/dz| times it, is the larger at a piezo offset), or F
 *     on an ADC's grid of 1e-6, 1e-5 and 1e-4 pull-off forces): every
 *     answer within DIGITS_PULL = 5 reported errors with n_pinned within 1
 *     of the curve's, the others refused MDR_E_MISFIT or
 *     MDR_E_DEGENERATE, and at least DIGITS_MIN_OK = 54 of the 66
 *     answered (measured: 58, worst 2.19 errors (2.32 before stop 80), 1.8e-3 relative; before
 *     stop 78's mdr_f_written 3 of the first 48, the rest refused: the
 *     rounding ended the pinned top's straight start; without F's digits,
 *     mdr_f_decimal, 49).
 *   z on a piezo's decimal grid (test_written_irregular, host only: three
 *     stiff contacts through soft levers, w_adv = w/4 and w/2, the top at
 *     2.5 fold radii, piezo offsets 1.3, 4.7 and 9.1 um, each position
 *     moved down to a whole unit 0, 1 or 2 digits below the mean step's
 *     leading one): with F computed there (z exact, its steps irregular),
 *     160 samples, every curve within PINOFF_REL of the truth with n_pinned
 *     within 1 (measured: 54 of 54, worst 7.1e-13; before stop 79's
 *     mdr_f_zexact 18 of the first 36 off, E* to 1.009 x, w to 0.957 x,
 *     n_pinned 0); with F at the positions before rounding (a file's
 *     rounding of z), 400 samples, every answer within DIGITS_PULL errors
 *     (measured: 18 answered, worst 1.63, 1.92 before stop 80; the rest refused).
 *   z a file's rounding whose errors drift linearly (test_written_drift,
 *     host only: the same 54 grids written exactly, F at them scaled about
 *     the bottom by -0.6 and +0.45 units over the span, DRIFT_LO/HI): every
 *     answer within DIGITS_PULL reported errors, at least DRIFT_MIN_OK = 80
 *     of the 108 answered (measured: 87, worst 1.49 errors; before stop
 *     80's errors with z's written unit, 72 of the 87 answers 8 to 30
 *     errors off, E* to 1.53 x).
 *   a glitch in a noisy pinned top (test_pinned_glitch, host only: the
 *     three regimes, w_adv = w/2, the top at 2.5 fold radii, 400 samples,
 *     noise GLITCH_SIG = 0.3 % of the pull-off force, 3 seeds; one sample
 *     of the pinned top moved by -0.3, -0.14, -0.05 and +0.14 pull-off
 *     forces, at every 6th sample from the 5th to 3 before its end): each
 *     fit has the status of the same curve without the glitch, and every
 *     answer lies within GLITCH_PULL = 5 reported errors (test_noise's
 *     rule; measured: 420 fits, 384 answered, worst 2.6 errors). Before
 *     stop 77's glitch rule (mdr_f_line) the straight start ended at the
 *     glitch and 195 of the 420 changed status: 81 (1 N/m lever) and 78
 *     (40 N/m) refused MDR_E_MISFIT where the curve without the glitch is
 *     answered, 36 (0.2 N/m) answered where it is refused MDR_E_PINNED.
 *   a step or glitch in the free tail (test_tail_step, host only): a
 *     tether of 10 or 20 % of the pull-off force over 60 % of the free
 *     samples, or one glitch sample of half or all of it, noise 0.3 %,
 *     4 seeds each: every answer within 5 reported errors, and at least
 *     half of the unflawed curves answered within 5 (measured with the
 *     baseline flat, opts.flat: 8 of 16 refused, the rest within 3.5;
 *     unflawed 4 of 4; with the slope fitted 12 refused, the rest within
 *     1.8). Before (sigma with the step in it) 3 answers 5.5 to 6.1 errors
 *     off.
 *   one glitch late in the free tail against the clean curve's errors
 *     (test_tail_glitch_clean, host only): the same curves, slope fitted,
 *     one sample raised by 0.2 .. 0.5 of the pull-off force at 80 .. 95 %
 *     of the free tail (112 curves): every answer within 12 of the
 *     unglitched fit's errors (measured 89 refused, the rest within 9.9;
 *     sigma untrimmed 0 refused, 50 beyond 12, the worst 26.9).
 *   a long-range tail after the pull-off (test_vdw_tail, host only): the
 *     free retract less 5 % or 10 % of the pull-off force times
 *     (D0/(D + D0))^2, D0 2 and 4 nm, noise 0.3 %, 4 seeds each: the same
 *     rule (measured: 16 of 16 refused, MDR_E_MISFIT, flat or sloped;
 *     before 8 of 16 answered 5.0 to 8.2 errors off).
 *   f32 at a piezo offset (test_f32_offset, host only): z + 100 um to
 *     3 mm, 1 500 samples 232 pm apart, noise 0.1 %, 8 seeds each: the
 *     same rule (measured: 32 of 32 answered, worst 2.4 errors with the
 *     baseline flat, 3.3 with the slope fitted; before the fold's base
 *     position was taken from z_po, 7 of 32 15 to 43 off).
 *   a tilted baseline (test_tilt, host only): tilts of -5 % to 5 % of the
 *     pull-off force over the curve, noise 0.3 %, 4 seeds each: the same
 *     rule, and F_slope within 5 of its errors of the tilt (measured: 16
 *     of 16 answered, the worst 2.1 errors; before the slope was fitted,
 *     16 of 16 answered 11 to 34 errors off).
 *   a dwell at the top (test_dwell, 100 rows, noise 0.3 %, relaxing 0 and
 *     5 % of the pull-off): E*, w, w_adv within 3.2 reported errors, 8 of
 *     10 answered, n_approach the approach's own samples.
 *   w_adv at its bound (test_wadv_bound, host only): curves without
 *     hysteresis through a 2.6 N/m lever, 1 999 samples a branch, noise
 *     0.77 %, a tilted baseline, WADV_SEEDS seeds: every w_adv within 5 of
 *     its errors, none of them 0, and at least one at the bound (below
 *     1e-2 of w). Before, 0 +- 0 (the fit stuck on s = 0) in 5 of 60.
 *   few receding samples after a pinned top (test_few_receding, host
 *     only): w_adv = 0 through 2.44 N/m, tops of 0.55 to 2.5 pull-off
 *     forces, 185 samples, noise 0.35 %, RECEDE_SEEDS seeds each: every
 *     answer within 5 reported errors (E*, w), MDR_E_FEW where fewer than
 *     MDR_FIT_MIN_RECEDE receding samples remain (every refusal), and at
 *     least half of the two highest tops' curves answered; the same without noise
 *     (test_few_receding_clean, host only: that retract and helper-80's, E*
 *     10.4 GPa through 0.115 N/m, tops of 0.55 to 8, 100 to 912
 *     samples, f64 and f32): every curve with fewer than
 *     MDR_FIT_MIN_RECEDE receding samples refused, f64's answers of the
 *     others within TOL_RT_CF (E*, w; measured worst: printed).
 *   coarse curves without hysteresis (test_coarse_top, host only): 26 and
 *     51 samples a branch through a 2 N/m lever, noise 0.3 % and 1 %, 30
 *     seeds each: the default fit answers within 5 reported errors or
 *     refuses MDR_E_PINNED (a pinned top the noise may hide); with the
 *     approach at least 27 of 30 answered, with every sample all 30, each
 *     within 5. Real pinned tops on coarse curves (test_coarse_pinned, host
 *     only): w_adv/w 0 to 0.9, tops 1.5 to 4 fold radii, 40 to 200 samples,
 *     0.2 and 2 N/m, noise 0.3 % and 1 %: every answer within 5 reported
 *     errors, at least 300 of 1 152 answered.
 *   (make test-fit-known builds this file with -DMDR_FIT_KNOWN_DEFECTS for
 *     the fit's known, open defects, which fail until fixed: test_known_curved,
 *     a curved baseline, flaw_run's rule; test_known_coarse_approach, coarse
 *     curves with a pinned top the approach's w_adv misses, every answer
 *     within 5 reported errors.)
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "mdr.h"
#include "applies.h"

#if !(MDR_CFG_HAS_FIT && MDR_CFG_F32 && MDR_CFG_F64 && MDR_CFG_ALL_PROFILES)
MDR_TEST_NOT_APPLICABLE("the fit, f32, f64 and every profile")
#else
#include "test_util.h"
#include "noise.h"

#define TOL_MODEL 1e-11
#define TOL_RT 5e-8
#define TOL_RT_CF 1e-10
#define TOL_RT32 5e-5
#define TOL_TP 1e-9
#define TOL_TP_GRID 0.5
#define TOL_MU 1e-13
#define COVER_FRAC 0.03
#define COVER_MAX 8.0
#ifdef MDR_TARGET_TEST
#define NMC 6 /* soft double on the M4F: fewer copies and points (the bounds scale with them) */
#define NFINE 600
#define NPROF 200
#define NPROF_SIZES 1 /* the coarse curves only */
#define NNOISE 300
#define NTP 500
#define NAPP 150
#else
#define NMC 40
#define NFINE 3000
#define NPROF 800
#define NPROF_SIZES 2
#define NNOISE 1000
#define NTP 2000
#define NAPP 300
#endif
#define NMAX 4000
/* the target's shorter sweeps of the refusal tests (the host runs them
 * whole): test_reversed the 300-sample curves only and every 2nd point of
 * each regime's E* x w_adv/w grid, test_two_point_errors without its
 * 1 000-sample class, test_order_coarse E* x 1 only and every 3rd point of
 * its size x tail grids, test_refuse_units 3 of its 6 spans,
 * test_refuse_distorted its extreme amplitudes and half waves. TARGET_F64:
 * the tests of f64 alone whose claim is statistical (test_two_point_mc,
 * test_refuse_bad_start, test_cover_fold, test_refuse_valley) run on the
 * host only: the M4F computes f64 in soft double, libgcc's IEEE routines,
 * the host's arithmetic, and they took 65 of its 181 s (stop 39); its f64
 * round trips, refusals and two-point tests stay */
#ifdef MDR_TARGET_TEST
#define NREV_SIZES 1
#define NTP_SIZES 3
#define BAD_START_STRIDE 1 /* (unused: host only) */
#define ORDER_E_FIRST 1
#define ORDER_E_STRIDE 3
#define DISTORT_STRIDE 3
#define DISTORT_K_STRIDE 2
#else
#define NREV_SIZES 2
#define NTP_SIZES 4
#define BAD_START_STRIDE 1
#define ORDER_E_FIRST 0
#define ORDER_E_STRIDE 1
#define DISTORT_STRIDE 1
#define DISTORT_K_STRIDE 1
#endif
/* time order (test_order_*, test_reversed_baseline_step) */
#define ORDER_SIG 1e-3  /* noise, of the pull-off force */
#define ORDER_STEP 5.0  /* approach's baseline above the retract's, noise widths (below MDR_FIT_NOISE_SIGMAS) */
#define ORDER_STEP_BIG 30.0 /* the same, far above them: 3 % of the pull-off force (drag, drift) */
#define ORDER_DRAG 1e-2 /* the same for the reversed curves, of the pull-off force (10 noise widths) */
#define ORDER_RHO 0.9   /* correlation of successive noise samples */
#define ORDER_TAIL_MAX 8 /* free samples after the pull-off, 3 (MDR_FIT_MIN_FREE) .. this */
#ifdef MDR_TARGET_TEST
#define NORDER 3 /* (6 until stop 72; the CI's minutes) */
#define NORDER_PTS 300
#else
#define NORDER 20
#define NORDER_PTS 1000
#endif
/* f32, a pinned top at a piezo offset (test_f32_pinned_offset) */
#define F32PIN_SIG 1e-3 /* noise, of the pull-off force */
#ifdef MDR_TARGET_TEST
#define NF32PIN 2
#else
#define NF32PIN 6
#endif
/* a glitch in a noisy pinned top (test_pinned_glitch) */
#define GLITCH_SIG 3e-3 /* noise, of the pull-off force */
#define GLITCH_PULL 5.0 /* every answer within this many reported errors */
/* f64, noise-free curves as written down (test_written_digits) */
#define DIGITS_PULL 5.0  /* every answer within this many reported errors */
#define DIGITS_MIN_OK 54 /* of the 66 curves answered */
#define DRIFT_LO (-0.6) /* test_written_drift's scales of z, units over the span */
#define DRIFT_HI 0.45
#define DRIFT_MIN_OK 80 /* of its 108 curves answered (measured: 87) */
/* f64, noisy curves with z written in nm to 0.01 nm (test_written_nm) */
#define NMW_SIG 2e-4   /* the noise, of the pull-off force */
#define NMW_PULL 5.0   /* every answer within this many reported errors */
#define NMW1_MIN_OK 20 /* of its 32 curves answered at 0.1 nm (measured: 24) */
#define NMW_MIN_OK 30 /* of its 32 curves answered (measured: 32; stop 80: 24, 8 MDR_E_MISFIT) */
/* f64, noise-free pinned tops at piezo offsets (test_pinned_offset_clean) */
#define PINOFF_REL 1e-8
#define PINOFF_STEP 0.25e-6
#define PINOFF_N 112
#define RATIO (1.0 + 4.0 / sqrt(2.0 * (NMC - 1)))

/* ---- JKR paraboloid through a cantilever, libm only --------------------- */

typedef struct {
    double R, E, w, km;
} jkr_par;

/* d, F and dz/da (z = d + F/km) at contact radius a (JKR 1971; seed
 * 4.30-4.35): d = a^2/R - sqrt(2 pi a w/E*), F = 4E* a^3/(3R) - sqrt(8 pi w E* a^3) */
static double jkr_z(const jkr_par *p, double a, double *F, double *dz)
{
    double d = a * a / p->R - sqrt(2 * M_PI * a * p->w / p->E);
    double f = 4 * p->E * a * a * a / (3 * p->R) - sqrt(8 * M_PI * p->w * p->E * a * a * a);
    double dd = 2 * a / p->R - 0.5 * sqrt(2 * M_PI * p->w / (p->E * a));
    double df = 4 * p->E * a * a / p->R - 1.5 * sqrt(8 * M_PI * p->w * p->E * a);
    if (F) {
        *F = f;
    }
    if (dz) {
        *dz = dd + df / p->km;
    }
    return d + f / p->km;
}

/* fold radius (dz/da = 0) for any parameters (the contact radius may
 * exceed R): the bracket grown until dz/da > 0, then geometric bisection */
static double jkr_fold(const jkr_par *p)
{
    double lo = 1e-30, hi = p->R, dz;
    int i;
    for (jkr_z(p, hi, NULL, &dz); !(dz > 0); jkr_z(p, hi, NULL, &dz)) {
        hi *= 2;
    }
    for (i = 0; i < 400; i++) {
        double mid = sqrt(lo * hi);
        const double lo_was = lo, hi_was = hi;
        jkr_z(p, mid, NULL, &dz);
        if (dz > 0) {
            hi = mid;
        } else {
            lo = mid;
        }
        if (lo == lo_was && hi == hi_was) {
            break; /* a fixed point: the 400 steps' answer (jkr_a) */
        }
    }
    return hi;
}

/* radius on the stable branch with z(a) = zp (bisection above the fold) */
static double jkr_a(const jkr_par *p, double zp, double af)
{
    double lo = af, hi = 2 * af;
    int i;
    while (jkr_z(p, hi, NULL, NULL) < zp) {
        hi *= 2;
    }
    for (i = 0; i < 400; i++) {
        double mid = 0.5 * (lo + hi);
        const double lo_was = lo, hi_was = hi;
        if (jkr_z(p, mid, NULL, NULL) > zp) {
            hi = mid;
        } else {
            lo = mid;
        }
        /* a step that left lo and hi as they were leaves them so for every
         * later step (each a function of lo, hi alone): the 400 steps end
         * on the same bits, so the bisection stops there, after some 60
         * steps (the closed-form curves in soft double: test_fit on the M4F
         * 159 -> 117 s with the same output, test_two_point_errors 14 -> 4 s,
         * test_refuse_units 16.5 -> 10.6; the host's output the same) */
        if (lo == lo_was && hi == hi_was) {
            break;
        }
    }
    return 0.5 * (lo + hi);
}

/* zero-force radius: 4E* a^3/(3R) = sqrt(8 pi w E* a^3) */
static double jkr_a0(const jkr_par *p)
{
    return pow(3 * p->R / (4 * p->E) * sqrt(8 * M_PI * p->w * p->E), 2.0 / 3.0);
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* A retract of n points, z' from 2|z'_fold| + z'(2.5 a_fold) down to
 * 0.4 of that range below the fold (free there), base offset z0, baseline
 * Fb. exact: the zero-force point and the fold are two of the samples (the
 * others uniform). Returns the index of the last contact point; *Fpo the
 * fold's force. */
static int jkr_curve(const jkr_par *p, double z0, double Fb, int n, double *z, double *F, int exact,
                     double *Fpo)
{
    double af = jkr_fold(p), Ff, zf = jkr_z(p, af, &Ff, NULL), ztop, zbot;
    int i, m = exact ? n - 2 : n, last = -1;
    ztop = 2.0 * fabs(zf) + jkr_z(p, 2.5 * af, NULL, NULL);
    zbot = zf - 0.4 * (ztop - zf);
    for (i = 0; i < m; i++) {
        z[i] = ztop + (zbot - ztop) * i / (m - 1);
    }
    if (exact) {
        z[m] = zf;
        z[m + 1] = jkr_z(p, jkr_a0(p), NULL, NULL);
        qsort(z, (size_t)n, sizeof *z, cmp_desc);
    }
    for (i = 0; i < n; i++) {
        double zp = z[i], f = 0.0;
        if (zp == zf) {
            f = Ff;
            last = i;
        } else if (zp > zf) {
            jkr_z(p, jkr_a(p, zp, af), &f, NULL);
            last = i;
        }
        z[i] = zp + z0;
        F[i] = f + Fb;
    }
    if (Fpo) {
        *Fpo = Ff;
    }
    return last;
}

/* how many reported errors v lies from the truth, in ln v (err: v's
 * standard error) */
static double nerr(double v, double truth, double err)
{
    return fabs(log(v / truth)) / (err / v);
}

/* A retract of n samples uniform in z' over jkr_curve's span, with the
 * grid shifted so that the fold lies the fraction `at` of a step below a
 * sample; Gaussian noise of sig_rel |F_po|; base offset twice the span.
 * Returns *z0. */
static double jkr_grid(const jkr_par *p, int n, double at, double sig_rel, double *z, double *F)
{
    double af = jkr_fold(p), Ff, zf = jkr_z(p, af, &Ff, NULL), ztop, zbot, step, z0;
    int i;
    ztop = 2.0 * fabs(zf) + jkr_z(p, 2.5 * af, NULL, NULL);
    zbot = zf - 0.4 * (ztop - zf);
    step = (ztop - zbot) / (n - 1);
    ztop = zf + (floor((ztop - zf) / step) + at) * step;
    zbot = ztop - (n - 1) * step;
    z0 = 2 * (ztop - zbot);
    for (i = 0; i < n; i++) {
        double zp = ztop + (zbot - ztop) * i / (n - 1), f = 0.0;
        if (zp > zf) {
            jkr_z(p, jkr_a(p, zp, af), &f, NULL);
        }
        z[i] = zp + z0;
        F[i] = f + sig_rel * fabs(Ff) * gauss();
    }
    return z0;
}

static double work64[2 * NMAX];
static float work32[2 * NMAX];
static double zs[NMAX], Fs[NMAX], Fm[NMAX];
static float zs32[NMAX], Fs32[NMAX];

/* the curve's first n points zs, Fs rounded to float, into zs32, Fs32 */
static void curve32(int n)
{
    int i;
    for (i = 0; i < n; i++) {
        zs32[i] = (float)zs[i];
        Fs32[i] = (float)Fs[i];
    }
}

/* the regimes: mu = 450 (JKR: a soft gel on a 1 um sphere), 1.2
 * (transition: 20 nm tip on a polymer), 0.016 (DMT: 10 nm tip on a hard
 * solid); k_m comparable to the contact's stiffness */
static const jkr_par regimes[3] = {
    {1e-6, 1e6, 0.05, 1.0},
    {20e-9, 1e9, 0.05, 0.2},
    {10e-9, 100e9, 0.01, 40.0},
};
static const uint8_t regime_of[3] = {MDR_REGIME_JKR, MDR_REGIME_TRANSITION, MDR_REGIME_DMT};

static mdr_contact_f64 paraboloid64(double R)
{
    mdr_contact_f64 c;
    double p[3] = {R, 0, 0};
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, p, 1.0, 0.0), MDR_OK);
    return c;
}

/* worst errors met, printed at the end of each test */
static double worst;
static void track(double got, double want, double scale, double tol, const char *what)
{
    double s = scale > 0 ? scale : fabs(want), e = fabs(got - want) / s;
    worst = e > worst ? e : worst;
    rel_le(got, want, scale, tol, what);
}

static void check_fit64(const mdr_fit_result_f64 *r, double E, double w, double z0, double Fb, double zscale,
                        double Fscale, double tol, const char *what)
{
    char msg[160];
    snprintf(msg, sizeof msg, "%s: E", what);
    track(r->E, E, 0, tol, msg);
    snprintf(msg, sizeof msg, "%s: w", what);
    track(r->w, w, 0, tol, msg);
    snprintf(msg, sizeof msg, "%s: z0", what);
    track(r->z0, z0, zscale, tol, msg);
    snprintf(msg, sizeof msg, "%s: F_b", what);
    track(r->F_base, Fb, Fscale, tol, msg);
}

/* ---- the forward model against the closed form -------------------------- */

static void test_model_vs_closed_form(void **state)
{
    int k;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        const jkr_par *p = &regimes[k];
        mdr_contact_f64 c;
        double pp[3] = {p->R, 0, 0}, Fpo, fmax = 0;
        int i, n = 500;
        jkr_curve(p, 1e-6, 2e-10, n, zs, Fs, 0, &Fpo);
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, pp, p->E, p->w), MDR_OK);
        assert_int_equal(mdr_fit_model_f64(&c, p->km, 1e-6, 2e-10, MDR_FIT_RETRACT, zs, (uint32_t)n, Fm), MDR_OK);
        for (i = 0; i < n; i++) {
            fmax = fabs(Fs[i]) > fmax ? fabs(Fs[i]) : fmax;
        }
        for (i = 0; i < n; i++) {
            track(Fm[i], Fs[i], fmax, TOL_MODEL, "model vs JKR closed form");
        }
    }
    print_message("model vs closed form: worst %.2g of max|F|\n", worst);
}

/* ---- noise-free round trips ---------------------------------------------- */

static void test_roundtrip_closed_form(void **state)
{
    static const int sizes[2] = {40, NFINE};
    int k, s;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        for (s = 0; s < 2; s++) {
            const jkr_par *p = &regimes[k];
            mdr_contact_f64 c = paraboloid64(p->R);
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            double Fpo, z0 = 3.2e-6, Fb = -0.7 * fabs(p->w * p->R);
            int n = sizes[s], last = jkr_curve(p, z0, Fb, n, zs, Fs, 0, &Fpo);
            mdr_fit_defaults_f64(&o, p->km);
            assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
            check_fit64(&r, p->E, p->w, z0, Fb, zs[0] - zs[last], fabs(Fpo), TOL_RT_CF, "closed form round trip");
            assert_int_equal(r.n, n);
            assert_int_equal(r.method, MDR_FIT_FULL);
            assert_true(r.iterations > 0 && r.iterations <= MDR_FIT_ITER_MAX);
            assert_true(r.rms < 1e-6 * fabs(Fpo));
            assert_int_equal(r.regime, regime_of[k]);
        }
    }
    print_message("closed-form round trip (f64): worst %.2g\n", worst);
}

/* every profile the fit takes, through the library's own forward model;
 * curves from 2.5 x the fold's radius to below the fold; machine stiffness
 * of the order of the contact's (a lever much softer than the contact
 * leaves E* undetermined: z' ~ F/k_m); 40 (coarse) and 800 points */
static void test_roundtrip_profiles(void **state)
{
    static const struct {
        uint8_t kind;
        double p[3], E, w, km;
    } cases[] = {
        {MDR_PROFILE_PARABOLOID, {50e-9, 0, 0}, 2e9, 0.1, 5.0},
        {MDR_PROFILE_SPHERE, {20e-9, 0, 0}, 5e8, 0.2, 2.0},
        {MDR_PROFILE_CONE, {0.2, 0, 0}, 1e9, 0.05, 2.0},
        {MDR_PROFILE_POWERLAW, {1e12, 3.0, 0}, 1e9, 0.05, 50.0},
        {MDR_PROFILE_POWERLAW, {1e3, 1.5, 0}, 1e9, 0.05, 5.0},
        {MDR_PROFILE_FLATTIP, {30e-9, 3e-9, 0}, 1e9, 0.05, 2.0},
#ifndef MDR_TARGET_TEST /* Struve functions at every point: 100x the others, minutes in soft double */
        {MDR_PROFILE_WAVY, {30e-9, 0.02e-9, 10e-9}, 1e9, 0.05, 2.0},
#endif
    };
    size_t k;
    (void)state;
    worst = 0;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        mdr_contact_f64 c, tip;
        mdr_critstate_f64 cs;
        mdr_eqstate_f64 e;
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        double as, ztop, zf, zbot, z0 = -1.5e-6, Fb = 0.3e-9;
        int i, n = NPROF, s;
        assert_int_equal(mdr_contact_init_f64(&c, cases[k].kind, cases[k].p, cases[k].E, cases[k].w), MDR_OK);
        assert_int_equal(mdr_contact_init_f64(&tip, cases[k].kind, cases[k].p, 1.0, 0.0), MDR_OK);
        assert_int_equal(mdr_default_start_f64(&c, &as), MDR_OK);
        assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_MACHINE, cases[k].km, as, &cs), MDR_OK);
        assert_int_equal(mdr_eq_f64(&c, 2.5 * cs.a, &e), MDR_OK);
        zf = cs.d + cs.F / cases[k].km;
        ztop = e.d + e.F / cases[k].km;
        zbot = zf - 0.3 * (ztop - zf);
        for (s = 0; s < NPROF_SIZES; s++) {
            int nn = s ? n : 40;
            for (i = 0; i < nn; i++) {
                zs[i] = z0 + ztop + (zbot - ztop) * i / (nn - 1);
            }
            assert_int_equal(mdr_fit_model_f64(&c, cases[k].km, z0, Fb, MDR_FIT_RETRACT, zs, (uint32_t)nn, Fs), MDR_OK);
            mdr_fit_defaults_f64(&o, cases[k].km);
            assert_int_equal(mdr_fit_curve_f64(&tip, &o, zs, Fs, (uint32_t)nn, work64, 2 * NMAX, &r), MDR_OK);
            check_fit64(&r, cases[k].E, cases[k].w, z0, Fb, ztop - zf, fabs(cs.F), TOL_RT, "profile round trip");
            /* the model's pull-off is the contact module's fold */
            track(r.pull_off_F, cs.F, 0, TOL_RT, "pull-off force");
        }
    }
    print_message("forward-model round trip, %u profiles (f64): worst %.2g\n",
                  (unsigned)(sizeof cases / sizeof cases[0]), worst);
}

static void test_roundtrip_f32(void **state)
{
    int k;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        const jkr_par *p = &regimes[k];
        mdr_contact_f32 c;
        mdr_fit_opts_f32 o;
        mdr_fit_result_f32 r;
        float pp[3] = {(float)p->R, 0, 0};
        double Fpo, z0 = 40e-9, Fb = 0.2 * fabs(p->w * p->R);
        int n = 1000, last = jkr_curve(p, z0, Fb, n, zs, Fs, 0, &Fpo);
        curve32(n);
        assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
        mdr_fit_defaults_f32(&o, (float)p->km);
        assert_int_equal(mdr_fit_curve_f32(&c, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r), MDR_OK);
        track(r.E, p->E, 0, TOL_RT32, "f32: E");
        track(r.w, p->w, 0, TOL_RT32, "f32: w");
        track(r.z0, z0, zs[0] - zs[last], TOL_RT32, "f32: z0");
        track(r.F_base, Fb, fabs(Fpo), TOL_RT32, "f32: F_b");
        assert_int_equal(r.regime, regime_of[k]);
    }
    print_message("closed-form round trip (f32): worst %.2g\n", worst);
}

/* A sampled paraboloid (a table tip) whose last radius r_max squares back
 * from its sqrt one ulp above itself, fl(sqrt(r_max))^2 > r_max (2e-7,
 * 1e-7, 5e-8 m in f64): the fit's solve in t = sqrt(a) started at the
 * table's end (mdr_default_start() of a table: its last radius) and asked
 * mdr_eq() for the ulp beyond it, MDR_E_RADIUS on clean curves depending on
 * the table's extent alone (the two-point first guess, mdr_f_tp_at's zero
 * force; found with the mdr CLI: r_max 50, 100, 200 nm refused, 40, 60,
 * 80 nm answered). r_max: the first of R j/8, j = 32.., with that rounding
 * in the arithmetic; 401 samples; the three regimes' closed-form retracts,
 * f64 and f32, round trip within TOL_RT (measured 2e-13) and TOL_RT32
 * (measured 7.8e-6; 7.7e-5 in w, transition regime, with a variant of the
 * fix that clamped every t^2 > hi, which moved other answers at rounding
 * level and is not the fix). Before the fix (mdr_fit.inc, mdr_f_solve)
 * MDR_E_RADIUS in both arithmetics. Host only (not timed on the target). */
#ifndef MDR_TARGET_TEST
enum { LAST_M = 401 };

/* the first R j/8 (j = 32 .. 255) whose square root squares back above it
 * in the arithmetic (f32: float), or 0 */
static double radius_past_sqrt(double R, int f32)
{
    int j;
    for (j = 32; j < 256; j++) {
        const double x = R * j / 8, t = sqrt(x);
        const float x32 = (float)x, t32 = sqrtf(x32);
        if (f32 ? t32 * t32 > x32 : t * t > x) {
            return f32 ? (double)x32 : x;
        }
    }
    return 0.0;
}

/* the paraboloid f = r^2/(2R) sampled at LAST_M radii to x (f32: each
 * radius rounded to float), and the slopes (f_i+1 - f_i)/h of its
 * intervals (0 past the last) */
static void last_radius_table(double R, double x, int f32, double *r, double *sl)
{
    int i;
    for (i = 0; i < LAST_M; i++) {
        r[i] = i == LAST_M - 1 ? x : x * i / (LAST_M - 1);
        r[i] = f32 ? (double)(float)r[i] : r[i];
    }
    for (i = 0; i + 1 < LAST_M; i++) {
        sl[i] = (r[i] + r[i + 1]) / (2 * R);
    }
    sl[LAST_M - 1] = 0;
}

static void test_table_last_radius(void **state)
{
    static double tr[LAST_M], ts[LAST_M];
    static float tr32[LAST_M], ts32[LAST_M];
    int k;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        const jkr_par *p = &regimes[k];
        mdr_contact_f64 c;
        mdr_contact_f32 c32;
        mdr_fit_opts_f64 o;
        mdr_fit_opts_f32 o32;
        mdr_fit_result_f64 r;
        mdr_fit_result_f32 r32;
        double Fpo, z0 = 40e-9, Fb = 0.2 * fabs(p->w * p->R), x = radius_past_sqrt(p->R, 0);
        int i, n = 300, last = jkr_curve(p, z0, Fb, n, zs, Fs, 0, &Fpo);
        assert_true(x > 0);
        last_radius_table(p->R, x, 0, tr, ts);
        assert_int_equal(mdr_contact_init_table_f64(&c, tr, ts, LAST_M, 1.0, 0.0), MDR_OK);
        mdr_fit_defaults_f64(&o, p->km);
        assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
        check_fit64(&r, p->E, p->w, z0, Fb, zs[0] - zs[last], fabs(Fpo), TOL_RT, "table to r_max (f64)");
        /* f32: its own r_max */
        x = radius_past_sqrt(p->R, 1);
        assert_true(x > 0);
        last_radius_table(p->R, x, 1, tr, ts);
        for (i = 0; i < LAST_M; i++) {
            tr32[i] = (float)tr[i];
            ts32[i] = (float)ts[i];
        }
        curve32(n);
        assert_int_equal(mdr_contact_init_table_f32(&c32, tr32, ts32, LAST_M, 1.0f, 0.0f), MDR_OK);
        mdr_fit_defaults_f32(&o32, (float)p->km);
        assert_int_equal(mdr_fit_curve_f32(&c32, &o32, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r32), MDR_OK);
        track(r32.E, p->E, 0, TOL_RT32, "table to r_max (f32): E");
        track(r32.w, p->w, 0, TOL_RT32, "table to r_max (f32): w");
    }
    print_message("table tips ending where sqrt(r_max)^2 > r_max: worst %.2g\n", worst);
}
#endif

/* Noise-free f32 fits through levers 100 to 10 000 times softer than the
 * contact (2 E* a0 / k_m; mdr_fit.inc, mdr_f_gn_escape). Closed-form
 * retracts (jkr_curve, R 20 nm, base offset 40 nm): every answer (status
 * ok) must have E* and w each within SOFT32_ERRS of its reported errors or
 * SOFT32_REL of the truth; a refusal passes. soft32[]: 8 curves that
 * Levenberg-Marquardt, its step test met in the valley of E*, w and the
 * fold's position (damped, not at the minimum), answered ok with w 0.11 %
 * to 1.6 % off at 10 to 21 reported errors before the escape (the first 8
 * such of the sweep below). The sweep: NSOFT32 draws in that lever ratio
 * (E* 1e6 to 1e11 Pa, w 1e-3 to 1 J/m^2, k_m 0.01 to 100 N/m log-uniform;
 * 80, 200 or 500 samples): measured 68 of 146 answers beyond the bound
 * before the escape, 31 of 147 with it (w up to 3 % off at up to 24
 * errors: the valley curved beyond Gauss-Newton's reach, the sum at its
 * f32 rounding; docs/fitting.md, not yet fixed), held at SOFT32_SWEEP_MAX
 * (a regression guard; the margin for another compiler's rounding of the
 * f32 model); host only. */
#define NSOFT32 150
#define SOFT32_SWEEP_MAX 36
#define SOFT32_ERRS 3.0
#define SOFT32_REL 1e-3
static const double soft32[][4] = { /* E*, w, k_m, samples */
    {11542769322.96981, 0.049565514194329356, 0.044228789591761908, 200},
    {39948135289.300591, 0.015587718058331243, 0.037213156195122117, 500},
    {31258636071.520149, 0.19710625350871949, 0.42387034450286809, 200},
    {17209251062.564987, 0.0012330385633526257, 0.038722404368912167, 500},
    {376865962.44773692, 0.76707594014891289, 0.029178540916652954, 200},
    {8957282406.4328022, 0.15747038746348724, 0.042119222457034061, 500},
    {45180001109.001709, 0.85144678577622812, 0.53437190886071673, 80},
    {19413365023.241024, 0.062139138125863864, 0.26782975735961251, 500},
};

/* one curve: 1 when answered beyond the bound (printed), else 0; *ok
 * counts the answers */
static int soft32_fit(const jkr_par *p, int n, int *ok, int print)
{
    double Fpo;
    mdr_contact_f32 c;
    mdr_fit_opts_f32 o;
    mdr_fit_result_f32 r;
    float pp[3] = {20e-9f, 0, 0};
    jkr_curve(p, 40e-9, 0.0, n, zs, Fs, 0, &Fpo);
    curve32(n);
    assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
    mdr_fit_defaults_f32(&o, (float)p->km);
    if (mdr_fit_curve_f32(&c, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r) != MDR_OK) {
        return 0;
    }
    (*ok)++;
    {
        const double eE = fabs(r.E / p->E - 1), ew = fabs(r.w / p->w - 1);
        const double nE = fabs(r.E - p->E) / r.E_err, nw = fabs(r.w - p->w) / r.w_err;
        if ((eE > SOFT32_REL && nE > SOFT32_ERRS) || (ew > SOFT32_REL && nw > SOFT32_ERRS)) {
            if (print) {
                print_message("f32 soft lever: E* %.17g, w %.17g, k_m %.17g, %d samples: E* %+.2g (%.1f errors), "
                              "w %+.2g (%.1f errors), status ok\n",
                              p->E, p->w, p->km, n, r.E / p->E - 1, nE, r.w / p->w - 1, nw);
            }
            return 1;
        }
    }
    return 0;
}

static void test_f32_soft_lever(void **state)
{
    const int sizes[3] = {80, 200, 500};
    int j, draws = 0, ok = 0, bad = 0;
    (void)state;
    for (j = 0; j < (int)(sizeof soft32 / sizeof soft32[0]); j++) {
        const jkr_par p = {20e-9, soft32[j][0], soft32[j][1], soft32[j][2]};
        bad += soft32_fit(&p, (int)soft32[j][3], &ok, 1);
    }
    print_message("f32 soft lever, the 8 curves: %d answered, %d beyond %g errors and %g\n", ok, bad, SOFT32_ERRS,
                  SOFT32_REL);
    assert_int_equal(bad, 0);
#ifndef MDR_TARGET_TEST /* (the sweep: host only) */
    noise_state = 0x5eed5eed12345ull;
    for (j = 0, ok = 0; j < NSOFT32;) {
        jkr_par p;
        int n;
        p.R = 20e-9;
        p.E = pow(10.0, 6.0 + 5.0 * noise_uniform());
        p.w = pow(10.0, -3.0 + 3.0 * noise_uniform());
        p.km = pow(10.0, -2.0 + 4.0 * noise_uniform());
        n = sizes[(int)(3.0 * noise_uniform()) % 3];
        draws++;
        if (!(2 * p.E * jkr_a0(&p) / p.km >= 100.0 && 2 * p.E * jkr_a0(&p) / p.km <= 1e4)) {
            continue;
        }
        j++;
        bad += soft32_fit(&p, n, &ok, 0);
    }
    print_message("f32 soft lever, noise-free sweep: %d of %d answered (%d draws), %d beyond %g errors and %g "
                  "(at most %d)\n",
                  ok, NSOFT32, draws, bad, SOFT32_ERRS, SOFT32_REL, SOFT32_SWEEP_MAX);
    assert_true(bad <= SOFT32_SWEEP_MAX);
#else
    (void)sizes;
    (void)draws;
#endif
}

/* ---- noise ------------------------------------------------------------------ */

#ifdef MDR_TARGET_TEST
#define NEST 5 /* test_noise's estimates: the five parameters */
#else
#define NEST 7 /* and E*, w with opts.flat */
#endif
static void test_noise(void **state)
{
    int k;
    (void)state;
    for (k = 0; k < 3; k++) {
        const jkr_par *p = &regimes[k];
        mdr_contact_f64 c = paraboloid64(p->R);
        mdr_fit_opts_f64 o;
        /* the five parameters, then E* and w with opts.flat (the slope held at 0) */
        double Fpo, z0 = -2e-6, Fb = 1.5 * p->w * p->R, sig, est[7][NMC], rep[7] = {0, 0, 0, 0, 0, 0, 0};
        double truth[7] = {p->E, p->w, z0, Fb, 0.0, p->E, p->w};
        static const char *names[7] = {"E", "w", "z0", "F_b", "sl", "E (flat)", "w (flat)"};
        int i, j, n = NNOISE;
        jkr_curve(p, z0, Fb, n, zs, Fm, 0, &Fpo);
        sig = 0.01 * fabs(Fpo);
        mdr_fit_defaults_f64(&o, p->km);
        for (j = 0; j < NMC; j++) {
            mdr_fit_result_f64 r;
            mdr_status st;
            for (i = 0; i < n; i++) {
                Fs[i] = Fm[i] + sig * gauss();
            }
            /* through the soft lever (k = 1) the retract is straight within
             * this noise to its pull-off: a pinned top could hide in it, and
             * the fit refuses unless told there is none (the curve is JKR's,
             * receding from its top) */
            o.unpinned = 0;
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            assert_int_equal(st, k == 1 ? MDR_E_PINNED : MDR_OK);
            o.unpinned = 1;
            assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
            est[0][j] = r.E;
            est[1][j] = r.w;
            est[2][j] = r.z0;
            est[3][j] = r.F_base;
            est[4][j] = r.F_slope;
            rep[0] += r.E_err / NMC;
            rep[1] += r.w_err / NMC;
            rep[2] += r.z0_err / NMC;
            rep[3] += r.F_base_err / NMC;
            rep[4] += r.F_slope_err / NMC;
            assert_true(fabs(r.F_slope) <= 5 * r.F_slope_err);
            /* every estimate within 5 reported standard errors */
            assert_true(fabs(r.E - p->E) <= 5 * r.E_err);
            assert_true(fabs(r.w - p->w) <= 5 * r.w_err);
            assert_true(fabs(r.z0 - z0) <= 5 * r.z0_err);
            assert_true(fabs(r.F_base - Fb) <= 5 * r.F_base_err);
            /* the residual is the noise */
            assert_true(fabs(r.rms / sig - 1) < 0.15);
            assert_int_equal(r.regime, regime_of[k]);
#ifndef MDR_TARGET_TEST /* (the same code with the slope held; the target's time) */
            /* the flat baseline known (opts.flat): the same rules */
            o.flat = 1;
            assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
            o.flat = 0;
            assert_true(r.F_slope == 0.0 && r.F_slope_err == 0.0);
            assert_true(fabs(r.E - p->E) <= 5 * r.E_err);
            assert_true(fabs(r.w - p->w) <= 5 * r.w_err);
            est[5][j] = r.E;
            est[6][j] = r.w;
            rep[5] += r.E_err / NMC;
            rep[6] += r.w_err / NMC;
#endif
        }
#ifndef MDR_TARGET_TEST
        /* what the slope costs where the baseline is flat: E*'s error */
        print_message("regime %d: E*'s reported error with the slope fitted %.3g x that with it held (opts.flat)\n", k,
                      rep[0] / rep[5]);
        assert_true(rep[5] <= rep[0]);
#endif
        for (i = 0; i < NEST; i++) {
            double m = 0, v = 0, sd;
            for (j = 0; j < NMC; j++) {
                m += est[i][j] / NMC;
            }
            for (j = 0; j < NMC; j++) {
                v += (est[i][j] - m) * (est[i][j] - m) / (NMC - 1);
            }
            sd = sqrt(v);
            print_message("regime %d %-8s: bias %+.2f sd/sqrt(N), sd %.3g, reported %.3g (ratio %.2f)\n", k,
                          names[i], (m - truth[i]) / (sd / sqrt(NMC)), sd, rep[i], sd / rep[i]);
            assert_true(fabs(m - truth[i]) <= 4 * (sd > rep[i] ? sd : rep[i]) / sqrt(NMC));
            if (NMC >= 20) {
                assert_true(sd / rep[i] < RATIO && rep[i] / sd < RATIO);
            }
        }
    }
}

/* ---- two-point -------------------------------------------------------------- */

static void test_two_point(void **state)
{
    int k;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        const jkr_par *p = &regimes[k];
        mdr_contact_f64 c = paraboloid64(p->R);
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        double Fpo, z0 = 1e-7, Fb = 0.0;
        int n = NTP, last = jkr_curve(p, z0, Fb, n, zs, Fs, 1, &Fpo);
        mdr_fit_defaults_f64(&o, p->km);
        o.method = MDR_FIT_TWO_POINT;
        assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
        /* the zero-force point and the fold are samples: exact */
        track(r.pull_off_F, Fpo, 0, TOL_TP, "two-point: pull-off");
        track(r.E, p->E, 0, TOL_TP, "two-point exact: E");
        track(r.w, p->w, 0, TOL_TP, "two-point exact: w");
        track(r.z0, z0, zs[0] - zs[last], TOL_TP, "two-point exact: z0");
        assert_int_equal(r.method, MDR_FIT_TWO_POINT);
        assert_int_equal(r.iterations, 0);
        assert_true(r.E_err > 0 && r.w_err > 0);
        /* on an ordinary grid: a first guess within 20 % */
        jkr_curve(p, z0, Fb, 300, zs, Fs, 0, &Fpo);
        assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, 300u, work64, 2 * NMAX, &r), MDR_OK);
        rel_le(r.E, p->E, 0, TOL_TP_GRID, "two-point on a grid: E");
        rel_le(r.w, p->w, 0, TOL_TP_GRID, "two-point on a grid: w");
    }
    print_message("two-point, exact samples: worst %.2g\n", worst);
}

/* The two-point method's standard errors cover the truth: NTPCOV
 * closed-form curves per class (E*, w, R, k_m log-uniform as in
 * test_fit_sweep, the fold anywhere in the sampling step) of 16, 40, 300
 * and 1 000 samples, noise-free and with noise of 0.1 % and 1 % of the
 * pull-off force, f64 and f32: every answer's ln E* and ln w within
 * COVER_MAX reported errors, noise-free with 40 samples or more within
 * TP_COVER (the error is then the step to the pull-off, bounded: measured
 * 2.5; with 16 the step's shape a sqrt(theta) + b theta is rough, measured
 * 4.9), with noise and 40 samples or more at most COVER_FRAC beyond 3 (with
 * 16, 3 of 16 answers beyond 3, the worst 4.3); the others refused
 * (MDR_E_DEGENERATE: E* not determined by the two measurements). A curve
 * refused MDR_E_PINNED (the retract straight within its noise, or f32's
 * rounding, past its zero-force point, where a pinned top would not show:
 * 0 to 4 of 40 per row noise-free and at 0.1 %, 3 to 13 at 1 %, soft
 * levers) is fitted again with opts.unpinned, the curve's truth, and
 * checked the same (without, fit-tp-round, z's rounding left out of the
 * errors, survived: its curves were refused). Before:
 * the errors were a least-squares fit's at the method's answer, without
 * the step: noise-free, 383 of 600 answers of 300 samples beyond 3 errors,
 * up to 17 (31 with 1 000 samples); with noise up to 200. */
#define TP_COVER 3.5
#ifdef MDR_TARGET_TEST
#define NTPCOV 4
#else
#ifndef NTPCOV
#define NTPCOV 40
#endif
#endif
static void test_two_point_errors(void **state)
{
    static const int sizes[4] = {16, 40, 300, 1000};
    static const double noises[3] = {0.0, 1e-3, 1e-2};
    int s, ni, f32, j, k;
    (void)state;
    noise_state = 0x9E3779B97F4A7C15ull;
    for (ni = 0; ni < 3; ni++) {
        for (f32 = 0; f32 < 2; f32++) {
            for (s = 0; s < NTP_SIZES; s++) {
                const int n = sizes[s];
                const double lim = ni == 0 && n >= 40 ? TP_COVER : COVER_MAX;
                int ok = 0, out3 = 0, pinned = 0;
                double worst_dev = 0;
                for (j = 0; j < NTPCOV; j++) {
                    jkr_par p;
                    mdr_status st;
                    double E, w, Ee, we, dE, dw, d;
                    p.E = pow(10.0, 3 + 9 * noise_uniform());
                    p.w = pow(10.0, -4 + 5 * noise_uniform());
                    p.R = pow(10.0, -9 + 7 * noise_uniform());
                    p.km = pow(10.0, -2 + 4 * noise_uniform());
                    (void)jkr_grid(&p, n, noise_uniform(), noises[ni], zs, Fs);
                    if (f32) {
                        mdr_contact_f32 c;
                        mdr_fit_opts_f32 o;
                        mdr_fit_result_f32 r;
                        const float pp[3] = {(float)p.R, 0, 0};
                        for (k = 0; k < n; k++) {
                            zs32[k] = (float)zs[k];
                            Fs32[k] = (float)Fs[k];
                        }
                        assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
                        mdr_fit_defaults_f32(&o, (float)p.km);
                        o.method = MDR_FIT_TWO_POINT;
                        st = mdr_fit_curve_f32(&c, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r);
                        if (st == MDR_E_PINNED) { /* (the curve's truth: no pinned top) */
                            pinned++;
                            o.unpinned = 1;
                            st = mdr_fit_curve_f32(&c, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r);
                        }
                        E = r.E, w = r.w, Ee = r.E_err, we = r.w_err;
                    } else {
                        const mdr_contact_f64 c = paraboloid64(p.R);
                        mdr_fit_opts_f64 o;
                        mdr_fit_result_f64 r;
                        mdr_fit_defaults_f64(&o, p.km);
                        o.method = MDR_FIT_TWO_POINT;
                        st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
                        if (st == MDR_E_PINNED) {
                            pinned++;
                            o.unpinned = 1;
                            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
                        }
                        E = r.E, w = r.w, Ee = r.E_err, we = r.w_err;
                    }
                    if (st != MDR_OK) {
                        if (!(st == MDR_E_DEGENERATE || st == MDR_E_NOCONV || st == MDR_E_FEW ||
                              st == MDR_E_NOPULLOFF || st == MDR_E_NOCONTACT)) {
                            fail_msg("two-point %d: status %d (%s)", j, st, mdr_status_str(st));
                        }
                        continue;
                    }
                    dE = nerr(E, p.E, Ee);
                    dw = nerr(w, p.w, we);
                    d = dE > dw ? dE : dw;
                    ok++;
                    out3 += d > 3;
                    worst_dev = d > worst_dev ? d : worst_dev;
                    if (!(d <= lim)) {
                        fail_msg("two-point, noise %g, %s, n %d, curve %d (E* %.4g, w %.4g, R %.4g, k_m %.4g): E* %.6g +- "
                                 "%.2g (%.1f errors), w %.6g +- %.2g (%.1f errors)", noises[ni], f32 ? "f32" : "f64", n,
                                 j, p.E, p.w, p.R, p.km, E, Ee, dE, w, we, dw);
                    }
                }
                print_message("two-point errors, noise %g, %s, %4d samples: %d answers of %d (%d first refused "
                              "MDR_E_PINNED, answered with opts.unpinned), %d beyond 3 errors, worst %.2f\n",
                              noises[ni], f32 ? "f32" : "f64", n, ok, NTPCOV, pinned, out3, worst_dev);
                if (ni > 0) {
                    assert_true(out3 <= (int)ceil(COVER_FRAC * ok));
                }
            }
        }
    }
    /* curves of the sweeps above (one per row: E*, w, R, k_m, where the
     * fold lies in its step, noise, samples, the noise generator's state):
     * where the method's answer has a relative error of 1 or more (16
     * samples, the fold at the first free one; answered: E* 19 times high at
     * 60 errors); where the noise moves it far (answered without the
     * reruns at 3 errors: E* 3e7 times low at 33); through a shallow zero
     * crossing (1 000 samples, 1 % noise: the zero-force point from two
     * samples put E* 18 times low at 9 errors). Each answered within
     * TP_COVER errors or refused. */
    {
        static const struct {
            double E, w, R, km, at, noise;
            int n;
            uint64_t seed;
        } cases[] = {
            {441126110.51272053, 2.1080590036073548, 0.00037554548363128858, 0.062784611166527171, 0.98025634466023837,
             0.0, 16, 0xfaf2146e03215da0ull},
            {280290335606.37164, 0.40214648092345129, 0.00045513233557131175, 0.010602650661454138, 0.67399166301590063,
             1e-3, 300, 0xac8ab7b66e10eeccull},
            {11457045.510298524, 1.3107264114709962, 3.5657641805797528e-05, 1.0685248811643997, 0.084466799426770878,
             1e-2, 1000, 0x159f9dbd22c1faf4ull},
            {7.7026e11, 9.0642, 1.3633e-3, 2.0279, 0.63853, 1e-3, 16, 0xa376f85579607e0cull},
            {4.4556e8, 5.48e-3, 7.962e-3, 1.3213, 0.23033, 1e-3, 16, 0x3af72489f3295e60ull},
            {1.6900e11, 0.016913, 2.2476e-4, 0.047457, 0.81602, 1e-3, 40, 0xd0e6d8590fda6cb4ull},
            {1.6900e11, 0.016913, 2.2476e-4, 0.047457, 0.81602, 1e-2, 40, 0xd0e6d8590fda6cb4ull},
        };
        size_t c;
        for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
            const jkr_par p = {cases[c].R, cases[c].E, cases[c].w, cases[c].km};
            const mdr_contact_f64 tip = paraboloid64(p.R);
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            mdr_status st;
            noise_state = cases[c].seed;
            (void)jkr_grid(&p, cases[c].n, cases[c].at, cases[c].noise, zs, Fs);
            mdr_fit_defaults_f64(&o, p.km);
            o.method = MDR_FIT_TWO_POINT;
            st = mdr_fit_curve_f64(&tip, &o, zs, Fs, (uint32_t)cases[c].n, work64, 2 * NMAX, &r);
            if (st == MDR_OK) {
                const double dE = nerr(r.E, p.E, r.E_err), dw = nerr(r.w, p.w, r.w_err);
                if (!(dE <= TP_COVER && dw <= TP_COVER)) {
                    fail_msg("two-point case %u: E* %.6g +- %.2g (%.1f errors), w %.6g +- %.2g (%.1f errors)",
                             (unsigned)c, r.E, r.E_err, dE, r.w, r.w_err, dw);
                }
            } else {
                assert_int_equal(st, MDR_E_DEGENERATE);
            }
            print_message("two-point case %u: %s\n", (unsigned)c, mdr_status_str(st));
        }
    }
}

/* The two-point method's standard errors against the spread they
 * describe (a check independent of the error model): for each regime,
 * noise-free and with noise of 0.1 % of the pull-off force, NMC curves of
 * 40, 300 and 1 000 samples with the fold anywhere in the sampling step
 * (uniform) and fresh noise; every one answered, and the root mean square
 * of ln E* - ln E*_true (and of ln w) over the copies, the method's bias
 * and spread together, against the root mean square of the reported
 * relative errors: within a factor RATIO either way with 300 samples or
 * more (measured 0.86 to 1.20), within TP_MC_COARSE with 40 (measured
 * 1.02 to 1.81: the reported errors too small, most in E* in the
 * transition regime, where the step's a sqrt(theta) + b theta is rough).
 * Host only (TARGET_F64). Fails when the errors leave out the step
 * (fit-tp-step) or inflate it. */
#define TP_MC_COARSE 2.0
#define NTPMC_SIZES 3
#ifndef MDR_TARGET_TEST /* (f64 only: host_tests/test_fit.c's header, TARGET_F64) */
static void test_two_point_mc(void **state)
{
    static const double noises[2] = {0.0, 1e-3};
    static const int sizes[3] = {40, 300, 1000};
    int k, ni, s, j;
    (void)state;
    noise_state = 0x2545F4914F6CDD1Dull;
    for (k = 0; k < 3; k++) {
        for (ni = 0; ni < 2; ni++) {
            for (s = 0; s < NTPMC_SIZES; s++) {
                const jkr_par *p = &regimes[k];
                const mdr_contact_f64 c = paraboloid64(p->R);
                const double lim = sizes[s] >= 300 ? RATIO : TP_MC_COARSE;
                mdr_fit_opts_f64 o;
                double msE = 0, msw = 0, repE = 0, repw = 0, qE, qw;
                mdr_fit_defaults_f64(&o, p->km);
                o.method = MDR_FIT_TWO_POINT;
                for (j = 0; j < NMC; j++) {
                    mdr_fit_result_f64 r;
                    (void)jkr_grid(p, sizes[s], noise_uniform(), noises[ni], zs, Fs);
                    assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)sizes[s], work64, 2 * NMAX, &r),
                                     MDR_OK);
                    msE += log(r.E / p->E) * log(r.E / p->E);
                    msw += log(r.w / p->w) * log(r.w / p->w);
                    repE += (r.E_err / r.E) * (r.E_err / r.E);
                    repw += (r.w_err / r.w) * (r.w_err / r.w);
                }
                qE = sqrt(msE / repE);
                qw = sqrt(msw / repw);
                print_message("two-point Monte Carlo, regime %d, noise %g, %4d samples: rms error / reported: E* "
                              "%.3g / %.3g (%.2f), w %.3g / %.3g (%.2f)\n", k, noises[ni], sizes[s], sqrt(msE / NMC),
                              sqrt(repE / NMC), qE, sqrt(msw / NMC), sqrt(repw / NMC), qw);
                if (NMC >= 20) {
                    assert_true(qE < lim && 1.0 / qE < lim);
                    assert_true(qw < lim && 1.0 / qw < lim);
                }
            }
        }
    }
}
#endif /* !MDR_TARGET_TEST */

/* The two-point method on a tilted baseline with a short free tail
 * (helper-61, stop 68): retracts of 40 to 300 samples over a span whose
 * free part below the fold is 0.1 to 0.4 of the contact part's, the
 * baseline tilted by +-2 % or +-5 % of the pull-off force across the whole
 * span (linear in z, 0 at the top), noise 0 to 0.3 % of the pull-off
 * force; E*, w, R, k_m over the whole ranges (levers up to 1e5 times
 * softer than the contact). Each answer within TP_COVER of its reported
 * errors (in ln E*, ln w), or refused. Before, the free tail's mean was
 * read where its line's extrapolation to the top exceeded 2 noise widths,
 * and neither the mean's bias nor the line's error was in the errors:
 * 5 of these 207 answers lay beyond TP_COVER, the worst E* 0.023 x the
 * truth at 14.0 errors (the helper's: 0.02 x at 49); now 182 answers, the
 * worst at 2.17 errors. Every other curve has 40 samples, 4 or 5 of them
 * free, noise-free: where the slope's error or the mean's bias is left
 * out of the errors (fit-tp-slope-var, fit-tp-slope-bias) some answer
 * beyond TP_COVER. */
#ifdef MDR_TARGET_TEST
#define NTPTILT 20
#else
#define NTPTILT 300
#endif
/* a retract of n samples (jittered by up to half a step) over jkr_curve's
 * span with the free part fr of the contact part's below the fold, the
 * baseline tilted by tl |F_po| across it (0 at the top), noise sig
 * |F_po|, base offset 1 um; the two-point answer (opts.unpinned) */
static mdr_status tilt_fit(const jkr_par *p, int n, double fr, double tl, double sig, mdr_fit_result_f64 *r)
{
    const mdr_contact_f64 c = paraboloid64(p->R);
    const double af = jkr_fold(p);
    double Ff, zf = jkr_z(p, af, &Ff, NULL), ztop = 2.0 * fabs(zf) + jkr_z(p, 2.5 * af, NULL, NULL);
    const double zbot = zf - fr * (ztop - zf);
    mdr_fit_opts_f64 o;
    int i;
    for (i = 0; i < n; i++) {
        const double zp = ztop + (zbot - ztop) * (i + 0.5 * noise_uniform()) / (n - 1);
        double f = 0.0;
        if (zp > zf) {
            jkr_z(p, jkr_a(p, zp, af), &f, NULL);
        }
        zs[i] = zp + 1e-6;
        Fs[i] = f + fabs(Ff) * (tl * (ztop - zp) / (ztop - zbot) + sig * gauss());
    }
    mdr_fit_defaults_f64(&o, p->km);
    o.method = MDR_FIT_TWO_POINT;
    o.unpinned = 1; /* (no pinned top: a retract alone) */
    return mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, r);
}

static void test_two_point_tilt(void **state)
{
    static const int sizes[3] = {40, 100, 300};
    static const double noises[4] = {0.0, 1e-4, 1e-3, 3e-3}, tilts[4] = {-0.05, -0.02, 0.02, 0.05};
    int j, ok = 0, refused = 0;
    double worst_dev = 0, d;
    (void)state;
    noise_state = 0x3C6EF372FE94F82Bull;
    for (j = 0; j < NTPTILT; j++) {
        jkr_par p;
        mdr_fit_result_f64 r;
        mdr_status st;
        double fr, tl, sig;
        int n;
        p.R = pow(10.0, -8 + 3 * noise_uniform());
        p.E = pow(10.0, 5 + 6 * noise_uniform());
        p.w = pow(10.0, -3 + 3 * noise_uniform());
        p.km = pow(10.0, -2 + 4 * noise_uniform());
        n = sizes[j % 3];
        sig = noises[(j / 3) % 4];
        tl = tilts[(j / 12) % 4];
        fr = 0.1 + 0.3 * noise_uniform();
        if (j % 2 == 1) { /* (every other one: 40 samples, 4 or 5 free, noise-free) */
            n = 40;
            sig = 0.0;
            fr = 0.1 + 0.02 * noise_uniform();
        }
        st = tilt_fit(&p, n, fr, tl, sig, &r);
        if (st != MDR_OK) {
            if (!(st == MDR_E_DEGENERATE || st == MDR_E_FEW || st == MDR_E_MISFIT)) {
                fail_msg("two-point tilt %d: status %d (%s)", j, st, mdr_status_str(st));
            }
            refused++;
            continue;
        }
        ok++;
        d = fmax(nerr(r.E, p.E, r.E_err), nerr(r.w, p.w, r.w_err));
        worst_dev = d > worst_dev ? d : worst_dev;
        if (!(d <= TP_COVER)) {
            fail_msg("two-point tilt %d (E* %.6g, w %.6g, R %.6g, k_m %.6g, n %d, tilt %g, free %.3f, noise %g): E* "
                     "%.6g +- %.2g, w %.6g +- %.2g, %.1f errors (F_slope %.4g +- %.2g)",
                     j, p.E, p.w, p.R, p.km, n, tl, fr, sig, r.E, r.E_err, r.w, r.w_err, d, r.F_slope, r.F_slope_err);
        }
    }
    print_message("two-point, tilted baseline, short free tail: %d answers of %d (%d refused), worst %.2f errors\n", ok,
                  NTPTILT, refused, worst_dev);
    assert_true(ok >= NTPTILT / 2);
    {
        /* helper-61's curve (its numbers; this file's generator): 40 free
         * samples, 0.01 % noise, the tilt plain in the tail (F_slope within
         * 3 of its errors), answered within TP_COVER; refused where the
         * tail's mean is read (its bias then in the errors), E* 0.02 x the
         * truth at 49 errors before either */
        const jkr_par p = {2.472398584230027e-06, 7971881.498635217, 0.21229169737135756, 0.01048083117755161};
        const double tl = -0.05;
        mdr_fit_result_f64 r;
        assert_int_equal(tilt_fit(&p, 300, 0.144, tl, 1e-4, &r), MDR_OK);
        d = fmax(nerr(r.E, p.E, r.E_err), nerr(r.w, p.w, r.w_err));
        print_message("two-point, helper-61's tilted curve: E* %.6g +- %.2g, w %.6g +- %.2g (%.2f errors), F_slope %.5g +- "
                      "%.2g\n", r.E, r.E_err, r.w, r.w_err, d, r.F_slope, r.F_slope_err);
        assert_true(d <= TP_COVER);
        assert_true(r.F_slope * tl < 0.0 && r.F_slope_err > 0.0 && r.F_slope_err < 1e-2 * fabs(r.F_slope));
    }
}

/* ---- the approach: w_adv ------------------------------------------------------ */

static void test_approach(void **state)
{
    static const double ratios[3] = {0.3, 1.0, 0.0};
    const jkr_par *p = &regimes[1];
    int k;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        mdr_contact_f64 c = paraboloid64(p->R), ca, cr;
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        double pp[3] = {p->R, 0, 0}, z0 = 5e-9, Fb = 1e-11, wadv = ratios[k] * p->w, Fpo;
        int i, na = NAPP, nr = 7 * NAPP / 3, last = jkr_curve(p, z0, Fb, nr, zs + na, Fs + na, 0, &Fpo);
        /* approach: from the retract's lowest z up to its top */
        for (i = 0; i < na; i++) {
            zs[i] = zs[na + nr - 1] + (zs[na] - zs[na + nr - 1]) * i / (na - 1);
        }
        assert_int_equal(mdr_contact_init_f64(&ca, MDR_PROFILE_PARABOLOID, pp, p->E, wadv), MDR_OK);
        assert_int_equal(mdr_contact_init_f64(&cr, MDR_PROFILE_PARABOLOID, pp, p->E, p->w), MDR_OK);
        assert_int_equal(mdr_fit_model_f64(&ca, p->km, z0, Fb, MDR_FIT_APPROACH, zs, (uint32_t)na, Fs), MDR_OK);
        mdr_fit_defaults_f64(&o, p->km);
        o.approach = 1;
        assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)(na + nr), work64, 2 * NMAX, &r), MDR_OK);
        assert_int_equal(r.n, nr);
        assert_int_equal(r.n_approach, na); /* the approach ends where the retract starts */
        check_fit64(&r, p->E, p->w, z0, Fb, zs[na] - zs[na + last], fabs(Fpo), TOL_RT, "with approach");
        if (wadv > 0) {
            track(r.w_adv, wadv, 0, TOL_RT, "w_adv");
        } else {
            assert_true(r.w_adv <= TOL_RT * p->w); /* the bound s = 0 */
        }
        (void)cr;
    }
    print_message("approach w_adv round trip: worst %.2g\n", worst);
}

/* ---- a pinned top ------------------------------------------------------- */

/* A retract after an approach with w_adv < w (closed forms, libm): the top
 * at radius at on the approach branch (JKR with w_adv), then pinned at at
 * (F = F_t + 2E* at (d - d_t): a flat punch of radius at, seed 4.16) down
 * to where the receding branch (w) has the radius at, then that branch to
 * the fold and free below; where at lies below the fold's radius the
 * pinned contact ruptures there (that point of the receding branch is
 * unstable) and the curve is free below it. n samples uniform in z';
 * returns the samples above the pinned part's end in *npin and the last
 * contact index; *Fpo the force where the contact lets go. */
/* pinned_curve's positions on a piezo's decimal grid (test_written_irregular):
 * each moved down to a whole unit of 10^curve_ue (0: not) */
static int curve_ue = 0;
static bool curve_rounded = false; /* z[] rounded down to that unit, F at the positions before */
/* z[] the unit's positions, F at them scaled about the bottom by this many
 * units over the span (a file's rounding of a grid whose errors drift
 * linearly, test_written_drift; 0: not) */
static double curve_drift = 0.0;

static double decimal_floor(double x, int ue)
{
    char buf[48];
    snprintf(buf, sizeof buf, "%.0fe%d", floor(x * pow(10.0, -ue)), ue);
    return strtod(buf, NULL);
}

static int pinned_curve(const jkr_par *p, double wadv, double at, double z0, double Fb, int n, double *z,
                        double *F, int *npin, double *Fpo)
{
    jkr_par pa = *p;
    double af = jkr_fold(p), Ff, zf = jkr_z(p, af, &Ff, NULL), Ft, zt, dt, zpin, k2 = 2 * p->E * at, ztop, zbot;
    int i, last = -1;
    pa.w = wadv;
    zt = jkr_z(&pa, at, &Ft, NULL);
    dt = zt - Ft / p->km;
    zpin = jkr_z(p, at, NULL, NULL); /* the receding branch at radius at */
    ztop = zt;
    zbot = zf - 0.4 * (ztop - zf);
    *npin = 0;
    for (i = 0; i < n; i++) {
        double zp = ztop + (zbot - ztop) * i / (n - 1), f = 0.0, zw = zp + z0;
        if (curve_ue != 0) {
            zw = decimal_floor(zw, curve_ue);
            zp = curve_rounded ? zp : zw - z0 + curve_drift * pow(10.0, curve_ue) * (zw - z0 - zbot) / (ztop - zbot);
        }
        if (zp > zpin) {
            /* z' = d + (F_t + k2 (d - d_t))/k_m */
            double d = (zp - (Ft - k2 * dt) / p->km) / (1 + k2 / p->km);
            f = Ft + k2 * (d - dt);
            (*npin)++;
            last = i;
        } else if (at > af && zp > zf) {
            jkr_z(p, jkr_a(p, zp, af), &f, NULL);
            last = i;
        }
        z[i] = zw;
        F[i] = f + Fb;
    }
    if (at > af) {
        *Fpo = Ff;
    } else {
        jkr_z(p, at, Fpo, NULL);
    }
    return last;
}

static void test_pinned_top(void **state)
{
    static const double ratios[3] = {0.0, 0.3, 0.7}, tops[3] = {1.5, 2.5, 4.0};
    const jkr_par *p = &regimes[1];
    int k, t;
    (void)state;
    worst = 0;
    for (k = 0; k < 3; k++) {
        for (t = 0; t < 3; t++) {
            mdr_contact_f64 c = paraboloid64(p->R);
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            double z0 = 5e-9, Fb = 1e-11, Fpo;
            int npin, n = NPROF, last = pinned_curve(p, ratios[k] * p->w, tops[t] * jkr_fold(p), z0, Fb, n, zs, Fs,
                                                     &npin, &Fpo);
            char what[96];
            snprintf(what, sizeof what, "pinned top, w_adv/w %.1f, a_t/a_fold %.1f", ratios[k], tops[t]);
            assert_true(npin > 0 && last > npin);
            mdr_fit_defaults_f64(&o, p->km);
            assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
            check_fit64(&r, p->E, p->w, z0, Fb, zs[0] - zs[last], fabs(Fpo), TOL_RT_CF, what);
            if (!((int)r.n_pinned == npin || (int)r.n_pinned == npin + 1)) {
                fail_msg("%s: n_pinned %u, the curve's %d", what, (unsigned)r.n_pinned, npin);
            }
            assert_int_equal(r.n, (uint32_t)n - r.n_pinned);
        }
    }
    print_message("pinned top round trip: worst %.2g\n", worst);
}

/* A retract pinned all the way to its rupture (a_t below the fold's
 * radius, w_adv < w, the soft lever of regime 1): a line and its end, three
 * numbers for E*, w, z0 and a_t, so no answer: MDR_E_PINNED, noise-free and
 * in NMC noisy copies (sigma 0.1 % of the rupture force; the line explains
 * them better than any receding branch). Before: E* 22 % high, status ok. */
static void test_pinned_rupture(void **state)
{
    /* (w_adv/w, a_t/a_fold) pairs with a compressive top (F_t > 0, which
     * the fit needs: MDR_E_NOCONTACT) */
    static const double ratios[3] = {0.0, 0.0, 0.02}, tops[3] = {0.6, 0.9, 0.9};
    const jkr_par *p = &regimes[1];
    int k, j, i;
    (void)state;
    for (k = 0; k < 3; k++) {
        mdr_contact_f64 c = paraboloid64(p->R);
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        double Fpo;
        int npin, n = NPROF, last = pinned_curve(p, ratios[k] * p->w, tops[k] * jkr_fold(p), 5e-9, 1e-11, n, zs, Fm,
                                                 &npin, &Fpo);
        assert_true(last + 1 == npin && n - npin > 8 && Fm[0] > 1e-11);
        mdr_fit_defaults_f64(&o, p->km);
        for (j = 0; j <= NMC; j++) {
            mdr_status st;
            for (i = 0; i < n; i++) {
                Fs[i] = Fm[i] + (j == 0 ? 0.0 : 1e-3 * fabs(Fpo) * gauss());
            }
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            if (st != MDR_E_PINNED) {
                fail_msg("pinned to the rupture (w_adv/w %.2f, a_t/a_fold %.1f, copy %d): status %d, E* %.4g",
                         ratios[k], tops[k], j, st, st == MDR_OK ? r.E : 0.0);
            }
        }
    }
}

/* A pinned top under noise through a lever stiff against the contact
 * (regime 1 with k_m = 2 N/m; w_adv/w 0 and 0.5, a_t 2.5 a_fold): NMC
 * copies, sigma 0.1 % of the pull-off force, every estimate within 5
 * reported standard errors of the truth (test_noise's rule). The straight
 * start is pinned whatever the refits say: without that floor the noise
 * walks the pinned part's end up to the top (E* 14 % high, 40 errors). */
static void test_pinned_noise(void **state)
{
    static const double ratios[2] = {0.0, 0.5};
    jkr_par p = regimes[1];
    int k, j, i;
    (void)state;
    p.km = 2.0;
    for (k = 0; k < 2; k++) {
        mdr_contact_f64 c = paraboloid64(p.R);
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        double Fpo, z0 = 5e-9, Fb = 1e-11;
        int npin, n = NNOISE;
        (void)pinned_curve(&p, ratios[k] * p.w, 2.5 * jkr_fold(&p), z0, Fb, n, zs, Fm, &npin, &Fpo);
        mdr_fit_defaults_f64(&o, p.km);
        for (j = 0; j < NMC; j++) {
            for (i = 0; i < n; i++) {
                Fs[i] = Fm[i] + 1e-3 * fabs(Fpo) * gauss();
            }
            assert_int_equal(mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r), MDR_OK);
            if (!(fabs(r.E - p.E) <= 5 * r.E_err && fabs(r.w - p.w) <= 5 * r.w_err)) {
                fail_msg("noisy pinned top (w_adv/w %.1f, copy %d): E* %.4g +- %.2g, w %.4g +- %.2g", ratios[k], j,
                         r.E, r.E_err, r.w, r.w_err);
            }
            assert_true(r.n_pinned > 0);
        }
    }
}

/* ---- the regime ----------------------------------------------------------------- */

static void test_tabor(void **state)
{
    mdr_contact_f64 c;
    double mu, R, pp[3] = {20e-9, 0, 0}, ze = 0.3e-9, E = 1e9, w;
    uint8_t rg;
    int k;
    (void)state;
    /* mu = (R w^2/(E*^2 z_e^3))^(1/3) at the thresholds and around them */
    for (k = 0; k < 6; k++) {
        double mu_want = (k < 3 ? 5.0 : 0.1) * (k % 3 == 0 ? 0.999 : k % 3 == 1 ? 1.0 : 1.001);
        w = sqrt(pow(mu_want, 3) * E * E * ze * ze * ze / pp[0]);
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, pp, E, w), MDR_OK);
        assert_int_equal(mdr_tabor_f64(&c, ze, 1e-9, &mu, &R, &rg), MDR_OK);
        rel_le(mu, cbrt(pp[0] * w * w / (E * E * ze * ze * ze)), 0, TOL_MU, "mu");
        rel_le(R, pp[0], 0, 0, "R of the paraboloid");
        if (k % 3 != 1) { /* at the threshold itself the rounding decides */
            assert_int_equal(rg, k == 0 ? MDR_REGIME_TRANSITION : k == 2 ? MDR_REGIME_JKR
                                 : k == 3 ? MDR_REGIME_DMT : MDR_REGIME_TRANSITION);
        }
    }
    assert_string_equal(mdr_regime_str(MDR_REGIME_JKR), "JKR");
    assert_string_equal(mdr_regime_str(MDR_REGIME_TRANSITION), "transition");
    assert_string_equal(mdr_regime_str(MDR_REGIME_DMT), "DMT");
    assert_string_equal(mdr_regime_str(0), "none");
    /* the apex radii and the equivalent radius a^2/g(a) */
    {
        double pw[3] = {30e-9, 1e-9, 10e-9}, pc[3] = {0.5, 0, 0}, pl[3] = {2e7, 2.0, 0}, g;
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_WAVY, pw, E, 0.05), MDR_OK);
        assert_int_equal(mdr_tabor_f64(&c, ze, 1e-9, &mu, &R, NULL), MDR_OK);
        rel_le(R, 1 / (1 / pw[0] + 4 * M_PI * M_PI * pw[1] / (pw[2] * pw[2])), 0, 1e-15, "wavy apex R");
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_POWERLAW, pl, E, 0.05), MDR_OK);
        assert_int_equal(mdr_tabor_f64(&c, ze, 1e-9, &mu, &R, NULL), MDR_OK);
        rel_le(R, 0.5 / pl[0], 0, 1e-15, "power law n = 2: R = 1/(2C)");
        assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_CONE, pc, E, 0.05), MDR_OK);
        assert_int_equal(mdr_tabor_f64(&c, ze, 3e-9, &mu, &R, NULL), MDR_OK);
        g = M_PI / 2 * tan(pc[0]) * 3e-9; /* cone: g = (pi/2) tan(theta) x */
        rel_le(R, 3e-9 * 3e-9 / g, 0, 1e-14, "cone: equivalent radius");
        assert_int_equal(mdr_tabor_f64(&c, 0.0, 3e-9, &mu, &R, NULL), MDR_E_PARAM);
        assert_int_equal(mdr_tabor_f64(&c, NAN, 3e-9, &mu, &R, NULL), MDR_E_NONFINITE);
        assert_int_equal(mdr_tabor_f64(&c, ze, -1.0, &mu, &R, NULL), MDR_E_RADIUS);
        assert_int_equal(mdr_tabor_f64(NULL, ze, 3e-9, &mu, &R, NULL), MDR_E_NULL);
    }
#if MDR_CFG_PROFILE_TABLE
    /* sampled tips: the apex curvature of the samples' model where it
     * starts smooth (a sampled paraboloid, and a sphere of 1 um sampled every
     * 25 nm: 1/f''(0) = R to O(h^2/R^2)); a worn (flat) or pointed apex
     * takes a^2/g(a), the worn paraboloid's g = (a/R) sqrt(a^2 - b^2) and,
     * for a cone with a paraboloid on it, f = r tan(theta) + r^2/(2R) (its
     * apex curved, but pointed), g = (pi/2) x tan(theta) + x^2/R, worked
     * out here */
    {
        enum { M = 41 };
        double r[M], s[M], b = 4e-9, h = 0.5e-9, g;
        int i, kind;
        for (kind = 0; kind < 4; kind++) {
            const double Rk = kind == 1 ? 1e-6 : 20e-9, hk = kind == 1 ? 25e-9 : h;
            for (i = 0; i < M; i++) {
                r[i] = i * hk;
            }
            for (i = 0; i + 1 < M; i++) { /* interval slopes of f */
                double f0, f1;
                if (kind == 0) {
                    f0 = r[i] * r[i] / (2 * Rk), f1 = r[i + 1] * r[i + 1] / (2 * Rk);
                } else if (kind == 1) {
                    f0 = Rk - sqrt(Rk * Rk - r[i] * r[i]), f1 = Rk - sqrt(Rk * Rk - r[i + 1] * r[i + 1]);
                } else if (kind == 2) {
                    f0 = r[i] < b ? 0 : (r[i] * r[i] - b * b) / (2 * Rk);
                    f1 = r[i + 1] < b ? 0 : (r[i + 1] * r[i + 1] - b * b) / (2 * Rk);
                } else {
                    f0 = r[i] * (tan(0.3) + r[i] / (2 * Rk)), f1 = r[i + 1] * (tan(0.3) + r[i + 1] / (2 * Rk));
                }
                s[i] = (f1 - f0) / (r[i + 1] - r[i]);
            }
            assert_int_equal(mdr_contact_init_table_f64(&c, r, s, M, E, 0.05), MDR_OK);
            assert_int_equal(mdr_tabor_f64(&c, ze, 10e-9, &mu, &R, NULL), MDR_OK);
            if (kind == 0) {
                rel_le(R, Rk, 0, 1e-13, "sampled paraboloid: apex R");
            } else if (kind == 1) {
                /* the one-sided curvature is f'' near r = h: 1/R (1 + 3h^2/(2R^2) + ...) */
                rel_le(R, Rk, 0, 2 * (hk / Rk) * (hk / Rk), "sampled sphere: apex R to 2 (h/R)^2");
            } else if (kind == 2) {
                g = 10e-9 / Rk * sqrt(100e-18 - b * b);
                rel_le(R, 100e-18 / g, 0, 1e-12, "worn tip: a^2/g(a)");
            } else {
                g = M_PI / 2 * tan(0.3) * 10e-9 + 100e-18 / Rk; /* the cone's and the paraboloid's g */
                rel_le(R, 100e-18 / g, 0, 1e-12, "pointed paraboloid (f'(0) != 0): a^2/g(a)");
            }
        }
    }
#endif
}

/* ---- bad input: named errors, nothing written ------------------------------------ */

static mdr_fit_result_f64 poisoned(void)
{
    mdr_fit_result_f64 r;
    memset(&r, 0xA5, sizeof r);
    return r;
}

static void expect_fail(const mdr_contact_f64 *c, const mdr_fit_opts_f64 *o, const double *z, const double *F,
                        uint32_t n, size_t wl, mdr_status want, const char *what)
{
    mdr_fit_result_f64 r = poisoned(), p = poisoned();
    mdr_status st = mdr_fit_curve_f64(c, o, z, F, n, work64, wl, &r);
    if (st != want) {
        print_error("%s: status %d (%s), want %d (%s)\n", what, st, mdr_status_str(st), want, mdr_status_str(want));
        fail();
    }
    assert_memory_equal(&r, &p, sizeof r);
}

/* expect_fail, and the same status from the f32 fit of the same curve
 * (zs, Fs rounded to float) on the paraboloid of radius R, k_m km */
static void expect_fail_both(double R, double km, uint32_t n, mdr_status want, const char *what)
{
    const mdr_contact_f64 c = paraboloid64(R);
    mdr_contact_f32 c32;
    mdr_fit_opts_f64 o;
    mdr_fit_opts_f32 o32;
    mdr_fit_result_f32 r32;
    const float pp[3] = {(float)R, 0, 0};
    assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
    mdr_fit_defaults_f64(&o, km);
    mdr_fit_defaults_f32(&o32, (float)km);
    expect_fail(&c, &o, zs, Fs, n, 2 * NMAX, want, what);
    curve32(n);
    assert_int_equal(mdr_fit_curve_f32(&c32, &o32, zs32, Fs32, n, work32, 2 * NMAX, &r32), want);
}

static void test_bad_input(void **state)
{
    const jkr_par *p = &regimes[1];
    mdr_contact_f64 c = paraboloid64(p->R), punch;
    mdr_fit_opts_f64 o, ob;
    double Fpo, pp[3] = {1e-8, 0, 0}, sig;
    int i, n = 400, last = jkr_curve(p, 0.0, 0.0, n, zs, Fs, 0, &Fpo);
    (void)state;
    mdr_fit_defaults_f64(&o, p->km);
    memcpy(Fm, Fs, sizeof Fm);
    /* arguments */
    expect_fail(NULL, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NULL, "NULL tip");
    expect_fail(&c, NULL, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NULL, "NULL opts");
    expect_fail(&c, &o, NULL, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NULL, "NULL z");
    expect_fail(&c, &o, zs, Fs, (uint32_t)n, 2 * (size_t)n - 1, MDR_E_SIZE, "workspace too small");
    ob = o;
    ob.k_m = 0;
    expect_fail(&c, &ob, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_PARAM, "k_m = 0");
    ob = o;
    ob.k_m = INFINITY;
    expect_fail(&c, &ob, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NONFINITE, "k_m = inf");
    ob = o;
    ob.z_e = -1;
    expect_fail(&c, &ob, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_PARAM, "z_e < 0");
    ob = o;
    ob.E0 = 1e9;
    expect_fail(&c, &ob, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_PARAM, "E0 without w0");
    ob = o;
    ob.method = 7;
    expect_fail(&c, &ob, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_PARAM, "unknown method");
    assert_int_equal(mdr_contact_init_f64(&punch, MDR_PROFILE_FLATPUNCH, pp, 1.0, 0.0), MDR_OK);
    expect_fail(&punch, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_KIND, "flat punch");
    /* curves */
    expect_fail(&c, &o, zs, Fs, 5u, 2 * NMAX, MDR_E_FEW, "too few points");
    /* three contact samples (compressive, zero-crossing, pull-off) and ten free ones */
    {
        double z3[13], F3[13];
        z3[0] = zs[0];
        F3[0] = Fs[0];
        z3[1] = zs[last / 2];
        F3[1] = Fs[last / 2];
        z3[2] = zs[last];
        F3[2] = Fs[last];
        for (i = 0; i < 10; i++) {
            z3[3 + i] = zs[last + 1 + i];
            F3[3 + i] = Fs[last + 1 + i];
        }
        expect_fail(&c, &o, z3, F3, 13u, 2 * NMAX, MDR_E_FEW, "too few contact points");
    }
    Fs[n / 2] = NAN;
    expect_fail(&c, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NONFINITE, "NaN row");
    memcpy(Fs, Fm, sizeof Fm);
    zs[n / 3] = zs[n / 3 - 2];
    expect_fail(&c, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_ORDER, "z not monotonic in the retract");
    last = jkr_curve(p, 0.0, 0.0, n, zs, Fs, 0, &Fpo);
    expect_fail(&c, &o, zs, Fs, (uint32_t)last, 2 * NMAX, MDR_E_NOPULLOFF, "never separates (ends in contact)");
    expect_fail(&c, &o, zs, Fs, (uint32_t)last + 3u, 2 * NMAX, MDR_E_NOPULLOFF, "two free points after the jump");
    /* ... and with noise (1 % of the pull-off force): a curve cut off in
     * contact at 8 lengths from a quarter of its contact part to all of it,
     * 6 noise draws each. The scan took the samples after the largest rise
     * of the noise for the free part, and its line for the baseline:
     * MDR_E_NOCONTACT for a curve in contact throughout (helper-44, stop 61:
     * the fit-plot curve cut at 2 600 or 3 000 of its 4 000 rows) */
    {
        int cut, draw, nopo = 0, tot = 0;
        sig = 1e-2 * fabs(Fpo);
        for (cut = 0; cut < 8; cut++) {
            const int m = last / 4 + (last - last / 4) * cut / 7 + 1;
            for (draw = 0; draw < 6; draw++) {
                mdr_fit_result_f64 r;
                for (i = 0; i < m; i++) {
                    Fs[i] = Fm[i] + sig * gauss();
                }
                mdr_status st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)m, work64, 2 * NMAX, &r);
                nopo += st == MDR_E_NOPULLOFF;
                tot++;
                if (st != MDR_E_NOPULLOFF) {
                    print_message("cut off in contact at %d of %d samples, draw %d: status %d\n", m, last + 1, draw,
                                  (int)st);
                }
            }
        }
        assert_int_equal(nopo, tot);
    }
    /* no contact: noise about a baseline */
    sig = 1e-3 * fabs(Fpo);
    for (i = 0; i < n; i++) {
        Fs[i] = 1e-10 + sig * gauss();
    }
    expect_fail(&c, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NOCONTACT, "no contact");
    for (i = 0; i < n; i++) {
        Fs[i] = 1e-12; /* no noise either: the rounding of the mean must not look like contact */
    }
    expect_fail(&c, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NOCONTACT, "no contact, noise-free");
    /* contact without adhesion: the force comes down to the baseline with no jump */
    for (i = 0; i < n; i++) {
        double zp = zs[i] - zs[n / 2];
        Fs[i] = zp > 0 ? 1e3 * zp * sqrt(zp / 1e-9) * 1e-6 : 0.0;
    }
    expect_fail(&c, &o, zs, Fs, (uint32_t)n, 2 * NMAX, MDR_E_NOPULLOFF, "no adhesion, no jump");
    /* the model refuses what the fit refuses */
    assert_int_equal(mdr_fit_model_f64(&punch, 1.0, 0.0, 0.0, MDR_FIT_RETRACT, zs, 3u, Fm), MDR_E_KIND);
    assert_int_equal(mdr_fit_model_f64(&c, 0.0, 0.0, 0.0, MDR_FIT_RETRACT, zs, 3u, Fm), MDR_E_PARAM);
    assert_int_equal(mdr_fit_model_f64(&c, 1.0, 0.0, 0.0, 9, zs, 3u, Fm), MDR_E_PARAM);
    assert_int_equal(mdr_fit_model_f64(&c, 1.0, 0.0, 0.0, MDR_FIT_APPROACH, zs, 3u, Fm), MDR_E_ORDER);
    assert_int_equal(mdr_fit_model_f64(NULL, 1.0, 0.0, 0.0, MDR_FIT_RETRACT, zs, 3u, Fm), MDR_E_NULL);
    /* contact_material */
    assert_int_equal(mdr_contact_material_f64(&c, -1.0, 0.1), MDR_E_PARAM);
    assert_int_equal(mdr_contact_material_f64(&c, 1.0, NAN), MDR_E_NONFINITE);
    assert_int_equal(mdr_contact_material_f64(NULL, 1.0, 0.1), MDR_E_NULL);
}

/* a wavy tip whose retract jumps before the pull-off: named error */
static void test_jumps(void **state)
{
    mdr_contact_f64 c;
    double pw[3] = {1e-6, 20e-9, 0.2e-6}, z[3] = {2e-6, 1e-6, 0.0}, F[3];
    (void)state;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_WAVY, pw, 1e6, 0.05), MDR_OK);
    assert_int_equal(mdr_fit_model_f64(&c, 1.0, 0.0, 0.0, MDR_FIT_RETRACT, z, 3u, F), MDR_E_JUMPS);
}

/* ---- answers the fit must refuse ------------------------------------------- */

/* A retract of n + 1 points uniform in z' from up s down to the fold's
 * z' - below s, s = max(|z'_fold|, a_fold^2/R) (the span of the
 * adversarial tester's generator), base offset z0, noise sig; *Fpo the
 * fold's force. Returns the number of points. */
static int jkr_span(const jkr_par *p, double up, double below, int n, double z0, double sig, double *z, double *F,
                    double *Fpo)
{
    double af = jkr_fold(p), Ff, zf = jkr_z(p, af, &Ff, NULL), s, top, bot;
    int i;
    s = fabs(zf) > af * af / p->R ? fabs(zf) : af * af / p->R;
    top = up * s;
    bot = zf - below * s;
    for (i = 0; i <= n; i++) {
        double zp = top - (top - bot) * i / n, f = 0.0;
        if (zp > zf) {
            jkr_z(p, jkr_a(p, zp, af), &f, NULL);
        }
        z[i] = zp + z0;
        F[i] = f + (sig > 0 ? sig * gauss() : 0.0);
    }
    *Fpo = Ff;
    return n + 1;
}

/* The fit from poor first guesses (E0, w0 over 1e3..1e14 Pa and
 * 1e-3..10 J/m^2) on a noise-free closed-form curve (regime 1): every
 * answer is the truth (TOL_RT) or a named refusal. Before: from E0 = 1e12,
 * w0 = 0.1, E* = 6.6e-21 Pa (a pull-off radius of metres, z0 at 1e9 m,
 * rms 45 % of the pull-off force), and from 1e13, 2: E* = 1e51 Pa (the
 * rigid limit, regime DMT), both status ok. */
#ifndef MDR_TARGET_TEST /* (f64 only: host_tests/test_fit.c's header, TARGET_F64) */
static void test_refuse_bad_start(void **state)
{
    const jkr_par *p = &regimes[1];
    mdr_contact_f64 c = paraboloid64(p->R);
    mdr_fit_opts_f64 o;
    double Fpo, z0 = 1e-6;
    int n = NNOISE, last = jkr_curve(p, z0, 0.0, n, zs, Fs, 0, &Fpo), ie, iw, ok = 0, refused = 0;
    (void)state;
    worst = 0;
    mdr_fit_defaults_f64(&o, p->km);
    for (ie = 3; ie <= 14; ie += BAD_START_STRIDE) {
        for (iw = -3; iw <= 1; iw++) {
            mdr_fit_result_f64 r = poisoned(), pz = poisoned();
            mdr_status st;
            char what[96];
            o.E0 = pow(10.0, ie);
            o.w0 = pow(10.0, iw);
            snprintf(what, sizeof what, "from E0 = %.0e, w0 = %.0e", o.E0, o.w0);
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            if (st == MDR_OK) {
                check_fit64(&r, p->E, p->w, z0, 0.0, zs[0] - zs[last], fabs(Fpo), TOL_RT, what);
                ok++;
            } else {
                /* (a refusal that names no answer found: on the Cortex-M4F,
                 * whose double arithmetic rounds otherwise, E0 = 1e13, w0 =
                 * 1 ends in an inner solve's cap, MDR_E_NOCONV) */
                if (!(st == MDR_E_MISFIT || st == MDR_E_DEGENERATE || st == MDR_E_FITCAP || st == MDR_E_NOCONV)) {
                    fail_msg("%s: status %d (%s)", what, st, mdr_status_str(st));
                }
                assert_memory_equal(&r, &pz, sizeof r); /* out untouched on error */
                refused++;
            }
        }
    }
    print_message("poor first guesses: %d the truth (worst %.2g), %d refused\n", ok, worst, refused);
}
#endif /* !MDR_TARGET_TEST */

/* z in nanometres (a unit slip: every z times 1e9) with k_m in N/m: the
 * indentation 1e9 times larger, the lever's bend nothing, and the best
 * model misses the curve. Closed-form curves of regime 1 spanning up s
 * above the contact to below s under the fold (s = |z'_fold|, jkr_span).
 * Before: E* = 1e-7 to 2.5e-7 Pa, a pull-off radius of 0.3 mm on a 20 nm
 * tip, the model's pull-off force 1/3 of the data's, status ok (f64 and
 * f32). Now MDR_E_MISFIT. */
static void test_refuse_units(void **state)
{
    static const double ups[3] = {0.5, 1.0, 2.0}, belows[2] = {0.3, 2.0};
    const jkr_par *p = &regimes[1];
    int i, u, b;
    (void)state;
    for (u = 0; u < 3; u++) {
#ifdef MDR_TARGET_TEST
        /* the target: every 2nd (up, below) pair, (0.5, 0.3), (1, 2),
         * (2, 0.3): every up and every below still met; the host runs all
         * six */
        for (b = u % 2; b < 2; b += 2) {
#else
        for (b = 0; b < 2; b++) {
#endif
            double Fpo;
            int n = jkr_span(p, ups[u], belows[b], 1000, 1e-6, 0.0, zs, Fs, &Fpo);
            char what[64];
            for (i = 0; i < n; i++) {
                zs[i] *= 1e9;
            }
            snprintf(what, sizeof what, "z in nm (up %.1f, below %.1f)", ups[u], belows[b]);
            expect_fail_both(p->R, p->km, (uint32_t)n, MDR_E_MISFIT, what);
        }
    }
}

/* A curve the model does not describe, with a fold for its pull-off: a
 * closed-form retract of regime 1 (jkr_span, up 1, below 0.5, noise-free)
 * with a smooth bump added over the upper half of its contact,
 * amp |F_po| sin^2(k pi (z' - z_m)/(z'_top - z_m)) for z' above z_m (the
 * middle of the contact's span), 0 below it and at the pull-off. Amplitudes
 * DISTORT_AMP (2 % to 30 % of the pull-off force, 20 to 300 times
 * MDR_FIT_MISFIT_REL of the force scale) and k = 1, 2, 3 half waves. The
 * residual's rms is then far above the noise bound plus
 * MDR_FIT_MISFIT_REL of the force scale, yet far below the scale itself,
 * and only the misfit test on the residual refuses: MDR_E_MISFIT, f64 and
 * f32 (the order and fold-end tests see a retract ending in a fold, as the
 * model's). */
static void test_refuse_distorted(void **state)
{
    static const double amps[4] = {0.02, 0.05, 0.1, 0.3};
    const jkr_par *p = &regimes[1];
    int a, k, i;
    (void)state;
    for (a = 0; a < 4; a += DISTORT_STRIDE) {
        for (k = 1; k <= 3; k += DISTORT_K_STRIDE) {
            double Fpo, zt, zm, zf;
            int n = jkr_span(p, 1.0, 0.5, 600, 1e-6, 0.0, zs, Fs, &Fpo), last;
            char what[80];
            for (last = n - 1; last > 0 && Fs[last] == 0.0; last--) {
            }
            zt = zs[0];
            zf = zs[last];
            zm = 0.5 * (zt + zf);
            for (i = 0; i < last; i++) {
                if (zs[i] > zm) {
                    const double sn = sin(k * M_PI * (zs[i] - zm) / (zt - zm));
                    Fs[i] += amps[a] * fabs(Fpo) * sn * sn;
                }
            }
            snprintf(what, sizeof what, "a bump of %.0f %% of the pull-off force, %d half waves", 100.0 * amps[a], k);
            expect_fail_both(p->R, p->km, (uint32_t)n, MDR_E_MISFIT, what);
        }
    }
}

/* E* runs off by itself (the default first guess) toward the rigid limit
 * where a lever much softer than the contact leaves E* undetermined: the
 * adversarial tester's curve (JKR, E* = 1.92e11 Pa, w = 4.47 J/m^2,
 * R = 29.8 um, k_m = 0.08 N/m: the contact 2e6 times stiffer than the
 * lever). Before: E* = 5.6e42 Pa +- 3.4e51, regime DMT, status ok. Now
 * MDR_E_DEGENERATE (relative error of E* above 1), f64 and f32. */
static void test_refuse_runaway(void **state)
{
    const jkr_par p = {2.97698e-5, 1.92274e11, 4.47239, 0.0799691};
    double Fpo;
    int n = jkr_span(&p, 2.176, 0.9695, 1000, 1e-6, 0.0, zs, Fs, &Fpo);
    (void)state;
    expect_fail_both(p.R, p.km, (uint32_t)n, MDR_E_DEGENERATE, "soft lever runaway");
}

/* Curves in reversed time order (rev_curve: the library's forward model,
 * paraboloid; the approach with w_adv from 0.4 of the span below the fold
 * to the top, the retract (w) back down, na and nr samples; noise of
 * sig_rel of the fold's force on both), over jkr_curve's span. Returns the
 * retract's start. */
static int rev_curve(const jkr_par *p, double wadv, int na, int nr, double sig_rel, double *z, double *F)
{
    mdr_contact_f64 ca, cr;
    mdr_critstate_f64 cs;
    mdr_eqstate_f64 e;
    double pp[3] = {p->R, 0, 0}, as, zf, ztop, zbot, z0 = 2e-6;
    int i;
    assert_int_equal(mdr_contact_init_f64(&cr, MDR_PROFILE_PARABOLOID, pp, p->E, p->w), MDR_OK);
    assert_int_equal(mdr_contact_init_f64(&ca, MDR_PROFILE_PARABOLOID, pp, p->E, wadv), MDR_OK);
    assert_int_equal(mdr_default_start_f64(&cr, &as), MDR_OK);
    assert_int_equal(mdr_critical_f64(&cr, MDR_CONTROL_MACHINE, p->km, as, &cs), MDR_OK);
    assert_int_equal(mdr_eq_f64(&cr, 2.5 * cs.a, &e), MDR_OK);
    zf = cs.d + cs.F / p->km;
    ztop = 2.0 * fabs(zf) + e.d + e.F / p->km; /* jkr_curve's span */
    zbot = zf - 0.4 * (ztop - zf);
    for (i = 0; i < na; i++) {
        z[i] = z0 + zbot + (ztop - zbot) * i / (na - 1);
    }
    for (i = 0; i < nr; i++) {
        z[na + i] = z0 + ztop + (zbot - ztop) * i / (nr - 1);
    }
    assert_int_equal(mdr_fit_model_f64(&ca, p->km, z0, 0.0, MDR_FIT_APPROACH, z, (uint32_t)na, F), MDR_OK);
    assert_int_equal(mdr_fit_model_f64(&cr, p->km, z0, 0.0, MDR_FIT_RETRACT, z + na, (uint32_t)nr, F + na), MDR_OK);
    for (i = 0; i < na + nr; i++) {
        F[i] += sig_rel * fabs(cs.F) * gauss();
    }
    return na;
}

static void reverse(double *v, int n)
{
    int i;
    for (i = 0; i < n / 2; i++) {
        double t = v[i];
        v[i] = v[n - 1 - i];
        v[n - 1 - i] = t;
    }
}

/* The approach's fit meets its samples or answers nothing (helper-61,
 * stop 68): a whole curve (regimes[1], w_adv = w, 300 + 300 samples, noise
 * 0.1 % of the pull-off force) with one approach sample in contact moved by
 * 3 and 1e5 pull-off forces is refused MDR_E_MISFIT (the retract's own
 * misfit test, on the approach's samples); before, answered ok, w_adv
 * 0.006 +- 0.049 for 0.05 (and in helper-61's curve, a sample 1e5 pull-off
 * forces off, w/4^4, four quartering steps' value, +- 745 J/m^2). The same
 * curve unmoved is answered, w_adv within 3 of its errors. */
static void test_approach_misfit(void **state)
{
    static const double moves[3] = {0.0, 3.0, 1e5};
    const jkr_par *p = &regimes[1];
    const mdr_contact_f64 c = paraboloid64(p->R);
    int k;
    (void)state;
    for (k = 0; k < 3; k++) {
        const int na = 300, nr = 300;
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        mdr_status st;
        double Fpo = 0.0;
        int i;
        noise_state = 0x6A09E667F3BCC908ull;
        rev_curve(p, p->w, na, nr, 1e-3, zs, Fs);
        for (i = na; i < na + nr; i++) {
            Fpo = Fs[i] < Fpo ? Fs[i] : Fpo;
        }
        Fs[3 * na / 4] += moves[k] * fabs(Fpo);
        mdr_fit_defaults_f64(&o, p->km);
        o.approach = 1;
        st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)(na + nr), work64, 2 * NMAX, &r);
        print_message("approach sample moved by %g pull-off forces: %s (w_adv %.4g +- %.2g)\n", moves[k],
                      mdr_status_str(st), st == MDR_OK ? r.w_adv : 0.0, st == MDR_OK ? r.w_adv_err : 0.0);
        if (k == 0) {
            assert_int_equal(st, MDR_OK);
            assert_true(fabs(r.w_adv - p->w) <= 3 * r.w_adv_err);
        } else {
            assert_int_equal(st, MDR_E_MISFIT);
        }
    }
}

/* status of the f64 and the f32 fit of zs, Fs (n samples) */
static void fit_both(const jkr_par *p, uint32_t n, int approach, mdr_status *st64, mdr_status *st32)
{
    mdr_contact_f64 c = paraboloid64(p->R);
    mdr_contact_f32 c32;
    mdr_fit_opts_f64 o;
    mdr_fit_opts_f32 o32;
    mdr_fit_result_f64 r;
    mdr_fit_result_f32 r32;
    const float pp[3] = {(float)p->R, 0, 0};
    assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
    mdr_fit_defaults_f64(&o, p->km);
    mdr_fit_defaults_f32(&o32, (float)p->km);
    o.approach = o32.approach = (uint8_t)approach;
    curve32(n);
    *st64 = mdr_fit_curve_f64(&c, &o, zs, Fs, n, work64, 2 * NMAX, &r);
    *st32 = mdr_fit_curve_f32(&c32, &o32, zs32, Fs32, n, work32, 2 * NMAX, &r32);
}

/* A curve passed in reversed time order is refused with MDR_E_ORDER, never
 * answered (before: an adhesive approach read backwards, which looks like
 * a retract, answered "ok" with w 16 to 44 x low noise-free; a reversed
 * retract, or an approach alone, refused as MDR_E_FEW). Swept over the
 * regimes with E* x 0.3, 1, 3, w_adv/w = 1, 0.5, 0.25, 300 and 1 000
 * samples, f64 and f32:
 *   - the whole curve reversed (approach and retract; noise 0, 0.1 %, 1 %
 *     of the fold's force): MDR_E_ORDER (the retract's last contact sample
 *     above where its approach first touched; or MDR_E_NOPULLOFF where
 *     the jump-in is below a sample's or the noise's resolution), with and without
 *     opts.approach, or MDR_E_MISFIT, the scan's fallback where the order
 *     test's samples hold a force within their noise bar (mdr_f_scan: 106
 *     of 61 000 reversed fits of a helper's sweep), in at most
 *     REV_MISFIT_FRAC of the fits (measured on the host 0 of 648 fits, f64
 *     and f32; on the M4F's thinned sweep, whose noise draws differ, once 4
 *     of 324: the curve of regime 1, E* x 3, w_adv = w, 300 samples, 0.1 %
 *     noise, f64 and f32, with and without opts.approach; at cfe9cab 0 of
 *     324, and 0 of 156 on its checkerboard, which keeps that curve's
 *     E* and w_adv); the same curve
 *     in time order (w_adv = w) fits
 *     noise-free (f64) and is never MDR_E_ORDER;
 *   - the approach alone, reversed (noise-free): never MDR_OK (MDR_E_MISFIT
 *     where the fit answered before: the pull-off no fold; else the
 *     global misfit, MDR_E_NOPULLOFF, in f32 also MDR_E_DEGENERATE; f32
 *     answers where its z does not resolve the sampling step, 256 eps |z|
 *     beyond it: the DMT contacts sampled every 0.1 pm at a 2 um offset);
 *   - z rising to the last sample (an approach alone in time order, a
 *     retract reversed): MDR_E_ORDER. */
#define REV_MISFIT_FRAC 0.02
static void test_reversed(void **state)
{
    static const double Ef[3] = {0.3, 1.0, 3.0}, wa[3] = {1.0, 0.5, 0.25}, sigs[3] = {0.0, 1e-3, 1e-2};
    static const int sizes[2] = {300, 1000};
    int k, ie, ia, is, s, n_app = 0, n_app_misfit = 0, n_full = 0, n_full_order = 0, n_full_misfit = 0;
    (void)state;
    for (k = 0; k < 3; k++) {
        for (ie = 0; ie < 3; ie++) {
            jkr_par p = regimes[k];
            p.E *= Ef[ie];
#ifdef MDR_TARGET_TEST
            /* the target: every 2nd point of each regime's E* x w_adv/w
             * grid, a checkerboard (each regime still meets every E* factor,
             * every w_adv/w and the time-order fits of w_adv = w; regime 1
             * E* x 3, w_adv = w, once refused MDR_E_MISFIT, among them); the
             * host runs every point */
            for (ia = (k + ie + 1) % 2; ia < 3; ia += 2) {
#else
            for (ia = 0; ia < 3; ia++) {
#endif
                for (s = 0; s < NREV_SIZES; s++) {
                    const int n = sizes[s];
                    mdr_status a, b;
                    for (is = 0; is < 3; is++) {
                        int ap;
                        rev_curve(&p, wa[ia] * p.w, n, n, sigs[is], zs, Fs);
                        if (ia == 0) { /* in time order (no pinned top): f64 answers noise-free;
                                          * never MDR_E_ORDER (noisy: MDR_E_PINNED where the retract
                                          * is straight within its noise; f32 with the DMT contact
                                          * 0.1 pm per sample: MDR_E_DEGENERATE) */
                            fit_both(&p, (uint32_t)(2 * n), 0, &a, &b);
                            if ((is == 0 && a != MDR_OK) || a == MDR_E_ORDER || b == MDR_E_ORDER) {
                                fail_msg("in time order, regime %d, E* x %g, n %d, noise %g: status %d, %d", k,
                                         Ef[ie], n, sigs[is], a, b);
                            }
                        }
                        reverse(zs, 2 * n);
                        reverse(Fs, 2 * n);
                        for (ap = 0; ap < 2; ap++) {
                            fit_both(&p, (uint32_t)(2 * n), ap, &a, &b);
                            n_full += 2;
                            n_full_order += (a == MDR_E_ORDER) + (b == MDR_E_ORDER);
                            n_full_misfit += (a == MDR_E_MISFIT) + (b == MDR_E_MISFIT);
                            /* the approach's jump-in (its "pull-off" read backwards)
                             * may be too small for the sampling or hide in the noise:
                             * MDR_E_NOPULLOFF first; the scan's misfit where the
                             * order test's samples are within their noise bar */
                            if (!(a == MDR_E_ORDER || a == MDR_E_NOPULLOFF || a == MDR_E_MISFIT) ||
                                !(b == MDR_E_ORDER || b == MDR_E_NOPULLOFF || b == MDR_E_MISFIT)) {
                                fail_msg("reversed curve, regime %d, E* x %g, w_adv/w %g, n %d, noise %g, approach "
                                         "%d: status %d, %d",
                                         k, Ef[ie], wa[ia], n, sigs[is], ap, a, b);
                            }
                        }
                    }
                    /* the approach alone, reversed, noise-free */
                    rev_curve(&p, wa[ia] * p.w, n, n, 0.0, zs, Fs);
                    reverse(zs, n);
                    reverse(Fs, n);
                    fit_both(&p, (uint32_t)n, 0, &a, &b);
                    n_app++;
                    n_app_misfit += a == MDR_E_MISFIT;
                    /* f32 where its z does not resolve the step (256 eps |z|, 2 um
                     * offset: the DMT contacts) is not tested for the fold's shape */
                    if (a == MDR_OK || (b == MDR_OK && 256 * 5.96e-8 * fabs(zs[0]) < (zs[0] - zs[n - 1]) / (n - 1))) {
                        fail_msg("reversed approach, regime %d, E* x %g, w_adv/w %g, n %d: status %d, %d", k,
                                 Ef[ie], wa[ia], n, a, b);
                    }
                    /* z rising to the end: the approach alone in time order, or
                     * the retract reversed */
                    rev_curve(&p, wa[ia] * p.w, n, n, 0.0, zs, Fs);
                    fit_both(&p, (uint32_t)n, 0, &a, &b);
                    assert_int_equal(a, MDR_E_ORDER);
                    assert_int_equal(b, MDR_E_ORDER);
                    reverse(zs + n, n);
                    reverse(Fs + n, n);
                    memmove(zs, zs + n, (size_t)n * sizeof *zs);
                    memmove(Fs, Fs + n, (size_t)n * sizeof *Fs);
                    fit_both(&p, (uint32_t)n, 0, &a, &b);
                    assert_int_equal(a, MDR_E_ORDER);
                    assert_int_equal(b, MDR_E_ORDER);
                }
            }
        }
    }
    print_message("reversed: whole curves %d fits (f64 and f32), %d MDR_E_ORDER, %d MDR_E_MISFIT (the others "
                  "MDR_E_NOPULLOFF); approaches %d, %d MDR_E_MISFIT in f64 (the others MDR_E_NOPULLOFF)\n",
                  n_full, n_full_order, n_full_misfit, n_app, n_app_misfit);
    if (n_full_misfit > (int)(REV_MISFIT_FRAC * n_full)) {
        fail_msg("reversed whole curves: %d of %d fits MDR_E_MISFIT, not MDR_E_ORDER (at most %.0f %%)", n_full_misfit,
                 n_full, 100.0 * REV_MISFIT_FRAC);
    }
}

/* ---- time order: what the order checks see in genuine curves ------------- */

/* A curve in time order (rev_curve noise-free: the library's forward model,
 * paraboloid, w_adv = w, n approach and n retract samples), its approach's
 * baseline `step` of the pull-off force above the retract's (hydrodynamic
 * drag, a drift between the two), Gaussian noise of sig_rel of the
 * pull-off force, AR(1) with correlation rho between successive samples
 * (0: white; a low-passed deflection signal). Returns the pull-off force
 * (the smallest noise-free sample's). */
static double order_curve(const jkr_par *p, int n, double step, double sig_rel, double rho, double *z, double *F)
{
    double Fpo = 0.0, e;
    int i;
    rev_curve(p, p->w, n, n, 0.0, z, F);
    for (i = 0; i < 2 * n; i++) {
        Fpo = F[i] < Fpo ? F[i] : Fpo;
    }
    e = gauss();
    for (i = 0; i < 2 * n; i++) {
        F[i] += (i < n ? step : 0.0) * fabs(Fpo) + sig_rel * fabs(Fpo) * e;
        e = rho * e + sqrt(1.0 - rho * rho) * gauss();
    }
    return Fpo;
}

/* Genuine curves in time order are never refused with MDR_E_ORDER. The
 * first-touch check (mdr_f_scan) takes the approach's first two samples
 * in a row beyond thr (6 noise widths) of the retract's baseline for its
 * first touch, and refuses where that lies at or below the retract's
 * first free sample; where the approach's baseline differs from the
 * retract's by a few noise widths (below thr: F[0] passes), the noise
 * alone puts two samples in a row beyond thr long before the contact.
 * The commit's own example (regimes[1]: R 20 nm, E* 1 GPa, w = w_adv =
 * 0.05, k_m 0.2 N/m), NORDER_PTS + NORDER_PTS samples, noise ORDER_SIG =
 * 0.1 % of the pull-off force, the approach's baseline ORDER_STEP = 5
 * noise widths above the retract's; NORDER noise seeds. Measured before a
 * fix: 15 of 20 MDR_E_ORDER (f64 or f32), the other 5 answered within
 * 1.66 errors of the truth; the 20 retracts alone all answered. */
static void test_order_baseline_step(void **state)
{
    static const double steps[2] = {ORDER_STEP, ORDER_STEP_BIG};
    const jkr_par *p = &regimes[1];
    mdr_contact_f64 c = paraboloid64(p->R);
    int s, l;
    (void)state;
    noise_state = 0x9e3779b97f4a7c15ull; /* its own noise, whatever ran before */
    for (l = 0; l < 2; l++) {
        int n_order = 0, n_ok = 0, n_ret = 0;
        double worst_err = 0.0;
        for (s = 0; s < NORDER; s++) {
            mdr_status a, b;
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            order_curve(p, NORDER_PTS, steps[l] * ORDER_SIG, ORDER_SIG, 0.0, zs, Fs);
            fit_both(p, 2u * NORDER_PTS, 0, &a, &b);
            n_order += a == MDR_E_ORDER || b == MDR_E_ORDER;
            mdr_fit_defaults_f64(&o, p->km);
            if (mdr_fit_curve_f64(&c, &o, zs, Fs, 2u * NORDER_PTS, work64, 2 * NMAX, &r) == MDR_OK) {
                double e1 = nerr(r.E, p->E, r.E_err), e2 = nerr(r.w, p->w, r.w_err);
                n_ok++;
                worst_err = e1 > worst_err ? e1 : worst_err;
                worst_err = e2 > worst_err ? e2 : worst_err;
            }
            n_ret += mdr_fit_curve_f64(&c, &o, zs + NORDER_PTS, Fs + NORDER_PTS, NORDER_PTS, work64, 2 * NMAX,
                                       &r) == MDR_OK;
        }
        print_message("baseline step %.0f noise widths: %d of %d curves in time order MDR_E_ORDER; %d answered "
                      "(f64), within %.2f errors; their retracts alone %d answered\n",
                      steps[l], n_order, NORDER, n_ok, worst_err, n_ret);
        if (n_order) {
            fail_msg("%d of %d genuine curves (in time order, approach baseline %.0f noise widths above the "
                     "retract's) refused with MDR_E_ORDER",
                     n_order, NORDER, steps[l]);
        }
    }
}

/* A glitch recorded over two samples (a spike through the deflection
 * signal's filter) on the approach's free part, far from the contact, of
 * a noise-free curve in time order (each regime, 300 + 300 samples, the
 * glitch 10 % of the pull-off force at samples 20 and 21): not MDR_E_ORDER
 * (the first-touch check took the glitch for the approach's first touch;
 * measured before a fix: MDR_E_ORDER in every regime, f64 and f32; the
 * retract is the glitch-free curve's, which the fit answers). */
static void test_order_glitch(void **state)
{
    mdr_status st[3][2];
    int k, bad = 0;
    (void)state;
    for (k = 0; k < 3; k++) {
        double Fpo = order_curve(&regimes[k], 300, 0.0, 0.0, 0.0, zs, Fs);
        Fs[20] += 0.1 * fabs(Fpo);
        Fs[21] += 0.1 * fabs(Fpo);
        fit_both(&regimes[k], 600u, 0, &st[k][0], &st[k][1]);
        bad += st[k][0] == MDR_E_ORDER || st[k][1] == MDR_E_ORDER;
    }
    print_message("two-sample glitch on the approach: status (f64, f32) %d, %d; %d, %d; %d, %d\n", st[0][0], st[0][1],
                  st[1][0], st[1][1], st[2][0], st[2][1]);
    if (bad) {
        fail_msg("%d of 3 curves in time order with a two-sample glitch on the approach's free part refused with "
                 "MDR_E_ORDER",
                 bad);
    }
}

/* Correlated noise (AR(1), ORDER_RHO = 0.9 between successive samples, of
 * 1 % of the pull-off force: a deflection signal sampled faster than its
 * bandwidth) on genuine curves in time order (regimes[0], NORDER_PTS +
 * NORDER_PTS samples, NORDER seeds): never MDR_E_ORDER. The noise width
 * from successive differences is then sqrt(1 - rho) = 0.32 of the true
 * one, thr 1.9 true widths, and the approach's wander crosses it long
 * before the contact. The fit may refuse such curves (its error model is
 * white noise: MDR_E_MISFIT for each of the 20 retracts alone), but not
 * as curves in reversed time order. Measured before a fix: 18 of 20
 * MDR_E_ORDER. */
static void test_order_correlated_noise(void **state)
{
    const jkr_par *p = &regimes[0];
    mdr_contact_f64 c = paraboloid64(p->R);
    mdr_fit_opts_f64 o;
    mdr_fit_result_f64 r;
    int s, n_order = 0, n_misfit = 0, n_ok = 0;
    double worst = 0.0;
    (void)state;
    noise_state = 0x2545f4914f6cdd1dull;
    for (s = 0; s < NORDER; s++) {
        mdr_status a, b;
        order_curve(p, NORDER_PTS, 0.0, 1e-2, ORDER_RHO, zs, Fs);
        fit_both(p, 2u * NORDER_PTS, 0, &a, &b);
        n_order += a == MDR_E_ORDER || b == MDR_E_ORDER;
        mdr_fit_defaults_f64(&o, p->km);
        if (mdr_fit_curve_f64(&c, &o, zs, Fs, 2u * NORDER_PTS, work64, 2 * NMAX, &r) == MDR_OK) {
            const double e1 = nerr(r.E, p->E, r.E_err), e2 = nerr(r.w, p->w, r.w_err);
            n_ok++;
            worst = e1 > worst ? e1 : worst;
            worst = e2 > worst ? e2 : worst;
        }
        n_misfit += mdr_fit_curve_f64(&c, &o, zs + NORDER_PTS, Fs + NORDER_PTS, NORDER_PTS, work64, 2 * NMAX, &r) ==
                    MDR_E_MISFIT;
    }
    print_message("correlated noise: %d of %d curves in time order MDR_E_ORDER, %d answered (f64; within %.2f "
                  "errors); their retracts alone %d MDR_E_MISFIT\n",
                  n_order, NORDER, n_ok, worst, n_misfit);
    if (n_order) {
        fail_msg("%d of %d genuine curves (in time order, AR(1) noise rho %.1f) refused with MDR_E_ORDER", n_order,
                 NORDER, ORDER_RHO);
    }
    /* the model knows nothing of the correlation: refused (a misfit), or
     * within 5 reported errors (test_noise's rule) */
    if (!(worst <= 5.0)) {
        fail_msg("correlated noise: a whole curve answered %.1f reported errors from the truth", worst);
    }
}

/* Coarse sampling: a step as large as the fold's distance below first
 * touch. In time order the approach is free a step below the retract's
 * last contact sample, but not necessarily a step above it (its jump-in
 * may lie within that step): genuine curves of 8 to 40 samples a branch
 * (the three regimes, E* x 0.3, 1, 3, w_adv/w = 1, 0.5, 0.25, noise-free or
 * ORDER_SIG with the retract ending 3, 4 or 6 samples after its
 * pull-off, f64 and f32) are never MDR_E_ORDER. Measured: none of 1 352
 * fits. The check before this test compared the approach's force with
 * the noise as 3 free samples gave it (0.09 of the truth): a curve of 12
 * samples a branch whose last contact sample is noise (regime 1, E* x
 * 0.3, w_adv = w/2; the last case, its noise as drawn then) was told
 * MDR_E_ORDER. */
static void test_order_coarse(void **state)
{
    static const int sizes[5] = {8, 12, 16, 24, 40}, tails[3] = {3, 4, 6};
    static const double Es[3] = {0.3, 1.0, 3.0}, ratios[3] = {1.0, 0.5, 0.25};
    int r, e, k, s, t, i, n_order = 0, n_all = 0, n_ok = 0;
    (void)state;
    noise_state = 0xbb67ae8584caa73bull;
    for (r = 0; r < 3; r++) {
        for (e = ORDER_E_FIRST; e < 3; e += ORDER_E_STRIDE) {
            for (k = 0; k < 3; k++) {
                for (s = 0; s < 5; s++) {
#ifdef MDR_TARGET_TEST
                    /* the target: every 3rd point of each (regime, w_adv/w)'s
                     * size x tail grid, its diagonals shifted by regime and
                     * ratio (each still meets every size and every one of the
                     * five tails); the host runs every point */
                    for (t = -2 + (r + k + s) % 3; t < 3; t += 3) {
#else
                    for (t = -2; t < 3; t++) { /* noise-free; noisy; noisy, the retract ending tails[t] after
                                                * its pull-off */
#endif
                        jkr_par p = regimes[r];
                        mdr_status a, b;
                        int last, n = 2 * sizes[s];
                        double Fpo = 0.0;
                        p.E *= Es[e];
                        (void)rev_curve(&p, ratios[k] * p.w, sizes[s], sizes[s], t == -1 ? ORDER_SIG : 0.0, zs, Fs);
                        if (t >= 0) {
                            for (last = n - 1; last > 0 && Fs[last] == 0.0; last--) {
                            }
                            n = last + 1 + tails[t] < n ? last + 1 + tails[t] : n;
                            for (i = 0; i <= last; i++) {
                                Fpo = Fs[i] < Fpo ? Fs[i] : Fpo;
                            }
                            for (i = 0; i < n; i++) {
                                Fs[i] += ORDER_SIG * fabs(Fpo) * gauss();
                            }
                        }
                        fit_both(&p, (uint32_t)n, 0, &a, &b);
                        n_all += 2;
                        n_ok += (a == MDR_OK) + (b == MDR_OK);
                        if (a == MDR_E_ORDER || b == MDR_E_ORDER) {
                            n_order += (a == MDR_E_ORDER) + (b == MDR_E_ORDER);
                            print_message("  MDR_E_ORDER: regime %d, E* x %g, w_adv/w %g, %d samples a branch, "
                                          "tail %d (0: noise-free, 1: noisy, full tail) (f64 %d, f32 %d)\n",
                                          r, Es[e], ratios[k], sizes[s], t < 0 ? -1 - t : tails[t], a, b);
                        }
                    }
                }
            }
        }
    }
    {
        /* the curve that was told MDR_E_ORDER (noise state as it was
         * drawn then): its last contact sample is noise, 3 free samples */
        jkr_par p = regimes[1];
        mdr_status a, b;
        p.E *= 0.3;
        noise_state = 0x20f221d61efea1f4ull;
        (void)rev_curve(&p, 0.5 * p.w, 12, 12, ORDER_SIG, zs, Fs);
        fit_both(&p, 24u, 0, &a, &b);
        n_all += 2;
        n_ok += (a == MDR_OK) + (b == MDR_OK);
        n_order += (a == MDR_E_ORDER) + (b == MDR_E_ORDER);
    }
    print_message("coarse sampling (8 to 40 samples a branch): %d of %d fits of curves in time order MDR_E_ORDER, "
                  "%d ok\n", n_order, n_all, n_ok);
    assert_int_equal(n_order, 0);
}

/* White noise alone, a retract cut short after its pull-off (its last
 * ORDER_TAIL samples free, as a recording stopped soon after the jump):
 * the noise width comes from those few free samples, a chance low estimate
 * puts thr within 2 true widths, and two approach samples in a row beyond
 * it long before the contact are then likely. Curves in time order
 * (regimes[1], w_adv = w, NORDER_PTS approach samples, the retract's
 * NORDER_PTS to its last contact sample, noise ORDER_SIG = 0.1 % of the
 * pull-off force), NORDER seeds x 3 .. ORDER_TAIL_MAX = 8 free samples:
 * never MDR_E_ORDER. Measured before a fix: 2 of 120 MDR_E_ORDER in f64
 * and f32, both with 3 free samples (2 of those 20 seeds); 117 answered. */
static void test_order_short_tail(void **state)
{
    const jkr_par *p = &regimes[1];
    int s, t, i, last, n_order = 0, n_all = 0, n_ok = 0;
    (void)state;
    noise_state = 0x3c6ef372fe94f82bull;
    for (t = 3; t <= ORDER_TAIL_MAX; t++) {
        for (s = 0; s < NORDER; s++) {
            mdr_status a, b;
            double Fpo = 0.0;
            rev_curve(p, p->w, NORDER_PTS, NORDER_PTS, 0.0, zs, Fs);
            for (last = 2 * NORDER_PTS - 1; Fs[last] == 0.0; last--) {
            }
            for (i = 0; i <= last; i++) {
                Fpo = Fs[i] < Fpo ? Fs[i] : Fpo;
            }
            for (i = 0; i <= last + t; i++) {
                Fs[i] += ORDER_SIG * fabs(Fpo) * gauss();
            }
            fit_both(p, (uint32_t)(last + 1 + t), 0, &a, &b);
            n_all++;
            n_ok += a == MDR_OK;
            if (a == MDR_E_ORDER || b == MDR_E_ORDER) {
                n_order++;
                print_message("  MDR_E_ORDER: %d free samples, seed %d (f64 %d, f32 %d)\n", t, s, a, b);
            }
        }
    }
    print_message("short retract tail (3 to %d free samples): %d of %d curves in time order MDR_E_ORDER, %d ok (f64)\n",
                  ORDER_TAIL_MAX, n_order, n_all, n_ok);
    if (n_order) {
        fail_msg("%d of %d genuine curves (white noise, the retract ending 3 to %d samples after its pull-off) refused "
                 "with MDR_E_ORDER",
                 n_order, n_all, ORDER_TAIL_MAX);
    }
}

/* A whole curve in reversed time order is never answered, whatever the
 * approach's baseline: the commit's own example (regimes[1], w_adv = w,
 * 300 + 300 samples, noise ORDER_SIG = 0.1 % of the pull-off force), the
 * approach's baseline ORDER_DRAG = 1 % of the pull-off force (10 noise
 * widths) above the retract's (hydrodynamic drag), reversed; NORDER seeds,
 * with and without opts.approach, f64 and f32: never MDR_OK. The
 * first-touch check is skipped where the first sample is beyond thr of
 * the baseline, and the fold-end test does not see the reversed end in
 * this noise. Measured before a fix: 64 of the 80 fits answered ok, w
 * 0.069 to 0.071 x the truth, 8.9 to 10.9 of its reported errors (such
 * curves in time order are answered: closed-form JKR curves with this
 * step and noise, 10 seeds, within 1.4 errors). */
static void test_reversed_baseline_step(void **state)
{
    const jkr_par *p = &regimes[1];
    mdr_contact_f64 c = paraboloid64(p->R);
    int s, ap, n_ok = 0, n = 300;
    double w_lo = 1.0, w_hi = 0.0, e_lo = 1e300, e_hi = 0.0;
    (void)state;
    noise_state = 0x6a09e667f3bcc909ull;
    for (s = 0; s < NORDER; s++) {
        order_curve(p, n, ORDER_DRAG, ORDER_SIG, 0.0, zs, Fs);
        reverse(zs, 2 * n);
        reverse(Fs, 2 * n);
        for (ap = 0; ap < 2; ap++) {
            mdr_status a, b;
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            fit_both(p, (uint32_t)(2 * n), ap, &a, &b);
            n_ok += (a == MDR_OK) + (b == MDR_OK);
            mdr_fit_defaults_f64(&o, p->km);
            o.approach = (uint8_t)ap;
            if (mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)(2 * n), work64, 2 * NMAX, &r) == MDR_OK) {
                double q = r.w / p->w, e = nerr(r.w, p->w, r.w_err);
                w_lo = q < w_lo ? q : w_lo;
                w_hi = q > w_hi ? q : w_hi;
                e_lo = e < e_lo ? e : e_lo;
                e_hi = e > e_hi ? e : e_hi;
            }
        }
    }
    if (w_hi > 0.0) {
        print_message("reversed, the approach's baseline %.2g of the pull-off force off: %d of %d fits ok "
                      "(f64: w %.3g to %.3g x the truth, %.1f to %.1f of its errors)\n",
                      ORDER_DRAG, n_ok, 4 * NORDER, w_lo, w_hi, e_lo, e_hi);
    } else {
        print_message("reversed, the approach's baseline %.2g of the pull-off force off: %d of %d fits ok\n",
                      ORDER_DRAG, n_ok, 4 * NORDER);
    }
    if (n_ok) {
        fail_msg("%d of %d fits of whole curves in reversed time order (the approach's baseline %.2g of the pull-off "
                 "force off the retract's) answered ok, w %.3g to %.3g x the truth",
                 n_ok, 4 * NORDER, ORDER_DRAG, w_lo, w_hi);
    }
}

/* f32 with an instrument's piezo offset on a pinned top: w_adv = 0 (the
 * retract pinned from a top at 2.5 a_fold: pinned_curve), 100 samples,
 * offsets z0 = 0, 0.5, 1, 2, 5 um, noise F32PIN_SIG = 0.1 % of the
 * pull-off force, NF32PIN seeds; the transition regime (regimes[1]) and the
 * DMT regime's contact stiffened (regimes[2], E* x 3: 300 GPa; samples
 * 2.4 pm apart, f32 keeps z to 0.12 pm at 2 um, 0.23 pm at 5 um): every
 * f32 answer within 5 reported errors of the truth (test_noise's rule),
 * as the f64 fits of the same samples are, and at least half of each
 * row's seeds answered (a refusal is no wrong answer, but a test that
 * passes on refusals alone tests nothing). Measured: every fit answered,
 * f32 worst 3.7 errors (f64 on the same samples 3.8; NF32PIN = 2: 2.9,
 * f64 2.8). Before the fix (mdr_f_line: z's
 * rounding, through the 40 N/m lever up to 10 noise widths, broke the
 * pinned top's straight start at its first sample, the fit took the
 * pinned samples in and their misfit hid the pinned top) f32 answered the
 * DMT curves at 1, 2, 5 um 21.3, 24.1, 21.4 errors off (E* 1.107 x the
 * truth at 2 um, n_pinned 0), within 1.2 at 0 and 0.5 um. */
static void test_f32_pinned_offset(void **state)
{
    static const double z0s[5] = {0.0, 0.5e-6, 1e-6, 2e-6, 5e-6};
    double worst64 = 0.0, worst32 = 0.0;
    int g, k, s, i, n = 100, npin, n32 = 0, nall = 0;
    (void)state;
    noise_state = 0xbb67ae8584caa73bull;
    for (g = 1; g <= 2; g++) {
        jkr_par p = regimes[g];
        mdr_contact_f64 c = paraboloid64(p.R);
        mdr_contact_f32 c32;
        const float pp[3] = {(float)p.R, 0, 0};
        if (g == 2) {
            p.E *= 3.0;
        }
        assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
        for (k = 0; k < 5; k++) {
            int row32 = 0;
            for (s = 0; s < NF32PIN; s++) {
                mdr_fit_opts_f64 o;
                mdr_fit_opts_f32 o32;
                mdr_fit_result_f64 r;
                mdr_fit_result_f32 r32;
                double Fpo, e;
                pinned_curve(&p, 0.0, 2.5 * jkr_fold(&p), z0s[k], 0.0, n, zs, Fs, &npin, &Fpo);
                for (i = 0; i < n; i++) {
                    Fs[i] += F32PIN_SIG * fabs(Fpo) * gauss();
                    zs32[i] = (float)zs[i];
                    Fs32[i] = (float)Fs[i];
                }
                mdr_fit_defaults_f64(&o, p.km);
                mdr_fit_defaults_f32(&o32, (float)p.km);
                if (mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r) == MDR_OK) {
                    e = fmax(nerr(r.E, p.E, r.E_err), nerr(r.w, p.w, r.w_err));
                    worst64 = e > worst64 ? e : worst64;
                }
                nall++;
                if (mdr_fit_curve_f32(&c32, &o32, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r32) == MDR_OK) {
                    e = fmax(nerr(r32.E, p.E, r32.E_err), nerr(r32.w, p.w, r32.w_err));
                    worst32 = e > worst32 ? e : worst32;
                    n32++;
                    row32++;
                    if (e > 5.0) {
                        fail_msg("f32, pinned top, regime %d%s, z0 = %.2g um, noise %.2g: an answer %.1f of its "
                                 "reported errors from the truth (E* %.4g x, w %.4g x, n_pinned %u)",
                                 g, g == 2 ? " (E* x 3)" : "", z0s[k] * 1e6, F32PIN_SIG, e, r32.E / p.E, r32.w / p.w,
                                 (unsigned)r32.n_pinned);
                    }
                }
            }
            if (2 * row32 < NF32PIN) {
                fail_msg("f32, pinned top, regime %d, z0 = %.2g um: %d of %d fits answered", g, z0s[k] * 1e6, row32,
                         NF32PIN);
            }
        }
    }
    print_message("f32 pinned top at offsets 0 to 5 um: %d of %d answered, worst %.1f errors (f64: %.1f)\n", n32, nall,
                  worst32, worst64);
}

/* f64, noise-free pinned tops at piezo offsets (test_pinned_offset_clean):
 * z = z' + z0 rounds each sample to half an ulp of z0's size, a sawtooth
 * along the uniform steps of z' whose wrap moved a sample 2 ulps times the
 * line's slope off the straight start (helper-80, stop 76: its closed-form
 * curve at 5 um answered E* 1.39 x, w 21 errors off, n_pinned 0, exact at
 * 0, 2, 10 and 15 um). The three regimes, w_adv = 0 and w/2, the top at
 * 2.5 fold radii, PINOFF_N samples, z0 from 0 to 20 um in PINOFF_STEP: every
 * fit answers E* and w within PINOFF_REL of the truth with every pinned
 * sample found (n_pinned as the curve's) */
static void test_pinned_offset_clean(void **state)
{
    static const double ratios[2] = {0.0, 0.5};
    int g, k, nz, npin, nfit = 0;
    double worst_rel = 0.0;
    (void)state;
    for (g = 0; g < 3; g++) {
        const jkr_par *p = &regimes[g];
        mdr_contact_f64 c = paraboloid64(p->R);
        for (k = 0; k < 2; k++) {
            for (nz = 0; nz * PINOFF_STEP <= 20e-6 + 1e-12; nz++) {
                const double z0 = nz * PINOFF_STEP;
                mdr_fit_opts_f64 o;
                mdr_fit_result_f64 r;
                double Fpo, e;
                mdr_status st;
                pinned_curve(p, ratios[k] * p->w, 2.5 * jkr_fold(p), z0, 0.0, PINOFF_N, zs, Fs, &npin, &Fpo);
                mdr_fit_defaults_f64(&o, p->km);
                st = mdr_fit_curve_f64(&c, &o, zs, Fs, PINOFF_N, work64, 2 * NMAX, &r);
                if (st != MDR_OK) {
                    fail_msg("regime %d, w_adv %.1f w, z0 = %.4g um: %s (noise-free, %d pinned)", g, ratios[k],
                             z0 * 1e6, mdr_status_str(st), npin);
                }
                e = fmax(fabs(r.E / p->E - 1.0), fabs(r.w / p->w - 1.0));
                if (e > PINOFF_REL || (int)r.n_pinned != npin) {
                    fail_msg("regime %d, w_adv %.1f w, z0 = %.4g um: E* %.12g x, w %.12g x, n_pinned %u of %d", g,
                             ratios[k], z0 * 1e6, r.E / p->E, r.w / p->w, (unsigned)r.n_pinned, npin);
                }
                worst_rel = e > worst_rel ? e : worst_rel;
                nfit++;
            }
        }
    }
    print_message("noise-free pinned tops at offsets 0 to 20 um: %d fits, worst relative error %.2g\n", nfit,
                  worst_rel);
}

#ifndef MDR_TARGET_TEST
/* How far an answer lies from the truth p in its reported errors: the
 * larger of E*'s and w's (the written-data tests' PULL measure) */
static double fit_pull(const mdr_fit_result_f64 *r, const jkr_par *p)
{
    return fmax(fabs(r->E - p->E) / r->E_err, fabs(r->w - p->w) / r->w_err);
}

/* Noise-free curves as a file keeps them (helper-80's defect (1), stop 76;
 * fixed at stop 78): z and F written with d significant digits and read
 * back, or F on an ADC's grid. The rounding ended the pinned top's
 * straight start (mdr_f_line), whose tolerance was the arithmetic's
 * rounding alone; the fit took the pinned top in (helper-80's curve: E*
 * 1.21 x, w 6.2 errors off, n_pinned 0). The rule: at the top of the
 * file. */
static void test_written_digits(void **state)
{
    enum { n = 160 };
    static const int digits[5] = {6, 7, 9, 12, 15};
    static const double grids[3] = {1e-6, 1e-5, 1e-4};
    static const double ratios[2] = {0.0, 0.5};
    int g, k, v, npin, nfit = 0, nok = 0;
    double worst_dev = 0.0, worst_rel = 0.0;
    (void)state;
    for (g = 0; g < 3; g++) {
        const jkr_par *p = &regimes[g];
        mdr_contact_f64 c = paraboloid64(p->R);
        for (k = 0; k < 2; k++) {
            for (v = 0; v < 11; v++) {
                mdr_fit_opts_f64 o;
                mdr_fit_result_f64 r;
                double Fpo, e, dev;
                mdr_status st;
                int i;
                pinned_curve(p, ratios[k] * p->w, 2.5 * jkr_fold(p), 2e-6, 0.0, n, zs, Fs, &npin, &Fpo);
                for (i = 0; i < n; i++) {
                    if (v < 5 || v >= 8) { /* (from 8: F alone, z exact) */
                        const int dg = v < 5 ? digits[v] : digits[2 * (v - 8)];
                        char buf[40];
                        if (v < 5) {
                            snprintf(buf, sizeof buf, "%.*e", dg - 1, zs[i]);
                            zs[i] = strtod(buf, NULL);
                        }
                        snprintf(buf, sizeof buf, "%.*e", dg - 1, Fs[i]);
                        Fs[i] = strtod(buf, NULL);
                    } else {
                        const double q = grids[v - 5] * fabs(Fpo);
                        Fs[i] = nearbyint(Fs[i] / q) * q;
                    }
                }
                mdr_fit_defaults_f64(&o, p->km);
                st = mdr_fit_curve_f64(&c, &o, zs, Fs, n, work64, 2 * NMAX, &r);
                nfit++;
                if (st != MDR_OK) {
                    if (!(st == MDR_E_MISFIT || st == MDR_E_DEGENERATE)) {
                        fail_msg("regime %d, w_adv %.1f w, case %d: %s", g, ratios[k], v, mdr_status_str(st));
                    }
                    continue;
                }
                nok++;
                e = fmax(fabs(r.E / p->E - 1.0), fabs(r.w / p->w - 1.0));
                dev = fit_pull(&r, p);
                if (!(dev <= DIGITS_PULL) || abs((int)r.n_pinned - npin) > 1) {
                    fail_msg("regime %d, w_adv %.1f w, case %d: E* %.9f x, w %.9f x, %.2f errors, n_pinned %u of %d", g,
                             ratios[k], v, r.E / p->E, r.w / p->w, dev, (unsigned)r.n_pinned, npin);
                }
                worst_rel = e > worst_rel ? e : worst_rel;
                worst_dev = dev > worst_dev ? dev : worst_dev;
            }
        }
    }
    print_message("written digits and ADC grids: %d of %d answered, worst %.2f errors, %.2g relative\n", nok, nfit,
                  worst_dev, worst_rel);
    assert_true(nok >= DIGITS_MIN_OK);
}
#endif

#ifndef MDR_TARGET_TEST
/* Noise-free curves whose z lie on a piezo's decimal grid with irregular
 * steps (each position moved down to a whole unit 0, 1 or 2 digits below
 * the mean step's leading one, so the steps differ by a unit; F computed
 * at them), which mdr_f_written took for a file's rounding of z before
 * mdr_f_zexact (stop 79): the straight start took in the receding branch's
 * first samples where a stiff contact meets a soft lever (a sweep of such
 * curves: E* up to 1.6 x at up to 32 errors, n_pinned 0, status ok). Three
 * stiff contacts, w_adv = w/4 and w/2, piezo offsets 1.3 to 9.1 um: every
 * curve answered within PINOFF_REL of the truth with n_pinned within 1 of
 * the curve's; and the same positions as a file's rounding of z: the
 * tolerances at the top of the file. */
/* test_written_irregular's curve of n samples, fitted: pinned_curve's
 * positions moved down to whole units `down` digits below the mean step's
 * leading one, F at them (rounded false) or at the positions before */
static mdr_status irregular_fit(const jkr_par *p, double wadv, double z0, int n, int down, bool rounded, double drift,
                                int *npin, mdr_fit_result_f64 *r)
{
    const mdr_contact_f64 c = paraboloid64(p->R);
    mdr_fit_opts_f64 fo;
    double Fpo;
    pinned_curve(p, wadv, 2.5 * jkr_fold(p), z0, 0.0, n, zs, Fs, npin, &Fpo);
    curve_ue = (int)floor(log10((zs[0] - zs[n - 1]) / (n - 1))) - down;
    curve_rounded = rounded;
    curve_drift = drift;
    pinned_curve(p, wadv, 2.5 * jkr_fold(p), z0, 0.0, n, zs, Fs, npin, &Fpo);
    curve_ue = 0;
    curve_rounded = false;
    curve_drift = 0.0;
    mdr_fit_defaults_f64(&fo, p->km);
    return mdr_fit_curve_f64(&c, &fo, zs, Fs, (uint32_t)n, work64, 2 * NMAX, r);
}

/* test_written_irregular's and test_written_drift's curves: three stiff
 * contacts through soft levers, w_adv ratios, piezo offsets; case i:
 * contact g, w_adv ratios[k], unit u digits down, offset o */
enum { IRR_NCASE = 3 * 2 * 3 * 3 };
static const double ratios[2] = {0.25, 0.5}, offs[3] = {1.3e-6, 4.7e-6, 9.1e-6};
static const jkr_par stiff[3] = {
    {1.24e-7, 9.5e9, 0.041, 0.27},
    {7.5e-8, 1.42e10, 0.040, 0.37},
    {3.2e-8, 1.34e10, 0.076, 0.22},
};
#define IRR_CASE const int g = i / 18, k = i / 9 % 2, u = i / 3 % 3, o = i % 3

static void test_written_irregular(void **state)
{
    enum { n = 160, nr = 400, ncase = IRR_NCASE };
    int i, npin, nfit = 0, nbad = 0;
    double worst = 0.0;
    (void)state;
    for (i = 0; i < ncase; i++) {
        IRR_CASE;
        const jkr_par *p = &stiff[g];
        mdr_fit_result_f64 r;
        const mdr_status st = irregular_fit(p, ratios[k] * p->w, offs[o], n, u, false, 0.0, &npin, &r);
        double e;
        nfit++;
        if (st != MDR_OK) {
            print_error("contact %d, w_adv %.2f w, unit %d, z0 %g: %s\n", g, ratios[k], u, offs[o], mdr_status_str(st));
            nbad++;
            continue;
        }
        e = fmax(fabs(r.E / p->E - 1.0), fabs(r.w / p->w - 1.0));
        if (!(e <= PINOFF_REL) || abs((int)r.n_pinned - npin) > 1) {
            print_error("contact %d, w_adv %.2f w, unit %d, z0 %g: E* %.9f x, w %.9f x, n_pinned %u of %d\n", g,
                        ratios[k], u, offs[o], r.E / p->E, r.w / p->w, (unsigned)r.n_pinned, npin);
            nbad++;
        }
        worst = e > worst ? e : worst;
    }
    print_message("irregular decimal z: %d of %d within %.0e with their pinned tops, worst %.2g relative\n",
                  nfit - nbad, nfit, PINOFF_REL, worst);
    assert_int_equal(nbad, 0);
    /* nr samples at positions rounded the same (F at the positions before:
     * a file's rounding, which mdr_f_zexact must not take for exact z):
     * answered within DIGITS_PULL errors (the pinned top's end within the
     * rounding: n_pinned a few samples off) or refused (measured: 18 of 54
     * answered, worst 1.63 errors (1.92 before stop 80); with the cubic's tolerance 8 times
     * wider, rounded z taken as exact, 6 of 18 beyond 5 errors) */
    nfit = nbad = 0;
    worst = 0.0;
    for (i = 0; i < ncase; i++) {
        IRR_CASE;
        const jkr_par *p = &stiff[g];
        mdr_fit_result_f64 r;
        double dev;
        if (irregular_fit(p, ratios[k] * p->w, offs[o], nr, u, true, 0.0, &npin, &r) != MDR_OK) {
            continue; /* (a refusal names its reason) */
        }
        nfit++;
        dev = fit_pull(&r, p);
        if (!(dev <= DIGITS_PULL)) {
            print_error("rounded: contact %d, w_adv %.2f w, unit %d, z0 %g: %.2f errors, n_pinned %u of %d\n", g,
                        ratios[k], u, offs[o], dev, (unsigned)r.n_pinned, npin);
            nbad++;
        }
        worst = dev > worst ? dev : worst;
    }
    print_message("rounded decimal z: %d of %d answered within %.0f errors, worst %.2f\n", nfit - nbad, nfit,
                  DIGITS_PULL, worst);
    assert_int_equal(nbad, 0);
}

/* A file's rounding of positions whose errors drift linearly (helper-83,
 * stop 79): test_written_irregular's uneven whole-unit grids written
 * exactly, F at them scaled about the bottom by DRIFT_LO and DRIFT_HI units over the
 * span (a grid scaled by a calibration, or a progression near a whole
 * number of units, rounded; where the errors do not wrap, the z written is
 * the true one scaled and shifted within a unit, and F is smooth in it).
 * No rule on the data tells such z from exact: every answer within
 * DIGITS_PULL reported errors (z's written unit in them: mdr_f_written's
 * ez), at least DRIFT_MIN_OK of the 108 answered, the others refused
 * (measured at the top of the file) */
static void test_written_drift(void **state)
{
    enum { n = 160, ncase = IRR_NCASE };
    int i, c, npin, nfit = 0, nbad = 0;
    double worst = 0.0;
    (void)state;
    for (c = 0; c < 2 * ncase; c++) {
        i = c / 2;
        {
            IRR_CASE;
            const jkr_par *p = &stiff[g];
            const double drift = c % 2 == 0 ? DRIFT_LO : DRIFT_HI;
            mdr_fit_result_f64 r;
            double dev;
            if (irregular_fit(p, ratios[k] * p->w, offs[o], n, u, false, drift, &npin, &r) != MDR_OK) {
                continue; /* (a refusal names its reason) */
            }
            nfit++;
            dev = fit_pull(&r, p);
            if (!(dev <= DIGITS_PULL)) {
                print_error("drift %.2f units: contact %d, w_adv %.2f w, unit %d, z0 %g: E* %.5f x, w %.5f x, "
                            "%.2f errors, n_pinned %u of %d\n",
                            drift, g, ratios[k], u, offs[o], r.E / p->E, r.w / p->w, dev, (unsigned)r.n_pinned,
                            npin);
                nbad++;
            }
            worst = dev > worst ? dev : worst;
        }
    }
    print_message("drifted decimal z: %d of %d answered, %d beyond %.0f errors, worst %.2f\n", nfit, 2 * ncase, nbad,
                  DIGITS_PULL, worst);
    assert_int_equal(nbad, 0);
    assert_true(nfit >= DRIFT_MIN_OK);
}
#undef IRR_CASE
#endif

#ifndef MDR_TARGET_TEST
/* z written in nm to two decimals and to one, as AFM export files write it
 * (python/tests/sweep_nm.py, stop 81: of 176 realistic noisy curves that
 * binary z answered, z to 0.01 nm answered 117, 50 refused MDR_E_MISFIT):
 * the fold-end test (mdr_f_fold_end) allows for z's rounding through the
 * model's slope at each sample. Contacts of 6.5 to 30 nm radius, E* 0.6 to
 * 15 GPa, through levers of 0.064 to 0.62 N/m, w_adv = 0.7 w, noise
 * NMW_SIG of the pull-off force, a 2.3 um piezo offset: every answer
 * within NMW_PULL reported errors, at least NMW_MIN_OK (0.01 nm) and
 * NMW1_MIN_OK (0.1 nm) of 32 answered (stop 80's lib: 24 at 0.01 nm) */
static double nm_written(double z, int decimals)
{
    char buf[48];
    snprintf(buf, sizeof buf, "%.*f", decimals, z * 1e9);
    return strtod(buf, NULL) * 1e-9;
}

/* test_written_nm's curves with z written to `decimals` in nm: every
 * answer within NMW_PULL reported errors, at least min_ok answered */
static void written_nm_pass(int decimals, int min_ok)
{
    static const jkr_par cases[] = {
        {8.0e-9, 0.6e9, 0.016, 0.62},  {6.5e-9, 15e9, 0.063, 0.24},  {11e-9, 1.6e9, 0.013, 0.55},
        {8.2e-9, 1.2e9, 0.021, 0.064}, {20e-9, 1e9, 0.05, 0.2},      {15e-9, 7.3e9, 0.019, 0.14},
        {30e-9, 3e9, 0.04, 0.3},       {12e-9, 0.8e9, 0.03, 0.1},
    };
    enum { ncase = sizeof cases / sizeof cases[0], nseed = 4, n = 200 };
    int c, s, i, npin, nfit = 0, nbad = 0;
    double worst = 0.0;
    noise_state = 0x6a09e667f3bcc908ull;
    for (c = 0; c < ncase; c++) {
        const jkr_par *p = &cases[c];
        const mdr_contact_f64 ct = paraboloid64(p->R);
        for (s = 0; s < nseed; s++) {
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            double Fpo, dev;
            mdr_status st;
            pinned_curve(p, 0.7 * p->w, 2.5 * jkr_fold(p), 2.3e-6, 0.0, n, zs, Fs, &npin, &Fpo);
            for (i = 0; i < n; i++) {
                zs[i] = nm_written(zs[i], decimals);
                Fs[i] += NMW_SIG * fabs(Fpo) * gauss();
            }
            mdr_fit_defaults_f64(&o, p->km);
            st = mdr_fit_curve_f64(&ct, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            if (st != MDR_OK) {
                print_message("z to 1e-%d nm: case %d seed %d: %s\n", decimals, c, s, mdr_status_str(st));
                continue; /* (a refusal names its reason) */
            }
            nfit++;
            dev = fit_pull(&r, p);
            if (!(dev <= NMW_PULL)) {
                print_error("z to 1e-%d nm: case %d seed %d: E* %.5f x, w %.5f x, %.2f errors, n_pinned %u of %d\n",
                            decimals, c, s, r.E / p->E, r.w / p->w, dev, (unsigned)r.n_pinned, npin);
                nbad++;
            }
            worst = dev > worst ? dev : worst;
        }
    }
    print_message("z written to 1e-%d nm: %d of %d answered, %d beyond %.0f errors, worst %.2f\n", decimals, nfit,
                  ncase * nseed, nbad, NMW_PULL, worst);
    assert_int_equal(nbad, 0);
    assert_true(nfit >= min_ok);
}

static void test_written_nm(void **state)
{
    (void)state;
    written_nm_pass(2, NMW_MIN_OK);
    written_nm_pass(1, NMW1_MIN_OK);
}

/* A curve recorded from a sweep (its z and F as the sweep wrote them) and
 * the truth it was computed from */
typedef struct {
    const double *z, *F;
    int n;
    jkr_par p;
} recorded_curve;

/* Each of the n recorded curves refused, or answered within NMW_PULL
 * reported errors */
static void check_recorded(const recorded_curve *rec, unsigned n, const char *what)
{
    unsigned c;
    for (c = 0; c < n; c++) {
        const jkr_par *p = &rec[c].p;
        const mdr_contact_f64 ct = paraboloid64(p->R);
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        mdr_status st;
        mdr_fit_defaults_f64(&o, p->km);
        memcpy(zs, rec[c].z, (size_t)rec[c].n * sizeof zs[0]);
        memcpy(Fs, rec[c].F, (size_t)rec[c].n * sizeof Fs[0]);
        st = mdr_fit_curve_f64(&ct, &o, zs, Fs, (uint32_t)rec[c].n, work64, 2 * NMAX, &r);
        if (st == MDR_OK) {
            const double dev = fit_pull(&r, p);
            print_message("%s, curve %u: E* %.4f x, w %.4f x, %.2f errors, n_pinned %u\n", what, c, r.E / p->E,
                          r.w / p->w, dev, (unsigned)r.n_pinned);
            assert_true(dev <= NMW_PULL);
        } else {
            print_message("%s, curve %u: %s\n", what, c, mdr_status_str(st));
        }
    }
}

/* Noise-free curves whose z a file rounded, answered wrong with their
 * pinned tops lost where the fold-end test allowed for z's rounding in
 * noise-free data too (stop 81: E* 1.33 x and 1.36 x, w 0.90 x and 0.86 x
 * at 14 and 9 errors, n_pinned 0): it does so in noisy data only
 * (mdr_f_fold_end), so these are refused, as before, or answered within
 * NMW_PULL reported errors. Recorded from python/tests/sweep_drift.py. */
/* sweep_drift.py's nonlinear, seed 1, case 169 (88 samples) */
static const double nl169_z[88] = {
    7.4379700000000011e-06, 7.4381200000000005e-06, 7.4382700000000009e-06, 7.4384200000000003e-06,
    7.4385699999999998e-06, 7.43873e-06, 7.4388800000000003e-06, 7.4390400000000005e-06, 7.43919e-06,
    7.439350000000001e-06, 7.4395100000000004e-06, 7.4396600000000007e-06, 7.43982e-06, 7.4399800000000002e-06,
    7.4401400000000004e-06, 7.4403000000000006e-06, 7.4404600000000008e-06, 7.4406100000000002e-06,
    7.4407700000000013e-06, 7.4409300000000006e-06, 7.4410900000000008e-06, 7.4412500000000001e-06,
    7.4414100000000003e-06, 7.4415600000000006e-06, 7.4417200000000008e-06, 7.4418700000000003e-06,
    7.4420300000000005e-06, 7.4421800000000008e-06, 7.442340000000001e-06, 7.4424900000000005e-06,
    7.4426400000000008e-06, 7.4427900000000003e-06, 7.4429399999999998e-06, 7.4430900000000009e-06,
    7.4432299999999997e-06, 7.4433800000000009e-06, 7.4435200000000005e-06, 7.4436700000000008e-06,
    7.4438100000000005e-06, 7.4439400000000003e-06, 7.4440800000000007e-06, 7.4442200000000004e-06,
    7.444350000000001e-06, 7.4444799999999999e-06, 7.4444799999999999e-06, 7.444350000000001e-06,
    7.4442200000000004e-06, 7.4440800000000007e-06, 7.4439400000000003e-06, 7.4438100000000005e-06,
    7.4436700000000008e-06, 7.4435200000000005e-06, 7.4433800000000009e-06, 7.4432299999999997e-06,
    7.4430900000000009e-06, 7.4429399999999998e-06, 7.4427900000000003e-06, 7.4426400000000008e-06,
    7.4424900000000005e-06, 7.442340000000001e-06, 7.4421800000000008e-06, 7.4420300000000005e-06,
    7.4418700000000003e-06, 7.4417200000000008e-06, 7.4415600000000006e-06, 7.4414100000000003e-06,
    7.4412500000000001e-06, 7.4410900000000008e-06, 7.4409300000000006e-06, 7.4407700000000013e-06,
    7.4406100000000002e-06, 7.4404600000000008e-06, 7.4403000000000006e-06, 7.4401400000000004e-06,
    7.4399800000000002e-06, 7.43982e-06, 7.4396600000000007e-06, 7.4395100000000004e-06, 7.439350000000001e-06,
    7.43919e-06, 7.4390400000000005e-06, 7.4388800000000003e-06, 7.43873e-06, 7.4385699999999998e-06,
    7.4384200000000003e-06, 7.4382700000000009e-06, 7.4381200000000005e-06, 7.4379700000000011e-06,
};
static const double nl169_F[88] = {
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    9.5361720563337234e-11, 2.4943428612073083e-10, 4.0459181433064091e-10, 5.6010421955431668e-10,
    7.155569841560372e-10, 8.7066857263412594e-10, 1.0252250684094706e-09, 1.1790512461106689e-09,
    1.3319959099735707e-09, 1.48392371914817e-09, 1.6347102935959362e-09, 1.7842391174045306e-09,
    1.9323994905994972e-09, 2.0790851243480681e-09, 2.224193147771621e-09, 2.3676233874761327e-09,
    2.5092778332589993e-09, 2.6490602342123945e-09, 2.7868757882791201e-09, 2.922630900055542e-09,
    2.9226309000555445e-09, 2.7858228783733702e-09, 2.6468408173163923e-09, 2.5057680658531583e-09,
    2.3626879729486674e-09, 2.2176838875750161e-09, 2.0708391586972028e-09, 1.9222371352837754e-09,
    1.7719611663032819e-09, 1.620094600724269e-09, 1.4667207875143976e-09, 1.3119230756395542e-09,
    1.1557848140709475e-09, 9.9838935177446361e-10, 8.3982003771865042e-10, 6.8016022087205496e-10,
    5.1949325020233813e-10, 3.6084791526764806e-10, 2.0230950113747746e-10, 4.3498689159046027e-11,
    -1.1539877805462176e-10, -2.7415308814490157e-10, -4.3245701921291468e-10, -5.8985040315502599e-10,
    -7.4550910260747571e-10, -8.9737165845788256e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
    1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10, 1.1243711804401753e-10,
};
/* sweep_drift.py's near_int_dup, seed 2, case 17 (66 samples) */
static const double dup17_z[66] = {
    8.9746000000000004e-06, 8.9756999999999995e-06, 8.9768000000000002e-06, 8.9778999999999992e-06,
    8.9789999999999999e-06, 8.9801000000000006e-06, 8.9811999999999997e-06, 8.9823000000000004e-06,
    8.9833999999999994e-06, 8.9845000000000001e-06, 8.9856000000000008e-06, 8.9866999999999999e-06,
    8.9878000000000006e-06, 8.9888999999999996e-06, 8.9900000000000003e-06, 8.9910999999999993e-06,
    8.9922000000000001e-06, 8.9933000000000008e-06, 8.9943999999999998e-06, 8.9955000000000005e-06,
    8.9965999999999995e-06, 8.9977000000000003e-06, 8.9987999999999993e-06, 8.9999e-06, 9.0010000000000007e-06,
    9.0020999999999998e-06, 9.0032000000000005e-06, 9.0042999999999995e-06, 9.0054000000000002e-06,
    9.0064999999999992e-06, 9.0076e-06, 9.0087000000000007e-06, 9.0087000000000007e-06, 9.0076e-06,
    9.0064999999999992e-06, 9.0054000000000002e-06, 9.0042999999999995e-06, 9.0032000000000005e-06,
    9.0020999999999998e-06, 9.0010000000000007e-06, 8.9999e-06, 8.9987999999999993e-06, 8.9987999999999993e-06,
    8.9977000000000003e-06, 8.9965999999999995e-06, 8.9955000000000005e-06, 8.9943999999999998e-06,
    8.9933000000000008e-06, 8.9922000000000001e-06, 8.9910999999999993e-06, 8.9910999999999993e-06,
    8.9900000000000003e-06, 8.9888999999999996e-06, 8.9878000000000006e-06, 8.9866999999999999e-06,
    8.9856000000000008e-06, 8.9845000000000001e-06, 8.9833999999999994e-06, 8.9823000000000004e-06,
    8.9811999999999997e-06, 8.9801000000000006e-06, 8.9789999999999999e-06, 8.9778999999999992e-06,
    8.9768000000000002e-06, 8.9756999999999995e-06, 8.9746000000000004e-06,
};
static const double dup17_F[66] = {
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 9.4432939897859721e-09,
    1.6637144981436444e-08, 2.3884280047916247e-08, 3.1167635847512597e-08, 3.8477883969490904e-08,
    4.5809227352928996e-08, 5.3157754625647717e-08, 6.0520670206404165e-08, 6.7895888783649014e-08,
    7.5281802673285931e-08, 8.2677139421920089e-08, 9.0080870090913386e-08, 9.7492147697614947e-08,
    9.7492147697614947e-08, 9.0030553702093037e-08, 8.256895970655964e-08, 7.5107365711037731e-08,
    6.7645771715504333e-08, 6.0184177719982424e-08, 5.2722583724449027e-08, 4.5260989728927117e-08,
    3.779939573339372e-08, 3.0337801737871811e-08, 3.0337801737871811e-08, 2.287620774233841e-08,
    1.5448565398920677e-08, 8.1344288498832919e-09, 8.4502380846929014e-10, -6.4120919955913368e-09,
    -1.3624187360844159e-08, -2.0766211503691917e-08, -2.0766211503691917e-08, -2.7771060974622235e-08,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09, 3.6914557389013921e-09,
    3.6914557389013921e-09, 3.6914557389013921e-09,
};

static void test_written_noisefree_end(void **state)
{
    static const recorded_curve rec[] = {
        {nl169_z, nl169_F, 88, {7.1539521850240185e-08, 3191798784.29638, 0.0033408529782751576, 1.0874309291225659}},
        {dup17_z, dup17_F, 66, {3.1479311779295863e-07, 5484200886.8907709, 0.024915812146639828, 7.0047351004010174}},
    };
    (void)state;
    check_recorded(rec, sizeof rec / sizeof rec[0], "noise-free, z rounded");
}

/* A noisy curve (sweep_nm.py's 149th: z written to 0.1 nm, 0.24 nm steps,
 * noise 5e-4 of the pull-off force, 343 samples a branch) that the
 * fold-end test's allowance for z's rounding (mdr_f_fold_end) admits;
 * without the last contact sample's rounding in the fold's position
 * (mdr_fit_curve) it was answered 8.1 errors off: refused or within
 * NMW_PULL reported errors. */
/* sweep_nm.py's curve 149 (z to 0.1 nm, 686 samples) */
static const double nm1a_z[686] = {
    2.5052000000000002e-06, 2.5055e-06, 2.5057e-06, 2.5060000000000002e-06, 2.5061999999999998e-06,
    2.5064000000000003e-06, 2.5067000000000001e-06, 2.5069000000000001e-06, 2.5071999999999999e-06,
    2.5074000000000003e-06, 2.5077000000000001e-06, 2.5079000000000002e-06, 2.5082e-06, 2.5084000000000004e-06,
    2.5086e-06, 2.5089000000000002e-06, 2.5091000000000003e-06, 2.5094000000000001e-06, 2.5096000000000001e-06,
    2.5099000000000003e-06, 2.5100999999999999e-06, 2.5104000000000001e-06, 2.5106000000000002e-06,
    2.5108000000000002e-06, 2.5111e-06, 2.5113000000000004e-06, 2.5116000000000002e-06, 2.5118000000000002e-06,
    2.5121000000000001e-06, 2.5123000000000005e-06, 2.5125999999999999e-06, 2.5128000000000003e-06,
    2.5130000000000003e-06, 2.5133000000000001e-06, 2.5135000000000002e-06, 2.5138000000000004e-06, 2.514e-06,
    2.5143000000000002e-06, 2.5145000000000002e-06, 2.5148000000000005e-06, 2.5150000000000001e-06,
    2.5152000000000001e-06, 2.5155000000000003e-06, 2.5156999999999999e-06, 2.5160000000000001e-06,
    2.5162000000000002e-06, 2.5165e-06, 2.5167e-06, 2.5170000000000002e-06, 2.5171999999999998e-06,
    2.5174000000000002e-06, 2.5177000000000001e-06, 2.5179000000000001e-06, 2.5181999999999999e-06,
    2.5184000000000003e-06, 2.5187000000000001e-06, 2.5189000000000001e-06, 2.5192e-06, 2.5194000000000004e-06,
    2.5196e-06, 2.5199000000000002e-06, 2.5201000000000002e-06, 2.5204e-06, 2.5206000000000001e-06,
    2.5209000000000003e-06, 2.5210999999999999e-06, 2.5214000000000001e-06, 2.5216000000000001e-06,
    2.5218000000000001e-06, 2.5221e-06, 2.5223000000000004e-06, 2.5226000000000002e-06, 2.5228000000000002e-06,
    2.5231e-06, 2.5233000000000005e-06, 2.5235999999999999e-06, 2.5238000000000003e-06, 2.5240000000000003e-06,
    2.5243000000000005e-06, 2.5245000000000001e-06, 2.5248000000000004e-06, 2.525e-06, 2.5253000000000002e-06,
    2.5255000000000002e-06, 2.5258000000000004e-06, 2.526e-06, 2.5262000000000001e-06, 2.5265000000000003e-06,
    2.5266999999999999e-06, 2.5270000000000001e-06, 2.5272000000000001e-06, 2.5275000000000004e-06, 2.5277e-06,
    2.5280000000000002e-06, 2.5281999999999998e-06, 2.5284000000000002e-06, 2.5287e-06, 2.5289e-06,
    2.5291999999999999e-06, 2.5294000000000003e-06, 2.5297000000000001e-06, 2.5299000000000001e-06,
    2.5301999999999999e-06, 2.5304000000000004e-06, 2.5306e-06, 2.5309000000000002e-06, 2.5311000000000002e-06,
    2.5314000000000004e-06, 2.5316e-06, 2.5319000000000003e-06, 2.5320999999999999e-06, 2.5324000000000001e-06,
    2.5326000000000001e-06, 2.5328000000000006e-06, 2.5330999999999999e-06, 2.5333000000000004e-06,
    2.5336000000000002e-06, 2.5338000000000002e-06, 2.5341e-06, 2.5343000000000005e-06, 2.5346000000000003e-06,
    2.5348000000000003e-06, 2.5350000000000003e-06, 2.5353000000000005e-06, 2.5355000000000001e-06,
    2.5358000000000004e-06, 2.5360000000000004e-06, 2.5363000000000002e-06, 2.5365000000000002e-06,
    2.5368000000000004e-06, 2.537e-06, 2.5372e-06, 2.5375000000000003e-06, 2.5376999999999999e-06,
    2.5380000000000001e-06, 2.5382000000000001e-06, 2.5385000000000003e-06, 2.5386999999999999e-06,
    2.5390000000000002e-06, 2.5392000000000002e-06, 2.5394000000000002e-06, 2.5397e-06, 2.5399000000000004e-06,
    2.5401999999999998e-06, 2.5404000000000003e-06, 2.5407000000000001e-06, 2.5409000000000001e-06,
    2.5411999999999999e-06, 2.5414000000000004e-06, 2.5415999999999999e-06, 2.5419000000000002e-06,
    2.5421000000000002e-06, 2.5424000000000004e-06, 2.5426e-06, 2.5429000000000003e-06, 2.5431000000000003e-06,
    2.5434000000000001e-06, 2.5436000000000001e-06, 2.5438000000000005e-06, 2.5440999999999999e-06,
    2.5443000000000004e-06, 2.5446000000000002e-06, 2.5448000000000002e-06, 2.5451e-06, 2.5453000000000004e-06,
    2.5456000000000002e-06, 2.5458000000000003e-06, 2.5460000000000003e-06, 2.5463000000000005e-06,
    2.5465000000000001e-06, 2.5468000000000003e-06, 2.5470000000000003e-06, 2.5473000000000002e-06,
    2.5475000000000002e-06, 2.5478000000000004e-06, 2.548e-06, 2.5482e-06, 2.5485000000000002e-06,
    2.5486999999999998e-06, 2.5490000000000001e-06, 2.5492000000000001e-06, 2.5495000000000003e-06,
    2.5496999999999999e-06, 2.5499000000000004e-06, 2.5502000000000002e-06, 2.5504000000000002e-06, 2.5507e-06,
    2.5509000000000004e-06, 2.5511999999999998e-06, 2.5514000000000003e-06, 2.5517000000000001e-06,
    2.5519000000000001e-06, 2.5521000000000001e-06, 2.5524000000000003e-06, 2.5525999999999999e-06,
    2.5529000000000002e-06, 2.5531000000000002e-06, 2.5534000000000004e-06, 2.5536e-06, 2.5539000000000002e-06,
    2.5541000000000002e-06, 2.5543000000000003e-06, 2.5546000000000001e-06, 2.5548000000000005e-06,
    2.5550999999999999e-06, 2.5553000000000003e-06, 2.5556000000000001e-06, 2.5558000000000002e-06, 2.5561e-06,
    2.5563000000000004e-06, 2.5565e-06, 2.5568000000000002e-06, 2.5570000000000003e-06, 2.5573000000000005e-06,
    2.5575000000000001e-06, 2.5578000000000003e-06, 2.5580000000000003e-06, 2.5583000000000001e-06,
    2.5585000000000002e-06, 2.5587000000000002e-06, 2.559e-06, 2.5592e-06, 2.5595000000000002e-06,
    2.5596999999999998e-06, 2.5600000000000001e-06, 2.5602000000000001e-06, 2.5605000000000003e-06,
    2.5606999999999999e-06, 2.5609000000000003e-06, 2.5612000000000001e-06, 2.5614000000000002e-06, 2.5617e-06,
    2.5619000000000004e-06, 2.5621999999999998e-06, 2.5624000000000002e-06, 2.5627e-06, 2.5629000000000001e-06,
    2.5631000000000001e-06, 2.5634000000000003e-06, 2.5635999999999999e-06, 2.5639000000000001e-06,
    2.5641000000000001e-06, 2.5644000000000004e-06, 2.5646e-06, 2.5649000000000002e-06, 2.5651000000000002e-06,
    2.5653000000000002e-06, 2.5656000000000001e-06, 2.5658000000000005e-06, 2.5660999999999999e-06,
    2.5663000000000003e-06, 2.5666000000000001e-06, 2.5668000000000001e-06, 2.5671e-06, 2.5673000000000004e-06,
    2.5675e-06, 2.5678000000000002e-06, 2.5680000000000002e-06, 2.5683000000000005e-06, 2.5685000000000001e-06,
    2.5688000000000003e-06, 2.5690000000000003e-06, 2.5693000000000005e-06, 2.5695000000000001e-06,
    2.5697000000000001e-06, 2.57e-06, 2.5702e-06, 2.5705000000000002e-06, 2.5706999999999998e-06, 2.571e-06,
    2.5712e-06, 2.5715000000000003e-06, 2.5716999999999999e-06, 2.5719000000000003e-06, 2.5722000000000001e-06,
    2.5724000000000001e-06, 2.5726999999999999e-06, 2.5729000000000004e-06, 2.5731999999999998e-06,
    2.5734000000000002e-06, 2.5737e-06, 2.5739000000000005e-06, 2.5741000000000001e-06, 2.5744000000000003e-06,
    2.5745999999999999e-06, 2.5749000000000001e-06, 2.5751000000000001e-06, 2.5754000000000004e-06, 2.5756e-06,
    2.5759000000000002e-06, 2.5761000000000002e-06, 2.5763000000000002e-06, 2.5766e-06, 2.5768000000000005e-06,
    2.5771000000000003e-06, 2.5773000000000003e-06, 2.5776000000000001e-06, 2.5778000000000005e-06,
    2.5780999999999999e-06, 2.5783000000000004e-06, 2.5785e-06, 2.5788000000000002e-06, 2.5790000000000002e-06,
    2.5793000000000004e-06, 2.5795e-06, 2.5798000000000003e-06, 2.5800000000000003e-06, 2.5803000000000005e-06,
    2.5805000000000001e-06, 2.5807000000000001e-06, 2.5810000000000004e-06, 2.5812e-06, 2.5815000000000002e-06,
    2.5816999999999998e-06, 2.582e-06, 2.5822e-06, 2.5825000000000003e-06, 2.5826999999999999e-06,
    2.5829000000000003e-06, 2.5832000000000001e-06, 2.5834000000000001e-06, 2.5836999999999999e-06,
    2.5839000000000004e-06, 2.5842000000000002e-06, 2.5844000000000002e-06, 2.5847e-06, 2.5849000000000004e-06,
    2.5851e-06, 2.5854000000000003e-06, 2.5855999999999999e-06, 2.5859000000000001e-06, 2.5861000000000001e-06,
    2.5864000000000003e-06, 2.5865999999999999e-06, 2.5869000000000002e-06, 2.5871000000000002e-06,
    2.5873000000000002e-06, 2.5876e-06, 2.5878000000000004e-06, 2.5881000000000003e-06, 2.5883000000000003e-06,
    2.5886000000000001e-06, 2.5888000000000005e-06, 2.5888000000000005e-06, 2.5886000000000001e-06,
    2.5883000000000003e-06, 2.5881000000000003e-06, 2.5878000000000004e-06, 2.5876e-06, 2.5873000000000002e-06,
    2.5871000000000002e-06, 2.5869000000000002e-06, 2.5865999999999999e-06, 2.5864000000000003e-06,
    2.5861000000000001e-06, 2.5859000000000001e-06, 2.5855999999999999e-06, 2.5854000000000003e-06, 2.5851e-06,
    2.5849000000000004e-06, 2.5847e-06, 2.5844000000000002e-06, 2.5842000000000002e-06, 2.5839000000000004e-06,
    2.5836999999999999e-06, 2.5834000000000001e-06, 2.5832000000000001e-06, 2.5829000000000003e-06,
    2.5826999999999999e-06, 2.5825000000000003e-06, 2.5822e-06, 2.582e-06, 2.5816999999999998e-06,
    2.5815000000000002e-06, 2.5812e-06, 2.5810000000000004e-06, 2.5807000000000001e-06, 2.5805000000000001e-06,
    2.5803000000000005e-06, 2.5800000000000003e-06, 2.5798000000000003e-06, 2.5795e-06, 2.5793000000000004e-06,
    2.5790000000000002e-06, 2.5788000000000002e-06, 2.5785e-06, 2.5783000000000004e-06, 2.5780999999999999e-06,
    2.5778000000000005e-06, 2.5776000000000001e-06, 2.5773000000000003e-06, 2.5771000000000003e-06,
    2.5768000000000005e-06, 2.5766e-06, 2.5763000000000002e-06, 2.5761000000000002e-06, 2.5759000000000002e-06,
    2.5756e-06, 2.5754000000000004e-06, 2.5751000000000001e-06, 2.5749000000000001e-06, 2.5745999999999999e-06,
    2.5744000000000003e-06, 2.5741000000000001e-06, 2.5739000000000005e-06, 2.5737e-06, 2.5734000000000002e-06,
    2.5731999999999998e-06, 2.5729000000000004e-06, 2.5726999999999999e-06, 2.5724000000000001e-06,
    2.5722000000000001e-06, 2.5719000000000003e-06, 2.5716999999999999e-06, 2.5715000000000003e-06, 2.5712e-06,
    2.571e-06, 2.5706999999999998e-06, 2.5705000000000002e-06, 2.5702e-06, 2.57e-06, 2.5697000000000001e-06,
    2.5695000000000001e-06, 2.5693000000000005e-06, 2.5690000000000003e-06, 2.5688000000000003e-06,
    2.5685000000000001e-06, 2.5683000000000005e-06, 2.5680000000000002e-06, 2.5678000000000002e-06, 2.5675e-06,
    2.5673000000000004e-06, 2.5671e-06, 2.5668000000000001e-06, 2.5666000000000001e-06, 2.5663000000000003e-06,
    2.5660999999999999e-06, 2.5658000000000005e-06, 2.5656000000000001e-06, 2.5653000000000002e-06,
    2.5651000000000002e-06, 2.5649000000000002e-06, 2.5646e-06, 2.5644000000000004e-06, 2.5641000000000001e-06,
    2.5639000000000001e-06, 2.5635999999999999e-06, 2.5634000000000003e-06, 2.5631000000000001e-06,
    2.5629000000000001e-06, 2.5627e-06, 2.5624000000000002e-06, 2.5621999999999998e-06, 2.5619000000000004e-06,
    2.5617e-06, 2.5614000000000002e-06, 2.5612000000000001e-06, 2.5609000000000003e-06, 2.5606999999999999e-06,
    2.5605000000000003e-06, 2.5602000000000001e-06, 2.5600000000000001e-06, 2.5596999999999998e-06,
    2.5595000000000002e-06, 2.5592e-06, 2.559e-06, 2.5587000000000002e-06, 2.5585000000000002e-06,
    2.5583000000000001e-06, 2.5580000000000003e-06, 2.5578000000000003e-06, 2.5575000000000001e-06,
    2.5573000000000005e-06, 2.5570000000000003e-06, 2.5568000000000002e-06, 2.5565e-06, 2.5563000000000004e-06,
    2.5561e-06, 2.5558000000000002e-06, 2.5556000000000001e-06, 2.5553000000000003e-06, 2.5550999999999999e-06,
    2.5548000000000005e-06, 2.5546000000000001e-06, 2.5543000000000003e-06, 2.5541000000000002e-06,
    2.5539000000000002e-06, 2.5536e-06, 2.5534000000000004e-06, 2.5531000000000002e-06, 2.5529000000000002e-06,
    2.5525999999999999e-06, 2.5524000000000003e-06, 2.5521000000000001e-06, 2.5519000000000001e-06,
    2.5517000000000001e-06, 2.5514000000000003e-06, 2.5511999999999998e-06, 2.5509000000000004e-06, 2.5507e-06,
    2.5504000000000002e-06, 2.5502000000000002e-06, 2.5499000000000004e-06, 2.5496999999999999e-06,
    2.5495000000000003e-06, 2.5492000000000001e-06, 2.5490000000000001e-06, 2.5486999999999998e-06,
    2.5485000000000002e-06, 2.5482e-06, 2.548e-06, 2.5478000000000004e-06, 2.5475000000000002e-06,
    2.5473000000000002e-06, 2.5470000000000003e-06, 2.5468000000000003e-06, 2.5465000000000001e-06,
    2.5463000000000005e-06, 2.5460000000000003e-06, 2.5458000000000003e-06, 2.5456000000000002e-06,
    2.5453000000000004e-06, 2.5451e-06, 2.5448000000000002e-06, 2.5446000000000002e-06, 2.5443000000000004e-06,
    2.5440999999999999e-06, 2.5438000000000005e-06, 2.5436000000000001e-06, 2.5434000000000001e-06,
    2.5431000000000003e-06, 2.5429000000000003e-06, 2.5426e-06, 2.5424000000000004e-06, 2.5421000000000002e-06,
    2.5419000000000002e-06, 2.5415999999999999e-06, 2.5414000000000004e-06, 2.5411999999999999e-06,
    2.5409000000000001e-06, 2.5407000000000001e-06, 2.5404000000000003e-06, 2.5401999999999998e-06,
    2.5399000000000004e-06, 2.5397e-06, 2.5394000000000002e-06, 2.5392000000000002e-06, 2.5390000000000002e-06,
    2.5386999999999999e-06, 2.5385000000000003e-06, 2.5382000000000001e-06, 2.5380000000000001e-06,
    2.5376999999999999e-06, 2.5375000000000003e-06, 2.5372e-06, 2.537e-06, 2.5368000000000004e-06,
    2.5365000000000002e-06, 2.5363000000000002e-06, 2.5360000000000004e-06, 2.5358000000000004e-06,
    2.5355000000000001e-06, 2.5353000000000005e-06, 2.5350000000000003e-06, 2.5348000000000003e-06,
    2.5346000000000003e-06, 2.5343000000000005e-06, 2.5341e-06, 2.5338000000000002e-06, 2.5336000000000002e-06,
    2.5333000000000004e-06, 2.5330999999999999e-06, 2.5328000000000006e-06, 2.5326000000000001e-06,
    2.5324000000000001e-06, 2.5320999999999999e-06, 2.5319000000000003e-06, 2.5316e-06, 2.5314000000000004e-06,
    2.5311000000000002e-06, 2.5309000000000002e-06, 2.5306e-06, 2.5304000000000004e-06, 2.5301999999999999e-06,
    2.5299000000000001e-06, 2.5297000000000001e-06, 2.5294000000000003e-06, 2.5291999999999999e-06, 2.5289e-06,
    2.5287e-06, 2.5284000000000002e-06, 2.5281999999999998e-06, 2.5280000000000002e-06, 2.5277e-06,
    2.5275000000000004e-06, 2.5272000000000001e-06, 2.5270000000000001e-06, 2.5266999999999999e-06,
    2.5265000000000003e-06, 2.5262000000000001e-06, 2.526e-06, 2.5258000000000004e-06, 2.5255000000000002e-06,
    2.5253000000000002e-06, 2.525e-06, 2.5248000000000004e-06, 2.5245000000000001e-06, 2.5243000000000005e-06,
    2.5240000000000003e-06, 2.5238000000000003e-06, 2.5235999999999999e-06, 2.5233000000000005e-06, 2.5231e-06,
    2.5228000000000002e-06, 2.5226000000000002e-06, 2.5223000000000004e-06, 2.5221e-06, 2.5218000000000001e-06,
    2.5216000000000001e-06, 2.5214000000000001e-06, 2.5210999999999999e-06, 2.5209000000000003e-06,
    2.5206000000000001e-06, 2.5204e-06, 2.5201000000000002e-06, 2.5199000000000002e-06, 2.5196e-06,
    2.5194000000000004e-06, 2.5192e-06, 2.5189000000000001e-06, 2.5187000000000001e-06, 2.5184000000000003e-06,
    2.5181999999999999e-06, 2.5179000000000001e-06, 2.5177000000000001e-06, 2.5174000000000002e-06,
    2.5171999999999998e-06, 2.5170000000000002e-06, 2.5167e-06, 2.5165e-06, 2.5162000000000002e-06,
    2.5160000000000001e-06, 2.5156999999999999e-06, 2.5155000000000003e-06, 2.5152000000000001e-06,
    2.5150000000000001e-06, 2.5148000000000005e-06, 2.5145000000000002e-06, 2.5143000000000002e-06, 2.514e-06,
    2.5138000000000004e-06, 2.5135000000000002e-06, 2.5133000000000001e-06, 2.5130000000000003e-06,
    2.5128000000000003e-06, 2.5125999999999999e-06, 2.5123000000000005e-06, 2.5121000000000001e-06,
    2.5118000000000002e-06, 2.5116000000000002e-06, 2.5113000000000004e-06, 2.5111e-06, 2.5108000000000002e-06,
    2.5106000000000002e-06, 2.5104000000000001e-06, 2.5100999999999999e-06, 2.5099000000000003e-06,
    2.5096000000000001e-06, 2.5094000000000001e-06, 2.5091000000000003e-06, 2.5089000000000002e-06, 2.5086e-06,
    2.5084000000000004e-06, 2.5082e-06, 2.5079000000000002e-06, 2.5077000000000001e-06, 2.5074000000000003e-06,
    2.5071999999999999e-06, 2.5069000000000001e-06, 2.5067000000000001e-06, 2.5064000000000003e-06,
    2.5061999999999998e-06, 2.5060000000000002e-06, 2.5057e-06, 2.5055e-06, 2.5052000000000002e-06,
};
static const double nm1a_F[686] = {
    2.9712281523000758e-10, 2.9529900430622601e-10, 2.953493721912198e-10, 2.9516444473364644e-10,
    2.93090390908918e-10, 2.9307416758785688e-10, 2.9755237261371928e-10, 2.9428023035638454e-10,
    2.9308630603075788e-10, 2.9416732778327194e-10, 2.9375048891405119e-10, 2.9568941715878374e-10,
    2.9668111749817159e-10, 2.9644670747085663e-10, 2.9685836832375517e-10, 2.9706385618935287e-10,
    2.9665231601668612e-10, 2.9569400094076665e-10, 2.9341059261311439e-10, 2.9699278427131553e-10,
    2.93564333754887e-10, 2.94938627554021e-10, 2.9594764694752003e-10, 2.9658550520378312e-10, 2.965633600839842e-10,
    2.9609970884644653e-10, 2.9492145909907628e-10, 2.9526309779609557e-10, 2.9633000592818688e-10,
    2.9823321726230513e-10, 2.9629844501030838e-10, 2.9651188657303553e-10, 2.9685324749180476e-10,
    2.9591201123583666e-10, 2.9691640481452037e-10, 2.9447048435693677e-10, 2.9660116220128212e-10,
    2.9383607909253293e-10, 2.9346862547257779e-10, 2.9618619762146631e-10, 2.92832062445956e-10,
    2.9274186673115998e-10, 2.9604262911353243e-10, 2.9703693320913349e-10, 2.9671711945158461e-10,
    2.9568587905443685e-10, 2.9520368459228107e-10, 2.958299930028867e-10, 2.9458583497177698e-10,
    2.9566533333075482e-10, 2.974797496460271e-10, 2.9581878256558144e-10, 2.9744800173514676e-10,
    2.9658812898156401e-10, 2.9256739150179909e-10, 2.94614128659154e-10, 2.9655955277003113e-10,
    2.9419004938574804e-10, 2.9500276650915699e-10, 2.9731149910383236e-10, 2.9720629904138407e-10,
    2.9654908582232313e-10, 2.9783328707494327e-10, 2.983972694077131e-10, 2.9555603990319857e-10,
    2.9509427054498646e-10, 2.9177093815903698e-10, 2.9677535336564799e-10, 2.9570589657464978e-10,
    2.9675663209819677e-10, 2.9369165216117055e-10, 2.9692288393061193e-10, 2.9642489167714851e-10,
    2.9687177852935099e-10, 2.9760417918008006e-10, 2.9990776254129644e-10, 2.9444636512373809e-10,
    2.9696808620522082e-10, 2.9837131683614548e-10, 2.9686858868705577e-10, 2.9419967928174465e-10,
    2.983240631648226e-10, 2.9636421320780614e-10, 2.9782827591956672e-10, 2.9644181529310538e-10,
    2.9673406213451414e-10, 2.9679404796081043e-10, 2.9604939831379345e-10, 2.9574490283407424e-10,
    2.9764953443969354e-10, 2.9495050645829484e-10, 2.964241865052226e-10, 2.9469074372703092e-10,
    2.9583033500322471e-10, 2.9742695119061874e-10, 2.9575365548908138e-10, 2.9570508930645176e-10,
    2.9706709532242593e-10, 2.9744925681491562e-10, 2.9605084283014661e-10, 2.9466614600902579e-10,
    2.9692735068806301e-10, 2.9511463533085084e-10, 2.9564818665207302e-10, 2.9509982493056402e-10,
    2.9609403585179254e-10, 2.9724277265819389e-10, 2.9503019428029693e-10, 2.9697185264984815e-10,
    2.946275145630941e-10, 2.972714835860523e-10, 2.9583012613389354e-10, 2.9463140778441552e-10,
    2.9564611629789536e-10, 2.9718536777886215e-10, 2.9509297075282592e-10, 2.9678727845970005e-10,
    2.9388459452247739e-10, 2.9629422582538255e-10, 2.9409426247509383e-10, 2.9826429134303985e-10,
    2.9606361072764179e-10, 2.9561800716890589e-10, 2.9832538392414461e-10, 2.9676756280597612e-10,
    2.9737760651470619e-10, 2.9596298901519574e-10, 2.9769934914152339e-10, 2.9501623539930046e-10,
    2.9621468614097281e-10, 2.9758013984522667e-10, 2.9542685373353058e-10, 2.9603853411763934e-10,
    2.9411126559915936e-10, 2.9388159017469855e-10, 2.9537991218775213e-10, 2.940717415468097e-10,
    2.9556479634308817e-10, 2.9853132065046923e-10, 2.9593308345694251e-10, 2.960576127401883e-10,
    2.940805343611059e-10, 2.9456274210191936e-10, 2.9545010384483069e-10, 2.9472158254245092e-10,
    2.9397599587099352e-10, 2.9520966319572306e-10, 2.9298653018928171e-10, 2.973842755255117e-10,
    2.979566588600661e-10, 2.9655302566803381e-10, 2.9514189687948467e-10, 2.9739031843277597e-10,
    2.9547722377102513e-10, 2.9633164583298653e-10, 2.9543745854606983e-10, 2.9873789941117153e-10,
    2.9542816537752541e-10, 2.9380272823868931e-10, 2.9564390894749231e-10, 2.9600354272279192e-10,
    2.9298676429091715e-10, 2.9642083264606452e-10, 2.9722908517636796e-10, 2.9595841555591418e-10,
    2.9782503960362712e-10, 2.9600951280279644e-10, 2.9405516246486046e-10, 2.9513234311453511e-10,
    2.9755547897023167e-10, 2.9671205515728659e-10, 2.9650352413169264e-10, 2.9474458832619629e-10,
    2.9727252761278162e-10, 2.9920742453006112e-10, 2.9596173490742531e-10, 2.9471380559362074e-10,
    2.9568493113427896e-10, 2.9735579549406079e-10, 2.9417388062415838e-10, 2.9754022086460282e-10,
    2.9583180526036485e-10, 2.9648448590632098e-10, 2.9654411197440423e-10, 2.9553525510885671e-10,
    2.9484862557437038e-10, 2.9524941247787086e-10, 2.9724177146580129e-10, 2.9674677238609266e-10,
    2.9612462693820038e-10, 2.9564045455240459e-10, 2.9555796913882001e-10, 2.9505708271449651e-10,
    2.9666896473902448e-10, 2.9624335902206591e-10, 2.9478062025459426e-10, 2.9580899743049782e-10,
    2.9439068476753372e-10, 2.9632656191219624e-10, 2.973073249385028e-10, 2.9642589526706394e-10,
    2.4807571857798853e-10, 3.0759086202150407e-10, 3.6952193435365531e-10, 4.3139146135366715e-10,
    4.9037442936254e-10, 5.5240261195660549e-10, 6.1457958671544021e-10, 6.7442778730126245e-10,
    7.3673542702909149e-10, 7.9377209485145042e-10, 8.5638251045856547e-10, 9.1778097786855639e-10,
    9.7828352734261225e-10, 1.0406340564196197e-09, 1.1001787160952975e-09, 1.1615842887086531e-09,
    1.2217609609250922e-09, 1.2834240126485657e-09, 1.34670318813514e-09, 1.4054232773966316e-09,
    1.467118312272227e-09, 1.5251184469377446e-09, 1.5890872162634326e-09, 1.651908893088852e-09,
    1.7097190977296697e-09, 1.7720937631726128e-09, 1.8360207166734327e-09, 1.8934773015186622e-09,
    1.9537247006381041e-09, 2.0134077667426225e-09, 2.0793675591624402e-09, 2.1358858466327323e-09,
    2.1995698965468949e-09, 2.2614519639231277e-09, 2.3220782424270388e-09, 2.3852135984093559e-09,
    2.4446326835156541e-09, 2.5087659387483818e-09, 2.5657174316413853e-09, 2.6272192320796644e-09,
    2.6901490252009465e-09, 2.7488443898578975e-09, 2.8123945315941567e-09, 2.8708733585301866e-09,
    2.932296803323245e-09, 2.9962823681178964e-09, 3.0559151609518664e-09, 3.1165328864533399e-09,
    3.1808400111067815e-09, 3.241622661412382e-09, 3.2989917781899084e-09, 3.3622329420080679e-09,
    3.4236125743978484e-09, 3.4830599536830016e-09, 3.5446222823746738e-09, 3.6088809057468418e-09,
    3.6675024418341412e-09, 3.7304415834521752e-09, 3.7896504312578581e-09, 3.8524060283336308e-09,
    3.9131254120392783e-09, 3.976541710054823e-09, 4.0376245102722934e-09, 4.0980617121523506e-09,
    4.1602144881304887e-09, 4.2186680552090761e-09, 4.2808030831202709e-09, 4.3424979343970435e-09,
    4.4058344565352265e-09, 4.4649790775144795e-09, 4.528257251375475e-09, 4.588497675393219e-09,
    4.6495295460369943e-09, 4.7127860611201821e-09, 4.7720143796982019e-09, 4.8357586672995017e-09,
    4.8969019648966056e-09, 4.9581352281667006e-09, 5.0176764582670938e-09, 5.0805044974409093e-09,
    5.143183556866365e-09, 5.2035043625236855e-09, 5.2631215876280685e-09, 5.3274377293358819e-09,
    5.3896281059954046e-09, 5.4496986997867486e-09, 5.5097332772318937e-09, 5.5725744624275397e-09,
    5.6310613807785351e-09, 5.6931363722273437e-09, 5.7537635205489437e-09, 5.8185470929502559e-09,
    5.8779505293492877e-09, 5.9384342441523875e-09, 6.0033148710404021e-09, 6.062433560412064e-09,
    6.1249473681261825e-09, 6.18669926132024e-09, 6.2477951014156956e-09, 6.307627251114824e-09,
    6.3706977743000559e-09, 6.431964923484391e-09, 6.4932208956431958e-09, 6.5547799657497157e-09,
    6.6180667115951902e-09, 6.6748711644708272e-09, 6.7423088980346769e-09, 6.8013361978752183e-09,
    6.8610094704637683e-09, 6.9215241429481302e-09, 6.9853098616651273e-09, 7.0473717355491617e-09,
    7.1088499247382899e-09, 7.1699650201363995e-09, 7.2302842043075154e-09, 7.2919949294493496e-09,
    7.353223050889003e-09, 7.4155888485710543e-09, 7.4767565714885499e-09, 7.5394950594745569e-09,
    7.5997611601228173e-09, 7.6624241545942221e-09, 7.7226322461335098e-09, 7.7857859222767305e-09,
    7.8470025105083899e-09, 7.9085729676158536e-09, 7.9682767533455985e-09, 8.0303413139397893e-09,
    8.0936981716312099e-09, 8.153909719010977e-09, 8.2166862777100477e-09, 8.2778674758251227e-09,
    8.3397214368573014e-09, 8.4011483348863386e-09, 8.4619018570654419e-09, 8.5244412120078542e-09,
    8.5854962265388242e-09, 8.6504320439267913e-09, 8.7080065269355382e-09, 8.7700226573251507e-09,
    8.8327949231270447e-09, 8.8923133927337611e-09, 8.8914163247233519e-09, 8.8324155948815778e-09,
    8.7693788431957411e-09, 8.7076855390453287e-09, 8.6476929665917455e-09, 8.5859797491885351e-09,
    8.5204505951213806e-09, 8.4585239501902874e-09, 8.3989542717851323e-09, 8.3354288813255731e-09,
    8.2746904196991063e-09, 8.2128023720265917e-09, 8.1511106126120362e-09, 8.0903027927859566e-09,
    8.0267227495363221e-09, 7.9658441505048473e-09, 7.904176690048674e-09, 7.8446759523882261e-09,
    7.7789699964234481e-09, 7.7177822001918497e-09, 7.6576120014479749e-09, 7.5927326076123261e-09,
    7.5339786469814182e-09, 7.4698184245401542e-09, 7.4083739321747981e-09, 7.3489936032801812e-09,
    7.2852938436470682e-09, 7.2241951606569484e-09, 7.1627448229203806e-09, 7.1000856144134756e-09,
    7.0372564202496976e-09, 6.974757472746107e-09, 6.9148910850583506e-09, 6.8518261761056422e-09,
    6.7914530107525554e-09, 6.7278669267700698e-09, 6.6662921939469243e-09, 6.6055701035394463e-09,
    6.543638488737899e-09, 6.4826188085676317e-09, 6.4203420007363574e-09, 6.3593113458190711e-09,
    6.2989611560681034e-09, 6.2376719756222394e-09, 6.1746202655250928e-09, 6.114407633499992e-09,
    6.053065773994875e-09, 5.9906264083674105e-09, 5.9316016702439751e-09, 5.8653721129114575e-09,
    5.8045335725411315e-09, 5.7459543834985874e-09, 5.682889921571369e-09, 5.6198802744263067e-09,
    5.5610259285013932e-09, 5.4998853931163505e-09, 5.4360328701280633e-09, 5.3760064734924878e-09,
    5.3145529671500512e-09, 5.2544042341219167e-09, 5.1916549129568366e-09, 5.1283255033782925e-09,
    5.0681100638503765e-09, 5.005945918729784e-09, 4.946140829910824e-09, 4.8827422679747939e-09,
    4.8236854684553231e-09, 4.7617256371987234e-09, 4.701162965040597e-09, 4.6410500162998936e-09,
    4.574417981592578e-09, 4.5154951813227582e-09, 4.4544193594916421e-09, 4.3901303767368656e-09,
    4.3321265456427626e-09, 4.270962665597696e-09, 4.2085124693934272e-09, 4.1466073077271271e-09,
    4.0846439295748077e-09, 4.0265640767751567e-09, 3.9617482789878995e-09, 3.9026966697434921e-09,
    3.8424522869344225e-09, 3.7801184967923924e-09, 3.7167031058913833e-09, 3.6564895973333735e-09,
    3.5959728859199037e-09, 3.5322617028282406e-09, 3.4717131258542327e-09, 3.4122508454348319e-09,
    3.3529013874191138e-09, 3.2905042590039109e-09, 3.2260943065323844e-09, 3.1632556876839192e-09,
    3.1027151510488294e-09, 3.0428692378845404e-09, 2.9803266583302352e-09, 2.9216549464423355e-09,
    2.8607154555970252e-09, 2.7957927478476921e-09, 2.7361228598625021e-09, 2.6763478469035982e-09,
    2.6123837583940841e-09, 2.5553338535572341e-09, 2.4935521854660349e-09, 2.4316627845974631e-09,
    2.370767773527675e-09, 2.3083588642270968e-09, 2.2442884842346918e-09, 2.1858960869079743e-09,
    2.1219271738851254e-09, 2.0636901128768715e-09, 2.0070127924073751e-09, 1.9416185165036728e-09,
    1.8800950880551942e-09, 1.8198354708930973e-09, 1.7577557883693026e-09, 1.696517451796606e-09,
    1.6346402599055963e-09, 1.5731941183163266e-09, 1.514428954683928e-09, 1.4528250458147648e-09,
    1.3912357972656976e-09, 1.329143672042621e-09, 1.2666501518849544e-09, 1.2094116621789025e-09,
    1.1467928951555078e-09, 1.0863773637326268e-09, 1.0245125755470665e-09, 9.6200409727571648e-10,
    9.0159914456301267e-10, 8.4013664427558934e-10, 7.8094506483544412e-10, 7.2016218555550228e-10,
    6.5720854898678543e-10, 5.96268174009862e-10, 5.3757596224798161e-10, 4.7412313810345016e-10,
    4.1358727667394444e-10, 3.5329630127046543e-10, 2.9154688788475389e-10, 2.3093327752548165e-10,
    1.693523770343415e-10, 1.0797934302254834e-10, 4.8410864198259423e-11, -1.1844702519431053e-11,
    -7.3475274820972738e-11, -1.3219408254156192e-10, -1.9366870290459694e-10, -2.5550446061611753e-10,
    -3.1621396004575022e-10, -3.7710514384660188e-10, -4.401160028022245e-10, -4.9822414036182462e-10,
    -5.597109418830359e-10, -6.207865829276557e-10, -6.8055210442755582e-10, -7.4383868662358641e-10,
    -8.0321288791589923e-10, -8.6288115456621966e-10, -9.236609922495715e-10, -9.8269529328000381e-10,
    -1.0445415026351626e-09, -1.1041618711677188e-09, -1.1657714821466166e-09, -1.2269807925945662e-09,
    -1.2871409727762478e-09, -1.3472266197825943e-09, -1.4077137272840215e-09, -1.4676658278463224e-09,
    -1.5302715723355171e-09, -1.5857557617644367e-09, -1.6477716779323359e-09, -1.7089697671918037e-09,
    -1.7672485619915555e-09, -1.8282713735571567e-09, -1.8887232333214339e-09, -1.9470192017704121e-09,
    -2.0058124602785257e-09, -2.067522263701161e-09, -2.1253419080277053e-09, -2.1835486709593463e-09,
    -2.2421100787379389e-09, -2.3037874410118641e-09, -2.3609622820350172e-09, -2.4252866585432684e-09,
    -2.4781653886815575e-09, -2.5359966875327319e-09, -2.5894620879621829e-09, -2.6421103896640902e-09,
    2.9671076819811635e-10, 2.9524890664287471e-10, 2.9524681033709641e-10, 2.9492463488941321e-10,
    2.9662919093465495e-10, 2.9619019131809918e-10, 2.960976416790908e-10, 2.9440804148952132e-10,
    2.939899358880622e-10, 2.9679241959210984e-10, 2.9601582225183525e-10, 2.9675811900900337e-10,
    2.9743308014205312e-10, 2.9705972287718377e-10, 2.956841997686396e-10, 2.9677551200219867e-10,
    2.948564940169066e-10, 2.9519237593653743e-10, 2.9725108901450651e-10, 2.9433695268193523e-10,
    2.9472523662584112e-10, 2.9401840019125278e-10, 2.963036955720147e-10, 2.9703227384092357e-10,
    2.9728104820253059e-10, 2.9626645387235097e-10, 2.970452140407294e-10, 2.9694964988286351e-10,
    2.923586521401721e-10, 2.9747622039391158e-10, 2.9571613144308251e-10, 2.9386282514143597e-10,
    2.9546591120004188e-10, 2.9977669374300686e-10, 2.9539179583786317e-10, 2.9702891057478057e-10,
    2.9813467817187253e-10, 2.9397838599765421e-10, 2.9552475689472069e-10, 2.9693024165308991e-10,
    2.9502598999681669e-10, 2.9583420918148952e-10, 2.9663560059464056e-10, 2.9693491435899055e-10,
    2.970758885848936e-10, 2.9579424672869354e-10, 2.945504798735443e-10, 2.9796835008876191e-10,
    2.9813579046401961e-10, 2.970648923401159e-10, 2.9672284010825744e-10, 2.9470337498500054e-10,
    2.9316474557658737e-10, 2.9648984576610414e-10, 2.9522558221478915e-10, 2.9571213747855505e-10,
    2.9468409315515816e-10, 2.962739741451663e-10, 2.9437540128382464e-10, 2.9716308435915674e-10,
    2.9502201212755547e-10, 2.9336430212882467e-10, 2.9818370840306903e-10, 2.9635524924767673e-10,
    2.9586417150206142e-10, 2.9544061252181214e-10, 2.9658208509539223e-10, 2.9573986459228389e-10,
    2.9809279179911186e-10, 2.9507500746364218e-10, 2.9695570983195784e-10, 2.9518662462199795e-10,
    2.9734713698016928e-10, 2.9796380853872081e-10, 2.9456227355109515e-10, 2.9668997036937984e-10,
    2.9494198853081685e-10, 2.9508274571895892e-10, 2.9751669415569311e-10, 2.9578359095005163e-10,
    2.9503654652861567e-10, 2.9256489595343615e-10, 2.956170831652175e-10, 2.961587488435905e-10,
    2.9643020411474403e-10, 2.9562699786759612e-10, 2.961417805698442e-10, 2.9659814748933486e-10,
    2.9505895937913698e-10, 2.9086245611539401e-10, 2.9643041478953673e-10, 2.9364937396592634e-10,
    2.9611015945360188e-10, 2.9813919741072768e-10, 2.9443147142995299e-10, 2.9872159145236639e-10,
    2.9587099510198596e-10, 2.9452325847471289e-10, 2.97934388202711e-10, 2.9585773290008837e-10,
    2.9574715834183462e-10, 2.9699695132616824e-10, 3.0042939743541469e-10, 2.9583079570809341e-10,
    2.9539056722048434e-10, 2.9518815922724732e-10, 2.980632072755806e-10, 2.9366501917423425e-10,
    2.9513780886099726e-10, 2.9402700072088448e-10, 2.9632625520229024e-10, 2.9875765645574648e-10,
    2.9713786149226805e-10, 2.9678761594976618e-10, 2.9716444945957567e-10, 2.9367225032715926e-10,
    2.9697274628275642e-10, 2.9592586293978061e-10, 2.9764417068945854e-10, 2.9544306072405295e-10,
    2.9736279359660169e-10, 2.9429648298847957e-10, 2.9535491697680144e-10, 2.9574190215188611e-10,
    2.9675584149947548e-10, 2.9665155017067784e-10, 2.9476890669220581e-10, 2.9446995379036873e-10,
    2.9416673895444524e-10, 2.9723197026825049e-10, 2.962889385784699e-10, 2.9510040497180662e-10,
    2.9483081105956325e-10, 2.9435275596486921e-10, 2.9860526175555167e-10, 2.980743190893503e-10,
    2.9335571256386484e-10, 2.9511306148558217e-10, 2.9526225277892114e-10, 2.9622534497891823e-10,
    2.9736949549872436e-10, 2.9597513094254337e-10, 2.968591830417858e-10, 2.9288744694788461e-10,
    2.9563000441378937e-10, 2.9661058811319556e-10, 2.9610128623953395e-10, 2.9732089103240774e-10,
    2.9555511253573514e-10, 2.9663386666547377e-10, 2.9622771869081705e-10, 2.9562106934885089e-10,
    2.9476915451853809e-10,
};

static void test_written_nm_coarse(void **state)
{
    static const recorded_curve rec[] = {
        {nm1a_z, nm1a_F, 686, {7.4217842253122984e-09, 2396332679.357213, 0.084644143368660121, 0.25667922133670634}},
    };
    (void)state;
    check_recorded(rec, sizeof rec / sizeof rec[0], "z to 0.1 nm");
}

/* One glitch in a noisy pinned top (helper-80, stop 76: one sample 14 % of
 * the pull-off force low ended the straight start, mdr_f_line, and the fit
 * from there took the rest of the pinned top in: E* 1.12 x at 6.7 errors,
 * n_pinned 88 of 581, status ok). The rule: at the top of the file. */
static void test_pinned_glitch(void **state)
{
    enum { n = 400 };
    static const double sizes[4] = {-0.3, -0.14, -0.05, 0.14};
    int r, s, g, pos, npin, n_all = 0, n_ok = 0;
    double worst_dev = 0.0;
    (void)state;
    noise_state = 0x3c6ef372fe94f82bull;
    for (r = 0; r < 3; r++) {
        const jkr_par *p = &regimes[r];
        const mdr_contact_f64 c = paraboloid64(p->R);
        for (s = 0; s < 3; s++) {
            static double Fn[n];
            double Fpo;
            mdr_status st0;
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 res;
            int i;
            pinned_curve(p, 0.5 * p->w, 2.5 * jkr_fold(p), 2e-6, 0.0, n, zs, Fn, &npin, &Fpo);
            for (i = 0; i < n; i++) {
                Fn[i] += GLITCH_SIG * fabs(Fpo) * gauss();
            }
            mdr_fit_defaults_f64(&o, p->km);
            memcpy(Fs, Fn, sizeof Fn);
            st0 = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &res);
            for (g = 0; g < 4; g++) {
                for (pos = 4; pos < npin - 3; pos += 6) {
                    mdr_status st;
                    memcpy(Fs, Fn, sizeof Fn);
                    Fs[pos] += sizes[g] * fabs(Fpo);
                    st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &res);
                    n_all++;
                    if (st != st0) {
                        fail_msg("regime %d, seed %d: a glitch of %g pull-off forces at pinned sample %d of %d: %s, "
                                 "without it %s", r, s, sizes[g], pos, npin, mdr_status_str(st), mdr_status_str(st0));
                    }
                    if (st == MDR_OK) {
                        const double dev = fmax(nerr(res.E, p->E, res.E_err), nerr(res.w, p->w, res.w_err));
                        n_ok++;
                        worst_dev = fmax(worst_dev, dev);
                        if (dev > GLITCH_PULL) {
                            fail_msg("regime %d, seed %d: a glitch of %g pull-off forces at pinned sample %d of %d: "
                                     "E* %.4g x, w %.4g x, %.1f reported errors off, n_pinned %u", r, s, sizes[g], pos,
                                     npin, res.E / p->E, res.w / p->w, dev, (unsigned)res.n_pinned);
                        }
                    }
                }
            }
        }
    }
    print_message("a glitch in a noisy pinned top: %d fits, each with the status of its curve without the glitch; "
                  "%d answered, worst %.2f errors\n", n_all, n_ok, worst_dev);
}
#endif

#ifndef MDR_TARGET_TEST /* (the host's: f64 as the target's, whose f32 fit is the same code) */
/* ---- flaws of measured curves (stop 39) --------------------------------
 * Found by a helper attacking the fit through `mdr fit` with curves flawed
 * as measured ones are. The rule, as test_noise's: an answer (MDR_OK)
 * within 5 reported errors of the truth in ln E* and ln w; a named refusal
 * is no wrong answer. Each test also fits the same curves without the
 * flaw, which must answer (at least half) within the same rule: a fix that
 * refuses everything passes nothing. Open ones (make test-fit-known,
 * built with -DMDR_FIT_KNOWN_DEFECTS; docs/fitting.md) fail until fixed:
 * test_known_curved (test_known_coarse_approach: every answer within 5
 * errors). Every answer's F_slope must also lie within 5 of its
 * errors of the slope the flaw gave the baseline (0 but for a tilt). */

/* A helper's engine path as closed-form curves, noise-free: the base
 * position from -40 nm to 20 nm and back (z0 = 2 um), n samples each way
 * (the top twice: the approach's last and the retract's first), w_adv = w;
 * returns the pull-off force through the lever */
static double span_curve(const jkr_par *p, int n, double *z, double *F)
{
    mdr_contact_f64 c;
    mdr_critstate_f64 cs;
    double pp[3] = {p->R, 0, 0}, as, z0 = 2e-6;
    int i;
    assert_int_equal(mdr_contact_init_f64(&c, MDR_PROFILE_PARABOLOID, pp, p->E, p->w), MDR_OK);
    assert_int_equal(mdr_default_start_f64(&c, &as), MDR_OK);
    assert_int_equal(mdr_critical_f64(&c, MDR_CONTROL_MACHINE, p->km, as, &cs), MDR_OK);
    for (i = 0; i < n; i++) {
        z[i] = z0 - 40e-9 + 60e-9 * i / (n - 1);
        z[n + i] = z0 + 20e-9 - 60e-9 * i / (n - 1);
    }
    assert_int_equal(mdr_fit_model_f64(&c, p->km, z0, 0.0, MDR_FIT_APPROACH, z, (uint32_t)n, F), MDR_OK);
    assert_int_equal(mdr_fit_model_f64(&c, p->km, z0, 0.0, MDR_FIT_RETRACT, z + n, (uint32_t)n, F + n), MDR_OK);
    return cs.F;
}

/* the worst of an answer's two distances from the truth, in its errors */
static double flaw_dev(const jkr_par *p, const mdr_fit_result_f64 *r)
{
    return fmax(nerr(r->E, p->E, r->E_err), nerr(r->w, p->w, r->w_err));
}

/* the curve flawed by flaw(k) = 0 (none) .. 4, then fitted; counts */
/* a flaw: flaw(k) = 0 (none) .. nflaw applied to the curve; returns the
 * slope dF/dz it gave the baseline [N/m] (0: none) */
typedef double (*flaw_fn)(int k, const jkr_par *p, int n, double Fpo, double *z, double *F);
static void flaw_run1(const char *what, flaw_fn flaw, int nflaw, int nseed, double sig, int arith32, int flat)
{
    const jkr_par p = regimes[1]; /* transition: 20 nm tip, E* 1 GPa, w 0.05, 0.2 N/m */
    const int n = arith32 ? 1500 : 400;
    mdr_contact_f64 c = paraboloid64(p.R);
    mdr_contact_f32 c32;
    const float pp[3] = {(float)p.R, 0, 0};
    const uint64_t saved = noise_state;
    int k, s, bad = 0, ok0 = 0, refused = 0;
    double worst_k = 0.0;
    assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
    noise_state = 0x3c6ef372fe94f82bull;
    for (k = 0; k <= nflaw; k++) {
        for (s = 0; s < nseed; s++) {
            mdr_fit_result_f64 r;
            mdr_status st;
            double Ff, dev, sl;
            (void)jkr_z(&p, jkr_fold(&p), &Ff, NULL);
            (void)jkr_grid(&p, n, noise_uniform(), sig, zs, Fs);
            sl = flaw(k, &p, n, fabs(Ff), zs, Fs);
            if (arith32) {
                mdr_fit_opts_f32 o32;
                mdr_fit_result_f32 r32;
                curve32(n);
                mdr_fit_defaults_f32(&o32, (float)p.km);
                o32.unpinned = 1;
                o32.flat = (uint8_t)flat;
                st = mdr_fit_curve_f32(&c32, &o32, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r32);
                r.E = r32.E, r.E_err = r32.E_err, r.w = r32.w, r.w_err = r32.w_err;
                r.F_slope = r32.F_slope, r.F_slope_err = r32.F_slope_err;
            } else {
                mdr_fit_opts_f64 o;
                mdr_fit_defaults_f64(&o, p.km);
                o.unpinned = 1;
                o.flat = (uint8_t)flat;
                st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            }
            if (st != MDR_OK) {
                refused += k > 0;
                continue;
            }
            /* the baseline's slope too, against the flaw's (0 but for a tilt) */
            dev = flaw_dev(&p, &r);
            if (!flat) {
                assert_true(r.F_slope_err > 0.0);
                dev = fmax(dev, fabs(r.F_slope - sl) / r.F_slope_err);
            } else {
                assert_true(r.F_slope == 0.0 && r.F_slope_err == 0.0);
            }
            if (k == 0) {
                ok0 += dev <= 5.0;
                continue;
            }
            worst_k = dev > worst_k ? dev : worst_k;
            if (dev > 5.0) {
                print_message("%s, flaw %d, seed %d: ok, E* %.4g x, w %.4g x the truth, slope %.3g N/m (truth %.3g), "
                              "%.1f errors off\n", what, k, s, r.E / p.E, r.w / p.w, r.F_slope, sl, dev);
                bad++;
            }
        }
    }
    noise_state = saved;
    print_message("%s (%d samples %.3g m apart, %s): of %d flawed curves %d refused, %d answers beyond 5 errors "
                  "(worst %.1f); unflawed within 5: %d of %d\n", what, n, (zs[0] - zs[n - 1]) / (n - 1),
                  flat ? "flat baseline" : "slope fitted", nflaw * nseed, refused, bad, worst_k, ok0, nseed);
    assert_true(2 * ok0 >= nseed);
    assert_int_equal(bad, 0);
}

/* flaw_run1 with the slope fitted and, flat_too, with the baseline held
 * flat (opts.flat) on the same curves: the flat model's tight errors show
 * a flaw the slope's larger ones cover (a tether's step in the free tail
 * is partly a slope: fit-sigma-trim survived the slope's fits alone) */
static void flaw_run(const char *what, flaw_fn flaw, int nflaw, int nseed, double sig, int arith32, int flat_too)
{
    flaw_run1(what, flaw, nflaw, nseed, sig, arith32, 0);
    if (flat_too) {
        flaw_run1(what, flaw, nflaw, nseed, sig, arith32, 1);
    }
}

/* A tilted baseline (an interferometric or virtual-deflection slope, as
 * raw AFM data carry before it is subtracted): F + t |F_po| (z - zmid) /
 * span, t = -5 %, -2 %, 2 %, 5 % of the pull-off force over the curve,
 * noise 0.3 %, 400 samples, 4 seeds each; the fitted F_slope within 5 of
 * its errors of t |F_po|/span. Before (stop 40: the model's baseline
 * flat, and the rms misfit test allows thr, 6 noise widths) 16 of 16
 * answers 11 to 34 errors off (E* 0.73 to 1.48 x the truth); the helper's
 * curves through `mdr fit --approach` 10 to 150. Now the slope is a
 * parameter: measured 16 of 16 answered, the worst 2.1 errors. */
/* the baseline bent by a = flaw_amp[k] of |F_po|, u = (z - zmid)/span:
 * power 1 a tilt, a |F_po| u (a |F_po| per span); power 2 a bow,
 * 4 a |F_po| u^2 (a |F_po| between the middle and the ends). Returns the
 * slope it gives the baseline: the tilt's, 0 for the bow (even in u). */
static const double flaw_amp[5] = {0.0, -0.05, -0.02, 0.02, 0.05};
static double flaw_bend(int k, int power, int n, double Fpo, double *z, double *F)
{
    const double mid = 0.5 * (z[0] + z[n - 1]), span = z[0] - z[n - 1];
    int i;
    for (i = 0; i < n; i++) {
        const double u = (z[i] - mid) / span;
        F[i] += power == 1 ? flaw_amp[k] * Fpo * (z[i] - mid) / span : 4.0 * flaw_amp[k] * Fpo * u * u;
    }
    return power == 1 ? flaw_amp[k] * Fpo / span : 0.0;
}

static double flaw_tilt(int k, const jkr_par *p, int n, double Fpo, double *z, double *F)
{
    (void)p;
    return flaw_bend(k, 1, n, Fpo, z, F);
}

static void test_tilt(void **state)
{
    (void)state;
    flaw_run("tilted baseline", flaw_tilt, 4, 4, 3e-3, 0, 0);
}

#ifndef MDR_TARGET_TEST
/* Coarse curves with a pinned top (pinned_curve: the closed forms, libm),
 * fitted: regimes[1] through 0.2 and 2 N/m, w_adv/w ratios[], tops of 1.5,
 * 2.5 and 4 fold radii, ns[] samples (a retract, or with approach the
 * approach branch of w_adv from the retract's lowest z to its top, then
 * the retract: ns[] samples each, opts.approach), noise 0.3 % and 1 % of
 * the pull-off force, 6 copies each; without the approach the first copy
 * noise-free, which must answer within TOL_RT_CF of the truth or 5 of its
 * errors (a misfit's), or refuse. Tallies the answers, the refusals by
 * status, and the worst noisy answer in reported errors (printing those
 * beyond 5). test_coarse_pinned, test_known_coarse_approach. */
typedef struct {
    int n_ok, n_nf, n_st[64]; /* answered (noise-free among them); refused, by -status */
    int n_bad;                /* noisy answers beyond 5 reported errors */
    double worst;
} coarse_sweep_t;

static void coarse_sweep(const double *ratios, int nrat, const int *ns, int nns, int approach, coarse_sweep_t *o)
{
    static const double tops[3] = {1.5, 2.5, 4.0}, sigs[2] = {3e-3, 1e-2}, kms[2] = {0.2, 2.0};
    int kk, a, b, k, t, s, i;
    memset(o, 0, sizeof *o);
    for (kk = 0; kk < 2; kk++) {
        for (a = 0; a < nns; a++) {
            for (b = 0; b < 2; b++) {
                for (k = 0; k < nrat; k++) {
                    for (t = 0; t < 3; t++) {
                        for (s = 0; s < 6; s++) {
                            jkr_par p = regimes[1];
                            const mdr_contact_f64 c = paraboloid64(p.R);
                            const int n = ns[a], na = approach ? n : 0;
                            const bool nf = s == 0 && !approach;
                            mdr_fit_opts_f64 op;
                            mdr_fit_result_f64 r;
                            double Fpo, dev;
                            int npin;
                            mdr_status st;
                            p.km = kms[kk];
                            (void)pinned_curve(&p, ratios[k] * p.w, tops[t] * jkr_fold(&p), 2e-6, 0.0, n, zs + na,
                                               Fs + na, &npin, &Fpo);
                            if (approach) {
                                mdr_contact_f64 ca;
                                double pp[3] = {p.R, 0, 0};
                                for (i = 0; i < n; i++) {
                                    zs[i] = zs[2 * n - 1] + (zs[n] - zs[2 * n - 1]) * i / (n - 1);
                                }
                                assert_int_equal(
                                    mdr_contact_init_f64(&ca, MDR_PROFILE_PARABOLOID, pp, p.E, ratios[k] * p.w), MDR_OK);
                                assert_int_equal(
                                    mdr_fit_model_f64(&ca, p.km, 2e-6, 0.0, MDR_FIT_APPROACH, zs, (uint32_t)n, Fs),
                                    MDR_OK);
                            }
                            for (i = 0; i < na + n; i++) {
                                Fs[i] += nf ? 0.0 : sigs[b] * fabs(Fpo) * gauss();
                            }
                            mdr_fit_defaults_f64(&op, p.km);
                            op.approach = (uint8_t)approach;
                            st = mdr_fit_curve_f64(&c, &op, zs, Fs, (uint32_t)(na + n), work64, 2 * NMAX, &r);
                            if (st != MDR_OK) {
                                o->n_st[st < 0 && st > -64 ? -st : 0]++;
                                continue;
                            }
                            o->n_ok++;
                            dev = flaw_dev(&p, &r);
                            if (nf) { /* noise-free: to rounding, or within its errors (a misfit's) */
                                const double e = fmax(fabs(r.E / p.E - 1.0), fabs(r.w / p.w - 1.0));
                                o->n_nf++;
                                if (!(e <= TOL_RT_CF) && !(dev <= 5.0)) {
                                    fail_msg("noise-free coarse pinned top: k_m %g, %d samples, w_adv/w %.2f, top "
                                             "%.1f: E* %.6f x, w %.6f x, %.1f errors off",
                                             kms[kk], n, ratios[k], tops[t], r.E / p.E, r.w / p.w, dev);
                                }
                                continue;
                            }
                            o->n_bad += dev > 5.0;
                            if (dev > 5.0) {
                                print_message("  coarse pinned top%s: k_m %g, %d samples, noise %g, w_adv/w %.2f, top "
                                              "%.1f, seed %d (%d pinned, %u left out): E* %.3f x, w %.3f x, w_adv "
                                              "%.3f w +- %.3f, %.1f errors off\n",
                                              approach ? " with the approach" : "", kms[kk], n, sigs[b], ratios[k],
                                              tops[t], s, npin, r.n_pinned, r.E / p.E, r.w / p.w, r.w_adv / p.w,
                                              r.w_adv_err / p.w, dev);
                            }
                            o->worst = fmax(o->worst, dev);
                        }
                    }
                }
            }
        }
    }
}

/* coarse_sweep's curves with the approach fitted: w_adv/w 0.5 to 0.95, 40,
 * 60 and 100 samples a branch (test_coarse_approach,
 * test_known_coarse_approach) */
static void coarse_approach_sweep(coarse_sweep_t *o)
{
    static const double ratios[5] = {0.5, 0.7, 0.8, 0.9, 0.95};
    static const int ns[3] = {40, 60, 100};
    const uint64_t saved = noise_state;
    noise_state = 0x7654321ull;
    coarse_sweep(ratios, 5, ns, 3, 1, o);
    print_message("coarse curves with a pinned top and the approach: %d of 1080 answered, %d beyond 5 errors (worst "
                  "%.2f)\n",
                  o->n_ok, o->n_bad, o->worst);
    noise_state = saved;
}
#endif

#ifdef MDR_FIT_KNOWN_DEFECTS
/* Coarse curves with a pinned top, the approach fitted (open, stop 59):
 * pinned_curve's retract (regimes[1], w_adv/w 0.5 to 0.95, tops of 1.5,
 * 2.5 and 4 fold radii, n samples) after the approach branch with w_adv
 * from its lowest z to its top (n samples), 0.2 and 2 N/m, n = 40, 60,
 * 100, noise 0.3 % and 1 % of the pull-off force, 6 seeds each (1 080
 * curves). Through 2 N/m, 40 samples a branch, 1 % noise, w_adv = w/2, a
 * top of 1.5 fold radii (19 of 40 retract samples pinned), the fit sees no
 * pinned top and answered E* 1.69 and 1.59 x the truth (7.0 and 5.8
 * errors; since the approach's own E* is checked, MDR_F_APP_EPULL, the
 * first is refused): the approach's w_adv, fitted with E* held at the retract's
 * answer, comes out 0.875 and 0.90 w (truth 0.5 w) and so rules the
 * pinned top out; without the approach those curves are refused
 * MDR_E_PINNED. Measured the same before stop 59. Fails until fixed:
 * every answer within 5 reported errors (the known defects' rule). */
static void test_known_coarse_approach(void **state)
{
    coarse_sweep_t o;
    (void)state;
    coarse_approach_sweep(&o);
    assert_true(o.worst <= 5.0);
}

/* A curved baseline (open, stop 40): F + c |F_po| 4 ((z - zmid)/span)^2,
 * c = -5 %, -2 %, 2 %, 5 % of the pull-off force between the middle and
 * the ends of the curve (a baseline bent by long-range forces or optics),
 * noise 1 %, 400 samples, 4 seeds each. The model's baseline is a line:
 * measured 9 of 16 refused, 2 answered 5.1 and 5.5 errors off (E* 2.5 and
 * 2.7 x the truth); a helper's whole curves (5 % over 80 nm, 1 % noise)
 * 40 of 40 answered, E* up to 2.86 x, about 8 errors off. */
static double flaw_curve(int k, const jkr_par *p, int n, double Fpo, double *z, double *F)
{
    (void)p;
    return flaw_bend(k, 2, n, Fpo, z, F);
}

static void test_known_curved(void **state)
{
    (void)state;
    flaw_run("curved baseline", flaw_curve, 4, 4, 1e-2, 0, 0);
}

#endif

#ifndef MDR_TARGET_TEST
/* Coarse curves without hysteresis (stop 50, a helper's engine curves):
 * regimes[1] through a 2 N/m lever (mu ~ 1.2), w_adv = w, span_curve's
 * path with n samples a branch and noise sig of the pull-off force (rows:
 * 51 and 0.3 %, 26 and 0.3 %, 51 and 1 %), 30 seeds each. The noise makes
 * the receding branch's top look straight (mdr_f_line), and that start
 * leaves fewer than MDR_FIT_MIN_RECEDE samples below it. Before stop 51
 * the default fit left it out as a pinned top: measured 7 of 30 beyond
 * 3.2 errors (worst 4.4), 16 of 26 (worst 25.4), 2 of 6 (worst 18.4); from
 * stop 51 to 58 it refused every curve MDR_E_FEW ("too few points"), with
 * the approach fitted too (measured with the approach: 0, 4 and 21 of 30
 * answered). Now the retract is fitted from its top there, and as a
 * pinned top may hide in the noise the default fit refuses MDR_E_PINNED
 * (named: fit with the approach, or state unpinned); with the approach
 * (w_adv within its errors of w) the curves are answered (measured 30 of
 * 30 in each row, worst 2.1, 4.3 and 2.6 errors), and with
 * every sample (opts.unpinned) 30 of 30 (the same). Tolerances: 5
 * reported errors (the flaw tests' rule); at least 25 of 30 refusals of
 * the default fit MDR_E_PINNED (measured 30; MDR_E_FEW allowed: a pinned
 * top the refits find); at least 27 of 30 answered with the approach
 * (measured 30). */
typedef struct {
    int n_ok, n_bad; /* answered; beyond 5 errors */
    double worst;
} coarse_tally;

static void test_coarse_top(void **state)
{
    static const struct {
        int n;
        double sig;
    } rows[3] = {{51, 3e-3}, {26, 3e-3}, {51, 1e-2}};
    jkr_par p = regimes[1];
    mdr_contact_f64 c = paraboloid64(p.R);
    int k;
    (void)state;
    p.km = 2.0;
    noise_state = 0x243f6a8885a308d3ull;
    for (k = 0; k < 3; k++) {
        /* the default fit, with every sample (unpinned), with the approach */
        coarse_tally t[3] = {{0, 0, 0.0}, {0, 0, 0.0}, {0, 0, 0.0}};
        int s, n_pin = 0, v;
        for (s = 0; s < 30; s++) {
            const int n = rows[k].n;
            const double Fpo = span_curve(&p, n, zs, Fs);
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            int i;
            for (i = 0; i < 2 * n; i++) {
                Fs[i] += rows[k].sig * fabs(Fpo) * gauss();
            }
            for (v = 0; v < 3; v++) {
                mdr_status st;
                mdr_fit_defaults_f64(&o, p.km);
                o.unpinned = (uint8_t)(v == 1);
                o.approach = (uint8_t)(v == 2);
                st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)(2 * n), work64, 2 * NMAX, &r);
                if (st == MDR_OK) {
                    const double dev = flaw_dev(&p, &r);
                    t[v].n_ok++;
                    t[v].n_bad += dev > 5.0;
                    t[v].worst = fmax(t[v].worst, dev);
                } else if (v == 0 && st != MDR_E_PINNED && st != MDR_E_FEW) {
                    fail_msg("coarse curve, %d samples, noise %g, seed %d: %s (MDR_E_PINNED, MDR_E_FEW or an answer "
                             "expected)",
                             n, rows[k].sig, s, mdr_status_str(st));
                } else if (v == 1 || (v == 2 && st != MDR_E_FEW)) {
                    fail_msg("coarse curve, %d samples, noise %g, seed %d, %s: %s", n, rows[k].sig, s,
                             v == 1 ? "unpinned" : "approach", mdr_status_str(st));
                }
                n_pin += v == 0 && st == MDR_E_PINNED;
            }
        }
        print_message("coarse curves, no hysteresis, %d samples a branch, noise %g: default %d of 30 answered (%d "
                      "MDR_E_PINNED), worst %.1f errors; unpinned %d answered, worst %.1f; approach %d answered, "
                      "worst %.1f\n",
                      rows[k].n, rows[k].sig, t[0].n_ok, n_pin, t[0].worst, t[1].n_ok, t[1].worst, t[2].n_ok,
                      t[2].worst);
        for (v = 0; v < 3; v++) {
            assert_int_equal(t[v].n_bad, 0);
        }
        assert_true(n_pin >= 25); /* (MDR_E_FEW: the split explains the curve better, the noise's luck) */
        assert_int_equal(t[1].n_ok, 30);
        assert_true(t[2].n_ok >= 27);
    }
}

/* test_known_coarse_approach's curves as a guard of what is fixed: the
 * approach rules a pinned top out only where its own E* agrees with the
 * retract's (MDR_F_APP_EPULL). Measured: 557 of 1 080 answered, 1 beyond 5
 * errors (5.78: the known defect); without that check 558 and 2 (7.0 and
 * 5.8). Tolerances: at most 1 answer beyond 5 errors, none beyond 6. */
static void test_coarse_approach(void **state)
{
    coarse_sweep_t o;
    (void)state;
    coarse_approach_sweep(&o);
    assert_true(o.n_bad <= 1 && o.worst <= 6.0);
}

/* Real pinned tops on coarse curves, the rival of test_coarse_top
 * (pinned_curve: the closed forms, libm): regimes[1] through 0.2 and 2
 * N/m, w_adv/w 0, 0.3, 0.6, 0.9, tops of 1.5, 2.5 and 4 fold radii, 40,
 * 60, 100 and 200 samples, noise 0.3 % and 1 % of the pull-off force, 6
 * copies each, the first noise-free (1 152 curves), the default fit. Where
 * the straight start leaves too few receding samples, a fit from the top
 * that answered whenever no pinned top was evidenced gave 11 of 72 (2
 * N/m, 200 samples, 1 %) up to 9.7 errors off (E* 1.5 x: up to 123 of 200
 * samples pinned, hidden in the noise), 4 of 72 at 40 samples, 0.3 %, up
 * to 11.3. The refusals: MDR_E_FEW where the fit from the top misses the
 * samples (measured 61 MDR_E_FEW, 20 MDR_E_MISFIT of the fit's other
 * checks; 0 and 81 where that miss was reported as a misfit).
 * Tolerances: every noisy answer within 5 reported errors, a
 * noise-free one within TOL_RT_CF of the truth or 5 of its errors (two
 * pinned tops of 2 and 3 samples are not seen: E* or w 1 % off, 1.5 and
 * 0.9 errors); at least 250 of the 960 noisy curves answered (measured
 * 291, the same as before the fit from the top). */
static void test_coarse_pinned(void **state)
{
    static const double ratios[4] = {0.0, 0.3, 0.6, 0.9};
    static const int ns[4] = {40, 60, 100, 200};
    coarse_sweep_t o;
    int i;
    (void)state;
    noise_state = 0x1234567ull;
    coarse_sweep(ratios, 4, ns, 4, 0, &o);
    print_message("coarse curves with a pinned top: %d of 960 noisy ones answered, worst %.2f errors; %d of 192 "
                  "noise-free\n",
                  o.n_ok - o.n_nf, o.worst, o.n_nf);
    for (i = 1; i < 64; i++) {
        if (o.n_st[i] > 0) {
            print_message("  refused %s: %d\n", mdr_status_str((mdr_status)-i), o.n_st[i]);
        }
    }
    assert_true(o.worst <= 5.0);
    assert_true(o.n_ok - o.n_nf >= 250);
    /* (a pinned top the fit from the top misses: MDR_E_FEW, not a misfit) */
    assert_true(o.n_st[-MDR_E_FEW] >= 40 && o.n_st[-MDR_E_MISFIT] <= 30);
}

/* A dwell at the top: DWELL_N rows at the largest z between the approach's
 * last sample and the retract's first (a piezo held at its turning point,
 * recorded), span_curve's path (regimes[1], w_adv = w, 1 000 samples a
 * branch) with noise 0.3 % of
 * the pull-off force, through the 0.2 N/m lever (the rows noise alone)
 * and a 2 N/m lever (the force relaxing by 5 % of the pull-off over the
 * dwell, the retract's first sample not), DWELL_SEEDS seeds each, fitted
 * with the approach. The dwell is one state: the approach ends at its
 * first row (n_approach the approach's samples), and w_adv comes out
 * within 3.2 reported errors (the retract's E* and w too), at least 8 of
 * 10 answered. Measured before the fix (the rows fitted into the
 * approach, each weighing the top state again; a helper's engine curves):
 * noise alone w_adv +4 errors, 7.5 at worst, 5 of 18 beyond 3; relaxing,
 * 8 to 10 errors. Tolerances: 3.2 reported errors (docs/fitting.md's
 * scatter of the estimates). */
#define DWELL_N 100
#define DWELL_PTS 1000
#define DWELL_SEEDS 10
static void test_dwell(void **state)
{
    int k;
    (void)state;
    noise_state = 0x13198a2e03707344ull;
    for (k = 0; k < 2; k++) {
        jkr_par p = regimes[1];
        const double creep = k == 0 ? 0.0 : 0.05;
        mdr_contact_f64 c = paraboloid64(p.R);
        int s, n_ok = 0;
        double worst = 0.0;
        p.km = k == 0 ? 0.2 : 2.0;
        for (s = 0; s < DWELL_SEEDS; s++) {
            const int na = DWELL_PTS, nr = DWELL_PTS, n = na + DWELL_N + nr;
            double Fpo, dev;
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            mdr_status st;
            int i;
            double Ftop;
            Fpo = span_curve(&p, na, zs, Fs);
            Ftop = Fs[na - 1];
            for (i = 0; i < na + nr; i++) { /* (the curve's noise first: the same with any dwell) */
                Fs[i] += 3e-3 * fabs(Fpo) * gauss();
            }
            for (i = na + nr - 1; i >= na; i--) { /* the retract moved past the dwell */
                zs[i + DWELL_N] = zs[i];
                Fs[i + DWELL_N] = Fs[i];
            }
            for (i = 0; i < DWELL_N; i++) {
                zs[na + i] = zs[na - 1];
                Fs[na + i] = Ftop - creep * fabs(Fpo) * (i + 1) / DWELL_N + 3e-3 * fabs(Fpo) * gauss();
            }
            assert_true(zs[na - 1] == zs[na + DWELL_N]); /* (span_curve: the top twice) */
            mdr_fit_defaults_f64(&o, p.km);
            o.approach = 1;
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            if (st != MDR_OK) {
                print_message("  dwell, lever %g N/m, seed %d: %s\n", p.km, s, mdr_status_str(st));
                continue;
            }
            n_ok++;
            assert_int_equal(r.n_approach, na);
            dev = fmax(flaw_dev(&p, &r), nerr(r.w_adv, p.w, r.w_adv_err));
            if (dev > 3.2) {
                print_message("  dwell, lever %g N/m, seed %d: E* %.4g x, w %.4g x, w_adv %.4g x, %.1f errors off\n",
                              p.km, s, r.E / p.E, r.w / p.w, r.w_adv / p.w, dev);
            }
            worst = fmax(worst, dev);
        }
        print_message("dwell of %d rows at the top, lever %g N/m, relaxing %g of the pull-off: %d of %d answered, "
                      "worst %.2f errors\n", DWELL_N, p.km, creep, n_ok, DWELL_SEEDS, worst);
        assert_true(n_ok >= 8);
        assert_true(worst <= 3.2);
    }
}

/* w_adv at its bound: a helper's curves without hysteresis (w_adv = w)
 * through a lever stiffer than at the dwell, where the retract's noise
 * shows a false pinned top that moves the held E* and z0 and the approach's
 * w_adv runs toward 0. s = sqrt(w_adv) = 0 is a stationary point of every
 * approach cost (the force at fixed z is Hertz's to first order in w_adv):
 * once projected onto it the fit stayed there, w_adv = 0 +- 0 with the
 * truth many errors away. The curve: the library's model (span_curve's
 * mdr_fit_model_f64) over the helper's z' range, 1 999 samples a branch,
 * Gaussian noise of 0.77 % and a baseline of -1 % and a tilt of -2.7 % of
 * the pull-off force. */
#define WADV_SEEDS 40
static void test_wadv_bound(void **state)
{
    const jkr_par p = {1.1724835271931731e-06, 258141221.2102252, 0.13875230321587065, 2.5733658037794167};
    const int n = 1999;
    const double z0 = 2e-6, zlo = -3.898124767575308e-06, zhi = 4.317381497895708e-06;
    mdr_contact_f64 c = paraboloid64(p.R), cm;
    mdr_critstate_f64 cs;
    double pp[3] = {p.R, 0, 0}, as, worst = 0.0;
    int s, i, at_bound = 0, n_ok = 0;
    (void)state;
    assert_int_equal(mdr_contact_init_f64(&cm, MDR_PROFILE_PARABOLOID, pp, p.E, p.w), MDR_OK);
    assert_int_equal(mdr_default_start_f64(&cm, &as), MDR_OK);
    assert_int_equal(mdr_critical_f64(&cm, MDR_CONTROL_MACHINE, p.km, as, &cs), MDR_OK);
    for (i = 0; i < n; i++) {
        zs[i] = z0 + zlo + (zhi - zlo) * i / (n - 1);
        zs[2 * n - 1 - i] = zs[i];
    }
    noise_state = 0x243f6a8885a308d3ull;
    for (s = 0; s < WADV_SEEDS; s++) {
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        mdr_status st;
        const double Fpo = fabs(cs.F);
        double dev;
        assert_int_equal(mdr_fit_model_f64(&cm, p.km, z0, 0.0, MDR_FIT_APPROACH, zs, (uint32_t)n, Fs), MDR_OK);
        assert_int_equal(mdr_fit_model_f64(&cm, p.km, z0, 0.0, MDR_FIT_RETRACT, zs + n, (uint32_t)n, Fs + n),
                         MDR_OK);
        for (i = 0; i < 2 * n; i++) {
            Fs[i] += Fpo * (-0.00994869684175441 - 0.027408803961932682 * (zs[i] - z0) / (zhi - zlo) +
                            0.007695096447905933 * gauss());
        }
        mdr_fit_defaults_f64(&o, p.km);
        o.approach = 1;
        st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)(2 * n), work64, 2 * NMAX, &r);
        if (st != MDR_OK) {
            print_message("  w_adv bound, seed %d: %s\n", s, mdr_status_str(st));
            continue;
        }
        n_ok++;
        dev = fabs(r.w_adv - p.w) / r.w_adv_err; /* (not nerr's logarithm: w_adv near 0) */
        if (!(r.w_adv_err > 0.0) || !(dev <= 5.0)) {
            print_message("  w_adv bound, seed %d: w_adv %.4g +- %.3g (truth %.4g), %u pinned\n", s, r.w_adv,
                          r.w_adv_err, p.w, r.n_pinned);
        }
        assert_true(r.w_adv_err > 0.0);
        worst = fmax(worst, dev);
        at_bound += r.w_adv < 1e-2 * p.w;
    }
    print_message("w_adv at its bound: %d of %d answered, %d at the bound, worst %.2f errors\n", n_ok, WADV_SEEDS,
                  at_bound, worst);
    assert_true(n_ok >= WADV_SEEDS / 2);
    assert_true(worst <= 5.0);
    assert_true(at_bound >= 1);
}

/* Few receding samples after a pinned top: a helper's retracts (w_adv = 0,
 * R 8 nm, E* 5.6 MPa, w 0.19, a lever 20 x stiffer than the contact) whose
 * pinned part ends a few samples above the pull-off. Fitted from 4 to 12
 * samples near the fold (F ~ sqrt(z' - z'_fold)), 1 to 6 of about 22
 * answers were 7.6 to 23 errors off, status ok; now MDR_E_FEW below
 * MDR_FIT_MIN_RECEDE (pinned_curve: the closed forms, libm). */
#define RECEDE_SEEDS 20
static void test_few_receding(void **state)
{
    static const double tops[6] = {0.55, 0.63, 0.8, 1.0, 1.5, 2.5};
    const jkr_par p = {8e-9, 5.57e6, 0.19, 2.44};
    const int n = 185;
    mdr_contact_f64 c = paraboloid64(p.R);
    double Ff, worst = 0.0;
    int t, s, i, n_ok = 0, n_few = 0, n_long = 0;
    (void)state;
    (void)jkr_z(&p, jkr_fold(&p), &Ff, NULL);
    noise_state = 0x452821e638d01377ull;
    for (t = 0; t < 6; t++) {
        /* the top: the Hertz approach (w_adv = 0) at tops[t] |F_fold| */
        const double at = cbrt(3 * p.R * tops[t] * fabs(Ff) / (4 * p.E));
        for (s = 0; s < RECEDE_SEEDS; s++) {
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            mdr_status st;
            double Fpo, dev;
            int npin, last = pinned_curve(&p, 0.0, at, 2e-6, 0.0, n, zs, Fs, &npin, &Fpo);
            for (i = 0; i < n; i++) {
                Fs[i] += 0.0035 * fabs(Fpo) * gauss();
            }
            mdr_fit_defaults_f64(&o, p.km);
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            if (st != MDR_OK) {
                n_few += st == MDR_E_FEW;
                continue;
            }
            n_ok++;
            n_long += t >= 4;
            dev = flaw_dev(&p, &r);
            if (dev > 5.0) {
                print_message("  few receding, top %.2f, seed %d: %d receding of %d contact, E* %.3g x, w %.3g x, "
                              "%.1f errors off\n", tops[t], s, last + 1 - npin, last + 1, r.E / p.E, r.w / p.w, dev);
            }
            worst = fmax(worst, dev);
        }
    }
    print_message("few receding samples after a pinned top: %d of %d answered (%d MDR_E_FEW; tops of 1.5 and 2.5 "
                  "pull-off forces: %d of %d answered), worst %.2f errors\n",
                  n_ok, 6 * RECEDE_SEEDS, n_few, n_long, 2 * RECEDE_SEEDS, worst);
    assert_true(worst <= 5.0);
    assert_true(n_long >= RECEDE_SEEDS);
    /* every refusal names the cause: the short receding branch (noisy: the
     * fit from the top misses the samples, MDR_E_FEW, not MDR_E_MISFIT;
     * mutation fit-top-misfit) */
    assert_int_equal(n_few + n_ok, 6 * RECEDE_SEEDS);
}

/* Few receding samples after a pinned top, noise-free: the straight start
 * (mdr_f_line) leaves fewer than MDR_FIT_MIN_RECEDE samples below it, a
 * pinned top, refused (MDR_E_FEW where the line sees it; MDR_E_PINNED or
 * MDR_E_MISFIT where the pinned part reaches the pull-off's samples); until
 * stop 76 the fit then started from the top, took the pinned samples in
 * and saw no pinned top: helper-80's curve, 39 pinned and 15 receding
 * samples, E* 1.22 x at 13 errors, n_pinned 0, status ok, f64 and f32.
 * With more, f64 answers exactly (TOL_RT_CF); the library's own f32 fit
 * still misses some such pinned tops (a known defect, docs/fitting.md: the
 * CLI and the Python package refuse those answers against f64's), so f32
 * is held to the refusal alone. */
static void test_few_receding_clean(void **state)
{
    static const double tops[2][4] = {{0.55, 0.8, 1.5, 2.5}, {2.0, 4.0, 5.63, 8.0}};
    static const int ns[4] = {40, 70, 100, 185};
    const jkr_par ps[2] = {{8e-9, 5.57e6, 0.19, 2.44}, {1.8e-8, 1.04e10, 0.00373, 0.115}};
    int m, t, k, f, i, a, n_short = 0, n_refused = 0, n_few = 0, n_ok = 0;
    double worst = 0.0;
    (void)state;
    for (m = 0; m < 2; m++) {
        const jkr_par *p = &ps[m];
        mdr_contact_f64 c = paraboloid64(p->R);
        mdr_contact_f32 c32;
        const float pp[3] = {(float)p->R, 0, 0};
        double Ff;
        assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
        (void)jkr_z(p, jkr_fold(p), &Ff, NULL);
        for (t = 0; t < 4; t++) {
            const double at = cbrt(3 * p->R * tops[m][t] * fabs(Ff) / (4 * p->E));
            for (k = 0; k < 8; k++) {
                /* pinned_curve's free tail (0.4 of the contact part's z
                 * span), or 16 spans (helper-80's: few samples in contact) */
                double Fpo;
                int npin, last = pinned_curve(p, 0.0, at, 2e-6, 0.0, ns[k % 4], zs, Fs, &npin, &Fpo), n = ns[k % 4];
                const int rec = last + 1 - npin;
                for (f = k < 4 ? 0 : (int)(15.6 * (n - 1) / 1.4), i = n; i < n + f; i++) {
                    zs[i] = zs[i - 1] - (zs[0] - zs[1]);
                    Fs[i] = 0.0;
                }
                n += f;
                curve32(n);
                for (a = 0; a < 2; a++) {
                    mdr_status st;
                    double E, w;
                    if (a == 0) {
                        mdr_fit_opts_f64 o;
                        mdr_fit_result_f64 r;
                        mdr_fit_defaults_f64(&o, p->km);
                        st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
                        E = r.E, w = r.w;
                    } else {
                        mdr_fit_opts_f32 o;
                        mdr_fit_result_f32 r;
                        mdr_fit_defaults_f32(&o, (float)p->km);
                        st = mdr_fit_curve_f32(&c32, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r);
                        E = r.E, w = r.w;
                    }
                    if (rec < MDR_FIT_MIN_RECEDE) {
                        n_short++;
                        n_refused += st != MDR_OK;
                        if (st == MDR_OK) {
                            print_message("  few receding, noise-free, E* %.3g, top %.2f, %d samples (%s): %d of %d "
                                          "pinned, %d receding, answered: E* %.4g x, w %.4g x\n", p->E, tops[m][t], n,
                                          a ? "f32" : "f64", npin, last + 1, rec, E / p->E, w / p->w);
                        } else if (a == 0) {
                            n_few += st == MDR_E_FEW;
                        }
                    } else if (a == 0 && st == MDR_OK) {
                        n_ok++;
                        worst = fmax(worst, fmax(fabs(E / p->E - 1), fabs(w / p->w - 1)));
                    }
                }
            }
        }
    }
    print_message("few receding samples, noise-free: %d of %d fits with fewer than %d receding refused (f64: %d "
                  "MDR_E_FEW); f64 answers %d of the others, worst %.2g\n", n_refused, n_short, MDR_FIT_MIN_RECEDE,
                  n_few, n_ok, worst);
    assert_int_equal(n_refused, n_short);
    assert_true(n_short >= 8);
    assert_true(n_ok >= 8);
    assert_true(worst <= TOL_RT_CF);
}
#endif

/* The same tilts on whole curves in time order (order_curve: regimes[1],
 * NORDER_PTS + NORDER_PTS samples, noise 0.3 %, both branches tilted
 * alike, 4 seeds each): the approach's free part below the pull-off is one
 * more observation of the slope (mdr_f_scan, mdr_f_eval). Every answer
 * within 5 errors in E*, w, F_slope, z0 and F_base (the baseline at z0:
 * F_base + F_slope (z - z0)) (flaw_run's rule), and the whole
 * curve's F_slope error below the retract's alone (the approach's part
 * counted); with opts.approach too. */
static void test_tilt_approach(void **state)
{
    static const double tilt[4] = {-0.05, -0.02, 0.02, 0.05};
    const jkr_par *p = &regimes[1];
    mdr_contact_f64 c = paraboloid64(p->R);
    int k, s, i, n_ok = 0, n_all = 0, n_less = 0, n_both = 0;
    double worst = 0.0;
    (void)state;
    noise_state = 0x6a09e667f3bcc908ull;
    for (k = 0; k < 4; k++) {
        for (s = 0; s < 4; s++) {
            const int n = 2 * NORDER_PTS;
            const double Fpo = fabs(order_curve(p, NORDER_PTS, 0.0, 3e-3, 0.0, zs, Fs));
            double zlo = zs[0], zhi = zs[0], sl;
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r, rr;
            mdr_status st, str;
            int a;
            for (i = 0; i < n; i++) {
                zlo = zs[i] < zlo ? zs[i] : zlo;
                zhi = zs[i] > zhi ? zs[i] : zhi;
            }
            sl = tilt[k] * Fpo / (zhi - zlo);
            for (i = 0; i < n; i++) {
                Fs[i] += sl * (zs[i] - 0.5 * (zlo + zhi));
            }
            mdr_fit_defaults_f64(&o, p->km);
            o.unpinned = 1;
            str = mdr_fit_curve_f64(&c, &o, zs + NORDER_PTS, Fs + NORDER_PTS, NORDER_PTS, work64, 2 * NMAX, &rr);
            for (a = 0; a < 2; a++) {
                double dev;
                o.approach = (uint8_t)a;
                n_all++;
                st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
                if (st != MDR_OK) {
                    continue;
                }
                n_ok++;
                /* and z0, and F_base at z0 (rev_curve: z0 = 2 um, no baseline but the tilt) */
                dev = fmax(flaw_dev(p, &r), fabs(r.F_slope - sl) / r.F_slope_err);
                dev = fmax(dev, fabs(r.z0 - 2e-6) / r.z0_err);
                dev = fmax(dev, fabs(r.F_base - sl * (2e-6 - 0.5 * (zlo + zhi))) / r.F_base_err);
                worst = dev > worst ? dev : worst;
                if (dev > 5.0) {
                    print_message("tilt %g, seed %d, approach %d: E* %.4g x, w %.4g x, slope %.3g (truth %.3g), %.1f "
                                  "errors off\n", tilt[k], s, a, r.E / p->E, r.w / p->w, r.F_slope, sl, dev);
                }
                if (str == MDR_OK && a == 0) {
                    n_both++;
                    n_less += r.F_slope_err < rr.F_slope_err;
                }
            }
        }
    }
    print_message("tilted whole curves (approach's free part counted): %d of %d answered, worst %.1f errors; F_slope's "
                  "error below the retract's alone in %d of %d\n", n_ok, n_all, worst, n_less, n_both);
    assert_true(2 * n_ok >= n_all);
    assert_true(worst <= 5.0);
    assert_true(n_both > 0 && n_less == n_both);
}

/* A step in the free tail: a tether that holds 10 % or 20 % of the
 * pull-off force for the first 60 % of the free samples, then lets go, or
 * one glitch sample of half or all of the pull-off force (noise 0.3 %,
 * 400 samples, 4 seeds each). Before (stop 39's fix of mdr_f_meannoise):
 * sigma, the rms successive difference of the free part, grew with the
 * step, and every check scaled by it loosened: 3 of 16 answers 5.5 to 6.1
 * errors off (w 0.88 x the truth); the helper's tether (20 %, 60 samples)
 * through `mdr fit` w 0.92 x, 13 errors off, its rms residual 15 noise
 * widths, status ok. Now sigma leaves such a difference out, and a flaw
 * the fit cannot absorb is the model's misfit: measured 8 of 16 refused,
 * the other 8 answers within 3.5 errors. */
static double flaw_tail(int k, const jkr_par *p, int n, double Fpo, double *z, double *F)
{
    int i, j = n - 1, nf;
    (void)p, (void)z;
    if (k == 0) {
        return 0.0;
    }
    while (j > 0 && F[j - 1] > -0.5 * Fpo) { /* the last contact sample: j - 1 */
        j--;
    }
    nf = n - j;
    if (k <= 2) {
        for (i = j; i < j + (6 * nf) / 10; i++) {
            F[i] -= (k == 1 ? 0.1 : 0.2) * Fpo;
        }
    } else {
        F[j + nf / 2] += (k == 3 ? 0.5 : 1.0) * Fpo;
    }
    return 0.0;
}

static void test_tail_step(void **state)
{
    (void)state;
    flaw_run("free tail with a step or glitch", flaw_tail, 4, 4, 3e-3, 0, 1);
}

#ifndef MDR_TARGET_TEST
/* One glitch sample late in the free tail, measured against the CLEAN
 * curve's errors: flaw_run1's curves (regime 1, 400 samples, noise 0.3 %,
 * slope fitted, 4 seeds), each fitted first without the glitch (that fit
 * must answer within 5 of its errors), then with one sample raised by
 * G = 0.2 .. 0.5 of the pull-off force (steps of 0.05) at 80, 85, 90 or
 * 95 % of the way along the free tail (112 glitched curves). A refusal
 * passes; an answer must lie within GLITCH_CLEAN_MAX = 12 of the clean
 * fit's errors of the truth in ln E* and ln w. Not 5, and not the
 * answer's own errors: the glitch pulls the fitted slope and with it E*,
 * and widens the errors with the rms residual, so the answers stay within
 * 2.5 of their own errors. Measured: the fit refuses (MDR_E_MISFIT) the
 * glitches its trimmed sigma sees as misfit, 89 of 112, and answers the
 * rest, E* up to 1.29 x the truth, the worst 9.9 clean errors (2.3 of its
 * own; 12 seeds: 9.9 too); untrimmed, or trimmed at 720 instead of 72
 * (fit-sigma-trim, fit-sigma-trim-lim), sigma counts the glitch and all
 * 112 answer, E* up to 1.7 x, 50 answers beyond 12 clean errors, the
 * worst 26.9 (12 seeds: 10 to 17 of each seed's 28 beyond 12, worst 24 to
 * 30 on each seed). */
#define GLITCH_CLEAN_MAX 12.0
#ifndef GLITCH_SEEDS
#define GLITCH_SEEDS 4
#endif
static void test_tail_glitch_clean(void **state)
{
    const jkr_par p = regimes[1];
    const int n = 400;
    mdr_contact_f64 c = paraboloid64(p.R);
    static double z0[NMAX], F0[NMAX];
    int s, g, q, nok = 0, nref = 0, bad = 0;
    double worst = 0.0;
    (void)state;
    noise_state = 0x3c6ef372fe94f82bull; /* flaw_run1's curves */
    for (s = 0; s < GLITCH_SEEDS; s++) {
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r0;
        double Ff;
        int j = n - 1, nf;
        (void)jkr_z(&p, jkr_fold(&p), &Ff, NULL);
        (void)jkr_grid(&p, n, noise_uniform(), 3e-3, z0, F0);
        while (j > 0 && F0[j - 1] > -0.5 * fabs(Ff)) { /* the last contact sample: j - 1 */
            j--;
        }
        nf = n - j;
        mdr_fit_defaults_f64(&o, p.km);
        o.unpinned = 1;
        assert_int_equal(mdr_fit_curve_f64(&c, &o, z0, F0, (uint32_t)n, work64, 2 * NMAX, &r0), MDR_OK);
        assert_true(r0.E_err > 0.0 && r0.w_err > 0.0);
        assert_true(flaw_dev(&p, &r0) <= 5.0);
        for (g = 0; g < 7; g++) {
            for (q = 0; q < 4; q++) {
                const double G = 0.2 + 0.05 * g, at = 0.8 + 0.05 * q;
                mdr_fit_result_f64 r;
                double dev;
                memcpy(zs, z0, (size_t)n * sizeof zs[0]);
                memcpy(Fs, F0, (size_t)n * sizeof Fs[0]);
                Fs[j + (int)(at * nf)] += G * fabs(Ff);
                if (mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r) != MDR_OK) {
                    nref++;
                    continue;
                }
                nok++;
                dev = fmax(nerr(r.E, p.E, r0.E_err), nerr(r.w, p.w, r0.w_err));
                worst = dev > worst ? dev : worst;
                if (dev > GLITCH_CLEAN_MAX) {
                    print_message("seed %d, glitch %.2f of the pull-off force at %.0f %% of the free tail: ok, E* %.4g "
                                  "x, w %.4g x the truth, %.1f of the clean curve's errors off (%.1f of its own)\n",
                                  s, G, 100.0 * at, r.E / p.E, r.w / p.w, dev, flaw_dev(&p, &r));
                    bad++;
                }
            }
        }
    }
    print_message("one glitch of 0.2 .. 0.5 of the pull-off force late in the free tail: %d refused, %d answered, the "
                  "worst %.1f of the clean curve's errors off, %d beyond %g\n", nref, nok, worst, bad,
                  GLITCH_CLEAN_MAX);
    assert_int_equal(bad, 0);
}
#endif

/* A long-range (van der Waals-like) tail after the pull-off: the free
 * retract F - f |F_po| (D0/(D + D0))^2, D the base's travel past the last
 * contact sample, (f, D0) = (2 %, 1 nm), (5 %, 1 nm), (2 %, 3 nm),
 * (5 %, 3 nm) (a tip's attraction the model, JKR without long-range
 * forces, does not hold), noise 0.3 %, 4 seeds each. Before (stop 58;
 * helper-28's attack, stop 57: E* 2 to 3.5 times the truth on its curves)
 * every flawed curve was answered, status ok, 9 of 16 beyond 5 errors
 * (the worst 11.4, E* 1.1 times the truth): the rms misfit test allows 6
 * noise widths over the whole curve and a tail local to the jump is far
 * below that. Now the free part next to the jump must hold its line
 * (mdr_f_tail_held): every flawed curve refused, MDR_E_MISFIT. */
static const double vdw_f[5] = {0.0, 0.05, 0.1, 0.05, 0.1}, vdw_D0[5] = {0.0, 2e-9, 2e-9, 4e-9, 4e-9};
static double flaw_vdw(int k, const jkr_par *p, int n, double Fpo, double *z, double *F)
{
    int i, j = n - 1;
    (void)p;
    while (j > 0 && F[j - 1] > -0.5 * Fpo) { /* the last contact sample: j - 1 */
        j--;
    }
    for (i = j; i < n; i++) {
        const double q = vdw_D0[k] / (z[j - 1] - z[i] + vdw_D0[k]);
        F[i] -= vdw_f[k] * Fpo * q * q;
    }
    return 0.0;
}

static void test_vdw_tail(void **state)
{
    (void)state;
    flaw_run("long-range tail after the pull-off", flaw_vdw, 4, 4, 3e-3, 0, 1);
}

/* f32 at a large piezo offset: z + 100 um, 300 um, 1 mm, 3 mm, 1 500
 * samples 232 pm apart, noise 0.1 % of the pull-off force (f32 keeps z to
 * eps |z|: 0.05 to 1.5 of a step), 8 seeds each. Before (stop 39's fix:
 * base positions from z_po, mdr_f_zr) the fold's position z_c = z_po -
 * gap u^2 was rounded to z_po's ulp, and the fit placed the fold on that
 * grid: 7 of 32 answers 15 to 43 errors off; the helper's curves (`mdr
 * cycle`, 73 pm steps) up to 21 errors off from 150 um on (E* 1.08 x the
 * truth at 1 mm, its w_err 5.6 x smaller than f64's on the same file),
 * status ok. Measured now: all 32 answered, the worst 2.4 errors. */
static double flaw_offset(int k, const jkr_par *p, int n, double Fpo, double *z, double *F)
{
    static const double off[5] = {0.0, 100e-6, 300e-6, 1000e-6, 3000e-6};
    int i;
    (void)p, (void)Fpo, (void)F;
    for (i = 0; i < n; i++) {
        z[i] += off[k];
    }
    return 0.0;
}

static void test_f32_offset(void **state)
{
    (void)state;
    flaw_run("f32 at a piezo offset", flaw_offset, 4, 8, 1e-3, 1, 1);
}

/* z0's error in f32 at large offsets covers z0's own rounding (a helper's
 * attack, stop 57: z0 at 1 mm and 1 cm, 1 % noise, answered 2.5 and 3.6
 * errors off in every draw, the answer on the float grid beside the
 * truth, z0_err the noise's alone): the transition regime's curve moved to
 * 1, 3 and 10 mm, 1 500 samples, 6 draws each, f32: every z0 within 3 of
 * its errors. Measured: the worst 2.34 (14.1 before). */
static void test_f32_z0_rounding(void **state)
{
    static const double off[3] = {1e-3, 3e-3, 1e-2};
    const jkr_par p = regimes[1];
    const float pp[3] = {(float)p.R, 0, 0};
    mdr_contact_f32 c32;
    double worst = 0;
    int k, s, i;
    (void)state;
    assert_int_equal(mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
    noise_state = 0x6a09e667f3bcc908ull;
    for (k = 0; k < 3; k++) {
        for (s = 0; s < 6; s++) {
            const int n = 1500;
            mdr_fit_opts_f32 o32;
            mdr_fit_result_f32 r32;
            double Ff, z0;
            (void)jkr_z(&p, jkr_fold(&p), &Ff, NULL);
            z0 = jkr_grid(&p, n, noise_uniform(), 1e-2, zs, Fs) + off[k];
            for (i = 0; i < n; i++) {
                zs32[i] = (float)(zs[i] + off[k]);
                Fs32[i] = (float)Fs[i];
            }
            mdr_fit_defaults_f32(&o32, (float)p.km);
            o32.unpinned = 1;
            assert_int_equal(mdr_fit_curve_f32(&c32, &o32, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r32), MDR_OK);
            worst = fmax(worst, fabs((double)r32.z0 - z0) / (double)r32.z0_err);
        }
    }
    print_message("f32 z0 at 1 to 10 mm offsets: the worst %.2f errors off\n", worst);
    assert_true(worst <= 3.0);
}
#endif /* !MDR_TARGET_TEST */

/* A model not quite the data's is no pinned top: the closed-form JKR
 * retract (noise-free, NFINE samples, each regime) with a ramp of 3e-5 of
 * the pull-off force added over the upper half of its contact (0 at the
 * middle, largest at the top: a profile or a lever slightly other than
 * the model's). The model then misses the top sample by more than thr
 * (noise-free: the forces' rounding), but by the misfit that its rms
 * residual (measured 3.7e-6 to 4e-6 of the pull-off force) shows
 * everywhere; mdr_f_pinned allows nsig times that rms, and takes it for no
 * contact pinned at the approach's radius: every answer has n_pinned = 0
 * (without the rms allowance, regime 0: n_pinned 1). Before the LM took
 * its last step the same held for a curve without the ramp, its residual
 * then the LM's stopping error. */
#ifndef MDR_TARGET_TEST /* (host only: the target's time) */
static void test_misfit_not_pinned(void **state)
{
    int k, i, n_ok = 0;
    (void)state;
    for (k = 0; k < 3; k++) {
        const jkr_par *p = &regimes[k];
        mdr_contact_f64 c = paraboloid64(p->R);
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        double Fpo, zm;
        mdr_status st;
        const int last = jkr_curve(p, 1e-6, 0.0, NFINE, zs, Fs, 0, &Fpo);
        zm = 0.5 * (zs[0] + zs[last]);
        for (i = 0; i <= last; i++) {
            Fs[i] += zs[i] > zm ? 3e-5 * fabs(Fpo) * (zs[i] - zm) / (zs[0] - zm) : 0.0;
        }
        mdr_fit_defaults_f64(&o, p->km);
        st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)NFINE, work64, 2 * NMAX, &r);
        print_message("regime %d with a ramp: status %d, n_pinned %u, rms %.2g of the pull-off force\n", k, st,
                      st == MDR_OK ? (unsigned)r.n_pinned : 0u, st == MDR_OK ? r.rms / fabs(Fpo) : 0.0);
        assert_int_equal(st, MDR_OK);
        assert_int_equal(r.n_pinned, 0);
        n_ok++;
    }
    assert_int_equal(n_ok, 3);
}
#endif

/* opts.unpinned: no pinned top is looked for, every retract sample is
 * fitted (n_pinned = 0). The adversarial tester's curve (JKR, E* =
 * 1.633 MPa, w = 0.476, R = 90 nm, k_m = 8.96 N/m, 201 retract samples,
 * noise 10 % of the pull-off force), NMC copies: every estimate of E* and
 * w within 5 reported errors (test_noise's rule). Before: the pinned-top
 * search ran anyway and left out 151 of 201 samples (E* 13x low). */
static void test_unpinned(void **state)
{
    const jkr_par p = {9.01e-8, 1.633e6, 0.4764, 8.963};
    mdr_contact_f64 c = paraboloid64(p.R);
    mdr_fit_opts_f64 o;
    double Ff;
    int j;
    (void)state;
    mdr_fit_defaults_f64(&o, p.km);
    o.unpinned = 1;
    jkr_z(&p, jkr_fold(&p), &Ff, NULL);
    for (j = 0; j < NMC; j++) {
        mdr_fit_result_f64 r;
        double Fpo, sig = 0.1 * fabs(Ff);
        int n = jkr_span(&p, 1.896, 0.618, 200, 1e-6, sig, zs, Fs, &Fpo);
        mdr_status st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
        if (st != MDR_OK || r.n_pinned != 0 || r.n != (uint32_t)n || !(fabs(r.E - p.E) <= 5 * r.E_err) ||
            !(fabs(r.w - p.w) <= 5 * r.w_err)) {
            fail_msg("unpinned, copy %d: status %d, n_pinned %u of %d, E* %.4g +- %.2g, w %.4g +- %.2g", j, st,
                     st == MDR_OK ? (unsigned)r.n_pinned : 0u, n, st == MDR_OK ? r.E : 0.0,
                     st == MDR_OK ? r.E_err : 0.0, st == MDR_OK ? r.w : 0.0, st == MDR_OK ? r.w_err : 0.0);
        }
    }
}

/* A sweep over the valid range: NSWEEP closed-form JKR curves (300
 * samples, jkr_curve's span, base offset twice the span) with E*, w, R and
 * k_m log-uniform over 1e3..1e12 Pa, 1e-4..10 J/m^2, 1 nm..1 cm and
 * 0.01..100 N/m, in four classes: noise-free and with noise of 1 % of the
 * pull-off force (opts.unpinned: the curves recede from their tops), f64
 * and f32. Every answer is good, every refusal named: an answer with
 * relative errors below 1 whose ln E* and ln w lie within 5 reported
 * errors (E_err/E*, w_err/w: the fit's parameters are the logarithms) or
 * SWEEP_TOL of the truth (SWEEP_TOL = 0.05: no claim of accuracy, which the
 * other tests make, but no nonsense; f32 answers on soft-lever curves err
 * by up to 3 %), a refusal one of the fit's statuses. The checks of the
 * answer refuse no good fit: the fit started at the truth (E0, w0) is
 * never MDR_E_MISFIT. The counts are printed (host, of 100 each: noise-free
 * f32 84 ok, 12 DEGENERATE, 4 FEW (a pinned top's end within
 * MDR_FIT_MIN_RECEDE samples of the pull-off, since stop 51); noise-free
 * f64 77 ok, 18 FITCAP, 5 DEGENERATE; noisy f32 59 ok, 28 DEGENERATE, 13
 * PINNED; noisy f64 67 ok, 19 DEGENERATE, 14 PINNED; MDR_E_MISFIT 0; the
 * curves follow the noise generator's state, which the tests before this
 * one leave); every class answers at least half. */
#define SWEEP_TOL 0.05
#ifdef MDR_TARGET_TEST
#define NSWEEP 16
#else
#define NSWEEP 400
#endif
static void test_fit_sweep(void **state)
{
    const int n = 300;
    int j, i, ok[4] = {0, 0, 0, 0}, tot[4] = {0, 0, 0, 0}, by[4][32];
    (void)state;
    memset(by, 0, sizeof by);
    for (j = 0; j < NSWEEP; j++) {
        jkr_par p;
        const int noisy = j & 1, f32 = (j >> 1) & 1, cls = 2 * noisy + (1 - f32);
        double Fpo, sig, z0, E, w, Ee, we;
        mdr_status st, st0;
        p.E = pow(10.0, 3 + 9 * noise_uniform());
        p.w = pow(10.0, -4 + 5 * noise_uniform());
        p.R = pow(10.0, -9 + 7 * noise_uniform());
        p.km = pow(10.0, -2 + 4 * noise_uniform());
        {
            double af = jkr_fold(&p), Ff, zf = jkr_z(&p, af, &Ff, NULL);
            double ztop = 2.0 * fabs(zf) + jkr_z(&p, 2.5 * af, NULL, NULL), zbot = zf - 0.4 * (ztop - zf);
            z0 = 2 * (ztop - zbot);
            sig = noisy ? 0.01 * fabs(Ff) : 0.0;
            Fpo = Ff;
            for (i = 0; i < n; i++) {
                double zp = ztop + (zbot - ztop) * i / (n - 1), f = 0.0;
                if (zp > zf) {
                    jkr_z(&p, jkr_a(&p, zp, af), &f, NULL);
                }
                zs[i] = zp + z0;
                Fs[i] = f + (noisy ? sig * gauss() : 0.0);
                zs32[i] = (float)zs[i];
                Fs32[i] = (float)Fs[i];
            }
        }
        (void)Fpo;
        if (f32) {
            mdr_contact_f32 c;
            mdr_fit_opts_f32 o;
            mdr_fit_result_f32 r;
            float pp[3] = {(float)p.R, 0, 0};
            assert_int_equal(mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, pp, 1.0f, 0.0f), MDR_OK);
            mdr_fit_defaults_f32(&o, (float)p.km);
            o.unpinned = (uint8_t)noisy;
            st = mdr_fit_curve_f32(&c, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r);
            E = r.E, w = r.w, Ee = r.E_err, we = r.w_err;
            o.E0 = (float)p.E;
            o.w0 = (float)p.w;
            st0 = mdr_fit_curve_f32(&c, &o, zs32, Fs32, (uint32_t)n, work32, 2 * NMAX, &r);
        } else {
            mdr_contact_f64 c = paraboloid64(p.R);
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            mdr_fit_defaults_f64(&o, p.km);
            o.unpinned = (uint8_t)noisy;
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            E = r.E, w = r.w, Ee = r.E_err, we = r.w_err;
            o.E0 = p.E;
            o.w0 = p.w;
            st0 = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
        }
        tot[cls]++;
        if (st == MDR_OK) {
            /* in the fit's parameters ln E*, ln w, whose standard errors
             * are E_err/E*, w_err/w */
            const double dE = fabs(log(E / p.E)), dw = fabs(log(w / p.w));
            ok[cls]++;
            if (!(Ee < E && we < w && (dE <= 5 * Ee / E || dE <= SWEEP_TOL) && (dw <= 5 * we / w || dw <= SWEEP_TOL))) {
                fail_msg("sweep %d (%s, %s; E* %.4g, w %.4g, R %.4g, k_m %.4g): E* %.6g +- %.2g, w %.6g +- %.2g", j,
                         noisy ? "noisy" : "noise-free", f32 ? "f32" : "f64", p.E, p.w, p.R, p.km, E, Ee, w, we);
            }
        } else {
            if (!(st == MDR_E_FITCAP || st == MDR_E_DEGENERATE || st == MDR_E_MISFIT || st == MDR_E_PINNED ||
                  st == MDR_E_NOCONV || st == MDR_E_FEW)) {
                fail_msg("sweep %d: status %d (%s)", j, st, mdr_status_str(st));
            }
            by[cls][-st]++;
        }
        if (st0 == MDR_E_MISFIT) {
            fail_msg("sweep %d (%s, %s; E* %.4g, w %.4g, R %.4g, k_m %.4g): the fit from the truth refused as a misfit",
                     j, noisy ? "noisy" : "noise-free", f32 ? "f32" : "f64", p.E, p.w, p.R, p.km);
        }
    }
    for (i = 0; i < 4; i++) {
        print_message("sweep, %s %s: %d of %d ok; refused: FITCAP %d, DEGENERATE %d, MISFIT %d, PINNED %d, NOCONV %d, "
                      "FEW %d\n",
                      i & 2 ? "noisy" : "noise-free", i & 1 ? "f64" : "f32", ok[i], tot[i], by[i][-MDR_E_FITCAP],
                      by[i][-MDR_E_DEGENERATE], by[i][-MDR_E_MISFIT], by[i][-MDR_E_PINNED], by[i][-MDR_E_NOCONV],
                      by[i][-MDR_E_FEW]);
        assert_true(2 * ok[i] >= tot[i]);
    }
}

/* The standard errors cover the truth: NCOVER closed-form curves (E*, w,
 * R, k_m log-uniform as in test_fit_sweep, 300 samples, the fold anywhere
 * in the sampling step, noise 1e-8 of the pull-off force, opts.unpinned),
 * and NCOVER more with the fold within 0.1 % of a step below a sample; of
 * the answers, at most COVER_FRAC with ln E*, ln w or z0 beyond 3 reported
 * errors, none beyond COVER_MAX (z0 since stop 43: its error without the
 * fold's step, fit-z0err-fold, put 25 of 448 beyond 3, worst 5.2; the
 * others did not see it). Before: a fit through a lever 1e3 to 1e6
 * times softer than the contact stopped with the fold at the last contact
 * sample (u near 0, where Gauss-Newton does not see the rest of the
 * retract pull the fold into the step: mdr_fit.inc, mdr_f_fold_saddle)
 * while the data put it 0.1 to 0.6 steps below; w 0.05 % to 3 % off, 35 to
 * 232 reported errors, the rms residual up to 3 times the noise. */
#define NCOVER 600
#ifndef MDR_TARGET_TEST /* (f64 only: host_tests/test_fit.c's header, TARGET_F64) */
static void test_cover_fold(void **state)
{
    const int n = 300;
    int j, pass, ok, out3, zout3;
    double worst_dev, zworst;
    (void)state;
    /* passes 0, 1: the baseline flat (opts.flat), whose tight errors show
     * a fold stuck at the wrong end (the slope's 3 x larger errors cover
     * much of it: fit-fold-var-saddle survived them); 2, 3: the same curves
     * with the slope fitted */
    for (pass = 0; pass < 4; pass++) {
        const double near = (pass & 1) ? 0.001 : 1.0;
        if ((pass & 1) == 0) {
            noise_state = 0x2545F4914F6CDD1Dull;
        }
        ok = out3 = zout3 = 0;
        worst_dev = zworst = 0;
        for (j = 0; j < NCOVER; j++) {
            jkr_par p;
            mdr_contact_f64 c;
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            mdr_status st;
            p.E = pow(10.0, 3 + 9 * noise_uniform());
            p.w = pow(10.0, -4 + 5 * noise_uniform());
            p.R = pow(10.0, -9 + 7 * noise_uniform());
            p.km = pow(10.0, -2 + 4 * noise_uniform());
            const double z0 = jkr_grid(&p, n, near * noise_uniform(), 1e-8, zs, Fs);
            c = paraboloid64(p.R);
            mdr_fit_defaults_f64(&o, p.km);
            o.unpinned = 1;
            o.flat = pass < 2;
            st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
            if (st == MDR_OK) {
                const double dE = nerr(r.E, p.E, r.E_err), dw = nerr(r.w, p.w, r.w_err);
                const double dz = fabs(r.z0 - z0) / r.z0_err;
                const double d = fmax(fmax(dE, dw), dz);
                zworst = dz > zworst ? dz : zworst;
                zout3 += dz > 3;
                ok++;
                out3 += d > 3;
                worst_dev = d > worst_dev ? d : worst_dev;
                if (!(d <= COVER_MAX)) {
                    fail_msg("cover %d.%d (E* %.4g, w %.4g, R %.4g, k_m %.4g): E* %.9g +- %.2g (%.1f errors), "
                             "w %.9g +- %.2g (%.1f errors), z0 %.9g +- %.2g (%.1f errors)", pass, j, p.E, p.w, p.R,
                             p.km, r.E, r.E_err, dE, r.w, r.w_err, dw, r.z0, r.z0_err, dz);
                }
            }
        }
        print_message("coverage (%s), the fold %s: %d answers of %d, %d beyond 3 errors, worst %.2f errors "
                      "(z0: %d, %.2f)\n",
                      pass < 2 ? "flat baseline" : "slope fitted",
                      (pass & 1) ? "within 0.1 % of a step below a sample" : "anywhere in the step", ok, NCOVER,
                      out3, worst_dev, zout3, zworst);
        assert_true(out3 <= (int)ceil(COVER_FRAC * ok));
        assert_true(2 * ok >= NCOVER);
    }
}
#endif /* !MDR_TARGET_TEST */

#ifndef MDR_TARGET_TEST /* (f64 only) */
/* The fold held at a saddle (mdr_fit.inc, mdr_f_fold_saddle, mdr_f_lm):
 * closed-form curves through levers 1e3 to 1e6 times softer than the
 * contact (2 E* a_fold / k_m), the fold 0.2 to 0.6 of a step below a
 * sample, 300 samples, noise SADDLE_SIG of the pull-off force
 * (opts.unpinned); the slope fitted (saddle_slope) and the baseline flat
 * (saddle_flat). An answer (status ok) must be a least-squares fit: its rms
 * residual at most SADDLE_RMS times that of the truth (the noise drawn, the
 * test's own sum), and the truth within COVER_MAX of its errors in ln E*,
 * ln w and z0; a refusal passes. The curves are those of 3 000 such draws
 * (E*, w, R log-uniform over test_cover_fold's span, the lever ratio
 * log-uniform in 1e3..1e6, the fold position uniform; noise_state
 * 0x2545F4914F6CDD1D) where a fit that stops with the fold at the last
 * contact sample answered ok: without the second-order term of the saddle
 * test (fit-fold-saddle-term) or with the test never applied
 * (fit-fold-usmall) 67 flat and 7 sloped of them answered with an rms 1.5
 * to 6.5 times the noise's, w 1 to 4 % low (within the profile's wide
 * errors, so test_cover_fold did not see it); with the search along u
 * stopped at u = 1/8 (fit-fold-search-fall) the 12 flat ones, 1.9 to 4.4
 * times. Measured (this commit): of the 19, one answered (flat: w 0.998
 * times the truth, 0.69 errors off, rms 1.04 times the noise's), the rest
 * refused (MDR_E_DEGENERATE); 0.3 s. */
#define SADDLE_SIG 1e-8
#define SADDLE_RMS 1.5
typedef struct {
    double R, E, w, km, at;
    uint64_t seed; /* noise_state before the curve's noise */
} saddle_curve;
static const saddle_curve saddle_flat[] = {
    {1.9391395449163312e-05, 4324233048.3775282, 0.00019030588070039655, 0.001195157974708748, 0.36442640821899719, 0xd0f09e27f82d02ddull},
    {0.0012331121362139743, 364724878817.87299, 0.0059036647388596179, 1.3532988548154992, 0.5184134639137975, 0xcaed3cf6daa1010full},
    {9.4233370384306516e-07, 10946342267.319729, 0.00047929726984802668, 0.00032770617159849847, 0.2146451298218848, 0xd784c6d9d345de23ull},
    {0.0011884534129904757, 12028896674.982985, 4.294365260947937, 0.87899616415751491, 0.23691677800088964, 0xd71e09d94e6edc97ull},
    {0.00020748649375973132, 10102185.166277474, 0.0011780678224447259, 0.00017809474670295479, 0.26426065156824785, 0xd2800bcb1722d7c2ull},
    {0.0035201208799661493, 2472924136.8078861, 0.83916465207373658, 0.3957108129853491, 0.30566773145155957, 0xd444f6d6ff0132baull},
    {6.4109771496655349e-09, 96776077.831111908, 0.00080809847625944837, 6.798543669954039e-07, 0.36814681480422673, 0xb99d3921fe315f91ull},
    {0.0037997559372481473, 12028079.903380804, 0.0054836090722177322, 0.002553399711575372, 0.33054930869827681, 0xceedc50e969a9d54ull},
    {1.5337245405803693e-05, 5349836.1217393829, 0.00088263943242200527, 2.3680856139297253e-05, 0.39000764420496581, 0xc9dc54dac71a6bd3ull},
    {1.0255602369911041e-05, 38542230.889754996, 0.013026658983953956, 0.00011222828977113026, 0.2588524259859023, 0xd871466e388c5bfaull},
    {5.4397938687411647e-09, 44715956632.663681, 1.3258384718476386, 0.0006128132606124004, 0.29559591931051321, 0xc6829563658f516bull},
    {0.00070493987616424231, 272904221423.20718, 5.6699981875407133, 6.7081127312268496, 0.23921679622602071, 0xcf7583253ebc6048ull},
};
static const saddle_curve saddle_slope[] = {
    {9.3368033730745181e-06, 30830372016.999096, 0.15985536546257492, 0.023979549421095592, 0.22728668178943578, 0xd35c73fdf6818552ull},
    {9.4233370384306516e-07, 10946342267.319729, 0.00047929726984802668, 0.00032770617159849847, 0.2146451298218848, 0xd784c6d9d345de23ull},
    {0.00052984759939477574, 33469793.335478239, 0.0070396589280757463, 0.001158685668318411, 0.29947717897848564, 0xd5d0cd72a17d37edull},
    {0.00020748649375973132, 10102185.166277474, 0.0011780678224447259, 0.00017809474670295479, 0.26426065156824785, 0xd2800bcb1722d7c2ull},
    {1.4321037172493793e-08, 1143530.1394750995, 0.00028611784935232123, 3.6285639182489998e-08, 0.3118681798998354, 0xce6bc2b3e8ef3419ull},
    {1.0711473511891956e-07, 144544967.26530245, 0.073330705781778555, 2.5814589588105104e-05, 0.21290169845065821, 0xbef97cccec86d8eaull},
    {3.4442823335991314e-08, 9609079.4978257511, 0.00033849161547895389, 3.7806117985351526e-07, 0.3588034406968576, 0xb42ead85409a787aull},
};

/* One closed-form curve of the saddle tests: n samples, the fold at of a
 * step below a sample, noise sig (jkr_grid), fitted with the fold
 * unpinned and the baseline flat or not; *z0: the curve's */
static mdr_status saddle_fit(const jkr_par *p, int n, double at, double sig, int flat, double *z0,
                             mdr_fit_result_f64 *r)
{
    mdr_contact_f64 c = paraboloid64(p->R);
    mdr_fit_opts_f64 o;
    *z0 = jkr_grid(p, n, at, sig, zs, Fs);
    mdr_fit_defaults_f64(&o, p->km);
    o.unpinned = 1;
    o.flat = (uint8_t)flat;
    return mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, r);
}

/* the largest of an answer's distances from the truth in its errors: ln
 * E*, ln w, z0 */
static double saddle_dev(const jkr_par *p, const mdr_fit_result_f64 *r, double z0)
{
    return fmax(fmax(nerr(r->E, p->E, r->E_err), nerr(r->w, p->w, r->w_err)), fabs(r->z0 - z0) / r->z0_err);
}

static void saddle_run(const saddle_curve *cv, int ncv, int flat)
{
    const int n = 300;
    const uint64_t saved = noise_state;
    int j, i, ok = 0;
    for (j = 0; j < ncv; j++) {
        const jkr_par p = {cv[j].R, cv[j].E, cv[j].w, cv[j].km};
        mdr_fit_result_f64 r;
        double Ff, z0, g2 = 0.0, rms_true;
        (void)jkr_z(&p, jkr_fold(&p), &Ff, NULL);
        noise_state = cv[j].seed; /* the noise jkr_grid draws, one gauss() a sample */
        for (i = 0; i < n; i++) {
            const double g = gauss();
            g2 += g * g;
        }
        rms_true = SADDLE_SIG * fabs(Ff) * sqrt(g2 / n);
        noise_state = cv[j].seed;
        if (saddle_fit(&p, n, cv[j].at, SADDLE_SIG, flat, &z0, &r) != MDR_OK) {
            continue;
        }
        {
            const double d = saddle_dev(&p, &r, z0);
            print_message("saddle curve %d (%s): w %.4g x the truth, %.2f errors off, rms %.3g of the noise's\n", j,
                          flat ? "flat" : "slope fitted", r.w / p.w, d, r.rms / rms_true);
            if (!(r.rms <= SADDLE_RMS * rms_true) || !(d <= COVER_MAX)) {
                fail_msg("saddle curve %d (%s; E* %.4g, w %.4g, R %.4g, k_m %.4g, fold %.3f of a step): ok with rms "
                         "%.3g of the noise's, w %.6g x the truth (+- %.2g), %.1f errors off", j,
                         flat ? "flat" : "slope fitted", p.E, p.w, p.R, p.km, cv[j].at, r.rms / rms_true, r.w / p.w,
                         r.w_err / r.w, d);
            }
            ok++;
        }
    }
    print_message("fold at a saddle (%s): %d of %d answered\n", flat ? "flat baseline" : "slope fitted", ok, ncv);
    noise_state = saved;
}

static void test_fold_saddle(void **state)
{
    (void)state;
    saddle_run(saddle_flat, (int)(sizeof saddle_flat / sizeof saddle_flat[0]), 1);
    saddle_run(saddle_slope, (int)(sizeof saddle_slope / sizeof saddle_slope[0]), 0);
}

/* The fold at a saddle, noise-free (mdr_fit.inc: mdr_f_fold_saddle, and
 * the standard errors of mdr_fit_curve): closed-form curves through levers
 * 1.7e5 to 9.8e5 times softer than the contact (2 E* a_fold / k_m), the
 * fold 5e-5 to 1e-3 of a step below a sample (jkr_grid), 300 samples, no
 * noise (opts.unpinned), the baseline flat and the slope fitted. The fit
 * stops with the fold on the sample (u ~ 0, a saddle the search does not
 * leave) and, the noise below the forces' rounding, the fold's profile
 * (mdr_f_fold_profile) does not widen the errors. An answer (status ok)
 * must have E* and w within TOL_RT of the truth or the truth within
 * COVER_MAX of its errors in ln E*, ln w and z0; a refusal passes. The
 * curves: those of 300 draws (E*, w, R log-uniform over test_cover_fold's
 * span, the lever ratio log-uniform in 1e3..1e6, the fold uniform in
 * 0..1e-3 of a step below a sample) that answered ok with the fold's
 * variance of 1/4 at such a saddle left out (fit-fold-var-saddle): w
 * 2.5e-6 to 4.8e-5 low (about 5 % of w a step) with reported errors of
 * 1.4e-8 to 2.2e-7 of it, 100 to 218 errors off, flat and sloped alike.
 * Measured: all 28 fits refused (MDR_E_DEGENERATE), under 0.1 s; since
 * mdr_f_gn_escape 22 of 28 answered, within 1.66 errors of the truth. */
static const double saddle_nf[][5] = { /* R, E*, w, k_m, the fold's fraction of a step */
    {1.2150039787506154e-05, 1288396.4489125495, 0.00026084744972124866, 2.8485441420305611e-06, 0.00012614124506844099},
    {7.219046015555128e-06, 51226452019.824265, 0.0052692819948957992, 0.0068903029347781933, 0.00095470075348555092},
    {3.5300855172942316e-07, 230979971201.82697, 0.78828456811732406, 0.0053980696122556864, 0.00033802981874965959},
    {1.0216510458296509e-05, 36989018263.545219, 0.0011374826040043708, 0.0023726912728659227, 0.00062411730088068288},
    {8.0379532372894349e-08, 880502432544.64185, 0.00096261765522276345, 0.00061765641747385915, 0.00088523319607464711},
    {0.0043138713842491598, 70407599849.774307, 0.0021944148374311908, 0.32989251789527896, 0.0003434512396094242},
    {3.0626666086422455e-07, 325607096344.28735, 0.58093465124161803, 0.0089457947702297463, 5.0040989317440336e-05},
    {4.086233848339285e-08, 1101179907.9291732, 0.12240392315089758, 4.1743465295316826e-05, 0.00031228851945861618},
    {1.6163776007180988e-07, 32459462451.768547, 0.00010341167969802855, 5.2562335611037919e-05, 0.00037006087388316051},
    {0.0025470187890468958, 130496113281.52133, 0.029683653156129353, 0.84653799245605321, 0.00060871503611883537},
    {1.2449830916348892e-05, 198010969.88348773, 0.023427367509466591, 0.00057999906562521413, 0.00023175533670553468},
    {4.3920771733232592e-08, 9726316410.1717415, 0.76948443007501743, 0.00092936724614774385, 0.00047654800020966885},
    {1.5923480425655356e-09, 1344067693.1903746, 0.016201792836176138, 1.6464153235563003e-06, 0.00018113181103842396},
    {0.00025734367596002455, 186878691220.22998, 0.7007257832342414, 0.41963759334512657, 0.00033358393424689987},
};

static void test_fold_saddle_noise_free(void **state)
{
    const int n = 300, ncv = (int)(sizeof saddle_nf / sizeof saddle_nf[0]);
    int j, flat, ok = 0;
    (void)state;
    for (j = 0; j < ncv; j++) {
        for (flat = 0; flat < 2; flat++) {
            const jkr_par p = {saddle_nf[j][0], saddle_nf[j][1], saddle_nf[j][2], saddle_nf[j][3]};
            mdr_fit_result_f64 r;
            double z0;
            /* (no noise: noise_state's draws unused) */
            if (saddle_fit(&p, n, saddle_nf[j][4], 0.0, flat, &z0, &r) != MDR_OK) {
                continue;
            }
            ok++;
            {
                const double d = saddle_dev(&p, &r, z0);
                const bool rt = fabs(r.E / p.E - 1) <= TOL_RT && fabs(r.w / p.w - 1) <= TOL_RT;
                print_message("noise-free saddle curve %d (%s): w %.9g x the truth, %.2f errors off\n", j,
                              flat ? "flat" : "slope fitted", r.w / p.w, d);
                if (!rt && !(d <= COVER_MAX)) {
                    fail_msg("noise-free saddle curve %d (%s; E* %.4g, w %.4g, R %.4g, k_m %.4g, fold %.3g of a "
                             "step): ok with w %.9g x the truth (+- %.2g), E* %.9g x (+- %.2g), %.1f errors off",
                             j, flat ? "flat" : "slope fitted", p.E, p.w, p.R, p.km, saddle_nf[j][4], r.w / p.w,
                             r.w_err / r.w, r.E / p.E, r.E_err / r.E, d);
                }
            }
        }
    }
    print_message("fold at a saddle, noise-free: %d of %d answered\n", ok, 2 * ncv);
}
#endif /* !MDR_TARGET_TEST */

/* Coarse curves: the fold's position within its sampling step carries w
 * (mdr_fit.inc, mdr_f_fold_profile). The transition regime's curve (R
 * 20 nm, E* 1 GPa, w 0.05 J/m^2, k_m 0.2 N/m) with COARSE_N[i] samples
 * over the retract (about two thirds of them in contact), noise COARSE_SIG
 * of the pull-off force, NCOARSE draws each (opts.unpinned): at most
 * COARSE_FRAC of the answers beyond 3 reported errors in ln w, none beyond
 * COARSE_MAX, and the spread of ln w within COARSE_RATIO of the median
 * reported error either way. Measured (stop 57): 25, 40, 60 samples: 1, 2,
 * 5 of 200 beyond 3 errors, the worst 3.69, 4.22, 4.68; the median error
 * 1.06, 1.21, 1.20 times the spread. Before: 13 of the 25-sample answers
 * beyond 3 (the worst 5.27), their errors 0.69 of the spread. */
#define NCOARSE 200
#define COARSE_SIG 1e-3
#define COARSE_FRAC 0.03
#define COARSE_MAX 5.0
#define COARSE_RATIO 1.6
#ifndef MDR_TARGET_TEST
static int cmp_dbl(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static void test_coarse_fold_errors(void **state)
{
    static const int COARSE_N[3] = {25, 40, 60};
    const jkr_par *p = &regimes[1];
    const mdr_contact_f64 c = paraboloid64(p->R);
    int k;
    (void)state;
    noise_state = 0x9E3779B97F4A7C15ull;
    for (k = 0; k < 3; k++) {
        const int n = COARSE_N[k];
        double Fpo, lw[NCOARSE], ew[NCOARSE], m = 0, v = 0, worst = 0;
        int j, i, ok = 0, out3 = 0;
        jkr_curve(p, -2e-6, 0.0, n, zs, Fm, 0, &Fpo);
        for (j = 0; j < NCOARSE; j++) {
            mdr_fit_opts_f64 o;
            mdr_fit_result_f64 r;
            for (i = 0; i < n; i++) {
                Fs[i] = Fm[i] + COARSE_SIG * fabs(Fpo) * gauss();
            }
            mdr_fit_defaults_f64(&o, p->km);
            o.unpinned = 1;
            if (mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r) != MDR_OK) {
                continue;
            }
            {
                const double d = nerr(r.w, p->w, r.w_err);
                worst = d > worst ? d : worst;
                out3 += d > 3;
            }
            lw[ok] = log(r.w);
            ew[ok] = r.w_err / r.w;
            ok++;
        }
        for (j = 0; j < ok; j++) {
            m += lw[j] / ok;
        }
        for (j = 0; j < ok; j++) {
            v += (lw[j] - m) * (lw[j] - m) / (ok - 1);
        }
        qsort(ew, (size_t)ok, sizeof *ew, cmp_dbl);
        print_message("coarse curves, %d samples: %d answers of %d, %d beyond 3 errors in w, worst %.2f; "
                      "spread of ln w %.3g, median reported %.3g\n",
                      n, ok, NCOARSE, out3, worst, sqrt(v), ew[ok / 2]);
        assert_true(2 * ok >= NCOARSE);
        assert_true(out3 <= (int)ceil(COARSE_FRAC * ok));
        assert_true(worst <= COARSE_MAX);
        assert_true(sqrt(v) / ew[ok / 2] < COARSE_RATIO && ew[ok / 2] / sqrt(v) < COARSE_RATIO);
    }
}
#endif /* !MDR_TARGET_TEST */

/* E* along a flat valley: NVALLEY closed-form curves of stiff contacts
 * through soft levers (E* 1e9..1e12 Pa, w 1e-4..10 J/m^2, R 10 um..5 mm,
 * k_m 0.01..3 N/m, log-uniform; test_fit_sweep's span, 300 samples, noise
 * 1 % of the pull-off force, opts.unpinned), where the sum of squares
 * flattens in ln E* toward the rigid limit faster than its quadratic model
 * says. Every answer within COVER_MAX reported errors of the truth in ln E*
 * and ln w, at most COVER_FRAC beyond 3; the rest refused. Before: E* 3 000
 * times low at a relative error of 0.75 (10.7 errors), status ok; over
 * 4 000 such curves 10 of 46 answers beyond 3 errors, the worst E* 6e4
 * times low (21.8 errors). Now, where E*'s relative error exceeds 0.1, it
 * is refused (MDR_E_DEGENERATE) unless the profile of the sum of squares
 * in ln E* rises by 3 errors within a factor 20 either way (mdr_fit.inc,
 * mdr_f_bounded_E): over the 4 000, 24 answers, none beyond 3 errors; here
 * 4, one at 3.2. At least one answer with E*'s relative error above 0.1
 * (measured 3 here): the check must not refuse every such answer. */
#define NVALLEY 400
#ifndef MDR_TARGET_TEST /* (f64 only: host_tests/test_fit.c's header, TARGET_F64) */
static void test_refuse_valley(void **state)
{
    const int n = 300;
    int j, i, ok = 0, okprof = 0, out3 = 0, refused = 0;
    double worst_dev = 0;
    (void)state;
    noise_state = NOISE_SEED0;
    for (j = 0; j < NVALLEY; j++) {
        jkr_par p;
        mdr_contact_f64 c;
        mdr_fit_opts_f64 o;
        mdr_fit_result_f64 r;
        mdr_status st;
        double af, Ff, zf, ztop, zbot, z0, sig;
        p.E = pow(10.0, 9 + 3 * noise_uniform());
        p.w = pow(10.0, -4 + 5 * noise_uniform());
        p.R = pow(10.0, -5 + 2.7 * noise_uniform());
        p.km = pow(10.0, -2 + 2.5 * noise_uniform());
        af = jkr_fold(&p);
        zf = jkr_z(&p, af, &Ff, NULL);
        ztop = 2.0 * fabs(zf) + jkr_z(&p, 2.5 * af, NULL, NULL);
        zbot = zf - 0.4 * (ztop - zf);
        z0 = 2 * (ztop - zbot);
        sig = 0.01 * fabs(Ff);
        for (i = 0; i < n; i++) {
            double zp = ztop + (zbot - ztop) * i / (n - 1), f = 0.0;
            if (zp > zf) {
                jkr_z(&p, jkr_a(&p, zp, af), &f, NULL);
            }
            zs[i] = zp + z0;
            Fs[i] = f + sig * gauss();
        }
        c = paraboloid64(p.R);
        mdr_fit_defaults_f64(&o, p.km);
        o.unpinned = 1;
        st = mdr_fit_curve_f64(&c, &o, zs, Fs, (uint32_t)n, work64, 2 * NMAX, &r);
        if (st == MDR_OK) {
            const double dE = nerr(r.E, p.E, r.E_err), dw = nerr(r.w, p.w, r.w_err);
            const double d = dE > dw ? dE : dw;
            ok++;
            okprof += r.E_err > 0.1 * r.E; /* answered through the profile's check */
            out3 += d > 3;
            worst_dev = d > worst_dev ? d : worst_dev;
            if (!(d <= COVER_MAX)) {
                fail_msg("valley %d (E* %.4g, w %.4g, R %.4g, k_m %.4g): E* %.6g +- %.2g (%.1f errors), w %.6g +- %.2g "
                         "(%.1f errors)", j, p.E, p.w, p.R, p.km, r.E, r.E_err, dE, r.w, r.w_err, dw);
            }
        } else {
            if (!(st == MDR_E_DEGENERATE || st == MDR_E_PINNED || st == MDR_E_FITCAP || st == MDR_E_NOCONV)) {
                fail_msg("valley %d: status %d (%s)", j, st, mdr_status_str(st));
            }
            refused++;
        }
    }
    print_message("flat valleys: %d answers of %d (%d refused; %d with E*'s relative error above 0.1), %d beyond 3 "
                  "errors, worst %.2f errors\n", ok, NVALLEY, refused, okprof, out3, worst_dev);
    assert_true(out3 <= (int)ceil(COVER_FRAC * ok));
    /* the check answers where the profile bounds E* (curve 0, relative
     * error 0.36, 3.2 errors off, is one; the host's 400 curves: 3) */
    assert_true(okprof >= 1);
}
#endif /* !MDR_TARGET_TEST */

/* every test from the noise's start (noise_reseed): its draws, and the
 * figures it prints, are those of the test run alone (MDR_FIT_TESTS),
 * whichever tests ran before it (until stop 75 a test that did not seed
 * itself took the state the tests before it left: helper-78) */
#define FIT_TEST(f) cmocka_unit_test_setup(f, noise_reseed)

int main(void)
{
    const struct CMUnitTest tests[] = {
        FIT_TEST(test_model_vs_closed_form),
        FIT_TEST(test_roundtrip_closed_form),
        FIT_TEST(test_roundtrip_profiles),
        FIT_TEST(test_roundtrip_f32),
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_table_last_radius),
#endif
        FIT_TEST(test_f32_soft_lever),
        FIT_TEST(test_noise),
        FIT_TEST(test_pinned_top),
        FIT_TEST(test_pinned_rupture),
        FIT_TEST(test_pinned_noise),
        FIT_TEST(test_two_point),
        FIT_TEST(test_two_point_errors),
        FIT_TEST(test_two_point_tilt),
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_two_point_mc),
#endif
        FIT_TEST(test_approach),
        FIT_TEST(test_approach_misfit),
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_dwell),
        FIT_TEST(test_wadv_bound),
        FIT_TEST(test_few_receding),
        FIT_TEST(test_few_receding_clean),
#endif
        FIT_TEST(test_tabor),
        FIT_TEST(test_bad_input),
        FIT_TEST(test_jumps),
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_refuse_bad_start),
#endif
        FIT_TEST(test_refuse_units),
        FIT_TEST(test_refuse_distorted),
        FIT_TEST(test_refuse_runaway),
        FIT_TEST(test_unpinned),
        FIT_TEST(test_reversed),
        FIT_TEST(test_order_baseline_step),
        FIT_TEST(test_order_glitch),
        FIT_TEST(test_order_correlated_noise),
        FIT_TEST(test_order_short_tail),
        FIT_TEST(test_order_coarse),
        FIT_TEST(test_reversed_baseline_step),
        FIT_TEST(test_f32_pinned_offset),
        FIT_TEST(test_pinned_offset_clean),
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_pinned_glitch),
        FIT_TEST(test_written_digits),
        FIT_TEST(test_written_irregular),
        FIT_TEST(test_written_drift),
        FIT_TEST(test_written_nm),
        FIT_TEST(test_written_noisefree_end),
        FIT_TEST(test_written_nm_coarse),
#endif
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_tail_step),
        FIT_TEST(test_tail_glitch_clean),
        FIT_TEST(test_vdw_tail),
        FIT_TEST(test_f32_offset),
        FIT_TEST(test_f32_z0_rounding),
        FIT_TEST(test_tilt),
        FIT_TEST(test_tilt_approach),
        FIT_TEST(test_misfit_not_pinned),
        FIT_TEST(test_coarse_top),
        FIT_TEST(test_coarse_pinned),
        FIT_TEST(test_coarse_approach),
#endif
        /* the fit's known, open defects (make test-fit-known, built with
         * -DMDR_FIT_KNOWN_DEFECTS; docs/fitting.md) */
#ifdef MDR_FIT_KNOWN_DEFECTS
        FIT_TEST(test_known_coarse_approach),
        FIT_TEST(test_known_curved),
#endif
        FIT_TEST(test_fit_sweep),
#ifndef MDR_TARGET_TEST
        FIT_TEST(test_cover_fold),
        FIT_TEST(test_fold_saddle),
        FIT_TEST(test_fold_saddle_noise_free),
        FIT_TEST(test_coarse_fold_errors),
        FIT_TEST(test_refuse_valley),
#endif
    };
#ifndef MDR_TARGET_TEST
    if (getenv("MDR_FIT_TESTS")) { /* run only these (cmocka's pattern: * and ?) */
        cmocka_set_test_filter(getenv("MDR_FIT_TESTS"));
    }
#endif
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#endif
