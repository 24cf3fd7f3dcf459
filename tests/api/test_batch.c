/* ts_spline_eval_batch / ts_spline_eval_batch_mt against one-by-one ts_spline_eval_deriv.
 *
 * Expected values: ts_spline_eval_deriv (whose values test_core.c checks against the
 * mpmath reference).  The batch may use the faster kernels of fast.c, bounded
 * there by ~4 ulp relative to max|B| of the interval; we compare with
 * tolerance 1e-13·max(1, max|f|, max|B|)·w^k for derivative k, w = π/(2 h_min)
 * (= dθ/dx; the bound on the θ-derivative scales by w^k), i.e. ~450 ulp: room
 * for any sound kernel, far below any formula error.  Outside the data
 * (extension) the basis grows to <= 19·(1 + |θ|) (test_basis.c), so that
 * tolerance is multiplied by 20·(1 + |θ|) there.
 * Invalid queries (NaN; outside the data under TS_EXTRAP_ERROR; ±Inf unless
 * TS_EXTRAP_CLAMP) must give NaN
 * and TS_ERR_DOMAIN with err.index = the first invalid query.
 */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define NQ 1200


typedef struct fix {
    const char *name;
    ts_spline *s;
    double x0, xn, scale, w, h0, hn;
    size_t n;
    ts_extrap ex;
} fix;

static int valid_query(const fix *F, double x)
{
    if (isnan(x))
        return 0;
    if (isinf(x)) /* header: ±Inf is clamped under CLAMP, an error otherwise */
        return F->ex == TS_EXTRAP_CLAMP;
    if (F->ex == TS_EXTRAP_ERROR)
        return F->x0 <= x && x <= F->xn;
    return 1;
}

static double tol_for(const fix *F, int deriv, double x)
{
    double t = 1e-13 * F->scale * pow(F->w, deriv);
    if (isinf(x))
        return 0; /* clamped: exactly the end value, derivatives 0 */
    if (x < F->x0)
        t *= 20 * (1 + PI / 2 * (F->x0 - x) / F->h0);
    else if (x > F->xn)
        t *= 20 * (1 + PI / 2 * (x - F->xn) / F->hn);
    return t;
}

/* One batch call (and the mt variants) vs one-by-one. */
static void compare(const fix *F, int deriv, const double *xq, size_t m, ts_cursor *cur, const char *what)
{
    double *yq = malloc(m * sizeof *yq), *ref = malloc(m * sizeof *ref);
    if (!yq || !ref) {
        free(yq);
        free(ref);
        CHECKF(0, "out of memory in the test");
        return;
    }
    size_t first_bad = TS_NO_INDEX;
    int status_mismatch = 0;
    for (size_t j = 0; j < m; j++) {
        double o[3];
        ts_status st = ts_spline_eval_deriv(F->s, xq[j], NULL, &o[0], &o[1], &o[2]);
        ref[j] = o[deriv];
        status_mismatch += (st == TS_OK) != (valid_query(F, xq[j]) != 0);
        if (st != TS_OK && first_bad == TS_NO_INDEX)
            first_bad = j;
        yq[j] = 12345.0; /* must be overwritten */
    }
    CHECKF(status_mismatch == 0, "%s/%s: ts_spline_eval_deriv status disagrees with the policy at %d queries", F->name,
           what, status_mismatch);
    ts_error err;
    ts_status st = ts_spline_eval_batch(F->s, deriv, xq, m, yq, cur, &err);
    int bad = 0;
    size_t where = 0;
    for (size_t j = 0; j < m; j++) {
        int ok;
        if (isnan(ref[j]))
            ok = isnan(yq[j]);
        else
            ok = fabs(yq[j] - ref[j]) <= tol_for(F, deriv, xq[j]);
        if (!ok && !bad++)
            where = j;
    }
    CHECKF(bad == 0, "%s/%s deriv %d: %d mismatches, first at %zu: x = %.17g batch %.17g one-by-one %.17g",
           F->name, what, deriv, bad, where, xq[where], yq[where], ref[where]);
    if (first_bad == TS_NO_INDEX) {
        CHECKF(st == TS_OK && err.status == TS_OK && err.index == TS_NO_INDEX, "%s/%s deriv %d: status %d",
               F->name, what, deriv, (int)st);
    } else {
        CHECKF(st == TS_ERR_DOMAIN && err.status == TS_ERR_DOMAIN && err.index == first_bad &&
                   err.where == TS_WHERE_QUERY,
               "%s/%s deriv %d: status %d index %zu, want DOMAIN at %zu", F->name, what, deriv, (int)st, err.index,
               first_bad);
    }
    /* multi-threaded: the same values and the same status / first index */
    const unsigned threads[4] = {1, 2, 3, 0};
    for (int t = 0; t < 4; t++) {
        double *ym = malloc(m * sizeof *ym);
        if (!ym)
            break;
        for (size_t j = 0; j < m; j++)
            ym[j] = 12345.0;
        ts_error em;
        ts_status sm = ts_spline_eval_batch_mt(F->s, deriv, xq, m, ym, threads[t], &em);
        int diff = 0;
        for (size_t j = 0; j < m; j++) {
            int ok = isnan(ref[j]) ? isnan(ym[j]) : fabs(ym[j] - ref[j]) <= tol_for(F, deriv, xq[j]);
            diff += !ok;
        }
        CHECKF(diff == 0, "%s/%s deriv %d, %u threads: %d mismatches", F->name, what, deriv, threads[t], diff);
        CHECKF(sm == st && em.status == err.status && em.index == err.index && em.where == err.where,
               "%s/%s deriv %d, %u threads: status %d index %zu, single-threaded %d index %zu", F->name, what,
               deriv, threads[t], (int)sm, em.index, (int)st, err.index);
        free(ym);
    }
    free(yq);
    free(ref);
}

