/* Per-interval reports and certification of a built spline against given
 * lines (docs/method.md §5). */
#include "internal.h"

#include <math.h>


static void report_base(const ts_spline *s, size_t i, ts_interval_report *rep)
{
    double X[4];
    int geo;
    rep->x0 = s->x[i];
    rep->x1 = s->x[i + 1];
    rep->alpha = s->alpha[i];
    rep->beta = s->beta[i];
    rep->a = s->alpha[i] + s->beta[i];
    ts__controls_of(s, i, rep->B, X, &geo);
    rep->term = (ts_term)s->term[i];
    rep->has_lower = rep->has_upper = 0;
    rep->gap_lower = rep->at_lower = rep->gap_upper = rep->at_upper = (double)NAN;
    rep->certified = 0;
    ts__range_ctl(s, i, rep->B, geo ? X : NULL, rep);
}

static void report_clear(ts_interval_report *rep)
{
    rep->struct_size = sizeof *rep;
    rep->x0 = rep->x1 = rep->alpha = rep->beta = rep->a = (double)NAN;
    rep->B[0] = rep->B[1] = rep->B[2] = rep->B[3] = (double)NAN;
    rep->term = TS_TERM_USER;
    rep->has_lower = rep->has_upper = 0;
    rep->gap_lower = rep->at_lower = rep->gap_upper = rep->at_upper = (double)NAN;
    rep->certified = 0;
    rep->y_min = rep->at_y_min = rep->y_max = rep->at_y_max = (double)NAN;
    rep->excursion_above = rep->excursion_below = (double)NAN;
}

void ts_interval_report_init(ts_interval_report *reports, size_t n)
{
    for (size_t i = 0; reports && i < n; i++)
        report_clear(&reports[i]);
}

ts_status ts_spline_report(const ts_spline *s, size_t i, ts_interval_report *rep)
{
    if (rep && rep->struct_size != sizeof *rep)
        return TS_ERR_VERSION; /* a struct of another layout: not written */
    if (rep)
        report_clear(rep);
    if (!s || !rep)
        return TS_ERR_NULL;
    if (i >= s->n)
        return TS_ERR_INDEX;
    report_base(s, i, rep);
    rep->certified = s->ncon != 0; /* built with constraint records: each proven (§13) */
    if (s->shape == TS_SHAPE_NONE)
        return TS_OK;
    double B[4], X[4];
    int geo;
    ts__cert cr;
    ts__controls_of(s, i, B, X, &geo);
    rep->has_lower = s->has_lower;
    rep->has_upper = s->has_upper;
    int ok = ts__check_ctl(s, i, B, geo ? X : NULL, s->have_certs, &cr, 1); /* fills cr */
    rep->certified = ok; /* a shaped spline that was built is certified (ts__certify_done) */
    if (s->have_certs) {
        /* the build's certificates, computed again (not stored: construction speed) */
        rep->gap_lower = cr.glo;
        rep->at_lower = cr.alo;
        rep->gap_upper = cr.gup;
        rep->at_upper = cr.aup;
    } else {
        /* certificates skipped at build (opt.certify = 0): compute them now */
        if (s->has_lower)
            rep->gap_lower = ts__gap_ctl(s, i, B, geo ? X : NULL, &s->lower, 1, &rep->at_lower, NULL);
        if (s->has_upper) /* a line skipped only in the geometric form (ts__certify_exact) */
            rep->gap_upper = ts__gap_ctl(s, i, B, X, &s->upper, -1, &rep->at_upper, NULL);
    }
    return TS_OK;
}

int ts_spline_certified(const ts_spline *s)
{
    /* construction of a shaped spline fails unless every interval is
     * certified (ts__certify_done) */
    return s && (s->shape != TS_SHAPE_NONE || s->ncon) ? 1 : 0;
}

ts_status ts_spline_certify(const ts_spline *s, const ts_line *lower, const ts_line *upper,
                            ts_interval_report *reports, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (reports && reports[0].struct_size != sizeof *reports)
        return ts__fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    for (size_t i = 0; s && reports && i < s->n; i++) /* out-params reset first */
        report_clear(&reports[i]);
    if (!s || (!lower && !upper)) {
        ts__error_set(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_ERR_NULL;
    }
    if ((lower && !(isfinite(lower->m) && isfinite(lower->c))) ||
        (upper && !(isfinite(upper->m) && isfinite(upper->c)))) {
        ts__error_set(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_ERR_NONFINITE;
    }
    size_t first = TS_NO_INDEX;
    for (size_t i = 0; i < s->n; i++) {
        double B[4], X[4], guard;
        int geo, ok = 1; /* no line given: certified */
        ts_interval_report r;
        r.struct_size = sizeof r;
        report_base(s, i, &r);
        ts__controls_of(s, i, B, X, &geo);
        /* the control gaps' proof (hull_inside) also counts */
        if (lower) {
            r.has_lower = 1;
            r.gap_lower = ts__gap_ctl(s, i, B, geo ? X : NULL, lower, 1, &r.at_lower, &guard);
            ok = r.gap_lower > guard || ts__hull_inside(s, i, B, geo ? X : NULL, lower, 1);
        }
        if (upper) {
            r.has_upper = 1;
            r.gap_upper = ts__gap_ctl(s, i, B, geo ? X : NULL, upper, -1, &r.at_upper, &guard);
            ok = ok && (r.gap_upper > guard || ts__hull_inside(s, i, B, geo ? X : NULL, upper, -1));
        }
        r.certified = ok;
        if (!ok && first == TS_NO_INDEX)
            first = i;
        if (reports)
            reports[i] = r;
    }
    if (first != TS_NO_INDEX) {
        ts__error_set(err, TS_ERR_VIOLATED, first, TS_WHERE_INTERVAL);
        return TS_ERR_VIOLATED;
    }
    return TS_OK;
}

