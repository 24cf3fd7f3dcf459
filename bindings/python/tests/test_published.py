"""The example problems published with TSPACK and SLM, and the classic data
sets of shape-preserving interpolation (data/published/README.md), with the
constraint records of docs/method.md §13.

Feasible problems: built, every record certified on every interval, each
report's exact minimum >= 0 up to its rounding and below dense samples of
the spline's own value, slope or curvature (which are >= 0 up to their
rounding too).  Infeasible ones: refused with TS_ERR_CONDITION, the record
and the necessary condition named, at the point or interval this test finds
itself in exact rational arithmetic (fractions.Fraction of the doubles).
interp (the gufunc) gives each feasible problem's values bit for bit.
"""
import math
import os
from fractions import Fraction

import numpy as np
import pytest

from conftest import REPO
from trigspline import Spline, TrigsplineError, interp

CONDITION = 31
DATA = os.path.join(REPO, "data")


def _csv(*path):
    """x, y of a CSV file: '#' lines, a header line, then rows x,y."""
    with open(os.path.join(DATA, *path), encoding="utf-8") as fh:
        rows = [line for line in fh if line.strip() and not line.startswith("#")][1:]
    a = np.array([[float(v) for v in r.split(",")[:2]] for r in rows])
    return a[:, 0].copy(), a[:, 1].copy()


def akima():
    return _csv("published", "akima1970.csv")


def rpn14():
    return _csv("realworld", "nag_pchip.csv")


def titanium():
    return _csv("published", "titanium_deboor.csv")


def tspack():
    x = np.arange(33) / 32.0
    return x, x * x


def slm_root():
    x = np.linspace(0.0, 1.0, 20)
    return x, x ** 0.2


def slm_sin11():
    x = -1.0 + 0.2 * np.arange(11)
    return x, np.sin(x)


def slm_sin100():
    x = np.linspace(-math.pi, math.pi, 100)
    return x, np.sin(x)


def slm_far():
    x = np.linspace(1e6, 1e6 + 3.0, 100)
    return x, np.sin(x)


def tspack_records():
    """TSPACK's driver: per interval i, H <= 1, H >= y_i, H' <= 2,
    H' >= 2 x_i (YPTRUE), H'' >= 0 (its bounds B for SIGBI)."""
    x, y = tspack()
    return (["convex", "upper=1", "slope<=2"]
            + [{"kind": "lower", "value": float(y[i]), "first": i, "count": 1}
               for i in range(32)]
            + [{"kind": "slope-min", "value": float(2.0 * x[i]), "first": i, "count": 1}
               for i in range(32)])


FEASIBLE = [
    ("akima", akima, ["increasing", "lower=10", "upper=85"]),
    ("rpn14", rpn14, ["increasing", "lower=0", "upper=1"]),
    ("titanium", titanium, ["lower=0"]),
    ("titanium", titanium, ["lower=0.6", "upper=2.2", "abs-slope<=0.06"]),
    ("tspack", tspack, tspack_records()),
    ("slm-root", slm_root, ["increasing", "concave"]),
    ("slm-root-swapped", lambda: slm_root()[::-1], ["increasing", "convex"]),
    ("slm-sin11", slm_sin11, ["increasing", "convex@0-4", "concave@5-9", "lower=-1",
                              "upper=1"]),
    ("slm-sin100", slm_sin100, ["lower=-1", "upper=1", "abs-slope<=1"]),
    ("slm-far", slm_far, ["lower=-1", "upper=1", "abs-slope<=1"]),
]


def _kind_value(rec):
    """(kind, value, first, count) of a SPEC string or dict as the tests use them."""
    if isinstance(rec, dict):
        return rec["kind"], rec.get("value", 0.0), rec.get("first", 0), rec.get("count", 0)
    spec, _, scope = rec.partition("@")
    first, count = 0, 0
    if scope:
        a, b = scope.split("-")
        first, count = int(a), int(b) - int(a) + 1
    for pre, kind in (("lower=", "lower"), ("upper=", "upper"), ("slope<=", "slope-max"),
                      ("slope>=", "slope-min"), ("abs-slope<=", "slope-abs")):
        if spec.startswith(pre):
            return kind, float(spec[len(pre):]), first, count
    return spec, 0.0, first, count


def _quantity(s, kind, value, xs):
    y, d1, d2 = s(xs), s(xs, 1), s(xs, 2)
    return {"convex": d2, "concave": -d2, "increasing": d1, "decreasing": -d1,
            "lower": y - value, "upper": value - y, "slope-min": d1 - value,
            "slope-max": value - d1, "slope-abs": value - np.abs(d1)}[kind]


