/* Surface build refusals and evaluation cursor paths at their edges
 * (include/trigspline.h, ts_surface_new, ts_surface_eval_batch).
 *
 * Refusals (TS_ERR_INFEASIBLE, index = the patch): a node gap near the
 * underflow threshold next to a slope asks for an a beyond 1e300
 * (docs/method.md §11.3, need 2 K |d| / g).  Where several patches refuse,
 * the one named is the first met in the order x before y, the least
 * interval, then the least line (the last line's nodes name the patch
 * before it); each case's patches are those of its refusals taken alone
 * (a node gap of 1e-310 in row j of a 3 x 3 grid on 0, 1, 2 refuses along
 * x on the interval whose far node is lower).  Gridded fields: the same
 * refusal against a lower field 0, along x (patch (1, 0)) and along y only
 * (the transposed data, patch (0, 1)); the tiny node 1e-90 is within the
 * range where its side of the field is decided exactly (2^-300 .. 2^300),
 * its neighbours 1e299 far above it, so 2 K |d| / g ~ 1e389.
 *
 * A twist clamp bound that is NaN (k_x infinite times a zero slope, the
 * clamp ignores it as fmax / fmin do) on data whose control values
 * overflow: TS_ERR_NONFINITE at a patch (the header), and the same data
 * with a tenth of the width build.
 *
 * Cursor: ts_surface_eval_batch keeps one cursor over its queries; a query
 * three intervals from the previous one skips the cursor, and the query
 * after that, one interval further, finds its interval by search and is
 * the cursor's next (then the cursor is tried again).  Nodes are
 * reproduced exactly (the header), and every value equals the one
 * ts_surface_eval gives without a cursor. */
#include "th.h"
#include "trigspline.h"

#include <string.h>

static const double x3[3] = {0.0, 1.0, 2.0};

static ts_status build(const double *z, int grids, ts_error *e)
{
    static const double fx[3] = {-1.0, 1.0, 3.0}, f0[9] = {0};
    ts_surface_options o;
    ts_surface *s = NULL;
    ts_surface_options_init(&o);
    if (grids) {
        o.shape = TS_SURFACE_GRIDS;
        o.has_lower = 1;
        o.lower_grid = (ts_grid_bound){fx, 3, fx, 3, f0};
    } else {
        o.shape = TS_SURFACE_POSITIVE;
    }
    ts_status st = ts_surface_new(x3, 3, x3, 3, z, &o, &s, e);
    ts_surface_free(s);
    return st;
}

#define REFUSES(z, grids, patch)                                                                 \
    do {                                                                                         \
        ts_error e_;                                                                             \
        ts_status st_ = build(z, grids, &e_);                                                    \
        CHECKF(st_ == TS_ERR_INFEASIBLE && e_.where == TS_WHERE_INTERVAL && e_.index == (patch), \
               "%s index %zu, expected patch %d", ts_status_name(st_), e_.index, (patch));       \
    } while (0)

