"""trigspline.Surface (docs/method.md §11): values, shape guarantees, SciPy's
call conventions, errors, safe objects.

Expected values come from elsewhere:
  - the C library built by CMake (libtrigspline.so through ctypes): the same
    ts_surface_eval_batch / ts_surface_eval_grid calls, bit for bit;
  - docs/method.md §11.1-§11.2 re-derived with numpy (ref_surface below): the
    basis of §2 (conftest.ref_basis), the control net (11.2) from the node
    slopes, twists and shape parameters the surface reports; the slopes
    themselves as the three-point parabola of §6 (numpy.gradient with
    edge_order=2 computes exactly that derivative on a non-uniform grid);
  - closed forms: bilinear data and planes, reproduced exactly by the
    geometric form (§11.2), and their integrals;
  - SciPy: RegularGridInterpolator for the call conventions (shapes,
    bounds_error, fill_value) and, on bilinear data, its 'linear' method
    (exact there); Gauss-Legendre quadrature for integrals;
  - dense sampling for the shape guarantees (never alone: the certificate
    is checked against the samples).
Tolerances: rounding of sums of 16 products of O(1) terms, i.e. a few
hundred ulps of the data's scale (1e-12 relative) unless stated.
"""
import copy
import ctypes
import gc
import math
import os
import pickle
import threading

import numpy as np
import pytest

import trigspline
from trigspline import Surface, TrigsplineError
from conftest import REPO, ref_basis

LIB = os.path.join(os.environ.get("TS_BUILD_DIR", os.path.join(REPO, "build")),
                   "libtrigspline.so")
FORMS = ("paper", "c1", "geometric")


def grid_data(nx=7, ny=5, seed=3, zeros=True, spiky=True):
    """Non-uniform grid, spiky positive values with zeros."""
    rng = np.random.default_rng(seed)
    x = np.cumsum(rng.uniform(0.2, 2.0, nx)) - 1.0
    y = np.cumsum(rng.uniform(0.1, 1.5, ny)) + 0.5
    z = rng.uniform(0.0, 1.0, (nx, ny)) ** (6 if spiky else 1) * 10.0
    if zeros:
        z[rng.uniform(size=(nx, ny)) < 0.3] = 0.0
    return x, y, z


def ref_surface(s, xq, yq):
    """S at the points (xq, yq) by docs/method.md §11.1-§11.2 (paper and C¹
    forms) from the surface's node data (z, p, q, r) and a^x, a^y."""
    x, y = np.asarray(s.x), np.asarray(s.y)
    z, p, q, r = (np.asarray(a) for a in (s.values, s.dzdx, s.dzdy, s.twist))
    ax, ay = np.asarray(s.ax), np.asarray(s.ay)
    nx, ny = len(x) - 1, len(y) - 1
    i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, nx - 1)
    j = np.clip(np.searchsorted(y, yq, side="right") - 1, 0, ny - 1)
    hx, hy = x[i + 1] - x[i], y[j + 1] - y[j]
    Kx, Ky = 2 * hx / (3 * math.pi), 2 * hy / (3 * math.pi)
    if s.form == "c1":  # every node's larger a in each direction (§11.2)
        Ax = np.maximum(np.r_[ax[0], ax], np.r_[ax, ax[-1]])
        Ay = np.maximum(np.r_[ay[0], ay], np.r_[ay, ay[-1]])
    B = np.empty((4, 4) + np.shape(xq))
    for cx in (0, 1):
        for cy in (0, 1):
            ni, nj = i + cx, j + cy
            sx, sy = (1 - 2 * cx), (1 - 2 * cy)
            if s.form == "c1":
                u, v = Kx / Ax[ni], Ky / Ay[nj]
            else:
                u, v = Kx / ax[i], Ky / ay[j]
            zz, pp, qq, rr = z[ni, nj], p[ni, nj], q[ni, nj], r[ni, nj]
            k0, l0 = 3 * cx, 3 * cy
            k1, l1 = k0 + sx, l0 + sy
            B[k0, l0] = zz
            B[k1, l0] = zz + sx * u * pp
            B[k0, l1] = zz + sy * v * qq
            B[k1, l1] = zz + sx * u * pp + sy * v * qq + sx * sy * u * v * rr
    Ath = ref_basis((math.pi / 2) * (xq - x[i]) / hx)
    Aph = ref_basis((math.pi / 2) * (yq - y[j]) / hy)
    return np.einsum("k...,l...,kl...->...", Ath, Aph, B)


def dense(s, per=24):
    """A dense grid: per samples per patch side, patch edges included."""
    def axis(t):
        return np.unique(np.concatenate([np.linspace(t[k], t[k + 1], per)
                                         for k in range(len(t) - 1)]))
    return axis(np.asarray(s.x)), axis(np.asarray(s.y))


# ---- values against independent derivations -------------------------------

@pytest.mark.parametrize("form", ["paper", "c1"])
@pytest.mark.parametrize("shape", ["none", "positive", "range"])
def test_values_against_rederived_net(form, shape):
    x, y, z = grid_data()
    s = Surface(x, y, z, form=form, shape=shape, alpha=0.7)
    rng = np.random.default_rng(5)
    pts = np.column_stack([rng.uniform(x[0], x[-1], 4000), rng.uniform(y[0], y[-1], 4000)])
    pts[:50, 0] = x[rng.integers(0, len(x), 50)]  # on grid lines
    want = ref_surface(s, pts[:, 0], pts[:, 1])
    assert np.allclose(s(pts), want, rtol=0, atol=1e-12 * np.abs(z).max())


