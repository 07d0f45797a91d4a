"""Exact symbolic NURBS pieces for the truth generators gen_nurbs_*.py.

Written for these generators, independently of intercurve's C code (which
uses de Boor's derivative algorithm on homogeneous points and the quotient
rule). Everything here is exact sympy arithmetic: knots, weights and points
are sympy numbers (Rational, or sqrt(2)/2 for the conics), and a patch is
handled one polynomial piece (one knot span pair) at a time.

Two independent constructions of the B-spline basis on a span:
  - basis_cox_de_boor: the Cox-de Boor recursion, run symbolically on the
    span [t_k, t_{k+1}) (N_{i,0} = 1 for i = k, else 0 on that span; the
    convention 0/0 = 0 for repeated knots);
  - basis_marsden: Marsden's identity (x - s)^p = sum_i psi_i(s) N_{i,p}(x),
    psi_i(s) = prod_{j=1..p} (t_{i+j} - s), solved as a linear system for the
    p+1 basis polynomials that are nonzero on the span (coefficients of s^m
    on both sides); no recursion and no division by knot differences.

Span convention: a parameter t on an interior knot belongs to the span to
its right, [t_k, t_{k+1}) (side = +1), or, when asked, to the span to its
left, (t_{k-1}, t_k] (side = -1); the last domain end t = t_n always takes
the last span (left), the first end t = t_p the first span (right).
"""
import sympy as sp

u, v = sp.symbols("u v")


def find_span(knots, p, n, t, side=+1):
    """Index k, p <= k <= n-1, of the span [knots[k], knots[k+1]] holding t:
    the span right of t when t is a knot and side = +1, left when side = -1."""
    lo, hi = knots[p], knots[n]
    if t < lo or t > hi:
        raise ValueError("parameter %s outside the domain [%s, %s]" % (t, lo, hi))
    if t == hi:
        side = -1
    if t == lo:
        side = +1
    for k in range(p, n):
        a, b = knots[k], knots[k + 1]
        if a == b:
            continue
        if side > 0 and a <= t < b:
            return k
        if side < 0 and a < t <= b:
            return k
    raise ValueError("no span for %s" % t)


def basis_cox_de_boor(knots, p, k, x):
    """The p+1 polynomials N_{k-p..k, p}(x) valid on the span k (Cox-de Boor)."""
    N = {k: sp.Integer(1)}  # degree 0: only N_{k,0} is 1 on the span
    for d in range(1, p + 1):
        new = {}
        for i in range(k - d, k + 1):
            term = sp.Integer(0)
            left = N.get(i, 0)
            den = knots[i + d] - knots[i]
            if left != 0 and den != 0:
                term += (x - knots[i]) / den * left
            right = N.get(i + 1, 0)
            den = knots[i + d + 1] - knots[i + 1]
            if right != 0 and den != 0:
                term += (knots[i + d + 1] - x) / den * right
            new[i] = sp.expand(term)
        N = new
    return [N[i] for i in range(k - p, k + 1)]


def basis_marsden(knots, p, k, x):
    """The same p+1 polynomials from Marsden's identity (a linear solve)."""
    s = sp.Symbol("s_marsden")
    idx = list(range(k - p, k + 1))
    psi = [sp.Poly(sp.prod([knots[i + j] - s for j in range(1, p + 1)]), s) for i in idx]
    A = sp.Matrix(p + 1, p + 1, lambda m, c: psi[c].coeff_monomial(s**m))
    b = sp.Matrix(p + 1, 1, lambda m, _: sp.binomial(p, m) * (-1)**m * x**(p - m))
    sol = A.LUsolve(b)
    return [sp.expand(sol[c]) for c in range(p + 1)]


def piece(patch, k, l, basis=basis_cox_de_boor):
    """Numerators X, Y, Z and denominator W (sympy Poly in u, v) of the patch
    on the span pair (k, l): R = (X, Y, Z) / W there."""
    p, q = patch["degree"]
    Nu = basis(patch["knots"][0], p, k, u)
    Nv = basis(patch["knots"][1], q, l, v)
    P, Wt = patch["points"], patch["weights"]
    num = [sp.Integer(0)] * 3
    den = sp.Integer(0)
    for a, i in enumerate(range(k - p, k + 1)):
        for b, j in enumerate(range(l - q, l + 1)):
            nw = Nu[a] * Nv[b] * Wt[i][j]
            den += nw
            for c in range(3):
                num[c] += nw * P[i][j][c]
    return [sp.Poly(sp.expand(e), u, v) for e in num], sp.Poly(sp.expand(den), u, v)


def spans(patch, uu, vv, side_u=+1, side_v=+1):
    n_u, n_v = len(patch["points"]), len(patch["points"][0])
    p, q = patch["degree"]
    return (find_span(patch["knots"][0], p, n_u, uu, side_u),
            find_span(patch["knots"][1], q, n_v, vv, side_v))


def span_list(knots, p, n):
    """Indices of the nonempty spans of the domain."""
    return [k for k in range(p, n) if knots[k] < knots[k + 1]]
