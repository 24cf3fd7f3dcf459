/* The one table of the command's options (every command, surface included):
 * name, value, commands, field, reader, help text (docs/cli.md).  args.c
 * walks argv with it, help.c prints it. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* enum fields are read and written as int (CLI_K_ENUM) */
_Static_assert(sizeof(ts_shape) == sizeof(int), "ts_shape is int-sized");
_Static_assert(sizeof(ts_slopes) == sizeof(int), "ts_slopes is int-sized");
_Static_assert(sizeof(ts_form) == sizeof(int), "ts_form is int-sized");
_Static_assert(sizeof(ts_extrap) == sizeof(int), "ts_extrap is int-sized");
_Static_assert(sizeof(ts_param) == sizeof(int), "ts_param is int-sized");
_Static_assert(sizeof(ts_surface_shape) == sizeof(int), "ts_surface_shape is int-sized");

#define FIELD(o, off, type) ((type *)(void *)((char *)(o) + (off)))

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

/* Digits only, no sign, within size_t. */
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

/* ---- readers of the generic kinds ------------------------------------- */

static int read_scalar(cli_cmd cmd, const char *name, const char *s, int allow_zero, double *v)
{
    if (!parse_number(s, strlen(s), 0, v))
        return cli_usage(cmd, "%s expects a finite number, found \"%s\"", name, s);
    if (!(allow_zero ? *v >= 0.0 : *v > 0.0))
        return cli_usage(cmd, "%s must be %s, found %s", name, allow_zero ? ">= 0" : "> 0", s);
    return CLI_OK;
}

static int read_enum(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s, int *v)
{
    int k;
    if (ts_vocab_value(d->vocab, s, &k) == TS_OK && !((d->skip >> k) & 1u)) {
        *v = k;
        return CLI_OK;
    }
    char list[256] = "";
    size_t len = 0;
    for (int i = 0; i < ts_vocab_count(d->vocab); i++) {
        if ((d->skip >> i) & 1u)
            continue;
        int w = snprintf(list + len, sizeof list - len, "%s%s", len ? "|" : "",
                         ts_vocab_name(d->vocab, i));
        if (w < 0 || (size_t)w >= sizeof list - len)
            break;
        len += (size_t)w;
    }
    return cli_usage(cmd, "%s: unknown value \"%s\" (expected %s)", name, s, list);
}

int cli_optdef_apply(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    int rc = CLI_OK;
    if (d->set != CLI_NO_FIELD && d->kind != CLI_K_ENUM && d->kind != CLI_K_COUNT)
        *FIELD(o, d->set, int) = 1;
    switch (d->kind) {
    case CLI_K_HELP:
        return CLI_HELP;
    case CLI_K_FLAG:
        *FIELD(o, d->off, int) = 1;
        return CLI_OK;
    case CLI_K_FILE:
        if (!*v)
            return cli_usage(cmd, "%s: empty file name", name);
        *FIELD(o, d->off, const char *) = v;
        return CLI_OK;
    case CLI_K_TEXT:
        *FIELD(o, d->off, const char *) = v;
        return CLI_OK;
    case CLI_K_POS:
    case CLI_K_NONNEG:
        return read_scalar(cmd, name, v, d->kind == CLI_K_NONNEG, FIELD(o, d->off, double));
    case CLI_K_ENUM: {
        int k = 0;
        if ((rc = read_enum(d, cmd, name, v, &k)) != CLI_OK)
            return rc;
        memcpy((char *)o + d->off, &k, sizeof k);
        break;
    }
    case CLI_K_COUNT: {
        size_t *n = FIELD(o, d->off, size_t);
        if (!parse_size(v, n) || !(d->lo <= (double)*n && (double)*n <= d->hi))
            return cli_usage(cmd, "%s expects an integer from %.0f to %.0f, found \"%s\"", name,
                             d->lo, d->hi, v);
        break;
    }
    case CLI_K_CUSTOM:
        return d->fn(d, cmd, name, v, o);
    }
    if (d->set != CLI_NO_FIELD)
        *FIELD(o, d->set, int) = 1;
    return rc;
}

/* ---- fit, certify, curve: readers of their own ------------------------ */

#define OPTS(o) ((cli_opts *)(o))