def test_slopes_and_twists_are_the_three_point_parabola():
    x, y, z = grid_data(zeros=False, spiky=False)
    s = Surface(x, y, z)
    p = np.gradient(z, x, axis=0, edge_order=2)
    q = np.gradient(z, y, axis=1, edge_order=2)
    r = 0.5 * (np.gradient(q, x, axis=0, edge_order=2) + np.gradient(p, y, axis=1,
                                                                     edge_order=2))
    scale = np.abs(z).max()
    assert np.allclose(s.dzdx, p, rtol=1e-12, atol=1e-12 * scale)
    assert np.allclose(s.dzdy, q, rtol=1e-12, atol=1e-12 * scale)
    assert np.allclose(s.twist, r, rtol=1e-11, atol=1e-11 * scale)
    assert np.all(s.ax == 1.0) and np.all(s.ay == 1.0)  # the library's alpha, beta 1, 0
    assert np.all(Surface(x, y, z, zero_twist=True).twist == 0.0)


def test_nodes_interpolated_exactly():
    x, y, z = grid_data()
    for form in FORMS:
        for shape in ("none", "positive"):
            s = Surface(x, y, z, form=form, shape=shape)
            assert np.array_equal(s(x, y, grid=True), z)


@pytest.mark.parametrize("form", FORMS)
def test_constant_data(form):
    x, y, _ = grid_data()
    s = Surface(x, y, np.full((len(x), len(y)), 2.5), form=form, shape="positive")
    X, Y = dense(s, 9)
    assert np.allclose(s(X, Y), 2.5, rtol=0, atol=4e-15)
    zz, zx, zy = s.partials(X, Y)
    assert np.allclose(zx, 0, atol=1e-13) and np.allclose(zy, 0, atol=1e-13)


def bilinear(x, y):
    return 1.0 + 2.0 * x - y + 0.5 * x * y


def test_geometric_reproduces_bilinear_data_and_scipy_linear():
    # §11.2: with p = ∂z/∂x, q = ∂z/∂y exact (the three-point slopes are exact
    # on lines) and r = 1/2, every control value is X_k-, Y_l-bilinear, so
    # S = 1 + 2x - y + xy/2 exactly; RegularGridInterpolator('linear') is exact too.
    from scipy.interpolate import RegularGridInterpolator
    x, y, _ = grid_data()
    z = bilinear(x[:, None], y[None, :])
    s = Surface(x, y, z, form="geometric")
    rng = np.random.default_rng(2)
    pts = np.column_stack([rng.uniform(x[0], x[-1], 3000), rng.uniform(y[0], y[-1], 3000)])
    exact = bilinear(pts[:, 0], pts[:, 1])
    scale = np.abs(z).max()
    assert np.allclose(s(pts), exact, rtol=0, atol=1e-12 * scale)
    rgi = RegularGridInterpolator((x, y), z)
    assert np.allclose(s(pts), rgi(pts), rtol=0, atol=1e-12 * scale)
    zz, zx, zy = s.partials(pts)
    assert np.allclose(zx, 2.0 + 0.5 * pts[:, 1], rtol=0, atol=1e-10 * scale)
    assert np.allclose(zy, -1.0 + 0.5 * pts[:, 0], rtol=0, atol=1e-10 * scale)
    xa, xb, ya, yb = x[0] + 0.3, x[-2] + 0.1, y[1] - 0.05, y[-1]
    F = lambda u, v: u * v + u * u * v - u * v * v / 2 + u * u * v * v / 8  # ∫∫ bilinear
    I = F(xb, yb) - F(xa, yb) - F(xb, ya) + F(xa, ya)
    assert s.integral(xa, xb, ya, yb) == pytest.approx(I, rel=1e-12)


def test_geometric_plane_bounds_exact():
    x, y, _ = grid_data()
    plane = (0.5, -0.25, 1.0)
    rng = np.random.default_rng(7)
    z = plane[0] * x[:, None] + plane[1] * y[None, :] + plane[2] + \
        rng.uniform(0.0, 2.0, (len(x), len(y))) ** 4 + 1e-3
    s = Surface(x, y, z, shape="planes", lower=plane, form="geometric")
    assert s.certified
    X, Y = dense(s)
    V = s(X, Y)
    assert (V - (plane[0] * X[:, None] + plane[1] * Y[None, :] + plane[2])).min() > 0
    # the plane itself is reproduced exactly
    zp = plane[0] * x[:, None] + plane[1] * y[None, :] + plane[2]
    sp = Surface(x, y, zp, form="geometric")
    assert np.allclose(sp(X, Y), plane[0] * X[:, None] + plane[1] * Y[None, :] + plane[2],
                       rtol=0, atol=1e-12 * np.abs(zp).max())


@pytest.mark.parametrize("form", ["paper", "c1"])
def test_integral_against_gauss_legendre(form):
    x, y, z = grid_data()
    s = Surface(x, y, z, form=form, shape="positive")
    # per patch, S is a trigonometric polynomial of degree 3 in θ and in φ,
    # both linear in x, y: 24-point Gauss-Legendre is exact to rounding
    g, w = np.polynomial.legendre.leggauss(24)

    def gl(a, b, t):
        cuts = np.unique(np.clip(np.r_[a, t[(t > a) & (t < b)], b], a, b))
        nodes = [(u + v) / 2 + (v - u) / 2 * g for u, v in zip(cuts[:-1], cuts[1:])]
        weights = [(v - u) / 2 * w for u, v in zip(cuts[:-1], cuts[1:])]
        return np.concatenate(nodes), np.concatenate(weights)
    for xa, xb, ya, yb in ((x[0], x[-1], y[0], y[-1]), (x[1] + 0.1, x[4] - 0.2, y[0] + 0.3,
                                                        y[2] + 0.01)):
        X, WX = gl(xa, xb, x)
        Y, WY = gl(ya, yb, y)
        want = WX @ s(X, Y) @ WY
        got = s.integral(xa, xb, ya, yb)
        assert got == pytest.approx(want, rel=1e-12, abs=1e-12)
        assert s.integral(xb, xa, ya, yb) == -got


