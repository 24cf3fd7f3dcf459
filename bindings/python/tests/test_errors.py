"""Every error path reachable from Python: a ValueError (TrigsplineError) with
.name, .index, .where and a message naming the point; no floating-point
warnings on valid input."""
import os
import warnings

import numpy as np
import pytest

import trigspline
from trigspline import Curve, Spline, TrigsplineError
from conftest import read_csv


def raises(name, fn, index=None, where=None, text=None):
    with pytest.raises(TrigsplineError) as ei:
        fn()
    e = ei.value
    assert isinstance(e, ValueError)
    assert e.name == name, (e.name, str(e))
    if index is not None:
        assert e.index == index and e.where == where, (e.index, e.where)
    if text is not None:
        assert text in str(e), str(e)
    return e


X = [0.0, 1.0, 2.0, 3.0, 4.0]


def test_construction_errors():
    raises("TS_ERR_TOO_FEW", lambda: Spline([1.0], [2.0]), text="1 data point; at least 2 are needed")
    raises("TS_ERR_LENGTH", lambda: Spline(X, [1.0, 2.0]))
    raises("TS_ERR_UNSORTED", lambda: Spline([0, 1, 1, 2], [1, 2, 3, 4]), 2, "point",
           "point 2 (x = 1) is not greater than the previous x = 1")
    raises("TS_ERR_NONFINITE", lambda: Spline(X, [1, np.nan, 1, 1, 1]), 1, "point")
    raises("TS_ERR_NEGATIVE", lambda: Spline(X, [1, 2, -0.5, 1, 1], shape="positive"), 2,
           "point", "point 2 (x = 2, f = -0.5) is negative")
    raises("TS_ERR_NONMONOTONE", lambda: Spline(X, [1, 2, 3, 2, 4], shape="monotone"), 3,
           "point")
    raises("TS_ERR_SIDE", lambda: Spline([1, 2, 3, 9, 12, 14, 15], [0.5, 3, 5, 25, 8, 2, 1],
                                         shape="above", lower=(0.31, 1.0)), 0, "point",
           "point 0 (x = 1, f = 0.5) is not above the lower line y = 0.31x + 1")
    raises("TS_ERR_LINES", lambda: Spline(X, [1, 2, 3, 2, 1], shape="between",
                                          lower=(1.0, 0.0), upper=(-1.0, 4.0)), 2, "point")
    raises("TS_ERR_PERIODIC", lambda: Spline(X, [1, 2, 3, 2, 2], slopes="periodic"), 4,
           "point")
    raises("TS_ERR_ZERO_SLOPE", lambda: Spline(X, [1, 0, 1, 2, 3], shape="positive",
                                               slopes=[0, 1, 0, 1, 1]), 1, "point")
    raises("TS_ERR_ALPHA", lambda: Spline(X, [1, 2, 3, 2, 1], alpha=[1, 1, -1, 1]), 2,
           "interval")
    raises("TS_ERR_BETA", lambda: Spline(X, [1, 2, 3, 2, 1], beta=-2.0))
    raises("TS_ERR_MARGIN", lambda: Spline(X, [1, 2, 3, 2, 1], shape="positive", margin=0.0))
    raises("TS_ERR_GEOMETRIC", lambda: Spline(X, [1, 2, 3, 2, 1], form="geometric",
                                              alpha=0.1), 0, "interval")
    raises("TS_ERR_LENGTH", lambda: Spline(X, [1, 2, 3, 2, 1], alpha=[1, 1]))
    raises("TS_ERR_LENGTH", lambda: Spline(X, [1, 2, 3, 2, 1], slopes=[1, 2]))


def test_python_argument_errors():
    f = [1, 2, 3, 2, 1]
    for bad in (lambda: Spline(X, f, shape="round"), lambda: Spline(X, f, form="x"),
                lambda: Spline(X, f, slopes="nope"), lambda: Spline(X, f, shape="above"),
                lambda: Spline(X, f, shape="positive", lower=(1, 2)),
                lambda: Spline(X, f, shape="below", lower=(1, 2)),
                lambda: Spline(X, f, shape="positive",
                                                                   beta=0.3),
                lambda: Spline(X, f, extrapolate="periodic"), lambda: Spline(X, f, axis=3),
                lambda: Spline(X, f, shape="between", lower=(0, 0)),
                lambda: Spline(X, f, slopes="user")):
        with pytest.raises(ValueError):
            bad()
    with pytest.raises(TypeError):
        Spline(X, "abcde")


