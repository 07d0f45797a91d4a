#!/usr/bin/env python3
"""Truth for tests/test_certificate.c, sweep_tiny_far: two cylinders
x^2 + y^2 = R^2 (axis z) and y^2 + z^2 = r^2 (axis x), r = 0.7 R, meet in
two closed curves x = +-sqrt(R^2 - r^2 sin^2 t), y = r sin t, z = r cos t.
Each has length R * L1, L1 = int_0^{2 pi} sqrt(x'^2 + r^2) dt at R = 1 with
x' = -r^2 sin t cos t / x. Placed anywhere, the length is the same.
Run: python3 tests/truth/gen_certificate_tiny_far_truth.py (mpmath)."""
from mpmath import mp, quad, sqrt, sin, cos, pi

mp.dps = 30
R, r = mp.mpf(1), mp.mpf(7) / 10


def speed(t):
    x = sqrt(R**2 - r**2 * sin(t)**2)
    return sqrt((r**2 * sin(t) * cos(t) / x)**2 + r**2)


print(mp.nstr(quad(speed, [0, pi / 2, pi, 3 * pi / 2, 2 * pi]), 25))
