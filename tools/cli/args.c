/* Command-line parsing: argv after the command into cli_opts
 * (docs/cli.md); the help texts are in help.c. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { F = 1u, C = 2u, V = 4u };

typedef enum opt_id {
    O_SHAPE, O_LINE, O_LOWER, O_UPPER, O_ALPHA, O_BETA, O_ALPHAS, O_BETAS, O_MARGIN,
    O_SLOPES, O_C1, O_FORM, O_SAMPLES, O_AT, O_DERIV, O_EXTRAP, O_OUT, O_JSON, O_SVG,
    O_TITLE, O_SHOWCTL, O_POINTSONLY, O_COLUMNS, O_NOSTREAM, O_CLOSED, O_PARAM, O_BOX,
    O_HELP, O_PNG, O_PDF, O_FORMAT, O_DELIM, O_DECCOMMA, O_NA, O_MISSING, O_SKIP, O_X, O_Y,
    O_XTIME, O_GRID, O_SAMPLES_TOTAL, O_WITH_SAMPLES, O_XLABEL, O_YLABEL, O_LOGY, O_SIZE,
    O_VERBOSE
} opt_id;

typedef struct optdef {
    const char *name;
    int has_arg;
    unsigned cmds;
    opt_id id;
} optdef;

static const optdef opts[] = {
    {"--shape", 1, F | C, O_SHAPE},
    {"--line", 1, F | C, O_LINE},
    {"--lower", 1, F | C, O_LOWER},
    {"--upper", 1, F | C, O_UPPER},
    {"--alpha", 1, F | C | V, O_ALPHA},
    {"--beta", 1, F | C | V, O_BETA},
    {"--alphas", 1, F | C | V, O_ALPHAS},
    {"--betas", 1, F | C | V, O_BETAS},
    {"--margin", 1, F | V, O_MARGIN},
    {"--slopes", 1, F | C | V, O_SLOPES},
    {"--c1", 0, F | C, O_C1},
    {"--form", 1, F | C, O_FORM},
    {"--samples", 1, F | C | V, O_SAMPLES},
    {"--at", 1, F, O_AT},
    {"--derivative", 1, F, O_DERIV},
    {"--extrapolate", 1, F, O_EXTRAP},
    {"-o", 1, F | C | V, O_OUT},
    {"--output", 1, F | C | V, O_OUT},
    {"--json", 0, F | C | V, O_JSON},
    {"--svg", 1, F | C | V, O_SVG},
    {"--title", 1, F | C | V, O_TITLE},
    {"--show-control", 0, F | C | V, O_SHOWCTL},
    {"--points-only", 0, F | C | V, O_POINTSONLY},
    {"--columns", 1, F | C, O_COLUMNS},
    {"--no-stream", 0, F, O_NOSTREAM},
    {"--closed", 0, V, O_CLOSED},
    {"--param", 1, V, O_PARAM},
    {"--box", 1, V, O_BOX},
    {"--png", 1, F | C | V, O_PNG},
    {"--pdf", 1, F | C | V, O_PDF},
    {"--format", 1, F | C | V, O_FORMAT},
    {"--delimiter", 1, F | C | V, O_DELIM},
    {"--decimal-comma", 0, F | C | V, O_DECCOMMA},
    {"--na", 1, F | C | V, O_NA},
    {"--missing", 1, F | C | V, O_MISSING},
    {"--skip", 1, F | C | V, O_SKIP},
    {"--x", 1, F | C, O_X},
    {"--y", 1, F | C, O_Y},
    {"--x-time", 0, F | C, O_XTIME},
    {"--grid", 1, F, O_GRID},
    {"--samples-total", 1, F | C | V, O_SAMPLES_TOTAL},
    {"--with-samples", 0, F | C, O_WITH_SAMPLES},
    {"--xlabel", 1, F | C | V, O_XLABEL},
    {"--ylabel", 1, F | C | V, O_YLABEL},
    {"--logy", 0, F | C | V, O_LOGY},
    {"--size", 1, F | C | V, O_SIZE},
    {"-v", 0, F | C | V, O_VERBOSE},
    {"--verbose", 0, F | C | V, O_VERBOSE},
    {"--help", 0, F | C | V, O_HELP},
    {"-h", 0, F | C | V, O_HELP},
};

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

/* ---- values ----------------------------------------------------------- */

