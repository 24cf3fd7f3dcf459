/* Sampling a spline into sinks: a CSV row writer, running min/max, point arrays. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define CLI_BLOCK 512

int cli_sample_after(const ts_spline *s, size_t i0, size_t i1, int with_end, size_t m, int deriv,
                     cli_sink sink, void *ctx, double *prev)
{
    double xs[CLI_BLOCK], ys[CLI_BLOCK];
    const double *X = ts_spline_x(s);
    size_t k = 0;
    ts_cursor cur = TS_CURSOR_INIT;
    ts_error e;
    int rc;
    double den = (double)(m - 1), last = *prev;
    for (size_t i = i0; i <= i1; i++) {
        size_t cnt = i < i1 ? m - 1 : (with_end ? 1 : 0);
        double x0 = X[i], h = i < i1 ? X[i + 1] - X[i] : 0.0;
        for (size_t j = 0; j < cnt; j++) {
            double x = x0;
            if (j > 0) {
                /* inside the interval; rounding may reach (not pass) x_{i+1} */
                x = x0 + h * ((double)j / den);
                if (x > X[i + 1])
                    x = X[i + 1];
            }
            /* strictly increasing: where x is so large that neighbouring
             * positions round to one double, the repeats are left out */
            if (!(x > last))
                continue;
            last = x;
            xs[k++] = x;
            if (k == CLI_BLOCK) {
                (void)ts_spline_eval_batch(s, deriv, xs, k, ys, &cur, &e);
                if ((rc = sink(ctx, xs, ys, k)) != 0)
                    return rc;
                k = 0;
            }
        }
    }
    *prev = last;
    if (k) {
        (void)ts_spline_eval_batch(s, deriv, xs, k, ys, &cur, &e);
        if ((rc = sink(ctx, xs, ys, k)) != 0)
            return rc;
    }
    return 0;
}

int cli_sample(const ts_spline *s, size_t i0, size_t i1, int with_end, size_t m, int deriv,
               cli_sink sink, void *ctx)
{
    double prev = -(double)INFINITY;
    return cli_sample_after(s, i0, i1, with_end, m, deriv, sink, ctx, &prev);
}

int cli_sample_even(const ts_spline *s, double a, double b, size_t n, int deriv, cli_sink sink,
                    void *ctx, ts_error *err, double *bad_x)
{
    double xs[CLI_BLOCK], ys[CLI_BLOCK], last = -(double)INFINITY;
    size_t k = 0;
    ts_cursor cur = TS_CURSOR_INIT;
    int rc;
    for (size_t i = 0; i < n; i++) {
        double x = i + 1 == n ? b : a + (b - a) * ((double)i / (double)(n - 1));
        if (!(x > last))
            continue;
        last = x;
        xs[k++] = x;
        if (k == CLI_BLOCK || i + 1 == n) {
            ts_status st = ts_spline_eval_batch(s, deriv, xs, k, ys, &cur, err);
            if (st != TS_OK) {
                *bad_x = xs[err->index < k ? err->index : 0];
                return -1;
            }
            if ((rc = sink(ctx, xs, ys, k)) != 0)
                return rc;
            k = 0;
        }
    }
    return 0;
}

double cli_step_x(const cli_step_grid *g, double j)
{
    return g->base + (g->den == 1.0 ? j * g->num : (j * g->num) / g->den);
}

/* The decimal step text as num * 10^e (num an integer below 2^53), e <= 0
 * when it has decimals; 0 when it has too many digits. */
static int step_decimal(const char *t, double *num, int *e)
{
    double m = 0;
    int digits = 0, frac = 0, exp = 0, seen_point = 0;
    const char *p = t;
    for (; (*p >= '0' && *p <= '9') || *p == '.'; p++) {
        if (*p == '.') {
            seen_point = 1;
            continue;
        }
        if (m == 0 && *p == '0') {
            frac += seen_point;
            continue;
        }
        if (++digits > 15)
            return 0;
        m = m * 10 + (*p - '0');
        frac += seen_point;
    }
    if (*p == 'e' || *p == 'E') {
        char *end;
        long v = strtol(p + 1, &end, 10);
        if (end == p + 1 || v < -30 || v > 30)
            return 0;
        exp = (int)v;
        p = end;
    }
    *num = m;
    *e = exp - frac;
    return 1;
}