/* --line / --lower / --upper M,C into the ts_line at off. */
static int opt_line(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s, void *o)
{
    ts_line *l = FIELD(o, d->off, ts_line);
    double *a = NULL;
    size_t n = 0;
    char bad[64];
    if (!parse_list(s, 0, &a, &n, bad, sizeof bad))
        return cli_usage(cmd,
                         "%s expects M,C (slope and intercept of y = M*x + C), found %s in \"%s\"",
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

static int opt_constraint(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s, void *o)
{
    (void)d;
    return cli_constraint_add(OPTS(o), cmd, name, s);
}
static int opt_constraints(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s,
                           void *o)
{
    (void)d;
    return cli_constraints_file(OPTS(o), cmd, name, s);
}

static int positive_list(cli_cmd cmd, const char *name, const char *s, int allow_zero,
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

static int opt_alphas(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s, void *o)
{
    (void)d;
    return positive_list(cmd, name, s, 0, &OPTS(o)->alphas, &OPTS(o)->n_alphas);
}

static int opt_betas(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s, void *o)
{
    (void)d;
    return positive_list(cmd, name, s, 1, &OPTS(o)->betas, &OPTS(o)->n_betas);
}

static int opt_at(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *vo)
{
    cli_opts *o = vo;
    (void)d, (void)cmd, (void)name;
    o->at = v;
    free(o->at_list);
    o->at_list = NULL;
    o->n_at = 0;
    if (strchr(v, ',') || parse_x_value(v, strlen(v), &(double){0}))
        (void)parse_at_list(v, &o->at_list, &o->n_at);
    return CLI_OK;
}

static int opt_derivative(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                          void *o)
{
    (void)d;
    if (strcmp(v, "0") && strcmp(v, "1") && strcmp(v, "2"))
        return cli_usage(cmd, "%s expects 0, 1 or 2, found \"%s\"", name, v);
    OPTS(o)->deriv = v[0] - '0';
    OPTS(o)->deriv_set = 1;
    return CLI_OK;
}

/* --svg / --png / --pdf: the plot's file and, for now, its format (args.c
 * checks it against --format and the extension). */
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
static int opt_svg(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    (void)d;
    return set_plot(cmd, name, v, CLI_PLOT_SVG, o);
}
static int opt_png(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    (void)d;
    return set_plot(cmd, name, v, CLI_PLOT_PNG, o);
}
static int opt_pdf(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    (void)d;
    return set_plot(cmd, name, v, CLI_PLOT_PDF, o);
}

static int opt_format(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    (void)d;
    if (strcmp(v, "svg") && strcmp(v, "png") && strcmp(v, "pdf"))
        return cli_usage(cmd, "%s expects svg, png or pdf, found \"%s\"", name, v);
    OPTS(o)->plot_format = v[1] == 'v' ? CLI_PLOT_SVG : v[1] == 'n' ? CLI_PLOT_PNG : CLI_PLOT_PDF;
    OPTS(o)->format_set = 1;
    return CLI_OK;
}

static int opt_columns(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *vo)
{
    cli_opts *o = vo;
    const char *comma = strchr(v, ',');
    (void)d;
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

/* --x / --y: the char * at off. */
static int opt_column(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    char **dst = FIELD(o, d->off, char *);
    free(*dst);
    *dst = col_spec(v, strlen(v));
    if (!*dst)
        return cli_usage(cmd, "%s expects a column number or header name", name);
    OPTS(o)->columns_set = 1;
    return CLI_OK;
}

static int opt_delimiter(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                         void *o)
{
    char *delim = &OPTS(o)->delim;
    (void)d;
    if (strcmp(v, "auto") == 0)
        *delim = 0;
    else if (strcmp(v, ",") == 0 || strcmp(v, "comma") == 0)
        *delim = ',';
    else if (strcmp(v, ";") == 0 || strcmp(v, "semicolon") == 0)
        *delim = ';';
    else if (strcmp(v, "\t") == 0 || strcmp(v, "\\t") == 0 || strcmp(v, "tab") == 0)
        *delim = '\t';
    else if (strcmp(v, " ") == 0 || strcmp(v, "space") == 0)
        *delim = ' ';
    else
        return cli_usage(cmd, "%s expects ',', ';', tab ('\\t'), space (' ') or auto, found "
                              "\"%s\"", name, v);
    return CLI_OK;
}

static int opt_missing(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    (void)d;
    if (strcmp(v, "error") && strcmp(v, "skip"))
        return cli_usage(cmd, "%s expects error or skip, found \"%s\"", name, v);
    OPTS(o)->missing_skip = v[0] == 's';
    return CLI_OK;
}

static int opt_skip(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    size_t nl;
    (void)d;
    if (!parse_size(v, &nl))
        return cli_usage(cmd, "%s expects a number of lines, found \"%s\"", name, v);
    OPTS(o)->skip = nl;
    return CLI_OK;
}

/* --grid A:B:N, A and B numbers or dates (a date-time needs its seconds or a zone). */
static int opt_grid(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *vo)
{
    cli_opts *o = vo;
    const char *last = strrchr(v, ':');
    size_t nn = 0;
    double a = 0, b = 0;
    const char *mid = NULL;
    (void)d;
    if (last && parse_size(last + 1, &nn)) {
        /* the ':' between A and B: the first one where both sides parse */
        for (const char *q = strchr(v, ':'); q && q < last; q = strchr(q + 1, ':'))
            if (parse_x_value(v, (size_t)(q - v), &a) &&
                parse_x_value(q + 1, (size_t)(last - q - 1), &b)) {
                mid = q;
                break;
            }
    }
    if (!mid || nn < 2) { /* A:B, the step from --step */
        mid = NULL;
        nn = 0;
        for (const char *q = strchr(v, ':'); q; q = strchr(q + 1, ':'))
            if (parse_x_value(v, (size_t)(q - v), &a) && parse_x_value(q + 1, strlen(q + 1), &b)) {
                mid = q;
                break;
            }
        if (mid && a < b) {
            o->grid_set = 1;
            o->grid_a = a;
            o->grid_b = b;
            o->grid_n = 0;
            return CLI_OK;
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

/* --step S: a number > 0, for a time x with a unit s, min, h or d ("15min"). */
static int opt_step(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *vo)
{
    static const struct {
        const char *unit;
        double seconds;
    } units[] = {{"s", 1}, {"min", 60}, {"h", 3600}, {"d", 86400}};
    cli_opts *o = vo;
    size_t len = strlen(v), k = len;
    double step = 0, unit = 0;
    (void)d;
    while (k > 0 && ((v[k - 1] >= 'a' && v[k - 1] <= 'z') || (v[k - 1] >= 'A' && v[k - 1] <= 'Z')))
        k--;
    if (k < len) {
        for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
            if (strcmp(v + k, units[i].unit) == 0)
                unit = units[i].seconds;
        if (unit == 0)
            return cli_usage(cmd, "%s: unknown unit \"%s\" in \"%s\" (s, min, h or d)", name,
                             v + k, v);
    }
    if (!parse_number(v, k, 0, &step) || !(step > 0))
        return cli_usage(cmd, "%s expects a number > 0, with a unit s, min, h or d for dates "
                              "(1h, 15min), found \"%s\"", name, v);
    o->step_set = 1;
    o->step = step;
    o->step_unit = unit;
    o->step_text = v;
    return CLI_OK;
}

static int opt_size(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o)
{
    const char *xch = strchr(v, 'x');
    size_t w = 0, h = 0;
    char tmp[32];
    size_t lw = xch ? (size_t)(xch - v) : 0;
    (void)d;
    if (xch && lw < sizeof tmp) {
        memcpy(tmp, v, lw);
        tmp[lw] = 0;
    }
    if (!xch || lw >= sizeof tmp || !parse_size(tmp, &w) || !parse_size(xch + 1, &h) ||
        w < TSU_PLOT_MIN_SIZE || w > TSU_PLOT_MAX_SIZE || h < TSU_PLOT_MIN_SIZE ||
        h > TSU_PLOT_MAX_SIZE)
        return cli_usage(cmd, "%s expects WxH in pixels, each from %d to %d, found \"%s\"", name,
                         TSU_PLOT_MIN_SIZE, TSU_PLOT_MAX_SIZE, v);
    OPTS(o)->width = (unsigned)w;
    OPTS(o)->height = (unsigned)h;
    return CLI_OK;
}

static int opt_box(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *vo)
{
    cli_opts *o = vo;
    double *a = NULL;
    size_t n = 0;
    char bad[64];
    (void)d;
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

/* ---- surface: readers of its own -------------------------------------- */

#define SOPTS(o) ((cli_surface_opts *)(o))

static int parse_finite(const char *s, size_t len, double *v)
{
    return parse_number(s, len, 0, v);
}

/* "C" or "P,Q,C" into the ts_plane at off (--lower / --upper). */
static int opt_plane(const cli_optdef *d, cli_cmd cmd, const char *name, const char *s, void *o)
{
    ts_plane r = {0.0, 0.0, 0.0};
    const char *c1 = strchr(s, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    int ok;
    if (!c1)
        ok = parse_finite(s, strlen(s), &r.c);
    else
        ok = c2 && !strchr(c2 + 1, ',') && parse_finite(s, (size_t)(c1 - s), &r.p) &&
             parse_finite(c1 + 1, (size_t)(c2 - c1 - 1), &r.q) &&
             parse_finite(c2 + 1, strlen(c2 + 1), &r.c);
    if (!ok)
        return cli_usage(cmd, "%s expects C or P,Q,C (the constant C or the plane "
                              "z = P*x + Q*y + C), found \"%s\"", name, s);
    *FIELD(o, d->off, ts_plane) = r;
    return CLI_OK;
}

/* An integer 1 to 1e7, written as any number ("1e3" too). */
static int surface_count(const char *s, size_t len, size_t *v)
{
    double d;
    if (!parse_finite(s, len, &d) || d < 1 || d > 1e7 || d != floor(d))
        return 0;
    *v = (size_t)d;
    return 1;
}

static int opt_surface_samples(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                               void *o)
{
    (void)d;
    if (!surface_count(v, strlen(v), &SOPTS(o)->samples))
        return cli_usage(cmd, "%s expects an integer from 1 to 10000000, found \"%s\"", name, v);
    return CLI_OK;
}

static int opt_surface_grid(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                            void *vo)
{
    cli_surface_opts *o = vo;
    const char *c = strchr(v, ',');
    (void)d;
    if (!c || !surface_count(v, (size_t)(c - v), &o->grid_x) ||
        !surface_count(c + 1, strlen(c + 1), &o->grid_y) || o->grid_x < 2 || o->grid_y < 2)
        return cli_usage(cmd, "%s expects NX,NY (integers from 2 to 10000000), found \"%s\"",
                         name, v);
    return CLI_OK;
}

/* The format is the option's; a plot extension that says another is
 * refused (no SVG silently written into a .png). */
static int surface_plot(cli_cmd cmd, const char *name, const char *v, cli_plot_format f, void *vo)
{
    static const char *const ext[3] = {".svg", ".png", ".pdf"};
    cli_surface_opts *o = vo;
    const char *dot = strrchr(v, '.');
    if (!*v || strcmp(v, "-") == 0)
        return cli_usage(cmd, "%s needs a file name", name);
    for (int e = 0; e < 3; e++)
        if (dot && e != (int)f && strcasecmp(dot, ext[e]) == 0)
            return cli_usage(cmd, "the plot's extension contradicts %s (\"%s\")", name, v);
    o->fmt = f;
    o->svg = v;
    return CLI_OK;
}
static int opt_surface_svg(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                           void *o)
{
    (void)d;
    return surface_plot(cmd, name, v, CLI_PLOT_SVG, o);
}
static int opt_surface_png(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                           void *o)
{
    (void)d;
    return surface_plot(cmd, name, v, CLI_PLOT_PNG, o);
}
static int opt_surface_pdf(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                           void *o)
{
    (void)d;
    return surface_plot(cmd, name, v, CLI_PLOT_PDF, o);
}

/* ---- the table -------------------------------------------------------- */

#define OFF(f) offsetof(cli_opts, f)
#define SOFF(f) offsetof(cli_surface_opts, f)
#define NOF CLI_NO_FIELD
#define FCV (CLI_F | CLI_C | CLI_V)
/* a row: name, short name, value, commands, kind, field, "given" field */
#define ROW(n, sn, meta, cmds, kind, off, set) n, sn, meta, cmds, kind, off, set
/* the rest: vocabulary, skip, range, defaults, reader, group, help */
#define REST(voc, skip, lo, hi, def, tdef, fn, g, h) voc, skip, lo, hi, def, tdef, fn, g, h
#define PLAIN(fn, g, h) REST(TS_VOCAB_STATUS, 0, 0, 0, (double)NAN, NULL, fn, g, h)
#define ENUM(voc, skip, g, h) REST(voc, skip, 0, 0, (double)NAN, NULL, NULL, g, h)
#define COUNT(lo, hi, def, g, h) REST(TS_VOCAB_STATUS, 0, lo, hi, def, NULL, NULL, g, h)

const cli_optdef cli_optdefs[] = {
    /* fit, certify, curve: shape */
    {ROW("--shape", NULL, NULL, CLI_F, CLI_K_ENUM, OFF(shape), OFF(shape_set)),
     ENUM(TS_VOCAB_SHAPE, 0, CLI_G_SHAPE, "(default %D)")},
    {ROW("--shape", NULL, NULL, CLI_C, CLI_K_ENUM, OFF(shape), OFF(shape_set)),
     ENUM(TS_VOCAB_SHAPE, 0, CLI_G_SHAPE,
          "positive: the lower line y = 0; above / below with --line; between with --lower "
          "and --upper")},
    {ROW("--line", NULL, "M,C", CLI_F | CLI_C, CLI_K_CUSTOM, OFF(line), OFF(has_line)),
     PLAIN(opt_line, CLI_G_SHAPE, "the line y = M*x + C for --shape above or below")},
    {ROW("--lower", NULL, "M,C", CLI_F | CLI_C, CLI_K_CUSTOM, OFF(lower), OFF(has_lower)),
     PLAIN(opt_line, CLI_G_SHAPE, "lower line (alone: implies above)")},
    {ROW("--upper", NULL, "M,C", CLI_F | CLI_C, CLI_K_CUSTOM, OFF(upper), OFF(has_upper)),
     PLAIN(opt_line, CLI_G_SHAPE, "upper line (alone: implies below; with --lower: between)")},
    {ROW("--constraint", NULL, "SPEC", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_constraint, CLI_G_SHAPE,
           "a constraint, certified per interval (repeatable): convex, concave, increasing, "
           "decreasing, lower=C, upper=C, lower=poly:X,Y;X,Y;..., upper=poly:..., "
           "lower=spline:FILE.csv, upper=spline:FILE.csv (the points of FILE fitted with the "
           "defaults), slope>=V, slope<=V, abs-slope<=V; @I0-I1 limits it to those intervals")},
    {ROW("--constraints", NULL, "FILE", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_constraints, CLI_G_SHAPE,
           "constraints from a JSON array of SPEC strings or {\"kind\", \"value\", "
           "\"points\", \"spline\", \"first\", \"count\"} objects")},
    {ROW("--margin", NULL, "T", CLI_F, CLI_K_POS, OFF(margin), OFF(margin_set)),
     PLAIN(NULL, CLI_G_SHAPE, "margin t added to beta (default %D; shape schemes only)")},
    /* parameters */
    {ROW("--closed", NULL, NULL, CLI_V, CLI_K_FLAG, OFF(closed), NOF),
     PLAIN(NULL, CLI_G_PARAM, "closed curve (the first point may be repeated at the end)")},
    {ROW("--param", NULL, NULL, CLI_V, CLI_K_ENUM, OFF(param), OFF(param_set)),
     ENUM(TS_VOCAB_PARAM, 0, CLI_G_PARAM, "parameter knots (default %D)")},
    {ROW("--alpha", NULL, "A", CLI_F | CLI_V, CLI_K_POS, OFF(alpha), OFF(alpha_set)),
     PLAIN(NULL, CLI_G_PARAM, "alpha on every interval (default %D, > 0)")},
    {ROW("--alpha", NULL, "A", CLI_C, CLI_K_POS, OFF(alpha), OFF(alpha_set)),
     PLAIN(NULL, CLI_G_PARAM, "alpha on every interval (> 0; this or --alphas required)")},
    {ROW("--alphas", NULL, "A0,A1,...", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_alphas, CLI_G_PARAM, "alpha per interval (exactly one value per interval)")},
    {ROW("--beta", NULL, "B", CLI_F, CLI_K_NONNEG, OFF(beta), OFF(beta_set)),
     PLAIN(NULL, CLI_G_PARAM, "beta on every interval (default %D; only with --shape none)")},
    {ROW("--beta", NULL, "B", CLI_C, CLI_K_NONNEG, OFF(beta), OFF(beta_set)),
     PLAIN(NULL, CLI_G_PARAM, "beta on every interval (>= 0; this or --betas required)")},
    {ROW("--beta", NULL, "B", CLI_V, CLI_K_NONNEG, OFF(beta), OFF(beta_set)),
     PLAIN(NULL, CLI_G_PARAM, "beta on every segment (default %D)")},
    {ROW("--betas", NULL, "B0,B1,...", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_betas, CLI_G_PARAM, "beta per interval (only with --shape none)")},
    {ROW("--betas", NULL, "B0,B1,...", CLI_C | CLI_V, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_betas, CLI_G_PARAM, "beta per interval")},
    {ROW("--slopes", NULL, NULL, CLI_F | CLI_C, CLI_K_ENUM, OFF(slopes), OFF(slopes_set)),
     ENUM(TS_VOCAB_SLOPES, 1u << TS_SLOPES_USER, CLI_G_PARAM,
          "slope estimate at the knots (default %D)")},
    {ROW("--slopes", NULL, NULL, CLI_V, CLI_K_ENUM, OFF(slopes), OFF(slopes_set)),
     ENUM(TS_VOCAB_SLOPES, 1u << TS_SLOPES_USER, CLI_G_PARAM,
          "slope estimate at the knots (default %D; periodic: closed curves only)")},
    {ROW("--form", NULL, NULL, CLI_F | CLI_C, CLI_K_ENUM, OFF(form), OFF(form_set)),
     ENUM(TS_VOCAB_FORM, 0, CLI_G_PARAM, "spline form (default %D)")},
    {ROW("--c1", NULL, NULL, CLI_F | CLI_C, CLI_K_FLAG, OFF(c1), NOF),
     PLAIN(NULL, CLI_G_PARAM, "the same as --form c1")},
    {ROW("--box", NULL, "XMIN,XMAX,YMIN,YMAX[,ZMIN,ZMAX]", CLI_V, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_box, CLI_G_PARAM,
           "keep the curve inside the box (inf / -inf: no bound on that side); beta is raised "
           "where needed and the curve is certified")},
    {ROW("--margin", NULL, "T", CLI_V, CLI_K_POS, OFF(margin), OFF(margin_set)),
     PLAIN(NULL, CLI_G_PARAM, "margin for the box rule (default %D)")},
    /* output */
    {ROW("--samples", NULL, "N", CLI_F | CLI_V, CLI_K_COUNT, OFF(samples), OFF(samples_set)),
     COUNT(2, 100000000, 50, CLI_G_OUTPUT, "points per interval, knots included (default %D)")},
    {ROW("--samples", NULL, "N", CLI_C, CLI_K_COUNT, OFF(samples), OFF(samples_set)),
     COUNT(2, 100000000, 50, CLI_G_OUTPUT,
           "points per interval for the plot and the JSON sample range (default %D)")},
    {ROW("--samples-total", NULL, "N", FCV, CLI_K_COUNT, OFF(samples_total), NOF),
     COUNT(2, 100000000, (double)NAN, CLI_G_OUTPUT, "N points evenly over the data range instead")},
    {ROW("--grid", NULL, "A:B:N", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_grid, CLI_G_OUTPUT,
           "N points evenly over [A, B] instead of --samples (A, B numbers or dates); --grid "
           "A:B --step S: A, A + S, ... up to B")},
    {ROW("--step", NULL, "S", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_step, CLI_G_OUTPUT,
           "points at the multiples of S within the data range (with --grid A:B: A, A + S, "
           "... up to B) instead of --samples; for dates S has a unit s, min, h or d (1h, "
           "15min), multiples counted from midnight in x's own UTC offset")},
    {ROW("--at", NULL, "FILE", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_at, CLI_G_OUTPUT,
           "evaluate at the x values of FILE (first column) instead; --at X1,X2,...: at these "
           "x values (numbers or dates)")},
    {ROW("--derivative", NULL, "0|1|2", CLI_F, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_derivative, CLI_G_OUTPUT, "print S, S' or S'' (default 0)")},
    {ROW("--extrapolate", NULL, NULL, CLI_F, CLI_K_ENUM, OFF(extrap), OFF(extrap_set)),
     ENUM(TS_VOCAB_EXTRAP, 0, CLI_G_OUTPUT, "queries of --at outside the data (default %D)")},
    {ROW("--output", "-o", "FILE", FCV, CLI_K_FILE, OFF(out), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "write there instead of standard output")},
    {ROW("--json", NULL, NULL, CLI_F | CLI_C, CLI_K_FLAG, OFF(json), NOF),
     PLAIN(NULL, CLI_G_OUTPUT,
           "a JSON report instead of CSV: knots, slopes, per interval alpha, beta, control "
           "values and certificate")},
    {ROW("--json", NULL, NULL, CLI_V, CLI_K_FLAG, OFF(json), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "a JSON report instead of CSV")},
    {ROW("--with-samples", NULL, NULL, CLI_F | CLI_C, CLI_K_FLAG, OFF(with_samples), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "with --json: also the samples (\"samples\": x, y)")},
    {ROW("--no-stream", NULL, NULL, CLI_F, CLI_K_FLAG, OFF(no_stream), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "never stream (see below)")},
    /* plots */
    {ROW("--svg", NULL, "FILE", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_svg, CLI_G_PLOT,
           "plot: data, curve, constraint lines with the forbidden region shaded, legend")},
    {ROW("--png", NULL, "FILE", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_png, CLI_G_PLOT, "the plot as PNG, made from the SVG by rsvg-convert "
                                "(librsvg2-bin)")},
    {ROW("--pdf", NULL, "FILE", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_pdf, CLI_G_PLOT, "the plot as PDF, made the same way")},
    {ROW("--format", NULL, "svg|png|pdf", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_format, CLI_G_PLOT, "the plot's format when its file's extension is another")},
    {ROW("--title", NULL, "TEXT", FCV, CLI_K_TEXT, OFF(title), NOF),
     PLAIN(NULL, CLI_G_PLOT, "plot title")},
    {ROW("--show-control", NULL, NULL, FCV, CLI_K_FLAG, OFF(show_control), NOF),
     PLAIN(NULL, CLI_G_PLOT, "also plot the control polygon")},
    {ROW("--points-only", NULL, NULL, FCV, CLI_K_FLAG, OFF(points_only), NOF),
     PLAIN(NULL, CLI_G_PLOT, "plot only the data (and the constraint lines)")},
    {ROW("--xlabel", NULL, "TEXT", FCV, CLI_K_TEXT, OFF(xlabel), NOF),
     PLAIN(NULL, CLI_G_PLOT, "x axis label (default: the column name)")},
    {ROW("--ylabel", NULL, "TEXT", FCV, CLI_K_TEXT, OFF(ylabel), NOF),
     PLAIN(NULL, CLI_G_PLOT, "y axis label (default: the column name)")},
    {ROW("--logy", NULL, NULL, CLI_F | CLI_C, CLI_K_FLAG, OFF(logy), NOF),
     PLAIN(NULL, CLI_G_PLOT, "logarithmic y axis (the data must be > 0)")},
    {ROW("--logy", NULL, NULL, CLI_V, CLI_K_FLAG, OFF(logy), NOF),
     PLAIN(NULL, CLI_G_NONE, NULL)}, /* refused by curve's checks (equal axes) */
    {ROW("--size", NULL, "WxH", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_size, CLI_G_PLOT, "size in pixels (default 720x450)")},
    /* reading DATA */
    {ROW("--columns", NULL, "X,Y", CLI_F | CLI_C, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_columns, CLI_G_INPUT,
           "take x and f from these columns of a wider table: 1-based numbers or header "
           "names; the other columns are not read and may hold any text")},
    {ROW("--x", NULL, "X", CLI_F | CLI_C, CLI_K_CUSTOM, OFF(xcol), NOF),
     PLAIN(opt_column, CLI_G_INPUT, "the x column alone (as in --columns)")},
    {ROW("--y", NULL, "Y", CLI_F | CLI_C, CLI_K_CUSTOM, OFF(ycol), NOF),
     PLAIN(opt_column, CLI_G_INPUT, "the y column alone (as in --columns)")},
    {ROW("--x-time", NULL, NULL, CLI_F | CLI_C, CLI_K_FLAG, OFF(x_time), NOF),
     PLAIN(NULL, CLI_G_INPUT, "x must hold ISO 8601 dates (else they are detected)")},
    {ROW("--date-format", NULL, "FMT", CLI_F | CLI_C, CLI_K_TEXT, OFF(date_format), NOF),
     PLAIN(NULL, CLI_G_INPUT,
           "x holds dates written in FMT (strptime: %Y %y %m %b %d %j %H %I %p %M %S %f %z; "
           "'%d/%m/%Y %H:%M'); without %z UTC; written back as ISO 8601")},
    {ROW("--delimiter", NULL, ",|;|tab|space|auto", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_delimiter, CLI_G_INPUT,
           "field separator (default auto: ';' if the first line has one, else ',', else tab, "
           "else white space)")},
    {ROW("--decimal-comma", NULL, NULL, FCV, CLI_K_FLAG, OFF(decimal_comma), NOF),
     PLAIN(NULL, CLI_G_INPUT, "',' is the decimal mark (then '.' is refused)")},
    {ROW("--na", NULL, "WORDS", FCV, CLI_K_TEXT, OFF(na), NOF),
     REST(TS_VOCAB_STATUS, 0, 0, 0, (double)NAN, "NA,NaN,null", NULL, CLI_G_INPUT,
          "comma-separated words meaning \"missing\" (default %D; any case); an empty field "
          "is always missing")},
    {ROW("--missing", NULL, "error|skip", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_missing, CLI_G_INPUT,
           "a row with a missing x or y: error naming the line (default) or left out (counted "
           "in --json, listed with -v)")},
    {ROW("--skip", NULL, "N", FCV, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_skip, CLI_G_INPUT, "skip N leading lines unread (metadata); '#' comments as "
                                  "always")},
    {ROW("--units-row", NULL, NULL, FCV, CLI_K_FLAG, OFF(units_row), NOF),
     PLAIN(NULL, CLI_G_INPUT, "the line after the header holds units (or other text): "
                              "skipped (--skip N counts lines before the header)")},
    {ROW("--verbose", "-v", NULL, FCV, CLI_K_FLAG, OFF(verbose), NOF),
     PLAIN(NULL, CLI_G_INPUT, "report skipped rows on standard error")},

    /* surface */
    {ROW("--matrix", NULL, NULL, CLI_S, CLI_K_FLAG, SOFF(matrix_in), NOF),
     PLAIN(NULL, CLI_G_INPUT, "read the matrix layout")},
    {ROW("--shape", NULL, NULL, CLI_S, CLI_K_ENUM, SOFF(so.shape), NOF),
     ENUM(TS_VOCAB_SURFACE_SHAPE, 0, CLI_G_SHAPE, "(default %D)")},
    {ROW("--lower", NULL, "C|P,Q,C", CLI_S, CLI_K_CUSTOM, SOFF(so.lower), SOFF(so.has_lower)),
     PLAIN(opt_plane, CLI_G_SHAPE, "lower bound: constant C or plane z = P x + Q y + C")},
    {ROW("--upper", NULL, "C|P,Q,C", CLI_S, CLI_K_CUSTOM, SOFF(so.upper), SOFF(so.has_upper)),
     PLAIN(opt_plane, CLI_G_SHAPE, "upper bound (bounds: constants; planes: planes)")},
    {ROW("--lower-grid", NULL, "FILE", CLI_S, CLI_K_FILE, SOFF(lower_grid), SOFF(so.has_lower)),
     PLAIN(NULL, CLI_G_SHAPE,
           "lower field: a grid of its own in DATA's layout, bilinear between its nodes, "
           "covering DATA's grid (shape grids, the default with it; nodes strictly above)")},
    {ROW("--upper-grid", NULL, "FILE", CLI_S, CLI_K_FILE, SOFF(upper_grid), SOFF(so.has_upper)),
     PLAIN(NULL, CLI_G_SHAPE, "upper field, as --lower-grid (nodes strictly below)")},
    {ROW("--form", NULL, NULL, CLI_S, CLI_K_ENUM, SOFF(so.form), NOF),
     ENUM(TS_VOCAB_FORM, 0, CLI_G_PARAM, "spline form (default %D)")},
    {ROW("--slopes", NULL, NULL, CLI_S, CLI_K_ENUM, SOFF(so.slopes), NOF),
     ENUM(TS_VOCAB_SLOPES, 1u << TS_SLOPES_USER | 1u << TS_SLOPES_PERIODIC, CLI_G_PARAM,
          "slope estimate along every grid line (default %D)")},
    {ROW("--alpha", NULL, "A", CLI_S, CLI_K_POS, SOFF(so.alpha), NOF),
     PLAIN(NULL, CLI_G_PARAM, "alpha (default %D, > 0; docs/method.md 11.3)")},
    {ROW("--beta", NULL, "B", CLI_S, CLI_K_NONNEG, SOFF(so.beta), NOF),
     PLAIN(NULL, CLI_G_PARAM, "beta (default %D, >= 0; --shape none only)")},
    {ROW("--margin", NULL, "T", CLI_S, CLI_K_POS, SOFF(so.margin), NOF),
     PLAIN(NULL, CLI_G_PARAM, "margin t of the shape schemes (default %D, > 0)")},
    {ROW("--zero-twist", NULL, NULL, CLI_S, CLI_K_FLAG, SOFF(so.zero_twist), NOF),
     PLAIN(NULL, CLI_G_PARAM, "twist 0 instead of the estimate")},
    {ROW("--samples", NULL, "N", CLI_S, CLI_K_CUSTOM, SOFF(samples), NOF),
     REST(TS_VOCAB_STATUS, 0, 0, 0, 4, NULL, opt_surface_samples, CLI_G_OUTPUT,
          "output N samples per patch side (default %D)")},
    {ROW("--grid", NULL, "NX,NY", CLI_S, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_surface_grid, CLI_G_OUTPUT,
           "output a uniform NX x NY grid instead (at most 10000000 points in all)")},
    {ROW("--matrix-out", NULL, NULL, CLI_S, CLI_K_FLAG, SOFF(matrix_out), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "write samples in the matrix layout")},
    {ROW("--json", NULL, NULL, CLI_S, CLI_K_FLAG, SOFF(json), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "write the report (JSON) instead of samples")},
    {ROW(NULL, "-o", "FILE", CLI_S, CLI_K_FILE, SOFF(out), NOF),
     PLAIN(NULL, CLI_G_OUTPUT, "output file (default standard output)")},
    {ROW("--svg", NULL, "FILE", CLI_S, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_surface_svg, CLI_G_PLOT, "heatmap with contours, nodes and active patches")},
    {ROW("--png", NULL, "FILE", CLI_S, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_surface_png, CLI_G_PLOT, "the same as PNG (converted from the SVG, as for fit)")},
    {ROW("--pdf", NULL, "FILE", CLI_S, CLI_K_CUSTOM, NOF, NOF),
     PLAIN(opt_surface_pdf, CLI_G_PLOT, "the same as PDF")},

    {ROW("--help", "-h", NULL, FCV | CLI_S, CLI_K_HELP, NOF, NOF),
     PLAIN(NULL, CLI_G_NONE, NULL)},
};
const size_t cli_n_optdefs = sizeof cli_optdefs / sizeof cli_optdefs[0];

/* ---- lookups and defaults --------------------------------------------- */

const cli_optdef *cli_optdef_find(unsigned cmds, const char *s, size_t len, const char **nm)
{
    for (size_t k = 0; k < cli_n_optdefs; k++) {
        const cli_optdef *d = &cli_optdefs[k];
        if (!(d->cmds & cmds))
            continue;
        const char *names[2] = {d->name, d->sname};
        for (int i = 0; i < 2; i++)
            if (names[i] && strlen(names[i]) == len && strncmp(names[i], s, len) == 0) {
                *nm = names[i];
                return d;
            }
    }
    return NULL;
}

void cli_opts_defaults(cli_cmd cmd, void *vo)
{
    if (cmd == CLI_SURFACE) {
        cli_surface_opts *s = vo;
        memset(s, 0, sizeof *s);
        ts_surface_options_init(&s->so);
    } else {
        cli_opts *o = vo;
        memset(o, 0, sizeof *o);
        o->cmd = cmd;
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
            ts_spline_options d;
            ts_spline_options_init(&d);
            o->shape = d.shape;
            o->slopes = d.slopes;
            o->form = d.form;
            o->alpha = d.alpha;
            o->beta = d.beta;
            o->margin = d.margin;
            o->extrap = d.extrapolate;
        }
    }
    /* and the command's own */
    for (size_t k = 0; k < cli_n_optdefs; k++) {
        const cli_optdef *d = &cli_optdefs[k];
        if (!(d->cmds & (1u << cmd)))
            continue;
        if (!isnan(d->def))
            *FIELD(vo, d->off, size_t) = (size_t)d->def;
        if (d->tdef)
            *FIELD(vo, d->off, const char *) = d->tdef;
    }
}
