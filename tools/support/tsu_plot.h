/*
 * tsu_plot — dependency-free SVG plots for the command-line tool and the demo
 * page (tool side: part of the static library trigspline_support, not of
 * libtrigspline).  Only the C standard library is used.
 *
 * Prefix tsu_ / TSU_ ("trigspline support"), never ts_: these are not the
 * library's API and know nothing of it (no trigspline.h, no src/internal.h).
 *
 * Usage:
 *
 *     tsu_plot *p;
 *     if (tsu_plot_new(0, 0, &p) != TSU_PLOT_OK) ...;     // 720 x 450 px
 *     tsu_plot_set_title(p, "Table 1");
 *     tsu_plot_set_labels(p, "x", "f(x)");
 *     tsu_plot_add_floor(p, 0.0, "f = 0", NULL);         // shaded region y < 0
 *     tsu_plot_add_polyline(p, xs, ys, 2000, "spline", NULL);
 *     tsu_plot_add_points(p, x, f, 9, "data", NULL);
 *     tsu_plot_save(p, "fig.svg");
 *     tsu_plot_free(p);
 *
 * What is drawn:
 *  - series, in this order whatever the order of the calls: shaded regions
 *    (with their boundary line), then polylines and straight lines in the
 *    order added, then point markers on top;
 *  - a frame, light grid lines at the ticks, tick labels, title, axis labels
 *    and a legend of every series that has a non-empty label.
 *
 * Axes.  Unless fixed by tsu_plot_set_xrange / _yrange, each range is the
 * extent of the data widened by 4 % on both sides (R's convention), and the
 * ticks are the multiples of a 1-2-5 step inside it (see tsu_plot_ticks_compute).
 * The x range comes from points and polylines; the y range also includes
 * the straight lines and region boundaries at the two ends of the data's x
 * extent, so constraint lines are always visible.  A range narrower than
 * 1e-10 of its magnitude (or than 1e-200) is widened to ±10 % of its value
 * (±1 around zero).  Very large or very small tick values are written as
 * short numbers with a common factor "×10^k" at the end of the axis.
 *
 * Numbers.  NaN or ±Inf coordinates, and values of magnitude above
 * TSU_PLOT_MAX_ABS, are skipped: they end a polyline (the next finite point
 * starts a new one) and are ignored for the ranges.  Lines and polylines
 * are clipped to the plot area by computation (no clipPath, so any number of
 * plots can be inlined in one HTML page without id clashes); so are points.
 * The output never contains "nan" or "inf".  Pixel coordinates have at most
 * two decimals; polylines drop vertices that lie within a tolerance of the
 * simplified line (default 0.1 px, tsu_plot_set_simplify).
 *
 * Text.  Titles and labels are UTF-8.  They are written as pure ASCII
 * XML: &, <, >, " and ' escaped, every non-ASCII character as a numeric
 * character reference, invalid UTF-8 bytes as U+FFFD, control characters as
 * spaces.  So the SVG is valid XML in any encoding and can be pasted into an
 * HTML page as is (tsu_plot_set_xml_declaration(p, 0) drops the <?xml?> line).
 *
 * Errors.  Every function that can fail returns a tsu_plot_status; nothing
 * aborts or prints.  Sizes are checked for overflow before allocating.
 * A failed call leaves the plot as it was.  Not thread-safe per plot object
 * (different plot objects may be used by different threads, except for the
 * test hook tsu_plot_test_fail_alloc_after).
 */
#ifndef TSU_PLOT_H
#define TSU_PLOT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum tsu_plot_status {
    TSU_PLOT_OK = 0,
    TSU_PLOT_ERR_NULL = 1,     /* a required pointer is NULL */
    TSU_PLOT_ERR_NOMEM = 2,    /* allocation failed */
    TSU_PLOT_ERR_OVERFLOW = 3, /* a size computation would overflow size_t */
    TSU_PLOT_ERR_ARG = 4,      /* an argument out of range: size, colour, range, NaN coefficient... */
    TSU_PLOT_ERR_IO = 5        /* writing or opening the output failed */
} tsu_plot_status;

/* A fixed, never-NULL English string for any value. */
const char *tsu_plot_strerror(tsu_plot_status st);

/* Coordinates of larger magnitude are treated as missing (like NaN). */
#define TSU_PLOT_MAX_ABS 1e300

