"""The package as a user installs it: a fresh venv with --system-site-packages,
plain `pip install` (build isolation, offline), import from another directory
without environment variables; version checks."""
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


@pytest.mark.skipif(os.environ.get("TS_SKIP_VENV_TEST") == "1", reason="TS_SKIP_VENV_TEST=1")
def test_fresh_venv_plain_pip_install(tmp_path):
    venv = tmp_path / "v"
    subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(venv)],
                   check=True)
    r = subprocess.run([str(venv / "bin" / "pip"), "install", "-q", PKG], env=clean_env(),
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    r = subprocess.run([str(venv / "bin" / "python"), "-c",
                        "import trigspline, numpy; s = trigspline.Spline([0, 1, 2], [1, 0, 1], "
                        "shape='positive'); print(trigspline.__version__, s.certified, "
                        "trigspline.__file__)"],
                       cwd=str(elsewhere), env=clean_env(), capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    version, certified, where = r.stdout.split()
    assert version == cmake_version() and certified == "True"
    assert where.startswith(str(venv))


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
