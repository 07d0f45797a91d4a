#!/usr/bin/env python3
"""Exact rational NURBS forms of a sphere, a cylinder, a cone and a torus,
their implicit forms, intersection problems between them with closed-form
truth (issue 12).

Writes
  tests/data/nurbs/surface-NAME.json     one surface object each (a problem
                                         file fragment): the NURBS forms and
                                         the matching implicit formulas
  tests/data/nurbs/problem-NAME.json     problem files ("surfaces": [A, B],
                                         "box"), the NURBS surface inlined
  tests/truth/nurbs_quadrics_truth.txt   the closed-form truth (format below)

The NURBS forms (Piegl and Tiller, The NURBS Book, 2nd ed., sections 7.5 and
8.5): the full circle is the 9-point rational quadratic with knots
{0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}, control points on the square
(1,0),(1,1),(0,1),(-1,1),(-1,0),(-1,-1),(0,-1),(1,-1),(1,0) and weights
1, s, 1, s, ... with s = sqrt(2)/2; a semicircle is the 5-point quadratic
(0,-1),(1,-1),(1,0),(1,1),(0,1), knots {0,0,0,1/2,1/2,1,1,1}, weights
1, s, 1, s, 1. A surface of revolution about the unit axis a through c with
the profile (rho_j, h_j, w_j) in v is the tensor product
  P_ij = c + rho_j (cx_i e1 + cy_i e2) + h_j a,   w_ij = wc_i w_j,
with (e1, e2, a) a right-handed orthonormal frame (axis z: e1 = x, e2 = y;
axis x: e1 = y, e2 = z; axis y: e1 = z, e2 = x). u runs along the circle
(control_points[i] is the i-th point of the circle), v along the profile.
  - sphere: profile = semicircle of radius r (rho = r cx, h = r cy);
  - cylinder: profile = the segment rho = 1, h from -2 to 2 (degree 1);
  - cone: profile = the segment from (rho, h) = (0.1, 0.2) to (1, 2): the
    half-angle atan(1/2), apex at the origin, v from h = 0.2 to 2;
  - torus: profile = full circle of radius r = 0.5 about rho = R = 2,
    started at its inner point: rho = 2 - 0.5 cx, h = -0.5 cy, so v = 0 is
    the inner equator and v = 1/2 the outer equator.
Every full circle closes with matching tangents (C^1 across u = 0 = 1), so
the closed directions are written "periodic": true (sphere and cylinder and
cone along u, torus along both); flip them to false for a test of open patches.

Verified here with sympy, exactly: on every span pair, the rational
parametrisation X/W, Y/W, Z/W substituted into the implicit equation
(multiplied by W^2, W^4 for the torus) expands to the zero polynomial, with
s = sqrt(2)/2 kept symbolic (the script asserts it: all 8 pieces of each
sphere, 4 of the cylinder and the cone, 16 of the torus). It also checks
exactly where the landmarks named below are: the torus's v = 1/2 is its outer
equator, v = 0 its inner one; the contact point is at (u, v) = (3/4, 1/2)
of the axis-x sphere; Viviani's branch point (1, 0, 0) is at (0, 1/2) on the
axis-z unit sphere and at (1/4, 1/2) on the axis-y one; the axis-z sphere's
edge v = 0 is its south pole.

The JSON holds the doubles nearest to the exact values, each written as
Python's repr (at most 17 significant digits, the shortest text that reads
back to the same double: 0.7071067811865476 for sqrt(2)/2, 0.5 for its
square), so the C forms lie on the quadrics to rounding (about 1e-16).
Surface fragments: surface-NAME.json (NURBS) and surface-NAME-implicit.json
(the same quadric as {"type": "implicit", "f": ...}), NAME one of sphere
(axis z), sphere-axis-x, unit-sphere (axis z), unit-sphere-axis-y, cylinder,
cone, torus. Problems: problem-NAME.json, NAME one of the cases below (the
NURBS surface first, the implicit one second).

Closed-form truth (derivations):
  sphere-plane-circle: sphere |p - c| = 1.5, c = (0.2, -0.1, 0.3), and the
    plane z = 0.8 = c_z + 0.5: a circle of centre (0.2, -0.1, 0.8) and
    radius rho = sqrt(1.5^2 - 0.5^2) = sqrt(2): length 2 pi sqrt(2),
    kappa = 1/sqrt(2), tau = 0 (plane curve). It stays off the poles
    (z = -1.2, 1.8) and off the equator knot line v = 1/2 (z = 0.3).
  cylinder-sphere: x^2 + y^2 = 1 and x^2 + y^2 + z^2 = 4 give z^2 = 3: two
    unit circles at z = +-sqrt(3), each of length 2 pi, kappa = 1, tau = 0;
    |z| = 1.732 < 2 lies inside the NURBS cylinder's height range.
  cone-plane-circle: x^2 + y^2 = z^2/4 and z = 1: a circle of radius 1/2,
    length pi, kappa = 2, tau = 0.
  viviani: x^2 + y^2 + z^2 = 1 and (x - 1/2)^2 + y^2 = 1/4 are met by
    c(t) = (cos^2 t, cos t sin t, sin t), t in [0, 2 pi) (substitute: 1 and
    1/4 exactly), once each. |c'(t)|^2 = sin^2 2t + cos^2 2t + cos^2 t =
    1 + cos^2 t = 2 (1 - sin^2(t)/2), so the total length is
    int_0^{2 pi} sqrt(1 + cos^2 t) dt = 4 sqrt(2) E(m = 1/2) (complete
    elliptic integral of the second kind, parameter m = k^2), computed with
    mpmath.ellipe at 50 digits and checked by mpmath.quad of the integrand.
    The curve crosses itself at (1, 0, 0) (t = 0 and t = pi), where the two
    surfaces are tangent (normals (1, 0, 0) on both): a branch point with
    unit tangents (0, 1, 1)/sqrt(2) and (0, 1, -1)/sqrt(2). kappa and tau at
    chosen points come from the exact formulas kappa = |c' x c''| / |c'|^3,
    tau = (c' x c'') . c''' / |c' x c''|^2 on c(t) (sympy, simplified, then
    evaluated at 30 digits), checked against the literature's closed forms
    kappa = sqrt(13 + 3 cos s) / (h (3 + cos s)^(3/2)), tau = 6 cos(s/2) /
    (h (13 + 3 cos s)) on (h (1 + cos s), h sin s, 2 h sin(s/2)), h = 1/2,
    s = 2t (to 1e-45). Two NURBS spheres: axis z (the usual CAD form:
    the curve passes through both poles (0, 0, +-1), degenerate points of
    the parametrisation, and the branch point is on the seam u = 0 and the
    knot line v = 1/2) and axis y (the curve, |y| <= 1/2, keeps off the
    poles (0, +-1, 0); the branch point is on the knot lines u = 1/4,
    v = 1/2).
  torus-sphere-tangential: the torus (R = 2, r = 0.5, axis z) and the
    sphere x^2 + y^2 + z^2 = 2.5^2: a torus point at profile angle phi is at
    distance^2 (2 + 0.5 cos phi)^2 + 0.25 sin^2 phi = 4.25 + 2 cos phi from
    the origin, at most 6.25, only at phi = 0: the surfaces touch along the
    outer equator (radius 2.5, z = 0; normals both radial) and meet nowhere
    else. Length 5 pi, kappa = 1/2.5 = 0.4, tau = 0; the circle is the torus's
    knot line v = 1/2.
  sphere-plane-contact: the sphere of the first problem and the plane
    z = -1.2 = c_z - 1.5: the single point (0.2, -0.1, -1.2), an isolated
    contact point (normal curvatures 1/1.5 and 0). With the sphere's axis
    z it is the south pole (a degenerate point of the parametrisation:
    the edge v = 0 maps to it); the variant with axis x puts it at a regular
    point on the knot lines u = 3/4, v = 1/2.

Truth file format (tests/truth/nurbs_quadrics_truth.txt; one item a line,
fields separated by single spaces, '#' lines are comments, numbers with 30
significant digits):
  problem FILE                  a problem file of tests/data/nurbs/
  curves N                      the number of intersection curves (0 when only
                                points); a figure-eight counts as 1
  length I L                    curve I (0-based, any order) has length L
  closed I 0|1
  tangential I 0|1              the surfaces touch all along curve I
  kappa I K                     constant curvature of curve I
  tau I T                       constant torsion of curve I
  centre I x y z                curve I is a circle of this centre
  total_length L                the sum of all curves' lengths
  point KIND x y z              an isolated contact point (KIND contact) or a
                                branch point (KIND branch)
  at x y z tx ty tz kappa tau   at the curve point (x, y, z), on the branch
                                with unit tangent +-(tx, ty, tz): kappa, tau
  end

Run:  python3 tests/truth/gen_nurbs_quadrics.py   (about two minutes)
"""
import json
import os
import sys

