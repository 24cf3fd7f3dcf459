/* The --help texts: every option's line generated from the option table
 * (options.c) with the defaults the parser starts from (cli_opts_defaults:
 * the library's, and the command's own sample counts). */
#include "cli.h"

#include <stdio.h>
#include <string.h>

static const char exit_text[] =
    "Exit status:\n"
    "  0  success (certify: every interval certified)\n"
    "  1  usage error: unknown option, bad option value, options that do not fit together\n"
    "  2  bad data: malformed input (FILE:LINE:COLUMN), too few points, x not increasing,\n"
    "     or data the scheme refuses (the point, its line and its x are named)\n"
    "  3  infeasible constraint: no beta keeps an interval inside the region (interval named)\n"
    "  4  certify: the curve leaves the region (violating intervals listed on stderr)\n"
    "  5  I/O error: cannot read or write a file (also out of memory)\n"
    "On failure nothing is written: -o and --svg files are written to a temporary file\n"
    "and renamed into place only on success.  (Exception: a long fit streamed to standard\n"
    "output, see STREAMING in trigspline(1).)\n";

void cli_print_main_help(void)
{
    printf("Usage: trigspline COMMAND [DATA] [OPTIONS]\n"
           "\n"
           "Shape-preserving interpolation with the GC1 cubic trigonometric spline.\n"
           "\n"
           "Commands:\n"
           "  fit      fit a spline through (x, f) data, optionally kept positive, above,\n"
           "           below or between lines, or monotone; write samples, JSON, SVG\n"
           "  certify  check a spline with your own alpha, beta against boundaries\n"
           "  curve    parametric curve through 2-D or 3-D points (open or closed)\n"
           "  surface  certified surface through gridded x,y,z data (long or matrix\n"
           "           layout): kept positive, within bounds, planes or the data range\n"
           "  disaggregate  bin totals (daily rain) to a finer grid's totals or a rate,\n"
           "           totals kept, never negative, smooth\n"
           "\n"
           "  trigspline COMMAND --help   options of a command\n"
           "  trigspline --version        print the version\n"
           "\n"
           "DATA is a CSV, TSV or whitespace-separated table with an optional header and\n"
           "# comments; \"-\" or no DATA reads standard input.\n"
           "\n%s",
           exit_text);
}

/* ---- generated option lists ------------------------------------------- */

/* The value of d's field in the defaults o, as text. */
static const char *default_text(const cli_optdef *d, const void *o, char *buf, size_t len)
{
    const char *p = (const char *)o + d->off;
    if (d->off == CLI_NO_FIELD)
        return "?";
    switch (d->kind) {
    case CLI_K_POS:
    case CLI_K_NONNEG: {
        double v;
        memcpy(&v, p, sizeof v);
        char b[TSU_FMT_SIZE];
        snprintf(buf, len, "%s", cli_num(v, b));
        return buf;
    }
    case CLI_K_ENUM: {
        int k;
        memcpy(&k, p, sizeof k);
        const char *s = ts_vocab_name(d->vocab, k);
        return s ? s : "?";
    }
    case CLI_K_TEXT: {
        const char *s;
        memcpy(&s, p, sizeof s);
        return s ? s : "";
    }
    default: {
        size_t n;
        memcpy(&n, p, sizeof n);
        snprintf(buf, len, "%zu", n);
        return buf;
    }
    }
}

#define HELP_COL 22 /* where the texts start */
#define HELP_WIDTH 80

/* The length of the next line of s at most w wide (broken at a space;
 * a longer word stands alone). */
static size_t line_length(const char *s, size_t w)
{
    size_t len = strlen(s), k = w;
    if (len <= w)
        return len;
    while (k > 0 && s[k] != ' ')
        k--;
    if (k == 0)
        for (k = w; s[k] && s[k] != ' '; k++)
            ;
    return k;
}

/* "  -o, --output FILE   write there ..." with "%D" the default of o; the
 * text wrapped into lines from HELP_COL to HELP_WIDTH. */
