#!/usr/bin/env python3
"""Truth for tests/test_certificate_crossings.c (issue 23): a tangential
circle crossed by a transversal one, and a tangential circle with a small
loop above it.

A is the unit sphere x^2 + y^2 + z^2 = 1. Both classes take B tangent to A
along the equator z = 0:

- crossed: B = x^2 + y^2 - 1 + z^2 (1 + k (y - d)). On A, x^2 + y^2 - 1 =
  -z^2, so B restricted to A is k z^2 (y - d): the equator, a double root
  (B touches A along it: grad B = (2x, 2y, 0) there, parallel to A's
  normal), and the circle y = d of radius sqrt(1 - d^2), a simple root,
  which crosses the equator at (+-sqrt(1 - d^2), d, 0).
- loop: B = x^2 + y^2 - 1 + z^2 (1 + K ((x - px)^2 + y^2 + (z - pz)^2 - r^2))
  with p = (sqrt(1 - pz^2), 0, pz) on A and pz = gap + r: restricted to A it
  is K z^2 s, s = |X - p|^2 - r^2; so the equator and the circle where the
  sphere of radius r about p meets A. That circle lies in the plane
  X . p = 1 - r^2 / 2 at distance 1 - r^2 / 2 from the centre: its radius
  is sqrt(1 - (1 - r^2/2)^2) = r sqrt(1 - r^2 / 4), its length 2 pi times
  that, and its lowest point at height above pz - r = gap.

Each restriction is checked here with sympy (B - q A, q the multiplier,
reduces to the claimed product), so the closed forms rest on algebra, not
on the code under test. Lengths at 40 digits with mpmath.

Printed, crossed: d k, the circle's length and the crossing's x; loop:
r gap K, the loop's length.

usage: gen_certificate_crossings_truth.py > certificate_crossings.txt
"""
import mpmath as mp
import sympy as sp

mp.mp.dps = 40
x, y, z = sp.symbols("x y z", real=True)
A = x**2 + y**2 + z**2 - 1

CROSSED = [("0.3", "1"), ("0", "1"), ("0.7", "2"), ("-0.5", "0.5"), ("0.95", "1"),
           ("0.3", "10")]
# (r, gap): K = 1 / r^2 keeps B's slope across the loop near 1
LOOPS = [("1e-2", "3e-3"), ("3e-3", "3e-3"), ("1e-3", "3e-3"), ("1e-3", "1e-3"),
         ("1e-3", "3e-4"), ("3e-3", "1e-2")]


def restricted(B, claimed):
    """B on A: B - z^2 ... with x^2 + y^2 replaced by 1 - z^2 equals claimed."""
    on_A = sp.expand(B.subs(x**2, 1 - y**2 - z**2))
    assert sp.simplify(on_A - sp.expand(claimed)) == 0, (B, claimed)


def crossed():
    print("# crossed: d k circle_length crossing_x")
    for ds, ks in CROSSED:
        d, k = sp.Rational(ds), sp.Rational(ks)
        restricted(x**2 + y**2 - 1 + z**2 * (1 + k * (y - d)), k * z**2 * (y - d))
        D = mp.mpf(ds)
        print(ds, ks, mp.nstr(2 * mp.pi * mp.sqrt(1 - D * D), 17),
              mp.nstr(mp.sqrt(1 - D * D), 17))


def loops():
    print("# loop: r gap K loop_length")
    for rs, gs in LOOPS:
        r, g = sp.Rational(rs), sp.Rational(gs)
        pz = g + r
        px = sp.sqrt(1 - pz**2)
        K = 1 / r**2
        s = (x - px)**2 + y**2 + (z - pz)**2 - r**2
        restricted(x**2 + y**2 - 1 + z**2 * (1 + K * s), K * z**2 * s)
        R = mp.mpf(rs)
        print(rs, gs, mp.nstr(1 / (R * R), 17),
              mp.nstr(2 * mp.pi * R * mp.sqrt(1 - R * R / 4), 17))


if __name__ == "__main__":
    crossed()
    loops()
