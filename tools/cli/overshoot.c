/* The curve's overshoot beyond its data (docs/method.md §5.9): summary,
 * warning line, JSON object. */
#include "cli.h"

#include <math.h>
#include <stdio.h>

void cli_overshoot_init(cli_overshoot *w)
{
    w->data_min = w->y_min = (double)INFINITY;
    w->data_max = w->y_max = -(double)INFINITY;
    w->above = w->below = 0.0;
    w->i_above = w->i_below = 0;
    w->count = 0;
    w->warn_only = 0;
}

/* warn_only: can interval i of s not be the one cli_overshoot_warn reports?
 * The curve lies within its control values' hull (docs/method.md §2, §4), so
 * each excursion is at most the hull's reach beyond the end values (plus the
 * exact extremum's rounding, far below the guard 1e-9 M).  The data range
 * only grows as intervals are added, and the warning needs an excursion
 * above CLI_OVERSHOOT_FRACTION of the final range: half of that fraction of
 * the range so far leaves it out. */
static int cannot_warn(const cli_overshoot *w, const ts_spline *s, size_t i)
{
    double B[4];
    if (ts_spline_control(s, i, B, NULL) != TS_OK)
        return 0;
    double lo = B[0], hi = B[0], m = fabs(B[0]);
    for (int l = 1; l < 4; l++) {
        lo = B[l] < lo ? B[l] : lo;
        hi = B[l] > hi ? B[l] : hi;
        m = fabs(B[l]) > m ? fabs(B[l]) : m;
    }
    double top = B[0] > B[3] ? B[0] : B[3], bottom = B[0] < B[3] ? B[0] : B[3];
    double reach = (hi - top > bottom - lo ? hi - top : bottom - lo) + 1e-9 * m;
    double dmin = w->data_min < bottom ? w->data_min : bottom,
           dmax = w->data_max > top ? w->data_max : top;
    return reach < 0.5 * CLI_OVERSHOOT_FRACTION * (dmax - dmin); /* NaN: 0, computed */
}

void cli_overshoot_add(cli_overshoot *w, const ts_spline *s, size_t i0, size_t i1, size_t offset)
{
    const double *f = ts_spline_f(s);
    for (size_t i = i0; i < i1; i++) {
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        if (w->warn_only && cannot_warn(w, s, i)) {
            for (int e = 0; e < 2; e++) {
                double v = f[i + (size_t)e];
                w->data_min = v < w->data_min ? v : w->data_min;
                w->data_max = v > w->data_max ? v : w->data_max;
            }
            w->count++;
            continue;
        }
        if (ts_spline_report(s, i, &r) != TS_OK)
            continue;
        for (int e = 0; e < 2; e++) {
            double v = f[i + (size_t)e];
            w->data_min = v < w->data_min ? v : w->data_min;
            w->data_max = v > w->data_max ? v : w->data_max;
        }
        w->y_min = r.y_min < w->y_min ? r.y_min : w->y_min;
        w->y_max = r.y_max > w->y_max ? r.y_max : w->y_max;
        if (r.excursion_above > w->above) {
            w->above = r.excursion_above;
            w->i_above = offset + i;
            w->r_above = r;
        }
        if (r.excursion_below > w->below) {
            w->below = r.excursion_below;
            w->i_below = offset + i;
            w->r_below = r;
        }
        w->count++;
    }
}

double cli_overshoot_ratio(const cli_overshoot *w)
{
    if (!w->count)
        return 0.0;
    double e = w->above > w->below ? w->above : w->below, range = w->data_max - w->data_min;
    if (e == 0.0)
        return 0.0;
    return range > 0.0 ? e / range : (double)INFINITY;
}

/* x inside [x0, x1] for a reader: a date to the second, a number to three
 * significant digits of its place in the interval (more when x is large
 * against the interval's width). */
static const char *x_near(const cli_cols *c, double x, double x0, double x1,
                          char buf[TSU_TIME_SIZE])
{
    if (c && c->x_time)
        return cli_x_text(c, nearbyint(x), buf);
    double big = fabs(x0) > fabs(x1) ? fabs(x0) : fabs(x1), w = x1 - x0;
    int sig = 3;
    if (w > 0.0 && big > w)
        sig += (int)ceil(log10(big / w));
    return cli_num_sig(x, sig, buf);
}

void cli_overshoot_warn(const cli_overshoot *w, const cli_cols *c)
{
    double ratio = cli_overshoot_ratio(w);
    if (!(ratio > CLI_OVERSHOOT_FRACTION))
        return;
    int up = w->above >= w->below;
    const ts_interval_report *r = up ? &w->r_above : &w->r_below;
    char b[7][TSU_TIME_SIZE];
    char pct[32];
    if (isfinite(ratio))
        snprintf(pct, sizeof pct, "%.3g%% of", 100.0 * ratio);
    else
        snprintf(pct, sizeof pct, "more than");
    cli_error("warning: the curve %s %s %s its data in interval %zu [%s, %s] (to %s at x = %s; "
              "%s the data range %s); a certificate covers the bounds, not overshoot: a larger "
              "--alpha reduces it",
              up ? "rises" : "dips", cli_num_sig(up ? w->above : w->below, 3, b[0]),
              up ? "above" : "below", up ? w->i_above : w->i_below, cli_x_text(c, r->x0, b[1]),
              cli_x_text(c, r->x1, b[2]), cli_num_sig(up ? r->y_max : r->y_min, 3, b[3]),
              x_near(c, up ? r->at_y_max : r->at_y_min, r->x0, r->x1, b[4]), pct,
              cli_num_sig(w->data_max - w->data_min, 3, b[5]));
}

void cli_overshoot_json(cli_json *j, const cli_overshoot *w)
{
    cli_json_key(j, "overshoot");
    cli_json_begin(j, '{');
    cli_json_knum(j, "data_min", w->data_min);
    cli_json_knum(j, "data_max", w->data_max);
    cli_json_knum(j, "y_min", w->y_min);
    cli_json_knum(j, "y_max", w->y_max);
    cli_json_knum(j, "max_excursion_above", w->above);
    cli_json_key(j, "interval_above");
    if (w->above > 0.0)
        cli_json_uint(j, w->i_above);
    else
        cli_json_null(j);
    cli_json_knum(j, "max_excursion_below", w->below);
    cli_json_key(j, "interval_below");
    if (w->below > 0.0)
        cli_json_uint(j, w->i_below);
    else
        cli_json_null(j);
    cli_json_knum(j, "warn_fraction", CLI_OVERSHOOT_FRACTION);
    cli_json_kbool(j, "warning", cli_overshoot_ratio(w) > CLI_OVERSHOOT_FRACTION);
    cli_json_end(j, '}');
}
