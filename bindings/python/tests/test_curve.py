"""Curve: the same conventions for parametric curves.  References: the paper's
closed-curve data, docs/method.md §7 knots re-derived, polygon length bounds."""
import math

import numpy as np
import pytest

from trigspline import Curve
from conftest import read_csv


def test_closed_curve_figure3():
    x, y = read_csv("fig3_closed.csv")
    pts = np.column_stack([x, y])
    c = Curve(pts, closed=True, alpha=0.37, beta=0.01)
    assert c.closed and c.dim == 2 and c.segments == len(np.unique(pts, axis=0))
    t = np.linspace(0, c.knots[-1], 41)
    P = c(t)
    assert P.shape == (41, 2)
    assert c(0.7).shape == (2,)
    assert c(t.reshape(41, 1)).shape == (41, 1, 2)
    assert np.allclose(c(c.knots[:-1]), pts[:c.segments], atol=1e-15)
    # centripetal knots (docs/method.md §7): steps |P_{i+1} - P_i|^(1/2)
    ring = np.vstack([pts[:c.segments], pts[:1]])
    steps = np.sqrt(np.hypot(*np.diff(ring, axis=0).T))
    assert np.allclose(np.diff(c.knots), steps, rtol=1e-14)
    # length: between the chord polygon's and the control polygon's
    L = c.length()
    poly = np.sum(np.hypot(*np.diff(ring, axis=0).T))
    ctrl = c.c  # (4, segments, dim)
    cpoly = sum(np.linalg.norm(ctrl[k + 1, i] - ctrl[k, i]) for i in range(c.segments)
                for k in range(3))
    assert poly <= L <= cpoly
    S = c.sample(8)
    assert S.shape == (c.segments * 7 + 1, 3)
    assert np.array_equal(c.control(1), ctrl[:, 1])
    assert len(c.alpha) == c.segments and np.all(c.beta == 0.01)


def test_curve_derivatives_and_nan():
    c = Curve([(0, 0, 0), (1, 2, 0.5), (2, 1, 1), (3, 3, 0)], param="chord")
    t = np.linspace(0.05, c.knots[-1] - 0.05, 17)
    h = 1e-6
    fd = (c(t + h) - c(t - h)) / (2 * h)
    assert np.max(np.abs(c(t, 1) - fd)) < 1e-6
    assert np.array_equal(c.derivative()(t), c(t, 1))
    r = c(np.array([0.5, np.nan]))
    assert np.isnan(r[1]).all() and np.isfinite(r[0]).all()


def test_curve_box_certified():
    c = Curve([(0, 0.1), (1, 0.9), (2, 0.1), (3, 0.9)], box=[None, (0.0, 1.0)])
    ok, rep = c.certify(report=True)
    assert ok and len(rep) == c.segments * 2
    t = np.linspace(0, c.knots[-1], 20001)
    y = c(t)[:, 1]
    assert y.min() > 0.0 and y.max() < 1.0
    assert c.certify(box=[None, (0.2, 0.8)]) is False  # data at 0.1 and 0.9


def test_curve_touching_box_sides():
    """A closed diamond with a point on each side of [0, 1]² (docs/method.md
    §5.8): built, certified, every sample inside to the evaluation's rounding
    (16 eps, values <= 1); a point outside the box is refused."""
    pts = [(0, 0.5), (0.5, 0), (1, 0.5), (0.5, 1)]
    c = Curve(pts, closed=True, box=[(0, 1), (0, 1)])
    assert c.certify() is True
    xy = c(np.linspace(0, c.knots[-1], 20001))
    eps = np.finfo(float).eps
    assert xy.min() >= -16 * eps and xy.max() <= 1 + 16 * eps
    with pytest.raises(Exception):
        Curve([(-1e-9, 0.5)] + pts[1:], closed=True, box=[(0, 1), (0, 1)])
