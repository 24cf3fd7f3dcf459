/* SVG plots for the tool side (see tsu_plot.h).  Standard C only. */
#include "tsu_plot.h"

#include <ctype.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ */
/* allocation (with the test hook)                                      */
/* ------------------------------------------------------------------ */

static long alloc_budget = -1;

void tsu_plot_test_fail_alloc_after(long n) { alloc_budget = n < 0 ? -1 : n; }

static int alloc_allowed(void)
{
    if (alloc_budget == 0)
        return 0;
    if (alloc_budget > 0)
        alloc_budget--;
    return 1;
}

static void *pl_malloc(size_t n) { return alloc_allowed() ? malloc(n ? n : 1) : NULL; }
static void *pl_realloc(void *p, size_t n) { return alloc_allowed() ? realloc(p, n ? n : 1) : NULL; }

static char *pl_strdup(const char *s)
{
    size_t n = strlen(s);
    char *d = pl_malloc(n + 1);
    if (d)
        memcpy(d, s, n + 1);
    return d;
}

const char *tsu_plot_strerror(tsu_plot_status st)
{
    switch (st) {
    case TSU_PLOT_OK: return "success";
    case TSU_PLOT_ERR_NULL: return "a required pointer is NULL";
    case TSU_PLOT_ERR_NOMEM: return "out of memory";
    case TSU_PLOT_ERR_OVERFLOW: return "size overflow";
    case TSU_PLOT_ERR_ARG: return "invalid argument";
    case TSU_PLOT_ERR_IO: return "output error";
    }
    return "unknown plot status";
}

/* ------------------------------------------------------------------ */
/* string buffer                                                        */
/* ------------------------------------------------------------------ */

void tsu_plot_buf_init(tsu_plot_buf *b)
{
    if (b) {
        b->data = NULL;
        b->len = b->cap = 0;
    }
}

void tsu_plot_buf_free(tsu_plot_buf *b)
{
    if (b) {
        free(b->data);
        tsu_plot_buf_init(b);
    }
}

static tsu_plot_status buf_reserve(tsu_plot_buf *b, size_t extra)
{
    if (extra > SIZE_MAX - 1 - b->len)
        return TSU_PLOT_ERR_OVERFLOW;
    size_t need = b->len + extra + 1;
    if (b->data && need <= b->cap)
        return TSU_PLOT_OK;
    size_t cap = b->cap < 256 ? 256 : b->cap;
    while (cap < need)
        cap = cap > SIZE_MAX / 2 ? need : cap * 2;
    char *d = pl_realloc(b->data, cap);
    if (!d)
        return TSU_PLOT_ERR_NOMEM;
    if (!b->data)
        d[0] = '\0';
    b->data = d;
    b->cap = cap;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_buf_append(tsu_plot_buf *b, const char *s, size_t n)
{
    if (!b || (!s && n))
        return TSU_PLOT_ERR_NULL;
    tsu_plot_status st = buf_reserve(b, n);
    if (st)
        return st;
    if (n)
        memcpy(b->data + b->len, s, n);
    b->len += n;
    b->data[b->len] = '\0';
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_buf_puts(tsu_plot_buf *b, const char *s)
{
    if (!s)
        return TSU_PLOT_ERR_NULL;
    return tsu_plot_buf_append(b, s, strlen(s));
}

tsu_plot_status tsu_plot_buf_vprintf(tsu_plot_buf *b, const char *fmt, va_list ap)
{
    if (!b || !fmt)
        return TSU_PLOT_ERR_NULL;
    va_list ap2;
    va_copy(ap2, ap);
    int n = vsnprintf(NULL, 0, fmt, ap);
    tsu_plot_status st = TSU_PLOT_ERR_ARG;
    if (n >= 0) {
        st = buf_reserve(b, (size_t)n);
        if (!st) {
            vsnprintf(b->data + b->len, (size_t)n + 1, fmt, ap2);
            b->len += (size_t)n;
        }
    }
    va_end(ap2);
    return st;
}

tsu_plot_status tsu_plot_buf_printf(tsu_plot_buf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    tsu_plot_status st = tsu_plot_buf_vprintf(b, fmt, ap);
    va_end(ap);
    return st;
}

/* Decode one UTF-8 character at s (NUL-terminated); returns its length and
 * the code point, or length 1 and U+FFFD for an invalid sequence. */
static size_t utf8_next(const unsigned char *s, unsigned long *cp)
{
    unsigned c = s[0];
    size_t len;
    unsigned long v, min;
    if (c < 0x80) {
        *cp = c;
        return 1;
    } else if (c >= 0xC2 && c <= 0xDF) {
        len = 2, v = c & 0x1Fu, min = 0x80;
    } else if (c >= 0xE0 && c <= 0xEF) {
        len = 3, v = c & 0x0Fu, min = 0x800;
    } else if (c >= 0xF0 && c <= 0xF4) {
        len = 4, v = c & 0x07u, min = 0x10000;
    } else {
        *cp = 0xFFFD;
        return 1;
    }
    for (size_t k = 1; k < len; k++) {
        if ((s[k] & 0xC0u) != 0x80u) {
            *cp = 0xFFFD;
            return 1;
        }
        v = (v << 6) | (s[k] & 0x3Fu);
    }
    if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF) || v == 0xFFFE || v == 0xFFFF) {
        *cp = 0xFFFD;
        return 1;
    }
    *cp = v;
    return len;
}

/* Characters shown (for width estimates). */
static size_t utf8_count(const char *s)
{
    size_t n = 0;
    unsigned long cp;
    const unsigned char *u = (const unsigned char *)s;
    while (*u) {
        u += utf8_next(u, &cp);
        n++;
    }
    return n;
}

tsu_plot_status tsu_plot_buf_xml(tsu_plot_buf *b, const char *text)
{
    if (!b || !text)
        return TSU_PLOT_ERR_NULL;
    size_t old = b->len;
    const unsigned char *u = (const unsigned char *)text;
    char tmp[16];
    tsu_plot_status st = TSU_PLOT_OK;
    while (*u && !st) {
        unsigned long cp;
        u += utf8_next(u, &cp);
        const char *rep = NULL;
        size_t rn = 0;
        switch (cp) {
        case '&': rep = "&amp;"; break;
        case '<': rep = "&lt;"; break;
        case '>': rep = "&gt;"; break;
        case '"': rep = "&quot;"; break;
        case '\'': rep = "&#39;"; break;
        default:
            if (cp < 0x20 || cp == 0x7F) {
                tmp[0] = ' ', rn = 1;
            } else if (cp < 0x80) {
                tmp[0] = (char)cp, rn = 1;
            } else {
                int k = snprintf(tmp, sizeof tmp, "&#x%lX;", cp);
                rn = k > 0 ? (size_t)k : 0;
            }
            rep = tmp;
        }
        if (rep != tmp)
            rn = strlen(rep);
        st = tsu_plot_buf_append(b, rep, rn);
    }
    if (st && b->data) {
        b->len = old;
        b->data[old] = '\0';
    }
    return st;
}

/* ------------------------------------------------------------------ */
/* ticks                                                                */
/* ------------------------------------------------------------------ */

static double p10(int e) { return pow(10.0, (double)e); } /* exact for 0 <= e <= 22 */

/* q * 10^e, correctly rounded when |e| <= 22 */
static double scaled(long long q, int e)
{
    return e >= 0 ? (double)q * p10(e) : (double)q / p10(-e);
}

static int ndigits(unsigned long long v)
{
    int n = 1;
    while (v >= 10) {
        v /= 10;
        n++;
    }
    return n;
}

/* label of q * 10^e shown with the factor 10^shift removed: exact digits */
static void tick_label(long long q, int e, int shift, char *out, size_t cap)
{
    char dig[80];
    unsigned long long a = q < 0 ? 0ULL - (unsigned long long)q : (unsigned long long)q;
    int z = e - shift; /* > 0: trailing zeros; < 0: -z decimals */
    int dec = z < 0 ? -z : 0;
    if (dec > 40)
        dec = 40;
    if (z > 20)
        z = 20;
    /* |q| with at least dec + 1 digits */
    int nd = snprintf(dig, sizeof dig, "%0*llu", dec + 1, a);
    char res[100];
    size_t k = 0;
    if (q < 0)
        res[k++] = '-';
    for (int i = 0; i < nd; i++) {
        if (dec && i == nd - dec)
            res[k++] = '.';
        res[k++] = dig[i];
    }
    for (int i = 0; a && i < z; i++) /* no "000" for zero */
        res[k++] = '0';
    res[k] = '\0';
    if (k >= cap)
        k = cap - 1;
    memcpy(out, res, k);
    out[k] = '\0';
}

