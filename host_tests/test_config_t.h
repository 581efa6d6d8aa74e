/* SPDX-License-Identifier: MIT */
/*
 * test_config_t.h: the checks of test_config.c for one floating arithmetic
 * (included once per arithmetic with T and SFX defined, like the library's
 * templates). Tolerances: test_config.c.
 */

/* Every profile kind: built ones initialise, removed ones answer
 * MDR_E_DISABLED and leave the instance as it was. */
static void SFX(profiles)(void)
{
    static const T p[3] = {(T)1e-6, (T)2e-7, (T)1e-5};
    uint8_t kind;
    for (kind = MDR_PROFILE_PARABOLOID; kind <= MDR_PROFILE_WAVY; kind++) {
        SFX(mdr_contact) c, keep;
        SFX(mdr_eqstate) e;
        mdr_status st;
        memset(&c, 0x5a, sizeof c);
        keep = c;
        st = SFX(mdr_contact_init)(&c, kind, p, (T)1e9, (T)0.1);
        if (!MDR_CFG_HAS_PROFILE(kind)) {
            assert_int_equal(st, MDR_E_DISABLED);
            assert_memory_equal(&c, &keep, sizeof c);
            continue;
        }
        assert_int_equal(st, MDR_OK);
        assert_int_equal(SFX(mdr_eq)(&c, (T)1e-7, &e), MDR_OK);
        if (kind != MDR_PROFILE_WAVY) { /* the wavy profile: test_vectors (GSL) */
            /* d and F against the closed forms (closed_forms.h) at the inputs as T holds them */
            double pd[3] = {(double)p[0], (double)p[1], (double)p[2]}, a = (double)(T)1e-7;
            double g, dg, G, dl = sqrt(2 * M_PI * a * (double)(T)0.1 / (double)(T)1e9);
            double tol = sizeof(T) == sizeof(float) ? TC_TOL32 : TC_TOL64;
            profile_cf(kind, pd, a, &g, &dg, &G);
            const int f32 = sizeof(T) == sizeof(float);
            rel_le(e.d, g - dl, g + dl, tol, f32 ? "d = g - dl (f32)" : "d = g - dl (f64)");
            rel_le(e.F, 2 * (double)(T)1e9 * (a * (g - dl) - G), 2 * (double)(T)1e9 * (a * (g + dl) + G), tol,
                   f32 ? "F = 2E*(a d - G) (f32)" : "F = 2E*(a d - G) (f64)");
        }
#if MDR_CFG_STRESS
        {
            T sig;
            assert_int_equal(SFX(mdr_stress)(&c, (T)1e-7, (T)5e-8, &sig), MDR_OK);
            if (kind == MDR_PROFILE_PARABOLOID) {
                /* 4.27 with 4.41: sigma = (E / pi)((g - d)/S - (2/R) S), S = sqrt(a^2 - r^2) */
                double a = (double)(T)1e-7, r = (double)(T)5e-8, R = (double)p[0], E = (double)(T)1e9;
                double S = sqrt(a * a - r * r), dl = sqrt(2 * M_PI * a * (double)(T)0.1 / E);
                double tol = sizeof(T) == sizeof(float) ? TC_TOL32 : TC_TOL64;
                rel_le(sig, E / M_PI * (dl / S - 2 / R * S), E / M_PI * (dl / S + 2 / R * S), tol,
                       sizeof(T) == sizeof(float) ? "paraboloid stress (f32)" : "paraboloid stress (f64)");
            }
        }
#endif
    }
}

