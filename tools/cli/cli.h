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
 *   table.c        reading DATA rows: options, columns by name, missing values
 *   data.c         reading DATA, explaining data and scheme errors
 *   fit_options.c  cli_opts -> ts_spline_options (fit, certify), ts_curve_options (curve)
 *   axis.c         date and log ticks of plots
 *   spline_json.c  the JSON report of a spline
 *   spline_plot.c  the SVG plot of a spline
 *   stream.c       fit in constant memory (CSV samples of long inputs)
 *   overshoot.c    the curve's excursions beyond the data
 *   options.c      the one table of every command's options, their values
 *   help.c         --help texts, generated from the table
 *   args.c         argv -> cli_opts / cli_surface_opts
 *   curve_json.c   the JSON report of a parametric curve
 *   curve_plot.c   the SVG plot of a parametric curve
 *   surface_plot.c the SVG heatmap of a surface
 *   fit.c, certify.c, curve.c   the commands
 *   surface.c      the surface command (gridded data)
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

typedef enum cli_cmd { CLI_FIT = 0, CLI_CERTIFY = 1, CLI_CURVE = 2, CLI_SURFACE = 3 } cli_cmd;

typedef enum cli_plot_format { CLI_PLOT_SVG = 0, CLI_PLOT_PNG = 1, CLI_PLOT_PDF = 2 } cli_plot_format;

/* Most sample points a command holds in memory (the plot's curve, curve's
 * CSV, --json --with-samples): beyond it --samples is refused (the streaming
 * CSV of fit has no limit). */
#define CLI_MAX_HELD_SAMPLES 10000000u

/* The parsed command line.  Values of options not given are the library's
 * defaults (ts_spline_options_init / ts_curve_options_init); *_set says "given". */
typedef struct cli_opts {
    cli_cmd cmd;
    const char *data; /* path, "-" = stdin */

    int shape_set;
    ts_shape shape;
    int has_line, has_lower, has_upper;
    ts_line line, lower, upper;
    ts_constraint *cons; /* --constraint, --constraints (owned; constraints.c) */
    size_t n_cons;

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
    const char *svg; /* the plot file (--svg, --png or --pdf), any format */
    const char *title;
    int show_control, points_only;

    int columns_set;
    char *xcol, *ycol; /* --columns / --x / --y: a 1-based number or a header name (owned) */
    int no_stream;

    /* reading DATA (table.c) */
    char delim;        /* 0: auto; ',', ';', '\t', ' ' */
    int decimal_comma;
    const char *na;    /* missing-value words */
    int missing_skip;  /* --missing skip */
    unsigned long long skip;
    int x_time;        /* --x-time */
    int verbose;

    /* more outputs */
    int grid_set;
    double grid_a, grid_b;
    size_t grid_n;
    double *at_list; /* --at X1,X2,... (owned); NULL: --at names a file */
    size_t n_at;
    size_t samples_total; /* 0: per-interval --samples */
    int with_samples;
    int format_set;
    cli_plot_format plot_format; /* of the plot written to o->svg (--svg / --png / --pdf) */
    const char *xlabel, *ylabel;
    int logy;
    unsigned width, height;

    /* curve */
    int closed;
    int param_set;
    ts_param param;
    int box_set;
    double box[6]; /* xmin, xmax, ymin, ymax[, zmin, zmax]; ±inf = absent */
    size_t n_box;

    /* reading DATA, more (table.c) */
    const char *date_format; /* --date-format: x read with tsu_parse_time_format */
    int units_row;           /* --units-row: the line after the header is skipped */
    /* --step S: samples at the multiples of S (of the seconds of step_unit for
     * a time x; step_unit 0: a plain number) */
    int step_set;
    double step;
    double step_unit;
    const char *step_text;
} cli_opts;

/* ---- names.c --------------------------------------------------------- */
/* Enum values are written with the library's vocabulary (ts_vocab_name,
 * ts_vocab_value, ts_vocab_count): one canonical name per value. */
/* "fit", "certify", "curve", "surface". */
const char *cli_cmd_name(cli_cmd c);
/* ts_vocab_name, "?" if unknown. */
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
/* Where cli_error, cli_usage and the option parsers write their messages:
 * stderr, unless cli_set_messages gave another stream (NULL: back to stderr;
 * the parser's fuzz harness, tests/fuzz/fuzz_cli.c, captures them). */
