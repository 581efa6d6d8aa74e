/*
 * mdr_cli_t.h: the commands of the mdr CLI for one arithmetic, included by
 * mdr_cli.c with CLI_T (float/double), CLI_SFX(name) and CLI_FMT ("%.9g" or
 * "%.17g") defined. Returns the process exit status.
 */

/* Controlled variable on the equilibrium curve (retraction work w). */
static CLI_T CLI_SFX(ctl_of)(const struct cli_args *A, const CLI_SFX(mdr_eqstate) *e)
{
    if (A->control == MDR_CONTROL_LOAD) {
        return e->F;
    }
    if (A->control == MDR_CONTROL_GRIPS) {
        return e->d;
    }
    return e->d + e->F / (CLI_T)A->k_m;
}

/* Default table extent for a cycle: 1.25 x the radius where the equilibrium
 * curve (work w, the widest of every approach branch) reaches the path's
 * largest value, found by doubling from mdr_default_start(); capped by the
 * profile's domain (flat punch: a0, sphere: 0.999 R). */
static int CLI_SFX(default_extent)(const struct cli_args *A, const CLI_SFX(mdr_contact) *c,
                                   CLI_T *a_max)
{
    CLI_T a, cap = (CLI_T)1e30, umax = (CLI_T)A->path[0];
    long i;
    mdr_status st;
    for (i = 1; i < A->npath; i++) {
        umax = (CLI_T)A->path[i] > umax ? (CLI_T)A->path[i] : umax;
    }
    if (A->kind == MDR_PROFILE_FLATPUNCH) {
        *a_max = c->p[0];
        return 0;
    }
    if (A->kind == MDR_PROFILE_SPHERE) {
        cap = (CLI_T)0.999 * c->p[0];
    }
    st = CLI_SFX(mdr_default_start)(c, &a);
    if (st != MDR_OK) {
        return cli_fail("default --a-max", st);
    }
    for (i = 0; i < 200 && a < cap; i++) {
        CLI_SFX(mdr_eqstate) e;
        st = CLI_SFX(mdr_eq)(c, a, &e);
        if (st != MDR_OK) {
            return cli_fail("default --a-max", st);
        }
        if (CLI_SFX(ctl_of)(A, &e) >= umax) {
            break;
        }
        a *= 2;
    }
    a *= (CLI_T)1.25;
    *a_max = a < cap ? a : cap;
    return 0;
}

/* The scene's contact. A tabulated profile keeps the samples it points to
 * in *keep (malloc'd, freed by the caller after the contact's last use):
 * r and the slopes formed in double by tip_slopes(), then converted. */
static int CLI_SFX(make_contact)(const struct cli_args *A, CLI_SFX(mdr_contact) *c, CLI_T **keep)
{
    mdr_status st;
    *keep = NULL;
    if (A->kind == KIND_TABLE) {
        CLI_T *r = malloc(2 * (size_t)A->ntab * sizeof *r);
        long i;
        if (r == NULL) {
            return cli_fail("table", MDR_E_SIZE);
        }
        for (i = 0; i < A->ntab; i++) {
            r[i] = (CLI_T)A->tr[i];
            r[A->ntab + i] = i + 1 < A->ntab ? (CLI_T)A->ts[i] : (CLI_T)0;
        }
        *keep = r;
        st = CLI_SFX(mdr_contact_init_table)(c, r, r + A->ntab, (uint16_t)A->ntab, (CLI_T)A->E,
                                             (CLI_T)A->w);
        return st == MDR_OK ? 0 : cli_fail(st == MDR_E_PARAM ? "--E/--w" : A->file, st);
    }
    {
        CLI_T p[3] = {(CLI_T)A->p[0], (CLI_T)A->p[1], (CLI_T)A->p[2]};
        st = CLI_SFX(mdr_contact_init)(c, A->kind, p, (CLI_T)A->E, (CLI_T)A->w);
    }
    return st == MDR_OK ? 0 : cli_fail("profile/material", st);
}

