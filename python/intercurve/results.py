"""The documents of the library (docs/output-formats.md) as Python objects
with numpy arrays. Undefined values (null in the documents: n, b and tau
where the curvature is 0, the parameters of an implicit surface) are NaN."""

import numpy as np


def _floats(values, shape):
    """A float array of `shape` from nested lists with None for undefined
    entries (a None where a vector is expected fills it with NaN)."""
    out = np.full(shape, np.nan)
    for i, v in enumerate(values):
        if v is None:
            continue
        if isinstance(v, (list, tuple)):
            out[i] = _floats(v, shape[1:]) if len(shape) > 2 else [
                np.nan if x is None else x for x in v]
        else:
            out[i] = v
    return out


def _vector(v, n=3):
    return _floats([v], (1, n))[0]


def _number(x):
    return np.nan if x is None else float(x)


class BSpline:
    """A B-spline curve (docs/bspline.md): `degree`, `periodic`, `knots`
    (M + degree + 1,) and `control_points` (M, dim). The space curve is
    parametrised by the traced curve's arc length s; a pcurve by the same s,
    in a parameter plane. A periodic one (a closed curve) has unclamped knots
    and its first `degree` control points repeated at the end; it is
    evaluated at s modulo its period."""

    def __init__(self, doc):
        self.degree = int(doc["degree"])
        self.periodic = bool(doc.get("periodic", False))
        self.knots = np.asarray(doc["knots"], dtype=float)
        self.control_points = np.asarray(doc["control_points"], dtype=float)

    def __call__(self, s):
        """The curve at arc lengths s (a number or an array), by de Boor's
        algorithm: an array (..., dim)."""
        s = np.asarray(s, dtype=float)
        flat = np.atleast_1d(s).ravel()
        p, t, c = self.degree, self.knots, self.control_points
        last = len(c) - 1
        if self.periodic:  # into [t_p, t_M)
            lo, period = t[p], t[last + 1] - t[p]
            flat = lo + np.mod(flat - lo, period)
        span = np.clip(np.searchsorted(t, flat, side="right") - 1, p, last)
        out = np.empty((flat.size, c.shape[1]))
        for j, (x, k) in enumerate(zip(flat, span)):
            d = c[k - p:k + 1].copy()
            for r in range(1, p + 1):
                for i in range(p, r - 1, -1):
                    lo, hi = t[k - p + i], t[k + 1 + i - r]
                    a = (x - lo) / (hi - lo) if hi > lo else 0.0
                    d[i] = (1 - a) * d[i - 1] + a * d[i]
            out[j] = d[p]
        return out.reshape(s.shape + (c.shape[1],))

    def __repr__(self):
        return "BSpline(degree=%d, %d control points%s)" % (
            self.degree, len(self.control_points), ", periodic" if self.periodic else "")


class Curve:
    """One traced curve: `closed`, `type` ("transversal" or "tangential"),
    `shape` ("line", "circle", "planar", "circular-helix", "helix",
    "general"), `shape_tolerance`, `length`, `ends` (how each end stopped),
    `bspline` (a BSpline, or None when not fitted), `pcurves` ([P_A, P_B],
    BSplines or None); and at its N points the arrays `s` (N,), `xyz`
    (N, 3), `params` (N, 2, 2: [[u, v], [p, q]], NaN for an implicit
    surface), `t`, `n`, `b` (N, 3), `kappa`, `tau`, `angle` (N,) and
    `point_types` (N strings)."""

    def __init__(self, doc):
        self.document = doc
        self.closed = bool(doc["closed"])
        self.type = doc["type"]
        self.shape = doc["shape"]
        self.shape_tolerance = _number(doc.get("shape_tolerance"))
        self.length = float(doc["length"])
        self.ends = list(doc["ends"])
        self.bspline = BSpline(doc["bspline"]) if doc.get("bspline") else None
        self.pcurves = [BSpline(p) if p else None for p in (doc.get("pcurves") or [None, None])]
        pts = doc["points"]
        n = len(pts)
        self.s = _floats([p["s"] for p in pts], (n,))
        self.xyz = _floats([p["xyz"] for p in pts], (n, 3))
        self.params = _floats([p.get("params") for p in pts], (n, 2, 2))
        self.t = _floats([p["t"] for p in pts], (n, 3))
        self.n = _floats([p["n"] for p in pts], (n, 3))
        self.b = _floats([p["b"] for p in pts], (n, 3))
        self.kappa = _floats([p["kappa"] for p in pts], (n,))
        self.tau = _floats([p["tau"] for p in pts], (n,))
        self.angle = _floats([p.get("angle") for p in pts], (n,))
        self.point_types = [p["type"] for p in pts]

    def __len__(self):
        return len(self.s)

    def __repr__(self):
        return "Curve(%s, %s, %s, length=%.12g, %d points)" % (
            "closed" if self.closed else "open", self.type, self.shape, self.length, len(self))


class SpecialPoint:
    """A tangential or singular point of a trace: `xyz`, `type`,
    `branches` (how many branches pass), `approximate`."""

    def __init__(self, doc):
        self.xyz = _vector(doc["xyz"])
        self.type = doc["type"]
        self.branches = int(doc["branches"])
        self.approximate = bool(doc["approximate"])

    def __repr__(self):
        return "SpecialPoint(%s at %s)" % (self.type, np.array2string(self.xyz, precision=6))


class Branch:
    """The apparatus of one branch through a point: `t`, `n`, `b` (3,),
    `kappa`, `tau`, `kappa_prime`, `tau_prime` (floats; NaN where
    undefined), `regular` (False only at a cusp), `undefined` (why, or
    None), `derivatives` (order, 3): c', ..., c^(K) with respect to arc
    length, and `surfaces` (the per-surface dicts of the document)."""

    def __init__(self, doc, order):
        self.t = _vector(doc.get("t"))
        self.n = _vector(doc.get("n"))
        self.b = _vector(doc.get("b"))
        self.kappa = _number(doc.get("kappa"))
        self.tau = _number(doc.get("tau"))
        self.kappa_prime = _number(doc.get("kappa_prime"))
        self.tau_prime = _number(doc.get("tau_prime"))
        self.regular = bool(doc.get("regular", True))
        self.undefined = doc.get("undefined")
        self.derivatives = _floats(doc.get("derivatives") or [], (order, 3))
        self.surfaces = doc.get("surfaces", [])

    def __repr__(self):
        return "Branch(kappa=%.12g, tau=%.12g)" % (self.kappa, self.tau)


class PointResult:
    """One point of the intersection (the point document): `xyz`, `residual`,
    `params` (2, 2; NaN for an implicit surface), `normals` (2, 3), `angle`,
    `type`, `discriminant`, `method`, `order`, `branches` (Branch objects)
    and `document` (the whole dict)."""

    def __init__(self, doc):
        self.document = doc
        self.xyz = _vector(doc["point"])
        self.residual = _number(doc.get("residual"))
        self.params = _floats(doc.get("params") or [None, None], (2, 2))
        self.normals = _floats(doc.get("normals") or [None, None], (2, 3))
        self.angle = _number(doc.get("angle"))
        self.type = doc["type"]
        self.discriminant = _number(doc.get("discriminant"))
        self.method = doc.get("method")
        self.order = int(doc["order"])
        self.branches = [Branch(b, self.order) for b in doc.get("branches", [])]

    def __repr__(self):
        return "PointResult(%s at %s, %d branches)" % (
            self.type, np.array2string(self.xyz, precision=6), len(self.branches))
