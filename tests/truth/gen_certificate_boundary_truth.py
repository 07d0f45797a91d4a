#!/usr/bin/env python3
"""Truth for tests/test_certificate_boundary.c (issue 23): Viviani's curve,
the sphere |X| = 2a met by the cylinder of radius a about the vertical line
through (a cos phi, a sin phi), which passes through the sphere's poles
(0, 0, +-2a) and crosses itself at (2a cos phi, 2a sin phi, 0).

In the cylinder's own frame the curve is X = a (1 + cos t), Y = a sin t,
Z = 2a sin(t/2), t in [0, 4 pi): |X'|^2 = a^2 (sin^2 t + cos^2 t) +
a^2 cos^2(t/2) = a^2 (1 + cos^2(t/2)), so its length is
2a * integral_0^{2 pi} sqrt(1 + cos^2 s) ds = 8 sqrt(2) a E(1/2)
(mpmath's ellipe takes the parameter m). Both ways at 40 digits, which must
agree to 1e-30, printed to 17 significant digits: a, the length.

usage: gen_certificate_boundary_truth.py > certificate_viviani.txt
"""
import mpmath as mp

mp.mp.dps = 40

RADII = ["0.5", "0.75", "1", "1.25", "1.5", "2"]


def length(a):
    by_e = 8 * mp.sqrt(2) * a * mp.ellipe(mp.mpf(1) / 2)
    by_q = 2 * a * mp.quad(lambda s: mp.sqrt(1 + mp.cos(s) ** 2), mp.linspace(0, 2 * mp.pi, 9))
    assert abs(by_e - by_q) < mp.mpf("1e-30"), (a, by_e, by_q)
    return by_e


print("# a  length  (tests/truth/gen_certificate_boundary_truth.py)")
for a in RADII:
    print(a, mp.nstr(length(mp.mpf(a)), 17))
