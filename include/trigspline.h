/*
 * trigspline — shape-preserving interpolation with the GC¹ cubic
 * trigonometric spline.
 *
 * The mathematics is in ../shared/design/SPEC.md (section numbers "SPEC §n"
 * below refer to it).  It restates and corrects the paper "Shape-Preserving
 * Positive Trigonometric Spline Curves".
 *
 * Conventions (modelled on GSL interpolation, tinyspline, libsamplerate):
 *  - A fitted spline (ts_spline) and curve (ts_curve) are opaque and
 *    immutable once built: any number of threads may evaluate one spline at
 *    the same time.  The only mutable lookup state is a small ts_cursor the
 *    caller owns (it may be NULL everywhere).
 *  - Every function that can fail returns a ts_status; the codes each one can
 *    return are listed next to it.  ts_strerror() maps a code to a fixed
 *    string.  Out-parameters are reset before any check, so the matching
 *    free function is always safe to call; ts_spline_free(NULL) is a no-op.
 *  - The library never aborts, never prints and never allocates while
 *    evaluating.  Only the *_new functions allocate.
 *  - Where an error concerns a data point, interval or query, its index is
 *    reported through an optional ts_error (may be NULL).
 */
#ifndef TRIGSPLINE_H
#define TRIGSPLINE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TS_VERSION_MAJOR 0
#define TS_VERSION_MINOR 1
#define TS_VERSION_PATCH 0

/* "0.1.0" */
const char *ts_version(void);

/* ------------------------------------------------------------------ */
/* Status codes                                                         */
/* ------------------------------------------------------------------ */

typedef enum ts_status {
    TS_OK = 0,
    TS_ERR_NULL = 1,         /* a required pointer argument is NULL */
    TS_ERR_NOMEM = 2,        /* allocation failed */
    TS_ERR_OVERFLOW = 3,     /* n * sizeof(...) would overflow size_t */
    TS_ERR_TOO_FEW = 4,      /* fewer than 2 points (n < 1 interval) */
    TS_ERR_NONFINITE = 5,    /* NaN or ±Inf in x, f, slopes or line coefficients */
    TS_ERR_UNSORTED = 6,     /* x not strictly increasing (unsorted or duplicate); index = i with x[i] <= x[i-1] */
    TS_ERR_ALPHA = 7,        /* alpha <= 0 or not finite; index = interval */
    TS_ERR_BETA = 8,         /* beta < 0, not finite, or alpha + beta <= 0; index = interval */
    TS_ERR_MARGIN = 9,       /* margin t <= 0 or not finite; index = interval */
    TS_ERR_LENGTH = 10,      /* a per-interval / per-point array has the wrong length */
    TS_ERR_OPTION = 11,      /* an enum value out of range, or options that do not fit together */
    TS_ERR_PERIODIC = 12,    /* periodic slopes need f[0] == f[n] */
    TS_ERR_DOMAIN = 13,      /* query outside [x0, xn] under TS_EXTRAP_ERROR, or a NaN query; index = query */
    TS_ERR_NEGATIVE = 14,    /* positive scheme: f[i] < 0; index = point */
    TS_ERR_SIDE = 15,        /* a data point on or across a constraint line; index = point */
    TS_ERR_LINES = 16,       /* lower line not strictly below the upper line at a data point; index = point */
    TS_ERR_NONMONOTONE = 17, /* monotone scheme: data change direction; index = point */
    TS_ERR_INFEASIBLE = 18,  /* no beta >= 0 keeps interval inside the region; index = interval */
    TS_ERR_VIOLATED = 19,    /* ts_certify: the spline leaves the region; index = first interval */
    TS_ERR_GEOMETRIC = 20,   /* geometric form: alpha+beta below the bound of SPEC §4; index = interval */
    TS_ERR_DIMENSION = 21,   /* curve dimension not 2 or 3 */
    TS_ERR_INDEX = 22,       /* accessor index out of range */
    TS_ERR_ZERO_SLOPE = 23,  /* a knot where the data touch a boundary (f = 0) got a user slope of the wrong sign; index = point */
    TS_STATUS_COUNT_ = 24    /* not a status: number of codes */
} ts_status;

/* A fixed, never-NULL English string for any value (unknown codes too). */
const char *ts_strerror(ts_status status);