void cli_set_messages(FILE *fp);
FILE *cli_messages(void);
/* "trigspline: ..." on cli_messages(). */
void cli_error(const char *fmt, ...) CLI_PRINTF(1, 2);
/* Map an I/O reader failure to an exit status (message printed). */
int cli_report_io(const tsu_io_error *e);
/* "trigspline CMD: ...", then the hint to --help; returns CLI_USAGE. */
int cli_usage(cli_cmd cmd, const char *fmt, ...) CLI_PRINTF(2, 3);
/* Shortest round-trip text of v (tsu_format_double). */
const char *cli_num(double v, char buf[TSU_FMT_SIZE]);
/* v to sig significant digits (1 to 17; "%.*g" without trailing zeros), for
 * texts meant for a reader rather than for a program: 4.69, -2.69e+05. */
const char *cli_num_sig(double v, int sig, char buf[TSU_FMT_SIZE]);
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
/* 1: the same path, or two names of one existing file (stat(2) only):
 * -o and the plot must differ. */
int cli_same_file(const char *a, const char *b);
/* CLI_OK, or CLI_USAGE (message printed) when DATA is a regular file that -o
 * or the plot would replace (same st_dev and st_ino: ./name, links). */
int cli_check_not_data(cli_cmd cmd, const char *data, const char *out, const char *svg);
/* 0 or an errno (message in msg). */
int cli_out_open(cli_out *c, const char *path, char *msg, size_t len);
FILE *cli_out_file(const cli_out *c);
int cli_out_commit(cli_out *c, char *msg, size_t len);
void cli_out_abort(cli_out *c);
int cli_write_outputs(const char *out_path, const tsu_plot_buf *text, cli_writer_fn fn,
                      void *fn_ctx, const char *plot_path, cli_plot_format fmt,
                      const tsu_plot_buf *svg);
/* The environment variable TRIGSPLINE_SVG_CONVERTER names the program that
 * turns SVG into PNG / PDF (default rsvg-convert, Debian package
 * librsvg2-bin); it is run as  PROG -f png|pdf  with the SVG on standard
 * input and the file on standard output.  A writer_fn returning ECANCELED
 * has reported its error itself (exit status CLI_DATA). */

/* ---- sample.c -------------------------------------------------------- */
/* Sampling: m points per interval of [i0, i1) (knots included, the right
 * knot belongs to the next interval), plus x_{i1} when with_end.  The sink
 * receives blocks; it returns 0 or an errno that stops the walk. */
typedef int (*cli_sink)(void *ctx, const double *x, const double *y, size_t k);
int cli_sample(const ts_spline *s, size_t i0, size_t i1, int with_end, size_t m, int deriv,
               cli_sink sink, void *ctx);
/* The same, continuing after the x *prev (updated): x strictly increasing
 * across calls (repeated positions at large |x| are left out). */
int cli_sample_after(const ts_spline *s, size_t i0, size_t i1, int with_end, size_t m, int deriv,
                     cli_sink sink, void *ctx, double *prev);
/* n points evenly over [a, b] (both included; repeats left out).  0, an
 * errno of the sink, or -1: an evaluation failed (outside the data without
 * --extrapolate; *err, *bad_x). */
int cli_sample_even(const ts_spline *s, double a, double b, size_t n, int deriv, cli_sink sink,
                    void *ctx, ts_error *err, double *bad_x);
/* Points at a step: x_j = base + j * num / den for j = j0 .. j0 + n - 1
 * (num, den integers, so that a decimal step such as 0.1 gives the doubles
 * nearest to 0.3, 0.7, ...; den 1 and num any double when the step has too
 * many digits). */
typedef struct cli_step_grid {
    double base, num, den, j0;
    size_t n;
} cli_step_grid;
double cli_step_x(const cli_step_grid *g, double j);
/* The grid of step text (a decimal number) times unit over [a, b]: aligned
 * (the multiples of the step counted from base) or from a.  0, or -1 when
 * more than max points (g->n is then max + 1). */
int cli_step_grid_make(const char *text, double unit, double a, double b, int aligned,
                       double base, size_t max, cli_step_grid *g);
/* The points of g (as cli_sample_even). */
int cli_sample_step(const ts_spline *s, const cli_step_grid *g, int deriv, cli_sink sink,
                    void *ctx, ts_error *err, double *bad_x);

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
 * cli_csv_sink ("x,y" rows, x as a date when the columns say so; its errno). */
