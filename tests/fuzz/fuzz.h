/* Shared by the harnesses of tests/fuzz/: the libFuzzer entry point and a
 * check that stops the run (abort) with the failing condition, so that both
 * libFuzzer and the corpus replay of `make test` see a failure. */
#ifndef TS_FUZZ_H
#define TS_FUZZ_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_CHECK(cond, ...)                                                            \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);    \
            fprintf(stderr, __VA_ARGS__);                                                \
            fputc('\n', stderr);                                                         \
            abort();                                                                     \
        }                                                                                \
    } while (0)

/* Counts for the report of a run: executions, certified objects, samples
 * checked against their region (a sample outside stops the run, so none
 * is ever counted outside).  Printed at exit (stderr) when TS_FUZZ_STATS
 * is set in the environment. */
enum { FUZZ_EXECS, FUZZ_CERTIFIED, FUZZ_SAMPLES };
static inline long *fuzz_counts(void)
{
    static long c[3];
    return c;
}
static inline void fuzz_stats_print(void)
{
    long *c = fuzz_counts();
    fprintf(stderr, "stats: %ld executions, %ld certified objects, %ld samples checked, 0 outside\n",
            c[FUZZ_EXECS], c[FUZZ_CERTIFIED], c[FUZZ_SAMPLES]);
}
/* call first in every execution */
static inline void fuzz_stats_exec(void)
{
    static int registered;
    if (!registered) {
        registered = 1;
        if (getenv("TS_FUZZ_STATS"))
            atexit(fuzz_stats_print);
    }
    fuzz_counts()[FUZZ_EXECS]++;
}

/* Input bytes taken in order; past the end every read gives 0. */
typedef struct fuzz_in {
    const uint8_t *p;
    size_t n;
} fuzz_in;

static inline unsigned fuzz_byte(fuzz_in *in)
{
    if (!in->n)
        return 0;
    in->n--;
    return *in->p++;
}

static inline double fuzz_raw_double(fuzz_in *in)
{
    uint64_t u = 0;
    for (int k = 0; k < 8; k++)
        u = u << 8 | fuzz_byte(in);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* A double of a kind picked by one byte: small integers and decimals
 * (most inputs), powers of ten of either sign, or raw bits (NaN, Inf,
 * subnormals and values near DBL_MAX included). */
static inline double fuzz_double(fuzz_in *in)
{
    unsigned kind = fuzz_byte(in);
    if (kind < 160) {
        int v = (int)(fuzz_byte(in) << 8 | fuzz_byte(in)) - 32768;
        return kind < 80 ? (double)v : v / 1000.0;
    }
    if (kind < 224) {
        int e = (int)fuzz_byte(in) % 617 - 308;
        double m = 1.0 + fuzz_byte(in) / 256.0;
        return (kind & 1 ? -m : m) * pow(10.0, e);
    }
    return fuzz_raw_double(in);
}

#endif