/* A whole-string number; allow_inf: ±inf accepted. 0 on failure. */
static int parse_number(const char *s, size_t len, int allow_inf, double *v)
{
    const char *stop;
    if (len == 0)
        return 0;
    tsu_num_status st = tsu_parse_double(s, s + len, v, &stop);
    if (stop != s + len)
        return 0;
    if (st == TSU_NUM_OK)
        return 1;
    if (st == TSU_NUM_NONFINITE && allow_inf && isinf(*v))
        return 1;
    return 0;
}

/* Comma-separated numbers into a new array (at least one). 0 on failure
 * (*bad = the offending field, or NULL for out of memory). */
static int parse_list(const char *s, int allow_inf, double **out, size_t *n, char *bad,
                      size_t badlen)
{
    size_t cnt = 1;
    for (const char *p = s; *p; p++)
        cnt += *p == ',';
    double *a = malloc(cnt * sizeof *a);
    if (!a) {
        snprintf(bad, badlen, "(out of memory)");
        return 0;
    }
    const char *p = s;
    for (size_t i = 0; i < cnt; i++) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        while (len && (*p == ' ' || *p == '\t'))
            p++, len--;
        while (len && (p[len - 1] == ' ' || p[len - 1] == '\t'))
            len--;
        if (!parse_number(p, len, allow_inf, &a[i])) {
            snprintf(bad, badlen, "\"%.*s\"", (int)(len > 40 ? 40 : len), p);
            free(a);
            return 0;
        }
        p = e ? e + 1 : p + len;
    }
    *out = a;
    *n = cnt;
    return 1;
}

/* A number, or an ISO 8601 date / date-time (seconds since the epoch). */
static int parse_x_value(const char *s, size_t len, double *v)
{
    const char *stop;
    if (parse_number(s, len, 0, v))
        return 1;
    return len && tsu_parse_time(s, s + len, v, NULL, &stop) && stop == s + len;
}

/* --at X1,X2,...: a list of values (numbers or dates), in order. 0: not a list. */
static int parse_at_list(const char *s, double **out, size_t *n)
{
    size_t cnt = 1;
    for (const char *p = s; *p; p++)
        cnt += *p == ',';
    double *a = malloc(cnt * sizeof *a);
    if (!a)
        return 0;
    const char *p = s;
    for (size_t i = 0; i < cnt; i++) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        while (len && (*p == ' ' || *p == '\t'))
            p++, len--;
        while (len && (p[len - 1] == ' ' || p[len - 1] == '\t'))
            len--;
        if (!parse_x_value(p, len, &a[i])) {
            free(a);
            return 0;
        }
        p = e ? e + 1 : p + len;
    }
    *out = a;
    *n = cnt;
    return 1;
}

/* --x / --y / --columns entry: a copy of [s, s + len) trimmed, or NULL. */
static char *col_spec(const char *s, size_t len)
{
    while (len && (*s == ' ' || *s == '\t'))
        s++, len--;
    while (len && (s[len - 1] == ' ' || s[len - 1] == '\t'))
        len--;
    if (!len)
        return NULL;
    char *d = malloc(len + 1);
    if (d) {
        memcpy(d, s, len);
        d[len] = 0;
    }
    return d;
}

static int set_plot(cli_cmd cmd, const char *name, const char *v, cli_plot_format f, cli_opts *o)
{
    if (!*v || strcmp(v, "-") == 0)
        return cli_usage(cmd, "%s needs a file name", name);
    if (o->svg)
        return cli_usage(cmd, "one plot per run: %s \"%s\" and \"%s\"", name, o->svg, v);
    o->svg = v;
    o->plot_format = f;
    return CLI_OK;
}

