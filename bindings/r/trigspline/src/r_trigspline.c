/* R interface (.Call) to the trigspline library compiled into this package.
 * Options left NULL by the R code keep the library's defaults
 * (ts_spline_options_init, ts_surface_options_init): no default is restated
 * here.  A failure is returned to R as a list of class "trigspline_failure"
 * (status name, the library's sentence, 1-based index, where), which the R
 * code turns into a condition of class "trigspline_error". */
#include <R.h>
#include <Rinternals.h>
#include <R_ext/Rdynload.h>
#include <R_ext/Visibility.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "trigspline.h"

/* ---- utilities ---------------------------------------------------------- */

static SEXP list_get(SEXP list, const char *name)
{
    SEXP names = Rf_getAttrib(list, R_NamesSymbol);
    if (TYPEOF(list) != VECSXP || TYPEOF(names) != STRSXP) return R_NilValue;
    for (R_xlen_t i = 0; i < Rf_xlength(list); i++)
        if (strcmp(CHAR(STRING_ELT(names, i)), name) == 0) return VECTOR_ELT(list, i);
    return R_NilValue;
}

/* The value of a canonical name, or an R error listing the names. */
static int vocab_value(ts_vocab vocab, SEXP s, const char *what)
{
    int v = -1;
    if (!Rf_isString(s) || Rf_xlength(s) != 1 || STRING_ELT(s, 0) == NA_STRING)
        Rf_error("'%s' must be a single string", what);
    if (ts_vocab_value(vocab, CHAR(STRING_ELT(s, 0)), &v) != TS_OK)
        Rf_error("'%s' = \"%s\" is not one of the library's names", what, CHAR(STRING_ELT(s, 0)));
    return v;
}

static const double *opt_real(SEXP list, const char *name, R_xlen_t *len)
{
    SEXP v = list_get(list, name);
    *len = 0;
    if (Rf_isNull(v)) return NULL;
    if (TYPEOF(v) != REALSXP) Rf_error("'%s' must be a double vector", name);
    *len = Rf_xlength(v);
    return REAL(v);
}

static SEXP failure(const ts_error *err, const ts_error_context *ctx)
{
    char buf[1024];
    ts_error_message(err, ctx, buf, sizeof buf);
    const char *names[] = {"status", "message", "index", "where", ""};
    SEXP out = PROTECT(Rf_mkNamed(VECSXP, names));
    SET_VECTOR_ELT(out, 0, Rf_mkString(ts_status_name(err->status)));
    SET_VECTOR_ELT(out, 1, Rf_mkString(buf));
    SET_VECTOR_ELT(out, 2, Rf_ScalarReal(err->index == TS_NO_INDEX ? NA_REAL
                                                                   : (double)err->index + 1.0));
    const char *where = ts_vocab_name(TS_VOCAB_WHERE, (int)err->where);
    SET_VECTOR_ELT(out, 3, Rf_mkString(where ? where : "none"));
    Rf_setAttrib(out, R_ClassSymbol, Rf_mkString("trigspline_failure"));
    UNPROTECT(1);
    return out;
}

static SEXP vocab_string(ts_vocab vocab, int value)
{
    const char *name = ts_vocab_name(vocab, value);
    return Rf_mkString(name ? name : "");
}

/* ---- vocabulary and defaults -------------------------------------------- */

static SEXP r_vocab(SEXP kind)
{
    ts_vocab vocab = (ts_vocab)Rf_asInteger(kind);
    int n = ts_vocab_count(vocab);
    SEXP out = PROTECT(Rf_allocVector(STRSXP, n));
    for (int i = 0; i < n; i++) SET_STRING_ELT(out, i, Rf_mkChar(ts_vocab_name(vocab, i)));
    UNPROTECT(1);
    return out;
}

