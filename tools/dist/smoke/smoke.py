"""The distribution smoke test in Python (the same as smoke.c): README.md's
example at x = 4.2, certified, and a refusal naming point 3.  Run from a
directory outside the source tree; prints the "smoke:" lines, exit status 0
when both behave as documented.  With --expect-prefix DIR the package must be
imported from under DIR (the installed copy, not the source tree)."""
import math
import os
import sys

import trigspline

x = [0, 2, 3, 5, 15, 25, 27, 28, 30]
f = [2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2]
ok = True
if "--expect-prefix" in sys.argv:
    prefix = os.path.realpath(sys.argv[sys.argv.index("--expect-prefix") + 1])
    where = os.path.realpath(trigspline.__file__)
    print("smoke: imported from %s" % where)
    ok = where.startswith(prefix + os.sep)
s = trigspline.Spline(x, f, shape="positive", alpha=0.15)
y = float(s(4.2))
print("smoke: version %s" % trigspline.__version__)
print("smoke: y(4.2) = %r certified %d" % (y, int(bool(s.certified))))
ok = ok and math.isfinite(y) and y > 0 and bool(s.certified)
f[3] = -1.0
try:
    trigspline.Spline(x, f, shape="positive", alpha=0.15)
    print("smoke: error none")
    ok = False
except trigspline.TrigsplineError as e:
    print("smoke: error %s index %s" % (e.name, e.index))
    ok = ok and e.name == "TS_ERR_NEGATIVE" and e.index == 3
sys.exit(0 if ok else 1)
