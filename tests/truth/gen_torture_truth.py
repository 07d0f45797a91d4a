#!/usr/bin/env python3
"""Truth for the torture set (tests/torture/*.json; tests/test_torture.c,
bench/bench_torture.c): for every problem file the exact intersection,
derived from the geometry by hand and checked here with sympy and mpmath,
never from intercurve's output.

Per case: the verdict the report must give, the number of curves and of
closed ones, each curve's length (sorted, 25 digits), whether it is closed,
tangential, and its shape where the shape is exact (a circle, a line, a
plane curve), the singular points with the library's type names
(include/intercurve/local.h, docs/tangential.md), and a length scale `size`
of the problem (point positions are compared within 1e-8 size).

Every curve is given by an exact parametrisation c(t), t in [t0, t1]; the
script checks
  - that c(t) lies on both surfaces, given by their implicit equations
    (sympy: expanded to 0, with sin = sqrt(1 - cos^2), or else
    |F(c(t))| < 1e-40 at 7 points at 60 digits),
  - that it lies in the box (implicit pairs; for parametric surfaces the
    comments state the preimages and why they lie in the domain),
  - the closed-form length against mpmath's tanh-sinh quadrature of |c'(t)|
    (a second route), to 1e-25 relative,
and the egg-crate loop counts by two routes (below).

Verdicts:
  complete       the report must say complete = 1 with exactly these curves;
  incomplete_ok  overflow cases: the right curves, or an honest incomplete
                 report (complete = 0 and the failures say why), or an error;
                 never complete = 1 with wrong curves;
  incomplete     coincident surfaces: the intersection is a surface, no set
                 of curves is it: complete = 1 is always wrong;
  input_error    the loader must reject the file.

The status column (`pass` or `known-failure: REASON`) records what the
tracer did when this set was written (test_torture prints XFAIL/XPASS for
the known failures); it is the only part of the file that comes from
running the code, and it is not truth.

Run:  python3 tests/truth/gen_torture_truth.py
"""
import os

import mpmath as mp
import sympy as sp

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "torture_truth.txt")
t = sp.Symbol("t", real=True)
x, y, z = sp.symbols("x y z", real=True)
R_ = sp.Rational


# What the tracer did when the set was written (commit 40b2785 and the
# working tree of that hour, which was changing under it; tests/test_torture.c prints XFAIL/XPASS): `pass`
# is asserted, `known-failure: REASON` is run and printed. Observed, not truth.
STATUS = {
    "scale-plane-R1e-6": "pass",
    "scale-plane-R1e-3": "pass",
    "scale-plane-R1": "pass",
    "scale-plane-R1e3": "pass",
    "scale-plane-R1e6": "pass",
    "scale-spheres-R1e4": "pass",
    "scale-spheres-R1e5": "pass",
    "tiny-overlap-circle": "pass",
    "seam-sphere-plane-c-1": "pass",
    "seam-sphere-sphere-c0.5": "pass",
    "seam-torus-plane-c3": "pass",
    "seam-torus-plane-c0.5": "pass",
    "seam-cylinder-plane-c-1": "pass",
    "cut-open-sphere": "pass",
    "cut-open-torus": "pass",
    "tangent-cylinder-plane-box": "pass",
    "tangent-sphere-cylinder-domain": "pass",
    "tangent-sphere-cylinder-box": "pass",
    "eggcrate-k10": "pass",
    "eggcrate-k100": "known-failure: benchmark only (bench/bench_torture.c)",
    "coincident-planes": "pass",
    "coincident-spheres": "pass",
    "near-planes-1e-9": "pass",
    "near-spheres-1e-9": "pass",
    "cone-apex": "pass",
    "overflow-exp": "pass",
    "overflow-pow1025": "pass",
    "overflow-box-1e160": "pass",
    "overflow-domain-1e300": "pass",
    "overflow-box-inf": "pass",
    "overflow-domain-inf": "pass",
    "contact-x4y4": "pass",
    "whitney-umbrella": "pass",
    "viviani-1e3-offset": "pass",
    "cylinders-1e-2-offset": "pass",
    "sphere-plane-angle": "pass",
}


def M(v):
    """An mpmath number from a sympy or Python one."""
    if isinstance(v, sp.Basic):
        return mp.mpf(str(sp.N(v, 50)))
    return mp.mpf(v)


def on_surface(F, c, t0, t1):
    """F(c(t)) == 0: symbolically, else numerically at 60 digits."""
    e = F.subs({x: c[0], y: c[1], z: c[2]}, simultaneous=True)
    e = sp.expand(e)
    if e == 0 or sp.expand(e.replace(sp.sin, lambda a: sp.sqrt(1 - sp.cos(a) ** 2))) == 0:
        return
    with mp.workdps(60):
        f = sp.lambdify(t, e, "mpmath")
        for k in range(7):
            tk = M(t0) + (M(t1) - M(t0)) * (k + mp.mpf(1) / 3) / 7
            v = f(tk)
            assert abs(v) < mp.mpf("1e-40"), (F, c, tk, v)