import mpmath as mp
import sympy as sp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nurbs_sym as ns  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "nurbs")
TRUTH = os.path.join(HERE, "nurbs_quadrics_truth.txt")
DIGITS = 30
mp.mp.dps = 50
R = sp.Rational
S = sp.sqrt(2) / 2
x, y, z = sp.symbols("x y z")

CIRCLE_KNOTS = [0, 0, 0, R(1, 4), R(1, 4), R(1, 2), R(1, 2), R(3, 4), R(3, 4), 1, 1, 1]
CIRCLE = [(1, 0, 1), (1, 1, S), (0, 1, 1), (-1, 1, S), (-1, 0, 1), (-1, -1, S), (0, -1, 1),
          (1, -1, S), (1, 0, 1)]
SEMI_KNOTS = [0, 0, 0, R(1, 2), R(1, 2), 1, 1, 1]
SEMI = [(0, -1, 1), (1, -1, S), (1, 0, 1), (1, 1, S), (0, 1, 1)]
FRAMES = {"z": ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
          "x": ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
          "y": ((0, 0, 1), (1, 0, 0), (0, 1, 0))}


def revolve(name, profile, profile_knots, q, centre, axis, periodic_v=False):
    """Tensor product of the full circle (u) and a profile (rho, h, w) in v."""
    e1, e2, a = FRAMES[axis]
    pts, wts = [], []
    for cx, cy, wc in CIRCLE:
        row, wrow = [], []
        for rho, h, wp in profile:
            row.append([sp.nsimplify(centre[k]) + rho * (cx * e1[k] + cy * e2[k]) + h * a[k]
                        for k in range(3)])
            wrow.append(wc * wp)
        pts.append(row)
        wts.append(wrow)
    return {"name": name, "degree": (2, q), "knots": [[R(t) for t in CIRCLE_KNOTS],
                                                      [R(t) for t in profile_knots]],
            "points": pts, "weights": wts, "periodic": [True, periodic_v]}


