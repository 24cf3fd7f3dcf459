/*
 * Internal interface of the trigspline command (tools/cli).  Uses only the
 * library's public API (trigspline.h) and the tool support code
 * (tools/support: tsu_io.h, tsu_plot.h).
 *
 * The files, lowest first; each uses only those listed before it:
 *   names.c        enum value names (command line, messages, JSON)
 *   messages.c     messages on stderr, number and line texts
 *   json.c         building a JSON document
 *   output.c       outputs written only on success
 *   sample.c       sampling a spline into sinks; growable point arrays
 *   data.c         reading DATA, explaining data and scheme errors
 *   fit_options.c  cli_opts -> ts_options for fit and certify
 *   spline_json.c  the JSON report of a spline
 *   spline_plot.c  the SVG plot of a spline
 *   stream.c       fit in constant memory (CSV samples of long inputs)
 *   fit.c, certify.c, curve.c   the commands
 *   surface.c      the surface command (its own options; gridded data)
 *   help.c         --help texts
 *   args.c         argv -> cli_opts
 *   main.c         picks the command
 */
#ifndef TS_CLI_H
#define TS_CLI_H

#include "trigspline.h"
#include "tsu_io.h"
#include "tsu_plot.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>

/* Exit statuses (docs/cli.md, docs/trigspline.1). */
enum {
    CLI_OK = 0,
    CLI_USAGE = 1,      /* bad option or option value */
    CLI_DATA = 2,       /* malformed input, or data the scheme refuses */
    CLI_INFEASIBLE = 3, /* no beta keeps an interval inside the region */
    CLI_VIOLATED = 4,   /* certify: the curve leaves the region */
    CLI_IO = 5,         /* cannot read or write a file (or out of memory) */
    CLI_HELP = -1       /* --help was printed: exit 0 */
};

typedef enum cli_cmd { CLI_FIT = 0, CLI_CERTIFY = 1, CLI_CURVE = 2 } cli_cmd;

/* Samples per interval when --samples is absent. */
#define CLI_DEFAULT_SAMPLES 50

/* The parsed command line.  Values of options not given are the library's
 * defaults (ts_options_init / ts_curve_options_init); *_set says "given". */
typedef struct cli_opts {
    cli_cmd cmd;
    const char *data; /* path, "-" = stdin */

    int shape_set;
    ts_shape shape;
    int has_line, has_lower, has_upper;
    ts_line line, lower, upper;

    int alpha_set, beta_set, margin_set;
    double alpha, beta, margin;
    double *alphas, *betas; /* owned */
    size_t n_alphas, n_betas;

    int slopes_set;
    ts_slopes slopes;
    int c1, form_set;
    ts_form form;

    int samples_set;
    size_t samples;
    const char *at;
    int deriv_set, deriv;
    int extrap_set;
    ts_extrap extrap;

    const char *out; /* NULL = stdout */
    int json;
    const char *svg;
    const char *title;
    int show_control, points_only;

    int columns_set;
    size_t col_x, col_y; /* 0-based */
    int no_stream;

    /* curve */
    int closed;
    int param_set;
    ts_param param;
    int box_set;
    double box[6]; /* xmin, xmax, ymin, ymax[, zmin, zmax]; ±inf = absent */
    size_t n_box;
} cli_opts;

/* ---- names.c --------------------------------------------------------- */
/* A table of names, index = enum value. */
typedef struct cli_names {
    const char *const *name;
    size_t n;
} cli_names;
extern const cli_names cli_shape_names, cli_slopes_names, cli_form_names, cli_param_names,
    cli_extrap_names;
/* Index of s in t, or -1. */
int cli_name_index(const cli_names *t, const char *s);
const char *cli_cmd_name(cli_cmd c);
/* Names of enum values as used on the command line and in JSON ("?" if unknown). */
const char *cli_shape_name(ts_shape s);
const char *cli_slopes_name(ts_slopes s);
const char *cli_form_name(ts_form f);
const char *cli_term_name(ts_term t);
const char *cli_param_name(ts_param p);
const char *cli_extrap_name(ts_extrap e);