def test_partials_against_finite_differences():
    x, y, z = grid_data(zeros=False, spiky=False)
    s = Surface(x, y, z, form="c1")
    rng = np.random.default_rng(4)
    # inside patches, away from the grid lines (central differences stay in one patch)
    i = rng.integers(0, len(x) - 1, 500)
    j = rng.integers(0, len(y) - 1, 500)
    px = x[i] + rng.uniform(0.2, 0.8, 500) * np.diff(x)[i]
    py = y[j] + rng.uniform(0.2, 0.8, 500) * np.diff(y)[j]
    pts = np.column_stack([px, py])
    zz, zx, zy = s.partials(pts)
    h = 1e-6
    fx = (s(np.column_stack([px + h, py])) - s(np.column_stack([px - h, py]))) / (2 * h)
    fy = (s(np.column_stack([px, py + h])) - s(np.column_stack([px, py - h]))) / (2 * h)
    # central differences: O(h²) S''' + rounding 1e-16·|S|/h ≈ 1e-9 relative
    assert np.allclose(zx, fx, rtol=1e-6, atol=1e-6)
    assert np.allclose(zy, fy, rtol=1e-6, atol=1e-6)
    assert np.array_equal(s(pts, nu=(1, 0)), zx) and np.array_equal(s(pts, nu=(0, 1)), zy)
    assert np.array_equal(zz, s(pts))


# ---- one path: grid, batch and scalar agree bit for bit; and with C ---------

@pytest.mark.parametrize("form", FORMS)
def test_grid_batch_scalar_bit_identical(form):
    x, y, z = grid_data()
    s = Surface(x, y, z, form=form, shape="positive")
    rng = np.random.default_rng(8)
    xq = np.sort(rng.uniform(x[0], x[-1], 37))
    yq = rng.uniform(y[0], y[-1], 23)  # unsorted
    G = s(xq, yq, grid=True)
    assert G.shape == (37, 23)
    X, Y = np.meshgrid(xq, yq, indexing="ij")
    assert np.array_equal(G, s(np.stack([X, Y], axis=-1)))
    assert np.array_equal(G, s((X, Y)))
    assert np.array_equal(G, s(X, Y, grid=False))
    assert np.array_equal(G, s(xq[:, None], yq[None, :], grid=False))
    for a in (0, 5, 36):
        for b in (0, 11, 22):
            assert s([xq[a], yq[b]])[0] == G[a, b]
            assert s(xq[a], yq[b], grid=False) == G[a, b]
    # partials on a grid go through the batch: the same values
    assert np.array_equal(s.partials(xq, yq)[0], G)


dp = ctypes.POINTER(ctypes.c_double)


class Plane(ctypes.Structure):
    _fields_ = [("p", ctypes.c_double), ("q", ctypes.c_double), ("c", ctypes.c_double)]


class GridBound(ctypes.Structure):  # ts_grid_bound
    _fields_ = [("x", dp), ("nx_points", ctypes.c_size_t), ("y", dp),
                ("ny_points", ctypes.c_size_t), ("z", dp)]


class SurfaceOptions(ctypes.Structure):  # ts_surface_options (include/trigspline.h)
    _fields_ = [("struct_size", ctypes.c_size_t),
                ("form", ctypes.c_int), ("slopes", ctypes.c_int), ("zero_twist", ctypes.c_int),
                ("alpha", ctypes.c_double), ("beta", ctypes.c_double),
                ("margin", ctypes.c_double), ("shape", ctypes.c_int),
                ("has_lower", ctypes.c_int), ("has_upper", ctypes.c_int),
                ("lower", Plane), ("upper", Plane),
                ("lower_grid", GridBound), ("upper_grid", GridBound)]


class Error(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("index", ctypes.c_size_t), ("where", ctypes.c_int)]


@pytest.mark.skipif(not os.path.exists(LIB), reason="no CMake build at " + LIB)
@pytest.mark.parametrize("form", [0, 1, 2])
def test_bit_identical_to_the_c_library(form):
    L = ctypes.CDLL(LIB)
    L.ts_surface_options_init.argtypes = [ctypes.POINTER(SurfaceOptions)]
    L.ts_surface_new.argtypes = [dp, ctypes.c_size_t, dp, ctypes.c_size_t, dp,
                                 ctypes.POINTER(SurfaceOptions),
                                 ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(Error)]
    L.ts_surface_eval_batch.argtypes = [ctypes.c_void_p, dp, dp, ctypes.c_size_t, dp, dp, dp,
                                        ctypes.POINTER(Error)]
    L.ts_surface_eval_grid.argtypes = [ctypes.c_void_p, dp, ctypes.c_size_t, dp,
                                       ctypes.c_size_t, dp, ctypes.POINTER(Error)]
    L.ts_surface_integral.argtypes = [ctypes.c_void_p] + [ctypes.c_double] * 4 + [dp]
    L.ts_surface_free.argtypes = [ctypes.c_void_p]
    x, y, z = grid_data(12, 9, seed=form)
    opt = SurfaceOptions()
    L.ts_surface_options_init(ctypes.byref(opt))
    assert opt.struct_size == ctypes.sizeof(SurfaceOptions)  # the mirror is the header's
    default_form = opt.form
    opt.form, opt.shape, opt.alpha = form, 1, 0.6
    zt = np.ascontiguousarray(z.T)
    h, err = ctypes.c_void_p(), Error()
    assert L.ts_surface_new(x.ctypes.data_as(dp), len(x), y.ctypes.data_as(dp), len(y),
                            zt.ctypes.data_as(dp), ctypes.byref(opt), ctypes.byref(h),
                            ctypes.byref(err)) == 0
    try:
        s = Surface(x, y, z, form=FORMS[form], shape="positive", alpha=0.6)
        rng = np.random.default_rng(form)
        m = 5000
        xq, yq = rng.uniform(x[0], x[-1], m), rng.uniform(y[0], y[-1], m)
        zq, zx, zy = np.empty(m), np.empty(m), np.empty(m)
        L.ts_surface_eval_batch(h, xq.ctypes.data_as(dp), yq.ctypes.data_as(dp), m,
                                zq.ctypes.data_as(dp), zx.ctypes.data_as(dp),
                                zy.ctypes.data_as(dp), ctypes.byref(err))
        got = s.partials(np.column_stack([xq, yq]))
        for a, b in zip(got, (zq, zx, zy)):
            assert np.array_equal(a, b)
        gx, gy = np.sort(xq[:100]), yq[:70]
        out = np.empty(70 * 100)
        L.ts_surface_eval_grid(h, gx.ctypes.data_as(dp), 100, gy.ctypes.data_as(dp), 70,
                               out.ctypes.data_as(dp), ctypes.byref(err))
        assert np.array_equal(s(gx, gy, grid=True), out.reshape(70, 100).T)
        I = ctypes.c_double()
        L.ts_surface_integral(h, x[0], x[-1], y[0], y[-1], ctypes.byref(I))
        assert s.integral(x[0], x[-1], y[0], y[-1]) == I.value
        assert Surface(x, y, z).form == FORMS[default_form]
    finally:
        L.ts_surface_free(h)


