#!/usr/bin/env python3
"""Truth for tests/test_certificate.c (issue 23): the lengths of the loops a
sphere of radius r centred at (1, 0, 0) cuts from the unit cylinder
x = cos u, y = sin u, z = v, the loop straddling the cylinder's seam u = 0.

On the cylinder, |X - (1, 0, 0)|^2 = 2 - 2 cos u + v^2 = r^2, that is
4 sin^2(u/2) + v^2 = r^2: with sin(u/2) = (r/2) sin(phi), v = r cos(phi) the
loop is phi in [0, 2 pi), and the cylinder being of unit radius its arc
length is du^2 + dv^2, u' = r cos(phi) / sqrt(1 - (r/2)^2 sin^2(phi)),
v' = -r sin(phi): a smooth integrand. A second form, 2 int sqrt(1 + v'(u)^2)
du over |u| <= 2 asin(r/2) with v(u) = sqrt(r^2 - 4 sin^2(u/2)) (singular where
the loop turns), must agree to 1e-18 (its endpoint singularity holds
quadrature to about 21 digits). mpmath's tanh-sinh quadrature at 40
digits; printed to 17 significant digits.

usage: gen_certificate_truth.py > certificate_seam_loops.txt
"""
import mpmath as mp

mp.mp.dps = 40

RADII = ["0.3", "0.5", "0.7", "0.9", "1.1", "1.3"]


def loop_length(r):
    r = mp.mpf(r)

    def speed(phi):
        du = r * mp.cos(phi) / mp.sqrt(1 - (r / 2) ** 2 * mp.sin(phi) ** 2)
        dv = -r * mp.sin(phi)
        return mp.sqrt(du * du + dv * dv)

    return mp.quad(speed, mp.linspace(0, 2 * mp.pi, 9))


def loop_length_by_u(r):
    r = mp.mpf(r)
    u0 = 2 * mp.asin(r / 2)

    def speed(u):
        v2 = r * r - 4 * mp.sin(u / 2) ** 2
        return mp.re(mp.sqrt(1 + mp.sin(u) ** 2 / v2))

    return 2 * mp.quad(speed, [-u0, 0, u0])


print("# r  loop_length  (tests/truth/gen_certificate_truth.py)")
for r in RADII:
    L = loop_length(r)
    assert abs(L - loop_length_by_u(r)) < mp.mpf("1e-18"), r
    print(r, mp.nstr(L, 17))
