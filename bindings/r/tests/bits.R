# The R package against the C library, bit for bit (bindings/r/tests/run.sh
# BUILD): for each case the values and derivatives of trigsplinefun() must be
# identical to those bits.c computes with the library of BUILD through the
# same function (ts_spline_eval_batch_mode).  The inputs go through hex floats
# both ways, so no decimal conversion is involved.  Prints
# "bits: N passed, M failed".
args <- commandArgs(TRUE)
bits <- args[1]
library(trigspline)
set.seed(7)
rain <- c(0, 0, 9.8, 0.6, 0, 1.2, 0.4, 0.2, 12.3, 0, 0, 0, 12.2, 2, 12.5, 0, 3.9, 0)
walk <- cumsum(rnorm(300))
cases <- list(
    list(x = c(0, 2, 3, 5, 15, 25, 27, 28, 30),
         y = c(2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2)),
    list(x = seq_along(rain), y = rain),
    list(x = sort(runif(300, 0, 100)), y = walk - min(walk)))
opts <- expand.grid(form = c("geometric", "paper", "c1"),
                    slopes = c("steffen", "arithmetic", "fritsch-carlson"),
                    shape = c("none", "positive"), alpha = c(0.85, 0.3),
                    stringsAsFactors = FALSE)
opts <- opts[!(opts$form == "geometric" & opts$alpha < 0.3472 & opts$shape == "none"), ]
pass <- 0L; fail <- 0L
dir <- tempfile("bits"); dir.create(dir)
for (ci in seq_along(cases)) {
    d <- cases[[ci]]
    q <- sort(c(d$x, runif(500, min(d$x), max(d$x))))
    writeLines(sprintf("%a %a", d$x, d$y), file.path(dir, "data"))
    writeLines(sprintf("%a", q), file.path(dir, "q"))
    for (r in seq_len(nrow(opts))) {
        o <- opts[r, ]
        out <- system2(bits, c(o$form, o$slopes, o$shape, format(o$alpha),
                               file.path(dir, "data"), file.path(dir, "q")), stdout = TRUE)
        f <- trigsplinefun(d$x, d$y, form = o$form, slopes = o$slopes, shape = o$shape,
                           alpha = o$alpha)
        ref <- matrix(as.numeric(unlist(strsplit(out, " "))), ncol = 4, byrow = TRUE)
        orders <- if (o$form == "geometric") 0:2 else 0:3
        ok <- length(out) == length(q) &&
            all(vapply(orders, function(k) identical(f(q, k), ref[, k + 1L]), TRUE))
        if (ok) pass <- pass + 1L else {
            fail <- fail + 1L
            cat("differs: case", ci, paste(o, collapse = " "), "\n")
        }
    }
}
cat(sprintf("bits: %d passed, %d failed\n", pass, fail))
