/* The command line of trigspline (tools/cli) parsed in-process: the bytes
 * are an argv, one argument per line (or NUL-terminated), at most MAX_ARGS;
 * a first argument fit / certify / curve / surface picks the command (else
 * the first byte does).  Runs cli_parse and the checks of cli_fit_options /
 * cli_certify_bounds (fit, certify) or cli_curve_options (curve), or
 * cli_surface_parse, with the messages captured (cli_set_messages): no file
 * is read or written, no fit is run.  Checks:
 *  - parsing is deterministic: twice the same status, message and options;
 *    argv is left unchanged;
 *  - success prints nothing and yields options inside their documented
 *    ranges (docs/cli.md, trigspline --help: alpha finite > 0, beta finite
 *    >= 0, --samples 2..100000000, one plot format, ...), options of other
 *    commands left unset;
 *  - a usage error prints one message "trigspline CMD: ...", ending with the
 *    hint to --help, that names an argument or an option;
 *  - no leak (cli_opts_free after every parse) under ASan. */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "cli.h"

#include <math.h>

#define MAX_ARGS 32

/* The option names of every command (an error message names one of them,
 * or an argument). */
static const char *const known[] = {
    "--shape", "--line", "--lower", "--upper", "--alpha", "--beta", "--alphas", "--betas",
    "--margin", "--slopes", "--c1", "--form", "--samples", "--at", "--derivative",
    "--extrapolate", "-o", "--output", "--json", "--svg", "--title", "--show-control",
    "--points-only", "--columns", "--no-stream", "--closed", "--param", "--box", "--png",
    "--pdf", "--format", "--delimiter", "--decimal-comma", "--na", "--missing", "--skip",
    "--x", "--y", "--x-time", "--grid", "--samples-total", "--with-samples", "--xlabel",
    "--ylabel", "--logy", "--size", "-v", "--verbose", "--matrix", "--matrix-out",
    "--zero-twist", "DATA"};

typedef struct captured {
    char *text;
    size_t len;
    FILE *fp;
} captured;

static void capture_begin(captured *c)
{
    c->text = NULL;
    c->len = 0;
    c->fp = open_memstream(&c->text, &c->len);
    FUZZ_CHECK(c->fp != NULL, "open_memstream");
    cli_set_messages(c->fp);
}

static void capture_end(captured *c)
{
    cli_set_messages(NULL);
    FUZZ_CHECK(fclose(c->fp) == 0, "fclose");
    c->fp = NULL;
}

static int fin(double v)
{
    return isfinite(v) != 0;
}

static int line_ok(const ts_line *l)
{
    return fin(l->m) && fin(l->c);
}

/* One usage message of cmd naming an argument or an option. */
static void check_usage_message(const char *cmd, const char *msg, int argc, char **argv)
{
    char head[32], tail[96];
    snprintf(head, sizeof head, "trigspline %s: ", cmd);
    snprintf(tail, sizeof tail, "\nTry 'trigspline %s --help' for more information.\n", cmd);
    size_t n = strlen(msg), hl = strlen(head), tl = strlen(tail);
    FUZZ_CHECK(n > hl + tl, "usage error without a message: \"%s\"", msg);
    FUZZ_CHECK(strncmp(msg, head, hl) == 0, "message does not start with \"%s\": \"%s\"", head,
               msg);
    FUZZ_CHECK(strcmp(msg + n - tl, tail) == 0, "message without the hint to --help: \"%s\"", msg);
    /* the body, without the hint */
    size_t bl = n - hl - tl;
    char *body = malloc(bl + 1);
    FUZZ_CHECK(body != NULL, "malloc");
    memcpy(body, msg + hl, bl);
    body[bl] = '\0';
    int named = 0;
    for (size_t k = 0; k < sizeof known / sizeof *known && !named; k++)
        named = strstr(body, known[k]) != NULL;
    for (int i = 0; i < argc && !named; i++) {
        const char *a = argv[i];
        const char *eq = strncmp(a, "--", 2) == 0 ? strchr(a, '=') : NULL;
        size_t al = eq ? (size_t)(eq - a) : strlen(a);
        if (al == 0) {
            named = strstr(body, "\"\"") != NULL;
            continue;
        }
        char *name = malloc(al + 1);
        FUZZ_CHECK(name != NULL, "malloc");
        memcpy(name, a, al);
        name[al] = '\0';
        named = strstr(body, name) != NULL;
        free(name);
    }
    FUZZ_CHECK(named, "the message names no argument or option: \"%s\"", body);
    free(body);
}

