test_that("defaults are the library's (ts_spline_options_init)", {
    d <- trigspline_defaults()$spline
    ## the values the header documents for ts_spline_options_init
    expect_identical(d$form, "geometric")
    expect_identical(d$slopes, "steffen")
    expect_identical(d$alpha, 0.85)
    expect_identical(d$shape, "none")
    expect_identical(d$extrapolate, "error")
    f <- trigsplinefun(table1$x, table1$f)
    g <- trigsplinefun(table1$x, table1$f, form = "geometric", slopes = "steffen",
                       alpha = 0.85)
    xq <- seq(0, 30, by = 0.37)
    expect_identical(f(xq), g(xq))
    expect_identical(trigspline_info(f)$form, "geometric")
})

test_that("the README example: Table 1, positive, alpha 0.15, at 4.2", {
    f <- trigsplinefun(table1$x, table1$f, shape = "positive", alpha = 0.15)
    expect_true(certified(f))
    info <- trigspline_info(f)
    a <- certificate(f)$a
    ## re-derived from the spline's own slopes and a; tolerance: uniroot to
    ## 1e-15 in theta times |dY/dtheta| < 1, plus rounding
    expect_equal(f(4.2), geometric_eval(info$x, info$y, info$slopes, a, 4.2),
                 tolerance = 1e-12)
    expect_gt(f(4.2), 0)
})

test_that("values agree with an independent evaluation of the geometric form", {
    f <- trigsplinefun(rain$day, rain$mm, alpha = 1.3)
    info <- trigspline_info(f)
    xq <- seq(1, 40, by = 0.173)
    expect_equal(f(xq), geometric_eval(info$x, info$y, info$slopes, rep(1.3, 39), xq),
                 tolerance = 1e-10)
    ## knots exactly
    expect_identical(f(rain$day), rain$mm)
})

test_that("derivatives: finite differences, orders by form", {
    for (form in c("paper", "c1", "geometric")) {
        f <- trigsplinefun(table1$x, table1$f, form = form)
        xq <- c(1.1, 4.2, 9.7, 20.3, 27.5)
        e <- 1e-5
        ## central differences: error O(e^2 |S'''|) + rounding 1e-16 / e
        expect_equal(f(xq, 1), (f(xq + e) - f(xq - e)) / (2 * e), tolerance = 1e-6)
        expect_equal(f(xq, 2), (f(xq + e, 1) - f(xq - e, 1)) / (2 * e), tolerance = 1e-5)
        if (form == "geometric") {
            err <- expect_error(f(xq, 3), class = "trigspline_error")
            expect_identical(err$status, "TS_ERR_OPTION")
            expect_match(conditionMessage(err), "up to order 2")
        } else {
            expect_equal(f(xq, 3), (f(xq + e, 2) - f(xq - e, 2)) / (2 * e), tolerance = 1e-4)
        }
    }
    expect_error(trigsplinefun(1:3, 1:3)(2, deriv = 4), class = "trigspline_error")
})

test_that("integral of a reproduced line is exact", {
    f <- trigsplinefun(0:3, 2 * (0:3) + 1)
    expect_equal(trigspline_integral(f, 0, 3), 12, tolerance = 1e-14)
    expect_equal(trigspline_integral(f, 3, 0), -12, tolerance = 1e-14)
})

test_that("trigspline() works like spline()", {
    r <- trigspline(table1$x, table1$f, n = 7)
    s <- spline(table1$x, table1$f, n = 7)
    expect_identical(names(r), c("x", "y"))
    expect_identical(r$x, s$x)
    r <- trigspline(table1$x, table1$f, xout = c(4.2, 0, 30))
    expect_identical(r$y[2:3], c(2, 2))
    expect_length(trigspline(table1)$x, 27)
})

