/* trigspline disaggregate: bin totals to a finer grid (docs/method.md §12,
 * docs/cli.md).  Reads bins as start,end,total rows or a regular series
 * start,total (each bin ends where the next starts, the last as wide as the
 * one before, or --width); writes the totals of the finer cells
 * (start,end,total) or the rate at the cells' starts (x,rate).  Dates in the
 * first column are read and written as elsewhere in the command (seconds
 * inside; --step and --width then take units s, min, h, d). */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct dis_opts {
    const char *data, *out, *step, *width;
    int rate;
    ts_histo_options ho;
} dis_opts;

static void dis_help(void)
{
    printf("Usage: trigspline disaggregate [DATA] --step S [OPTIONS]\n"
           "Totals over bins to totals over a finer grid, or to a rate (docs/method.md\n"
           "section 12): every bin's total kept, the rate never negative (or within\n"
           "--lo/--hi) and continuously differentiable.\n\n"
           "DATA: rows start,end,total (contiguous bins) or start,total (a series: each\n"
           "bin ends where the next starts, the last as wide as the one before).\n"
           "The first column may hold dates (ISO 8601).\n\n"
           "Options:\n"
           "  --step S      the finer step (a number; with dates a duration such as 1h,\n"
           "                30min, 90s, 1d)\n"
           "  --rate        write x,rate at the finer points instead of the cells' totals\n"
           "  --lo L        lower bound of the rate (default 0)\n"
           "  --hi H        upper bound of the rate (default none)\n"
           "  --alpha A     tension: larger is flatter (default the library's)\n"
           "  --width W     width of the last bin of a series (as --step)\n"
           "  -o, --output FILE  write there (default standard output)\n"
           "  -h, --help    this text\n");
}

/* A number, or with dates a duration with unit s, min, h, d: *v in the
 * unit of x (seconds for dates).  1 on success. */
static int parse_step(const char *s, int dates, double *v)
{
    char *end;
    errno = 0;
    double x = strtod(s, &end);
    if (end == s || errno || !(x > 0.0) || !isfinite(x))
        return 0;
    if (*end == '\0') {
        *v = x;
        return 1;
    }
    if (!dates)
        return 0;
    static const struct {
        const char *u;
        double f;
    } units[] = {{"s", 1.0}, {"min", 60.0}, {"h", 3600.0}, {"d", 86400.0}};
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (strcmp(end, units[i].u) == 0) {
            *v = x * units[i].f;
            return 1;
        }
    return 0;
}

static int parse_num(const char *opt, const char *s, double *v)
{
    char *end;
    errno = 0;
    double x = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE) {
        cli_error("disaggregate: %s: not a number: \"%s\"", opt, s);
        return 0;
    }
    *v = x;
    return 1;
}

static int dis_parse(int argc, char **argv, dis_opts *o)
{
    memset(o, 0, sizeof *o);
    ts_histo_options_init(&o->ho);
    o->data = "-";
    o->out = "-";
    int have_data = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0)
            return CLI_HELP;
        if (strcmp(a, "--rate") == 0) {
            o->rate = 1;
        } else if ((strcmp(a, "--step") == 0 || strcmp(a, "--width") == 0 ||
                    strcmp(a, "--lo") == 0 || strcmp(a, "--hi") == 0 ||
                    strcmp(a, "--alpha") == 0 || strcmp(a, "-o") == 0 ||
                    strcmp(a, "--output") == 0)) {
            if (!more) {
                cli_error("disaggregate: %s needs a value", a);
                return CLI_USAGE;
            }
            const char *v = argv[++i];
            if (strcmp(a, "--step") == 0)
                o->step = v;
            else if (strcmp(a, "--width") == 0)
                o->width = v;
            else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0)
                o->out = v;
            else if (!parse_num(a, v, strcmp(a, "--lo") == 0   ? &o->ho.lo
                                      : strcmp(a, "--hi") == 0 ? &o->ho.hi
                                                               : &o->ho.alpha))
                return CLI_USAGE;
        } else if (a[0] == '-' && a[1] != '\0') {
            cli_error("disaggregate: unknown option \"%s\"", a);
            return CLI_USAGE;
        } else if (!have_data) {
            o->data = a;
            have_data = 1;
        } else {
            cli_error("disaggregate: more than one DATA (\"%s\")", a);
            return CLI_USAGE;
        }
    }
    if (!o->step) {
        cli_error("disaggregate: --step is required");
        return CLI_USAGE;
    }
    return CLI_OK;
}

