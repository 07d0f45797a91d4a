#!/usr/bin/env python3
"""Truth for tests/test_certificate_strips.c (issue 23): narrow strips of two
unit cylinders beside their branch points.

A = (cos u, sin u, v), the cylinder x^2 + y^2 = 1, on the strip
v in [a0, a1]; B = (cos s, t, sin s), the cylinder x^2 + z^2 = 1, on
t in [b0, b1] (B's whole height [-1.5, 1.5] when it is not a strip). The
two meet in the ellipses y = z and y = -z, which cross at the branch
points (+-1, 0, 0). On A the strip bounds z = v, on B y = t, so the part of
ellipse e (y = e z) inside both strips is z in [a0, a1] intersected with
e [b0, b1], on each side x > 0 and x < 0 alike.

The ellipse y = e z is theta -> (cos theta, e sin theta, sin theta): speed
sqrt(1 + cos^2 theta), z = sin theta, so the side x > 0 between z0 and z1
is the integral of that speed over [asin z0, asin z1]; x < 0 mirrors it.
Each integral two ways at 40 digits, agreeing to 1e-30: mpmath's quadrature
and the incomplete elliptic integral sqrt(2) E(theta | 1/2), since
1 + cos^2 = 2 (1 - sin^2 / 2).

Printed: a0 a1 b0 b1 (as written in the test, 17 digits) and the total
length at 17 significant digits, with the number of arcs (pieces of an
ellipse on one side of x = 0: a piece through a branch point counts once).

usage: gen_certificate_strips_truth.py > certificate_strips.txt
"""
import mpmath as mp

mp.mp.dps = 40

W = "7e-4"
FULL = ("-1.5", "1.5")
# (a0, a1), (b0, b1): the strip beside, at or across the branch points
CASES = [
    (("0", W), FULL),                    # A's edge through the branch points
    (("-3.5e-4", "3.5e-4"), FULL),       # A's strip across them
    (("1e-5", "7.1e-4"), FULL),          # beside them, 1e-5 away
    (("-7.1e-4", "-1e-5"), FULL),        # beside them, below
    (("2e-4", "9e-4"), FULL),            # 2e-4 away
    (("0", "1e-4"), FULL),               # a strip of 1e-4 from the points
    (("-3.5e-4", "3.5e-4"), ("-2.3e-4", "4.6e-4")),  # both strips across
    (("1e-5", "7.1e-4"), ("-7e-4", "3.5e-4")),       # A beside, B across
]


def side_length(z0, z1):
    lo, hi = mp.asin(z0), mp.asin(z1)
    by_q = mp.quad(lambda th: mp.sqrt(1 + mp.cos(th) ** 2), [lo, hi])
    by_e = mp.sqrt(2) * (mp.ellipe(hi, mp.mpf(1) / 2) - mp.ellipe(lo, mp.mpf(1) / 2))
    assert abs(by_q - by_e) < mp.mpf("1e-30"), (z0, z1, by_q, by_e)
    return by_q


def total(a, b):
    a0, a1, b0, b1 = (mp.mpf(x) for x in a + b)
    length, arcs = mp.mpf(0), 0
    for e in (1, -1):
        lo, hi = sorted((e * b0, e * b1))
        z0, z1 = max(a0, lo), min(a1, hi)
        if z1 > z0:
            length += 2 * side_length(z0, z1)
            arcs += 2
    return length, arcs


print("# a0 a1 b0 b1 total_length arcs  (tests/truth/gen_certificate_strips_truth.py)")
for a, b in CASES:
    length, arcs = total(a, b)
    print(*a, *b, mp.nstr(length, 17), arcs)
