/* Every value a certified object returns lies in its region, with ZERO
 * tolerance (docs/method.md §7 "Evaluation inside the box", §11.5 "Values
 * inside the region"):
 *  - the end knot of a boxed curve (the data point, exactly, in the box)
 *    where the neighbouring point is 1e17 times larger: formed from the
 *    segment's left end it was fl(B0 + fl(B3 − B0)) = 0, outside y > 0.5;
 *    the same through a closed curve's seam row;
 *  - boxed curves at extreme scale disparities (coordinates log-uniform in
 *    1e-300..1e300 with either sign, boxes whose sides the data touch), open
 *    and closed, 2-D and 3-D, every parameterisation: ts_curve_sample and
 *    ts_curve_eval (knots, random t) inside the closed box (doubles compared
 *    exactly), and every knot equal to its data point;
 *  - surfaces whose data touch their bounds, every form and every scheme
 *    (positive, bounds lower / upper / both, range, constant planes, sloped
 *    planes in the geometric form), grids at offsets up to 1e9 and scales
 *    1e-3..1e6: scalar, batch and grid values on a lattice inside the region
 *    (constant bounds compared exactly; planes strictly, the side decided
 *    exactly, tests/common/th_exact.h);
 *  - surfaces whose nodes lie one to nine ulps beyond a plane (constant in
 *    every form, sloped in the geometric form), where the sums round onto it;
 *  - surfaces whose control values the scheme's a leaves on a sloped plane
 *    by rounding, certified by raising a (docs/method.md §11.6).
 * Each property prints objects, samples and samples outside (which must be
 * 0).  Fixed seeds. */
#include "th.h"
#include "common/th_exact.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <string.h>

typedef struct tally {
    long tried, built, samples, outside, knots_off;
} tally;

static void print_tally(const char *name, const tally *t)
{
    printf("  %-34s objects %5ld certified %5ld samples %8ld outside %ld knots off %ld\n", name,
           t->tried, t->built, t->samples, t->outside, t->knots_off);
}

/* ---- curves -------------------------------------------------------------- */

static int in_box(const ts_curve_options *o, size_t dim, const double *p)
{
    for (size_t k = 0; k < dim; k++)
        if ((o->has_lo[k] && !(p[k] >= o->lo[k])) || (o->has_hi[k] && !(p[k] <= o->hi[k])))
            return 0;
    return 1;
}

static void end_knot_regression(void)
{
    /* the points (0, 2), (1, 1e17), (2, 1), uniform knots t = 0, 1, 2, box
     * -1 < x < 3, 0.5 < y < 2e17 */
    const double P[6] = {0, 2, 1, 1e17, 2, 1};
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.param = TS_PARAM_UNIFORM;
    o.has_lo[0] = o.has_hi[0] = o.has_lo[1] = o.has_hi[1] = 1;
    o.lo[0] = -1;
    o.hi[0] = 3;
    o.lo[1] = 0.5;
    o.hi[1] = 2e17;
    for (int closed = 0; closed < 2; closed++) {
        o.closed = closed;
        ts_curve *c = NULL;
        ts_error e;
        ts_status st = ts_curve_new(P, 3, 2, &o, &c, &e);
        CHECKF(st == TS_OK, "closed %d: %s", closed, ts_strerror(st));
        if (!c)
            continue;
        double out[7 * 3 * 4], p[2];
        size_t rows = 0, segs = ts_curve_segments(c);
        CHECK(ts_curve_sample(c, 5, out, sizeof out / sizeof *out, &rows) == TS_OK &&
              rows == 4 * segs + 1);
        for (size_t r = 0; r < rows; r++)
            CHECKF(in_box(&o, 2, out + 3 * r + 1), "closed %d: row %zu (%.17g, %.17g)", closed,
                   r, out[3 * r + 1], out[3 * r + 2]);
        /* the last row: (2, 1) for the open curve, the seam (0, 2) closed */
        const double *last = out + 3 * (rows - 1) + 1, *want = closed ? P : P + 4;
        CHECKF(last[0] == want[0] && last[1] == want[1], "closed %d: last row (%.17g, %.17g)",
               closed, last[0], last[1]);
        const double *t = ts_curve_knots(c);
        for (size_t i = 0; i <= segs; i++) {
            CHECK(ts_curve_eval(c, t[i], NULL, p, NULL, NULL) == TS_OK);
            const double *w = P + 2 * (i % 3);
            CHECKF(p[0] == w[0] && p[1] == w[1], "closed %d: knot %zu (%.17g, %.17g)", closed, i,
                   p[0], p[1]);
        }
        ts_curve_free(c);
    }
}

