/* The batch kernels' outputs, bit for bit, against a fixed table.
 *
 * tests/data/kernel_bits.txt holds the value, S' and S'' of four splines
 * (paper form, paper form with the positive scheme, C¹ form, geometric
 * form; seeded data with flat runs) at 160 sorted queries (knots exactly; a
 * dense block and a sparse one whose gaps the cursor gallops over, short)
 * and 160 in random order, as hex floats: the portable kernel's, then the
 * FMA kernels' (AVX2+FMA and AVX-512F give the same bits) as GCC and as
 * Clang compile them (each contracts into fused multiply-adds in its own
 * way, so the FMA bits differ from the portable ones and between the
 * compilers in the last place for S', S'' and a few geometric-form values).
 * The table is the expected value: it was written by
 * tests/data/gen_kernel_bits.sh from the library before the kernels'
 * staging was rewritten (the rewrite must not change a bit), and every
 * kernel this CPU has must reproduce its column exactly (the FMA column of
 * the compiler that built this test; the library is built by the same).  No
 * tolerance: equality of the bits.  Under AddressSanitizer GCC contracts the
 * geometric form's solve differently (its instrumentation changes what is
 * inlined), so there the FMA kernels are checked against each other and the
 * portable one against the table (an ASan build of the library before the
 * rewrite and one after gave the same bits for every kernel: checked when
 * the rewrite was made).  Not for valgrind: its emulation of fused
 * multiply-adds gives some zero second derivatives the other sign.
 *
 * test_kernel_bits --write prints the portable, AVX2+FMA and AVX-512F
 * kernels' bits ("-" for one this CPU does not have).
 */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"
#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NP 2001
#define NQ 160
#define NS 4

static double X[NP], F[NP], FM[NP];
static double QS[NQ], QR[NQ];

static void make_data(void)
{
    th_rng r = TH_RNG_INIT(20261206);
    double x = 0.0;
    for (size_t i = 0; i < NP; i++) {
        X[i] = x;
        F[i] = 1.5 + sin(0.001 * x) + 0.3 * sin(0.37 * x) + 0.2 * th_rng_unit(&r);
        x += 0.5 + th_rng_unit(&r);
    }
    for (size_t i = 100; i < 106; i++) /* a flat run */
        F[i] = F[99];
    F[700] = F[701] = 1e-3; /* near zero: the positive scheme acts */
    (void)FM;
    /* sorted: a first block of 128 in ten intervals (runs of about 13: the
     * staging by runs, long and short), then a sparse one over all of them
     * (query by query, galloping; short: padded), knots exactly, both ends */
    for (size_t j = 0; j < NQ; j++) {
        double u = th_rng_unit(&r);
        QS[j] = j < 128 ? X[90] + (X[100] - X[90]) * u : X[100] + (X[NP - 1] - X[100]) * u;
    }
    for (size_t j = 0; j < 128; j += 13)
        QS[j] = X[90 + th_rng_below(&r, 10)];
    for (size_t j = 128; j < NQ; j += 7)
        QS[j] = X[100 + th_rng_below(&r, NP - 100)];
    QS[1] = X[90];
    QS[NQ - 1] = X[NP - 1];
    for (size_t a = 1; a < NQ; a++) /* insertion sort */
        for (size_t b = a; b > 0 && QS[b - 1] > QS[b]; b--) {
            double t = QS[b];
            QS[b] = QS[b - 1];
            QS[b - 1] = t;
        }
    for (size_t j = 0; j < NQ; j++)
        QR[j] = j % 11 == 0 ? X[th_rng_below(&r, NP)] : X[0] + (X[NP - 1] - X[0]) * th_rng_unit(&r);
}

static ts_spline *build(int which)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = which == 2 ? TS_FORM_C1 : which == 3 ? TS_FORM_GEOMETRIC : TS_FORM_PAPER;
    if (which == 1)
        o.shape = TS_SHAPE_POSITIVE;
    ts_spline *s = NULL;
    if (ts_spline_new(X, F, NP, &o, &s, NULL) != TS_OK)
        return NULL;
    return s;
}

/* y[NS][3][2][NQ] by kernel isa; 0 if the kernel is not on this CPU */
static int run(ts_spline *const *sp, int isa, double *y)
{
    for (int s = 0; s < NS; s++)
        for (int d = 0; d < 3; d++)
            for (int o = 0; o < 2; o++) {
                ts_cursor c = TS_CURSOR_INIT;
                size_t done = 0;
                double *out = y + ((size_t)(s * 3 + d) * 2 + (size_t)o) * NQ;
                if (!ts__fast_batch_isa(sp[s], d, o ? QR : QS, NQ, out, &c, isa, &done))
                    return 0;
                if (done != NQ)
                    return -1;
            }
    return 1;
}

