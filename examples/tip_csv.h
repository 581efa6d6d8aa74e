/* SPDX-License-Identifier: MIT */
/*
 * tip_csv.h: the tabulated-profile (measured tip) reader of the mdr CLI, as a
 * parser of a text held in memory, so that the CLI and the fuzz target
 * (host_tests/fuzz/fuzz_table.c) run the same code.
 *
 * Format: one pair "r f" per line, radius r and gap f(r) in metres (any
 * strtod number), separated by a comma (spaces around it allowed), by tabs
 * or by spaces; empty lines and lines starting with '#' are skipped; the
 * first data line may instead be a header (a line that does not parse and
 * contains 'r', e.g. "r,f"). A line is at most TIP_CSV_LINE_MAX - 1
 * characters; a NUL byte, a longer line, or any other line that does not
 * parse makes the whole text malformed (tip_csv_parse_at() names its line).
 * Values are not checked here: mdr_table_init_gap_*() validates them (r[0]
 * = 0, strictly increasing, finite).
 */
#ifndef TIP_CSV_H
#define TIP_CSV_H

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#define TIP_CSV_LINE_MAX 256

/* strtod, except that a nonzero number too small in magnitude for any
 * double (it underflows to 0, with ERANGE) does not parse (*end = s):
 * 1e-400 is refused, not read as 0 (the CLI's numbers, the tip and curve
 * files; a subnormal is kept, for the range checks that follow). errno is
 * as before the call. */
static inline double tip_csv_strtod(const char *s, char **end)
{
    const int e0 = errno;
    double v;
    errno = 0;
    v = strtod(s, end);
    if (errno == ERANGE && v == 0.0) {
        *end = (char *)s; /* (strtod's own end is not const either) */
        v = 0.0;
    }
    errno = e0;
    return v;
}

/* Lines in text: an upper bound of the number of pairs it can hold. */
static inline size_t tip_csv_lines(const char *text, size_t len)
{
    size_t i, n = len > 0;
    for (i = 0; i + 1 < len; i++) {
        n += text[i] == '\n';
    }
    return n;
}

/* One "r , f", "r<TAB>f" or "r f" line (NUL-terminated) into *r, *f: 1,
 * or 0 if it does not parse. strtod, not sscanf: out-of-range numbers are
 * defined (+-inf, 0). */
static inline int tip_csv_pair(const char *line, double *r, double *f)
{
    char *end;
    const char *p = line;
    *r = tip_csv_strtod(p, &end);
    if (end == p) {
        return 0;
    }
    for (p = end; isspace((unsigned char)*p); p++) {
    }
    if (*p == ',') {
        p++;
    } else if (p == end) {
        return 0; /* neither a comma nor white space after r */
    }
    for (; isspace((unsigned char)*p); p++) {
    }
    *f = tip_csv_strtod(p, &end);
    if (end == p) {
        return 0;
    }
    for (p = end; isspace((unsigned char)*p); p++) {
    }
    return *p == '\0';
}

/* Parse len bytes of text (no NUL terminator needed) into r[], f[] of
 * capacity cap, and the 1-based text line of each pair into lines[] (if not
 * NULL). Returns the number of pairs, -1 when a line is malformed (or holds
 * a NUL byte), -2 when the text holds more than cap pairs, -3 when a line is
 * longer than TIP_CSV_LINE_MAX - 1 characters; *bad (if not NULL) is then
 * the line. */
static inline long tip_csv_parse_at(const char *text, size_t len, double *r, double *f, size_t cap,
                                    long *lines, long *bad)
{
    size_t pos = 0, n = 0;
    long lineno = 0, dummy;
    int header_ok = 1;
    if (bad == NULL) {
        bad = &dummy;
    }
    while (pos < len) {
        char line[TIP_CSV_LINE_MAX];
        const char *nl = memchr(text + pos, '\n', len - pos);
        size_t l = (nl != NULL ? (size_t)(nl - text) : len) - pos;
        double a, b;
        *bad = ++lineno;
        if (l >= sizeof line) {
            return -3;
        }
        if (memchr(text + pos, '\0', l) != NULL) {
            return -1;
        }
        memcpy(line, text + pos, l);
        line[l] = '\0';
        pos += l + 1;
        if (l > 0 && line[l - 1] == '\r') {
            line[--l] = '\0';
        }
        if (l == 0 || line[0] == '#') {
            continue;
        }
        if (!tip_csv_pair(line, &a, &b)) {
            if (header_ok && strchr(line, 'r') != NULL) {
                header_ok = 0;
                continue;
            }
            return -1;
        }
        header_ok = 0;
        if (n == cap) {
            return -2;
        }
        r[n] = a;
        f[n] = b;
        if (lines != NULL) {
            lines[n] = lineno;
        }
        n++;
    }
    return (long)n;
}

/* tip_csv_parse_at() without the line numbers; -3 reported as -1 */
static inline long tip_csv_parse(const char *text, size_t len, double *r, double *f, size_t cap)
{
    long n = tip_csv_parse_at(text, len, r, f, cap, NULL, NULL);
    return n == -3 ? -1 : n;
}

/* The interval slopes s[j] = (f[j+1] - f[j])/(r[j+1] - r[j]), j = 0..n-2,
 * that mdr_contact_init_table_*() takes, formed in double: the difference of
 * two heights keeps its digits here, not after a conversion to float (a
 * 1 m height offset on a 10 um sphere moved the f32 pull-off by 46 %).
 * Returns 0; -1 where r does not increase strictly (s then partly
 * written); -2 where f falls (f[j+1] < f[j]; equal heights, a flat, are
 * taken), every slope written all the same (the library takes any slopes:
 * the fuzzer's samples): the gap of a tip grows with the radius, and a dip
 * is off MDR's disc of contact and, in the model, a fold the tip does not
 * have (docs/profiles.md, "Tabulated tips"; a dip was taken by the CLI and
 * the Python package, an attack after stop 59). *bad (if not NULL): the
 * first sample j + 1 that breaks the rule. The CLI (load_tip) and the
 * Python package (mdrpy_contact_tip) refuse through this one test. */
static inline int tip_slopes(const double *r, const double *f, long n, double *s, long *bad)
{
    long j, fall = 0;
    for (j = 0; j + 1 < n; j++) {
        if (!(r[j + 1] > r[j])) {
            if (bad != NULL) {
                *bad = j + 1;
            }
            return -1;
        }
        if (f[j + 1] < f[j] && fall == 0) {
            fall = j + 1;
        }
        s[j] = (f[j + 1] - f[j]) / (r[j + 1] - r[j]);
    }
    if (fall != 0 && bad != NULL) {
        *bad = fall;
    }
    return fall != 0 ? -2 : 0;
}

#endif /* TIP_CSV_H */
