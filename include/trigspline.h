/*
 * trigspline — shape-preserving interpolation with the GC¹ cubic
 * trigonometric spline.
 *
 * The mathematics is in docs/method.md (the "docs/method.md §n" below are its
 * sections): the method of the paper "Shape-Preserving Positive
 * Trigonometric Spline Curves", derived and corrected.
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

/* TS_API marks the functions the shared library exports; the library is
 * built with -fvisibility=hidden, so everything else stays internal.  A
 * build may predefine TS_API (e.g. as dllexport/dllimport) to override. */
#ifndef TS_API
#if defined(__GNUC__) || defined(__clang__)
#define TS_API __attribute__((visibility("default")))
#else
#define TS_API
#endif
#endif

/* TS_VERSION_MAJOR, _MINOR, _PATCH, TS_VERSION_STRING ("0.2.0"),
 * TS_VERSION_NUM (MAJOR << 16 | MINOR << 8 | PATCH) and
 * TS_VERSION_AT_LEAST(maj, min, pat): the version of this header, generated
 * from CMakeLists.txt; docs/versions.md has the compatibility policy. */
#include "trigspline_version.h"

/* The version of the library linked in, "MAJOR.MINOR.PATCH": equal to
 * TS_VERSION_STRING of the header it was built with. */
TS_API const char *ts_version(void);

/* ------------------------------------------------------------------ */
/* Status codes                                                         */
/* ------------------------------------------------------------------ */

typedef enum ts_status {
    TS_OK = 0,
    TS_ERR_NULL = 1,         /* a required pointer argument is NULL */
    TS_ERR_NOMEM = 2,        /* allocation failed */
    TS_ERR_OVERFLOW = 3,     /* n * sizeof(...) would overflow size_t */
    TS_ERR_TOO_FEW = 4,      /* fewer than 2 points (n < 1 interval) */
    TS_ERR_NONFINITE = 5,    /* NaN or ±Inf in x, f, user slopes or line coefficients (index =
                                point); quantities of finite data that leave the double range
                                have codes of their own (TS_ERR_SLOPE_OVERFLOW, TS_ERR_TOO_LARGE,
                                TS_ERR_CONTROL_OVERFLOW, TS_ERR_WIDTH) */
    TS_ERR_UNSORTED = 6,     /* x not strictly increasing (unsorted or duplicate); index = i with x[i] <= x[i-1] */
    TS_ERR_ALPHA = 7,        /* alpha <= 0 or not finite; index = interval */
    TS_ERR_BETA = 8,         /* beta < 0 or not finite, or alpha + beta <= 0 or not finite; index = interval */
    TS_ERR_MARGIN = 9,       /* margin t <= 0 or not finite; index = interval */
    TS_ERR_LENGTH = 10,      /* a per-interval / per-point array has the wrong length */
    TS_ERR_OPTION = 11,      /* an enum value out of range, or options that do not fit together */
    TS_ERR_PERIODIC = 12,    /* periodic slopes need f[0] == f[n] */
    TS_ERR_DOMAIN = 13,      /* query outside [x0, xn] under TS_EXTRAP_ERROR, or a NaN query; index = query */
    TS_ERR_NEGATIVE = 14,    /* positive scheme: f[i] < 0; index = point */
    TS_ERR_SIDE = 15,        /* a data point across a constraint line, or on a sloped one; index = point */
    TS_ERR_LINES = 16,       /* lower line not strictly below the upper line at a data point; index = point */
    TS_ERR_NONMONOTONE = 17, /* monotone scheme: data change direction; index = point */
    TS_ERR_INFEASIBLE = 18,  /* no beta >= 0 keeps interval inside the region; index = interval */
    TS_ERR_VIOLATED = 19,    /* ts_spline_certify: the spline leaves the region; index = first interval */
    TS_ERR_GEOMETRIC = 20,   /* geometric form: alpha+beta below the bound of docs/method.md §4; index = interval */
    TS_ERR_DIMENSION = 21,   /* curve dimension not 2 or 3 */
    TS_ERR_INDEX = 22,       /* accessor index out of range */
    TS_ERR_ZERO_SLOPE = 23,  /* a knot where the data touch a boundary (f = 0, or f = c on a constant line) got a user slope of the wrong sign; index = point */
    TS_ERR_SLOPE_OVERFLOW = 24,   /* finite data whose slope estimate overflows a double (huge steps
                                     of f over narrow intervals); index = point */
    TS_ERR_TOO_LARGE = 25,        /* |f_i| > TS_VALUE_MAX (index = point) or a control value
                                     |B_l| > TS_VALUE_MAX (index = interval): beyond it S could
                                     overflow between the knots */
    TS_ERR_CONTROL_OVERFLOW = 26, /* control values overflow: alpha + beta too small for the
                                     slopes (B = f ± 2h d/(3π a)); index = interval */
    TS_ERR_WIDTH = 27,            /* an interval width x_{i+1} − x_i overflows (x of both signs
                                     near ±DBL_MAX) or underflows (below DBL_MIN, subnormal);
                                     index = its right point */
    TS_ERR_PRECISION = 28,        /* line schemes: a beta_i whose exact gap is positive exists, but the
                                     gap stays below the rounding bound of the certificate: cannot
                                     be certified in double precision; index = interval */
    TS_ERR_UNPROVEN = 29,         /* C¹ form: no beta was found that certifies the interval, and
                                     the search did not prove that none exists; index = interval
                                     (surfaces with gridded bounds: no a^x, a^y certified the
                                     patch; index = patch) */
    TS_ERR_VERSION = 30,          /* a struct's struct_size is not the sizeof of this library's
                                     struct: built against another version's header, or not
                                     initialised by its *_init function (see "Struct guards") */
    TS_ERR_CONDITION = 31,        /* constraint records (ts_constraint): the data violate a necessary
                                     condition of one (convex data, a secant beyond a slope bound, a
                                     point across a bound or on a polyline's corner that turns into
                                     the region); index = point or interval;
                                     ts_constraints_diagnose names the constraint and the condition */
    TS_ERR_BOUND_GRID = 32,       /* a gridded surface bound (TS_SURFACE_GRIDS) is malformed or does
                                     not cover the surface's grid; index = 0 (the lower bound's
                                     grid) or 1 (the upper's), where = TS_WHERE_NONE */
    TS_STATUS_COUNT_ = 33    /* not a status: number of codes */
} ts_status;

/* The largest |f_i| and |B_l| a spline accepts (TS_ERR_TOO_LARGE beyond):
 * a quarter of DBL_MAX, so that S = Σ A_l B_l (Σ A_l = 1 up to rounding) and
 * the differences B_{l+1} − B_l of its derivative cannot overflow. */
#define TS_VALUE_MAX 0x1p1022

/* A fixed, never-NULL English string for any value (unknown codes too). */
TS_API const char *ts_strerror(ts_status status);

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
/* Vocabulary: the one spelling of every enum value                    */
/* ------------------------------------------------------------------ */

/*
 * The canonical name of each value of the library's enums, the names every
 * front-end (command line, JSON, Python, JavaScript) uses.  One spelling per
 * value, lower case, words joined by hyphens:
 *   TS_VOCAB_STATUS         the enumerator names: "TS_OK", "TS_ERR_NULL", ...
 *   TS_VOCAB_FORM           ts_form: paper, c1, geometric
 *   TS_VOCAB_SLOPES         ts_slopes: arithmetic, geometric, harmonic,
 *                           fritsch-carlson, akima, makima, user, periodic
 *   TS_VOCAB_SHAPE          ts_shape: none, positive, above, below, between, monotone
 *   TS_VOCAB_EXTRAP         ts_extrap: error, clamp, extend, linear
 *   TS_VOCAB_PARAM          ts_param: centripetal, chord, uniform
 *   TS_VOCAB_SURFACE_SHAPE  ts_surface_shape: none, positive, bounds, planes, range, grids
 *   TS_VOCAB_TERM           ts_term: user, margin, lower-left, lower-right,
 *                           upper-left, upper-right, monotone, certify, geometric
 *   TS_VOCAB_WHERE          ts_where: none, point, interval, query
 * Values are the enum values, 0 .. ts_vocab_count(vocab) - 1.  The strings
 * are static; every function here is thread-safe.
 */
typedef enum ts_vocab {
    TS_VOCAB_STATUS = 0,
    TS_VOCAB_FORM = 1,
    TS_VOCAB_SLOPES = 2,
    TS_VOCAB_SHAPE = 3,
    TS_VOCAB_EXTRAP = 4,
    TS_VOCAB_PARAM = 5,
    TS_VOCAB_SURFACE_SHAPE = 6,
    TS_VOCAB_TERM = 7,
    TS_VOCAB_WHERE = 8,
    TS_VOCAB_CONSTRAINT = 9, /* ts_constraint_kind: convex, concave, increasing, decreasing,
                                lower, upper, slope-min, slope-max, slope-abs */
    TS_VOCAB_BOUND = 10,     /* ts_bound: constant, polyline, spline */
    TS_VOCAB_CONDITION = 11, /* ts_condition: none, convex-data, concave-data, monotone-data,
                                inside-bound, secant-slope, slope-conflict, unproven,
                                touch-corner, curvature-slope */
    TS_VOCAB_COUNT_ = 12 /* not a vocabulary: their number */
} ts_vocab;

/* The canonical name of value in vocab; NULL when vocab or value is out of
 * range. */
TS_API const char *ts_vocab_name(ts_vocab vocab, int value);
/* The value whose canonical name is name (exact, case-sensitive match).
 * *value is -1 first (value not NULL).  TS_OK; TS_ERR_NULL (name or value
 * NULL); TS_ERR_OPTION (no value of vocab has that name, or vocab out of
 * range). */
TS_API ts_status ts_vocab_value(ts_vocab vocab, const char *name, int *value);
/* Number of values in vocab (for listing them in help texts and docs); 0
 * when vocab is out of range. */
TS_API int ts_vocab_count(ts_vocab vocab);
/* The enumerator name of status ("TS_ERR_SIDE"); "TS_STATUS_UNKNOWN" for a
 * value that is not a status.  Never NULL. */
TS_API const char *ts_status_name(ts_status status);

/* ------------------------------------------------------------------ */
/* Struct guards                                                        */
/* ------------------------------------------------------------------ */

/*
 * Every options, report and context struct the caller allocates
 * (ts_spline_options, ts_curve_options, ts_surface_options, ts_interval_report,
 * ts_patch_report, ts_error_context) starts with
 *     size_t struct_size;
 * which its initialiser sets to sizeof the struct as this header declares it:
 * ts_spline_options_init, ts_curve_options_init, ts_surface_options_init,
 * ts_error_context_init, TS_INTERVAL_REPORT_INIT / ts_interval_report_init,
 * TS_PATCH_REPORT_INIT / ts_patch_report_init.  A function that reads or
 * fills such a struct first compares struct_size with its own sizeof and
 * returns TS_ERR_VERSION on a mismatch, before reading or writing anything
 * else in it: a program compiled against another version's header (where
 * the struct may have other fields) or one that skipped the initialiser
 * fails cleanly instead of reading garbage or writing past the struct.  For
 * an array of reports the first entry's struct_size is checked; the
 * function sets struct_size in every entry it writes.
 */

/* ------------------------------------------------------------------ */
/* Options                                                              */
/* ------------------------------------------------------------------ */

/* docs/method.md §3 paper form, §3 C¹ option, §4 geometric form (default of
 * ts_spline_options_init, docs/method.md §5.10). */
typedef enum ts_form {
    TS_FORM_PAPER = 0,
    TS_FORM_C1 = 1,
    TS_FORM_GEOMETRIC = 2
} ts_form;

/*
 * The geometric form (docs/method.md §4, derivations in docs/accuracy.md).  Each
 * interval is the parametric curve (X(θ), Y(θ)), θ in [0, π/2], with
 * X = [x_i, x_i + k_i, x_{i+1} - k_i, x_{i+1}], Y = the B0..B3 of docs/method.md §3 and
 * k_i = 2 h_i / (3π a_i).  The graph has slope exactly d_i at every knot from
 * both sides (C¹ whatever a_i is; a_i acts as a tension: a_i -> ∞ gives the
 * straight chord), and straight lines are reproduced exactly.
 *
 * Bound on a_i = alpha_i + beta_i.  X(θ) is strictly increasing with X' > 0
 * everywhere exactly when a_i > a* = (16 - 9√2)/(3π) = 0.3471783 (at a* the
 * derivative X' vanishes at θ = π/4: a vertical tangent).  The library
 * requires a_i >= TS_GEOMETRIC_A_MIN = 0.3472 (a* rounded up; there
 * min X' is 1e-4 of its mean, so slopes stay finite):
 *  - beta given by the caller (TS_SHAPE_NONE): a_i < TS_GEOMETRIC_A_MIN fails
 *    with TS_ERR_GEOMETRIC, index = the first such interval.  The library
 *    does not change a curve the caller specified.
 *  - shape schemes (beta chosen by the library): where the scheme's a_i is
 *    below TS_GEOMETRIC_A_RAISE = 4/(3π) it is raised to 4/(3π) (beta_i =
 *    4/(3π) - alpha_i, term TS_TERM_GEOMETRIC).  At 4/(3π) the inner control
 *    abscissae meet (k_i = h_i/2) and X' >= 0.28 of its mean: a well
 *    conditioned curve instead of a near-vertical one at a*.  Raising a_i
 *    never breaks a constraint of docs/method.md §5: every condition there holds on an
 *    interval 0 <= k_i < k_max, so a smaller k_i keeps it.
 * Evaluation solves X(θ) = x by a safeguarded Newton iteration (bracketed,
 * bisection fallback, from the nearer end of the interval; typically 3–5
 * steps), then dS/dx = Y'/X', d²S/dx² = (Y''X' - Y'X'')/X'³.  Knots are
 * reproduced exactly.  Integrals: whole intervals in closed form
 * h(f_i + f_{i+1})/2 + k(d_i - d_{i+1})(2h/5 - Q k), Q = 56/5 - 111π/32;
 * partial intervals by a 12-point Gauss–Legendre rule in θ over at most
 * π/4, exact to rounding for the degree-6 trigonometric integrand.
 * TS_EXTRAP_EXTEND continues the end segment by its osculating parabola
 * (end value, exact end slope d, one-sided end second derivative): the
 * parametric curve itself cannot be continued as a graph.
 */