static int range_ok(double lo, double hi)
{
    return fabs(lo) <= TSU_PLOT_MAX_ABS && fabs(hi) <= TSU_PLOT_MAX_ABS;
}

/* a fixed range wide enough for distinct labels */
static int span_ok(double lo, double hi)
{
    double mag = fmax(fabs(lo), fabs(hi));
    double span = hi - lo;
    return span > mag * 1e-10 && span >= 1e-200;
}

tsu_plot_status tsu_plot_ticks_compute(double lo, double hi, tsu_plot_range_mode mode,
                                     tsu_plot_ticks *t)
{
    if (!t)
        return TSU_PLOT_ERR_NULL;
    memset(t, 0, sizeof *t);
    if (!range_ok(lo, hi) || (mode != TSU_PLOT_RANGE_AUTO && mode != TSU_PLOT_RANGE_FIXED))
        return TSU_PLOT_ERR_ARG;
    if (mode == TSU_PLOT_RANGE_FIXED) {
        if (!(lo < hi) || !span_ok(lo, hi))
            return TSU_PLOT_ERR_ARG;
    } else {
        if (!(lo <= hi))
            return TSU_PLOT_ERR_ARG;
        if (!span_ok(lo, hi)) {
            double mid = 0.5 * lo + 0.5 * hi;
            double half = 0.1 * fabs(mid);
            if (!(half >= 1e-200) || !span_ok(mid - half, mid + half))
                mid = 0.0, half = 1.0;
            lo = mid - half;
            hi = mid + half;
        } else {
            double pad = 0.04 * (hi - lo);
            lo -= pad;
            hi += pad;
        }
    }
    double span = hi - lo;
    double mag = fmax(fabs(lo), fabs(hi));
    int e0 = (int)floor(log10(span)) - 1;
    static const int mants[3] = {1, 2, 5};
    int best_e = 0, best_m = 0;
    double best_score = HUGE_VAL, best_k0 = 0, best_k1 = -1;
    for (int e = e0 - 1; e <= e0 + 2; e++) {
        for (int j = 0; j < 3; j++) {
            double step = scaled(mants[j], e);
            double tol = 1e-9 + 8 * DBL_EPSILON * mag / step;
            double k0 = ceil(lo / step - tol), k1 = floor(hi / step + tol);
            double cnt = k1 - k0 + 1;
            double score = (cnt >= 4 && cnt <= 8) ? fabs(cnt - 6) : 100 + (cnt < 4 ? 4 - cnt : cnt - 8);
            if (score <= best_score) { /* ascending steps: ties go to the larger */
                best_score = score;
                best_e = e, best_m = mants[j];
                best_k0 = k0, best_k1 = k1;
            }
        }
    }
    t->lo = lo;
    t->hi = hi;
    t->step = scaled(best_m, best_e);
    size_t n = 0;
    long long qs[TSU_PLOT_MAX_TICKS];
    unsigned long long qmax = 0;
    for (double k = best_k0; k <= best_k1 && n < TSU_PLOT_MAX_TICKS; k += 1.0) {
        long long q = (long long)k * best_m;
        unsigned long long a = q < 0 ? 0ULL - (unsigned long long)q : (unsigned long long)q;
        if (a > qmax)
            qmax = a;
        qs[n++] = q;
    }
    int P = ndigits(qmax) - 1 + best_e; /* decimal exponent of the largest |tick| */
    int shift = 0;
    if (qmax > 0 && (P <= -4 || (P >= 5 && (P - best_e <= 3 || P >= 10))))
        shift = P;
    t->exponent = shift;
    t->n = n;
    for (size_t i = 0; i < n; i++) {
        double v = scaled(qs[i], best_e);
        t->value[i] = v < lo ? lo : v > hi ? hi : v;
        tick_label(qs[i], best_e, shift, t->label[i], TSU_PLOT_LABEL_MAX);
    }
    return TSU_PLOT_OK;
}

/* ------------------------------------------------------------------ */
/* plot object                                                          */
/* ------------------------------------------------------------------ */

enum kind { K_POINTS, K_POLY, K_LINE, K_REGION };

typedef struct series {
    enum kind kind;
    char *label;      /* NULL: no legend entry */
    char color[24];
    int explicit_color;
    double width, marker_r, opacity;
    int dash, markers;
    double *xy;       /* n (x, y) pairs */
    size_t n;
    double m, c;      /* K_LINE, K_REGION */
    tsu_plot_side side;
} series;

struct tsu_plot {
    unsigned w, h;
    char *title, *xlabel, *ylabel;
    int fixed[2];
    double rng[2][2];
    int equal, xmldecl, grid;
    tsu_plot_legend legend;
    double simplify;
    series *s;
    size_t ns, cap;
    size_t next_color;
    tsu_plot_tick_fn tick_fn[2];
    void *tick_ctx[2];
};

static const char *const palette[8] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                       "#E69F00", "#56B4E9", "#000000", "#F0E442"};

const char *tsu_plot_palette(size_t i) { return palette[i % 8]; }

tsu_plot_status tsu_plot_new(unsigned width_px, unsigned height_px, tsu_plot **out)
{
    if (!out)
        return TSU_PLOT_ERR_NULL;
    *out = NULL;
    if (width_px == 0)
        width_px = TSU_PLOT_DEFAULT_WIDTH;
    if (height_px == 0)
        height_px = TSU_PLOT_DEFAULT_HEIGHT;
    if (width_px < TSU_PLOT_MIN_SIZE || width_px > TSU_PLOT_MAX_SIZE ||
        height_px < TSU_PLOT_MIN_SIZE || height_px > TSU_PLOT_MAX_SIZE)
        return TSU_PLOT_ERR_ARG;
    tsu_plot *p = pl_malloc(sizeof *p);
    if (!p)
        return TSU_PLOT_ERR_NOMEM;
    memset(p, 0, sizeof *p);
    p->w = width_px;
    p->h = height_px;
    p->xmldecl = 1;
    p->grid = 1;
    p->simplify = 0.1;
    p->legend = TSU_PLOT_LEGEND_AUTO;
    *out = p;
    return TSU_PLOT_OK;
}

void tsu_plot_free(tsu_plot *p)
{
    if (!p)
        return;
    for (size_t i = 0; i < p->ns; i++) {
        free(p->s[i].label);
        free(p->s[i].xy);
    }
    free(p->s);
    free(p->title);
    free(p->xlabel);
    free(p->ylabel);
    free(p);
}

/* replace *dst by a copy of src (NULL/"" clears) */
static tsu_plot_status set_text(char **dst, const char *src)
{
    char *d = NULL;
    if (src && *src) {
        d = pl_strdup(src);
        if (!d)
            return TSU_PLOT_ERR_NOMEM;
    }
    free(*dst);
    *dst = d;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_set_title(tsu_plot *p, const char *title)
{
    return p ? set_text(&p->title, title) : TSU_PLOT_ERR_NULL;
}

tsu_plot_status tsu_plot_set_labels(tsu_plot *p, const char *xlabel, const char *ylabel)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    char *x = NULL, *y = NULL;
    if (set_text(&x, xlabel) || set_text(&y, ylabel)) {
        free(x);
        return TSU_PLOT_ERR_NOMEM;
    }
    free(p->xlabel);
    free(p->ylabel);
    p->xlabel = x;
    p->ylabel = y;
    return TSU_PLOT_OK;
}

static tsu_plot_status set_range(tsu_plot *p, int axis, double lo, double hi)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    if (isnan(lo) && isnan(hi)) {
        p->fixed[axis] = 0;
        return TSU_PLOT_OK;
    }
    if (!range_ok(lo, hi) || !(lo < hi) || !span_ok(lo, hi))
        return TSU_PLOT_ERR_ARG;
    p->fixed[axis] = 1;
    p->rng[axis][0] = lo;
    p->rng[axis][1] = hi;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_set_xrange(tsu_plot *p, double lo, double hi) { return set_range(p, 0, lo, hi); }
tsu_plot_status tsu_plot_set_yrange(tsu_plot *p, double lo, double hi) { return set_range(p, 1, lo, hi); }

