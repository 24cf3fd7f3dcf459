/* Surfaces on gridded data (docs/method.md §11).
 *
 *  - property: seeded random spiky grids (sizes 2×2 to 64×64 in three size
 *    classes, zeros and nodes on the bounds included, non-uniform spacing),
 *    every form and scheme: built (certified) or refused with a reason that
 *    is checked; dense samples on a fine grid (>= 1e6 per size class) never
 *    outside the region; nodes interpolated exactly; continuity of the value
 *    across every inner grid line, and of both partials in the C¹ and
 *    geometric forms.
 *  - certificate: the proven bound of ts_surface_report against an
 *    independent minimum: the gap Σ A_k(θ)A_l(φ)G_kl rebuilt in long double
 *    from the reported control values (basis of docs/method.md §2 written
 *    out here), a 48×48 grid in (θ, φ) refined by coordinate-wise golden
 *    section.  proven <= reference + 1e-12·scale (it is a bound) and >=
 *    reference − 2e-9·scale (the stated tolerance 1e-9·scale plus the
 *    rounding guard, §11.4).
 *  - transposition symmetry to 1e-12 relative; exact planes (geometric form);
 *    integrals against a plane's closed form and a tensor Gauss–Legendre
 *    rule of the library's own evaluation; grid = pointwise evaluation;
 *    partials against central differences; every error path.
 * Without the scheme (TS_SURFACE_NONE) the same spiky data go negative in a
 * sizeable share of grids (asserted: the test can fail). */
#include "th.h"
#include "trigspline.h"

#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double urand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

typedef struct grid {
    size_t nx, ny; /* points */
    double x[64], y[64], z[64 * 64];
} grid;

/* spiky: u^6 scaled, 15% zeros, a few at the top value */
static void make_grid(grid *g, size_t nx, size_t ny, double top)
{
    g->nx = nx;
    g->ny = ny;
    g->x[0] = urand();
    g->y[0] = -urand();
    for (size_t i = 1; i < nx; i++)
        g->x[i] = g->x[i - 1] + 0.1 + 2.0 * urand();
    for (size_t j = 1; j < ny; j++)
        g->y[j] = g->y[j - 1] + 0.1 + 2.0 * urand();
    for (size_t n = 0; n < nx * ny; n++) {
        double u = urand();
        g->z[n] = u < 0.15 ? 0.0 : (u > 0.97 ? top : top * pow(urand(), 6.0));
    }
}

