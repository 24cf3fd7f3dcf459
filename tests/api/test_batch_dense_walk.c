/* The batch kernels' dense walk (src/kernels.c: sorted blocks averaging at
 * least TS_FAST_RUN = 8 queries per interval) stepping from one interval to
 * the next without a gallop: 10 sorted queries in each of 13 intervals, so
 * that every step of the walk lands in the adjacent interval, for the three
 * forms and derivatives 0..2.  Each value must match ts_spline_eval_deriv
 * at the same x within the kernels' bounds of tests/unit/test_fast.c:
 * 1600 ε M w^k (paper, C¹) and 170000 ε (M/h^k + |S^(k)|) (geometric), with
 * M = max |f| = 2 and h = w = 1 here; taken as 2e5 ε (M + |S^(k)|) for
 * every form.  A kernel that mislocated a query by one interval would be
 * off by the data's O(1) differences. */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

enum { NP = 40, PER = 10, NI = 13, M = PER * NI };

int main(void)
{
    double x[NP], f[NP], q[M], y[M];
    for (int k = 0; k < NP; k++) {
        x[k] = k;
        f[k] = 1.0 + sin(0.7 * k); /* in [0, 2] */
    }
    for (int i = 0; i < NI; i++)
        for (int j = 0; j < PER; j++)
            q[i * PER + j] = 3.0 + i + (j + 0.5) / PER;
    for (int form = 0; form < 3; form++) {
        TH_CASE(form == 0 ? "paper" : form == 1 ? "C1" : "geometric");
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)form;
        ts_spline *s = NULL;
        ts_error e;
        CHECK(ts_spline_new(x, f, NP, &o, &s, &e) == TS_OK);
        if (!s)
            continue;
        for (int d = 0; d <= 2; d++) {
            CHECK(ts_spline_eval_batch(s, d, q, M, y, NULL, &e) == TS_OK);
            for (int k = 0; k < M; k++) {
                double v[3];
                CHECK(ts_spline_eval_deriv(s, q[k], NULL, &v[0], &v[1], &v[2]) == TS_OK);
                double tol = 2e5 * DBL_EPSILON * (2.0 + fabs(v[d]));
                CHECKF(fabs(y[k] - v[d]) <= tol, "deriv %d at %g: %.17g vs %.17g", d, q[k], y[k],
                       v[d]);
            }
        }
        ts_spline_free(s);
    }
    return th_report("test_batch_dense_walk");
}
