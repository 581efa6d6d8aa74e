/* SPDX-License-Identifier: MIT */
/*
 * mdr_cli_t.h: the commands of the mdr CLI for one arithmetic, included by
 * mdr_cli.c with CLI_T (float/double), CLI_SFX(name) and CLI_FMT ("%.9g" or
 * "%.17g") defined. Returns the process exit status.
 */

/* Default table extent for a cycle (mdr_host_extent(); q31:
 * mdr_host_extent_q31(), widened until the q31 engine takes the path; both
 * in mdr_host_t.h, shared with the Python package). */
static int CLI_SFX(default_extent)(const struct cli_args *A, const CLI_SFX(mdr_contact) *c,
                                   CLI_T *a_max)
{
    mdr_status st;
    if (A->q31) {
        const size_t nn = MDR_TABLE_NODES((uint16_t)A->springs);
        CLI_SFX(mdr_node) *nodes = malloc(nn * sizeof *nodes);
        mdr_node_q31 *qnodes = malloc(nn * sizeof *qnodes);
        mdr_host_q31 *q = malloc(sizeof *q);
        st = MDR_E_SIZE;
        if (nodes != NULL && qnodes != NULL && q != NULL) {
            st = CLI_SFX(mdr_host_extent_q31)(c, (uint16_t)A->springs, A->E, A->w, A->w_adv, A->k_m, A->control,
                                              A->path, A->npath, A->steps, nodes, qnodes, q, a_max);
        }
        free(q);
        free(qnodes);
        free(nodes);
    } else {
        st = CLI_SFX(mdr_host_extent)(c, A->control, A->k_m, A->path, A->npath, a_max);
    }
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
    if (!CLI_F64) {
        /* a profile that f32's rounding of its parameters moves beyond
         * f32's accuracy (the cone near pi/2: mdr_host_f32_shape_change) */
        double ch;
        const int no = mdr_host_f32_shape_refused(A->kind, A->p, &ch);
        int k;
        for (k = 0; k < 3 && profiles[A->pi].flags[k] != NULL && no; k++) {
            if ((double)(float)A->p[k] != A->p[k]) {
                char how[80];
                if (ch < DBL_MAX) {
                    (void)snprintf(how, sizeof how, "which moves the profile by %.2g (more than %g)", ch,
                                   MDR_HOST_F32_SHAPE_MAX);
                } else {
                    (void)snprintf(how, sizeof how, "outside the profile's range");
                }
                return usage_errf("%s %.15g: f32 rounds it to %.9g, %s: --arith f64%s", profiles[A->pi].flags[k],
                                  A->p[k], (double)(float)A->p[k], how,
                                  A->kind == MDR_PROFILE_CONE ? ", or the cone as --profile powerlaw --C tan(theta) --n 1"
                                                              : "");
            }
        }
    }
    {
        CLI_T p[3] = {(CLI_T)A->p[0], (CLI_T)A->p[1], (CLI_T)A->p[2]};
        st = CLI_SFX(mdr_contact_init)(c, A->kind, p, (CLI_T)A->E, (CLI_T)A->w);
        if (st != MDR_OK) {
            /* which argument: the profile's with a valid material (E* = 1,
             * w = 0), then E* alone (w = 0): its flags, --E or --w */
            CLI_SFX(mdr_contact) t;
            char what[160];
            if (CLI_SFX(mdr_contact_init)(&t, A->kind, p, (CLI_T)1, (CLI_T)0) != MDR_OK) {
                int k;
                (void)snprintf(what, sizeof what, "profile %s (", profiles[A->pi].name);
                for (k = 0; k < 3 && profiles[A->pi].flags[k] != NULL; k++) {
                    (void)snprintf(what + strlen(what), sizeof what - strlen(what), "%s%s", k > 0 ? ", " : "",
                                   profiles[A->pi].flags[k]);
                }
                /* (the rule; a value inside it whose coefficients pass the
                 * arithmetic's range, a cone of theta next to pi/2, is
                 * refused all the same) */
                (void)snprintf(what + strlen(what), sizeof what - strlen(what), "; %s, finite in this arithmetic)",
                               profiles[A->pi].range);
            } else if (CLI_SFX(mdr_contact_init)(&t, A->kind, p, (CLI_T)A->E, (CLI_T)0) != MDR_OK) {
                (void)snprintf(what, sizeof what, "--E");
            } else if (CLI_SFX(mdr_contact_init)(&t, A->kind, p, (CLI_T)1, (CLI_T)A->w) != MDR_OK) {
                (void)snprintf(what, sizeof what, "--w");
            } else {
                /* each valid alone: their ratio, the adhesion length's
                 * w/E*, is beyond the arithmetic (it named --w alone) */
                (void)snprintf(what, sizeof what, "--E/--w (w/E* beyond this arithmetic: w %.3g, E* %.3g)", A->w, A->E);
            }
            return cli_fail(what, st);
        }
    }
    return 0;
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
    if (st == MDR_E_OVERFLOW) {
        fprintf(stderr,
                "mdr: --a-max: the table's values leave this arithmetic's range, above it or so far below it that "
                "the springs' curvature terms lose their digits%s (%s, status %d)\n",
                CLI_F64 ? "" : "; --arith f64 reaches further", cli_stname(st), (int)st);
        return 2;
    }
    if (st != MDR_OK) {
        return cli_fail("--a-max", st);
    }
    return 0;
}

