/* Thread safety (header: "a fitted spline and curve are immutable ... any
 * number of threads may evaluate one spline at the same time; the only
 * mutable lookup state is a caller-owned ts_cursor").
 *
 * One spline per form (paper/positive, C¹/between, geometric/monotone) and
 * two curves (closed 2-D with a box, open 3-D) are built once.  The expected
 * values are those of the same calls made first on the main thread alone;
 * then 4 threads make every call again at the same time (released together
 * by a barrier), each in its own order (forward, reverse, sorted, shuffled),
 * threads 0 and 2 with NULL cursors, 1 and 3 each with its own cursor, and
 * each also builds its own copy of a spline (construction must be
 * reentrant).  Tolerance: none, results must be bitwise identical: the code
 * is deterministic on immutable data, and the interval a cursor finds is the
 * one the binary search finds (the right-hand one at a knot), so any
 * difference can only come from shared mutable state.
 *
 * Run under the ASan build by make test; a ThreadSanitizer build is a manual
 * check (see the review report), not part of make test.
 */
#define _POSIX_C_SOURCE 200809L
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NTH 4
#define NP 300    /* data points per spline */
#define NQ 2000   /* queries per spline */
#define NCQ 1500  /* queries per curve */
#define ROUNDS 2


/* Bitwise equality, NaN == NaN of the same bits. */
static int same(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

enum { NSPL = 3, NCRV = 2 };

typedef struct ref_spline {
    ts_spline *s;
    double x[NP], f[NP];
    ts_spline_options opt;
    double q[NQ], qs[NQ];              /* queries; sorted copy */
    int sidx[NQ];                      /* q[sidx[j]] = qs[j] */
    ts_status st[NQ];
    double y[NQ], dy[NQ], d2y[NQ];     /* ts_spline_eval_deriv */
    double yb[3][NQ], ybs[3][NQ];      /* ts_spline_eval_batch unsorted / sorted, deriv 0..2 */
    ts_status stb[3], stbs[3];
    double ia[NQ / 2];                 /* ts_spline_integral of (q[2j], q[2j+1]) */
    ts_status sti[NQ / 2];
    ts_interval_report rep[NP];
    ts_interval_report cert[NP];
    ts_status stc;
    ts_line lo, up;
} ref_spline;

typedef struct ref_curve {
    ts_curve *c;
    size_t dim;
    double t[NCQ];
    ts_status st[NCQ];
    double p[NCQ][3], dp[NCQ][3], d2p[NCQ][3];
    double len;
} ref_curve;

static ref_spline S[NSPL];
static ref_curve C[NCRV];

/* what each thread found */
typedef struct out_thread {
    int id;
    long eval_bad, batch_bad, mt_bad, integral_bad, report_bad, certify_bad, curve_bad,
        length_bad, build_bad, calls;
} out_thread;

static pthread_barrier_t barrier;

static int report_same(const ts_interval_report *a, const ts_interval_report *b)
{
    int ok = same(a->x0, b->x0) && same(a->x1, b->x1) && same(a->alpha, b->alpha) &&
             same(a->beta, b->beta) && same(a->a, b->a) && a->term == b->term &&
             a->has_lower == b->has_lower && a->has_upper == b->has_upper &&
             same(a->gap_lower, b->gap_lower) && same(a->at_lower, b->at_lower) &&
             same(a->gap_upper, b->gap_upper) && same(a->at_upper, b->at_upper) &&
             a->certified == b->certified;
    for (int l = 0; l < 4; l++)
        ok = ok && same(a->B[l], b->B[l]);
    return ok;
}

static void make_splines(void)
{
    for (int k = 0; k < NSPL; k++) {
        ref_spline *R = &S[k];
        double x = 0.0;
        for (int i = 0; i < NP; i++) {
            x += 0.05 + th_unit();
            R->x[i] = x;
        }
        ts_spline_options_init(&R->opt);
        R->lo = (ts_line){0.01, -3.0};
        R->up = (ts_line){0.01, 3.0};
        if (k == 0) { /* paper form, positive, data touching zero */
            for (int i = 0; i < NP; i++)
                R->f[i] = i % 37 == 5 ? 0.0 : 1.2 + sin(R->x[i]);
            R->opt.shape = TS_SHAPE_POSITIVE;
            R->opt.alpha = 0.2;
            R->opt.extrapolate = TS_EXTRAP_LINEAR;
        } else if (k == 1) { /* C¹ form between two lines */
            for (int i = 0; i < NP; i++)
                R->f[i] = 0.01 * R->x[i] + 2.9 * sin(3.0 * R->x[i]);
            R->opt.form = TS_FORM_C1;
            R->opt.shape = TS_SHAPE_BETWEEN;
            R->opt.lower = R->lo;
            R->opt.upper = R->up;
            R->opt.alpha = 0.05;
            R->opt.slopes = TS_SLOPES_AKIMA;
            R->opt.extrapolate = TS_EXTRAP_EXTEND;
        } else { /* geometric form, monotone with flat runs */
            double f = 0.0;
            for (int i = 0; i < NP; i++) {
                f += i % 11 < 3 ? 0.0 : th_unit() * th_unit() * 5.0;
                R->f[i] = f;
            }
            R->opt.form = TS_FORM_GEOMETRIC;
            R->opt.shape = TS_SHAPE_MONOTONE;
            R->opt.slopes = TS_SLOPES_FRITSCH_CARLSON;
            R->opt.extrapolate = TS_EXTRAP_CLAMP;
        }
        ts_error e;
        ts_status st = ts_spline_new(R->x, R->f, NP, &R->opt, &R->s, &e);
        CHECKF(st == TS_OK, "spline %d: %s at %zu", k, ts_strerror(st), e.index);
        if (st != TS_OK)
            exit(th_report("test_threads"));
        double x0 = R->x[0], xn = R->x[NP - 1], w = xn - x0;
        for (int j = 0; j < NQ; j++) {
            double u = th_unit();
            R->q[j] = j % 97 == 0 ? R->x[(size_t)(th_unit() * NP) % NP]       /* knots */
                      : j % 389 == 1 ? TH_NAN
                      : x0 - 0.05 * w + 1.1 * w * u;                       /* some outside */
        }
        /* insertion sort of the indices by value, NaN last */
        for (int j = 0; j < NQ; j++) {
            int v = j, i = j - 1;
            while (i >= 0 && (isnan(R->q[R->sidx[i]]) ||
                              (!isnan(R->q[v]) && R->q[R->sidx[i]] > R->q[v]))) {
                R->sidx[i + 1] = R->sidx[i];
                i--;
            }
            R->sidx[i + 1] = v;
        }
        for (int j = 0; j < NQ; j++)
            R->qs[j] = R->q[R->sidx[j]];
        for (int j = 0; j < NQ; j++)
            R->st[j] = ts_spline_eval_deriv(R->s, R->q[j], NULL, &R->y[j], &R->dy[j], &R->d2y[j]);
        for (int d = 0; d < 3; d++) {
            R->stb[d] = ts_spline_eval_batch(R->s, d, R->q, NQ, R->yb[d], NULL, NULL);
            R->stbs[d] = ts_spline_eval_batch(R->s, d, R->qs, NQ, R->ybs[d], NULL, NULL);
        }
        for (int j = 0; j < NQ / 2; j++)
            R->sti[j] = ts_spline_integral(R->s, R->q[2 * j], R->q[2 * j + 1], &R->ia[j]);
        for (size_t i = 0; i + 1 < NP; i++)
            CHECK(ts_spline_report(R->s, i, &R->rep[i]) == TS_OK);
        R->stc = ts_spline_certify(R->s, &R->lo, &R->up, R->cert, NULL);
    }
}

static void make_curves(void)
{
    for (int k = 0; k < NCRV; k++) {
        ref_curve *R = &C[k];
        ts_curve_options co;
        ts_curve_options_init(&co);
        double pts[64 * 3];
        size_t np;
        if (k == 0) { /* closed 2-D star inside a box */
            np = 40;
            R->dim = 2;
            for (size_t i = 0; i < np; i++) {
                double a = 2.0 * 3.14159265358979323846 * (double)i / (double)np;
                double r = i % 2 ? 0.9 : 0.4;
                pts[2 * i] = r * cos(a);
                pts[2 * i + 1] = r * sin(a);
            }
            co.closed = 1;
            co.alpha = 0.37;
            for (int d = 0; d < 2; d++) {
                co.has_lo[d] = co.has_hi[d] = 1;
                co.lo[d] = -0.95;
                co.hi[d] = 0.95;
            }
        } else { /* open 3-D helix, chord length, modified Akima */
            np = 60;
            R->dim = 3;
            for (size_t i = 0; i < np; i++) {
                double a = 0.4 * (double)i;
                pts[3 * i] = cos(a);
                pts[3 * i + 1] = sin(a);
                pts[3 * i + 2] = 0.1 * a;
            }
            co.param = TS_PARAM_CHORD;
            co.slopes = TS_SLOPES_MAKIMA;
            co.beta = 0.3;
        }
        ts_error e;
        ts_status st = ts_curve_new(pts, np, R->dim, &co, &R->c, &e);
        CHECKF(st == TS_OK, "curve %d: %s at %zu", k, ts_strerror(st), e.index);
        if (st != TS_OK)
            exit(th_report("test_threads"));
        const double *t = ts_curve_knots(R->c);
        double tn = t[ts_curve_segments(R->c)];
        for (int j = 0; j < NCQ; j++) {
            R->t[j] = j % 50 == 0 ? t[(size_t)(th_unit() * (double)ts_curve_segments(R->c))]
                      : -0.1 * tn + 1.2 * tn * th_unit(); /* closed: wraps; open: some outside */
            R->st[j] = ts_curve_eval(R->c, R->t[j], NULL, R->p[j], R->dp[j], R->d2p[j]);
        }
        CHECK(ts_curve_length(R->c, 1e-10, &R->len) == TS_OK);
    }
}

/* order[j]: the query thread id evaluates j-th */
static void make_order(int id, int n, int *order, uint64_t seed)
{
    for (int j = 0; j < n; j++)
        order[j] = id == 1 ? n - 1 - j : j;
    if (id == 3) {
        th_rng gen = TH_RNG_INIT(seed); /* the calling thread's own generator */
        for (int j = n - 1; j > 0; j--) {
            int r = (int)th_rng_below(&gen, (size_t)j + 1);
            int tmp = order[j];
            order[j] = order[r];
            order[r] = tmp;
        }
    }
}

static void *worker(void *arg)
{
    out_thread *o = arg;
    int id = o->id;
    int use_cursor = id % 2 == 1;
    static int orders[NTH][NQ]; /* each thread writes only its own row */
    int *order = orders[id];
    double yb[NQ];
    ts_interval_report rep, cert[NP];
    pthread_barrier_wait(&barrier);
    for (int round = 0; round < ROUNDS; round++) {
        for (int k = 0; k < NSPL; k++) {
            ref_spline *R = &S[k];
            ts_cursor cur = TS_CURSOR_INIT;
            ts_cursor *cp = use_cursor ? &cur : NULL;
            make_order(id, NQ, order, 77u + (uint64_t)id);
            if (id == 2) /* ascending x */
                memcpy(order, R->sidx, sizeof R->sidx);
            for (int jj = 0; jj < NQ; jj++) {
                int j = order[jj];
                double y, dy, d2y;
                ts_status st = ts_spline_eval_deriv(R->s, R->q[j], cp, &y, &dy, &d2y);
                o->calls++;
                if (st != R->st[j] || !same(y, R->y[j]) || !same(dy, R->dy[j]) ||
                    !same(d2y, R->d2y[j]))
                    o->eval_bad++;
                if (jj % 4 == 0) { /* ts_spline_eval (value only) agrees too */
                    double v;
                    if (ts_spline_eval(R->s, R->q[j], cp, &v) != R->st[j] || !same(v, R->y[j]))
                        o->eval_bad++;
                }
            }
            for (int d = 0; d < 3; d++) {
                ts_error e;
                ts_status st = ts_spline_eval_batch(R->s, d, R->q, NQ, yb, cp, &e);
                if (st != R->stb[d] || memcmp(yb, R->yb[d], sizeof yb) != 0)
                    o->batch_bad++;
                st = ts_spline_eval_batch(R->s, d, R->qs, NQ, yb, cp, &e);
                if (st != R->stbs[d] || memcmp(yb, R->ybs[d], sizeof yb) != 0)
                    o->batch_bad++;
                if (round == 0) { /* threads inside threads */
                    st = ts_spline_eval_batch_mt(R->s, d, R->q, NQ, yb, 2, &e);
                    if (st != R->stb[d] || memcmp(yb, R->yb[d], sizeof yb) != 0)
                        o->mt_bad++;
                }
                o->calls += 3;
            }
            for (int j = 0; j < NQ / 2; j++) {
                double v;
                ts_status st = ts_spline_integral(R->s, R->q[2 * j], R->q[2 * j + 1], &v);
                if (st != R->sti[j] || !same(v, R->ia[j]))
                    o->integral_bad++;
            }
            for (size_t i = 0; i + 1 < NP; i++)
                if (ts_spline_report(R->s, i, &rep) != TS_OK || !report_same(&rep, &R->rep[i]))
                    o->report_bad++;
            if (ts_spline_certify(R->s, &R->lo, &R->up, cert, NULL) != R->stc)
                o->certify_bad++;
            for (size_t i = 0; i + 1 < NP; i++)
                if (!report_same(&cert[i], &R->cert[i]))
                    o->certify_bad++;
        }
        for (int k = 0; k < NCRV; k++) {
            ref_curve *R = &C[k];
            ts_cursor cur = TS_CURSOR_INIT;
            ts_cursor *cp = use_cursor ? &cur : NULL;
            make_order(id, NCQ, order, 99u + (uint64_t)id);
            for (int jj = 0; jj < NCQ; jj++) {
                int j = order[jj];
                double p[3], dp[3], d2p[3];
                ts_status st = ts_curve_eval(R->c, R->t[j], cp, p, dp, d2p);
                o->calls++;
                if (st != R->st[j])
                    o->curve_bad++;
                for (size_t d = 0; d < R->dim; d++)
                    if (!same(p[d], R->p[j][d]) || !same(dp[d], R->dp[j][d]) ||
                        !same(d2p[d], R->d2p[j][d]))
                        o->curve_bad++;
            }
            double len;
            if (ts_curve_length(R->c, 1e-10, &len) != TS_OK || !same(len, R->len))
                o->length_bad++;
        }
        /* reentrant construction: a private copy equals the shared spline */
        {
            ref_spline *R = &S[(id + round) % NSPL];
            ts_spline *mine = NULL;
            if (ts_spline_new(R->x, R->f, NP, &R->opt, &mine, NULL) != TS_OK) {
                o->build_bad++;
            } else {
                size_t n = NP - 1;
                if (memcmp(ts_spline_beta(mine), ts_spline_beta(R->s), n * sizeof(double)) ||
                    memcmp(ts_spline_slopes(mine), ts_spline_slopes(R->s), NP * sizeof(double)))
                    o->build_bad++;
                for (size_t i = 0; i < n; i++) {
                    double B1[4], B2[4];
                    ts_spline_control(mine, i, B1, NULL);
                    ts_spline_control(R->s, i, B2, NULL);
                    if (memcmp(B1, B2, sizeof B1))
                        o->build_bad++;
                }
            }
            ts_spline_free(mine);
        }
    }
    return NULL;
}

int main(void)
{
    TH_CASE("fixtures");
    make_splines();
    make_curves();

    /* the fixtures are what they claim (else the comparison proves little) */
    CHECK(ts_spline_certified(S[0].s) && ts_spline_certified(S[1].s) &&
          ts_spline_certified(S[2].s));
    CHECK(S[1].stc == TS_OK); /* spline 1 keeps between its own lines */
    {
        int outside = 0, nanq = 0;
        for (int j = 0; j < NQ; j++) {
            outside += S[0].q[j] < S[0].x[0] || S[0].q[j] > S[0].x[NP - 1];
            nanq += isnan(S[0].q[j]);
        }
        CHECK(outside > 10 && nanq > 2);
        int nan_out = 0; /* clamp: only the NaN queries fail */
        for (int j = 0; j < NQ; j++)
            nan_out += isnan(S[2].yb[0][j]);
        CHECK(nan_out == nanq && S[2].stb[0] == TS_ERR_DOMAIN);
        CHECK(S[0].stb[0] == TS_ERR_DOMAIN);  /* NaN queries */
    }
    CHECK(ts_curve_certify(C[0].c, NULL, NULL) == TS_OK);

    TH_CASE("threads");
    pthread_t th[NTH];
    static out_thread outs[NTH];
    CHECK(pthread_barrier_init(&barrier, NULL, NTH) == 0);
    for (int t = 0; t < NTH; t++) {
        outs[t].id = t;
        CHECK(pthread_create(&th[t], NULL, worker, &outs[t]) == 0);
    }
    for (int t = 0; t < NTH; t++)
        CHECK(pthread_join(th[t], NULL) == 0);
    pthread_barrier_destroy(&barrier);
    for (int t = 0; t < NTH; t++) {
        const out_thread *o = &outs[t];
        CHECKF(o->eval_bad == 0, "thread %d: %ld eval mismatches", t, o->eval_bad);
        CHECKF(o->batch_bad == 0, "thread %d: %ld batch mismatches", t, o->batch_bad);
        CHECKF(o->mt_bad == 0, "thread %d: %ld batch_mt mismatches", t, o->mt_bad);
        CHECKF(o->integral_bad == 0, "thread %d: %ld integral mismatches", t, o->integral_bad);
        CHECKF(o->report_bad == 0, "thread %d: %ld report mismatches", t, o->report_bad);
        CHECKF(o->certify_bad == 0, "thread %d: %ld certify mismatches", t, o->certify_bad);
        CHECKF(o->curve_bad == 0, "thread %d: %ld curve mismatches", t, o->curve_bad);
        CHECKF(o->length_bad == 0, "thread %d: %ld length mismatches", t, o->length_bad);
        CHECKF(o->build_bad == 0, "thread %d: %ld construction mismatches", t, o->build_bad);
        CHECK(o->calls > (long)(ROUNDS * NSPL * NQ));
    }
    for (int k = 0; k < NSPL; k++)
        ts_spline_free(S[k].s);
    for (int k = 0; k < NCRV; k++)
        ts_curve_free(C[k].c);
    return th_report("test_threads");
}
