#!/usr/bin/env python3
"""Length of each double curve of the Enneper-type surface of Hassan and
Badr (2016), Example 2, R(u, v) = (u - u^3/3 + u v^2, -v - u^2 v + v^3/3,
u^2 - v^2) over [-5, 5]^2 (tests/test_trust.c, "self-intersection at any
depth").

R(u, v) = R(u, -v) for v != 0 needs -v - u^2 v + v^3/3 = 0, that is
v^2 = 3 (1 + u^2); then R = (4u + 8u^3/3, 0, -3 - 2u^2). In the domain,
v^2 <= 25 gives |u| <= sqrt(22/3). The curve's speed is
sqrt((4 + 8u^2)^2 + (4u)^2); its length is integrated here at 40 digits.
By the symmetry (u, v) -> (v, u) composed with a rotation, the other
double curve (x = 0) has the same length."""
import sympy as sp
from mpmath import mp, mpf, quad, sqrt

u, v = sp.symbols("u v", real=True)
R = sp.Matrix([u - u**3 / 3 + u * v**2, -v - u**2 * v + v**3 / 3, u**2 - v**2])
on = {v: sp.sqrt(3 * (1 + u**2))}
# both preimages give the same point, and the point is the closed form
assert sp.simplify(R.subs(on) - R.subs({v: -sp.sqrt(3 * (1 + u**2))})) == sp.zeros(3, 1)
c = sp.Matrix([4 * u + sp.Rational(8, 3) * u**3, 0, -3 - 2 * u**2])
assert sp.simplify(R.subs(on) - c) == sp.zeros(3, 1)
mp.dps = 40
a = sqrt(mpf(22) / 3)
print(quad(lambda t: sqrt((4 + 8 * t**2) ** 2 + 16 * t**2), [-a, 0, a]))