test_that("NA handling and ties as in splinefun", {
    x <- c(1, 2, NA, 3, 4); y <- c(1, 4, 5, NA, 2)
    f <- trigsplinefun(x, y)
    expect_identical(trigspline_info(f)$x, c(1, 2, 4))
    expect_identical(f(c(NA, 2)), c(NA, 4))
    err <- expect_error(trigsplinefun(x, y, na.rm = FALSE), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_NONFINITE")
    expect_match(conditionMessage(err), "x or f is NaN")
    expect_warning(g <- trigsplinefun(c(1, 1, 2, 3), c(1, 3, 5, 6)), "collapsing")
    expect_identical(g(1), 2)
    g <- trigsplinefun(c(3, 1, 1, 2), c(6, 1, 3, 5), ties = max)
    expect_identical(g(1:3), c(3, 5, 6))
    g <- trigsplinefun(c(1, 2, 2, 3), c(1, 4, 2, 6), ties = list("ordered", min))
    expect_identical(g(2), 2)
})

test_that("errors are conditions naming the point", {
    err <- expect_error(trigsplinefun(1:4, c(1, -1, 2, 3), shape = "positive"),
                        class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_NEGATIVE")
    expect_identical(err$index, 2)
    expect_identical(err$where, "point")
    expect_match(conditionMessage(err), "point 2 (x = 2, f = -1)", fixed = TRUE)
    f <- trigsplinefun(1:4, c(1, 2, 2, 3))
    err <- expect_error(f(c(2, 5)), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_DOMAIN")
    expect_match(conditionMessage(err), "query 2 (x = 5) lies outside [1, 4]", fixed = TRUE)
    expect_identical(f(c(0, 5), extrapolate = "clamp"), c(1, 3))
    err <- expect_error(trigsplinefun(1:4, c(1, 3, 2, 4), shape = "monotone"),
                        class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_NONMONOTONE")
    err <- expect_error(trigsplinefun(1:3, 1:3, alpha = -1), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_ALPHA")
    err <- expect_error(trigsplinefun(1:3, 1:3, form = "cubic"), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_OPTION")
    expect_match(conditionMessage(err), "\"geometric\"")
    err <- expect_error(trigsplinefun(1:3, 1:3, lower = 2), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_SIDE")
})

test_that("shapes, lines and the certificate data.frame", {
    f <- trigsplinefun(table1$x, table1$f, lower = c(1, 0.01), form = "paper", alpha = 0.3)
    cert <- certificate(f)
    expect_s3_class(cert, "data.frame")
    expect_identical(nrow(cert), 8L)
    expect_true(all(cert$certified))
    expect_true(all(cert$bound == "lower"))
    expect_true(all(cert$gap_lower > 0))
    xq <- seq(0, 30, by = 0.01)
    expect_true(all(f(xq) > 1 + 0.01 * xq))
    ## the reported minimum is attained where the report says
    expect_equal(f(cert$at_min), cert$min, tolerance = 1e-13)
    g <- trigsplinefun(c(0, 1, 2, 3), c(0.1, 0.9, 0.95, 0.2), lower = 0, upper = 1)
    expect_identical(certificate(g)$bound, rep("lower+upper", 3))
    expect_false(certified(trigsplinefun(1:3, c(1, 3, 2))))
})

test_that("per-interval parameters, user slopes, names", {
    f <- trigsplinefun(1:4, c(1, 3, 2, 4), alpha = c(1, 2, 3), form = "paper")
    expect_identical(trigspline_info(f)$alpha, c(1, 2, 3))
    err <- expect_error(trigsplinefun(1:4, c(1, 3, 2, 4), alpha = c(1, 2)),
                        class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_LENGTH")
    err <- expect_error(trigsplinefun(1:4, c(1, 3, 2, 4), slopes = c(0, 1)),
                        class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_LENGTH")
    expect_identical(trigspline_info(trigsplinefun(1:3, c(1, 3, 2), slopes = "fritsch"))$slopes[2], 0)
    expect_true(all(c("paper", "c1", "geometric") %in% trigspline_names("form")))
    expect_true("TS_ERR_NEGATIVE" %in% trigspline_names("status"))
    expect_output(print(f), "4 points, paper form, shape none")
})

test_that("a function restored by unserialize() refits its data", {
    f <- trigsplinefun(table1$x, table1$f, shape = "positive", alpha = 0.15)
    g <- unserialize(serialize(f, NULL))
    expect_identical(g(c(4.2, 17)), f(c(4.2, 17)))
    expect_identical(certificate(g), certificate(f))
})
