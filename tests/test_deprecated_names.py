#!/usr/bin/env python3
"""The 0.1 names still compile, with a deprecation warning naming the new
name, and give the new names' results (tests/deprecated_use.c); with
TS_NO_DEPRECATED they are gone (the program no longer compiles).

Usage: python3 tests/test_deprecated_names.py BUILD_DIR   (standard library only)
BUILD_DIR holds libtrigspline.a and the generated header trigspline_version.h.
Last line: "test_deprecated_names: N passed, M failed".
"""
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
repo = os.path.dirname(here)
build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(repo, "build"))
src = os.path.join(here, "deprecated_use.c")
cc = os.environ.get("CC", "cc")
passed = failed = 0


def check(ok, what):
    global passed, failed
    passed, failed = passed + bool(ok), failed + (not ok)
    if not ok:
        print("FAIL: " + what)


OLD = {"ts_options": "ts_spline_options", "ts_options_init": "ts_spline_options_init",
       "ts_eval": "ts_spline_eval", "ts_eval_deriv": "ts_spline_eval_deriv",
       "ts_eval_batch": "ts_spline_eval_batch", "ts_eval_batch_mt": "ts_spline_eval_batch_mt",
       "ts_integral": "ts_spline_integral", "ts_certify": "ts_spline_certify",
       "ts_error_bound": "ts_spline_error_bound"}
with tempfile.TemporaryDirectory() as tmp:
    exe = os.path.join(tmp, "deprecated_use")
    base = [cc, "-std=c11", "-Wall", "-Wextra", "-I" + os.path.join(repo, "include"),
            "-I" + os.path.join(build, "include"), src]
    p = subprocess.run(base + ["-o", exe, os.path.join(build, "libtrigspline.a"), "-lm",
                               "-lpthread"], capture_output=True, text=True)
    check(p.returncode == 0, "the old names compile and link: " + p.stderr[-2000:])
    for old, new in OLD.items():
        pat = r"['\u2018]%s['\u2019] is deprecated: use %s\b" % (old, new)
        check(re.search(pat, p.stderr) is not None, "a warning names %s's replacement %s"
              % (old, new))
    if p.returncode == 0:
        r = subprocess.run([exe], capture_output=True, text=True)
        print(r.stdout.strip())
        check(r.returncode == 0 and " 0 failed" in r.stdout, "old and new names agree bit for bit")
    p = subprocess.run(base + ["-DTS_NO_DEPRECATED", "-c", "-o", exe + ".o"],
                       capture_output=True, text=True)
    check(p.returncode != 0 and "ts_options" in p.stderr,
          "TS_NO_DEPRECATED hides the old names")

print("test_deprecated_names: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
