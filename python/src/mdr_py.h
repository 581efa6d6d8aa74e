/* SPDX-License-Identifier: MIT */
/*
 * mdr_py.h: the C side of the Python package (python/mdr): loops over
 * arrays of points and over the ticks of a path, so that no Python loop runs
 * per point or per tick. Plain C99 over the public headers of libmdr and
 * the host helpers the CLI uses (examples/mdr_host.h); compiled with the
 * library's warning flags into the extension. Every function returns the
 * library's status and names the element or tick that failed.
 *
 * Arrays: inputs and outputs are double (SI), whatever the arithmetic; the
 * f32 functions convert each input to float (a finite value beyond float's
 * range is MDR_E_OVERFLOW) and widen each output exactly. Outputs of n
 * points with k columns are stored column after column, out[j * n + i]
 * (column j as the MDRPY_* index below), so each column is a contiguous
 * array. On an error nothing after the failing element is written.
 */
#ifndef MDR_PY_H
#define MDR_PY_H

#include <stddef.h>
#include <stdint.h>

#include "mdr.h"
#include "mdr_host.h"

/** Arithmetic of an engine. */
#define MDRPY_F32 0u
#define MDRPY_F64 1u
#define MDRPY_Q31 2u

/** mdrpy_run(): the event buffers are full; call again from tick0 + *done
 *  with room for more events (not an error: no status is negative). */
#define MDRPY_MORE 1

/** Columns of mdrpy_eq_*(): the equilibrium state at a (mdr_eqstate). */
#define MDRPY_EQ_A 0
#define MDRPY_EQ_D 1
#define MDRPY_EQ_F 2
#define MDRPY_EQ_DD_DA 3
#define MDRPY_EQ_DF_DA 4
#define MDRPY_EQ_DL 5
#define MDRPY_EQ_K_I 6
#define MDRPY_EQ_G 7
#define MDRPY_EQ_N 8
/** Columns of the flags of mdrpy_eq_*() (0 or 1). */
#define MDRPY_EQ_STABLE_LOAD 0
#define MDRPY_EQ_STABLE_GRIPS 1
#define MDRPY_EQ_NFLAGS 2

/** Columns of mdrpy_state_*(): any state (a, d). */
#define MDRPY_ST_A 0
#define MDRPY_ST_D 1
#define MDRPY_ST_F 2
#define MDRPY_ST_K_I 3
#define MDRPY_ST_G 4
#define MDRPY_ST_N 5

/** Columns of mdrpy_profile_*(): the equivalent profile at x. */
#define MDRPY_PR_G 0
#define MDRPY_PR_DG 1
#define MDRPY_PR_GINT 2
#define MDRPY_PR_N 3

/** Columns of the event values of mdrpy_run(). */
#define MDRPY_EV_A0 0
#define MDRPY_EV_D0 1
#define MDRPY_EV_F0 2
#define MDRPY_EV_A1 3
#define MDRPY_EV_D1 4
#define MDRPY_EV_F1 5
#define MDRPY_EV_N 6

/** An engine of any arithmetic with its table (nodes are the caller's). */
typedef struct {
    uint8_t arith;           /**< MDRPY_F32, _F64, _Q31 */
    double E, w, w_adv, k_m; /**< as given to init [Pa, J/m^2, J/m^2, N/m] */
    mdr_table_f32 table_f32; /**< f32 */
    mdr_engine_f32 engine_f32;
    mdr_table_f64 table_f64; /**< f64; q31: the table the q31 one is made from */
    mdr_engine_f64 engine_f64;
    mdr_host_q31 q;          /**< q31: table, engine, SI units */
} mdrpy_engine;

/** State of an engine in SI (double). */
typedef struct {
    double a, d, F;        /**< contact radius [m], depth [m], force [N] after the last step */
    double dissipated;     /**< energy dissipated over completed cycles [J] */
    double last_cycle;     /**< energy dissipated in the last completed cycle [J] */
    double a_max;          /**< table extent [m] */
    double L, D0, F0, Z0;  /**< q31: units of the Q formats [m, m, N, m]; 0 otherwise */
    uint32_t cycles;       /**< completed cycles */
    uint16_t springs;      /**< springs of the table */
    uint8_t contact;       /**< 1 in contact */
    uint8_t flags;         /**< sticky MDR_FLAG_* */
} mdrpy_info;

