/* ts__skip_proven (src/certificate.c, internal.h) for a spline without a
 * shape: certification never asks (ts__certify_range runs for a shape
 * only), but the helper must answer on its own: no boundary and no
 * monotone shape, so no interval is passed by a control-value proof and
 * the first interval asked for is returned, in every form.  With the
 * positive shape the same data's intervals are all proven (controls of
 * positive data with PCHIP-like slopes: f > 0 and B1, B2 > 0, checked here
 * from ts_spline_control), so the whole range is skipped. */
#include "internal.h"
#include "th.h"

int main(void)
{
    static const double x[6] = {0, 1, 2, 3, 4, 5}, f[6] = {1, 3, 2, 4, 3, 5};
    const ts_form forms[3] = {TS_FORM_PAPER, TS_FORM_C1, TS_FORM_GEOMETRIC};
    for (int k = 0; k < 3; k++) {
        for (int shaped = 0; shaped < 2; shaped++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = forms[k];
            o.shape = shaped ? TS_SHAPE_POSITIVE : TS_SHAPE_NONE;
            ts_spline *s = NULL;
            CHECK(ts_spline_new(x, f, 6, &o, &s, NULL) == TS_OK);
            if (!s)
                continue;
            int inside = 1;
            for (size_t i = 0; i < 5; i++) {
                double B[4];
                CHECK(ts_spline_control(s, i, B, NULL) == TS_OK);
                inside &= B[0] > 0 && B[1] > 0 && B[2] > 0 && B[3] > 0;
            }
            CHECK(inside);
            size_t want0 = shaped ? 5 : 0, want2 = shaped ? 5 : 2;
            CHECKF(ts__skip_proven(s, 0, 5) == want0, "form %d shape %d", (int)forms[k], shaped);
            CHECKF(ts__skip_proven(s, 2, 5) == want2, "form %d shape %d", (int)forms[k], shaped);
            ts_spline_free(s);
        }
    }
    return th_report("test_skip_proven");
}