typedef struct cli_csv_sink {
    tsu_writer *w;
    const struct cli_cols *cols; /* NULL: plain numbers */
} cli_csv_sink;
int cli_sink_stats(void *ctx, const double *x, const double *y, size_t k);
int cli_sink_xy(void *ctx, const double *x, const double *y, size_t k);
int cli_sink_writer(void *ctx, const double *x, const double *y, size_t k);

/* ---- table.c --------------------------------------------------------- */
/* The x and y columns of DATA: indices, names for the outputs ("x", "y"
 * without a header), whether x holds dates, rows skipped for missing values. */
struct cli_cols {
    size_t ix, iy;
    char xname[256], yname[256];
    int x_time;
    tsu_time_form tform; /* of the first x value, when x_time */
    unsigned long long skipped;
};
typedef struct cli_cols cli_cols;
/* Reader options from --delimiter, --decimal-comma, --na, --skip (dates detected). */
void cli_read_options(const cli_opts *o, tsu_read_options *ro);
/* Before the first row: resolve --columns / --x / --y (numbers or header
 * names; tsu_reader_layout) and have the reader parse only those two columns,
 * so the others may hold any text (a numeric choice also limits the header
 * test to them).  CLI_OK or an exit status (message printed). */
int cli_cols_select(const cli_opts *o, tsu_reader *r, const char *name, cli_cols *c);
/* After the first row: whether x is a time (--x-time checked; y must not be).
 * CLI_OK or CLI_DATA (message printed). */
int cli_cols_resolve(const cli_opts *o, const tsu_reader *r, const char *name, cli_cols *c);
/* x, y of row: 1 taken, 0 skipped (missing, --missing skip), -1 error
 * (missing, --missing error; message printed). */
int cli_cols_take(const cli_opts *o, const tsu_reader *r, const char *name, const double *row,
                  cli_cols *c, double *x, double *y);
/* A name as a CSV field (quoted when needed). */
void cli_cols_csv_name(const char *nm, char *buf, size_t len);
/* The name of the y column of the output: y, d_y_dx, d2_y_dx2. */
void cli_cols_y_header(const cli_cols *c, int deriv, char *buf, size_t len);
/* "x,y\n" with the names; 0 or -1 (no memory). */
int cli_header_line(const cli_cols *c, int deriv, tsu_plot_buf *b);
/* x as written: an ISO 8601 date when x is a time, else the shortest number. */
const char *cli_x_text(const cli_cols *c, double x, char buf[TSU_TIME_SIZE]);

/* ---- data.c ---------------------------------------------------------- */
struct cli_data {
    const char *name; /* for messages: the path, or "<stdin>" */
    size_t n;         /* points */
    size_t dim;       /* columns kept (2 for fit/certify; 2 or 3 for curve) */
    double *col[3];   /* owned */
    unsigned long long *line;
    cli_cols cols;    /* fit / certify: the columns and their names */
};
typedef struct cli_data cli_data;
/* Read DATA: fit/certify keep two columns (x, f; --columns picks them);
 * curve keeps 2 or 3.  Returns CLI_OK, CLI_DATA or CLI_IO (message printed). */
int cli_read_data(const cli_opts *o, cli_data *d);
void cli_data_free(cli_data *d);
/* Report a ts_spline_new failure on points x[0..n) (lines[i] their lines,
 * NULL if unknown; index_offset the index of x[0] in the whole data) read
 * from name: "NAME:LINE: " (an interval: "NAME:LINE-LINE: ") and the
 * library's sentence (ts_error_message), x written as cli_x_text(cols)
 * (cols NULL: numbers).  Returns the exit status. */
int cli_report_build_error(const cli_opts *o, const ts_spline_options *opt, const char *name,
                           const cli_cols *cols, const double *x, const double *f,
                           const unsigned long long *lines, size_t n, const ts_error *e,
                           ts_status st, size_t index_offset);
/* Read DATA (cli_read_data) and fit the spline with opt; on failure the
 * error is reported (cli_report_build_error), d freed, *s NULL.  Returns the
 * exit status. */
int cli_read_and_fit(const cli_opts *o, const ts_spline_options *opt, cli_data *d, ts_spline **s);

/* ---- fit_options.c --------------------------------------------------- */
/* The checks of options that depend on each other, after cli_parse; like
 * it they read no file and print only on cli_messages().
 * Fill opt from o (fit and certify).  Returns CLI_OK or CLI_USAGE (message
 * printed). */