/* ------------------------------------------------------------------ */
/* Growable string buffer (also handy for building a whole HTML page)   */
/* ------------------------------------------------------------------ */

/* data is NUL-terminated whenever it is not NULL; len excludes the NUL.
 * Zero-initialise (TSU_PLOT_BUF_INIT) or call tsu_plot_buf_init. */
typedef struct tsu_plot_buf {
    char *data;
    size_t len;
    size_t cap;
} tsu_plot_buf;
#define TSU_PLOT_BUF_INIT {NULL, 0, 0}

void tsu_plot_buf_init(tsu_plot_buf *b);
/* Frees the memory and re-initialises; NULL is a no-op. */
void tsu_plot_buf_free(tsu_plot_buf *b);
/* Append n bytes / a C string.  On failure b is unchanged.
 * TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_NOMEM, TSU_PLOT_ERR_OVERFLOW. */
tsu_plot_status tsu_plot_buf_append(tsu_plot_buf *b, const char *s, size_t n);
tsu_plot_status tsu_plot_buf_puts(tsu_plot_buf *b, const char *s);
/* printf-style append; also TSU_PLOT_ERR_ARG if the format fails. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
tsu_plot_status tsu_plot_buf_printf(tsu_plot_buf *b, const char *fmt, ...);
/* The same with a va_list (ap is used up). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 0)))
#endif
tsu_plot_status tsu_plot_buf_vprintf(tsu_plot_buf *b, const char *fmt, va_list ap);
/* Append UTF-8 text escaped for XML/HTML as described above (pure ASCII). */
tsu_plot_status tsu_plot_buf_xml(tsu_plot_buf *b, const char *text);

/* ------------------------------------------------------------------ */
/* Ticks                                                                */
/* ------------------------------------------------------------------ */

#define TSU_PLOT_MAX_TICKS 16
#define TSU_PLOT_LABEL_MAX 32

typedef struct tsu_plot_ticks {
    double lo, hi;   /* the axis range */
    size_t n;        /* number of ticks, <= TSU_PLOT_MAX_TICKS */
    double step;     /* distance between ticks: 1, 2 or 5 times a power of 10 */
    double value[TSU_PLOT_MAX_TICKS];            /* increasing, inside [lo, hi] */
    char label[TSU_PLOT_MAX_TICKS][TSU_PLOT_LABEL_MAX]; /* value / 10^exponent, ASCII ("-1.5") */
    int exponent;    /* 0, or the power of ten the labels are scaled by */
} tsu_plot_ticks;

typedef enum tsu_plot_range_mode {
    TSU_PLOT_RANGE_AUTO = 0, /* [lo, hi] is the data extent: widen by 4 % (degenerate ranges more) */
    TSU_PLOT_RANGE_FIXED = 1 /* [lo, hi] is the axis range itself; needs lo < hi */
} tsu_plot_range_mode;

/*
 * Ticks for an axis.  The step is the 1-2-5 step that puts 4..8 ticks inside
 * the range, closest to 6 (ties: the larger step); if none gives 4..8, the
 * one closest to that interval.  All labels of an axis have the same number
 * of decimals, chosen from the step (so 0.1 + 0.2 never shows as
 * 0.30000000000000004).  When the largest tick magnitude is >= 1e5 (and the
 * scaled labels need at most 3 decimals, or it is >= 1e10) or < 1e-3, labels
 * are value / 10^exponent with exponent = the decimal exponent of that largest
 * magnitude.
 * lo and hi must be finite with |.| <= TSU_PLOT_MAX_ABS, and lo <= hi (AUTO)
 * or lo < hi (FIXED).  TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG.
 */
tsu_plot_status tsu_plot_ticks_compute(double lo, double hi, tsu_plot_range_mode mode,
                                     tsu_plot_ticks *t);

/* ------------------------------------------------------------------ */
/* Plot object                                                          */
/* ------------------------------------------------------------------ */

typedef struct tsu_plot tsu_plot;

#define TSU_PLOT_DEFAULT_WIDTH 720
#define TSU_PLOT_DEFAULT_HEIGHT 450
#define TSU_PLOT_MIN_SIZE 160
#define TSU_PLOT_MAX_SIZE 16384

/* width_px, height_px: 0 for the default, else in [TSU_PLOT_MIN_SIZE,
 * TSU_PLOT_MAX_SIZE].  *out is set to NULL first.
 * TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG, TSU_PLOT_ERR_NOMEM. */
