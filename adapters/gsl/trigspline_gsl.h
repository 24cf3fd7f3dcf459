/*
 * trigspline_gsl — the trigonometric spline of libtrigspline as GSL
 * interpolation types (optional adapter; built only when GSL is found).
 *
 * A GSL user changes one word:
 *
 *     gsl_spline *sp = gsl_spline_alloc(ts_gsl_interp_positive, n);
 *     gsl_interp_accel *acc = gsl_interp_accel_alloc();
 *     if (gsl_spline_init(sp, x, y, n) != GSL_SUCCESS) { ... }   // e.g. y < 0: GSL_EDOM
 *     double v = gsl_spline_eval(sp, 4.2, acc);                   // never below zero
 *     ...
 *     gsl_spline_free(sp);
 *     gsl_interp_accel_free(acc);
 *
 * Link with libtrigspline_gsl.a, libtrigspline and -lgsl -lgslcblas -lm: installed,
 * CMake find_package(trigspline COMPONENTS gsl) and trigspline::gsl, or
 * pkg-config --cflags --libs trigspline_gsl.
 *
 * The types (all min_size 2, the library's defaults of ts_spline_options_init —
 * Steffen's slopes of docs/method.md §6, alpha = TS_DEFAULT_ALPHA, the
 * geometric form of docs/method.md §4 — unless "_c1"):
 *
 *   ts_gsl_interp_trig         "trigspline"              no shape scheme: every
 *                                                        interval monotone and inside
 *                                                        its two data values, no new
 *                                                        extrema (PCHIP's promise,
 *                                                        docs/method.md §5.10), C¹,
 *                                                        S'(x_i) = d_i, lines exact
 *   ts_gsl_interp_positive     "trigspline-positive"     docs/method.md §5.1: S >= 0
 *                                                        (S > 0 where all data > 0),
 *                                                        certified
 *   ts_gsl_interp_monotone     "trigspline-monotone"     docs/method.md §5.5: monotone
 *                                                        where the data are
 *   ts_gsl_interp_positive_c1  "trigspline-positive-c1"  the same schemes in the C¹
 *   ts_gsl_interp_monotone_c1  "trigspline-monotone-c1"  form of docs/method.md §3 (no
 *                                                        derivative jump at the knots;
 *                                                        same guarantees)
 *
 * Default alpha: TS_DEFAULT_ALPHA (0.85) for every type, margin t =
 * TS_DEFAULT_MARGIN (0.01).  The shape schemes only raise beta_i where a
 * constraint needs it, so a GSL user gets the least deformed curve that keeps
 * the promise.  The paper's own spline (paper form, arithmetic slopes,
 * alpha = 1) and its figures' small alpha (0.15 in Figure 4c) are one
 * ts_gsl_configure() away (below).
 *
 * Calling convention.  GSL passes the data arrays x, y again to every eval
 * function; the adapter ignores them and evaluates the spline built by the
 * last successful gsl_interp_init / gsl_spline_init (ts_spline_new copies the
 * data, as gsl_spline_init does).  Change the data only through a new init.
 * The accelerator, when given, is used as the ts_cursor hint: its cache holds
 * the interval index of the last query, as for GSL's own types, and
 * hit_count / miss_count are updated.  NULL accelerators are accepted.
 *
 * Errors.  The adapter never aborts and never calls the GSL error handler;
 * every type function returns a GSL status:
 *   GSL_SUCCESS  TS_OK
 *   GSL_EDOM     the data are outside the scheme's domain (TS_ERR_NEGATIVE,
 *                TS_ERR_NONMONOTONE, TS_ERR_SIDE, TS_ERR_LINES,
 *                TS_ERR_INFEASIBLE, TS_ERR_ZERO_SLOPE), or a query is NaN
 *                (TS_ERR_DOMAIN; GSL itself rejects queries outside the data)
 *   GSL_ENOMEM   TS_ERR_NOMEM
 *   GSL_EINVAL   everything else: NaN or Inf in y (TS_ERR_NONFINITE), invalid
 *                options, and every evaluation after an init that failed
 *                (the outputs are then NaN)
 * GSL's wrappers do call the handler for what they check themselves (x not
 * increasing, a query outside [x0, xn], too few points), and the non-"_e"
 * functions (gsl_spline_eval, ...) raise a nonzero status of the type through
 * the handler (GSL's DISCARD_STATUS), which aborts by default: use the "_e"
 * functions or gsl_set_error_handler_off() to receive statuses instead.
 * gsl_interp_alloc calls the handler when the adapter's small state cannot be
 * allocated.  The ts_error of the last init (with the index of the
 * offending point or interval) is available from ts_gsl_last_error().
 */
#ifndef TRIGSPLINE_GSL_H
#define TRIGSPLINE_GSL_H

#include <gsl/gsl_interp.h>
#include <gsl/gsl_spline.h>

#include "trigspline.h"

#ifdef __cplusplus
extern "C" {
#endif

extern const gsl_interp_type *const ts_gsl_interp_trig;
extern const gsl_interp_type *const ts_gsl_interp_positive;
extern const gsl_interp_type *const ts_gsl_interp_monotone;
extern const gsl_interp_type *const ts_gsl_interp_positive_c1;
extern const gsl_interp_type *const ts_gsl_interp_monotone_c1;

/* Map a ts_status to the GSL status above. */
int ts_gsl_status(ts_status status);

/* 1 if T is one of the types above, else 0 (also for NULL). */
int ts_gsl_is_trigspline(const gsl_interp_type *T);

/*
 * Options for the next inits of this object, replacing the type's defaults
 * entirely (start from ts_spline_options_init(), set fields).  The struct is copied;
 * arrays it points to (user_slopes, alphas, betas, margins) are read at each
 * init and must stay valid until the last gsl_*_init of this object.  opt ==
 * NULL restores the type's defaults.  Takes effect at the next init (call
 * gsl_spline_init again after it).  Returns GSL_SUCCESS, or GSL_EINVAL when
 * interp is NULL or not of a trigspline type, or an enum field of opt is out
 * of range.  For a gsl_spline pass spline->interp.
 */
int ts_gsl_configure(gsl_interp *interp, const ts_spline_options *opt);

/* The spline built by the last successful init: use it with the whole
 * library API (ts_spline_report, ts_spline_certified, ts_spline_eval_batch, ...).
 * NULL when interp is NULL, not of a trigspline type, not initialised yet, or
 * its last init failed.  Lives until the next init or gsl_*_free. */
const ts_spline *ts_gsl_spline(const gsl_interp *interp);

/* Status (and, if err is not NULL, the full ts_error) of the last init:
 * TS_OK after a successful one; TS_ERR_NULL when interp is NULL, not of a
 * trigspline type, or never initialised. */
ts_status ts_gsl_last_error(const gsl_interp *interp, ts_error *err);

#ifdef __cplusplus
}
#endif
#endif /* TRIGSPLINE_GSL_H */
