/* Struct guards (include/trigspline.h "Struct guards"): every options and
 * report struct starts with struct_size; a constructor or report filler
 * given a struct whose struct_size is not its own sizeof returns
 * TS_ERR_VERSION before reading or writing anything else in it, and accepts
 * the struct its initialiser prepared.  The "older, smaller struct" cases
 * allocate exactly the smaller size, so ASan catches any write past it. */
#include "th.h"
#include "trigspline.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* sizes a caller built against another header could have */
static const size_t deltas[] = {0, 8, 16};

static int untouched(const void *p, size_t n, unsigned char fill, size_t skip)
{
    const unsigned char *b = p;
    for (size_t k = skip; k < n; k++)
        if (b[k] != fill)
            return 0;
    return 1;
}

static void test_options(void)
{
    TH_CASE("options");
    double x[] = {0, 1, 2, 3}, f[] = {1, 2, 0.5, 3};
    double pts[] = {0, 0, 1, 0, 1, 1, 0, 1};
    double gx[] = {0, 1, 2}, gy[] = {0, 1}, gz[] = {1, 2, 3, 2, 1, 2};
    ts_error e;

    ts_spline_options o;
    ts_spline_options_init(&o);
    CHECK(o.struct_size == sizeof(ts_spline_options));
    ts_spline *s = (ts_spline *)&e; /* not NULL: must be reset */
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_OK && s);
    ts_spline_free(s);
    CHECK(ts_spline_new(x, f, 4, NULL, &s, &e) == TS_OK && s); /* NULL: defaults */
    ts_spline_free(s);
    for (size_t k = 0; k < sizeof deltas / sizeof deltas[0]; k++) {
        size_t sizes[2] = {sizeof(ts_spline_options) - 8 - deltas[k], sizeof(ts_spline_options) + 8 + deltas[k]};
        for (int w = 0; w < 2; w++) {
            o.struct_size = sizes[w];
            s = (ts_spline *)&e;
            CHECKF(ts_spline_new(x, f, 4, &o, &s, &e) == TS_ERR_VERSION && !s &&
                       e.status == TS_ERR_VERSION && e.index == TS_NO_INDEX &&
                       e.where == TS_WHERE_NONE,
                   "ts_spline_options.struct_size %zu", sizes[w]);
        }
    }
    o.struct_size = 0; /* not initialised (e.g. = {0}) */
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_ERR_VERSION && !s);
    /* the NULL arguments come first, the guard right after them */
    CHECK(ts_spline_new(NULL, f, 4, &o, &s, &e) == TS_ERR_NULL);
    CHECK(ts_spline_new(x, f, 1, &o, &s, &e) == TS_ERR_VERSION);
    /* an older, smaller struct: only struct_size is read */
    size_t small = offsetof(ts_spline_options, alpha);
    unsigned char *old = malloc(small);
    CHECK(old != NULL);
    if (old) {
        memset(old, 0, small);
        memcpy(old, &small, sizeof small); /* its struct_size */
        CHECK(ts_spline_new(x, f, 4, (const ts_spline_options *)(void *)old, &s, &e) == TS_ERR_VERSION &&
              !s);
        free(old);
    }

    ts_curve_options co;
    ts_curve_options_init(&co);
    CHECK(co.struct_size == sizeof(ts_curve_options));
    ts_curve *c = (ts_curve *)&e;
    CHECK(ts_curve_new(pts, 4, 2, &co, &c, &e) == TS_OK && c);
    ts_curve_free(c);
    co.struct_size = sizeof(ts_curve_options) - 8;
    CHECK(ts_curve_new(pts, 4, 2, &co, &c, &e) == TS_ERR_VERSION && !c && e.status == TS_ERR_VERSION);
    co.struct_size = 0;
    CHECK(ts_curve_new(pts, 4, 7, &co, &c, &e) == TS_ERR_VERSION); /* before the dimension */
    CHECK(ts_curve_new(NULL, 4, 2, &co, &c, &e) == TS_ERR_NULL);

    ts_surface_options so;
    ts_surface_options_init(&so);
    CHECK(so.struct_size == sizeof(ts_surface_options));
    ts_surface *sf = (ts_surface *)&e;
    CHECK(ts_surface_new(gx, 3, gy, 2, gz, &so, &sf, &e) == TS_OK && sf);
    ts_surface_free(sf);
    so.struct_size = sizeof(ts_surface_options) + 8;
    CHECK(ts_surface_new(gx, 3, gy, 2, gz, &so, &sf, &e) == TS_ERR_VERSION && !sf &&
          e.status == TS_ERR_VERSION);
    CHECK(ts_surface_new(gx, 1, gy, 2, gz, &so, &sf, &e) == TS_ERR_VERSION); /* before too few */
    CHECK(ts_surface_new(gx, 3, gy, 2, NULL, &so, &sf, &e) == TS_ERR_NULL);
}