tsu_plot_status tsu_plot_new(unsigned width_px, unsigned height_px, tsu_plot **out);
void tsu_plot_free(tsu_plot *p); /* NULL is a no-op */

/* Text is copied.  NULL or "" removes it.
 * TSU_PLOT_OK, TSU_PLOT_ERR_NULL (p), TSU_PLOT_ERR_NOMEM. */
tsu_plot_status tsu_plot_set_title(tsu_plot *p, const char *title);
tsu_plot_status tsu_plot_set_labels(tsu_plot *p, const char *xlabel, const char *ylabel);

/* Fix an axis range (lo < hi, finite, |.| <= TSU_PLOT_MAX_ABS), or both NaN to
 * return to the automatic range.  TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG. */
tsu_plot_status tsu_plot_set_xrange(tsu_plot *p, double lo, double hi);
tsu_plot_status tsu_plot_set_yrange(tsu_plot *p, double lo, double hi);

/* Custom ticks for an axis (0: x, 1: y), e.g. dates or decades of a log
 * axis whose data the caller passes as log10 values.  Once the axis range
 * [t->lo, t->hi] is fixed, fn(ctx, t) replaces t->n, t->value (increasing,
 * inside the range) and t->label; t->exponent is then 0.  fn NULL: the
 * 1-2-5 ticks again.  TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG (axis). */
typedef void (*tsu_plot_tick_fn)(void *ctx, tsu_plot_ticks *t);
tsu_plot_status tsu_plot_set_tick_fn(tsu_plot *p, int axis, tsu_plot_tick_fn fn, void *ctx);

/* 1: one data unit is as long on both axes (closed curves); the axis that
 * needs it is widened about its centre, even a fixed one.  Default 0.  TSU_PLOT_OK, TSU_PLOT_ERR_NULL. */
tsu_plot_status tsu_plot_set_equal_aspect(tsu_plot *p, int on);

typedef enum tsu_plot_legend {
    TSU_PLOT_LEGEND_AUTO = 0,    /* inside, at the first of: the four corners, the middles of the
                                   right, left, top and bottom edges, the centre, that covers no
                                   data (shading may pass under it); if each covers some, right
                                   of the plot area when that leaves it >= 45 % of the width,
                                   else the position covering least */
    TSU_PLOT_LEGEND_NONE = 1,
    TSU_PLOT_LEGEND_OUTSIDE = 2, /* right of the plot area (the legend box is not shrunk) */
    TSU_PLOT_LEGEND_UPPER_RIGHT = 3,
    TSU_PLOT_LEGEND_UPPER_LEFT = 4,
    TSU_PLOT_LEGEND_LOWER_LEFT = 5,
    TSU_PLOT_LEGEND_LOWER_RIGHT = 6
} tsu_plot_legend;
/* TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG (unknown value). */
tsu_plot_status tsu_plot_set_legend(tsu_plot *p, tsu_plot_legend where);

/* Write "<?xml ...?>" first (default 1).  Use 0 for SVG inlined in HTML. */
tsu_plot_status tsu_plot_set_xml_declaration(tsu_plot *p, int on);
/* Light grid lines at the ticks (default 1). */
tsu_plot_status tsu_plot_set_grid(tsu_plot *p, int on);
/* Polyline simplification tolerance in px: 0 keeps every vertex (except
 * exact repeats after rounding), default 0.1, at most 10.
 * TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG. */
tsu_plot_status tsu_plot_set_simplify(tsu_plot *p, double tol_px);

/* ---- series ------------------------------------------------------- */

/*
 * Look of a series.  All-zero (or a NULL pointer) means "defaults":
 *   colour: the next colour of the palette (tsu_plot_palette) in the order
 *           series are added, skipping colours an earlier series was given
 *           explicitly;
 *   width:  polylines 2 px, dashed polylines 1.25 px, lines and region
 *           boundaries 1.5 px;
 *   dash:   0 solid, 1 dashed, 2 dotted (tsu_plot_add_polygon: 0 means dashed);
 *   marker_radius: points 3.5 px; polyline vertex markers 2.5 px;
 *   markers: polylines only: also mark each vertex (e.g. control points);
 *   fill_opacity: regions 0.13.
 * color is "#rgb", "#rrggbb" or a colour name of 1..20 ASCII letters
 * ("black", "gray"); anything else is TSU_PLOT_ERR_ARG.  width, marker_radius
 * must be finite and in [0, 50]; fill_opacity in [0, 1]; dash in {0, 1, 2}.
 */
