#!/usr/bin/env python3
"""Truth for a curve that crosses a C^1 knot line (issue 12): a non-rational
bicubic patch with a double knot at u = 1/2 (so only C^1 across u = 1/2)
and the plane x = c.

Writes
  tests/data/nurbs/surface-knotline.json        the patch (NURBS, exact dyadic
                                                numbers)
  tests/data/nurbs/problem-knotline-plane.json  the patch and the implicit
                                                plane "x - c"
  tests/truth/nurbs_knotline_truth.txt          the truth (format below)

The curve. On each polynomial piece (u <= 1/2 and u >= 1/2; v has one
piece) F(u, v) = x(u, v) - c is a polynomial (cubic in u and in v), and the
curve is its zero set mapped by R(u, v). The patch is built so that F_v > 0
on the whole patch (asserted from the control net: its differences along v
are all positive) with x < c on the edge v = 0 and x > c on v = 1: the
intersection is exactly one arc, the graph v = V(u) over the whole u range
[0, 1], from the edge u = 0 to the edge u = 1, and it crosses the knot line
once. The surface is C^1 across u = 1/2, so V is C^1 and the
curve's tangent is continuous there, but R_uu jumps, so the curvature does:
the truth gives it on both sides.

Formulas (derived here with sympy: F(u0 + s, V(u0 + s)) = 0 with F's Taylor
polynomial in symbolic partials F_ab and V = v0 + V1 s + V2 s^2/2; the
coefficients of s and s^2 give):
  V'  = -F_u / F_v,
  V'' = -(F_uu + 2 F_uv V' + F_vv V'^2) / F_v,
  g(u) = R(u, V(u)):  g' = R_u + R_v V',
                      g'' = R_uu + 2 R_uv V' + R_vv V'^2 + R_v V'',
  kappa = |g' x g''| / |g'|^3,
  tau = 0 (the curve lies in the plane x = c: every derivative of g has
  x component 0, so g' . (g'' x g''') = 0).
The partial derivatives are exact (sympy polynomials on the piece), the
points (u, V(u)) are roots of F(u, .) found by sympy's real_roots (exact
algebraic numbers), evaluated at 50 digits, printed with 30.

Second route (asserted): points on the curve by mpmath.findroot at 120
digits on the polynomial pieces rebuilt from the Marsden-identity basis
(nurbs_sym.py, not Cox-de Boor), and the curvature of the circle through
three curve points at u0, u0 + h, u0 + 2h (h = 1e-35 in u, on the side whose
piece the truth uses; error O(h)): agreement within 1e-25 (measured below
1e-33). The length is tanh-sinh quadrature of |g'(u)| over each piece,
checked against Gauss-Legendre quadrature (agreement within 1e-30 asserted).

File format (tests/truth/nurbs_knotline_truth.txt; one item a line, fields
separated by single spaces, '#' lines are comments, 30 significant digits):
  problem problem-knotline-plane.json
  plane c                           the plane is x = c (exact decimal)
  knot 0.5                          the C^1 knot line u = 1/2
  curves 1
  length 0 L                        the whole arc, edge u = 0 to edge u = 1
  end_point u v x y z               its two ends (u = 0 and u = 1)
  crossing u v x y z tx ty tz       where it crosses u = 1/2, unit tangent
                                    oriented towards increasing u
  kappa_at u v x y z side kappa     curvature at the curve point (u, v); side
                                    -1: from the piece u <= 1/2, +1: from the
                                    piece u >= 1/2 (at the crossing both are
                                    given; they differ)
  tau 0 0                           torsion 0 along the curve
  end

Run:  python3 tests/truth/gen_nurbs_knotline.py   (about four minutes)
"""
import os
import sys

import mpmath as mp
import sympy as sp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nurbs_sym as ns  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "nurbs")
TRUTH = os.path.join(HERE, "nurbs_knotline_truth.txt")
DIGITS = 30
R = sp.Rational
u, v = ns.u, ns.v
KNOT = R(1, 2)
PLANE_C = R(3, 4)
STEP = mp.mpf("1e-35")       # parameter units, for the three-point circles
AGREE = mp.mpf("1e-25")      # relative agreement of the two curvature routes
QUAD_DEGREE = 10             # mpmath's default (6) leaves Gauss-Legendre at 1e-17 here
SAMPLES_U = [R(1, 8), R(1, 4), R(3, 8), R(15, 32), R(17, 32), R(5, 8), R(3, 4), R(7, 8)]