int cli_fit_options(const cli_opts *o, ts_spline_options *opt);
/* Fill co from o (curve; the box as given, whatever the data's dimension).
 * Returns CLI_OK or CLI_USAGE (message printed). */
int cli_curve_options(const cli_opts *o, ts_curve_options *co);
/* The boundaries certify checks (after cli_fit_options succeeded): the
 * resolved shape and the lower / upper lines (*hl, *hu: present). */
void cli_certify_bounds(const cli_opts *o, ts_shape *sh, ts_line *lo, int *hl, ts_line *up,
                        int *hu);

/* ---- axis.c ---------------------------------------------------------- */
/* tsu_plot_tick_fn for a time axis (ctx: the tsu_time_form of x; ticks at
 * whole seconds / minutes / hours / days / months / years in its zone) and
 * for a log10 y axis (ctx unused; the plot holds log10 y; ticks at decades). */
void cli_time_ticks(void *ctx, tsu_plot_ticks *t);
void cli_log_ticks(void *ctx, tsu_plot_ticks *t);

/* ---- spline_json.c --------------------------------------------------- */
/* The report of fit --json and certify --json ("schema": "trigspline-fit/1"):
 * lower / upper are the boundaries (NULL: none), reps the interval reports
 * (NULL: asked of s), smp the statistics of the samples, d the data (column
 * names, rows skipped), held the samples themselves (--with-samples; NULL:
 * not written). */
void cli_spline_json(cli_json *j, const cli_opts *o, const ts_spline *s, ts_shape shape,
                     const ts_line *lower, const ts_line *upper, int certified,
                     const ts_interval_report *reps, const cli_stats *smp,
                     const struct cli_data *d, const cli_xy *held);

/* ---- spline_plot.c --------------------------------------------------- */
/* Render the plot of a spline read from name into svg; bad: points to mark
 * (NULL or empty: none).  Returns CLI_OK or an exit status (message printed). */
int cli_spline_plot(const cli_opts *o, const struct cli_data *d, const ts_spline *s, ts_shape shape,
                    const ts_line *lower, const ts_line *upper, cli_xy *bad,
                    tsu_plot_buf *svg);

/* Axis labels (--xlabel / --ylabel, else the column names of c, else
 * xdef / ydef), a date axis when x is a time, decades with --logy. */
tsu_plot_status cli_plot_axes(const cli_opts *o, tsu_plot *p, const cli_cols *c, const char *xdef,
                              const char *ydef);

/* ---- stream.c -------------------------------------------------------- */
/* 1 when fit can stream (CSV samples only, see stream.c). */
int cli_can_stream(const cli_opts *o);
/* The environment variable TRIGSPLINE_CHUNK overrides the chunk size (tests
 * of chunk borders), TRIGSPLINE_DEBUG reports border rebuilds. */
int cli_fit_stream(const cli_opts *o, const ts_spline_options *opt);

/* ---- overshoot.c ----------------------------------------------------- */
/* The curve's range and its largest excursions beyond the data of an
 * interval (the report's y_min ... excursion_below, docs/method.md §5.9),
 * gathered over the intervals written.  A warning is printed when an
 * excursion exceeds CLI_OVERSHOOT_FRACTION of the data range (docs/cli.md). */
#define CLI_OVERSHOOT_FRACTION 0.1
typedef struct cli_overshoot {
    double data_min, data_max; /* of the knots seen */
    double y_min, y_max;       /* of the curve */
    double above, below;       /* largest excursion_above, excursion_below */
    size_t i_above, i_below;   /* their intervals (global index) */
    ts_interval_report r_above, r_below;
    size_t count;              /* intervals seen */
    int warn_only;             /* set after cli_overshoot_init when only the warning is wanted:
                                  intervals whose control values (docs/method.md §2, convex hull)
                                  bound both excursions well below CLI_OVERSHOOT_FRACTION of
                                  the data range so far are not computed exactly, so y_min,
                                  y_max, above and below then cover only the others */
} cli_overshoot;
void cli_overshoot_init(cli_overshoot *w);
/* Intervals [i0, i1) of s; offset = the global index of s's interval 0. */
void cli_overshoot_add(cli_overshoot *w, const ts_spline *s, size_t i0, size_t i1, size_t offset);
/* The larger excursion relative to the data range (0 for no data). */
double cli_overshoot_ratio(const cli_overshoot *w);
/* One warning line on stderr when cli_overshoot_ratio > CLI_OVERSHOOT_FRACTION
 * (x written as cli_x_text(c)). */
