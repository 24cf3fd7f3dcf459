#!/usr/bin/env python3
"""make demo's page: builds it with the CLI of BUILD_DIR into a temporary
directory and checks it (standard library only).

- every figure is an inline SVG that xml.etree accepts;
- Figures 2-7 are all there, each panel with its command line;
- every constrained panel made by `fit` is certified, every `certify` panel
  whose paper parameters or chosen ones leave the region says so (exit 4);
- the notes on the paper's differences (docs/method.md §9) are present.
Prints "N passed, M failed" last.
"""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

build = sys.argv[1] if len(sys.argv) > 1 else "build"
repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
cli = os.path.abspath(os.path.join(build, "trigspline"))
data = os.path.join(repo, "data", "paper")
passed = failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL:", what)


with tempfile.TemporaryDirectory() as out:
    p = subprocess.run([sys.executable, os.path.join(repo, "scripts", "paper_demo.py"), cli, data, out],
                       capture_output=True, text=True)
    check(p.returncode == 0, "paper_demo.py exit %d: %s" % (p.returncode, p.stderr[-500:]))
    page_path = os.path.join(out, "index.html")
    check(p.stdout.strip().endswith("index.html"), "prints the page's path")
    check(os.path.exists(page_path), "index.html written")
    page = open(page_path, encoding="utf-8").read() if os.path.exists(page_path) else ""

svgs = re.findall(r"<svg\b.*?</svg>", page, re.S)
check(len(svgs) >= 30, "at least 30 inline SVGs (got %d)" % len(svgs))
for k, s in enumerate(svgs):
    try:
        root = ET.fromstring(s)
        check(root.tag.endswith("svg"), "svg %d root" % k)
        check(len(root.findall(".//{http://www.w3.org/2000/svg}polyline")) +
              len(root.findall(".//{http://www.w3.org/2000/svg}circle")) +
              len(root.findall(".//{http://www.w3.org/2000/svg}path")) > 0, "svg %d draws something" % k)
    except ET.ParseError as e:
        check(False, "svg %d does not parse: %s" % (k, e))
    check("nan" not in s.lower().replace("nan-", ""), "svg %d has no NaN" % k)

for fig in ("2", "3", "4", "5", "6", "7"):
    check(("Figure %s " % fig) in page, "Figure %s present" % fig)

panels = re.findall(r'<div class="panel"><h4>(.*?)</h4>\s*<pre>\$ (.*?)</pre>.*?<p class="sum">(.*?)</p>',
                    page, re.S)
check(len(panels) >= 30, "panels with command lines (got %d)" % len(panels))
for title, cmd, summary in panels:
    status = re.search(r"exit status (\d+)", summary)
    status = int(status.group(1)) if status else -1
    if cmd.startswith("trigspline fit") and "--shape" in cmd and "--points-only" not in cmd:
        if "0.31,1" in cmd:  # Table 2 with the paper's line: refused, naming x = 1
            check(status == 2, "%s: refused (exit 2), got %d" % (title, status))
        else:
            check(status == 0 and "certified: <b>yes</b>" in summary, "%s: certified (%s)" % (title, summary))
    if cmd.startswith("trigspline certify"):
        check(status in (0, 4), "%s: certify exit 0 or 4, got %d" % (title, status))
        check(("certified: <b>NO</b>" in summary) == (status == 4), "%s: flag matches exit status" % title)

for title, cmd, summary in panels:  # full command lines, nothing elided
    full = "…" not in cmd and "--json --svg" in cmd and (
        "--title" in cmd or cmd.startswith("trigspline surface"))
    check(full, "%s: full command line" % title)
check('href="../why/index.html"' in page, "links the why page")
check("x = 1, 14, 15" in page or "x = 1, 14 and 15" in page, "Table 2 note names x = 1, 14, 15")
check(page.count("Differs from the paper") >= 3, "notes on the paper's differences (Fig. 4b, Table 2, Theorem 4)")
check("What really happens" in page, "note on the closed curves and large beta")
check("−145" in page or "-145" in page or "145" in page, "printed Theorem 4 panel shows the violation")
# the surface section (docs/method.md §11): certified panels say so; the
# unconstrained ones and the bicubic of the same data leave the region
check("Surfaces — certified" in page, "surface section present")
surf = [(t, c, sm) for t, c, sm in panels if c.startswith("trigspline surface")]
check(len(surf) == 4, "four surface panels (got %d)" % len(surf))
for title, cmd, summary in surf:
    status = re.search(r"exit status (\d+)", summary)
    check(status is not None and status.group(1) == "0", "%s: exit 0" % title)
    rng = re.search(r"range on \d+ samples: \[([^,]+), ([^\]]+)\]", summary)
    lo, hi = (float(rng.group(1)), float(rng.group(2))) if rng else (float("nan"),) * 2
    if "--shape" in cmd:
        check("certified: <b>yes</b>" in summary and lo >= 0, "%s: certified, >= 0" % title)
        if "--upper 100" in cmd:
            check(hi <= 100, "%s: <= 100" % title)
    else:
        check(lo < 0, "%s: the unconstrained surface goes below 0 (%s)" % (title, lo))
check(len(re.findall(r"ranges over \[-", page)) == 2, "the bicubic goes negative on both fields")
print("test_demo: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
