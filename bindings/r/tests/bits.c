/* The C library's values for the R package's bit-identity check
 * (bindings/r/tests/run.sh BUILD): bits FORM SLOPES SHAPE ALPHA DATA QUERIES
 * fits the points of DATA (lines "x y", hex floats) with those options and
 * prints, per query of QUERIES (one hex float a line), S, S', S'' and S'''
 * through ts_spline_eval_batch_mode (the path the package uses; S''' NaN in
 * the geometric form) as hex floats.  Exit 1 on bad input, 2 on a library
 * failure. */
#include <stdio.h>
#include <stdlib.h>

#include "trigspline.h"

static double *read_column(const char *path, int cols, size_t *n)
{
    FILE *f = fopen(path, "r");
    size_t cap = 1024, len = 0;
    double *v = malloc(cap * sizeof *v);
    if (!f || !v) exit(1);
    double a, b;
    while (cols == 2 ? fscanf(f, "%la %la", &a, &b) == 2 : fscanf(f, "%la", &a) == 1) {
        if (len + 2 > cap) {
            cap *= 2;
            double *w = realloc(v, cap * sizeof *v);
            if (!w) exit(1);
            v = w;
        }
        v[len++] = a;
        if (cols == 2) v[len++] = b;
    }
    fclose(f);
    *n = len / (size_t)cols;
    return v;
}

int main(int argc, char **argv)
{
    if (argc != 7) return 1;
    ts_spline_options o;
    ts_spline_options_init(&o);
    int v;
    if (ts_vocab_value(TS_VOCAB_FORM, argv[1], &v) != TS_OK) return 1;
    o.form = (ts_form)v;
    if (ts_vocab_value(TS_VOCAB_SLOPES, argv[2], &v) != TS_OK) return 1;
    o.slopes = (ts_slopes)v;
    if (ts_vocab_value(TS_VOCAB_SHAPE, argv[3], &v) != TS_OK) return 1;
    o.shape = (ts_shape)v;
    o.alpha = strtod(argv[4], NULL);
    size_t n, m;
    double *xy = read_column(argv[5], 2, &n), *q = read_column(argv[6], 1, &m);
    double *x = malloc(n * sizeof *x), *f = malloc(n * sizeof *f);
    double *out = malloc(4 * (m ? m : 1) * sizeof *out);
    if (!x || !f || !out) return 1;
    for (size_t i = 0; i < n; i++) {
        x[i] = xy[2 * i];
        f[i] = xy[2 * i + 1];
    }
    ts_spline *s = NULL;
    ts_error err;
    if (ts_spline_new(x, f, n, &o, &s, &err) != TS_OK) return 2;
    for (int k = 0; k < 4; k++) {
        ts_cursor cur = TS_CURSOR_INIT;
        ts_status st = ts_spline_eval_batch_mode(s, k, TS_EXTRAP_ERROR, q, m, out + k * m, &cur,
                                                 &err);
        if (st != TS_OK && !(k == 3 && o.form == TS_FORM_GEOMETRIC)) return 2;
    }
    for (size_t j = 0; j < m; j++)
        printf("%a %a %a %a\n", out[j], out[m + j], out[2 * m + j], out[3 * m + j]);
    ts_spline_free(s);
    free(xy);
    free(q);
    free(x);
    free(f);
    free(out);
    return 0;
}