static void print_option(const cli_optdef *d, const void *o)
{
    char syn[512], text[1024], b[64];
    size_t n = 0;
    if (d->sname)
        n += (size_t)snprintf(syn + n, sizeof syn - n, "%s%s", d->sname, d->name ? ", " : "");
    if (d->name)
        n += (size_t)snprintf(syn + n, sizeof syn - n, "%s", d->name);
    if (d->meta)
        n += (size_t)snprintf(syn + n, sizeof syn - n, " %s", d->meta);
    else if (d->kind == CLI_K_ENUM)
        for (int k = 0, first = 1; k < ts_vocab_count(d->vocab) && n < sizeof syn; k++)
            if (!((d->skip >> k) & 1u)) {
                n += (size_t)snprintf(syn + n, sizeof syn - n, "%s%s", first ? " " : "|",
                                      ts_vocab_name(d->vocab, k));
                first = 0;
            }
    /* the text with %D replaced */
    size_t m = 0;
    for (const char *s = d->help; *s && m + 1 < sizeof text; s++) {
        if (s[0] == '%' && s[1] == 'D') {
            m += (size_t)snprintf(text + m, sizeof text - m, "%s", default_text(d, o, b, sizeof b));
            s++;
        } else {
            text[m++] = *s;
        }
    }
    text[m < sizeof text ? m : sizeof text - 1] = '\0';
    /* the synopsis, then the text wrapped at HELP_WIDTH from HELP_COL on */
    const char *s = text;
    size_t w = HELP_WIDTH - HELP_COL, len = strlen(s);
    if (2 + n + 2 <= HELP_COL)
        printf("  %-*s", HELP_COL - 2, syn);
    else if (2 + n + 3 + len <= HELP_WIDTH)
        printf("  %s   ", syn), w = len;
    else
        printf("  %s\n%*s", syn, HELP_COL, "");
    for (;;) {
        size_t k = line_length(s, w);
        printf("%.*s\n", (int)k, s);
        s += k;
        while (*s == ' ')
            s++;
        if (!*s)
            break;
        printf("%*s", HELP_COL, "");
        w = HELP_WIDTH - HELP_COL;
    }
}

/* The options of cmd in group g, in the table's order. */
static void print_group(cli_cmd cmd, cli_group g, const void *o)
{
    for (size_t k = 0; k < cli_n_optdefs; k++) {
        const cli_optdef *d = &cli_optdefs[k];
        if ((d->cmds & (1u << cmd)) && d->group == g && d->help)
            print_option(d, o);
    }
}

/* ---- the pages -------------------------------------------------------- */

typedef struct help_section {
    cli_group group; /* CLI_G_NONE: the end */
    const char *title, *tail;
} help_section;

typedef struct help_page {
    const char *head;
    help_section sec[6];
    const char *tail;
} help_page;

static const char input_title[] = "\nReading DATA:\n";
static const char input_tail[] =
    "Fields may be quoted (RFC 4180: \"1,5\", \"say \"\"hi\"\"\"); a quoted number is a\n"
    "number.  A first line with a field that is text is the header; its names are kept\n"
    "in the outputs.  ISO 8601 dates and date-times (YYYY-MM-DD[THH:MM[:SS[.f]]]\n"
    "[Z|+HH:MM]) in the x column are read as seconds since 1970 (UTC, no leap seconds)\n"
    "and written back in the same form.\n";
static const char plot_title[] =
    "\nPlots (the format follows the file's extension, --format for another name):\n";
static const char plot_tail[] =
    "  A plot holds at most 10000000 sample points (--samples times intervals).\n";