/* ---- independent reference of a patch minimum --------------------------- */
static void basis_ld(long double th, long double A[4])
{
    long double s = sinl(th), c = cosl(th);
    A[0] = (1 - s) * (1 - s) * (1 - s);
    A[1] = s * (1 - s) * (3 - s);
    A[2] = c * (1 - c) * (3 - c);
    A[3] = (1 - c) * (1 - c) * (1 - c);
}
static long double gap_ld(const long double G[16], long double th, long double ph)
{
    long double A[4], B[4], v = 0;
    basis_ld(th, A);
    basis_ld(ph, B);
    for (int k = 0; k < 4; k++)
        for (int l = 0; l < 4; l++)
            v += A[k] * B[l] * G[4 * k + l];
    return v;
}
#define REF_STEP 96
/* compass search from (th, ph): 8 directions, step halved when none improves */
static long double compass(const long double G[16], long double th, long double ph)
{
    const long double top = (long double)TH_HALF_PI;
    long double f = gap_ld(G, th, ph), step = top / REF_STEP;
    static const int dir[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    while (step > 1e-14L) {
        int moved = 0;
        for (int d = 0; d < 8; d++) {
            long double a = fminl(top, fmaxl(0, th + dir[d][0] * step));
            long double b = fminl(top, fmaxl(0, ph + dir[d][1] * step));
            long double v = gap_ld(G, a, b);
            if (v < f) {
                f = v, th = a, ph = b, moved = 1;
                break;
            }
        }
        if (!moved)
            step *= 0.5L;
    }
    return f;
}
/* the least of a 97×97 grid in (θ, φ), each of the 10 best points refined.
 * The grid is clustered at the patch's edges (Chebyshev points): there
 * minima can sit in dips narrower than a uniform grid's spacing (one seen
 * 0.0016 from an edge, 0.003 wide). */
#define REF_N 96
#define REF_STARTS 10
static long double ref_node(int a)
{
    return (long double)TH_HALF_PI * 0.5L * (1.0L - cosl(3.14159265358979323846264L * a / REF_N));
}
static double ref_min(const long double G[16])
{
    static long double A[REF_N + 1][4];
    static int init;
    if (!init) {
        for (int a = 0; a <= REF_N; a++)
            basis_ld(ref_node(a), A[a]);
        init = 1;
    }
    long double bv[REF_STARTS], bt[REF_STARTS], bp[REF_STARTS];
    for (int k = 0; k < REF_STARTS; k++)
        bv[k] = (long double)INFINITY, bt[k] = bp[k] = 0;
    for (int a = 0; a <= REF_N; a++) {
        long double C[4];
        for (int l = 0; l < 4; l++)
            C[l] = A[a][0] * G[l] + A[a][1] * G[4 + l] + A[a][2] * G[8 + l] + A[a][3] * G[12 + l];
        for (int b = 0; b <= REF_N; b++) {
            long double v = A[b][0] * C[0] + A[b][1] * C[1] + A[b][2] * C[2] + A[b][3] * C[3];
            int w = 0;
            for (int k = 1; k < REF_STARTS; k++)
                w = bv[k] > bv[w] ? k : w;
            if (v < bv[w])
                bv[w] = v, bt[w] = ref_node(a), bp[w] = ref_node(b);
        }
    }
    long double best = (long double)INFINITY;
    for (int k = 0; k < REF_STARTS; k++)
        best = fminl(best, compass(G, bt[k], bp[k]));
    return (double)best;
}

/* ---- checks of one built surface ----------------------------------------- */
typedef struct bounds {
    int lo, hi;
    ts_plane L, U;
} bounds;

static long n_samples[3], n_outside[3], n_certs, n_fail_none;

static double plane(const ts_plane *p, double x, double y)
{
    return p->p * x + p->q * y + p->c;
}

static void check_surface(const ts_surface *s, const grid *g, const bounds *bd, int cls,
                          ts_form form, int want_certs, size_t samples)
{
    size_t nx = g->nx - 1, ny = g->ny - 1;
    /* nodes exactly */
    int exact = 1;
    ts_surface_cursor cur = TS_SURFACE_CURSOR_INIT;
    for (size_t n = 0; n < g->nx * g->ny; n++) {
        double v;
        ts_surface_eval(s, g->x[n % g->nx], g->y[n / g->nx], &cur, &v, NULL, NULL);
        exact &= v == g->z[n];
    }
    CHECK(exact);
    /* dense samples: m per patch side */
    size_t m = 2;
    while ((m + 1) * (m + 1) * nx * ny <= samples)
        m++;
    size_t mx = nx * m + 1, my = ny * m + 1;
    double *xq = malloc(mx * sizeof *xq), *yq = malloc(my * sizeof *yq);
    double *out = malloc(mx * my * sizeof *out);
    for (size_t i = 0; i < nx; i++)
        for (size_t a = 0; a < m; a++)
            xq[i * m + a] = g->x[i] + (g->x[i + 1] - g->x[i]) * ((double)a + urand()) / (double)m;
    xq[0] = g->x[0];
    xq[mx - 1] = g->x[nx];
    for (size_t j = 0; j < ny; j++)
        for (size_t b = 0; b < m; b++)
            yq[j * m + b] = g->y[j] + (g->y[j + 1] - g->y[j]) * ((double)b + urand()) / (double)m;
    yq[0] = g->y[0];
    yq[my - 1] = g->y[ny];
    CHECK(ts_surface_eval_grid(s, xq, mx, yq, my, out, NULL) == TS_OK);
    long outside = 0;
    for (size_t b = 0; b < my; b++)
        for (size_t a = 0; a < mx; a++) {
            double v = out[b * mx + a];
            /* evaluation rounding: a convex combination formed in floating
             * point is within ~8ε of the bound's size; 0 is exact (all terms >= 0) */
            if (bd->lo) {
                double L = plane(&bd->L, xq[a], yq[b]);
                if (!(v >= L - 1e-13 * (fabs(L) + 1e-300)))
                    outside++;
            }
            if (bd->hi) {
                double U = plane(&bd->U, xq[a], yq[b]);
                if (!(v <= U + 1e-13 * fabs(U)))
                    outside++;
            }
        }
    n_samples[cls] += (long)(mx * my);
    n_outside[cls] += outside;
    CHECKF(outside == 0, "%ld samples outside (form %d)", outside, (int)form);
    /* one pointwise sample agrees with the grid */
    {
        size_t a = mx / 3, b = my / 2;
        double v;
        ts_surface_eval(s, xq[a], yq[b], NULL, &v, NULL, NULL);
        CHECK_CLOSE(v, out[b * mx + a], 1e-13 * (fabs(v) + 1.0));
    }
    /* continuity across inner grid lines */
    double zmax = 1.0;
    for (size_t n = 0; n < g->nx * g->ny; n++)
        zmax = fmax(zmax, fabs(g->z[n]));
    int cont = 1, c1 = 1;
    /* C¹ is checked one ulp from the line; in the geometric form a huge a
     * (a node gap tiny against its slopes) makes the derivative turn within
     * ~κ²h of the knot (κ = 2/(3πa)): an ulp moves it by ~1e-15/κ²
     * relative, so lines next to a > 100 (1e-10 relative) are skipped */
    const double *ax = ts_surface_ax(s), *ay = ts_surface_ay(s);
    for (size_t i = 1; i < nx; i++) {
        int tense = form == TS_FORM_GEOMETRIC && (ax[i - 1] > 100 || ax[i] > 100);
        double yv = g->y[0] + (g->y[ny] - g->y[0]) * urand(), xl = nextafter(g->x[i], -1e300);
        double v0, v1, d0, d1, e0, e1;
        ts_surface_eval(s, g->x[i], yv, NULL, &v0, &d0, &e0);
        ts_surface_eval(s, xl, yv, NULL, &v1, &d1, &e1);
        /* one ulp of x times the slope, plus rounding */
        cont &= fabs(v0 - v1) <= 1e-12 * zmax + fabs(d0) * 4e-16 * fabs(g->x[i]) + 1e-300;
        if (form != TS_FORM_PAPER && !tense)
            c1 &= fabs(d0 - d1) <= 1e-7 * (fabs(d0) + zmax) && fabs(e0 - e1) <= 1e-7 * (fabs(e0) + zmax);
    }
    for (size_t j = 1; j < ny; j++) {
        int tense = form == TS_FORM_GEOMETRIC && (ay[j - 1] > 100 || ay[j] > 100);
        double xv = g->x[0] + (g->x[nx] - g->x[0]) * urand(), yl = nextafter(g->y[j], -1e300);
        double v0, v1, d0, d1, e0, e1;
        ts_surface_eval(s, xv, g->y[j], NULL, &v0, &d0, &e0);
        ts_surface_eval(s, xv, yl, NULL, &v1, &d1, &e1);
        cont &= fabs(v0 - v1) <= 1e-12 * zmax + fabs(e0) * 4e-16 * fabs(g->y[j]) + 1e-300;
        if (form != TS_FORM_PAPER && !tense)
            c1 &= fabs(d0 - d1) <= 1e-7 * (fabs(d0) + zmax) && fabs(e0 - e1) <= 1e-7 * (fabs(e0) + zmax);
    }
    CHECK(cont);
    CHECKF(c1, "C1 form %d nx %zu ny %zu", (int)form, nx, ny);
    /* certificates of a few patches against the independent minimum */
    for (int t = 0; t < want_certs && (bd->lo || bd->hi); t++) {
        size_t i = (size_t)(urand() * (double)nx), j = (size_t)(urand() * (double)ny);
        ts_patch_report r = TS_PATCH_REPORT_INIT;
        CHECK(ts_surface_report(s, i, j, &r) == TS_OK);
        CHECK(r.certified == 1);
        for (int side = 0; side < 2; side++) {
            if (!(side ? r.has_upper : r.has_lower))
                continue;
            const ts_plane *P = side ? &bd->U : &bd->L;
            double X[4], Y[4], B[16];
            ts_surface_control(s, i, j, B, X, Y);
            long double G[16];
            double scale = 0;
            for (int k = 0; k < 16; k++) {
                /* geometric form: (11.3); else the bounds are constants */
                long double Lv = (long double)P->p * (long double)X[k / 4] +
                                 (long double)P->q * (long double)Y[k % 4] + (long double)P->c;
                if (form != TS_FORM_GEOMETRIC)
                    Lv = (long double)P->c;
                G[k] = side ? Lv - (long double)B[k] : (long double)B[k] - Lv;
                scale = fmax(scale, fabs((double)G[k]));
            }
            double ref = ref_min(G);
            double proven = side ? r.proven_upper : r.proven_lower;
            double sampled = side ? r.sampled_upper : r.sampled_lower;
            CHECKF(proven <= ref + 1e-12 * scale, "proven %.17g ref %.17g", proven, ref);
            CHECKF(proven >= ref - 2e-9 * scale, "form %d side %d patch %zu %zu proven %.17g ref %.17g scale %g", (int)form, side, i, j, proven, ref,
                   scale);
            CHECKF(sampled >= ref - 1e-12 * scale && sampled <= ref + 2e-9 * scale,
                   "sampled %.17g ref %.17g", sampled, ref);
            /* the place of the sampled minimum carries that value */
            const double *at = side ? r.at_upper : r.at_lower;
            double v;
            CHECK(ts_surface_eval(s, at[0], at[1], NULL, &v, NULL, NULL) == TS_OK);
            double gv = side ? plane(P, at[0], at[1]) - v : v - plane(P, at[0], at[1]);
            CHECK_CLOSE(gv, sampled, 1e-9 * scale + 1e-12 * zmax);
            n_certs++;
        }
    }
    free(xq);
    free(yq);
    free(out);
}

static void test_property(void)
{
    TH_CASE("property");
    const size_t lo_sz[3] = {2, 5, 17}, hi_sz[3] = {4, 16, 64};
    const int count[3] = {TH_ASAN ? 150 : 600, TH_ASAN ? 60 : 300, TH_ASAN ? 12 : 100};
    const size_t samples[3] = {600, 3000, 20000};
    long grids = 0, none_neg = 0;
    for (int cls = 0; cls < 3; cls++) {
        for (int gi = 0; gi < count[cls]; gi++) {
            grid g;
            size_t span = hi_sz[cls] - lo_sz[cls] + 1;
            size_t nx = lo_sz[cls] + (size_t)(urand() * (double)span);
            size_t ny = lo_sz[cls] + (size_t)(urand() * (double)span);
            make_grid(&g, nx, ny, 100.0);
            grids++;
            for (int form = 0; form < 3; form++) {
                for (int sh = 0; sh <= TS_SURFACE_RANGE; sh++) {
                    ts_surface_options o;
                    ts_surface_options_init(&o);
                    o.form = (ts_form)form;
                    o.shape = (ts_surface_shape)sh;
                    o.zero_twist = gi % 5 == 4;
                    o.slopes = (ts_slopes)(gi % 6); /* every estimating method */
                    o.alpha = gi % 3 == 0 ? 0.05 + urand() : 1.0;
                    o.beta = form == 2 ? 0.4 : 0.0; /* NONE: the geometric bound on a */
                    bounds bd = {0, 0, {0, 0, 0}, {0, 0, 0}};
                    if (sh == TS_SURFACE_POSITIVE)
                        bd.lo = 1;
                    if (sh == TS_SURFACE_BOUNDS) { /* percentages */
                        o.has_lower = o.has_upper = 1;
                        o.lower.c = 0.0;
                        o.upper.c = 100.0;
                        bd.lo = bd.hi = 1;
                        bd.U.c = 100.0;
                    }
                    if (sh == TS_SURFACE_RANGE) {
                        double mn = 1e300, mxv = -1e300;
                        for (size_t n = 0; n < nx * ny; n++)
                            mn = fmin(mn, g.z[n]), mxv = fmax(mxv, g.z[n]);
                        bd.lo = bd.hi = 1;
                        bd.L.c = mn;
                        bd.U.c = mxv;
                    }
                    if (sh == TS_SURFACE_PLANES) { /* sloped in the geometric form */
                        double P = form == 2 ? 3.0 * (urand() - 0.5) : 0.0;
                        double Q = form == 2 ? 3.0 * (urand() - 0.5) : 0.0;
                        double cl = 1e300, cu = -1e300;
                        for (size_t n = 0; n < nx * ny; n++) {
                            double w = g.z[n] - P * g.x[n % nx] - Q * g.y[n / nx];
                            cl = fmin(cl, w);
                            cu = fmax(cu, w);
                        }
                        ts_plane L = {P, Q, cl - 0.5 - 5.0 * urand()};
                        ts_plane U = {-P, Q, 0};
                        /* upper: above every node by 1..6 */
                        double cu2 = -1e300;
                        for (size_t n = 0; n < nx * ny; n++)
                            cu2 = fmax(cu2, g.z[n] + P * g.x[n % nx] - Q * g.y[n / nx]);
                        U.c = cu2 + 1.0 + 5.0 * urand();
                        (void)cu;
                        o.has_lower = o.has_upper = 1;
                        o.lower = L;
                        o.upper = U;
                        bd.lo = bd.hi = 1;
                        bd.L = L;
                        bd.U = U;
                    }
                    ts_surface *s = NULL;
                    ts_error e;
                    ts_status st = ts_surface_new(g.x, nx, g.y, ny, g.z, &o, &s, &e);
                    CHECKF(st == TS_OK, "%s (form %d shape %d node %zu)", ts_strerror(st), form,
                           sh, e.index);
                    if (st != TS_OK)
                        continue;
                    CHECK(ts_surface_certified(s) == (sh != TS_SURFACE_NONE));
                    if (sh == TS_SURFACE_NONE) {
                        /* the unconstrained surface with a small a goes negative */
                        ts_surface_free(s);
                        o.alpha = 0.1;
                        o.beta = form == 2 ? 0.3 : 0.0;
                        ts_surface_new(g.x, nx, g.y, ny, g.z, &o, &s, NULL);
                        double mn = 0;
                        ts_surface_cursor c = TS_SURFACE_CURSOR_INIT;
                        for (size_t a = 0; a < 40; a++)
                            for (size_t b = 0; b < 40; b++) {
                                double v, xv = g.x[0] + (g.x[nx - 1] - g.x[0]) * urand(),
                                          yv = g.y[0] + (g.y[ny - 1] - g.y[0]) * urand();
                                ts_surface_eval(s, xv, yv, &c, &v, NULL, NULL);
                                mn = fmin(mn, v);
                            }
                        none_neg += mn < 0;
                        ts_patch_report r = TS_PATCH_REPORT_INIT;
                        ts_surface_report(s, 0, 0, &r);
                        CHECK(r.certified == 0 && r.has_lower == 0 && isnan(r.proven_lower));
                        ts_surface_free(s);
                        continue;
                    }
                    check_surface(s, &g, &bd, cls, (ts_form)form, gi % 4 == 0, samples[cls]);
                    ts_surface_free(s);
                }
            }
        }
    }
    /* the negative control: most spiky grids need the scheme */
    CHECKF(none_neg * 2 > grids * 3, "%ld of %ld unconstrained fits went negative", none_neg,
           3 * grids);
    n_fail_none = none_neg;
    for (int cls = 0; cls < 3; cls++) {
        if (!TH_ASAN)
            CHECKF(n_samples[cls] >= 1000000, "class %d: %ld samples", cls, n_samples[cls]);
        printf("size class %d: %ld dense samples, %ld outside\n", cls, n_samples[cls],
               n_outside[cls]);
    }
    printf("grids %ld, certificates compared %ld, unconstrained negative %ld of %ld\n", grids,
           n_certs, none_neg, 3 * grids);
}

/* ---- symmetry, planes, integrals, derivatives ------------------------------ */
static void test_transpose(void)
{
    TH_CASE("transpose");
    for (int rep = 0; rep < 40; rep++) {
        grid g, t;
        size_t nx = 2 + (size_t)(urand() * 9), ny = 2 + (size_t)(urand() * 9);
        make_grid(&g, nx, ny, 10.0);
        t.nx = ny;
        t.ny = nx;
        memcpy(t.x, g.y, ny * sizeof(double));
        memcpy(t.y, g.x, nx * sizeof(double));
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < nx; i++)
                t.z[i * ny + j] = g.z[j * nx + i];
        ts_surface_options o;
        ts_surface_options_init(&o);
        o.form = (ts_form)(rep % 3);
        o.shape = (ts_surface_shape)(rep % 5 == 3 ? 1 : rep % 5);
        o.slopes = (ts_slopes)(rep % 6);
        o.has_lower = 1;
        o.lower.c = 0.0;
        ts_surface *a = NULL, *b = NULL;
        CHECK(ts_surface_new(g.x, nx, g.y, ny, g.z, &o, &a, NULL) == TS_OK);
        CHECK(ts_surface_new(t.x, ny, t.y, nx, t.z, &o, &b, NULL) == TS_OK);
        double worst = 0, zmax = 1e-300;
        for (int k = 0; k < 400; k++) {
            double xv = g.x[0] + (g.x[nx - 1] - g.x[0]) * urand();
            double yv = g.y[0] + (g.y[ny - 1] - g.y[0]) * urand();
            double v1, v2, dx1, dy1, dx2, dy2;
            ts_surface_eval(a, xv, yv, NULL, &v1, &dx1, &dy1);
            ts_surface_eval(b, yv, xv, NULL, &v2, &dx2, &dy2);
            worst = fmax(worst, fabs(v1 - v2) + 0 * fabs(dx1 - dy2));
            zmax = fmax(zmax, fabs(v1));
        }
        CHECKF(worst <= 1e-12 * zmax, "rep %d: %g of %g", rep, worst, zmax);
        ts_surface_free(a);
        ts_surface_free(b);
    }
}