static SEXP r_defaults(void)
{
    ts_spline_options o;
    ts_surface_options so;
    ts_spline_options_init(&o);
    ts_surface_options_init(&so);
    const char *sn[] = {"form", "slopes", "alpha", "beta", "shape", "margin", "certify",
                        "extrapolate", ""};
    SEXP sp = PROTECT(Rf_mkNamed(VECSXP, sn));
    SET_VECTOR_ELT(sp, 0, vocab_string(TS_VOCAB_FORM, o.form));
    SET_VECTOR_ELT(sp, 1, vocab_string(TS_VOCAB_SLOPES, o.slopes));
    SET_VECTOR_ELT(sp, 2, Rf_ScalarReal(o.alpha));
    SET_VECTOR_ELT(sp, 3, Rf_ScalarReal(o.beta));
    SET_VECTOR_ELT(sp, 4, vocab_string(TS_VOCAB_SHAPE, o.shape));
    SET_VECTOR_ELT(sp, 5, Rf_ScalarReal(o.margin));
    SET_VECTOR_ELT(sp, 6, Rf_ScalarLogical(o.certify != 0));
    SET_VECTOR_ELT(sp, 7, vocab_string(TS_VOCAB_EXTRAP, o.extrapolate));
    const char *fn[] = {"form", "slopes", "alpha", "beta", "shape", "margin", "zero_twist", ""};
    SEXP sf = PROTECT(Rf_mkNamed(VECSXP, fn));
    SET_VECTOR_ELT(sf, 0, vocab_string(TS_VOCAB_FORM, so.form));
    SET_VECTOR_ELT(sf, 1, vocab_string(TS_VOCAB_SLOPES, so.slopes));
    SET_VECTOR_ELT(sf, 2, Rf_ScalarReal(so.alpha));
    SET_VECTOR_ELT(sf, 3, Rf_ScalarReal(so.beta));
    SET_VECTOR_ELT(sf, 4, vocab_string(TS_VOCAB_SURFACE_SHAPE, so.shape));
    SET_VECTOR_ELT(sf, 5, Rf_ScalarReal(so.margin));
    SET_VECTOR_ELT(sf, 6, Rf_ScalarLogical(so.zero_twist != 0));
    const char *tn[] = {"spline", "surface", "version", ""};
    SEXP out = PROTECT(Rf_mkNamed(VECSXP, tn));
    SET_VECTOR_ELT(out, 0, sp);
    SET_VECTOR_ELT(out, 1, sf);
    SET_VECTOR_ELT(out, 2, Rf_mkString(ts_version()));
    UNPROTECT(3);
    return out;
}

/* ---- splines ------------------------------------------------------------ */

static void spline_finalize(SEXP ptr)
{
    ts_spline_free((ts_spline *)R_ExternalPtrAddr(ptr));
    R_ClearExternalPtr(ptr);
}

static const ts_spline *spline_of(SEXP ptr)
{
    if (TYPEOF(ptr) != EXTPTRSXP || R_ExternalPtrAddr(ptr) == NULL)
        Rf_error("not a fitted trigspline (or one restored by readRDS or load)");
    return (const ts_spline *)R_ExternalPtrAddr(ptr);
}

static void line_of(SEXP list, const char *name, ts_line *line)
{
    R_xlen_t len;
    const double *v = opt_real(list, name, &len);
    if (v == NULL) return;
    if (len != 2) Rf_error("'%s' must be c(intercept, slope)", name);
    line->c = v[0];
    line->m = v[1];
}

static SEXP r_ptr_valid(SEXP ptr)
{
    return Rf_ScalarLogical(TYPEOF(ptr) == EXTPTRSXP && R_ExternalPtrAddr(ptr) != NULL);
}

/* x, f: double vectors of one length; opts: a named list (NULL entries keep
 * the library's default). */