# ---- shape guarantees: certificate and dense sampling ----------------------

@pytest.mark.parametrize("form", FORMS)
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_positive_never_below_zero(form, seed):
    x, y, z = grid_data(9, 8, seed=seed)
    s = Surface(x, y, z, shape="positive", form=form, alpha=0.2)
    assert s.certified and s.certify()
    X, Y = dense(s, 40)
    V = s(X, Y)
    assert V.min() >= 0.0
    r = s.report()
    assert r.shape == s.patches and r["certified"].all()
    assert (r["proven_lower"] >= 0).all()
    # the proven bound never exceeds a true value of the surface
    assert (r["proven_lower"] <= r["sampled_lower"]).all()
    ax_, ay_ = r["at_lower"][..., 0].ravel(), r["at_lower"][..., 1].ravel()
    assert np.allclose(s(np.column_stack([ax_, ay_])), r["sampled_lower"].ravel(),
                       rtol=0, atol=1e-13 * z.max())
    # and on a dense sample the proven bound holds patch by patch
    for i in range(s.patches[0]):
        for j in range(s.patches[1]):
            m = V[(X >= x[i]) & (X <= x[i + 1])][:, (Y >= y[j]) & (Y <= y[j + 1])].min()
            assert r["proven_lower"][i, j] <= m


def test_positive_data_where_scipy_cubic_goes_negative():
    # why surfaces exist: the same grid with SciPy's cubic method
    # (a tensor spline) undershoots; the certified surface does not
    from scipy.interpolate import RegularGridInterpolator
    x, y, z = grid_data(9, 8, seed=2)
    s = Surface(x, y, z, shape="positive")
    X, Y = dense(s, 30)
    cubic = RegularGridInterpolator((x, y), z, method="cubic")
    XX, YY = np.meshgrid(X, Y, indexing="ij")
    assert cubic((XX, YY)).min() < 0
    assert s(X, Y).min() >= 0


@pytest.mark.parametrize("form", FORMS)
def test_bounds_and_range(form):
    x, y, z = grid_data(8, 7, seed=9)
    pct = np.clip(z * 10, 0, 100)  # percentages touching 0 and 100
    pct[2, 3] = 100.0
    s = Surface(x, y, pct, shape="bounds", lower=0, upper=100, form=form)
    X, Y = dense(s, 30)
    V = s(X, Y)
    # the bound 0 holds exactly (every term of the sum is >= 0); a nonzero
    # constant up to the rounding of a convex combination formed in floating
    # point, ~8ε of the bound's size (as tests/api/test_surface.c): 1e-13 relative
    assert s.certified and V.min() >= 0 and V.max() <= 100 * (1 + 1e-13)
    r = Surface(x, y, z + 1.0, shape="range", form=form)
    W = r(X, Y)
    lo, hi = (z + 1).min(), (z + 1).max()
    assert W.min() >= lo * (1 - 1e-13) and W.max() <= hi * (1 + 1e-13)
    assert r.bounds == ((0.0, 0.0, (z + 1).min()), (0.0, 0.0, (z + 1).max()))
    assert r.certify()


def test_certify_any_bound_and_shape_none():
    x, y, z = grid_data(6, 5, seed=4, zeros=False)
    s = Surface(x, y, z + 1.0)  # no scheme, no promise
    assert not s.certified
    assert not s.report()["certified"].any()
    ok, rep = s.certify(lower=0.5, report=True)
    X, Y = dense(s, 40)
    V = s(X, Y)
    assert rep.shape == s.patches and rep["has_lower"].all() and not rep["has_upper"].any()
    # a certificate never claims more than the samples show, patch by patch
    for i in range(s.patches[0]):
        for j in range(s.patches[1]):
            m = V[(X >= x[i]) & (X <= x[i + 1])][:, (Y >= y[j]) & (Y <= y[j + 1])].min()
            assert 0.5 + rep["proven_lower"][i, j] <= m + 1e-12
            assert rep["certified"][i, j] == (rep["proven_lower"][i, j] > 0) or \
                rep["proven_lower"][i, j] == 0
    assert ok == bool(rep["certified"].all())
    assert (not ok) or V.min() >= 0.5
    assert not s.certify(upper=(z + 1).max() - 0.5)  # a node above it: cannot be certified
    with pytest.raises(ValueError, match="certify needs"):
        s.certify()


