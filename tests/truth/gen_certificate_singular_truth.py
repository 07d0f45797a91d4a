#!/usr/bin/env python3
"""Truth for tests/test_certificate_singular.c (issue 23): two cylinders of
unit radius, A about the y axis (x^2 + z^2 = 1) and B about the horizontal
direction d = (sin a, cos a, 0) (the y axis turned by a about z), meet in
two ellipses through the branch points (0, 0, +-1).

Subtracting the equations, |X|^2 - (X.d)^2 - (x^2 + z^2) = 0 gives
y^2 = (x sin a + y cos a)^2: the two planes y = +-(x sin a + y cos a), both
holding the z axis. Plane k holds the horizontal unit vector h_k, and its
ellipse on A is s h_k + t e_z with (s h_kx)^2 + t^2 = 1: semi-axes 1/|h_kx|
and 1. Plane 1: y (1 - cos a) = x sin a, h_1x^2 = (1 - cos a)/2; plane 2:
y (1 + cos a) = -x sin a, h_2x^2 = (1 + cos a)/2.

Each perimeter two ways at 40 digits, which must agree to 1e-30: 4 A E(m)
with m = 1 - 1/A^2 (mpmath's ellipe takes the parameter m), and the
quadrature of the speed of theta -> (A cos theta, sin theta) over a period.
Printed to 17 significant digits: a (degrees), the two perimeters.

usage: gen_certificate_singular_truth.py > certificate_branch_cylinders.txt
"""
import mpmath as mp

mp.mp.dps = 40

ANGLES = ["90", "80", "70", "60", "50", "40"]


def perimeter(A):
    by_e = 4 * A * mp.ellipe(1 - 1 / A**2)
    by_q = mp.quad(lambda t: mp.sqrt((A * mp.sin(t)) ** 2 + mp.cos(t) ** 2),
                   mp.linspace(0, 2 * mp.pi, 9))
    assert abs(by_e - by_q) < mp.mpf("1e-30"), (A, by_e, by_q)
    return by_e


print("# a_degrees  perimeter_1  perimeter_2  (tests/truth/gen_certificate_singular_truth.py)")
for a in ANGLES:
    ar = mp.radians(mp.mpf(a))
    A1 = 1 / mp.sqrt((1 - mp.cos(ar)) / 2)
    A2 = 1 / mp.sqrt((1 + mp.cos(ar)) / 2)
    print(a, mp.nstr(perimeter(A1), 17), mp.nstr(perimeter(A2), 17))
