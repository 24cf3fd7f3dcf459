/* Prints a table of values of the paper's Table 1 spline (docs/method.md §10):
 * arithmetic-mean slopes, alpha = 1.4, beta = 1.9 (Figure 4b). */
#include <stdio.h>
#include <trigspline.h>

int main(void)
{
    static const double x[] = {0, 2, 3, 5, 15, 25, 27, 28, 30};
    static const double f[] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
    ts_spline_options opt;
    ts_spline_options_init(&opt);
    opt.alpha = 1.4;
    opt.beta = 1.9;
    ts_spline *s = NULL;
    ts_error err;
    ts_status st = ts_spline_new(x, f, sizeof x / sizeof x[0], &opt, &s, &err);
    if (st != TS_OK) {
        fprintf(stderr, "table1: %s\n", ts_strerror(st));
        return 1;
    }
    printf("%-22s %-22s %-22s\n", "x", "S(x)", "S'(x)");
    ts_cursor cur = TS_CURSOR_INIT;
    for (int k = 0; k <= 60; k++) {
        double xx = 0.5 * k, y, dy;
        ts_spline_eval_deriv(s, xx, &cur, &y, &dy, NULL);
        printf("%-22.17g %-22.17g %-22.17g\n", xx, y, dy);
    }
    ts_spline_free(s);
    return 0;
}
