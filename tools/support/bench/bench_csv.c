/*
 * bench_csv — the table reader of tsu_io against Debian's libcsv (libcsv-dev,
 * an RFC 4180 tokenizer with callbacks), on the same in-memory file
 * (docs/design.md, "Real-world input: the tokenizer").
 *
 * Three files of N rows: plain "x,y" numbers, every field quoted, and quoted
 * ISO 8601 timestamps with a value.  libcsv tokenizes (strict mode, fields
 * NUL-terminated) and its field callback converts each field with the same
 * converters the reader uses (tsu_parse_double, tsu_parse_time), so the
 * comparison is tokenizer against tokenizer on the same work; the sums of all
 * values are checked equal.  Best of 3 runs (CLOCK_MONOTONIC).
 * Not built by default: cmake -DTS_BUILD_CSV_BENCH=ON (needs libcsv-dev), then
 * BUILD/tools/bench_csv [N]   (default 5000000).
 */
#define _POSIX_C_SOURCE 200809L
#include "tsu_io.h"

#include <csv.h>

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

static char *make_file(size_t n, int kind, size_t *len)
{
    size_t cap = n * 48 + 64, k = 0;
    char *b = malloc(cap);
    if (!b)
        return NULL;
    k += (size_t)sprintf(b, kind ? "\"x\",\"y\"\n" : "x,y\n");
    for (size_t i = 0; i < n; i++) {
        unsigned v = (unsigned)((i * 2654435761u) % 100000u);
        if (kind == 0)
            k += (size_t)sprintf(b + k, "%zu.%03u,%u.%02u\n", i, v % 1000, v / 100, v % 100);
        else if (kind == 1)
            k += (size_t)sprintf(b + k, "\"%zu.%03u\",\"%u.%02u\"\n", i, v % 1000, v / 100, v % 100);
        else {
            size_t s = i;
            k += (size_t)sprintf(b + k, "\"2001-%02zu-%02zuT%02zu:%02zu:%02zuZ\",\"%u.%02u\"\n",
                                 1 + s / 2419200 % 12, 1 + s / 86400 % 28, s / 3600 % 24,
                                 s / 60 % 60, s % 60, v / 100, v % 100);
        }
    }
    *len = k;
    return b;
}

typedef struct acc {
    double sum;
    size_t field, rows;
    int kind;
} acc;

static void on_field(void *s, size_t len, void *data)
{
    acc *a = data;
    double v = 0;
    const char *t = s;
    if (a->rows > 0) { /* not the header */
        if (a->kind == 2 && a->field == 0)
            (void)tsu_parse_time(t, t + len, &v, NULL, NULL);
        else
            (void)tsu_parse_double(t, t + len, &v, NULL);
        a->sum += v;
    }
    a->field++;
}

static void on_row(int c, void *data)
{
    acc *a = data;
    (void)c;
    a->field = 0;
    a->rows++;
}

static double run_libcsv(const char *b, size_t len, int kind, double *sum)
{
    struct csv_parser p;
    acc a = {0, 0, 0, kind};
    double t0 = now();
    csv_init(&p, CSV_STRICT | CSV_APPEND_NULL);
    /* fed in 1 MiB pieces, as a stream would be */
    for (size_t off = 0; off < len; off += 1u << 20) {
        size_t k = len - off < (1u << 20) ? len - off : (1u << 20);
        if (csv_parse(&p, b + off, k, on_field, on_row, &a) != k)
            fprintf(stderr, "libcsv: %s\n", csv_strerror(csv_error(&p)));
    }
    csv_fini(&p, on_field, on_row, &a);
    csv_free(&p);
    *sum = a.sum;
    return now() - t0;
}

static double run_tsu(const char *b, size_t len, double *sum)
{
    FILE *f = fmemopen((void *)b, len, "r");
    tsu_reader *r;
    tsu_io_error e;
    tsu_read_options o;
    const double *row;
    double s = 0, t0 = now();
    tsu_read_options_init(&o);
    o.time_detect = 1;
    o.na = "NA";
    if (!f || tsu_reader_open(&r, f, "bench", &o, &e) != TSU_IO_OK)
        return -1;
    while (tsu_reader_next(r, &row, &e) == TSU_IO_OK)
        s += row[0] + row[1];
    tsu_reader_free(r);
    fclose(f);
    *sum = s;
    return now() - t0;
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)strtoull(argv[1], NULL, 10) : 5000000;
    static const char *const names[3] = {"plain x,y", "quoted \"x\",\"y\"", "quoted ISO dates"};
    printf("%-20s %14s %14s %8s\n", "file", "tsu_reader M/s", "libcsv M/s", "ratio");
    for (int kind = 0; kind < 3; kind++) {
        size_t len;
        char *b = make_file(n, kind, &len);
        double best_t = 1e30, best_c = 1e30, st = 0, sc = 0;
        if (!b)
            return 1;
        for (int rep = 0; rep < 3; rep++) {
            double t = run_tsu(b, len, &st), c = run_libcsv(b, len, kind, &sc);
            if (t < best_t)
                best_t = t;
            if (c < best_c)
                best_c = c;
        }
        printf("%-20s %14.2f %14.2f %8.2f%s\n", names[kind], n / best_t / 1e6, n / best_c / 1e6,
               best_c / best_t, st == sc ? "" : "  (sums differ!)");
        free(b);
    }
    return 0;
}