@pytest.mark.parametrize("form", FORMS)
@pytest.mark.parametrize("shape", ["none", "positive"])
def test_transposition_symmetry(form, shape):
    # docs/method.md §11.5: the transposed grid gives the transposed surface
    x, y, z = grid_data(8, 6, seed=12)
    s = Surface(x, y, z, form=form, shape=shape)
    t = Surface(y, x, z.T, form=form, shape=shape)
    X, Y = dense(s, 12)
    a, b = s(X, Y), t(Y, X).T
    assert np.allclose(a, b, rtol=1e-12, atol=1e-12 * z.max())
    assert np.allclose(s.ax, t.ay) and np.allclose(s.ay, t.ax)


# ---- SciPy's call conventions ---------------------------------------------

def test_call_shapes_as_regular_grid_interpolator():
    from scipy.interpolate import RegularGridInterpolator
    x, y, _ = grid_data()
    z = bilinear(x[:, None], y[None, :])
    s = Surface((x, y), z, form="geometric")  # RegularGridInterpolator's argument order
    rgi = RegularGridInterpolator((x, y), z)
    rng = np.random.default_rng(1)

    def pts(*shape):
        return np.stack([rng.uniform(x[0], x[-1], shape), rng.uniform(y[0], y[-1], shape)],
                        axis=-1)
    xs, ys = np.linspace(x[0], x[-1], 4), np.linspace(y[0], y[-1], 3)
    for q in (pts(1)[0], pts(1), pts(7), pts(3, 4), pts(2, 1, 5), list(map(tuple, pts(3))),
              np.array([x[1], y[1], x[2], y[2]]), tuple(np.meshgrid(xs, ys, indexing="ij")),
              tuple(np.meshgrid(xs, ys, sparse=True)), (xs[:3], ys), pts(4).astype(np.float32)):
        want = rgi(q)
        got = s(q)
        assert got.shape == want.shape
        assert np.allclose(got, want, rtol=0, atol=1e-12 * np.abs(z).max())
    for bad in (pts(3)[:, :1], np.zeros((2, 3)), [1.0, 2.0, 3.0]):
        with pytest.raises(ValueError):
            rgi(bad)
        with pytest.raises(ValueError):
            s(bad)
    with pytest.raises(ValueError):
        s(1.0)  # a scalar is no point (SciPy: IndexError)
    assert s.grid[0] is s.x and np.array_equal(s.values, z)


def test_bounds_error_and_fill_value_as_scipy():
    from scipy.interpolate import RegularGridInterpolator
    x, y, _ = grid_data()
    z = bilinear(x[:, None], y[None, :])
    q = np.array([[x[0] - 1, y[1]], [x[1], y[-1] + 0.1], [x[1], y[1]], [np.inf, y[1]],
                  [x[-1], y[0]], [x[2], -np.inf]])
    for fill in (np.nan, -7.5):
        s = Surface(x, y, z, form="geometric", bounds_error=False, fill_value=fill)
        rgi = RegularGridInterpolator((x, y), z, bounds_error=False, fill_value=fill)
        assert np.allclose(s(q), rgi(q), rtol=0, atol=1e-12 * np.abs(z).max(), equal_nan=True)
        assert s.bounds_error is False and s.fill_value == fill or np.isnan(fill)
    # NaN queries: NaN (RegularGridInterpolator 1.10 raises with bounds_error=True)
    s = Surface(x, y, z)
    v = s([[np.nan, y[1]], [x[1], y[1]], [x[1], np.nan]])
    assert np.isnan(v[0]) and np.isnan(v[2]) and np.isfinite(v[1])
    G = s(np.array([np.nan, x[1]]), np.array([y[1], np.nan, y[2]]))
    assert np.isnan(G[0]).all() and np.isnan(G[:, 1]).all() and np.isfinite(G[1, [0, 2]]).all()
    rgi = RegularGridInterpolator((x, y), z)
    for bad in ([[x[0] - 1, y[1]]], [[x[1], y[-1] + 1]]):
        with pytest.raises(ValueError):
            rgi(bad)
        with pytest.raises(TrigsplineError, match="outside the grid"):
            s(bad)
    with pytest.raises(ValueError, match="fill_value=None"):
        Surface(x, y, z, bounds_error=False, fill_value=None)
    # grid with fill: the rows and columns outside get the fill value
    f = Surface(x, y, z, bounds_error=False, fill_value=-1.0)
    G = f(np.array([x[0] - 1, x[1], np.nan]), np.array([y[1], y[-1] + 1]))
    assert G[0, 0] == -1 and G[0, 1] == -1 and G[1, 1] == -1 and np.isfinite(G[1, 0])
    assert np.isnan(G[2]).all()
    zz, zx, zy = f.partials([[x[0] - 1, y[1]]])
    assert zz[0] == zx[0] == zy[0] == -1.0


# ---- errors -----------------------------------------------------------------

def err_of(fn):
    with pytest.raises(TrigsplineError) as ei:
        fn()
    assert isinstance(ei.value, ValueError)
    return ei.value


