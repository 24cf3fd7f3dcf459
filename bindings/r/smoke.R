# The smoke test of the installed R package (tools/dist/r.sh test): the
# README's example (a positive spline of the paper's Table 1, alpha 0.15, at
# x = 4.2, certified) and one error case (negative data under the positive
# shape: a trigspline_error naming the point).  Exits non-zero on failure.
library(trigspline)
x <- c(0, 2, 3, 5, 15, 25, 27, 28, 30)
y <- c(2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2)
f <- trigsplinefun(x, y, shape = "positive", alpha = 0.15)
v <- f(4.2)
# certified positive, and on [3, 5] between its data values 1.55 and 1.54:
# Steffen's slope is 0 at x = 5 (the data turn there) and within twice the
# secant at x = 3, so with a >= 4/(3 pi) (the geometric form's floor) the
# interval's control values are monotone (docs/method.md §5.10)
stopifnot(certified(f), is.finite(v), v > 0, v >= 1.54, v <= 1.55)
e <- tryCatch(trigsplinefun(1:4, c(1, -1, 2, 3), shape = "positive"),
              trigspline_error = function(e) e)
stopifnot(inherits(e, "trigspline_error"), identical(e$status, "TS_ERR_NEGATIVE"),
          grepl("point 2 (x = 2, f = -1)", conditionMessage(e), fixed = TRUE))
# one version: DESCRIPTION's (from CMakeLists.txt by stage.sh) is the
# compiled-in library's ts_version()
stopifnot(identical(as.character(utils::packageVersion("trigspline")),
                    trigspline_defaults()$version))
cat(sprintf("R smoke test: trigspline %s, f(4.2) = %.17g, certified; error: %s\n",
            trigspline_defaults()$version, v, conditionMessage(e)))
# the line tools/dist/run.py compares across channels
cat(sprintf("smoke: y(4.2) = %.17g certified %d\n", v, as.integer(certified(f))))