tsu_plot_status tsu_plot_set_equal_aspect(tsu_plot *p, int on)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    p->equal = on != 0;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_set_legend(tsu_plot *p, tsu_plot_legend where)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    if (!(where >= TSU_PLOT_LEGEND_AUTO && where <= TSU_PLOT_LEGEND_LOWER_RIGHT))
        return TSU_PLOT_ERR_ARG;
    p->legend = where;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_set_xml_declaration(tsu_plot *p, int on)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    p->xmldecl = on != 0;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_set_grid(tsu_plot *p, int on)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    p->grid = on != 0;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_set_simplify(tsu_plot *p, double tol_px)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    if (!(tol_px >= 0 && tol_px <= 10))
        return TSU_PLOT_ERR_ARG;
    p->simplify = tol_px;
    return TSU_PLOT_OK;
}

static int color_ok(const char *c)
{
    size_t n = strlen(c);
    if (c[0] == '#') {
        if (n != 4 && n != 7)
            return 0;
        for (size_t i = 1; i < n; i++) {
            char ch = c[i];
            if (!((ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'f') || (ch >= 'A' && ch <= 'F')))
                return 0;
        }
        return 1;
    }
    if (n < 1 || n > 20)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!((c[i] >= 'a' && c[i] <= 'z') || (c[i] >= 'A' && c[i] <= 'Z')))
            return 0;
    return 1;
}

static tsu_plot_status style_ok(const tsu_plot_style *st)
{
    if (!st)
        return TSU_PLOT_OK;
    if (st->color && st->color[0] && !color_ok(st->color))
        return TSU_PLOT_ERR_ARG;
    if (!(st->width >= 0 && st->width <= 50) || !(st->marker_radius >= 0 && st->marker_radius <= 50))
        return TSU_PLOT_ERR_ARG;
    if (!(st->fill_opacity >= 0 && st->fill_opacity <= 1) || st->dash < 0 || st->dash > 2)
        return TSU_PLOT_ERR_ARG;
    return TSU_PLOT_OK;
}

static int same_color(const char *a, const char *b)
{
    for (; *a && *b; a++, b++) {
        char ca = (char)tolower((unsigned char)*a), cb = (char)tolower((unsigned char)*b);
        if (ca != cb)
            return 0;
    }
    return *a == *b;
}

static int color_used(const tsu_plot *p, const char *c)
{
    for (size_t i = 0; i < p->ns; i++)
        if (p->s[i].explicit_color && same_color(p->s[i].color, c))
            return 1;
    return 0;
}

/* Validate, copy data, append a series.  On failure the plot is unchanged. */
static tsu_plot_status add_series(tsu_plot *p, enum kind kind, const double *x, const double *y,
                                 size_t n, const char *label, const tsu_plot_style *st,
                                 double m, double c, tsu_plot_side side)
{
    if (!p || (n && (!x || !y)))
        return TSU_PLOT_ERR_NULL;
    tsu_plot_status rc = style_ok(st);
    if (rc)
        return rc;
    if (n > SIZE_MAX / (2 * sizeof(double)))
        return TSU_PLOT_ERR_OVERFLOW;
    if (p->ns == p->cap && p->cap > SIZE_MAX / 2 / sizeof(series))
        return TSU_PLOT_ERR_OVERFLOW;
    series s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.n = n;
    s.m = m;
    s.c = c;
    s.side = side;
    if (n) {
        s.xy = pl_malloc(n * 2 * sizeof(double));
        if (!s.xy)
            return TSU_PLOT_ERR_NOMEM;
        for (size_t i = 0; i < n; i++) {
            s.xy[2 * i] = x[i];
            s.xy[2 * i + 1] = y[i];
        }
    }
    if (label && *label && !(s.label = pl_strdup(label))) {
        free(s.xy);
        return TSU_PLOT_ERR_NOMEM;
    }
    if (p->ns == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 8;
        series *ns = pl_realloc(p->s, cap * sizeof(series));
        if (!ns) {
            free(s.xy);
            free(s.label);
            return TSU_PLOT_ERR_NOMEM;
        }
        p->s = ns;
        p->cap = cap;
    }
    /* style, with the defaults of tsu_plot.h */
    tsu_plot_style d;
    memset(&d, 0, sizeof d);
    if (st)
        d = *st;
    if (d.color && d.color[0]) {
        memcpy(s.color, d.color, strlen(d.color) + 1);
        s.explicit_color = 1;
    } else { /* next palette colour no earlier series was given explicitly */
        for (int tries = 0; tries < 8 && color_used(p, palette[p->next_color % 8]); tries++)
            p->next_color++;
        memcpy(s.color, palette[p->next_color % 8], 8);
        p->next_color++;
    }
    s.dash = d.dash;
    s.markers = d.markers != 0;
    s.width = d.width > 0 ? d.width : kind == K_POLY ? (d.dash ? 1.25 : 2.0) : 1.5;
    s.marker_r = d.marker_radius > 0 ? d.marker_radius : kind == K_POINTS ? 3.5 : 2.5;
    s.opacity = d.fill_opacity > 0 ? d.fill_opacity : 0.13;
    p->s[p->ns++] = s;
    return TSU_PLOT_OK;
}

tsu_plot_status tsu_plot_add_points(tsu_plot *p, const double *x, const double *y, size_t n,
                                  const char *label, const tsu_plot_style *st)
{
    return add_series(p, K_POINTS, x, y, n, label, st, 0, 0, TSU_PLOT_FORBID_BELOW);
}

tsu_plot_status tsu_plot_add_polyline(tsu_plot *p, const double *x, const double *y, size_t n,
                                    const char *label, const tsu_plot_style *st)
{
    return add_series(p, K_POLY, x, y, n, label, st, 0, 0, TSU_PLOT_FORBID_BELOW);
}

tsu_plot_status tsu_plot_add_polygon(tsu_plot *p, const double *x, const double *y, size_t n,
                                   const char *label, const tsu_plot_style *st)
{
    tsu_plot_style d;
    memset(&d, 0, sizeof d);
    if (st)
        d = *st;
    if (d.dash == 0)
        d.dash = 1;
    d.markers = 1;
    return add_series(p, K_POLY, x, y, n, label, &d, 0, 0, TSU_PLOT_FORBID_BELOW);
}

tsu_plot_status tsu_plot_add_line(tsu_plot *p, double m, double c, const char *label,
                                const tsu_plot_style *st)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    if (!isfinite(m) || !isfinite(c))
        return TSU_PLOT_ERR_ARG;
    return add_series(p, K_LINE, NULL, NULL, 0, label, st, m, c, TSU_PLOT_FORBID_BELOW);
}

tsu_plot_status tsu_plot_add_region(tsu_plot *p, tsu_plot_side side, double m, double c,
                                  const char *label, const tsu_plot_style *st)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    if (!isfinite(m) || !isfinite(c) || (side != TSU_PLOT_FORBID_BELOW && side != TSU_PLOT_FORBID_ABOVE))
        return TSU_PLOT_ERR_ARG;
    return add_series(p, K_REGION, NULL, NULL, 0, label, st, m, c, side);
}

tsu_plot_status tsu_plot_add_floor(tsu_plot *p, double level, const char *label,
                                 const tsu_plot_style *st)
{
    return tsu_plot_add_region(p, TSU_PLOT_FORBID_BELOW, 0.0, level, label, st);
}

tsu_plot_status tsu_plot_add_ceiling(tsu_plot *p, double level, const char *label,
                                   const tsu_plot_style *st)
{
    return tsu_plot_add_region(p, TSU_PLOT_FORBID_ABOVE, 0.0, level, label, st);
}

/* ------------------------------------------------------------------ */
/* layout                                                               */
/* ------------------------------------------------------------------ */

#define FS_TICK 12.0
#define FS_LABEL 14.0
#define FS_TITLE 16.0
#define FS_LEGEND 12.0
#define CHAR_W 0.58   /* average advance of a sans-serif character, in em */
#define TICK_LEN 5.0
#define LEG_ROW 18.0
#define LEG_SWATCH 28.0

enum { LG_NONE, LG_OUTSIDE, LG_UR, LG_UL, LG_LL, LG_LR, LG_R, LG_L, LG_T, LG_B, LG_C };

typedef struct layout {
    double L, T, PW, PH;
    tsu_plot_ticks tx, ty;
    int lg;               /* LG_* */
    double lgx, lgy, lgw, lgh;
    size_t nleg;
} layout;

