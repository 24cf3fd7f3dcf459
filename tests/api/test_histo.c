/* Rates from bin totals (docs/method.md §12): totals kept, bounds never
 * left, C¹ across edges, on closed forms, seeded intermittent series
 * (spikes ×1000, most bins dry) and the daily rainfall example; every
 * status of the ts_histo_* functions provoked.
 *
 * TS_HISTO_SERIES (environment) sets the number of random series
 * (default 10000; `make test-histo` runs 200000).
 *
 * Tolerances: totals 1e-13 relative (the goal of docs/method.md §12.6; the
 * quadrature reference sums 24 rounded terms, ~1e-15); C¹: the derivative's
 * jump at a knot within 1e-12 of the local derivative scale (§12.6: the
 * rounding of the control-value differences, a few ε of the values divided
 * by the width).  No FE_INVALID, FE_DIVBYZERO or FE_OVERFLOW may be raised by
 * building, evaluating, subdividing or taking grid totals of valid series
 * (the header's promise; the vector loops form every lane's quotients). */
#include "th.h"
#include "trigspline.h"

#include <fenv.h>
#include <stdint.h>
#include <string.h>

#ifndef TS_SOURCE_DIR
#define TS_SOURCE_DIR "."
#endif

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static uint64_t rnd(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
static double urand(void)
{
    return (double)(rnd() >> 11) * 0x1p-53;
}

/* 12-point Gauss–Legendre nodes and weights on [−1, 1], the positive half
 * (numpy.polynomial.legendre.leggauss(12)). */
static const double gl_x[6] = {0.1252334085114689, 0.3678314989981802, 0.5873179542866175,
                               0.7699026741943047, 0.9041172563704748, 0.9815606342467192};
static const double gl_w[6] = {0.2491470458134027, 0.23349253653835464, 0.20316742672306565,
                               0.1600783285433461, 0.10693932599531888, 0.04717533638651202};

/* ∫ r over [a, b] by 12-point Gauss–Legendre on the evaluated rate: the
 * rate is a trigonometric polynomial of degree 3 in an angle linear in x on
 * [a, b] (a piece), so the rule's error is far below rounding. */
static double quad(const ts_histo *h, double a, double b, double *slack)
{
    double m = 0.5 * (a + b), r = 0.5 * (b - a), s = 0.0, sl = 0.0;
    for (int k = 0; k < 6; k++) {
        double v1, v2, d1, d2, x1 = m - r * gl_x[k], x2 = m + r * gl_x[k];
        ts_histo_eval(h, x1, &v1, &d1);
        ts_histo_eval(h, x2, &v2, &d2);
        s += gl_w[k] * (v1 + v2);
        /* the nodes are rounded to the grid of x: up to 2 ulps of x aside */
        sl += gl_w[k] * (fabs(d1) * 2.0 * (nextafter(fabs(x1), TH_INF) - fabs(x1)) +
                         fabs(d2) * 2.0 * (nextafter(fabs(x2), TH_INF) - fabs(x2)));
    }
    *slack += r * sl;
    return r * s;
}

typedef struct stats {
    long bins, dry, series;
    long below, above;        /* returned values outside [lo, hi] */
    long uncert, report_below;
    double tot_err;           /* largest relative error of a bin total */
    double c1_jump;           /* largest relative jump of r' at a knot */
    double c0_jump;
    double sub_diff;          /* ts_histo_subdivide against ts_histo_totals */
    long flagged;             /* calls on valid input that raised FE_INVALID / FE_DIVBYZERO /
                                 FE_OVERFLOW */
} stats;

static int fp_flags(void)
{
    int f = fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
    feclearexcept(FE_ALL_EXCEPT);
    return f != 0;
}

static void check_series(const double *e, const double *T, size_t n, const ts_histo_options *o,
                         stats *st, int dense)
{
    ts_histo *h = NULL;
    ts_error err;
    feclearexcept(FE_ALL_EXCEPT);
    ts_status s = ts_histo_new(e, T, n, o, &h, &err);
    st->flagged += fp_flags();
    CHECKF(s == TS_OK, "build: %s index %zu", ts_status_name(s), err.index);
    if (s != TS_OK)
        return;
    double lo = o ? o->lo : 0.0, hi = o ? o->hi : TH_INF;
    st->series++;
    for (size_t j = 0; j < n; j++) {
        double w = e[j + 1] - e[j], mid = e[j] + 0.5 * w;
        st->bins++;
        st->dry += T[j] == lo * w;
        /* totals: quadrature of the evaluated rate, the integral, the report */
        double slack = 0.0;
        double q = quad(h, e[j], mid, &slack) + quad(h, mid, e[j + 1], &slack);
        double scale = fabs(T[j]) > 0.0 ? fabs(T[j]) : DBL_MIN;
        double err1 = fmax(fabs(q - T[j]) - slack, 0.0) / scale;
        double iv;
        ts_histo_integral(h, e[j], e[j + 1], &iv);
        double err2 = fabs(iv - T[j]) / scale;
        double e12 = err1 > err2 ? err1 : err2;
        st->tot_err = e12 > st->tot_err ? e12 : st->tot_err;
        /* exact minimum and maximum, and the control-value proof */
        ts_bin_report rep;
        ts_bin_report_init(&rep);
        ts_histo_report(h, j, &rep);
        st->uncert += !rep.certified;
        st->report_below += !(rep.r_min >= lo - rep.guard) || !(rep.r_max <= hi + rep.guard);
        /* dense samples */
        int ns = dense;
        for (int k = 0; k <= ns; k++) {
            double x = e[j] + w * k / ns, r;
            if (x > e[j + 1])
                x = e[j + 1];
            ts_histo_eval(h, x, &r, NULL);
            st->below += !(r >= lo);
            st->above += !(r <= hi);
        }
        st->flagged += fp_flags();
        /* C¹ at the left edge (inner) and at the three inner knots: the
         * left side from the end of the piece before the knot (its control
         * values, the end slope 3(B3 − B2)·π/(2q) of §2), the right side
         * evaluated at the edge, or from the next piece's control values
         * (the quarter points need not be doubles) */
        ts_bin_report pr, pl;
        ts_bin_report_init(&pr);
        ts_bin_report_init(&pl);
        ts_histo_report(h, j, &pr);
        if (j > 0)
            ts_histo_report(h, j - 1, &pl);
        double qq = 0.25 * w;
        for (int kn = 0; kn < 4; kn++) {
            if (!kn && j == 0)
                continue;
            const double *P = kn ? pr.B + 4 * (kn - 1) : pl.B + 12;
            double ql = kn ? qq : 0.25 * (pl.e1 - pl.e0);
            double rl = lo + P[3], dl = 3.0 * (P[3] - P[2]) * (TH_HALF_PI / ql), rr, dr;
            if (kn) {
                rr = lo + pr.B[4 * kn];
                dr = 3.0 * (pr.B[4 * kn + 1] - pr.B[4 * kn]) * (TH_HALF_PI / qq);
            } else {
                ts_histo_eval(h, e[j], &rr, &dr);
                st->flagged += fp_flags();
            }
            double wmin = kn ? qq : fmin(qq, ql);
            double mu = T[j] / w - lo;
            if (!kn)
                mu = fmax(mu, T[j - 1] / (e[j] - e[j - 1]) - lo);
            double sc = fmax(fmax(fabs(dl), fabs(dr)), fmax(mu, fabs(rr - lo)) / wmin);
            if (sc > 0.0) {
                double jd = fabs(dl - dr) / sc, jv = fabs(rl - rr) / (sc * wmin);
                st->c1_jump = jd > st->c1_jump ? jd : st->c1_jump;
                st->c0_jump = jv > st->c0_jump ? jv : st->c0_jump;
            }
        }
    }
    /* a finer grid: its cells add up to each bin's total */
    size_t sub = 7, m = n * sub + 1;
    double *g = malloc(m * sizeof *g), *out = malloc((m - 1) * sizeof *out);
    if (g && out) {
        for (size_t j = 0; j < n; j++)
            for (size_t k = 0; k < sub; k++)
                g[j * sub + k] = e[j] + (e[j + 1] - e[j]) * (double)k / (double)sub;
        g[m - 1] = e[n];
        s = ts_histo_totals(h, g, m, out, &err);
        CHECK(s == TS_OK);
        for (size_t j = 0; j < n && s == TS_OK; j++) {
            double sum = 0.0;
            for (size_t k = 0; k < sub; k++) {
                double c = out[j * sub + k], cw = g[j * sub + k + 1] - g[j * sub + k];
                st->below += !(c >= lo * cw);
                st->above += !(c <= hi * cw);
                sum += c;
            }
            double scale = fabs(T[j]) > 0.0 ? fabs(T[j]) : DBL_MIN;
            double er = fabs(sum - T[j]) / scale;
            st->tot_err = er > st->tot_err ? er : st->tot_err;
        }
        /* the same cells by ts_histo_subdivide: its sums, and the same
         * values as the grid's to rounding (1e-13 of the bin's total) once
         * the grid's own rounding is allowed for: its points are up to an
         * ulp of x from the exact subdivision, which moves a cell's total
         * by up to the bin's peak rate times that */
        feclearexcept(FE_ALL_EXCEPT);
        s = ts_histo_subdivide(h, sub, out, &err);
        st->flagged += fp_flags();
        CHECK(s == TS_OK);
        double *gt = malloc((m - 1) * sizeof *gt);
        ts_status sg = gt ? ts_histo_totals(h, g, m, gt, NULL) : TS_ERR_NOMEM;
        st->flagged += fp_flags();
        if (gt && s == TS_OK && sg == TS_OK) {
            for (size_t j = 0; j < n; j++) {
                double sum = 0.0, scale = fabs(T[j]) > 0.0 ? fabs(T[j]) : DBL_MIN;
                ts_bin_report br;
                ts_bin_report_init(&br);
                ts_histo_report(h, j, &br);
                for (size_t k = 0; k < sub; k++) {
                    double c = out[j * sub + k], cw = (e[j + 1] - e[j]) / (double)sub;
                    double ga = fabs(g[j * sub + k]), gb = fabs(g[j * sub + k + 1]);
                    double allow = fabs(br.r_max) * ((nextafter(ga, TH_INF) - ga) + (nextafter(gb, TH_INF) - gb));
                    st->below += !(c >= lo * cw);
                    st->above += !(c <= hi * cw);
                    sum += c;
                    double d = fmax(fabs(c - gt[j * sub + k]) - allow, 0.0) / scale;
                    st->sub_diff = d > st->sub_diff ? d : st->sub_diff;
                }
                double er = fabs(sum - T[j]) / scale;
                st->tot_err = er > st->tot_err ? er : st->tot_err;
            }
        }
        free(gt);
    }
    free(g);
    free(out);
    ts_histo_free(h);
}

static void print_stats(const char *what, const stats *st)
{
    printf("%s: %ld series, %ld bins (%.1f %% dry): total error %.3g, %ld below, %ld above, "
           "%ld uncertified, C1 jump %.3g, C0 jump %.3g, subdivide vs grid %.3g, %ld flagged\n",
           what, st->series, st->bins, 100.0 * (double)st->dry / (double)(st->bins ? st->bins : 1),
           st->tot_err, st->below, st->above, st->uncert, st->c1_jump, st->c0_jump, st->sub_diff,
           st->flagged);
}

static void check_stats(const stats *st)
{
    CHECKF(st->tot_err <= 1e-13, "total error %.3g", st->tot_err);
    CHECK(st->below == 0);
    CHECK(st->above == 0);
    CHECK(st->uncert == 0);
    CHECK(st->report_below == 0);
    CHECKF(st->c1_jump <= 1e-12, "C1 jump %.3g", st->c1_jump);
    CHECKF(st->c0_jump <= 1e-12, "C0 jump %.3g", st->c0_jump);
    CHECKF(st->sub_diff <= 1e-13, "subdivide against the grid %.3g", st->sub_diff);
    CHECKF(st->flagged == 0, "%ld calls raised a floating-point flag", st->flagged);
}

/* One random intermittent series: bins of width 1 (or irregular), about 70 %
 * dry, gamma-like amounts, spikes ×1000, scales from 1e-6 to 1e6. */
static size_t gen_series(double *e, double *T, size_t nmax)
{
    size_t n = 8 + (size_t)(rnd() % (nmax - 7));
    int irregular = rnd() % 4 == 0;
    double scale = pow(10.0, -6.0 + 12.0 * urand());
    e[0] = irregular ? -50.0 * urand() : (double)(rnd() % 1000);
    for (size_t j = 0; j < n; j++) {
        double w = irregular ? 0.05 + 3.0 * urand() : 1.0;
        e[j + 1] = e[j] + w;
        double u = urand();
        if (u < 0.7)
            T[j] = 0.0;
        else {
            double a = -log(urand() + 1e-300) * scale;
            if (urand() < 0.05)
                a *= 1000.0;
            T[j] = a * w;
        }
    }
    return n;
}

static void random_series(long count)
{
    TH_CASE("random intermittent series");
    enum { NMAX = 64 };
    double e[NMAX + 1], T[NMAX];
    stats st = {0};
    for (long k = 0; k < count; k++) {
        size_t n = gen_series(e, T, NMAX);
        check_series(e, T, n, NULL, &st, 16);
    }
    print_stats("random", &st);
    CHECK(st.series == count);
    CHECKF((double)st.dry >= 0.6 * (double)st.bins, "dry fraction %ld / %ld", st.dry, st.bins);
    check_stats(&st);

    TH_CASE("random series with bounds");
    stats sb = {0};
    long nb = count / 10 > 1 ? count / 10 : 1, built = 0;
    for (long k = 0; k < nb; k++) {
        size_t n = gen_series(e, T, NMAX);
        /* lo = 0.1 (a base rate) and hi: twice the largest mean + the
         * base, so that every neighbouring pair is joinable (§12.4) */
        double mx = 0.0;
        for (size_t j = 0; j < n; j++)
            mx = fmax(mx, T[j] / (e[j + 1] - e[j]));
        ts_histo_options o;
        ts_histo_options_init(&o);
        o.lo = 0.1;
        o.hi = 0.1 + 2.0 * mx + 1.0;
        for (size_t j = 0; j < n; j++)
            T[j] += 0.1 * (e[j + 1] - e[j]);
        if (urand() < 0.5 && mx > 0.0) { /* some bins at the cap itself */
            o.hi = 0.1 + mx;
            int ok = 1;
            for (size_t j = 1; j < n; j++) {
                double p = T[j - 1] / (e[j] - e[j - 1]) - 0.1, q = T[j] / (e[j + 1] - e[j]) - 0.1;
                ok &= fabs(p - q) <= 0.5 * mx;
            }
            if (!ok)
                continue;
        }
        built++;
        check_series(e, T, n, &o, &sb, 16);
    }
    print_stats("bounded", &sb);
    CHECK(built > 0);
    check_stats(&sb);
}

static void closed_forms(void)
{
    TH_CASE("constant data: constant rate");
    {
        double e[5] = {0, 1, 3, 3.5, 7}, T[4];
        for (int j = 0; j < 4; j++)
            T[j] = 2.5 * (e[j + 1] - e[j]);
        ts_histo *h = NULL;
        CHECK(ts_histo_new(e, T, 4, NULL, &h, NULL) == TS_OK);
        for (int k = 0; k <= 70; k++) {
            double r, d;
            ts_histo_eval(h, 0.1 * k, &r, &d);
            CHECK_CLOSE(r, 2.5, 4 * DBL_EPSILON * 2.5);
            CHECK(fabs(d) <= 1e-13);
        }
        double v;
        CHECK(ts_histo_integral(h, 0.5, 6.25, &v) == TS_OK);
        CHECK_CLOSE(v, 2.5 * 5.75, 1e-14 * 15);
        CHECK(ts_histo_integral(h, 6.25, 0.5, &v) == TS_OK);
        CHECK_CLOSE(v, -2.5 * 5.75, 1e-14 * 15);
        CHECK(ts_histo_bins(h) == 4);
        ts_histo_free(h);
    }
    TH_CASE("isolated wet bin between dry ones");
    {
        double e[4] = {0, 1, 2, 3}, T[3] = {0, 24, 0};
        ts_histo *h = NULL;
        CHECK(ts_histo_new(e, T, 3, NULL, &h, NULL) == TS_OK);
        double r, d;
        /* dry bins: r ≡ 0 (their total is 0 and r >= 0) */
        for (int k = 0; k <= 10; k++) {
            ts_histo_eval(h, 0.1 * k, &r, &d);
            CHECK(r == 0.0 && d == 0.0);
            ts_histo_eval(h, 2.0 + 0.1 * k, &r, &d);
            CHECK(r == 0.0 && d == 0.0);
        }
        /* so r = r' = 0 at the wet bin's edges, both sides */
        ts_histo_eval(h, 1.0, &r, &d);
        CHECK(r == 0.0 && d == 0.0);
        ts_histo_eval(h, 2.0, &r, &d);
        CHECK(r == 0.0 && d == 0.0);
        /* the wet bin: its total, symmetric, peak at the middle */
        ts_bin_report rep = {.struct_size = sizeof rep};
        CHECK(ts_histo_report(h, 1, &rep) == TS_OK);
        CHECK_CLOSE(rep.total, 24.0, 1e-14 * 24);
        CHECK_CLOSE(rep.mean, 24.0, 1e-14 * 24);
        CHECK(rep.certified);
        CHECK_CLOSE(rep.at_max, 1.5, 1e-9);
        /* §12.3, (12.3) by hand with zero edge data: Y1 = Y3 = T/(10q),
         * Y2 = 4T/(5q), q = w/4: the peak 3.2 T/w at the middle */
        CHECK_CLOSE(rep.r_max, 76.8, 1e-13 * 77);
        CHECK(rep.r_min == 0.0);
        ts_histo_eval(h, 1.25, &r, &d);
        CHECK_CLOSE(r, 9.6, 1e-13 * 77);
        ts_histo_eval(h, 1.75, &r, &d);
        CHECK_CLOSE(r, 9.6, 1e-13 * 77);
        double a, b;
        ts_histo_eval(h, 1.3, &a, NULL);
        ts_histo_eval(h, 1.7, &b, NULL);
        CHECK_CLOSE(a, b, 1e-14 * 48);
        ts_histo_free(h);
    }
    TH_CASE("bins a few DBL_MIN wide (K subnormal, §12.6)");
    {
        double e[5] = {0, 3e-308, 6e-308, 1e-307, 1.3e-307};
        double T[4] = {1e-300, 5e-300, 2e-300, 0};
        stats st = {0};
        check_series(e, T, 4, NULL, &st, 64);
        print_stats("tiny widths", &st);
        CHECK(st.series == 1 && st.below == 0 && st.uncert == 0);
        CHECKF(st.tot_err <= 1e-13, "%.3g", st.tot_err);
    }
    TH_CASE("the integral of a piece (closed form, §12.2)");
    {
        /* one bin: edge values are the mean, slopes 0: r ≡ mean */
        double e[2] = {10, 14}, T[1] = {8};
        ts_histo *h = NULL;
        CHECK(ts_histo_new(e, T, 1, NULL, &h, NULL) == TS_OK);
        double v;
        ts_histo_integral(h, 10, 14, &v);
        CHECK_CLOSE(v, 8.0, 1e-15 * 8);
        ts_histo_integral(h, 11, 12.5, &v);
        CHECK_CLOSE(v, 3.0, 1e-15 * 8);
        ts_histo_free(h);
    }
}

static void rainfall(void)
{
    TH_CASE("daily rainfall example (data/examples/rainfall_daily.csv)");
    FILE *fp = fopen(TS_SOURCE_DIR "/data/examples/rainfall_daily.csv", "r");
    CHECK(fp != NULL);
    if (!fp)
        return;
    double e[128], T[128];
    size_t n = 0;
    char line[256];
    while (fgets(line, sizeof line, fp) && n < 127) {
        double day, mm;
        if (sscanf(line, "%lf,%lf", &day, &mm) == 2) {
            e[n] = (day - 1.0) * 24.0; /* hours */
            T[n++] = mm;
        }
    }
    fclose(fp);
    CHECK(n == 40);
    e[n] = e[n - 1] + 24.0;
    stats st = {0};
    check_series(e, T, n, NULL, &st, 240);
    print_stats("rainfall", &st);
    check_stats(&st);
}

static void errors(void)
{
    TH_CASE("statuses");
    double e[4] = {0, 1, 2, 3}, T[3] = {1, 2, 3};
    ts_histo *h = (ts_histo *)&e; /* reset to NULL by every call */
    ts_error err;
    CHECK(ts_histo_new(NULL, T, 3, NULL, &h, &err) == TS_ERR_NULL && h == NULL);
    CHECK(err.status == TS_ERR_NULL);
    CHECK(ts_histo_new(e, NULL, 3, NULL, &h, &err) == TS_ERR_NULL);
    CHECK(ts_histo_new(e, T, 3, NULL, NULL, &err) == TS_ERR_NULL);
    ts_histo_options o;
    ts_histo_options_init(&o);
    o.struct_size = 8;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_VERSION);
    ts_histo_options_init(&o);
    CHECK(o.alpha == TS_DEFAULT_ALPHA && o.lo == 0.0 && o.hi == TH_INF);
    CHECK(ts_histo_new(e, T, 0, &o, &h, &err) == TS_ERR_TOO_FEW);
    o.alpha = 0.0;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_ALPHA);
    o.alpha = TH_NAN;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_ALPHA);
    ts_histo_options_init(&o);
    o.hi = 0.0;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_OPTION);
    o.hi = TH_NAN;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_OPTION);
    ts_histo_options_init(&o);
    o.lo = -TH_INF;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_OPTION);
    CHECK(ts_histo_new(e, T, SIZE_MAX / 4, NULL, &h, &err) == TS_ERR_OVERFLOW);
    double eb[4] = {0, 1, TH_NAN, 3};
    CHECK(ts_histo_new(eb, T, 3, NULL, &h, &err) == TS_ERR_NONFINITE);
    CHECK(err.index == 2 && err.where == TS_WHERE_POINT);
    double Tb[3] = {1, TH_INF, 3};
    CHECK(ts_histo_new(e, Tb, 3, NULL, &h, &err) == TS_ERR_NONFINITE);
    CHECK(err.index == 1 && err.where == TS_WHERE_INTERVAL);
    double eu[4] = {0, 1, 1, 3};
    CHECK(ts_histo_new(eu, T, 3, NULL, &h, &err) == TS_ERR_UNSORTED && err.index == 2);
    double ew2[4] = {0, 0x1p-1070, 1, 3}; /* a subnormal width */
    CHECK(ts_histo_new(ew2, T, 3, NULL, &h, &err) == TS_ERR_WIDTH && err.index == 1);
    double et[4] = {-1.7e308, 1.7e308, 1.75e308, 1.78e308}; /* a width overflows */
    CHECK(ts_histo_new(et, T, 3, NULL, &h, &err) == TS_ERR_WIDTH && err.index == 1);
    double Tl[3] = {1, 1e300, 1};
    double el[4] = {0, 1, 1 + 1e-15, 2};
    CHECK(ts_histo_new(el, Tl, 3, NULL, &h, &err) == TS_ERR_TOO_LARGE && err.index == 1);
    /* a mean within the limit whose integral overflows: lo = -1e300 over a
     * width of 1e300 (lo w = -1e600), which ts_histo_check does not build */
    {
        ts_histo_options ol;
        ts_histo_options_init(&ol);
        ol.lo = -1e300;
        double eo[3] = {0, 1, 1e300}, To[2] = {0, 0};
        CHECK(ts_histo_new(eo, To, 2, &ol, &h, &err) == TS_ERR_TOO_LARGE && err.index == 1 &&
              err.where == TS_WHERE_INTERVAL && h == NULL);
        CHECK(ts_histo_check(eo, To, 2, &ol, NULL, NULL) == TS_OK);
    }
    double Tn[3] = {1, -1e-300, 1};
    CHECK(ts_histo_new(e, Tn, 3, NULL, &h, &err) == TS_ERR_NEGATIVE && err.index == 1);
    CHECK(err.where == TS_WHERE_INTERVAL);
    /* bounds: a mean above the cap; below a lower bound; neighbours too far apart */
    ts_histo_options_init(&o);
    o.hi = 2.5;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_INFEASIBLE && err.index == 2);
    ts_status bs[3];
    CHECK(ts_histo_check(e, T, 3, &o, bs, &err) == TS_ERR_INFEASIBLE);
    CHECK(bs[0] == TS_OK && bs[1] == TS_OK && bs[2] == TS_ERR_INFEASIBLE);
    o.hi = 3.0;
    o.lo = 1.5;
    CHECK(ts_histo_new(e, T, 3, &o, &h, &err) == TS_ERR_INFEASIBLE && err.index == 0);
    /* |p − q| > H/2 for the first pair: bins 0 and 1 (the mean 3 = hi fits) */
    double Tc[3] = {0.1, 3, 2};
    ts_histo_options_init(&o);
    o.hi = 3.0;
    CHECK(ts_histo_check(e, Tc, 3, &o, bs, &err) == TS_ERR_INFEASIBLE && err.index == 0);
    CHECK(bs[0] == TS_ERR_INFEASIBLE && bs[1] == TS_ERR_INFEASIBLE && bs[2] == TS_OK);
    CHECK(ts_histo_new(e, Tc, 3, &o, &h, &err) == TS_ERR_INFEASIBLE);
    CHECK(ts_histo_check(e, T, 3, NULL, bs, &err) == TS_OK && bs[2] == TS_OK);
    CHECK(ts_histo_check(NULL, T, 3, NULL, bs, &err) == TS_ERR_NULL);
    CHECK(ts_histo_check(e, T, 0, NULL, bs, &err) == TS_ERR_TOO_FEW);
    ts_histo_options_init(&o);
    o.struct_size = 1;
    CHECK(ts_histo_check(e, T, 3, &o, bs, &err) == TS_ERR_VERSION);
    CHECK(ts_histo_check(e, Tn, 3, NULL, NULL, &err) == TS_ERR_NEGATIVE && err.index == 1);
    CHECK(ts_histo_check(eu, T, 3, NULL, bs, &err) == TS_ERR_UNSORTED);
    CHECK(bs[0] == TS_OK && bs[1] == TS_ERR_UNSORTED && bs[2] == TS_ERR_UNSORTED);

    /* evaluation */
    CHECK(ts_histo_new(e, T, 3, NULL, &h, &err) == TS_OK && err.status == TS_OK);
    double r = 1, d = 1, v = 1;
    CHECK(ts_histo_eval(h, 3.5, &r, &d) == TS_ERR_DOMAIN && isnan(r) && isnan(d));
    CHECK(ts_histo_eval(h, TH_NAN, &r, NULL) == TS_ERR_DOMAIN);
    CHECK(ts_histo_eval(NULL, 1.0, &r, &d) == TS_ERR_NULL && isnan(r));
    CHECK(ts_histo_eval(h, 1.0, NULL, &d) == TS_ERR_NULL && isnan(d));
    CHECK(ts_histo_integral(h, -1.0, 1.0, &v) == TS_ERR_DOMAIN && isnan(v));
    CHECK(ts_histo_integral(h, 0.0, 1.0, NULL) == TS_ERR_NULL);
    CHECK(ts_histo_integral(NULL, 0.0, 1.0, &v) == TS_ERR_NULL);
    double xq[3] = {0.5, 4.0, 1.0}, rq[3], dq[3];
    CHECK(ts_histo_eval_batch(h, xq, 3, rq, dq, &err) == TS_ERR_DOMAIN);
    CHECK(err.index == 1 && err.where == TS_WHERE_QUERY && isnan(rq[2]) && isnan(dq[1]));
    CHECK(ts_histo_eval_batch(h, NULL, 3, rq, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_histo_eval_batch(h, xq, 0, NULL, NULL, &err) == TS_OK);
    xq[1] = 2.0;
    CHECK(ts_histo_eval_batch(h, xq, 3, rq, dq, &err) == TS_OK);
    for (int k = 0; k < 3; k++) {
        double r1, d1;
        ts_histo_eval(h, xq[k], &r1, &d1);
        CHECK(r1 == rq[k] && d1 == dq[k]);
    }
    double g[3] = {0, 2, 1}, out[2];
    CHECK(ts_histo_totals(h, g, 3, out, &err) == TS_ERR_UNSORTED && err.index == 2);
    g[2] = 5;
    CHECK(ts_histo_totals(h, g, 3, out, &err) == TS_ERR_DOMAIN && err.index == 2 && isnan(out[0]));
    CHECK(ts_histo_totals(h, NULL, 3, out, &err) == TS_ERR_NULL);
    CHECK(ts_histo_totals(NULL, g, 3, out, &err) == TS_ERR_NULL);
    CHECK(ts_histo_eval_batch(NULL, xq, 3, rq, dq, &err) == TS_ERR_NULL);
    CHECK(ts_histo_totals(h, g, 1, NULL, &err) == TS_OK);
    g[2] = 3;
    CHECK(ts_histo_totals(h, g, 3, out, &err) == TS_OK);
    CHECK_CLOSE(out[0], 3.0, 1e-14 * 3);
    CHECK_CLOSE(out[1], 3.0, 1e-14 * 3);
    {
        /* repeated points (zero-width cells: total 0, no flag without an
         * upper bound) and more points than one block of the grid path:
         * each cell as ts_histo_integral over it, bit for bit (the same
         * expressions, docs/method.md §12.5) */
        enum { GM = 700 };
        double gg[GM], go[GM - 1];
        for (int k = 0; k < GM; k++)
            gg[k] = 3.0 * (double)(k - k % 3) / (double)(GM - 1);
        gg[GM - 1] = 3.0;
        feclearexcept(FE_ALL_EXCEPT);
        CHECK(ts_histo_totals(h, gg, GM, go, &err) == TS_OK);
        CHECK(ts_histo_integral(h, 1.0, 1.0, &v) == TS_OK && v == 0.0);
        CHECK(!fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW));
        int same = 1;
        for (int k = 0; k + 1 < GM; k++) {
            double iv;
            same &= ts_histo_integral(h, gg[k], gg[k + 1], &iv) == TS_OK && iv == go[k];
            same &= gg[k] != gg[k + 1] || go[k] == 0.0;
        }
        CHECK(same);
    }
    double so[6];
    CHECK(ts_histo_subdivide(h, 0, so, &err) == TS_ERR_OPTION);
    CHECK(ts_histo_subdivide(h, 2, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_histo_subdivide(NULL, 2, so, &err) == TS_ERR_NULL);
    CHECK(ts_histo_subdivide(h, SIZE_MAX / 2, so, &err) == TS_ERR_OVERFLOW);
    CHECK(ts_histo_subdivide(h, 2, so, &err) == TS_OK && err.status == TS_OK);
    CHECK_CLOSE(so[0] + so[1], 1.0, 1e-15);
    CHECK_CLOSE(so[4] + so[5], 3.0, 3e-15);
    CHECK(ts_histo_subdivide(h, 1, so, &err) == TS_OK);
    CHECK_CLOSE(so[0], 1.0, 1e-15);
    CHECK_CLOSE(so[2], 3.0, 3e-15);
    /* reports */
    ts_bin_report rep;
    CHECK(ts_histo_report(h, 0, NULL) == TS_ERR_NULL);
    rep.struct_size = 3;
    rep.total = 7.0;
    CHECK(ts_histo_report(h, 0, &rep) == TS_ERR_VERSION && rep.total == 7.0);
    ts_bin_report_init(&rep);
    CHECK(ts_histo_report(h, 3, &rep) == TS_ERR_INDEX && isnan(rep.total));
    CHECK(ts_histo_report(NULL, 0, &rep) == TS_ERR_NULL);
    CHECK(ts_histo_report(h, 2, &rep) == TS_OK && rep.certified);
    ts_bin_report_init(NULL);
    ts_histo_options_init(NULL);
    ts_histo_free(h);
    ts_histo_free(NULL);
    CHECK(ts_histo_bins(NULL) == 0);
}

int main(void)
{
    long count = 10000;
    const char *env = getenv("TS_HISTO_SERIES");
    if (env)
        count = strtol(env, NULL, 10);
    closed_forms();
    errors();
    rainfall();
    random_series(count);
    return th_report("test_histo");
}
