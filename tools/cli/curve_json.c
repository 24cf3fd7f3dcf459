/* The JSON report of curve --json: knots, segments (alpha, beta, control
 * points, box certificate) and the range of the samples. */
#include "cli.h"

#include <math.h>
#include <stdio.h>

void cli_curve_json(cli_json *j, const cli_opts *o, const cli_curve_run *cr)
{
    double len = (double)NAN;
    double mn[3] = {(double)INFINITY, (double)INFINITY, (double)INFINITY};
    double mx[3] = {-(double)INFINITY, -(double)INFINITY, -(double)INFINITY};
    const char *axn[3] = {"x", "y", "z"};
    char key[16];
    (void)ts_curve_length(cr->c, 0.0, &len);
    for (size_t r = 0; r < cr->rows; r++)
        for (size_t k = 0; k < cr->dim; k++) {
            double v = cr->smp[r * (1 + cr->dim) + 1 + k];
            if (v < mn[k])
                mn[k] = v;
            if (v > mx[k])
                mx[k] = v;
        }
    cli_json_begin(j, '{');
    cli_json_kstr(j, "command", "curve");
    cli_json_kbool(j, "closed", ts_curve_closed(cr->c));
    cli_json_kstr(j, "param", cli_param_name(o->param));
    cli_json_kstr(j, "slopes", cli_slopes_name(o->slopes));
    cli_json_kuint(j, "dim", cr->dim);
    cli_json_kuint(j, "n_points", cr->n);
    cli_json_kuint(j, "n_segments", cr->seg);
    cli_json_key(j, "box");
    if (cr->reps) {
        cli_json_begin(j, '{');
        for (size_t k = 0; k < cr->dim; k++) {
            snprintf(key, sizeof key, "%smin", axn[k]);
            cli_json_key(j, key);
            if (cr->co->has_lo[k])
                cli_json_num(j, cr->co->lo[k]);
            else
                cli_json_null(j);
            snprintf(key, sizeof key, "%smax", axn[k]);
            cli_json_key(j, key);
            if (cr->co->has_hi[k])
                cli_json_num(j, cr->co->hi[k]);
            else
                cli_json_null(j);
        }
        cli_json_end(j, '}');
    } else {
        cli_json_null(j);
    }
    cli_json_kbool(j, "certified", cr->certified);
    cli_json_key(j, "min_gap");
    if (cr->reps)
        cli_json_num(j, cr->min_gap);
    else
        cli_json_null(j);
    cli_json_knum(j, "length", len);
    cli_json_nl(j);
    cli_json_key(j, "knots");
    cli_json_begin(j, '[');
    const double *t = ts_curve_knots(cr->c);
    for (size_t i = 0; i <= cr->seg; i++)
        cli_json_num(j, t[i]);
    cli_json_end(j, ']');
    cli_json_nl(j);
    cli_json_key(j, "segments");
    cli_json_begin(j, '[');
    for (size_t i = 0; i < cr->seg; i++) {
        double al, be, P[12];
        (void)ts_curve_params(cr->c, i, &al, &be);
        (void)ts_curve_control(cr->c, i, P);
        cli_json_nl(j);
        cli_json_begin(j, '{');
        cli_json_kuint(j, "i", i);
        cli_json_knum(j, "t0", t[i]);
        cli_json_knum(j, "t1", t[i + 1]);
        cli_json_knum(j, "alpha", al);
        cli_json_knum(j, "beta", be);
        cli_json_knum(j, "a", al + be);
        cli_json_key(j, "P");
        cli_json_begin(j, '[');
        for (int l = 0; l < 4; l++) {
            cli_json_begin(j, '[');
            for (size_t k = 0; k < cr->dim; k++)
                cli_json_num(j, P[(size_t)l * cr->dim + k]);
            cli_json_end(j, ']');
        }
        cli_json_end(j, ']');
        cli_json_key(j, "min_gap");
        if (cr->reps) {
            double g = (double)INFINITY;
            int ok = 1;
            for (size_t k = 0; k < cr->dim; k++) {
                const ts_interval_report *r = &cr->reps[i * cr->dim + k];
                if (r->has_lower && !(r->gap_lower >= g))
                    g = r->gap_lower;
                if (r->has_upper && !(r->gap_upper >= g))
                    g = r->gap_upper;
                ok &= r->certified || (!r->has_lower && !r->has_upper);
            }
            cli_json_num(j, g);
            cli_json_kbool(j, "certified", ok);
        } else {
            cli_json_null(j);
            cli_json_key(j, "certified");
            cli_json_null(j);
        }
        cli_json_end(j, '}');
    }
    cli_json_end(j, ']');
    cli_json_nl(j);
    cli_json_key(j, "samples");
    cli_json_begin(j, '{');
    cli_json_kuint(j, "count", cr->rows);
    for (size_t k = 0; k < cr->dim; k++) {
        snprintf(key, sizeof key, "min_%s", axn[k]);
        cli_json_knum(j, key, mn[k]);
        snprintf(key, sizeof key, "max_%s", axn[k]);
        cli_json_knum(j, key, mx[k]);
    }
    cli_json_end(j, '}');
    cli_json_end(j, '}');
    cli_json_raw(j, "\n");
}