static double text_w(const char *s, double fs) { return (double)utf8_count(s) * CHAR_W * fs; }

static int valid_xy(double x, double y)
{
    return fabs(x) <= TSU_PLOT_MAX_ABS && fabs(y) <= TSU_PLOT_MAX_ABS;
}

/* the data extents (auto ranges before padding) */
static void data_extent(const tsu_plot *p, double ext[2][2])
{
    double xl = HUGE_VAL, xh = -HUGE_VAL, yl = HUGE_VAL, yh = -HUGE_VAL;
    for (size_t i = 0; i < p->ns; i++) {
        const series *s = &p->s[i];
        if (s->kind != K_POINTS && s->kind != K_POLY)
            continue;
        for (size_t j = 0; j < s->n; j++) {
            double x = s->xy[2 * j], y = s->xy[2 * j + 1];
            if (!valid_xy(x, y))
                continue;
            xl = fmin(xl, x), xh = fmax(xh, x);
            yl = fmin(yl, y), yh = fmax(yh, y);
        }
    }
    if (p->fixed[0]) {
        xl = p->rng[0][0], xh = p->rng[0][1];
    } else if (!(xl <= xh)) {
        xl = 0, xh = 1;
    }
    for (size_t i = 0; i < p->ns; i++) {
        const series *s = &p->s[i];
        if (s->kind != K_LINE && s->kind != K_REGION)
            continue;
        for (int e = 0; e < 2; e++) {
            double y = s->m * (e ? xh : xl) + s->c;
            if (fabs(y) <= TSU_PLOT_MAX_ABS)
                yl = fmin(yl, y), yh = fmax(yh, y);
        }
    }
    if (!(yl <= yh))
        yl = 0, yh = 1;
    ext[0][0] = xl, ext[0][1] = xh, ext[1][0] = yl, ext[1][1] = yh;
}

static double ticks_label_w(const tsu_plot_ticks *t)
{
    double w = 0;
    for (size_t i = 0; i < t->n; i++)
        w = fmax(w, text_w(t->label[i], FS_TICK));
    return w;
}

static void legend_size(const tsu_plot *p, layout *ly)
{
    double tw = 0;
    ly->nleg = 0;
    for (size_t i = 0; i < p->ns; i++)
        if (p->s[i].label) {
            ly->nleg++;
            tw = fmax(tw, text_w(p->s[i].label, FS_LEGEND));
        }
    ly->lgw = 10 + LEG_SWATCH + 8 + tw + 10;
    ly->lgh = 8 + (double)ly->nleg * LEG_ROW;
}

/* margins and plot area from the ticks, legend placement class */
static void place_area(const tsu_plot *p, layout *ly)
{
    double top = 12, bottom = 10, left = 10, right = 16;
    if (p->title)
        top += FS_TITLE + 12;
    if (ly->ty.exponent)
        top += FS_TICK + 4;
    else
        top += 4;
    if (p->ylabel)
        left += FS_LABEL + 8;
    left += ticks_label_w(&ly->ty) + TICK_LEN + 5;
    bottom += TICK_LEN + 4 + FS_TICK;
    if (p->xlabel || ly->tx.exponent)
        bottom += FS_LABEL + 10;
    if (ly->tx.n)
        right = fmax(right, 0.5 * text_w(ly->tx.label[ly->tx.n - 1], FS_TICK) + 6);
    if (ly->lg == LG_OUTSIDE)
        right = 12 + ly->lgw + 12;
    ly->L = floor(left);
    ly->T = floor(top);
    ly->PW = floor((double)p->w - ly->L - right);
    ly->PH = floor((double)p->h - ly->T - bottom);
    if (ly->PW < 20)
        ly->PW = 20;
    if (ly->PH < 20)
        ly->PH = 20;
}

static void custom_ticks(const tsu_plot *p, int a, tsu_plot_ticks *t)
{
    if (!p->tick_fn[a])
        return;
    t->n = 0;
    t->exponent = 0;
    p->tick_fn[a](p->tick_ctx[a], t);
    if (t->n > TSU_PLOT_MAX_TICKS)
        t->n = TSU_PLOT_MAX_TICKS;
    for (size_t i = 0; i < t->n; i++)
        t->label[i][TSU_PLOT_LABEL_MAX - 1] = 0;
}

static void base_ticks(const tsu_plot *p, double ext[2][2], layout *ly)
{
    tsu_plot_ticks *t[2] = {&ly->tx, &ly->ty};
    for (int a = 0; a < 2; a++) {
        if (p->fixed[a])
            tsu_plot_ticks_compute(p->rng[a][0], p->rng[a][1], TSU_PLOT_RANGE_FIXED, t[a]);
        else
            tsu_plot_ticks_compute(ext[a][0], ext[a][1], TSU_PLOT_RANGE_AUTO, t[a]);
        custom_ticks(p, a, t[a]);
    }
}

tsu_plot_status tsu_plot_set_tick_fn(tsu_plot *p, int axis, tsu_plot_tick_fn fn, void *ctx)
{
    if (!p)
        return TSU_PLOT_ERR_NULL;
    if (axis != 0 && axis != 1)
        return TSU_PLOT_ERR_ARG;
    p->tick_fn[axis] = fn;
    p->tick_ctx[axis] = ctx;
    return TSU_PLOT_OK;
}

/* equal aspect: from the base ranges, widen one axis about its centre */
static void apply_aspect(layout *ly, const tsu_plot_ticks base[2])
{
    double ux = (base[0].hi - base[0].lo) / ly->PW, uy = (base[1].hi - base[1].lo) / ly->PH;
    int a = ux > uy ? 1 : 0; /* the axis to widen */
    double len = a ? ly->PH : ly->PW;
    double mid = 0.5 * base[a].lo + 0.5 * base[a].hi, half = 0.5 * fmax(ux, uy) * len;
    ly->tx = base[0];
    ly->ty = base[1];
    tsu_plot_ticks nt;
    if (tsu_plot_ticks_compute(mid - half, mid + half, TSU_PLOT_RANGE_FIXED, &nt) == TSU_PLOT_OK)
        *(a ? &ly->ty : &ly->tx) = nt;
}

static void area_with_ticks(const tsu_plot *p, double ext[2][2], layout *ly)
{
    base_ticks(p, ext, ly);
    place_area(p, ly);
    if (p->equal) {
        tsu_plot_ticks base[2] = {ly->tx, ly->ty};
        for (int it = 0; it < 3; it++) {
            apply_aspect(ly, base);
            place_area(p, ly);
        }
        apply_aspect(ly, base);
    }
}

/* ---- mapping and clipping -------------------------------------------- */

static int to_px(const layout *ly, double x, double y, double *px, double *py)
{
    if (!valid_xy(x, y))
        return 0;
    double u = (x - ly->tx.lo) / (ly->tx.hi - ly->tx.lo);
    double v = (y - ly->ty.lo) / (ly->ty.hi - ly->ty.lo);
    if (!(fabs(u) <= 1e150 && fabs(v) <= 1e150))
        return 0;
    *px = ly->L + u * ly->PW;
    *py = ly->T + (1 - v) * ly->PH;
    return 1;
}

/* axis positions of values inside the axis ranges (ticks) */
static double map_x(const layout *ly, double x)
{
    return ly->L + (x - ly->tx.lo) / (ly->tx.hi - ly->tx.lo) * ly->PW;
}

static double map_y(const layout *ly, double y)
{
    return ly->T + (1 - (y - ly->ty.lo) / (ly->ty.hi - ly->ty.lo)) * ly->PH;
}

/* Liang–Barsky against the plot area; t0, t1 the visible parameter range */
static int clip_seg(const layout *ly, double x0, double y0, double x1, double y1,
                    double *t0o, double *t1o)
{
    double dx = x1 - x0, dy = y1 - y0;
    double pp[4] = {-dx, dx, -dy, dy};
    double qq[4] = {x0 - ly->L, ly->L + ly->PW - x0, y0 - ly->T, ly->T + ly->PH - y0};
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 4; i++) {
        if (pp[i] == 0) {
            if (qq[i] < 0)
                return 0;
        } else {
            double r = qq[i] / pp[i];
            if (pp[i] < 0) {
                if (r > t1)
                    return 0;
                if (r > t0)
                    t0 = r;
            } else {
                if (r < t0)
                    return 0;
                if (r < t1)
                    t1 = r;
            }
        }
    }
    *t0o = t0;
    *t1o = t1;
    return 1;
}

