/* The constraint records' public functions: initialisers and the
 * per-interval report (docs/method.md §13). */
#include "internal.h"

#include <math.h>
#include <string.h>

void ts_constraint_init(ts_constraint *c, ts_constraint_kind kind)
{
    if (!c)
        return;
    memset(c, 0, sizeof *c);
    c->struct_size = sizeof *c;
    c->kind = kind;
    c->bound = TS_BOUND_CONSTANT;
    c->value = 0.0;
    c->px = c->py = NULL;
}

void ts_constraint_report_init(ts_constraint_report *r)
{
    if (!r)
        return;
    memset(r, 0, sizeof *r);
    r->struct_size = sizeof *r;
    r->gap = r->at = (double)NAN;
}

size_t ts_spline_constraints(const ts_spline *s)
{
    return s ? s->ncon : 0;
}

ts_status ts_spline_constraint_report(const ts_spline *s, size_t k, size_t i,
                                      ts_constraint_report *rep)
{
    if (rep && rep->struct_size != sizeof *rep)
        return TS_ERR_VERSION;
    if (!s || !rep)
        return TS_ERR_NULL;
    size_t sz = rep->struct_size;
    memset(rep, 0, sizeof *rep);
    rep->struct_size = sz;
    rep->gap = rep->at = (double)NAN;
    if (k >= s->ncon || i >= s->n)
        return TS_ERR_INDEX;
    ts__con_report(s, k, i, rep);
    return TS_OK;
}