A_U = [R(0), R(1, 16), R(3, 16), R(5, 16), R(7, 16), R(1, 2)]
B_V = [R(0), R(5, 16), R(11, 16), R(1)]
Z_U = [R(0), R(1, 8), R(0), R(1, 4), R(1, 8), R(3, 8)]
Z_V = [R(0), R(1, 4), R(1, 8), R(-1, 8)]
PATCH = {
    "name": "knotline", "degree": (3, 3),
    "knots": [[R(t) for t in (0, 0, 0, 0, KNOT, KNOT, 1, 1, 1, 1)],
              [R(t) for t in (0, 0, 0, 0, 1, 1, 1, 1)]],
    "points": [[[A_U[i] + B_V[j] + R((i * j) % 3 - 1, 32),
                 R(j, 2) + R(i, 16),
                 Z_U[i] + Z_V[j] + R((i * j) % 2, 16)] for j in range(4)] for i in range(6)],
    "weights": [[R(1)] * 4 for _ in range(6)],
    "periodic": [False, False],
}


def pieces(basis):
    """(X, Y, Z) polynomials on the left (u <= 1/2) and right pieces."""
    out = {}
    for side, k in ((-1, 3), (+1, 5)):
        num, den = ns.piece(PATCH, k, 3, basis)
        assert den.as_expr() == 1  # non-rational
        out[side] = [e.as_expr() for e in num]
    return out


FSYM = {(a, b): sp.Symbol("F%d%d" % (a, b)) for a in range(3) for b in range(3) if a + b <= 2}


def implicit_formulas():
    """V'(u0), V''(u0) from F(u0 + s, V(u0 + s)) = 0, derived symbolically:
    F as its Taylor polynomial with symbolic partials F_ab, V(u0 + s) =
    v0 + V1 s + V2 s^2 / 2; the coefficients of s and s^2 must vanish."""
    s_, V1, V2 = sp.symbols("s V1 V2")
    dv = V1 * s_ + V2 * s_**2 / 2
    taylor = sum(FSYM[(a, b)] * s_**a * dv**b / (sp.factorial(a) * sp.factorial(b))
                 for (a, b) in FSYM if a + b > 0)
    ser = sp.Poly(sp.expand(taylor), s_)
    v1 = sp.solve(ser.coeff_monomial(s_), V1)[0]
    v2 = sp.solve(ser.coeff_monomial(s_**2).subs(V1, v1), V2)[0]
    return sp.simplify(v1), sp.simplify(v2)


def curvature_exact(P, uu, vv, forms):
    """kappa and unit tangent at (uu, vv) on the piece P (exact polynomials)."""
    Vp_f, Vpp_f = forms
    F = P[0] - PLANE_C
    vals = {}
    for a in range(3):
        for b in range(3 - a):
            vals[(a, b)] = sp.diff(F, u, a, v, b).subs({u: uu, v: vv})
    num = {FSYM[ab]: vals[ab] for ab in FSYM}
    Vp, Vpp = Vp_f.subs(num), Vpp_f.subs(num)
    Ru = sp.Matrix([sp.diff(c, u) for c in P]).subs({u: uu, v: vv})
    Rv = sp.Matrix([sp.diff(c, v) for c in P]).subs({u: uu, v: vv})
    Ruu = sp.Matrix([sp.diff(c, u, 2) for c in P]).subs({u: uu, v: vv})
    Ruv = sp.Matrix([sp.diff(c, u, v) for c in P]).subs({u: uu, v: vv})
    Rvv = sp.Matrix([sp.diff(c, v, 2) for c in P]).subs({u: uu, v: vv})
    g1 = Ru + Rv * Vp
    g2 = Ruu + 2 * Ruv * Vp + Rvv * Vp**2 + Rv * Vpp
    cr = g1.cross(g2)
    n1 = sp.sqrt(g1.dot(g1))
    return sp.sqrt(cr.dot(cr)) / n1**3, g1 / n1, vals