typedef struct sink {
    void (*pt)(struct sink *k, double x, double y); /* next vertex of the current run */
    void (*brk)(struct sink *k);                   /* end of the current run */
} sink;

/* Feed the visible, clipped pieces of a data polyline to k, in pixels. */
static void visit_poly(const layout *ly, const double *xy, size_t n, sink *k)
{
    int have_prev = 0, open = 0;
    double px0 = 0, py0 = 0;
    for (size_t i = 0; i < n; i++) {
        double px, py;
        if (!to_px(ly, xy[2 * i], xy[2 * i + 1], &px, &py)) {
            if (open)
                k->brk(k);
            open = have_prev = 0;
            continue;
        }
        if (have_prev) {
            double t0, t1;
            if (clip_seg(ly, px0, py0, px, py, &t0, &t1)) {
                double dx = px - px0, dy = py - py0;
                if (t0 > 0 || !open) {
                    if (open)
                        k->brk(k);
                    k->pt(k, px0 + t0 * dx, py0 + t0 * dy);
                    open = 1;
                }
                k->pt(k, t1 < 1 ? px0 + t1 * dx : px, t1 < 1 ? py0 + t1 * dy : py);
                if (t1 < 1) {
                    k->brk(k);
                    open = 0;
                }
            } else if (open) {
                k->brk(k);
                open = 0;
            }
        }
        px0 = px, py0 = py, have_prev = 1;
    }
    if (open)
        k->brk(k);
}

/* the two ends of y = m x + c at the left and right edges, in pixels */
static int line_px(const layout *ly, const series *s, double xy[4])
{
    double ys = ly->ty.hi - ly->ty.lo;
    double va = (s->m * ly->tx.lo + s->c - ly->ty.lo) / ys;
    double vb = (s->m * ly->tx.hi + s->c - ly->ty.lo) / ys;
    if (!(fabs(va) <= 1e150 && fabs(vb) <= 1e150))
        return 0;
    xy[0] = ly->L;
    xy[1] = ly->T + (1 - va) * ly->PH;
    xy[2] = ly->L + ly->PW;
    xy[3] = ly->T + (1 - vb) * ly->PH;
    return 1;
}

/* Forbidden part of the plot area (convex, <= 5 vertices) in pixels.  In
 * plot-normalised coordinates (u, v) the line is v = va + (vb - va) u. */
static size_t region_poly(const layout *ly, const series *s, double out[10])
{
    double ys = ly->ty.hi - ly->ty.lo;
    double va = (s->m * ly->tx.lo + s->c - ly->ty.lo) / ys;
    double vb = (s->m * ly->tx.hi + s->c - ly->ty.lo) / ys;
    if (!(fabs(va) <= 1e150 && fabs(vb) <= 1e150))
        return 0;
    static const double cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1};
    double sgn = s->side == TSU_PLOT_FORBID_BELOW ? 1.0 : -1.0;
    double g[4];
    for (int i = 0; i < 4; i++)
        g[i] = sgn * (va + (vb - va) * cu[i] - cv[i]); /* >= 0: forbidden */
    size_t n = 0;
    for (int i = 0; i < 4; i++) {
        int j = (i + 1) % 4;
        double u, v;
        if (g[i] >= 0) {
            out[2 * n] = ly->L + cu[i] * ly->PW;
            out[2 * n + 1] = ly->T + (1 - cv[i]) * ly->PH;
            n++;
        }
        if ((g[i] > 0 && g[j] < 0) || (g[i] < 0 && g[j] > 0)) { /* corners on the line: once */
            double t = g[i] / (g[i] - g[j]);
            u = cu[i] + t * (cu[j] - cu[i]);
            v = cv[i] + t * (cv[j] - cv[i]);
            out[2 * n] = ly->L + u * ly->PW;
            out[2 * n + 1] = ly->T + (1 - v) * ly->PH;
            n++;
        }
    }
    return n; /* < 3: the line runs along an edge or outside: nothing to shade */
}

/* ---- legend placement ------------------------------------------------ */

typedef struct score_sink {
    sink k;
    double bx0, by0, bx1, by1;
    double lx, ly_;
    int have;
    double score;
} score_sink;

static int in_box(const score_sink *s, double x, double y)
{
    return x >= s->bx0 && x <= s->bx1 && y >= s->by0 && y <= s->by1;
}

static void score_pt(sink *k, double x, double y)
{
    score_sink *s = (score_sink *)(void *)k;
    if (s->have) {
        double len = hypot(x - s->lx, y - s->ly_);
        double steps = ceil(len / 3.0);
        if (steps > 1e5)
            steps = 1e5;
        for (double i = 1; i <= steps; i++) {
            double t = i / steps;
            s->score += in_box(s, s->lx + t * (x - s->lx), s->ly_ + t * (y - s->ly_));
        }
    } else {
        s->score += in_box(s, x, y);
    }
    s->lx = x, s->ly_ = y, s->have = 1;
}

static void score_brk(sink *k) { ((score_sink *)(void *)k)->have = 0; }

static void legend_box_at(layout *ly, int where)
{
    const double inset = 8;
    double left = ly->L + inset, right = ly->L + ly->PW - inset - ly->lgw;
    double top = ly->T + inset, bottom = ly->T + ly->PH - inset - ly->lgh;
    double cx = floor(ly->L + 0.5 * (ly->PW - ly->lgw)), cy = floor(ly->T + 0.5 * (ly->PH - ly->lgh));
    switch (where) {
    case LG_UL: ly->lgx = left, ly->lgy = top; break;
    case LG_LL: ly->lgx = left, ly->lgy = bottom; break;
    case LG_LR: ly->lgx = right, ly->lgy = bottom; break;
    case LG_R: ly->lgx = right, ly->lgy = cy; break;
    case LG_L: ly->lgx = left, ly->lgy = cy; break;
    case LG_T: ly->lgx = cx, ly->lgy = top; break;
    case LG_B: ly->lgx = cx, ly->lgy = bottom; break;
    case LG_C: ly->lgx = cx, ly->lgy = cy; break;
    case LG_OUTSIDE: ly->lgx = ly->L + ly->PW + 12, ly->lgy = ly->T; break;
    default: ly->lgx = right, ly->lgy = top; break;
    }
    ly->lgx = fmax(ly->lgx, 2); /* a legend wider than the plot stays on the canvas */
    ly->lgy = fmax(ly->lgy, 2);
}

static double legend_score(const tsu_plot *p, const layout *ly)
{
    score_sink s;
    memset(&s, 0, sizeof s);
    s.k.pt = score_pt;
    s.k.brk = score_brk;
    s.bx0 = ly->lgx - 4, s.by0 = ly->lgy - 4;
    s.bx1 = ly->lgx + ly->lgw + 4, s.by1 = ly->lgy + ly->lgh + 4;
    for (size_t i = 0; i < p->ns; i++) {
        const series *se = &p->s[i];
        if (se->kind == K_POINTS) {
            for (size_t j = 0; j < se->n; j++) {
                double px, py;
                if (to_px(ly, se->xy[2 * j], se->xy[2 * j + 1], &px, &py) &&
                    px >= s.bx0 - se->marker_r && px <= s.bx1 + se->marker_r &&
                    py >= s.by0 - se->marker_r && py <= s.by1 + se->marker_r)
                    s.score += 5;
            }
        } else if (se->kind == K_POLY) {
            visit_poly(ly, se->xy, se->n, &s.k);
        } else {
            double xy[4];
            if (line_px(ly, se, xy)) {
                score_pt(&s.k, xy[0], xy[1]);
                score_pt(&s.k, xy[2], xy[3]);
                score_brk(&s.k);
            }
            if (se->kind == K_REGION) { /* shading under the legend: mild */
                for (int a = 0; a < 5; a++)
                    for (int b = 0; b < 4; b++) {
                        double px = s.bx0 + (s.bx1 - s.bx0) * (a + 0.5) / 5;
                        double py = s.by0 + (s.by1 - s.by0) * (b + 0.5) / 4;
                        double x = ly->tx.lo + (px - ly->L) / ly->PW * (ly->tx.hi - ly->tx.lo);
                        double y = ly->ty.lo + (ly->T + ly->PH - py) / ly->PH * (ly->ty.hi - ly->ty.lo);
                        double g = se->m * x + se->c - y;
                        if (se->side == TSU_PLOT_FORBID_ABOVE)
                            g = -g;
                        if (g > 0) /* all 20 together weigh less than one data sample */
                            s.score += 0.04;
                    }
            }
        }
    }
    return s.score;
}

