#!/usr/bin/env python3
"""Writes the example data sets of data/examples/ (see README.md there).

Usage: python3 data/examples/make_examples.py [OUT_DIR]   (standard library only)

Every set is synthetic, made here from a stated model and a fixed seed, so
the files are reproduced byte for byte; the page of `make demo`
(scripts/why_demo.py) reads the files, not this script.
"""
import math
import os
import random
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))


def write(name, header, comment, rows, fmt):
    path = os.path.join(OUT, name)
    with open(path, "w") as fh:
        for line in comment.strip().splitlines():
            fh.write("# %s\n" % line.strip())
        fh.write(header + "\n")
        for r in rows:
            fh.write(fmt % r + "\n")
    return path


def rainfall():
    """Daily rainfall (mm) for 40 days: a two-state Markov chain (dry -> wet with
    probability 0.3, wet -> wet 0.6) and gamma-distributed amounts (shape 0.8,
    scale 9 mm) rounded to 0.1 mm (a rain gauge's resolution), seed 11."""
    rng = random.Random(11)
    wet, rows = False, []
    for day in range(1, 41):
        wet = rng.random() < (0.6 if wet else 0.3)
        mm = round(rng.gammavariate(0.8, 9.0), 1) if wet else 0.0
        rows.append((day, mm))
    return write("rainfall_daily.csv", "day,rain_mm",
                 "Daily rainfall (mm), 40 days: synthetic (make_examples.py: Markov chain\n"
                 "wet/dry occurrence, gamma amounts, 0.1 mm gauge resolution, seed 11).\n"
                 "Must stay >= 0: rain is never negative.", rows, "%d,%.1f")


def concentration():
    """Plasma concentration (mg/L) after one oral dose: one-compartment model
    C(t) = 9.6 (exp(-0.18 t) - exp(-1.4 t)) plus the detection floor 0.05 mg/L,
    times lognormal noise (sd 6%), seed 5, rounded to 0.001 mg/L; sampled at
    a typical sparse clinical schedule.  Values stay above the floor 0.05."""
    rng = random.Random(5)
    ts = [0.25, 0.5, 1, 1.5, 2, 3, 4, 6, 8, 12, 24, 36, 48]
    rows = []
    for t in ts:
        c = 9.6 * (math.exp(-0.18 * t) - math.exp(-1.4 * t))
        c = 0.05 + c * math.exp(rng.gauss(0.0, 0.06))
        rows.append((t, max(round(c, 3), 0.051)))
    return write("drug_concentration.csv", "hours,mg_per_L",
                 "Drug concentration after one oral dose (mg/L): synthetic one-compartment\n"
                 "model (make_examples.py), 6% lognormal noise, seed 5; the assay's\n"
                 "detection floor is 0.05 mg/L: the curve must stay above it.", rows, "%g,%.3f")


def cloud_cover():
    """Hourly cloud cover (%) over two days: a random walk in logit space
    (step sd 1.1, seed 9), values beyond 97% or below 3% reported as 100 and
    0 (an observer's whole-sky cover), rounded to 1%."""
    rng = random.Random(9)
    z, rows = 0.0, []
    for h in range(0, 48, 2):
        z += rng.gauss(0.0, 1.1)
        p = 100.0 / (1.0 + math.exp(-z))
        p = 100.0 if p > 97 else 0.0 if p < 3 else round(p)
        rows.append((h, p))
    return write("cloud_cover.csv", "hour,cover_percent",
                 "Cloud cover (%), every 2 hours for two days: synthetic (make_examples.py,\n"
                 "logit random walk, seed 9); 0 and 100 occur exactly.\n"
                 "Must stay between 0 and 100.", rows, "%d,%g")


def growth():
    """Weight (kg) of a growing animal, weekly for 20 weeks, that must stay above
    the reference line 1.5 t + 10 (a welfare threshold rising with age):
    growth in spurts (weekly gain 0.2 kg, plus exponential(mean 1.5) kg in 35% of
    weeks, seed 8),
    never below the line + 0.15 kg, rounded to 0.01 kg."""
    rng = random.Random(8)
    w, rows = 10.6, []
    for t in range(0, 21):
        w = max(w, 1.5 * t + 10 + 0.15)
        rows.append((t, round(w, 2)))
        w += 0.2 + (rng.expovariate(1 / 1.5) if rng.random() < 0.35 else 0.0)
    return write("growth_above_trend.csv", "week,weight_kg",
                 "Weekly weight (kg) of a growing animal: synthetic growth in spurts\n"
                 "(make_examples.py, seed 8).  Must stay above the reference line\n"
                 "weight = 1.5 week + 10 (every point is at least 0.15 kg above it).",
                 rows, "%d,%.2f")


def outline():
    """A closed outline (a field boundary, metres) inside the box [0, 100] x [0, 60]:
    12 points on a rounded rectangle touching the sides, moved inwards by 0.2 to
    1 m (seed 4): the surveyed corners lie within a metre of the fence."""
    rng = random.Random(4)
    rows = []
    for k in range(12):
        a = 2 * math.pi * k / 12
        c, s = math.cos(a), math.sin(a)
        # superellipse |x|^4 + |y|^4 = 1 scaled to the box, then jittered inwards
        r = (abs(c) ** 4 + abs(s) ** 4) ** -0.25
        x = 50 + 50 * r * c - rng.uniform(0.2, 1.0) * (1 if c > 0 else -1)
        y = 30 + 30 * r * s - rng.uniform(0.2, 1.0) * (1 if s > 0 else -1)
        x, y = min(max(x, 0.2), 99.8), min(max(y, 0.2), 59.8)
        rows.append((round(x, 2), round(y, 2)))
    return write("field_outline.csv", "x_m,y_m",
                 "Closed outline of a field (m), 12 points: synthetic (make_examples.py,\n"
                 "superellipse moved 0.2-1 m inwards, seed 4).  Must stay inside the\n"
                 "property box 0 <= x <= 100, 0 <= y <= 60.", rows, "%.2f,%.2f")


if __name__ == "__main__":
    for fn in (rainfall, concentration, cloud_cover, growth, outline):
        print(fn())
