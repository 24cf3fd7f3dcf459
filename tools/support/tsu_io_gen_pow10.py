#!/usr/bin/env python3
"""Prints the C table of tools/support/tsu_number.c (p10e): for a = -13..12, 10^(27a) ~= T * 2^s with
2^127 <= T < 2^128, T = floor(10^(27a) / 2^s), exact flag.  Standard library only."""
from fractions import Fraction

for a in range(-13, 13):
    x = Fraction(10) ** (27 * a)
    # smallest s with x / 2^s < 2^128
    s = x.numerator.bit_length() - x.denominator.bit_length() - 128
    while x / Fraction(2) ** s >= 2 ** 128:
        s += 1
    while x / Fraction(2) ** s < 2 ** 127:
        s -= 1
    y = x / Fraction(2) ** s
    t = y.numerator // y.denominator
    exact = 1 if y.denominator == 1 else 0
    assert 2 ** 127 <= t < 2 ** 128
    print("    {0x%016xu, 0x%016xu, %d, %d}, /* 10^%d */"
          % (t >> 64, t & (2 ** 64 - 1), s, exact, 27 * a))