def sphere(name, centre, r, axis):
    r = sp.nsimplify(r)
    return revolve(name, [(r * cx, r * cy, w) for cx, cy, w in SEMI], SEMI_KNOTS, 2, centre, axis)


def implicit_sphere(centre, r):
    c = [sp.nsimplify(t) for t in centre]
    return (x - c[0])**2 + (y - c[1])**2 + (z - c[2])**2 - sp.nsimplify(r)**2


SPHERE_C, SPHERE_R = (R(1, 5), R(-1, 10), R(3, 10)), R(3, 2)
SURFACES = {
    "sphere": (sphere("sphere", SPHERE_C, SPHERE_R, "z"), implicit_sphere(SPHERE_C, SPHERE_R),
               "(x - 0.2)^2 + (y + 0.1)^2 + (z - 0.3)^2 - 2.25"),
    "sphere-axis-x": (sphere("sphere", SPHERE_C, SPHERE_R, "x"),
                      implicit_sphere(SPHERE_C, SPHERE_R),
                      "(x - 0.2)^2 + (y + 0.1)^2 + (z - 0.3)^2 - 2.25"),
    "unit-sphere": (sphere("sphere", (0, 0, 0), 1, "z"), implicit_sphere((0, 0, 0), 1),
                    "x^2 + y^2 + z^2 - 1"),
    "unit-sphere-axis-y": (sphere("sphere", (0, 0, 0), 1, "y"), implicit_sphere((0, 0, 0), 1),
                           "x^2 + y^2 + z^2 - 1"),
    "cylinder": (revolve("cylinder", [(1, -2, 1), (1, 2, 1)], [0, 0, 1, 1], 1, (0, 0, 0), "z"),
                 x**2 + y**2 - 1, "x^2 + y^2 - 1"),
    "cone": (revolve("cone", [(R(1, 10), R(1, 5), 1), (1, 2, 1)], [0, 0, 1, 1], 1, (0, 0, 0),
                     "z"),
             x**2 + y**2 - z**2 / 4, "x^2 + y^2 - z^2/4"),
    "torus": (revolve("torus", [(2 - R(1, 2) * cx, -R(1, 2) * cy, w) for cx, cy, w in CIRCLE],
                      CIRCLE_KNOTS, 2, (0, 0, 0), "z", periodic_v=True),
              (x**2 + y**2 + z**2 + R(15, 4))**2 - 16 * (x**2 + y**2),
              "(x^2 + y^2 + z^2 + 3.75)^2 - 16*(x^2 + y^2)"),
}