def test_errors_name_the_node_patch_or_coordinate():
    x, y = np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 3.0])
    z = np.arange(9.0).reshape(3, 3) + 1.0
    zn = z.copy()
    zn[1, 2] = np.nan
    e = err_of(lambda: Surface(x, y, zn))
    assert e.name == "TS_ERR_NONFINITE" and e.node == (1, 2) and e.where == "node"
    assert "node (1, 2) at (x = 1, y = 3) has z = nan" in str(e)
    e = err_of(lambda: Surface(np.array([0.0, np.inf, 2.0]), y, z))
    assert e.where == "x" and e.index == 1 and "x[1] = inf" in str(e)
    e = err_of(lambda: Surface(x, np.array([0.0, 1.0, 1.0]), z))
    assert e.name == "TS_ERR_UNSORTED" and e.where == "y" and e.index == 2
    assert "y[2] = 1 is not greater than y[1] = 1" in str(e)
    e = err_of(lambda: Surface(np.array([0.0, 2.0, 1.0]), y, z))
    assert e.where == "x" and "strictly increasing" in str(e)
    e = err_of(lambda: Surface(x, y[:2], z))
    assert e.name == "TS_ERR_LENGTH" and "(3, 2)" in str(e)
    e = err_of(lambda: Surface(x, np.array([0.0, 1.0]), z[:2]))
    assert e.name == "TS_ERR_LENGTH" and "pass z.T" in str(e)
    e = err_of(lambda: Surface(x, y, z[:, :, None]))
    assert e.name == "TS_ERR_LENGTH"
    zneg = z.copy()
    zneg[2, 0] = -1.0
    e = err_of(lambda: Surface(x, y, zneg, shape="positive"))
    assert e.name == "TS_ERR_NEGATIVE" and e.node == (2, 0) and "z = -1 < 0" in str(e)
    e = err_of(lambda: Surface(x, y, z, shape="bounds", lower=0, upper=8.5))
    assert e.name == "TS_ERR_SIDE" and e.node == (2, 2)
    assert "has z = 9 above the upper bound 8.5" in str(e)
    e = err_of(lambda: Surface(x, y, z, shape="planes", lower=(1.0, 1.0, 0.0),
                               form="geometric"))
    # z[i, j] = 3i + j + 1 against x + y: node (0, 2) at (0, 3) is on the plane
    assert e.name == "TS_ERR_SIDE" and e.node == (0, 2)
    assert "lies on or across the lower plane z = 1*x + 1*y (z = 3, plane value 3)" in str(e)
    e = err_of(lambda: Surface(x, y, z, shape="bounds", lower=5, upper=3))
    assert e.name == "TS_ERR_LINES"
    e = err_of(lambda: Surface(x, y, z, shape="planes", lower=(0, 1.0, 0.0),
                               upper=(0, 0, 4.0), form="geometric"))
    assert e.name in ("TS_ERR_LINES", "TS_ERR_SIDE") and e.node is not None
    e = err_of(lambda: Surface(x, y, z, alpha=-1))
    assert e.name == "TS_ERR_ALPHA" and "alpha = -1" in str(e)
    e = err_of(lambda: Surface(x, y, z, margin=0))
    assert e.name == "TS_ERR_MARGIN"
    e = err_of(lambda: Surface(x, y, z, form="geometric", alpha=0.1))
    assert e.name == "TS_ERR_GEOMETRIC"
    e = err_of(lambda: Surface(x[:1], y, z[:1]))
    assert e.name == "TS_ERR_TOO_FEW"
    # a gap near the underflow threshold against a slope: patch (1, 0) refused
    zu = np.array([4, 1e-310, 1, 4, 1, 1, 4, 1, 1.0]).reshape(3, 3).T
    e = err_of(lambda: Surface(x, x, zu, shape="positive"))
    assert e.name == "TS_ERR_INFEASIBLE" and e.patch == (1, 0) and e.where == "patch"
    assert "patch (1, 0) [1, 2] x [0, 1]" in str(e)
    # control values that overflow: patch named
    zc = np.array([0, 1e300, 0, 1e300, 0, 1e300, 0, 1e300, 0.0]).reshape(3, 3).T
    e = err_of(lambda: Surface(x, y, zc, zero_twist=True, alpha=1e-300))
    assert e.name == "TS_ERR_NONFINITE" and e.patch is not None
    # slopes that overflow at a finite node
    zh = np.zeros((3, 3))
    zh[1, 0] = 1e300
    e = err_of(lambda: Surface(np.array([0, 1e-300, 1]), y, zh))
    assert e.name == "TS_ERR_NONFINITE" and e.node is not None and "overflows" in str(e)
    # errors pickle with their node / patch
    e2 = pickle.loads(pickle.dumps(e))
    assert e2.node == e.node and str(e2) == str(e)


def test_argument_errors():
    x, y = np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 3.0])
    z = np.arange(9.0).reshape(3, 3) + 1.0
    s = Surface(x, y, z, shape="positive")
    for kw, msg in (({"shape": "convex"}, "shape must be one of"),
                    ({"shape": "positive", "lower": 0}, "lower and upper go with"),
                    ({"shape": "bounds"}, "needs lower= and/or upper="),
                    ({"shape": "bounds", "lower": (1, 0, 0)}, "takes constants"),
                    ({"shape": "planes", "lower": (1, 0, -9)}, "needs form='geometric'"),
                    ({"shape": "positive", "beta": 0.5}, "beta is chosen"),
                    ({"slopes": "periodic"}, "not offered for surfaces"),
                    ({"form": "bezier"}, "form must be one of"),
                    ({"shape": "planes", "lower": (1, 2)}, "a plane \\(p, q, c\\)")):
        with pytest.raises(ValueError, match=msg):
            Surface(x, y, z, **kw)
    with pytest.raises(TypeError, match="z is missing"):
        Surface(x, y)
    with pytest.raises(ValueError, match="first partials"):
        s([[0.5, 0.5]], nu=(1, 1))
    with pytest.raises(ValueError, match="grid=True takes 1-D"):
        s(np.zeros((2, 2)), np.zeros(2))
    with pytest.raises(ValueError, match="broadcast"):
        s(np.zeros(2), np.zeros(3), grid=False)
    e = err_of(lambda: s(np.array([0.5, 9.0]), np.array([1.0]), grid=True))
    assert e.name == "TS_ERR_DOMAIN" and e.index == 1 and "x[1] = 9 lies outside [0, 2]" in str(e)
    e = err_of(lambda: s(np.array([0.5]), np.array([1.0, 2.0, -1.0])))
    assert e.index == 2 and "y[2] = -1" in str(e)
    e = err_of(lambda: s(np.array([[[0.5, 1.0], [0.5, 4.0]]])))
    assert e.index == 1 and "point (0, 1) (x = 0.5, y = 4)" in str(e)
    e = err_of(lambda: s.integral(0, 3, 0, 1))
    assert e.name == "TS_ERR_DOMAIN" and "must lie on the grid" in str(e)
    e = err_of(lambda: s.control(2, 0))
    assert e.name == "TS_ERR_INDEX" and e.patch == (2, 0)
    B, X, Y = s.control(1, 1)
    assert B.shape == (4, 4) and B[0, 0] == z[1, 1] and B[3, 3] == z[2, 2]
    assert X[0] == x[1] and X[3] == x[2] and Y[0] == y[1] and Y[3] == y[2]


