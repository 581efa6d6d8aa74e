/*
 * port/link_check.c: a freestanding program that calls the public functions
 * of one arithmetic, linked with -nostdlib -lgcc to prove lib/ needs nothing
 * else; `make cross` / `make size` link it once per core and arithmetic:
 *   MDR_LC_F32     closed forms, critical states, spring tables and the f32
 *                  engine (every profile; add MDR_LC_STRESS for the stress
 *                  functions)
 *   MDR_LC_Q31     a q31 engine on a table made from a profile: table
 *                  conversion, float init and the integer steps
 *   MDR_LC_SCENE   alone: the minimal scene (paraboloid, f32, force only,
 *                  table-free)
 * Everything else is dropped by --gc-sections, so the program's size is
 * what a firmware using those functions pays.
 * The only library functions it may need are on the allow-list (a firmware's
 * C library provides them; GCC may emit calls to them for struct copies):
 * memcpy, memset. They are defined here so the link is complete.
 */
#include <stddef.h>

#include "mdr.h"

void *memcpy(void *dst, const void *src, size_t n);
void *memset(void *dst, int v, size_t n);
void link_check_entry(void);

void *memcpy(void *dst, const void *src, size_t n)
{
    unsigned char *d = dst;
    const unsigned char *s = src;
    while (n--) {
        *d++ = *s++;
    }
    return dst;
}

void *memset(void *dst, int v, size_t n)
{
    unsigned char *d = dst;
    while (n--) {
        *d++ = (unsigned char)v;
    }
    return dst;
}

volatile float mdr_link_sink;

#ifdef MDR_LC_SCENE
/* The minimal scene (issue 7): a paraboloid finger, f32, force only, fixed
 * grips, no table. Nothing else of the library is linked. */
void link_check_entry(void)
{
    mdr_scene_f32 s;
    mdr_step_f32 o;
    int i;
    if (mdr_scene_init_paraboloid_f32(&s, 2e-3f, 1e6f, 0.05f, 0.02f, 0.0f, MDR_OUT_FORCE, NULL) != MDR_OK) {
        return;
    }
    for (i = 0; i < 100; i++) {
        if (mdr_scene_step_d_f32(&s, 1e-7f * (float)i, &o) == MDR_OK) {
            mdr_link_sink = o.F;
        }
    }
}
#else
void link_check_entry(void)
{
    static const float p[3] = {1e-6f, 2e-7f, 1e-5f};
    static mdr_node_f32 nodes[MDR_TABLE_NODES(16)];
    mdr_contact_f32 c;
    mdr_table_f32 t;
    uint8_t kind;
    /* every profile kind: each one's code is linked */
    for (kind = MDR_PROFILE_PARABOLOID; kind <= MDR_PROFILE_WAVY; kind++) {
        if (mdr_contact_init_f32(&c, kind, p, 1e9f, 0.1f) != MDR_OK ||
            mdr_table_init_profile_f32(&t, nodes, 16, &c, 1e-7f) != MDR_OK) {
            continue;
        }
#ifdef MDR_LC_F32
        {
            /* closed forms and critical states */
            mdr_eqstate_f32 e;
            mdr_critstate_f32 o;
            float a0 = 0.0f, g = 0.0f, dg = 0.0f, G = 0.0f;
            (void)mdr_profile_eval_f32(&c, 1e-7f, &g, &dg, &G);
            (void)mdr_eq_f32(&c, 1e-7f, &e);
            (void)mdr_default_start_f32(&c, &a0);
            (void)mdr_critical_f32(&c, MDR_CONTROL_LOAD, 1.0f, a0, &o);
            mdr_link_sink = e.F + o.F + g + dg + G;
        }
#ifdef MDR_LC_STRESS
        {
            float k = 0.0f, s = 0.0f;
            (void)mdr_stress_intensity_f32(&c, 1e-7f, 0.0f, &k, NULL);
            (void)mdr_stress_f32(&c, 1e-7f, 0.0f, &s);
            (void)mdr_stress_at_f32(&c, 1e-7f, 0.0f, 0.0f, &s);
            mdr_link_sink = k + s;
        }
#endif
        {
            /* the spring engine: every table builder and step function */
            static const float r[3] = {0.0f, 1e-7f, 2e-7f}, f[3] = {0.0f, 1e-9f, 4e-9f};
            mdr_engine_f32 en;
            mdr_step_f32 st;
            mdr_table_f32 t2;
            (void)mdr_table_init_g_f32(&t2, nodes, 2, 1e-7f, f);
            (void)mdr_table_init_gap_f32(&t2, nodes, 16, r, f, 3);
            if (mdr_engine_init_f32(&en, &t, 1e9f, 0.1f, 0.05f, 1.0f) == MDR_OK) {
                (void)mdr_engine_step_d_f32(&en, 1e-9f, &st);
                (void)mdr_engine_step_F_f32(&en, 1e-9f, &st);
                (void)mdr_engine_step_z_f32(&en, 1e-9f, &st);
                mdr_link_sink = st.F + (float)mdr_engine_clear_flags_f32(&en);
            }
            (void)mdr_event_str(MDR_EV_NONE);
        }
#endif
#ifdef MDR_LC_Q31
        {
            /* the q31 engine: table conversion, float init, integer steps */
            static mdr_node_q31 qn[MDR_TABLE_NODES(16)];
            mdr_table_q31 tq;
            mdr_engine_q31 eq;
            mdr_step_q31 sq;
            if (mdr_table_q31_from_f32(&tq, qn, &t) == MDR_OK &&
                mdr_engine_init_q31_f32(&eq, &tq, 1e9f, 0.1f, 0.05f, 1.0f) == MDR_OK) {
                (void)mdr_engine_step_d_q31(&eq, mdr_q31_in(&eq, MDR_Q_D, 1e-9f), &sq);
                (void)mdr_engine_step_F_q31(&eq, 1, &sq);
                (void)mdr_engine_step_z_q31(&eq, 1, &sq);
                mdr_link_sink = mdr_q31_out(&eq, MDR_Q_F, sq.F) + mdr_q31_energy(&eq, eq.work) +
                                (float)mdr_engine_clear_flags_q31(&eq);
            }
        }
#endif
    }
    (void)mdr_status_str(MDR_OK);
}
#endif /* MDR_LC_SCENE */