/** Result of mdrpy_fit_*() in double (mdr_fit_result of either arithmetic,
 *  widened exactly; fields as there). */
typedef struct {
    double E, w, z0, F_base;                 /**< [Pa, J/m^2, m, N] */
    double E_err, w_err, z0_err, F_base_err; /**< standard errors, same units */
    double rms;                              /**< rms residual [N] */
    double pull_off_F, pull_off_z, a_pull_off; /**< model's pull-off [N, m, m] */
    double mu, R_mu;                         /**< Tabor parameter [1], its radius [m] */
    double w_adv, w_adv_err;                 /**< approach (n_approach > 0) [J/m^2] */
    double F_slope, F_slope_err;             /**< the baseline's slope and its error [N/m] */
    uint32_t n, n_approach;                  /**< points used */
    uint32_t n_pinned;                       /**< retract samples left out as its pinned top */
    uint16_t iterations;                     /**< Levenberg-Marquardt iterations */
    uint8_t method, regime;                  /**< MDR_FIT_*, MDR_REGIME_* */
} mdrpy_fit_res;

/**
 * @brief Workspace of mdrpy_fit_*() and mdrpy_fit_model_*() for a curve of
 *        n points, in elements of the arithmetic: the samples converted
 *        (2 n) and the kernel's MDR_FIT_WORK_LEN(n).
 * @return the length, or 0 when it overflows size_t
 */
size_t mdrpy_fit_work_len(size_t n);

/** The change above which the f32 calls refuse their inputs' rounding
 *  (MDR_HOST_F32_EQ_MAX, examples/mdr_host.h), for the package's messages. */
double mdrpy_f32_eq_max(void);
/** The error above which they refuse an f32 answer (MDR_HOST_F32_ANSWER_MAX). */
double mdrpy_f32_answer_max(void);
double mdrpy_f32_slope_max(void);
double mdrpy_f32_crit_max(void);
/** The f32 fit's tolerances against f64's fit of the same samples
 *  (MDR_HOST_F32_FIT_MAX: a value's relative difference; MDR_HOST_F32_FIT_ERR:
 *  the ratio of f64's reported error to f32's). */
double mdrpy_f32_fit_max(void);
double mdrpy_f32_fit_err(void);
/**
 * @brief The f32 fit's check against f64's fit of the same samples
 *        (mdr_host_f32_fit_check, as `mdr fit --arith f32` makes it).
 * @param p32 E*, w, w_adv of the f32 fit; e32 their reported errors; p64,
 *            e64 f64's; n 2 (E*, w) or 3 (with the approach)
 * @param which set to 0 (E*), 1 (w) or 2 (w_adv): the one refused
 * @param x set to the relative difference (1) or the errors' ratio (2)
 * @return 0 the answer stands, 1 a value off f64's, 2 an error too small
 */
int mdrpy_f32_fit_check(const double p32[3], const double e32[3], const double p64[3], const double e64[3], int n,
                        int *which, double *x);
/** The name of mdrpy_f32_fit_check()'s which ("E*", "w", "w_adv"). */
const char *mdrpy_f32_fit_which(int which);

