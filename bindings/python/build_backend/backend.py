"""PEP 517 backend: setuptools' own, found without a download.

pip's isolated build environment hides the interpreter's site-packages; with
no build requirements to install (pyproject.toml) this module adds them back
when setuptools is not importable, so the installed setuptools, wheel and
numpy (Debian's python3-setuptools, python3-wheel, python3-numpy) build the
package offline.  Everything else is setuptools.build_meta.
"""
import site
import sys

try:
    import setuptools.build_meta as _meta
except ImportError:
    for _p in site.getsitepackages():
        if _p not in sys.path:
            sys.path.append(_p)
    try:
        import setuptools.build_meta as _meta
    except ImportError:
        raise ImportError("building trigspline needs setuptools, wheel and numpy installed "
                          "(Debian: apt-get install python3-setuptools python3-wheel "
                          "python3-numpy python3-dev)") from None

build_wheel = _meta.build_wheel
build_sdist = _meta.build_sdist
prepare_metadata_for_build_wheel = _meta.prepare_metadata_for_build_wheel
if hasattr(_meta, "build_editable"):
    build_editable = _meta.build_editable
    prepare_metadata_for_build_editable = _meta.prepare_metadata_for_build_editable


def _nothing(config_settings=None):
    """Nothing to download: setuptools, wheel and numpy are installed."""
    return []


get_requires_for_build_wheel = _nothing
get_requires_for_build_sdist = _nothing
get_requires_for_build_editable = _nothing