/* Why a spring table has no q31 form, named on one line (exit 2):
 * mdr_table_q31_from() refuses N not a power of two (MDR_E_SIZE) and, with
 * MDR_E_OVERFLOW, a spring slope (g_{i+1} - g_i) N / Dg >= 8 (Q3.28: the
 * profile too steep over the table, e.g. a sphere tabulated close to
 * x = R, where g' grows without bound), a curvature term |b_i| = |q_i| 6 N / (L Dg) >= 2 (Q1.30: too few
 * springs for the profile's curvature) or a length or depth beyond float's
 * range (Dg: the least power of two >= max|g|). The two ratios are formed
 * here again, in double, only to name the cause. */
static int CLI_SFX(q31_table_fail)(const struct cli_args *A, const CLI_SFX(mdr_table) *tab, mdr_status st)
{
    const unsigned n = tab->n;
    const double L = (double)tab->h * (double)n;
    double gmax = 0.0, Dg = 1.0, smax = 0.0, bmax = 0.0;
    unsigned i, imax = 0;
    if (st != MDR_E_OVERFLOW) {
        return cli_fail(st == MDR_E_SIZE ? "q31 table (--springs must be a power of two)" : "q31 table", st);
    }
    for (i = 0; i <= n; i++) {
        const double g = (double)tab->node[i].g < 0.0 ? -(double)tab->node[i].g : (double)tab->node[i].g;
        gmax = g > gmax ? g : gmax;
    }
    gmax = gmax > 0.0 ? gmax : L / 1024.0;
    while (Dg < gmax && Dg < DBL_MAX / 2) {
        Dg *= 2.0;
    }
    while (Dg / 2.0 >= gmax && Dg > DBL_MIN * 2) {
        Dg /= 2.0;
    }
    for (i = 0; i < n; i++) {
        const double dg = (double)tab->node[i + 1].g - (double)tab->node[i].g, q = (double)tab->node[i].q;
        const double sl = (dg < 0.0 ? -dg : dg) * (double)n / Dg, b = (q < 0.0 ? -q : q) * 6.0 * (double)n / (L * Dg);
        imax = sl > smax ? i : imax;
        smax = sl > smax ? sl : smax;
        bmax = b > bmax ? b : bmax;
    }
    if (smax / 8.0 >= bmax / 2.0 && smax >= 7.99 && imax + 2u < n) {
        /* the steepest spring inside the table (a flat's rim, a kink: g
         * rises like a square root above it): its slope in max|g| per
         * spring falls with fewer springs or a longer table, and grows as
         * the table shortens (the flattened tip R = 1 mm, b = 50 um on
         * 1 024 springs: 32.5 at a_max = 60 um, 120 at 51 um; a helper's
         * find, stop 57: the message said "lower --a-max") */
        /* (a sampled tip's table ends at its last sample: only fewer
         * springs help there; helper-64, stop 70: the message offered a
         * higher --a-max, which that profile refuses) */
        char higher[64] = "";
        if (A->kind != KIND_TABLE) {
            (void)snprintf(higher, sizeof higher, " or a higher --a-max (%.9g m)", L);
        }
        return usage_errf("q31 table: the profile is too steep inside the table (spring slope %.3g >= 8 of Q3.28, "
                          "in max|g| per spring, at x = %.3g m: a rim or kink); fewer --springs (%u)%s",
                          smax, (double)tab->h * (double)imax, n, higher);
    }
    if (smax / 8.0 >= bmax / 2.0 && smax >= 7.99) {
        return usage_errf("q31 table: the profile is too steep over the table (spring slope %.3g >= 8 of "
                          "Q3.28, in max|g| per spring); lower --a-max (%.9g m)%s",
                          smax, L, A->kind == MDR_PROFILE_SPHERE ? ", further below the sphere's R" : "");
    }
    if (bmax >= 1.99) {
        return usage_errf("q31 table: too few springs for the profile's curvature (curvature term %.3g >= 2 "
                          "of Q1.30); raise --springs (%u) or lower --a-max (%.9g m)", bmax, n, L);
    }
    return usage_errf("q31 table: the table's length (%.9g m) or depth (%.9g m) is beyond the q31 formats "
                      "or float's range", L, gmax);
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
    const char *sfx = A->q31 ? "q31" : CLI_NAME;
    char inc[1024] = "mdr.h"; /* what the .c includes: the header, if one is written */
    FILE *out = stdout;
    int rc = CLI_SFX(make_table)(A, &tab, &nodes);
    unsigned i;
    if (rc == 0) {
        char warn[256];
        table_warning(A, (double)tab.h, warn, sizeof warn);
        if (warn[0] != '\0') {
            fprintf(stderr, "mdr: warning: %s\n", warn);
        }
    }
    if (rc == 0 && A->q31) {
        mdr_status st = MDR_E_SIZE;
        qn = malloc(MDR_TABLE_NODES(tab.n) * sizeof *qn);
        if (qn != NULL) {
            st = CLI_SFX(mdr_table_q31_from)(&tq, qn, &tab);
        }
        if (st != MDR_OK) {
            rc = CLI_SFX(q31_table_fail)(A, &tab, st);
        }
    }
    if (rc != 0) {
        free(qn);
        free(nodes);
        return rc;
    }
    if (A->header != NULL || A->output != NULL) {
        rc = write_table_header(A, sfx, (unsigned)tab.n, inc, sizeof inc);
        if (rc != 0) {
            free(qn);
            free(nodes);
            return rc;
        }
    }
    if (A->output != NULL) {
        out = fopen(A->output, "w");
        if (out == NULL) {
            free(qn);
            free(nodes);
            return usage_sys("cannot write", A->output);
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
                (double)tq.Dg, inc, A->name, (unsigned)MDR_TABLE_NODES(tq.n));
        for (i = 0; i < MDR_TABLE_NODES(tq.n); i++) {
            fprintf(out, "    {%ld, %ld, %ld, %ld, %ld},\n", (long)qn[i].g, (long)qn[i].G, (long)qn[i].t,
                    (long)qn[i].s, (long)qn[i].b);
        }
        fprintf(out, "};\n\nconst mdr_table_q31 %s = {%s_nodes, %.9ef, %.9ef, %.9ef, %ld, %u, %u, %u, %u, %u};\n",
                A->name, A->name, (double)tq.L, (double)tq.L_lo, (double)tq.Dg, (long)tq.gmax,
                (unsigned)tq.n, (unsigned)tq.m, (unsigned)tq.fb, (unsigned)tq.wall, (unsigned)tq.rim0);
    } else {
        const char *lit = CLI_LIT;
        fprintf(out,
                "/* spring table generated by `mdr table` (libmdr %d.%d): %u springs of\n"
                " * width " CLI_FMT " m, x_max = " CLI_FMT " m. Nodes {g [m], G [m^2] (the integral\n"
                " * of g), sqrt(x) [m^0.5], q [m^2]}, then the block bounds; see\n"
                " * lib/include/mdr_engine_t.h. */\n"
                "#include \"%s\"\n\n"
                "static const mdr_node_%s %s_nodes[%u] = {\n",
                MDR_VERSION_MAJOR, MDR_VERSION_MINOR, (unsigned)tab.n, (double)tab.h,
                (double)(tab.h * (CLI_T)tab.n), inc, sfx, A->name,
                (unsigned)MDR_TABLE_NODES(tab.n));
        for (i = 0; i < MDR_TABLE_NODES(tab.n); i++) {
            fprintf(out, "    {" CLI_EFMT "%s, " CLI_EFMT "%s, " CLI_EFMT "%s, " CLI_EFMT "%s},\n",
                    (double)nodes[i].g, lit, (double)nodes[i].G, lit, (double)nodes[i].t, lit,
                    (double)nodes[i].q, lit);
        }
        fprintf(out, "};\n\nconst mdr_table_%s %s = {%s_nodes, " CLI_EFMT "%s, %u, %u, %u};\n", sfx, A->name,
                A->name, (double)tab.h, lit, (unsigned)tab.n, (unsigned)tab.wall, (unsigned)tab.rim0);
    }
    if (out != stdout && fclose(out) != 0) {
        rc = usage_sys("cannot write", A->output);
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
    bool adh;
    char *list = NULL;
    size_t llen = 0, lcap = 0;
    double dissipated;
    FILE *sum = NULL;
    cli_json js;
    char warn[256];
    if (rc != 0) {
        free(nodes);
        return rc;
    }
    table_warning(A, (double)tab.h, warn, sizeof warn);
    if (A->q31) {
        qnodes = malloc(MDR_TABLE_NODES(tab.n) * sizeof *qnodes);
        st = MDR_E_SIZE;
        if (qnodes != NULL) {
            st = CLI_SFX(mdr_table_q31_from)(&Q.t, qnodes, &tab);
        }
        if (st != MDR_OK) {
            rc = CLI_SFX(q31_table_fail)(A, &tab, st); /* (reads tab's nodes: before they are freed) */
            free(qnodes);
            free(nodes);
            return rc;
        }
        st = CLI_SFX(mdr_engine_init_q31)(&Q.e, &Q.t, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                          (CLI_T)A->k_m);
        mdr_host_q31_units(&Q, A->E);
    } else {
        st = CLI_SFX(mdr_engine_init)(&eng, &tab, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                      (CLI_T)A->k_m);
    }
    /* MDR_E_PARAM of a valid material (0 <= w_adv <= w, and the float
     * engine takes it without adhesion): an adhesion the arithmetic does not
     * resolve on this table, named as such */
    adh = st == MDR_E_PARAM && A->w_adv >= 0 && A->w_adv <= A->w &&
          CLI_SFX(mdr_engine_init)(&eng, &tab, (CLI_T)A->E, (CLI_T)0, (CLI_T)0, (CLI_T)A->k_m) == MDR_OK;
    if (adh && tab.rim0) { /* the rim's refusal (mdr_table_f32.rim0), if the same table without it is taken */
        bool taken;
        if (A->q31) {
            mdr_table_q31 q0 = Q.t;
            mdr_engine_q31 e0;
            q0.rim0 = 0;
            taken = CLI_SFX(mdr_engine_init_q31)(&e0, &q0, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv,
                                                 (CLI_T)A->k_m) == MDR_OK;
        } else {
            CLI_SFX(mdr_table) t0 = tab;
            t0.rim0 = 0;
            taken = CLI_SFX(mdr_engine_init)(&eng, &t0, (CLI_T)A->E, (CLI_T)A->w, (CLI_T)A->w_adv, (CLI_T)A->k_m) ==
                    MDR_OK;
        }
        if (taken && tab.rim0 == 2u) { /* a power law's x^n, n not 1 or 2 */
            free(qnodes);
            free(nodes);
            fprintf(stderr,
                    "mdr: %sengine (--springs, --a-max, table to %.6g m): the pull-off lies in the first two of %u "
                    "springs (%.6g m wide), whose quadratics do not resolve the power law's C r^n for n other than 1 "
                    "and 2; use more springs or a lower --a-max, so that the pull-off radius (mdr critical) spans two "
                    "springs or more (%s, status %d)\n",
                    A->q31 ? "q31 " : "", (double)tab.h * (double)tab.n, (unsigned)tab.n, (double)tab.h, cli_stname(st),
                    (int)st);
            return 2;
        }
        if (taken) {
            free(qnodes);
            free(nodes);
            fprintf(stderr,
                    "mdr: %sengine (--springs, --a-max, table to %.6g m): the flat's rim (--b, or the samples' flat end or "
                    "first kink) lies inside the first of %u springs (%.6g m wide), and the pull-off may lie there, which "
                    "no spring resolves; use more springs or a lower --a-max, so that a spring is no wider than the "
                    "rim (%s, status %d)\n",
                    A->q31 ? "q31 " : "", (double)tab.h * (double)tab.n, (unsigned)tab.n, (double)tab.h, cli_stname(st), (int)st);
            return 2;
        }
    }
    if (adh && !A->q31) { /* (MDR_ENGINE_ADH_COND) */
        free(nodes);
        fprintf(stderr,
                "mdr: engine (--springs, --a-max, table to %.6g m): the pull-off lies so deep inside the first of %u "
                "springs, or its force is so small, that this arithmetic does not resolve it to 1/%d; use more "
                "springs, a lower --a-max%s (%s, status %d)\n",
                (double)tab.h * (double)tab.n, (unsigned)tab.n, MDR_ENGINE_ADH_COND,
                CLI_F64 ? "" : ", or --arith f64", cli_stname(st), (int)st);
        return 2;
    }
    if (adh) { /* q31 (MDR_Q31_ADH_LSB) */
        free(qnodes);
        free(nodes);
        fprintf(stderr,
                "mdr: q31 engine (--a-max, table to %.6g m): the pull-off force is below %d LSB of the q31 force "
                "unit over a table this far beyond the pull-off radius; lower --a-max or use --arith f32 (%s, status %d)\n",
                (double)Q.t.L + (double)Q.t.L_lo, MDR_Q31_ADH_LSB, cli_stname(st), (int)st);
        return 2;
    }
    if (st == MDR_E_CONTROL && A->q31 && A->k_m > 0) {
        /* the q31 engine's machine range, kappa = 2 E* L / k_m <= 2^16
         * (mdr_engine_init_q31_f32): named, with what to change (the
         * generic message said "unknown control mode", helper-21, stop 54) */
        const double L = (double)Q.t.L + (double)Q.t.L_lo, kap = 2.0 * A->E * L / A->k_m;
        free(qnodes);
        free(nodes);
        fprintf(stderr,
                "mdr: q31 engine (--k-machine, --E, --a-max): the machine is too soft for q31 on this table: "
                "kappa = 2 E* L / k_m = %.6g (L = %.6g m, the table) is above 65536: q31 needs --k-machine above "
                "2 E* L / 65536 = %.6g N/m on this table; raise --k-machine, lower --a-max, or use --arith f32 "
                "(%s, status %d)\n",
                kap, L, 2.0 * A->E * L / 65536.0, cli_stname(st), (int)st);
        return 2;
    }
    if (st != MDR_OK) {
        free(qnodes);
        free(nodes);
        return cli_fail("engine (--E, --w, --w-adv, --k-machine)", st);
    }
    if (A->q31) {
        /* the path within the q31 input range (+-2 units), by the very
         * conversion the step makes (mdr_host_q31_raw(): the value in double
         * over the double unit, rounded; it also names NaN and inf): each
         * vertex, then each tick's value (the interpolation may round a
         * vertex's value by an ulp) */
        const double unit = mdr_host_q31_unit(&Q, A->control);
        const char *un = A->control == MDR_CONTROL_GRIPS ? "D0" : A->control == MDR_CONTROL_LOAD ? "F0" : "Z0",
                   *si = A->control == MDR_CONTROL_LOAD ? "N" : "m";
        /* (a machine's z also at or above z_min, where a free body's depth
         * z 2^sz fits: below it the step saturates, and before stop 56 an
         * explicit --a-max let such a path through with exit 0 and wrong
         * numbers after the pull-off, helper-23) */
        const int32_t zmin = A->control == MDR_CONTROL_MACHINE && Q.e.machine ? Q.e.z_min : INT32_MIN;
        if (mdr_host_q31_path(A->path, A->npath, A->steps, unit, zmin, &seg, &j) != MDR_OK) {
            const double v = j == 0 ? A->path[seg] : mdr_host_path_value(A->path, A->steps, seg, j);
            int32_t raw;
            free(qnodes);
            free(nodes);
            if (mdr_host_q31_raw(v, unit, &raw) == MDR_OK && raw < zmin) {
                return usage_errf("--path value %ld%s (%.17g m): below the q31 machine's least base position z_min = "
                                  "%.9g m, where the free body's depth still fits the q31 range; a larger --a-max "
                                  "(the q31 units grow with the table) or --arith f32", seg + 1 + (j != 0), j != 0 ? " (a tick toward it)" : "",
                                  v, (double)zmin / 536870912.0 * unit);
            }
            if (j == 0) {
                return usage_errf("--path value %ld (%.9g %s): outside the q31 input range +-2 %s = +-%.9g %s",
                                  seg + 1, A->path[seg], si, un, 2.0 * unit, si);
            }
            return usage_errf("--path segment %ld, tick %ld (%.17g %s): outside the q31 input range "
                              "+-2 %s = +-%.17g %s", seg + 1, j, mdr_host_path_value(A->path, A->steps, seg, j), si,
                              un, 2.0 * unit, si);
        }
        /* a nonzero vertex that rounds to 0 LSB: a cycle the q31 engine
         * never makes (a path to 2e-12 N under load gave no event, every
         * row 0, exit 0; helper-37, stop 59) */
        seg = mdr_host_q31_lost(A->path, A->npath, unit); /* (shared with the Python package) */
        if (seg >= 0) {
            free(qnodes);
            free(nodes);
            return usage_errf("--path value %ld (%.9g %s): below half a q31 LSB of %s (one LSB: %.9g %s), it "
                              "rounds to 0; --arith f32",
                              seg + 1, A->path[seg], si, un, unit / 536870912.0, si);
        }
    }
    if (A->summary != NULL) {
        /* the summary's first byte written through at once: a file that
         * cannot be written (/dev/full, a full disk) is refused here,
         * before the CSV goes to stdout */
        sum = fopen(A->summary, "w");
        if (sum != NULL) {
            json_begin(&js, sum, CLI_F64);
            if (fflush(sum) != 0 || ferror(sum)) {
                (void)fclose(sum);
                sum = NULL;
            }
        }
        if (sum == NULL) {
            free(qnodes);
            free(nodes);
            return usage_sys("cannot write --summary", A->summary);
        }
    }
    if (sum != NULL && warn[0] != '\0') {
        fprintf(stderr, "mdr: warning: %s\n", warn); /* (stderr free of the summary) */
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
                fprintf(stderr, "mdr: step %ld (value %.9g): %s (%s, status %d)%s\n", step, v,
                        mdr_status_str(st), cli_stname(st), (int)st,
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
    if (A->q31 && (Q.e.flags & MDR_FLAG_SAT) && rc == 0) {
        /* saturated numbers are no results: exit 1 (it was 0 with this
         * warning; helper-37, stop 59); after a failed step, that step's
         * line alone */
        fprintf(stderr, "mdr: q31 inputs or results saturated (beyond +-2 units: D0 = %.9g m, "
                        "F0 = %.9g N)\n", Q.D0, Q.F0);
        rc = 1;
    }
    /* the summary: in --summary FILE always (up to a failure); on stderr
     * only for a run that succeeds, so that a failed run's stderr is its
     * one line (the JSON followed it, two lines; an attack after stop 59) */
    if (sum != NULL || rc == 0) {
        if (sum == NULL) {
            json_begin(&js, stderr, CLI_F64);
        }
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
        json_key(&js, "warnings");
        fputc('[', js.fp);
        if (warn[0] != '\0') {
            json_strv(js.fp, warn);
        }
        fputc(']', js.fp);
        /* the event objects' keys, for the units object */
        json_key_only(&js, "a0");
        json_key_only(&js, "d0");
        json_key_only(&js, "F0");
        json_key_only(&js, "a1");
        json_key_only(&js, "d1");
        json_key_only(&js, "F1");
        json_end(&js, A);
    }
    if (sum == NULL && (fflush(stderr) != 0 || ferror(stderr))) {
        rc = rc ? rc : 1; /* the summary on stderr lost (2>/dev/full: exit 0 before; helper-37, stop 59) */
    }
    if (sum != NULL) {
        const int werr = ferror(sum);
        if ((fclose(sum) != 0 || werr) && rc == 0) {
            /* the file took the first byte but not the rest (the disk filled
             * during the run): a failure of the run, not a bad argument
             * (after a failed step, that step's line alone) */
            (void)usage_sys("cannot write --summary", A->summary);
            rc = 1;
        }
    }
    free(list);
    free(qnodes);
    free(nodes);
    return rc;
}

/* An f32 answer refused for its inputs' rounding (mdr_host_f32_eq_change,
 * change ch beyond MDR_HOST_F32_EQ_MAX): the option, its value, where */
static int CLI_SFX(f32_refuse)(const char *opt, double v, double ch, const char *where)
{
    char how[80];
    if (ch < DBL_MAX) {
        (void)snprintf(how, sizeof how, "moves the state by %.2g (more than %g)", ch, MDR_HOST_F32_EQ_MAX);
    } else {
        (void)snprintf(how, sizeof how, "puts the state outside the profile");
    }
    return usage_errf("%s %.15g%s: f32's rounding of the inputs to float %s: --arith f64", opt, v, where, how);
}

/* An f32 answer refused for its error against f64 at the values given
 * (mdr_host_f32_eq_pair_err, er beyond MDR_HOST_F32_ANSWER_MAX) */
static int CLI_SFX(f32_wrong)(const char *opt, double v, double er, const char *where, int q)
{
    return usage_errf("%s %.15g%s: f32's %s is %.2g off f64's at the values given (more than %g): --arith f64", opt,
                      v, where, mdr_host_f32_which(q), er, mdr_host_f32_max(q));
}

/* eq, critical, curve and stress on the scene's contact; x32: the f32
 * checks' f64 contacts (every one of these commands in f32), or NULL */
static int CLI_SFX(contact_cmd_x)(const struct cli_args *A, const CLI_SFX(mdr_contact) *cp,
                                  const mdr_host_f32_eq_pair *x32)
{
    const CLI_SFX(mdr_contact) c = *cp;
    mdr_status st;
    if (A->cmd == CMD_EQ) {
        CLI_SFX(mdr_eqstate) e;
        if (x32 != NULL) {
            /* a state that f32's rounding of its inputs moves beyond f32's
             * accuracy (mdr_host_f32_eq_change: the sphere near a = R, a
             * measured tip's samples) */
            const double ch = mdr_host_f32_eq_pair_change(x32, A->a, A->have_d ? &A->d : NULL);
            if (ch > MDR_HOST_F32_EQ_MAX) {
                return CLI_SFX(f32_refuse)("--a", A->a, ch, "");
            }
        }
        st = CLI_SFX(mdr_eq)(&c, (CLI_T)A->a, &e);
        if (st != MDR_OK) {
            return cli_fail("--a", st);
        }
        {
            cli_json j;
            CLI_T d = e.d, F = e.F, K = e.K_I, G = e.G;
            if (A->have_d) {
                /* the state (a, d) as given: F (mdr_host_state_F), K_I and
                 * G_rel of that state (4.17, 4.14) */
                d = (CLI_T)A->d;
                st = CLI_SFX(mdr_host_state_F)(&c, &e, d, &F);
                if (st == MDR_OK) {
                    st = CLI_SFX(mdr_stress_intensity)(&c, e.a, d, &K, &G);
                }
                if (st == MDR_OK && !(F - F == (CLI_T)0)) {
                    st = MDR_E_OVERFLOW; /* (printed "F": inf, exit 0; helper-37, stop 59) */
                }
                if (st != MDR_OK) {
                    return cli_fail("--a/--d", st);
                }
            }
            if (x32 != NULL) {
                /* f32's own error beyond its goal (a coarse table near its
                 * axis): mdr_host_f32_eq_pair_err */
                const double dv[2] = {(double)e.dd_da, (double)e.dF_da}, Kd = (double)K; /* (printed too) */
                int q = 0;
                const double er = mdr_host_f32_eq_pair_err(x32, A->a, A->have_d ? &A->d : NULL, (double)d, (double)F,
                                                           dv, A->have_d ? &Kd : NULL, &q);
                if (er > mdr_host_f32_max(q)) {
                    return CLI_SFX(f32_wrong)("--a", A->a, er, "", q);
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
        /* every row is computed before the first is written (pass 0 only
         * checks): a radius the library refuses part-way (outside the
         * profile's domain, an overflow) is one line on stderr and no
         * output, as any other refusal; in f32 pass 0 also refuses a row
         * that the rounding of its inputs moves beyond f32's accuracy,
         * from f64 contacts made once (mdr_host_f32_eq_pair) */
        long i;
        int pass;
        const int f32chk = x32 != NULL;
        for (pass = 0; pass < 2; pass++) {
            if (pass == 1) {
                printf("a,d,F\n");
            }
            for (i = 1; i <= A->n; i++) {
                CLI_SFX(mdr_eqstate) e;
                CLI_T a = (CLI_T)(A->a_max * (double)i / (double)A->n);
                if (f32chk && pass == 0) {
                    const double ch = mdr_host_f32_eq_pair_change(x32, A->a_max * (double)i / (double)A->n, NULL);
                    if (ch > MDR_HOST_F32_EQ_MAX) {
                        char row[64];
                        (void)snprintf(row, sizeof row, ", its row %ld (a = %.9g)", i, (double)a);
                        return CLI_SFX(f32_refuse)("--a-max", A->a_max, ch, row);
                    }
                }
                st = CLI_SFX(mdr_eq)(&c, a, &e);
                if (st != MDR_OK) {
                    return cli_fail("--a-max", st);
                }
                if (f32chk && pass == 0) {
                    /* (its rows print a, d, F: no derivatives) */
                    const double er = mdr_host_f32_eq_pair_err(x32, A->a_max * (double)i / (double)A->n, NULL,
                                                               (double)e.d, (double)e.F, NULL, NULL, NULL);
                    if (er > MDR_HOST_F32_ANSWER_MAX) {
                        char row[64];
                        (void)snprintf(row, sizeof row, ", its row %ld (a = %.9g)", i, (double)a);
                        return CLI_SFX(f32_wrong)("--a-max", A->a_max, er, row, 0);
                    }
                }
                if (pass == 1) {
                    printf(CLI_FMT "," CLI_FMT "," CLI_FMT "\n", (double)e.a, (double)e.d, (double)e.F);
                }
            }
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
        if (st == MDR_E_RADIUS) {
            /* which radius: --a-start itself, or the path from it to the
             * pull-off leaving the profile's domain (a tip tabulated short
             * of the pull-off radius); both said "critical: contact radius
             * outside the profile's domain" (an attack after stop 59) */
            CLI_SFX(mdr_eqstate) e;
            if (A->have_a_start && (!(a0 > (CLI_T)0) || CLI_SFX(mdr_eq)(&c, a0, &e) == MDR_E_RADIUS)) {
                return usage_errf("--a-start %.9g: outside the profile's domain (%s, status %d)", A->a_start,
                                  cli_stname(st), (int)st);
            }
            /* (mdr_critical's refusal next to n = 1/2, helper-62: its band
             * of MDR_CRIT_HALF_BAND unit roundoffs) */
            const double band = MDR_CRIT_HALF_BAND * (CLI_F64 ? DBL_EPSILON : (double)FLT_EPSILON) / 2;
            if (A->kind == MDR_PROFILE_POWERLAW && A->w > 0 && fabs((double)(CLI_T)A->p[1] - 0.5) <= band) {
                return usage_errf("--n %.17g: within 2^10 eps of 1/2 (%.2g in %s) a power law's critical radius "
                                  "(3c/(2 n kappa C))^(1/(n - 1/2)) is not resolved to 1 %%, and n = 1/2 has none "
                                  "(%s, status %d)",
                                  A->p[1], band, CLI_F64 ? "f64" : "f32", cli_stname(st), (int)st);
            }
            if (A->kind == KIND_TABLE) {
                return usage_errf("%s: the tip ends (its last sample r = %.9g m) before the pull-off: its contact "
                                  "radius lies beyond; tabulate the tip further (%s, status %d)",
                                  A->file, A->tr[A->ntab - 1], cli_stname(st), (int)st);
            }
            return usage_errf("--profile %s: the path to the pull-off leaves the profile's domain%s (%s, status %d)",
                              profiles[A->pi].name, A->have_a_start ? " (from --a-start)" : "", cli_stname(st),
                              (int)st);
        }
        if (st != MDR_OK) {
            return cli_fail("critical", st);
        }
        if (x32 != NULL) {
            /* f32's critical state beyond its tolerance against f64's
             * (a measured tip; also for the stress there):
             * mdr_host_f32_crit_err */
            const double er = mdr_host_f32_crit_err(x32, A->control, A->k_m, A->have_a_start ? &A->a_start : NULL,
                                                    (double)o.a, (double)o.d, (double)o.F, (double)o.F_min);
            if (er > MDR_HOST_F32_CRIT_MAX) {
                return usage_errf("critical: f32's critical state is %.2g off f64's at the values given (more than "
                                  "%g): --arith f64",
                                  er, MDR_HOST_F32_CRIT_MAX);
            }
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
            if (x32 != NULL) {
                /* and f32's stress there against f64's answer to the same
                 * command: mdr_host_f32_crit_stress_err */
                const double er = mdr_host_f32_crit_stress_err(x32, A->control, A->k_m,
                                                               A->have_a_start ? &A->a_start : NULL, A->r, (double)sg);
                if (er > MDR_HOST_F32_CRIT_MAX) {
                    return usage_errf("--r %.15g: f32's stress at the critical state is %.2g off f64's at the values "
                                      "given (more than %g): --arith f64",
                                      A->r, er, MDR_HOST_F32_CRIT_MAX);
                }
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
        if (x32 != NULL) {
            /* f32's stress beyond its goal (a measured tip):
             * mdr_host_f32_stress_err */
            const double er = mdr_host_f32_stress_err(x32, A->a, A->have_d ? &A->d : NULL, A->r, (double)sg);
            if (er > MDR_HOST_F32_ANSWER_MAX) {
                return CLI_SFX(f32_wrong)("--r", A->r, er, "", 0);
            }
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

/* contact_cmd_x with, for eq, curve and stress at a in f32, the f32 check's f64
 * contacts: an analytic profile's, or a sampled tip's (the samples'
 * conversions to float in memory held for the command) */
static int CLI_SFX(contact_cmd)(const struct cli_args *A, const CLI_SFX(mdr_contact) *cp)
{
    mdr_host_f32_eq_pair x32;
    double *rd;
    int rc;
    if (CLI_F64 || (A->cmd != CMD_EQ && A->cmd != CMD_CURVE && A->cmd != CMD_CRITICAL && A->cmd != CMD_STRESS)) {
        return CLI_SFX(contact_cmd_x)(A, cp, NULL);
    }
    if (A->kind != KIND_TABLE) {
        return CLI_SFX(contact_cmd_x)(A, cp, mdr_host_f32_eq_pair_init(&x32, A->kind, A->p, A->E, A->w) ? &x32 : NULL);
    }
    rd = malloc(2 * (size_t)A->ntab * sizeof *rd);
    if (rd == NULL) {
        return cli_fail("table", MDR_E_SIZE);
    }
    rc = CLI_SFX(contact_cmd_x)(
        A, cp, mdr_host_f32_eq_pair_init_tip(&x32, A->tr, A->ts, (uint16_t)A->ntab, A->E, A->w, rd) ? &x32 : NULL);
    free(rd);
    return rc;
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