# ---- safe objects -----------------------------------------------------------

def variants():
    x, y, z = grid_data()
    yield Surface(x, y, z)
    yield Surface(x, y, z, shape="positive", form="c1", alpha=0.4, margin=0.05,
                  slopes="fritsch-carlson", bounds_error=False, fill_value=-3.0)
    yield Surface(x, y, z + 1, shape="planes", lower=(0.01, 0.0, 0.5), upper=20.0,
                  form="geometric", zero_twist=True)
    yield Surface(x, y, z, shape="bounds", lower=0.0, beta=0.0)
    yield Surface(x, y, np.asfortranarray(z), shape="range")


@pytest.mark.parametrize("s", list(variants()))
def test_copies_are_bit_identical(s):
    X, Y = dense(s, 7)
    want = s.partials(X, Y)
    grid = s(X, Y)
    clones = [copy.copy(s), copy.deepcopy(s), pickle.loads(pickle.dumps(s)),
              pickle.loads(pickle.dumps(s, protocol=0))]
    rep = s.report()
    del s
    gc.collect()
    for c in clones:
        for a, b in zip(c.partials(X, Y), want):
            assert np.array_equal(a, b, equal_nan=True)
        assert np.array_equal(c(X, Y), grid)
        r2 = c.report()
        assert np.array_equal(r2["proven_lower"], rep["proven_lower"], equal_nan=True)


def test_views_keep_the_surface_alive_and_are_read_only():
    x, y, z = grid_data()
    zin = z.copy()
    s = Surface(x, y, zin, shape="positive")
    views = (s.x, s.y, s.values, s.dzdx, s.dzdy, s.twist, s.ax, s.ay)
    zin[:] = -1.0  # the surface keeps its own copy
    del s
    gc.collect()
    assert np.array_equal(views[2], z) and views[0][3] == x[3]
    for v in views:
        with pytest.raises(ValueError):
            v[0] = 1.0