static SEXP r_spline_new(SEXP x, SEXP f, SEXP opts)
{
    if (TYPEOF(x) != REALSXP || TYPEOF(f) != REALSXP || Rf_xlength(x) != Rf_xlength(f))
        Rf_error("x and y must be double vectors of one length");
    ts_spline_options o;
    ts_spline_options_init(&o);
    SEXP v;
    R_xlen_t len;
    const double *p;
    if (!Rf_isNull(v = list_get(opts, "form"))) o.form = (ts_form)vocab_value(TS_VOCAB_FORM, v, "form");
    if (!Rf_isNull(v = list_get(opts, "slopes")))
        o.slopes = (ts_slopes)vocab_value(TS_VOCAB_SLOPES, v, "slopes");
    if ((p = opt_real(opts, "user_slopes", &len)) != NULL) {
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = p;
        o.n_user_slopes = (size_t)len;
    }
    if ((p = opt_real(opts, "alpha", &len)) != NULL) {
        if (len == 1) o.alpha = p[0];
        else { o.alphas = p; o.n_alphas = (size_t)len; }
    }
    if ((p = opt_real(opts, "beta", &len)) != NULL) {
        if (len == 1) o.beta = p[0];
        else { o.betas = p; o.n_betas = (size_t)len; }
    }
    if ((p = opt_real(opts, "margin", &len)) != NULL) {
        if (len == 1) o.margin = p[0];
        else { o.margins = p; o.n_margins = (size_t)len; }
    }
    if (!Rf_isNull(v = list_get(opts, "shape")))
        o.shape = (ts_shape)vocab_value(TS_VOCAB_SHAPE, v, "shape");
    line_of(opts, "lower", &o.lower);
    line_of(opts, "upper", &o.upper);
    if (!Rf_isNull(v = list_get(opts, "certify"))) o.certify = Rf_asLogical(v) == TRUE;
    if (!Rf_isNull(v = list_get(opts, "extrapolate")))
        o.extrapolate = (ts_extrap)vocab_value(TS_VOCAB_EXTRAP, v, "extrapolate");

    /* the pointer (with its finalizer) first: nothing leaks if an R
     * allocation fails afterwards */
    SEXP ptr = PROTECT(R_MakeExternalPtr(NULL, Rf_install("trigspline"), R_NilValue));
    R_RegisterCFinalizerEx(ptr, spline_finalize, TRUE);
    ts_spline *s = NULL;
    ts_error err;
    size_t n = (size_t)Rf_xlength(x);
    if (ts_spline_new(REAL(x), REAL(f), n, &o, &s, &err) != TS_OK) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = REAL(x);
        ctx.f = REAL(f);
        ctx.n_points = n;
        ctx.spline_options = &o;
        ctx.first_index = 1;
        UNPROTECT(1);
        return failure(&err, &ctx);
    }
    R_SetExternalPtrAddr(ptr, s);
    UNPROTECT(1);
    return ptr;
}

/* NA queries give NA, as in R's interpolators: a domain failure that only
 * NaN queries caused is no failure; otherwise err names the first finite (or
 * infinite) query outside.  Valid queries never give NaN. */
static void na_queries(const double *xq, double *out, size_t m, ts_status *st, ts_error *err)
{
    size_t bad = TS_NO_INDEX;
    for (size_t j = 0; j < m; j++) {
        if (isnan(xq[j])) out[j] = NA_REAL;
        else if (isnan(out[j]) && bad == TS_NO_INDEX) bad = j;
    }
    if (bad == TS_NO_INDEX) {
        *st = TS_OK;
    } else {
        err->index = bad;
        err->where = TS_WHERE_QUERY;
    }
}

/* S^(deriv)(xq) under extrapolation extrap (NULL: the spline's own). */
static SEXP r_spline_eval(SEXP ptr, SEXP xq, SEXP deriv, SEXP extrap)
{
    const ts_spline *s = spline_of(ptr);
    if (TYPEOF(xq) != REALSXP) Rf_error("x must be a double vector");
    ts_extrap e = Rf_isNull(extrap) ? ts_spline_extrapolation(s)
                                    : (ts_extrap)vocab_value(TS_VOCAB_EXTRAP, extrap, "extrapolate");
    R_xlen_t m = Rf_xlength(xq);
    SEXP out = PROTECT(Rf_allocVector(REALSXP, m));
    ts_cursor cur = TS_CURSOR_INIT;
    ts_error err;
    ts_status st = ts_spline_eval_batch_mode(s, Rf_asInteger(deriv), e, REAL(xq), (size_t)m,
                                             REAL(out), &cur, &err);
    if (st == TS_ERR_DOMAIN) na_queries(REAL(xq), REAL(out), (size_t)m, &st, &err);
    if (st != TS_OK) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = ts_spline_x(s);
        ctx.f = ts_spline_f(s);
        ctx.n_points = ts_spline_intervals(s) + 1;
        ctx.queries = REAL(xq);
        ctx.n_queries = (size_t)m;
        ctx.first_index = 1;
        out = failure(&err, &ctx);
    }
    UNPROTECT(1);
    return out;
}

