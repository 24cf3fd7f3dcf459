/* From the command-line options to the ts_spline_options of fit and certify and
 * the ts_curve_options of curve. */
#include "cli.h"

#include <string.h>

/* Lines of a shape from --line / --lower / --upper (fit and certify). */
static int resolve_lines(const cli_opts *o, ts_shape *sh, ts_line *lo, int *has_lo, ts_line *up,
                         int *has_up)
{
    cli_cmd cmd = o->cmd;
    *has_lo = *has_up = 0;
    switch (*sh) {
    case TS_SHAPE_NONE:
        if (o->has_line)
            return cli_usage(cmd, "--line needs --shape above or --shape below (or use --lower "
                                  "/ --upper)");
        *has_lo = o->has_lower;
        *has_up = o->has_upper;
        *lo = o->lower;
        *up = o->upper;
        *sh = *has_lo && *has_up ? TS_SHAPE_BETWEEN
              : *has_lo          ? TS_SHAPE_ABOVE
              : *has_up          ? TS_SHAPE_BELOW
                                 : TS_SHAPE_NONE;
        return CLI_OK;
    case TS_SHAPE_POSITIVE:
    case TS_SHAPE_MONOTONE:
        if (o->has_line || o->has_lower || o->has_upper)
            return cli_usage(cmd, "--shape %s takes no --line, --lower or --upper",
                             cli_shape_name(*sh));
        if (*sh == TS_SHAPE_POSITIVE) {
            lo->m = lo->c = 0.0;
            *has_lo = 1;
        }
        return CLI_OK;
    case TS_SHAPE_ABOVE:
        if (o->has_upper)
            return cli_usage(cmd, "--shape above takes a lower line only (--upper given; use "
                                  "--shape between)");
        if (o->has_line && o->has_lower)
            return cli_usage(cmd, "give the line once: --line or --lower");
        if (!o->has_line && !o->has_lower)
            return cli_usage(cmd, "--shape above needs --line M,C");
        *lo = o->has_line ? o->line : o->lower;
        *has_lo = 1;
        return CLI_OK;
    case TS_SHAPE_BELOW:
        if (o->has_lower)
            return cli_usage(cmd, "--shape below takes an upper line only (--lower given; use "
                                  "--shape between)");
        if (o->has_line && o->has_upper)
            return cli_usage(cmd, "give the line once: --line or --upper");
        if (!o->has_line && !o->has_upper)
            return cli_usage(cmd, "--shape below needs --line M,C");
        *up = o->has_line ? o->line : o->upper;
        *has_up = 1;
        return CLI_OK;
    case TS_SHAPE_BETWEEN:
        if (o->has_line)
            return cli_usage(cmd, "--shape between takes --lower and --upper, not --line");
        if (!o->has_lower || !o->has_upper)
            return cli_usage(cmd, "--shape between needs both --lower M,C and --upper M,C");
        *lo = o->lower;
        *up = o->upper;
        *has_lo = *has_up = 1;
        return CLI_OK;
    }
    return CLI_OK;
}

/* Options of both commands that only make sense with others. */
static int check_output_opts(const cli_opts *o)
{
    if (!o->svg && (o->title || o->show_control || o->points_only))
        return cli_usage(o->cmd, "%s only applies to the plot (--svg FILE)",
                         o->title ? "--title" : o->show_control ? "--show-control" : "--points-only");
    if (o->show_control && o->points_only)
        return cli_usage(o->cmd, "--show-control and --points-only do not fit together");
    if (o->extrap_set && !o->at && !o->grid_set)
        return cli_usage(o->cmd, "--extrapolate only applies with --at or --grid");
    /* parallel lines with the lower one on or above the upper one contradict
     * each other for any data: an option error (crossing lines depend on
     * where the data are: a data error naming the point) */
    if (o->has_lower && o->has_upper && o->lower.m == o->upper.m && !(o->lower.c < o->upper.c)) {
        char a[200], b[200];
        cli_line_text(&o->lower, a, sizeof a);
        cli_line_text(&o->upper, b, sizeof b);
        return cli_usage(o->cmd, "--lower %s is nowhere below --upper %s (parallel lines)", a, b);
    }
    return CLI_OK;
}

/* One value or one per interval, not both (fit, certify and curve). */
static int check_alpha_beta(const cli_opts *o)
{
    if (o->alpha_set && o->alphas)
        return cli_usage(o->cmd, "give --alpha or --alphas, not both");
    if (o->beta_set && o->betas)
        return cli_usage(o->cmd, "give --beta or --betas, not both");
    return CLI_OK;
}

