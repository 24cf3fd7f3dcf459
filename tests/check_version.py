#!/usr/bin/env python3
"""Every place that states trigspline's version agrees with its one source,
project(trigspline VERSION X.Y.Z) in CMakeLists.txt:

  built code   ts_version() of BUILD/libtrigspline.so (ctypes), the generated
               BUILD/include/trigspline_version.h (= the template filled the way
               scripts/version.py and bindings/python/setup.py fill it),
               `BUILD/trigspline --version`, the Python package's
               trigspline.__version__ (the venv bindings/python/tests/run.sh
               made in BUILD/python-venv; tests/run_all.sh runs this script
               after it) and the JavaScript module's ts.version (when a web
               build exists: out/web, or TS_WEB_OUT)
  text files   CITATION.cff, the man page docs/trigspline.1,
               bindings/web/package.json and package-lock.json, debian/changelog,
               packaging/conda/meta.yaml

Usage: python3 tests/check_version.py BUILD_DIR       (standard library only)
Last line: "version: N passed, M failed".  A part whose build is absent (no
venv, no web build) is reported as skipped, not passed.
"""
import ctypes
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, "scripts"))
import version as version_script  # noqa: E402  (scripts/version.py)

build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(REPO, "build"))
passed = failed = 0


def check(what, got, want):
    global passed, failed
    if got == want:
        passed += 1
    else:
        failed += 1
        print("FAIL: %s says %r, CMakeLists.txt %r" % (what, got, want))


def read(path):
    with open(path, encoding="utf-8") as fh:
        return fh.read()


want = ".".join(version_script.cmake_version(REPO))

# ---- built code --------------------------------------------------------
lib = ctypes.CDLL(os.path.join(build, "libtrigspline.so"))
lib.ts_version.restype = ctypes.c_char_p
check("ts_version() of libtrigspline.so", lib.ts_version().decode(), want)

header = read(os.path.join(build, "include", "trigspline_version.h"))
check("the generated trigspline_version.h", header, version_script.version_header(REPO))
m = re.search(r'#define TS_VERSION_STRING "([^"]*)"', header)
check("TS_VERSION_STRING", m and m.group(1), want)

cli = os.path.join(build, "trigspline")
if os.path.exists(cli):
    out = subprocess.run([cli, "--version"], capture_output=True, text=True).stdout
    check("trigspline --version", out, "trigspline %s\n" % want)
else:
    print("skipped: %s not built" % cli)

venv_python = os.path.join(build, "python-venv", "bin", "python")
if os.path.exists(venv_python):
    out = subprocess.run([venv_python, "-c", "import trigspline; print(trigspline.__version__, "
                          "trigspline.library_version())"],
                         capture_output=True, text=True, cwd=build)
    check("Python trigspline.__version__, library_version()", out.stdout.split(),
          [want, want])
else:
    print("skipped: no Python package installed in %s/python-venv" % build)

web = os.environ.get("TS_WEB_OUT", os.path.join(REPO, "out", "web"))
mjs = os.path.join(web, "trigspline.mjs")
if os.path.exists(mjs) and os.path.exists(os.path.join(web, "trigspline.wasm")):
    code = ("import(process.argv[1]).then(async (m) => { const ts = await m.load(); "
            "console.log(ts.version); })")
    out = subprocess.run(["node", "-e", code, "file://" + os.path.abspath(mjs)],
                         capture_output=True, text=True)
    check("JavaScript module ts.version", out.stdout.strip(), want)
else:
    print("skipped: no web build in %s" % web)

# ---- text files ----------------------------------------------------------
m = re.search(r"^version:\s*(\S+)\s*$", read(os.path.join(REPO, "CITATION.cff")), re.M)
check("CITATION.cff version", m and m.group(1), want)
m = re.match(r'\.TH TRIGSPLINE 1 "[^"]*" "trigspline ([^"]*)"', read(os.path.join(REPO, "docs",
                                                                               "trigspline.1")))
check("docs/trigspline.1 .TH", m and m.group(1), want)
pkg = json.loads(read(os.path.join(REPO, "bindings", "web", "package.json")))
check("bindings/web/package.json", pkg.get("version"), want)
lock = json.loads(read(os.path.join(REPO, "bindings", "web", "package-lock.json")))
check("bindings/web/package-lock.json", [lock.get("version"), lock["packages"][""].get("version")],
      [want, want])
# packaging: Debian (upstream part of the first changelog entry), conda recipe
m = re.match(r"trigspline \(([^)-]*)-[^)]*\)", read(os.path.join(REPO, "debian", "changelog")))
check("debian/changelog", m and m.group(1), want)
m = re.search(r'set version = "([^"]*)"', read(os.path.join(REPO, "packaging", "conda", "meta.yaml")))
check("packaging/conda/meta.yaml", m and m.group(1), want)

print("version: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
