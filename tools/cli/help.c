/* The --help texts (defaults shown: the library's, from ts_options_init and
 * ts_curve_options_init). */
#include "cli.h"

#include <stdio.h>

static const char input_text[] =
    "Reading DATA (all commands):\n"
    "  --delimiter ,|;|tab|space|auto   field separator (default auto: ';' if the first\n"
    "                      line has one, else ',', else tab, else white space)\n"
    "  --decimal-comma     ',' is the decimal mark (then '.' is refused)\n"
    "  --na WORDS          comma-separated words meaning \"missing\" (default NA,NaN,null;\n"
    "                      any case); an empty field is always missing\n"
    "  --missing error|skip   a row with a missing x or y: error naming the line\n"
    "                      (default) or left out (counted in --json, listed with -v)\n"
    "  --skip N            skip N leading lines unread (metadata); '#' comments as always\n"
    "  -v, --verbose       report skipped rows on standard error\n"
    "Fields may be quoted (RFC 4180: \"1,5\", \"say \"\"hi\"\"\"); a quoted number is a\n"
    "number.  A first line with a field that is text is the header; its names are kept\n"
    "in the outputs.  ISO 8601 dates and date-times (YYYY-MM-DD[THH:MM[:SS[.f]]]\n"
    "[Z|+HH:MM]) in the x column are read as seconds since 1970 (UTC, no leap seconds)\n"
    "and written back in the same form.\n";

static const char plot_text[] =
    "Plots:\n"
    "  --svg FILE | --png FILE | --pdf FILE   the plot; the format follows the file's\n"
    "                      extension (--format svg|png|pdf for another name); PNG and\n"
    "                      PDF are made from the SVG by rsvg-convert (librsvg2-bin)\n"
    "  --xlabel TEXT, --ylabel TEXT   axis labels (default: the column names)\n"
    "  --logy              logarithmic y axis (the data must be > 0)\n"
    "  --size WxH          size in pixels (default 720x450)\n"
    "  A plot holds at most 10000000 sample points (--samples times intervals).\n";

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
           "\n"
           "  trigspline COMMAND --help   options of a command\n"
           "  trigspline --version        print the version\n"
           "\n"
           "DATA is a CSV, TSV or whitespace-separated table with an optional header and\n"
           "# comments; \"-\" or no DATA reads standard input.\n"
           "\n%s",
           exit_text);
}