int main(int argc, char **argv)
{
    make_data();
    ts_spline *sp[NS];
    for (int s = 0; s < NS; s++) {
        sp[s] = build(s);
        if (!sp[s]) {
            fprintf(stderr, "test_kernel_bits: spline %d not built\n", s);
            return 1;
        }
    }
    size_t total = (size_t)NS * 3 * 2 * NQ;
    static double want[3][NS * 3 * 2 * NQ], got[NS * 3 * 2 * NQ];
    static int have[3][NS * 3 * 2 * NQ];
    if (argc > 1 && !strcmp(argv[1], "--write")) {
        int r[3];
        for (int isa = 0; isa < 3; isa++)
            if ((r[isa] = run(sp, isa, want[isa])) < 0)
                return 1;
        printf("# spline deriv order index portable avx2 avx512 (tests/unit/test_kernel_bits.c)\n");
        for (size_t k = 0; k < total; k++) {
            printf("%zu %zu %zu %zu", k / (6 * NQ), k / (2 * NQ) % 3, k / NQ % 2, k % NQ);
            for (int isa = 0; isa < 3; isa++)
                if (r[isa])
                    printf(" %a", want[isa][k]);
                else
                    printf(" -");
            printf("\n");
        }
        for (int s = 0; s < NS; s++)
            ts_spline_free(sp[s]);
        return 0;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/tests/data/kernel_bits.txt", TS_SOURCE_DIR);
    FILE *f = fopen(path, "r");
    CHECKF(f != NULL, "%s", path);
    size_t nread = 0;
    if (f) {
        char line[256];
        while (fgets(line, sizeof line, f)) {
            size_t s, d, o, j;
            char v[3][64];
            if (line[0] == '#' || sscanf(line, "%zu %zu %zu %zu %63s %63s %63s", &s, &d, &o, &j,
                                         v[0], v[1], v[2]) != 7)
                continue;
#if defined(__clang__)
            memcpy(v[1], v[2], sizeof v[1]); /* Clang's FMA column */
#else
            memcpy(v[2], v[1], sizeof v[2]); /* GCC's */
#endif
            size_t k = ((s * 3 + d) * 2 + o) * NQ + j;
            if (s < NS && d < 3 && o < 2 && j < NQ && k == nread) {
                for (int isa = 0; isa < 3; isa++) {
                    have[isa][k] = strcmp(v[isa], "-") != 0;
                    want[isa][k] = have[isa][k] ? strtod(v[isa], NULL) : 0.0;
                }
                nread++;
            }
        }
        fclose(f);
    }
    CHECKF(nread == total, "%zu of %zu table rows read in order", nread, total);
    const char *kname[3] = {"portable", "AVX2+FMA", "AVX-512F"};
    static double fma_got[NS * 3 * 2 * NQ];
    int fma_have = 0;
    for (int isa = 0; isa < 3 && nread == total; isa++) {
        TH_CASE(kname[isa]);
        int r = run(sp, isa, got);
        if (r == 0) {
            printf("  %s kernel: not on this CPU\n", kname[isa]);
            continue;
        }
        CHECK(r == 1);
        long bad = 0, absent = 0;
        if (TH_ASAN && isa > 0) { /* the FMA kernels against each other */
            if (fma_have)
                for (size_t k = 0; k < total; k++)
                    if (memcmp(&got[k], &fma_got[k], sizeof(double)) != 0 && bad++ < 5)
                        fprintf(stderr, "%s: %zu: %a, the other FMA kernel %a\n", kname[isa], k,
                                got[k], fma_got[k]);
            memcpy(fma_got, got, sizeof fma_got);
            fma_have = 1;
            CHECKF(bad == 0, "%s kernel: %ld of %zu values differ from the other FMA kernel's",
                   kname[isa], bad, total);
            continue;
        }
        for (size_t k = 0; k < total; k++) {
            if (!have[isa][k]) {
                absent++;
                continue;
            }
            if (memcmp(&got[k], &want[isa][k], sizeof(double)) != 0 && bad++ < 5)
                fprintf(stderr, "%s: spline %zu deriv %zu order %zu index %zu: %a, table %a\n",
                        kname[isa], k / (6 * NQ), k / (2 * NQ) % 3, k / NQ % 2, k % NQ, got[k],
                        want[isa][k]);
        }
        if (absent) /* the table was written on a CPU without this kernel */
            printf("  %s kernel: no column in the table\n", kname[isa]);
        CHECKF(bad == 0, "%s kernel: %ld of %zu values differ from the table", kname[isa], bad,
               total);
    }
    for (int s = 0; s < NS; s++)
        ts_spline_free(sp[s]);
    return th_report("test_kernel_bits");
}