/* a coordinate of extreme scale: ±10^e, e uniform in [-300, 300] */
static double wild(th_rng *r)
{
    double v = pow(10.0, th_rng_range(r, -300.0, 300.0)) * th_rng_range(r, 1.0, 10.0);
    return th_rng_chance(r, 0.5) ? -v : v;
}

static void curves_extreme(void)
{
    th_rng r = TH_RNG_INIT(20261206);
    tally t;
    memset(&t, 0, sizeof t);
    enum { NP = 8, M = 33 };
    static double out[(NP + 1) * (M - 1) * 4 + 4];
    for (int rep = 0; rep < 3000; rep++) {
        size_t dim = 2 + th_rng_below(&r, 2), np = 3 + th_rng_below(&r, NP - 2);
        double P[NP * 3];
        for (size_t n = 0; n < np * dim; n++)
            P[n] = th_rng_chance(&r, 0.7) ? wild(&r) : th_rng_range(&r, -10.0, 10.0);
        ts_curve_options o;
        ts_curve_options_init(&o);
        o.closed = th_rng_chance(&r, 0.3);
        o.param = (ts_param)th_rng_below(&r, 3);
        for (size_t k = 0; k < dim; k++) {
            double lo = P[k], hi = P[k];
            for (size_t n = 1; n < np; n++) {
                lo = fmin(lo, P[n * dim + k]);
                hi = fmax(hi, P[n * dim + k]);
            }
            /* the data on a side (touching) or a side beyond them */
            o.has_lo[k] = th_rng_chance(&r, 0.7);
            o.has_hi[k] = th_rng_chance(&r, 0.7);
            o.lo[k] = th_rng_chance(&r, 0.5) ? lo : lo - fabs(lo) * th_rng_range(&r, 0.0, 1.0) - 1.0;
            o.hi[k] = th_rng_chance(&r, 0.5) ? hi : hi + fabs(hi) * th_rng_range(&r, 0.0, 1.0) + 1.0;
        }
        t.tried++;
        ts_curve *c = NULL;
        ts_error e;
        if (ts_curve_new(P, np, dim, &o, &c, &e) != TS_OK)
            continue;
        t.built++;
        size_t rows = 0, segs = ts_curve_segments(c);
        CHECK(ts_curve_sample(c, M, out, sizeof out / sizeof *out, &rows) == TS_OK);
        double ctrl[12];
        for (size_t row = 0; row < rows; row++) {
            const double *p = out + row * (1 + dim) + 1;
            t.samples++;
            if (!in_box(&o, dim, p)) {
                t.outside++;
                CHECKF(t.outside > 5, "sample row %zu of a boxed curve outside its box", row);
            }
            if (row % (M - 1) == 0) { /* a knot: the data point */
                size_t i = row / (M - 1), l = 0;
                if (i == segs) {
                    i = segs - 1;
                    l = 3;
                }
                ts_curve_control(c, i, ctrl);
                for (size_t k = 0; k < dim; k++)
                    if (p[k] != ctrl[l * dim + k]) {
                        t.knots_off++;
                        CHECKF(t.knots_off > 5, "knot row %zu coord %zu: %.17g vs %.17g", row, k,
                               p[k], ctrl[l * dim + k]);
                    }
            }
        }
        const double *kt = ts_curve_knots(c);
        for (int q = 0; q < 16; q++) {
            double tq = q == 0 ? kt[segs] : th_rng_range(&r, kt[0], kt[segs]), p[3];
            if (ts_curve_eval(c, tq, NULL, p, NULL, NULL) != TS_OK)
                continue;
            t.samples++;
            if (!in_box(&o, dim, p)) {
                t.outside++;
                CHECKF(t.outside > 5, "eval at %.17g outside the box", tq);
            }
        }
        ts_curve_free(c);
    }
    print_tally("boxed curves, scales 1e-300..1e300", &t);
    CHECK(t.built > 1000);
    CHECK(t.outside == 0 && t.knots_off == 0);
}