void cli_print_help(cli_cmd cmd)
{
    /* the defaults shown are the library's own */
    ts_options d;
    ts_curve_options c;
    char b[3][TSU_FMT_SIZE];
    ts_options_init(&d);
    ts_curve_options_init(&c);
    if (cmd == CLI_FIT) {
        printf(
            "Usage: trigspline fit [DATA] [OPTIONS]\n"
            "\n"
            "Fit the spline through the points (x, f) of DATA (two numeric columns; \"-\" or\n"
            "none: standard input) and write samples as CSV \"x,y\" (shortest round-trip\n"
            "numbers), or a JSON report, and optionally an SVG plot.\n"
            "\n"
            "Shape (docs/method.md §5):\n"
            "  --shape none|positive|above|below|between|monotone   (default %s)\n"
            "  --line M,C          the line y = M*x + C for --shape above or below\n"
            "  --lower M,C         lower line (alone: implies above)\n"
            "  --upper M,C         upper line (alone: implies below; with --lower: between)\n"
            "  --margin T          margin t added to beta (default %s; shape schemes only)\n"
            "Parameters:\n"
            "  --alpha A           alpha on every interval (default %s, > 0)\n"
            "  --alphas A0,A1,...  alpha per interval (exactly one value per interval)\n"
            "  --beta B            beta on every interval (default %s; only with --shape none)\n"
            "  --betas B0,B1,...   beta per interval (only with --shape none)\n"
            "  --slopes arithmetic|geometric|harmonic|fritsch-carlson|akima|makima|periodic\n"
            "                      slope estimate at the knots (default %s)\n"
            "  --form paper|c1|geometric   spline form (default %s); --c1 = --form c1\n"
            "Output:\n"
            "  --samples N         points per interval, knots included (default %d)\n"
            "  --at FILE           evaluate at the x values of FILE (first column) instead\n"
            "  --derivative 0|1|2  print S, S' or S'' (default 0)\n"
            "  --extrapolate error|clamp|extend|linear   queries of --at outside the data\n"
            "                      (default %s)\n"
            "  -o, --output FILE   write there instead of standard output\n"
            "  --json              a JSON report instead of CSV: knots, slopes, per interval\n"
            "                      alpha, beta, control values and certificate\n"
            "  --svg FILE          plot: data, curve, constraint lines with the forbidden\n"
            "                      region shaded, legend\n"
            "  --title TEXT        plot title\n"
            "  --show-control      also plot the control polygon\n"
            "  --points-only       plot only the data (and the constraint lines)\n"
            "  --columns X,Y       take x and f from these columns of a wider table: 1-based\n"
            "                      numbers or header names (also --x X, --y Y); the other\n"
            "                      columns are not read and may hold any text\n"
            "  --x-time            x must hold ISO 8601 dates (else they are detected)\n"
            "  --grid A:B:N        N points evenly over [A, B] instead of --samples (A, B\n"
            "                      numbers or dates)\n"
            "  --samples-total N   N points evenly over the data range instead\n"
            "  --at X1,X2,...      evaluate at these x values (numbers or dates; --at FILE:\n"
            "                      the first column of FILE)\n"
            "  --with-samples      with --json: also the samples (\"samples\": x, y)\n"
            "  --no-stream         never stream (see below)\n"
            "CSV output: header from DATA's names (x,y without a header); derivative columns\n"
            "are named d_Y_dX and d2_Y_dX2; sample x values strictly increase.\n"
            "\n%s\n%s\n"
            "Long inputs are processed in constant memory when the output is CSV samples and\n"
            "none of --json, a plot, --at, --grid, --samples-total, --alphas, --betas,\n"
            "--slopes periodic is given:\n"
            "the data are read and checked in chunks as they stream.  An error found after\n"
            "output has started is reported with its line; what was already written to\n"
            "standard output is then incomplete (with -o the file is not created).\n"
            "\n%s",
            cli_shape_name(d.shape), cli_num(d.margin, b[0]), cli_num(d.alpha, b[1]),
            cli_num(d.beta, b[2]), cli_slopes_name(d.slopes), cli_form_name(d.form),
            CLI_DEFAULT_SAMPLES, cli_extrap_name(d.extrapolate), input_text, plot_text,
            exit_text);
    } else if (cmd == CLI_CERTIFY) {
        printf(
            "Usage: trigspline certify [DATA] --alpha A --beta B BOUNDARY [OPTIONS]\n"
            "\n"
            "Build the spline with your own alpha and beta (no scheme) and certify it: the\n"
            "exact minimum distance to each boundary on every interval.\n"
            "\n"
            "Boundaries (at least one):\n"
            "  --shape positive    the lower line y = 0\n"
            "  --shape above --line M,C    lower line y = M*x + C (same as --lower M,C)\n"
            "  --shape below --line M,C    upper line (same as --upper M,C)\n"
            "  --lower M,C / --upper M,C   either or both (both: --shape between)\n"
            "Parameters:\n"
            "  --alpha A | --alphas A0,A1,...   (required, > 0)\n"
            "  --beta B | --betas B0,B1,...     (required, >= 0)\n"
            "  --slopes METHOD, --form paper|c1|geometric, --c1   as for fit\n"
            "Output:\n"
            "  a per-interval table (or --json, the same object as fit --json) on standard\n"
            "  output or -o FILE; --svg FILE, --title TEXT, --show-control, --points-only and\n"
            "  --samples N (for the plot and the JSON sample range) as for fit;\n"
            "  --columns X,Y, --x, --y, --x-time, --with-samples as for fit.\n"
            "The report is CSV: interval, X_start, X_end, alpha, beta, gap_lower,\n"
            "X_at_gap_lower, gap_upper, X_at_gap_upper, certified (true/false), X the name\n"
            "of the x column; an absent boundary leaves its fields empty.\n"
            "The violating intervals (index, x-range, minimum gap and where) are listed on\n"
            "standard error and the exit status is 4; the report and plot are still\n"
            "written (they are the result).\n"
            "\n%s\n%s\n%s",
            input_text, plot_text, exit_text);
    } else {
        printf(
            "Usage: trigspline curve [DATA] [OPTIONS]\n"
            "\n"
            "Parametric curve (docs/method.md §7) through the points of DATA (2 or 3 columns).\n"
            "Writes samples as CSV \"t,x,y\" (or \"t,x,y,z\").\n"
            "\n"
            "  --closed            closed curve (the first point may be repeated at the end)\n"
            "  --param uniform|chord|centripetal   parameter knots (default %s)\n"
            "  --alpha A, --beta B (defaults %s and %s), --alphas/--betas per segment\n"
            "  --slopes METHOD     as for fit (periodic: closed curves only)\n"
            "  --box XMIN,XMAX,YMIN,YMAX[,ZMIN,ZMAX]   keep the curve inside the box\n"
            "                      (inf / -inf: no bound on that side); beta is raised\n"
            "                      where needed and the curve is certified\n"
            "  --margin T          margin for the box rule (default %s)\n"
            "  --samples N         points per segment, knots included (default %d)\n"
            "  -o, --output FILE, --json, --svg FILE, --title TEXT, --show-control,\n"
            "  --points-only       as for fit (curve holds at most 10000000 samples)\n"
            "\n%s\n%s\n%s",
            cli_param_name(c.param), cli_num(c.alpha, b[0]), cli_num(c.beta, b[1]),
            cli_num(c.margin, b[2]), CLI_DEFAULT_SAMPLES, input_text, plot_text, exit_text);
    }
}