static void do_layout(const tsu_plot *p, layout *ly)
{
    double ext[2][2];
    memset(ly, 0, sizeof *ly);
    data_extent(p, ext);
    legend_size(p, ly);
    ly->lg = LG_NONE;
    area_with_ticks(p, ext, ly);
    if (ly->nleg == 0 || p->legend == TSU_PLOT_LEGEND_NONE)
        return;
    static const int corner_of[] = {0, 0, LG_OUTSIDE, LG_UR, LG_UL, LG_LL, LG_LR};
    int want = corner_of[p->legend];
    int fits = ly->lgw <= ly->PW - 16 && ly->lgh <= ly->PH - 16;
    if (p->legend == TSU_PLOT_LEGEND_AUTO) {
        /* corners first, then edge middles, then the centre; ties keep the earlier */
        static const int order[9] = {LG_UR, LG_UL, LG_LR, LG_LL, LG_R, LG_L, LG_T, LG_B, LG_C};
        double best = HUGE_VAL;
        want = LG_UR;
        for (int i = 0; i < 9 && best > 0; i++) {
            legend_box_at(ly, order[i]);
            double sc = legend_score(p, ly);
            if (sc < best)
                best = sc, want = order[i];
        }
        if (best >= 1 || !fits) { /* covers data: outside, if there is room */
            layout o = *ly;
            o.lg = LG_OUTSIDE;
            area_with_ticks(p, ext, &o);
            if (o.PW >= 0.45 * (double)p->w) {
                *ly = o;
                legend_box_at(ly, LG_OUTSIDE);
                return;
            }
        }
    } else if (want == LG_OUTSIDE) {
        ly->lg = LG_OUTSIDE;
        area_with_ticks(p, ext, ly);
    }
    ly->lg = want;
    legend_box_at(ly, want);
}

tsu_plot_status tsu_plot_get_ticks(const tsu_plot *p, int axis, tsu_plot_ticks *t)
{
    if (!p || !t)
        return TSU_PLOT_ERR_NULL;
    if (axis != 0 && axis != 1)
        return TSU_PLOT_ERR_ARG;
    layout ly;
    do_layout(p, &ly);
    *t = axis ? ly.ty : ly.tx;
    return TSU_PLOT_OK;
}

/* ------------------------------------------------------------------ */
/* SVG writer                                                           */
/* ------------------------------------------------------------------ */

typedef struct wr {
    tsu_plot_buf *b;
    tsu_plot_status st;
} wr;

static void w_raw(wr *w, const char *s, size_t n)
{
    if (!w->st)
        w->st = tsu_plot_buf_append(w->b, s, n);
}

static void w_s(wr *w, const char *s) { w_raw(w, s, strlen(s)); }

static void w_xml(wr *w, const char *s)
{
    if (!w->st)
        w->st = tsu_plot_buf_xml(w->b, s);
}

/* pixel value, 2 decimals, no trailing zeros; never nan/inf */
static size_t fmt_num(char *o, double v)
{
    if (!(fabs(v) <= 1e12))
        v = 0;
    long long r = llround(v * 100.0);
    size_t k = 0;
    if (r < 0) {
        o[k++] = '-';
        r = -r;
    }
    long long ip = r / 100, fp = r % 100;
    char tmp[24];
    size_t t = 0;
    do {
        tmp[t++] = (char)('0' + (int)(ip % 10));
        ip /= 10;
    } while (ip);
    while (t)
        o[k++] = tmp[--t];
    if (fp) {
        o[k++] = '.';
        o[k++] = (char)('0' + (int)(fp / 10));
        if (fp % 10)
            o[k++] = (char)('0' + (int)(fp % 10));
    }
    o[k] = '\0';
    return k;
}

static void w_num(wr *w, double v)
{
    char o[40];
    w_raw(w, o, fmt_num(o, v));
}

/* name="value" with a pixel number */
static void w_attr(wr *w, const char *name, double v)
{
    w_s(w, " ");
    w_s(w, name);
    w_s(w, "=\"");
    w_num(w, v);
    w_s(w, "\"");
}

/* tick label: the '-' of a number's sign or exponent written as a real minus
 * sign; other hyphens (dates: 2024-01-05) stay ASCII */
static void w_label(wr *w, const char *s)
{
    for (const char *s0 = s; *s; s++) {
        if (*s == '-' && (s == s0 || s[-1] == 'e' || s[-1] == 'E' || s[-1] == ' ' ||
                          s[-1] == '('))
            w_s(w, "&#8722;");
        else
            w_raw(w, s, 1);
    }
}

static void w_line(wr *w, double x1, double y1, double x2, double y2)
{
    w_s(w, "<line");
    w_attr(w, "x1", x1);
    w_attr(w, "y1", y1);
    w_attr(w, "x2", x2);
    w_attr(w, "y2", y2);
    w_s(w, "/>");
}

static void w_circle(wr *w, double x, double y, double r)
{
    w_s(w, "<circle");
    w_attr(w, "cx", x);
    w_attr(w, "cy", y);
    w_attr(w, "r", r);
    w_s(w, "/>");
}

static void w_dash(wr *w, int dash)
{
    if (dash == 1)
        w_s(w, " stroke-dasharray=\"6,4\"");
    else if (dash == 2)
        w_s(w, " stroke-dasharray=\"1,3.5\"");
}

/* ---- polyline emitter with simplification ----------------------------
 * Sleeve method: from the last written vertex A, the skipped vertices
 * each allow a cone of directions in which a segment passes within tol of
 * them; a new end point P replaces the pending one while its direction
 * lies in every cone and it is the farthest from A so far, so each dropped
 * vertex stays within tol of the written segment. */
typedef struct poly_sink {
    sink k;
    wr *w;
    double tol;
    int open;
    size_t run_start, nrun;
    long long lrx, lry;     /* last written vertex, in 0.01 px */
    double ax, ay;          /* anchor A */
    int has_q;
    double qx, qy;          /* pending end point */
    int has_cone;
    double base, clo, chi;  /* cone, radians relative to base */
    double maxd;
    size_t runs;            /* polylines written */
} poly_sink;

static double wrap_pi(double a)
{
    const double tp = 6.283185307179586;
    while (a > 3.141592653589793)
        a -= tp;
    while (a <= -3.141592653589793)
        a += tp;
    return a;
}

static void ps_emit(poly_sink *s, double x, double y)
{
    long long rx = llround(x * 100), ry = llround(y * 100);
    if (s->nrun && rx == s->lrx && ry == s->lry)
        return;
    char o[100];
    size_t k = 0;
    if (s->nrun)
        o[k++] = ' ';
    k += fmt_num(o + k, x);
    o[k++] = ',';
    k += fmt_num(o + k, y);
    w_raw(s->w, o, k);
    s->lrx = rx, s->lry = ry;
    s->nrun++;
}

static void ps_reset(poly_sink *s, double x, double y)
{
    s->ax = x, s->ay = y;
    s->has_q = 0;
    s->has_cone = 0;
    s->maxd = 0;
}

static void ps_constrain(poly_sink *s, double x, double y)
{
    double d = hypot(x - s->ax, y - s->ay);
    if (d > s->maxd)
        s->maxd = d;
    if (d <= s->tol)
        return;
    double half = asin(s->tol / d), ang = atan2(y - s->ay, x - s->ax);
    if (!s->has_cone) {
        s->has_cone = 1;
        s->base = ang;
        s->clo = -half, s->chi = half;
    } else {
        double dl = wrap_pi(ang - s->base);
        s->clo = fmax(s->clo, dl - half);
        s->chi = fmin(s->chi, dl + half);
    }
}

static int ps_accept(const poly_sink *s, double x, double y)
{
    double d = hypot(x - s->ax, y - s->ay);
    if (d <= s->tol)
        return s->maxd <= s->tol;
    if (d < s->maxd)
        return 0;
    if (!s->has_cone)
        return 1;
    double dl = wrap_pi(atan2(y - s->ay, x - s->ax) - s->base);
    return dl >= s->clo && dl <= s->chi;
}