typedef struct tsu_plot_style {
    const char *color;
    double width;
    int dash;
    double marker_radius;
    int markers;
    double fill_opacity;
} tsu_plot_style;

/* Colour-blind-safe palette (Okabe & Ito 2008): blue, vermillion, bluish
 * green, reddish purple, orange, sky blue, black, yellow; i is taken mod 8.
 * Returns "#rrggbb". */
const char *tsu_plot_palette(size_t i);

/*
 * Data series.  x and y (n values each) are copied; n may be 0.  label may be
 * NULL or "" (no legend entry).  Common statuses: TSU_PLOT_OK,
 * TSU_PLOT_ERR_NULL (p, or x / y with n > 0), TSU_PLOT_ERR_OVERFLOW,
 * TSU_PLOT_ERR_NOMEM, TSU_PLOT_ERR_ARG (style).
 */
/* Markers (data points). */
tsu_plot_status tsu_plot_add_points(tsu_plot *p, const double *x, const double *y, size_t n,
                                  const char *label, const tsu_plot_style *st);
/* Connected line, e.g. a sampled curve (thousands of points are fine). */
tsu_plot_status tsu_plot_add_polyline(tsu_plot *p, const double *x, const double *y, size_t n,
                                    const char *label, const tsu_plot_style *st);
/* A control polygon: like tsu_plot_add_polyline, dashed unless dotted, and
 * always with vertex markers. */
tsu_plot_status tsu_plot_add_polygon(tsu_plot *p, const double *x, const double *y, size_t n,
                                   const char *label, const tsu_plot_style *st);

/* The straight line y = m x + c across the plot area.  m, c finite
 * (TSU_PLOT_ERR_ARG otherwise). */
tsu_plot_status tsu_plot_add_line(tsu_plot *p, double m, double c, const char *label,
                                const tsu_plot_style *st);

typedef enum tsu_plot_side {
    TSU_PLOT_FORBID_BELOW = 0, /* shade y < m x + c: the line is a floor ("above" constraint) */
    TSU_PLOT_FORBID_ABOVE = 1  /* shade y > m x + c: the line is a ceiling ("below" constraint) */
} tsu_plot_side;

/* A forbidden region: the part of the plot area on one side of y = m x + c,
 * shaded semi-transparently in the series colour, and its boundary line.
 * TSU_PLOT_ERR_ARG for a non-finite m or c, or an unknown side. */
tsu_plot_status tsu_plot_add_region(tsu_plot *p, tsu_plot_side side, double m, double c,
                                  const char *label, const tsu_plot_style *st);
/* Horizontal special cases: shade y < level / y > level. */
tsu_plot_status tsu_plot_add_floor(tsu_plot *p, double level, const char *label,
                                 const tsu_plot_style *st);
tsu_plot_status tsu_plot_add_ceiling(tsu_plot *p, double level, const char *label,
                                   const tsu_plot_style *st);

/* ---- output -------------------------------------------------------- */

/* Append the SVG document to b.  On failure b keeps its previous content.
 * TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_NOMEM, TSU_PLOT_ERR_OVERFLOW. */
tsu_plot_status tsu_plot_render(const tsu_plot *p, tsu_plot_buf *b);
/* Render and write to f (flushed).  Also TSU_PLOT_ERR_IO. */
tsu_plot_status tsu_plot_write(const tsu_plot *p, FILE *f);
/* Render and write to a new file at path.  Also TSU_PLOT_ERR_IO. */
tsu_plot_status tsu_plot_save(const tsu_plot *p, const char *path);

/* The ticks of the final layout (axis 0: x, 1: y), as rendering would draw
 * them (automatic ranges, equal aspect included).
 * TSU_PLOT_OK, TSU_PLOT_ERR_NULL, TSU_PLOT_ERR_ARG (axis). */
tsu_plot_status tsu_plot_get_ticks(const tsu_plot *p, int axis, tsu_plot_ticks *t);

/* Test hook: let the next n allocations of this module succeed and every
 * later one fail (n < 0: never fail, the default).  Global, not
 * thread-safe: for tests of the TSU_PLOT_ERR_NOMEM paths only. */
void tsu_plot_test_fail_alloc_after(long n);

#ifdef __cplusplus
}
#endif
#endif /* TSU_PLOT_H */
