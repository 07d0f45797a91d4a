#!/usr/bin/env python3
"""Truth for the jet tests (tests/test_jet_truth.c), computed independently
of the C code's Taylor recurrences.

For a function f and an input jet a (a polynomial in 1-3 variables), the jet
of f(a) is  sum_k f_k (a - a0)^k,  where f_k = f^(k)(a0)/k! are univariate
Taylor coefficients computed by mpmath at 60 digits (and checked against
sympy's exact derivatives), and the powers are plain truncated polynomial
products. Two-argument functions reduce to one-argument ones:
  a / b = a * (1/b),  atan2(y, x) = atan(y * (1/x)) (+ pi when x0 < 0).
Output: tests/truth/jet_truth.txt, coefficients printed with 20 digits in
the monomial order of jet.h (total degree, then decreasing exponents).

Run:  python3 tests/truth/gen_jet_truth.py
"""
import itertools
import os
import random

import mpmath as mp
import sympy as sp

mp.mp.dps = 60
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "jet_truth.txt")


def monomials(m, K):
    """Monomials of jet.h's order: degree, then decreasing first exponent..."""
    out = []
    for d in range(K + 1):
        def rec(v, rest, prefix):
            if v == m - 1:
                out.append(tuple(prefix + [rest]))
                return
            for a in range(rest, -1, -1):
                rec(v + 1, rest - a, prefix + [a])
        rec(0, d, [])
    return out


def mul(p, q, K):
    r = {}
    for a, x in p.items():
        da = sum(a)
        for b, y in q.items():
            if da + sum(b) > K:
                continue
            c = tuple(i + j for i, j in zip(a, b))
            r[c] = r.get(c, mp.mpf(0)) + x * y
    return r


def compose_univariate(coefs, a, m, K):
    """sum_k coefs[k] (a - a0)^k."""
    zero = (0,) * m
    delta = {k: v for k, v in a.items() if k != zero}
    result = {zero: coefs[0]}
    power = {zero: mp.mpf(1)}
    for k in range(1, K + 1):
        power = mul(power, delta, K)
        for mono, v in power.items():
            result[mono] = result.get(mono, mp.mpf(0)) + coefs[k] * v
    return result


def taylor(f, x0, K):
    return [c for c in mp.taylor(f, x0, K)]


FUNCS = {
    "exp": mp.exp, "log": mp.log, "sqrt": mp.sqrt, "sin": mp.sin, "cos": mp.cos,
    "tan": mp.tan, "asin": mp.asin, "acos": mp.acos, "atan": mp.atan, "sinh": mp.sinh,
    "cosh": mp.cosh, "tanh": mp.tanh, "inv": lambda t: 1 / t,
}
SYMPY = {
    "exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt, "sin": sp.sin, "cos": sp.cos,
    "tan": sp.tan, "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "sinh": sp.sinh,
    "cosh": sp.cosh, "tanh": sp.tanh, "inv": lambda t: 1 / t,
}


def check_against_sympy():
    """mpmath's numerical Taylor coefficients against exact derivatives."""
    t = sp.Symbol("t")
    x0 = sp.Rational(3, 10)
    for name, f in SYMPY.items():
        expr = f(t)
        mpc = taylor(FUNCS[name], mp.mpf(3) / 10, 12)
        for k in range(13):
            exact = sp.diff(expr, t, k).subs(t, x0) / sp.factorial(k)
            ex = mp.mpf(sp.N(exact, 50))
            assert abs(ex - mpc[k]) <= mp.mpf(10) ** -40 * max(1, abs(ex)), (name, k)


def random_jet(rng, m, K, a0, scale):
    """a0 + terms of degree 1..3 with 'high-entropy' coefficients."""
    jet = {(0,) * m: mp.mpf(a0)}
    for mono in monomials(m, min(K, 3)):
        d = sum(mono)
        if d == 0:
            continue
        jet[mono] = mp.mpf(rng.choice([-1, 1]) * rng.randint(100, 999)) / 1000 * scale ** d
    return jet