static int parse_size(const char *s, size_t *v)
{
    if (!*s)
        return 0;
    unsigned long long acc = 0;
    for (const char *p = s; *p; p++) {
        if (*p < '0' || *p > '9')
            return 0;
        if (acc > (unsigned long long)SIZE_MAX / 10)
            return 0;
        acc = acc * 10 + (unsigned long long)(*p - '0');
        if (acc > (unsigned long long)SIZE_MAX)
            return 0;
    }
    *v = (size_t)acc;
    return 1;
}

static int parse_line_opt(cli_cmd cmd, const char *name, const char *s, ts_line *l)
{
    double *a = NULL;
    size_t n = 0;
    char bad[64];
    if (!parse_list(s, 0, &a, &n, bad, sizeof bad))
        return cli_usage(cmd, "%s expects M,C (slope and intercept of y = M*x + C), found %s in \"%s\"",
                         name, bad, s);
    if (n != 2) {
        free(a);
        return cli_usage(cmd, "%s expects two numbers M,C, found %zu in \"%s\"", name, n, s);
    }
    l->m = a[0];
    l->c = a[1];
    free(a);
    return CLI_OK;
}

static int parse_positive_list(cli_cmd cmd, const char *name, const char *s, int allow_zero,
                               double **out, size_t *n)
{
    char bad[64];
    free(*out);
    *out = NULL;
    if (!parse_list(s, 0, out, n, bad, sizeof bad))
        return cli_usage(cmd, "%s expects comma-separated numbers, found %s", name, bad);
    for (size_t i = 0; i < *n; i++) {
        double v = (*out)[i];
        if (!(allow_zero ? v >= 0.0 : v > 0.0)) {
            char b[TSU_FMT_SIZE];
            return cli_usage(cmd, "%s: value %zu is %s, must be %s", name, i + 1, cli_num(v, b),
                             allow_zero ? ">= 0" : "> 0");
        }
    }
    return CLI_OK;
}

static int parse_scalar(cli_cmd cmd, const char *name, const char *s, int allow_zero, double *v)
{
    if (!parse_number(s, strlen(s), 0, v))
        return cli_usage(cmd, "%s expects a finite number, found \"%s\"", name, s);
    if (!(allow_zero ? *v >= 0.0 : *v > 0.0))
        return cli_usage(cmd, "%s must be %s, found %s", name, allow_zero ? ">= 0" : "> 0", s);
    return CLI_OK;
}

static int parse_enum(cli_cmd cmd, const char *name, const char *s, const cli_names *t,
                      size_t skip_mask, int *v)
{
    int k = cli_name_index(t, s);
    if (k >= 0 && !((skip_mask >> k) & 1u)) {
        *v = k;
        return CLI_OK;
    }
    char list[256] = "";
    size_t len = 0;
    for (size_t i = 0; i < t->n; i++) {
        if ((skip_mask >> i) & 1u)
            continue;
        int w = snprintf(list + len, sizeof list - len, "%s%s", len ? "|" : "", t->name[i]);
        if (w < 0 || (size_t)w >= sizeof list - len)
            break;
        len += (size_t)w;
    }
    return cli_usage(cmd, "%s: unknown value \"%s\" (expected %s)", name, s, list);
}

/* ---- parse ------------------------------------------------------------ */

void cli_opts_free(cli_opts *o)
{
    if (!o)
        return;
    free(o->alphas);
    free(o->betas);
    free(o->at_list);
    free(o->xcol);
    free(o->ycol);
    o->alphas = o->betas = NULL;
    o->at_list = NULL;
    o->xcol = o->ycol = NULL;
}