static void test_plane_and_integral(void)
{
    TH_CASE("plane, integral, partials");
    double x[5] = {0, 0.3, 1.1, 1.5, 3}, y[4] = {-1, 0, 0.25, 2}, z[20];
    const double P = 0.7, Q = -1.3, C = 2.0;
    for (size_t n = 0; n < 20; n++)
        z[n] = P * x[n % 5] + Q * y[n / 5] + C;
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    ts_surface *s = NULL;
    CHECK(ts_surface_new(x, 5, y, 4, z, &o, &s, NULL) == TS_OK);
    double worst = 0, wd = 0;
    for (int k = 0; k < 500; k++) {
        double xv = 3 * urand(), yv = -1 + 3 * urand(), v, dx, dy;
        ts_surface_eval(s, xv, yv, NULL, &v, &dx, &dy);
        worst = fmax(worst, fabs(v - (P * xv + Q * yv + C)));
        wd = fmax(wd, fabs(dx - P) + fabs(dy - Q));
    }
    /* planes are exact (§11.2); tolerance: rounding of the solve and sums */
    CHECKF(worst <= 1e-13, "plane error %g", worst);
    CHECKF(wd <= 1e-12, "plane slope error %g", wd);
    /* integral of the plane: closed form */
    double I;
    CHECK(ts_surface_integral(s, 0.1, 2.9, -0.5, 1.7, &I) == TS_OK);
    double exact = (2.8 * 2.2) * C + P * 2.2 * (2.9 * 2.9 - 0.01) / 2 + Q * 2.8 * (1.7 * 1.7 - 0.25) / 2;
    CHECK_CLOSE(I, exact, 1e-13 * fabs(exact));
    double Ir;
    CHECK(ts_surface_integral(s, 2.9, 0.1, -0.5, 1.7, &Ir) == TS_OK);
    CHECK(Ir == -I);
    CHECK(ts_surface_integral(s, 0.1, 2.9, 1.7, -0.5, &Ir) == TS_OK);
    CHECK(Ir == -I);
    ts_surface_free(s);

    /* every form on spiky data: the integral against a tensor Gauss–Legendre
     * rule (20 points per patch side) of the surface's own values; the
     * rule is exact to ~1e-14 for these smooth patch functions */
    static const double gx[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195,
                                  0.5108670019508271, 0.6360536807265150, 0.7463319064601508,
                                  0.8391169718222188, 0.9122344282513259, 0.9639719272779138,
                                  0.9931285991850949};
    static const double gw[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820,
                                  0.1316886384491766, 0.1181945319615184, 0.1019301198172404,
                                  0.0832767415767048, 0.0626720483341091, 0.0406014298003869,
                                  0.0176140071391521};
    for (int form = 0; form < 3; form++) {
        grid g;
        make_grid(&g, 4, 3, 5.0);
        ts_surface_options_init(&o);
        o.form = (ts_form)form;
        /* geometric form: a = 1 (no scheme), so that θ(x) has no
         * near-singularity at the knots (X̂'(0) = 3κ) and a Gauss rule in x
         * converges; larger a are covered by the plane above */
        o.shape = form == 2 ? TS_SURFACE_NONE : TS_SURFACE_POSITIVE;
        CHECK(ts_surface_new(g.x, 4, g.y, 3, g.z, &o, &s, NULL) == TS_OK);
        double xa = g.x[0] + 0.3 * (g.x[1] - g.x[0]), xb = g.x[3] - 0.2 * (g.x[3] - g.x[2]);
        double ya = g.y[0] + 0.5 * (g.y[1] - g.y[0]), yb = g.y[2];
        CHECK(ts_surface_integral(s, xa, xb, ya, yb, &I) == TS_OK);
        double ref = 0;
        double ex[4] = {xa, g.x[1], g.x[2], xb}, ey[3] = {ya, g.y[1], yb};
        for (int pi = 0; pi < 3; pi++)
            for (int pj = 0; pj < 2; pj++) {
                double cx = 0.5 * (ex[pi] + ex[pi + 1]), hx = 0.5 * (ex[pi + 1] - ex[pi]);
                double cy = 0.5 * (ey[pj] + ey[pj + 1]), hy = 0.5 * (ey[pj + 1] - ey[pj]);
                for (int a = 0; a < 20; a++)
                    for (int b = 0; b < 20; b++) {
                        double u = a < 10 ? -gx[a] : gx[a - 10], wu = gw[a % 10];
                        double v = b < 10 ? -gx[b] : gx[b - 10], wv = gw[b % 10];
                        double val;
                        ts_surface_eval(s, cx + hx * u, cy + hy * v, NULL, &val, NULL, NULL);
                        ref += wu * wv * hx * hy * val;
                    }
            }
        CHECKF(fabs(I - ref) <= 1e-10 * fabs(ref), "form %d: %.17g vs %.17g", form, I, ref);
        /* partials against central differences (h = 1e-6: error ~1e-9) */
        double wdx = 0;
        for (int k = 0; k < 200; k++) {
            double xv = g.x[0] + 1e-5 + (g.x[3] - g.x[0] - 2e-5) * urand();
            double yv = g.y[0] + 1e-5 + (g.y[2] - g.y[0] - 2e-5) * urand();
            double v, dx, dy, a1, a2, b1, b2;
            ts_surface_eval(s, xv, yv, NULL, &v, &dx, &dy);
            ts_surface_eval(s, xv + 1e-6, yv, NULL, &a1, NULL, NULL);
            ts_surface_eval(s, xv - 1e-6, yv, NULL, &a2, NULL, NULL);
            ts_surface_eval(s, xv, yv + 1e-6, NULL, &b1, NULL, NULL);
            ts_surface_eval(s, xv, yv - 1e-6, NULL, &b2, NULL, NULL);
            /* skip samples straddling a grid line (the paper form's jump) */
            int near = 0;
            for (int i = 0; i < 4; i++)
                near |= fabs(xv - g.x[i]) < 2e-6;
            for (int j = 0; j < 3; j++)
                near |= fabs(yv - g.y[j]) < 2e-6;
            if (!near)
                wdx = fmax(wdx, fabs(dx - (a1 - a2) / 2e-6) + fabs(dy - (b1 - b2) / 2e-6));
        }
        CHECKF(wdx <= 1e-5 * 5.0 * 50, "form %d: partial error %g", form, wdx);
        /* batch = pointwise, with partials */
        double xq[3] = {g.x[0], 0.5 * (g.x[0] + g.x[3]), g.x[3]}, yq[3] = {g.y[2], g.y[1], g.y[0]};
        double zq[3], zx[3], zy[3];
        CHECK(ts_surface_eval_batch(s, xq, yq, 3, zq, zx, zy, NULL) == TS_OK);
        for (int k = 0; k < 3; k++) {
            double v, dx, dy;
            ts_surface_eval(s, xq[k], yq[k], NULL, &v, &dx, &dy);
            CHECK(v == zq[k] && dx == zx[k] && dy == zy[k]);
        }
        ts_surface_free(s);
    }
}

