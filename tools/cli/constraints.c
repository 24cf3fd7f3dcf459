/* --constraint SPEC and --constraints FILE.json: constraint records
 * (docs/method.md §13, docs/cli.md), and their part of the JSON report. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_constraints_free(cli_opts *o)
{
    for (size_t k = 0; k < o->n_cons; k++) {
        free((double *)o->cons[k].px);                  /* px and py: one block */
        ts_spline_free((ts_spline *)o->cons[k].spline); /* spline:FILE (read_spline) */
    }
    free(o->cons);
    o->cons = NULL;
    o->n_cons = 0;
}

static int num_at(const char **s, double *v)
{
    char *end;
    while (isspace((unsigned char)**s))
        (*s)++;
    *v = strtod(*s, &end);
    if (end == *s || !isfinite(*v))
        return 0;
    *s = end;
    while (isspace((unsigned char)**s))
        (*s)++;
    return 1;
}

static int append(cli_opts *o, const ts_constraint *c)
{
    ts_constraint *n = realloc(o->cons, (o->n_cons + 1) * sizeof *n);
    if (!n) {
        free((double *)c->px);
        ts_spline_free((ts_spline *)c->spline);
        return 0;
    }
    o->cons = n;
    o->cons[o->n_cons++] = *c;
    return 1;
}

/* "X,Y;X,Y;..." into a block px[0..m), py = px + m. */
static int read_points(const char *s, ts_constraint *c)
{
    size_t m = 1;
    for (const char *p = s; *p; p++)
        m += *p == ';';
    double *b = malloc(2 * m * sizeof *b);
    if (!b)
        return 0;
    for (size_t j = 0; j < m; j++) {
        double xv, yv;
        if (!num_at(&s, &xv) || *s++ != ',' || !num_at(&s, &yv) ||
            (j + 1 < m ? *s++ != ';' : *s != '\0')) {
            free(b);
            return 0;
        }
        b[j] = xv;
        b[m + j] = yv;
    }
    c->bound = TS_BOUND_POLYLINE;
    c->px = b;
    c->py = b + m;
    c->n_poly = m;
    return 1;
}

/* "spline:FILE": the bound curve B (docs/method.md §13.7), the points of
 * FILE (x, y columns) fitted with the library's defaults, as `trigspline
 * fit FILE` would; a read or fit failure is reported with FILE's lines. */
static int read_spline(const char *path, ts_constraint *c)
{
    cli_opts bo;
    cli_data d;
    ts_spline_options opt;
    ts_spline *b = NULL;
    cli_opts_defaults(CLI_FIT, &bo);
    bo.data = path;
    ts_spline_options_init(&opt);
    int rc = cli_read_and_fit(&bo, &opt, &d, &b);
    if (rc != CLI_OK)
        return rc;
    cli_data_free(&d);
    c->bound = TS_BOUND_SPLINE;
    c->spline = b;
    return CLI_OK;
}