static void ps_pt(sink *k, double x, double y)
{
    poly_sink *s = (poly_sink *)(void *)k;
    if (!s->open) {
        s->open = 1;
        s->nrun = 0;
        s->run_start = s->w->b->len;
        w_s(s->w, "<polyline points=\"");
        ps_emit(s, x, y);
        ps_reset(s, x, y);
        return;
    }
    if (s->tol <= 0) {
        ps_emit(s, x, y);
        return;
    }
    if (s->has_q) {
        if (ps_accept(s, x, y)) {
            ps_constrain(s, x, y);
            s->qx = x, s->qy = y;
            return;
        }
        ps_emit(s, s->qx, s->qy);
        ps_reset(s, s->qx, s->qy);
    }
    s->has_q = 1;
    s->qx = x, s->qy = y;
    ps_constrain(s, x, y);
}

static void ps_brk(sink *k)
{
    poly_sink *s = (poly_sink *)(void *)k;
    if (!s->open)
        return;
    if (s->has_q)
        ps_emit(s, s->qx, s->qy);
    s->open = 0;
    if (s->w->st)
        return;
    if (s->nrun < 2) { /* nothing visible: take the run back */
        s->w->b->len = s->run_start;
        s->w->b->data[s->run_start] = '\0';
        return;
    }
    w_s(s->w, "\"/>");
    s->runs++;
}

static void poly_sink_init(poly_sink *s, wr *w, double tol)
{
    memset(s, 0, sizeof *s);
    s->k.pt = ps_pt;
    s->k.brk = ps_brk;
    s->w = w;
    s->tol = tol;
}

/* ---- pieces ------------------------------------------------------------ */

static void w_series_title(wr *w, const series *s)
{
    if (s->label) {
        w_s(w, "<title>");
        w_xml(w, s->label);
        w_s(w, "</title>");
    }
}

static void w_points_group(wr *w, const layout *ly, const series *s)
{
    w_s(w, "<g class=\"series points\" fill=\"");
    w_s(w, s->color);
    w_s(w, "\" stroke=\"#ffffff\" stroke-width=\"1\">");
    w_series_title(w, s);
    for (size_t j = 0; j < s->n; j++) {
        double px, py;
        if (!to_px(ly, s->xy[2 * j], s->xy[2 * j + 1], &px, &py))
            continue;
        if (px < ly->L - 0.5 || px > ly->L + ly->PW + 0.5 || py < ly->T - 0.5 ||
            py > ly->T + ly->PH + 0.5)
            continue;
        w_circle(w, px, py, s->marker_r);
    }
    w_s(w, "</g>\n");
}

static void w_stroke(wr *w, const series *s)
{
    w_s(w, " fill=\"none\" stroke=\"");
    w_s(w, s->color);
    w_s(w, "\"");
    w_attr(w, "stroke-width", s->width);
    w_dash(w, s->dash);
}

static void w_poly_group(wr *w, const layout *ly, const series *s, double tol)
{
    w_s(w, "<g class=\"series polyline\"");
    w_stroke(w, s);
    w_s(w, " stroke-linejoin=\"round\" stroke-linecap=\"round\">");
    w_series_title(w, s);
    poly_sink ps;
    poly_sink_init(&ps, w, tol);
    visit_poly(ly, s->xy, s->n, &ps.k);
    if (s->markers) {
        w_s(w, "<g fill=\"");
        w_s(w, s->color);
        w_s(w, "\" stroke=\"none\">");
        for (size_t j = 0; j < s->n; j++) {
            double px, py;
            if (to_px(ly, s->xy[2 * j], s->xy[2 * j + 1], &px, &py) && px >= ly->L - 0.5 &&
                px <= ly->L + ly->PW + 0.5 && py >= ly->T - 0.5 && py <= ly->T + ly->PH + 0.5)
                w_circle(w, px, py, s->marker_r);
        }
        w_s(w, "</g>");
    }
    w_s(w, "</g>\n");
}

/* the straight line of a K_LINE / K_REGION series, clipped */
static void w_clipped_line(wr *w, const layout *ly, const series *s)
{
    double xy[4], t0, t1;
    if (!line_px(ly, s, xy) || !clip_seg(ly, xy[0], xy[1], xy[2], xy[3], &t0, &t1) || !(t1 > t0))
        return;
    double dx = xy[2] - xy[0], dy = xy[3] - xy[1];
    w_line(w, xy[0] + t0 * dx, xy[1] + t0 * dy, xy[0] + t1 * dx, xy[1] + t1 * dy);
}

static void w_line_group(wr *w, const layout *ly, const series *s)
{
    w_s(w, s->kind == K_REGION ? "<g class=\"series region\">" : "<g class=\"series line\"");
    if (s->kind == K_LINE) {
        w_stroke(w, s);
        w_s(w, ">");
    }
    w_series_title(w, s);
    if (s->kind == K_REGION) {
        double poly[10];
        size_t n = region_poly(ly, s, poly);
        if (n >= 3) {
            w_s(w, "<polygon points=\"");
            for (size_t i = 0; i < n; i++) {
                if (i)
                    w_s(w, " ");
                w_num(w, poly[2 * i]);
                w_s(w, ",");
                w_num(w, poly[2 * i + 1]);
            }
            w_s(w, "\" fill=\"");
            w_s(w, s->color);
            w_s(w, "\"");
            w_attr(w, "fill-opacity", s->opacity);
            w_s(w, " stroke=\"none\"/>");
        }
        w_s(w, "<g");
        w_stroke(w, s);
        w_s(w, ">");
        w_clipped_line(w, ly, s);
        w_s(w, "</g>");
    } else {
        w_clipped_line(w, ly, s);
    }
    w_s(w, "</g>\n");
}

static void w_exponent(wr *w, const char *cls, double x, double y, const char *anchor, int e)
{
    char num[16];
    snprintf(num, sizeof num, "%d", e);
    w_s(w, "<text class=\"");
    w_s(w, cls);
    w_s(w, "\"");
    w_attr(w, "x", x);
    w_attr(w, "y", y);
    w_s(w, " text-anchor=\"");
    w_s(w, anchor);
    w_s(w, "\" fill=\"#444444\">&#215;10<tspan dy=\"-5\" font-size=\"9\">");
    w_label(w, num);
    w_s(w, "</tspan></text>\n");
}

static void w_axes(wr *w, const tsu_plot *p, const layout *ly)
{
    double L = ly->L, T = ly->T, R = ly->L + ly->PW, B = ly->T + ly->PH;
    double xs[TSU_PLOT_MAX_TICKS], ys[TSU_PLOT_MAX_TICKS];
    for (size_t i = 0; i < ly->tx.n; i++)
        xs[i] = map_x(ly, ly->tx.value[i]);
    for (size_t i = 0; i < ly->ty.n; i++)
        ys[i] = map_y(ly, ly->ty.value[i]);
    /* frame and tick marks */
    w_s(w, "<g class=\"axes\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\" "
           "shape-rendering=\"crispEdges\"><rect");
    w_attr(w, "x", L);
    w_attr(w, "y", T);
    w_attr(w, "width", ly->PW);
    w_attr(w, "height", ly->PH);
    w_s(w, "/>");
    for (size_t i = 0; i < ly->tx.n; i++)
        w_line(w, xs[i], B, xs[i], B + TICK_LEN);
    for (size_t i = 0; i < ly->ty.n; i++)
        w_line(w, L - TICK_LEN, ys[i], L, ys[i]);
    w_s(w, "</g>\n");
    /* tick labels */
    double xbase = B + TICK_LEN + 4 + FS_TICK - 2;
    w_s(w, "<g class=\"xticks\" fill=\"#444444\" text-anchor=\"middle\">");
    for (size_t i = 0; i < ly->tx.n; i++) {
        w_s(w, "<text");
        w_attr(w, "x", xs[i]);
        w_attr(w, "y", xbase);
        w_s(w, ">");
        w_label(w, ly->tx.label[i]);
        w_s(w, "</text>");
    }
    w_s(w, "</g>\n<g class=\"yticks\" fill=\"#444444\" text-anchor=\"end\">");
    for (size_t i = 0; i < ly->ty.n; i++) {
        w_s(w, "<text");
        w_attr(w, "x", L - TICK_LEN - 4);
        w_attr(w, "y", ys[i] + 0.35 * FS_TICK);
        w_s(w, ">");
        w_label(w, ly->ty.label[i]);
        w_s(w, "</text>");
    }
    w_s(w, "</g>\n");
    double lbase = xbase + FS_LABEL + 8;
    if (ly->tx.exponent)
        w_exponent(w, "xexp", R, lbase, "end", ly->tx.exponent);
    if (ly->ty.exponent)
        w_exponent(w, "yexp", L, T - 7, "start", ly->ty.exponent);
    if (p->xlabel) {
        w_s(w, "<text class=\"xlabel\"");
        w_attr(w, "x", L + 0.5 * ly->PW);
        w_attr(w, "y", lbase);
        w_s(w, " text-anchor=\"middle\" font-size=\"14\" fill=\"#222222\">");
        w_xml(w, p->xlabel);
        w_s(w, "</text>\n");
    }
    if (p->ylabel) {
        double x = 10 + FS_LABEL - 2, y = T + 0.5 * ly->PH;
        w_s(w, "<text class=\"ylabel\"");
        w_attr(w, "x", x);
        w_attr(w, "y", y);
        w_s(w, " transform=\"rotate(-90 ");
        w_num(w, x);
        w_s(w, " ");
        w_num(w, y);
        w_s(w, ")\" text-anchor=\"middle\" font-size=\"14\" fill=\"#222222\">");
        w_xml(w, p->ylabel);
        w_s(w, "</text>\n");
    }
    if (p->title) {
        w_s(w, "<text class=\"title\"");
        w_attr(w, "x", L + 0.5 * ly->PW);
        w_attr(w, "y", 12 + FS_TITLE - 2);
        w_s(w, " text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\" fill=\"#222222\">");
        w_xml(w, p->title);
        w_s(w, "</text>\n");
    }
}