/* ---- fit, certify, curve ------------------------------------------------- */

/* Every field of o as text (doubles in hex: bit for bit). */
static void dump_opts(FILE *f, const cli_opts *o)
{
#define S(p) ((p) ? (p) : "(null)")
    fprintf(f, "cmd %d data %s shape %d/%d lines %d %a %a %d %a %a %d %a %a\n", (int)o->cmd,
            S(o->data), o->shape_set, (int)o->shape, o->has_line, o->line.m, o->line.c,
            o->has_lower, o->lower.m, o->lower.c, o->has_upper, o->upper.m, o->upper.c);
    fprintf(f, "alpha %d %a beta %d %a margin %d %a\n", o->alpha_set, o->alpha, o->beta_set,
            o->beta, o->margin_set, o->margin);
    fprintf(f, "alphas %zu:", o->n_alphas);
    for (size_t i = 0; o->alphas && i < o->n_alphas; i++)
        fprintf(f, " %a", o->alphas[i]);
    fprintf(f, "\nbetas %zu:", o->n_betas);
    for (size_t i = 0; o->betas && i < o->n_betas; i++)
        fprintf(f, " %a", o->betas[i]);
    fprintf(f, "\nslopes %d/%d c1 %d form %d/%d samples %d/%zu at %s deriv %d/%d extrap %d/%d\n",
            o->slopes_set, (int)o->slopes, o->c1, o->form_set, (int)o->form, o->samples_set,
            o->samples, S(o->at), o->deriv_set, o->deriv, o->extrap_set, (int)o->extrap);
    fprintf(f, "out %s json %d svg %s title %s ctl %d pts %d cols %d %s %s nostream %d\n",
            S(o->out), o->json, S(o->svg), S(o->title), o->show_control, o->points_only,
            o->columns_set, S(o->xcol), S(o->ycol), o->no_stream);
    fprintf(f, "delim %d dc %d na %s skipmiss %d skip %llu xtime %d v %d\n", o->delim,
            o->decimal_comma, S(o->na), o->missing_skip, o->skip, o->x_time, o->verbose);
    fprintf(f, "grid %d %a %a %zu at %zu:", o->grid_set, o->grid_a, o->grid_b, o->grid_n, o->n_at);
    for (size_t i = 0; o->at_list && i < o->n_at; i++)
        fprintf(f, " %a", o->at_list[i]);
    fprintf(f, "\ntotal %zu ws %d fmt %d/%d labels %s %s logy %d size %ux%u\n", o->samples_total,
            o->with_samples, o->format_set, (int)o->plot_format, S(o->xlabel), S(o->ylabel),
            o->logy, o->width, o->height);
    fprintf(f, "closed %d param %d/%d box %d %zu:", o->closed, o->param_set, (int)o->param,
            o->box_set, o->n_box);
    for (size_t i = 0; i < o->n_box && i < 6; i++)
        fprintf(f, " %a", o->box[i]);
    fputc('\n', f);
#undef S
}

static int positive_list(const double *a, size_t n, int allow_zero)
{
    if (!a)
        return n == 0;
    if (n == 0)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!(fin(a[i]) && (allow_zero ? a[i] >= 0.0 : a[i] > 0.0)))
            return 0;
    return 1;
}

static int blank(char c)
{
    return c == ' ' || c == '\t';
}

static void check_column(const char *c)
{
    if (!c)
        return;
    size_t n = strlen(c);
    FUZZ_CHECK(n > 0 && !blank(c[0]) && !blank(c[n - 1]), "column \"%s\" not trimmed", c);
}

