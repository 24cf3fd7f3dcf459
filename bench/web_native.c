/* The native side of bench/web_bench.mjs (make bench-web): the sorted batch
 * with the portable C kernel of the native library (ts__fast_batch_isa,
 * kernel 0, as bench.c's "portable C" rows), on the data web_bench.mjs
 * builds in WebAssembly (web_data below and dataOf there: the same
 * arithmetic, exact in both).  It reads commands on stdin, one a line, and
 * answers each with one line, so that node interleaves it with the modules:
 *   setup FORM N M   fit N knots (FORM 0 paper, 1 c1, 2 geometric; positive
 *                    scheme) and M sorted queries; answers "ok" or "error ..."
 *   run DERIV        one batch; answers the thread CPU time in ns and the sum
 *                    of the outputs ("ns sum")
 *   quit
 * usage: web_native   (a child of web_bench.mjs) */
#define _POSIX_C_SOURCE 200809L
#include "internal.h"
#include "trigspline.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double thread_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

/* Knots x_i = i + u_i/2 (u_i in [0, 1) from a 32-bit LCG, a multiple of
 * 2^-32: exact), values f_i = 1 + 2 u'_i, or 0 at every seventh knot (the
 * positive scheme has work to do); queries evenly spread over [x_0, x_{n-1}]:
 * x_0 + (j + 0.5) (x_{n-1} − x_0) / m. */
static void web_data(size_t n, size_t m, double *x, double *f, double *xq)
{
    uint32_t s = 12345u;
    for (size_t i = 0; i < n; i++) {
        s = s * 1664525u + 1013904223u;
        x[i] = (double)i + 0.5 * ((double)s * 0x1p-32);
        s = s * 1664525u + 1013904223u;
        f[i] = i % 7 == 3 ? 0.0 : 1.0 + 2.0 * ((double)s * 0x1p-32);
    }
    double span = x[n - 1] - x[0];
    for (size_t j = 0; j < m; j++)
        xq[j] = x[0] + ((double)j + 0.5) * span / (double)m;
}

int main(void)
{
    char line[256];
    ts_spline *sp = NULL;
    double *x = NULL, *f = NULL, *xq = NULL, *yq = NULL;
    size_t m = 0;
    setvbuf(stdout, NULL, _IOLBF, 0);
    while (fgets(line, sizeof line, stdin)) {
        int form, deriv;
        unsigned long long nn, mm;
        if (sscanf(line, "setup %d %llu %llu", &form, &nn, &mm) == 3) {
            ts_spline_free(sp);
            sp = NULL;
            free(x), free(f), free(xq), free(yq);
            m = (size_t)mm;
            size_t n = (size_t)nn;
            x = malloc(n * sizeof *x), f = malloc(n * sizeof *f);
            xq = malloc(m * sizeof *xq), yq = malloc(m * sizeof *yq);
            if (n < 2 || n > SIZE_MAX / 8 || m > SIZE_MAX / 8 || !x || !f || !xq || !yq) {
                printf("error no memory\n");
                continue;
            }
            web_data(n, m, x, f, xq);
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = (ts_form)form;
            o.shape = TS_SHAPE_POSITIVE;
            ts_status st = ts_spline_new(x, f, n, &o, &sp, NULL);
            if (st != TS_OK)
                printf("error %s\n", ts_status_name(st));
            else
                printf("ok\n");
        } else if (sscanf(line, "run %d", &deriv) == 1 && sp) {
            size_t done = 0;
            double t0 = thread_ns();
            int ok = ts__fast_batch_isa(sp, deriv, xq, m, yq, NULL, 0, &done);
            double t = thread_ns() - t0, sum = 0.0;
            for (size_t j = 0; j < m; j++)
                sum += yq[j];
            if (!ok || done != m)
                printf("error portable kernel did %zu of %zu\n", done, m);
            else
                printf("%.0f %.17g\n", t, sum);
        } else if (strncmp(line, "quit", 4) == 0) {
            break;
        } else {
            printf("error bad command\n");
        }
    }
    ts_spline_free(sp);
    free(x), free(f), free(xq), free(yq);
    return 0;
}
