/* The distribution smoke test in C: README.md's example (the paper's Table 1,
 * a positive spline with alpha = 0.15) evaluated at x = 4.2 and certified,
 * and one refusal (a negative value under the positive scheme: TS_ERR_NEGATIVE
 * naming point 3).  Prints two "smoke:" lines; tools/dist/run.py compares
 * the value across channels.  Exit 0 when both behave as documented. */
#include <math.h>
#include <stdio.h>
#include <trigspline.h>

int main(void)
{
    double x[] = {0, 2, 3, 5, 15, 25, 27, 28, 30};
    double f[] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
    ts_spline_options opt;
    ts_spline_options_init(&opt);
    opt.shape = TS_SHAPE_POSITIVE;
    opt.alpha = 0.15;
    ts_spline *s = NULL;
    ts_error err;
    if (ts_spline_new(x, f, 9, &opt, &s, &err) != TS_OK) {
        printf("smoke: FAILED: %s\n", ts_strerror(err.status));
        return 1;
    }
    double y = NAN;
    ts_status st = ts_spline_eval(s, 4.2, NULL, &y);
    int certified = ts_spline_certified(s);
    ts_spline_free(s);
    printf("smoke: version %s\n", ts_version());
    printf("smoke: y(4.2) = %.17g certified %d\n", y, certified);
    f[3] = -1.0;
    ts_status bad = ts_spline_new(x, f, 9, &opt, &s, &err);
    printf("smoke: error %s index %zu\n", ts_status_name(bad), err.index);
    return !(st == TS_OK && y > 0 && isfinite(y) && certified == 1 && bad == TS_ERR_NEGATIVE &&
             err.index == 3 && s == NULL);
}
