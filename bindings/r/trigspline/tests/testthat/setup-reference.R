## An independent evaluation of the geometric form (docs/method.md §2, §4)
## from knots x, values y, slopes d and a = alpha + beta per interval: on
## [x_i, x_i+1] the curve is (X(t), Y(t)), t in [0, pi/2], with control
## abscissae X = x_i + (0, k, h - k, h), values Y = (y_i, y_i + k d_i,
## y_i+1 - k d_i+1, y_i+1), k = 2h / (3 pi a) and the basis
## A0 = (1-s)^3, A1 = s(1-s)(3-s), A2 = c(1-c)(3-c), A3 = (1-c)^3.
geometric_eval <- function(x, y, d, a, xq) {
    basis <- function(t) {
        s <- sin(t); c <- cos(t)
        c((1 - s)^3, s * (1 - s) * (3 - s), c * (1 - c) * (3 - c), (1 - c)^3)
    }
    vapply(xq, function(q) {
        i <- min(findInterval(q, x), length(x) - 1L)
        h <- x[i + 1L] - x[i]
        k <- 2 * h / (3 * pi * a[i])
        X <- x[i] + c(0, k, h - k, h)
        Y <- c(y[i], y[i] + k * d[i], y[i + 1L] - k * d[i + 1L], y[i + 1L])
        if (q == x[i]) return(y[i])
        t <- uniroot(function(t) sum(basis(t) * X) - q, c(0, pi / 2),
                     tol = 1e-15)$root
        sum(basis(t) * Y)
    }, 0)
}

## Daily rainfall (mm), 40 days: data/examples/rainfall_daily.csv of the
## repository (synthetic, make_examples.py, seed 11).
rain <- data.frame(day = 1:40, mm = c(
    0, 0, 0, 0, 0, 0, 9.8, 0.6, 0, 1.2, 0.4, 0.2, 12.3, 0, 0, 0,
    0, 12.2, 2, 12.5, 0, 0, 3.9, 0, 0, 0.6, 0, 0, 2.2, 10, 4.5, 0,
    7.2, 1.8, 0, 0, 0, 0, 7.1, 0))

## The paper's Table 1 (data/paper/table1_positive.csv).
table1 <- data.frame(x = c(0, 2, 3, 5, 15, 25, 27, 28, 30),
                     f = c(2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2))