int cli_constraint_add(cli_opts *o, cli_cmd cmd, const char *name, const char *spec)
{
    static const struct {
        const char *pre;
        ts_constraint_kind kind;
    } ops[] = {{"slope>=", TS_CONSTRAINT_SLOPE_MIN},     {"slope<=", TS_CONSTRAINT_SLOPE_MAX},
               {"abs-slope<=", TS_CONSTRAINT_SLOPE_ABS}, {"|slope|<=", TS_CONSTRAINT_SLOPE_ABS},
               {"slope-min=", TS_CONSTRAINT_SLOPE_MIN},  {"slope-max=", TS_CONSTRAINT_SLOPE_MAX},
               {"slope-abs=", TS_CONSTRAINT_SLOPE_ABS},  {"lower=", TS_CONSTRAINT_LOWER},
               {"upper=", TS_CONSTRAINT_UPPER}};
    ts_constraint c;
    char buf[4096];
    if (strlen(spec) >= sizeof buf)
        return cli_usage(cmd, "%s: the constraint is too long", name);
    strcpy(buf, spec);
    ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
    /* scope "@I0-I1", "@I0-" or "@I" (interval indices, inclusive) */
    char *at = strrchr(buf, '@');
    if (at) {
        *at++ = '\0';
        char *end;
        unsigned long long a = strtoull(at, &end, 10), b;
        if (end == at)
            return cli_usage(cmd, "%s: \"@%s\" is not a scope (intervals I0-I1)", name, at);
        if (*end == '-' && end[1] == '\0') {
            b = 0;
        } else if (*end == '-') {
            char *e2;
            b = strtoull(end + 1, &e2, 10);
            if (*e2 || b < a)
                return cli_usage(cmd, "%s: \"@%s\" is not a scope (intervals I0-I1)", name, at);
            b = b - a + 1;
        } else if (*end == '\0') {
            b = 1;
        } else {
            return cli_usage(cmd, "%s: \"@%s\" is not a scope (intervals I0-I1)", name, at);
        }
        c.first = (size_t)a;
        c.count = (size_t)b;
    }
    int v = -1;
    if (ts_vocab_value(TS_VOCAB_CONSTRAINT, buf, &v) == TS_OK && v <= TS_CONSTRAINT_DECREASING) {
        c.kind = (ts_constraint_kind)v;
        return append(o, &c) ? CLI_OK : cli_usage(cmd, "%s: out of memory", name);
    }
    for (size_t k = 0; k < sizeof ops / sizeof ops[0]; k++) {
        size_t len = strlen(ops[k].pre);
        if (strncmp(buf, ops[k].pre, len) != 0)
            continue;
        const char *val = buf + len;
        c.kind = ops[k].kind;
        if ((c.kind == TS_CONSTRAINT_LOWER || c.kind == TS_CONSTRAINT_UPPER) &&
            strncmp(val, "poly:", 5) == 0) {
            if (!read_points(val + 5, &c))
                return cli_usage(cmd, "%s: \"%s\" is not a polyline X,Y;X,Y;...", name, val + 5);
        } else if ((c.kind == TS_CONSTRAINT_LOWER || c.kind == TS_CONSTRAINT_UPPER) &&
                   strncmp(val, "spline:", 7) == 0) {
            if (!val[7])
                return cli_usage(cmd, "%s: \"spline:\" needs a file (spline:FILE.csv)", name);
            int rc = read_spline(val + 7, &c);
            if (rc != CLI_OK)
                return rc;
        } else {
            double x;
            const char *p = val;
            if (!num_at(&p, &x) || *p)
                return cli_usage(cmd, "%s: \"%s\" is not a finite number", name, val);
            c.value = x;
        }
        return append(o, &c) ? CLI_OK : cli_usage(cmd, "%s: out of memory", name);
    }
    return cli_usage(cmd,
                     "%s: unknown constraint \"%s\" (convex, concave, increasing, decreasing, "
                     "lower=C, upper=C, lower=poly:X,Y;..., upper=poly:..., lower=spline:FILE.csv, "
                     "upper=spline:FILE.csv, slope>=V, slope<=V, "
                     "abs-slope<=V; a scope @I0-I1 may follow)",
                     name, spec);
}

/* ---- the JSON file: an array of SPEC strings or objects --------------- */

typedef struct jin {
    const char *s;
    int ok;
} jin;

static void ws(jin *j)
{
    while (isspace((unsigned char)*j->s))
        j->s++;
}
static int eat(jin *j, char c)
{
    ws(j);
    if (*j->s != c)
        return 0;
    j->s++;
    return 1;
}
/* a string without escapes other than \" and \\ into b */
static int jstr(jin *j, char *b, size_t cap)
{
    size_t k = 0;
    if (!eat(j, '"'))
        return 0;
    while (*j->s && *j->s != '"') {
        char c = *j->s++;
        if (c == '\\' && (*j->s == '"' || *j->s == '\\'))
            c = *j->s++;
        else if (c == '\\')
            return 0;
        if (k + 1 >= cap)
            return 0;
        b[k++] = c;
    }
    b[k] = '\0';
    return eat(j, '"');
}
static int jnum(jin *j, double *v)
{
    ws(j);
    return num_at(&j->s, v);
}

/* {"kind": K, "value": V, "points": [[x, y], ...], "spline": "FILE.csv",
 *  "first": I, "count": N} */