def in_box(c, t0, t1, box):
    f = sp.lambdify(t, list(c), "mpmath")
    for k in range(101):
        p = f(M(t0) + (M(t1) - M(t0)) * k / 100)
        for i in range(3):
            assert M(box[i][0]) - mp.mpf("1e-30") <= p[i] <= M(box[i][1]) + mp.mpf("1e-30"), (c, k, p, box)


def quad_length(c, t0, t1, breaks=()):
    speed = sp.sqrt(sum(sp.diff(ci, t) ** 2 for ci in c))
    f = sp.lambdify(t, speed, "mpmath")
    pts = [M(t0)] + [M(b) for b in breaks] + [M(t1)]
    return mp.quad(f, pts)


class Case:
    def __init__(self, name, verdict, size):
        self.name, self.verdict, self.size = name, verdict, size
        self.status = STATUS[name]
        self.curves = []  # (length, closed, tangential, shape, count)
        self.points = []  # (xyz, type)
        self.extra_points = None
        self.bench_only = False
        self.ncurves = None  # None: from the curve list; -1: a surface

    def curve(self, c, t0, t1, closed, shape, L, surfaces, box=None, tangential=False,
              count=1, breaks=()):
        """c: sympy 3-tuple in t; L: the closed-form length (mpmath)."""
        for F in surfaces:
            on_surface(F, c, t0, t1)
        if box is not None:
            in_box(c, t0, t1, box)
        Lq = quad_length(c, t0, t1, breaks)
        assert abs(Lq - L) <= mp.mpf("1e-25") * abs(L), (self.name, Lq, L)
        if closed:
            f = sp.lambdify(t, list(c), "mpmath")
            a, b = f(M(t0)), f(M(t1))
            assert max(abs(a[i] - b[i]) for i in range(3)) < mp.mpf("1e-30"), (self.name, "not closed")
        self.curves.append((L, closed, tangential, shape, count))

    def raw_curve(self, L, closed, shape, count=1, tangential=False):
        self.curves.append((L, closed, tangential, shape, count))