static int apply(cli_cmd cmd, const optdef *d, const char *name, const char *v, cli_opts *o)
{
    int k = 0, rc;
    switch (d->id) {
    case O_SHAPE:
        rc = parse_enum(cmd, name, v, &cli_shape_names, 0, &k);
        if (rc == CLI_OK) {
            o->shape = (ts_shape)k;
            o->shape_set = 1;
        }
        return rc;
    case O_LINE:
        o->has_line = 1;
        return parse_line_opt(cmd, name, v, &o->line);
    case O_LOWER:
        o->has_lower = 1;
        return parse_line_opt(cmd, name, v, &o->lower);
    case O_UPPER:
        o->has_upper = 1;
        return parse_line_opt(cmd, name, v, &o->upper);
    case O_ALPHA:
        o->alpha_set = 1;
        return parse_scalar(cmd, name, v, 0, &o->alpha);
    case O_BETA:
        o->beta_set = 1;
        return parse_scalar(cmd, name, v, 1, &o->beta);
    case O_ALPHAS:
        return parse_positive_list(cmd, name, v, 0, &o->alphas, &o->n_alphas);
    case O_BETAS:
        return parse_positive_list(cmd, name, v, 1, &o->betas, &o->n_betas);
    case O_MARGIN:
        o->margin_set = 1;
        return parse_scalar(cmd, name, v, 0, &o->margin);
    case O_SLOPES:
        /* "user" is not offered on the command line */
        rc = parse_enum(cmd, name, v, &cli_slopes_names, 1u << TS_SLOPES_USER, &k);
        if (rc == CLI_OK) {
            o->slopes = (ts_slopes)k;
            o->slopes_set = 1;
        }
        return rc;
    case O_C1:
        o->c1 = 1;
        return CLI_OK;
    case O_FORM:
        rc = parse_enum(cmd, name, v, &cli_form_names, 0, &k);
        if (rc == CLI_OK) {
            o->form = (ts_form)k;
            o->form_set = 1;
        }
        return rc;
    case O_SAMPLES:
        if (!parse_size(v, &o->samples) || o->samples < 2 || o->samples > 100000000)
            return cli_usage(cmd, "%s expects an integer from 2 to 100000000, found \"%s\"",
                             name, v);
        o->samples_set = 1;
        return CLI_OK;
    case O_AT:
        o->at = v;
        free(o->at_list);
        o->at_list = NULL;
        o->n_at = 0;
        if (strchr(v, ',') || parse_x_value(v, strlen(v), &(double){0}))
            (void)parse_at_list(v, &o->at_list, &o->n_at);
        return CLI_OK;
    case O_DERIV:
        if (strcmp(v, "0") && strcmp(v, "1") && strcmp(v, "2"))
            return cli_usage(cmd, "%s expects 0, 1 or 2, found \"%s\"", name, v);
        o->deriv = v[0] - '0';
        o->deriv_set = 1;
        return CLI_OK;
    case O_EXTRAP:
        rc = parse_enum(cmd, name, v, &cli_extrap_names, 0, &k);
        if (rc == CLI_OK) {
            o->extrap = (ts_extrap)k;
            o->extrap_set = 1;
        }
        return rc;
    case O_OUT:
        if (!*v)
            return cli_usage(cmd, "%s: empty file name", name);
        o->out = v;
        return CLI_OK;
    case O_JSON:
        o->json = 1;
        return CLI_OK;
    case O_SVG:
        return set_plot(cmd, name, v, CLI_PLOT_SVG, o);
    case O_TITLE:
        o->title = v;
        return CLI_OK;
    case O_SHOWCTL:
        o->show_control = 1;
        return CLI_OK;
    case O_POINTSONLY:
        o->points_only = 1;
        return CLI_OK;
    case O_COLUMNS: {
        const char *comma = strchr(v, ',');
        if (!comma || strchr(comma + 1, ','))
            return cli_usage(cmd, "%s expects X,Y (1-based column numbers or header names), "
                                  "found \"%s\"", name, v);
        free(o->xcol);
        free(o->ycol);
        o->xcol = col_spec(v, (size_t)(comma - v));
        o->ycol = col_spec(comma + 1, strlen(comma + 1));
        if (!o->xcol || !o->ycol)
            return cli_usage(cmd, "%s expects X,Y (1-based column numbers or header names), "
                                  "found \"%s\"", name, v);
        o->columns_set = 1;
        return CLI_OK;
    }
    case O_X:
    case O_Y: {
        char **dst = d->id == O_X ? &o->xcol : &o->ycol;
        free(*dst);
        *dst = col_spec(v, strlen(v));
        if (!*dst)
            return cli_usage(cmd, "%s expects a column number or header name", name);
        o->columns_set = 1;
        return CLI_OK;
    }
    case O_PNG:
        return set_plot(cmd, name, v, CLI_PLOT_PNG, o);
    case O_PDF:
        return set_plot(cmd, name, v, CLI_PLOT_PDF, o);
    case O_FORMAT:
        if (strcmp(v, "svg") && strcmp(v, "png") && strcmp(v, "pdf"))
            return cli_usage(cmd, "%s expects svg, png or pdf, found \"%s\"", name, v);
        o->plot_format = v[1] == 'v' ? CLI_PLOT_SVG : v[1] == 'n' ? CLI_PLOT_PNG : CLI_PLOT_PDF;
        o->format_set = 1;
        return CLI_OK;
    case O_DELIM:
        if (strcmp(v, "auto") == 0)
            o->delim = 0;
        else if (strcmp(v, ",") == 0 || strcmp(v, "comma") == 0)
            o->delim = ',';
        else if (strcmp(v, ";") == 0 || strcmp(v, "semicolon") == 0)
            o->delim = ';';
        else if (strcmp(v, "\t") == 0 || strcmp(v, "\\t") == 0 || strcmp(v, "tab") == 0)
            o->delim = '\t';
        else if (strcmp(v, " ") == 0 || strcmp(v, "space") == 0)
            o->delim = ' ';
        else
            return cli_usage(cmd, "%s expects ',', ';', tab ('\\t'), space (' ') or auto, found "
                                  "\"%s\"", name, v);
        return CLI_OK;
    case O_DECCOMMA:
        o->decimal_comma = 1;
        return CLI_OK;
    case O_NA:
        o->na = v;
        return CLI_OK;
    case O_MISSING:
        if (strcmp(v, "error") && strcmp(v, "skip"))
            return cli_usage(cmd, "%s expects error or skip, found \"%s\"", name, v);
        o->missing_skip = v[0] == 's';
        return CLI_OK;
    case O_SKIP: {
        size_t nl;
        if (!parse_size(v, &nl))
            return cli_usage(cmd, "%s expects a number of lines, found \"%s\"", name, v);
        o->skip = nl;
        return CLI_OK;
    }
    case O_XTIME:
        o->x_time = 1;
        return CLI_OK;
    case O_GRID: {
        /* A:B:N, A and B numbers or dates (a date-time needs its seconds or a zone) */
        const char *last = strrchr(v, ':');
        size_t nn = 0;
        double a = 0, b = 0;
        const char *mid = NULL;
        if (last && parse_size(last + 1, &nn)) {
            /* the ':' between A and B: the first one where both sides parse */
            for (const char *q = strchr(v, ':'); q && q < last; q = strchr(q + 1, ':'))
                if (parse_x_value(v, (size_t)(q - v), &a) &&
                    parse_x_value(q + 1, (size_t)(last - q - 1), &b)) {
                    mid = q;
                    break;
                }
        }
        if (!mid || nn < 2 || nn > 100000000 || !(a < b))
            return cli_usage(cmd, "%s expects A:B:N (A < B numbers or ISO 8601 dates, 2 <= N <= "
                                  "100000000), found \"%s\"", name, v);
        o->grid_set = 1;
        o->grid_a = a;
        o->grid_b = b;
        o->grid_n = nn;
        return CLI_OK;
    }
    case O_SAMPLES_TOTAL:
        if (!parse_size(v, &o->samples_total) || o->samples_total < 2 ||
            o->samples_total > 100000000)
            return cli_usage(cmd, "%s expects an integer from 2 to 100000000, found \"%s\"",
                             name, v);
        return CLI_OK;
    case O_WITH_SAMPLES:
        o->with_samples = 1;
        return CLI_OK;
    case O_XLABEL:
        o->xlabel = v;
        return CLI_OK;
    case O_YLABEL:
        o->ylabel = v;
        return CLI_OK;
    case O_LOGY:
        o->logy = 1;
        return CLI_OK;
    case O_SIZE: {
        const char *xch = strchr(v, 'x');
        size_t w = 0, h = 0;
        char tmp[32];
        size_t lw = xch ? (size_t)(xch - v) : 0;
        if (xch && lw < sizeof tmp) {
            memcpy(tmp, v, lw);
            tmp[lw] = 0;
        }
        if (!xch || lw >= sizeof tmp || !parse_size(tmp, &w) || !parse_size(xch + 1, &h) ||
            w < TSU_PLOT_MIN_SIZE || w > TSU_PLOT_MAX_SIZE || h < TSU_PLOT_MIN_SIZE ||
            h > TSU_PLOT_MAX_SIZE)
            return cli_usage(cmd, "%s expects WxH in pixels, each from %d to %d, found \"%s\"",
                             name, TSU_PLOT_MIN_SIZE, TSU_PLOT_MAX_SIZE, v);
        o->width = (unsigned)w;
        o->height = (unsigned)h;
        return CLI_OK;
    }
    case O_VERBOSE:
        o->verbose = 1;
        return CLI_OK;
    case O_NOSTREAM:
        o->no_stream = 1;
        return CLI_OK;
    case O_CLOSED:
        o->closed = 1;
        return CLI_OK;
    case O_PARAM:
        rc = parse_enum(cmd, name, v, &cli_param_names, 0, &k);
        if (rc == CLI_OK) {
            o->param = (ts_param)k;
            o->param_set = 1;
        }
        return rc;
    case O_BOX: {
        double *a = NULL;
        size_t n = 0;
        char bad[64];
        if (!parse_list(v, 1, &a, &n, bad, sizeof bad))
            return cli_usage(cmd, "%s expects XMIN,XMAX,YMIN,YMAX[,ZMIN,ZMAX] (inf for none), found %s",
                             name, bad);
        if (n != 4 && n != 6) {
            free(a);
            return cli_usage(cmd, "%s expects 4 numbers (or 6 for 3-D data), found %zu", name, n);
        }
        for (size_t i = 0; i < n; i += 2) {
            if (isinf(a[i]) && a[i] > 0.0) {
                free(a);
                return cli_usage(cmd, "%s: a lower bound cannot be +inf", name);
            }
            if (isinf(a[i + 1]) && a[i + 1] < 0.0) {
                free(a);
                return cli_usage(cmd, "%s: an upper bound cannot be -inf", name);
            }
            if (!(a[i] < a[i + 1])) {
                free(a);
                return cli_usage(cmd, "%s: each minimum must be below its maximum", name);
            }
        }
        memcpy(o->box, a, n * sizeof *a);
        o->n_box = n;
        o->box_set = 1;
        free(a);
        return CLI_OK;
    }
    case O_HELP:
        break;
    }
    return CLI_OK;
}

