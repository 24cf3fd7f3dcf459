/*
 * trigspline fit in constant memory (CSV samples only).
 *
 * The data are read row by row (tsu_reader) into a window; a spline is built
 * on each chunk of CLI_CHUNK intervals plus a context of extra points on each
 * side, and only the chunk's own intervals are sampled.  The scheme is local:
 * slopes use at most two neighbours on each side (Akima), beta_i the slopes
 * and values at both knots of interval i, and the C¹ form the a of both
 * neighbours; so with a context of CTX0 = 16 points an interval's spline is
 * the one a whole-data build gives.  Certificate repairs in the C¹ form can
 * change a neighbour's a and so travel further; therefore every chunk border
 * is checked: the intervals within CTX/2 of the border must come out
 * bitwise identical (a, B, X) from both chunks that contain them, otherwise
 * both are rebuilt with four times the context (up to CTX_MAX), and a chunk
 * is written only after its right border was checked.  Interval errors that
 * come from a chunk's cut end (an infeasible interval or an overflowing
 * slope next to the cut) are retried with more context in the same way.
 *
 * Errors: bad rows (reader), x not increasing, data changing direction under
 * --shape monotone and scheme errors name their line.  Output starts only
 * after the first chunk was built, so inputs of up to CLI_CHUNK intervals are
 * validated completely before anything is written; an error in a later chunk
 * leaves what was already written to standard output (-o: the temporary file
 * is removed).
 */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CLI_CHUNK 4096
#define CTX0 16
#define CTX_MAX 2048

enum { ART_LEFT = -10, ART_RIGHT = -11 };

typedef struct stream {
    const cli_opts *o;
    const ts_spline_options *opt;
    const char *name;
    FILE *fp;
    tsu_reader *r;
    size_t chunk;
    cli_cols cols;
    double prev_x; /* last sample x written */
    /* points [base, base + len) */
    double *x, *f;
    unsigned long long *line;
    size_t base, len, cap;
    int eof;
    int dir; /* monotone: direction of the data so far */
    tsu_writer *w;
    cli_out out;
    int started;
    int debug; /* TRIGSPLINE_DEBUG: report border rebuilds */
    cli_overshoot ov; /* of the intervals written */
} stream;

typedef struct chunk {
    ts_spline *s;
    size_t wl, wr;     /* window: points [wl, wr] (global indices) */
    size_t e0, e1;     /* written intervals [e0, e1) */
    size_t lctx, rctx; /* context points wanted on each side */
    ts_status st;      /* last failure */
    ts_error err;
} chunk;

static size_t npts(const stream *s)
{
    return s->base + s->len;
}

int cli_can_stream(const cli_opts *o)
{
    return o->cmd == CLI_FIT && !o->json && !o->svg && !o->at && !o->alphas && !o->betas &&
           !o->grid_set && !o->samples_total && !o->step_set &&
           o->slopes != TS_SLOPES_PERIODIC && !o->no_stream;
}

static int grow(stream *s)
{
    size_t cap = s->cap ? s->cap * 2 : 8192;
    if (cap > SIZE_MAX / sizeof(unsigned long long))
        return cli_nomem();
    double *nx = realloc(s->x, cap * sizeof *nx);
    if (!nx)
        return cli_nomem();
    s->x = nx;
    double *nf = realloc(s->f, cap * sizeof *nf);
    if (!nf)
        return cli_nomem();
    s->f = nf;
    unsigned long long *nl = realloc(s->line, cap * sizeof *nl);
    if (!nl)
        return cli_nomem();
    s->line = nl;
    s->cap = cap;
    return CLI_OK;
}

/* Drop the points before global index keep. */
static void compact(stream *s, size_t keep)
{
    if (keep <= s->base)
        return;
    size_t drop = keep - s->base;
    if (drop > s->len)
        drop = s->len;
    s->len -= drop;
    memmove(s->x, s->x + drop, s->len * sizeof *s->x);
    memmove(s->f, s->f + drop, s->len * sizeof *s->f);
    memmove(s->line, s->line + drop, s->len * sizeof *s->line);
    s->base += drop;
}

/* The stream's own checks that span chunks: point (x, f) on line ln, the
 * next after the last one read, fails with st (the library's sentence). */