void cli_overshoot_warn(const cli_overshoot *w, const cli_cols *c);
/* The "overshoot" object of the JSON report. */
void cli_overshoot_json(cli_json *j, const cli_overshoot *w);

/* ---- options.c ------------------------------------------------------- */
/* The surface command's options (docs/cli.md). */
typedef struct cli_surface_opts {
    const char *data, *out, *svg; /* svg: the plot's file, in format fmt */
    const char *lower_grid, *upper_grid; /* gridded fields (shape grids), in DATA's layout */
    cli_plot_format fmt;
    int matrix_in, matrix_out, json;
    ts_surface_options so;
    size_t samples, grid_x, grid_y; /* samples 1 to 1e7; grid: 0 (none) or 2 to 1e7 each */
} cli_surface_opts;

/* Which commands take an option: bit 1 << cli_cmd. */
enum {
    CLI_F = 1u << CLI_FIT,
    CLI_C = 1u << CLI_CERTIFY,
    CLI_V = 1u << CLI_CURVE,
    CLI_S = 1u << CLI_SURFACE
};

/* How an option's value is read into its field (the option's off, in
 * cli_opts, or in cli_surface_opts for surface's own rows). */
typedef enum cli_kind {
    CLI_K_HELP,   /* --help: the parser returns CLI_HELP */
    CLI_K_FLAG,   /* no value: int field = 1 */
    CLI_K_TEXT,   /* const char * field = the value */
    CLI_K_FILE,   /* the same, the value a non-empty file name */
    CLI_K_POS,    /* double field: a finite number > 0 */
    CLI_K_NONNEG, /* double field: a finite number >= 0 */
    CLI_K_ENUM,   /* int-sized enum field: a name of vocab, not one in skip */
    CLI_K_COUNT,  /* size_t field: an integer (digits) from lo to hi */
    CLI_K_CUSTOM  /* fn */
} cli_kind;

/* Help sections (help.c lists an option under its group). */
typedef enum cli_group {
    CLI_G_NONE, /* not listed (--help) */
    CLI_G_SHAPE, CLI_G_PARAM, CLI_G_OUTPUT, CLI_G_PLOT, CLI_G_INPUT
} cli_group;

typedef struct cli_optdef cli_optdef;
/* Read value v of the option named name (as given) into the options o (a
 * cli_opts or a cli_surface_opts).  CLI_OK or CLI_USAGE (message printed). */
typedef int (*cli_opt_fn)(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v,
                          void *o);

#define CLI_NO_FIELD ((size_t)-1)

/* One option of one or more commands.  An option name may have several rows
 * (other commands, another field or help text): a command takes the first
 * row with its bit. */
struct cli_optdef {
    const char *name;  /* "--shape"; NULL: the short name only */
    const char *sname; /* "-o", or NULL */
    const char *meta;  /* the value's name in help ("M,C"), NULL: takes no value;
                          CLI_K_ENUM: NULL (the names, from the vocabulary) */
    unsigned cmds;     /* CLI_F | CLI_C | CLI_V | CLI_S */
    cli_kind kind;
    size_t off;        /* the field */
    size_t set;        /* an int field set to 1 when given, or CLI_NO_FIELD */
    ts_vocab vocab;    /* CLI_K_ENUM */
    unsigned skip;     /* CLI_K_ENUM: bit k = value k is not offered */
    double lo, hi;     /* CLI_K_COUNT: the range */
    double def;        /* a default of the command's own for a size_t field (not
                          the library's: sample counts), NAN: none */
    const char *tdef;  /* CLI_K_TEXT: the same, NULL: none */
    cli_opt_fn fn;     /* CLI_K_CUSTOM */
    cli_group group;
    const char *help;  /* "%D": the default; "\n": a new line of the text */
};
extern const cli_optdef cli_optdefs[];
extern const size_t cli_n_optdefs;
/* The options of cmd before argv: the library's defaults (ts_spline_options_init,
 * ts_curve_options_init, ts_surface_options_init) and the rows' def; o is a
 * cli_opts, or a cli_surface_opts for CLI_SURFACE. */
void cli_opts_defaults(cli_cmd cmd, void *o);
/* The first row of one of cmds (CLI_F | ...) named s[0..len) (long or
 * short name), or NULL; *nm: the name matched. */
