/* Flat runs are constant in floating point (docs/method.md §5.5): where
 * f_i = f_{i+1} and all four control values are equal, every evaluation
 * (ts_spline_eval, ts_spline_eval_batch at sorted and unsorted queries, every form)
 * returns f_i exactly, and its derivatives are exactly 0.  Before, Σ A_l f
 * wobbled by ±2 ulp and sampled monotone data with flat runs were not
 * monotone.  Also: the monotone scheme's samples of such data are monotone
 * in floating point (checked on this data; the expected values are the data
 * themselves). */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <stddef.h>

#define NP 12
#define M 400

int main(void)
{
    static const double x[NP] = {0, 1, 2.5, 3, 4.75, 6, 7, 8.5, 9, 10.25, 11, 13};
    static const double f[NP] = {0.1, 0.1, 0.3, 0.3, 0.3, 1.7, 2.9, 2.9, 3.3, 3.3, 3.3, 7.1};
    for (int form = TS_FORM_PAPER; form <= TS_FORM_GEOMETRIC; form++) {
        TH_CASE(form == 0 ? "paper" : form == 1 ? "c1" : "geometric");
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)form;
        o.shape = TS_SHAPE_MONOTONE;
        o.alpha = 0.3;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, NP, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        static double xs[M * (NP - 1)], ys[M * (NP - 1)], y0[M * (NP - 1)];
        size_t m = 0;
        for (size_t i = 0; i + 1 < NP; i++)
            for (int j = 0; j < M; j++)
                xs[m++] = x[i] + (x[i + 1] - x[i]) * j / M;
        CHECK(ts_spline_eval_batch(s, 0, xs, m, ys, NULL, NULL) == TS_OK);
        long wrong = 0, nonmono = 0;
        for (size_t q = 0; q < m; q++) {
            size_t i = q / M;
            double y, dy, d2y;
            CHECK(ts_spline_eval_deriv(s, xs[q], NULL, &y, &dy, &d2y) == TS_OK);
            y0[q] = y;
            if (f[i] == f[i + 1])
                wrong += !(y == f[i] && ys[q] == f[i] && dy == 0.0 && d2y == 0.0);
            if (q > 0)
                nonmono += (ys[q] < ys[q - 1]) + (y0[q] < y0[q - 1]);
        }
        CHECKF(wrong == 0, "form %d: %ld flat-run samples not exactly f", form, wrong);
        CHECKF(nonmono == 0, "form %d: %ld decreasing sample pairs", form, nonmono);
        /* unsorted batch: the same values */
        th_seed(11u + (unsigned)form);
        for (size_t q = m - 1; q > 0; q--) {
            size_t r = (size_t)th_range(0, (double)q + 1);
            r = r > q ? q : r;
            double t = xs[q];
            xs[q] = xs[r];
            xs[r] = t;
        }
        CHECK(ts_spline_eval_batch(s, 0, xs, m, ys, NULL, NULL) == TS_OK);
        long diff = 0;
        for (size_t q = 0; q < m; q++) {
            double y;
            (void)ts_spline_eval(s, xs[q], NULL, &y);
            size_t i = 0;
            while (i + 2 < NP && xs[q] >= x[i + 1])
                i++;
            if (f[i] == f[i + 1])
                diff += !(ys[q] == f[i] && y == f[i]);
        }
        CHECKF(diff == 0, "form %d: unsorted: %ld flat-run samples not exactly f", form, diff);
        ts_spline_free(s);
    }
    return th_report("test_flat");
}
