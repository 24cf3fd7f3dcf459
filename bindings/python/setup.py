"""Build of the trigspline Python package (setuptools; pyproject.toml names
the build requirements: setuptools, wheel, numpy).

The C library is compiled from the repository's own sources (../../src; in an
sdist its copy csrc/, which Sdist below writes) into
every extension module listed in EXT_MODULES, so the installed package needs
nothing else on the system.  One place for what the library needs to compile:
LIB_SOURCES and LIB_SOURCE_FLAGS (read from src/CMakeLists.txt), INCLUDE_DIRS,
COMPILE_ARGS, DEFINE_MACROS.  A further extension is one more extension(...)
line in EXT_MODULES.  The version is the CMake project version.
"""
import os
import re
from concurrent.futures import ThreadPoolExecutor

import numpy
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py
from setuptools.command.sdist import sdist

HERE = os.path.dirname(os.path.abspath(__file__))
# The library's tree: the repository (../..) or, in an sdist, csrc/.
CSRC = os.path.join(HERE, "csrc")
ROOT = CSRC if os.path.isdir(CSRC) else os.path.normpath(os.path.join(HERE, "..", ".."))
SRC = os.path.join(ROOT, "src")


def read(path):
    with open(path, encoding="utf-8") as fh:
        return fh.read()


# One source of truth: project(trigspline VERSION x.y.z) in CMakeLists.txt.
VERSION = re.search(r"project\(trigspline\s+VERSION\s+([0-9.]+)",
                    read(os.path.join(ROOT, "CMakeLists.txt"))).group(1)

# trigspline_version.h (included by trigspline.h), written from the template
# CMake's configure_file fills (cmake/trigspline_version.h.in) with VERSION:
# the same header as a CMake build's.  BuildExt puts it in build_temp/include.
VERSION_TEMPLATE = os.path.join(ROOT, "cmake", "trigspline_version.h.in")


def version_header():
    text = read(VERSION_TEMPLATE)
    for part, value in zip(("MAJOR", "MINOR", "PATCH"), VERSION.split(".")):
        text = text.replace("@PROJECT_VERSION_%s@" % part, value)
    assert "@" not in text, "cmake/trigspline_version.h.in: a variable setup.py does not fill"
    return text


# The library's sources as listed in src/CMakeLists.txt (TS_LIBRARY_SOURCES).
_block = re.search(r"set\(TS_LIBRARY_SOURCES(.*?)\)", read(os.path.join(SRC, "CMakeLists.txt")),
                   re.S).group(1)
LIB_SOURCES = [os.path.join(SRC, name)
               for name in re.findall(r"([A-Za-z0-9_]+\.c)\b", re.sub(r"#[^\n]*", "", _block))]
# Per-source options of src/CMakeLists.txt (set_source_files_properties ...
# COMPILE_OPTIONS "a;b"), read from there so that the package's objects are
# compiled exactly as the CMake library's (bit-identical results).
LIB_SOURCE_FLAGS = {
    name: opts.split(";")
    for name, opts in re.findall(r"set_source_files_properties\(\$\{CMAKE_CURRENT_SOURCE_DIR\}/"
                                 r"([A-Za-z0-9_]+\.c)\s+PROPERTIES\s+COMPILE_OPTIONS\s+\"([^\"]*)\"",
                                 read(os.path.join(SRC, "CMakeLists.txt")))}
assert LIB_SOURCE_FLAGS, "src/CMakeLists.txt: no per-source compile options found"
INCLUDE_DIRS = [os.path.join(ROOT, "include"), SRC, numpy.get_include()]
# C11 as the CMake build; the library's public functions stay hidden in the
# extension (TS_API empty, -fvisibility=hidden): each module has its own copy.
COMPILE_ARGS = ["-std=c11", "-fvisibility=hidden", "-Wall", "-Wextra"]
DEFINE_MACROS = [("TS_API", ""), ("NPY_NO_DEPRECATED_API", "NPY_1_7_API_VERSION")]
LIBRARIES = ["m"]


