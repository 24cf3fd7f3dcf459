## Shared internals: the library's vocabulary and defaults, option checks,
## conditions.

.vocab_ids <- c(status = 0L, form = 1L, slopes = 2L, shape = 3L, extrapolate = 4L,
                param = 5L, surface_shape = 6L, term = 7L, where = 8L)

## The library's names of one option (its canonical spellings).
trigspline_names <- function(what = c("form", "slopes", "shape", "extrapolate",
                                      "surface_shape", "term", "status")) {
    what <- match.arg(what)
    .Call(C_vocab, .vocab_ids[[what]])
}

trigspline_defaults <- function() .Call(C_defaults)

## A name given by the user, matched (partially, as match.arg) against the
## library's names; NULL stays NULL (the library's default).
.choose <- function(value, what, vocab = what, exclude = character()) {
    if (is.null(value)) return(NULL)
    choices <- setdiff(trigspline_names(vocab), exclude)
    if (!is.character(value) || length(value) != 1L || is.na(value))
        .stop_option(sprintf("'%s' must be one string: %s", what,
                             paste(dQuote(choices, FALSE), collapse = ", ")))
    i <- pmatch(value, choices)
    if (is.na(i))
        .stop_option(sprintf("'%s' = \"%s\" is not one of %s", what, value,
                             paste(dQuote(choices, FALSE), collapse = ", ")))
    choices[[i]]
}

.num <- function(value, what) {
    if (is.null(value)) return(NULL)
    if (!is.numeric(value) || length(value) == 0L)
        .stop_option(sprintf("'%s' must be numeric", what))
    as.double(value)
}

## A condition of class "trigspline_error" carrying the library's status name,
## its sentence, the 1-based index and what it refers to.
.condition <- function(status, message, index = NA_real_, where = "none", call = NULL) {
    structure(class = c("trigspline_error", "error", "condition"),
              list(message = message, call = call, status = status,
                   index = index, where = where))
}

.stop_option <- function(message, call = sys.call(-1L))
    stop(.condition("TS_ERR_OPTION", message, call = call))

## The value of a .Call, or the failure it returned signalled as a condition.
.check <- function(res, call = sys.call(-1L)) {
    if (inherits(res, "trigspline_failure"))
        stop(.condition(res$status, res$message, res$index, res$where, call))
    res
}

## x, y as splinefun() takes them (the rules of stats' regularize.values(),
## not exported before R 4.3): xy.coords; pairs with an NA dropped
## (na.rm = TRUE) or kept (the library then names the point); sorted unless
## ties = "ordered" (or list("ordered", fun)); tied x collapsed by ties.
.regularize <- function(x, y, ties, warn, na.rm) {
    xy <- grDevices::xy.coords(x, y, setLab = FALSE)
    x <- xy$x
    y <- xy$y
    na <- is.na(x) | is.na(y)
    if (na.rm && any(na)) {
        x <- x[!na]
        y <- y[!na]
    }
    if (!identical(ties, "ordered")) {
        ordered <- FALSE
        if (is.list(ties) && length(ties) == 2L && is.function(ties[[2L]])) {
            ordered <- identical(ties[[1L]], "ordered")
            ties <- ties[[2L]]
        } else if (!is.function(ties) && !is.character(ties)) {
            stop("'ties' is not \"ordered\", a function, or list(<string>, <function>)")
        }
        if (!ordered && is.unsorted(x, na.rm = TRUE)) {
            o <- order(x)
            x <- x[o]
            y <- y[o]
        }
        ux <- unique(x)
        if (length(ux) < length(x)) {
            if (warn) warning("collapsing to unique 'x' values")
            y <- as.vector(tapply(y, match(x, x), ties))
            x <- ux
        }
    }
    list(x = as.double(x), y = as.double(y))
}

## A constant line (one number) or c(intercept, slope), as abline(a, b).
.line <- function(value, what) {
    if (is.null(value)) return(NULL)
    value <- .num(value, what)
    if (length(value) == 1L) value <- c(value, 0)
    if (length(value) != 2L)
        .stop_option(sprintf("'%s' must be a constant or c(intercept, slope)", what))
    value
}