static void w_grid(wr *w, const layout *ly)
{
    w_s(w, "<g class=\"grid\" stroke=\"#e3e3e3\" stroke-width=\"1\" shape-rendering=\"crispEdges\">");
    for (size_t i = 0; i < ly->tx.n; i++) {
        double x = map_x(ly, ly->tx.value[i]);
        if (x > ly->L + 0.5 && x < ly->L + ly->PW - 0.5)
            w_line(w, x, ly->T, x, ly->T + ly->PH);
    }
    for (size_t i = 0; i < ly->ty.n; i++) {
        double y = map_y(ly, ly->ty.value[i]);
        if (y > ly->T + 0.5 && y < ly->T + ly->PH - 0.5)
            w_line(w, ly->L, y, ly->L + ly->PW, y);
    }
    w_s(w, "</g>\n");
}

static void w_legend(wr *w, const tsu_plot *p, const layout *ly)
{
    w_s(w, "<g class=\"legend\"><rect");
    w_attr(w, "x", ly->lgx);
    w_attr(w, "y", ly->lgy);
    w_attr(w, "width", ly->lgw);
    w_attr(w, "height", ly->lgh);
    w_s(w, " rx=\"3\" fill=\"#ffffff\" fill-opacity=\"0.9\" stroke=\"#bbbbbb\" stroke-width=\"1\"/>");
    size_t row = 0;
    for (size_t i = 0; i < p->ns; i++) {
        const series *s = &p->s[i];
        if (!s->label)
            continue;
        double cy = ly->lgy + 4 + LEG_ROW * ((double)row + 0.5);
        double x0 = ly->lgx + 10, x1 = x0 + LEG_SWATCH;
        row++;
        switch (s->kind) {
        case K_POINTS:
            w_s(w, "<g fill=\"");
            w_s(w, s->color);
            w_s(w, "\" stroke=\"#ffffff\" stroke-width=\"1\">");
            w_circle(w, 0.5 * (x0 + x1), cy, s->marker_r);
            w_s(w, "</g>");
            break;
        case K_POLY:
        case K_LINE:
            w_s(w, "<g");
            w_stroke(w, s);
            w_s(w, " stroke-linecap=\"round\">");
            w_line(w, x0, cy, x1, cy);
            if (s->kind == K_POLY && s->markers) {
                w_s(w, "<g fill=\"");
                w_s(w, s->color);
                w_s(w, "\" stroke=\"none\">");
                w_circle(w, 0.5 * (x0 + x1), cy, s->marker_r);
                w_s(w, "</g>");
            }
            w_s(w, "</g>");
            break;
        case K_REGION: {
            double edge = s->side == TSU_PLOT_FORBID_BELOW ? cy - 5 : cy + 5;
            w_s(w, "<rect");
            w_attr(w, "x", x0);
            w_attr(w, "y", cy - 5);
            w_attr(w, "width", LEG_SWATCH);
            w_attr(w, "height", 10);
            w_s(w, " fill=\"");
            w_s(w, s->color);
            w_s(w, "\"");
            w_attr(w, "fill-opacity", fmin(1.0, 2 * s->opacity));
            w_s(w, " stroke=\"none\"/><g");
            w_stroke(w, s);
            w_s(w, ">");
            w_line(w, x0, edge, x1, edge);
            w_s(w, "</g>");
            break;
        }
        }
        w_s(w, "<text");
        w_attr(w, "x", x1 + 8);
        w_attr(w, "y", cy + 0.35 * FS_LEGEND);
        w_s(w, " fill=\"#222222\">");
        w_xml(w, s->label);
        w_s(w, "</text>");
    }
    w_s(w, "</g>\n");
}

tsu_plot_status tsu_plot_render(const tsu_plot *p, tsu_plot_buf *b)
{
    if (!p || !b)
        return TSU_PLOT_ERR_NULL;
    size_t old = b->len;
    wr w = {b, TSU_PLOT_OK};
    layout ly;
    do_layout(p, &ly);
    char hdr[400];
    if (p->xmldecl)
        w_s(&w, "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n");
    snprintf(hdr, sizeof hdr,
             "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%u\" "
             "height=\"%u\" viewBox=\"0 0 %u %u\" font-family=\"Helvetica, Arial, "
             "'Liberation Sans', 'DejaVu Sans', sans-serif\" font-size=\"12\">\n",
             p->w, p->h, p->w, p->h);
    w_s(&w, hdr);
    if (p->title) {
        w_s(&w, "<title>");
        w_xml(&w, p->title);
        w_s(&w, "</title>\n");
    }
    snprintf(hdr, sizeof hdr, "<rect width=\"%u\" height=\"%u\" fill=\"#ffffff\"/>\n", p->w, p->h);
    w_s(&w, hdr);
    if (p->grid)
        w_grid(&w, &ly);
    for (size_t i = 0; i < p->ns; i++)
        if (p->s[i].kind == K_REGION)
            w_line_group(&w, &ly, &p->s[i]);
    for (size_t i = 0; i < p->ns; i++) {
        if (p->s[i].kind == K_POLY)
            w_poly_group(&w, &ly, &p->s[i], p->simplify);
        else if (p->s[i].kind == K_LINE)
            w_line_group(&w, &ly, &p->s[i]);
    }
    for (size_t i = 0; i < p->ns; i++)
        if (p->s[i].kind == K_POINTS)
            w_points_group(&w, &ly, &p->s[i]);
    w_axes(&w, p, &ly);
    if (ly.lg != LG_NONE)
        w_legend(&w, p, &ly);
    w_s(&w, "</svg>\n");
    if (w.st && b->data) {
        b->len = old;
        b->data[old] = '\0';
    }
    return w.st;
}

tsu_plot_status tsu_plot_write(const tsu_plot *p, FILE *f)
{
    if (!p || !f)
        return TSU_PLOT_ERR_NULL;
    tsu_plot_buf b = TSU_PLOT_BUF_INIT;
    tsu_plot_status st = tsu_plot_render(p, &b);
    if (!st) {
        if (fwrite(b.data, 1, b.len, f) != b.len || fflush(f) != 0 || ferror(f))
            st = TSU_PLOT_ERR_IO;
    }
    tsu_plot_buf_free(&b);
    return st;
}

tsu_plot_status tsu_plot_save(const tsu_plot *p, const char *path)
{
    if (!p || !path)
        return TSU_PLOT_ERR_NULL;
    tsu_plot_buf b = TSU_PLOT_BUF_INIT;
    tsu_plot_status st = tsu_plot_render(p, &b);
    if (!st) {
        FILE *f = fopen(path, "wb");
        if (!f) {
            st = TSU_PLOT_ERR_IO;
        } else {
            if (fwrite(b.data, 1, b.len, f) != b.len)
                st = TSU_PLOT_ERR_IO;
            if (fclose(f) != 0)
                st = TSU_PLOT_ERR_IO;
        }
    }
    tsu_plot_buf_free(&b);
    return st;
}