/* What ts_error.index refers to. */
typedef enum ts_where {
    TS_WHERE_NONE = 0,     /* index is TS_NO_INDEX */
    TS_WHERE_POINT = 1,    /* data point i (x[i], f[i]) */
    TS_WHERE_INTERVAL = 2, /* interval i = [x[i], x[i+1]] */
    TS_WHERE_QUERY = 3     /* i-th query of a batch call */
} ts_where;

#define TS_NO_INDEX ((size_t)-1)

/* Optional detail of a failure.  Functions that take a ts_error* reset it
 * to {TS_OK, TS_NO_INDEX, TS_WHERE_NONE} first, then fill it on failure. */
typedef struct ts_error {
    ts_status status;
    size_t index;
    ts_where where;
} ts_error;

/* ------------------------------------------------------------------ */
/* Options                                                              */
/* ------------------------------------------------------------------ */

/* SPEC §3 paper form (default), §3 C¹ option, §4 geometric form. */
typedef enum ts_form {
    TS_FORM_PAPER = 0,
    TS_FORM_C1 = 1,
    TS_FORM_GEOMETRIC = 2
} ts_form;

/* SPEC §6.  With two points (n = 1) every method gives d0 = d1 = Δ0. */
typedef enum ts_slopes {
    TS_SLOPES_ARITHMETIC = 0,     /* three-point arithmetic mean (default) */
    TS_SLOPES_GEOMETRIC = 1,      /* geometric mean of neighbouring secants (0 if signs differ) */
    TS_SLOPES_HARMONIC = 2,       /* weighted harmonic mean, Fritsch–Butland / Brodlie */
    TS_SLOPES_FRITSCH_CARLSON = 3,/* PCHIP (Fritsch–Carlson 1980 with Brodlie weights; ends as in Fritsch–Carlson/Moler) */
    TS_SLOPES_AKIMA = 4,          /* Akima 1970 */
    TS_SLOPES_MAKIMA = 5,         /* modified Akima (Moler 2019) */
    TS_SLOPES_USER = 6,           /* ts_options.user_slopes, n+1 values */
    TS_SLOPES_PERIODIC = 7        /* periodic three-point mean; needs f[0] == f[n] */
} ts_slopes;
#define TS_SLOPES_COUNT_ 8

/* SPEC §5.  Which region the curve must stay in. */
typedef enum ts_shape {
    TS_SHAPE_NONE = 0,      /* beta given by the caller */
    TS_SHAPE_POSITIVE = 1,  /* S >= 0 (S > 0 where all data > 0); Theorem 2 */
    TS_SHAPE_ABOVE = 2,     /* S > lower line; Theorem 3 */
    TS_SHAPE_BELOW = 3,     /* S < upper line; Theorem 4 (corrected signs) */
    TS_SHAPE_BETWEEN = 4,   /* lower < S < upper; Theorem 5 (corrected) */
    TS_SHAPE_MONOTONE = 5   /* S monotone where the data are; SPEC §5.5 */
} ts_shape;

/* Queries outside [x0, xn]. */
typedef enum ts_extrap {
    TS_EXTRAP_ERROR = 0,  /* TS_ERR_DOMAIN (default) */
    TS_EXTRAP_CLAMP = 1,  /* value of the nearest end; derivatives 0 */
    TS_EXTRAP_EXTEND = 2, /* the end segment's own formula continued (theta outside [0, pi/2]) */
    TS_EXTRAP_LINEAR = 3  /* tangent line at the end (end value + one-sided end slope) */
} ts_extrap;

/* The line y = m x + c. */
typedef struct ts_line {
    double m;
    double c;
} ts_line;

/* Default margin t of SPEC §5 (dimensionless, added to beta). */
#define TS_DEFAULT_MARGIN 0.01

/*
 * Construction options.  Always start from ts_options_init(), then set
 * fields.  Per-interval arrays override the scalar when non-NULL and must
 * have exactly n = n_points - 1 entries (else TS_ERR_LENGTH).
 */
typedef struct ts_options {
    ts_form form;              /* default TS_FORM_PAPER */
    ts_slopes slopes;          /* default TS_SLOPES_ARITHMETIC */
    const double *user_slopes; /* TS_SLOPES_USER: n_points values */
    size_t n_user_slopes;

    double alpha;              /* default 1 */
    const double *alphas;      /* optional, per interval */
    size_t n_alphas;

    double beta;               /* default 0; used with TS_SHAPE_NONE only */
    const double *betas;
    size_t n_betas;

    ts_shape shape;            /* default TS_SHAPE_NONE */
    ts_line lower;             /* TS_SHAPE_ABOVE and TS_SHAPE_BETWEEN */
    ts_line upper;             /* TS_SHAPE_BELOW and TS_SHAPE_BETWEEN */
    double margin;             /* t of SPEC §5, default TS_DEFAULT_MARGIN */
    const double *margins;
    size_t n_margins;
    int certify;               /* default 1: exact certificate per interval (SPEC §5), repair if needed.
                                  0 skips the certificate where the scheme is already rigorous
                                  (positive, monotone, geometric form); line schemes in the paper
                                  and C¹ forms are always certified. */

    ts_extrap extrapolate;     /* default TS_EXTRAP_ERROR */
} ts_options;

