/* Seeded property test of the shape schemes (SPEC §5), paper and C¹ forms.
 *
 * For each scheme (positive with zeros, above, below, between, monotone) and
 * form, TS_PROP_SETS random data sets (10,000 in a normal build): non-uniform
 * x over several decades of spacing, values over several orders of
 * magnitude, near-boundary points, steep and flat runs, n from 1 to 200,
 * alpha log-uniform in [1e-4, 10] (scalar or per interval), margins default
 * or random, arithmetic-mean or random user slopes.  Asserts:
 *  - the build succeeds (or, for lines, reports TS_ERR_INFEASIBLE, whose
 *    claim is checked: the limit curve of that interval is not inside, and
 *    in the paper form no a on a grid from alpha to 1e6·alpha is);
 *  - certified; every certificate > 0 (>= 0 at a zero knot of positive data);
 *  - 64 samples per interval (ts_eval_batch) inside the region and never
 *    below the certificate by more than rounding; the certificate within
 *    the sampling bound of the sampled minimum; monotone data give monotone
 *    samples;
 *  - knots interpolated.
 * Negative control: the same data with TS_SHAPE_NONE and a small alpha
 * (beta = 0) leave the region in a sizeable share of sets (asserted, so this
 * test could fail), and ts_certify reports VIOLATED whenever a sample is
 * outside (it never certifies a curve that leaves).
 *
 * Seed: fixed (TS_PROP_SEED); each set is reproducible from (scheme, form, k).
 */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
#define TS_PROP_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TS_PROP_ASAN 1
#endif
#endif
#ifdef TS_PROP_ASAN
#define TS_PROP_SETS 1000 /* sanitizer build: 10x slower, fewer sets */
#else
#define TS_PROP_SETS 10000
#endif
#define TS_PROP_SEED 0x5eed2026u
#define NMAX 200
#define SAMPLES 64

#define EPS DBL_EPSILON
static const double PI = 3.14159265358979323846;
static const double HALF_PI = 1.57079632679489661923;