int cli_step_grid_make(const char *text, double unit, double a, double b, int aligned,
                       double base, size_t max, cli_step_grid *g)
{
    double num, step;
    int e;
    g->base = aligned ? base : a;
    g->den = 1.0;
    if (step_decimal(text, &num, &e) && e >= -22) {
        double scale = 1.0;
        for (int k = 0; k < (e < 0 ? -e : e); k++)
            scale *= 10.0;
        num *= unit != 0.0 ? unit : 1.0;
        if (e >= 0)
            num *= scale;
        else
            g->den = scale;
    } else {
        (void)tsu_parse_double(text, NULL, &num, NULL);
        num *= unit != 0.0 ? unit : 1.0;
    }
    g->num = num;
    step = num / g->den;
    g->j0 = 0.0;
    if (aligned) {
        double j = ceil((a - g->base) / step);
        while (cli_step_x(g, j) < a)
            j++;
        while (cli_step_x(g, j - 1) >= a)
            j--;
        g->j0 = j;
    } else {
        /* A itself a multiple of the step: count from 0 (round decimals) */
        double j = nearbyint(a / step);
        if (fabs(j) < 9007199254740992.0 && cli_step_x(&(cli_step_grid){0, g->num, g->den, 0, 0},
                                                      j) == a) {
            g->base = 0.0;
            g->j0 = j;
        }
    }
    double last = floor((b - g->base) / step);
    while (cli_step_x(g, last) > b)
        last--;
    while (cli_step_x(g, last + 1) <= b)
        last++;
    if (last - g->j0 + 1 > (double)max) {
        g->n = max + 1;
        return -1;
    }
    g->n = last < g->j0 ? 0 : (size_t)(last - g->j0 + 1);
    return 0;
}

int cli_sample_step(const ts_spline *s, const cli_step_grid *g, int deriv, cli_sink sink,
                    void *ctx, ts_error *err, double *bad_x)
{
    double xs[CLI_BLOCK], ys[CLI_BLOCK], last = -(double)INFINITY;
    size_t k = 0;
    ts_cursor cur = TS_CURSOR_INIT;
    int rc;
    for (size_t i = 0; i < g->n; i++) {
        double x = cli_step_x(g, g->j0 + (double)i);
        if (x > last) {
            last = x;
            xs[k++] = x;
        }
        if (k && (k == CLI_BLOCK || i + 1 == g->n)) {
            ts_status st = ts_spline_eval_batch(s, deriv, xs, k, ys, &cur, err);
            if (st != TS_OK) {
                *bad_x = xs[err->index < k ? err->index : 0];
                return -1;
            }
            if ((rc = sink(ctx, xs, ys, k)) != 0)
                return rc;
            k = 0;
        }
    }
    return 0;
}

int cli_sink_stats(void *ctx, const double *x, const double *y, size_t k)
{
    cli_stats *st = ctx;
    (void)x;
    for (size_t j = 0; j < k; j++) {
        if (y[j] < st->lo)
            st->lo = y[j];
        if (y[j] > st->hi)
            st->hi = y[j];
    }
    st->count += k;
    return 0;
}

int cli_sink_xy(void *ctx, const double *x, const double *y, size_t k)
{
    cli_xy *a = ctx;
    for (size_t j = 0; j < k; j++)
        cli_xy_push(a, x[j], y[j]);
    return a->failed ? ENOMEM : 0;
}

int cli_sink_writer(void *ctx, const double *x, const double *y, size_t k)
{
    cli_csv_sink *c = ctx;
    int rc = 0;
    if (!c->cols || !c->cols->x_time) {
        for (size_t j = 0; j < k && !rc; j++)
            rc = tsu_writer_xy(c->w, x[j], y[j]);
        return rc;
    }
    for (size_t j = 0; j < k && !rc; j++) {
        char b[TSU_TIME_SIZE + 1];
        size_t n = tsu_format_time(x[j], &c->cols->tform, b);
        b[n++] = ',';
        rc = tsu_writer_text(c->w, b, n);
        if (!rc)
            rc = tsu_writer_row(c->w, &y[j], 1);
    }
    return rc;
}

void cli_xy_push(cli_xy *a, double x, double y)
{
    if (a->failed)
        return;
    if (a->n == a->cap) {
        size_t cap = a->cap ? a->cap * 2 : 256;
        if (cap < a->cap || cap > SIZE_MAX / sizeof(double)) {
            a->failed = 1;
            return;
        }
        double *nx = realloc(a->x, cap * sizeof *nx);
        if (!nx) {
            a->failed = 1;
            return;
        }
        a->x = nx;
        double *ny = realloc(a->y, cap * sizeof *ny);
        if (!ny) {
            a->failed = 1;
            return;
        }
        a->y = ny;
        a->cap = cap;
    }
    a->x[a->n] = x;
    a->y[a->n] = y;
    a->n++;
}

void cli_xy_free(cli_xy *a)
{
    free(a->x);
    free(a->y);
    memset(a, 0, sizeof *a);
}