void ts_options_init(ts_options *opt);

/* ------------------------------------------------------------------ */
/* Slopes on their own                                                  */
/* ------------------------------------------------------------------ */

/*
 * Estimate slopes d[0..n_points-1] by a method of SPEC §6 (not TS_SLOPES_USER).
 * Returns TS_OK, TS_ERR_NULL, TS_ERR_TOO_FEW, TS_ERR_NONFINITE,
 * TS_ERR_UNSORTED, TS_ERR_OPTION, TS_ERR_PERIODIC.
 */
ts_status ts_slopes_compute(ts_slopes method, const double *x, const double *f,
                            size_t n_points, double *d, ts_error *err);

/* ------------------------------------------------------------------ */
/* The spline                                                           */
/* ------------------------------------------------------------------ */

typedef struct ts_spline ts_spline;

/*
 * Fit the spline through (x[i], f[i]), i = 0..n_points-1.  opt may be NULL
 * (all defaults).  *out is set to NULL first, then to the new spline on
 * success; on failure nothing is left allocated.
 *
 * Returns TS_OK, TS_ERR_NULL, TS_ERR_NOMEM, TS_ERR_OVERFLOW, TS_ERR_TOO_FEW,
 * TS_ERR_NONFINITE, TS_ERR_UNSORTED, TS_ERR_ALPHA, TS_ERR_BETA,
 * TS_ERR_MARGIN, TS_ERR_LENGTH, TS_ERR_OPTION, TS_ERR_PERIODIC,
 * TS_ERR_NEGATIVE, TS_ERR_SIDE, TS_ERR_LINES, TS_ERR_NONMONOTONE,
 * TS_ERR_INFEASIBLE, TS_ERR_GEOMETRIC, TS_ERR_ZERO_SLOPE.
 */
ts_status ts_spline_new(const double *x, const double *f, size_t n_points,
                        const ts_options *opt, ts_spline **out, ts_error *err);

void ts_spline_free(ts_spline *s);

/* ---- accessors (never fail on a valid spline; pointers live as long as s) */
size_t ts_spline_intervals(const ts_spline *s);     /* n */
const double *ts_spline_x(const ts_spline *s);      /* n+1 knots */
const double *ts_spline_f(const ts_spline *s);      /* n+1 values */
const double *ts_spline_slopes(const ts_spline *s); /* n+1 slopes d_i actually used (after any shape adjustment) */
const double *ts_spline_alpha(const ts_spline *s);  /* n */
const double *ts_spline_beta(const ts_spline *s);   /* n */
ts_form ts_spline_form(const ts_spline *s);
ts_shape ts_spline_shape(const ts_spline *s);
ts_extrap ts_spline_extrapolation(const ts_spline *s);

/* a_i = alpha_i + beta_i.  TS_OK or TS_ERR_NULL, TS_ERR_INDEX. */
ts_status ts_spline_a(const ts_spline *s, size_t i, double *a);

/* The four control values B0..B3 of interval i (SPEC §3; for the C¹ option the
 * ones built from d̂).  In the geometric form also the abscissae X0..X3 of §4
 * (X may be NULL; in the other forms X is x_i + (0, 1/3, 2/3, 1)·h_i only as a
 * plotting convenience).  TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
ts_status ts_spline_control(const ts_spline *s, size_t i, double B[4], double X[4]);

/* Which term of the SPEC §5 rule set beta_i. */
typedef enum ts_term {
    TS_TERM_USER = 0,        /* beta given by the caller (TS_SHAPE_NONE) */
    TS_TERM_MARGIN = 1,      /* max{...} was 0: beta = t */
    TS_TERM_LOWER_LEFT = 2,  /* -alpha - K d_i / g_i */
    TS_TERM_LOWER_RIGHT = 3, /* -alpha + K d_{i+1} / g_{i+1} */
    TS_TERM_UPPER_LEFT = 4,  /* -alpha + K d_i / G_i */
    TS_TERM_UPPER_RIGHT = 5, /* -alpha - K d_{i+1} / G_{i+1} */
    TS_TERM_MONOTONE = 6,    /* 2(d_i + d_{i+1})/(3 pi Δ_i) - alpha */
    TS_TERM_CERTIFY = 7,     /* raised by the certificate repair (SPEC §5) */
    TS_TERM_GEOMETRIC = 8    /* raised to the geometric-form bound (SPEC §4) */
} ts_term;

