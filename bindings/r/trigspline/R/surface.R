## Surfaces on a grid: trigsurfacefun() and trigsurface().

## A constant (bounds) or c(intercept, x slope, y slope) (a plane).
.plane <- function(value, what) {
    if (is.null(value)) return(NULL)
    value <- .num(value, what)
    if (length(value) == 1L) value <- c(value, 0, 0)
    if (length(value) != 3L)
        .stop_option(sprintf("'%s' must be a constant or c(intercept, x slope, y slope)", what))
    value
}

## x as the only argument: a matrix (z, with x, y its indices) or a list
## with components x, y, z (as persp() and image() take).
.grid_of <- function(x) {
    if (is.list(x) && !is.null(x$z)) return(list(x = x$x, y = x$y, z = x$z))
    if (is.matrix(x)) return(list(x = seq_len(nrow(x)), y = NULL, z = x))
    stop("no 'z' matrix given")
}

trigsurfacefun <- function(x = seq_len(nrow(z)), y = seq_len(ncol(z)), z,
                           shape = NULL, lower = NULL, upper = NULL, form = NULL,
                           alpha = NULL, beta = NULL, slopes = NULL, margin = NULL,
                           zero.twist = NULL) {
    call <- match.call()
    if (missing(z)) {
        g <- .grid_of(x)
        x <- g$x; z <- g$z
        if (!is.null(g$y)) y <- g$y
    }
    z <- as.matrix(z)
    if (!is.numeric(z)) stop("'z' must be a numeric matrix")
    storage.mode(z) <- "double"
    x <- as.double(x)
    y <- as.double(y)
    if (nrow(z) != length(x) || ncol(z) != length(y))
        stop("'z' must have length(x) rows and length(y) columns")
    lower <- .plane(lower, "lower")
    upper <- .plane(upper, "upper")
    shape <- .choose(shape, "shape", "surface_shape")
    if (is.null(shape) && (!is.null(lower) || !is.null(upper))) {
        sloped <- any(c(lower[-1L], upper[-1L]) != 0)
        shape <- if (sloped) "planes" else "bounds"
    }
    opts <- list(form = .choose(form, "form"),
                 slopes = .choose(slopes, "slopes", exclude = c("user", "periodic")),
                 alpha = .num(alpha, "alpha"), beta = .num(beta, "beta"),
                 margin = .num(margin, "margin"), shape = shape, lower = lower, upper = upper,
                 zero_twist = if (is.null(zero.twist)) NULL else isTRUE(as.logical(zero.twist)))
    for (a in c("alpha", "beta", "margin"))
        if (length(opts[[a]]) > 1L) .stop_option(sprintf("'%s' must be one number", a))
    ptr <- .check(.Call(C_surface_new, x, y, z, opts), call)
    info <- .Call(C_surface_info, ptr)
    state <- new.env(parent = emptyenv())
    state$ptr <- ptr
    surface <- function() {
        if (identical(.Call(C_ptr_valid, state$ptr), FALSE))
            state$ptr <- .check(.Call(C_surface_new, x, y, z, opts), call)
        state$ptr
    }
    rm(alpha, beta, margin, shape, slopes, form, zero.twist)
    f <- function(x, y, grid = FALSE, deriv = c(0L, 0L)) {
        deriv <- as.integer(deriv)
        which <- if (identical(deriv, c(0L, 0L))) 0L else if (identical(deriv, c(1L, 0L))) 1L
                 else if (identical(deriv, c(0L, 1L))) 2L
                 else .stop_option("'deriv' must be c(0, 0), c(1, 0) or c(0, 1)")
        x <- as.double(x)
        y <- as.double(y)
        if (grid) {
            if (which == 0L && !anyNA(x) && !anyNA(y))
                return(.check(.Call(C_surface_grid, surface(), x, y)))
            g <- expand.grid(x = x, y = y)
            return(matrix(f(g$x, g$y, deriv = deriv), length(x), length(y)))
        }
        if (length(x) != length(y)) {
            n <- max(length(x), length(y))
            x <- rep_len(x, n)
            y <- rep_len(y, n)
        }
        .check(.Call(C_surface_eval, surface(), x, y, which))
    }
    environment(f) <- environment()
    class(f) <- c("trigsurfacefun", "function")
    f
}

print.trigsurfacefun <- function(x, ...) {
    info <- environment(x)$info
    cat(sprintf("trigspline surface: %d x %d grid, %s form, shape %s, %s\n",
                length(info$x), length(info$y), info$form, info$shape,
                if (info$shape == "none") "no certificate (no shape asked for)"
                else if (info$certified) "certified" else "NOT certified"))
    invisible(x)
}

certified.trigsurfacefun <- function(object) environment(object)$info$certified

certificate.trigsurfacefun <- function(object, ...) {
    as.data.frame(.Call(C_surface_report, environment(object)$surface()))
}

trigsurface <- function(x = seq_len(nrow(z)), y = seq_len(ncol(z)), z,
                        nx = 2L * length(x), ny = 2L * length(y),
                        xout = seq(min(x), max(x), length.out = nx),
                        yout = seq(min(y), max(y), length.out = ny), ...) {
    if (missing(z)) {
        g <- .grid_of(x)
        x <- g$x; z <- g$z
        if (!is.null(g$y)) y <- g$y
    }
    f <- trigsurfacefun(x, y, z, ...)
    list(x = xout, y = yout, z = f(xout, yout, grid = TRUE))
}