/* A successful cli_parse: the documented ranges (docs/cli.md, --help). */
static void check_opts(const cli_opts *o)
{
    FUZZ_CHECK(o->data && o->na, "data / na unset");
    FUZZ_CHECK(strcmp(cli_shape_name(o->shape), "?") && strcmp(cli_form_name(o->form), "?") &&
                   strcmp(cli_extrap_name(o->extrap), "?") &&
                   strcmp(cli_param_name(o->param), "?") &&
                   strcmp(cli_slopes_name(o->slopes), "?") && o->slopes != TS_SLOPES_USER,
               "enum out of range: shape %d form %d extrap %d param %d slopes %d", (int)o->shape,
               (int)o->form, (int)o->extrap, (int)o->param, (int)o->slopes);
    FUZZ_CHECK(fin(o->alpha) && o->alpha > 0.0, "alpha %a", o->alpha);
    FUZZ_CHECK(fin(o->beta) && o->beta >= 0.0, "beta %a", o->beta);
    FUZZ_CHECK(fin(o->margin) && o->margin > 0.0, "margin %a", o->margin);
    FUZZ_CHECK(positive_list(o->alphas, o->n_alphas, 0), "alphas");
    FUZZ_CHECK(positive_list(o->betas, o->n_betas, 1), "betas");
    FUZZ_CHECK((!o->has_line || line_ok(&o->line)) && (!o->has_lower || line_ok(&o->lower)) &&
                   (!o->has_upper || line_ok(&o->upper)),
               "a line is not finite");
    FUZZ_CHECK(o->samples >= 2 && o->samples <= 100000000, "samples %zu", o->samples);
    FUZZ_CHECK(o->samples_total == 0 || (o->samples_total >= 2 && o->samples_total <= 100000000),
               "samples-total %zu", o->samples_total);
    FUZZ_CHECK(!o->grid_set || (fin(o->grid_a) && fin(o->grid_b) && o->grid_a < o->grid_b &&
                                o->grid_n >= 2 && o->grid_n <= 100000000),
               "grid %a %a %zu", o->grid_a, o->grid_b, o->grid_n);
    FUZZ_CHECK(o->grid_set + (o->at != NULL) + (o->samples_total != 0) <= 1 &&
                   !(o->samples_set && o->samples_total),
               "more than one of --samples, --samples-total, --grid, --at");
    FUZZ_CHECK(!o->at_list || (o->at && o->n_at > 0), "--at list without --at");
    for (size_t i = 0; o->at_list && i < o->n_at; i++)
        FUZZ_CHECK(fin(o->at_list[i]), "--at value %zu not finite", i);
    FUZZ_CHECK(o->deriv >= 0 && o->deriv <= 2, "derivative %d", o->deriv);
    FUZZ_CHECK(!o->box_set || o->n_box == 4 || o->n_box == 6, "box of %zu", o->n_box);
    for (size_t i = 0; o->box_set && i < o->n_box; i += 2)
        FUZZ_CHECK(o->box[i] < o->box[i + 1] && o->box[i] != (double)INFINITY &&
                       o->box[i + 1] != -(double)INFINITY,
                   "box %a %a", o->box[i], o->box[i + 1]);
    FUZZ_CHECK(o->delim == 0 || o->delim == ',' || o->delim == ';' || o->delim == '\t' ||
                   o->delim == ' ',
               "delimiter %d", o->delim);
    FUZZ_CHECK(!(o->decimal_comma && o->delim == ','), "decimal comma with ','");
    check_column(o->xcol);
    check_column(o->ycol);
    FUZZ_CHECK(!(o->xcol && o->ycol && strcmp(o->xcol, o->ycol) == 0), "same columns");
    FUZZ_CHECK(!o->out || *o->out, "empty -o");
    if (o->svg) {
        FUZZ_CHECK(*o->svg && strcmp(o->svg, "-") != 0, "plot \"%s\"", o->svg);
        FUZZ_CHECK((int)o->plot_format >= 0 && (int)o->plot_format <= 2, "plot format %d",
                   (int)o->plot_format);
        FUZZ_CHECK(!o->out || strcmp(o->out, "-") == 0 || strcmp(o->out, o->svg) != 0,
                   "-o and the plot are \"%s\"", o->svg);
    } else {
        FUZZ_CHECK(!o->format_set && !o->xlabel && !o->ylabel && !o->logy && !o->width,
                   "plot options without a plot");
    }
    FUZZ_CHECK((o->width == 0 && o->height == 0) ||
                   (o->width >= TSU_PLOT_MIN_SIZE && o->width <= TSU_PLOT_MAX_SIZE &&
                    o->height >= TSU_PLOT_MIN_SIZE && o->height <= TSU_PLOT_MAX_SIZE),
               "size %ux%u", o->width, o->height);
    FUZZ_CHECK(!o->with_samples || o->json, "--with-samples without --json");
    FUZZ_CHECK(!o->c1 || (o->form_set && o->form == TS_FORM_C1), "--c1 but form %d", (int)o->form);
    /* options of the other commands are not taken */
    if (o->cmd == CLI_CURVE)
        FUZZ_CHECK(!o->shape_set && !o->has_line && !o->has_lower && !o->has_upper && !o->c1 &&
                       !o->form_set && !o->at && !o->deriv_set && !o->extrap_set &&
                       !o->columns_set && !o->no_stream && !o->x_time && !o->grid_set &&
                       !o->with_samples,
                   "an option of fit / certify taken by curve");
    else
        FUZZ_CHECK(!o->closed && !o->param_set && !o->box_set, "an option of curve taken by %s",
                   cli_cmd_name(o->cmd));
    if (o->cmd == CLI_CERTIFY)
        FUZZ_CHECK(!o->margin_set && !o->at && !o->deriv_set && !o->extrap_set && !o->no_stream &&
                       !o->grid_set,
                   "an option of fit taken by certify");
}

