/*
 * bench_support — the hand-written pieces of tools/support against the C
 * library's own way of doing the same (docs/design.md, "Tool support"):
 *
 *   1. tsu_parse_double        vs strtod, on typical CSV numbers
 *   2. tsu_format_double       vs snprintf("%.17g"), then shorter precisions
 *                              while the text still reads back (strtod) as v
 *   3. tsu_read_table          vs a plain fgets + strtok + strtod loop into
 *                              growing arrays, on an "x,y" file
 *
 * Each timing is the best of 3 runs (CLOCK_MONOTONIC).  Every pair is also
 * checked for equal results, so the speed is compared on the same work.
 * Not built by default: cmake -DTS_BUILD_SUPPORT_BENCH=ON, then
 * BUILD/tools/bench_support [N]   (N numbers per set, default 10000000).
 */
#define _POSIX_C_SOURCE 200809L
#include "tsu_io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t rng = 0x9e3779b97f4a7c15u;
static uint64_t next(void) /* xorshift64* */
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 2685821657736338717u;
}
static double uniform(void) /* [0, 1) */
{
    return (double)(next() >> 11) * 0x1p-53;
}

static volatile double sink; /* keeps the loops from being optimised away */

/* ---- 1. parsing ------------------------------------------------------- */

/* n NUL-terminated numbers back to back in one buffer. */
static char *make_texts(size_t n, int kind, size_t *len)
{
    char *buf = malloc(n * 26 + 1), *p = buf;
    if (!buf)
        exit(1);
    for (size_t i = 0; i < n; i++) {
        double v = uniform() * 1000.0;
        if (kind == 0) /* short: what people type, 1 to 6 significant digits */
            p += sprintf(p, "%.*g", 1 + (int)(next() % 6), v);
        else /* long: the shortest round trip of a computed double (~16-17 digits) */
            p += tsu_format_double(v, p);
        *p++ = '\0';
    }
    *len = (size_t)(p - buf);
    return buf;
}

static double time_parse(const char *buf, size_t len, int use_strtod, double *sum)
{
    double best = 1e30;
    for (int rep = 0; rep < 3; rep++) {
        double s = 0.0, t0 = now();
        for (const char *p = buf; p < buf + len;) {
            double v;
            const char *stop;
            if (use_strtod) {
                char *e;
                v = strtod(p, &e);
                stop = e;
            } else {
                (void)tsu_parse_double(p, NULL, &v, &stop);
            }
            s += v;
            p = stop + 1;
        }
        double t = now() - t0;
        best = t < best ? t : best;
        *sum = s;
    }
    return best;
}

static void bench_parse(size_t n)
{
    const char *kinds[2] = {"short (1-6 digits)", "round-trip (16-17 digits)"};
    for (int kind = 0; kind < 2; kind++) {
        size_t len;
        char *buf = make_texts(n, kind, &len);
        double s1, s2;
        double t1 = time_parse(buf, len, 0, &s1), t2 = time_parse(buf, len, 1, &s2);
        printf("parse  %-26s tsu_parse_double %6.1f M/s   strtod %6.1f M/s   ratio %.2f%s\n",
               kinds[kind], (double)n / t1 / 1e6, (double)n / t2 / 1e6, t2 / t1,
               s1 == s2 ? "" : "   RESULTS DIFFER");
        free(buf);
    }
}

/* ---- 2. formatting ---------------------------------------------------- */

/* The libc way to the shortest round trip: %.17g, then %.16g, ... while the
 * text still converts back to v.  Returns the length. */
static size_t libc_shortest(double v, char *out)
{
    char tmp[40];
    int len = snprintf(out, 40, "%.17g", v);
    for (int p = 16; p >= 1; p--) {
        int l = snprintf(tmp, sizeof tmp, "%.*g", p, v);
        if (strtod(tmp, NULL) != v)
            break;
        memcpy(out, tmp, (size_t)l + 1);
        len = l;
    }
    return (size_t)len;
}

/* Same digits?  (The layouts differ: %.Pg switches to an exponent when the
 * decimal exponent reaches P, tsu_format_double only at 17.) */
static int same_value_text(const char *a, const char *b)
{
    return strtod(a, NULL) == strtod(b, NULL);
}