const cli_optdef *cli_optdef_find(unsigned cmds, const char *s, size_t len, const char **nm);
/* Read value v (NULL for an option without one) as row d says. */
int cli_optdef_apply(const cli_optdef *d, cli_cmd cmd, const char *name, const char *v, void *o);

/* ---- help.c ---------------------------------------------------------- */
/* --help of a command, generated from cli_optdefs (defaults: cli_opts_defaults). */
void cli_print_help(cli_cmd cmd);
void cli_print_main_help(void);

/* ---- args.c ---------------------------------------------------------- */
/* Parse argv (after the sub-command).  Returns CLI_OK, CLI_USAGE (message
 * printed on cli_messages()) or CLI_HELP (--help given: the caller prints
 * cli_print_help).  Only stat(2) is called (to tell whether -o and the plot
 * name one file); nothing is read, written or printed elsewhere.  Call
 * cli_opts_free afterwards whatever it returned. */
int cli_parse(cli_cmd cmd, int argc, char **argv, cli_opts *o);
void cli_opts_free(cli_opts *o);
/* The same for surface (argv after "surface"); allocates nothing. */
int cli_surface_parse(int argc, char **argv, cli_surface_opts *o);

/* ---- curve_json.c, curve_plot.c -------------------------------------- */
/* A built, sampled and (with a box) certified curve. */
typedef struct cli_curve_run {
    const ts_curve *c;
    const ts_curve_options *co;
    size_t dim, n, seg;                  /* dimension, points, segments */
    size_t rows;                         /* samples: rows of t, x, y[, z] */
    const double *smp;
    const ts_interval_report *reps;      /* dim per segment; NULL: no box */
    int certified;                       /* with a box: every segment inside */
    double min_gap;                      /* with a box: the least gap */
} cli_curve_run;
/* The report of curve --json ("command": "curve"). */
void cli_curve_json(cli_json *j, const cli_opts *o, const cli_curve_run *cr);
/* The plot of curve --svg into svg.  CLI_OK or CLI_IO (message printed). */
int cli_curve_plot(const cli_opts *o, const cli_data *d, const cli_curve_run *cr,
                   tsu_plot_buf *svg);

/* ---- constraints.c ----------------------------------------------------- */
/* --constraint SPEC (docs/cli.md) appended to o->cons; CLI_OK or CLI_USAGE. */
int cli_constraint_add(cli_opts *o, cli_cmd cmd, const char *name, const char *spec);
/* --constraints FILE: a JSON array of SPEC strings or objects {"kind", "value",
 * "points", "first", "count"}. */
int cli_constraints_file(cli_opts *o, cli_cmd cmd, const char *name, const char *path);
void cli_constraints_free(cli_opts *o);
/* "constraints": per record, per interval {active, gap, at, certified} or null. */
void cli_constraints_json(cli_json *j, const ts_spline *s);

/* ---- text.c ----------------------------------------------------------- */
/* Text appended to b until an append fails (bad set: the text is then
 * incomplete and must not be written; report out of memory). */
typedef struct cli_text {
    tsu_plot_buf *b;
    int bad;
} cli_text;
void cli_text_puts(cli_text *w, const char *s);
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void cli_text_printf(cli_text *w, const char *fmt, ...);

/* ---- surface_plot.c -------------------------------------------------- */
/* The heatmap of surface s through the grid x, y, z (z[j*nx + i]) built with
 * so: viridis, or a diverging map centred on 0 when the values straddle 0;
 * contours, axis ticks, colour bar; the patches where the shape scheme
 * acts (the surface built without it leaves the bounds; else active[c])
 * hatched.  rep, active: per patch, or NULL.  0 or ENOMEM. */
int cli_surface_plot(const double *x, size_t nx, const double *y, size_t ny, const double *z,
                     const ts_surface *s, const ts_surface_options *so,
                     const ts_patch_report *rep, const int *active, tsu_plot_buf *svg);

/* ---- fit.c, certify.c, curve.c, surface.c ---------------------------- */
int cli_fit(cli_opts *o);
int cli_certify(cli_opts *o);
int cli_curve(cli_opts *o);
/* The whole surface command (argv after "surface"). */
int cli_surface(int argc, char **argv);
/* disaggregate.c: trigspline disaggregate (bin totals to a finer grid). */
int cli_disaggregate(int argc, char **argv);

#endif