static int point_error(const stream *s, ts_status st, double x, double f,
                       unsigned long long ln)
{
    double x2[2] = {s->x[s->len - 1], x}, f2[2] = {s->f[s->len - 1], f};
    unsigned long long l2[2] = {s->line[s->len - 1], ln};
    ts_error e = {st, 1, TS_WHERE_POINT};
    return cli_report_build_error(s->o, s->opt, s->name, &s->cols, x2, f2, l2, 2, &e, st,
                                  npts(s) - 1);
}

/* Read until there are want points or the input ends. */
static int fill(stream *s, size_t want)
{
    tsu_io_error ie;
    const double *row;
    while (!s->eof && npts(s) < want) {
        tsu_io_status st = tsu_reader_next(s->r, &row, &ie);
        if (st == TSU_IO_END) {
            s->eof = 1;
            break;
        }
        if (st != TSU_IO_OK)
            return cli_report_io(&ie);
        unsigned long long ln = tsu_reader_line(s->r);
        if (tsu_reader_rows(s->r) == 1) {
            int rc = cli_cols_resolve(s->o, s->r, s->name, &s->cols);
            if (rc != CLI_OK)
                return rc;
        }
        double x, f;
        int k = cli_cols_take(s->o, s->r, s->name, row, &s->cols, &x, &f);
        if (k < 0)
            return CLI_DATA;
        if (k == 0)
            continue;
        if (s->len) {
            double px = s->x[s->len - 1], pf = s->f[s->len - 1];
            if (!(x > px))
                return point_error(s, TS_ERR_UNSORTED, x, f, ln);
            if (s->opt->shape == TS_SHAPE_MONOTONE) {
                /* docs/method.md §5.5 needs one direction over the whole data, not per chunk */
                int sg = (f > pf) - (f < pf);
                if (sg && !s->dir)
                    s->dir = sg;
                else if (sg && sg != s->dir)
                    return point_error(s, TS_ERR_NONMONOTONE, x, f, ln);
            }
        }
        if (s->len == s->cap) {
            int rc = grow(s);
            if (rc != CLI_OK)
                return rc;
        }
        s->x[s->len] = x;
        s->f[s->len] = f;
        s->line[s->len] = ln;
        s->len++;
    }
    return CLI_OK;
}

/* Explain the last failure of chunk c; returns the exit status. */
static int report(const stream *s, const chunk *c)
{
    size_t off = c->wl - s->base, np = npts(s) ? c->wr - c->wl + 1 : 0;
    return cli_report_build_error(s->o, s->opt, s->name, &s->cols, s->x + off, s->f + off,
                                  s->line + off, np, &c->err, c->st, c->wl);
}

/* Build c->s for c->e0, c->lctx, c->rctx.  Returns CLI_OK, ART_LEFT /
 * ART_RIGHT (a failure in the context that more context may cure; c->st,
 * c->err kept), or an exit status (message printed). */
static int chunk_build(stream *s, chunk *c)
{
    ts_spline_free(c->s);
    c->s = NULL;
    size_t want = c->e0 + s->chunk + c->rctx + 1;
    int rc = fill(s, want < c->e0 ? SIZE_MAX : want);
    if (rc != CLI_OK)
        return rc;
    size_t last = npts(s) ? npts(s) - 1 : 0;
    c->e1 = s->eof && last < c->e0 + s->chunk ? last : c->e0 + s->chunk;
    c->wl = c->e0 > c->lctx ? c->e0 - c->lctx : 0;
    c->wr = c->e1 + c->rctx < last ? c->e1 + c->rctx : last;
    if (c->wl < s->base)
        c->wl = s->base; /* cannot happen: compact keeps the pending window */
    size_t off = c->wl - s->base, np = c->wr - c->wl + 1;
    if (npts(s) == 0)
        np = 0;
    c->st = ts_spline_new(s->x + off, s->f + off, np, s->opt, &c->s, &c->err);
    if (c->st == TS_OK)
        return CLI_OK;
    /* failures that may come from the cut ends of the window */
    if ((c->st == TS_ERR_INFEASIBLE && c->err.where == TS_WHERE_INTERVAL) ||
        (c->st == TS_ERR_NONFINITE && c->err.where == TS_WHERE_POINT)) {
        size_t g = c->wl + c->err.index;
        int true_right = s->eof && c->wr == last;
        if (g < c->e0 && c->wl > 0 && c->lctx < CTX_MAX)
            return ART_LEFT;
        if (g >= c->e1 && !true_right && c->rctx < CTX_MAX)
            return ART_RIGHT;
    }
    return report(s, c);
}

