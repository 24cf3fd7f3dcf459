/* The external program of tests/package/run.sh: uses only the installed
 * header and library.  Spline through (0,0), (1,1) with user slopes 1, 1,
 * alpha = 1, beta = 0, paper form; prints the library version and
 * S(x), S'(x) at a few x for run.sh to compare with the closed form of
 * docs/method.md §2-§3 (computed there, not here). */
#include <stdio.h>
#include <string.h>
#include <trigspline.h>

int main(void)
{
    static const double x[2] = {0.0, 1.0}, f[2] = {0.0, 1.0}, d[2] = {1.0, 1.0};
    ts_spline_options opt;
    ts_spline_options_init(&opt);
    opt.form = TS_FORM_PAPER;
    opt.slopes = TS_SLOPES_USER;
    opt.user_slopes = d;
    opt.n_user_slopes = 2;
    opt.alpha = 1.0;
    opt.beta = 0.0;
    ts_spline *s = NULL;
    ts_error err;
    ts_status st = ts_spline_new(x, f, 2, &opt, &s, &err);
    if (st != TS_OK) {
        fprintf(stderr, "app: ts_spline_new: %s\n", ts_strerror(st));
        return 1;
    }
    char header_version[32];
    snprintf(header_version, sizeof header_version, "%d.%d.%d", TS_VERSION_MAJOR,
             TS_VERSION_MINOR, TS_VERSION_PATCH);
    printf("version %s %s\n", ts_version(), header_version);
    static const double q[3] = {0.5, 1.0 / 3.0, 0.25};
    for (int i = 0; i < 3; i++) {
        double y, dy;
        st = ts_spline_eval_deriv(s, q[i], NULL, &y, &dy, NULL);
        if (st != TS_OK) {
            fprintf(stderr, "app: ts_spline_eval_deriv: %s\n", ts_strerror(st));
            ts_spline_free(s);
            return 1;
        }
        printf("at %.17g %.17g %.17g\n", q[i], y, dy);
    }
    ts_spline_free(s);
    return 0;
}
