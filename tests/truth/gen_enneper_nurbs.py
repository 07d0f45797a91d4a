#!/usr/bin/env python3
"""The Enneper-type surface of Hassan and Badr (2016), Example 2,
    R(u, v) = (u - u^3/3 + u v^2, -v - u^2 v + v^3/3, u^2 - v^2),
written EXACTLY as a bicubic B-spline over [-5, 5]^2 with interior knots, so
the NURBS reader and tracer can be checked against the formula surface's
known double curves (tests/truth/gen_enneper_length.py: two curves, each
131.07476547127208... long).

A polynomial of degree <= p is a B-spline of degree p over any knot vector;
its de Boor control points are blossom values P_i = f(t_{i+1}, ..., t_{i+p})
(Ramshaw 1989). The blossom of u^m in p arguments is the elementary
symmetric polynomial e_m of the arguments divided by binomial(p, m). The
blossoms are computed here with exact rationals (sympy), and the control
points are printed as the nearest doubles (17 digits), which moves the
surface by at most 1e-15 of its size.

Run: python3 tests/truth/gen_enneper_nurbs.py > tests/data/nurbs/enneper-nurbs.json
"""
import itertools
import json
from sympy import Rational, binomial, symbols, Poly

P = 3
KNOTS = [Rational(k) for k in (-5, -5, -5, -5, -2, 0, Rational(5, 2), 5, 5, 5, 5)]
KNOTS_V = [Rational(k) for k in (-5, -5, -5, -5, -1, Rational(3, 2), 5, 5, 5, 5)]
u, v = symbols("u v")
XYZ = [u - u**3 / 3 + u * v**2, -v - u**2 * v + v**3 / 3, u**2 - v**2]


def elementary(m, args):
    return sum((Rational(1) if m == 0 else
                __import__("functools").reduce(lambda a, b: a * b, c))
               for c in itertools.combinations(args, m)) if m else Rational(1)


def blossom(poly, args_u, args_v):
    """Blossom of a polynomial in u, v (degree <= P in each) at the given
    P arguments along u and along v."""
    total = Rational(0)
    for (mu, mv), coeff in Poly(poly, u, v).terms():
        total += (coeff * elementary(mu, args_u) / binomial(P, mu)
                  * elementary(mv, args_v) / binomial(P, mv))
    return total


def main():
    nu, nv = len(KNOTS) - P - 1, len(KNOTS_V) - P - 1
    net = []
    for i in range(nu):
        row = []
        for j in range(nv):
            au, av = KNOTS[i + 1:i + 1 + P], KNOTS_V[j + 1:j + 1 + P]
            row.append([float(blossom(f, au, av)) for f in XYZ])
        net.append(row)
    doc = {
        "title": "Enneper-type surface (Hassan and Badr (2016), Example 2) as an exact "
                 "bicubic B-spline with interior knots (tests/truth/gen_enneper_nurbs.py)",
        "surfaces": [{"name": "enneper", "type": "nurbs", "degree": [P, P],
                      "knots": [[float(k) for k in KNOTS], [float(k) for k in KNOTS_V]],
                      "control_points": net}],
        "self": True,
    }
    print(json.dumps(doc))


if __name__ == "__main__":
    main()
