/* SPDX-License-Identifier: MIT */
/*
 * vecdiff.c: compares two reference-vector CSV files field by field:
 * identical headers, identical row counts, every number equal to within
 * 1e-11 relative (absolute 1e-300 floor), so that `make ref-check` passes on
 * a machine whose libm rounds a last digit differently but catches any real
 * change of the reference. Exit 0 if equal, 1 (with the first difference) if not.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    FILE *a, *b;
    char la[4096], lb[4096];
    long row = 0;
    double worst = 0.0;
    if (argc != 3 || (a = fopen(argv[1], "r")) == NULL || (b = fopen(argv[2], "r")) == NULL) {
        fprintf(stderr, "usage: vecdiff COMMITTED.csv REGENERATED.csv\n");
        return 2;
    }
    for (;;) {
        char *ra = fgets(la, sizeof la, a), *rb = fgets(lb, sizeof lb, b);
        char *pa = la, *pb = lb;
        if (ra == NULL || rb == NULL) {
            if (ra != rb) {
                printf("%s: row counts differ after row %ld\n", argv[2], row);
                return 1;
            }
            break;
        }
        if (row++ == 0) {
            if (strcmp(la, lb) != 0) {
                printf("headers differ\n");
                return 1;
            }
            continue;
        }
        for (int f = 0; *pa && *pb; f++) {
            char *ea, *eb;
            double x = strtod(pa, &ea), y = strtod(pb, &eb);
            double d = fabs(x - y), s = fmax(fabs(x), fabs(y));
            if (ea == pa || eb == pb) {
                break;
            }
            if (d > 1e-11 * s && d > 1e-300) {
                printf("row %ld field %d: %.17g vs %.17g (rel %.2g)\n", row, f, x, y, d / s);
                return 1;
            }
            if (s > 0) {
                worst = fmax(worst, d / s);
            }
            pa = *ea ? ea + 1 : ea;
            pb = *eb ? eb + 1 : eb;
        }
    }
    printf("%s: %ld rows equal (largest relative difference %.2g)\n", argv[2], row - 1, worst);
    return 0;
}