#define TS_GEOMETRIC_A_MIN 0.3472
#define TS_GEOMETRIC_A_RAISE 0.42441318157838756 /* 4/(3π) */

/*
 * docs/method.md §6.  With two points (n = 1) every method gives d0 = d1 = Δ0.
 * Δ_i is the secant of interval i; at an inner point i the three-point
 * weights are w = h_i/(h_{i-1} + h_i) on Δ_{i-1} and 1 - w on Δ_i (w = 1/2 on
 * a uniform grid).  "Sign-limited ends": the three-point end formula of
 * TS_SLOPES_ARITHMETIC, replaced by 0 unless it has the (non-zero) sign of
 * the end secant.  Every method returns exactly m on data of a line y = m x + c
 * whose secants are exactly equal, never NaN on flat runs (Δ = 0), and d_i = 0
 * at local extrema and flat points for GEOMETRIC, HARMONIC, FRITSCH_CARLSON and
 * STEFFEN.
 *
 *  ARITHMETIC  d_i = w Δ_{i-1} + (1-w) Δ_i; ends d_0 = Δ_0 + (Δ_0 - Δ_1) h_0/(h_0 + h_1)
 *              and its mirror: the slopes of the parabola through three
 *              consecutive points, so exact on quadratics (ends too).
 *  GEOMETRIC   d_i = ±|Δ_{i-1}|^w |Δ_i|^(1-w) when Δ_{i-1}, Δ_i have one sign, else 0
 *              (sign·sqrt(Δ_{i-1} Δ_i) on a uniform grid); sign-limited ends.
 *  HARMONIC    1/d_i = w/Δ_{i-1} + (1-w)/Δ_i when the signs agree, else 0
 *              (Fritsch–Butland 2 Δ_{i-1} Δ_i/(Δ_{i-1} + Δ_i) on a uniform grid);
 *              sign-limited ends.  Same weights as the arithmetic mean, so
 *              |arithmetic| >= |geometric| >= |harmonic| at every inner point.
 *  FRITSCH_CARLSON  Moler's pchip: Brodlie's weighted harmonic mean
 *              d_i = (w1 + w2)/(w1/Δ_{i-1} + w2/Δ_i), w1 = 2h_i + h_{i-1},
 *              w2 = h_i + 2h_{i-1} (0 unless the signs agree); ends: sign-limited,
 *              then 3Δ_0 if Δ_0, Δ_1 differ in sign and |d_0| > 3|Δ_0| (and
 *              mirrored).  On strictly monotone data 0 <= d/Δ <= 3 at both ends of every
 *              interval (Fritsch–Carlson monotonicity region for cubics).
 *  AKIMA       Akima 1970: d_i = (|m_{i+1} - m_i| m_{i-1} + |m_{i-1} - m_{i-2}| m_i)
 *              / (sum of the two weights), m = secants; the plain average
 *              (m_{i-1} + m_i)/2 when both weights are 0.  Two ghost secants at
 *              each end continue the secants linearly: m_{-1} = 2m_0 - m_1,
 *              m_{-2} = 2m_{-1} - m_0, m_n = 2m_{n-1} - m_{n-2}, m_{n+1} = 2m_n - m_{n-1}.
 *              Three points (n = 2): all weights are equal, d = (3Δ_0 - Δ_1)/2,
 *              (Δ_0 + Δ_1)/2, (3Δ_1 - Δ_0)/2 (the parabola's slopes on a uniform grid).
 *  MAKIMA      modified Akima (Moler/Ionita 2019): weights |m_{i+1} - m_i| +
 *              |m_{i+1} + m_i|/2 and |m_{i-1} - m_{i-2}| + |m_{i-1} + m_{i-2}|/2, same
 *              ghosts (also for n = 2); where a flat run (Δ = 0, at least two
 *              intervals) meets a run of another constant slope it gives 0
 *              where Akima's 0/0 rule gives the average.
 *  PERIODIC    the arithmetic mean with wrap-around: interval n-1 is the left
 *              neighbour of point 0; d_n = d_0 exactly.  Needs f[0] == f[n]
 *              exactly (TS_ERR_PERIODIC, index n).
 *  STEFFEN     Steffen 1990 (the default): d_i = (sgn Δ_{i-1} + sgn Δ_i)
 *              min(|Δ_{i-1}|, |Δ_i|, |p_i|/2), p_i the three-point (arithmetic)
 *              slope; so d_i = 0 where the data turn or a neighbouring secant is
 *              0, and d_i = p_i on smooth monotone data away from extrema.
 *              Ends (Steffen's eq. 26): the three-point end value p_0 of
 *              ARITHMETIC, 0 if p_0 Δ_0 <= 0, 2Δ_0 if |p_0| > 2|Δ_0| (and
 *              mirrored).  On every interval 0 <= d/Δ <= 2 at both ends, which
 *              with alpha >= 8/(3π) keeps PCHIP's promise (docs/method.md §5.10).
 *              GSL's gsl_interp_steffen takes d_0 = Δ_0, d_n = Δ_{n-1} at the
 *              ends instead; inner slopes are the same.
 *
 * ts_slopes_compute fills d with NaN when it fails; finite data whose
 * slope overflows (huge f over a tiny h) give TS_ERR_SLOPE_OVERFLOW with the
 * index of the first such point.  No intermediate overflows where the slope
 * is finite (secants of f near ±DBL_MAX, the end formula's Δ_0 − Δ_1).
 */
typedef enum ts_slopes {
    TS_SLOPES_ARITHMETIC = 0,     /* three-point arithmetic mean (the paper's) */
    TS_SLOPES_GEOMETRIC = 1,      /* weighted geometric mean of neighbouring secants (0 if signs differ) */
    TS_SLOPES_HARMONIC = 2,       /* weighted harmonic mean, Fritsch–Butland (three-point weights) */
    TS_SLOPES_FRITSCH_CARLSON = 3,/* PCHIP (Fritsch–Carlson 1980 with Brodlie weights; ends as in Fritsch–Carlson/Moler) */
    TS_SLOPES_AKIMA = 4,          /* Akima 1970 */
    TS_SLOPES_MAKIMA = 5,         /* modified Akima (Moler 2019) */
    TS_SLOPES_USER = 6,           /* ts_spline_options.user_slopes, n+1 values */
    TS_SLOPES_PERIODIC = 7,       /* periodic three-point mean; needs f[0] == f[n] */
    TS_SLOPES_STEFFEN = 8         /* Steffen 1990 (default): 0 <= d/Δ <= 2 on every interval */
} ts_slopes;
#define TS_SLOPES_COUNT_ 9

/*
 * docs/method.md §5.  Which region the curve must stay in.  The caller gives alpha and
 * the margin t; beta_i = t_i + max{0, terms of the §5 rule} (the upper-line
 * terms with the corrected signs of §5.3), recorded in ts_interval_report.term.
 * Then every interval is certified (ts_spline_options.certify) and beta_i changed
 * where the certificate fails (term TS_TERM_CERTIFY).
 *  - Data checks, first offending point named: TS_ERR_NEGATIVE (f < 0),
 *    TS_ERR_LINES (lower line not strictly below the upper at a data point;
 *    checked before TS_ERR_SIDE at the same point), TS_ERR_SIDE (a point
 *    across a line, or on a sloped one: touching a sloped line cannot be
 *    kept; both decided in exact arithmetic, docs/method.md §5.8), and
 *    TS_ERR_NONMONOTONE (index = first i such that f[0..i] is not monotone;
 *    flat runs are allowed).
 *  - Positive data may contain zeros: there S >= 0 (and S > 0 wherever both
 *    ends of an interval are > 0).  At a zero knot the slope is set to 0 (at
 *    the first knot d_0 >= 0, at the last d_n <= 0: clamped; with periodic
 *    slopes both ends are one knot, d_0 = d_n = 0).  Estimated slopes are
 *    changed silently (see ts_spline_slopes); user slopes that break this are
 *    refused with TS_ERR_ZERO_SLOPE (index = the knot).
 *  - Likewise data may touch a constant line (m = 0) of above, below or
 *    between, e.g. probabilities with exact 0 and 1 between y = 0 and
 *    y = 1: there S >= lower (S <= upper), strict on every interval whose
 *    ends are both off that line; the slope at a touching knot is set as
 *    for a zero (pointing into the region at the first and last knot),
 *    user slopes that break it refused with TS_ERR_ZERO_SLOPE.
 *  - Monotone: slopes of the wrong sign are set to 0, user slopes too
 *    (docs/method.md §5.5), and both slopes of a flat interval are 0.  There is no boundary
 *    line: the certificate is the control polygon's monotonicity, which
 *    proves S monotone (docs/method.md (2.1)); the report's gaps are NaN.
 *  - Lines in the paper and C¹ forms: the rule is not a proof (docs/method.md §5), so
 *    a failing interval gets beta_i raised (bisection on a_i) until its
 *    certificate is positive; if the limit a -> ∞ is not inside either (a
 *    steep line, close data), the largest certificate over all beta_i >= 0
 *    is searched (golden section; exact in the paper form, where the gap is
 *    concave in 1/a) and the smallest certified a taken.  If none exists:
 *    TS_ERR_INFEASIBLE, index = interval; if the best gap is positive but
 *    below the certificate's rounding bound: TS_ERR_PRECISION.  (Any scheme also reports it when
 *    the a needed exceeds 1e307, e.g. a value near the underflow threshold
 *    next to a slope of order one.)  In the C¹ form an interval's
 *    curve also depends on its neighbours' a (d̂ of docs/method.md §3); there a
 *    neighbour whose larger a caps the shared knot's slope may be lowered
 *    once; if that fails too, the uniform family a_j = max(alpha_j, A) for
 *    all j is searched (A from max alpha_j upwards by factors 1.1 to 1e6
 *    times it, then bisection to the smallest certified A, plus t).  If
 *    that fails, TS_ERR_INFEASIBLE only where the interval alone is
 *    infeasible (its gap, concave in the two capped slopes' 1/a, has a
 *    negative maximum over every beta >= 0 of it and its neighbours),
 *    TS_ERR_PRECISION where that maximum is positive but below the guard,
 *    and TS_ERR_UNPROVEN otherwise (the search gave up without a proof).
 */
typedef enum ts_shape {
    TS_SHAPE_NONE = 0,      /* beta given by the caller */
    TS_SHAPE_POSITIVE = 1,  /* S >= 0 (S > 0 where all data > 0); Theorem 2 */
    TS_SHAPE_ABOVE = 2,     /* S > lower line (S >= a constant one the data touch); Theorem 3 */
    TS_SHAPE_BELOW = 3,     /* S < upper line (S <= a constant one the data touch); Theorem 4 (corrected signs) */
    TS_SHAPE_BETWEEN = 4,   /* lower < S < upper (<= where data touch a constant line); Theorem 5 (corrected) */
    TS_SHAPE_MONOTONE = 5   /* S monotone where the data are; docs/method.md §5.5 */
} ts_shape;

/* Queries outside [x0, xn]. */
typedef enum ts_extrap {
    TS_EXTRAP_ERROR = 0,  /* TS_ERR_DOMAIN (default) */
    TS_EXTRAP_CLAMP = 1,  /* value of the nearest end; derivatives 0 */
    TS_EXTRAP_EXTEND = 2, /* the end segment's own formula continued (theta outside [0, pi/2]);
                             geometric form: the end's osculating parabola (see TS_FORM_GEOMETRIC) */
    TS_EXTRAP_LINEAR = 3  /* tangent line at the end (end value + one-sided end slope) */
} ts_extrap;

/* The line y = m x + c. */
typedef struct ts_line {
    double m;
    double c;
} ts_line;

/*
 * Default alpha (docs/method.md §5.10).  With slopes in the box
 * 0 <= d/Δ <= D at both ends of an interval, a_i >= 4D/(3π) keeps its control
 * values monotone and between its two data values, so S is monotone there
 * and stays inside the interval's data range (PCHIP's promise; no new
 * extrema).  Steffen's slopes (the default) have D = 2: the bound is
 * 8/(3π) = 0.8488263631567751, rounded up to 0.85 (relative slack 1.4e-3
 * against rounding of the control values).  The geometric form needs
 * a_i >= TS_GEOMETRIC_A_MIN, which 0.85 satisfies.
 */
#define TS_DEFAULT_ALPHA 0.85

/* Default margin t of docs/method.md §5 (dimensionless, added to beta). */
#define TS_DEFAULT_MARGIN 0.01

/*
 * Construction options.  Always start from ts_spline_options_init(), then set
 * fields.  Per-interval arrays override the scalar when non-NULL and must
 * have exactly n = n_points - 1 entries (else TS_ERR_LENGTH).
 */