def root_v(P, uu):
    """The root v in [0, 1] of x(uu, v) = c (exact algebraic; it is unique)."""
    poly = sp.Poly(sp.expand(P[0].subs(u, uu) - PLANE_C), v)
    roots = [r for r in sp.real_roots(poly) if 0 <= r <= 1]
    assert len(roots) == 1, (uu, roots)
    return roots[0]


def circle_curvature(P_mp, u0, v0, side):
    """Curvature of the circle through three curve points (second route)."""
    with mp.workdps(120):
        pts = []
        vv = v0
        for m in range(3):
            uu = u0 + side * m * STEP
            vv = mp.findroot(lambda t: P_mp[0](uu, t) - mp.mpf(PLANE_C.p) / PLANE_C.q, vv)
            pts.append(mp.matrix([P_mp[c](uu, vv) for c in range(3)]))
        a = mp.norm(pts[1] - pts[0])
        b = mp.norm(pts[2] - pts[1])
        c = mp.norm(pts[2] - pts[0])
        e1, e2 = pts[1] - pts[0], pts[2] - pts[0]
        cross = mp.matrix([e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                           e1[0] * e2[1] - e1[1] * e2[0]])
        return 2 * mp.norm(cross) / (a * b * c)


def mp_piece(expr):
    f = sp.lambdify((u, v), expr, "mpmath")
    return lambda a, b: f(a, b)


def length(P_by_side):
    """Arc length over both pieces: tanh-sinh, checked by Gauss-Legendre."""
    c = mp.mpf(PLANE_C.p) / PLANE_C.q
    total = {}
    for method in ("tanh-sinh", "gauss-legendre"):
        acc = mp.mpf(0)
        for side, (lo, hi) in ((-1, (0, mp.mpf(1) / 2)), (+1, (mp.mpf(1) / 2, 1))):
            P = P_by_side[side]
            X, Xu, Xv = [mp_piece(e) for e in (P[0], sp.diff(P[0], u), sp.diff(P[0], v))]
            Gu = [mp_piece(sp.diff(e, u)) for e in P]
            Gv = [mp_piece(sp.diff(e, v)) for e in P]
            state = {"v": mp.mpf(1) / 2}

            def speed(t):
                vv = mp.findroot(lambda s: X(t, s) - c, state["v"])
                state["v"] = vv
                vp = -Xu(t, vv) / Xv(t, vv)
                return mp.sqrt(sum((Gu[k](t, vv) + Gv[k](t, vv) * vp)**2 for k in range(3)))
            acc += mp.quad(speed, [lo, hi], method=method, maxdegree=QUAD_DEGREE)
        total[method] = acc
    assert abs(total["tanh-sinh"] - total["gauss-legendre"]) < mp.mpf("1e-30"), total
    return total["tanh-sinh"]


def fmt(e):
    val = sp.N(e, DIGITS + 15)
    if val == 0:
        return "0"
    return mp.nstr(mp.mpf(str(val)), DIGITS, min_fixed=-4, max_fixed=6)


def exact(q):
    s = mp.nstr(mp.mpf(sp.Rational(q).p) / sp.Rational(q).q, 40)
    assert sp.Rational(s) == q
    return s


def write_json():
    sys.path.insert(0, HERE)
    from gen_nurbs_quadrics import dump
    surf = {"name": "knotline", "type": "nurbs", "degree": list(PATCH["degree"]),
            "knots": [[float(t) for t in ks] for ks in PATCH["knots"]],
            "control_points": [[[float(c) for c in P] for P in row] for row in PATCH["points"]],
            "weights": [[1.0] * 4 for _ in range(6)], "periodic": [False, False]}
    for row in PATCH["points"]:
        for P in row:
            assert all(sp.Rational(float(c)) == c for c in P)  # exact doubles
    dump(surf, os.path.join(DATA, "surface-knotline.json"))
    prob = {"title": "Bicubic NURBS with a C^1 knot line at u = 0.5 and the plane x = 0.75",
            "surfaces": [surf, {"name": "plane", "type": "implicit", "f": "x - 0.75"}],
            "box": [[0.5, 1.0], [-0.5, 2.5], [-1.0, 1.0]]}
    dump(prob, os.path.join(DATA, "problem-knotline-plane.json"))