/* Build with more right context while the failure is at the right cut. */
static int chunk_build_right(stream *s, chunk *c)
{
    for (;;) {
        int rc = chunk_build(s, c);
        if (rc != ART_RIGHT && rc != ART_LEFT)
            return rc;
        if (rc == ART_LEFT)
            return rc;
        c->rctx = c->rctx * 4 < CTX_MAX ? c->rctx * 4 : CTX_MAX;
        if (s->debug)
            fprintf(stderr, "trigspline: debug: chunk at interval %zu rebuilt with %zu points "
                            "of right context (%s next to the cut)\n",
                    c->e0, c->rctx, ts_strerror(c->st));
    }
}

/* Intervals near border E identical in both chunks (a, B, X bitwise)? */
static int border_equal(const chunk *a, const chunk *b, size_t E)
{
    size_t v = (a->rctx < b->lctx ? a->rctx : b->lctx) / 2;
    size_t lo = E > v ? E - v : 0, hi = E + v;
    /* not beyond a's own intervals on the left (its left border was checked
     * before) nor b's on the right */
    if (lo < a->e0)
        lo = a->e0;
    if (lo < b->wl)
        lo = b->wl;
    if (hi > b->e1)
        hi = b->e1;
    if (hi > a->wr)
        hi = a->wr;
    for (size_t g = lo; g < hi; g++) {
        double Ba[4], Xa[4], Bb[4], Xb[4], aa, ab;
        (void)ts_spline_control(a->s, g - a->wl, Ba, Xa);
        (void)ts_spline_control(b->s, g - b->wl, Bb, Xb);
        (void)ts_spline_a(a->s, g - a->wl, &aa);
        (void)ts_spline_a(b->s, g - b->wl, &ab);
        if (aa != ab)
            return 0;
        for (int l = 0; l < 4; l++)
            if (Ba[l] != Bb[l] || Xa[l] != Xb[l])
                return 0;
    }
    return 1;
}

static int emit(stream *s, const chunk *c, int last)
{
    char msg[TSU_IO_MSG_SIZE];
    int rc;
    if (!s->started) {
        rc = cli_out_open(&s->out, s->o->out ? s->o->out : "-", msg, sizeof msg);
        if (rc) {
            cli_error("%s", msg);
            return CLI_IO;
        }
        s->started = 1;
        s->w = tsu_writer_new(cli_out_file(&s->out), ',');
        if (!s->w)
            return cli_nomem();
        tsu_plot_buf hb = TSU_PLOT_BUF_INIT;
        if (cli_header_line(&s->cols, s->o->deriv, &hb) != 0) {
            tsu_plot_buf_free(&hb);
            return cli_nomem();
        }
        rc = tsu_writer_text(s->w, hb.data, hb.len);
        tsu_plot_buf_free(&hb);
        if (rc)
            goto werr;
    }
    cli_csv_sink sk = {s->w, &s->cols};
    rc = cli_sample_after(c->s, c->e0 - c->wl, c->e1 - c->wl, last, s->o->samples, s->o->deriv,
                          cli_sink_writer, &sk, &s->prev_x);
    cli_overshoot_add(&s->ov, c->s, c->e0 - c->wl, c->e1 - c->wl, c->wl);
    if (!rc)
        return CLI_OK;
werr:
    cli_error("cannot write %s: %s", s->o->out ? s->o->out : "standard output", strerror(rc));
    return CLI_IO;
}

static int is_last(const stream *s, const chunk *c)
{
    return s->eof && c->e1 + 1 == npts(s);
}

