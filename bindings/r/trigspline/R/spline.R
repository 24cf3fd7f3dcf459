## One-dimensional splines: trigsplinefun(), trigspline() and their
## certificate.

trigsplinefun <- function(x, y = NULL, shape = NULL, lower = NULL, upper = NULL,
                          form = NULL, alpha = NULL, beta = NULL, slopes = NULL,
                          margin = NULL, extrapolate = NULL, certify = NULL,
                          ties = mean, na.rm = TRUE) {
    call <- match.call()
    xy <- .regularize(x, y, ties, missing(ties), na.rm)
    lower <- .line(lower, "lower")
    upper <- .line(upper, "upper")
    shape <- .choose(shape, "shape")
    if (is.null(shape) && (!is.null(lower) || !is.null(upper)))
        shape <- if (is.null(upper)) "above" else if (is.null(lower)) "below" else "between"
    user_slopes <- NULL
    if (is.numeric(slopes)) {
        user_slopes <- as.double(slopes)
        slopes <- NULL
    } else {
        slopes <- .choose(slopes, "slopes", exclude = "user")
    }
    opts <- list(form = .choose(form, "form"), slopes = slopes, user_slopes = user_slopes,
                 alpha = .num(alpha, "alpha"), beta = .num(beta, "beta"),
                 margin = .num(margin, "margin"), shape = shape, lower = lower,
                 upper = upper,
                 certify = if (is.null(certify)) NULL else isTRUE(as.logical(certify)),
                 extrapolate = .choose(extrapolate, "extrapolate"))
    ptr <- .check(.Call(C_spline_new, xy$x, xy$y, opts), call)
    info <- .Call(C_spline_info, ptr)
    state <- new.env(parent = emptyenv())
    state$ptr <- ptr
    ## restored by readRDS() or load(): the pointer is gone, refit the same data
    spline <- function() {
        if (identical(.Call(C_ptr_valid, state$ptr), FALSE))
            state$ptr <- .check(.Call(C_spline_new, xy$x, xy$y, opts), call)
        state$ptr
    }
    rm(x, y, ties, na.rm, alpha, beta, margin, certify, shape, slopes, form, user_slopes)
    f <- function(x, deriv = 0L, extrapolate = NULL) {
        deriv <- as.integer(deriv)
        if (length(deriv) != 1L || is.na(deriv) || deriv < 0L || deriv > 3L)
            .stop_option("'deriv' must be 0, 1, 2 or 3")
        if (deriv == 3L && info$form == "geometric")
            .stop_option(paste0("the geometric form has derivatives up to order 2 only; ",
                                "fit with form = \"paper\" or \"c1\" for deriv = 3"))
        res <- .Call(C_spline_eval, spline(), as.double(x), deriv,
                     .choose(extrapolate, "extrapolate"))
        .check(res)
    }
    environment(f) <- environment()
    class(f) <- c("trigsplinefun", "function")
    f
}

print.trigsplinefun <- function(x, ...) {
    info <- environment(x)$info
    cat(sprintf("trigspline: %d points, %s form, shape %s, %s\n", length(info$x),
                info$form, info$shape,
                if (info$shape == "none") "no certificate (no shape asked for)"
                else if (info$certified) "certified" else "NOT certified"))
    cat("Call: "); print(environment(x)$call)
    invisible(x)
}

## The fitted spline's knots, slopes and parameters.
trigspline_info <- function(f) {
    .fun_check(f)
    environment(f)$info
}

.fun_check <- function(f, class = "trigsplinefun") {
    if (!inherits(f, class))
        stop(sprintf("'%s' must be a function made by %s()", deparse(substitute(f)),
                     if (class == "trigsplinefun") "trigsplinefun" else "trigsurfacefun"),
             call. = FALSE)
}

certified <- function(object) UseMethod("certified")
certified.trigsplinefun <- function(object) environment(object)$info$certified

certificate <- function(object, ...) UseMethod("certificate")

certificate.trigsplinefun <- function(object, ...) {
    r <- .Call(C_spline_report, environment(object)$spline())
    bound <- ifelse(r$has_lower & r$has_upper, "lower+upper",
                    ifelse(r$has_lower, "lower", ifelse(r$has_upper, "upper", "none")))
    data.frame(interval = seq_along(r$x0), x0 = r$x0, x1 = r$x1, certified = r$certified,
               bound = bound, term = r$term, alpha = r$alpha, beta = r$beta, a = r$a,
               gap_lower = r$gap_lower, at_lower = r$at_lower,
               gap_upper = r$gap_upper, at_upper = r$at_upper,
               min = r$min, at_min = r$at_min, max = r$max, at_max = r$at_max,
               excursion_above = r$excursion_above, excursion_below = r$excursion_below)
}

trigspline_integral <- function(f, lower, upper) {
    .fun_check(f)
    .check(.Call(C_spline_integral, environment(f)$spline(), as.double(lower),
                 as.double(upper)))
}

trigspline <- function(x, y = NULL, n = 3 * length(x), xmin = min(x), xmax = max(x),
                       xout, ties = mean, na.rm = TRUE, ...) {
    xy <- .regularize(x, y, ties, missing(ties), na.rm)
    x <- xy$x
    f <- trigsplinefun(xy$x, xy$y, ...)
    if (missing(xout)) {
        xout <- seq.int(xmin, xmax, length.out = n)
    } else {
        n <- length(xout)
    }
    if (n <= 0L) stop("'trigspline' requires n >= 1")
    xout <- as.double(xout)
    list(x = xout, y = f(xout))
}