/* ---- surfaces ------------------------------------------------------------ */

typedef struct scase {
    const char *name;
    ts_form form;
    ts_surface_shape shape;
    int has_lo, has_up, sloped;
} scase;

/* z at (x, y) inside the region of o (zmin, zmax: range); zero tolerance */
static int surf_inside(const ts_surface_options *o, double zmin, double zmax, double x, double y,
                       double z)
{
    switch (o->shape) {
    case TS_SURFACE_POSITIVE:
        return z >= 0.0;
    case TS_SURFACE_BOUNDS:
        return (!o->has_lower || z >= o->lower.c) && (!o->has_upper || z <= o->upper.c);
    case TS_SURFACE_RANGE:
        return zmin <= z && z <= zmax;
    case TS_SURFACE_PLANES: {
        int a = o->has_lower ? th_plane_side(z, o->lower.p, o->lower.q, o->lower.c, x, y) : 1;
        int b = o->has_upper ? th_plane_side(z, o->upper.p, o->upper.q, o->upper.c, x, y) : -1;
        return a == 1 && b == -1;
    }
    default:
        return 1;
    }
}

enum { SN = 5, PER = 9, QM = (SN - 1) * (PER - 1) + 1 };

static void surfaces_touching(const scase *sc, th_rng *r)
{
    tally t;
    memset(&t, 0, sizeof t);
    static double xq[QM], yq[QM], bx[QM * QM], by[QM * QM], bz[QM * QM], grid[QM * QM];
    for (int rep = 0; rep < 160; rep++) {
        double x[SN], y[SN], z[SN * SN];
        double off = rep % 4 == 0 ? 0.0 : rep % 4 == 1 ? 1e3 : rep % 4 == 2 ? 1e6 : 1e9;
        double scale = th_rng_logu(r, 1e-3, 1e6);
        x[0] = off;
        y[0] = -off;
        for (int k = 1; k < SN; k++) {
            x[k] = x[k - 1] + scale * (double)(1 + th_rng_below(r, 50));
            y[k] = y[k - 1] + scale * (double)(1 + th_rng_below(r, 50));
        }
        ts_surface_options o;
        ts_surface_options_init(&o);
        o.form = sc->form;
        o.shape = sc->shape;
        o.has_lower = sc->has_lo;
        o.has_upper = sc->has_up;
        double zs = th_rng_logu(r, 1e-3, 1e6);
        o.lower.c = sc->shape == TS_SURFACE_POSITIVE ? 0.0 : -zs * th_rng_range(r, 0.0, 1.0);
        o.upper.c = o.lower.c + zs;
        if (sc->sloped) {
            o.lower.p = o.upper.p = (double)((int)th_rng_below(r, 9) - 4) / 8.0;
            o.lower.q = o.upper.q = (double)((int)th_rng_below(r, 9) - 4) / 8.0;
            o.lower.c -= o.lower.p * off - o.lower.q * off;
            o.upper.c -= o.upper.p * off - o.upper.q * off;
        }
        for (int j = 0; j < SN; j++)
            for (int i = 0; i < SN; i++) {
                double L = o.lower.p * x[i] + o.lower.q * y[j] + o.lower.c;
                double U = o.upper.p * x[i] + o.upper.q * y[j] + o.upper.c;
                double u = th_rng_unit(r), v;
                if (sc->shape == TS_SURFACE_PLANES)
                    v = L + (U - L) * (0.001 + 0.998 * u); /* strictly between */
                else if (u < 0.3 && sc->has_lo)
                    v = L; /* touching */
                else if (u < 0.6 && sc->has_up)
                    v = U;
                else if (sc->has_lo && sc->has_up)
                    v = L + (U - L) * th_rng_unit(r);
                else if (sc->has_lo)
                    v = L + zs * th_rng_unit(r);
                else
                    v = U - zs * th_rng_unit(r);
                z[j * SN + i] = v;
            }
        double zmin = z[0], zmax = z[0];
        for (int n = 0; n < SN * SN; n++) {
            zmin = fmin(zmin, z[n]);
            zmax = fmax(zmax, z[n]);
        }
        t.tried++;
        ts_surface *s = NULL;
        ts_error e;
        if (ts_surface_new(x, SN, y, SN, z, &o, &s, &e) != TS_OK)
            continue;
        CHECK(ts_surface_certified(s));
        t.built++;
        size_t m = 0;
        for (int i = 0; i + 1 < SN; i++)
            for (int a = 0; a + 1 < PER; a++) {
                xq[m] = fmin(x[i] + (x[i + 1] - x[i]) * (a / (double)(PER - 1)), x[i + 1]);
                yq[m] = fmin(y[i] + (y[i + 1] - y[i]) * (a / (double)(PER - 1)), y[i + 1]);
                m++;
            }
        xq[m] = x[SN - 1];
        yq[m] = y[SN - 1];
        m++;
        for (size_t b = 0; b < m; b++)
            for (size_t a = 0; a < m; a++) {
                bx[b * m + a] = xq[a];
                by[b * m + a] = yq[b];
            }
        CHECK(ts_surface_eval_grid(s, xq, m, yq, m, grid, &e) == TS_OK);
        CHECK(ts_surface_eval_batch(s, bx, by, m * m, bz, NULL, NULL, &e) == TS_OK);
        for (size_t n = 0; n < m * m; n++) {
            double v;
            CHECK(ts_surface_eval(s, bx[n], by[n], NULL, &v, NULL, NULL) == TS_OK);
            const double vals[3] = {v, bz[n], grid[n]};
            for (int w = 0; w < 3; w++) {
                t.samples++;
                if (!surf_inside(&o, zmin, zmax, bx[n], by[n], vals[w])) {
                    t.outside++;
                    CHECKF(t.outside > 5, "%s: %s value %.17g at (%.17g, %.17g) outside", sc->name,
                           w == 0 ? "scalar" : w == 1 ? "batch" : "grid", vals[w], bx[n], by[n]);
                }
            }
        }
        ts_surface_free(s);
    }
    print_tally(sc->name, &t);
    CHECKF(t.built >= 30, "%s: %ld of %ld built", sc->name, t.built, t.tried);
    CHECK(t.outside == 0);
}