int cli_fit_options(const cli_opts *o, ts_spline_options *opt)
{
    int rc;
    ts_spline_options_init(opt);
    if ((rc = check_output_opts(o)) != CLI_OK)
        return rc;
    opt->form = o->form;
    opt->slopes = o->slopes;
    opt->alpha = o->alpha;
    opt->alphas = o->alphas;
    opt->n_alphas = o->n_alphas;
    opt->extrapolate = o->extrap;
    if ((rc = check_alpha_beta(o)) != CLI_OK)
        return rc;

    ts_shape sh = o->shape;
    int hl, hu;
    if (o->cmd == CLI_CERTIFY) {
        if (sh == TS_SHAPE_MONOTONE)
            return cli_usage(o->cmd, "certify checks boundaries: --shape positive, above, below "
                                     "or between (or --lower / --upper)");
        if ((rc = resolve_lines(o, &sh, &opt->lower, &hl, &opt->upper, &hu)) != CLI_OK)
            return rc;
        if (!hl && !hu)
            return cli_usage(o->cmd, "certify needs a boundary: --shape positive, --lower M,C, "
                                     "--upper M,C, or --shape above|below --line M,C");
        if (!o->alpha_set && !o->alphas)
            return cli_usage(o->cmd, "certify needs your --alpha A (or --alphas)");
        if (!o->beta_set && !o->betas)
            return cli_usage(o->cmd, "certify needs your --beta B (or --betas)");
        /* the spline itself is built without a scheme */
        opt->shape = TS_SHAPE_NONE;
        opt->beta = o->beta;
        opt->betas = o->betas;
        opt->n_betas = o->n_betas;
        /* the boundaries themselves: cli_certify_bounds */
        opt->lower.m = opt->lower.c = opt->upper.m = opt->upper.c = 0.0;
        return CLI_OK;
    }
    if ((rc = resolve_lines(o, &sh, &opt->lower, &hl, &opt->upper, &hu)) != CLI_OK)
        return rc;
    if (sh != TS_SHAPE_NONE && (o->beta_set || o->betas))
        return cli_usage(o->cmd, "--beta/--betas only with --shape none: the %s scheme computes "
                                 "beta (use --alpha, --margin)",
                         cli_shape_name(sh));
    if (sh == TS_SHAPE_NONE && o->margin_set && !o->n_cons)
        return cli_usage(o->cmd, "--margin only applies to a shape scheme (--shape ...)");
    if (o->n_cons) {
        if (sh != TS_SHAPE_NONE)
            return cli_usage(o->cmd, "--constraint replaces --shape: give lower=, upper=, "
                                     "increasing, ... as constraints");
        if (o->form != TS_FORM_GEOMETRIC)
            return cli_usage(o->cmd, "--constraint needs the geometric form");
        opt->constraints = o->cons;
        opt->n_constraints = o->n_cons;
    }
    opt->shape = sh;
    opt->margin = o->margin;
    opt->beta = o->beta;
    opt->betas = o->betas;
    opt->n_betas = o->n_betas;
    if (o->at && strcmp(o->at, "-") == 0 && strcmp(o->data, "-") == 0)
        return cli_usage(o->cmd, "DATA and --at cannot both be standard input");
    return CLI_OK;
}

int cli_curve_options(const cli_opts *o, ts_curve_options *co)
{
    int rc;
    ts_curve_options_init(co);
    if (!o->svg && (o->title || o->show_control || o->points_only))
        return cli_usage(o->cmd, "%s only applies to the plot (--svg FILE)",
                         o->title ? "--title" : o->show_control ? "--show-control" : "--points-only");
    if (o->show_control && o->points_only)
        return cli_usage(o->cmd, "--show-control and --points-only do not fit together");
    if (o->logy)
        return cli_usage(o->cmd, "--logy is not available for curve (equal axes)");
    if ((rc = check_alpha_beta(o)) != CLI_OK)
        return rc;
    if (o->margin_set && !o->box_set)
        return cli_usage(o->cmd, "--margin only applies with --box");
    if (o->slopes == TS_SLOPES_PERIODIC && !o->closed)
        return cli_usage(o->cmd, "--slopes periodic needs --closed");
    co->param = o->param;
    co->closed = o->closed;
    co->slopes = o->slopes;
    co->alpha = o->alpha;
    co->alphas = o->alphas;
    co->n_alphas = o->n_alphas;
    co->beta = o->beta;
    co->betas = o->betas;
    co->n_betas = o->n_betas;
    co->margin = o->margin;
    for (size_t k = 0; o->box_set && k < o->n_box / 2; k++) {
        if (isfinite(o->box[2 * k])) {
            co->has_lo[k] = 1;
            co->lo[k] = o->box[2 * k];
        }
        if (isfinite(o->box[2 * k + 1])) {
            co->has_hi[k] = 1;
            co->hi[k] = o->box[2 * k + 1];
        }
    }
    return CLI_OK;
}

void cli_certify_bounds(const cli_opts *o, ts_shape *sh, ts_line *lo, int *hl, ts_line *up,
                        int *hu)
{
    *sh = o->shape;
    (void)resolve_lines(o, sh, lo, hl, up, hu);
}