int cli_parse(cli_cmd cmd, int argc, char **argv, cli_opts *o)
{
    unsigned bit = cmd == CLI_FIT ? F : cmd == CLI_CERTIFY ? C : V;
    int only_args = 0;
    memset(o, 0, sizeof *o);
    o->cmd = cmd;
    o->samples = CLI_DEFAULT_SAMPLES;
    /* what an option left out means: the library's own defaults */
    if (cmd == CLI_CURVE) {
        ts_curve_options d;
        ts_curve_options_init(&d);
        o->slopes = d.slopes;
        o->alpha = d.alpha;
        o->beta = d.beta;
        o->margin = d.margin;
        o->param = d.param;
    } else {
        ts_options d;
        ts_options_init(&d);
        o->shape = d.shape;
        o->slopes = d.slopes;
        o->form = d.form;
        o->alpha = d.alpha;
        o->beta = d.beta;
        o->margin = d.margin;
        o->extrap = d.extrapolate;
    }
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (only_args || a[0] != '-' || strcmp(a, "-") == 0) {
            if (o->data)
                return cli_usage(cmd, "more than one data file (\"%s\" and \"%s\")", o->data, a);
            o->data = a;
            continue;
        }
        if (strcmp(a, "--") == 0) {
            only_args = 1;
            continue;
        }
        const char *eq = strncmp(a, "--", 2) == 0 ? strchr(a, '=') : NULL;
        size_t nlen = eq ? (size_t)(eq - a) : strlen(a);
        const optdef *d = NULL;
        for (size_t k = 0; k < NELEM(opts); k++)
            if (strlen(opts[k].name) == nlen && strncmp(opts[k].name, a, nlen) == 0) {
                d = &opts[k];
                break;
            }
        if (!d)
            return cli_usage(cmd, "unknown option \"%.*s\"", (int)nlen, a);
        if (!(d->cmds & bit))
            return cli_usage(cmd, "option %s is not available for \"%s\"", d->name,
                             cli_cmd_name(cmd));
        if (d->id == O_HELP)
            return CLI_HELP;
        const char *val = NULL;
        if (d->has_arg) {
            if (eq)
                val = eq + 1;
            else if (i + 1 < argc)
                val = argv[++i];
            else
                return cli_usage(cmd, "option %s needs a value", d->name);
        } else if (eq) {
            return cli_usage(cmd, "option %s takes no value", d->name);
        }
        int rc = apply(cmd, d, d->name, val, o);
        if (rc != CLI_OK)
            return rc;
    }
    if (!o->data)
        o->data = "-";
    if (!o->na)
        o->na = "NA,NaN,null";
    if (o->decimal_comma && o->delim == ',')
        return cli_usage(cmd, "--decimal-comma needs another delimiter than ',' (--delimiter ';')");
    if (o->xcol && o->ycol && strcmp(o->xcol, o->ycol) == 0)
        return cli_usage(cmd, "--columns / --x / --y: X and Y must be different columns (both "
                              "\"%s\")", o->xcol);
    if (o->out && o->svg && strcmp(o->out, "-") != 0 && cli_same_file(o->out, o->svg))
        return cli_usage(cmd, "-o and the plot name the same file (\"%s\"): the plot would replace "
                              "the samples", o->svg);
    if (o->svg) {
        /* the format: --format, else the extension, which must agree with it */
        const char *dot = strrchr(o->svg, '.'), *slash = strrchr(o->svg, '/');
        int ext = -1;
        if (dot && (!slash || dot > slash)) {
            if (strcmp(dot, ".svg") == 0 || strcmp(dot, ".SVG") == 0)
                ext = CLI_PLOT_SVG;
            else if (strcmp(dot, ".png") == 0 || strcmp(dot, ".PNG") == 0)
                ext = CLI_PLOT_PNG;
            else if (strcmp(dot, ".pdf") == 0 || strcmp(dot, ".PDF") == 0)
                ext = CLI_PLOT_PDF;
        }
        static const char *const fname[3] = {"svg", "png", "pdf"};
        if (o->format_set) {
            if (ext >= 0 && ext != (int)o->plot_format)
                return cli_usage(cmd, "--format %s contradicts the extension of \"%s\"",
                                 fname[o->plot_format], o->svg);
        } else if (ext < 0) {
            return cli_usage(cmd, "cannot tell the plot format of \"%s\": use a .svg, .png or "
                                  ".pdf name, or --format svg|png|pdf", o->svg);
        } else if (ext != (int)o->plot_format) {
            return cli_usage(cmd, "--%s \"%s\": the extension says %s (use --%s, or --format)",
                             fname[o->plot_format], o->svg, fname[ext], fname[ext]);
        }
    } else if (o->format_set || o->xlabel || o->ylabel || o->logy || o->width) {
        return cli_usage(cmd, "%s only applies to a plot (--svg, --png or --pdf FILE)",
                         o->format_set ? "--format" : o->xlabel ? "--xlabel"
                         : o->ylabel ? "--ylabel" : o->logy ? "--logy" : "--size");
    }
    if (o->with_samples && !o->json)
        return cli_usage(cmd, "--with-samples only applies with --json");
    if (o->grid_set + (o->at != NULL) + (o->samples_total != 0) > 1 ||
        (o->samples_set && o->samples_total))
        return cli_usage(cmd, "give one of --samples, --samples-total, --grid and --at");

    if (o->c1) {
        if (o->form_set && o->form != TS_FORM_C1)
            return cli_usage(cmd, "--c1 contradicts --form %s", cli_form_name(o->form));
        o->form = TS_FORM_C1;
        o->form_set = 1;
    }
    return CLI_OK;
}
