#!/usr/bin/env python3
"""Speed of trigspline.disaggregate (the gufunc, docs/method.md §12) against
PCHIP on the cumulative sum (SciPy's PchipInterpolator, the anchor that keeps
totals and positivity), in the same run: daily totals to hourly totals.

Usage: python3 bench/bench_histo.py [SERIES] [DAYS]     (a bench, not a test)

Both produce the same thing — the hourly totals of every series — from the
same seeded intermittent daily series (62 % dry days, spikes x1000):
trigspline as one gufunc call (per_bin=24, the path the xarray accessor
takes for whole steps per bin; also the general grid path); SciPy as one vectorised PchipInterpolator
over the series axis, evaluated on the hourly grid and differenced.  CPU
seconds (time.process_time), median of ROUNDS interleaved rounds (ours,
grid, PCHIP, in an order that turns each round); each call starts with the
previous result of the same method released, so both meet the allocator in
the same state (a result kept alive while the next is made puts one of them
in fresh pages).  Prints output values per CPU-second for each and their
ratio with the goal (>= 3x) and its verdict, with the largest relative total
error and the number of negative hours of each.
"""
import sys
import time

import numpy as np
from scipy.interpolate import PchipInterpolator

import trigspline

S = int(sys.argv[1]) if len(sys.argv) > 1 else 400
D = int(sys.argv[2]) if len(sys.argv) > 2 else 365
rng = np.random.default_rng(2026)
t = np.where(rng.random((S, D)) < 0.62, 0.0, rng.gamma(0.8, 9.0, (S, D)))
t[rng.random((S, D)) < 0.03] *= 1000.0
e = np.arange(D + 1.0)
g = np.linspace(0.0, D, 24 * D + 1)


def ours():
    return trigspline.disaggregate(e, t, per_bin=24)


def ours_grid():
    return trigspline.disaggregate(e, t, g)


def pchip():
    c = np.concatenate([np.zeros((S, 1)), np.cumsum(t, axis=1)], axis=1)
    return np.diff(PchipInterpolator(e, c, axis=1)(g), axis=1)


ROUNDS = 7


def timed(fns):
    """Median CPU time of each of fns over ROUNDS interleaved rounds, and
    each one's last output."""
    times = [[] for _ in fns]
    outs = [None] * len(fns)
    for r in range(ROUNDS):
        order = list(range(len(fns)))
        order = order[r % len(order):] + order[:r % len(order)]
        for k in order:
            outs[k] = None  # release the previous result first
            c0 = time.process_time()
            outs[k] = fns[k]()
            times[k].append(time.process_time() - c0)
    return [float(np.median(ts)) for ts in times], outs


def quality(out):
    back = out.reshape(S, D, 24).sum(-1)
    wet = t > 0
    err = np.abs(back - t)[wet] / t[wet]
    return err.max(), int((out < 0).sum())


(to, tg, tp), (oo, og, op) = timed([ours, ours_grid, pchip])
n = S * D * 24
eo, no = quality(oo)
ep, np_ = quality(op)
print("series %d x %d days -> %d hourly totals" % (S, D, n))
print("trigspline.disaggregate: %.3g values per CPU-second (%.3f s); total error %.2g, %d negative"
      % (n / to, to, eo, no))
print("trigspline on the grid:  %.3g values per CPU-second (%.3f s)" % (n / tg, tg))
print("PCHIP on the cumulative: %.3g values per CPU-second (%.3f s); total error %.2g, %d negative"
      % (n / tp, tp, ep, np_))
ratio = tp / to
print("ratio (trigspline / PCHIP): %.2f   goal >= 3: %s" % (ratio, "holds" if ratio >= 3 else "NOT HELD"))