static SEXP copy_real(const double *v, size_t n)
{
    SEXP out = Rf_allocVector(REALSXP, (R_xlen_t)n);
    if (n) memcpy(REAL(out), v, n * sizeof(double));
    return out;
}

static SEXP r_spline_info(SEXP ptr)
{
    const ts_spline *s = spline_of(ptr);
    size_t n = ts_spline_intervals(s);
    const char *names[] = {"x", "y", "slopes", "alpha", "beta", "form", "shape", "extrapolate",
                           "certified", ""};
    SEXP out = PROTECT(Rf_mkNamed(VECSXP, names));
    SET_VECTOR_ELT(out, 0, copy_real(ts_spline_x(s), n + 1));
    SET_VECTOR_ELT(out, 1, copy_real(ts_spline_f(s), n + 1));
    SET_VECTOR_ELT(out, 2, copy_real(ts_spline_slopes(s), n + 1));
    SET_VECTOR_ELT(out, 3, copy_real(ts_spline_alpha(s), n));
    SET_VECTOR_ELT(out, 4, copy_real(ts_spline_beta(s), n));
    SET_VECTOR_ELT(out, 5, vocab_string(TS_VOCAB_FORM, ts_spline_form(s)));
    SET_VECTOR_ELT(out, 6, vocab_string(TS_VOCAB_SHAPE, ts_spline_shape(s)));
    SET_VECTOR_ELT(out, 7, vocab_string(TS_VOCAB_EXTRAP, ts_spline_extrapolation(s)));
    SET_VECTOR_ELT(out, 8, Rf_ScalarLogical(ts_spline_certified(s) != 0));
    UNPROTECT(1);
    return out;
}

/* The per-interval report as a list of columns (the R code makes the data.frame). */
static SEXP r_spline_report(SEXP ptr)
{
    const ts_spline *s = spline_of(ptr);
    R_xlen_t n = (R_xlen_t)ts_spline_intervals(s);
    const char *names[] = {"x0", "x1", "alpha", "beta", "a", "term", "has_lower", "has_upper",
                           "gap_lower", "at_lower", "gap_upper", "at_upper", "certified",
                           "min", "at_min", "max", "at_max", "excursion_above",
                           "excursion_below", ""};
    SEXP out = PROTECT(Rf_mkNamed(VECSXP, names));
    enum { NREAL = 19 };
    SET_VECTOR_ELT(out, 5, Rf_allocVector(STRSXP, n));
    for (int k = 0; k < NREAL; k++) {
        if (k == 5) continue;
        SET_VECTOR_ELT(out, k, Rf_allocVector(k == 6 || k == 7 || k == 12 ? LGLSXP : REALSXP, n));
    }
    for (R_xlen_t i = 0; i < n; i++) {
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        if (ts_spline_report(s, (size_t)i, &r) != TS_OK) Rf_error("ts_spline_report failed");
        double vals[NREAL] = {r.x0, r.x1, r.alpha, r.beta, r.a, 0, 0, 0, r.gap_lower, r.at_lower,
                              r.gap_upper, r.at_upper, 0, r.y_min, r.at_y_min, r.y_max, r.at_y_max,
                              r.excursion_above, r.excursion_below};
        for (int k = 0; k < NREAL; k++)
            if (TYPEOF(VECTOR_ELT(out, k)) == REALSXP) REAL(VECTOR_ELT(out, k))[i] = vals[k];
        SET_STRING_ELT(VECTOR_ELT(out, 5), i, Rf_mkChar(ts_vocab_name(TS_VOCAB_TERM, (int)r.term)));
        LOGICAL(VECTOR_ELT(out, 6))[i] = r.has_lower != 0;
        LOGICAL(VECTOR_ELT(out, 7))[i] = r.has_upper != 0;
        LOGICAL(VECTOR_ELT(out, 12))[i] = r.certified != 0;
    }
    UNPROTECT(1);
    return out;
}