def check_on_quadric(patch, F):
    """Every polynomial piece satisfies F = 0 identically (exact)."""
    deg = sp.Poly(F, x, y, z).total_degree()
    w = sp.Symbol("w")  # F homogenised: w^deg F(x/w, y/w, z/w), a polynomial
    Fh = sp.expand(sp.cancel(F.subs({x: x / w, y: y / w, z: z / w}, simultaneous=True) * w**deg))
    n_u, n_v = len(patch["points"]), len(patch["points"][0])
    pieces = 0
    for k in ns.span_list(patch["knots"][0], patch["degree"][0], n_u):
        for l in ns.span_list(patch["knots"][1], patch["degree"][1], n_v):
            num, den = ns.piece(patch, k, l)
            X, Y, Z, W = [e.as_expr() for e in num] + [den.as_expr()]
            hom = sp.expand(Fh.subs({x: X, y: Y, z: Z, w: W}, simultaneous=True))
            assert hom == 0, (patch["name"], k, l)
            pieces += 1
    return pieces


def dbl(e):
    return float(sp.N(e, 40))


def nurbs_json(patch):
    return {"name": patch["name"], "type": "nurbs", "degree": list(patch["degree"]),
            "knots": [[dbl(t) for t in ks] for ks in patch["knots"]],
            "control_points": [[[dbl(c) for c in P] for P in row] for row in patch["points"]],
            "weights": [[dbl(w) for w in row] for row in patch["weights"]],
            "periodic": list(patch["periodic"])}


def dump(obj, path):
    """JSON with one control-point or weight row per line (repr of each double)."""
    def line(o):
        if isinstance(o, list):
            return "[" + ", ".join(line(r) for r in o) + "]"
        return repr(o) if isinstance(o, float) else json.dumps(o)

    def rows(o, pad):
        return "[\n" + ",\n".join(pad + "  " + line(r) for r in o) + "\n" + pad + "]"

    def enc(o, indent):
        pad = " " * indent
        if isinstance(o, dict):
            items = ['%s  "%s": %s' % (pad, k, enc(v, indent + 2)) for k, v in o.items()]
            return "{\n" + ",\n".join(items) + "\n" + pad + "}"
        if isinstance(o, list) and o and isinstance(o[0], dict):
            return ("[\n" + ",\n".join(pad + "  " + enc(r, indent + 2) for r in o) + "\n" + pad
                    + "]")
        if isinstance(o, list) and o and isinstance(o[0], list) and len(o) > 2:
            return rows(o, pad)
        return line(o)
    text = enc(obj, 0) + "\n"
    json.loads(text)  # well-formed
    with open(path, "w") as f:
        f.write(text)


def implicit_json(name, formula):
    return {"name": name, "type": "implicit", "f": formula}


def fmt(e):
    v = sp.N(e, DIGITS + 10)
    if v == 0:
        return "0"
    return mp.nstr(mp.mpf(str(v)), DIGITS, min_fixed=-4, max_fixed=6)


def viviani_truth():
    """Length and kappa, tau at chosen points of c(t) = (cos^2 t, cos t sin t, sin t)."""
    t = sp.Symbol("t", real=True)
    c = sp.Matrix([sp.cos(t)**2, sp.cos(t) * sp.sin(t), sp.sin(t)])
    assert sp.simplify(c.dot(c) - 1) == 0
    assert sp.simplify((c[0] - R(1, 2))**2 + c[1]**2 - R(1, 4)) == 0
    d1, d2, d3 = c.diff(t), c.diff(t, 2), c.diff(t, 3)
    assert sp.simplify(d1.dot(d1) - (1 + sp.cos(t)**2)) == 0
    length = 4 * mp.sqrt(2) * mp.ellipe(mp.mpf(1) / 2)
    quad = mp.quad(lambda s: mp.sqrt(1 + mp.cos(s)**2), [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2,
                                                           2 * mp.pi])
    assert abs(length - quad) < mp.mpf("1e-40"), (length, quad)
    rows = []
    for t0 in (0, sp.pi, sp.pi / 4, sp.pi / 2, sp.pi / 3):
        a, b, cc = [m.subs(t, t0) for m in (d1, d2, d3)]
        cr = a.cross(b)
        kappa = sp.sqrt(sp.simplify(cr.dot(cr))) / sp.sqrt(sp.simplify(a.dot(a)))**3
        tau = sp.simplify(cr.dot(cc) / cr.dot(cr))
        tangent = a / sp.sqrt(a.dot(a))
        # the literature's closed forms on (h(1 + cos s), h sin s, 2h sin(s/2)), h = 1/2,
        # which is c(t) with s = 2t: kappa = sqrt(13 + 3 cos s) / (h (3 + cos s)^(3/2)),
        # tau = 6 cos(s/2) / (h (13 + 3 cos s))
        s0, h = 2 * t0, R(1, 2)
        k_lit = sp.sqrt(13 + 3 * sp.cos(s0)) / (h * (3 + sp.cos(s0))**R(3, 2))
        t_lit = 6 * sp.cos(s0 / 2) / (h * (13 + 3 * sp.cos(s0)))
        assert abs(sp.N(kappa - k_lit, 50)) < 1e-45 and abs(sp.N(tau - t_lit, 50)) < 1e-45
        rows.append(([sp.simplify(e) for e in c.subs(t, t0)], [sp.simplify(e) for e in tangent],
                     sp.simplify(kappa), tau))
    return length, rows