static void test_reports(void)
{
    TH_CASE("interval reports");
    double x[] = {0, 1, 2, 3}, f[] = {1, 2, 0.5, 3};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_POSITIVE;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 4, &o, &s, NULL) == TS_OK);
    ts_line lo = {0, -1};
    ts_error e;

    ts_interval_report r = TS_INTERVAL_REPORT_INIT;
    CHECK(r.struct_size == sizeof r);
    CHECK(ts_spline_report(s, 1, &r) == TS_OK && r.x0 == 1 && r.x1 == 2 && r.certified);
    CHECK(r.struct_size == sizeof r);
    /* wrong size: refused and the struct left as it was */
    memset(&r, 0xA5, sizeof r);
    r.struct_size = sizeof r - 8;
    CHECK(ts_spline_report(s, 1, &r) == TS_ERR_VERSION);
    CHECK(r.struct_size == sizeof r - 8 && untouched(&r, sizeof r, 0xA5, sizeof r.struct_size));
    CHECK(ts_spline_report(NULL, 1, &r) == TS_ERR_VERSION); /* the guard first */
    r.struct_size = sizeof r;
    CHECK(ts_spline_report(NULL, 1, &r) == TS_ERR_NULL && isnan(r.x0)); /* reset */

    /* arrays: the first entry's guard; every entry written gets its own */
    ts_interval_report reps[3];
    memset(reps, 0, sizeof reps);
    reps[0].struct_size = sizeof reps[0];
    CHECK(ts_spline_certify(s, &lo, NULL, reps, &e) == TS_OK);
    for (int i = 0; i < 3; i++)
        CHECKF(reps[i].struct_size == sizeof reps[i] && reps[i].x0 == i && reps[i].certified,
               "certify entry %d", i);
    memset(reps, 0xA5, sizeof reps);
    reps[0].struct_size = 0;
    CHECK(ts_spline_certify(s, &lo, NULL, reps, &e) == TS_ERR_VERSION && e.status == TS_ERR_VERSION &&
          e.index == TS_NO_INDEX);
    CHECK(untouched(reps, sizeof reps, 0xA5, sizeof reps[0].struct_size));
    CHECK(ts_spline_certify(s, &lo, NULL, NULL, &e) == TS_OK); /* no reports: no guard */

    /* ts_interval_report_init */
    memset(reps, 0, sizeof reps);
    ts_interval_report_init(reps, 3);
    for (int i = 0; i < 3; i++)
        CHECK(reps[i].struct_size == sizeof reps[i] && isnan(reps[i].x0) &&
              isnan(reps[i].gap_lower) && reps[i].certified == 0 && reps[i].has_lower == 0);
    ts_interval_report_init(NULL, 3); /* no-op */
    ts_spline_free(s);

    TH_CASE("curve reports");
    double pts[] = {0.2, 0.2, 0.8, 0.2, 0.8, 0.8, 0.2, 0.8};
    ts_curve_options co;
    ts_curve_options_init(&co);
    co.closed = 1;
    co.has_lo[0] = co.has_lo[1] = co.has_hi[0] = co.has_hi[1] = 1;
    co.hi[0] = co.hi[1] = 1;
    ts_curve *c = NULL;
    CHECK(ts_curve_new(pts, 4, 2, &co, &c, NULL) == TS_OK);
    size_t nr = ts_curve_segments(c) * 2;
    ts_interval_report *cr = malloc(nr * sizeof *cr);
    CHECK(cr != NULL);
    if (cr) {
        memset(cr, 0, nr * sizeof *cr);
        cr[0].struct_size = sizeof *cr;
        CHECK(ts_curve_certify(c, cr, &e) == TS_OK);
        for (size_t i = 0; i < nr; i++)
            CHECK(cr[i].struct_size == sizeof *cr && cr[i].certified);
        cr[0].struct_size = sizeof *cr + 8;
        CHECK(ts_curve_certify(c, cr, &e) == TS_ERR_VERSION && e.status == TS_ERR_VERSION);
        int has[3] = {1, 1, 0};
        double lo3[3] = {0, 0, 0};
        CHECK(ts_curve_certify_box(c, has, lo3, NULL, NULL, cr, &e) == TS_ERR_VERSION);
        CHECK(cr[0].struct_size == sizeof *cr + 8 && cr[1].certified); /* untouched */
        ts_interval_report_init(cr, 1);
        CHECK(ts_curve_certify_box(c, has, lo3, NULL, NULL, cr, &e) == TS_OK &&
              cr[nr - 1].struct_size == sizeof *cr);
        free(cr);
    }
    ts_curve_free(c);
}