typedef struct ts_spline_options {
    size_t struct_size;        /* sizeof(ts_spline_options), set by ts_spline_options_init (struct guards) */
    ts_form form;              /* default TS_FORM_GEOMETRIC (the paper's: TS_FORM_PAPER) */
    ts_slopes slopes;          /* default TS_SLOPES_STEFFEN (the paper's: TS_SLOPES_ARITHMETIC) */
    const double *user_slopes; /* TS_SLOPES_USER: n_points values */
    size_t n_user_slopes;

    double alpha;              /* default TS_DEFAULT_ALPHA (the paper's: 1) */
    const double *alphas;      /* optional, per interval */
    size_t n_alphas;

    double beta;               /* default 0; used with TS_SHAPE_NONE only */
    const double *betas;
    size_t n_betas;

    ts_shape shape;            /* default TS_SHAPE_NONE */
    ts_line lower;             /* TS_SHAPE_ABOVE and TS_SHAPE_BETWEEN */
    ts_line upper;             /* TS_SHAPE_BELOW and TS_SHAPE_BETWEEN */
    double margin;             /* t of docs/method.md §5, default TS_DEFAULT_MARGIN */
    const double *margins;
    size_t n_margins;
    int certify;               /* default 1: exact certificate per interval (docs/method.md §5), repair if needed.
                                  0 skips the certificate where the scheme is already rigorous
                                  (positive, monotone, geometric form); line schemes in the paper
                                  and C¹ forms are always certified.  With 0 those schemes are
                                  still checked through the control values alone (S = Σ A_l B_l,
                                  A_l >= 0, Σ A_l = 1: positive needs B1, B2 >= 0 and B0, B3 > 0,
                                  monotone a monotone polygon, geometric lines every
                                  Y_l − m X_l − c > 0), which is a proof, so the spline is still
                                  certified (ts_spline_certified = 1); ts_spline_report then
                                  computes the exact gaps on demand. */

    ts_extrap extrapolate;     /* default TS_EXTRAP_ERROR */

    /* Constraint records (see "Constraints" below): NULL / 0 by default.  With
     * n_constraints > 0 the spline is built by the constraint scheme of
     * docs/method.md §13 (geometric form only; shape must be TS_SHAPE_NONE). */
    const struct ts_constraint *constraints;
    size_t n_constraints;
} ts_spline_options;

/* The defaults: geometric form, Steffen's slopes, alpha = TS_DEFAULT_ALPHA,
 * beta 0, no shape scheme, margin TS_DEFAULT_MARGIN, certify on, extrapolation
 * error.  Every interval of the default curve is monotone and between its two
 * data values (docs/method.md §5.10).  The paper's own spline: form
 * TS_FORM_PAPER, slopes TS_SLOPES_ARITHMETIC, alpha 1. */
TS_API void ts_spline_options_init(ts_spline_options *opt);

/* ------------------------------------------------------------------ */
/* Slopes on their own                                                  */
/* ------------------------------------------------------------------ */

/*
 * Estimate slopes d[0..n_points-1] by a method of docs/method.md §6 (not TS_SLOPES_USER).
 * Returns TS_OK, TS_ERR_NULL, TS_ERR_TOO_FEW, TS_ERR_NONFINITE (index =
 * point), TS_ERR_UNSORTED, TS_ERR_WIDTH (a width overflows), TS_ERR_OPTION,
 * TS_ERR_PERIODIC, TS_ERR_SLOPE_OVERFLOW (a slope overflows; index = point).  On failure d (if not NULL) is filled with NaN.
 */