int cli_fit_stream(const cli_opts *o, const ts_spline_options *opt)
{
    stream s;
    chunk pend, next;
    tsu_io_error ie;
    int rc;
    memset(&s, 0, sizeof s);
    memset(&pend, 0, sizeof pend);
    memset(&next, 0, sizeof next);
    s.o = o;
    s.opt = opt;
    cli_overshoot_init(&s.ov);
    s.ov.warn_only = 1; /* only cli_overshoot_warn reads it */
    s.chunk = CLI_CHUNK;
    s.prev_x = -(double)INFINITY;
    const char *env = getenv("TRIGSPLINE_CHUNK");
    if (env && *env) {
        char *end;
        unsigned long v = strtoul(env, &end, 10);
        if (!*end && v >= 4 && v <= 1000000)
            s.chunk = (size_t)v;
    }
    env = getenv("TRIGSPLINE_DEBUG");
    s.debug = env && *env && strcmp(env, "0") != 0;
    if (strcmp(o->data, "-") == 0) {
        s.name = "<stdin>";
        s.fp = stdin;
    } else {
        s.name = o->data;
        s.fp = fopen(o->data, "rb");
        if (!s.fp) {
            cli_error("%s: cannot open: %s", o->data, strerror(errno));
            return CLI_IO;
        }
    }
    tsu_read_options ro;
    cli_read_options(o, &ro);
    if (tsu_reader_open(&s.r, s.fp, s.name, &ro, &ie) != TSU_IO_OK) {
        rc = cli_report_io(&ie);
        goto done;
    }
    if ((rc = cli_cols_select(o, s.r, s.name, &s.cols)) != CLI_OK)
        goto done;

    /* first chunk: no left context */
    pend.e0 = 0;
    pend.lctx = 0;
    pend.rctx = CTX0;
    rc = chunk_build_right(&s, &pend);
    if (rc == ART_LEFT)
        rc = report(&s, &pend); /* not expected: no left context */
    if (rc != CLI_OK)
        goto done;
    for (;;) {
        if ((rc = fill(&s, pend.e1 + 2)) != CLI_OK)
            goto done;
        if (is_last(&s, &pend)) {
            rc = emit(&s, &pend, 1);
            goto done;
        }
        size_t border = CTX0;
        next.e0 = pend.e1;
        next.lctx = border;
        next.rctx = CTX0;
        for (;;) {
            rc = chunk_build_right(&s, &next);
            if (rc == CLI_OK && border_equal(&pend, &next, next.e0))
                break;
            if (rc != CLI_OK && rc != ART_LEFT)
                goto done;
            /* the border needs more context on both sides */
            if (border >= CTX_MAX) {
                if (rc == ART_LEFT) {
                    rc = report(&s, &next);
                } else {
                    cli_error("%s:%llu: streaming: the C1 certificate repairs near this line "
                              "reach further than %d points; use --no-stream",
                              s.name, s.line[next.e0 - s.base], CTX_MAX);
                    rc = CLI_DATA;
                }
                goto done;
            }
            border = border * 4 < CTX_MAX ? border * 4 : CTX_MAX;
            if (s.debug)
                fprintf(stderr, "trigspline: debug: chunk border at interval %zu rebuilt with "
                                "%zu points of context\n",
                        next.e0, border);
            pend.rctx = border;
            next.lctx = border;
            rc = chunk_build_right(&s, &pend);
            if (rc == ART_LEFT)
                rc = report(&s, &pend); /* its left border was already checked */
            if (rc != CLI_OK)
                goto done;
        }
        rc = emit(&s, &pend, 0);
        if (rc != CLI_OK)
            goto done;
        ts_spline_free(pend.s);
        pend = next;
        next.s = NULL;
        compact(&s, pend.wl);
    }
done:
    if (s.w) {
        int wr = tsu_writer_free(s.w);
        if (wr && rc == CLI_OK) {
            cli_error("cannot write %s: %s", o->out ? o->out : "standard output", strerror(wr));
            rc = CLI_IO;
        }
    }
    if (s.started) {
        if (rc == CLI_OK) {
            char msg[TSU_IO_MSG_SIZE];
            if (cli_out_commit(&s.out, msg, sizeof msg)) {
                cli_error("%s", msg);
                rc = CLI_IO;
            } else {
                cli_overshoot_warn(&s.ov, &s.cols);
            }
        } else {
            if (!o->out || strcmp(o->out, "-") == 0)
                cli_error("the output written so far is incomplete");
            cli_out_abort(&s.out);
        }
    }
    if (o->verbose && s.cols.skipped)
        cli_error("%s: %llu row%s with missing values skipped", s.name, s.cols.skipped,
                  s.cols.skipped == 1 ? "" : "s");
    ts_spline_free(pend.s);
    ts_spline_free(next.s);
    tsu_reader_free(s.r);
    if (s.fp && s.fp != stdin)
        fclose(s.fp);
    free(s.x);
    free(s.f);
    free(s.line);
    return rc;
}
