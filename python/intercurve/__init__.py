"""intercurve: the differential geometry of surface intersection curves,
over the C library (libintercurve.so) with ctypes (docs/python.md).

    import intercurve as ic
    p = ic.Problem.load("examples/viviani.json")
    r = p.trace(tol=1e-10)          # r.curves, r.points, r.report, r.complete
    c = r.curves[0]                 # c.length, c.xyz (N, 3), c.kappa (N,), ...
    q = p.point(at=(2, 0, 0))       # q.type, q.branches[0].kappa, ...
    p.plot("figure.png")
    results = ic.batch([p, "examples/cusp.json"], workers=4)   # or client=dask_client
"""

from ._lib import ComputationError, Error, InputError, library_path
from .batch import batch
from .problem import Problem, TraceResult, default
from .results import BSpline, Branch, Curve, PointResult, SpecialPoint

__version__ = "0.1.0"

__all__ = ["Problem", "TraceResult", "Curve", "BSpline", "SpecialPoint", "PointResult",
           "Branch", "batch", "default", "Error", "InputError", "ComputationError",
           "library_path"]