def test_messages_name_the_cause():
    """The message says what is wrong, not a consequence of it: a string for a
    per-interval parameter (was: "alpha has 1 values; a per-interval alpha
    needs exactly n = 2"), and one point queried outside a surface (was:
    "point () (x = 0.5, ...)")."""
    for kw in ("alpha", "beta"):
        with pytest.raises(TypeError) as ei:
            Spline([0, 1, 2], [1, 2, 1], **{kw: "1"})
        assert "%s must be a number or an array of numbers" % kw in str(ei.value)
        assert "got a string '1'" in str(ei.value) and "values" not in str(ei.value)
    with pytest.raises(TypeError) as ei:
        Spline([0, 1, 2], [1, 2, 1], alpha=[1.0, "x"])
    assert "alpha must be a number or an array of numbers" in str(ei.value)
    with pytest.raises(TypeError) as ei:
        Curve([[0, 0], [1, 1], [2, 0]], alpha="1")
    assert "alpha must be a number or an array of numbers" in str(ei.value)
    s = trigspline.Surface([0, 1, 2], [0, 1, 2], np.ones((3, 3)), extrapolate="error")
    for q in ((0.5, 5.0), np.array([0.5, 5.0])):
        e = raises("TS_ERR_DOMAIN", lambda: s(q))
        assert "()" not in str(e), str(e)
        assert "(x = 0.5, y = 5) lies outside" in str(e), str(e)
    e = raises("TS_ERR_DOMAIN", lambda: s([[0.5, 1.0], [0.5, 5.0]]))
    assert "point (1,) (x = 0.5, y = 5)" in str(e), str(e)


def test_query_errors():
    s = Spline(X, [1, 2, 3, 2, 1], extrapolate="error")
    e = raises("TS_ERR_DOMAIN", lambda: s([0.5, 7.0]), 1, "query")
    assert "query 1 (x = 7) lies outside [0, 4]" in str(e)
    raises("TS_ERR_DOMAIN", lambda: s(-1.0), None, None, "query x = -1")
    with pytest.raises(ValueError):
        s(1.0, out=np.empty(3))
    raises("TS_ERR_INDEX", lambda: s.control(9), 9, "interval")


def test_curve_errors():
    raises("TS_ERR_DIMENSION", lambda: Curve([[0, 1, 2, 3]] * 3))
    raises("TS_ERR_TOO_FEW", lambda: Curve([[0, 0]]))
    raises("TS_ERR_UNSORTED", lambda: Curve([[0, 0], [1, 1], [1, 1], [2, 0]]), 2, "point",
           "point 2 (1, 1) repeats the previous point")
    raises("TS_ERR_SIDE", lambda: Curve([[0, 0], [1, 1], [2, 0]], box=[None, (0.5, None)]),
           0, "point", "point 0 (0, 0) is outside the box")
    c = Curve([[0, 0], [1, 1], [2, 0]])
    e = raises("TS_ERR_DOMAIN", lambda: c([0.5, 100.0]), 1, "query")
    assert "outside" in str(e)
    assert np.isnan(c([0.5, 100.0], extrapolate=False)[1]).all()
    assert np.isnan(c(np.nan)).all()
    with pytest.raises(ValueError):
        c(0.5, 3)


def test_no_floating_point_warnings_on_valid_input():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(all="raise"):
            for name, shape, kw in (("table1_positive.csv", "positive", {"alpha": 0.15}),
                                    ("table2_above_line.csv", "above", {"lower": (0.31, 1.0)}),
                                    ("table4_between_lines.csv", "between",
                                     {"lower": (1, 0.1), "upper": (8, 6), "alpha": 0.1})):
                x, f = read_csv(name)
                if shape == "above":
                    f = f + 10 * x  # the paper's table 2 data violate the line; lift them
                    kw = {"lower": (0.31, 1.0)}
                s = Spline(x, f, shape=shape, **{"form": "paper", **kw})  # s(xq, 3)
                xq = np.linspace(x[0], x[-1], 1001)
                s(xq), s(xq, 1), s(xq, 2), s(xq, 3), s.integrate(x[0], x[-1]), s.roots()
                assert s.certified


def test_error_pickles():
    import pickle
    e = raises("TS_ERR_NEGATIVE", lambda: Spline(X, [1, 2, -0.5, 1, 1], shape="positive"))
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.name, e2.index, e2.where, str(e2)) == (e.name, e.index, e.where, str(e))
    assert isinstance(trigspline.strerror(14), str) and trigspline.strerror(14)


def test_status_names_are_the_headers():
    """The package's status table is the ts_status enum of include/trigspline.h,
    read from the header here (names and values), so a new status cannot be
    missed."""
    import re
    from conftest import REPO
    from trigspline import _util
    with open(os.path.join(REPO, "include", "trigspline.h"), encoding="utf-8") as fh:
        text = fh.read()
    enum = text[text.index("typedef enum ts_status"):]
    enum = enum[:enum.index("} ts_status;")]
    pairs = re.findall(r"\b(TS_(?:OK|ERR_[A-Z0-9_]+))\s*=\s*(\d+)", enum)
    assert pairs and [int(v) for _, v in pairs] == list(range(len(pairs)))
    assert tuple(n for n, _ in pairs) == _util.STATUS_NAMES