/* Per-interval report: what was built and its certificate. */
typedef struct ts_interval_report {
    double x0, x1;          /* interval ends */
    double alpha, beta, a;  /* a = alpha + beta */
    double B[4];            /* control values */
    ts_term term;           /* which term chose beta */
    int has_lower, has_upper;
    double gap_lower;       /* exact min over the interval of S(x) - lower(x) (NaN if !has_lower) */
    double at_lower;        /* the x where it is attained */
    double gap_upper;       /* exact min of upper(x) - S(x) (NaN if !has_upper) */
    double at_upper;
    int certified;          /* every active gap > 0 (with the rounding guard of certify.c) */
} ts_interval_report;

/* Report of interval i.  For shape schemes the boundaries are the scheme's
 * (positive: lower = 0); for TS_SHAPE_NONE no boundary (has_* = 0).
 * TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
ts_status ts_spline_report(const ts_spline *s, size_t i, ts_interval_report *rep);

/* 1 when every interval of a shape-constrained spline is certified, 0 otherwise
 * (also 0 for TS_SHAPE_NONE: nothing was promised). */
int ts_spline_certified(const ts_spline *s);

/*
 * Certify any spline (e.g. one built with the caller's own beta) against an
 * optional lower and upper line (either may be NULL; both NULL is
 * TS_ERR_NULL).  reports, if not NULL, receives n entries.  Returns TS_OK
 * when every interval keeps lower < S < upper, TS_ERR_VIOLATED otherwise
 * (err->index = first violating interval), TS_ERR_NONFINITE for a non-finite
 * line, TS_ERR_NULL.
 */
ts_status ts_certify(const ts_spline *s, const ts_line *lower, const ts_line *upper,
                     ts_interval_report *reports, ts_error *err);

/* ---- evaluation ---------------------------------------------------- */

/* Caller-owned lookup hint; zero-initialise (TS_CURSOR_INIT) or pass NULL. */
typedef struct ts_cursor {
    size_t interval;
} ts_cursor;
#define TS_CURSOR_INIT {0}

/*
 * Value and derivatives at x.  Any of y, dy, d2y may be NULL.  On failure the
 * non-NULL outputs are set to NaN.
 * Returns TS_OK, TS_ERR_NULL (s), TS_ERR_DOMAIN (x NaN, or outside the data
 * under TS_EXTRAP_ERROR).
 * At an inner knot the right-hand interval is used (derivatives of the paper
 * form jump there, SPEC §3).
 */
ts_status ts_eval(const ts_spline *s, double x, ts_cursor *cur, double *y);
ts_status ts_eval_deriv(const ts_spline *s, double x, ts_cursor *cur,
                        double *y, double *dy, double *d2y);

/*
 * Batch: yq[j] = S^(deriv)(xq[j]), deriv in {0, 1, 2}.  Fast for sorted
 * queries, correct for any order; may use the fast kernels of fast.c, which
 * agree with ts_eval_deriv to the bound stated there.  Every valid query is
 * evaluated; invalid ones get NaN and the call returns TS_ERR_DOMAIN with
 * err->index = first invalid query.  Also TS_ERR_NULL, TS_ERR_OPTION (deriv).
 */
ts_status ts_eval_batch(const ts_spline *s, int deriv, const double *xq, size_t m,
                        double *yq, ts_cursor *cur, ts_error *err);

/* Same, split over nthreads threads (0 = number of cores).  Off unless called.
 * Same statuses. */
ts_status ts_eval_batch_mt(const ts_spline *s, int deriv, const double *xq, size_t m,
                           double *yq, unsigned nthreads, ts_error *err);

/*
 * Definite integral of S over [a, b] (b < a gives the negative), closed form.
 * a and b must lie in [x0, xn]: TS_ERR_DOMAIN otherwise (or NaN).  TS_ERR_NULL.
 */
ts_status ts_integral(const ts_spline *s, double a, double b, double *out);

