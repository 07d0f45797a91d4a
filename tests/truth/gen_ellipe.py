#!/usr/bin/env python3
"""Truth for the complete elliptic integral of the second kind E(m) (parameter
m = k^2), which tests/test_exact_conics.c computes by the arithmetic-geometric
mean and uses for the length of an ellipse of semi-axes a >= b, 4 a
E(1 - b^2 / a^2): mpmath's ellipe at 30 digits, and the same by quadrature of
sqrt(1 - m sin^2 t) over [0, pi/2] (they agree to the digits printed). The
last line is the length of each of Steinmetz's two ellipses, semi-axes sqrt 2
and 1: 4 sqrt(2) E(1/2)."""
from mpmath import mp, mpf, ellipe, quad, sin, sqrt, pi

mp.dps = 30
for m in ("0.5", "0.9", "0.999"):
    e = ellipe(mpf(m))
    q = quad(lambda t: sqrt(1 - mpf(m) * sin(t) ** 2), [0, pi / 2])
    assert abs(e - q) < mpf(10) ** -25
    print(f"E({m}) = {mp.nstr(e, 21)}")
print(f"4 sqrt(2) E(1/2) = {mp.nstr(4 * sqrt(2) * ellipe(mpf('0.5')), 21)}")
