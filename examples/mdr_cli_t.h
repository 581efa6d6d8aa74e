/*
 * mdr_cli_t.h: the commands of the mdr CLI for one arithmetic, included by
 * mdr_cli.c with CLI_T (float/double), CLI_SFX(name) and CLI_FMT ("%.9g" or
 * "%.17g") defined. Returns the process exit status.
 */
static int CLI_SFX(run)(const struct cli_args *A)
{
    CLI_SFX(mdr_contact) c;
    CLI_T p[3] = {(CLI_T)A->p[0], (CLI_T)A->p[1], (CLI_T)A->p[2]};
    mdr_status st = CLI_SFX(mdr_contact_init)(&c, A->kind, p, (CLI_T)A->E, (CLI_T)A->w);
    if (st != MDR_OK) {
        return cli_fail("profile/material", st);
    }
    if (A->cmd == CMD_EQ) {
        CLI_SFX(mdr_eqstate) e;
        st = CLI_SFX(mdr_eq)(&c, (CLI_T)A->a, &e);
        if (st != MDR_OK) {
            return cli_fail("--a", st);
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
                   ", \"jumps\": %u, \"a_start\": " CLI_FMT "}\n",
                   (double)o.a, (double)o.d, (double)o.F, (unsigned)o.jumps, (double)a0);
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
        st = CLI_SFX(mdr_stress)(&c, (CLI_T)A->a, (CLI_T)A->r, &sg);
        if (st != MDR_OK) {
            return cli_fail("--a/--r", st);
        }
        printf("{\"sigma\": " CLI_FMT "}\n", (double)sg);
        return 0;
    }
}
