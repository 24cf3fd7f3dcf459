/* Instruction counts of the batch kernels (bench/HISTORY.md): run under
 *   valgrind --tool=callgrind --toggle-collect=measured bench/icount FORM ISA ORDER [DERIV]
 * FORM paper | c1 | geometric | gsl (GSL steffen, gsl_interp_eval + accel);
 * ISA 0 portable, 1 AVX2+FMA, 2 AVX-512F (valgrind has no AVX-512), -1 one
 * ts_spline_eval call per point with a cursor instead of the batch kernel;
 * ORDER sorted | random.  The bench's data at 10001 knots, 1e5 queries
 * (ICOUNT_NP, ICOUNT_M to change them); instructions per point = the Ir of
 * `measured` / the queries.  With ICOUNT_REPS=r
 * in the environment it also times r runs (thread CPU time) and prints the
 * minimum and median ns per point. */
#define _POSIX_C_SOURCE 200809L
#include "trigspline.h"
#include "internal.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static size_t NP = 10001, M = 100000; /* ICOUNT_NP, ICOUNT_M in the environment */

static uint64_t rng = 0x9E3779B97F4A7C15u;
static double urand(void)
{
    rng = rng * 6364136223846793005u + 1442695040888963407u;
    return (double)(rng >> 11) * 0x1p-53;
}

static double *X, *F, *Q, *Y;

__attribute__((noinline)) static int measured(const ts_spline *s, gsl_interp *g,
                                              gsl_interp_accel *acc, int deriv, int isa)
{
    if (g) {
        for (size_t j = 0; j < M; j++)
            Y[j] = gsl_interp_eval(g, X, F, Q[j], acc);
        return 1;
    }
    ts_cursor c = TS_CURSOR_INIT;
    if (isa < 0) { /* one ts_spline_eval call per point */
        for (size_t j = 0; j < M; j++)
            if (ts_spline_eval(s, Q[j], &c, &Y[j]) != TS_OK)
                return 0;
        return 1;
    }
    size_t done = 0;
    return ts__fast_batch_isa(s, deriv, Q, M, Y, &c, isa, &done) && done == M;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: icount paper|c1|geometric|gsl ISA sorted|random [DERIV]\n");
        return 2;
    }
    if (getenv("ICOUNT_NP"))
        NP = (size_t)atol(getenv("ICOUNT_NP"));
    if (getenv("ICOUNT_M"))
        M = (size_t)atol(getenv("ICOUNT_M"));
    if (NP < 3 || M < 2 || NP > 100000000 || M > 1000000000)
        return 2;
    X = malloc(NP * sizeof *X);
    F = malloc(NP * sizeof *F);
    Q = malloc(M * sizeof *Q);
    Y = malloc(M * sizeof *Y);
    if (!X || !F || !Q || !Y)
        return 3;
    int isa = atoi(argv[2]), random_q = !strcmp(argv[3], "random"),
        deriv = argc > 4 ? atoi(argv[4]) : 0;
    X[0] = 0.0;
    for (size_t i = 1; i < NP; i++)
        X[i] = X[i - 1] + 0.5 + urand();
    for (size_t i = 0; i < NP; i++)
        F[i] = 1.5 + sin(0.001 * X[i]) + 0.3 * sin(0.37 * X[i]) + 0.2 * urand();
    for (size_t j = 0; j < M; j++)
        Q[j] = random_q ? X[NP - 1] * urand() : X[NP - 1] * ((double)j / (double)(M - 1));
    ts_spline *s = NULL;
    gsl_interp *g = NULL;
    gsl_interp_accel *acc = NULL;
    if (!strcmp(argv[1], "gsl")) {
        g = gsl_interp_alloc(gsl_interp_steffen, NP);
        acc = gsl_interp_accel_alloc();
        if (!g || !acc || gsl_interp_init(g, X, F, NP))
            return 1;
    } else {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = !strcmp(argv[1], "paper") ? TS_FORM_PAPER
                 : !strcmp(argv[1], "c1")  ? TS_FORM_C1
                                           : TS_FORM_GEOMETRIC;
        if (ts_spline_new(X, F, NP, &o, &s, NULL) != TS_OK)
            return 1;
    }
    int ok = measured(s, g, acc, deriv, isa);
    const char *reps_env = getenv("ICOUNT_REPS");
    int reps = reps_env ? atoi(reps_env) : 0;
    if (reps > 0 && reps <= 1000) {
        double t[1000];
        for (int r = 0; r < reps; r++) {
            struct timespec a, b;
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
            measured(s, g, acc, deriv, isa);
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
            t[r] = ((double)(b.tv_sec - a.tv_sec) * 1e9 + (double)(b.tv_nsec - a.tv_nsec)) /
                   (double)M;
        }
        for (int a = 1; a < reps; a++) /* insertion sort */
            for (int b = a; b > 0 && t[b - 1] > t[b]; b--) {
                double u = t[b];
                t[b] = t[b - 1];
                t[b - 1] = u;
            }
        printf("ns/point: min %.3f median %.3f\n", t[0], t[reps / 2]);
    }
    double sum = 0.0;
    for (size_t j = 0; j < M; j++)
        sum += Y[j];
    printf("%s isa %d %s deriv %d: %s, sum %.17g\n", argv[1], isa, argv[3], deriv,
           ok ? "ok" : "not run", sum);
    ts_spline_free(s);
    gsl_interp_free(g);
    gsl_interp_accel_free(acc);
    free(X);
    free(F);
    free(Q);
    free(Y);
    return ok ? 0 : 1;
}