def point_at(patch, uu, vv):
    k, l = ns.spans(patch, uu, vv)
    num, den = ns.piece(patch, k, l)
    w = den.eval({ns.u: uu, ns.v: vv})
    return [sp.nsimplify(sp.simplify(c.eval({ns.u: uu, ns.v: vv}) / w)) for c in num]


def check_landmarks():
    """The parameter places the truth file's comments name (exact)."""
    S_ = SURFACES
    assert point_at(S_["sphere-axis-x"][0], R(3, 4), R(1, 2)) == [R(1, 5), R(-1, 10), R(-6, 5)]
    assert point_at(S_["sphere"][0], R(1, 3), 0) == [R(1, 5), R(-1, 10), R(-6, 5)]
    assert point_at(S_["unit-sphere"][0], 0, R(1, 2)) == [1, 0, 0]
    assert point_at(S_["unit-sphere-axis-y"][0], R(1, 4), R(1, 2)) == [1, 0, 0]
    for uu in (0, R(1, 7), R(1, 3), R(5, 8)):
        P = point_at(S_["torus"][0], uu, R(1, 2))
        assert sp.simplify(P[0]**2 + P[1]**2 - R(25, 4)) == 0 and P[2] == 0
        P = point_at(S_["torus"][0], uu, 0)
        assert sp.simplify(P[0]**2 + P[1]**2 - R(9, 4)) == 0 and P[2] == 0


def problem(title, A, B, box):
    return {"title": title, "surfaces": [A, B], "box": box}


