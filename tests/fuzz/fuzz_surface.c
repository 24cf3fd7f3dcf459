/* ts_surface_new on fuzzer-chosen grids, values, forms, schemes and bounds
 * (nodes on a constant bound, or a plane's value at the node, offered
 * often), then scalar, batch and grid evaluation.  Checks:
 *  - a status from ts_surface_new's documented list; a surface exactly
 *    when TS_OK; a scheme's surface is certified;
 *  - nodes reproduced exactly;
 *  - every value returned for a certified surface (scalar, batch, grid; a
 *    5 × 5 lattice per patch, edges included) is in the certified region
 *    with ZERO tolerance: positive S >= 0, bounds and range lower.c <= S <=
 *    upper.c (doubles: compared exactly), planes strictly beyond each plane,
 *    decided exactly (tests/common/th_exact.h; a product beyond 2^1020 is
 *    left undecided, as the library leaves it), gridded fields (the planes
 *    sampled on a 2 × 2 or 3 × 3 grid, docs/method.md §11.7) strictly
 *    beyond each field, decided exactly; never NaN. */
#include "fuzz.h"
#include "../common/th_exact.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

#define PMAX 6 /* points per axis */
#define PER 5  /* lattice points per patch side */
#define QMAX ((PMAX - 1) * (PER - 1) + 1)

static int documented(ts_status st)
{
    switch (st) {
    case TS_OK: case TS_ERR_TOO_FEW: case TS_ERR_OPTION: case TS_ERR_OVERFLOW:
    case TS_ERR_NONFINITE: case TS_ERR_UNSORTED: case TS_ERR_ALPHA: case TS_ERR_BETA:
    case TS_ERR_MARGIN: case TS_ERR_GEOMETRIC: case TS_ERR_NEGATIVE: case TS_ERR_LINES:
    case TS_ERR_SIDE: case TS_ERR_INFEASIBLE: case TS_ERR_NOMEM: case TS_ERR_BOUND_GRID:
    case TS_ERR_UNPROVEN:
        return 1;
    default:
        return 0;
    }
}

/* sign of z − field g at (x, y) (inside its grid), exact; 2 undecidable */
static int field_side(const ts_grid_bound *g, double z, double x, double y)
{
    size_t i = 0, j = 0;
    while (i + 2 < g->nx_points && g->x[i + 1] <= x)
        i++;
    while (j + 2 < g->ny_points && g->y[j + 1] <= y)
        j++;
    const double *z0 = g->z + j * g->nx_points + i, *z1 = z0 + g->nx_points;
    return th_bilinear_side(z, x, y, g->x[i], g->x[i + 1], g->y[j], g->y[j + 1], z0[0], z0[1],
                            z1[0], z1[1]);
}

/* z at (x, y) in the region of s built with options o (ZERO tolerance) */
static void in_region(const ts_surface_options *o, double zmin, double zmax, double x, double y,
                      double z, const char *how)
{
    FUZZ_CHECK(!isnan(z), "%s: S(%.17g, %.17g) is NaN", how, x, y);
    switch (o->shape) {
    case TS_SURFACE_POSITIVE:
        FUZZ_CHECK(z >= 0.0, "%s: S(%.17g, %.17g) = %.17g < 0", how, x, y, z);
        break;
    case TS_SURFACE_BOUNDS:
        FUZZ_CHECK(!o->has_lower || z >= o->lower.c, "%s: S(%.17g, %.17g) = %.17g < %.17g", how,
                   x, y, z, o->lower.c);
        FUZZ_CHECK(!o->has_upper || z <= o->upper.c, "%s: S(%.17g, %.17g) = %.17g > %.17g", how,
                   x, y, z, o->upper.c);
        break;
    case TS_SURFACE_RANGE:
        FUZZ_CHECK(zmin <= z && z <= zmax, "%s: S(%.17g, %.17g) = %.17g outside [%.17g, %.17g]",
                   how, x, y, z, zmin, zmax);
        break;
    case TS_SURFACE_GRIDS:
        if (o->has_lower) {
            int sd = field_side(&o->lower_grid, z, x, y);
            FUZZ_CHECK(sd == 1 || sd == 2, "%s: S(%.17g, %.17g) = %.17g not above the lower field",
                       how, x, y, z);
        }
        if (o->has_upper) {
            int sd = field_side(&o->upper_grid, z, x, y);
            FUZZ_CHECK(sd == -1 || sd == 2,
                       "%s: S(%.17g, %.17g) = %.17g not below the upper field", how, x, y, z);
        }
        break;
    case TS_SURFACE_PLANES:
        if (o->has_lower) {
            int sd = th_plane_side(z, o->lower.p, o->lower.q, o->lower.c, x, y);
            FUZZ_CHECK(sd == 1 || sd == 2, "%s: S(%.17g, %.17g) = %.17g not above the lower plane",
                       how, x, y, z);
        }
        if (o->has_upper) {
            int sd = th_plane_side(z, o->upper.p, o->upper.q, o->upper.c, x, y);
            FUZZ_CHECK(sd == -1 || sd == 2,
                       "%s: S(%.17g, %.17g) = %.17g not below the upper plane", how, x, y, z);
        }
        break;
    default:
        break;
    }
}