@pytest.mark.parametrize("name,data,records", FEASIBLE, ids=[f[0] for f in FEASIBLE])
def test_feasible_problems_are_certified(name, data, records):
    x, f = data()
    s = Spline(x, f, constraints=records)
    assert s.certified
    rep = s.constraint_report()
    n = len(x) - 1
    scale = float(np.max(np.abs(f))) + 1.0
    for k, rec in enumerate(records):
        kind, value, first, count = _kind_value(rec)
        for i in range(n):
            r = rep[k][i]
            if r is None:  # outside the record's scope
                assert not (first <= i < (first + count if count else n))
                continue
            assert r["certified"], (name, k, i)
            h = x[i + 1] - x[i]
            # the tolerance of each quantity's rounding (as test_constraints:
            # values 1e-12, slopes 1e-9 / h, S'' 1e-7 / h² of the data's scale)
            tol = {"lower": 1e-12, "upper": 1e-12}.get(kind, 1e-9 / h) * scale
            if kind in ("convex", "concave"):
                tol = 1e-7 * scale / (h * h)
            assert r["gap"] >= -tol, (name, k, i, r["gap"])
            # the interval's own samples (its right end belongs to the next one)
            xs = np.linspace(x[i], x[i + 1], 401)
            xs[-1] = np.nextafter(x[i + 1], -np.inf) if i + 1 < n else x[i + 1]
            q = _quantity(s, kind, value, xs)
            assert q.min() >= -tol, (name, k, i, q.min())
            assert r["gap"] <= q.min() + tol, (name, k, i, r["gap"], q.min())
    # the batch path (the gufunc) gives the same values bit for bit
    xq = np.linspace(x[0], x[-1], 997)
    assert np.array_equal(interp(x, f, xq, constraints=records), s(xq))


def test_touching_data_reach_the_bound_exactly():
    # Akima's flat run lies on lower=10: the exact minimum there is 0
    x, f = akima()
    s = Spline(x, f, constraints=["increasing", "lower=10"])
    low = s.constraint_report()[1]
    assert low[0]["gap"] == 0.0 and np.all(s(np.linspace(0.0, 8.0, 801)) >= 10.0)
    # TSPACK: every interval's left datum is its own lower bound y_i
    x, y = tspack()
    s = Spline(x, y, constraints=tspack_records())
    rep = s.constraint_report()
    for i in range(32):
        assert rep[3 + i][i]["gap"] == 0.0 and rep[3 + i][i]["at"] == x[i]


def _first_convex_failure(x, f, sign):
    """The first inner point j where sign [(f_{j+1} − f_j)(x_j − x_{j−1}) −
    (f_j − f_{j−1})(x_{j+1} − x_j)] < 0, exactly."""
    X, F = [Fraction(v) for v in x], [Fraction(v) for v in f]
    for j in range(1, len(x) - 1):
        if sign * ((F[j + 1] - F[j]) * (X[j] - X[j - 1]) - (F[j] - F[j - 1]) * (X[j + 1] - X[j])) < 0:
            return j
    return None


def _first_turn(f, sign):
    """The point ending the first interval that goes against sign (exactly)."""
    for i in range(len(f) - 1):
        if sign * (Fraction(f[i + 1]) - Fraction(f[i])) < 0:
            return i + 1
    return None


def _first_secant_beyond(x, f, cap):
    X, F, C = [Fraction(v) for v in x], [Fraction(v) for v in f], Fraction(cap)
    for i in range(len(x) - 1):
        if abs(F[i + 1] - F[i]) > C * (X[i + 1] - X[i]):
            return i
    return None


INFEASIBLE = [
    ("akima convex", akima, "convex", lambda x, f: _first_convex_failure(x, f, 1), "convex-data",
     12.0),
    ("rpn14 convex", rpn14, "convex", lambda x, f: _first_convex_failure(x, f, 1), "convex-data",
     8.19),
    ("rpn14 concave", rpn14, "concave", lambda x, f: _first_convex_failure(x, f, -1),
     "concave-data", 8.09),
    ("titanium increasing", titanium, "increasing", lambda x, f: _first_turn(f, 1),
     "monotone-data", 605.0),
    ("titanium convex", titanium, "convex", lambda x, f: _first_convex_failure(x, f, 1),
     "convex-data", 615.0),
    ("titanium slope cap", titanium, "abs-slope<=0.05",
     lambda x, f: _first_secant_beyond(x, f, 0.05), "secant-slope", 875.0),
    ("slm-root decreasing", slm_root, "decreasing", lambda x, f: _first_turn(f, -1),
     "monotone-data", None),
    ("slm-root convex", slm_root, "convex", lambda x, f: _first_convex_failure(x, f, 1),
     "convex-data", None),
]


@pytest.mark.parametrize("name,data,record,find,condition,at", INFEASIBLE,
                         ids=[p[0] for p in INFEASIBLE])
def test_infeasible_problems_are_refused_with_the_reason(name, data, record, find, condition,
                                                          at):
    x, f = data()
    where = find(x, f)
    assert where is not None  # the data do break the condition
    if at is not None:  # the place data/published/README.md names
        assert x[where] == at
    with pytest.raises(TrigsplineError) as e:
        Spline(x, f, constraints=[record])
    assert e.value.status == CONDITION and e.value.index == where
    msg = str(e.value)
    kind = _kind_value(record)[0]
    assert msg.endswith("(constraint 0, %s)" % kind), msg
    want = {"convex-data": "the data are not", "concave-data": "the data are not",
            "monotone-data": "the data change direction here",
            "secant-slope": "is beyond the slope-abs bound"}[condition]
    assert want in msg
    # the batch path: the same status and index per series, NaN values
    r = interp(x, f, x, constraints=[record], errors="nan", full=True)
    assert r.status == CONDITION and r.index == where and np.isnan(r.values).all()
