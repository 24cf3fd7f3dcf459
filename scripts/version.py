#!/usr/bin/env python3
"""The version's one source is project(trigspline VERSION X.Y.Z) in
CMakeLists.txt.  This script reads it for the builds that do not run CMake
(the WebAssembly module and the musl references of `make web`).

Usage (standard library only):
  python3 scripts/version.py                 prints X.Y.Z
  python3 scripts/version.py --header OUT    writes trigspline_version.h from
                                             cmake/trigspline_version.h.in, as
                                             CMake's configure_file does
"""
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def cmake_version(root=ROOT):
    with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as fh:
        m = re.search(r"project\(trigspline\s+VERSION\s+([0-9]+)\.([0-9]+)\.([0-9]+)", fh.read())
    if not m:
        raise SystemExit("CMakeLists.txt: no project(trigspline VERSION X.Y.Z)")
    return m.group(1), m.group(2), m.group(3)


def version_header(root=ROOT):
    major, minor, patch = cmake_version(root)
    with open(os.path.join(root, "cmake", "trigspline_version.h.in"), encoding="utf-8") as fh:
        text = fh.read()
    for name, value in (("MAJOR", major), ("MINOR", minor), ("PATCH", patch)):
        text = text.replace("@PROJECT_VERSION_%s@" % name, value)
    if "@" in text:
        raise SystemExit("cmake/trigspline_version.h.in: a variable this script does not know")
    return text


def main(argv):
    if len(argv) == 1:
        print(".".join(cmake_version()))
    elif len(argv) == 3 and argv[1] == "--header":
        text = version_header()
        os.makedirs(os.path.dirname(os.path.abspath(argv[2])), exist_ok=True)
        try:
            with open(argv[2], encoding="utf-8") as fh:
                if fh.read() == text:
                    return 0  # unchanged: keep its time stamp
        except OSError:
            pass
        with open(argv[2], "w", encoding="utf-8") as fh:
            fh.write(text)
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