/* The bins of DATA: edges (n + 1) and totals (n), *dates with *form. */
typedef struct dis_bins {
    size_t n;
    double *e, *T;
    unsigned long long *line; /* of each bin */
    int dates;
    tsu_time_form form;
} dis_bins;

static int read_bins(const dis_opts *o, dis_bins *b)
{
    memset(b, 0, sizeof *b);
    const char *name = strcmp(o->data, "-") == 0 ? "<stdin>" : o->data;
    FILE *fp = strcmp(o->data, "-") == 0 ? stdin : fopen(o->data, "r");
    if (!fp) {
        cli_error("%s: cannot open: %s", name, strerror(errno));
        return CLI_IO;
    }
    tsu_read_options ro;
    tsu_read_options_init(&ro);
    ro.time_detect = 1;
    tsu_reader *r = NULL;
    tsu_io_error e;
    int rc = CLI_DATA;
    size_t cap = 0, k = 0, nc = 0;
    double step_w = 0.0;
    tsu_io_status st = tsu_reader_open(&r, fp, name, &ro, &e);
    const double *row;
    while (st == TSU_IO_OK && (st = tsu_reader_next(r, &row, &e)) == TSU_IO_OK) {
        if (k == 0) {
            nc = tsu_reader_ncols(r);
            b->dates = tsu_reader_is_time(r, 0, &b->form);
            if (nc != 2 && nc != 3) {
                cli_error("%s: %zu columns; disaggregate reads start,end,total or start,total",
                          name, nc);
                goto done;
            }
            if (nc == 3 && tsu_reader_is_time(r, 1, NULL) != b->dates) {
                cli_error("%s: start and end columns must both be dates or both numbers", name);
                goto done;
            }
        }
        if (k + 2 > cap) {
            size_t nc2 = cap ? 2 * cap : 64;
            double *ne = realloc(b->e, nc2 * sizeof *ne), *nT = ne ? realloc(b->T, nc2 * sizeof *nT) : NULL;
            unsigned long long *nl = nT ? realloc(b->line, nc2 * sizeof *nl) : NULL;
            if (ne)
                b->e = ne;
            if (nT)
                b->T = nT;
            if (nl)
                b->line = nl;
            if (!ne || !nT || !nl || nc2 < cap) {
                rc = cli_nomem();
                goto done;
            }
            cap = nc2;
        }
        b->line[k] = tsu_reader_line(r);
        if (nc == 3) {
            if (k > 0 && row[0] != b->e[k]) {
                cli_error("%s:%llu: the bin starts where the previous one does not end "
                          "(bins must be contiguous)", name, b->line[k]);
                goto done;
            }
            b->e[k] = row[0];
            b->e[k + 1] = row[1];
            b->T[k] = row[2];
        } else {
            b->e[k] = row[0];
            b->T[k] = row[1];
        }
        k++;
    }
    if (st != TSU_IO_END) {
        rc = cli_report_io(&e);
        goto done;
    }
    if (nc == 2) {
        if (o->width) {
            if (!parse_step(o->width, b->dates, &step_w)) {
                cli_error("disaggregate: --width: not a positive %s: \"%s\"",
                          b->dates ? "duration" : "number", o->width);
                rc = CLI_USAGE;
                goto done;
            }
        } else if (k >= 2) {
            step_w = b->e[k - 1] - b->e[k - 2];
        } else {
            cli_error("%s: one bin of a series needs --width", name);
            rc = CLI_USAGE;
            goto done;
        }
        b->e[k] = b->e[k - 1] + step_w;
    }
    b->n = k;
    rc = CLI_OK;
done:
    tsu_reader_free(r);
    if (fp != stdin)
        fclose(fp);
    return rc;
}

static void bins_free(dis_bins *b)
{
    free(b->e);
    free(b->T);
    free(b->line);
}

static const char *xtext(const dis_bins *b, double x, char buf[TSU_TIME_SIZE])
{
    if (b->dates) {
        tsu_format_time(x, &b->form, buf);
        return buf;
    }
    return cli_num(x, buf);
}

/* ts_format_x_fn: an edge as the command writes it (a date or a number). */
static int x_text(double x, char *buf, size_t len, void *user)
{
    char b[TSU_TIME_SIZE];
    return snprintf(buf, len, "%s", xtext(user, x, b));
}