/**
 * @brief The CLI's two f32 checks of `eq` and `curve` over n points, from
 *        one pair of f64 contacts (mdr_host_f32_eq_pair: at the values
 *        given and at their roundings to float) and one f64 state per
 *        point (mdr_host_f32_eq_pair_check()): point i is refused where
 *        f32's rounding of the inputs moves its state by more than
 *        MDR_HOST_F32_EQ_MAX (*what 0, *value the change; DBL_MAX: f64
 *        takes the values and refuses their rounding; skipped where every
 *        input is already a float), or, answered (i < k), where its f32
 *        answer d32[i], F32[i] lies more than MDR_HOST_F32_ANSWER_MAX from
 *        the f64 state at the values given, or with dd32, dF32 (the
 *        equilibria's dd/da, dF/da; NULL for states) those of f64's
 *        equilibrium, with K32 (the states' K_I; NULL for equilibria) that
 *        of the state, on mdr_host_f32_K_err()'s scale (*what 1 for d or
 *        F, 2 dd/da, 3 dF/da, 4 K_I, whichever is off most; *value the
 *        error).
 *        The contact: a sampled tip's (r not NULL: m radii r, the slopes s
 *        formed in double as mdrpy_contact_tip forms them, converted to
 *        float as `mdr eq --profile table --arith f32` converts them; the
 *        memory for those taken and freed here, and where it is not there
 *        point 0 is refused with *what 0, *value DBL_MAX) or else the
 *        analytic (kind, p). p, E, w: the values given (not rounded).
 * @param d  NULL: the equilibria at a; else the states (a[i], d[i])
 * @param k  the points answered (the f32 loop's refusal at k, or n): the
 *           rounding is checked up to k, which it refuses first, the
 *           answers below k
 * @return the index of the first refused point, or n (*what, *value
 *         untouched)
 */
size_t mdrpy_f32_eq_check(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m, double E,
                          double w, size_t n, const double *a, const double *d, size_t k, const double *d32,
                          const double *F32, const double *dd32, const double *dF32, const double *K32, int *what,
                          double *value);

/**
 * @brief The error of an f32 critical state (a32, d32, F32, the most tensile
 *        force Fm32) against f64's at the values given, from the start *a0
 *        (NULL: f64's default start), as `mdr critical --arith f32` checks
 *        it (mdr_host_f32_crit_err(); the contact as mdrpy_f32_eq_check()
 *        takes it); DBL_MAX where memory for a tip's samples is not there.
 */
double mdrpy_f32_crit_wrong(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m, double E,
                            double w, uint8_t control, double k_m, const double *a0, double a32, double d32, double F32,
                            double Fm32);

/**
 * @brief The first of n f32 stresses s32[i] at rr[i] in the states (a[i],
 *        d[i]) (d NULL: the equilibria at a) beyond MDR_HOST_F32_ANSWER_MAX
 *        of f64's at the values given (mdr_host_f32_stress_err(), as `mdr
 *        stress --a` checks it; the contact as mdrpy_f32_eq_check() takes
 *        it); *err the refused stress's error. Where memory for a tip's
 *        converted samples is not there, point 0 with DBL_MAX.
 * @return its index, or n
 */
size_t mdrpy_f32_stress_wrong(uint8_t kind, const double p[3], const double *r, const double *s, uint16_t m,
                              double E, double w, size_t n, const double *a, const double *d, const double *rr,
                              const double *s32, double *err);

/* ---- contacts: one set per floating arithmetic (mdr_py_t.h) ---- */
#define MDR_TEMPLATE "mdr_py_t.h"
#include "mdr_each_arith.h"

/* ---- engines ---- */

/**
 * @brief Default table extent for a path (mdr_host_extent(), as the CLI):
 *        computed in f32 for MDRPY_F32, in f64 otherwise.
 * @return MDR_OK or the library's status (contact init, default start, eq)
 */
mdr_status mdrpy_extent(uint8_t arith, uint8_t kind, const double p[3], double E, double w,
                        uint8_t control, double k_m, const double *path, size_t npath,
                        double *a_max);

/**
 * @brief Default table extent of a q31 engine for a path
 *        (mdr_host_extent_q31(), as `mdr cycle --arith q31`): the f64
 *        extent of mdrpy_extent(), doubled (at most MDR_HOST_Q31_WIDEN
 *        times) until the q31 table of springs springs exists and every
 *        tick of the path (steps per segment) fits the q31 ranges.
 * @return MDR_OK; MDR_E_NULL (npath < 2); MDR_E_PARAM (steps < 1);
 *         MDR_E_SIZE (no memory); or the library's status (contact init,
 *         default start, eq)
 */
mdr_status mdrpy_extent_q31(uint8_t kind, const double p[3], double E, double w, double w_adv,
                            uint8_t control, double k_m, uint16_t springs, const double *path,
                            size_t npath, long steps, double *a_max);

