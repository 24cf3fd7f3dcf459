/* The JSON report of a spline (fit --json, certify --json). */
#include "cli.h"

#include <math.h>

void cli_spline_json(cli_json *j, const cli_opts *o, const ts_spline *s, ts_shape shape,
                     const ts_line *lower, const ts_line *upper, int certified,
                     const ts_interval_report *reps, const cli_stats *smp, const cli_data *data,
                     const cli_xy *held)
{
    size_t n = ts_spline_intervals(s);
    const double *x = ts_spline_x(s), *f = ts_spline_f(s), *d = ts_spline_slopes(s);
    ts_interval_report r = TS_INTERVAL_REPORT_INIT;
    double gl = (double)INFINITY, gu = (double)INFINITY;

    for (size_t i = 0; i < n; i++) {
        if (reps)
            r = reps[i];
        else
            (void)ts_spline_report(s, i, &r);
        if (lower && !(r.gap_lower >= gl))
            gl = r.gap_lower;
        if (upper && !(r.gap_upper >= gu))
            gu = r.gap_upper;
    }
    cli_json_begin(j, '{');
    cli_json_kstr(j, "schema", "trigspline-fit/1");
    cli_json_kstr(j, "command", cli_cmd_name(o->cmd));
    cli_json_kstr(j, "form", cli_form_name(ts_spline_form(s)));
    cli_json_kstr(j, "shape", cli_shape_name(shape));
    cli_json_kstr(j, "slopes", cli_slopes_name(o->slopes));
    cli_json_kuint(j, "n_points", n + 1);
    cli_json_kuint(j, "n_intervals", n);
    cli_json_kline(j, "lower", lower);
    cli_json_kline(j, "upper", upper);
    cli_json_kbool(j, "certified", certified);
    cli_json_key(j, "min_gap_lower");
    if (lower)
        cli_json_num(j, gl);
    else
        cli_json_null(j);
    cli_json_key(j, "min_gap_upper");
    if (upper)
        cli_json_num(j, gu);
    else
        cli_json_null(j);
    cli_json_nl(j);
    cli_json_key(j, "columns");
    cli_json_begin(j, '{');
    cli_json_kstr(j, "x", data->cols.xname);
    cli_json_kstr(j, "y", data->cols.yname);
    cli_json_kbool(j, "x_time", data->cols.x_time);
    cli_json_end(j, '}');
    cli_json_key(j, "rows");
    cli_json_begin(j, '{');
    cli_json_kuint(j, "used", data->n);
    cli_json_kuint(j, "skipped_missing", data->cols.skipped);
    cli_json_end(j, '}');
    cli_json_nl(j);

    cli_json_key(j, "knots");
    cli_json_begin(j, '[');
    for (size_t i = 0; i <= n; i++) {
        char b[TSU_TIME_SIZE];
        cli_json_nl(j);
        cli_json_begin(j, '{');
        if (data->cols.x_time) /* as samples.x: the input's ISO form */
            cli_json_kstr(j, "x", cli_x_text(&data->cols, x[i], b));
        else
            cli_json_knum(j, "x", x[i]);
        cli_json_knum(j, "f", f[i]);
        cli_json_knum(j, "d", d[i]);
        cli_json_end(j, '}');
    }
    cli_json_end(j, ']');
    cli_json_nl(j);

    if (ts_spline_constraints(s)) { /* docs/method.md §13: only with --constraint */
        cli_constraints_json(j, s);
        cli_json_nl(j);
    }

    cli_json_key(j, "intervals");
    cli_json_begin(j, '[');
    for (size_t i = 0; i < n; i++) {
        double B[4], X[4];
        if (reps)
            r = reps[i];
        else
            (void)ts_spline_report(s, i, &r);
        (void)ts_spline_control(s, i, B, X);
        cli_json_nl(j);
        cli_json_begin(j, '{');
        cli_json_kuint(j, "i", i);
        cli_json_knum(j, "x0", r.x0);
        cli_json_knum(j, "x1", r.x1);
        cli_json_knum(j, "alpha", r.alpha);
        cli_json_knum(j, "beta", r.beta);
        cli_json_knum(j, "a", r.a);
        cli_json_kstr(j, "term", cli_term_name(r.term));
        cli_json_key(j, "B");
        cli_json_begin(j, '[');
        for (int l = 0; l < 4; l++)
            cli_json_num(j, B[l]);
        cli_json_end(j, ']');
        cli_json_key(j, "X");
        cli_json_begin(j, '[');
        for (int l = 0; l < 4; l++)
            cli_json_num(j, X[l]);
        cli_json_end(j, ']');
        cli_json_key(j, "gap_lower");
        if (r.has_lower)
            cli_json_num(j, r.gap_lower);
        else
            cli_json_null(j);
        cli_json_key(j, "at_lower");
        if (r.has_lower)
            cli_json_num(j, r.at_lower);
        else
            cli_json_null(j);
        cli_json_key(j, "gap_upper");
        if (r.has_upper)
            cli_json_num(j, r.gap_upper);
        else
            cli_json_null(j);
        cli_json_key(j, "at_upper");
        if (r.has_upper)
            cli_json_num(j, r.at_upper);
        else
            cli_json_null(j);
        cli_json_kbool(j, "certified", r.certified);
        cli_json_knum(j, "y_min", r.y_min);
        cli_json_knum(j, "at_y_min", r.at_y_min);
        cli_json_knum(j, "y_max", r.y_max);
        cli_json_knum(j, "at_y_max", r.at_y_max);
        cli_json_knum(j, "excursion_above", r.excursion_above);
        cli_json_knum(j, "excursion_below", r.excursion_below);
        cli_json_end(j, '}');
    }
    cli_json_end(j, ']');
    cli_json_nl(j);

    cli_json_key(j, "samples");
    cli_json_begin(j, '{');
    cli_json_key(j, "min_y");
    if (smp->count)
        cli_json_num(j, smp->lo);
    else
        cli_json_null(j);
    cli_json_key(j, "max_y");
    if (smp->count)
        cli_json_num(j, smp->hi);
    else
        cli_json_null(j);
    cli_json_kuint(j, "count", smp->count);
    if (held) {
        char b[TSU_TIME_SIZE];
        cli_json_nl(j);
        cli_json_key(j, "x");
        cli_json_begin(j, '[');
        for (size_t i = 0; i < held->n; i++) {
            if (data->cols.x_time)
                cli_json_str(j, cli_x_text(&data->cols, held->x[i], b));
            else
                cli_json_num(j, held->x[i]);
        }
        cli_json_end(j, ']');
        cli_json_nl(j);
        cli_json_key(j, "y");
        cli_json_begin(j, '[');
        for (size_t i = 0; i < held->n; i++)
            cli_json_num(j, held->y[i]);
        cli_json_end(j, ']');
    }
    cli_json_end(j, '}');
    cli_json_nl(j);
    cli_overshoot ov;
    cli_overshoot_init(&ov);
    cli_overshoot_add(&ov, s, 0, n, 0);
    cli_overshoot_json(j, &ov);
    cli_json_end(j, '}');
    cli_json_raw(j, "\n");
}
