#!/usr/bin/env python3
"""Truth for the NURBS derivative tests (issue 12): every partial derivative
d^(a+b) R / du^a dv^b, a + b <= 8, of four NURBS patches at several points,
exact (sympy rational arithmetic), printed with 30 significant digits.

How it is computed (independent of intercurve's C code, which uses de Boor's
derivative algorithm on homogeneous points and the quotient rule):
  1. the basis functions of the span holding the point come from the
     Cox-de Boor recursion run symbolically on that span (nurbs_sym.py), so
     R = (X, Y, Z) / W with X, Y, Z, W exact polynomials in u, v;
  2. the derivatives are taken symbolically: with R_ab = P_ab / W^m, one more
     derivative is (P_ab' W - m P_ab W') / W^(m+1) (exact polynomials);
  3. each P_ab / W^m is evaluated at the (dyadic rational) point exactly.
Cross-check by a different route, at every point of the file: the basis from
Marsden's identity (a linear solve, no recursion), R's Taylor coefficients
at the point from the exact power-series division X(u0+s, v0+t) /
W(u0+s, v0+t) (no symbolic differentiation), derivative = a! b! coefficient.
Agreement: the two routes give identical rational numbers for every
derivative at every point (the script asserts equality, not closeness); the
two bases also agree as polynomials on every span of every patch.
Third route, for orders <= 2 at every point: one-sided finite differences
(step 1e-30, on the side whose piece the truth uses) of R summed over all
control points with the global Cox-de Boor recursion on the whole knot
vector, at 120 digits: agreement within 1.9e-28 relative (asserted < 1e-24);
these differences do catch a wrong side at the double knot (error 4.5) and a
weight changed by 1/1024 (error 1.7e-3).

All knots, weights, control points and parameters are dyadic rationals, so
the doubles the C test reads from this file are the exact values used here.

Knot convention: a parameter on an interior knot t_k is evaluated on the
polynomial piece of the span to its right, [t_k, t_{k+1}) (side +1, the usual
convention); for such points the file also holds the piece to the left,
(t_{k-1}, t_k] (side -1): every combination of sides for the directions in
which the point is on an interior knot. At the domain's upper end the last
span is used (side -1 printed), at the lower end the first (side +1).

Patches:
  a-bicubic:   degree (3, 3), non-rational, clamped non-uniform knots, an
               interior double knot at u = 1/2 (C^1 there), a single one at
               u = 1/4 (C^2) and at v = 3/8;
  b-biquad:    degree (2, 2), rational, weights 1/2 .. 3;
  c-deg32:     degree (3, 2), rational, u clamped, v unclamped uniform
               (knots 1/4, 1/2, ..., 2; domain v in [3/4, 3/2]);
  d-deg51:     degree (5, 1), rational, interior knots u = 1/2, v = 1/2
               (C^0 along v = 1/2).

File format (tests/truth/nurbs_derivs.txt; one item per line, fields
separated by single spaces; '#' lines are comments):
  patch NAME                      a new patch
  degree p q
  count n_u n_v                   control points along u and along v
  rational 0|1                    0: all weights are 1 (the C test may pass NULL)
  periodic 0 0
  knots_u m t_0 ... t_{m-1}       m = n_u + p + 1
  knots_v m t_0 ... t_{m-1}       m = n_v + q + 1
  cp i j x y z w                  n_u * n_v lines, i = 0..n_u-1 outer, j inner;
                                  point (i, j) is ic_nurbs.points[3*(i*n_v + j)]
  at u v side_u side_v span_u span_v onknot
                                  a point; side +1/-1 as above; span_u = k with
                                  the piece on [t_k, t_{k+1}] (likewise v);
                                  onknot = 1 (u on an interior knot) + 2 (v on
                                  an interior knot), 0 if neither
  d a b x y z                     d^(a+b)R/du^a dv^b (not divided by
                                  factorials), 45 lines after each 'at', in the
                                  order of jet.h: a + b = 0, 1, ..., 8, then a
                                  decreasing
  end                             end of the patch
Numbers: knots, points, weights and parameters are exact decimals; the
derivatives have 30 significant digits (an exact 0 is printed "0").

Run:  python3 tests/truth/gen_nurbs_derivs.py   (about a minute)
"""
import math
import os
import sys
from fractions import Fraction

import mpmath as mp
import sympy as sp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nurbs_sym as ns  # noqa: E402

ORDER = 8
DIGITS = 30
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "nurbs_derivs.txt")
R = sp.Rational
u, v = ns.u, ns.v
mp.mp.dps = 60


def derivative_order():
    """(a, b) with a + b <= ORDER in jet.h's order: degree, then a decreasing."""
    return [(d - b, b) for d in range(ORDER + 1) for b in range(d + 1)]


