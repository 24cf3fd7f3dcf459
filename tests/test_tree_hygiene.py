#!/usr/bin/env python3
"""The tree keeps no stale pointers and no process words.

1. Every repository path that a comment of a source file, or a document,
   cites (src/..., tools/..., docs/..., tests/..., bindings/..., scripts/...,
   bench/..., data/..., include/..., adapters/..., examples/..., cmake/...)
   exists, as a file or a folder (a trailing glob or "NAME.*" pattern is
   resolved with glob).
2. Comments of source files carry no process words: "issue N", "finding N",
   "findings of", "review" (the code says what it does and why, the history
   lives in git and CHANGELOG.md).

Usage: python3 tests/test_tree_hygiene.py [BUILD_DIR]   (standard library only;
BUILD_DIR is accepted for tests/run_all.sh and not used)
Last line: "test_tree_hygiene: N passed, M failed".
"""
import glob
import os
import re
import subprocess
import sys

repo = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
files = subprocess.run(["git", "-C", repo, "ls-files"], capture_output=True, text=True,
                       check=True).stdout.split()

SOURCE = (".c", ".h", ".py", ".js", ".mjs", ".sh", ".cmake", ".txt", ".in")
DOCS = (".md", ".1")
HISTORY = {"CHANGELOG.md", "bench/HISTORY.md", "bench/RESULTS.md"}
ROOTS = ("src", "tools", "docs", "tests", "bindings", "scripts", "bench", "data", "include",
         "adapters", "examples", "cmake", "accuracy")
PATH = re.compile(r"(?<![\w./-])((?:%s)/[\w.*/-]*[\w*])" % "|".join(ROOTS))
PROCESS = re.compile(r"\bissue\s+#?\d+|\bfindings?\s+(?:[0-9]+|[A-Z]\b|of)|\breview\b",
                     re.IGNORECASE)

passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + what)


def comments(path, text):
    """The comment text of a source file (C, Python, shell, CMake, JS)."""
    if path.endswith((".c", ".h", ".js", ".mjs")):
        parts = re.findall(r"/\*.*?\*/|//[^\n]*", text, re.S)
        if path.endswith((".js", ".mjs")):
            parts = [p for p in parts if not p.startswith("//") or "://" not in p]
        return "\n".join(parts)
    if path.endswith(".py"):
        return "\n".join(re.findall(r"#[^\n]*|\"\"\".*?\"\"\"", text, re.S))
    return "\n".join(re.findall(r"#[^\n]*", text))


def exists(p, cited_in):
    """p exists from the top of the repository or from a folder above the citing file;
    a program's path counts when its source (p.c) exists."""
    p = p.rstrip(".")
    d, bases = os.path.dirname(cited_in), [repo]
    while d:
        bases.append(os.path.join(repo, d))
        d = os.path.dirname(d)
    for base in bases:
        q = os.path.join(base, p)
        if glob.glob(q) if "*" in p else (os.path.exists(q) or os.path.exists(q + ".c")):
            return True
    return False


def file_like(p):
    """A cited path worth checking: it names a file (has an extension) or lies two
    folders deep, and is not a placeholder such as fuzz_NAME.c."""
    return not re.search(r"[A-Z]{3,}", p) and ("." in os.path.basename(p) or p.count("/") >= 2)


for f in files:
    if f.startswith(("tests/fuzz/corpus", "data/", "tests/data")) or f in HISTORY:
        continue
    is_doc = f.endswith(DOCS)
    if not (is_doc or f.endswith(SOURCE) or os.path.basename(f) in ("Makefile",)):
        continue
    try:
        text = open(os.path.join(repo, f), encoding="utf-8").read()
    except (UnicodeDecodeError, FileNotFoundError):
        continue
    body = text if is_doc else comments(f, text)
    if not body:
        continue
    for m in sorted(set(PATH.findall(body))):
        m = m.rstrip("/.")
        # node_modules: what npm installs (package-lock.json), not the tree's
        if file_like(m) and "node_modules" not in m.split("/"):
            check(exists(m, f), "%s cites %s, which does not exist" % (f, m))
    if not is_doc and f != "tests/test_tree_hygiene.py":  # it names the words it bans
        for m in PROCESS.finditer(body):
            line = body[: m.start()].count("\n")
            check(False, "%s: process word %r in a comment (comment line %d)"
                  % (f, m.group(0), line + 1))
        passed += 1

print("test_tree_hygiene: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