static unsigned long long rs;
static void seed(unsigned scheme, unsigned form, unsigned k)
{
    rs = ((unsigned long long)TS_PROP_SEED << 32) ^ ((unsigned long long)scheme << 24) ^
         ((unsigned long long)form << 20) ^ (unsigned long long)k;
    rs = rs * 0x9E3779B97F4A7C15ULL + 1;
    if (!rs)
        rs = 1;
}
static double urand(void)
{
    rs ^= rs >> 12;
    rs ^= rs << 25;
    rs ^= rs >> 27;
    return (double)((rs * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
}
static double uni(double a, double b) { return a + (b - a) * urand(); }
static double logu(double a, double b) { return exp(uni(log(a), log(b))); }
static int chance(double p) { return urand() < p; }

static double line_at(const ts_line *l, double x) { return l->m * x + l->c; }

typedef struct dataset {
    size_t n;
    double x[NMAX + 1], f[NMAX + 1], us[NMAX + 1];
    double alphas[NMAX], margins[NMAX];
    ts_options o;
} dataset;

/* a "profile" in (0, 1]: mostly order-one, with near-zero points, steep
 * jumps and flat runs; scaled by 10^[-3, 3] factors */
static void profile(size_t np, double *p, int allow_zero, double p_near)
{
    double v = logu(1e-3, 1e3);
    for (size_t i = 0; i < np; i++) {
        double r = urand();
        if (i > 0 && r < 0.15) {
            v = p[i - 1]; /* flat run */
        } else if (r < 0.30) {
            v = logu(1e-3, 1e3); /* steep jump */
        } else if (r < 0.30 + p_near) {
            v = logu(1e-12, 1e-6); /* near the boundary */
        } else if (allow_zero && r < 0.40 + p_near) {
            v = 0.0;
        } else if (i > 0) {
            v = fabs(p[i - 1] == 0 ? logu(1e-3, 1) : p[i - 1] * logu(0.3, 3));
        }
        p[i] = v;
    }
}

static double hmax(const dataset *D, size_t i)
{
    double a = i > 0 ? D->x[i] - D->x[i - 1] : 0, b = i < D->n ? D->x[i + 1] - D->x[i] : 0;
    return a > b ? a : b;
}

static void gen(dataset *D, int scheme, int form)
{
    ts_options *o = &D->o;
    ts_options_init(o);
    o->form = (ts_form)form;
    o->shape = (ts_shape)scheme;
    double r = urand();
    size_t n = r < 0.08 ? 1 : r < 0.85 ? (size_t)uni(2, 17) : (size_t)uni(17, NMAX + 1);
    if (n > NMAX)
        n = NMAX;
    D->n = n;
    size_t np = n + 1;
    /* x: offset and spacing scale over many decades, non-uniform steps */
    double H = logu(1e-3, 1e3);
    D->x[0] = uni(-1e3, 1e3) * (chance(0.5) ? 1.0 : H);
    for (size_t i = 1; i < np; i++)
        D->x[i] = D->x[i - 1] + H * logu(1e-2, 1e1);
    double p[NMAX + 1];
    double V = logu(1e-4, 1e4);
    switch (scheme) {
    case TS_SHAPE_POSITIVE:
        profile(np, p, 1, 0.1);
        for (size_t i = 0; i < np; i++)
            D->f[i] = V * p[i];
        break;
    case TS_SHAPE_ABOVE:
    case TS_SHAPE_BELOW: {
        ts_line L;
        double xspan = D->x[n] - D->x[0];
        L.m = chance(0.3) ? 0.0 : (chance(0.5) ? 1 : -1) * V / xspan * logu(1e-3, 1e2);
        L.c = uni(-1, 1) * V * 10 - L.m * D->x[0];
        /* near-boundary points next to a sloped line are infeasible in the
         * paper form whenever |m| h >> gap (SPEC §5): fewer of them there */
        profile(np, p, 0, L.m == 0 ? 0.1 : 0.005);
        for (size_t i = 0; i < np; i++) {
            double g = V * p[i];
            /* mostly keep the gap at least a fraction of |m| h: otherwise
             * the paper form cannot follow the line (SPEC §5, the limit
             * curve misses a line by up to 0.105 |m| h) */
            if (chance(0.9))
                g += fabs(L.m) * hmax(D, i) * logu(0.15, 3);
            D->f[i] = scheme == TS_SHAPE_ABOVE ? line_at(&L, D->x[i]) + g : line_at(&L, D->x[i]) - g;
            /* rounding could put a tiny gap on the line: keep it a gap */
            double gg = scheme == TS_SHAPE_ABOVE ? D->f[i] - line_at(&L, D->x[i])
                                                 : line_at(&L, D->x[i]) - D->f[i];
            if (!(gg > 0))
                D->f[i] += (scheme == TS_SHAPE_ABOVE ? 1 : -1) * (fabs(line_at(&L, D->x[i])) * 1e-12 + 1e-300);
        }
        if (scheme == TS_SHAPE_ABOVE)
            o->lower = L;
        else
            o->upper = L;
        break;
    }
    case TS_SHAPE_BETWEEN: {
        ts_line L, U;
        double xspan = D->x[n] - D->x[0];
        L.m = chance(0.3) ? 0.0 : (chance(0.5) ? 1 : -1) * V / xspan * logu(1e-3, 1e1);
        L.c = uni(-1, 1) * V * 10 - L.m * D->x[0];
        /* band width positive at both ends, so at every data point */
        double w0 = V * logu(1e-1, 1e1), w1 = chance(0.3) ? w0 : V * logu(1e-1, 1e1);
        U.m = L.m + (w1 - w0) / xspan;
        U.c = line_at(&L, D->x[0]) + w0 - U.m * D->x[0];
        profile(np, p, 0, L.m == 0 && U.m == 0 ? 0.1 : 0.005);
        for (size_t i = 0; i < np; i++) {
            double lo = line_at(&L, D->x[i]), up = line_at(&U, D->x[i]), w = up - lo;
            double q = p[i] / (1 + p[i]); /* in (0, 1), some very near 0 */
            if (chance(L.m == 0 && U.m == 0 ? 0.1 : 0.005))
                q = 1 - q * 1e-6; /* near the upper line */
            /* as for one line: mostly a gap of a fraction of |m| h to each */
            double gl = fabs(L.m) * hmax(D, i) * 0.15, gu = fabs(U.m) * hmax(D, i) * 0.15;
            if (chance(0.85) && gl + gu < w) {
                double qa = gl / w, qb = 1 - gu / w;
                q = qa + (qb - qa) * q;
            }
            double f = lo + w * q;
            if (!(f > lo && f < up))
                f = lo + 0.5 * w;
            D->f[i] = f;
        }
        o->lower = L;
        o->upper = U;
        break;
    }
    default: { /* monotone */
        int dir = chance(0.5) ? 1 : -1;
        profile(np, p, 1, 0.1);
        D->f[0] = uni(-1, 1) * V;
        for (size_t i = 1; i < np; i++)
            D->f[i] = D->f[i - 1] + dir * V * (chance(0.2) ? 0.0 : p[i]);
        break;
    }
    }
    /* alpha log-uniform in [1e-4, 10], scalar or per interval */
    if (chance(0.5)) {
        o->alpha = logu(1e-4, 10);
    } else {
        for (size_t i = 0; i < n; i++)
            D->alphas[i] = logu(1e-4, 10);
        o->alphas = D->alphas;
        o->n_alphas = n;
    }
    if (chance(0.3)) {
        for (size_t i = 0; i < n; i++)
            D->margins[i] = logu(1e-6, 1);
        o->margins = D->margins;
        o->n_margins = n;
    }
    /* user slopes sometimes: random, sign-valid at zero knots */
    if (chance(0.25)) {
        double sc = V / H;
        for (size_t i = 0; i < np; i++) {
            double d = uni(-3, 3) * sc * logu(1e-2, 1e2);
            if (scheme == TS_SHAPE_POSITIVE && D->f[i] == 0)
                d = i == 0 ? fabs(d) : i == n ? -fabs(d) : 0.0;
            D->us[i] = d;
        }
        o->slopes = TS_SLOPES_USER;
        o->user_slopes = D->us;
        o->n_user_slopes = np;
    }
}

/* control values of a paper-form interval at a (for the infeasibility check) */
static double curve_min(const double B[4], double x0, double h, const ts_line *L, int sign, int M)
{
    double mn = INFINITY;
    for (int j = 0; j <= M; j++) {
        double th = HALF_PI * j / M, s = sin(th), c = cos(th);
        double A0 = (1 - s) * (1 - s) * (1 - s), A1 = 3 * s - 4 * s * s + s * s * s;
        double A2 = 3 * c - 4 * c * c + c * c * c, A3 = (1 - c) * (1 - c) * (1 - c);
        double y = A0 * B[0] + A1 * B[1] + A2 * B[2] + A3 * B[3];
        double g = sign * (y - line_at(L, x0 + h * j / M));
        mn = g < mn ? g : mn;
    }
    return mn;
}

static double scale_of(const double B[4], const ts_line *L, double x0, double x1)
{
    double sc = fabs(L->c) + fabs(L->m) * (fabs(x0) + fabs(x1));
    for (int l = 0; l < 4; l++)
        sc = fabs(B[l]) > sc ? fabs(B[l]) : sc;
    return sc;
}

typedef struct stats {
    long ok, infeasible, sets, control_violate, control_sets, repaired;
} stats;

static double xq[NMAX * SAMPLES + 1], yq[NMAX * SAMPLES + 1];

static int fill_queries(const ts_spline *s)
{
    size_t n = ts_spline_intervals(s);
    const double *x = ts_spline_x(s);
    int m = 0;
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < SAMPLES; j++)
            xq[m++] = x[i] + (x[i + 1] - x[i]) * j / SAMPLES;
    xq[m++] = x[n];
    return m;
}

/* check one certified spline; returns the number of failed checks */
static long check_spline(const ts_spline *s, const dataset *D, int scheme, stats *st)
{
    long fails0 = th_fail_;
    size_t n = D->n;
    const double *x = D->x, *f = D->f;
    CHECK(ts_spline_certified(s) == 1);
    int m = fill_queries(s);
    ts_cursor cur = TS_CURSOR_INIT;
    CHECK(ts_eval_batch(s, 0, xq, (size_t)m, yq, &cur, NULL) == TS_OK);
    for (size_t i = 0; i < n; i++) {
        ts_interval_report r;
        CHECK(ts_spline_report(s, i, &r) == TS_OK);
        CHECK(r.certified == 1);
        st->repaired += r.term == TS_TERM_CERTIFY;
        const double *ys = yq + i * SAMPLES;
        const double *xs = xq + i * SAMPLES;
        /* knots: θ = 0 exactly at x_i, so S = B0 = f_i up to the batch
         * kernel's 8 ε·M (fast.c); at x_n, θ = h·((π/2)/h) is off π/2 by
         * ≤ 3 ε·π/2 and |dS/dθ| ≤ 3(|D0|+|D1|+|D2|) ≤ 18 M (SPEC (2.1)):
         * 8 εM + 16 εM (ts_eval) + 85 εM < 128 ε·M */
        double bsc = 0;
        for (int l = 0; l < 4; l++)
            bsc = fabs(r.B[l]) > bsc ? fabs(r.B[l]) : bsc;
        CHECK(fabs(ys[0] - f[i]) <= 8 * EPS * bsc);
        if (i + 1 == n)
            CHECK(fabs(yq[m - 1] - f[n]) <= 128 * EPS * bsc);
        if (scheme == TS_SHAPE_MONOTONE) {
            /* B lies between f_i and f_{i+1}: M = max(|f_i|, |f_{i+1}|);
             * evaluation 24 εM (ts_eval + batch), θ rounding of each
             * sample moves S along the curve (not off it), so monotonicity
             * needs only the value rounding */
            double tol = 24 * EPS * (fabs(f[i]) + fabs(f[i + 1]));
            int dir = (f[i + 1] > f[i]) - (f[i + 1] < f[i]);
            double lo = f[i] < f[i + 1] ? f[i] : f[i + 1], hi = f[i] + f[i + 1] - lo;
            int bad = 0;
            for (int j = 0; j <= SAMPLES; j++) {
                double y = ys[j];
                if (y < lo - tol || y > hi + tol)
                    bad++;
                if (j && dir * (y - ys[j - 1]) < -tol)
                    bad++;
            }
            CHECKF(bad == 0, "monotone interval %zu: %d bad samples", i, bad);
            continue;
        }
        for (int side = 0; side < 2; side++) {
            if (!(side == 0 ? r.has_lower : r.has_upper))
                continue;
            ts_line ln = scheme == TS_SHAPE_POSITIVE ? (ts_line){0, 0}
                         : side == 0                 ? D->o.lower
                                                     : D->o.upper;
            int sign = side == 0 ? 1 : -1;
            double gap = side == 0 ? r.gap_lower : r.gap_upper;
            int zero_end = scheme == TS_SHAPE_POSITIVE && !(f[i] > 0 && f[i + 1] > 0);
            CHECKF(gap > 0 || (zero_end && gap >= 0), "interval %zu: certificate %.17g", i, gap);
            /* te = 256 ε·sc: certificate rounding (its guard, typically
             * ≤ 64 ε·sc) + S at a sample (ts_eval 16 εM, batch 8 εM more)
             * + the rounding of θ = (x − x_i)(π/2)/h (≤ 3 ε relative) times
             * |dS/dθ| ≤ 18 M, ≤ 86 εM, against L evaluated at x itself;
             * ts = ½|g''|(Δ/2)², the sampling bound (test_shape.c) */
            double sc = scale_of(r.B, &ln, x[i], x[i + 1]);
            double te = 256 * EPS * sc;
            double L0 = line_at(&ln, x[i]), C[4];
            for (int l = 0; l < 4; l++)
                C[l] = r.B[l] - L0;
            double Dt = HALF_PI / SAMPLES;
            double ts = 0.5 * (8 * fabs(C[1] - C[0]) + 8 * fabs(C[2] - C[0]) + 6 * fabs(C[3] - C[0])) *
                        (Dt / 2) * (Dt / 2);
            double mn = INFINITY;
            for (int j = 0; j <= SAMPLES; j++) {
                double g = sign * (ys[j] - line_at(&ln, xs[j]));
                mn = g < mn ? g : mn;
            }
            /* inside, and never below the certificate */
            CHECKF((zero_end ? mn >= -te : mn > -te) && mn >= gap - te && mn <= gap + ts + te,
                   "interval %zu side %d: sampled min %.17g certificate %.17g te %.3g ts %.3g", i,
                   side, mn, gap, te, ts);
        }
    }
    return th_fail_ - fails0;
}

/* TS_ERR_INFEASIBLE on interval j: check what it claims */
static void check_infeasible(const dataset *D, size_t j, int form)
{
    double d[NMAX + 1];
    if (D->o.slopes == TS_SLOPES_USER)
        memcpy(d, D->us, (D->n + 1) * sizeof *d);
    else
        ts_slopes_compute(TS_SLOPES_ARITHMETIC, D->x, D->f, D->n + 1, d, NULL);
    double x0 = D->x[j], h = D->x[j + 1] - x0, al = D->o.alphas ? D->alphas[j] : D->o.alpha;
    double K = 2 * h / (3 * PI);
    const ts_line *lines[2] = {D->o.shape != TS_SHAPE_BELOW ? &D->o.lower : NULL,
                               D->o.shape != TS_SHAPE_ABOVE ? &D->o.upper : NULL};
    /* limit a -> ∞ not inside (within rounding and sampling) */
    double Bl[4] = {D->f[j], D->f[j], D->f[j + 1], D->f[j + 1]};
    double worst = INFINITY;
    for (int k = 0; k < 2; k++) {
        if (!lines[k])
            continue;
        double sc = scale_of(Bl, lines[k], x0, D->x[j + 1]);
        double v = curve_min(Bl, x0, h, lines[k], k ? -1 : 1, 256) - 1e-4 * sc;
        worst = v < worst ? v : worst;
    }
    CHECKF(worst <= 0, "infeasible interval %zu: limit is inside by %.3g", j, worst);
    if (form != TS_FORM_PAPER)
        return;
    /* paper form: no a on a grid in [alpha, 1e6 alpha] is inside */
    int any = 0;
    for (double a = al; a <= 1e6 * al && !any; a *= 1.25) {
        double B[4] = {D->f[j], D->f[j] + K * d[j] / a, D->f[j + 1] - K * d[j + 1] / a, D->f[j + 1]};
        double mn = INFINITY;
        for (int k = 0; k < 2; k++) {
            if (!lines[k])
                continue;
            double v = curve_min(B, x0, h, lines[k], k ? -1 : 1, 256);
            double sc = scale_of(B, lines[k], x0, D->x[j + 1]);
            v -= 1e-4 * sc; /* sampled min exceeds the true one by ≤ ½|g''|(Δ/2)², well below this */
            mn = v < mn ? v : mn;
        }
        if (mn > 0)
            any = 1;
    }
    CHECKF(!any, "infeasible interval %zu: some a in [alpha, 1e6 alpha] is inside", j);
}

/* negative control: same data, no scheme, small alpha */
static void control(const dataset *D, int scheme, stats *st)
{
    ts_options o = D->o;
    o.shape = TS_SHAPE_NONE;
    o.alphas = NULL;
    o.margins = NULL;
    o.alpha = logu(1e-4, 0.05);
    o.beta = 0;
    ts_spline *s = NULL;
    if (ts_spline_new(D->x, D->f, D->n + 1, &o, &s, NULL) != TS_OK) {
        CHECK(0);
        return;
    }
    st->control_sets++;
    int m = fill_queries(s);
    ts_eval_batch(s, 0, xq, (size_t)m, yq, NULL, NULL);
    size_t first_out = TS_NO_INDEX;
    for (size_t i = 0; i < D->n && first_out == TS_NO_INDEX; i++) {
        const double *ys = yq + i * SAMPLES, *xs = xq + i * SAMPLES;
        double B[4];
        ts_spline_control(s, i, B, NULL);
        for (int j = 0; j <= SAMPLES && first_out == TS_NO_INDEX; j++) {
            if (scheme == TS_SHAPE_MONOTONE) {
                int dir = (D->f[i + 1] > D->f[i]) - (D->f[i + 1] < D->f[i]);
                double tol = 24 * EPS * (fabs(D->f[i]) + fabs(D->f[i + 1]));
                if (j && (dir * (ys[j] - ys[j - 1]) < -tol - 1e-9 * fabs(D->f[i + 1] - D->f[i]) ||
                          (dir == 0 && fabs(ys[j] - D->f[i]) > tol + 1e-9 * fabs(D->f[i]))))
                    first_out = i;
                continue;
            }
            for (int k = 0; k < 2; k++) {
                ts_line ln;
                if (scheme == TS_SHAPE_POSITIVE) {
                    if (k)
                        continue;
                    ln.m = ln.c = 0;
                } else if (k == 0) {
                    if (scheme == TS_SHAPE_BELOW)
                        continue;
                    ln = D->o.lower;
                } else {
                    if (scheme == TS_SHAPE_ABOVE)
                        continue;
                    ln = D->o.upper;
                }
                double te = 256 * EPS * scale_of(B, &ln, D->x[i], D->x[i + 1]);
                double g = (k ? -1 : 1) * (ys[j] - line_at(&ln, xs[j]));
                if (g < -te)
                    first_out = i;
            }
        }
    }
    if (first_out != TS_NO_INDEX) {
        st->control_violate++;
        if (scheme != TS_SHAPE_MONOTONE) {
            /* ts_certify must not certify a curve that leaves */
            ts_line zero = {0, 0};
            const ts_line *lo = scheme == TS_SHAPE_POSITIVE ? &zero
                                : scheme == TS_SHAPE_BELOW  ? NULL
                                                            : &D->o.lower;
            const ts_line *up = scheme == TS_SHAPE_ABOVE || scheme == TS_SHAPE_POSITIVE ? NULL
                                                                                        : &D->o.upper;
            ts_error e;
            CHECK(ts_certify(s, lo, up, NULL, &e) == TS_ERR_VIOLATED && e.index <= first_out);
        }
    }
    ts_spline_free(s);
}

static const char *names[] = {"none", "positive", "above", "below", "between", "monotone"};

int main(void)
{
    static dataset D;
    for (int scheme = TS_SHAPE_POSITIVE; scheme <= TS_SHAPE_MONOTONE; scheme++) {
        for (int form = 0; form < 2; form++) {
            stats st = {0, 0, 0, 0, 0, 0};
            long fail0 = th_fail_;
            for (unsigned k = 0; k < TS_PROP_SETS; k++) {
                seed((unsigned)scheme, (unsigned)form, k);
                gen(&D, scheme, form);
                st.sets++;
                ts_spline *s = NULL;
                ts_error e;
                ts_status rc = ts_spline_new(D.x, D.f, D.n + 1, &D.o, &s, &e);
                long before = th_fail_;
                int lines = scheme >= TS_SHAPE_ABOVE && scheme <= TS_SHAPE_BETWEEN;
                if (rc == TS_OK) {
                    st.ok++;
                    check_spline(s, &D, scheme, &st);
                } else if (rc == TS_ERR_INFEASIBLE && lines) {
                    st.infeasible++;
                    CHECK(e.where == TS_WHERE_INTERVAL && e.index < D.n);
                    if (e.index < D.n)
                        check_infeasible(&D, e.index, form);
                } else {
                    CHECKF(0, "status %d index %zu", rc, e.index);
                }
                ts_spline_free(s);
                control(&D, scheme, &st);
                if (th_fail_ > before && th_fail_ - fail0 < 20)
                    fprintf(stderr, "  ^ scheme %s form %d set %u (n = %zu)\n", names[scheme], form, k,
                            D.n);
            }
            printf("%-8s form %d: %ld sets, %ld certified (%ld intervals repaired), %ld infeasible; "
                   "control: %ld of %ld leave the region\n",
                   names[scheme], form, st.sets, st.ok, st.repaired, st.infeasible,
                   st.control_violate, st.control_sets);
            /* the certified path is the common one */
            CHECKF(st.ok >= st.sets * 6 / 10, "%s form %d: only %ld of %ld certified", names[scheme],
                   form, st.ok, st.sets);
            /* negative control: a meaningful share violates (could fail) */
            CHECKF(st.control_violate >= st.control_sets / 5, "%s form %d: control %ld of %ld",
                   names[scheme], form, st.control_violate, st.control_sets);
        }
    }
    return th_report("test_property");
}
