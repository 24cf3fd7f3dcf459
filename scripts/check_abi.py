#!/usr/bin/env python3
"""The library's ABI against the checked-in list abi/trigspline.abi.

The list has one line per fact a compiled program depends on, sorted:
  symbol NAME                   a function exported by BUILD/libtrigspline.so
                                (nm -D --defined-only)
  size STRUCT N                 sizeof of each public struct of trigspline.h
  offset STRUCT.FIELD N         offsetof of each of its fields
  value ENUMERATOR N            each enumerator of the public enums
Sizes and offsets are those of the platform named in the list's "# platform"
line (the C compiler of BUILD, a program compiled and run here); on another
platform only the symbols and values are compared.

Usage (standard library only):
  python3 scripts/check_abi.py BUILD_DIR            compare; last line
                                                    "abi: N passed, M failed"
  python3 scripts/check_abi.py BUILD_DIR --update   rewrite abi/trigspline.abi

A difference fails with the lines that differ.  Update the list on purpose,
in the same commit as the change, after checking docs/versions.md: removing
or changing anything is an ABI break (soname and version policy there);
adding a symbol or an enumerator is not.
"""
import os
import platform
import re
import subprocess
import sys
import tempfile

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
HEADER = os.path.join(REPO, "include", "trigspline.h")
LIST = os.path.join(REPO, "abi", "trigspline.abi")


def strip_comments(code):
    code = re.sub(r"/\*.*?\*/", " ", code, flags=re.S)
    return re.sub(r"//[^\n]*", " ", code)


def public_structs(code):
    """{struct name: [field names]} of every `typedef struct NAME {...} NAME;`."""
    out = {}
    for m in re.finditer(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", code, re.S):
        fields = []
        for decl in m.group(2).split(";"):
            decl = re.sub(r"\[[^\]]*\]", "", decl).strip()
            if not decl:
                continue
            words = decl.split(",")
            fields.append(re.findall(r"\w+", words[0])[-1])
            fields.extend(w.strip().lstrip("*").strip() for w in words[1:])
        out[m.group(3)] = fields
    return out


def enumerators(code):
    names = []
    for m in re.finditer(r"typedef\s+enum\s+\w+\s*\{(.*?)\}\s*\w+\s*;", code, re.S):
        names += re.findall(r"\b(TS_[A-Z0-9_]+)\b\s*(?:=[^,]*)?(?:,|$)", m.group(1).strip())
    return names


def compiler(build):
    try:
        with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8") as fh:
            m = re.search(r"^CMAKE_C_COMPILER:\w+=(.+)$", fh.read(), re.M)
            if m:
                return m.group(1).strip()
    except OSError:
        pass
    return os.environ.get("CC", "cc")


def layout(build):
    """size/offset/value lines from a program compiled against the header."""
    code = strip_comments(open(HEADER, encoding="utf-8").read())
    structs = public_structs(code)
    prog = ["#include <stdio.h>", "#include <stddef.h>", '#include "trigspline.h"',
            "int main(void) {"]
    for s, fields in sorted(structs.items()):
        prog.append('printf("size %s %%zu\\n", sizeof(%s));' % (s, s))
        for f in fields:
            prog.append('printf("offset %s.%s %%zu\\n", offsetof(%s, %s));' % (s, f, s, f))
    for e in enumerators(code):
        prog.append('printf("value %s %%lld\\n", (long long)%s);' % (e, e))
    prog += ["return 0;", "}"]
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "abi.c")
        exe = os.path.join(tmp, "abi")
        with open(src, "w", encoding="utf-8") as fh:
            fh.write("\n".join(prog) + "\n")
        subprocess.run([compiler(build), "-std=c11", "-I", os.path.join(REPO, "include"),
                        "-I", os.path.join(build, "include"), src, "-o", exe], check=True)
        return subprocess.run([exe], check=True, capture_output=True,
                              text=True).stdout.splitlines()


def symbols(build):
    out = subprocess.run(["nm", "-D", "--defined-only", os.path.join(build, "libtrigspline.so")],
                         check=True, capture_output=True, text=True).stdout
    return ["symbol " + f[2].split("@")[0] for f in (l.split() for l in out.splitlines())
            if len(f) >= 3 and f[1] in "TtWiV"]


def platform_name():
    import struct
    return "%s, %d-bit pointers" % (platform.machine(), 8 * struct.calcsize("P"))


def main(argv):
    if len(argv) < 2 or argv[1].startswith("-"):
        print(__doc__, file=sys.stderr)
        return 2
    build = os.path.abspath(argv[1])
    update = "--update" in argv[2:]
    facts = sorted(set(symbols(build) + layout(build)))
    plat = platform_name()
    if update:
        os.makedirs(os.path.dirname(LIST), exist_ok=True)
        with open(LIST, "w", encoding="utf-8") as fh:
            fh.write("# The ABI of libtrigspline (scripts/check_abi.py; docs/versions.md).\n"
                     "# Rewritten by `python3 scripts/check_abi.py BUILD_DIR --update`: only on\n"
                     "# purpose, in the commit that changes the ABI.\n")
            fh.write("# platform: %s\n" % plat)
            fh.write("\n".join(facts) + "\n")
        print("abi: wrote %s (%d lines)" % (os.path.relpath(LIST, REPO), len(facts)))
        print("abi: 1 passed, 0 failed")
        return 0
    with open(LIST, encoding="utf-8") as fh:
        text = fh.read()
    m = re.search(r"^# platform: (.*)$", text, re.M)
    same_platform = bool(m) and m.group(1) == plat
    want = sorted(l for l in text.splitlines() if l and not l.startswith("#"))
    if not same_platform:
        print("abi: list made on %s, this is %s: sizes and offsets not compared"
              % (m.group(1) if m else "?", plat))
        keep = lambda l: not l.startswith(("size ", "offset "))  # noqa: E731
        want = [l for l in want if keep(l)]
        facts = [l for l in facts if keep(l)]
    gone = sorted(set(want) - set(facts))
    new = sorted(set(facts) - set(want))
    for l in gone:
        print("- " + l)
    for l in new:
        print("+ " + l)
    if gone or new:
        print("FAIL: the ABI of %s differs from %s (- listed, + built).\n"
              "If the change is intended, check docs/versions.md (removing or changing a line\n"
              "breaks the ABI), then run\n"
              "    python3 scripts/check_abi.py %s --update\n"
              "and commit abi/trigspline.abi with the change."
              % (os.path.join(argv[1], "libtrigspline.so"), os.path.relpath(LIST, REPO), argv[1]))
        print("abi: %d passed, 1 failed" % (len(facts) - len(new)))
        return 1
    print("abi: %d passed, 0 failed" % len(facts))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