def sphere(r=1, c=(0, 0, 0)):
    return (x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2 - r ** 2


def circle(center, e1, e2, r):
    return tuple(center[i] + r * (e1[i] * sp.cos(t) + e2[i] * sp.sin(t)) for i in range(3))


PI = mp.pi
TWO_PI = 2 * sp.pi
cases = []

# ---------------------------------------------------------------- scales
# Sphere of radius R cut by z = 0: the great circle, 2 pi R. Box
# [-2R, 2R]^2 x [-1.3R, 2.1R] (the files).
for Rs in ["1e-6", "1e-3", "1", "1e3", "1e6"]:
    R = sp.Rational(Rs) if "e" not in Rs else sp.Rational(10) ** int(Rs.split("e")[1])
    box = [(-2 * R, 2 * R), (-2 * R, 2 * R), (-R_(13, 10) * R, R_(21, 10) * R)]
    k = Case("scale-plane-R" + Rs, "complete", 2 * R)
    k.curve(circle((0, 0, 0), (1, 0, 0), (0, 1, 0), R), 0, TWO_PI, True, "circle",
            2 * PI * mp.mpf(R), [sphere(R), z], box)
    cases.append(k)

# Spheres of radius R at the origin and at (R, 0, 0): |x|^2 = |x - R e1|^2
# gives x = R/2, radius R sqrt(3)/2, length pi sqrt(3) R.
for Rs in ["1e4", "1e5"]:
    R = sp.Integer(10) ** int(Rs[2:])
    box = [(-R_(13, 10) * R, R_(22, 10) * R), (-R_(12, 10) * R, R_(11, 10) * R),
           (-R_(11, 10) * R, R_(125, 100) * R)]
    k = Case("scale-spheres-R" + Rs, "complete", R_(22, 10) * R)
    k.curve(circle((R / 2, 0, 0), (0, 1, 0), (0, 0, 1), sp.sqrt(3) * R / 2), 0, TWO_PI, True,
            "circle", PI * mp.sqrt(3) * mp.mpf(R), [sphere(R), sphere(R, (R, 0, 0))], box)
    cases.append(k)

# Two unit spheres, centres 0 and d = 2 - 2^-20 (exact in binary): the plane
# x = d/2, radius sqrt(1 - d^2/4) (about 1e-3).
d = 2 - R_(1, 2 ** 20)
r = sp.sqrt(1 - d ** 2 / 4)
k = Case("tiny-overlap-circle", "complete", R_(24, 10))
k.curve(circle((d / 2, 0, 0), (0, 1, 0), (0, 0, 1), r), 0, TWO_PI, True, "circle",
        2 * PI * mp.sqrt(1 - mp.mpf(d) ** 2 / 4), [sphere(1), sphere(1, (d, 0, 0))],
        [(-R_(14, 10), R_(33, 10)), (-R_(15, 10), R_(14, 10)), (-R_(13, 10), R_(16, 10))])
cases.append(k)

# ---------------------------------------------------------------- seams
# Parametric unit sphere (u periodic over any 2 pi interval, v in
# [-pi/2, pi/2]: the whole sphere) cut by 0.2 x - z + 0.3 = 0: the foot of
# the perpendicular from the centre is -0.3 n/|n|^2, n = (0.2, 0, -1),
# distance 0.3/sqrt(1.04), radius sqrt(1 - 0.09/1.04).
n2 = R_(104, 100)
foot = (-R_(3, 10) * R_(2, 10) / n2, 0, R_(3, 10) / n2)
rr = sp.sqrt(1 - R_(9, 100) / n2)
k = Case("seam-sphere-plane-c-1", "complete", 1)
k.curve(circle(foot, (1 / sp.sqrt(n2), 0, R_(2, 10) / sp.sqrt(n2)), (0, 1, 0), rr), 0, TWO_PI, True,
        "circle", 2 * PI * mp.sqrt(1 - mp.mpf("0.09") / mp.mpf("1.04")),
        [sphere(1), z - R_(3, 10) - R_(2, 10) * x])
cases.append(k)

k = Case("seam-sphere-sphere-c0.5", "complete", 1)
k.curve(circle((R_(1, 2), 0, 0), (0, 1, 0), (0, 0, 1), sp.sqrt(3) / 2), 0, TWO_PI, True, "circle",
        PI * mp.sqrt(3), [sphere(1), sphere(1, (1, 0, 0))])
cases.append(k)


def torus(Rm, rm):
    return (x ** 2 + y ** 2 + z ** 2 + Rm ** 2 - rm ** 2) ** 2 - 4 * Rm ** 2 * (x ** 2 + y ** 2)


# Torus (2, 1/2) and y = 0: sin u = 0, the meridians u = pi, 2 pi (in
# [3, 3 + 2 pi]), circles of radius 1/2 centred at (+-2, 0, 0): pi each.
k = Case("seam-torus-plane-c3", "complete", R_(5, 2))
for sgn in (1, -1):
    k.curve((sgn * (2 + sp.cos(t) / 2), 0, sp.sin(t) / 2), 0, TWO_PI, True, "circle", PI,
            [torus(2, R_(1, 2)), y])
cases.append(k)

# Torus (2, 1/2) and z = 1/4: sin v = 1/2, v = pi/6, 5 pi/6, circles of
# radii 2 +- sqrt(3)/4 in the plane z = 1/4.
k = Case("seam-torus-plane-c0.5", "complete", R_(5, 2))
for sgn in (1, -1):
    rho = 2 + sgn * sp.sqrt(3) / 4
    k.curve(circle((0, 0, R_(1, 4)), (1, 0, 0), (0, 1, 0), rho), 0, TWO_PI, True, "circle",
            2 * PI * (2 + sgn * mp.sqrt(3) / 4), [torus(2, R_(1, 2)), z - R_(1, 4)])
cases.append(k)

# Cylinder x^2 + y^2 = 1 and z = x/2: the ellipse (cos t, sin t, cos t / 2),
# semi-axes a = sqrt(5)/2 (in the plane) and b = 1: perimeter 4 a E(1 - b^2/a^2)
# = 2 sqrt(5) E(1/5) (mpmath's ellipe takes the parameter m = k^2).
k = Case("seam-cylinder-plane-c-1", "complete", 2)
k.curve((sp.cos(t), sp.sin(t), sp.cos(t) / 2), 0, TWO_PI, True, "planar",
        2 * mp.sqrt(5) * mp.ellipe(mp.mpf(1) / 5), [x ** 2 + y ** 2 - 1, z - x / 2])
cases.append(k)

# Sphere cut open: u in [0.5, 0.5 + 3 pi/2] not periodic, z = 0.3: the arc
# of the circle of radius sqrt(0.91) over that range of u (the circle's
# polar angle is u itself).
k = Case("cut-open-sphere", "complete", 1)
rr = sp.sqrt(R_(91, 100))
k.curve((rr * sp.cos(t), rr * sp.sin(t), R_(3, 10)), R_(1, 2), R_(1, 2) + 3 * sp.pi / 2, False, "circle",
        mp.mpf(3) * PI / 2 * mp.sqrt(mp.mpf("0.91")), [sphere(1), z - R_(3, 10)])
cases.append(k)

# Upper half torus (2, 1/4), v in [0, pi] not periodic, cut by y = 0: the
# half meridians at u = 0 and u = pi, pi/4 each.
k = Case("cut-open-torus", "complete", R_(9, 4))
for sgn in (1, -1):
    k.curve((sgn * (2 + sp.cos(t) / 4), 0, sp.sin(t) / 4), 0, sp.pi, False, "circle", PI / 4,
            [torus(2, R_(1, 4)), y])
cases.append(k)

# ---------------------------------------------------------------- tangential curves
# Cylinder x^2 + (z - 1)^2 = 1 on z = 0: x^2 = 0, the double line x = z = 0,
# y in the box [-1.3, 1.7]: length 3.
box = [(-R_(11, 10), R_(9, 10)), (-R_(13, 10), R_(17, 10)), (-R_(6, 10), R_(14, 10))]
k = Case("tangent-cylinder-plane-box", "complete", R_(17, 10))
k.curve((0, t, 0), -R_(13, 10), R_(17, 10), False, "line", mp.mpf(3),
        [x ** 2 + (z - 1) ** 2 - 1, z], box, tangential=True)
cases.append(k)

# Unit sphere inside x^2 + y^2 = 1: x^2 + y^2 = 1 - z^2 = 1 gives z = 0 (a
# double root: the surfaces touch along the equator). Parametric sphere
# u in [0, 2]: the arc u in [0, 2], length 2.
k = Case("tangent-sphere-cylinder-domain", "complete", 1)
k.curve((sp.cos(t), sp.sin(t), 0), 0, 2, False, "circle", mp.mpf(2),
        [sphere(1), x ** 2 + y ** 2 - 1], tangential=True)
cases.append(k)

# The same, implicit, box x <= 0.5: the arc of the equator with cos t <= 1/2,
# t in [pi/3, 5 pi/3], length 4 pi/3.
box = [(-R_(15, 10), R_(1, 2)), (-R_(15, 10), R_(15, 10)), (-R_(7, 10), R_(9, 10))]
k = Case("tangent-sphere-cylinder-box", "complete", R_(15, 10))
k.curve((sp.cos(t), sp.sin(t), 0), sp.pi / 3, 5 * sp.pi / 3, False, "circle", 4 * PI / 3,
        [sphere(1), x ** 2 + y ** 2 - 1], box, tangential=True)
cases.append(k)


# ---------------------------------------------------------------- many loops
# z = A sin(kx) sin(ky) against z = c over [-W, W]^2: in phases a = kx,
# b = ky the level set sin a sin b = s0 = c/A. The zero lines a, b = j pi
# cut the plane into cells; sin a sin b has sign (-1)^(i+j) on cell (i, j)
# and |sin a sin b| <= 1 with the maximum 1 at the centre, so for 0 < s0 < 1
# each positive cell holds one loop (convex: cos p cos q is log-concave on
# |p|, |q| < pi/2) around its centre and negative cells hold nothing. In
# local phases (alpha, beta) in [0, pi]^2 of a cell the loop is
# cos(rho cos phi) cos(rho sin phi) = s0 in polar coordinates about the
# centre (pi/2, pi/2); the box cuts the cell to a rectangle, and each
# connected arc of the loop inside it is one curve (the whole loop: closed).
# Length in space: the plane z = c is isometric to (x, y) = (a, b)/k.
def eggcrate(k_, W, s0):
    k_, W, s0 = mp.mpf(k_), mp.mpf(W), mp.mpf(s0)

    def rho(phi):
        return mp.findroot(lambda r: mp.cos(r * mp.cos(phi)) * mp.cos(r * mp.sin(phi)) - s0,
                           mp.acos(s0) * 0.9)

    def speed(phi):
        r = rho(phi)
        p, q = r * mp.cos(phi), r * mp.sin(phi)
        # F(r, phi) = cos p cos q - s0; dr/dphi = -F_phi / F_r
        Fr = -mp.sin(p) * mp.cos(q) * mp.cos(phi) - mp.cos(p) * mp.sin(q) * mp.sin(phi)
        Fphi = mp.sin(p) * mp.cos(q) * r * mp.sin(phi) - mp.cos(p) * mp.sin(q) * r * mp.cos(phi)
        dr = -Fphi / Fr
        return mp.sqrt(r * r + dr * dr)

    lo, hi = -W * k_, W * k_
    imin, imax = int(mp.floor(lo / mp.pi)), int(mp.floor(hi / mp.pi))
    pieces = {}  # (A0, A1, B0, B1) local rectangle -> count

    def local(i):
        return (max(mp.mpf(0), lo - i * mp.pi), min(mp.pi, hi - i * mp.pi))

    for i in range(imin, imax + 1):
        for j in range(imin, imax + 1):
            if (i + j) % 2:
                continue  # a negative cell: sin a sin b <= 0 < s0, no point
            A, B = local(i), local(j)
            if A[1] <= A[0] or B[1] <= B[0]:
                continue
            key = tuple(mp.nstr(v, 30) for v in A + B)
            pieces[key] = pieces.get(key, 0) + 1
    loops, arcs = [], []  # (length, count)
    for key, cnt in pieces.items():
        A0, A1, B0, B1 = (mp.mpf(v) for v in key)
        # points of the loop by angle; find the angles inside the rectangle
        def inside(phi):
            r = rho(phi)
            a, b = mp.pi / 2 + r * mp.cos(phi), mp.pi / 2 + r * mp.sin(phi)
            return A0 <= a <= A1 and B0 <= b <= B1

        def edge(phi):  # signed distance into the rectangle (min over faces)
            r = rho(phi)
            a, b = mp.pi / 2 + r * mp.cos(phi), mp.pi / 2 + r * mp.sin(phi)
            return min(a - A0, A1 - a, b - B0, B1 - b)

        N = 720
        grid = [2 * mp.pi * m / N for m in range(N)]
        vals = [edge(p) for p in grid]
        if all(v > 0 for v in vals):
            L = mp.quad(speed, [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]) / k_
            loops.append((L, cnt))
            continue
        if all(v <= 0 for v in vals):
            continue
        # crossings of the rectangle's boundary, refined by bisection
        cross = []
        for m in range(N):
            p0, p1 = grid[m], grid[(m + 1) % N] + (2 * mp.pi if m == N - 1 else 0)
            v0, v1 = vals[m], vals[(m + 1) % N]
            if (v0 > 0) != (v1 > 0):
                a_, b_ = p0, p1
                for _ in range(120):
                    mid = (a_ + b_) / 2
                    if (edge(mid) > 0) == (v0 > 0):
                        a_ = mid
                    else:
                        b_ = mid
                cross.append(((a_ + b_) / 2, v0 <= 0))  # True: entering
        # arcs: from an entering crossing to the next leaving one
        cross.sort()
        for n_, (p, entering) in enumerate(cross):
            if entering:
                q = cross[(n_ + 1) % len(cross)][0]
                if q < p:
                    q += 2 * mp.pi
                assert inside((p + q) / 2)
                arcs.append((mp.quad(speed, [p, q]) / k_, cnt))
    return loops, arcs


def eggcrate_second_route(k_, W, s0):
    """Counts by the issue's rule: a grid cell of whole phase [i pi, (i+1) pi]
    x [j pi, (j+1) pi] inside the box whose maximum of (sin a sin b) exceeds
    s0 (the maximum is 1 on positive cells, 0 on negative ones) holds one
    whole loop; and the whole loop's length by the graph b = asin(s0/sin a),
    8 times its arc from the diagonal (sin^2 a = s0) to a = pi/2."""
    k_, W, s0 = mp.mpf(k_), mp.mpf(W), mp.mpf(s0)
    n = 0
    for i in range(-200, 200):
        for j in range(-200, 200):
            if i * mp.pi >= -W * k_ and (i + 1) * mp.pi <= W * k_ and j * mp.pi >= -W * k_ \
                    and (j + 1) * mp.pi <= W * k_:
                mx = 1 if (i + j) % 2 == 0 else 0
                n += mx > s0
    a_d = mp.asin(mp.sqrt(s0))

    def g(a):
        sa = mp.sin(a)
        db = -s0 * mp.cos(a) / (sa * sa * mp.sqrt(1 - (s0 / sa) ** 2))
        return mp.sqrt(1 + db * db)

    return n, 8 * mp.quad(g, [a_d, mp.pi / 2]) / k_


def rect_arc_second_route(k_, A, B, s0):
    """Length of the part of a cell's loop in the local rectangle
    [0, A] x [0, B] (A, B <= pi), by the loop's two branches as graphs over
    beta: alpha_L = asin(s0/sin beta) in (0, pi/2] and alpha_R = pi - alpha_L,
    beta in [beta_min, pi - beta_min], sin(beta_min) = s0, where they meet
    and alpha' has an integrable 1/sqrt singularity.
    alpha_L <= A iff A >= pi/2 or sin beta >= s0/sin A; alpha_R <= A iff
    A > pi/2 and sin beta <= s0/sin A. The other partial cells are mirror
    images of these (alpha -> pi - alpha, beta -> pi - beta). Each interval
    is split at its middle and integrated in w with beta = beta_min + w^2 (or
    pi - beta_min - w^2) towards an end at the singularity, and
    1 - (s0/sin beta)^2 = sin(beta - beta_min) sin(pi - beta_min - beta) /
    sin^2 beta, with both offsets computed from w (no cancellation: plain
    tanh-sinh on the singular form was 2e-21 off)."""
    k_, A, B, s0 = mp.mpf(k_), mp.mpf(A), mp.mpf(B), mp.mpf(s0)
    bmin = mp.asin(s0)
    top = mp.pi - bmin

    def g(b, dlo, dhi):
        sb = mp.sin(b)
        q = mp.sin(dlo) * mp.sin(dhi) / (sb * sb)
        da = -s0 * mp.cos(b) / (sb * sb * mp.sqrt(q))
        return mp.sqrt(1 + da * da)

    def piece(lo_, hi_):
        """the integral of g over [lo_, hi_], one end possibly singular"""
        if lo_ == bmin:
            return mp.quad(lambda w: g(bmin + w * w, w * w, top - bmin - w * w) * 2 * w,
                           [0, mp.sqrt(hi_ - bmin)])
        if hi_ == top:
            return mp.quad(lambda w: g(top - w * w, top - bmin - w * w, w * w) * 2 * w,
                           [0, mp.sqrt(top - lo_)])
        return mp.quad(lambda b: g(b, b - bmin, top - b), [lo_, hi_])

    def clip(ivs):
        out = []
        for lo_, hi_ in ivs:
            lo_, hi_ = max(lo_, bmin), min(hi_, top, B)
            if hi_ > lo_:
                out.append((lo_, hi_))
        return out

    def above(K):  # sin beta >= K
        return [(mp.mpf(0), mp.pi)] if K <= 0 else [] if K > 1 else [(mp.asin(K), mp.pi - mp.asin(K))]

    def below(K):  # sin beta <= K
        return [(mp.mpf(0), mp.pi)] if K >= 1 else [(mp.mpf(0), mp.asin(K)), (mp.pi - mp.asin(K), mp.pi)]

    left = clip([(mp.mpf(0), mp.pi)] if A >= mp.pi / 2 else above(s0 / mp.sin(A)))
    right = clip(below(s0 / mp.sin(A))) if A > mp.pi / 2 else []
    total = mp.mpf(0)
    for lo_, hi_ in left + right:
        mid = (lo_ + hi_) / 2
        total += piece(lo_, mid) + piece(mid, hi_)
    return total / k_


def eggcrate_case(name, k_, bench_only):
    W, s0 = 2, mp.mpf("0.5")  # c / A = 0.05 / 0.1
    loops, arcs = eggcrate(k_, W, s0)
    n2, L2 = eggcrate_second_route(k_, W, s0)
    assert sum(c for _, c in loops) == n2, (name, loops, n2)
    for L, _ in loops:
        assert abs(L - L2) < mp.mpf("1e-25") * L2, (L, L2)
    full = rect_arc_second_route(k_, mp.pi, mp.pi, s0)
    assert abs(full - L2) < mp.mpf("1e-25") * L2, (full, L2)
    # the partial cells at the box edges: local width A of phase beyond the
    # last zero line (the box is symmetric, so all four sides alike)
    A = mp.mpf(W) * k_ - mp.floor(mp.mpf(W) * k_ / mp.pi) * mp.pi
    ea, ca = rect_arc_second_route(k_, A, mp.pi, s0), rect_arc_second_route(k_, A, A, s0)
    for L, _ in arcs:
        assert min(abs(L - ea), abs(L - ca)) < mp.mpf("1e-25") * L, (name, L, ea, ca)
    print("%s: loop %s, edge arc %s, corner arc %s (second route)" % (name, mp.nstr(L2, 20), mp.nstr(ea, 20), mp.nstr(ca, 20)))
    kc = Case(name, "complete", W)
    kc.bench_only = bench_only
    for L, c in loops:
        kc.raw_curve(L, True, "planar", c)
    for L, c in arcs:
        kc.raw_curve(L, False, "planar", c)
    return kc, sum(c for _, c in loops), sum(c for _, c in arcs)


kc, nl, na = eggcrate_case("eggcrate-k10", 10, False)
print("eggcrate k = 10: %d loops, %d arcs" % (nl, na))
cases.append(kc)
kc, nl, na = eggcrate_case("eggcrate-k100", 100, True)
assert nl == 7938, nl  # the count
print("eggcrate k = 100: %d loops, %d arcs" % (nl, na))
cases.append(kc)

# ---------------------------------------------------------------- coincident
k = Case("coincident-planes", "incomplete", 1)
k.ncurves = -1
k.extra_points = "the surfaces coincide: any points may be listed"
cases.append(k)
k = Case("coincident-spheres", "incomplete", R_(15, 10))
k.ncurves = -1
k.extra_points = "the surfaces coincide: any points may be listed"
cases.append(k)
# z = 0 and z = 1e-9 have no common point; nor have |x| = 1 and |x| = 1 + 1e-9.
cases.append(Case("near-planes-1e-9", "complete", R_(14, 10)))
cases.append(Case("near-spheres-1e-9", "complete", R_(15, 10)))

# ---------------------------------------------------------------- cone apex
# x^2 + y^2 = z^2 and y = 0: x = +-z, z in the box's [-0.8, 0.8] (|x| <= 0.8
# < 1): two lines of length 1.6 sqrt(2) crossing at the apex. The cone has no
# normal there (grad f = 0): a singular point of the surface itself, which the
# library names surface-singular (docs/tracing.md).
box = [(-1, 1), (-1, 1), (-R_(8, 10), R_(8, 10))]
k = Case("cone-apex", "complete", 1)
for sgn in (1, -1):
    k.curve((sgn * t, 0, t), -R_(8, 10), R_(8, 10), False, "line", mp.mpf("1.6") * mp.sqrt(2),
            [x ** 2 + y ** 2 - z ** 2, y], box)
k.points.append(((0, 0, 0), "surface-singular"))  # the cone's own singular point (grad f = 0), docs/tracing.md
cases.append(k)

# ---------------------------------------------------------------- overflow
k = Case("overflow-exp", "incomplete_ok", 800)
k.curve((0, sp.cos(t), sp.sin(t)), 0, TWO_PI, True, "circle", 2 * PI,
        [sp.exp(x) - 1, sphere(1)], [(-800, 800), (-2, 2), (-2, 2)])
cases.append(k)

# x^1025 = -1/4: x0 = -(1/4)^(1/1025), the circle of radius sqrt(1 - x0^2).
with mp.workdps(60):
    x0 = -mp.power(mp.mpf(1) / 4, mp.mpf(1) / 1025)
    Lp = 2 * mp.pi * mp.sqrt(1 - x0 ** 2)
x0s = -sp.Rational(1, 4) ** sp.Rational(1, 1025)
k = Case("overflow-pow1025", "incomplete_ok", 2)
k.curve(circle((x0s, 0, 0), (0, 1, 0), (0, 0, 1), sp.sqrt(1 - x0s ** 2)), 0, TWO_PI, True, "circle",
        Lp, [x ** 1025 + R_(1, 4), sphere(1)], [(-2, 2)] * 3)
cases.append(k)

k = Case("overflow-box-1e160", "incomplete_ok", sp.Float("1e160", 30))
k.curve(circle((0, 0, R_(1, 2)), (1, 0, 0), (0, 1, 0), sp.sqrt(3) / 2), 0, TWO_PI, True, "circle",
        PI * mp.sqrt(3), [sphere(1), z - R_(1, 2)])
cases.append(k)

k = Case("overflow-domain-1e300", "incomplete_ok", 1)
k.curve(circle((0, 0, R_(1, 2)), (1, 0, 0), (0, 1, 0), sp.sqrt(3) / 2), 0, TWO_PI, True, "circle",
        PI * mp.sqrt(3), [sphere(1), z - R_(1, 2)])
cases.append(k)

cases.append(Case("overflow-box-inf", "input_error", 2))
cases.append(Case("overflow-domain-inf", "input_error", 2))

# ---------------------------------------------------------------- higher-order contact
# z = x^4 + y^4 and z = 0: x^4 + y^4 = 0 only at the origin; the height
# difference x^4 + y^4 has no quadratic part (docs/tangential.md:
# higher-order-contact) and its quartic form has no real root (no branch).
k = Case("contact-x4y4", "complete", 1)
k.points.append(((0, 0, 0), "higher-order-contact"))
cases.append(k)

# ---------------------------------------------------------------- Whitney umbrella
# R(u, v) = (u v, v, u^2): R(u, v) = R(p, q) with (u, v) != (p, q) needs
# q = v, p^2 = u^2, so p = -u != 0, and then u v = -u v: v = 0. The double
# curve is (0, 0, u^2) with preimages (u, 0), (-u, 0), both in the domain
# u in [-1.2, 1.5], v in [-0.7, 1.1] for 0 < u <= 1.2: the segment from the
# pinch point (0, 0, 0) to (0, 0, 1.44), length 1.44. At the pinch point
# R_u x R_v = 0 (a singular point of the surface itself, typed surface-singular; any point there is allowed).
k = Case("whitney-umbrella", "complete", R_(15, 10))
u_, v_ = sp.symbols("u v", real=True)
Rw = sp.Matrix([u_ * v_, v_, u_ ** 2])
# both preimages (u, 0) and (-u, 0) give (0, 0, u^2) = c(u^2)
assert sp.simplify(Rw.subs({u_: t, v_: 0}) - Rw.subs({u_: -t, v_: 0})) == sp.zeros(3, 1)
assert sp.simplify(Rw.subs({u_: t, v_: 0}) - sp.Matrix([0, 0, t ** 2])) == sp.zeros(3, 1)
k.curve((0, 0, t), 0, R_(144, 100), False, "line", mp.mpf("1.44"), [x, y])
k.extra_points = "the pinch point (0, 0, 0): a singular point of the surface itself (surface-singular)"
cases.append(k)

# ---------------------------------------------------------------- classics
# Viviani, scale s = 1000, centre C: C + s (1 + cos p, sin p, 2 sin(p/2)),
# p in [0, 4 pi], one closed figure-eight through the branch point C + 2 s e1;
# speed s sqrt(1 + cos^2(p/2)); length s * 8 sqrt(2) E(1/2).
s, C = 1000, (-3000, 1000, 2000)
k = Case("viviani-1e3-offset", "complete", 2400)
k.curve(tuple(C[i] + s * e for i, e in enumerate((1 + sp.cos(t), sp.sin(t), 2 * sp.sin(t / 2)))),
        0, 4 * sp.pi, True, "general", s * 8 * mp.sqrt(2) * mp.ellipe(mp.mpf(1) / 2),
        [(x - C[0] - s) ** 2 + (y - C[1]) ** 2 - s ** 2, sphere(2 * s, C)],
        [(C[0] - 2.3 * s, C[0] + 2.4 * s), (C[1] - 2.2 * s, C[1] + 2.5 * s), (C[2] - 2.35 * s, C[2] + 2.3 * s)],
        breaks=[sp.pi, 2 * sp.pi, 3 * sp.pi])
k.points.append(((C[0] + 2 * s, C[1], C[2]), "branch-point"))
cases.append(k)

# Cylinders (x-a)^2 + (y-b)^2 = s^2 and (x-a)^2 + (z-c)^2 = (0.7 s)^2:
# x = a + 0.7 s cos t, z = c + 0.7 s sin t, y = b +- s sqrt(1 - 0.49 cos^2 t):
# two closed loops (|x - a| <= 0.7 s < s), of equal length by symmetry; no
# closed form: the length is s * integral_0^{2 pi} |(..)'|, by tanh-sinh at
# 40 digits, checked against Gauss-Legendre.
s, a, b, c = R_(1, 100), R_(5, 100), -R_(3, 100), R_(2, 100)
k = Case("cylinders-1e-2-offset", "complete", R_(15, 1000))
for sgn in (1, -1):
    cc = (a + R_(7, 10) * s * sp.cos(t), b + sgn * s * sp.sqrt(1 - R_(49, 100) * sp.cos(t) ** 2),
          c + R_(7, 10) * s * sp.sin(t))
    spd = sp.lambdify(t, sp.sqrt(sum(sp.diff(ci, t) ** 2 for ci in cc)), "mpmath")
    Lg = mp.quad(spd, mp.linspace(0, 2 * mp.pi, 9), method="gauss-legendre")
    k.curve(cc, 0, TWO_PI, True, "general", Lg,
            [(x - a) ** 2 + (y - b) ** 2 - s ** 2, (x - a) ** 2 + (z - c) ** 2 - (R_(7, 10) * s) ** 2],
            [(a - R_(15, 10) * s, a + R_(15, 10) * s), (b - R_(15, 10) * s, b + R_(15, 10) * s),
             (c - R_(15, 10) * s, c + R_(15, 10) * s)])
cases.append(k)

# Sphere of radius 30 at C and the plane n . (x - C) = 17, n = (1, 2, 2)/3:
# the circle about C + 17 n of radius sqrt(900 - 289) = sqrt(611).
C = (10, -20, 5)
nvec = (R_(1, 3), R_(2, 3), R_(2, 3))
e1 = (R_(2, 3), -R_(1, 3), 0)
e1 = tuple(v / sp.sqrt(R_(5, 9)) for v in e1)
e2 = (nvec[1] * e1[2] - nvec[2] * e1[1], nvec[2] * e1[0] - nvec[0] * e1[2], nvec[0] * e1[1] - nvec[1] * e1[0])
k = Case("sphere-plane-angle", "complete", 30)
k.curve(circle(tuple(C[i] + 17 * nvec[i] for i in range(3)), e1, e2, sp.sqrt(611)), 0, TWO_PI, True,
        "circle", 2 * PI * mp.sqrt(611),
        [sphere(30, C), sum(nvec[i] * ((x, y, z)[i] - C[i]) for i in range(3)) - 17])
cases.append(k)


# ---------------------------------------------------------------- output
def num(v):
    if isinstance(v, sp.Basic):
        v = mp.mpf(str(sp.N(v, 40)))
    return mp.nstr(mp.mpf(v), 25, min_fixed=-4, max_fixed=4)


with open(OUT, "w") as out:
    out.write("# Torture set truth (tests/truth/gen_torture_truth.py; docs in its header).\n")
    out.write("# case NAME / verdict V / size S / curves N closed M / curve LENGTH closed|open\n")
    out.write("# transversal|tangential SHAPE [xCOUNT] (sorted by length) / point X Y Z TYPE /\n")
    out.write("# extra_points REASON / bench_only / status pass|known-failure: REASON / end\n")
    for kc in cases:
        out.write("\ncase %s\n" % kc.name)
        out.write("verdict %s\n" % kc.verdict)
        out.write("size %s\n" % num(sp.sympify(kc.size)))
        if kc.ncurves == -1:
            out.write("curves surface\n")
        else:
            n = sum(c[4] for c in kc.curves)
            m = sum(c[4] for c in kc.curves if c[1])
            out.write("curves %d closed %d\n" % (n, m))
            for L, closed, tang, shape, cnt in sorted(kc.curves, key=lambda c: c[0]):
                out.write("curve %s %s %s %s%s\n" % (num(L), "closed" if closed else "open",
                                                     "tangential" if tang else "transversal", shape,
                                                     " x%d" % cnt if cnt > 1 else ""))
        for p, ty in kc.points:
            out.write("point %s %s %s %s\n" % (num(p[0]), num(p[1]), num(p[2]), ty))
        if kc.extra_points:
            out.write("extra_points %s\n" % kc.extra_points)
        if kc.bench_only:
            out.write("bench_only\n")
        out.write("status %s\n" % kc.status)
        out.write("end\n")
print("%d cases written to %s" % (len(cases), OUT))