static void run_sets(const fix *F)
{
    static double xq[NQ];
    double L = F->xn - F->x0;
    const int kinds = 7;
    for (int kind = 0; kind < kinds; kind++) {
        size_t m = NQ;
        const char *what = "";
        switch (kind) {
        case 0: /* sorted, both ends included */
            what = "sorted";
            for (size_t j = 0; j < m; j++)
                xq[j] = F->x0 + L * (double)j / (double)(m - 1);
            break;
        case 1: /* reverse-sorted */
            what = "reverse";
            for (size_t j = 0; j < m; j++)
                xq[j] = F->xn - L * (double)j / (double)(m - 1);
            break;
        case 2: /* random */
            what = "random";
            for (size_t j = 0; j < m; j++)
                xq[j] = F->x0 + L * th_unit();
            break;
        case 3: /* duplicated: runs of equal queries, random order of runs */
            what = "duplicated";
            for (size_t j = 0; j < m; j += 4) {
                double v = F->x0 + L * th_unit();
                for (size_t k = j; k < j + 4 && k < m; k++)
                    xq[k] = v;
            }
            break;
        case 4: /* sorted with out-of-range and NaN mixed in */
            what = "sorted+invalid";
            for (size_t j = 0; j < m; j++)
                xq[j] = F->x0 - 0.5 * F->h0 + (L + 0.5 * F->h0 + 1.2 * F->hn) * (double)j / (double)(m - 1);
            xq[17] = TH_NAN;
            xq[500] = TH_NAN;
            xq[m - 1] = TH_NAN;
            break;
        case 5: /* random with invalid queries, first invalid late */
            what = "random+invalid";
            for (size_t j = 0; j < m; j++)
                xq[j] = F->x0 + L * th_unit();
            xq[700] = F->xn + 0.25 * F->hn;
            xq[701] = TH_NAN;
            xq[900] = F->x0 - 1e-3 * F->h0;
            xq[1100] = F->x0 - 1e6 * F->h0;
            xq[1150] = HUGE_VAL;
            xq[1160] = -HUGE_VAL;
            break;
        case 6: /* knots exactly and their neighbours */
            what = "knots";
            {
                /* knots from the accessor; neighbours one ulp away */
                const double *X = ts_spline_x(F->s);
                size_t j = 0;
                for (size_t i = 0; i <= F->n && j + 3 <= m; i++) {
                    xq[j++] = X[i];
                    xq[j++] = nextafter(X[i], -TH_INF);
                    xq[j++] = nextafter(X[i], TH_INF);
                }
                m = j;
            }
            break;
        }
        for (int deriv = 0; deriv <= 2; deriv++) {
            compare(F, deriv, xq, m, NULL, what);
            ts_cursor cur = TS_CURSOR_INIT;
            compare(F, deriv, xq, m, &cur, what);
            cur.interval = F->n + 1000; /* stale hint from elsewhere */
            compare(F, deriv, xq, m, &cur, what);
            cur.interval = F->n - 1;
            compare(F, deriv, xq, m, &cur, what);
        }
    }
}

/* A query's value does not depend on where it sits in a batch: the sorted
 * batch in one call equals the same queries evaluated one at a time and in
 * chunks of every length 1..7 (bit for bit; chunked callers such as dask
 * rely on it).  Expected values: the same function, so the check is exact. */
