/* gsl_eval: GSL's own interpolants on a data file, for comparisons (the why
 * page of `make demo`, scripts/why_demo.py).  Not part of the library.
 *
 *   gsl_eval METHOD DATA M
 *
 * METHOD: cspline (natural cubic spline), steffen (monotone, Steffen 1990),
 * akima; DATA: two columns x, f (CSV, TSV or whitespace; header and #
 * comments allowed); M >= 2 points per interval, knots included.  Prints
 * "x,y" rows (shortest round-trip numbers): M per interval counting both
 * knots (x_i + h j/(M-1), j < M-1; the right knot belongs to the next
 * interval), and the last knot: the x grid of `trigspline fit --samples M`.  Exit 0, 1 usage, 2 bad data, 5 I/O. */
#include "tsu_io.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int usage(void)
{
    fputs("usage: gsl_eval cspline|steffen|akima DATA M\n", stderr);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 4)
        return usage();
    const gsl_interp_type *type = strcmp(argv[1], "cspline") == 0   ? gsl_interp_cspline
                                  : strcmp(argv[1], "steffen") == 0 ? gsl_interp_steffen
                                  : strcmp(argv[1], "akima") == 0   ? gsl_interp_akima
                                                                    : NULL;
    char *end;
    long m = strtol(argv[3], &end, 10);
    if (!type || *end || m < 2 || m > 1000000)
        return usage();
    tsu_table t;
    tsu_io_error e;
    if (tsu_read_table_path(argv[2], NULL, &t, &e) != TSU_IO_OK) {
        fprintf(stderr, "gsl_eval: %s\n", e.msg);
        return e.status == TSU_IO_ERR_OPEN || e.status == TSU_IO_ERR_READ ? 5 : 2;
    }
    if (t.ncols < 2 || t.nrows < gsl_interp_type_min_size(type)) {
        fprintf(stderr, "gsl_eval: %s: need two columns and at least %u rows\n", argv[2],
                gsl_interp_type_min_size(type));
        tsu_table_free(&t);
        return 2;
    }
    gsl_set_error_handler_off();
    const double *x = t.cols[0], *f = t.cols[1];
    size_t n = t.nrows;
    gsl_interp *in = gsl_interp_alloc(type, n);
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    int rc = 0;
    if (!in || !acc || gsl_interp_init(in, x, f, n) != GSL_SUCCESS) {
        fprintf(stderr, "gsl_eval: %s: GSL refused the data (x must increase)\n", argv[2]);
        rc = 2;
        goto done;
    }
    char bx[TSU_FMT_SIZE], by[TSU_FMT_SIZE];
    printf("x,y\n");
    for (size_t i = 0; i + 1 < n; i++) {
        for (long j = 0; j < m - 1; j++) {
            double xv = x[i] + (x[i + 1] - x[i]) * ((double)j / (double)(m - 1));
            double y = gsl_interp_eval(in, x, f, xv, acc);
            tsu_format_double(xv, bx);
            tsu_format_double(y, by);
            printf("%s,%s\n", bx, by);
        }
    }
    tsu_format_double(x[n - 1], bx);
    tsu_format_double(f[n - 1], by);
    printf("%s,%s\n", bx, by);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "gsl_eval: cannot write standard output\n");
        rc = 5;
    }
done:
    gsl_interp_accel_free(acc);
    gsl_interp_free(in);
    tsu_table_free(&t);
    return rc;
}