def extension(name, source):
    """An extension module of this package with the library compiled in."""
    return Extension(name, sources=[source], include_dirs=INCLUDE_DIRS,
                     define_macros=DEFINE_MACROS, extra_compile_args=COMPILE_ARGS,
                     libraries=LIBRARIES,
                     # setup.py and src/CMakeLists.txt hold the compile options:
                     # a change there relinks (build_ext skips an up-to-date module)
                     depends=LIB_SOURCES + [os.path.join(ROOT, "include", "trigspline.h"),
                                            os.path.join(SRC, "internal.h"),
                                            os.path.join(SRC, "CMakeLists.txt"),
                                            os.path.join(ROOT, "CMakeLists.txt"),
                                            VERSION_TEMPLATE,
                                            os.path.join(HERE, "setup.py")])


EXT_MODULES = [
    extension("trigspline._core", "src/_core.c"),
    extension("trigspline._gufunc", "src/_gufunc.c"),
    extension("trigspline._histo", "src/_histo.c"),
]


class BuildExt(build_ext):
    """Compiles the library's objects once (with their per-source flags) and
    links them into every extension."""

    _lib_objects = None

    def run(self):
        gen = os.path.join(self.build_temp, "include")
        path = os.path.join(gen, "trigspline_version.h")
        text = version_header()
        if not os.path.exists(path) or read(path) != text:
            os.makedirs(gen, exist_ok=True)
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text)
        self.include_dirs = [gen] + list(self.include_dirs or [])
        super().run()

    def library_objects(self):
        if self._lib_objects is None:
            out = os.path.join(self.build_temp, "libtrigspline")

            def compile_one(src):
                flags = COMPILE_ARGS + LIB_SOURCE_FLAGS.get(os.path.basename(src), [])
                return self.compiler.compile([src], output_dir=out, macros=DEFINE_MACROS,
                                             include_dirs=INCLUDE_DIRS, extra_postargs=flags,
                                             debug=self.debug)
            # one compiler process per core (the sources are independent)
            with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
                self._lib_objects = [o for objs in pool.map(compile_one, LIB_SOURCES)
                                     for o in objs]
        return self._lib_objects

    def build_extension(self, ext):
        ext.extra_objects = list(ext.extra_objects or []) + self.library_objects()
        super().build_extension(ext)


class BuildPy(build_py):
    """Writes trigspline/_version.py (the CMake project version) into the build."""

    def run(self):
        super().run()
        if not self.dry_run:
            path = os.path.join(self.build_lib, "trigspline", "_version.py")
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as fh:
                fh.write('"""Generated by setup.py from CMakeLists.txt."""\n'
                         '__version__ = "%s"\n' % VERSION)


class Sdist(sdist):
    """The sdist carries what setup.py reads from the repository (the
    library's sources and header, src/CMakeLists.txt, the version template and
    the top CMakeLists.txt for the version) under csrc/, in the same layout,
    so that it builds outside the repository."""

    def make_release_tree(self, base_dir, files):
        super().make_release_tree(base_dir, files)
        if ROOT == CSRC:
            names = [os.path.relpath(p, ROOT) for p in LIB_SOURCES]
        else:
            names = ["src/" + n for n in sorted(os.listdir(SRC)) if n.endswith((".c", ".h"))]
        names += ["src/CMakeLists.txt", "include/trigspline.h", "CMakeLists.txt",
                  "cmake/trigspline_version.h.in", "LICENSE"]
        for name in sorted(set(names)):
            dst = os.path.join(base_dir, "csrc", name)
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            self.copy_file(os.path.join(ROOT, name), dst)


setup(version=VERSION, packages=["trigspline"], package_data={"trigspline": ["py.typed"]},
      ext_modules=EXT_MODULES,
      cmdclass={"build_ext": BuildExt, "build_py": BuildPy, "sdist": Sdist})
