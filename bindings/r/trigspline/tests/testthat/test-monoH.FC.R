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

test_that("the library's \"fritsch-carlson\" slopes are not monoH.FC's", {
    ## the library's are Brodlie's weighted harmonic mean (PCHIP, 0 at
    ## extrema); monoH.FC starts from the plain mean of the two secants and
    ## only limits it, so it keeps a non-zero slope at a local extremum
    x <- c(0, 1, 3, 4, 7)
    y <- c(0, 2, 1, 3, 3.5)
    m <- splinefun(x, y, method = "monoH.FC")(x, deriv = 1)
    d <- trigspline_info(trigsplinefun(x, y, slopes = "fritsch-carlson"))$slopes
    ## at x = 1 (a maximum): the mean of the secants 2 and -0.5
    expect_equal(m[2], 0.75, tolerance = 1e-14)
    expect_identical(d[2], 0)
    ## at x = 4 the secants 2 and 1/6 have one sign: Brodlie's weights
    ## (w1 = 2 h_i + h_(i-1) = 7, w2 = h_i + 2 h_(i-1) = 5), where
    ## monoH.FC's mean 13/12 is then cut by its limiter
    expect_equal(d[4], 12 / (7 / 2 + 5 * 6), tolerance = 1e-14)
    expect_false(isTRUE(all.equal(d[4], m[4])))
})