/* ---- accessors and errors ------------------------------------------------- */
static void test_errors(void)
{
    TH_CASE("errors");
    double x[3] = {0, 1, 2}, y[3] = {0, 1, 3}, z[9] = {1, 2, 3, 4, 0, 6, 7, 8, 9};
    ts_surface *s = (ts_surface *)1;
    ts_error e;
    ts_surface_options o;
    ts_surface_options_init(NULL);
    CHECK(ts_surface_new(NULL, 3, y, 3, z, NULL, &s, &e) == TS_ERR_NULL && s == NULL);
    CHECK(ts_surface_new(x, 3, NULL, 3, z, NULL, &s, NULL) == TS_ERR_NULL);
    CHECK(ts_surface_new(x, 3, y, 3, NULL, NULL, &s, NULL) == TS_ERR_NULL);
    CHECK(ts_surface_new(x, 3, y, 3, z, NULL, NULL, NULL) == TS_ERR_NULL);
    CHECK(ts_surface_new(x, 1, y, 3, z, NULL, &s, NULL) == TS_ERR_TOO_FEW);
    CHECK(ts_surface_new(x, 3, y, 1, z, NULL, &s, NULL) == TS_ERR_TOO_FEW);
#define OPT_IS(field, value, status)                                                        \
    do {                                                                                    \
        ts_surface_options_init(&o);                                                        \
        field = value;                                                                      \
        CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == status && s == NULL);            \
    } while (0)
    OPT_IS(o.form, (ts_form)3, TS_ERR_OPTION);
    OPT_IS(o.slopes, (ts_slopes)TS_SLOPES_COUNT_, TS_ERR_OPTION);
    OPT_IS(o.slopes, TS_SLOPES_USER, TS_ERR_OPTION);
    OPT_IS(o.slopes, TS_SLOPES_PERIODIC, TS_ERR_OPTION);
    OPT_IS(o.shape, (ts_surface_shape)5, TS_ERR_OPTION);
    OPT_IS(o.shape, TS_SURFACE_BOUNDS, TS_ERR_OPTION);
    OPT_IS(o.shape, TS_SURFACE_PLANES, TS_ERR_OPTION);
    OPT_IS(o.alpha, 0.0, TS_ERR_ALPHA);
    OPT_IS(o.alpha, TH_INF, TS_ERR_ALPHA);
    OPT_IS(o.beta, -1.0, TS_ERR_BETA);
    OPT_IS(o.beta, TH_NAN, TS_ERR_BETA);
    OPT_IS(o.beta, TH_INF, TS_ERR_BETA);
    OPT_IS(o.margin, 0.0, TS_ERR_MARGIN);
    OPT_IS(o.margin, TH_INF, TS_ERR_MARGIN);
    ts_surface_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.alpha = 0.3;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_GEOMETRIC);
    /* sloped planes outside the geometric form; upper only; lower only */
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_PLANES;
    o.has_upper = 1;
    o.upper.q = 1.0;
    o.upper.c = 100;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_OPTION);
    o.has_upper = 0;
    o.has_lower = 1;
    o.lower.p = 1.0;
    o.lower.c = -100;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_OPTION);
    o.lower.p = 0.0;
    o.lower.c = TH_NAN;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_NONFINITE);
    o.lower.c = 0.0;
    o.lower.q = TH_INF;
    o.form = TS_FORM_GEOMETRIC;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_NONFINITE);
    o.lower.q = 0.0;
    o.lower.p = TH_NAN;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_NONFINITE);
    o.lower.p = 0.0;
    o.has_upper = 1;
    o.upper.p = 0;
    o.upper.q = TH_NAN;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_NONFINITE);
    /* a node on the lower plane (node (1, 1), z = 0); lines crossing */
    o.upper.q = 0;
    o.upper.c = 100;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_SIDE && e.index == 4 &&
          e.where == TS_WHERE_POINT);
    o.lower.c = -1;
    o.upper.p = -60; /* upper at (2, 0) = -20: below lower... at node 2 */
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_LINES && e.index == 2);
    o.upper.p = 0;
    o.upper.c = 8.5; /* node (2, 2) = 9 above */
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_SIDE && e.index == 8);
    /* bounds */
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_BOUNDS;
    o.has_lower = o.has_upper = 1;
    o.lower.c = 5;
    o.upper.c = 5;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_LINES);
    o.lower.c = 0.5;
    o.upper.c = 100;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_SIDE && e.index == 4);
    o.lower.c = 0;
    o.upper.c = 8;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_SIDE && e.index == 8);
    o.has_lower = 0;
    o.upper.c = 9; /* touching from below only */
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_OK);
    ts_surface_free(s);
    o.has_lower = 1;
    o.has_upper = 0;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_OK);
    ts_surface_free(s);
    /* positive: negative node named */
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_POSITIVE;
    double zn[9] = {1, 2, 3, 4, 5, 6, 7, -8, 9};
    CHECK(ts_surface_new(x, 3, y, 3, zn, &o, &s, &e) == TS_ERR_NEGATIVE && e.index == 7);
    /* non-finite and unsorted, named */
    double xb[3] = {0, TH_NAN, 2}, yb[3] = {0, 1, 1};
    CHECK(ts_surface_new(xb, 3, y, 3, z, NULL, &s, &e) == TS_ERR_NONFINITE && e.index == 1);
    CHECK(ts_surface_new(x, 3, yb, 3, z, NULL, &s, &e) == TS_ERR_UNSORTED && e.index == 2);
    /* both faults on one axis: every non-finite knot first, then the order
     * (as ts_spline_new and ts_slopes_compute name them) */
    double xm[3] = {1, 0, TH_NAN};
    CHECK(ts_surface_new(xm, 3, y, 3, z, NULL, &s, &e) == TS_ERR_NONFINITE && e.index == 2 &&
          e.where == TS_WHERE_POINT);
    ts_spline *sp_m = NULL;
    CHECK(ts_spline_new(xm, y, 3, NULL, &sp_m, &e) == TS_ERR_NONFINITE && e.index == 2 && !sp_m);
    double zi[9] = {1, 2, 3, 4, 5, TH_INF, 7, 8, 9};
    CHECK(ts_surface_new(x, 3, y, 3, zi, NULL, &s, &e) == TS_ERR_NONFINITE && e.index == 5);
    /* slopes that overflow (huge values over a tiny width): node named */
    double xt[3] = {0, 1e-300, 1}, zh[9] = {0, 1e300, 0, 0, 0, 0, 0, 0, 0};
    CHECK(ts_surface_new(xt, 3, y, 3, zh, NULL, &s, &e) == TS_ERR_NONFINITE &&
          e.where == TS_WHERE_POINT);
    double zv[9] = {0, 0, 0, 0, 1e300, 0, 0, 1e300, 0}, yt[3] = {0, 1e-300, 1};
    CHECK(ts_surface_new(x, 3, yt, 3, zv, NULL, &s, &e) == TS_ERR_NONFINITE);
    /* the twist overflows (finite slopes, ~z/(hx hy)): node named */
    double zw[9] = {0, 0, 0, 0, 1e150, 0, 0, 0, 0};
    double xw[3] = {0, 1e-100, 2e-100}, yw[3] = {0, 1e-100, 2e-100};
    ts_status st = ts_surface_new(xw, 3, yw, 3, zw, NULL, &s, &e);
    CHECK(st == TS_ERR_NONFINITE && e.where == TS_WHERE_POINT);
    /* control values that overflow: zero twist, large slopes, tiny a */
    ts_surface_options_init(&o);
    o.zero_twist = 1;
    o.alpha = 1e-300;
    double zc[9] = {0, 1e300, 0, 1e300, 0, 1e300, 0, 1e300, 0};
    CHECK(ts_surface_new(x, 3, y, 3, zc, &o, &s, &e) == TS_ERR_NONFINITE &&
          e.where == TS_WHERE_INTERVAL);
    /* infeasible by rounding: a node 1 ulp above a plane of size 1e16 */
    ts_surface_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SURFACE_PLANES;
    o.has_lower = 1;
    o.lower.p = 1.0;
    o.lower.c = 1e16;
    double zp[9];
    for (int n = 0; n < 9; n++)
        zp[n] = 1e16 + x[n % 3] + 2.0 + (n == 4 ? 0.0 : 1e3);
    st = ts_surface_new(x, 3, y, 3, zp, &o, &s, &e);
    CHECKF(st == TS_ERR_INFEASIBLE && e.where == TS_WHERE_INTERVAL, "%s", ts_strerror(st));
    /* a gap near the underflow threshold against a slope: a beyond 1e300,
     * along x (patch (1, 0)) and along y (the transposed data: patch (0, 1)) */
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_POSITIVE;
    double zu[9] = {4, 1e-310, 1, 4, 1, 1, 4, 1, 1}, zut[9] = {4, 4, 4, 1e-310, 1, 1, 1, 1, 1};
    CHECK(ts_surface_new(x, 3, x, 3, zu, &o, &s, &e) == TS_ERR_INFEASIBLE && e.index == 1 &&
          e.where == TS_WHERE_INTERVAL);
    CHECK(ts_surface_new(x, 3, x, 3, zut, &o, &s, &e) == TS_ERR_INFEASIBLE && e.index == 2);
    /* the same on the last row (the patch below it is named) */
    double zl[9] = {4, 4, 4, 1, 1, 1, 4, 1e-310, 1};
    CHECK(ts_surface_new(x, 3, x, 3, zl, &o, &s, &e) == TS_ERR_INFEASIBLE && e.index == 3);
    /* and on the last column (zl transposed: along y, the patch left of it) */
    double zlt[9] = {4, 1, 4, 4, 1, 1e-310, 4, 1, 1};
    CHECK(ts_surface_new(x, 3, x, 3, zlt, &o, &s, &e) == TS_ERR_INFEASIBLE && e.index == 3);
    /* two refusals along y on interval 0: column 2 rises from the tiny
     * node (2, 0) (slope < 0 at its lower end) and column 0 through the
     * tiny node (0, 1) (slope > 0 at the interval's upper end); the rows
     * are flat to within the tiny values, so nothing along x.  The least
     * line is named: patch (0, 0), not (1, 0) */
    double zt[9] = {0, 0, 1e-310, 1e-310, 0, 0, 10, 10, 10};
    CHECK(ts_surface_new(x, 3, x, 3, zt, &o, &s, &e) == TS_ERR_INFEASIBLE && e.index == 0);
    /* planes: lower only, upper only (valid) */
    ts_surface_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SURFACE_PLANES;
    o.has_lower = 1;
    o.lower.p = 0.5;
    o.lower.c = -3;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_OK && ts_surface_certified(s));
    ts_surface_free(s);
    o.has_lower = 0;
    o.has_upper = 1;
    o.upper.q = -0.5;
    o.upper.c = 12;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_OK && ts_surface_certified(s));
    ts_surface_free(s);
    /* overflow of the size */
    CHECK(ts_surface_new(x, SIZE_MAX / 2, y, SIZE_MAX / 2, z, NULL, &s, &e) == TS_ERR_OVERFLOW);

    /* accessors, report, certify, eval errors */
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_POSITIVE;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_OK);
    CHECK(ts_surface_nx(s) == 2 && ts_surface_ny(s) == 2);
    CHECK(ts_surface_x(s)[2] == 2 && ts_surface_y(s)[2] == 3 && ts_surface_z(s)[4] == 0);
    /* the zero node is inner: its slopes and twist are 0 (§11.3) */
    CHECK(ts_surface_dzdx(s)[4] == 0 && ts_surface_dzdy(s)[4] == 0 && ts_surface_twist(s)[4] == 0);
    CHECK(ts_surface_ax(s)[0] >= 1 && ts_surface_ay(s)[1] >= 1);
    CHECK(ts_surface_form(s) == TS_FORM_PAPER && ts_surface_shape_of(s) == TS_SURFACE_POSITIVE);
    double B[16], X[4], Y[4];
    CHECK(ts_surface_control(NULL, 0, 0, B, X, Y) == TS_ERR_NULL);
    CHECK(ts_surface_control(s, 0, 0, NULL, X, Y) == TS_ERR_NULL);
    CHECK(ts_surface_control(s, 2, 0, B, X, Y) == TS_ERR_INDEX);
    CHECK(ts_surface_control(s, 0, 2, B, X, Y) == TS_ERR_INDEX);
    CHECK(ts_surface_control(s, 1, 1, B, NULL, NULL) == TS_OK && B[0] == 0.0 && B[15] == 9);
    ts_patch_report r = TS_PATCH_REPORT_INIT, rs[4];
    ts_patch_report_init(rs, sizeof rs / sizeof rs[0]);
    CHECK(ts_surface_report(s, 0, 0, NULL) == TS_ERR_NULL);
    CHECK(ts_surface_report(NULL, 0, 0, &r) == TS_ERR_NULL && isnan(r.proven_lower));
    CHECK(ts_surface_report(s, 2, 0, &r) == TS_ERR_INDEX);
    CHECK(ts_surface_report(s, 0, 2, &r) == TS_ERR_INDEX);
    CHECK(ts_surface_report(s, 1, 1, &r) == TS_OK && r.certified && r.proven_lower == 0.0 &&
          r.sampled_lower == 0.0 && r.at_lower[0] == 1.0 && r.at_lower[1] == 1.0);
    ts_plane lo = {0, 0, -1}, hi = {0, 0, 9.5}, bad = {0, TH_NAN, 0}, sl = {0.5, 0.25, -3};
    CHECK(ts_surface_certify(NULL, &lo, NULL, rs, &e) == TS_ERR_NULL);
    CHECK(ts_surface_certify(s, NULL, NULL, rs, &e) == TS_ERR_NULL && isnan(rs[0].B[0]));
    CHECK(ts_surface_certify(s, &bad, NULL, rs, &e) == TS_ERR_NONFINITE);
    CHECK(ts_surface_certify(s, NULL, &bad, NULL, &e) == TS_ERR_NONFINITE);
    CHECK(ts_surface_certify(s, &lo, &hi, rs, &e) == TS_OK && rs[3].certified);
    CHECK(ts_surface_certify(s, &sl, NULL, NULL, &e) == TS_OK); /* sloped, paper form */
    CHECK(ts_surface_certify(s, &lo, NULL, NULL, NULL) == TS_OK);
    hi.c = 8.5; /* the node 9 is above */
    CHECK(ts_surface_certify(s, NULL, &hi, rs, &e) == TS_ERR_VIOLATED && e.index == 3 &&
          !rs[3].certified && rs[3].proven_upper < 0 && rs[0].certified);
    hi.c = 5.0; /* several patches violate: the first is named */
    CHECK(ts_surface_certify(s, NULL, &hi, rs, &e) == TS_ERR_VIOLATED);
    {
        size_t first = 4, count = 0;
        for (size_t c = 4; c-- > 0;)
            if (!rs[c].certified)
                first = c, count++;
        CHECK(count >= 2 && e.index == first);
    }
    ts_plane sl2 = {0.0, 0.25, -3};
    CHECK(ts_surface_certify(s, &sl2, NULL, NULL, &e) == TS_OK); /* sloped in y only */
    /* gaps at the bottom of the subnormal range: the certificate's work is
     * bounded (depth and piece count) and still a valid bound */
    {
        double zs[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        zs[4] = 3e-322;
        ts_surface *t = NULL;
        ts_surface_options oo;
        ts_surface_options_init(&oo);
        oo.shape = TS_SURFACE_NONE;
        oo.alpha = 0.2;
        CHECK(ts_surface_new(x, 3, y, 3, zs, &oo, &t, &e) == TS_OK);
        ts_plane below = {0, 0, -1e-323};
        ts_patch_report rr[4];
        ts_patch_report_init(rr, sizeof rr / sizeof rr[0]);
        ts_surface_certify(t, &below, NULL, rr, &e);
        CHECK(rr[0].proven_lower <= rr[0].sampled_lower && isfinite(rr[0].proven_lower));
        ts_surface_free(t);
    }
    double v = 0, dx = 0, dy = 0;
    CHECK(ts_surface_eval(NULL, 0, 0, NULL, &v, &dx, &dy) == TS_ERR_NULL && isnan(v) &&
          isnan(dx) && isnan(dy));
    CHECK(ts_surface_eval(s, -1, 0, NULL, &v, NULL, NULL) == TS_ERR_DOMAIN && isnan(v));
    CHECK(ts_surface_eval(s, 0, TH_NAN, NULL, NULL, NULL, NULL) == TS_ERR_DOMAIN);
    CHECK(ts_surface_eval(s, 2, 3, NULL, NULL, &dx, NULL) == TS_OK && isfinite(dx));
    CHECK(ts_surface_eval(s, 2, 3, NULL, NULL, NULL, &dy) == TS_OK && isfinite(dy));
    double xq[3] = {0.5, 5, 1}, yq[3] = {0.5, 0.5, TH_NAN}, zq[3], zx[3], zy[3];
    CHECK(ts_surface_eval_batch(NULL, xq, yq, 3, zq, NULL, NULL, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_batch(s, NULL, yq, 3, zq, NULL, NULL, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_batch(s, xq, NULL, 3, zq, NULL, NULL, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_batch(s, xq, yq, 3, NULL, NULL, NULL, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_batch(s, NULL, NULL, 0, NULL, NULL, NULL, &e) == TS_OK);
    CHECK(ts_surface_eval_batch(s, xq, yq, 3, zq, zx, zy, &e) == TS_ERR_DOMAIN && e.index == 1 &&
          isfinite(zq[0]) && isnan(zq[1]) && isnan(zx[2]) && isnan(zy[2]));
    CHECK(ts_surface_eval_batch(s, xq, yq, 3, zq, NULL, NULL, &e) == TS_ERR_DOMAIN);
    double out[9];
    CHECK(ts_surface_eval_grid(NULL, xq, 3, yq, 3, out, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_grid(s, NULL, 3, yq, 3, out, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_grid(s, xq, 3, NULL, 3, out, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_grid(s, xq, 3, yq, 3, NULL, &e) == TS_ERR_NULL);
    CHECK(ts_surface_eval_grid(s, NULL, 0, NULL, 0, NULL, &e) == TS_OK);
    CHECK(ts_surface_eval_grid(s, xq, 1, NULL, 0, NULL, &e) == TS_OK);
    CHECK(ts_surface_eval_grid(s, xq, 3, yq, 3, out, &e) == TS_ERR_DOMAIN && e.index == 1 &&
          isfinite(out[0]) && isnan(out[1]) && isnan(out[6]));
    double xg[2] = {0.5, 1.5}, yg[2] = {0.5, -2};
    CHECK(ts_surface_eval_grid(s, xg, 2, yg, 2, out, &e) == TS_ERR_DOMAIN && e.index == 3 &&
          isnan(out[2]) && isfinite(out[1]));
    double I = 0;
    CHECK(ts_surface_integral(NULL, 0, 1, 0, 1, &I) == TS_ERR_NULL && isnan(I));
    CHECK(ts_surface_integral(s, 0, 1, 0, 1, NULL) == TS_ERR_NULL);
    CHECK(ts_surface_integral(s, -1, 1, 0, 1, &I) == TS_ERR_DOMAIN);
    CHECK(ts_surface_integral(s, 0, 3, 0, 1, &I) == TS_ERR_DOMAIN);
    CHECK(ts_surface_integral(s, 0, 1, TH_NAN, 1, &I) == TS_ERR_DOMAIN);
    CHECK(ts_surface_integral(s, 0, 1, 0, 4, &I) == TS_ERR_DOMAIN);
    CHECK(ts_surface_integral(s, 0, 2, 1, 1, &I) == TS_OK && I == 0.0);
    ts_surface_free(s);
    ts_surface_free(NULL);
    /* a constant surface: the range scheme with every node on both bounds */
    double zf[9] = {3, 3, 3, 3, 3, 3, 3, 3, 3};
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_RANGE;
    CHECK(ts_surface_new(x, 3, y, 3, zf, &o, &s, &e) == TS_OK);
    CHECK(ts_surface_eval(s, 0.7, 2.2, NULL, &v, &dx, &dy) == TS_OK);
    /* Σ A_k A_l = 1 up to rounding (a few ε) */
    CHECK_CLOSE(v, 3.0, 1e-14);
    CHECK_CLOSE(dx, 0.0, 1e-13);
    CHECK_CLOSE(dy, 0.0, 1e-13);
    ts_surface_free(s);
}

/* the geometric form's certificate against a sloped plane, and the paper
 * form's linear rest */
static void test_sloped_certify(void)
{
    TH_CASE("sloped certificates");
    grid g;
    make_grid(&g, 6, 5, 4.0);
    for (int form = 0; form < 3; form++) {
        ts_surface_options o;
        ts_surface_options_init(&o);
        o.form = (ts_form)form;
        o.shape = TS_SURFACE_POSITIVE;
        ts_surface *s = NULL;
        CHECK(ts_surface_new(g.x, 6, g.y, 5, g.z, &o, &s, NULL) == TS_OK);
        /* a plane through (x0, y0) falling steeply: below the data? check
         * against dense samples whether certify's verdict is consistent */
        ts_plane pl = {0.3, -0.2, -3.0};
        ts_patch_report rs[20];
        ts_patch_report_init(rs, sizeof rs / sizeof rs[0]);
        ts_status st = ts_surface_certify(s, &pl, NULL, rs, NULL);
        int ok_all = 1;
        for (int c = 0; c < 20; c++) {
            /* the proven bound never exceeds a sampled gap */
            double worst = 1e300;
            for (int a = 0; a <= 30; a++)
                for (int b = 0; b <= 30; b++) {
                    double xv = rs[c].x0 + (rs[c].x1 - rs[c].x0) * a / 30.0;
                    double yv = rs[c].y0 + (rs[c].y1 - rs[c].y0) * b / 30.0, v;
                    ts_surface_eval(s, xv, yv, NULL, &v, NULL, NULL);
                    worst = fmin(worst, v - (pl.p * xv + pl.q * yv + pl.c));
                }
            ok_all &= rs[c].proven_lower <= worst + 1e-12;
            /* the stated tolerance (1e-4 of the plane's variation, here <= 6e-4)
             * plus what 31² samples of a smooth patch can miss */
            ok_all &= rs[c].proven_lower >= worst - 0.05;
        }
        CHECK(ok_all);
        CHECK(st == TS_OK || st == TS_ERR_VIOLATED);
        ts_surface_free(s);
    }
}

/* Which side of a sloped plane a node lies on, and the planes' order, are
 * decided exactly (docs/method.md §5.8, §11.3), at coordinates where p x is
 * about 2^70 and the plane's value rounds by up to 2^17.  Integer
 * coordinates and coefficients make the exact value V = p x + q y + c an
 * integer computed exactly in __int128 (independent of the library); the
 * node's z = V rounded to a double (doubles beyond 2^53 are integers), so
 * sign(z − V) is known exactly.  Expected: TS_ERR_SIDE at that node exactly
 * when z <= V; otherwise the node passes the check (the build may still
 * find the patch infeasible, as a node within rounding of the plane). */
__extension__ typedef __int128 i128;
static void test_exact_side(void)
{
    TH_CASE("exact side of a plane");
    uint64_t r = 0x2545F4914F6CDD1Du;
    int refused_above = 0, passed_below = 0, trials = 0, on_or_below = 0;
    for (int t = 0; t < 600; t++) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        int64_t X0 = (int64_t)(r >> 24) | ((int64_t)1 << 39); /* 2^39 .. 2^40 */
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        int64_t Y0 = (int64_t)(r >> 25) | ((int64_t)1 << 38);
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        int64_t P = (int64_t)((r >> 34) | (1u << 29)), Q = -(int64_t)((r & 0x3fffffff) | (1u << 28));
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        int64_t C = (int64_t)(r >> 12) - ((int64_t)1 << 51);
        double x[3], y[3], z[9];
        for (int k = 0; k < 3; k++) {
            x[k] = (double)(X0 + k);
            y[k] = (double)(Y0 + k);
        }
        i128 V4 = (i128)P * (X0 + 1) + (i128)Q * (Y0 + 1) + C;
        for (int n = 0; n < 9; n++) {
            i128 V = (i128)P * (X0 + n % 3) + (i128)Q * (Y0 + n / 3) + C;
            /* the other nodes far above: 2^-20 of the value (ulp 2^-52 of it) */
            double vd = (double)V;
            z[n] = n == 4 ? vd : vd + fabs(vd) * 0x1p-20;
        }
        int sgn = ((i128)z[4] > V4) - ((i128)z[4] < V4);
        on_or_below += sgn <= 0;
        ts_surface_options o;
        ts_surface_options_init(&o);
        o.form = TS_FORM_GEOMETRIC;
        o.shape = TS_SURFACE_PLANES;
        o.has_lower = 1;
        o.lower = (ts_plane){(double)P, (double)Q, (double)C};
        ts_surface *s = NULL;
        ts_error e;
        ts_status st = ts_surface_new(x, 3, y, 3, z, &o, &s, &e);
        int side = st == TS_ERR_SIDE && e.index == 4;
        CHECKF(st == TS_OK || st == TS_ERR_SIDE || st == TS_ERR_INFEASIBLE, "trial %d: %s", t,
               ts_strerror(st));
        CHECKF(st != TS_ERR_SIDE || e.index == 4, "trial %d: SIDE at node %zu", t, e.index);
        refused_above += sgn > 0 && side;
        passed_below += sgn <= 0 && !side;
        trials++;
        ts_surface_free(s);
        /* the order of two planes differing by 1 in c: exactly ordered although
         * equal as rounded; no double lies strictly between them */
        o.has_upper = 1;
        o.upper = o.lower;
        o.upper.c = (double)(C + 1);
        if ((int64_t)o.upper.c == C + 1) {
            st = ts_surface_new(x, 3, y, 3, z, &o, &s, &e);
            CHECKF(st == TS_ERR_SIDE && e.index == 0, "trial %d: upper = lower + 1: %s at %zu", t,
                   ts_strerror(st), e.index);
            ts_surface_free(s);
            o.upper.c = (double)(C - 1);
            st = ts_surface_new(x, 3, y, 3, z, &o, &s, &e);
            CHECKF(st == TS_ERR_LINES && e.index == 0, "trial %d: upper = lower - 1: %s at %zu", t,
                   ts_strerror(st), e.index);
            ts_surface_free(s);
        }
    }
    CHECKF(refused_above == 0, "%d of %d nodes strictly above the plane refused", refused_above,
           trials);
    CHECKF(passed_below == 0, "%d of %d nodes on or below the plane accepted", passed_below, trials);
    /* both sides occur (the test can tell them apart) */
    CHECKF(on_or_below > 50 && on_or_below < trials - 50, "%d of %d on or below", on_or_below,
           trials);
}

/* no floating-point exception flag but inexact on valid input */
static void test_fenv(void)
{
    TH_CASE("fenv");
    grid g;
    make_grid(&g, 7, 6, 50.0);
    feclearexcept(FE_ALL_EXCEPT);
    for (int form = 0; form < 3; form++)
        for (int sh = 0; sh <= TS_SURFACE_RANGE; sh++) {
            ts_surface_options o;
            ts_surface_options_init(&o);
            o.form = (ts_form)form;
            o.shape = (ts_surface_shape)sh;
            o.has_lower = o.has_upper = 1;
            o.upper.c = 50.0;
            o.lower.c = sh == TS_SURFACE_PLANES ? -1.0 : 0.0;
            ts_surface *s = NULL;
            if (ts_surface_new(g.x, 7, g.y, 6, g.z, &o, &s, NULL) != TS_OK)
                continue;
            double v, dx, dy, xq[50], yq[50], out[2500], I;
            for (int k = 0; k < 50; k++) {
                xq[k] = g.x[0] + (g.x[6] - g.x[0]) * k / 49.0;
                yq[k] = g.y[0] + (g.y[5] - g.y[0]) * k / 49.0;
            }
            ts_surface_eval(s, xq[7], yq[9], NULL, &v, &dx, &dy);
            ts_surface_eval_grid(s, xq, 50, yq, 50, out, NULL);
            ts_surface_eval_batch(s, xq, yq, 50, out, out + 50, out + 100, NULL);
            ts_surface_integral(s, g.x[0], g.x[6], g.y[1], g.y[4], &I);
            ts_patch_report r[30];
            ts_patch_report_init(r, sizeof r / sizeof r[0]);
            ts_plane pl = {0.1, -0.1, -20.0};
            ts_surface_certify(s, &pl, NULL, r, NULL);
            ts_surface_free(s);
        }
    int fl = fetestexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW | FE_UNDERFLOW);
    CHECKF(fl == 0, "flags %#x", fl);
}

int main(void)
{
    test_fenv();
    test_exact_side();
    test_errors();
    test_plane_and_integral();
    test_transpose();
    test_sloped_certify();
    test_property();
    return th_report("test_surface");
}
