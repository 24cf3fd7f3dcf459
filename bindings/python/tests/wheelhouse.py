"""A local package index (a --find-links directory) standing in for PyPI,
which is not reachable here: wheels of setuptools, wheel and numpy made from
Debian's installed copies, so that pip's default path -- build isolation,
build requirements (pyproject.toml) and runtime requirements downloaded from
an index -- can be exercised offline.

setuptools: Debian's own wheel (python3-setuptools-whl, the one ensurepip
uses).  wheel and numpy: the installed package directories of
python3-wheel and python3-numpy zipped as wheels (dist-info from the
installed PKG-INFO and entry points, a RECORD with sha256 hashes).  numpy's wheel is tagged
for this interpreter and platform; its extension modules link Debian's BLAS,
present on this machine.

    python3 wheelhouse.py DIR      # writes the wheels into DIR
"""
import base64
import hashlib
import importlib.metadata
import os
import shutil
import sys
import sysconfig
import zipfile

DIST_PACKAGES = "/usr/lib/python3/dist-packages"
DEBIAN_WHEELS = "/usr/share/python-wheels"


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return "%s,sha256=%s,%d" % (arcname, digest, len(data))


def wheel_from_installed(name, tag, dest):
    """A wheel of the installed distribution NAME (its top-level packages)."""
    dist = next(d for d in importlib.metadata.distributions(path=[DIST_PACKAGES])
                if d.metadata["Name"].lower() == name.lower())
    version = dist.version
    top = (dist.read_text("top_level.txt") or name).split()
    info = "%s-%s.dist-info" % (name, version)
    path = os.path.join(dest, "%s-%s-%s.whl" % (name, version, tag))
    record = []
    with zipfile.ZipFile(path, "w", zipfile.ZIP_STORED) as zf:
        def add(arcname, data):
            zf.writestr(arcname, data)
            record.append(_record_line(arcname, data))
        for pkg in top:
            base = os.path.join(DIST_PACKAGES, pkg)
            for root, dirs, files in os.walk(base):
                dirs[:] = sorted(d for d in dirs if d != "__pycache__")
                for fn in sorted(files):
                    full = os.path.join(root, fn)
                    with open(full, "rb") as fh:
                        add(os.path.relpath(full, DIST_PACKAGES), fh.read())
        metadata = dist.read_text("PKG-INFO") or dist.read_text("METADATA")
        add(info + "/METADATA", metadata.encode())
        # entry points: setuptools finds wheel's bdist_wheel command through them
        entry_points = dist.read_text("entry_points.txt")
        if entry_points:
            add(info + "/entry_points.txt", entry_points.encode())
        purelib = tag.endswith("none-any")
        add(info + "/WHEEL", ("Wheel-Version: 1.0\nGenerator: trigspline-wheelhouse\n"
                              "Root-Is-Purelib: %s\nTag: %s\n"
                              % ("true" if purelib else "false", tag)).encode())
        record.append(info + "/RECORD,,")
        zf.writestr(info + "/RECORD", "\n".join(record) + "\n")
    return path


def make(dest):
    """Writes the wheelhouse into DEST; returns DEST."""
    os.makedirs(dest, exist_ok=True)
    for fn in os.listdir(DEBIAN_WHEELS):
        if fn.startswith("setuptools-"):
            shutil.copy(os.path.join(DEBIAN_WHEELS, fn), dest)
    wheel_from_installed("wheel", "py3-none-any", dest)
    impl = "cp%d%d" % sys.version_info[:2]
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    wheel_from_installed("numpy", "%s-%s-%s" % (impl, impl, platform), dest)
    return dest


if __name__ == "__main__":
    make(sys.argv[1])
    print("\n".join(sorted(os.listdir(sys.argv[1]))))