/* The spring table of the scene into malloc'd nodes (freed by the caller):
 * from the contact's closed forms, or for a tabulated profile from the same
 * exact Abel integration (the same nodes as mdr_table_init_gap() in double;
 * in float from the slopes formed in double). */
static int CLI_SFX(make_table)(const struct cli_args *A, CLI_SFX(mdr_table) *tab,
                               CLI_SFX(mdr_node) **nodes)
{
    uint16_t n = (uint16_t)A->springs;
    mdr_status st;
    CLI_SFX(mdr_contact) c;
    CLI_T *keep, a_max = (CLI_T)A->a_max;
    int rc;
    *nodes = malloc(MDR_TABLE_NODES(n) * sizeof **nodes);
    if (*nodes == NULL) {
        return cli_fail("table", MDR_E_SIZE);
    }
    rc = CLI_SFX(make_contact)(A, &c, &keep);
    if (rc != 0) {
        free(keep);
        return rc;
    }
    if (A->kind == KIND_TABLE && !A->have_amax) {
        a_max = c.p[0]; /* the last sample */
    } else if (!A->have_amax && (rc = CLI_SFX(default_extent)(A, &c, &a_max)) != 0) {
        free(keep);
        return rc;
    }
    st = CLI_SFX(mdr_table_init_profile)(tab, *nodes, n, &c, a_max);
    free(keep);
    if (st != MDR_OK) {
        return cli_fail("--a-max", st);
    }
    return 0;
}

/* mdr table: the table as C source (round-trip exact literals). */
static int CLI_SFX(table_cmd)(const struct cli_args *A)
{
    CLI_SFX(mdr_table) tab;
    CLI_SFX(mdr_node) *nodes = NULL;
    const char *sfx = CLI_NAME, *lit = CLI_LIT;
    int rc = CLI_SFX(make_table)(A, &tab, &nodes);
    unsigned i;
    if (rc == 0 && A->q31) {
        mdr_table_q31 tq;
        mdr_node_q31 *qn = malloc(MDR_TABLE_NODES(tab.n) * sizeof *qn);
        mdr_status st = MDR_E_SIZE;
        if (qn != NULL) {
            st = CLI_SFX(mdr_table_q31_from)(&tq, qn, &tab);
        }
        if (st != MDR_OK) {
            free(qn);
            free(nodes);
            return cli_fail("q31 table (--springs must be a power of two)", st);
        }
        printf("/* q31 spring table generated by `mdr table --arith q31` (libmdr %d.%d):\n"
               " * %u springs, x_max = L = %.9g + %.9g m, depth unit Dg = %.9g m. Nodes\n"
               " * {g, G, t, s, b} in Q formats; see lib/include/mdr_q31.h. */\n"
               "#include \"mdr.h\"\n\n"
               "static const mdr_node_q31 %s_nodes[%u] = {\n",
               MDR_VERSION_MAJOR, MDR_VERSION_MINOR, (unsigned)tq.n, (double)tq.L, (double)tq.L_lo,
               (double)tq.Dg, A->name, (unsigned)tq.n + 1u);
        for (i = 0; i <= tq.n; i++) {
            printf("    {%ld, %ld, %ld, %ld, %ld},\n", (long)qn[i].g, (long)qn[i].G, (long)qn[i].t,
                   (long)qn[i].s, (long)qn[i].b);
        }
        printf("};\n\nconst mdr_table_q31 %s = {%s_nodes, %.9ef, %.9ef, %.9ef, %ld, %u, %u, %u, %u};\n",
               A->name, A->name, (double)tq.L, (double)tq.L_lo, (double)tq.Dg, (long)tq.gmax,
               (unsigned)tq.n, (unsigned)tq.m, (unsigned)tq.fb, (unsigned)tq.wall);
        free(qn);
    } else if (rc == 0) {
        printf("/* spring table generated by `mdr table` (libmdr %d.%d): %u springs of\n"
               " * width " CLI_FMT " m, x_max = " CLI_FMT " m. Nodes {g [m], G [m^2], sqrt(x) [m^0.5],\n"
               " * q [m^2]}; see lib/include/mdr_engine_t.h. */\n"
               "#include \"mdr.h\"\n\n"
               "static const mdr_node_%s %s_nodes[%u] = {\n",
               MDR_VERSION_MAJOR, MDR_VERSION_MINOR, (unsigned)tab.n, (double)tab.h,
               (double)(tab.h * (CLI_T)tab.n), sfx, A->name, (unsigned)tab.n + 1u);
        for (i = 0; i <= tab.n; i++) {
            printf("    {" CLI_EFMT "%s, " CLI_EFMT "%s, " CLI_EFMT "%s, " CLI_EFMT "%s},\n",
                   (double)nodes[i].g, lit, (double)nodes[i].G, lit, (double)nodes[i].t, lit,
                   (double)nodes[i].q, lit);
        }
        printf("};\n\nconst mdr_table_%s %s = {%s_nodes, " CLI_EFMT "%s, %u, %u};\n", sfx,
               A->name, A->name, (double)tab.h, lit, (unsigned)tab.n, (unsigned)tab.wall);
    }
    free(nodes);
    return rc;
}