static void position_independence(const double *x, const double *f, size_t np)
{
    enum { M = 1001 };
    static double xq[M], y1[M], yc[M];
    const ts_form forms[3] = {TS_FORM_PAPER, TS_FORM_C1, TS_FORM_GEOMETRIC};
    const char *names[3] = {"position/paper", "position/c1", "position/geometric"};
    for (int k = 0; k < 3; k++) {
        TH_CASE(names[k]);
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = forms[k];
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, np, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        for (int j = 0; j < M; j++)
            xq[j] = x[0] + (x[np - 1] - x[0]) * j / (M - 1.0);
        for (int deriv = 0; deriv < 3; deriv++) {
            CHECK(ts_spline_eval_batch(s, deriv, xq, M, y1, NULL, NULL) == TS_OK);
            size_t bad = 0;
            for (size_t len = 1; len <= 7; len++) {
                for (size_t j0 = 0; j0 < M; j0 += len) {
                    size_t nb = M - j0 < len ? M - j0 : len;
                    CHECK(ts_spline_eval_batch(s, deriv, xq + j0, nb, yc + j0, NULL, NULL) == TS_OK);
                }
                for (int j = 0; j < M; j++)
                    bad += memcmp(&yc[j], &y1[j], sizeof(double)) != 0;
            }
            CHECKF(bad == 0, "%s deriv %d: %zu values differ from the whole batch", names[k],
                   deriv, bad);
        }
        ts_spline_free(s);
    }
}

int main(void)
{
    /* non-uniform data with mixed signs; per-interval alpha and beta */
    enum { NP = 14 };
    double x[NP], f[NP], al[NP - 1], be[NP - 1];
    x[0] = -3.0;
    for (int i = 1; i < NP; i++)
        x[i] = x[i - 1] + 0.05 + 2.0 * th_unit();
    for (int i = 0; i < NP; i++)
        f[i] = 40.0 * (th_unit() - 0.3);
    for (int i = 0; i < NP - 1; i++) {
        al[i] = 0.1 + 2.0 * th_unit();
        be[i] = i % 3 ? 1.5 * th_unit() : 0.0;
    }
    const ts_extrap exs[4] = {TS_EXTRAP_ERROR, TS_EXTRAP_CLAMP, TS_EXTRAP_EXTEND, TS_EXTRAP_LINEAR};
    const char *names[2][4] = {{"paper/error", "paper/clamp", "paper/extend", "paper/linear"},
                               {"c1/error", "c1/clamp", "c1/extend", "c1/linear"}};
    for (int form = 0; form < 2; form++) {
        for (int e = 0; e < 4; e++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = form ? TS_FORM_C1 : TS_FORM_PAPER;
            o.alphas = al, o.n_alphas = NP - 1;
            o.betas = be, o.n_betas = NP - 1;
            o.extrapolate = exs[e];
            TH_CASE(names[form][e]);
            fix F;
            memset(&F, 0, sizeof F);
            F.name = names[form][e];
            F.ex = exs[e];
            CHECK(ts_spline_new(x, f, NP, &o, &F.s, NULL) == TS_OK);
            if (!F.s)
                continue;
            F.n = NP - 1;
            F.x0 = x[0], F.xn = x[NP - 1];
            F.h0 = x[1] - x[0], F.hn = x[NP - 1] - x[NP - 2];
            double hmin = TH_INF, sc = 1;
            for (size_t i = 0; i < F.n; i++) {
                double B[4];
                hmin = fmin(hmin, x[i + 1] - x[i]);
                CHECK(ts_spline_control(F.s, i, B, NULL) == TS_OK);
                for (int l = 0; l < 4; l++)
                    sc = fmax(sc, fabs(B[l]));
            }
            F.scale = sc;
            F.w = PI / (2 * hmin);
            run_sets(&F);
            /* m = 1 and a two-point spline */
            double one = 0.5 * (x[0] + x[1]), y1, yr;
            CHECK(ts_spline_eval_batch(F.s, 0, &one, 1, &y1, NULL, NULL) == TS_OK);
            CHECK(ts_spline_eval(F.s, one, NULL, &yr) == TS_OK && fabs(y1 - yr) <= tol_for(&F, 0, one));
            ts_spline_free(F.s);
        }
    }
    /* a two-point spline: one interval, every query in it or outside */
    TH_CASE("two points");
    {
        double x2[2] = {1.0, 2.5}, f2[2] = {-1.0, 3.0};
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.extrapolate = TS_EXTRAP_EXTEND;
        fix F;
        memset(&F, 0, sizeof F);
        F.name = "two-point";
        F.ex = TS_EXTRAP_EXTEND;
        CHECK(ts_spline_new(x2, f2, 2, &o, &F.s, NULL) == TS_OK);
        if (F.s) {
            F.n = 1, F.x0 = 1.0, F.xn = 2.5, F.h0 = F.hn = 1.5, F.w = PI / 3.0;
            double B[4];
            CHECK(ts_spline_control(F.s, 0, B, NULL) == TS_OK);
            F.scale = fmax(1, fmax(fmax(fabs(B[0]), fabs(B[1])), fmax(fabs(B[2]), fabs(B[3]))));
            run_sets(&F);
            ts_spline_free(F.s);
        }
    }
    position_independence(x, f, NP);
    return th_report("test_batch");
}