static void test_patch_reports(void)
{
    TH_CASE("patch reports");
    double gx[] = {0, 1, 2}, gy[] = {0, 1}, gz[] = {1, 2, 3, 2, 1, 2};
    ts_surface_options so;
    ts_surface_options_init(&so);
    so.shape = TS_SURFACE_POSITIVE;
    ts_surface *sf = NULL;
    CHECK(ts_surface_new(gx, 3, gy, 2, gz, &so, &sf, NULL) == TS_OK);
    ts_patch_report r = TS_PATCH_REPORT_INIT;
    CHECK(ts_surface_report(sf, 1, 0, &r) == TS_OK && r.i == 1 && r.certified &&
          r.struct_size == sizeof r);
    memset(&r, 0x5A, sizeof r);
    r.struct_size = sizeof r - 8;
    CHECK(ts_surface_report(sf, 1, 0, &r) == TS_ERR_VERSION);
    CHECK(untouched(&r, sizeof r, 0x5A, sizeof r.struct_size));
    CHECK(ts_surface_report(sf, 1, 0, NULL) == TS_ERR_NULL);

    ts_patch_report reps[2];
    ts_plane lo = {0, 0, -1};
    ts_error e;
    memset(reps, 0x5A, sizeof reps);
    reps[0].struct_size = 3;
    CHECK(ts_surface_certify(sf, &lo, NULL, reps, &e) == TS_ERR_VERSION &&
          e.status == TS_ERR_VERSION);
    CHECK(untouched(reps, sizeof reps, 0x5A, sizeof reps[0].struct_size));
    ts_patch_report_init(reps, 2);
    CHECK(reps[1].struct_size == sizeof reps[1] && isnan(reps[1].x0) && reps[1].certified == 0);
    CHECK(ts_surface_certify(sf, &lo, NULL, reps, &e) == TS_OK && reps[0].struct_size == sizeof r &&
          reps[1].struct_size == sizeof r && reps[1].certified);
    ts_patch_report_init(NULL, 2); /* no-op */
    ts_surface_free(sf);
}

int main(void)
{
    test_options();
    test_reports();
    test_patch_reports();
    TH_CASE("status");
    CHECK(strcmp(ts_status_name(TS_ERR_VERSION), "TS_ERR_VERSION") == 0);
    CHECK(strstr(ts_strerror(TS_ERR_VERSION), "struct_size") != NULL);
    CHECK(TS_ERR_VERSION == 30 && TS_ERR_CONDITION == 31 && TS_ERR_BOUND_GRID == 32 &&
          TS_ERR_BOUND_GRID + 1 == TS_STATUS_COUNT_);
    return th_report("struct_guard");
}