static void check_ts_spline_options(const cli_opts *o, const ts_spline_options *opt)
{
    FUZZ_CHECK(fin(opt->alpha) && opt->alpha > 0.0 && fin(opt->beta) && opt->beta >= 0.0 &&
                   fin(opt->margin) && opt->margin > 0.0,
               "alpha %a beta %a margin %a", opt->alpha, opt->beta, opt->margin);
    FUZZ_CHECK(opt->alphas == o->alphas && opt->n_alphas == o->n_alphas &&
                   opt->betas == o->betas && opt->n_betas == o->n_betas,
               "per-interval lists");
    FUZZ_CHECK(!(o->alpha_set && o->alphas) && !(o->beta_set && o->betas),
               "a value and a list of it");
    FUZZ_CHECK(opt->slopes != TS_SLOPES_USER && opt->form == o->form &&
                   opt->extrapolate == o->extrap,
               "slopes / form / extrapolate");
    ts_shape sh = opt->shape;
    if (o->cmd == CLI_CERTIFY) {
        FUZZ_CHECK(sh == TS_SHAPE_NONE, "certify builds with shape %d", (int)sh);
        FUZZ_CHECK((o->alpha_set || o->alphas) && (o->beta_set || o->betas),
                   "certify without alpha or beta");
        ts_line lo, up;
        int hl = 0, hu = 0;
        cli_certify_bounds(o, &sh, &lo, &hl, &up, &hu);
        FUZZ_CHECK(hl || hu, "certify without a boundary");
        FUZZ_CHECK((!hl || line_ok(&lo)) && (!hu || line_ok(&up)), "a boundary is not finite");
        FUZZ_CHECK(!(hl && hu && lo.m == up.m && !(lo.c < up.c)), "parallel lines crossed");
        return;
    }
    FUZZ_CHECK(strcmp(cli_shape_name(sh), "?") != 0, "shape %d", (int)sh);
    FUZZ_CHECK(sh == TS_SHAPE_NONE || (!o->beta_set && !o->betas), "beta with a shape scheme");
    FUZZ_CHECK(sh != TS_SHAPE_NONE || !o->margin_set, "margin without a scheme");
    if (sh == TS_SHAPE_ABOVE || sh == TS_SHAPE_BETWEEN)
        FUZZ_CHECK(line_ok(&opt->lower), "lower line");
    if (sh == TS_SHAPE_BELOW || sh == TS_SHAPE_BETWEEN)
        FUZZ_CHECK(line_ok(&opt->upper), "upper line");
    if (sh == TS_SHAPE_BETWEEN)
        FUZZ_CHECK(!(opt->lower.m == opt->upper.m && !(opt->lower.c < opt->upper.c)),
                   "parallel lines crossed");
    FUZZ_CHECK(!(o->at && strcmp(o->at, "-") == 0 && strcmp(o->data, "-") == 0),
               "DATA and --at both standard input");
}