def make_patch(name, degree, knots_u, knots_v, n_u, n_v, point, weight):
    pts = [[[R(c) for c in point(i, j)] for j in range(n_v)] for i in range(n_u)]
    wts = [[R(weight(i, j)) for j in range(n_v)] for i in range(n_u)]
    ku, kv = [R(t) for t in knots_u], [R(t) for t in knots_v]
    assert len(ku) == n_u + degree[0] + 1 and len(kv) == n_v + degree[1] + 1
    return {"name": name, "degree": degree, "knots": [ku, kv], "points": pts, "weights": wts,
            "rational": any(w != 1 for row in wts for w in row)}


WEIGHTS = [R(1, 2), R(3, 4), R(1), R(5, 4), R(3, 2), R(2), R(5, 2), R(3)]

PATCHES = [
    (make_patch("a-bicubic", (3, 3),
                [0, 0, 0, 0, R(1, 4), R(1, 2), R(1, 2), 1, 1, 1, 1],
                [0, 0, 0, 0, R(3, 8), 1, 1, 1, 1], 7, 5,
                lambda i, j: (R(i, 2) + R((i * j) % 3, 16), R(j, 2) + R((i + 2 * j) % 5, 32),
                              R((i * 7 + j * 13) % 11 - 5, 8)),
                lambda i, j: 1),
     [(R(5, 16), R(11, 16)), (R(1, 2), R(3, 16)), (R(1, 4), R(3, 8)), (0, 0), (1, 1),
      (R(13, 16), R(1, 8))]),
    (make_patch("b-biquad", (2, 2),
                [0, 0, 0, R(1, 2), 1, 1, 1],
                [0, 0, 0, R(1, 4), R(3, 4), 1, 1, 1], 4, 5,
                lambda i, j: (i + R(j, 8), j - R(i * i, 16), R((3 * i + 2 * j) % 7 - 3, 4)),
                lambda i, j: WEIGHTS[(3 * i + 5 * j) % 8]),
     [(R(3, 8), R(5, 8)), (R(1, 2), R(1, 4)), (R(15, 16), R(1, 16)), (R(1, 8), R(3, 4))]),
    (make_patch("c-deg32", (3, 2),
                [0, 0, 0, 0, R(1, 2), 1, 1, 1, 1],
                [R(k, 4) for k in range(1, 9)], 5, 5,
                lambda i, j: (R(3 * i, 4) + R(j, 16), R(j, 2) + R((i * j) % 4, 8),
                              R((5 * i + 3 * j) % 9 - 4, 8)),
                lambda i, j: WEIGHTS[(i + 3 * j + 1) % 8]),
     [(R(3, 16), R(7, 8)), (R(1, 2), R(1)), (R(7, 8), R(3, 4)), (R(5, 8), R(3, 2))]),
    (make_patch("d-deg51", (5, 1),
                [0] * 6 + [R(1, 2)] + [1] * 6,
                [0, 0, R(1, 2), 1, 1], 7, 3,
                lambda i, j: (R(i, 4), R(j, 1) + R(i % 3, 8), R((2 * i + 5 * j) % 7 - 3, 8)),
                lambda i, j: WEIGHTS[(5 * i + 2 * j + 3) % 8]),
     [(R(5, 16), R(3, 8)), (R(1, 2), R(1, 2)), (R(3, 4), R(7, 8))]),
]


def interior_knot(knots, p, n, t):
    return knots[p] < t < knots[n] and t in knots


def sides(patch, uu, vv):
    """Side combinations for a point: both sides where it is on an interior knot."""
    n_u, n_v = len(patch["points"]), len(patch["points"][0])
    p, q = patch["degree"]
    on_u = interior_knot(patch["knots"][0], p, n_u, uu)
    on_v = interior_knot(patch["knots"][1], q, n_v, vv)
    su = [+1, -1] if on_u else [+1]
    sv = [+1, -1] if on_v else [+1]
    flag = (1 if on_u else 0) + (2 if on_v else 0)
    return [(a, b, flag) for a in su for b in sv]


def derivs_symbolic(num, den, uu, vv):
    """Route 1: symbolic quotient derivatives of X/W, evaluated exactly."""
    table = {(0, 0): (num, 1)}
    Wu, Wv = den.diff(u), den.diff(v)
    for a, b in derivative_order():
        if (a, b) in table:
            continue
        if b == 0:
            P, m = table[(a - 1, 0)]
            P = [Pc.diff(u) * den - m * Pc * Wu for Pc in P]
        else:
            P, m = table[(a, b - 1)]
            P = [Pc.diff(v) * den - m * Pc * Wv for Pc in P]
        table[(a, b)] = (P, m + 1)
    w0 = den.eval({u: uu, v: vv})
    out = {}
    for ab, (P, m) in table.items():
        out[ab] = [sp.Rational(Pc.eval({u: uu, v: vv})) / w0**m for Pc in P]
    return out