/* docs/method.md §11.6: a surface refused by its control values at the
 * scheme's a, certified by raising a.  Geometric form, upper plane
 * z = −2^30 x − 18.88 y + 1.001 over x in [−6, −5] (the plane near 6e9),
 * nodes 1e-3..1 below it (log-uniform): the plane's rounding at the control
 * abscissae leaves control values on the plane at a ≈ 1 (210 of 400 such
 * grids were refused, TS_ERR_INFEASIBLE); a ~1000 certifies.  Every grid
 * must be built, pass ts_surface_certify, and sample strictly below. */
static void surfaces_raised_a(void)
{
    th_rng r = TH_RNG_INIT(1000);
    tally t;
    memset(&t, 0, sizeof t);
    long raised = 0;
    const ts_plane up = {-1073741824.0, -18.88, 1.001};
    for (int rep = 0; rep < 100; rep++) {
        double x[5], y[5], z[25];
        for (int k = 0; k < 5; k++) {
            x[k] = -6.0 + 0.25 * k + (rep % 7) * 0.01;
            y[k] = 0.5 * k;
        }
        for (int n = 0; n < 25; n++)
            z[n] = up.p * x[n % 5] + up.q * y[n / 5] + up.c - th_rng_logu(&r, 1e-3, 1.0);
        ts_surface_options o;
        ts_surface_options_init(&o);
        o.form = TS_FORM_GEOMETRIC;
        o.shape = TS_SURFACE_PLANES;
        o.has_upper = 1;
        o.upper = up;
        ts_surface *s = NULL;
        ts_error e;
        t.tried++;
        ts_status st = ts_surface_new(x, 5, y, 5, z, &o, &s, &e);
        CHECKF(st == TS_OK, "grid %d: %s at patch %zu", rep, ts_strerror(st), e.index);
        if (!s)
            continue;
        t.built++;
        CHECK(ts_surface_certify(s, NULL, &up, NULL, &e) == TS_OK);
        double amax = 0.0;
        for (int k = 0; k < 4; k++)
            amax = fmax(amax, fmax(ts_surface_ax(s)[k], ts_surface_ay(s)[k]));
        raised += amax >= 10.0;
        for (int b = 0; b <= 16; b++)
            for (int a = 0; a <= 16; a++) {
                double xv = fmin(x[0] + (x[4] - x[0]) * a / 16.0, x[4]);
                double yv = fmin(y[0] + (y[4] - y[0]) * b / 16.0, y[4]), v;
                CHECK(ts_surface_eval(s, xv, yv, NULL, &v, NULL, NULL) == TS_OK);
                t.samples++;
                if (th_plane_side(v, up.p, up.q, up.c, xv, yv) != -1)
                    t.outside++;
            }
        ts_surface_free(s);
    }
    print_tally("geometric sloped planes, raised a", &t);
    printf("  (%ld of %ld with an a raised tenfold or more)\n", raised, t.built);
    CHECK(raised > 10 && t.outside == 0);
}

