/* trigspline certify: your alpha and beta, the exact distance to each boundary. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* CSV report of certify: one row per interval, x in the data's own form. */
static int certify_csv(tsu_plot_buf *b, const cli_data *d, const ts_interval_report *reps,
                       size_t n)
{
    char xn[700], h[4][800];
    const char *suffix[4] = {"_start", "_end", "_at_gap_lower", "_at_gap_upper"};
    int ok = 1;
    for (int k = 0; k < 4; k++) {
        char raw[600];
        snprintf(raw, sizeof raw, "%s%s", d->cols.xname, suffix[k]);
        cli_cols_csv_name(raw, h[k], sizeof h[k]);
    }
    (void)xn;
    ok &= tsu_plot_buf_printf(b, "interval,%s,%s,alpha,beta,gap_lower,%s,gap_upper,%s,certified\n",
                             h[0], h[1], h[2], h[3]) == TSU_PLOT_OK;
    for (size_t i = 0; i < n && ok; i++) {
        const ts_interval_report *r = &reps[i];
        char v[8][TSU_TIME_SIZE];
        ok &= tsu_plot_buf_printf(
                  b, "%zu,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", i, cli_x_text(&d->cols, r->x0, v[0]),
                  cli_x_text(&d->cols, r->x1, v[1]), cli_num(r->alpha, v[2]),
                  cli_num(r->beta, v[3]), r->has_lower ? cli_num(r->gap_lower, v[4]) : "",
                  r->has_lower ? cli_x_text(&d->cols, r->at_lower, v[5]) : "",
                  r->has_upper ? cli_num(r->gap_upper, v[6]) : "",
                  r->has_upper ? cli_x_text(&d->cols, r->at_upper, v[7]) : "",
                  r->certified ? "true" : "false") == TSU_PLOT_OK;
    }
    return ok ? CLI_OK : cli_nomem();
}

int cli_certify(cli_opts *o)
{
    ts_spline_options opt;
    int rc = cli_fit_options(o, &opt);
    if (rc != CLI_OK)
        return rc;
    ts_shape shape;
    ts_line lo, up;
    int hl, hu;
    cli_certify_bounds(o, &shape, &lo, &hl, &up, &hu);
    const ts_line *lower = hl ? &lo : NULL, *upper = hu ? &up : NULL;

    cli_data d;
    ts_spline *s = NULL;
    if ((rc = cli_read_and_fit(o, &opt, &d, &s)) != CLI_OK)
        return rc;
    size_t n = ts_spline_intervals(s);
    if ((o->svg || o->with_samples) &&
        (double)n * (double)(o->samples - 1) + 1.0 > CLI_MAX_HELD_SAMPLES) {
        cli_error("%s: %.0f sample points (--samples %zu over %zu intervals) exceed the limit of "
                  "%u that a plot or --with-samples holds in memory; lower --samples",
                  d.name, (double)n * (double)(o->samples - 1) + 1.0, o->samples, n,
                  CLI_MAX_HELD_SAMPLES);
        ts_spline_free(s);
        cli_data_free(&d);
        return CLI_USAGE;
    }
    ts_interval_report *reps = calloc(n, sizeof *reps);
    cli_json j;
    cli_json_init(&j);
    tsu_plot_buf svg = TSU_PLOT_BUF_INIT, text = TSU_PLOT_BUF_INIT;
    cli_xy bad = {0};
    cli_stats smp = CLI_STATS_INIT;
    int certified = 0;
    if (!reps) {
        rc = cli_nomem();
        goto done;
    }
    ts_error e;
    ts_status st = ts_spline_certify(s, lower, upper, reps, &e);
    if (st != TS_OK && st != TS_ERR_VIOLATED) {
        cli_error("certify: %s", ts_strerror(st));
        rc = st == TS_ERR_NONFINITE ? CLI_USAGE : CLI_DATA;
        goto done;
    }
    certified = st == TS_OK;
    for (size_t i = 0; i < n; i++) {
        const ts_interval_report *r = &reps[i];
        if (r->certified)
            continue;
        double at = r->has_lower && !(r->gap_lower > 0.0) ? r->at_lower : r->at_upper;
        double y;
        if (!isfinite(at) || ts_spline_eval(s, at, NULL, &y) != TS_OK)
            continue;
        cli_xy_push(&bad, at, y);
    }
    if (o->json) {
        cli_xy held = {0};
        cli_sample(s, 0, n, 1, o->samples, 0, cli_sink_stats, &smp);
        if (o->with_samples)
            cli_sample(s, 0, n, 1, o->samples, 0, cli_sink_xy, &held);
        cli_spline_json(&j, o, s, shape, lower, upper, certified, reps, &smp, &d,
                        o->with_samples ? &held : NULL);
        cli_xy_free(&held);
        if (j.failed) {
            rc = cli_nomem();
            goto done;
        }
    } else if ((rc = certify_csv(&text, &d, reps, n)) != CLI_OK) {
        goto done;
    }
    if (o->svg && (rc = cli_spline_plot(o, &d, s, shape, lower, upper, &bad, &svg)) != CLI_OK)
        goto done;
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, NULL, NULL, o->svg, o->plot_format, &svg);
    if (rc == CLI_OK) {
        cli_overshoot ov;
        cli_overshoot_init(&ov);
        cli_overshoot_add(&ov, s, 0, n, 0);
        cli_overshoot_warn(&ov, &d.cols);
    }
    if (rc == CLI_OK && !certified) {
        size_t cnt = 0;
        for (size_t i = 0; i < n; i++)
            cnt += !reps[i].certified;
        cli_error("certificate violated on %zu of %zu intervals:", cnt, n);
        for (size_t i = 0; i < n; i++) {
            const ts_interval_report *r = &reps[i];
            char b[6][TSU_TIME_SIZE];
            if (r->certified)
                continue;
            fprintf(stderr, "  interval %zu [%s, %s] (lines %llu-%llu):", i,
                    cli_x_text(&d.cols, r->x0, b[0]), cli_x_text(&d.cols, r->x1, b[1]),
                    d.line ? d.line[i] : 0ULL, d.line ? d.line[i + 1] : 0ULL);
            if (r->has_lower && !(r->gap_lower > 0.0))
                fprintf(stderr, " min gap above the lower boundary %s at x = %s;",
                        cli_num(r->gap_lower, b[2]), cli_x_text(&d.cols, r->at_lower, b[3]));
            if (r->has_upper && !(r->gap_upper > 0.0))
                fprintf(stderr, " min gap below the upper boundary %s at x = %s;",
                        cli_num(r->gap_upper, b[4]), cli_x_text(&d.cols, r->at_upper, b[5]));
            if ((!r->has_lower || r->gap_lower > 0.0) && (!r->has_upper || r->gap_upper > 0.0))
                fprintf(stderr, " gap within rounding of zero;");
            fputc('\n', stderr);
        }
        rc = CLI_VIOLATED;
    }
done:
    free(reps);
    cli_xy_free(&bad);
    cli_json_free(&j);
    tsu_plot_buf_free(&svg);
    tsu_plot_buf_free(&text);
    ts_spline_free(s);
    cli_data_free(&d);
    return rc;
}