static SEXP r_spline_integral(SEXP ptr, SEXP a, SEXP b)
{
    const ts_spline *s = spline_of(ptr);
    double v;
    ts_status st = ts_spline_integral(s, Rf_asReal(a), Rf_asReal(b), &v);
    if (st != TS_OK) {
        ts_error err = {st, TS_NO_INDEX, TS_WHERE_NONE};
        return failure(&err, NULL);
    }
    return Rf_ScalarReal(v);
}

/* ---- surfaces ----------------------------------------------------------- */

static void surface_finalize(SEXP ptr)
{
    ts_surface_free((ts_surface *)R_ExternalPtrAddr(ptr));
    R_ClearExternalPtr(ptr);
}

static const ts_surface *surface_of(SEXP ptr)
{
    if (TYPEOF(ptr) != EXTPTRSXP || R_ExternalPtrAddr(ptr) == NULL)
        Rf_error("not a fitted trigspline surface (or one restored by readRDS or load)");
    return (const ts_surface *)R_ExternalPtrAddr(ptr);
}

static void plane_of(SEXP list, const char *name, int *has, ts_plane *plane)
{
    R_xlen_t len;
    const double *v = opt_real(list, name, &len);
    if (v == NULL) return;
    if (len != 3) Rf_error("'%s' must be c(intercept, x slope, y slope)", name);
    *has = 1;
    plane->c = v[0];
    plane->p = v[1];
    plane->q = v[2];
}

/* z: the R matrix z[i, j] at (x[i], y[j]), column-major, which is the
 * library's layout z[j * nx + i]. */
static SEXP r_surface_new(SEXP x, SEXP y, SEXP z, SEXP opts)
{
    if (TYPEOF(x) != REALSXP || TYPEOF(y) != REALSXP || TYPEOF(z) != REALSXP ||
        Rf_xlength(z) != Rf_xlength(x) * Rf_xlength(y))
        Rf_error("z must be a double matrix of length(x) rows and length(y) columns");
    ts_surface_options o;
    ts_surface_options_init(&o);
    SEXP v;
    R_xlen_t len;
    const double *p;
    if (!Rf_isNull(v = list_get(opts, "form"))) o.form = (ts_form)vocab_value(TS_VOCAB_FORM, v, "form");
    if (!Rf_isNull(v = list_get(opts, "slopes")))
        o.slopes = (ts_slopes)vocab_value(TS_VOCAB_SLOPES, v, "slopes");
    if (!Rf_isNull(v = list_get(opts, "shape")))
        o.shape = (ts_surface_shape)vocab_value(TS_VOCAB_SURFACE_SHAPE, v, "shape");
    if ((p = opt_real(opts, "alpha", &len)) != NULL && len == 1) o.alpha = p[0];
    if ((p = opt_real(opts, "beta", &len)) != NULL && len == 1) o.beta = p[0];
    if ((p = opt_real(opts, "margin", &len)) != NULL && len == 1) o.margin = p[0];
    if (!Rf_isNull(v = list_get(opts, "zero_twist"))) o.zero_twist = Rf_asLogical(v) == TRUE;
    plane_of(opts, "lower", &o.has_lower, &o.lower);
    plane_of(opts, "upper", &o.has_upper, &o.upper);

    SEXP ptr = PROTECT(R_MakeExternalPtr(NULL, Rf_install("trigspline_surface"), R_NilValue));
    R_RegisterCFinalizerEx(ptr, surface_finalize, TRUE);
    ts_surface *s = NULL;
    ts_error err;
    size_t nx = (size_t)Rf_xlength(x), ny = (size_t)Rf_xlength(y);
    if (ts_surface_new(REAL(x), nx, REAL(y), ny, REAL(z), &o, &s, &err) != TS_OK) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = REAL(x);
        ctx.n_points = nx;
        ctx.y = REAL(y);
        ctx.ny_points = ny;
        ctx.f = REAL(z);
        ctx.surface_options = &o;
        ctx.first_index = 1;
        UNPROTECT(1);
        return failure(&err, &ctx);
    }
    R_SetExternalPtrAddr(ptr, s);
    UNPROTECT(1);
    return ptr;
}