def taylor(poly, uu, vv):
    """Taylor coefficients of a Poly in u, v about (uu, vv), as Fractions."""
    s, t = sp.symbols("s t")
    shifted = sp.Poly(poly.as_expr().subs({u: uu + s, v: vv + t}, simultaneous=True), s, t)
    return {mon: Fraction(int(sp.numer(c)), int(sp.denom(c)))
            for mon, c in zip(shifted.monoms(), shifted.coeffs())}


def derivs_series(num, den, uu, vv):
    """Route 2: power-series division R W = X, then a! b! coefficient."""
    w = taylor(den, uu, vv)
    out = {}
    for c in range(3):
        x = taylor(num[c], uu, vv)
        r = {}
        for a, b in sorted(derivative_order(), key=lambda ab: ab[0] + ab[1]):
            acc = x.get((a, b), Fraction(0))
            for (i, j), wij in w.items():
                if (i, j) != (0, 0) and i <= a and j <= b:
                    acc -= wij * r[(a - i, b - j)]
            r[(a, b)] = acc / w[(0, 0)]
        for ab in derivative_order():
            val = r[ab] * math.factorial(ab[0]) * math.factorial(ab[1])
            out.setdefault(ab, [None] * 3)[c] = sp.Rational(val.numerator, val.denominator)
    return out


def check_bases(patch):
    """Cox-de Boor and Marsden bases agree as polynomials on every span."""
    for d in range(2):
        knots, p = patch["knots"][d], patch["degree"][d]
        n = len(patch["points"]) if d == 0 else len(patch["points"][0])
        for k in ns.span_list(knots, p, n):
            a = ns.basis_cox_de_boor(knots, p, k, u)
            b = ns.basis_marsden(knots, p, k, u)
            assert all(sp.expand(x - y) == 0 for x, y in zip(a, b)), (patch["name"], d, k)
            assert sp.expand(sum(a) - 1) == 0


def global_basis(knots, p, t):
    """All N_{i,p}(t) by the textbook global recursion (mpmath, step functions
    of the whole knot vector; the domain's upper end closes the last span)."""
    m = len(knots)
    end = knots[m - p - 1]
    N = []
    for i in range(m - 1):
        a, b = knots[i], knots[i + 1]
        N.append(mp.mpf(1) if (a <= t < b) or (a < b and t == b == end) else mp.mpf(0))
    for d in range(1, p + 1):
        new = []
        for i in range(m - 1 - d):
            term = mp.mpf(0)
            if knots[i + d] != knots[i]:
                term += (t - knots[i]) / (knots[i + d] - knots[i]) * N[i]
            if knots[i + d + 1] != knots[i + 1]:
                term += (knots[i + d + 1] - t) / (knots[i + d + 1] - knots[i + 1]) * N[i + 1]
            new.append(term)
        N = new
    return N


def global_eval(patch, mpatch, uu, vv):
    """R(u, v) summed over every control point (no span bookkeeping)."""
    Nu = global_basis(mpatch[0], patch["degree"][0], uu)
    Nv = global_basis(mpatch[1], patch["degree"][1], vv)
    num, den = [mp.mpf(0)] * 3, mp.mpf(0)
    for i, row in enumerate(mpatch[2]):
        for j, (P, w) in enumerate(row):
            nw = Nu[i] * Nv[j] * w
            den += nw
            num = [num[c] + nw * P[c] for c in range(3)]
    return [x / den for x in num]


FD_STEP = mp.mpf("1e-30")    # parameter units; one-sided differences, error O(h)
FD_AGREE = mp.mpf("1e-24")   # relative to max(1, |value|)
WORST_FD = [mp.mpf(0)]


