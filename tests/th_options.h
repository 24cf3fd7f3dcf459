/* The paper's options (docs/method.md §3): paper form, three-point
 * arithmetic slopes, alpha = 1 — the library's defaults before 1.0.  Tests
 * whose expected values were derived for that form (tests/ref/core_ref.csv
 * and the closed forms of docs/method.md §3, §5) start from these instead of
 * ts_spline_options_init's defaults (docs/method.md §5.10). */
#ifndef TS_TH_OPTIONS_H
#define TS_TH_OPTIONS_H
#include "trigspline.h"

static inline void th_options_paper(ts_spline_options *o)
{
    ts_spline_options_init(o);
    o->form = TS_FORM_PAPER;
    o->slopes = TS_SLOPES_ARITHMETIC;
    o->alpha = 1.0;
}
#endif
