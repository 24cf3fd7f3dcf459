/* Control values B1, B2 (and κ of the geometric form) of every form
 * (docs/method.md §3, §4). */
#include "internal.h"

/* docs/method.md §3 (paper, C¹) and §4 (geometric) control values, one loop per form
 * with the arrays as restrict parameters, so that they vectorise. */
TS_VECTOR_LOOP static void controls_paper(const double *restrict f, const double *restrict d,
                                          const double *restrict x, const double *restrict al,
                                          const double *restrict be, double *restrict b1,
                                          double *restrict b2, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++) {
        double k = ts__geo_k(x[i + 1] - x[i], al[i] + be[i]);
        b1[i] = f[i] + k * d[i];
        b2[i] = f[i + 1] - k * d[i + 1];
    }
}

/* The geometric form: κ; B1, B2 are derived (ts__B) unless stored (b1 not
 * NULL: constraint records, which may nudge them). */
TS_VECTOR_LOOP static void controls_geo(const double *restrict al, const double *restrict be,
                                        double *restrict kappa, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++)
        kappa[i] = ts__kappa(al[i] + be[i]);
}

/* docs/method.md §3 C¹ option: d̂_j = d_j / max(a_{j-1}, a_j), one-sided at the ends;
 * intervals [i0, i1) with both neighbours (0 < i0, i1 < n). */
TS_VECTOR_LOOP static void controls_c1(const double *restrict f, const double *restrict d,
                                       const double *restrict x, const double *restrict al,
                                       const double *restrict be, double *restrict b1,
                                       double *restrict b2, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++) {
        double K = ts__geo_K(x[i + 1] - x[i]);
        double a = al[i] + be[i], ap = al[i - 1] + be[i - 1], an = al[i + 1] + be[i + 1];
        double aL = ap > a ? ap : a, aR = an > a ? an : a;
        b1[i] = f[i] + K * (d[i] / aL);
        b2[i] = f[i + 1] - K * (d[i + 1] / aR);
    }
}

void ts__ends_a(const ts_spline *sp, size_t i, double *aL, double *aR)
{
    *aL = *aR = sp->alpha[i] + sp->beta[i];
}

void ts__ends_a_c1(const ts_spline *sp, size_t i, double *aL, double *aR)
{
    const double *al = sp->alpha, *be = sp->beta;
    double a = al[i] + be[i];
    *aL = *aR = a;
    if (i > 0) {
        double ap = al[i - 1] + be[i - 1];
        *aL = ap > a ? ap : a;
    }
    if (i + 1 < sp->n) {
        double an = al[i + 1] + be[i + 1];
        *aR = an > a ? an : a;
    }
}

/* The same for one interval, also at an end. */
static void controls_c1_one(ts_spline *sp, size_t i)
{
    double K = ts__geo_K(ts__h(sp, i)), aL, aR;
    ts__ends_a_c1(sp, i, &aL, &aR);
    sp->b1[i] = sp->f[i] + K * (sp->d[i] / aL);
    sp->b2[i] = sp->f[i + 1] - K * (sp->d[i + 1] / aR);
}

void ts__controls_c1(ts_spline *sp, size_t i0, size_t i1)
{
    size_t n = sp->n;
    size_t m0 = i0 > 0 ? i0 : 1, m1 = i1 < n ? i1 : n - 1; /* both neighbours */
    if (i0 == 0)
        controls_c1_one(sp, 0);
    if (m0 < m1)
        controls_c1(sp->f, sp->d, sp->x, sp->alpha, sp->beta, sp->b1, sp->b2, m0, m1);
    if (i1 == n && n - 1 > 0)
        controls_c1_one(sp, n - 1);
}

void ts__controls_geo(ts_spline *sp, size_t i0, size_t i1)
{
    controls_geo(sp->alpha, sp->beta, sp->kappa, i0, i1);
    if (sp->b1)
        controls_paper(sp->f, sp->d, sp->x, sp->alpha, sp->beta, sp->b1, sp->b2, i0, i1);
}

void ts__controls_paper(ts_spline *sp, size_t i0, size_t i1)
{
    controls_paper(sp->f, sp->d, sp->x, sp->alpha, sp->beta, sp->b1, sp->b2, i0, i1);
}

