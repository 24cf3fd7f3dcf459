test_that("surface defaults are the library's (ts_surface_options_init)", {
    d <- trigspline_defaults()$surface
    expect_identical(d$form, "paper")
    expect_identical(d$slopes, "arithmetic")
    expect_identical(d$alpha, 1)
})

test_that("volcano: nodes reproduced, range kept, certified", {
    x <- 10 * seq_len(nrow(volcano))
    y <- 10 * seq_len(ncol(volcano))
    s <- trigsurfacefun(x, y, volcano, shape = "range")
    expect_true(certified(s))
    expect_identical(s(x, y, grid = TRUE), volcano + 0)
    v <- trigsurface(x, y, volcano, nx = 200, ny = 150, shape = "range")
    expect_identical(dim(v$z), c(200L, 150L))
    expect_true(min(v$z) >= min(volcano) && max(v$z) <= max(volcano))
    ## scattered and grid evaluation agree; derivatives by differences
    expect_equal(s(c(15, 333), c(27, 401)), diag(s(c(15, 333), c(27, 401), grid = TRUE)),
                 tolerance = 1e-12)
    e <- 1e-4
    expect_equal(s(333.3, 401.7, deriv = c(1, 0)),
                 (s(333.3 + e, 401.7) - s(333.3 - e, 401.7)) / (2 * e), tolerance = 1e-6)
    expect_equal(s(333.3, 401.7, deriv = c(0, 1)),
                 (s(333.3, 401.7 + e) - s(333.3, 401.7 - e)) / (2 * e), tolerance = 1e-6)
})

test_that("bounds, the patch certificate and errors", {
    z <- matrix(c(0, 20, 100, 50, 0, 80, 100, 30, 0, 60, 90, 10), 4, 3)
    s <- trigsurfacefun(z = z, lower = 0, upper = 100)
    cert <- certificate(s)
    expect_identical(nrow(cert), 6L)
    expect_true(all(cert$certified))
    g <- s(seq(1, 4, by = 0.05), seq(1, 3, by = 0.05), grid = TRUE)
    expect_true(all(g >= 0 & g <= 100))
    err <- expect_error(trigsurfacefun(z = z, shape = "positive", lower = NULL) -> t0, NA)
    z[2, 3] <- -1
    err <- expect_error(trigsurfacefun(z = z, shape = "positive"), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_NEGATIVE")
    expect_match(conditionMessage(err), "node (2, 3) (x = 2, y = 3, z = -1)", fixed = TRUE)
    err <- expect_error(s(5, 1), class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_DOMAIN")
    expect_identical(s(NA, 1), NA_real_)
})

test_that("a surface restored by unserialize() refits its data", {
    s <- trigsurfacefun(z = volcano[1:5, 1:4], shape = "range")
    t2 <- unserialize(serialize(s, NULL))
    expect_identical(t2(2.5, 3.5), s(2.5, 3.5))
})

test_that("a matrix or a list(x, y, z) as the only argument, as persp()", {
    v <- trigsurface(volcano, nx = 20, ny = 10)
    expect_identical(range(v$x), c(1, 87))
    expect_identical(dim(v$z), c(20L, 10L))
    w <- trigsurface(list(x = 10 * (1:87), y = 5 * (1:61), z = volcano), nx = 3, ny = 3)
    expect_identical(w$y, c(5, 155, 305))
    expect_identical(w$z[1, 1], 100)
    expect_identical(trigsurfacefun(volcano)(1, 1), 100)
})

test_that("sloped planes in the geometric form", {
    x <- 0:4; y <- 0:3
    z <- outer(x, y, function(x, y) 1 + 0.5 * x + 0.25 * y + sin(x + y)^2)
    s <- trigsurfacefun(x, y, z, lower = c(0.9, 0.5, 0.25), form = "geometric")
    expect_identical(trigspline_defaults()$surface$form, "paper")
    expect_true(certified(s))
    expect_identical(environment(s)$info$shape, "planes")
    g <- expand.grid(x = seq(0, 4, by = 0.05), y = seq(0, 3, by = 0.05))
    expect_true(all(s(g$x, g$y) > 0.9 + 0.5 * g$x + 0.25 * g$y))
    err <- expect_error(trigsurfacefun(x, y, z, lower = c(0.9, 0.5, 0.25)),
                        class = "trigspline_error")
    expect_identical(err$status, "TS_ERR_OPTION")
})