def check_single_arc():
    """x increases strictly in v over the whole patch (every difference of the
    x control net along j is positive, so x_v > 0 by the convex hull
    property), x < c on the edge v = 0 and x > c on v = 1 (control nets of
    those edges): the plane meets the patch in exactly one arc, a graph
    v = V(u) over the whole of [0, 1]."""
    X = [[P[0] for P in row] for row in PATCH["points"]]
    assert all(row[j + 1] > row[j] for row in X for j in range(3))
    assert max(row[0] for row in X) < PLANE_C < min(row[3] for row in X)


def main():
    mp.mp.dps = 50
    check_single_arc()
    P1 = pieces(ns.basis_cox_de_boor)
    P2 = pieces(ns.basis_marsden)
    for side in (-1, 1):
        assert all(sp.expand(a - b) == 0 for a, b in zip(P1[side], P2[side]))
    # C^1 but not C^2 across the knot line
    for c in range(3):
        for a in range(2):
            gap = (sp.diff(P1[-1][c], u, a) - sp.diff(P1[1][c], u, a)).subs(u, KNOT)
            assert sp.expand(gap) == 0
    jump = [sp.expand((sp.diff(P1[-1][c], u, 2) - sp.diff(P1[1][c], u, 2)).subs(u, KNOT))
            for c in range(3)]
    assert any(j != 0 for j in jump)
    forms = implicit_formulas()
    print("V' =", forms[0], "\nV'' =", forms[1])
    mpP = {s: [mp_piece(e) for e in P2[s]] for s in (-1, 1)}
    lines = ["# generated by gen_nurbs_knotline.py; do not edit (derivation in its header)",
             "problem problem-knotline-plane.json", "plane %s" % exact(PLANE_C), "knot 0.5",
             "curves 1"]
    L = length(P1)
    lines.append("length 0 %s" % mp.nstr(L, DIGITS))
    for uu, side in ((R(0), -1), (R(1), 1)):
        vv = root_v(P1[side], uu)
        lines.append("end_point %s %s %s" % (fmt(uu), fmt(vv),
                                             " ".join(fmt(e.subs({u: uu, v: vv}))
                                                      for e in P1[side])))
    worst = mp.mpf(0)
    cases = [(uu, -1 if uu < KNOT else 1) for uu in SAMPLES_U] + [(KNOT, -1), (KNOT, 1)]
    cases.sort(key=lambda c: (c[0], c[1]))
    for uu, side in cases:
        P = P1[side]
        vv = root_v(P, uu)
        Fv = sp.diff(P[0], v).subs({u: uu, v: vv})
        assert sp.N(Fv) > 0.1, (uu, Fv)  # the curve is a graph over u
        kappa, tangent, _ = curvature_exact(P, uu, vv, forms)
        k2 = circle_curvature(mpP[side], mp.mpf(uu.p) / uu.q, mp.mpf(str(sp.N(vv, 60))), side)
        k1 = mp.mpf(str(sp.N(kappa, 60)))
        worst = max(worst, abs(k1 - k2) / k1)
        assert abs(k1 - k2) < AGREE * k1, (uu, side, k1, k2)
        xyz = " ".join(fmt(e.subs({u: uu, v: vv})) for e in P)
        if uu == KNOT and side == -1:
            lines.append("crossing %s %s %s %s" % (fmt(uu), fmt(vv), xyz,
                                                   " ".join(fmt(t) for t in tangent)))
        lines.append("kappa_at %s %s %s %d %s" % (fmt(uu), fmt(vv), xyz, side, fmt(kappa)))
        print("u = %s side %+d: kappa %s (circle route differs by %s)"
              % (uu, side, fmt(kappa), mp.nstr(abs(k1 - k2), 3)))
    lines += ["tau 0 0", "end"]
    with open(TRUTH, "w") as f:
        f.write("\n".join(lines) + "\n")
    write_json()
    print("length %s; worst relative curvature difference %s" % (mp.nstr(L, 35),
                                                                   mp.nstr(worst, 3)))


if __name__ == "__main__":
    main()