def unary(name, a, m, K, param=None):
    a0 = a[(0,) * m]
    if name == "powr":
        coefs = taylor(lambda t: t ** param, a0, K)
    elif name == "powi":
        coefs = taylor(lambda t: t ** int(param), a0, K)
    else:
        coefs = taylor(FUNCS[name], a0, K)
    return compose_univariate(coefs, a, m, K)


def fmt(jet, m, K):
    return " ".join(mp.nstr(jet.get(mono, mp.mpf(0)), 20, min_fixed=-1, max_fixed=0)
                    for mono in monomials(m, K))


def main():
    check_against_sympy()
    rng = random.Random(20261122)
    # (function, values of a0 at which to expand, parameter): several points each
    unary_cases = [
        ("exp", (0.385, -1.7, 2.2), None), ("log", (1.7, 0.61, 3.3), None),
        ("sqrt", (2.385, 0.7, 5.1), None), ("sin", (0.9, -2.6, 4.1), None),
        ("cos", (-1.3, 0.2, 2.9), None), ("tan", (0.6, -1.1, 2.5), None),
        ("asin", (0.35, -0.62, 0.05), None), ("acos", (-0.45, 0.57, 0.12), None),
        ("atan", (1.2, -0.3, 3.7), None), ("sinh", (0.7, -1.9, 2.4), None),
        ("cosh", (-0.55, 1.3, 0.05), None), ("tanh", (0.45, -1.2, 2.1), None),
        ("powr", (1.6, 0.9, 3.1), 0.37), ("powr", (2.2, 1.1), -1.5),
        ("powi", (1.3, -0.8), 5), ("powi", (0.8, -1.9), -3),
    ]
    shapes = [(1, 16), (2, 16), (2, 8), (3, 8), (3, 12)]
    lines = []
    ncases = 0
    for m, K in shapes:
        scale = 0.5 if K >= 12 else 0.6
        for name, points, param in unary_cases:
            if (m, K) == (3, 12) and name not in ("exp", "log", "sin", "atan", "powr"):
                continue  # the slowest shape: a subset of the functions
            for a0 in points:
                a = random_jet(rng, m, K, mp.mpf(str(a0)), scale)
                r = unary(name, a, m, K, param)
                lines.append("case %s %d %d %s" % (name, m, K, "-" if param is None else repr(param)))
                lines.append("a " + fmt(a, m, K))
                lines.append("r " + fmt(r, m, K))
                ncases += 1
        # binary: mul, div, atan2 (x0 > 0 and x0 < 0)
        for name, y0, x0 in [("mul", 0.75, -1.4), ("div", 0.75, 1.9), ("atan2", 0.8, 1.25),
                             ("atan2", -0.6, -0.9)]:
            y = random_jet(rng, m, K, mp.mpf(str(y0)), scale)
            x = random_jet(rng, m, K, mp.mpf(str(x0)), scale)
            if name == "mul":
                r = mul(y, x, K)
            elif name == "div":
                r = mul(y, unary("inv", x, m, K), K)
            else:
                q = mul(y, unary("inv", x, m, K), K)
                r = unary("atan", q, m, K)
                if x0 < 0:
                    zero = (0,) * m
                    r[zero] += mp.pi if y0 >= 0 else -mp.pi
            lines.append("case %s %d %d -" % (name, m, K))
            ncases += 1
            lines.append("a " + fmt(y, m, K))
            lines.append("b " + fmt(x, m, K))
            lines.append("r " + fmt(r, m, K))
    with open(OUT, "w") as f:
        f.write("# generated by gen_jet_truth.py; do not edit; %d cases\n" % ncases)
        f.write("\n".join(lines) + "\n")
    print("wrote", OUT, len(lines), "lines")


if __name__ == "__main__":
    main()
