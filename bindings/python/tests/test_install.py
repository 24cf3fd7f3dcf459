"""The package as a user installs it: its declared build and runtime
requirements, a fresh venv without system site-packages and plain
`pip install` (build isolation) from a local index, import from another
directory without environment variables; version checks.  (tests/run.sh
installs the package under test with --no-build-isolation into a venv made
with --system-site-packages: Debian's numpy, no index.)"""
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

import trigspline
from conftest import REPO

PKG = os.path.join(REPO, "bindings", "python")


def cmake_version():
    with open(os.path.join(REPO, "CMakeLists.txt")) as fh:
        return re.search(r"project\(trigspline\s+VERSION\s+([0-9.]+)", fh.read()).group(1)


def test_version_is_the_cmake_version():
    assert trigspline.__version__ == cmake_version() == trigspline.library_version()


def test_typed():
    assert os.path.exists(os.path.join(os.path.dirname(trigspline.__file__), "py.typed"))


def clean_env():
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "PIP_"))}
    env["PIP_NO_INDEX"] = "1"          # prove no download is needed
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return env


def pyproject():
    import tomllib  # Python 3.11 (Debian 12's); the package itself needs 3.9
    with open(os.path.join(PKG, "pyproject.toml"), "rb") as fh:
        return tomllib.load(fh)


def test_build_requirements_declared():
    # PEP 517/518: setuptools' own backend, and what it needs to build the
    # extension modules (numpy's headers) is named, not assumed installed
    build = pyproject()["build-system"]
    assert build["build-backend"] == "setuptools.build_meta"
    assert "backend-path" not in build
    names = {re.split(r"[<>=!~ \[;]", r)[0].lower() for r in build["requires"]}
    assert {"setuptools", "wheel", "numpy"} <= names
    project = pyproject()["project"]
    assert [re.split(r"[<>=!~ ]", d)[0] for d in project["dependencies"]] == ["numpy"]
    assert project["requires-python"].startswith(">=3.")


@pytest.mark.skipif(os.environ.get("TS_SKIP_VENV_TEST") == "1", reason="TS_SKIP_VENV_TEST=1")
def test_pip_install_with_build_isolation_from_an_index(tmp_path):
    # pip's default path outside Debian: a venv without system site-packages
    # (no numpy, no wheel), build isolation, build and runtime requirements
    # fetched from an index.  The index is a local wheelhouse (wheelhouse.py:
    # setuptools, wheel and numpy wheels made from Debian's copies), since
    # PyPI is not reachable; PIP_NO_INDEX proves nothing else is fetched.
    import wheelhouse
    wh = wheelhouse.make(str(tmp_path / "wheelhouse"))
    venv = tmp_path / "v"
    subprocess.run(["/usr/bin/python3", "-m", "venv", str(venv)], check=True)
    r = subprocess.run([str(venv / "bin" / "python"), "-c", "import numpy"],
                       env=clean_env(), capture_output=True, text=True)
    assert r.returncode != 0, "the venv must start without numpy"
    r = subprocess.run([str(venv / "bin" / "pip"), "install", "-q", "--find-links", wh, PKG],
                       env=clean_env(), capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    r = subprocess.run([str(venv / "bin" / "python"), "-c",
                        "import trigspline, numpy, json, importlib.metadata as m; "
                        "s = trigspline.Spline([0, 1, 2], [1, 0, 1], shape='positive'); "
                        "md = m.metadata('trigspline'); "
                        "print(trigspline.__version__, s.certified, trigspline.__file__, "
                        "numpy.__file__); "
                        "print(md['Requires-Python']); print(json.dumps(md.get_all('Requires-Dist'))); "
                        "print(md['License'], md.get_all('Classifier')); "
                        "print(sorted(str(p) for p in m.files('trigspline') "
                        "if p.name.startswith('LICENSE')))"],
                       cwd=str(elsewhere), env=clean_env(), capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    first, requires_python, requires, licence, files = r.stdout.splitlines()
    version, certified, where, numpy_where = first.split()
    assert version == cmake_version() and certified == "True"
    assert where.startswith(str(venv)) and numpy_where.startswith(str(venv))
    assert requires_python == pyproject()["project"]["requires-python"]
    assert any(q.startswith("numpy") and "extra" not in q for q in json.loads(requires))
    assert "BSD-3-Clause" in licence and "License :: OSI Approved :: BSD License" in licence
    assert "LICENSE" in files


def test_stale_extension_is_refused(tmp_path):
    # the installed package with a different _version.py: import must refuse it
    src = os.path.dirname(trigspline.__file__)
    dst = tmp_path / "trigspline"
    shutil.copytree(src, dst)
    (dst / "_version.py").write_text('__version__ = "9.9.9"\n')
    r = subprocess.run([sys.executable, "-c", "import trigspline"], cwd=str(tmp_path),
                       env=clean_env(), capture_output=True, text=True)
    assert r.returncode != 0
    assert "ImportError" in r.stderr and "9.9.9" in r.stderr and "0." in r.stderr