static void bench_format(size_t n)
{
    double *v = malloc(n * sizeof *v);
    if (!v)
        exit(1);
    const char *kinds[2] = {"short (1-6 digits)", "computed doubles"};
    for (int kind = 0; kind < 2; kind++) {
        for (size_t i = 0; i < n; i++) {
            double x = uniform() * 1000.0;
            if (kind == 0) { /* a value with a short decimal form, e.g. read from a CSV */
                char t[32];
                snprintf(t, sizeof t, "%.*g", 1 + (int)(next() % 6), x);
                x = strtod(t, NULL);
            }
            v[i] = x;
        }
        double best1 = 1e30, best2 = 1e30;
        size_t total = 0, differ = 0, layout = 0;
        char a[40], b[40];
        for (int rep = 0; rep < 3; rep++) {
            double t0 = now();
            for (size_t i = 0; i < n; i++)
                total += tsu_format_double(v[i], a);
            double t1 = now();
            for (size_t i = 0; i < n; i++)
                total += libc_shortest(v[i], b);
            double t2 = now();
            best1 = t1 - t0 < best1 ? t1 - t0 : best1;
            best2 = t2 - t1 < best2 ? t2 - t1 : best2;
        }
        for (size_t i = 0; i < n; i += 97) { /* a sample: both give the same value */
            tsu_format_double(v[i], a);
            libc_shortest(v[i], b);
            differ += !same_value_text(a, b);
            layout += strcmp(a, b) != 0;
        }
        sink = (double)total;
        printf("format %-26s tsu_format_double %6.1f M/s   snprintf loop %6.1f M/s   ratio %.1f"
               "   (sample: %zu differ in value, %zu in text)\n",
               kinds[kind], (double)n / best1 / 1e6, (double)n / best2 / 1e6, best2 / best1,
               differ, layout);
    }
    free(v);
}

/* ---- 3. reading a table ----------------------------------------------- */

typedef struct cols {
    double *x, *y;
    size_t n, cap;
} cols;

/* The plain loop: fgets, strtok on ",\n", strtod; skips a header line.  It
 * checks nothing the reader checks (fields per row, text after a number,
 * nan/inf, overflow, line numbers in messages, comments, blank lines). */
static int plain_read(FILE *fp, cols *c)
{
    char line[4096];
    int first = 1;
    while (fgets(line, sizeof line, fp)) {
        if (first) {
            first = 0;
            continue;
        }
        char *a = strtok(line, ",\n"), *b = a ? strtok(NULL, ",\n") : NULL;
        if (!b)
            return -1;
        if (c->n == c->cap) {
            c->cap = c->cap ? 2 * c->cap : 1024;
            c->x = realloc(c->x, c->cap * sizeof *c->x);
            c->y = realloc(c->y, c->cap * sizeof *c->y);
            if (!c->x || !c->y)
                return -1;
        }
        c->x[c->n] = strtod(a, NULL);
        c->y[c->n] = strtod(b, NULL);
        c->n++;
    }
    return 0;
}

static void bench_table(size_t rows)
{
    FILE *fp = tmpfile();
    if (!fp)
        exit(1);
    fputs("x,f\n", fp);
    double x = 0.0;
    char bx[TSU_FMT_SIZE], by[TSU_FMT_SIZE];
    for (size_t i = 0; i < rows; i++) {
        x += 0.1 + uniform();
        tsu_format_double(x, bx);
        tsu_format_double(uniform() * 10.0, by);
        fprintf(fp, "%s,%s\n", bx, by);
    }
    double best1 = 1e30, best2 = 1e30;
    int same = 1;
    for (int rep = 0; rep < 3; rep++) {
        tsu_table t;
        tsu_io_error e;
        cols c = {NULL, NULL, 0, 0};
        rewind(fp);
        double t0 = now();
        if (tsu_read_table(fp, "bench", NULL, &t, &e) != TSU_IO_OK) {
            fprintf(stderr, "%s\n", e.msg);
            exit(1);
        }
        double t1 = now();
        rewind(fp);
        double t2 = now();
        if (plain_read(fp, &c) != 0)
            exit(1);
        double t3 = now();
        best1 = t1 - t0 < best1 ? t1 - t0 : best1;
        best2 = t3 - t2 < best2 ? t3 - t2 : best2;
        same &= c.n == t.nrows && memcmp(c.x, t.cols[0], c.n * sizeof *c.x) == 0 &&
                memcmp(c.y, t.cols[1], c.n * sizeof *c.y) == 0;
        tsu_table_free(&t);
        free(c.x);
        free(c.y);
    }
    fclose(fp);
    printf("table  %-26s tsu_read_table %6.1f M rows/s   fgets+strtok+strtod %6.1f M rows/s"
           "   ratio %.2f%s\n",
           "x,y rows", (double)rows / best1 / 1e6, (double)rows / best2 / 1e6, best2 / best1,
           same ? "" : "   RESULTS DIFFER");
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)strtoull(argv[1], NULL, 10) : 10000000u;
    if (n < 1000)
        n = 1000;
    bench_parse(n);
    bench_format(n / 10); /* the snprintf loop is slow: a tenth is enough */
    bench_table(n / 2); /* n numbers: n/2 rows of two */
    return 0;
}
