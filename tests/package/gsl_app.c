/* An outside program using the installed GSL adapter (tests/package/run.sh):
 * gsl_spline with ts_gsl_interp_positive through data on the line
 * y = 2x + 1, which the default (geometric) form reproduces exactly
 * (docs/method.md §4), and data below zero, which the positive scheme
 * refuses with GSL_EDOM.  Prints "name ...", "at X Y" lines and "edom 1". */
#include <trigspline_gsl.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_spline.h>
#include <stdio.h>

int main(void)
{
    double x[5] = {0, 1, 2, 3, 4}, y[5], neg[5] = {1, 2, -1, 2, 1};
    static const double at[3] = {0.37, 1.5, 3.99};
    for (int i = 0; i < 5; i++)
        y[i] = 2.0 * x[i] + 1.0;
    gsl_set_error_handler_off();
    gsl_spline *sp = gsl_spline_alloc(ts_gsl_interp_positive, 5);
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    if (!sp || !acc || gsl_spline_init(sp, x, y, 5) != GSL_SUCCESS)
        return 1;
    printf("name %s\n", gsl_spline_name(sp));
    for (int k = 0; k < 3; k++)
        printf("at %.17g %.17g\n", at[k], gsl_spline_eval(sp, at[k], acc));
    printf("edom %d\n", gsl_spline_init(sp, x, neg, 5) == GSL_EDOM);
    gsl_spline_free(sp);
    gsl_interp_accel_free(acc);
    return 0;
}