int main(void)
{
    TH_CASE("refusals met in memory order after a first one");
    {
        /* row 0: {1, g, 4} refuses on x interval 0 (patch 0); row 2:
         * {4, g, 1} on x interval 1, last line (patch 3) */
        double r0[9] = {1, 1e-310, 4, 1, 1, 1, 1, 1, 1};
        double r2[9] = {4, 4, 4, 1, 1, 1, 4, 1e-310, 1};
        double r0a[9] = {4, 1e-310, 1, 4, 1, 1, 4, 1, 1};
        REFUSES(r0, 0, 0);
        REFUSES(r2, 0, 3);
        REFUSES(r0a, 0, 1);
        /* a larger interval met later: the least interval, patch 0 */
        double both[9] = {1, 1e-310, 4, 1, 1, 1, 4, 1e-310, 1};
        REFUSES(both, 0, 0);
        /* the same interval on a later, larger line: the least line, patch 1 */
        double lines[9] = {4, 1e-310, 1, 4, 1, 1, 4, 1e-310, 1};
        REFUSES(lines, 0, 1);
    }

    TH_CASE("refusals of the scheme against gridded fields");
    {
        double zx[9] = {4e299, 1e-90, 1e299, 4e299, 1e299, 1e299, 4e299, 1e299, 1e299};
        double zy[9] = {4e299, 4e299, 4e299, 1e-90, 1e299, 1e299, 1e299, 1e299, 1e299};
        REFUSES(zx, 1, 1);
        REFUSES(zy, 1, 2);
        /* the same data against the constant bound 0: the same patches */
        REFUSES(zx, 0, 1);
        REFUSES(zy, 0, 2);
    }

    TH_CASE("a twist bound that is NaN: k_x infinite times a zero slope");
    {
        /* alpha = margin = 1e-300: a = 2e-300, k_x = 2 h / (3 pi a)
         * overflows for h = 1e10 (1.06e309; for h = 1e9 it is 1.06e308,
         * below the largest double 1.8e308); rows flat in x, so the twist clamp's
         * bound -F/(2c) is inf * 0 = NaN, which the clamp ignores (fmax /
         * fmin), and the patch's control values z + k_x * 0 are NaN:
         * TS_ERR_NONFINITE at a patch.  With h = 1e9 the same data build. */
        double zf[9] = {1, 1, 1, 2, 2, 2, 3, 3, 3}, y[3] = {0, 1, 2};
        for (int big = 0; big < 2; big++) {
            double h = big ? 1e10 : 1e9, x[3] = {0.0, h, 2.0 * h};
            ts_surface_options o;
            ts_surface *s = NULL;
            ts_error e;
            ts_surface_options_init(&o);
            o.shape = TS_SURFACE_BOUNDS;
            o.has_lower = o.has_upper = 1;
            o.lower.c = 0.5;
            o.upper.c = 3.5;
            o.alpha = o.margin = 1e-300;
            ts_status st = ts_surface_new(x, 3, y, 3, zf, &o, &s, &e);
            if (big)
                CHECKF(st == TS_ERR_NONFINITE && e.where == TS_WHERE_INTERVAL && e.index < 4, "%s",
                       ts_status_name(st));
            else
                CHECKF(st == TS_OK, "%s", ts_status_name(st));
            ts_surface_free(s);
        }
    }

    TH_CASE("a batch's cursor after a query that skipped it");
    {
        enum { N = 9 };
        double t[N], z[N * N];
        for (int k = 0; k < N; k++)
            t[k] = k * 0.5 + (k % 3) * 0.125;
        for (int n = 0; n < N * N; n++)
            z[n] = (double)((n * 7) % 11) - 3.0;
        ts_surface_options o;
        ts_surface *s = NULL;
        ts_error e;
        ts_surface_options_init(&o);
        ts_status st = ts_surface_new(t, N, t, N, z, &o, &s, &e);
        CHECKF(st == TS_OK && s, "%s", ts_status_name(st));
        if (s) {
            /* x intervals 0, 3 (cursor skipped), 4 (found by search, the
             * cursor's next), 5 (the cursor tried again), 1; nodes and midpoints */
            int ix[5] = {0, 3, 4, 5, 1}, iy = 2;
            double xq[10], yq[10], zq[10], zxq[10], zyq[10];
            for (int k = 0; k < 5; k++) {
                xq[k] = t[ix[k]];
                yq[k] = t[iy];
                xq[5 + k] = 0.5 * (t[ix[k]] + t[ix[k] + 1]);
                yq[5 + k] = 0.5 * (t[iy] + t[iy + 1]);
            }
            CHECK(ts_surface_eval_batch(s, xq, yq, 10, zq, zxq, zyq, &e) == TS_OK);
            for (int k = 0; k < 5; k++)
                CHECKF(zq[k] == z[iy * N + ix[k]], "node %d: %a", k, zq[k]);
            for (int k = 0; k < 10; k++) {
                double v, vx, vy;
                CHECK(ts_surface_eval(s, xq[k], yq[k], NULL, &v, &vx, &vy) == TS_OK);
                CHECKF(memcmp(&v, zq + k, sizeof v) == 0 && memcmp(&vx, zxq + k, sizeof v) == 0 &&
                           memcmp(&vy, zyq + k, sizeof v) == 0,
                       "query %d: %a %a", k, v, zq[k]);
            }
        }
        ts_surface_free(s);
    }
    return th_report("test_surface_build_edges");
}