/* ---- messages.c ------------------------------------------------------ */
#if defined(__GNUC__)
#define CLI_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define CLI_PRINTF(a, b)
#endif
/* "trigspline: ..." on stderr. */
void cli_error(const char *fmt, ...) CLI_PRINTF(1, 2);
/* "trigspline CMD: ...", then the hint to --help; returns CLI_USAGE. */
int cli_usage(cli_cmd cmd, const char *fmt, ...) CLI_PRINTF(2, 3);
/* Shortest round-trip text of v (tsu_format_double). */
const char *cli_num(double v, char buf[TSU_FMT_SIZE]);
/* "y = M*x + C" into buf. */
void cli_line_text(const ts_line *l, char *buf, size_t len);
/* "out of memory"; returns the exit status for it. */
int cli_nomem(void);

/* ---- json.c ---------------------------------------------------------- */
/* A JSON document being built (numbers shortest round-trip, NaN/Inf -> null). */
typedef struct cli_json {
    tsu_plot_buf b;
    int need_comma;
    int nl; /* next separator starts a new line */
    int failed;
} cli_json;
void cli_json_init(cli_json *j);
void cli_json_free(cli_json *j);
void cli_json_raw(cli_json *j, const char *s);
void cli_json_nl(cli_json *j); /* put the next item on a new line */
void cli_json_key(cli_json *j, const char *key); /* also writes the comma before */
void cli_json_begin(cli_json *j, char c);        /* '{' or '[' as a value */
void cli_json_end(cli_json *j, char c);          /* '}' or ']' */
void cli_json_num(cli_json *j, double v);        /* as a value (comma handled) */
void cli_json_uint(cli_json *j, unsigned long long v);
void cli_json_bool(cli_json *j, int v);
void cli_json_null(cli_json *j);
void cli_json_str(cli_json *j, const char *s);
/* key + value shorthands */
void cli_json_knum(cli_json *j, const char *k, double v);
void cli_json_kuint(cli_json *j, const char *k, unsigned long long v);
void cli_json_kbool(cli_json *j, const char *k, int v);
void cli_json_kstr(cli_json *j, const char *k, const char *s);
void cli_json_kline(cli_json *j, const char *k, const ts_line *l); /* NULL -> null */

/* ---- output.c -------------------------------------------------------- */
/*
 * Outputs of one command, written only when everything succeeded: the main
 * output (text in memory, or a callback that streams rows) to -o / stdout and
 * the SVG to --svg, each through a temporary file renamed into place.
 * Returns CLI_OK or CLI_IO (message printed); nothing is left behind on failure.
 */
typedef int (*cli_writer_fn)(void *ctx, FILE *fp); /* 0 or an errno */

/* An output: tsu_out (temporary file + rename; "-" = stdout), except that an
 * existing target that is not a regular file (/dev/null, a FIFO, /dev/stdout)
 * is opened and written directly: renaming over it would replace the device. */
typedef struct cli_out {
    tsu_out *o;
    FILE *direct;
} cli_out;
/* 0 or an errno (message in msg). */
int cli_out_open(cli_out *c, const char *path, char *msg, size_t len);
FILE *cli_out_file(const cli_out *c);
int cli_out_commit(cli_out *c, char *msg, size_t len);
void cli_out_abort(cli_out *c);
int cli_write_outputs(const char *out_path, const tsu_plot_buf *text, cli_writer_fn fn,
                      void *fn_ctx, const char *svg_path, const tsu_plot_buf *svg);

/* ---- sample.c -------------------------------------------------------- */
/* Sampling: m points per interval of [i0, i1) (knots included, the right
 * knot belongs to the next interval), plus x_{i1} when with_end.  The sink
 * receives blocks; it returns 0 or an errno that stops the walk. */
typedef int (*cli_sink)(void *ctx, const double *x, const double *y, size_t k);
int cli_sample(const ts_spline *s, size_t i0, size_t i1, int with_end, size_t m, int deriv,
               cli_sink sink, void *ctx);

/* Growable pair of double arrays (failed: an allocation failed, nothing
 * more is added). */
typedef struct cli_xy {
    double *x, *y;
    size_t n, cap;
    int failed;
} cli_xy;
void cli_xy_push(cli_xy *a, double x, double y);
void cli_xy_free(cli_xy *a);

/* Least and greatest y seen, and how many. */
typedef struct cli_stats {
    double lo, hi;
    unsigned long long count;
} cli_stats;
#define CLI_STATS_INIT {(double)INFINITY, -(double)INFINITY, 0}

/* Sinks: ctx is a cli_stats, a cli_xy (ENOMEM when it failed), or a
 * tsu_writer ("x,y" rows; its errno). */