/* mdr cycle: drive the engine along the path. */
static int CLI_SFX(cycle_cmd)(const struct cli_args *A)
{
    CLI_SFX(mdr_table) tab;
    CLI_SFX(mdr_node) *nodes = NULL;
    CLI_SFX(mdr_engine) eng;
    CLI_SFX(mdr_step) o, po;
    cli_q31 Q;
    long seg, j, step = 0, events = 0, jumps = 0, have_po = 0, have_t = 0;
    double tF = 0, td = 0; /* the most tensile force along the path, and its depth */
    int rc = CLI_SFX(make_table)(A, &tab, &nodes);
    mdr_status st;
    char *list = NULL;
    size_t llen = 0, lcap = 0;
    double dissipated;
    if (rc != 0) {
        free(nodes);
        return rc;
    }
    Q.nodes = NULL;
    if (A->q31) {
        Q.nodes = malloc(MDR_TABLE_NODES(tab.n) * sizeof *Q.nodes);
        st = MDR_E_SIZE;
        if (Q.nodes != NULL) {
            st = CLI_SFX(mdr_table_q31_from)(&Q.t, Q.nodes, &tab);
        }
        if (st != MDR_OK) {
            free(Q.nodes);
            free(nodes);
            return cli_fail("q31 table (--springs must be a power of two)", st);
        }
        st = CLI_SFX(mdr_engine_init_q31)(&Q.e, &Q.t, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                          (CLI_T)A->k_m);
        Q.L = (double)Q.t.L + (double)Q.t.L_lo;
        Q.D0 = (double)Q.e.D0;
        Q.F0 = 2.0 * A->E * Q.L * Q.D0;
        Q.Z0 = (double)Q.e.Z0;
    } else {
        st = CLI_SFX(mdr_engine_init)(&eng, &tab, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                      (CLI_T)A->k_m);
    }
    if (st != MDR_OK) {
        free(Q.nodes);
        free(nodes);
        return cli_fail("engine (--E, --w, --w-adv, --k-machine)", st);
    }
    memset(&po, 0, sizeof po);
    printf("step,z,d,F,a,event\n");
    for (seg = 0; seg + 1 < A->npath && rc == 0; seg++) {
        for (j = seg == 0 ? 0 : 1; j <= A->steps; j++) {
            double v = A->path[seg] + (A->path[seg + 1] - A->path[seg]) * (double)j / (double)A->steps;
            if (A->q31) {
                mdr_step_q31 oq;
                st = q31_step(&Q, A->control, v, &oq);
                if (st == MDR_OK) {
                    const double ua = Q.L / 1073741824.0, ud = Q.D0 / 536870912.0;
                    const double uF = Q.F0 / 536870912.0, uz = Q.Z0 / 536870912.0;
                    o.z = (CLI_T)(oq.z * (Q.e.machine ? uz : ud));
                    o.d = (CLI_T)(oq.d * ud);
                    o.F = (CLI_T)(oq.F * uF);
                    o.a = (CLI_T)(oq.a * ua);
                    o.a0 = (CLI_T)(oq.a0 * ua);
                    o.d0 = (CLI_T)(oq.d0 * ud);
                    o.F0 = (CLI_T)(oq.F0 * uF);
                    o.a1 = (CLI_T)(oq.a1 * ua);
                    o.d1 = (CLI_T)(oq.d1 * ud);
                    o.F1 = (CLI_T)(oq.F1 * uF);
                    o.event = oq.event;
                    o.jumps = oq.jumps;
                }
            } else if (A->control == MDR_CONTROL_GRIPS) {
                st = CLI_SFX(mdr_engine_step_d)(&eng, (CLI_T)v, &o);
            } else if (A->control == MDR_CONTROL_LOAD) {
                st = CLI_SFX(mdr_engine_step_F)(&eng, (CLI_T)v, &o);
            } else {
                st = CLI_SFX(mdr_engine_step_z)(&eng, (CLI_T)v, &o);
            }
            if (st != MDR_OK) {
                fprintf(stderr, "mdr: step %ld (value %.9g): %s (status %d)%s\n", step, v,
                        mdr_status_str(st), (int)st,
                        st == MDR_E_OUTSIDE ? "; raise --a-max" : "");
                rc = 1;
                break;
            }
            printf("%ld," CLI_FMT "," CLI_FMT "," CLI_FMT "," CLI_FMT ",%s\n", step, (double)o.z,
                   (double)o.d, (double)o.F, (double)o.a, mdr_event_str(o.event));
            /* the states of the step: after it, and around a jump (the last
             * stable state before it, the state right after it) */
            {
                const double Fs[3] = {(double)o.F, (double)o.F0, (double)o.F1};
                const double ds[3] = {(double)o.d, (double)o.d0, (double)o.d1};
                int k, nk = o.event != MDR_EV_NONE ? 3 : 1;
                for (k = 0; k < nk; k++) {
                    if (Fs[k] < 0 && (!have_t || Fs[k] < tF)) {
                        tF = Fs[k];
                        td = ds[k];
                        have_t = 1;
                    }
                }
            }
            if (o.event != MDR_EV_NONE) {
                char buf[512];
                int len = snprintf(buf, sizeof buf,
                                   "%s{\"step\": %ld, \"event\": \"%s\", \"jumps\": %u, "
                                   "\"a0\": " CLI_FMT ", \"d0\": " CLI_FMT ", \"F0\": " CLI_FMT
                                   ", \"a1\": " CLI_FMT ", \"d1\": " CLI_FMT ", \"F1\": " CLI_FMT "}",
                                   events ? ", " : "", step, mdr_event_str(o.event),
                                   (unsigned)o.jumps, (double)o.a0, (double)o.d0, (double)o.F0,
                                   (double)o.a1, (double)o.d1, (double)o.F1);
                if (len > 0 && llen + (size_t)len + 1 > lcap) {
                    char *nl;
                    lcap = 2 * (llen + (size_t)len + 1);
                    nl = realloc(list, lcap);
                    if (nl == NULL) {
                        free(list);
                        free(nodes);
                        return cli_fail("event list", MDR_E_SIZE);
                    }
                    list = nl;
                }
                if (len > 0) {
                    memcpy(list + llen, buf, (size_t)len + 1);
                    llen += (size_t)len;
                }
                events++;
                jumps += o.jumps;
                if (o.event == MDR_EV_PULL_OFF) {
                    po = o;
                    have_po = 1;
                }
            }
            step++;
        }
    }
    /* energy: Q15.48 of W0 = F0 D0 for q31 */
    dissipated = A->q31 ? (double)Q.e.dissipated * (Q.F0 * Q.D0 / 281474976710656.0)
                        : (double)eng.dissipated;
    if (A->q31 && (Q.e.flags & MDR_FLAG_SAT)) {
        fprintf(stderr, "mdr: q31 inputs or results saturated (beyond +-2 units: D0 = %.9g m, "
                        "F0 = %.9g N)\n", Q.D0, Q.F0);
    }
    if (have_po) {
        fprintf(stderr, "{\"pull_off_F\": " CLI_FMT ", \"pull_off_d\": " CLI_FMT, (double)po.F0,
                (double)po.d0);
    } else {
        fprintf(stderr, "{\"pull_off_F\": null, \"pull_off_d\": null");
    }
    if (have_t) {
        fprintf(stderr, ", \"max_tensile_F\": " CLI_FMT ", \"max_tensile_d\": " CLI_FMT, tF, td);
    } else {
        fprintf(stderr, ", \"max_tensile_F\": null, \"max_tensile_d\": null");
    }
    fprintf(stderr,
            ", \"events\": %ld, \"dissipated\": " CLI_FMT ", \"cycles\": %lu, \"jumps\": %ld"
            ", \"springs\": %u, \"a_max\": " CLI_FMT ", \"arith\": \"%s\", \"event_list\": [%s]}\n",
            events, dissipated, (unsigned long)(A->q31 ? Q.e.cycles : eng.cycles), jumps,
            (unsigned)tab.n, (double)(tab.h * (CLI_T)tab.n),
            A->q31 ? "q31" : CLI_NAME, list ? list : "");
    free(list);
    free(Q.nodes);
    free(nodes);
    return rc;
}

