"""trigspline: shape-preserving interpolation with the GC¹ cubic trigonometric
spline, certified.  The interface of SciPy's interpolators; the C library
(libtrigspline) is compiled into the extension module ``trigspline._core``.

    >>> import numpy as np, trigspline
    >>> s = trigspline.Spline([0, 2, 3, 5, 15, 25, 27, 28, 30],
    ...                       [2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2],
    ...                       shape="positive", alpha=0.15)
    >>> bool(s.certified)
    True

See the package README (bindings/python/README.md in the repository).
"""
try:
    from ._version import __version__
    from . import _core
except ImportError as _e:  # the source tree, not an installed package
    raise ImportError(
        "trigspline is imported from %s, which has no built extension module (%s); install "
        "the package (pip install bindings/python) and import it from elsewhere"
        % (__path__[0], _e)) from None

if _core.library_version() != __version__ or _core.HEADER_VERSION != __version__:
    raise ImportError(
        "trigspline %s: its extension module trigspline._core (%s) was built from "
        "libtrigspline %s (header %s); reinstall the package (a stale build is on the path)"
        % (__version__, _core.__file__, _core.library_version(), _core.HEADER_VERSION))

from ._options import defaults  # noqa: E402
from .curve import Curve  # noqa: E402
from .errors import TrigsplineError, strerror  # noqa: E402
from .spline import Antiderivative, Derivative, Spline, estimate_slopes  # noqa: E402
from .surface import Surface  # noqa: E402
from .interp import interp  # noqa: E402
from .histo import disaggregate  # noqa: E402

__all__ = ["Spline", "Curve", "Surface", "Derivative", "Antiderivative", "TrigsplineError",
           "interp", "disaggregate", "estimate_slopes", "strerror", "defaults", "library_version",
           "__version__"]


def library_version() -> str:
    """Version of the libtrigspline compiled into the package, e.g. "0.2.0"."""
    return _core.library_version()


# The xarray accessor (``da.trigspline``, ``ds.trigspline``) registers itself
# when xarray is installed, as rioxarray's does; without xarray nothing is
# imported (find_spec only looks the package up).
def _register_xarray():
    import importlib.util
    if importlib.util.find_spec("xarray") is not None:
        from . import xarray  # noqa: F401


_register_xarray()