static const help_page pages[4] = {
    [CLI_FIT] = {
        "Usage: trigspline fit [DATA] [OPTIONS]\n"
        "\n"
        "Fit the spline through the points (x, f) of DATA (two numeric columns; \"-\" or\n"
        "none: standard input) and write samples as CSV \"x,y\" (shortest round-trip\n"
        "numbers), or a JSON report, and optionally an SVG plot.\n",
        {{CLI_G_SHAPE, "\nShape (docs/method.md §5):\n", NULL},
         {CLI_G_PARAM, "Parameters:\n", NULL},
         {CLI_G_OUTPUT, "Output:\n",
          "CSV output: header from DATA's names (x,y without a header); derivative columns\n"
          "are named d_Y_dX and d2_Y_dX2; sample x values strictly increase.\n"},
         {CLI_G_INPUT, input_title, input_tail},
         {CLI_G_PLOT, plot_title, plot_tail}},
        "\n"
        "Long inputs are processed in constant memory when the output is CSV samples and\n"
        "none of --json, a plot, --at, --grid, --samples-total, --alphas, --betas,\n"
        "--slopes periodic is given:\n"
        "the data are read and checked in chunks as they stream.  An error found after\n"
        "output has started is reported with its line; what was already written to\n"
        "standard output is then incomplete (with -o the file is not created).\n"},
    [CLI_CERTIFY] = {
        "Usage: trigspline certify [DATA] --alpha A --beta B BOUNDARY [OPTIONS]\n"
        "\n"
        "Build the spline with your own alpha and beta (no scheme) and certify it: the\n"
        "exact minimum distance to each boundary on every interval.\n",
        {{CLI_G_SHAPE, "\nBoundaries (at least one; --lower and --upper: between):\n", NULL},
         {CLI_G_PARAM, "Parameters:\n", NULL},
         {CLI_G_OUTPUT, "Output:\n",
          "The report is CSV: interval, X_start, X_end, alpha, beta, gap_lower,\n"
          "X_at_gap_lower, gap_upper, X_at_gap_upper, certified (true/false), X the name\n"
          "of the x column; an absent boundary leaves its fields empty.  With --json it is\n"
          "the same object as fit --json.\n"
          "The violating intervals (index, x-range, minimum gap and where) are listed on\n"
          "standard error and the exit status is 4; the report and plot are still\n"
          "written (they are the result).\n"},
         {CLI_G_INPUT, input_title, input_tail},
         {CLI_G_PLOT, plot_title, plot_tail}},
        ""},
    [CLI_CURVE] = {
        "Usage: trigspline curve [DATA] [OPTIONS]\n"
        "\n"
        "Parametric curve (docs/method.md §7) through the points of DATA (2 or 3 columns).\n"
        "Writes samples as CSV \"t,x,y\" (or \"t,x,y,z\").\n",
        {{CLI_G_PARAM, "\nCurve:\n", NULL},
         {CLI_G_OUTPUT, "Output:\n", "  (curve holds at most 10000000 samples)\n"},
         {CLI_G_INPUT, input_title, input_tail},
         {CLI_G_PLOT, plot_title, plot_tail}},
        ""},
    [CLI_SURFACE] = {
        "Usage: trigspline surface DATA [OPTIONS]\n"
        "Certified surface through gridded data (docs/method.md section 11).\n\n"
        "DATA: x,y,z rows of a full rectilinear grid in any order (long format), or\n"
        "with --matrix a table whose first row holds the x values and first column\n"
        "the y values (the first cell is ignored). '-' reads standard input.\n",
        {{CLI_G_INPUT, "\n", NULL},
         {CLI_G_SHAPE, "Shape:\n", NULL},
         {CLI_G_PARAM, "Parameters:\n", NULL},
         {CLI_G_OUTPUT, "Output:\n", NULL},
         {CLI_G_PLOT, "Plots (PNG and PDF converted from the SVG, as for fit):\n", NULL}},
        "\n"
        "Exit status: 0 ok, 1 usage, 2 bad data (names the line and node),\n"
        "3 infeasible patch, 5 input/output error.\n"},
};

void cli_print_help(cli_cmd cmd)
{
    /* the defaults shown are those the parser starts from */
    cli_opts o;
    cli_surface_opts so;
    const void *def = &o;
    if (cmd == CLI_SURFACE) {
        cli_opts_defaults(cmd, &so);
        def = &so;
    } else {
        cli_opts_defaults(cmd, &o);
    }
    const help_page *p = &pages[cmd];
    fputs(p->head, stdout);
    for (size_t k = 0; k < sizeof p->sec / sizeof p->sec[0] && p->sec[k].group; k++) {
        fputs(p->sec[k].title, stdout);
        print_group(cmd, p->sec[k].group, def);
        if (p->sec[k].tail)
            fputs(p->sec[k].tail, stdout);
    }
    fputs(p->tail, stdout);
    if (cmd != CLI_SURFACE)
        printf("\n%s", exit_text);
}
