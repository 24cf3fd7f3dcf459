"""copy, deepcopy, pickle, multiprocessing, threads: safe objects."""
import copy
import gc
import multiprocessing
import pickle
import threading

import numpy as np
import pytest

from trigspline import Curve, Spline


def data(n=200, seed=11):
    rng = np.random.default_rng(seed)
    x = np.cumsum(rng.uniform(0.1, 1.0, n))
    return x, rng.uniform(0.0, 5.0, n)


def variants():
    x, f = data()
    yield Spline(x, f, extrapolate=True)
    yield Spline(x, f, shape="positive", alpha=np.linspace(0.2, 1.0, len(x) - 1),
                 form="c1", extrapolate="clamp")
    yield Spline(x, f, slopes=np.cos(x), form="geometric", margin=0.05, extrapolate="linear")
    yield Spline(x, np.stack([f, f + 1.0, 2 * f + 0.1]), axis=1, shape="between",
                 lower=(0.0, -1.0), upper=(0.0, 20.0), extrapolate="extend")
    yield Spline(x, f, shape="above", lower=(0.0, -0.5), extrapolate=False)


@pytest.mark.parametrize("s", list(variants()))
def test_copies_are_bit_identical(s):
    x = s.x
    xq = np.linspace(x[0] - 1, x[-1] + 1, 3001)
    want = [s(xq, nu) for nu in (0, 1, 2)]
    clones = [copy.copy(s), copy.deepcopy(s), pickle.loads(pickle.dumps(s)),
              pickle.loads(pickle.dumps(s, protocol=0))]
    del s
    gc.collect()
    for c in clones:
        for nu in (0, 1, 2):
            assert np.array_equal(c(xq, nu), want[nu], equal_nan=True)


def test_use_after_original_deleted():
    x, f = data()
    s = Spline(x, f)
    xs = s.x            # a view of the C object's memory keeps it alive
    d = s.derivative()
    F = s.antiderivative()
    want = s(1.5)
    del s
    gc.collect()
    assert xs[3] == x[3]
    assert d(1.5) == d.spline(1.5, 1) and F(1.5) == F.spline.integrate(x[0], 1.5)
    assert d.spline(1.5) == want
    c = copy.copy(d)
    del d
    gc.collect()
    assert c(1.5) == c.spline(1.5, 1)


def test_input_mutation_after_build():
    x, f = data()
    x2, f2 = x.copy(), f.copy()
    s = Spline(x2, f2)
    want = s(x[5] + 0.1)
    x2[:] = 0.0
    f2[:] = np.nan
    assert s(x[5] + 0.1) == want
    assert np.array_equal(pickle.loads(pickle.dumps(s)).values, f)


def _evaluate(s):
    return s(np.linspace(s.x[0], s.x[-1], 101))


def test_multiprocessing_pool_map():
    x, f = data()
    splines = [Spline(x, f * k + 0.1, shape="positive") for k in (1, 2, 3)]
    ctx = multiprocessing.get_context("spawn")
    with ctx.Pool(2) as pool:
        got = pool.map(_evaluate, splines)
    for s, g in zip(splines, got):
        assert np.array_equal(g, _evaluate(s))


def test_threads_share_one_spline():
    x, f = data(5000)
    s = Spline(x, f, shape="positive")
    xq = np.random.default_rng(1).uniform(x[0], x[-1], 200000)
    want = s(xq)
    results = [None] * 8

    def work(k):
        results[k] = s(xq)

    ts = [threading.Thread(target=work, args=(k,)) for k in range(8)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    for r in results:
        assert np.array_equal(r, want)
    assert np.array_equal(s(xq, threads=0), want)


def test_curve_copies():
    c = Curve([(-1, 0), (0, -1), (1, 0), (0, 1)], closed=True, alpha=0.37, beta=0.01,
              box=[(-1.5, 1.5), None])
    t = np.linspace(0, c.knots[-1], 50)
    want = c(t)
    for k in (copy.copy(c), copy.deepcopy(c), pickle.loads(pickle.dumps(c))):
        assert np.array_equal(k(t), want)


def test_raw_handles_cannot_be_duplicated():
    # the C handle itself is never copied or made from Python: only the
    # package's objects are, by rebuilding (no shared pointer to free twice)
    from trigspline import _core
    h = _core.spline_new([0.0, 1.0, 2.0], [1.0, 2.0, 1.0])
    for fn in (lambda: copy.copy(h), lambda: copy.deepcopy(h), lambda: pickle.dumps(h),
               lambda: _core.SplineHandle(), lambda: _core.CurveHandle()):
        with pytest.raises(TypeError):
            fn()