/* ------------------------------------------------------------------ */
/* Parametric curves (SPEC §7)                                          */
/* ------------------------------------------------------------------ */

typedef struct ts_curve ts_curve;

typedef enum ts_param {
    TS_PARAM_CENTRIPETAL = 0, /* default: t_{i+1} - t_i = |P_{i+1} - P_i|^(1/2) */
    TS_PARAM_CHORD = 1,       /* |P_{i+1} - P_i| */
    TS_PARAM_UNIFORM = 2      /* 1 */
} ts_param;

typedef struct ts_curve_options {
    ts_param param;          /* default TS_PARAM_CENTRIPETAL */
    int closed;              /* default 0; 1: closed, first point repeated or implied */
    ts_slopes slopes;        /* default TS_SLOPES_ARITHMETIC (periodic automatically when closed) */
    double alpha;            /* default 1 */
    const double *alphas;    /* per segment */
    size_t n_alphas;
    double beta;             /* default 0 */
    const double *betas;
    size_t n_betas;
    /* Box constraint (SPEC §5 per coordinate, shared beta per segment):
     * coordinate k kept > lo[k] when has_lo[k], < hi[k] when has_hi[k]. */
    int has_lo[3], has_hi[3];
    double lo[3], hi[3];
    double margin;           /* default TS_DEFAULT_MARGIN */
} ts_curve_options;

void ts_curve_options_init(ts_curve_options *opt);

/*
 * points: n_points rows of dim (2 or 3) doubles, row-major.
 * TS_OK, TS_ERR_NULL, TS_ERR_NOMEM, TS_ERR_OVERFLOW, TS_ERR_TOO_FEW,
 * TS_ERR_NONFINITE, TS_ERR_UNSORTED (two consecutive equal points: zero
 * parameter step; index = point), TS_ERR_DIMENSION, TS_ERR_ALPHA,
 * TS_ERR_BETA, TS_ERR_MARGIN, TS_ERR_LENGTH, TS_ERR_OPTION, TS_ERR_SIDE,
 * TS_ERR_INFEASIBLE.
 */
ts_status ts_curve_new(const double *points, size_t n_points, size_t dim,
                       const ts_curve_options *opt, ts_curve **out, ts_error *err);
void ts_curve_free(ts_curve *c);

size_t ts_curve_segments(const ts_curve *c);
size_t ts_curve_dim(const ts_curve *c);
const double *ts_curve_knots(const ts_curve *c);   /* segments+1 parameter values */
/* Control points of segment i: ctrl receives 4 rows of dim doubles.  The
 * spline of coordinate k in segment i has values ctrl[l*dim + k].
 * TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
ts_status ts_curve_control(const ts_curve *c, size_t i, double *ctrl);
/* alpha_i, beta_i of segment i; TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
ts_status ts_curve_params(const ts_curve *c, size_t i, double *alpha, double *beta);

/* Point, first and second derivative in t (each may be NULL; dim doubles).
 * t outside [t0, tn]: TS_ERR_DOMAIN (closed curves wrap t periodically).
 * TS_OK, TS_ERR_NULL, TS_ERR_DOMAIN. */
ts_status ts_curve_eval(const ts_curve *c, double t, ts_cursor *cur,
                        double *p, double *dp, double *d2p);
/* m samples per segment (knots included, m >= 2) into out (rows of 1+dim:
 * t then the point); *rows receives segments*(m-1)+1.  out must hold
 * rows*(1+dim) doubles; out_len is its length in doubles.
 * TS_OK, TS_ERR_NULL, TS_ERR_OPTION (m < 2), TS_ERR_LENGTH (out too short). */
ts_status ts_curve_sample(const ts_curve *c, size_t m, double *out, size_t out_len,
                          size_t *rows);
/* Arc length by adaptive Gauss–Legendre quadrature to relative tolerance tol
 * (tol <= 0: 1e-12).  TS_OK, TS_ERR_NULL. */
ts_status ts_curve_length(const ts_curve *c, double tol, double *len);

/* Curve certificate against its box: reports per segment and coordinate
 * (segments*dim entries, may be NULL).  TS_OK if every gap > 0 or no box;
 * TS_ERR_VIOLATED (index = segment); TS_ERR_NULL. */
ts_status ts_curve_certify(const ts_curve *c, ts_interval_report *reports, ts_error *err);

#ifdef __cplusplus
}
#endif
#endif /* TRIGSPLINE_H */
