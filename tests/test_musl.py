#!/usr/bin/env python3
"""The library on musl (Alpine, musllinux wheels): built with Debian's
musl-gcc (musl-tools) by CMake into BUILD_DIR/musl, it must load and pass
some of its C tests there.  musl's loader has no ifunc (IRELATIVE
relocations: "unsupported relocation type 37", exit 127), so src/internal.h
keeps target_clones to glibc; checked here on both sides:
  - the musl library and test programs carry no IRELATIVE relocation,
  - BUILD_DIR's own library, when GCC built it for glibc on x86-64 Linux,
    still has them (the clones were not dropped everywhere);
  - the smoke program (tools/dist/smoke/smoke.c, README's example) linked
    with the musl shared library prints exactly what the same program
    linked with BUILD_DIR's library prints (same bits on both C libraries:
    every clone gives the same values, src/internal.h);
  - the API tests test_core, test_batch, test_eval_mode pass on musl.
Usage: python3 tests/test_musl.py BUILD_DIR   (last line "test_musl: N passed, M failed")
`make test` installs musl-tools; without musl-gcc this test fails.
"""
import glob
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TESTS = ["test_core", "test_batch", "test_eval_mode"]
passed = failed = 0


def check(ok, what, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAILED: %s%s" % (what, ("\n" + detail) if detail else ""))


def run(cmd, **kw):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)


def irelative(path):
    r = run(["readelf", "-r", path])
    return r.stdout.count("IRELATIV") if r.returncode == 0 else -1


def gcc_glibc_x86_64(build):
    """BUILD was configured with GCC (not Clang) and is not a ThreadSanitizer
    build: the conditions of src/internal.h besides the C library."""
    ids = glob.glob(os.path.join(build, "CMakeFiles", "*", "CMakeCCompiler.cmake"))
    if not ids or os.uname().machine != "x86_64":
        return False
    text = open(ids[0]).read()
    cache = open(os.path.join(build, "CMakeCache.txt")).read()
    return 'CMAKE_C_COMPILER_ID "GNU"' in text and "sanitize=thread" not in cache


def main():
    build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build")
    if not shutil.which("musl-gcc"):
        check(False, "musl-gcc not found (apt-get install musl-tools; make test does)")
        return
    mb = os.path.join(build, "musl")
    env = dict(os.environ, CC="musl-gcc")
    r = run(["cmake", "-S", ROOT, "-B", mb, "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
             "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2", "-DTS_WERROR=ON", "-DTS_BUILD_TOOLS=OFF",
             "-DTS_BUILD_EXAMPLES=OFF"], env=env)
    check(r.returncode == 0, "cmake configure with musl-gcc", r.stdout[-3000:])
    if r.returncode:
        return
    r = run(["cmake", "--build", mb, "-j", "2", "--target", "trigspline_shared"] + TESTS)
    check(r.returncode == 0, "musl-gcc build", r.stdout[-3000:])
    if r.returncode:
        return
    lib = os.path.join(mb, "libtrigspline.so")
    for path in [lib] + [os.path.join(mb, "tests", t) for t in TESTS]:
        n = irelative(path)
        check(n == 0, "%s: %d IRELATIVE relocations on musl" % (os.path.basename(path), n))
    glibc_lib = os.path.join(build, "libtrigspline.so")
    if os.path.exists(glibc_lib) and gcc_glibc_x86_64(build):
        n = irelative(glibc_lib)
        check(n > 0, "the glibc library of %s has no IRELATIVE relocation (target_clones gone)"
              % build)
    for t in TESTS:
        r = run([os.path.join(mb, "tests", t)])
        check(r.returncode == 0 and re.search(r" 0 failed", r.stdout),
              "%s on musl" % t, r.stdout[-3000:])
    smoke = os.path.join(ROOT, "tools", "dist", "smoke", "smoke.c")
    inc = ["-I" + os.path.join(ROOT, "include")]
    outs = {}
    for cc, libdir in (("musl-gcc", mb), ("cc", build)):
        if not os.path.exists(os.path.join(libdir, "libtrigspline.so")):
            continue
        exe = os.path.join(mb, "smoke-" + cc)
        r = run([cc, "-std=c11", "-O2"] + inc + ["-I" + os.path.join(libdir, "include"), smoke,
                "-L" + libdir, "-Wl,-rpath," + libdir, "-ltrigspline", "-lm", "-o", exe])
        check(r.returncode == 0, "compile the smoke program with " + cc, r.stdout)
        if r.returncode == 0:
            r = run([exe])
            check(r.returncode == 0, "smoke program with %s's library" % cc, r.stdout)
            outs[cc] = r.stdout
    if len(outs) == 2:
        check(outs["musl-gcc"] == outs["cc"], "musl and glibc builds print different results",
              outs["musl-gcc"] + "---\n" + outs["cc"])
    else:
        check("musl-gcc" in outs, "smoke program on musl")


if __name__ == "__main__":
    main()
    print("test_musl: %d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)
