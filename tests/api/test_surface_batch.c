/* ts_surface_eval_batch on a grid large enough for every path of its
 * search and its blocks (include/trigspline.h): 700 × 101 nodes (an axis of
 * more than 512 knots, more than 65536 nodes), positive scheme, paper form,
 * scattered queries with some outside the grid in the middle of a block and
 * a count that is no multiple of a block.
 *
 * Expected values: the patch's own control net and abscissae
 * (ts_surface_control) in the cubic trigonometric basis of docs/method.md
 * §2 at θ = (π/2)(x − x_i)/h (paper form), in long double: the library
 * rounds about 40 operations of values up to max |B| (about 1e-14 relative);
 * the tolerance 1e-12 · max |B| leaves room for that and fails by orders of
 * magnitude for a wrong patch (neighbouring nets differ by O(1) here).
 * Partials and values of the batch are bit for bit those of
 * ts_surface_eval at the same points (the header: one evaluation, two
 * entry points); a query outside gives NaN and the first such index. */
#include "th.h"
#include "trigspline.h"

#include <math.h>
#include <stdlib.h>

static unsigned long long rng = 0x2545F4914F6CDD1DULL;
static double urand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

static void basis(long double th, long double A[4])
{
    long double s = sinl(th), c = cosl(th), ms = 1.0L - s, mc = 1.0L - c;
    A[0] = ms * ms * ms;
    A[1] = s * ms * (3.0L - s);
    A[2] = c * mc * (3.0L - c);
    A[3] = mc * mc * mc;
}

/* the patch (i, j) of v on the axis t (interval i: t[i] <= v < t[i + 1], or
 * the last one) found by a linear scan */
static size_t scan(const double *t, size_t n, double v)
{
    size_t i = 0;
    while (i + 2 < n && t[i + 1] <= v)
        i++;
    return i;
}

static double reference(const ts_surface *s, const double *x, size_t nx, const double *y,
                        size_t ny, double xv, double yv, double *bmax)
{
    size_t i = scan(x, nx, xv), j = scan(y, ny, yv);
    double B[16];
    ts_surface_control(s, i, j, B, NULL, NULL);
    long double Ax[4], Ay[4], v = 0.0L;
    basis((long double)TH_HALF_PI * ((long double)xv - (long double)x[i]) /
              ((long double)x[i + 1] - (long double)x[i]),
          Ax);
    basis((long double)TH_HALF_PI * ((long double)yv - (long double)y[j]) /
              ((long double)y[j + 1] - (long double)y[j]),
          Ay);
    *bmax = 0.0;
    for (int k = 0; k < 4; k++)
        for (int l = 0; l < 4; l++) {
            v += Ax[k] * Ay[l] * (long double)B[4 * k + l];
            *bmax = fmax(*bmax, fabs(B[4 * k + l]));
        }
    return (double)v;
}

int main(void)
{
    enum { NX = 700, NY = 101, M = 1001 };
    double *x = malloc(NX * sizeof *x), *y = malloc(NY * sizeof *y);
    double *z = malloc((size_t)NX * NY * sizeof *z);
    double *xq = malloc(M * sizeof *xq), *yq = malloc(M * sizeof *yq);
    double *zq = malloc(M * sizeof *zq), *zx = malloc(M * sizeof *zx), *zy = malloc(M * sizeof *zy);
    if (!x || !y || !z || !xq || !yq || !zq || !zx || !zy)
        return 2;
    x[0] = y[0] = 0.0;
    for (size_t i = 1; i < NX; i++)
        x[i] = x[i - 1] + 0.5 + urand();
    for (size_t j = 1; j < NY; j++)
        y[j] = y[j - 1] + 0.5 + urand();
    for (size_t n = 0; n < (size_t)NX * NY; n++)
        z[n] = urand() < 0.2 ? 0.0 : 100.0 * pow(urand(), 6);
    for (size_t k = 0; k < M; k++) {
        xq[k] = x[NX - 1] * urand();
        yq[k] = y[NY - 1] * urand();
    }
    xq[40] = -1.0;             /* outside, within the second block */
    yq[41] = y[NY - 1] + 1.0;  /* and the next */
    xq[M - 1] = x[NX - 1];     /* the last knot: the last patch */

    TH_CASE("a large positive surface, scattered queries");
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.form = TS_FORM_PAPER;
    o.shape = TS_SURFACE_POSITIVE;
    ts_surface *s = NULL;
    ts_error e;
    CHECK(ts_surface_new(x, NX, y, NY, z, &o, &s, &e) == TS_OK);
    if (s) {
        CHECK(ts_surface_eval_batch(s, xq, yq, M, zq, NULL, NULL, &e) == TS_ERR_DOMAIN &&
              e.index == 40 && e.where == TS_WHERE_QUERY);
        CHECK(isnan(zq[40]) && isnan(zq[41]));
        int close = 1, same = 1;
        for (size_t k = 0; k < M; k++) {
            if (k == 40 || k == 41)
                continue;
            double bmax, ref = reference(s, x, NX, y, NY, xq[k], yq[k], &bmax);
            if (!(fabs(zq[k] - ref) <= 1e-12 * bmax)) {
                if (close)
                    printf("query %zu: %.17g, reference %.17g\n", k, zq[k], ref);
                close = 0;
            }
        }
        CHECK(close);

        TH_CASE("the batch's values and partials are those of ts_surface_eval");
        double v0 = zq[7];
        CHECK(ts_surface_eval_batch(s, xq, yq, M, zq, zx, zy, &e) == TS_ERR_DOMAIN &&
              e.index == 40);
        CHECK(zq[7] == v0 && isnan(zx[40]) && isnan(zy[41]));
        for (size_t k = 0; k < M; k++) {
            if (k == 40 || k == 41)
                continue;
            double v, vx, vy;
            ts_surface_eval(s, xq[k], yq[k], NULL, &v, &vx, &vy);
            same &= v == zq[k] && vx == zx[k] && vy == zy[k];
        }
        CHECK(same);
    }
    ts_surface_free(s);
    free(x);
    free(y);
    free(z);
    free(xq);
    free(yq);
    free(zq);
    free(zx);
    free(zy);
    return th_report("test_surface_batch");
}