/* Nodes one or a few ulps beyond a plane (constant in every form, sloped in
 * the geometric form; lower and upper): the sums Σ A_k Σ A_l B_kl round
 * onto the plane (before: 5–19 of 3721 values per constant case on it),
 * and the returned value must be strictly beyond, decided exactly. */
static void surfaces_ulps_from_plane(void)
{
    tally t;
    memset(&t, 0, sizeof t);
    const double x[4] = {0, 1, 2.5, 3}, y[4] = {0, 0.7, 2, 3};
    static double xq[61], yq[61], bx[61 * 61], by[61 * 61], bz[61 * 61], grid[61 * 61];
    for (int k = 0; k <= 60; k++)
        xq[k] = yq[k] = 3.0 * k / 60.0;
    for (int b = 0; b <= 60; b++)
        for (int a = 0; a <= 60; a++) {
            bx[b * 61 + a] = xq[a];
            by[b * 61 + a] = yq[b];
        }
    for (int form = 0; form < 3; form++)
        for (int sloped = 0; sloped < (form == TS_FORM_GEOMETRIC ? 2 : 1); sloped++)
            for (int side = 0; side < 2; side++) {
                ts_plane pl = {sloped ? 0.5 : 0.0, sloped ? 0.25 : 0.0, 1.0};
                double sg = side ? -1.0 : 1.0, z[16];
                for (int n = 0; n < 16; n++) {
                    /* the first double strictly beyond the plane, then 0 or 8 ulps more */
                    double v = pl.p * x[n % 4] + pl.q * y[n / 4] + pl.c;
                    while (th_plane_side(v, pl.p, pl.q, pl.c, x[n % 4], y[n / 4]) != (int)sg)
                        v = nextafter(v, sg * TH_INF);
                    /* sloped: 256 ulps more (within the plane's rounding
                     * guard at the control abscissae, §11.3, a node one ulp
                     * beyond, or 64, is not provable) */
                    for (int k = 0; k < (n % 3 ? 8 : 0) + (sloped ? 256 : 0); k++)
                        v = nextafter(v, sg * TH_INF);
                    z[n] = v;
                }
                ts_surface_options o;
                ts_surface_options_init(&o);
                o.form = (ts_form)form;
                o.shape = TS_SURFACE_PLANES;
                if (side) {
                    o.has_upper = 1;
                    o.upper = pl;
                } else {
                    o.has_lower = 1;
                    o.lower = pl;
                }
                ts_surface *s = NULL;
                ts_error e;
                t.tried++;
                ts_status st = ts_surface_new(x, 4, y, 4, z, &o, &s, &e);
                CHECKF(st == TS_OK, "form %d sloped %d side %d: %s", form, sloped, side,
                       ts_strerror(st));
                if (!s)
                    continue;
                t.built++;
                CHECK(ts_surface_eval_grid(s, xq, 61, yq, 61, grid, &e) == TS_OK);
                CHECK(ts_surface_eval_batch(s, bx, by, 61 * 61, bz, NULL, NULL, &e) == TS_OK);
                for (int n = 0; n < 61 * 61; n++) {
                    double v;
                    CHECK(ts_surface_eval(s, bx[n], by[n], NULL, &v, NULL, NULL) == TS_OK);
                    const double vals[3] = {v, bz[n], grid[n]};
                    for (int w = 0; w < 3; w++) {
                        t.samples++;
                        if (th_plane_side(vals[w], pl.p, pl.q, pl.c, bx[n], by[n]) != (int)sg) {
                            t.outside++;
                            CHECKF(t.outside > 5, "form %d sloped %d side %d: %.17g at (%g, %g)",
                                   form, sloped, side, vals[w], bx[n], by[n]);
                        }
                    }
                }
                ts_surface_free(s);
            }
    print_tally("planes, nodes ulps beyond them", &t);
    CHECK(t.built == t.tried && t.outside == 0);
}