/**
 * @brief Engine on the spring table of an analytic profile of extent a_max.
 *        f32: f32 contact and table; f64: f64; q31: the f64 table converted
 *        (mdr_table_q31_from_f64) and the double init, as `mdr cycle`.
 * @param n32, n64, nq  caller storage of MDR_TABLE_NODES(springs) nodes for
 *        the arithmetic (n64 and nq for q31); the others may be NULL
 * @return MDR_OK or the library's status (x is then unusable: build it
 *         again)
 */
mdr_status mdrpy_engine_profile(mdrpy_engine *x, uint8_t arith, uint8_t kind, const double p[3],
                                double E, double w, double w_adv, double k_m, uint16_t springs,
                                double a_max, mdr_node_f32 *n32, mdr_node_f64 *n64,
                                mdr_node_q31 *nq);

/**
 * @brief Engine on the spring table of a sampled gap profile f(r_i), m
 *        points, extent r[m-1], built as `mdr cycle --profile table` builds
 *        it: the slopes formed in double, the contact of the samples
 *        (mdr_host_tip_contact(), mdr_contact_init_table_*), its table
 *        (mdr_table_init_profile_*; the same model as mdr_table_init_gap_*).
 *        Nodes as above.
 */
mdr_status mdrpy_engine_tip(mdrpy_engine *x, uint8_t arith, const double *r, const double *f,
                            uint16_t m, double E, double w, double w_adv, double k_m,
                            uint16_t springs, mdr_node_f32 *n32, mdr_node_f64 *n64,
                            mdr_node_q31 *nq);

/** @brief Back to separated, no history, on the same table (the init again). */
mdr_status mdrpy_engine_reset(mdrpy_engine *x);

/** @brief The engine's state in SI. */
void mdrpy_engine_info(const mdrpy_engine *x, mdrpy_info *o);

/**
 * @brief Check a path before running it: every value finite, and for q31
 *        inside the steps' documented input range (+-2 units of D0, F0 or
 *        Z0). x NULL: finiteness only (before the engine is built).
 * @param[out] bad  index of the first refused value
 * @return MDR_OK, MDR_E_CONTROL (control not MDR_CONTROL_*), MDR_E_NONFINITE,
 *         MDR_E_OVERFLOW (f32: beyond float; q31: beyond the range, or a
 *         nonzero vertex below half an LSB, which rounds to 0:
 *         mdr_host_q31_lost(), as `mdr cycle --arith q31`)
 */
mdr_status mdrpy_check_path(const mdrpy_engine *x, uint8_t control, const double *path,
                            size_t npath, size_t *bad);

/**
 * @brief Step the engine along ticks tick0 ... tick0 + nticks - 1 of the
 *        piecewise-linear path (mdr_host_path_value(): tick 0 is path[0],
 *        then steps ticks per segment), as `mdr cycle`.
 * @param z, d, F, a  nticks outputs each [m, m, N, m], or all NULL (the
 *        loop without storing: the benchmark's C step time)
 * @param event   nticks MDR_EV_* codes, or NULL
 * @param ev_cap  room for events in ev_step (tick index), ev_code
 *        ([ev_cap][2]: MDR_EV_*, jumps) and ev_val ([ev_cap][MDRPY_EV_N]);
 *        ev_n events stored so far (in and out); 0: events not stored
 * @param[out] done  ticks completed
 * @return MDR_OK (all done); MDRPY_MORE (event buffer full: *done ticks
 *         done); a step's status (the tick *done was refused, the engine
 *         is as after tick *done - 1); MDR_E_OVERFLOW for q31 when a step
 *         saturated an output (MDR_FLAG_SAT newly set; that tick stored)
 */
mdr_status mdrpy_run(mdrpy_engine *x, uint8_t control, const double *path, size_t npath, long steps,
                     size_t tick0, size_t nticks, double *z, double *d, double *F, double *a,
                     uint8_t *event, size_t ev_cap, size_t *ev_n, size_t *ev_step,
                     uint8_t *ev_code, double *ev_val, size_t *done);

#endif /* MDR_PY_H */
