/*
 * test_util.h: the comparison every cmocka test here uses (include after
 * <cmocka.h> and <math.h>).
 */
/* |got - want| <= tol * scale, scale = |want| when scale <= 0; prints both
 * and the relative error on failure. */
static void rel_le(double got, double want, double scale, double tol, const char *what)
{
    double s = scale > 0 ? scale : fabs(want);
    if (!(fabs(got - want) <= tol * s)) {
        print_error("%s: got %.17g want %.17g rel %.3g > %.3g\n", what, got, want,
                    fabs(got - want) / s, tol);
        fail();
    }
}