int main(void)
{
    TH_CASE("end knot of a boxed curve, scale 1e17");
    end_knot_regression();
    TH_CASE("boxed curves at extreme scale disparities");
    curves_extreme();
    static const scase cases[] = {
        {"paper positive", TS_FORM_PAPER, TS_SURFACE_POSITIVE, 1, 0, 0},
        {"paper bounds lower", TS_FORM_PAPER, TS_SURFACE_BOUNDS, 1, 0, 0},
        {"paper bounds upper", TS_FORM_PAPER, TS_SURFACE_BOUNDS, 0, 1, 0},
        {"paper bounds both", TS_FORM_PAPER, TS_SURFACE_BOUNDS, 1, 1, 0},
        {"paper range", TS_FORM_PAPER, TS_SURFACE_RANGE, 1, 1, 0},
        {"paper planes", TS_FORM_PAPER, TS_SURFACE_PLANES, 1, 1, 0},
        {"C1 positive", TS_FORM_C1, TS_SURFACE_POSITIVE, 1, 0, 0},
        {"C1 bounds lower", TS_FORM_C1, TS_SURFACE_BOUNDS, 1, 0, 0},
        {"C1 bounds upper", TS_FORM_C1, TS_SURFACE_BOUNDS, 0, 1, 0},
        {"C1 bounds both", TS_FORM_C1, TS_SURFACE_BOUNDS, 1, 1, 0},
        {"C1 range", TS_FORM_C1, TS_SURFACE_RANGE, 1, 1, 0},
        {"C1 planes", TS_FORM_C1, TS_SURFACE_PLANES, 1, 1, 0},
        {"geometric positive", TS_FORM_GEOMETRIC, TS_SURFACE_POSITIVE, 1, 0, 0},
        {"geometric bounds lower", TS_FORM_GEOMETRIC, TS_SURFACE_BOUNDS, 1, 0, 0},
        {"geometric bounds upper", TS_FORM_GEOMETRIC, TS_SURFACE_BOUNDS, 0, 1, 0},
        {"geometric bounds both", TS_FORM_GEOMETRIC, TS_SURFACE_BOUNDS, 1, 1, 0},
        {"geometric range", TS_FORM_GEOMETRIC, TS_SURFACE_RANGE, 1, 1, 0},
        {"geometric planes", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 1, 0},
        {"geometric sloped planes lower", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 0, 1},
        {"geometric sloped planes upper", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 0, 1, 1},
        {"geometric sloped planes between", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 1, 1},
    };
    TH_CASE("nodes ulps beyond a plane");
    surfaces_ulps_from_plane();
    TH_CASE("surfaces certified by raising a");
    surfaces_raised_a();
    th_rng r = TH_RNG_INIT(33);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        TH_CASE(cases[c].name);
        surfaces_touching(&cases[c], &r);
    }
    return th_report("test_region_samples");
}
