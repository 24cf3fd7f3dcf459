#!/usr/bin/env python3
"""Writes tests/tools/data/io_parse_ref.txt and tests/tools/data/io_format_ref.txt, the
independent references of tests/tools/test_io.c (standard library only; CPython's
float() is correctly rounded and repr() gives the shortest round-trip string,
nearest to the value -- David Gay's dtoa, not glibc).

io_parse_ref.txt:  <decimal string> <expected: 16 hex digits of the bits | inf | -inf>
io_format_ref.txt: <16 hex digits of the bits> <repr()>
Run from anywhere: python3 tests/tools/data/io_gen_reference.py
"""
import os
import random
import struct
from decimal import Decimal, getcontext

getcontext().prec = 2000
HERE = os.path.dirname(os.path.abspath(__file__))
rng = random.Random(20240611)


def bits(x):
    return struct.unpack("<Q", struct.pack("<d", x))[0]


def from_bits(u):
    return struct.unpack("<d", struct.pack("<Q", u))[0]


def expect(s):
    v = float(s)
    if v == float("inf"):
        return "inf"
    if v == float("-inf"):
        return "-inf"
    return "%016x" % bits(v)


def exact(d):
    """Exact plain decimal text of a Decimal (no exponent)."""
    t = format(d, "f")
    if "." in t:
        t = t.rstrip("0").rstrip(".")
    return t


def midpoint(u):
    """Exact decimal of the midpoint between double u and the next one up."""
    a = Decimal(from_bits(u))
    b = Decimal(from_bits(u + 1))
    return (a + b) / 2


def sci(d, ndig):
    """d rounded down (truncated) to ndig significant digits, as d.ddde±x."""
    s = format(d, "e")  # exact with prec 2000
    mant, e = s.split("e")
    digs = mant.replace(".", "").lstrip("-")
    digs = (digs + "0" * ndig)[:ndig]
    return digs[0] + "." + digs[1:] + "e" + e


cases = []
# midpoints: exact (ties to even), and just below / above
exps = list(range(0, 2046))
for i in range(70):
    be = rng.choice(exps) if i % 7 else rng.choice([0, 1, 2, 1023, 1075, 2045])
    f = rng.getrandbits(52)
    u = (be << 52) | f
    if from_bits(u + 1) == float("inf"):
        u -= 1
    m = midpoint(u)
    t = exact(m)
    if len(t) > 900:  # keep the file small; scientific form is as exact
        t = format(m.normalize(), "e")
    cases.append(t)
    cases.append(sci(m, 17))
    cases.append(sci(m, 25))
    cases.append(format(m.normalize(), "e").replace("e", "000000000001e", 1)
                 if "." in format(m.normalize(), "e") else format(m.normalize(), "e"))
# short midpoints: integers 2^53..2^64 and halves
for i in range(60):
    sh = rng.randint(1, 11)
    mm = rng.randint(2 ** 52, 2 ** 53 - 1)
    cases.append(str((2 * mm + 1) << (sh - 1)))
    cases.append(str((2 * mm + 1) << (sh - 1)) + ".000000000000000000001")
    cases.append(str(((2 * mm + 1) << (sh - 1)) - 1) + ".99999999999999999999")
# boundaries
ovf = Decimal(2) ** 1024 - Decimal(2) ** 970  # DBL_MAX + half an ulp: rounds to inf
cases += [exact(ovf), exact(ovf - 1), exact(ovf + 1), "1.7976931348623158e308",
          "1.7976931348623157e308", "1.797693134862315807e308", "1e309", "-1e309"]
half_min = Decimal(2) ** -1075
cases += [format(half_min, "e"), format(half_min * Decimal("1.000000000000000000001"), "e"),
          format(half_min * Decimal("0.999999999999999999999"), "e"),
          format(half_min * 3, "e"), "2.4703282292062327e-324", "2.4703282292062328e-324",
          "4.9406564584124654e-324", "1e-324", "3e-324", "1e-400", "2.2250738585072011e-308",
          "2.2250738585072012e-308", "2.2250738585072014e-308",
          "9007199254740993", "9007199254740993.0000000000000000000001", "9007199254740995",
          "0.1", "0.30000000000000004", "123456789012345678901234567890",
          "0." + "0" * 300 + "1", "1" + "0" * 308, "1" + "0" * 309,
          "0.000000000000000000000000000000000000000000001e45"]
# random decimals of many shapes
for i in range(1500):
    nd = rng.choice([1, 2, 3, 5, 8, 12, 15, 16, 17, 18, 19, 20, 21, 25, 30, 40])
    digs = "".join(rng.choice("0123456789") for _ in range(nd))
    pt = rng.randint(0, nd)
    s = digs[:pt] + "." + digs[pt:] if rng.random() < 0.7 else digs
    if s.startswith("."):
        s = "0" + s
    if rng.random() < 0.7:
        s += "e%d" % rng.randint(-345, 330)
    if rng.random() < 0.3:
        s = "-" + s
    cases.append(s)

with open(os.path.join(HERE, "io_parse_ref.txt"), "w") as fh:
    for s in cases:
        fh.write("%s %s\n" % (s, expect(s)))

with open(os.path.join(HERE, "io_format_ref.txt"), "w") as fh:
    vals = []
    for i in range(1500):
        u = rng.getrandbits(63)
        if (u >> 52) == 0x7FF:
            continue
        vals.append(u)
    for e in range(-1074, 1024, 7):  # powers of two (asymmetric intervals)
        vals.append(bits(2.0 ** e))
    for e in range(-323, 309, 3):
        vals.append(bits(float("1e%d" % e)))
    for i in range(300):  # short decimals
        vals.append(bits(float("%d.%d" % (rng.randint(0, 9999), rng.randint(0, 999)))))
    vals += [1, 0x000FFFFFFFFFFFFF, 0x0010000000000000, 0x7FEFFFFFFFFFFFFF]
    for u in vals:
        fh.write("%016x %s\n" % (u, repr(from_bits(u))))
