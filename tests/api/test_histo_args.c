/* The argument checks of the histogram rate's evaluation calls (statuses as
 * listed next to each in include/trigspline.h: NULL outputs, queries and
 * grid points outside [e_0, e_n] on either side or NaN, with the query
 * index), and ts_histo_subdivide with more cells per bin than its weight
 * table holds at once (sub = 40 > 32 cells: two tables per bin), checked
 * against its own promise: the cells of a bin add up to the bin's total
 * (docs/method.md §12.5; tolerance: 40 sums of rounded cells, 64 ε of the
 * total), each cell inside [lo, hi] times its width, and equal to
 * ts_histo_totals on the same grid up to 64 ε of the bin's total.  A check
 * that let a bad argument through would return TS_OK (or write through a
 * NULL pointer, which the ASan build reports). */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

enum { NB = 4, SUB = 40 };

int main(void)
{
    const double e[NB + 1] = {0.0, 1.0, 3.0, 4.0, 7.0};
    const double tot[NB] = {2.0, 1.0, 5.0, 0.5};
    ts_histo *h = NULL;
    ts_error err;
    TH_CASE("build");
    CHECK(ts_histo_new(e, tot, NB, NULL, &h, &err) == TS_OK && h);
    if (!h)
        return th_report("test_histo_args");

    TH_CASE("eval_batch arguments");
    double x[3] = {0.5, 2.0, 6.0}, r[3], dr[3];
    CHECK(ts_histo_eval_batch(h, x, 3, NULL, dr, &err) == TS_ERR_NULL);
    CHECK(ts_histo_eval_batch(h, NULL, 3, r, dr, &err) == TS_ERR_NULL);
    CHECK(ts_histo_eval_batch(NULL, x, 3, r, dr, &err) == TS_ERR_NULL);
    CHECK(ts_histo_eval_batch(h, x, 0, NULL, NULL, &err) == TS_OK);
    CHECK(ts_histo_eval_batch(h, x, 3, r, dr, &err) == TS_OK);
    x[1] = 7.5; /* above e_n */
    CHECK(ts_histo_eval_batch(h, x, 3, r, NULL, &err) == TS_ERR_DOMAIN && err.index == 1 &&
          err.where == TS_WHERE_QUERY && isnan(r[1]) && isnan(r[2]));
    x[1] = -0.5; /* below e_0 */
    CHECK(ts_histo_eval_batch(h, x, 3, r, NULL, &err) == TS_ERR_DOMAIN && err.index == 1);
    x[1] = (double)NAN;
    CHECK(ts_histo_eval_batch(h, x, 3, r, NULL, &err) == TS_ERR_DOMAIN && err.index == 1);

    TH_CASE("integral arguments");
    double v = 0.0;
    CHECK(ts_histo_integral(h, 0.0, 7.0, &v) == TS_OK);
    CHECK_CLOSE(v, 8.5, 16.0 * DBL_EPSILON * 8.5); /* the totals' sum */
    CHECK(ts_histo_integral(h, 0.0, 7.0, NULL) == TS_ERR_NULL);
    CHECK(ts_histo_integral(h, -1.0, 7.0, &v) == TS_ERR_DOMAIN && isnan(v));
    CHECK(ts_histo_integral(h, 8.0, 7.0, &v) == TS_ERR_DOMAIN);
    CHECK(ts_histo_integral(h, 0.0, -1.0, &v) == TS_ERR_DOMAIN);
    CHECK(ts_histo_integral(h, 0.0, 7.5, &v) == TS_ERR_DOMAIN);
    CHECK(ts_histo_integral(h, 0.0, (double)NAN, &v) == TS_ERR_DOMAIN);

    TH_CASE("totals arguments");
    double g[3] = {0.0, 2.0, 7.0}, out[2];
    CHECK(ts_histo_totals(h, g, 3, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_histo_totals(h, NULL, 3, out, &err) == TS_ERR_NULL);
    CHECK(ts_histo_totals(NULL, g, 3, out, &err) == TS_ERR_NULL);
    g[2] = 7.5; /* above e_n */
    CHECK(ts_histo_totals(h, g, 3, out, &err) == TS_ERR_DOMAIN && err.index == 2 &&
          err.where == TS_WHERE_QUERY);
    g[0] = -0.5; /* below e_0 */
    CHECK(ts_histo_totals(h, g, 3, out, &err) == TS_ERR_DOMAIN && err.index == 0);
    g[0] = 0.0;
    g[2] = 1.0; /* below its predecessor */
    CHECK(ts_histo_totals(h, g, 3, out, &err) == TS_ERR_UNSORTED && err.index == 2);

    TH_CASE("subdivide beyond one weight table");
    static double cells[NB * SUB];
    CHECK(ts_histo_subdivide(h, SUB, cells, &err) == TS_OK);
    for (int j = 0; j < NB; j++) {
        double sum = 0.0, w = (e[j + 1] - e[j]) / SUB;
        for (int k = 0; k < SUB; k++) {
            double c = cells[j * SUB + k];
            CHECK(c >= 0.0 && isfinite(c)); /* lo = 0, hi = +inf */
            sum += c;
            double gg[2] = {e[j] + k * w, k + 1 == SUB ? e[j + 1] : e[j] + (k + 1) * w}, t;
            CHECK(ts_histo_totals(h, gg, 2, &t, &err) == TS_OK);
            CHECK_CLOSE(c, t, 64.0 * DBL_EPSILON * tot[j]);
        }
        CHECK_CLOSE(sum, tot[j], 64.0 * DBL_EPSILON * tot[j]);
    }
    ts_histo_free(h);

    /* ts_histo_check's per-bin statuses (include/trigspline.h: an edge
     * failing names both of its bins, an edge the scheme cannot join marks
     * both; the return value is the first failure) */
    TH_CASE("per-bin statuses");
    {
        ts_status sb[5];
        double e5[6] = {(double)NAN, 1.0, 1.0, 3.0, 4.0, 5.0}, t5[5] = {1, 1, 1, 1, 1};
        /* edge 0 NaN (bin 0), edge 2 not increasing (bins 1, 2); edge 1
         * follows a non-finite edge and is not judged */
        CHECK(ts_histo_check(e5, t5, 5, NULL, sb, &err) == TS_ERR_NONFINITE && err.index == 0 &&
              err.where == TS_WHERE_POINT);
        CHECK(sb[0] == TS_ERR_NONFINITE && sb[1] == TS_ERR_UNSORTED && sb[2] == TS_ERR_UNSORTED &&
              sb[3] == TS_OK && sb[4] == TS_OK);
        double e6[6] = {0, 1, 2, 3, 4, 5}, t6[5] = {1, (double)INFINITY, -1.0, (double)NAN, 1};
        /* default bounds [0, inf): two non-finite totals and a negative one */
        CHECK(ts_histo_check(e6, t6, 5, NULL, sb, &err) == TS_ERR_NONFINITE && err.index == 1 &&
              err.where == TS_WHERE_INTERVAL);
        CHECK(sb[0] == TS_OK && sb[1] == TS_ERR_NONFINITE && sb[2] == TS_ERR_NEGATIVE &&
              sb[3] == TS_ERR_NONFINITE && sb[4] == TS_OK);
        /* bounds [0, 2]: means 3, 1, −1, 1.9, 0.01: bins 0 and 2 outside;
         * bins 3 and 4 cannot be joined (the edge value must be >= 2·1.9 − 2
         * = 1.8 and <= 2·0.01, docs/method.md §12.4); the pairs with an
         * outside bin are not judged, so bin 1 stays TS_OK */
        ts_histo_options hb;
        ts_histo_options_init(&hb);
        hb.hi = 2.0;
        double t7[5] = {3.0, 1.0, -1.0, 1.9, 0.01};
        CHECK(ts_histo_check(e6, t7, 5, &hb, sb, &err) == TS_ERR_INFEASIBLE && err.index == 0);
        CHECK(sb[0] == TS_ERR_INFEASIBLE && sb[1] == TS_OK && sb[2] == TS_ERR_INFEASIBLE &&
              sb[3] == TS_ERR_INFEASIBLE && sb[4] == TS_ERR_INFEASIBLE);
    }

    /* a mean one ulp above hi: within the rounding of total / width (4 ε,
     * docs/method.md §12.6), so it is taken as hi, built, and the rate and
     * the totals stay within [lo, hi] */
    TH_CASE("mean at hi within rounding");
    {
        ts_histo_options hb;
        ts_histo_options_init(&hb);
        hb.hi = 2.0;
        double e2[3] = {0.0, 1.0, 2.0}, t2[2] = {nextafter(2.0, 3.0), 1.0};
        ts_histo *h2 = NULL;
        CHECK(ts_histo_new(e2, t2, 2, &hb, &h2, &err) == TS_OK && h2);
        for (int k = 0; h2 && k <= 40; k++) {
            double rv = TH_NAN;
            CHECK(ts_histo_eval(h2, k / 20.0, &rv, NULL) == TS_OK && 0.0 <= rv && rv <= 2.0);
        }
        ts_histo_free(h2);
    }

#if defined(__SSE2__)
    /* rate bounds one ulp apart at DBL_MIN: hi − lo is subnormal, 0 when
     * the caller runs with flush-to-zero; the options check refuses the
     * empty range there (TS_ERR_OPTION) rather than divide by it, and
     * accepts it with the default rounding */
    TH_CASE("rate bounds flushed to zero");
    ts_histo_options ho;
    ts_histo_options_init(&ho);
    ho.lo = DBL_MIN;
    ho.hi = nextafter(DBL_MIN, 1.0);
    double tt[NB] = {DBL_MIN, DBL_MIN * 2.0, DBL_MIN * 1.0, DBL_MIN * 3.0};
    ts_status st1 = ts_histo_check(e, tt, NB, &ho, NULL, &err);
    unsigned csr = _mm_getcsr();
    _mm_setcsr(csr | 0x8000u); /* FTZ */
    volatile double tiny = DBL_MIN;
    double flushed = tiny * 0.5; /* 0 where FTZ is in effect (not under valgrind) */
    ts_status st2 = ts_histo_check(e, tt, NB, &ho, NULL, &err);
    _mm_setcsr(csr);
    CHECKF(st1 != TS_ERR_OPTION, "%s", ts_strerror(st1));
    if (flushed == 0.0)
        CHECKF(st2 == TS_ERR_OPTION, "%s", ts_strerror(st2));
    else
        printf("test_histo_args: flush-to-zero not in effect here; its case skipped\n");
#endif
    return th_report("test_histo_args");
}