TS_API ts_status ts_slopes_compute(ts_slopes method, const double *x, const double *f,
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
 * TS_ERR_INFEASIBLE, TS_ERR_GEOMETRIC, TS_ERR_ZERO_SLOPE, TS_ERR_SLOPE_OVERFLOW,
 * TS_ERR_TOO_LARGE, TS_ERR_CONTROL_OVERFLOW, TS_ERR_WIDTH, TS_ERR_PRECISION,
 * TS_ERR_UNPROVEN, TS_ERR_VERSION (opt->struct_size, checked right after the
 * NULL arguments).
 *
 * Which fault is reported when the input has several: first the arguments
 * (NULL, too few points, an enum out of range, sizes), then every point
 * (non-finite, unsorted, widths, |f| > TS_VALUE_MAX), then options that concern all the data
 * (user slopes array, periodic ends, array lengths, the scheme's options and
 * lines); then the intervals are built in consecutive blocks of 1024, and
 * in each block the stages run in order — slopes (non-finite), alpha, beta
 * or the scheme's data checks and rule, the geometric bound, controls and
 * certificates (TS_ERR_INFEASIBLE) — so the fault reported is the first of
 * the first block that has one (for n_points <= 1025: the first in stage
 * order).  In the C¹ form certificates follow all blocks.  Control values
 * that overflow (TS_ERR_CONTROL_OVERFLOW) or exceed TS_VALUE_MAX
 * (TS_ERR_TOO_LARGE), an interval, are reported last.
 */
TS_API ts_status ts_spline_new(const double *x, const double *f, size_t n_points,
                        const ts_spline_options *opt, ts_spline **out, ts_error *err);

TS_API void ts_spline_free(ts_spline *s);

/* ---- accessors (never fail on a valid spline; pointers live as long as s;
 * s NULL: 0, NULL, TS_FORM_PAPER, TS_SHAPE_NONE, TS_EXTRAP_ERROR) */
TS_API size_t ts_spline_intervals(const ts_spline *s);     /* n */
TS_API const double *ts_spline_x(const ts_spline *s);      /* n+1 knots */
TS_API const double *ts_spline_f(const ts_spline *s);      /* n+1 values */
TS_API const double *ts_spline_slopes(const ts_spline *s); /* n+1 slopes d_i actually used (after any shape adjustment) */
TS_API const double *ts_spline_alpha(const ts_spline *s);  /* n */
TS_API const double *ts_spline_beta(const ts_spline *s);   /* n */
TS_API ts_form ts_spline_form(const ts_spline *s);
TS_API ts_shape ts_spline_shape(const ts_spline *s);
TS_API ts_extrap ts_spline_extrapolation(const ts_spline *s);

/* a_i = alpha_i + beta_i.  TS_OK or TS_ERR_NULL, TS_ERR_INDEX. */
TS_API ts_status ts_spline_a(const ts_spline *s, size_t i, double *a);

/* The four control values B0..B3 of interval i (docs/method.md §3; for the C¹ option the
 * ones built from d̂) and abscissae X0..X3 for plotting the control polygon
 * (X may be NULL).  Geometric form: the X of docs/method.md §4, x_i + (0, k, h − k, h)
 * with k = 2h/(3π a_i).  Paper and C¹ forms: x_i + (0, K, h − K, h) with
 * K = 2h/(3π), so that the polygon's first and last legs are tangent to the
 * curve (S'(x_i+) = (B1 − B0)/K).  TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
TS_API ts_status ts_spline_control(const ts_spline *s, size_t i, double B[4], double X[4]);

/* Which term of the docs/method.md §5 rule set beta_i. */
typedef enum ts_term {
    TS_TERM_USER = 0,        /* beta given by the caller (TS_SHAPE_NONE) */
    TS_TERM_MARGIN = 1,      /* max{...} was 0: beta = t */
    TS_TERM_LOWER_LEFT = 2,  /* -alpha - K d_i / g_i */
    TS_TERM_LOWER_RIGHT = 3, /* -alpha + K d_{i+1} / g_{i+1} */
    TS_TERM_UPPER_LEFT = 4,  /* -alpha + K d_i / G_i */
    TS_TERM_UPPER_RIGHT = 5, /* -alpha - K d_{i+1} / G_{i+1} */
    TS_TERM_MONOTONE = 6,    /* 2(d_i + d_{i+1})/(3 pi Δ_i) - alpha */
    TS_TERM_CERTIFY = 7,     /* raised by the certificate repair (docs/method.md §5) */
    TS_TERM_GEOMETRIC = 8    /* raised to the geometric-form bound (docs/method.md §4) */
} ts_term;

/* Per-interval report: what was built and its certificate. */
typedef struct ts_interval_report {
    size_t struct_size;     /* sizeof(ts_interval_report): TS_INTERVAL_REPORT_INIT or
                               ts_interval_report_init before the first call (struct guards) */
    double x0, x1;          /* interval ends */
    double alpha, beta, a;  /* a = alpha + beta */
    double B[4];            /* control values */
    ts_term term;           /* which term chose beta */
    int has_lower, has_upper;
    double gap_lower;       /* exact min over the interval of S(x) - lower(x) (NaN if !has_lower) */
    double at_lower;        /* the x where it is attained */
    double gap_upper;       /* exact min of upper(x) - S(x) (NaN if !has_upper) */
    double at_upper;
    int certified;          /* every active gap > 0 (with the rounding guard of docs/method.md §5.6);
                               a spline built with constraint records: 1 (every record proven on
                               the interval, ts_spline_constraint_report) */
    /* Range and overshoot of the interval (docs/method.md §5.9), for every
     * spline (shape scheme or not; also from ts_spline_certify, and per coordinate
     * from ts_curve_certify*, there in the parameter t).  Exact extrema of the
     * interval's trigonometric polynomial, computed as the gaps are (the gap to
     * the line y = 0), without a rounding guard.  NaN when not computed. */
    double y_min, at_y_min; /* min of S over [x0, x1] and an x where it is attained */
    double y_max, at_y_max; /* max of S over [x0, x1] and an x where it is attained */
    double excursion_above; /* y_max - max(S(x0), S(x1)) >= 0: how far the curve rises above
                             * the larger of the interval's two data values (0: it does not) */
    double excursion_below; /* min(S(x0), S(x1)) - y_min >= 0: how far it dips below the smaller */
} ts_interval_report;
/* ts_interval_report rep = TS_INTERVAL_REPORT_INIT;  (a C99 designated
 * initialiser, which C++ accepts from C++20 on; before that, and for arrays,
 * call ts_interval_report_init) */
#define TS_INTERVAL_REPORT_INIT {.struct_size = sizeof(ts_interval_report)}
/* Initialise n reports (an array for ts_spline_certify, ts_curve_certify*): struct_size
 * set, values NaN, flags 0.  reports may be NULL (then nothing happens). */
TS_API void ts_interval_report_init(ts_interval_report *reports, size_t n);
/*
 * The gaps are exact: the minimum of a degree-3 trigonometric polynomial
 * (minus a linear function) from all its critical points (docs/method.md §2, §5),
 * computed in floating point, in the interval's own coordinates (the line
 * as its value at x0 and its rise m (x1 - x0): translating x and the line
 * together by an exact shift changes nothing).  "certified" requires
 * gap > guard, a bound on the rounding of that computation (about 1e-14 of
 * the size of the control values, of the line at x0 and of its rise over the
 * interval, never of m x or c on their own; docs/method.md §5.6 derives it).
 * Where no beta brings the gap above it although the gap may be positive,
 * construction returns TS_ERR_PRECISION.  Exceptions:
 * positive intervals are also certified by B1, B2 >= 0 and B0, B3 > 0, and
 * an interval with a zero end (positive data with zeros) by all B_l >= 0;
 * its gap is then 0, attained at the zero knot.  Monotone intervals are
 * certified by a monotone control polygon and have no gap (NaN).  In the
 * paper and C¹ forms an interval against a constant line (m = 0) is also
 * certified when every control value B_l is strictly on the line's side
 * (S - c = Σ A_l (B_l - c), a convex combination), however small the gaps,
 * and against any line when min_l B_l - max(L(x0), L(x1)) (lower line; for
 * the upper min(U(x0), U(x1)) - max_l B_l) exceeds its own rounding guard
 * (S >= min B_l, and a line is largest at an end: docs/method.md §5.6 item 8);
 * the reported gap is still the exact minimum.
 * In the geometric form a line interval (and ts_spline_certify there) is also certified
 * when every control gap Y_l - m X_l - c is positive (convex hull, docs/method.md §4),
 * each evaluated to the rounding of the gap itself (fma and error-free sums),
 * so a knot 1e-14 of |c| from the line is no obstacle; its guard likewise.
 */

/* Report of interval i.  For shape schemes the boundaries are the scheme's
 * (positive: lower = 0); for TS_SHAPE_NONE no boundary (has_* = 0).
 * TS_OK, TS_ERR_NULL, TS_ERR_INDEX, TS_ERR_VERSION (rep->struct_size; rep is
 * then left untouched; checked first). */
TS_API ts_status ts_spline_report(const ts_spline *s, size_t i, ts_interval_report *rep);

/* 1 when every interval of a shape-constrained spline is certified, 0 otherwise
 * (also 0 for TS_SHAPE_NONE without constraint records: nothing was
 * promised; 1 for a spline built with records, every one certified). */
TS_API int ts_spline_certified(const ts_spline *s);

/*
 * Certify any spline (e.g. one built with the caller's own beta) against an
 * optional lower and upper line (either may be NULL; both NULL is
 * TS_ERR_NULL).  reports, if not NULL, receives n entries.  Returns TS_OK
 * when every interval keeps lower < S < upper, TS_ERR_VIOLATED otherwise
 * (err->index = first violating interval), TS_ERR_NONFINITE for a non-finite
 * line, TS_ERR_NULL, TS_ERR_VERSION (reports[0].struct_size; checked first,
 * reports then untouched).  reports are reset (NaN) before any other check.
 */
TS_API ts_status ts_spline_certify(const ts_spline *s, const ts_line *lower, const ts_line *upper,
                     ts_interval_report *reports, ts_error *err);

/* ------------------------------------------------------------------ */
/* Constraints: any shape a user can state, certified                  */
/* ------------------------------------------------------------------ */

/*
 * A list of constraint records, passed in ts_spline_options.constraints
 * (n_constraints of them), each certified exactly on every interval it
 * covers (docs/method.md §13 has the derivations and proofs).  The
 * geometric form only (TS_ERR_OPTION otherwise, and with a shape scheme).
 *
 *   TS_CONSTRAINT_CONVEX      S'' >= 0        CONCAVE  S'' <= 0
 *   TS_CONSTRAINT_INCREASING  S' >= 0         DECREASING  S' <= 0
 *   TS_CONSTRAINT_LOWER       S >= bound      UPPER    S <= bound
 *   TS_CONSTRAINT_SLOPE_MIN   S' >= value     SLOPE_MAX  S' <= value
 *   TS_CONSTRAINT_SLOPE_ABS   |S'| <= value (value >= 0)
 *
 * A bound (lower, upper) is TS_BOUND_CONSTANT (y = value) or
 * TS_BOUND_POLYLINE: the piecewise-linear function through (px[j], py[j]),
 * j < n_poly (n_poly >= 2, px strictly increasing), on [px[0],
 * px[n_poly-1]] and no bound outside it; its breakpoints need not be knots;
 * or TS_BOUND_SPLINE: another spline B (any form, its own knots, built by
 * ts_spline_new), the bound on [x_0, x_m] of B and none outside it.  The
 * fitted spline copies B's knots and control values (ts_spline_free frees
 * them): B may be freed once ts_spline_new has returned, and
 * ts_spline_constraint_report still reports S − B.  Data must lie strictly
 * on their side of B (a point touching B, or within the rounding enclosure
 * of B(x_j), is refused: TS_ERR_CONDITION, inside-bound); S − B is
 * certified by subdivision with the convex hull of rational Bernstein
 * coefficients in rigorous enclosures (docs/method.md §13.7).
 * Scope: intervals first .. first + count − 1 (count 0: first .. n − 1;
 * both 0 by ts_constraint_init: the whole range).
 *
 * The scheme (docs/method.md §13): slopes are estimated by opt->slopes and
 * changed where a constraint needs it (convex/concave: the three-point
 * slope, strictly between the neighbouring secants; increasing, slope
 * bounds: clamped), then a_i = alpha_i + beta_i is raised to the largest
 * closed-form requirement of the constraints on interval i (each a proof
 * through the control polygon), then every interval and constraint is
 * certified (exact signs of control-polygon quantities, or for a polyline
 * bound the exact minimum on each piece with a rounding guard) and a_i
 * doubled where a certificate fails.
 *
 * Failures of ts_spline_new with constraints (index as for other schemes):
 *   TS_ERR_CONDITION   the data violate a necessary condition (index = point
 *                      or interval): second divided differences of the wrong
 *                      sign (convex/concave), a secant beyond a slope bound,
 *                      data changing direction (increasing/decreasing), a
 *                      data point across a bound, or on a polyline's inner
 *                      breakpoint that turns into the region (lower: the
 *                      slope rises there; touch-corner), or on or within
 *                      rounding of a bound spline (not certified there),
 *                      or a knot where the slope a record allows (slope
 *                      bound, monotone, a touched bound) lies beyond the
 *                      secant a convex/concave record needs on its side
 *                      (curvature-slope, index = point).
 *                      A bound may be touched: a constant one with slope 0
 *                      there (pointing into the region at the ends), a
 *                      polyline with the slope between those of its two
 *                      pieces (docs/method.md §13.6);
 *   TS_ERR_INFEASIBLE  the slopes the constraints require at a knot
 *                      exclude each other (a proof that no C¹ curve exists);
 *   TS_ERR_UNPROVEN    no certified a_i up to 2^60 alpha_i was found, without
 *                      a proof that none exists (certified: every record's
 *                      certificate holds and the stored curve's slope at each
 *                      inner knot is d_i within 2^-20 of the slopes there,
 *                      docs/method.md §13.4; polyline and spline bounds;
 *                      also a slope bound that a data secant reaches exactly:
 *                      the interval must then be that line, and its rounded
 *                      control values are collinear only where f_{i+1} − L h κ
 *                      is a double, which doubling a does not change);
 *   TS_ERR_OPTION      an unknown kind or bound type, a scope beyond the
 *                      intervals, a form other than geometric, a shape;
 *   TS_ERR_NONFINITE   a non-finite value or polyline point;
 *   TS_ERR_UNSORTED    polyline abscissae not strictly increasing;
 *   TS_ERR_LENGTH      a polyline with fewer than 2 points;
 *   TS_ERR_NULL        constraints NULL with n_constraints > 0, px/py NULL,
 *                      spline NULL (TS_BOUND_SPLINE);
 *   TS_ERR_VERSION     a record whose struct_size is not sizeof(ts_constraint).
 * ts_constraints_diagnose says which constraint and which condition.
 */
typedef enum ts_constraint_kind {
    TS_CONSTRAINT_CONVEX = 0,
    TS_CONSTRAINT_CONCAVE = 1,
    TS_CONSTRAINT_INCREASING = 2,
    TS_CONSTRAINT_DECREASING = 3,
    TS_CONSTRAINT_LOWER = 4,
    TS_CONSTRAINT_UPPER = 5,
    TS_CONSTRAINT_SLOPE_MIN = 6,
    TS_CONSTRAINT_SLOPE_MAX = 7,
    TS_CONSTRAINT_SLOPE_ABS = 8
} ts_constraint_kind;
#define TS_CONSTRAINT_COUNT_ 9

typedef enum ts_bound {
    TS_BOUND_CONSTANT = 0,
    TS_BOUND_POLYLINE = 1,
    TS_BOUND_SPLINE = 2
} ts_bound;

typedef struct ts_constraint {
    size_t struct_size;        /* sizeof(ts_constraint), set by ts_constraint_init */
    ts_constraint_kind kind;
    ts_bound bound;            /* LOWER, UPPER: default TS_BOUND_CONSTANT */
    double value;              /* constant bound, slope bound, |S'| cap; default 0 */
    const double *px, *py;     /* TS_BOUND_POLYLINE: n_poly points */
    size_t n_poly;
    size_t first, count;       /* scope in intervals; default 0, 0: all */
    const ts_spline *spline;   /* TS_BOUND_SPLINE: the bound curve B (kept alive by the
                                  caller during ts_spline_new only; the fitted spline
                                  keeps its own copy of what it needs) */
} ts_constraint;

/* A record of kind with every other field at its default. */
TS_API void ts_constraint_init(ts_constraint *c, ts_constraint_kind kind);

/* Which necessary condition or search failed (ts_constraints_diagnose). */
typedef enum ts_condition {
    TS_CONDITION_NONE = 0,           /* nothing failed */
    TS_CONDITION_CONVEX_DATA = 1,    /* Δ_{i-1} <= Δ_i (convex) violated at point i */
    TS_CONDITION_CONCAVE_DATA = 2,   /* Δ_{i-1} >= Δ_i (concave) violated at point i */
    TS_CONDITION_MONOTONE_DATA = 3,  /* data change direction at point i */
    TS_CONDITION_INSIDE_BOUND = 4,   /* point i across the bound */
    TS_CONDITION_SECANT_SLOPE = 5,   /* the secant of interval i beyond the slope bound
                                        (S' = Δ_i somewhere in it: mean value theorem) */
    TS_CONDITION_SLOPE_CONFLICT = 6, /* the slope ranges required at knot i are disjoint */
    TS_CONDITION_UNPROVEN = 7,       /* interval i: the search gave up, no proof of infeasibility */
    TS_CONDITION_TOUCH_CORNER = 8,   /* point i lies on a polyline bound at a breakpoint that
                                        turns towards the region (lower: the slope rises there):
                                        no C¹ curve on the bound's side passes through it */
    TS_CONDITION_CURVATURE_SLOPE = 9 /* at knot i the slope the record allows (slope bound,
                                        monotone, a bound the data touch) excludes the secant
                                        side a convex / concave record on a neighbouring
                                        interval needs (convex: S'(x_i) >= Δ_{i-1},
                                        S'(x_i) <= Δ_i) */
} ts_condition;

typedef struct ts_constraint_failure {
    size_t struct_size;   /* sizeof(ts_constraint_failure): ts_constraint_failure_init */
    ts_status status;     /* what ts_spline_new returned */
    size_t constraint;    /* index of the record; TS_NO_INDEX when none is to blame */
    size_t index;         /* point or interval (where) */
    ts_where where;
    ts_condition condition;
} ts_constraint_failure;
TS_API void ts_constraint_failure_init(ts_constraint_failure *f);

/*
 * Build as ts_spline_new would and say why it fails: fills *fail (status,
 * the constraint record, point or interval, the condition); TS_OK with
 * fail->condition TS_CONDITION_NONE when ts_spline_new succeeds.  Returns
 * what ts_spline_new returns; TS_ERR_NULL (fail NULL too), TS_ERR_VERSION
 * (fail->struct_size; checked first).
 */
TS_API ts_status ts_constraints_diagnose(const double *x, const double *f, size_t n_points,
                                         const ts_spline_options *opt,
                                         ts_constraint_failure *fail);

/* Per interval and constraint: was it active, its exact gap, its proof. */
typedef struct ts_constraint_report {
    size_t struct_size;   /* sizeof(ts_constraint_report): ts_constraint_report_init */
    int in_scope;         /* the constraint covers interval i (else the rest is NaN / 0) */
    int active;           /* it set a_i (its requirement was the largest) or changed a
                             slope at one of the interval's knots */
    double gap;           /* exact minimum over the interval (the part covered by a
                             polyline or a bound spline) of: S'' (convex), −S'' (concave), S' (increasing),
                             −S' (decreasing), S − bound (lower), bound − S (upper),
                             S' − value (slope-min), value − S' (slope-max),
                             value − |S'| (slope-abs); >= 0 where certified */
    double at;            /* an x where it is attained */
    int certified;        /* 1: proved (control polygon in exact arithmetic, the
                             minimum above its rounding guard, or for a bound
                             spline the subdivision of docs/method.md §13.7) */
} ts_constraint_report;
TS_API void ts_constraint_report_init(ts_constraint_report *r);

/* Number of constraint records the spline was built with (0 for none). */
TS_API size_t ts_spline_constraints(const ts_spline *s);
/* The report of record k on interval i.  TS_OK, TS_ERR_NULL, TS_ERR_INDEX
 * (k or i out of range), TS_ERR_VERSION (rep->struct_size; checked first,
 * rep untouched). */
TS_API ts_status ts_spline_constraint_report(const ts_spline *s, size_t k, size_t i,
                                             ts_constraint_report *rep);

/* ---- evaluation ---------------------------------------------------- */

/* Caller-owned lookup hint; zero-initialise (TS_CURSOR_INIT) or pass NULL. */
typedef struct ts_cursor {
    size_t interval;
} ts_cursor;
#define TS_CURSOR_INIT {0}

/*
 * Value and derivatives at x.  Any of y, dy, d2y may be NULL.  On failure the
 * non-NULL outputs are set to NaN.
 * Returns TS_OK, TS_ERR_NULL (s), TS_ERR_DOMAIN (x NaN; x outside the data
 * under TS_EXTRAP_ERROR; x = ±Inf under any policy but TS_EXTRAP_CLAMP).
 * At an inner knot the right-hand interval is used (derivatives of the paper
 * form jump there, docs/method.md §3).
 */
TS_API ts_status ts_spline_eval(const ts_spline *s, double x, ts_cursor *cur, double *y);
TS_API ts_status ts_spline_eval_deriv(const ts_spline *s, double x, ts_cursor *cur,
                        double *y, double *dy, double *d2y);

/*
 * Batch: yq[j] = S^(deriv)(xq[j]), deriv >= 0.  Fast for sorted
 * queries, correct for any order; deriv 0, 1, 2 use the batch kernels of
 * src/kernels.c (every form), which agree with ts_spline_eval_deriv to the bounds
 * derived and tested in tests/unit/test_fast.c (not bitwise).  deriv >= 3:
 * paper and C¹ forms only, the closed form of docs/method.md §2
 * (derivatives of any order) per query, as ts_spline_eval_mode; outside the
 * data 0 under TS_EXTRAP_CLAMP and TS_EXTRAP_LINEAR, the end interval's
 * formula under TS_EXTRAP_EXTEND.  Every valid query is
 * evaluated; invalid ones get NaN and the call returns TS_ERR_DOMAIN with
 * err->index = first invalid query.  Also TS_ERR_NULL, TS_ERR_OPTION (deriv
 * < 0, or deriv > 2 in the geometric form; every yq[j] NaN).
 */
TS_API ts_status ts_spline_eval_batch(const ts_spline *s, int deriv, const double *xq, size_t m,
                        double *yq, ts_cursor *cur, ts_error *err);

/* Same, split over nthreads threads (0 = number of cores).  Off unless called.
 * Same statuses. */
TS_API ts_status ts_spline_eval_batch_mt(const ts_spline *s, int deriv, const double *xq, size_t m,
                           double *yq, unsigned nthreads, ts_error *err);

/*
 * Evaluation with the extrapolation given per call (extrap overrides the
 * spline's own, which stays as built) and a derivative of any order nu >= 0.
 * Inside [x0, xn] the values are those of ts_spline_eval_deriv (nu <= 2, scalar),
 * ts_spline_eval_batch (batch) and, for nu >= 3 (paper and C¹ forms only), the
 * closed form of docs/method.md §2 (derivatives of any order) on the
 * interval of the query (the right-hand one at an inner knot).  Outside:
 *   TS_EXTRAP_ERROR   TS_ERR_DOMAIN (NaN)
 *   TS_EXTRAP_CLAMP   the end value; every derivative 0 (x = ±Inf too)
 *   TS_EXTRAP_EXTEND  the end interval's formula continued (the geometric
 *                     form: the osculating parabola), every order
 *   TS_EXTRAP_LINEAR  f_end + d (x − x_end), d the one-sided end slope; S' = d,
 *                     higher derivatives 0.  x = ±Inf gives the limit: the end
 *                     value where d = 0, else ±Inf (ts_spline_eval instead returns
 *                     TS_ERR_DOMAIN at ±Inf under a stored TS_EXTRAP_LINEAR)
 * For finite x every mode gives the bits ts_spline_eval_deriv / ts_spline_eval_batch give
 * on a spline built with that mode.  NaN is always TS_ERR_DOMAIN, ±Inf under
 * ERROR and EXTEND too.  No allocation.
 * ts_spline_eval_mode: *y (NaN on failure).  TS_OK, TS_ERR_NULL (s, y),
 * TS_ERR_OPTION (nu < 0, nu > 2 in the geometric form, extrap out of range),
 * TS_ERR_DOMAIN.
 * ts_spline_eval_batch_mode: as ts_spline_eval_batch (invalid queries NaN,
 * TS_ERR_DOMAIN with err->index = the first; TS_ERR_NULL; TS_ERR_OPTION for
 * nu or extrap, every yq[j] NaN).  _mt: split over nthreads threads as
 * ts_spline_eval_batch_mt, same statuses.
 */
TS_API ts_status ts_spline_eval_mode(const ts_spline *s, double x, int nu, ts_extrap extrap,
                                     ts_cursor *cur, double *y);
TS_API ts_status ts_spline_eval_batch_mode(const ts_spline *s, int nu, ts_extrap extrap,
                                           const double *xq, size_t m, double *yq, ts_cursor *cur,
                                           ts_error *err);
TS_API ts_status ts_spline_eval_batch_mode_mt(const ts_spline *s, int nu, ts_extrap extrap,
                                              const double *xq, size_t m, double *yq,
                                              unsigned nthreads, ts_error *err);

/*
 * The interval of x: the largest i <= n − 1 with x_i <= x (the right-hand
 * interval at an inner knot, the last one at xn), the search every
 * evaluation uses; the cursor (may be NULL) is tried first (and its
 * successor, for sorted queries) and left on the interval found.
 * *i = TS_NO_INDEX first.  TS_OK, TS_ERR_NULL (s, i), TS_ERR_DOMAIN (x
 * outside [x0, xn] or NaN).
 */
TS_API ts_status ts_spline_find_interval(const ts_spline *s, double x, ts_cursor *cur, size_t *i);

/*
 * Every x in [x0, xn] with S(x) = y, increasing (scipy.interpolate.PPoly.solve
 * without extrapolation): per interval the real roots of q³(S − y), a
 * polynomial of degree 6 in t = tan(θ/2), q = 1 + t² (docs/method.md §2,
 * roots), isolated in Bernstein form and bisected to rounding in t; a knot
 * where f_i = y exactly is returned exactly, once.  An interval on which
 * S == y identically (all four control values equal y) gives its left end
 * followed by NaN, as SciPy.  Multiple roots (S touching y) are returned
 * once, to about the square root of the rounding.  No root when y is not
 * finite or |y| > TS_VALUE_MAX (|S| <= max |B_l| there).  No allocation.
 * roots receives at most cap values; *count the number of values there are
 * (also when they do not fit), so (roots = NULL, cap = 0) asks for the size.
 * TS_OK; TS_ERR_LENGTH (*count > cap: the first cap are in roots);
 * TS_ERR_NULL (s or count NULL, or roots NULL with cap > 0; *count 0).
 */
TS_API ts_status ts_spline_solve(const ts_spline *s, double y, double *roots, size_t cap,
                                 size_t *count);

/*
 * Definite integral of S over [a, b] (b < a gives the negative), closed form
 * (geometric form: Gauss–Legendre exact to rounding inside an interval, see
 * TS_FORM_GEOMETRIC).
 * a and b must lie in [x0, xn]: TS_ERR_DOMAIN otherwise (or NaN).  TS_ERR_NULL.
 * The result is finite wherever the integral is (also when partial sums
 * overflow: the pieces are then summed again scaled by a power of 2) and
 * ±Inf where it overflows; never NaN for a and b in range.
 */
TS_API ts_status ts_spline_integral(const ts_spline *s, double a, double b, double *out);

/* ------------------------------------------------------------------ */
/* Parametric curves (docs/method.md §7)                                          */
/* ------------------------------------------------------------------ */

typedef struct ts_curve ts_curve;

/*
 * A curve through points P_0..P_m in R^dim (dim 2 or 3).  Every coordinate is
 * a spline of docs/method.md §3 in the parameter t, with the same alpha_i, beta_i in
 * all coordinates of segment i.  At an inner knot the derivative of each
 * coordinate is d_i/a_{i-1} from the left and d_i/a_i from the right
 * (a = alpha + beta), so the tangent directions agree (GC¹) and the curve is
 * C¹ in t wherever neighbouring segments have equal a.
 *
 * Not every property of the points carries over to the curve:
 *  - Uniform parameters with linear slopes (arithmetic, periodic) and no box:
 *    the curve of A·P + b is A·curve + b for any affine map (same t).
 *  - Chord and centripetal parameters: invariant under similarity maps only
 *    (rotation, reflection, uniform scale s, translation; t scales by s resp.
 *    sqrt(s)).  A shear or non-uniform scale changes the knots and the curve.
 *  - The nonlinear slope methods (geometric, harmonic, Fritsch–Carlson, Akima,
 *    modified Akima) act per coordinate: with uniform knots they are
 *    invariant under translation and per-axis scaling, not under rotation.  Fritsch–Carlson, harmonic and
 *    geometric give d = 0 in a coordinate at its local extrema; where every
 *    coordinate has one at the same point the tangent vector is 0 (a corner).
 *  - Each segment lies in the convex hull of its 4 control points (the basis
 *    is >= 0 and sums to 1, docs/method.md §2).
 *  - As beta grows each segment tends to the chord P_i c² + P_{i+1} s²: the
 *    curve tends to the polygon through the points (see docs/curves.md).
 */
typedef enum ts_param {
    TS_PARAM_CENTRIPETAL = 0, /* default: t_{i+1} - t_i = |P_{i+1} - P_i|^(1/2) */
    TS_PARAM_CHORD = 1,       /* |P_{i+1} - P_i| */
    TS_PARAM_UNIFORM = 2      /* 1 */
} ts_param;

/* Start from ts_curve_options_init(), then set fields.  "Segments" below is
 * n_points - 1 for an open curve and the number of distinct points for a
 * closed one. */
typedef struct ts_curve_options {
    size_t struct_size;      /* sizeof(ts_curve_options), set by ts_curve_options_init */
    ts_param param;          /* default TS_PARAM_CENTRIPETAL; knots start at t_0 = 0 */
    int closed;              /* default 0; nonzero: closed.  The first point may be
                                repeated at the end (detected by exact equality of all
                                coordinates) or left implied; both give the same curve. */
    ts_slopes slopes;        /* default TS_SLOPES_ARITHMETIC.  Any method of docs/method.md §6 except
                                TS_SLOPES_USER (TS_ERR_OPTION), applied per coordinate in t.
                                Closed curves: the method is applied to the periodic
                                extension of the data, so the seam is like any inner knot
                                (arithmetic = the periodic three-point mean).
                                TS_SLOPES_PERIODIC: closed curves only (same as arithmetic
                                there); TS_ERR_OPTION for an open curve. */
    double alpha;            /* default 1 */
    const double *alphas;    /* per segment (n_alphas == segments) */
    size_t n_alphas;
    double beta;             /* default 0; with a box: beta_i = max(this, docs/method.md §5 value) */
    const double *betas;
    size_t n_betas;
    /* Box constraint (docs/method.md §5 per coordinate, shared beta per segment):
     * coordinate k kept > lo[k] when has_lo[k], < hi[k] when has_hi[k]
     * (nonzero = active; entries k >= dim are ignored); a point may lie on
     * a side (>=, <= there: its tangent component along k is set to 0,
     * clamped into the box at an open curve's ends; docs/method.md §5.8).  beta_i is the max over
     * the coordinates of the lower/upper-boundary rule with a constant line
     * (and margin t), then every segment and coordinate is certified exactly;
     * where a certificate fails (rounding only: the rule is rigorous for a
     * constant bound), beta_i is raised by bisection.  Evaluation returns
     * points in the box, sides included (ts_curve_eval, ts_curve_sample):
     * a coordinate that rounding puts beyond a side is set to that side,
     * a move no larger than its rounding error, as the exact point is
     * inside (docs/method.md §7 "Evaluation inside the box"). */
    int has_lo[3], has_hi[3];
    double lo[3], hi[3];
    double margin;           /* default TS_DEFAULT_MARGIN; checked only with a box */
} ts_curve_options;

TS_API void ts_curve_options_init(ts_curve_options *opt);

/*
 * points: n_points rows of dim (2 or 3) doubles, row-major.  opt may be NULL
 * (defaults).  *out is set to NULL first, then to the curve on success.
 * Returns:
 *   TS_ERR_NULL        points or out NULL
 *   TS_ERR_DIMENSION   dim not 2 or 3
 *   TS_ERR_OPTION      param or slopes out of range, TS_SLOPES_USER, or
 *                      TS_SLOPES_PERIODIC on an open curve
 *   TS_ERR_TOO_FEW     n_points < 2; closed: fewer than 3 distinct points
 *   TS_ERR_OVERFLOW    n_points * 4 * dim * sizeof(double) (the control
 *                      points) overflows size_t
 *   TS_ERR_NONFINITE   NaN/Inf coordinate (index = point); a non-finite box
 *                      bound; or knots or control points that overflow
 *                      (index = point, or segment for control points)
 *   TS_ERR_SLOPE_OVERFLOW  a slope in t overflows (index = point)
 *   TS_ERR_LENGTH      alphas/betas given with n_* != segments
 *   TS_ERR_ALPHA       alpha_i <= 0 or not finite (index = segment)
 *   TS_ERR_BETA        beta_i < 0 or not finite, or alpha_i + beta_i overflows (index = segment)
 *   TS_ERR_MARGIN      a box with margin <= 0 or not finite
 *   TS_ERR_UNSORTED    two consecutive equal points, any parameterisation
 *                      (index = the second of the pair; for the seam of a closed
 *                      curve, the last point kept), or a knot step lost to rounding
 *   TS_ERR_SIDE        a point outside the box (index = point)
 *   TS_ERR_INFEASIBLE  the docs/method.md §5 value of beta_i overflows, or no finite
 *                      beta_i certifies (slope/gap ratios beyond ~1e300 only;
 *                      index = segment)
 *   TS_ERR_NOMEM
 *   TS_ERR_VERSION     opt->struct_size (checked right after TS_ERR_NULL).
 */
TS_API ts_status ts_curve_new(const double *points, size_t n_points, size_t dim,
                       const ts_curve_options *opt, ts_curve **out, ts_error *err);
/* NULL is a no-op. */
TS_API void ts_curve_free(ts_curve *c);

/* Accessors; 0 / NULL for c == NULL.  Pointers live as long as c. */
TS_API size_t ts_curve_segments(const ts_curve *c);
TS_API size_t ts_curve_dim(const ts_curve *c);
TS_API int ts_curve_closed(const ts_curve *c);            /* 1 for a closed curve */
TS_API const double *ts_curve_knots(const ts_curve *c);   /* segments+1 parameter values */
/* Control points of segment i: ctrl receives 4 rows of dim doubles.  The
 * spline of coordinate k in segment i has values ctrl[l*dim + k]:
 * P_i, P_i + k_i d_i, P_{i+1} - k_i d_{i+1}, P_{i+1} with k_i = 2h_i/(3 pi a_i)
 * (docs/method.md §3, h_i = t_{i+1} - t_i).  TS_OK, TS_ERR_NULL, TS_ERR_INDEX (ctrl
 * set to NaN). */
TS_API ts_status ts_curve_control(const ts_curve *c, size_t i, double *ctrl);
/* alpha_i, beta_i of segment i (both set to NaN first; with a box beta_i is the
 * computed one).  TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
TS_API ts_status ts_curve_params(const ts_curve *c, size_t i, double *alpha, double *beta);

/* Point, first and second derivative in t (each may be NULL; dim doubles; set
 * to NaN first when c is not NULL).  At an inner knot the right-hand segment
 * is used.  Each segment is evaluated from its nearer end: knots return the
 * data points exactly; with a box the point is in the box (see the box
 * options).  Open curves: t outside [t0, tn] or NaN/Inf is TS_ERR_DOMAIN.
 * Closed curves wrap any finite t periodically (t = tn gives segment 0 at
 * t0); NaN/Inf is TS_ERR_DOMAIN.  cur may be NULL.  No allocation.
 * TS_OK, TS_ERR_NULL, TS_ERR_DOMAIN. */
TS_API ts_status ts_curve_eval(const ts_curve *c, double t, ts_cursor *cur,
                        double *p, double *dp, double *d2p);
/* m samples per segment (knots included, m >= 2, equally spaced in t) into
 * out (rows of 1+dim: t then the point); *rows receives segments*(m-1)+1.
 * out must hold rows*(1+dim) doubles; out_len is its length in doubles.  On
 * TS_ERR_LENGTH *rows still holds the number of rows needed, so
 * (out = NULL, out_len = 0) queries the size.  *rows is 0 on other errors.
 * TS_OK, TS_ERR_NULL (c or rows NULL, or out NULL with out_len > 0),
 * TS_ERR_OPTION (m < 2), TS_ERR_LENGTH (out too short), TS_ERR_OVERFLOW. */
TS_API ts_status ts_curve_sample(const ts_curve *c, size_t m, double *out, size_t out_len,
                          size_t *rows);
/* Arc length: per segment, adaptive 10-point Gauss–Legendre in θ with
 * bisection until two halves agree with the whole to tol relative
 * (tol <= 0 or NaN: 1e-12; below 1e-14: 1e-14).  The returned sum uses the
 * halves, so on smooth curves its relative error is far below tol (measured:
 * 6e-16 for every tol in [1e-14, 1e-3] on a 64-point circle, docs/curves.md);
 * near a point of zero speed inside a segment the error can approach tol.  Bisection stops at depth 48
 * or 20000 pieces per segment.  *len is NaN first; a length beyond the double
 * range is +Inf, never NaN.  TS_OK, TS_ERR_NULL. */
TS_API ts_status ts_curve_length(const ts_curve *c, double tol, double *len);

/* Curve certificate against its box: exact minimum per segment and coordinate
 * (ts_interval_report entry i*dim + k, x0/x1/at_* are parameter values t,
 * B the control values of coordinate k, gap_* the exact minimum distance to
 * the side; reports may be NULL).  A side is certified when all 4 control
 * values are strictly inside (a proof: convex hull) or its exact gap exceeds
 * a rounding guard of ~64 ε max|B - bound|.
 * TS_OK if every active side is certified or there is no box;
 * TS_ERR_VIOLATED (index = first segment); TS_ERR_NULL; TS_ERR_VERSION
 * (reports[0].struct_size, checked first). */
TS_API ts_status ts_curve_certify(const ts_curve *c, ts_interval_report *reports, ts_error *err);
/* Same against any box (e.g. to test a curve built without one): coordinate k
 * > lo[k] where has_lo[k], < hi[k] where has_hi[k] (k < dim; has_lo/lo and
 * has_hi/hi may both be NULL pairs: that side is absent).  TS_OK,
 * TS_ERR_VIOLATED (index = first segment), TS_ERR_NONFINITE (an active bound),
 * TS_ERR_NULL (c NULL, or has_* given without its bounds), TS_ERR_VERSION
 * (reports[0].struct_size, checked first).  reports are reset before any
 * other check. */
TS_API ts_status ts_curve_certify_box(const ts_curve *c, const int has_lo[3], const double lo[3],
                               const int has_hi[3], const double hi[3],
                               ts_interval_report *reports, ts_error *err);

/* ------------------------------------------------------------------ */
/* Accuracy (docs/method.md §8; derivations and measurements in docs/accuracy.md) */
/* ------------------------------------------------------------------ */

/*
 * Error constants of one interval with a = alpha + beta, in units of the
 * interval length h, for the exact slopes d_i = f'(x_i):
 *   |f(x) - S(x)| <= first * h * max|f'|                          (1)
 *   |f(x) - S(x)| <= line * h * max|f'| + second * h² * max|f''|  (2)
 * (max over the interval).  (1) is docs/method.md §8's bound; its constant is the
 * total variation of the error functional as a measure acting on f', so it
 * is the best bound in terms of max|f'| alone.  (2) separates the error on
 * straight lines: line = max |f - S| / (h |m|) for f = m x + c (0.003446 at
 * a = 1 in the paper form; 0 in the geometric form, whose error is O(h²));
 * second is the L1 norm of the exact Peano kernel of the rest.  The paper's
 * Theorem 1 (|f - S| <= ½ C h³ max|f'''|) is false: f = x has f''' = 0 but
 * error line·h.
 * Maxima over the interval are computed numerically: a 128-cell grid in θ,
 * each local maximum refined by golden section, then enlarged by 1e-12
 * relative.
 * form TS_FORM_C1 is treated as the paper form with a on both sides.
 * Returns TS_OK, TS_ERR_NULL, TS_ERR_OPTION (form out of range, a not finite
 * or <= 0), TS_ERR_GEOMETRIC (geometric form, a < TS_GEOMETRIC_A_MIN).
 */
typedef struct ts_error_constants {
    double first;
    double line;
    double second;
} ts_error_constants;

TS_API ts_status ts_error_constants_get(ts_form form, double a, ts_error_constants *c);

/*
 * A bound on max |f - S| over [x0, xn] for any f with f(x_i) = f_i and
 * max |f'| <= fprime_max on [x0, xn], any form:
 *  - always (any slopes, estimated ones too): per interval the maximum over
 *    θ of  h [fprime_max (c²δ + s²(1-δ)) + κ_L |d_i| A1 + κ_R |d_{i+1}| A2]
 *    with the slopes d the spline uses (ts_spline_slopes), δ the position in
 *    the interval (δ = X(θ) in the geometric form) and κ = 2/(3π a)
 *    (C¹: a of each end, the larger of its two intervals).  With exact slopes
 *    this is at most (1) above;
 *  - if exact_slopes != 0 (the caller promises d_i = f'(x_i), e.g. user
 *    slopes from the true derivative) and fsecond_max (max |f''|) is
 *    finite, also the sharper (2), evaluated jointly per interval, and the
 *    smaller of the two is used.  fsecond_max may be INFINITY (unknown); it
 *    is ignored when exact_slopes == 0.
 * *bound receives the maximum over intervals; per_interval, if not NULL,
 * receives n = ts_spline_intervals(s) values.  On failure *bound is NaN.
 * Returns TS_OK, TS_ERR_NULL (s or bound), TS_ERR_NONFINITE (fprime_max not
 * finite, fsecond_max NaN), TS_ERR_OPTION (a negative bound).
 */
TS_API ts_status ts_spline_error_bound(const ts_spline *s, double fprime_max, double fsecond_max,
                         int exact_slopes, double *bound, double *per_interval);

/* ================================================================== */
/* Surfaces: gridded 2-D data (docs/method.md §11)                      */
/* ================================================================== */

/*
 * S(x, y) through z_ij on a rectilinear grid x_0 < ... < x_nx, y_0 < ... < y_ny
 * (non-uniform allowed).  On the patch [x_i, x_{i+1}] × [y_j, y_{j+1}]
 * S = Σ_k Σ_l A_k(θ) A_l(φ) B_kl, the basis of docs/method.md §2 in each
 * direction: 16 control values per patch, built from the node values z,
 * the partial slopes p = ∂z/∂x, q = ∂z/∂y (1-D slope methods along the grid
 * lines) and a twist r (docs/method.md §11.1).  One shape parameter per
 * column interval (a^x_i) and per row interval (a^y_j), shared along the
 * grid.  The forms of docs/method.md §3–§4 carry over (§11.2): paper
 * (continuous), C¹ and geometric (C¹, planes reproduced exactly).
 *
 * Layout: z[j * nx_points + i] is the value at (x[i], y[j]) (rows of constant
 * y, x fastest).  A node (i, j) is reported in ts_error as index
 * j * nx_points + i (where = TS_WHERE_POINT); a patch (i, j) as
 * j * (nx_points - 1) + i (where = TS_WHERE_INTERVAL); the n-th query as n.
 */
typedef struct ts_surface ts_surface;

/* The plane z = p x + q y + c. */
typedef struct ts_plane {
    double p, q, c;
} ts_plane;

/* docs/method.md §11.3.  The region the surface must stay in. */
typedef enum ts_surface_shape {
    TS_SURFACE_NONE = 0,     /* a^x = a^y = alpha + beta (caller's); no promise */
    TS_SURFACE_POSITIVE = 1, /* S >= 0 (zeros in the data allowed; S > 0 inside patches
                                with a positive corner) */
    TS_SURFACE_BOUNDS = 2,   /* lower.c <= S and/or S <= upper.c (constants, has_lower /
                                has_upper; the data may touch them); lower.p/q, upper.p/q
                                are ignored */
    TS_SURFACE_PLANES = 3,   /* lower < S and/or S < upper (planes, has_lower / has_upper;
                                every node strictly between).  Sloped planes need
                                TS_FORM_GEOMETRIC, where they are exact (TS_ERR_OPTION
                                otherwise); constant planes work in every form. */
    TS_SURFACE_RANGE = 4,    /* min z <= S <= max z: no overshoot beyond the data */
    TS_SURFACE_GRIDS = 5     /* lower(x, y) < S and/or S < upper(x, y), each bound a gridded
                                field bilinear between its nodes (lower_grid / upper_grid,
                                has_lower / has_upper; every node strictly between; every
                                form; docs/method.md §11.7) */
} ts_surface_shape;

/*
 * A bound given as a gridded field (TS_SURFACE_GRIDS, docs/method.md §11.7):
 * values z on its own rectilinear grid x_0 < ... < x_{nx_points-1},
 * y_0 < ... < y_{ny_points-1} (finite, at least 2 nodes each way; values
 * finite with |z| <= TS_VALUE_MAX), z[j * nx_points + i] at (x[i], y[j]) as
 * the data of ts_surface_new.  Between its nodes the bound is bilinear on
 * each cell: a + b x + c y + d x y.  It is not extended: its grid must cover
 * the surface's grid [x_0, x_nx] × [y_0, y_ny] (TS_ERR_BOUND_GRID
 * otherwise).  ts_surface_new copies the arrays; the caller's may be freed
 * after it returns.
 */
typedef struct ts_grid_bound {
    const double *x;
    size_t nx_points;
    const double *y;
    size_t ny_points;
    const double *z;
} ts_grid_bound;

/* Start from ts_surface_options_init(), then set fields. */
typedef struct ts_surface_options {
    size_t struct_size;      /* sizeof(ts_surface_options), set by ts_surface_options_init */
    ts_form form;            /* default TS_FORM_PAPER (stated explicitly by careful callers) */
    ts_slopes slopes;        /* default TS_SLOPES_ARITHMETIC, applied along every grid line;
                                TS_SLOPES_USER and TS_SLOPES_PERIODIC: TS_ERR_OPTION */
    int zero_twist;          /* default 0: twist r = (∂p/∂y + ∂q/∂x)/2 by the same
                                method; nonzero: r = 0 */
    double alpha;            /* default 1; > 0 */
    double beta;             /* default 0; TS_SURFACE_NONE only: a = alpha + beta */
    double margin;           /* t of docs/method.md §5, default TS_DEFAULT_MARGIN; > 0 */
    ts_surface_shape shape;  /* default TS_SURFACE_NONE */
    int has_lower, has_upper;/* TS_SURFACE_BOUNDS, TS_SURFACE_PLANES, TS_SURFACE_GRIDS */
    ts_plane lower, upper;
    ts_grid_bound lower_grid, upper_grid; /* TS_SURFACE_GRIDS (default: all NULL / 0);
                                             read only by ts_surface_new (copied) */
} ts_surface_options;

TS_API void ts_surface_options_init(ts_surface_options *opt);

/*
 * Build the surface.  opt may be NULL (defaults).  *out is NULL first, then
 * the surface on success; on failure nothing stays allocated.
 * Returns (checked in this order; node errors name the first node in z order):
 *   TS_ERR_NULL        x, y, z or out NULL
 *   TS_ERR_TOO_FEW     nx_points < 2 or ny_points < 2
 *   TS_ERR_OPTION      form, slopes or shape out of range; USER/PERIODIC slopes;
 *                      BOUNDS/PLANES with neither side; sloped planes outside
 *                      the geometric form
 *   TS_ERR_OVERFLOW    the grid's size in bytes overflows size_t
 *   TS_ERR_NONFINITE   NaN/Inf in x (index i), y (index j), z (node), a bound,
 *                      or a slope or control value that overflows (node / patch)
 *   TS_ERR_UNSORTED    x or y not strictly increasing (index i resp. j; every
 *                      non-finite knot of an axis is named before an unsorted one)
 *   TS_ERR_ALPHA, TS_ERR_BETA, TS_ERR_MARGIN   (no index)
 *   TS_ERR_GEOMETRIC   TS_SURFACE_NONE in the geometric form with
 *                      alpha + beta < TS_GEOMETRIC_A_MIN
 *   TS_ERR_BOUND_GRID  GRIDS: a side's ts_grid_bound with a NULL array, fewer
 *                      than 2 nodes in a direction, coordinates not finite and
 *                      strictly increasing, a value not finite or beyond
 *                      TS_VALUE_MAX, or a grid that does not cover the
 *                      surface's grid; index = 0 (lower) or 1 (upper), the
 *                      lower checked first (ts_error_message says what)
 *   TS_ERR_NEGATIVE    POSITIVE: a node with z < 0
 *   TS_ERR_LINES       BOUNDS: lower.c >= upper.c; PLANES: lower not strictly
 *                      below upper at a node; GRIDS: the upper field not above
 *                      the lower by more than 5 times their rounding bounds
 *                      (docs/method.md §11.7) at a node of the union of the
 *                      two grids and the surface's border (where =
 *                      TS_WHERE_NONE; ts_error_message names the place)
 *   TS_ERR_SIDE        BOUNDS: a node outside [lower.c, upper.c]; PLANES: a node on
 *                      or across a plane; GRIDS: a node on or across a field
 *                      (decided exactly where the node's value, the field's
 *                      values and the weights lie between 2^-300 and 2^300 in
 *                      magnitude or are 0; beyond that range a node the exact
 *                      sum cannot place is refused as across; ts_error_message
 *                      gives the field's value there)
 *   TS_ERR_INFEASIBLE  a patch whose control values, as rounded, leave the region
 *                      even after a^x, a^y of its column and row were raised
 *                      tenfold up to 12 times (docs/method.md §11.6; the rule
 *                      of §11.3 is a proof in exact arithmetic; this is
 *                      rounding, e.g. a node 1e-16 relative from a plane),
 *                      or whose a would exceed 1e300 (a node gap near the
 *                      underflow threshold next to a slope); index = the patch
 *   TS_ERR_UNPROVEN    GRIDS: a patch that the certificate of docs/method.md
 *                      §11.7 did not prove inside the fields after the repair
 *                      of §11.6 (12 tenfold raises of its a^x, a^y): e.g. a
 *                      field that bulges past the data between their nodes;
 *                      index = the patch
 *   TS_ERR_NOMEM
 *   TS_ERR_VERSION     opt->struct_size (checked right after TS_ERR_NULL)
 */
TS_API ts_status ts_surface_new(const double *x, size_t nx_points, const double *y,
                                size_t ny_points, const double *z,
                                const ts_surface_options *opt, ts_surface **out,
                                ts_error *err);
TS_API void ts_surface_free(ts_surface *s); /* NULL: no-op */

/* ---- accessors (s must be valid; pointers live as long as s) */
TS_API size_t ts_surface_nx(const ts_surface *s);         /* patches along x (points - 1) */
TS_API size_t ts_surface_ny(const ts_surface *s);         /* patches along y */
TS_API const double *ts_surface_x(const ts_surface *s);   /* nx + 1 */
TS_API const double *ts_surface_y(const ts_surface *s);   /* ny + 1 */
TS_API const double *ts_surface_z(const ts_surface *s);   /* (nx+1)(ny+1), layout of z */
TS_API const double *ts_surface_dzdx(const ts_surface *s); /* slopes p used (after the scheme) */
TS_API const double *ts_surface_dzdy(const ts_surface *s); /* slopes q used */
TS_API const double *ts_surface_twist(const ts_surface *s);/* twists r used */
TS_API const double *ts_surface_ax(const ts_surface *s);  /* nx: a^x_i */
TS_API const double *ts_surface_ay(const ts_surface *s);  /* ny: a^y_j */
TS_API ts_form ts_surface_form(const ts_surface *s);
TS_API ts_surface_shape ts_surface_shape_of(const ts_surface *s);
/* 1 when a scheme was applied and every patch is proven inside its region
 * (always, when ts_surface_new succeeded with a scheme); 0 for NONE.
 * Values returned by ts_surface_eval, _eval_batch and _eval_grid of a
 * certified surface are in the region in floating point: a value that
 * rounding puts beyond a constant bound (positive, bounds, range) is set to
 * the bound, one on or across a plane (planes) to the nearest doubles
 * strictly beyond it (decided exactly); the move is at most the value's
 * rounding error (plus one ulp of the plane's value for planes), as the
 * exact surface is inside (docs/method.md §11.5 "Values inside the
 * region").  Gridded fields (grids): a value not strictly inside the exact
 * bilinear field (decided exactly) is set to the field's rounded value
 * moved outward by twice its rounding bound and one ulp (§11.7).  Partial
 * derivatives are not moved. */
TS_API int ts_surface_certified(const ts_surface *s);

/* Caller-owned lookup hint: zero-initialise (TS_SURFACE_CURSOR_INIT) or NULL. */
typedef struct ts_surface_cursor {
    ts_cursor x, y;
} ts_surface_cursor;
#define TS_SURFACE_CURSOR_INIT {{0}, {0}}

/*
 * Value and first partials at (x, y) (z, zx, zy may each be NULL; NaN on
 * failure).  On an inner grid line the patch to the right / above is used.
 * TS_OK, TS_ERR_NULL (s), TS_ERR_DOMAIN (outside the grid or NaN).
 * No allocation; nodes are reproduced exactly.
 */
TS_API ts_status ts_surface_eval(const ts_surface *s, double x, double y,
                                 ts_surface_cursor *cur, double *z, double *zx, double *zy);
/* Scattered points (xq[n], yq[n]), n < m; zq required, zxq / zyq may be NULL.
 * Invalid points get NaN, the rest are evaluated; TS_ERR_DOMAIN with
 * err->index = the first invalid point.  TS_OK, TS_ERR_NULL. */
TS_API ts_status ts_surface_eval_batch(const ts_surface *s, const double *xq, const double *yq,
                                       size_t m, double *zq, double *zxq, double *zyq,
                                       ts_error *err);
/* Outer product: out[b * mx + a] = S(xq[a], yq[b]) (the layout of z).  Fast
 * for sorted xq (bases computed once per block of x values).  Entries whose
 * xq or yq is invalid get NaN; TS_ERR_DOMAIN with err->index = a (an invalid
 * xq[a]) or mx + b (an invalid yq[b]), the first of those.
 * TS_OK, TS_ERR_NULL (s, out, or xq / yq with a count > 0). */
TS_API ts_status ts_surface_eval_grid(const ts_surface *s, const double *xq, size_t mx,
                                      const double *yq, size_t my, double *out, ts_error *err);
/* ∫∫ S over [xa, xb] × [ya, yb] (reversed limits give the sign), closed form
 * per patch (paper, C¹); geometric form: Gauss–Legendre in θ exact to
 * rounding (docs/method.md §11.5).  TS_OK, TS_ERR_NULL, TS_ERR_DOMAIN (a limit
 * outside the grid or NaN; *out NaN). */
TS_API ts_status ts_surface_integral(const ts_surface *s, double xa, double xb, double ya,
                                     double yb, double *out);

/* The 16 control values of patch (i, j), B[4*k + l] with k along x and l
 * along y, and (X, Y may be NULL) the control abscissae of the form (as for
 * ts_spline_control).  TS_OK, TS_ERR_NULL, TS_ERR_INDEX. */
TS_API ts_status ts_surface_control(const ts_surface *s, size_t i, size_t j, double B[16],
                                    double X[4], double Y[4]);

/*
 * The certificate of one patch (docs/method.md §11.4).  For each active
 * bound: a proven lower bound on the gap (S − lower, resp. upper − S) over
 * the patch, from the control values of a rational Bernstein form of the
 * patch, refined by subdivision until it is within 1e-9 of the patch's
 * scale (max |control gap|) of the smallest sampled gap, minus a rounding guard; the
 * smallest sampled gap (a true value of the surface) and where it is.
 * certified = every active proven bound > 0, or the control values
 * themselves inside the region (a proof: the basis is >= 0 and sums to 1;
 * then the proven bound is at least 0).
 */
typedef struct ts_patch_report {
    size_t struct_size;     /* sizeof(ts_patch_report): TS_PATCH_REPORT_INIT or
                               ts_patch_report_init before the first call (struct guards) */
    size_t i, j;
    double x0, x1, y0, y1;
    double ax, ay;
    double B[16];
    int has_lower, has_upper;
    double proven_lower, sampled_lower, at_lower[2]; /* NaN when absent */
    double proven_upper, sampled_upper, at_upper[2];
    int certified;
} ts_patch_report;
/* ts_patch_report rep = TS_PATCH_REPORT_INIT;  (C++ before C++20, and
 * arrays: ts_patch_report_init) */
#define TS_PATCH_REPORT_INIT {.struct_size = sizeof(ts_patch_report)}
/* Initialise n patch reports (for ts_surface_certify): struct_size set,
 * values NaN, flags 0.  reports may be NULL. */
TS_API void ts_patch_report_init(ts_patch_report *reports, size_t n);

/* Report of patch (i, j) against the scheme's bounds (NONE: no bound,
 * certified 0; GRIDS: against the fields, with the certificate of
 * docs/method.md §11.7, whose proven bound is within a factor 2 of the
 * sampled gap where it succeeds).  TS_OK, TS_ERR_NULL (rep NULL checked first, then s),
 * TS_ERR_INDEX, TS_ERR_VERSION (rep->struct_size; rep then untouched). */
TS_API ts_status ts_surface_report(const ts_surface *s, size_t i, size_t j,
                                   ts_patch_report *rep);
/* Certify against any planes (lower, upper may be NULL; not both): reports
 * (if not NULL) receive nx*ny entries (patch (i, j) at j*nx + i).  Paper and
 * C¹ forms with a sloped plane: the plane's variation over a sub-patch is
 * subtracted; that bound converges only linearly, so there the tolerance
 * adds 1e-4 of the plane's variation over the patch.  TS_OK when every patch is certified; TS_ERR_VIOLATED (index
 * = first patch that is not); TS_ERR_NONFINITE (a plane); TS_ERR_NULL;
 * TS_ERR_VERSION (reports[0].struct_size, checked first). */
TS_API ts_status ts_surface_certify(const ts_surface *s, const ts_plane *lower,
                                    const ts_plane *upper, ts_patch_report *reports,
                                    ts_error *err);

/* ================================================================== */
/* Error messages                                                       */
/* ================================================================== */

/*
 * Formats an abscissa for ts_error_message (e.g. as a date): writes at most
 * len bytes including the terminating NUL and returns the length of the
 * whole text (as snprintf; a negative value or one >= len means "use the
 * number instead").  user is ts_error_context.format_x_user.
 */
typedef int (*ts_format_x_fn)(double x, char *buf, size_t len, void *user);

/*
 * What ts_error_message needs besides the ts_error: the data and options of
 * the call that failed.  Start from ts_error_context_init(), then set the
 * fields that apply; every pointer may stay NULL (the sentence then names
 * the index without values).  The library only reads through them, during
 * ts_error_message.
 */
struct ts_histo_options;

typedef struct ts_error_context {
    size_t struct_size;          /* sizeof(ts_error_context), set by ts_error_context_init */
    /* ---- the data */
    const double *x;             /* spline: the abscissae x[0..n_points);
                                    surface: the grid's x[0..n_points) */
    const double *f;             /* spline: the values f[0..n_points); surface: z in the
                                    layout of ts_surface_new (ny_points rows of n_points) */
    size_t n_points;             /* spline: points; surface: nx_points; curve: points */
    const double *y;             /* surface only: the grid's y[0..ny_points) */
    size_t ny_points;            /* surface only */
    const double *points;        /* curve only: n_points rows of dim coordinates */
    size_t dim;                  /* curve only: 2 or 3 */
    const double *queries;       /* evaluation: the query abscissae (index = query) */
    size_t n_queries;
    /* ---- the options of the call (at most one; NULL: defaults) */
    const ts_spline_options *spline_options;
    const ts_curve_options *curve_options;
    const ts_surface_options *surface_options;
    /* ---- presentation */
    size_t first_index;          /* added to every point, interval and query index
                                    printed (the data are a block of a longer series) */
    ts_format_x_fn format_x;     /* NULL: x printed as a number */
    void *format_x_user;
    /* ---- histograms (ts_histo_new, ts_histo_check): set histo_options (the
       options of the call, or ts_histo_options_init's defaults) to say so;
       then x = the edges, n_points = n_bins + 1, f = the totals (n_bins) */
    const struct ts_histo_options *histo_options;
} ts_error_context;

/* Defaults: struct_size set, everything else NULL / 0. */
TS_API void ts_error_context_init(ts_error_context *ctx);

/*
 * The full English sentence of a failure, without a prefix and without a
 * final period or newline; front-ends put their own prefix (e.g.
 * "data.csv:12: ") in front.  snprintf-like: writes at most len bytes
 * including the NUL (buf may be NULL when len is 0), always NUL-terminates
 * when len > 0, and returns the length of the whole sentence, so a return
 * >= len means it was truncated.  err NULL: the sentence of TS_ERR_NULL
 * ("a required pointer argument is NULL").  ctx may be NULL (no data);
 * a ctx whose struct_size is not sizeof(ts_error_context) is ignored and the
 * sentence says so ("(error context of another version ignored)").
 *
 * Numbers are in the shortest form that reads back to the same double
 * (%.17g trimmed: 0.1, 2.5e-07, nan, inf); x values through ctx->format_x
 * when given.  Indices are ctx->first_index + the index of err.  Where the
 * index is outside the data given, the sentence names the index only.
 *
 * The form of the sentence ("P" = "point I (x = X, f = F)"):
 *   TS_ERR_TOO_FEW      "N data points; at least 2 are needed"
 *   TS_ERR_UNSORTED     "point I (x = X) is not greater than the previous x = X'; x must
 *                        be strictly increasing"
 *   TS_ERR_NONFINITE    "P: x or f is NaN or infinite" / "P: the user slope D is not
 *                        finite" / "P: the step from the previous point, or a slope
 *                        there, overflows a double"
 *   TS_ERR_WIDTH        "point I (x = X): the step H from the previous x = X' overflows
 *                        a double" (or "underflows: ...")
 *   TS_ERR_PERIODIC     "periodic slopes need the last value equal to the first: f = A at
 *                        point N-1, f = B at point 0"
 *   TS_ERR_NEGATIVE     "P is negative; the positive shape needs f >= 0 (negative at
 *                        x = X1, X2, ...)"
 *   TS_ERR_SIDE         "P is not above the lower line y = 2x + 1; the data are on or
 *                        below it at x = X1, ..." (or below / upper / above)
 *   TS_ERR_LINES        "at point I (x = X) the lower line L (value A) is not below the
 *                        upper line U (value B)"
 *   TS_ERR_NONMONOTONE  "P: the data change direction here; the monotone shape needs
 *                        monotone data"
 *   TS_ERR_ZERO_SLOPE   "P touches the boundary and the user slope D there points out of
 *                        the region"
 *   TS_ERR_ALPHA, _BETA, _MARGIN  "interval I [X0, X1]: alpha = A must be finite and > 0"
 *                        (beta: ">= 0, and alpha + beta > 0"; the margin likewise)
 *   TS_ERR_LENGTH       "alphas has K values, but the data have N intervals (one value
 *                        per interval is needed)" (betas, margins; user slopes: points)
 *   TS_ERR_GEOMETRIC    "interval I [X0, X1]: alpha + beta = A is below the geometric-form
 *                        bound 0.3472; raise alpha or beta"
 *   TS_ERR_INFEASIBLE   "interval I [X0, X1]: no beta >= 0 keeps the spline inside the
 *                        region on this interval"
 *   TS_ERR_CONTROL_OVERFLOW "interval I [X0, X1]: alpha + beta = A is too small for the
 *                        slopes: the control values overflow"
 *   TS_ERR_DOMAIN       "query I (x = X) lies outside [X0, XN]" / "query I is NaN" /
 *                        "query I (x = inf) is infinite"
 *   other statuses      "P: TEXT", "interval I [X0, X1]: TEXT", "query I: TEXT" or
 *                        "TEXT", TEXT = ts_strerror(status)
 * The lists of other failing points name at most 12 x values, then ", ...".
 * Surfaces (ctx->surface_options or ctx->y given): a node is "node (I, J) (x = X,
 * y = Y, z = Z)", a patch "patch (I, J) [X0, X1] x [Y0, Y1]"; curves
 * (ctx->curve_options or ctx->points given): "point I (C1, C2[, C3])",
 * "segment I".  Surfaces between gridded fields (surface_options->shape
 * TS_SURFACE_GRIDS): TS_ERR_BOUND_GRID says which field and what ("the lower
 * field's grid [A, B] x [C, D] does not cover the surface's grid [..] x [..];
 * a field is not extended beyond its grid", "the upper field's x[1] = 0 is
 * not finite, or not greater than ...", ...); TS_ERR_SIDE "node (I, J) (...)
 * is not above the lower field, whose value there is V; ..."; TS_ERR_LINES
 * "at (x = X, y = Y) the upper field (value U) is not above the lower field
 * (value L) by more than their rounding bound R"; TS_ERR_UNPROVEN "patch
 * (I, J) [..]: not proven strictly between the gridded fields, ...".
 * Histograms (ctx->histo_options given; "B" = "bin I [X0, X1]"):
 *   TS_ERR_TOO_FEW      "0 bins; at least 1 is needed"
 *   TS_ERR_ALPHA        "alpha = A must be finite and > 0"
 *   TS_ERR_OPTION       "the rate bounds lo = L, hi = H need lo finite and lo < hi"
 *   TS_ERR_NONFINITE    "edge I (x = X) is NaN or infinite" / "B: total T is NaN or
 *                        infinite"
 *   TS_ERR_UNSORTED     "edge I (x = X) is not greater than the previous edge X'; edges
 *                        must be strictly increasing"
 *   TS_ERR_WIDTH        "B: the width W overflows a double" (or "is below the smallest
 *                        normal double")
 *   TS_ERR_TOO_LARGE    "B: total T gives the mean M, too large in magnitude" /
 *                        "B: total T over the width W: the integral of the rates (the
 *                        lower bound L times the width included) overflows a double"
 *   TS_ERR_NEGATIVE     "B: total T is negative; totals must be >= 0"
 *   TS_ERR_INFEASIBLE   "B: total T gives the mean M, outside the rate bounds [L, H]" /
 *                        "B and bin I+1 [X1, X2]: the means M1 and M2 are too far apart
 *                        to be joined inside the rate bounds [L, H]"
 * The wording names the library's options (alpha, beta, the
 * positive shape, ...), never a front-end's flags.
 */
TS_API size_t ts_error_message(const ts_error *err, const ts_error_context *ctx, char *buf,
                               size_t len);

/* ================================================================== */
/* Histograms: a rate from bin totals (disaggregation)                 */
/* ================================================================== */

/*
 * From bins [e_j, e_{j+1}] (edges e[0..n_bins], strictly increasing) and
 * their totals T_j, a rate r(x) on [e_0, e_n] with (docs/method.md §12)
 *   - ∫ r over bin j = T_j to rounding (a few ulps of T_j + lo w_j);
 *   - lo <= r <= hi everywhere (default lo = 0, hi = +inf: r >= 0), proved
 *     per bin by the control values and reported with the exact minimum
 *     and maximum; values returned never leave [lo, hi];
 *   - r continuous with a continuous derivative (C¹) across bin edges and
 *     inside the bins.  A bin with mean lo (a dry bin) forces r ≡ lo on it,
 *     hence r = lo, r' = 0 at its edges.
 * Each bin is four cubic trigonometric pieces (the basis of §2; knots at
 * the edges and quarter points): edge values and slopes from the
 * neighbouring bin means, the inner knots from a linear system that meets
 * the total exactly and makes r C² (r'' continuous, 0 at the edges),
 * blended towards a flat solution only where that would leave [lo, hi].
 * The tension alpha divides the edge slopes (larger: flatter), as in §3.
 *
 * Designed for 1-D bins; a rectilinear grid of cell averages (the 2-D
 * case) follows the same construction per axis (docs/method.md §12.7).
 */
typedef struct ts_histo ts_histo;

/* Start from ts_histo_options_init(), then set fields. */
typedef struct ts_histo_options {
    size_t struct_size;     /* sizeof(ts_histo_options), set by ts_histo_options_init */
    double alpha;           /* tension > 0, finite; default TS_DEFAULT_ALPHA */
    double lo, hi;          /* rate bounds: lo finite, lo < hi (hi may be +inf);
                               default 0 and +inf */
} ts_histo_options;
TS_API void ts_histo_options_init(ts_histo_options *opt);

/*
 * Build the rate of n_bins bins (edges: n_bins + 1 values, totals: n_bins).
 * opt may be NULL (defaults).  *out (required) is set to NULL first and to
 * the new object on success; err may be NULL (reset first).  Statuses:
 *   TS_ERR_NULL        edges, totals or out NULL
 *   TS_ERR_VERSION     opt->struct_size (checked right after TS_ERR_NULL)
 *   TS_ERR_TOO_FEW     n_bins == 0
 *   TS_ERR_ALPHA       alpha not > 0 and finite
 *   TS_ERR_OPTION      lo not finite, or not lo < hi, or hi NaN
 *   TS_ERR_OVERFLOW    n_bins too large for the arrays
 *   TS_ERR_NONFINITE   an edge (where = point) or a total (where = interval) NaN/inf
 *   TS_ERR_UNSORTED    edges not strictly increasing (point i with e[i] <= e[i-1])
 *   TS_ERR_WIDTH       a bin width overflows or is below DBL_MIN (point i = its right edge)
 *   TS_ERR_TOO_LARGE   a bin mean beyond TS_VALUE_MAX / 4 in magnitude, or a bin
 *                      whose integral (lo times its width included) overflows
 *                      (interval)
 *   TS_ERR_NEGATIVE    a total below lo times the bin width, with lo = 0 and
 *                      hi = +inf: a negative total (interval)
 *   TS_ERR_INFEASIBLE  with other bounds, a bin whose mean is outside [lo, hi], or two
 *                      neighbouring bins the scheme cannot join inside the bounds
 *                      (docs/method.md §12.4; interval = the first such bin;
 *                      ts_histo_check gives every bin's status)
 *   TS_ERR_NOMEM       allocation failed
 */
TS_API ts_status ts_histo_new(const double *edges, const double *totals, size_t n_bins,
                              const ts_histo_options *opt, ts_histo **out, ts_error *err);
/* The same checks, without building: status[j] (n_bins entries; may be
 * NULL) is TS_OK or the status of bin j (an edge failing names both of its
 * bins; TS_ERR_INFEASIBLE marks both bins of an edge the scheme cannot
 * join).  Statuses as ts_histo_new, except TS_ERR_NOMEM and an integral
 * that overflows (found by building); status[] is
 * written (all TS_OK first) whenever the arguments are not NULL, the
 * options valid and n_bins > 0. */
TS_API ts_status ts_histo_check(const double *edges, const double *totals, size_t n_bins,
                                const ts_histo_options *opt, ts_status *status, ts_error *err);
TS_API void ts_histo_free(ts_histo *h);
TS_API size_t ts_histo_bins(const ts_histo *h);

/*
 * r(x) and r'(x) (dr may be NULL).  x in [e_0, e_n]; no allocation.  Both
 * outputs are set to NaN first.  TS_OK, TS_ERR_NULL (h, r),
 * TS_ERR_DOMAIN (x outside [e_0, e_n] or NaN).  r is within [lo, hi]
 * exactly (docs/method.md §12.5).
 */
TS_API ts_status ts_histo_eval(const ts_histo *h, double x, double *r, double *dr);
/* r (and r' when dr is not NULL) at m queries; outputs NaN first; the
 * first query outside [e_0, e_n] stops with TS_ERR_DOMAIN (err index =
 * query, where = TS_WHERE_QUERY).  TS_OK, TS_ERR_NULL (h, or x, r with
 * m > 0), TS_ERR_DOMAIN. */
TS_API ts_status ts_histo_eval_batch(const ts_histo *h, const double *x, size_t m, double *r,
                                     double *dr, ts_error *err);
/* ∫_a^b r dx (negative when b < a).  *out = NaN first.  TS_OK,
 * TS_ERR_NULL (h, out), TS_ERR_DOMAIN (a or b outside [e_0, e_n] or NaN). */
TS_API ts_status ts_histo_integral(const ts_histo *h, double a, double b, double *out);
/*
 * Totals over the m − 1 cells of a grid: out[k] = ∫ r over
 * [grid[k], grid[k+1]], grid non-decreasing inside [e_0, e_n] (m >= 2; m
 * < 2 writes nothing).  Each is kept within [lo, hi] times the cell width
 * (rounding); the cells of one bin add up to its total to rounding.
 * O(n_bins + m).  outputs NaN first.  TS_OK, TS_ERR_NULL,
 * TS_ERR_DOMAIN (grid[k] outside or NaN, index k, where = TS_WHERE_QUERY),
 * TS_ERR_UNSORTED (grid[k] < grid[k-1], index k, where = TS_WHERE_QUERY).
 */
TS_API ts_status ts_histo_totals(const ts_histo *h, const double *grid, size_t m, double *out,
                                 ts_error *err);

/*
 * Every bin cut into sub equal cells: out[j * sub + k] = ∫ r over cell k of
 * bin j (n_bins * sub values; daily totals to hourly ones: sub = 24).  The
 * same values as ts_histo_totals on that grid up to rounding, faster: the
 * cells' weights on the control values are computed once for all bins
 * (docs/method.md §12.5).  Each within [lo, hi] times the cell width; the
 * cells of a bin add up to its total to rounding.  No allocation.  TS_OK,
 * TS_ERR_NULL (h, out), TS_ERR_OPTION (sub == 0), TS_ERR_OVERFLOW (n_bins *
 * sub overflows).
 */
TS_API ts_status ts_histo_subdivide(const ts_histo *h, size_t sub, double *out, ts_error *err);

/* One bin's certificate (docs/method.md §12.5). */
typedef struct ts_bin_report {
    size_t struct_size;  /* sizeof(ts_bin_report): ts_bin_report_init before the first call */
    double e0, e1;       /* the bin */
    double total;        /* ∫ r over the bin, from the pieces (compare with the given total) */
    double mean;         /* total / (e1 − e0) */
    double r_min, at_min;/* exact minimum of r over the bin and an x where it is attained */
    double r_max, at_max;/* exact maximum (the peak) and an x where it is attained */
    double guard;        /* the rounding bound of r_min and r_max (docs/method.md §5.6) */
    double B[16];        /* control values of the four pieces (4 each), minus lo */
    int certified;       /* every control value in [lo, hi]: lo <= r <= hi proved */
} ts_bin_report;
/* struct_size set, values NaN, certified 0; rep may be NULL. */
TS_API void ts_bin_report_init(ts_bin_report *rep);
/* TS_OK, TS_ERR_NULL (h, rep), TS_ERR_VERSION (rep->struct_size; rep then
 * untouched), TS_ERR_INDEX (bin >= n_bins; rep reset to NaN). */
TS_API ts_status ts_histo_report(const ts_histo *h, size_t bin, ts_bin_report *rep);

/* ------------------------------------------------------------------ */
/* Deprecated names (docs/versions.md)                                  */
/* ------------------------------------------------------------------ */

/*
 * The names of 0.1, before the rule ts_<object>_<verb>.  They stay exported
 * for one minor release (removed in 0.3) and behave exactly as the new
 * names they forward to; using one gives a compiler warning naming its
 * replacement.  Define TS_NO_DEPRECATED before including this header to
 * hide them (a check that a code base has moved).
 */
#ifndef TS_NO_DEPRECATED
#if defined(__GNUC__) || defined(__clang__)
#define TS_DEPRECATED(replacement) __attribute__((deprecated("use " replacement)))
#else
#define TS_DEPRECATED(replacement)
#endif
typedef ts_spline_options ts_options TS_DEPRECATED("ts_spline_options");
TS_API TS_DEPRECATED("ts_spline_options_init") void ts_options_init(ts_spline_options *opt);
TS_API TS_DEPRECATED("ts_spline_eval") ts_status ts_eval(const ts_spline *s, double x,
                                                         ts_cursor *cur, double *y);
TS_API TS_DEPRECATED("ts_spline_eval_deriv") ts_status
ts_eval_deriv(const ts_spline *s, double x, ts_cursor *cur, double *y, double *dy, double *d2y);
TS_API TS_DEPRECATED("ts_spline_eval_batch") ts_status
ts_eval_batch(const ts_spline *s, int deriv, const double *xq, size_t m, double *yq,
              ts_cursor *cur, ts_error *err);
TS_API TS_DEPRECATED("ts_spline_eval_batch_mt") ts_status
ts_eval_batch_mt(const ts_spline *s, int deriv, const double *xq, size_t m, double *yq,
                 unsigned nthreads, ts_error *err);
TS_API TS_DEPRECATED("ts_spline_integral") ts_status ts_integral(const ts_spline *s, double a,
                                                                 double b, double *out);
TS_API TS_DEPRECATED("ts_spline_certify") ts_status
ts_certify(const ts_spline *s, const ts_line *lower, const ts_line *upper,
           ts_interval_report *reports, ts_error *err);
TS_API TS_DEPRECATED("ts_spline_error_bound") ts_status
ts_error_bound(const ts_spline *s, double fprime_max, double fsecond_max, int exact_slopes,
               double *bound, double *per_interval);
#endif /* TS_NO_DEPRECATED */

#ifdef __cplusplus
}
#endif
#endif /* TRIGSPLINE_H */
