#!/usr/bin/env python3
"""Checks the library's layering (src/internal.h): every call between
library files goes from a higher layer to a strictly lower one, so there is
no include or call cycle, and no library file calls a public entry point
(a function declared in include/trigspline.h).

Usage: python3 scripts/check_layers.py [REPO]     (standard library only)
Prints one line per violation and, last, "layers: N passed, M failed".
"""
import os
import re
import sys

repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
src = os.path.join(repo, "src")

# The layers, as documented at the top of src/internal.h.
text = open(os.path.join(src, "internal.h"), encoding="utf-8").read()
layer = {}
current = None
for line in text[: text.index("*/")].splitlines():
    m = re.match(r"\s*\*\s+L(\d)\s+(.*)", line)
    if m:
        current = int(m.group(1))
        rest = m.group(2)
    elif current is not None and re.match(r"\s*\*\s{5,}\S", line):
        rest = line
    else:
        continue
    for name in re.findall(r"\b([a-z0-9_]+)\.c\b", rest):
        layer[name + ".c"] = current

def strip(code):
    code = re.sub(r"/\*.*?\*/", " ", code, flags=re.S)
    code = re.sub(r"//[^\n]*", " ", code)
    code = re.sub(r'"(\\.|[^"\\])*"', '""', code)
    return code

files = sorted(f for f in os.listdir(src) if f.endswith(".c"))
defs = {}    # function name -> file defining it (external linkage)
bodies = {}
for f in files:
    code = strip(open(os.path.join(src, f), encoding="utf-8").read())
    bodies[f] = code
    for m in re.finditer(r"^(?!static)[A-Za-z_][\w \*]*?\b(ts_\w+)\s*\([^;{]*\)\s*\{", code, re.M):
        defs[m.group(1)] = f
public = set(re.findall(r"\b(ts_[a-z0-9_]+)\s*\(",
                        strip(open(os.path.join(repo, "include", "trigspline.h"),
                                   encoding="utf-8").read())))
inline = set(re.findall(r"static inline [\w \*]+?\b(ts__\w+)\s*\(", strip(text)))

passed = failed = 0
def verdict(ok, msg):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + msg)

for f in files:
    verdict(f in layer, f"{f} has no layer in src/internal.h")
for f in files:
    code = bodies[f]
    # calls: a name followed by "(" that is not its own definition
    for m in re.finditer(r"\b(ts_{1,2}[a-z0-9_]+)\s*\(", code):
        name = m.group(1)
        line_start = code.rfind("\n", 0, m.start()) + 1
        head = code[line_start:m.start()]
        if re.match(r"^[A-Za-z_][\w \*]*$", head) and not head.strip().startswith("return"):
            continue  # a definition or declaration
        if name in public:
            # deprecated.c: the old names forward to the public new ones
            verdict(f == "deprecated.c", f"{f} calls the public entry point {name}")
            continue
        g = defs.get(name)
        if g is None or g == f or name in inline:
            continue
        verdict(layer.get(f, -1) > layer.get(g, 99),
                f"{f} (L{layer.get(f)}) calls {name} of {g} (L{layer.get(g)})")
    for inc in re.findall(r'#include\s+"([^"]+)"', open(os.path.join(src, f), encoding="utf-8").read()):
        verdict(inc in ("internal.h", "trigspline.h"), f"{f} includes {inc}")
print(f"layers: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