static void check_curve_options(const cli_opts *o, const ts_curve_options *co)
{
    FUZZ_CHECK(fin(co->alpha) && co->alpha > 0.0 && fin(co->beta) && co->beta >= 0.0 &&
                   fin(co->margin) && co->margin > 0.0,
               "alpha %a beta %a margin %a", co->alpha, co->beta, co->margin);
    FUZZ_CHECK(co->slopes != TS_SLOPES_USER && (co->slopes != TS_SLOPES_PERIODIC || co->closed),
               "slopes %d", (int)co->slopes);
    FUZZ_CHECK(!o->margin_set || o->box_set, "margin without a box");
    FUZZ_CHECK(!o->logy, "logy");
    for (int k = 0; k < 3; k++) {
        FUZZ_CHECK((!co->has_lo[k] || fin(co->lo[k])) && (!co->has_hi[k] || fin(co->hi[k])),
                   "box bound %d not finite", k);
        FUZZ_CHECK(!(co->has_lo[k] && co->has_hi[k]) || co->lo[k] < co->hi[k], "box %d empty", k);
    }
}

/* cli_parse and the checks after it, as main and the command run them;
 * the options and the status as text into f.  Returns the status. */
static int parse_once(cli_cmd cmd, int argc, char **argv, FILE *f, captured *msg)
{
    cli_opts o;
    capture_begin(msg);
    int rc = cli_parse(cmd, argc, argv, &o);
    int rc2 = CLI_OK;
    ts_spline_options opt;
    ts_curve_options co;
    if (rc == CLI_OK) {
        if (cmd == CLI_CURVE)
            rc2 = cli_curve_options(&o, &co);
        else
            rc2 = cli_fit_options(&o, &opt);
    }
    capture_end(msg);
    FUZZ_CHECK(rc == CLI_OK || rc == CLI_USAGE || rc == CLI_HELP, "cli_parse returned %d", rc);
    FUZZ_CHECK(rc2 == CLI_OK || rc2 == CLI_USAGE, "option check returned %d", rc2);
    dump_opts(f, &o);
    fprintf(f, "rc %d %d\n", rc, rc2);
    if (rc == CLI_OK) {
        check_opts(&o);
        if (rc2 == CLI_OK && cmd == CLI_CURVE)
            check_curve_options(&o, &co);
        else if (rc2 == CLI_OK)
            check_ts_spline_options(&o, &opt);
    }
    cli_opts_free(&o);
    FUZZ_CHECK(!o.alphas && !o.betas && !o.at_list && !o.xcol && !o.ycol, "cli_opts_free");
    return rc == CLI_OK ? rc2 : rc;
}

/* ---- surface --------------------------------------------------------------- */

static void dump_surface(FILE *f, const cli_surface_opts *o)
{
#define S(p) ((p) ? (p) : "(null)")
    const ts_surface_options *s = &o->so;
    fprintf(f, "data %s out %s svg %s fmt %d mi %d mo %d json %d zt %d\n", S(o->data), S(o->out),
            S(o->svg), (int)o->fmt, o->matrix_in, o->matrix_out, o->json, s->zero_twist);
    fprintf(f, "form %d slopes %d a %a b %a t %a shape %d lo %d %a %a %a up %d %a %a %a\n",
            (int)s->form, (int)s->slopes, s->alpha, s->beta, s->margin, (int)s->shape,
            s->has_lower, s->lower.p, s->lower.q, s->lower.c, s->has_upper, s->upper.p, s->upper.q,
            s->upper.c);
    fprintf(f, "samples %zu grid %zu %zu\n", o->samples, o->grid_x, o->grid_y);
#undef S
}

static int plane_ok(const ts_plane *p)
{
    return fin(p->p) && fin(p->q) && fin(p->c);
}