int cli_disaggregate(int argc, char **argv)
{
    dis_opts o;
    int rc = dis_parse(argc, argv, &o);
    if (rc == CLI_HELP) {
        dis_help();
        return fflush(stdout) == 0 ? CLI_OK : CLI_IO;
    }
    if (rc != CLI_OK)
        return rc;
    dis_bins b;
    rc = read_bins(&o, &b);
    if (rc != CLI_OK) {
        bins_free(&b);
        return rc;
    }
    const char *name = strcmp(o.data, "-") == 0 ? "<stdin>" : o.data;
    double step;
    if (!parse_step(o.step, b.dates, &step)) {
        cli_error("disaggregate: --step: not a positive %s: \"%s\"",
                  b.dates ? "duration (such as 1h)" : "number", o.step);
        bins_free(&b);
        return CLI_USAGE;
    }
    ts_histo *h = NULL;
    ts_error err;
    ts_status st = ts_histo_new(b.e, b.T, b.n, &o.ho, &h, &err);
    if (st != TS_OK) {
        char msg[1024];
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = b.e;
        ctx.f = b.T;
        ctx.n_points = b.n + 1;
        ctx.histo_options = &o.ho;
        ctx.format_x = x_text;
        ctx.format_x_user = &b;
        ts_error_message(&err, &ctx, msg, sizeof msg);
        if (err.where == TS_WHERE_INTERVAL && err.index < b.n)
            cli_error("%s:%llu: %s", name, b.line[err.index], msg);
        else if (err.where == TS_WHERE_POINT && err.index <= b.n)
            cli_error("%s:%llu: %s", name, b.line[err.index < b.n ? err.index : b.n - 1], msg);
        else
            cli_error("%s: %s", name, msg);
        bins_free(&b);
        return st == TS_ERR_ALPHA || st == TS_ERR_OPTION ? CLI_USAGE
               : st == TS_ERR_INFEASIBLE                 ? CLI_INFEASIBLE
                                                         : CLI_DATA;
    }
    double e0 = b.e[0], en = b.e[b.n];
    /* a whole number of steps to rounding (a step such as 1/24) is that
     * number, not one more cell of a few ulps */
    double span = (en - e0) / step, cells = nearbyint(span);
    if (!(fabs(span - cells) <= 1e-9 * span))
        cells = ceil(span);
    if (!(cells >= 1.0 && cells <= 1e9)) {
        cli_error("disaggregate: --step %s gives %.0f cells", o.step, cells);
        ts_histo_free(h);
        bins_free(&b);
        return CLI_USAGE;
    }
    size_t m = (size_t)cells;
    double *g = malloc((m + 1) * sizeof *g), *v = malloc((m + 1) * sizeof *v);
    if (!g || !v) {
        free(g);
        free(v);
        ts_histo_free(h);
        bins_free(&b);
        return cli_nomem();
    }
    for (size_t k = 0; k < m; k++)
        g[k] = e0 + (double)k * step;
    g[m] = en;
    if (o.rate)
        st = ts_histo_eval_batch(h, g, m + 1, v, NULL, &err);
    else
        st = ts_histo_totals(h, g, m + 1, v, &err);
    rc = CLI_OK;
    FILE *fp = stdout;
    cli_out co;
    char msg[512];
    if (st != TS_OK) {
        cli_error("disaggregate: %s", ts_strerror(st));
        rc = CLI_DATA;
    } else if (strcmp(o.out, "-") != 0 && cli_out_open(&co, o.out, msg, sizeof msg) != 0) {
        cli_error("%s", msg);
        rc = CLI_IO;
    } else {
        if (strcmp(o.out, "-") != 0)
            fp = cli_out_file(&co);
        char xb[TSU_TIME_SIZE], xb2[TSU_TIME_SIZE], nb[TSU_FMT_SIZE];
        fputs(o.rate ? "x,rate\n" : "start,end,total\n", fp);
        for (size_t k = 0; k < (o.rate ? m + 1 : m); k++) {
            if (o.rate)
                fprintf(fp, "%s,%s\n", xtext(&b, g[k], xb), cli_num(v[k], nb));
            else
                fprintf(fp, "%s,%s,%s\n", xtext(&b, g[k], xb), xtext(&b, g[k + 1], xb2),
                        cli_num(v[k], nb));
        }
        if (strcmp(o.out, "-") != 0) {
            if (cli_out_commit(&co, msg, sizeof msg) != 0) {
                cli_error("%s", msg);
                rc = CLI_IO;
            }
        } else if (fflush(stdout) != 0) {
            rc = CLI_IO;
        }
    }
    free(g);
    free(v);
    ts_histo_free(h);
    bins_free(&b);
    return rc;
}
