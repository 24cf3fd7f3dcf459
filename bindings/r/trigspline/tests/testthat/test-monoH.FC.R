## R's splinefun(method = "monoH.FC") is a cubic Hermite interpolant with
## Fritsch-Carlson-limited slopes m.  trigspline's geometric form is a
## Hermite interpolant too: S(x_i) = y_i and S'(x_i) = d_i exactly
## (docs/method.md §4).  Given monoH.FC's slopes as user slopes the two
## must therefore agree in value and first derivative at every knot, and
## both reproduce straight lines exactly (everywhere, not just at knots).
## Between the knots they differ: the basis is trigonometric, and the
## default slopes (Steffen's) are 0 at extrema where monoH.FC's are not.

test_that("with monoH.FC's slopes the two agree at the knots", {
    for (d in list(table1, data.frame(x = rain$day, f = rain$mm))) {
        h <- splinefun(d[[1]], d[[2]], method = "monoH.FC")
        m <- h(d[[1]], deriv = 1)
        f <- trigsplinefun(d[[1]], d[[2]], slopes = m)
        expect_identical(trigspline_info(f)$slopes, m)
        expect_identical(f(d[[1]]), d[[2]])
        expect_equal(h(d[[1]]), d[[2]], tolerance = 1e-14)
        ## dS/dx = Y'/X' at t = 0: a quotient of rounded control differences
        expect_equal(f(d[[1]], 1), m, tolerance = 1e-12)
    }
})

test_that("on a straight line they agree everywhere", {
    x <- c(0, 0.5, 2, 2.25, 4, 7)
    y <- -1.5 * x + 3
    h <- splinefun(x, y, method = "monoH.FC")
    f <- trigsplinefun(x, y)
    xq <- seq(0, 7, by = 0.01)
    expect_equal(f(xq), h(xq), tolerance = 1e-14)
    expect_equal(f(xq, 1), h(xq, 1), tolerance = 1e-13)
    expect_equal(f(xq, 2), rep(0, length(xq)), tolerance = 1e-10)
})

test_that("both are monotone on monotone data", {
    x <- c(1790, 1800, 1810, 1830, 1870, 1900, 1950, 1970)
    y <- c(3.93, 5.31, 7.24, 12.87, 38.56, 75.99, 150.7, 203.2)
    xq <- seq(1790, 1970, by = 0.25)
    h <- splinefun(x, y, method = "monoH.FC")
    expect_true(all(diff(h(xq)) >= 0))
    f <- trigsplinefun(x, y, shape = "monotone")
    expect_true(certified(f))
    expect_true(all(diff(f(xq)) >= 0))
})

test_that("they differ on rain: monoH.FC goes negative, trigspline stays >= 0", {
    xq <- seq(1, 40, length.out = 20001)
    h <- splinefun(rain$day, rain$mm, method = "monoH.FC")
    ## monoH.FC's slopes at the zero knots are not 0 (unweighted average of
    ## the secants): it dips below 0, measured -0.667 near day 12.4
    expect_lt(min(h(xq)), -0.6)
    f <- trigsplinefun(rain$day, rain$mm, shape = "positive")
    expect_true(certified(f))
    expect_gte(min(f(xq)), 0)
    expect_true(all(certificate(f)$min >= 0))
    ## the default spline too: each interval stays in its data range (5.10)
    expect_gte(min(trigsplinefun(rain$day, rain$mm)(xq)), 0)
})