static void check_surface(const cli_surface_opts *o)
{
    const ts_surface_options *s = &o->so;
    FUZZ_CHECK(o->data != NULL, "no DATA");
    FUZZ_CHECK((int)s->shape >= 0 && (int)s->shape <= 4, "shape %d", (int)s->shape);
    FUZZ_CHECK(strcmp(cli_form_name(s->form), "?") != 0, "form %d", (int)s->form);
    FUZZ_CHECK(strcmp(cli_slopes_name(s->slopes), "?") != 0 && s->slopes != TS_SLOPES_USER &&
                   s->slopes != TS_SLOPES_PERIODIC,
               "slopes %d", (int)s->slopes);
    FUZZ_CHECK(fin(s->alpha) && s->alpha > 0.0 && fin(s->beta) && s->beta >= 0.0 &&
                   fin(s->margin) && s->margin > 0.0,
               "alpha %a beta %a margin %a", s->alpha, s->beta, s->margin);
    FUZZ_CHECK((!s->has_lower || plane_ok(&s->lower)) && (!s->has_upper || plane_ok(&s->upper)),
               "a bound is not finite");
    FUZZ_CHECK(o->samples >= 1 && o->samples <= 10000000, "samples %zu", o->samples);
    FUZZ_CHECK((o->grid_x == 0 && o->grid_y == 0) ||
                   (o->grid_x >= 2 && o->grid_x <= 10000000 && o->grid_y >= 2 &&
                    o->grid_y <= 10000000),
               "grid %zu,%zu", o->grid_x, o->grid_y);
    FUZZ_CHECK(!o->out || *o->out, "empty -o");
    if (o->svg) {
        FUZZ_CHECK(*o->svg && strcmp(o->svg, "-") != 0, "plot \"%s\"", o->svg);
        FUZZ_CHECK((int)o->fmt >= 0 && (int)o->fmt <= 2, "plot format %d", (int)o->fmt);
        FUZZ_CHECK(!o->out || strcmp(o->out, "-") == 0 || strcmp(o->out, o->svg) != 0,
                   "-o and the plot are \"%s\"", o->svg);
    }
}

static int parse_surface_once(int argc, char **argv, FILE *f, captured *msg)
{
    cli_surface_opts o;
    capture_begin(msg);
    int rc = cli_surface_parse(argc, argv, &o);
    capture_end(msg);
    FUZZ_CHECK(rc == CLI_OK || rc == CLI_USAGE || rc == CLI_HELP, "cli_surface_parse returned %d",
               rc);
    dump_surface(f, &o);
    fprintf(f, "rc %d\n", rc);
    if (rc == CLI_OK)
        check_surface(&o);
    return rc;
}

/* ---- the input as an argv ----------------------------------------------------- */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const cmds[] = {"fit", "certify", "curve", "surface"};
    char *buf = malloc(size + 1), *copy = malloc(size + 1);
    FUZZ_CHECK(buf && copy, "malloc");
    memcpy(buf, data, size);
    buf[size] = '\0';
    char *argv[MAX_ARGS + 1];
    int argc = 0;
    char *p = buf, *end = buf + size;
    while (p < end && argc < MAX_ARGS) {
        char *q = p;
        while (q < end && *q != '\n' && *q != '\0')
            q++;
        *q = '\0';
        argv[argc++] = p;
        p = q + 1;
    }
    argv[argc] = NULL;
    int c = size ? data[0] % 4 : 0, first = 0;
    for (int k = 0; k < 4 && argc > 0; k++)
        if (strcmp(argv[0], cmds[k]) == 0) {
            c = k;
            first = 1;
        }
    int n = argc - first;
    char **args = argv + first;
    memcpy(copy, buf, size + 1);

    char *dump[2] = {NULL, NULL};
    size_t dlen[2];
    captured msg[2];
    int rc[2];
    for (int r = 0; r < 2; r++) {
        FILE *f = open_memstream(&dump[r], &dlen[r]);
        FUZZ_CHECK(f != NULL, "open_memstream");
        rc[r] = c == 3 ? parse_surface_once(n, args, f, &msg[r])
                       : parse_once((cli_cmd)c, n, args, f, &msg[r]);
        FUZZ_CHECK(fclose(f) == 0, "fclose");
        FUZZ_CHECK(memcmp(copy, buf, size + 1) == 0, "argv changed by the parser");
    }
    FUZZ_CHECK(rc[0] == rc[1], "status %d then %d", rc[0], rc[1]);
    FUZZ_CHECK(strcmp(msg[0].text, msg[1].text) == 0, "messages differ:\n%s---\n%s", msg[0].text,
               msg[1].text);
    FUZZ_CHECK(strcmp(dump[0], dump[1]) == 0, "options differ:\n%s---\n%s", dump[0], dump[1]);
    if (rc[0] == CLI_USAGE)
        check_usage_message(cmds[c], msg[0].text, n, args);
    else
        FUZZ_CHECK(msg[0].len == 0, "status %d with a message: \"%s\"", rc[0], msg[0].text);
    for (int r = 0; r < 2; r++) {
        free(msg[r].text);
        free(dump[r]);
    }
    free(buf);
    free(copy);
    return 0;
}