def main():
    os.makedirs(DATA, exist_ok=True)
    for key, (patch, F, formula) in SURFACES.items():
        n = check_on_quadric(patch, F)
        assert sp.expand(sp.nsimplify(sp.sympify(formula.replace("^", "**")), rational=True)
                         - F) == 0, key
        print("%s: %d pieces on the quadric (exact)" % (key, n))
        dump(nurbs_json(patch), os.path.join(DATA, "surface-%s.json" % key))
        dump(implicit_json(patch["name"], formula),
             os.path.join(DATA, "surface-%s-implicit.json" % key))

    check_landmarks()
    N = {k: nurbs_json(v[0]) for k, v in SURFACES.items()}
    sphere_box = [[-1.4, 1.8], [-1.7, 1.5], [-1.3, 1.9]]
    unit_box = [[-1.25, 1.25], [-1.25, 1.25], [-1.25, 1.25]]
    problems = {
        "sphere-plane-circle": problem(
            "NURBS sphere (centre (0.2, -0.1, 0.3), radius 1.5) and the plane z = 0.8: a circle",
            N["sphere"], implicit_json("plane", "z - 0.8"), sphere_box),
        "cylinder-sphere": problem(
            "NURBS cylinder (radius 1, axis z, |z| <= 2) and the sphere of radius 2: two circles",
            N["cylinder"], implicit_json("sphere", "x^2 + y^2 + z^2 - 4"),
            [[-2.5, 2.5], [-2.5, 2.5], [-2.5, 2.5]]),
        "cone-plane-circle": problem(
            "NURBS cone (apex 0, half-angle atan(1/2), 0.2 <= z <= 2) and the plane z = 1",
            N["cone"], implicit_json("plane", "z - 1"), [[-1.5, 1.5], [-1.5, 1.5], [0, 2.5]]),
        "viviani": problem(
            "Viviani: NURBS unit sphere (axis z, poles on the curve) and the cylinder "
            "(x - 0.5)^2 + y^2 = 0.25",
            N["unit-sphere"], implicit_json("cylinder", "(x - 0.5)^2 + y^2 - 0.25"), unit_box),
        "viviani-axis-y": problem(
            "Viviani: NURBS unit sphere (axis y, poles off the curve) and the cylinder "
            "(x - 0.5)^2 + y^2 = 0.25",
            N["unit-sphere-axis-y"], implicit_json("cylinder", "(x - 0.5)^2 + y^2 - 0.25"),
            unit_box),
        "torus-sphere-tangential": problem(
            "NURBS torus (R = 2, r = 0.5) and the sphere of radius 2.5 touching it along its "
            "outer equator",
            N["torus"], implicit_json("sphere", "x^2 + y^2 + z^2 - 6.25"),
            [[-3, 3], [-3, 3], [-1, 1]]),
        "sphere-plane-contact": problem(
            "NURBS sphere (axis z) resting on the plane z = -1.2: contact at its south pole",
            N["sphere"], implicit_json("plane", "z + 1.2"), sphere_box),
        "sphere-plane-contact-axis-x": problem(
            "NURBS sphere (axis x) resting on the plane z = -1.2: contact at a regular point",
            N["sphere-axis-x"], implicit_json("plane", "z + 1.2"), sphere_box),
    }
    for key, prob in problems.items():
        dump(prob, os.path.join(DATA, "problem-%s.json" % key))

    pi, r2 = sp.pi, sp.sqrt(2)
    length, rows = viviani_truth()
    lines = ["# generated by gen_nurbs_quadrics.py; do not edit. Closed forms derived in",
             "# the script's header; the NURBS forms are verified exactly on their quadrics."]

    def circle(i, L, kappa, centre, tangential=0):
        return ["length %d %s" % (i, fmt(L)), "closed %d 1" % i,
                "tangential %d %d" % (i, tangential), "kappa %d %s" % (i, fmt(kappa)),
                "tau %d 0" % i, "centre %d %s" % (i, " ".join(fmt(c) for c in centre))]
    lines += ["problem problem-sphere-plane-circle.json", "curves 1"]
    lines += circle(0, 2 * pi * r2, 1 / r2, (R(1, 5), R(-1, 10), R(4, 5)))
    lines += ["total_length %s" % fmt(2 * pi * r2), "end"]
    lines += ["problem problem-cylinder-sphere.json", "curves 2"]
    lines += circle(0, 2 * pi, 1, (0, 0, sp.sqrt(3))) + circle(1, 2 * pi, 1, (0, 0, -sp.sqrt(3)))
    lines += ["total_length %s" % fmt(4 * pi), "end"]
    lines += ["problem problem-cone-plane-circle.json", "curves 1"]
    lines += circle(0, pi, 2, (0, 0, 1)) + ["total_length %s" % fmt(pi), "end"]
    for name in ("problem-viviani.json", "problem-viviani-axis-y.json"):
        lines += ["problem %s" % name, "curves 1", "length 0 %s" % mp.nstr(length, DIGITS),
                  "closed 0 1", "tangential 0 0", "total_length %s" % mp.nstr(length, DIGITS),
                  "point branch 1 0 0"]
        for P, T, kappa, tau in rows:
            lines.append("at %s %s %s %s" % (" ".join(fmt(c) for c in P),
                                             " ".join(fmt(c) for c in T), fmt(kappa), fmt(tau)))
        lines.append("end")
    lines += ["problem problem-torus-sphere-tangential.json", "curves 1"]
    lines += circle(0, 5 * pi, R(2, 5), (0, 0, 0), tangential=1)
    lines += ["total_length %s" % fmt(5 * pi), "end"]
    for name in ("problem-sphere-plane-contact.json", "problem-sphere-plane-contact-axis-x.json"):
        lines += ["problem %s" % name, "curves 0", "total_length 0",
                  "point contact 0.2 -0.1 -1.2", "end"]
    with open(TRUTH, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %d surfaces, %d problems, %s" % (len(SURFACES), len(problems), TRUTH))
    print("Viviani length %s" % mp.nstr(length, 35))


if __name__ == "__main__":
    main()