static void lattice(const double *t, size_t np, double *q, size_t *m)
{
    size_t k = 0;
    for (size_t i = 0; i + 1 < np; i++)
        for (int a = 0; a + 1 < PER; a++) {
            double v = t[i] + (t[i + 1] - t[i]) * (a / (double)(PER - 1));
            q[k++] = v < t[i] ? t[i] : v > t[i + 1] ? t[i + 1] : v;
        }
    q[k++] = t[np - 1];
    *m = k;
}

/* a plane from the input: constant (most inputs) or sloped */
static void plane(fuzz_in *in, ts_plane *pl)
{
    unsigned b = fuzz_byte(in);
    pl->c = fuzz_double(in);
    pl->p = b & 1 ? fuzz_double(in) : 0.0;
    pl->q = b & 2 ? fuzz_double(in) : 0.0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in in = {data, size};
    fuzz_stats_exec();
    ts_surface_options o;
    ts_surface_options_init(&o);
    unsigned b0 = fuzz_byte(&in), b1 = fuzz_byte(&in);
    o.form = (ts_form)(b0 % 3);
    o.shape = (ts_surface_shape)(b0 / 3 % 5);
    o.zero_twist = (b0 / 15) & 1;
    o.slopes = (ts_slopes)(b0 / 30 % 6); /* arithmetic .. makima: not USER, PERIODIC */
    size_t nx = 2 + (b1 & 15) % (PMAX - 1), ny = 2 + (b1 >> 4) % (PMAX - 1);
    double x[PMAX], y[PMAX], z[PMAX * PMAX];
    /* grids: a start and steps (small integers, or fuzzed) times a scale */
    double *ax[2] = {x, y};
    size_t na[2] = {nx, ny};
    for (int d = 0; d < 2; d++) {
        unsigned sb = fuzz_byte(&in);
        double scale = sb & 1 ? fabs(fuzz_double(&in)) : 1.0;
        ax[d][0] = sb & 2 ? fuzz_double(&in) : 0.0;
        for (size_t k = 1; k < na[d]; k++) {
            unsigned st = fuzz_byte(&in);
            ax[d][k] = ax[d][k - 1] + (st < 240 ? (1 + st % 100) * scale : fuzz_double(&in));
        }
    }
    o.alpha = (fuzz_byte(&in) + 1) / 64.0;
    unsigned ab = fuzz_byte(&in);
    if (ab >= 250)
        o.alpha = fuzz_double(&in);
    o.beta = fuzz_byte(&in) / 64.0;
    o.margin = (fuzz_byte(&in) + 1) / 256.0;
    unsigned sides = fuzz_byte(&in);
    o.has_lower = sides & 1;
    o.has_upper = (sides >> 1) & 1;
    plane(&in, &o.lower);
    plane(&in, &o.upper);
    if (sides & 4) /* a band above the lower bound */
        o.upper.c = o.lower.c + fabs(o.upper.c);
    /* gridded fields (docs/method.md §11.7): the planes sampled on a grid
     * of 2 or 3 lines each way over the data's rectangle */
    static double fx[3], fy[3], flo[9], fup[9];
    if ((sides & 8) && (o.shape == TS_SURFACE_BOUNDS || o.shape == TS_SURFACE_PLANES)) {
        size_t m = 2;
        fx[0] = x[0];
        fy[0] = y[0];
        double mx = 0.5 * (x[0] + x[nx - 1]), my = 0.5 * (y[0] + y[ny - 1]);
        if ((sides & 16) && x[0] < mx && mx < x[nx - 1] && y[0] < my && my < y[ny - 1]) {
            fx[1] = mx;
            fy[1] = my;
            m = 3;
        }
        fx[m - 1] = x[nx - 1];
        fy[m - 1] = y[ny - 1];
        for (size_t b = 0; b < m; b++)
            for (size_t a = 0; a < m; a++) {
                flo[b * m + a] = o.lower.p * fx[a] + o.lower.q * fy[b] + o.lower.c;
                fup[b * m + a] = o.upper.p * fx[a] + o.upper.q * fy[b] + o.upper.c;
            }
        o.shape = TS_SURFACE_GRIDS;
        o.lower_grid = (ts_grid_bound){fx, m, fy, m, flo};
        o.upper_grid = (ts_grid_bound){fx, m, fy, m, fup};
    }
    /* values: fuzzed, on a bound (or a plane's value at the node), or between */
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            unsigned kind = fuzz_byte(&in);
            double lo = o.lower.p * x[i] + o.lower.q * y[j] + o.lower.c;
            double up = o.upper.p * x[i] + o.upper.q * y[j] + o.upper.c;
            double v;
            switch (kind % 6) {
            case 0: v = lo; break;
            case 1: v = up; break;
            case 2: v = lo + (up - lo) * (fuzz_byte(&in) / 256.0); break;
            case 3: v = o.shape == TS_SURFACE_POSITIVE ? 0.0 : lo; break;
            default: v = fuzz_double(&in); break;
            }
            z[j * nx + i] = v;
        }
    ts_surface *s = NULL;
    ts_error e;
    ts_status st = ts_surface_new(x, nx, y, ny, z, &o, &s, &e);
    FUZZ_CHECK(documented(st), "status %d", (int)st);
    FUZZ_CHECK((st == TS_OK) == (s != NULL), "status %d", (int)st);
    if (!s)
        return 0;
    FUZZ_CHECK(ts_surface_certified(s) == (o.shape != TS_SURFACE_NONE), "certified %d",
               ts_surface_certified(s));
    double zmin = z[0], zmax = z[0];
    for (size_t n = 0; n < nx * ny; n++) {
        zmin = fmin(zmin, z[n]);
        zmax = fmax(zmax, z[n]);
    }
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            double v;
            FUZZ_CHECK(ts_surface_eval(s, x[i], y[j], NULL, &v, NULL, NULL) == TS_OK, "node");
            FUZZ_CHECK(v == z[j * nx + i], "node (%zu, %zu): %.17g vs %.17g", i, j, v,
                       z[j * nx + i]);
        }
    static double xq[QMAX], yq[QMAX], grid[QMAX * QMAX], bx[QMAX * QMAX], by[QMAX * QMAX],
        bz[QMAX * QMAX];
    size_t mx, my;
    lattice(x, nx, xq, &mx);
    lattice(y, ny, yq, &my);
    st = ts_surface_eval_grid(s, xq, mx, yq, my, grid, &e);
    FUZZ_CHECK(st == TS_OK, "grid: %s", ts_strerror(st));
    for (size_t b = 0; b < my; b++)
        for (size_t a = 0; a < mx; a++) {
            bx[b * mx + a] = xq[a];
            by[b * mx + a] = yq[b];
        }
    st = ts_surface_eval_batch(s, bx, by, mx * my, bz, NULL, NULL, &e);
    FUZZ_CHECK(st == TS_OK, "batch: %s", ts_strerror(st));
    int region = o.shape != TS_SURFACE_NONE;
    fuzz_counts()[FUZZ_CERTIFIED] += region;
    ts_surface_cursor cur = TS_SURFACE_CURSOR_INIT;
    for (size_t n = 0; n < mx * my; n++) {
        double v, vx, vy;
        FUZZ_CHECK(ts_surface_eval(s, bx[n], by[n], &cur, &v, &vx, &vy) == TS_OK, "eval");
        if (!region)
            continue;
        in_region(&o, zmin, zmax, bx[n], by[n], v, "scalar");
        in_region(&o, zmin, zmax, bx[n], by[n], bz[n], "batch");
        in_region(&o, zmin, zmax, bx[n], by[n], grid[n], "grid");
        fuzz_counts()[FUZZ_SAMPLES] += 3;
    }
    ts_surface_free(s);
    return 0;
}