def check_finite_differences(patch, uu, vv, su, sv, d1):
    """Third route for orders <= 2: one-sided differences of the global sum at
    120 digits, on the side whose piece the truth uses."""
    with mp.workdps(120):
        tomp = lambda r: mp.mpf(r.p) / r.q
        mpatch = ([tomp(t) for t in patch["knots"][0]], [tomp(t) for t in patch["knots"][1]],
                  [[([tomp(c) for c in P], tomp(w)) for P, w in zip(prow, wrow)]
                   for prow, wrow in zip(patch["points"], patch["weights"])])
        h = FD_STEP
        u0, v0 = tomp(uu), tomp(vv)
        f = lambda a, b: global_eval(patch, mpatch, u0 + a * su * h, v0 + b * sv * h)
        F = {(a, b): f(a, b) for a in range(3) for b in range(3) if a + b <= 2}
        est = {
            (0, 0): F[(0, 0)],
            (1, 0): [(F[(1, 0)][c] - F[(0, 0)][c]) / (su * h) for c in range(3)],
            (0, 1): [(F[(0, 1)][c] - F[(0, 0)][c]) / (sv * h) for c in range(3)],
            (2, 0): [(F[(2, 0)][c] - 2 * F[(1, 0)][c] + F[(0, 0)][c]) / h**2 for c in range(3)],
            (0, 2): [(F[(0, 2)][c] - 2 * F[(0, 1)][c] + F[(0, 0)][c]) / h**2 for c in range(3)],
            (1, 1): [(F[(1, 1)][c] - F[(1, 0)][c] - F[(0, 1)][c] + F[(0, 0)][c]) / (su * sv * h**2)
                     for c in range(3)],
        }
        worst = mp.mpf(0)
        for ab, vals in est.items():
            for c in range(3):
                exact_v = tomp(d1[ab][c])
                err = abs(vals[c] - exact_v) / max(1, abs(exact_v))
                worst = max(worst, err)
        assert worst < FD_AGREE, (patch["name"], uu, vv, worst)
        return worst


def fmt(x):
    if x == 0:
        return "0"
    return mp.nstr(mp.mpf(x.p) / x.q, DIGITS, min_fixed=-4, max_fixed=6)


def exact(x):
    """A dyadic rational as an exact decimal string."""
    x = sp.Rational(x)
    s = mp.nstr(mp.mpf(x.p) / x.q, 40)
    assert sp.Rational(s) == x, (x, s)
    return s


def write_patch(f, patch, points):
    p, q = patch["degree"]
    n_u, n_v = len(patch["points"]), len(patch["points"][0])
    f.write("patch %s\n" % patch["name"])
    f.write("degree %d %d\ncount %d %d\n" % (p, q, n_u, n_v))
    f.write("rational %d\nperiodic 0 0\n" % (1 if patch["rational"] else 0))
    for d, key in enumerate(("knots_u", "knots_v")):
        ks = patch["knots"][d]
        f.write("%s %d %s\n" % (key, len(ks), " ".join(exact(t) for t in ks)))
    for i in range(n_u):
        for j in range(n_v):
            P = patch["points"][i][j]
            f.write("cp %d %d %s %s %s %s\n" % (i, j, exact(P[0]), exact(P[1]), exact(P[2]),
                                                 exact(patch["weights"][i][j])))
    cases = 0
    for uu, vv in points:
        uu, vv = sp.Rational(uu), sp.Rational(vv)
        for su, sv, flag in sides(patch, uu, vv):
            k, l = ns.spans(patch, uu, vv, su, sv)
            # the side actually used (domain ends take their only span)
            ku, kv = patch["knots"][0], patch["knots"][1]
            su_used = -1 if uu == ku[k + 1] else +1
            sv_used = -1 if vv == kv[l + 1] else +1
            num, den = ns.piece(patch, k, l, ns.basis_cox_de_boor)
            d1 = derivs_symbolic(num, den, uu, vv)
            num2, den2 = ns.piece(patch, k, l, ns.basis_marsden)
            d2 = derivs_series(num2, den2, uu, vv)
            for ab in derivative_order():
                assert d1[ab] == d2[ab], (patch["name"], uu, vv, ab)
            WORST_FD[0] = max(WORST_FD[0], check_finite_differences(patch, uu, vv, su_used,
                                                                   sv_used, d1))
            f.write("at %s %s %d %d %d %d %d\n" % (exact(uu), exact(vv), su_used, sv_used, k, l,
                                                   flag))
            for a, b in derivative_order():
                f.write("d %d %d %s\n" % (a, b, " ".join(fmt(c) for c in d1[(a, b)])))
            cases += 1
    f.write("end\n")
    return cases


def main():
    total = 0
    with open(OUT, "w") as f:
        f.write("# generated by gen_nurbs_derivs.py; do not edit. Exact sympy derivatives,\n"
                "# cross-checked exactly by a second route (see the script's header).\n")
        for patch, points in PATCHES:
            check_bases(patch)
            n = write_patch(f, patch, points)
            print("%s: %d evaluation cases" % (patch["name"], n))
            total += n
    print("wrote %s: %d cases, %d derivatives each" % (OUT, total, len(derivative_order())))
    print("routes 1 and 2 identical; finite differences (orders <= 2) within %s"
          % mp.nstr(WORST_FD[0], 3))


if __name__ == "__main__":
    main()
