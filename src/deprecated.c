/* The 0.1 names, each forwarding to its ts_<object>_<verb> name (the
 * header's "Deprecated names"; docs/versions.md).  The only library file
 * that calls public entry points: it is a layer of its own above them. */
#include "internal.h"

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif

void ts_options_init(ts_spline_options *opt)
{
    ts_spline_options_init(opt);
}

ts_status ts_eval(const ts_spline *s, double x, ts_cursor *cur, double *y)
{
    return ts_spline_eval(s, x, cur, y);
}

ts_status ts_eval_deriv(const ts_spline *s, double x, ts_cursor *cur, double *y, double *dy,
                        double *d2y)
{
    return ts_spline_eval_deriv(s, x, cur, y, dy, d2y);
}

ts_status ts_eval_batch(const ts_spline *s, int deriv, const double *xq, size_t m, double *yq,
                        ts_cursor *cur, ts_error *err)
{
    return ts_spline_eval_batch(s, deriv, xq, m, yq, cur, err);
}

ts_status ts_eval_batch_mt(const ts_spline *s, int deriv, const double *xq, size_t m,
                           double *yq, unsigned nthreads, ts_error *err)
{
    return ts_spline_eval_batch_mt(s, deriv, xq, m, yq, nthreads, err);
}

ts_status ts_integral(const ts_spline *s, double a, double b, double *out)
{
    return ts_spline_integral(s, a, b, out);
}

ts_status ts_certify(const ts_spline *s, const ts_line *lower, const ts_line *upper,
                     ts_interval_report *reports, ts_error *err)
{
    return ts_spline_certify(s, lower, upper, reports, err);
}

ts_status ts_error_bound(const ts_spline *s, double fprime_max, double fsecond_max,
                         int exact_slopes, double *bound, double *per_interval)
{
    return ts_spline_error_bound(s, fprime_max, fsecond_max, exact_slopes, bound,
                                 per_interval);
}
