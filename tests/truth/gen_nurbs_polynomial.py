#!/usr/bin/env python3
"""Polynomial surfaces of the bundled examples written exactly as B-spline
patches, so every kind of tangential point can be traced on NURBS and
compared with the same surfaces as formulas (tests/test_nurbs_traces.c):

  - the cusp of examples/cusp.json (Bendrici and Boumedien-Zidani (2022),
    Example 2): z = u^3 - v^2 over [-1, 1]^2, degrees (3, 2), with the plane
    z = 0 as a bilinear patch: both surfaces NURBS;
  - the tacnode of examples/tacnode.json: the quartic
    (c z - s x) = (y - X^2/2)^2 - X^4, X = c x + s z, c = cos 0.3, s = sin 0.3,
    is the graph Z = (v - u^2/2)^2 - u^4 over (X, y) = (u, v), rotated back:
    (x, y, z) = (c u - s Z, v, s u + c Z), degrees (4, 2) over
    [-0.9, 0.9] x [-1.1, 1.1] (inside the example's box), with the example's
    implicit plane c z - s x = 0.

A polynomial of degree <= p is a B-spline of degree p over any knot vector;
its de Boor points are blossom values P_i = f(t_{i+1}, ..., t_{i+p})
(Ramshaw 1989). The blossom of u^m in p arguments is the elementary
symmetric polynomial e_m of the arguments over binomial(p, m). Interior
knots are put in on purpose (the curves cross knot lines). Exact rationals
(sympy) except cos 0.3 and sin 0.3, evaluated to 40 digits; control points
are printed as the nearest doubles.

Run: python3 tests/truth/gen_nurbs_polynomial.py  (writes tests/data/nurbs/
problem-cusp-nurbs.json and problem-tacnode-nurbs.json)
"""
import functools
import itertools
import json
import os

from sympy import Poly, Rational, binomial, cos, sin, symbols

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "nurbs")
u, v = symbols("u v")


def elementary(m, args):
    if m == 0:
        return Rational(1)
    return sum(functools.reduce(lambda a, b: a * b, c) for c in itertools.combinations(args, m))


def blossom(poly, p, q, args_u, args_v):
    total = 0
    for (mu, mv), coeff in Poly(poly, u, v).terms():
        total += (coeff * elementary(mu, args_u) / binomial(p, mu)
                  * elementary(mv, args_v) / binomial(q, mv))
    return total


def clamped(lo, hi, p, interior):
    return [lo] * (p + 1) + list(interior) + [hi] * (p + 1)


def bspline(xyz, p, q, ku, kv, name):
    nu, nv = len(ku) - p - 1, len(kv) - q - 1
    net = [[[float(blossom(f, p, q, ku[i + 1:i + 1 + p], kv[j + 1:j + 1 + q]).evalf(40))
             for f in xyz] for j in range(nv)] for i in range(nu)]
    return {"name": name, "type": "nurbs", "degree": [p, q],
            "knots": [[float(k) for k in ku], [float(k) for k in kv]], "control_points": net}


def cusp():
    r = Rational
    surface = bspline([u, v, u**3 - v**2], 3, 2, clamped(-1, 1, 3, [r(-1, 3), r(1, 4)]),
                      clamped(-1, 1, 2, [r(-1, 2), r(1, 5)]), "f")
    plane = {"name": "g", "type": "nurbs", "degree": [1, 1], "knots": [[-1, -1, 1, 1], [-1, -1, 1, 1]],
             "control_points": [[[-1, -1, 0], [-1, 1, 0]], [[1, -1, 0], [1, 1, 0]]]}
    return {"title": "The cusp of z = u^3 - v^2 with the plane z = 0, both as B-spline patches "
                     "(tests/truth/gen_nurbs_polynomial.py; formulas: examples/cusp.json)",
            "surfaces": [surface, plane]}


def tacnode():
    r = Rational
    c, s = cos(r(3, 10)), sin(r(3, 10))
    Z = (v - u**2 / 2)**2 - u**4
    surface = bspline([c * u - s * Z, v, s * u + c * Z], 4, 2,
                      clamped(r(-9, 10), r(9, 10), 4, [r(-3, 10), r(1, 5)]),
                      clamped(r(-11, 10), r(11, 10), 2, [r(1, 4)]), "quartic")
    return {"title": "The tacnode of examples/tacnode.json with the quartic as a B-spline patch "
                     "(tests/truth/gen_nurbs_polynomial.py)",
            "constants": {"c": "cos(0.3)", "s": "sin(0.3)"},
            "surfaces": [{"name": "plane", "type": "implicit", "f": "c*z - s*x"}, surface],
            "box": [[-1, 1], [-1.2, 1.2], [-1, 1]]}


def main():
    for name, doc in (("problem-cusp-nurbs.json", cusp()), ("problem-tacnode-nurbs.json", tacnode())):
        with open(os.path.join(DATA, name), "w") as f:
            json.dump(doc, f)
            f.write("\n")


if __name__ == "__main__":
    main()