static int jobject(jin *j, cli_opts *o, cli_cmd cmd, const char *name)
{
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
    int have_kind = 0;
    double *pts = NULL;
    char spl[4096] = "";
    size_t m = 0;
    if (eat(j, '}'))
        return cli_usage(cmd, "%s: an empty constraint object", name);
    do {
        char key[64], kind[64];
        if (!jstr(j, key, sizeof key) || !eat(j, ':'))
            goto bad;
        if (strcmp(key, "kind") == 0) {
            int v;
            if (!jstr(j, kind, sizeof kind) || ts_vocab_value(TS_VOCAB_CONSTRAINT, kind, &v) != TS_OK) {
                free(pts);
                return cli_usage(cmd, "%s: unknown constraint kind", name);
            }
            c.kind = (ts_constraint_kind)v;
            have_kind = 1;
        } else if (strcmp(key, "value") == 0) {
            if (!jnum(j, &c.value))
                goto bad;
        } else if (strcmp(key, "first") == 0 || strcmp(key, "count") == 0) {
            double v;
            if (!jnum(j, &v) || !(v >= 0.0 && v < 1e15) || v != floor(v))
                goto bad;
            *(key[0] == 'f' ? &c.first : &c.count) = (size_t)v;
        } else if (strcmp(key, "spline") == 0) {
            if (!jstr(j, spl, sizeof spl) || !spl[0])
                goto bad;
        } else if (strcmp(key, "points") == 0) {
            if (!eat(j, '['))
                goto bad;
            do {
                double xy[2];
                double *n = realloc(pts, (m + 1) * 2 * sizeof *n);
                if (!n || !eat(j, '[') || !jnum(j, &xy[0]) || !eat(j, ',') || !jnum(j, &xy[1]) ||
                    !eat(j, ']')) {
                    free(n ? n : pts);
                    return cli_usage(cmd, "%s: points must be [[x, y], ...]", name);
                }
                pts = n;
                pts[2 * m] = xy[0];
                pts[2 * m + 1] = xy[1];
                m++;
            } while (eat(j, ','));
            if (!eat(j, ']'))
                goto bad;
        } else {
            free(pts);
            return cli_usage(cmd, "%s: unknown key \"%s\" in a constraint", name, key);
        }
    } while (eat(j, ','));
    if (!eat(j, '}') || !have_kind || (pts && spl[0]))
        goto bad;
    if (spl[0]) {
        if (c.kind != TS_CONSTRAINT_LOWER && c.kind != TS_CONSTRAINT_UPPER)
            goto bad;
        int rc = read_spline(spl, &c);
        if (rc != CLI_OK)
            return rc;
    }
    if (pts) {
        double *b = malloc(2 * m * sizeof *b);
        if (!b)
            goto bad;
        for (size_t k = 0; k < m; k++)
            b[k] = pts[2 * k], b[m + k] = pts[2 * k + 1];
        free(pts);
        c.bound = TS_BOUND_POLYLINE;
        c.px = b;
        c.py = b + m;
        c.n_poly = m;
    }
    return append(o, &c) ? CLI_OK : cli_usage(cmd, "%s: out of memory", name);
bad:
    free(pts);
    return cli_usage(cmd, "%s: not a constraint object {\"kind\": ..., \"value\": ..., "
                          "\"points\": [[x, y], ...] or \"spline\": \"FILE.csv\" (lower, upper), "
                          "\"first\": I, \"count\": N}",
                     name);
}

int cli_constraints_file(cli_opts *o, cli_cmd cmd, const char *name, const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return cli_usage(cmd, "%s: cannot open \"%s\"", name, path);
    size_t cap = 1 << 16, len = 0;
    char *txt = malloc(cap + 1);
    while (txt && (len += fread(txt + len, 1, cap - len, fp)) == cap) {
        char *n = cap < (1u << 26) ? realloc(txt, 2 * cap + 1) : NULL;
        if (!n) {
            free(txt);
            txt = NULL;
            break;
        }
        txt = n;
        cap *= 2;
    }
    fclose(fp);
    if (!txt)
        return cli_usage(cmd, "%s: \"%s\" is too large", name, path);
    txt[len] = '\0';
    jin j = {txt, 1};
    int rc = CLI_OK;
    if (!eat(&j, '[')) {
        rc = cli_usage(cmd, "%s: \"%s\" is not a JSON array of constraints", name, path);
    } else if (!eat(&j, ']')) {
        do {
            ws(&j);
            if (*j.s == '"') {
                char spec[4096];
                if (!jstr(&j, spec, sizeof spec))
                    rc = cli_usage(cmd, "%s: a bad string in \"%s\"", name, path);
                else
                    rc = cli_constraint_add(o, cmd, name, spec);
            } else if (eat(&j, '{')) {
                rc = jobject(&j, o, cmd, name);
            } else {
                rc = cli_usage(cmd, "%s: \"%s\": each constraint is a string or an object", name,
                               path);
            }
        } while (rc == CLI_OK && eat(&j, ','));
        if (rc == CLI_OK && (!eat(&j, ']') || (ws(&j), *j.s)))
            rc = cli_usage(cmd, "%s: \"%s\" is not a JSON array of constraints", name, path);
    }
    free(txt);
    return rc;
}

void cli_constraints_json(cli_json *j, const ts_spline *s)
{
    size_t nc = ts_spline_constraints(s), n = ts_spline_intervals(s);
    cli_json_key(j, "constraints");
    cli_json_begin(j, '[');
    for (size_t k = 0; k < nc; k++) {
        cli_json_nl(j);
        cli_json_begin(j, '[');
        for (size_t i = 0; i < n; i++) {
            ts_constraint_report r;
            ts_constraint_report_init(&r);
            if (ts_spline_constraint_report(s, k, i, &r) != TS_OK || !r.in_scope) {
                cli_json_null(j);
                continue;
            }
            cli_json_begin(j, '{');
            cli_json_kbool(j, "active", r.active);
            cli_json_knum(j, "gap", r.gap);
            cli_json_knum(j, "at", r.at);
            cli_json_kbool(j, "certified", r.certified);
            cli_json_end(j, '}');
        }
        cli_json_end(j, ']');
    }
    cli_json_end(j, ']');
}