/* eq, critical, curve and stress on the scene's contact */
static int CLI_SFX(contact_cmd)(const struct cli_args *A, const CLI_SFX(mdr_contact) *cp)
{
    const CLI_SFX(mdr_contact) c = *cp;
    mdr_status st;
    if (A->cmd == CMD_EQ) {
        CLI_SFX(mdr_eqstate) e;
        st = CLI_SFX(mdr_eq)(&c, (CLI_T)A->a, &e);
        if (st != MDR_OK) {
            return cli_fail("--a", st);
        }
        if (A->have_d) {
            /* the state (a, d) as given: F = F_eq + 2 E* a (d - d_eq) (F is
             * linear in d at fixed a), K_I and G of that state (4.17, 4.14) */
            CLI_T d = (CLI_T)A->d, K, G;
            CLI_T F = e.F + (CLI_T)2 * c.E * e.a * (d - e.d);
            st = CLI_SFX(mdr_stress_intensity)(&c, e.a, d, &K, &G);
            if (st != MDR_OK) {
                return cli_fail("--a/--d", st);
            }
            printf("{\"a\": " CLI_FMT ", \"d\": " CLI_FMT ", \"F\": " CLI_FMT ", \"dd_da\": " CLI_FMT
                   ", \"dF_da\": " CLI_FMT ", \"dl\": " CLI_FMT ", \"K_I\": " CLI_FMT ", \"G\": " CLI_FMT
                   ", \"stable_load\": %s, \"stable_grips\": %s, \"d_eq\": " CLI_FMT ", \"F_eq\": " CLI_FMT
                   "}\n",
                   (double)e.a, (double)d, (double)F, (double)e.dd_da, (double)e.dF_da, (double)e.dl,
                   (double)K, (double)G, e.stable_load ? "true" : "false", e.stable_grips ? "true" : "false",
                   (double)e.d, (double)e.F);
            return 0;
        }
        printf("{\"a\": " CLI_FMT ", \"d\": " CLI_FMT ", \"F\": " CLI_FMT ", \"dd_da\": " CLI_FMT
               ", \"dF_da\": " CLI_FMT ", \"dl\": " CLI_FMT ", \"K_I\": " CLI_FMT ", \"G\": " CLI_FMT
               ", \"stable_load\": %s, \"stable_grips\": %s}\n",
               (double)e.a, (double)e.d, (double)e.F, (double)e.dd_da, (double)e.dF_da, (double)e.dl,
               (double)e.K_I, (double)e.G, e.stable_load ? "true" : "false",
               e.stable_grips ? "true" : "false");
        return 0;
    }
    if (A->cmd == CMD_CURVE) {
        long i;
        printf("a,d,F\n");
        for (i = 1; i <= A->n; i++) {
            CLI_SFX(mdr_eqstate) e;
            CLI_T a = (CLI_T)(A->a_max * (double)i / (double)A->n);
            st = CLI_SFX(mdr_eq)(&c, a, &e);
            if (st != MDR_OK) {
                return cli_fail("--a-max", st);
            }
            printf(CLI_FMT "," CLI_FMT "," CLI_FMT "\n", (double)e.a, (double)e.d, (double)e.F);
        }
        return 0;
    }
    /* critical, and stress at the critical state */
    if (A->cmd == CMD_CRITICAL || (A->cmd == CMD_STRESS && A->have_control)) {
        CLI_SFX(mdr_critstate) o;
        CLI_T a0 = (CLI_T)A->a_start;
        if (!A->have_a_start) {
            st = CLI_SFX(mdr_default_start)(&c, &a0);
            if (st != MDR_OK) {
                return cli_fail("default --a-start", st);
            }
        }
        st = CLI_SFX(mdr_critical)(&c, A->control, (CLI_T)A->k_m, a0, &o);
        if (st != MDR_OK) {
            return cli_fail("critical", st);
        }
        if (A->cmd == CMD_CRITICAL) {
            printf("{\"a\": " CLI_FMT ", \"d\": " CLI_FMT ", \"F\": " CLI_FMT
                   ", \"jumps\": %u, \"a_start\": " CLI_FMT ", \"max_tensile_F\": " CLI_FMT
                   ", \"max_tensile_d\": " CLI_FMT "}\n",
                   (double)o.a, (double)o.d, (double)o.F, (unsigned)o.jumps, (double)a0,
                   (double)o.F_min, (double)o.d_F_min);
            return 0;
        }
        {
            CLI_T sg;
            st = CLI_SFX(mdr_stress)(&c, o.a, (CLI_T)(A->r * (double)o.a), &sg);
            if (st != MDR_OK) {
                return cli_fail("--r (fraction of the critical radius)", st);
            }
            printf("{\"sigma\": " CLI_FMT ", \"a\": " CLI_FMT ", \"r\": " CLI_FMT "}\n", (double)sg,
                   (double)o.a, (double)(A->r * (double)o.a));
            return 0;
        }
    }
    {
        CLI_T sg;
        if (A->have_d) {
            st = CLI_SFX(mdr_stress_at)(&c, (CLI_T)A->a, (CLI_T)A->d, (CLI_T)A->r, &sg);
        } else {
            st = CLI_SFX(mdr_stress)(&c, (CLI_T)A->a, (CLI_T)A->r, &sg);
        }
        if (st != MDR_OK) {
            return cli_fail(A->have_d ? "--a/--d/--r" : "--a/--r", st);
        }
        if (A->have_d) {
            printf("{\"sigma\": " CLI_FMT ", \"a\": " CLI_FMT ", \"d\": " CLI_FMT ", \"r\": " CLI_FMT
                   "}\n",
                   (double)sg, A->a, A->d, A->r);
        } else {
            printf("{\"sigma\": " CLI_FMT "}\n", (double)sg);
        }
        return 0;
    }
}

static int CLI_SFX(run)(const struct cli_args *A)
{
    CLI_SFX(mdr_contact) c;
    CLI_T *keep;
    int rc;
    if (A->cmd == CMD_CYCLE) {
        return CLI_SFX(cycle_cmd)(A);
    }
    if (A->cmd == CMD_TABLE) {
        return CLI_SFX(table_cmd)(A);
    }
    rc = CLI_SFX(make_contact)(A, &c, &keep);
    if (rc == 0) {
        rc = CLI_SFX(contact_cmd)(A, &c);
    }
    free(keep);
    return rc;
}