#if MDR_CFG_SCENE && MDR_CFG_PROFILE_PARABOLOID
static void SFX(scene)(void)
{
    SFX(mdr_scene) s, all, keep;
    SFX(mdr_energy) en;
    SFX(mdr_step) o, oa;
    double Fmin = 0.0;
    int i;
    assert_int_equal(SFX(mdr_scene_init_paraboloid)(&s, (T)TC_R, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0,
                                                    MDR_OUT_FORCE, NULL),
                     MDR_OK);
    memset(&keep, 0x5a, sizeof keep);
    all = keep;
#if MDR_CFG_EVENTS
    assert_int_equal(SFX(mdr_scene_init_paraboloid)(&all, (T)TC_R, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0,
                                                    MDR_OUT_ALL, &en),
                     MDR_OK);
#else
    /* the events group and the energy are not in this build */
    assert_int_equal(SFX(mdr_scene_init_paraboloid)(&all, (T)TC_R, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0,
                                                    MDR_OUT_EVENTS, NULL),
                     MDR_E_DISABLED);
    assert_int_equal(SFX(mdr_scene_init_paraboloid)(&all, (T)TC_R, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0,
                                                    MDR_OUT_FORCE, &en),
                     MDR_E_DISABLED);
    assert_memory_equal(&all, &keep, sizeof all);
    assert_int_equal(SFX(mdr_scene_init_paraboloid)(&all, (T)TC_R, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0,
                                                    MDR_OUT_RADIUS, NULL),
                     MDR_OK);
#endif
    for (i = 0; i <= NTICK; i++) {
        T d = (T)grips_d(i);
        assert_int_equal(SFX(mdr_scene_step_d)(&s, d, &o), MDR_OK);
        assert_int_equal(SFX(mdr_scene_step_d)(&all, d, &oa), MDR_OK);
        /* the outputs asked for do not change the force */
        assert_memory_equal(&o.F, &oa.F, sizeof o.F);
        assert_memory_equal(&o.d, &oa.d, sizeof o.d);
        Fmin = fmin(Fmin, (double)o.F);
    }
    rel_le(Fmin, JKR_F, 0, TOL_MIN, "scene: min F of a grips cycle vs -1.5 pi w R");
}
#endif

#if MDR_CFG_ENGINE && MDR_CFG_PROFILE_PARABOLOID
static void SFX(engine)(void)
{
    static SFX(mdr_node) node[MDR_TABLE_NODES(NSPR)];
    const T p[3] = {(T)TC_R, (T)0.0, (T)0.0};
    SFX(mdr_contact) c;
    SFX(mdr_table) tab;
    SFX(mdr_engine) e;
    SFX(mdr_step) o;
    double Fmin = 0.0;
    int i;
    assert_int_equal(SFX(mdr_contact_init)(&c, MDR_PROFILE_PARABOLOID, p, (T)TC_E, (T)TC_W), MDR_OK);
    assert_int_equal(SFX(mdr_table_init_profile)(&tab, node, NSPR, &c, (T)AMAX), MDR_OK);
    assert_int_equal(SFX(mdr_engine_init)(&e, &tab, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0), MDR_OK);
    for (i = 0; i <= NTICK; i++) {
        assert_int_equal(SFX(mdr_engine_step_d)(&e, (T)grips_d(i), &o), MDR_OK);
        Fmin = fmin(Fmin, (double)o.F);
    }
    rel_le(Fmin, JKR_F, 0, TOL_MIN, "engine: min F of a grips cycle vs -1.5 pi w R");
#if MDR_CFG_Q31
    {
        static mdr_node_q31 qn[MDR_TABLE_NODES(NSPR)];
        mdr_table_q31 tq;
        mdr_engine_q31 eq;
        mdr_step_q31 sq;
        const double Fmin_float = Fmin;
        Fmin = 0.0;
        assert_int_equal(SFX(mdr_table_q31_from)(&tq, qn, &tab), MDR_OK);
        assert_int_equal(SFX(mdr_engine_init_q31)(&eq, &tq, (T)TC_E, (T)TC_W, (T)TC_W, (T)0.0), MDR_OK);
        for (i = 0; i <= NTICK; i++) {
            /* the same (rounded) depth as the float engine, as Q2.29 of D0 */
            double d = (double)(T)grips_d(i) / (double)eq.D0 * MDR_Q29_ONE;
            assert_int_equal(mdr_engine_step_d_q31(&eq, (int32_t)lround(d), &sq), MDR_OK);
            Fmin = fmin(Fmin, (double)sq.F / MDR_Q29_ONE * (double)eq.F0);
        }
        /* against the float engine on the same depths, in LSB of F0
         * (one LSB is 7e-7 of this minimum: D0 is set by the table's
         * extent, 3 R) */
        rel_le(Fmin, Fmin_float, (double)eq.F0 / MDR_Q29_ONE, TOL_MIN_Q31_LSB,
               "q31: min F of a grips cycle vs the float engine's (LSB)");
    }
#endif
}
#endif