def test_threads_share_one_surface():
    x, y, z = grid_data(40, 30)
    s = Surface(x, y, z, shape="positive")
    rng = np.random.default_rng(3)
    pts = np.column_stack([rng.uniform(x[0], x[-1], 100000), rng.uniform(y[0], y[-1], 100000)])
    want = s(pts)
    gx, gy = dense(s, 8)
    wgrid = s(gx, gy)
    res = [None] * 6

    def work(k):
        res[k] = (s(pts), s(gx, gy))

    ts = [threading.Thread(target=work, args=(k,)) for k in range(6)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    for a, b in res:
        assert np.array_equal(a, want) and np.array_equal(b, wgrid)


def test_raw_handle_cannot_be_duplicated():
    from trigspline import _core
    h = _core.surface_new([0.0, 1.0], [0.0, 1.0], [[1.0, 2.0], [3.0, 4.0]])
    for fn in (lambda: copy.copy(h), lambda: pickle.dumps(h), lambda: _core.SurfaceHandle()):
        with pytest.raises(TypeError):
            fn()


def test_repr_and_exports():
    x, y, z = grid_data()
    s = Surface(x, y, z, shape="positive")
    assert "Surface 6 x 4 patches" in repr(s) and "positive" in repr(s)
    assert "Surface" in trigspline.__all__


def test_smallest_grid_and_empty_queries():
    # 2 x 2 nodes: the slopes are the secants (docs/method.md §6), so the
    # geometric form reproduces the bilinear interpolant of the four values
    x, y = np.array([0.0, 1.0]), np.array([0.0, 2.0])
    z = np.array([[1.0, 2.0], [3.0, 7.0]])
    s = Surface(x, y, z, form="geometric")
    u, v = np.meshgrid(np.linspace(0, 1, 11), np.linspace(0, 2, 7), indexing="ij")
    want = (z[0, 0] * (1 - u) * (2 - v) + z[1, 0] * u * (2 - v) + z[0, 1] * (1 - u) * v
            + z[1, 1] * u * v) / 2
    assert np.allclose(s((u, v)), want, rtol=0, atol=1e-14 * 7)
    assert s(np.empty((0, 2))).shape == (0,)
    assert s(np.empty(0), np.empty(0)).shape == (0, 0)
    assert all(a.shape == (0, 3) for a in s.partials(np.empty((0, 3, 2))))


# ---- gridded fields (docs/method.md §11.7) -------------------------------------
def _exact_field(g, x, y):
    """The field g = (xf, yf, zf) at (x, y) in exact rational arithmetic
    (fractions), bilinear on its cell: the reference for the sides."""
    from fractions import Fraction as Fr
    xf, yf, zf = g
    i = min(max(int(np.searchsorted(xf, x, side="right")) - 1, 0), len(xf) - 2)
    j = min(max(int(np.searchsorted(yf, y, side="right")) - 1, 0), len(yf) - 2)
    X0, X1, Y0, Y1 = (Fr(float(v)) for v in (xf[i], xf[i + 1], yf[j], yf[j + 1]))
    X, Y = Fr(float(x)), Fr(float(y))
    z = [[Fr(float(zf[i + a, j + b])) for b in (0, 1)] for a in (0, 1)]
    return (z[0][0] * (X1 - X) * (Y1 - Y) + z[1][0] * (X - X0) * (Y1 - Y) +
            z[0][1] * (X1 - X) * (Y - Y0) + z[1][1] * (X - X0) * (Y - Y0)) / ((X1 - X0) * (Y1 - Y0))


def _fields_case():
    x = np.array([0.0, 0.5, 1.25, 2.0])
    y = np.array([0.0, 1.0, 1.5, 3.0])
    rng = np.random.default_rng(7)
    lo = (np.array([-0.5, 0.75, 2.5]), np.array([-1.0, 1.2, 3.5]),
          rng.uniform(-1.0, 0.0, (3, 3)))
    up = (np.array([-0.25, 1.0, 2.25]), np.array([0.0, 2.0, 3.0]),
          rng.uniform(2.0, 3.0, (3, 3)))
    z = np.empty((x.size, y.size))
    for i, xv in enumerate(x):
        for j, yv in enumerate(y):
            a, b = float(_exact_field(lo, xv, yv)), float(_exact_field(up, xv, yv))
            z[i, j] = a + 0.01 if (i + j) % 3 == 0 else (b - 0.01 if (i + j) % 3 == 1
                                                         else 0.5 * (a + b))
    return x, y, z, lo, up


@pytest.mark.parametrize("form", FORMS)
def test_grids_values_strictly_between_exact_fields(form):
    x, y, z, lo, up = _fields_case()
    try:
        s = Surface(x, y, z, lower=lo, upper=up, form=form)
    except TrigsplineError as e:  # the paper and C1 forms may not prove it
        assert e.name == "TS_ERR_UNPROVEN" and form != "geometric", str(e)
        return
    assert s.shape == "grids" and s.certify()
    assert all(np.array_equal(a, b) for a, b in zip(s.bounds[0], lo))
    xs, ys = np.linspace(0, 2, 41), np.linspace(0, 3, 41)
    v = s(xs, ys, grid=True)
    for a, xv in enumerate(xs):
        for b, yv in enumerate(ys):
            w = v[a, b]
            assert _exact_field(lo, xv, yv) < w < _exact_field(up, xv, yv), (xv, yv, w)
    # nodes reproduced, pickling rebuilds the same surface
    assert np.array_equal(s(x, y, grid=True), z)
    t = pickle.loads(pickle.dumps(s))
    assert np.array_equal(t(xs, ys, grid=True), v)


def test_grids_xarray_field():
    xr = pytest.importorskip("xarray")
    x, y, z, lo, up = _fields_case()
    # dims named y, x (the usual raster order): taken by name
    da = xr.DataArray(up[2].T, dims=("y", "x"), coords={"x": up[0], "y": up[1]})
    s1 = Surface(x, y, z, lower=lo, upper=da, form="geometric")
    s2 = Surface(x, y, z, lower=lo, upper=up, form="geometric")
    q = np.linspace(0, 2, 9)
    assert np.array_equal(s1(q, q, grid=True), s2(q, q, grid=True))


def test_grids_errors():
    x, y, z, lo, up = _fields_case()
    short = (up[0], np.array([0.0, 2.0, 2.5]), up[2])
    with pytest.raises(TrigsplineError) as e:
        Surface(x, y, z, lower=lo, upper=short, form="geometric")
    assert e.value.name == "TS_ERR_BOUND_GRID" and "upper field" in str(e.value)
    assert "does not cover" in str(e.value)
    zz = z.copy()
    zz[1, 1] = float(_exact_field(lo, x[1], y[1]))  # exactly on the lower field
    if zz[1, 1] == _exact_field(lo, x[1], y[1]):
        with pytest.raises(TrigsplineError) as e:
            Surface(x, y, zz, lower=lo, upper=up, form="geometric")
        assert e.value.name == "TS_ERR_SIDE" and "lower field" in str(e.value)
        assert e.value.node == (1, 1)
    with pytest.raises(ValueError):
        Surface(x, y, z, lower=lo, upper=5.0)
    with pytest.raises(ValueError):
        Surface(x, y, z, shape="grids")
    with pytest.raises(ValueError):
        Surface(x, y, z, shape="bounds", lower=lo)
    with pytest.raises(TrigsplineError):
        Surface(x, y, z, lower=(lo[0], lo[1], lo[2].T[:2]))


def test_grids_unproven_names_the_patch():
    # flat data under a tent-shaped lower field: every node above it, but the
    # field bulges past the data between them (docs/method.md §11.7)
    t = np.array([0.0, 1.0, 2.0])
    tent = np.full((3, 3), -1.0)
    tent[1, 1] = 0.5
    with pytest.raises(TrigsplineError) as e:
        Surface([0.0, 2.0], [0.0, 2.0], np.zeros((2, 2)), lower=(t, t, tent))
    assert e.value.name == "TS_ERR_UNPROVEN" and e.value.patch == (0, 0)
    assert "gridded fields" in str(e.value)


def test_grids_other_errors_keep_their_sentences():
    x, y, z, lo, up = _fields_case()
    with pytest.raises(TrigsplineError) as e:
        Surface(x, y, z, lower=lo, upper=up, alpha=-1.0)
    assert e.value.name == "TS_ERR_ALPHA" and "alpha = -1" in str(e.value)