static SEXP surface_query_failure(const ts_surface *s, const ts_error *err, const double *xq,
                                  size_t m)
{
    ts_error_context ctx;
    ts_error_context_init(&ctx);
    ctx.x = ts_surface_x(s);
    ctx.n_points = ts_surface_nx(s) + 1;
    ctx.y = ts_surface_y(s);
    ctx.ny_points = ts_surface_ny(s) + 1;
    ctx.f = ts_surface_z(s);
    ctx.queries = xq;
    ctx.n_queries = m;
    ctx.first_index = 1;
    return failure(err, &ctx);
}

/* Values at scattered points (xq[k], yq[k]); which: 0 value, 1 dz/dx, 2 dz/dy. */
static SEXP r_surface_eval(SEXP ptr, SEXP xq, SEXP yq, SEXP which)
{
    const ts_surface *s = surface_of(ptr);
    if (TYPEOF(xq) != REALSXP || TYPEOF(yq) != REALSXP || Rf_xlength(xq) != Rf_xlength(yq))
        Rf_error("x and y must be double vectors of one length");
    R_xlen_t m = Rf_xlength(xq);
    int w = Rf_asInteger(which);
    SEXP out = PROTECT(Rf_allocVector(REALSXP, m));
    SEXP tmp = PROTECT(Rf_allocVector(REALSXP, w == 0 ? 0 : m));
    ts_error err;
    ts_status st = ts_surface_eval_batch(s, REAL(xq), REAL(yq), (size_t)m,
                                         w == 0 ? REAL(out) : REAL(tmp),
                                         w == 1 ? REAL(out) : NULL, w == 2 ? REAL(out) : NULL, &err);
    if (st == TS_ERR_DOMAIN) {
        /* NA in either coordinate gives NA */
        size_t bad = TS_NO_INDEX;
        for (R_xlen_t k = 0; k < m; k++) {
            if (isnan(REAL(xq)[k]) || isnan(REAL(yq)[k])) REAL(out)[k] = NA_REAL;
            else if (isnan(REAL(out)[k]) && bad == TS_NO_INDEX) bad = (size_t)k;
        }
        if (bad == TS_NO_INDEX) st = TS_OK;
        else err.index = bad;
    }
    if (st != TS_OK) out = surface_query_failure(s, &err, NULL, 0);
    UNPROTECT(2);
    return out;
}

/* The outer product: a length(xq) x length(yq) matrix of values. */
static SEXP r_surface_grid(SEXP ptr, SEXP xq, SEXP yq)
{
    const ts_surface *s = surface_of(ptr);
    if (TYPEOF(xq) != REALSXP || TYPEOF(yq) != REALSXP) Rf_error("x and y must be double vectors");
    R_xlen_t mx = Rf_xlength(xq), my = Rf_xlength(yq);
    if (mx > INT_MAX || my > INT_MAX) Rf_error("grid too large for a matrix");
    SEXP out = PROTECT(Rf_allocMatrix(REALSXP, (int)mx, (int)my));
    ts_error err;
    if (ts_surface_eval_grid(s, REAL(xq), (size_t)mx, REAL(yq), (size_t)my, REAL(out), &err) !=
        TS_OK)
        out = surface_query_failure(s, &err, NULL, 0);
    UNPROTECT(1);
    return out;
}

static SEXP r_surface_info(SEXP ptr)
{
    const ts_surface *s = surface_of(ptr);
    size_t nx = ts_surface_nx(s), ny = ts_surface_ny(s);
    const char *names[] = {"x", "y", "z", "ax", "ay", "form", "shape", "certified", ""};
    SEXP out = PROTECT(Rf_mkNamed(VECSXP, names));
    SET_VECTOR_ELT(out, 0, copy_real(ts_surface_x(s), nx + 1));
    SET_VECTOR_ELT(out, 1, copy_real(ts_surface_y(s), ny + 1));
    SEXP z = Rf_allocMatrix(REALSXP, (int)(nx + 1), (int)(ny + 1));
    SET_VECTOR_ELT(out, 2, z);
    memcpy(REAL(z), ts_surface_z(s), (nx + 1) * (ny + 1) * sizeof(double));
    SET_VECTOR_ELT(out, 3, copy_real(ts_surface_ax(s), nx));
    SET_VECTOR_ELT(out, 4, copy_real(ts_surface_ay(s), ny));
    SET_VECTOR_ELT(out, 5, vocab_string(TS_VOCAB_FORM, ts_surface_form(s)));
    SET_VECTOR_ELT(out, 6, vocab_string(TS_VOCAB_SURFACE_SHAPE, ts_surface_shape_of(s)));
    SET_VECTOR_ELT(out, 7, Rf_ScalarLogical(ts_surface_certified(s) != 0));
    UNPROTECT(1);
    return out;
}