int cli_sink_stats(void *ctx, const double *x, const double *y, size_t k);
int cli_sink_xy(void *ctx, const double *x, const double *y, size_t k);
int cli_sink_writer(void *ctx, const double *x, const double *y, size_t k);

/* ---- data.c ---------------------------------------------------------- */
typedef struct cli_data {
    const char *name; /* for messages: the path, or "<stdin>" */
    size_t n;         /* points */
    size_t dim;       /* columns kept (2 for fit/certify; 2 or 3 for curve) */
    double *col[3];   /* borrowed from t */
    unsigned long long *line;
    tsu_table t;
} cli_data;
/* Read DATA: fit/certify keep two columns (x, f; --columns picks them);
 * curve keeps 2 or 3.  Returns CLI_OK, CLI_DATA or CLI_IO (message printed). */
int cli_read_data(const cli_opts *o, cli_data *d);
void cli_data_free(cli_data *d);
/* Report a ts_spline_new failure on points x[0..n) (lines[i] their lines,
 * NULL if unknown) read from name.  Returns the exit status. */
int cli_report_build_error(const cli_opts *o, const ts_options *opt, const char *name,
                           const double *x, const double *f,
                           const unsigned long long *lines, size_t n, const ts_error *e,
                           ts_status st, size_t index_offset);
/* Read DATA (cli_read_data) and fit the spline with opt; on failure the
 * error is reported (cli_report_build_error), d freed, *s NULL.  Returns the
 * exit status. */
int cli_read_and_fit(const cli_opts *o, const ts_options *opt, cli_data *d, ts_spline **s);
/* Map an I/O reader failure to an exit status (message printed). */
int cli_report_io(const tsu_io_error *e);

/* ---- fit_options.c --------------------------------------------------- */
/* Fill opt from o (fit and certify).  Returns CLI_OK or CLI_USAGE (message
 * printed). */
int cli_fit_options(const cli_opts *o, ts_options *opt);
/* The boundaries certify checks (after cli_fit_options succeeded): the
 * resolved shape and the lower / upper lines (*hl, *hu: present). */
void cli_certify_bounds(const cli_opts *o, ts_shape *sh, ts_line *lo, int *hl, ts_line *up,
                        int *hu);

/* ---- spline_json.c --------------------------------------------------- */
/* The report of fit --json and certify --json: lower / upper are the
 * boundaries (NULL: none), reps the interval reports (NULL: asked of s),
 * smp the statistics of the samples. */
void cli_spline_json(cli_json *j, const cli_opts *o, const ts_spline *s, ts_shape shape,
                     const ts_line *lower, const ts_line *upper, int certified,
                     const ts_interval_report *reps, const cli_stats *smp);

/* ---- spline_plot.c --------------------------------------------------- */
/* Render the plot of a spline read from name into svg; bad: points to mark
 * (NULL or empty: none).  Returns CLI_OK or an exit status (message printed). */
int cli_spline_plot(const cli_opts *o, const char *name, const ts_spline *s, ts_shape shape,
                    const ts_line *lower, const ts_line *upper, const cli_xy *bad,
                    tsu_plot_buf *svg);

/* ---- stream.c -------------------------------------------------------- */
/* 1 when fit can stream (CSV samples only, see stream.c). */
int cli_can_stream(const cli_opts *o);
/* The environment variable TRIGSPLINE_CHUNK overrides the chunk size (tests
 * of chunk borders), TRIGSPLINE_DEBUG reports border rebuilds. */
int cli_fit_stream(const cli_opts *o, const ts_options *opt);

/* ---- fit.c, certify.c, curve.c --------------------------------------- */
int cli_fit(cli_opts *o);
int cli_certify(cli_opts *o);
int cli_curve(cli_opts *o);
/* surface.c: the whole `surface` command, its own options (argv after it). */
int cli_surface(int argc, char **argv);

/* ---- help.c ---------------------------------------------------------- */
void cli_print_help(cli_cmd cmd);
void cli_print_main_help(void);

/* ---- args.c ---------------------------------------------------------- */
/* Parse argv (after the sub-command).  Returns CLI_OK, CLI_USAGE (message
 * printed) or CLI_HELP (help printed). */
int cli_parse(cli_cmd cmd, int argc, char **argv, cli_opts *o);
void cli_opts_free(cli_opts *o);

#endif
