"""trigspline: shape-preserving interpolation with the GC¹ cubic trigonometric
spline, certified (Python binding of libtrigspline via ctypes).

    >>> from trigspline import Spline
    >>> s = Spline([0, 2, 3, 5, 15, 25, 27, 28, 30],
    ...            [2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2],
    ...            shape="positive", alpha=0.15)
    >>> s.certified
    True

See python/README.md.  The shared library is found through TRIGSPLINE_LIB,
next to this package, in the repository's build/ directory, or on the system
library path (in that order).
"""
from ._ffi import lib_path
from ._util import np as _np
from .curve import Curve
from .errors import TrigsplineError, strerror
from .spline import Spline, estimate_slopes

__all__ = ["Spline", "Curve", "TrigsplineError", "estimate_slopes", "strerror",
           "library_version", "lib_path", "HAVE_NUMPY"]

HAVE_NUMPY = _np is not None


def library_version():
    """Version string of the loaded libtrigspline, e.g. "0.1.0"."""
    from ._ffi import lib
    return lib.ts_version().decode("ascii")


__version__ = "0.1.0"
