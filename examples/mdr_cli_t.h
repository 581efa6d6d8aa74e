/*
 * mdr_cli_t.h: the commands of the mdr CLI for one arithmetic, included by
 * mdr_cli.c with CLI_T (float/double), CLI_SFX(name) and CLI_FMT ("%.9g" or
 * "%.17g") defined. Returns the process exit status.
 */

/* Default table extent for a cycle (mdr_host_extent(), mdr_host_t.h). */
static int CLI_SFX(default_extent)(const struct cli_args *A, const CLI_SFX(mdr_contact) *c,
                                   CLI_T *a_max)
{
    mdr_status st = CLI_SFX(mdr_host_extent)(c, A->control, A->k_m, A->path, A->npath, a_max);
    return st == MDR_OK ? 0 : cli_fail("default --a-max", st);
}

/* The scene's contact. A tabulated profile keeps the samples it points to
 * in *keep (malloc'd, freed by the caller after the contact's last use):
 * r and the slopes formed in double by tip_slopes(), then converted
 * (mdr_host_tip_contact(), shared with the Python package). */
static int CLI_SFX(make_contact)(const struct cli_args *A, CLI_SFX(mdr_contact) *c, CLI_T **keep)
{
    mdr_status st;
    *keep = NULL;
    if (A->kind == KIND_TABLE) {
        CLI_T *buf = malloc(2 * (size_t)A->ntab * sizeof *buf);
        if (buf == NULL) {
            return cli_fail("table", MDR_E_SIZE);
        }
        *keep = buf;
        st = CLI_SFX(mdr_host_tip_contact)(c, A->tr, A->ts, (uint16_t)A->ntab, (CLI_T)A->E, (CLI_T)A->w,
                                           buf);
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

/* mdr table: the table as C source (round-trip exact literals) on stdout or
 * in --output FILE.c, and the header declaring it (--header, or FILE.h next
 * to --output FILE.c), which the .c then includes. */
static int CLI_SFX(table_cmd)(const struct cli_args *A)
{
    CLI_SFX(mdr_table) tab;
    CLI_SFX(mdr_node) *nodes = NULL;
    mdr_table_q31 tq;
    mdr_node_q31 *qn = NULL;
    const char *sfx = A->q31 ? "q31" : CLI_NAME, *lit = CLI_LIT;
    char hpath[1024], guard[256];
    const char *hname = NULL;
    FILE *out = stdout;
    int rc = CLI_SFX(make_table)(A, &tab, &nodes);
    unsigned i;
    if (rc == 0 && A->q31) {
        mdr_status st = MDR_E_SIZE;
        qn = malloc(MDR_TABLE_NODES(tab.n) * sizeof *qn);
        if (qn != NULL) {
            st = CLI_SFX(mdr_table_q31_from)(&tq, qn, &tab);
        }
        if (st != MDR_OK) {
            rc = cli_fail("q31 table (--springs must be a power of two)", st);
        }
    }
    if (rc != 0) {
        free(qn);
        free(nodes);
        return rc;
    }
    /* the header: its path, the name the .c includes it by, its guard */
    if (A->header != NULL || A->output != NULL) {
        const char *base;
        size_t l;
        if (A->header != NULL) {
            l = strlen(A->header);
            if (l >= sizeof hpath) {
                free(qn);
                free(nodes);
                return usage_error("--header: path too long", A->header);
            }
            memcpy(hpath, A->header, l + 1);
        } else {
            l = strlen(A->output);
            if (l >= sizeof hpath) {
                free(qn);
                free(nodes);
                return usage_error("--output: path too long", A->output);
            }
            memcpy(hpath, A->output, l + 1);
            hpath[l - 1] = 'h';
        }
        base = strrchr(hpath, '/');
        hname = base != NULL ? base + 1 : hpath;
        (void)snprintf(guard, sizeof guard, "MDR_TABLE_%s_H", A->name);
        for (i = 0; guard[i]; i++) {
            if (guard[i] >= 'a' && guard[i] <= 'z') {
                guard[i] = (char)(guard[i] - ('a' - 'A'));
            }
        }
        out = fopen(hpath, "w");
        if (out == NULL) {
            free(qn);
            free(nodes);
            return usage_error("cannot write", hpath);
        }
        fprintf(out,
                "/* spring table generated by `mdr table` (libmdr %d.%d): the declaration of\n"
                " * %s (%u springs, %s); its definition is in the generated .c. */\n"
                "#ifndef %s\n#define %s\n\n#include \"mdr.h\"\n\n"
                "/** springs of %s */\n#define %.*s_SPRINGS %uu\n\n"
                "extern const mdr_table_%s %s;\n\n#endif /* %s */\n",
                MDR_VERSION_MAJOR, MDR_VERSION_MINOR, A->name, (unsigned)tab.n, sfx, guard, guard, A->name,
                (int)strlen(guard) - 2, guard, (unsigned)tab.n, sfx, A->name, guard);
        if (fclose(out) != 0) {
            free(qn);
            free(nodes);
            return usage_error("cannot write", hpath);
        }
        out = stdout;
    }
    if (A->output != NULL) {
        out = fopen(A->output, "w");
        if (out == NULL) {
            free(qn);
            free(nodes);
            return usage_error("cannot write", A->output);
        }
    }
    if (A->q31) {
        fprintf(out,
                "/* q31 spring table generated by `mdr table --arith q31` (libmdr %d.%d):\n"
                " * %u springs, x_max = L = %.9g + %.9g m, depth unit Dg = %.9g m. Nodes\n"
                " * {g, G, t, s, b} in Q formats (G: the integral of g); see\n"
                " * lib/include/mdr_q31.h. */\n"
                "#include \"%s\"\n\n"
                "static const mdr_node_q31 %s_nodes[%u] = {\n",
                MDR_VERSION_MAJOR, MDR_VERSION_MINOR, (unsigned)tq.n, (double)tq.L, (double)tq.L_lo,
                (double)tq.Dg, hname != NULL ? hname : "mdr.h", A->name, (unsigned)MDR_TABLE_NODES(tq.n));
        for (i = 0; i < MDR_TABLE_NODES(tq.n); i++) {
            fprintf(out, "    {%ld, %ld, %ld, %ld, %ld},\n", (long)qn[i].g, (long)qn[i].G, (long)qn[i].t,
                    (long)qn[i].s, (long)qn[i].b);
        }
        fprintf(out, "};\n\nconst mdr_table_q31 %s = {%s_nodes, %.9ef, %.9ef, %.9ef, %ld, %u, %u, %u, %u};\n",
                A->name, A->name, (double)tq.L, (double)tq.L_lo, (double)tq.Dg, (long)tq.gmax,
                (unsigned)tq.n, (unsigned)tq.m, (unsigned)tq.fb, (unsigned)tq.wall);
    } else {
        fprintf(out,
                "/* spring table generated by `mdr table` (libmdr %d.%d): %u springs of\n"
                " * width " CLI_FMT " m, x_max = " CLI_FMT " m. Nodes {g [m], G [m^2] (the integral\n"
                " * of g), sqrt(x) [m^0.5], q [m^2]}, then the block bounds; see\n"
                " * lib/include/mdr_engine_t.h. */\n"
                "#include \"%s\"\n\n"
                "static const mdr_node_%s %s_nodes[%u] = {\n",
                MDR_VERSION_MAJOR, MDR_VERSION_MINOR, (unsigned)tab.n, (double)tab.h,
                (double)(tab.h * (CLI_T)tab.n), hname != NULL ? hname : "mdr.h", sfx, A->name,
                (unsigned)MDR_TABLE_NODES(tab.n));
        for (i = 0; i < MDR_TABLE_NODES(tab.n); i++) {
            fprintf(out, "    {" CLI_EFMT "%s, " CLI_EFMT "%s, " CLI_EFMT "%s, " CLI_EFMT "%s},\n",
                    (double)nodes[i].g, lit, (double)nodes[i].G, lit, (double)nodes[i].t, lit,
                    (double)nodes[i].q, lit);
        }
        fprintf(out, "};\n\nconst mdr_table_%s %s = {%s_nodes, " CLI_EFMT "%s, %u, %u};\n", sfx, A->name,
                A->name, (double)tab.h, lit, (unsigned)tab.n, (unsigned)tab.wall);
    }
    if (out != stdout && fclose(out) != 0) {
        rc = usage_error("cannot write", A->output);
    }
    free(qn);
    free(nodes);
    return rc;
}

/* mdr cycle: drive the engine along the path. */
static int CLI_SFX(cycle_cmd)(const struct cli_args *A)
{
    CLI_SFX(mdr_table) tab;
    CLI_SFX(mdr_node) *nodes = NULL;
    CLI_SFX(mdr_engine) eng;
    CLI_SFX(mdr_step) o;
    mdr_step_f64 r, po; /* the step of any arithmetic, in double (exact) */
    mdr_host_q31 Q;
    mdr_node_q31 *qnodes = NULL;
    long seg, j, step = 0, events = 0, jumps = 0, have_po = 0, have_t = 0;
    double tF = 0, td = 0; /* the most tensile force along the path, and its depth */
    int rc = CLI_SFX(make_table)(A, &tab, &nodes);
    mdr_status st;
    char *list = NULL;
    size_t llen = 0, lcap = 0;
    double dissipated;
    FILE *sum = NULL;
    cli_json js;
    if (rc != 0) {
        free(nodes);
        return rc;
    }
    if (A->q31) {
        qnodes = malloc(MDR_TABLE_NODES(tab.n) * sizeof *qnodes);
        st = MDR_E_SIZE;
        if (qnodes != NULL) {
            st = CLI_SFX(mdr_table_q31_from)(&Q.t, qnodes, &tab);
        }
        if (st != MDR_OK) {
            free(qnodes);
            free(nodes);
            return cli_fail("q31 table (--springs must be a power of two)", st);
        }
        st = CLI_SFX(mdr_engine_init_q31)(&Q.e, &Q.t, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                          (CLI_T)A->k_m);
        mdr_host_q31_units(&Q, A->E);
    } else {
        st = CLI_SFX(mdr_engine_init)(&eng, &tab, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                      (CLI_T)A->k_m);
    }
    if (st != MDR_OK) {
        free(qnodes);
        free(nodes);
        return cli_fail("engine (--E, --w, --w-adv, --k-machine)", st);
    }
    if (A->q31) {
        /* the path within the q31 input range (+-2 units): its vertices bound
         * every interpolated value; the conversion names NaN, inf and the
         * int32 overflow (mdr_q31_from_si: no NaN converted to an integer) */
        const uint8_t q = A->control == MDR_CONTROL_GRIPS ? MDR_Q_D
                          : A->control == MDR_CONTROL_LOAD ? MDR_Q_F : MDR_Q_Z;
        const double unit = q == MDR_Q_D ? Q.D0 : q == MDR_Q_F ? Q.F0 : Q.Z0;
        for (seg = 0; seg < A->npath; seg++) {
            int32_t raw = 0;
            st = mdr_q31_from_si(&Q.e, q, (float)A->path[seg], &raw);
            if (st != MDR_OK || raw > MDR_Q30_ONE || raw < -MDR_Q30_ONE) {
                free(qnodes);
                free(nodes);
                return usage_errf("--path value %ld (%.9g %s): outside the q31 input range +-2 %s = +-%.9g %s",
                                  seg + 1, A->path[seg], q == MDR_Q_F ? "N" : "m",
                                  q == MDR_Q_D ? "D0" : q == MDR_Q_F ? "F0" : "Z0", 2.0 * unit,
                                  q == MDR_Q_F ? "N" : "m");
            }
        }
    }
    if (A->summary != NULL) {
        sum = fopen(A->summary, "w");
        if (sum == NULL) {
            free(qnodes);
            free(nodes);
            return usage_error("cannot write --summary", A->summary);
        }
    }
    memset(&po, 0, sizeof po);
    printf("step,z,d,F,a,event\n");
    for (seg = 0; seg + 1 < A->npath && rc == 0; seg++) {
        for (j = seg == 0 ? 0 : 1; j <= A->steps; j++) {
            double v = mdr_host_path_value(A->path, A->steps, seg, j);
            if (A->q31) {
                /* within the range (checked above); strict all the same */
                st = mdr_host_q31_step(&Q, A->control, v, 1, &r);
            } else {
                if (A->control == MDR_CONTROL_GRIPS) {
                    st = CLI_SFX(mdr_engine_step_d)(&eng, (CLI_T)v, &o);
                } else if (A->control == MDR_CONTROL_LOAD) {
                    st = CLI_SFX(mdr_engine_step_F)(&eng, (CLI_T)v, &o);
                } else {
                    st = CLI_SFX(mdr_engine_step_z)(&eng, (CLI_T)v, &o);
                }
                if (st == MDR_OK) {
                    CLI_SFX(mdr_host_widen)(&o, &r);
                }
            }
            if (st != MDR_OK) {
                fprintf(stderr, "mdr: step %ld (value %.9g): %s (status %d)%s\n", step, v,
                        mdr_status_str(st), (int)st,
                        st == MDR_E_OUTSIDE ? "; raise --a-max" : "");
                rc = 1;
                break;
            }
            printf("%ld," CLI_FMT "," CLI_FMT "," CLI_FMT "," CLI_FMT ",%s\n", step, r.z, r.d, r.F,
                   r.a, mdr_event_str(r.event));
            /* the states of the step: after it, and around a jump (the last
             * stable state before it, the state right after it) */
            {
                const double Fs[3] = {r.F, r.F0, r.F1};
                const double ds[3] = {r.d, r.d0, r.d1};
                int k, nk = r.event != MDR_EV_NONE ? 3 : 1;
                for (k = 0; k < nk; k++) {
                    if (Fs[k] < 0 && (!have_t || Fs[k] < tF)) {
                        tF = Fs[k];
                        td = ds[k];
                        have_t = 1;
                    }
                }
            }
            if (r.event != MDR_EV_NONE) {
                char buf[512];
                int len = snprintf(buf, sizeof buf,
                                   "%s{\"step\": %ld, \"event\": \"%s\", \"jumps\": %u, "
                                   "\"a0\": " CLI_FMT ", \"d0\": " CLI_FMT ", \"F0\": " CLI_FMT
                                   ", \"a1\": " CLI_FMT ", \"d1\": " CLI_FMT ", \"F1\": " CLI_FMT "}",
                                   events ? ", " : "", step, mdr_event_str(r.event),
                                   (unsigned)r.jumps, r.a0, r.d0, r.F0, r.a1, r.d1, r.F1);
                if (len > 0 && llen + (size_t)len + 1 > lcap) {
                    char *nl;
                    lcap = 2 * (llen + (size_t)len + 1);
                    nl = realloc(list, lcap);
                    if (nl == NULL) {
                        free(list);
                        free(qnodes);
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
                jumps += r.jumps;
                if (r.event == MDR_EV_PULL_OFF) {
                    po = r;
                    have_po = 1;
                }
            }
            step++;
        }
    }
    /* energy: Q15.48 of W0 = F0 D0 for q31 */
    dissipated = A->q31 ? mdr_host_q31_energy(&Q, Q.e.en.dissipated) : (double)eng.en.dissipated;
    if (A->q31 && (Q.e.flags & MDR_FLAG_SAT)) {
        fprintf(stderr, "mdr: q31 inputs or results saturated (beyond +-2 units: D0 = %.9g m, "
                        "F0 = %.9g N)\n", Q.D0, Q.F0);
    }
    json_begin(&js, sum != NULL ? sum : stderr, CLI_F64);
    if (have_po) {
        json_num(&js, "pull_off_F", po.F0);
        json_num(&js, "pull_off_d", po.d0);
    } else {
        json_key(&js, "pull_off_F");
        fputs("null", js.fp);
        json_key(&js, "pull_off_d");
        fputs("null", js.fp);
    }
    if (have_t) {
        json_num(&js, "max_tensile_F", tF);
        json_num(&js, "max_tensile_d", td);
    } else {
        json_key(&js, "max_tensile_F");
        fputs("null", js.fp);
        json_key(&js, "max_tensile_d");
        fputs("null", js.fp);
    }
    json_key(&js, "events");
    fprintf(js.fp, "%ld", events);
    json_num(&js, "dissipated", dissipated);
    json_key(&js, "cycles");
    fprintf(js.fp, "%lu", (unsigned long)(A->q31 ? Q.e.en.cycles : eng.en.cycles));
    json_key(&js, "jumps");
    fprintf(js.fp, "%ld", jumps);
    json_key(&js, "springs");
    fprintf(js.fp, "%u", (unsigned)tab.n);
    json_num(&js, "a_max", (double)(tab.h * (CLI_T)tab.n));
    json_str(&js, "arith", A->q31 ? "q31" : CLI_NAME);
    json_key(&js, "event_list");
    fprintf(js.fp, "[%s]", list ? list : "");
    /* the event objects' keys, for the units object */
    json_key_only(&js, "a0");
    json_key_only(&js, "d0");
    json_key_only(&js, "F0");
    json_key_only(&js, "a1");
    json_key_only(&js, "d1");
    json_key_only(&js, "F1");
    json_end(&js, A);
    if (sum != NULL && (fclose(sum) != 0)) {
        rc = rc ? rc : usage_error("cannot write --summary", A->summary);
    }
    free(list);
    free(qnodes);
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
        {
            cli_json j;
            CLI_T d = e.d, F = e.F, K = e.K_I, G = e.G;
            if (A->have_d) {
                /* the state (a, d) as given: F = F_eq + 2 E* a (d - d_eq) (F is
                 * linear in d at fixed a), K_I and G_rel of that state (4.17, 4.14) */
                d = (CLI_T)A->d;
                F = e.F + (CLI_T)2 * c.E * e.a * (d - e.d);
                st = CLI_SFX(mdr_stress_intensity)(&c, e.a, d, &K, &G);
                if (st != MDR_OK) {
                    return cli_fail("--a/--d", st);
                }
            }
            json_begin(&j, stdout, CLI_F64);
            json_num(&j, "a", (double)e.a);
            json_num(&j, "d", (double)d);
            json_num(&j, "F", (double)F);
            json_num(&j, "dd_da", (double)e.dd_da);
            json_num(&j, "dF_da", (double)e.dF_da);
            json_num(&j, "dl", (double)e.dl);
            json_num(&j, "K_I", (double)K);
            json_num(&j, "G_rel", (double)G);
            json_num(&j, "G", (double)G); /* G_rel's old name, kept for the programs that read it */
            json_key(&j, "stable_load");
            fputs(e.stable_load ? "true" : "false", stdout);
            json_key(&j, "stable_grips");
            fputs(e.stable_grips ? "true" : "false", stdout);
            if (A->have_d) {
                json_num(&j, "d_eq", (double)e.d);
                json_num(&j, "F_eq", (double)e.F);
            }
            json_end(&j, A);
        }
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
            cli_json j;
            json_begin(&j, stdout, CLI_F64);
            json_num(&j, "a", (double)o.a);
            json_num(&j, "d", (double)o.d);
            json_num(&j, "F", (double)o.F);
            json_key(&j, "jumps");
            printf("%u", (unsigned)o.jumps);
            json_num(&j, "a_start", (double)a0);
            json_num(&j, "max_tensile_F", (double)o.F_min);
            json_num(&j, "max_tensile_d", (double)o.d_F_min);
            json_end(&j, A);
            return 0;
        }
        {
            CLI_T sg;
            st = CLI_SFX(mdr_stress)(&c, o.a, (CLI_T)(A->r * (double)o.a), &sg);
            if (st != MDR_OK) {
                return cli_fail("--r (fraction of the critical radius)", st);
            }
            {
                cli_json j;
                json_begin(&j, stdout, CLI_F64);
                json_num(&j, "sigma", (double)sg);
                json_num(&j, "a", (double)o.a);
                json_num(&j, "r", A->r * (double)o.a);
                json_end(&j, A);
            }
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
        {
            cli_json j;
            json_begin(&j, stdout, CLI_F64);
            json_num(&j, "sigma", (double)sg);
            if (A->have_d) { /* the state's a, d, r (as before: not only in the input) */
                json_num(&j, "a", A->a);
                json_num(&j, "d", A->d);
                json_num(&j, "r", A->r);
            }
            json_end(&j, A);
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