/* The patch certificates as a list of columns, patch (i, j) in row j*nx + i. */
static SEXP r_surface_report(SEXP ptr)
{
    const ts_surface *s = surface_of(ptr);
    size_t nx = ts_surface_nx(s), ny = ts_surface_ny(s);
    R_xlen_t n = (R_xlen_t)(nx * ny);
    const char *names[] = {"i", "j", "x0", "x1", "y0", "y1", "ax", "ay", "has_lower",
                           "has_upper", "proven_lower", "sampled_lower", "at_lower_x",
                           "at_lower_y", "proven_upper", "sampled_upper", "at_upper_x",
                           "at_upper_y", "certified", ""};
    enum { NCOL = 19 };
    SEXP out = PROTECT(Rf_mkNamed(VECSXP, names));
    for (int k = 0; k < NCOL; k++)
        SET_VECTOR_ELT(out, k, Rf_allocVector(k < 2 ? INTSXP : (k == 8 || k == 9 || k == 18)
                                                                ? LGLSXP : REALSXP, n));
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            R_xlen_t r = (R_xlen_t)(j * nx + i);
            ts_patch_report p = TS_PATCH_REPORT_INIT;
            if (ts_surface_report(s, i, j, &p) != TS_OK) Rf_error("ts_surface_report failed");
            INTEGER(VECTOR_ELT(out, 0))[r] = (int)i + 1;
            INTEGER(VECTOR_ELT(out, 1))[r] = (int)j + 1;
            double vals[NCOL] = {0, 0, p.x0, p.x1, p.y0, p.y1, p.ax, p.ay, 0, 0,
                                 p.proven_lower, p.sampled_lower, p.at_lower[0], p.at_lower[1],
                                 p.proven_upper, p.sampled_upper, p.at_upper[0], p.at_upper[1], 0};
            for (int k = 2; k < NCOL; k++)
                if (TYPEOF(VECTOR_ELT(out, k)) == REALSXP) REAL(VECTOR_ELT(out, k))[r] = vals[k];
            LOGICAL(VECTOR_ELT(out, 8))[r] = p.has_lower != 0;
            LOGICAL(VECTOR_ELT(out, 9))[r] = p.has_upper != 0;
            LOGICAL(VECTOR_ELT(out, 18))[r] = p.certified != 0;
        }
    UNPROTECT(1);
    return out;
}

/* ---- registration ------------------------------------------------------- */

static const R_CallMethodDef call_methods[] = {
    {"vocab", (DL_FUNC)&r_vocab, 1},
    {"defaults", (DL_FUNC)&r_defaults, 0},
    {"ptr_valid", (DL_FUNC)&r_ptr_valid, 1},
    {"spline_new", (DL_FUNC)&r_spline_new, 3},
    {"spline_eval", (DL_FUNC)&r_spline_eval, 4},
    {"spline_info", (DL_FUNC)&r_spline_info, 1},
    {"spline_report", (DL_FUNC)&r_spline_report, 1},
    {"spline_integral", (DL_FUNC)&r_spline_integral, 3},
    {"surface_new", (DL_FUNC)&r_surface_new, 4},
    {"surface_eval", (DL_FUNC)&r_surface_eval, 4},
    {"surface_grid", (DL_FUNC)&r_surface_grid, 3},
    {"surface_info", (DL_FUNC)&r_surface_info, 1},
    {"surface_report", (DL_FUNC)&r_surface_report, 1},
    {NULL, NULL, 0}};

void attribute_visible R_init_trigspline(DllInfo *dll)
{
    R_registerRoutines(dll, NULL, call_methods, NULL, NULL);
    R_useDynamicSymbols(dll, FALSE);
    R_forceSymbols(dll, TRUE);
}
