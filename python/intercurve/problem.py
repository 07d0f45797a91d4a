"""A problem (docs/problem-files.md) and what the library computes on it:
traces, points, pictures (docs/python.md)."""

import ctypes
import json
import os
import threading
import weakref

from . import _lib
from ._view import view_html
from .results import Curve, PointResult, SpecialPoint

# the defaults that are counts (ic_default_value gives every value as a double)
_INT_DEFAULTS = ("depth", "threads", "point_order", "point_closed_form_order", "width",
                 "height", "frames", "mesh")


def default(name):
    """The library's default (or limit) called `name`, as `intercurve trace`,
    `point` and `plot` take it (include/intercurve/defaults.h,
    ic_default_value): an int for "depth", "threads", "point_order",
    "point_closed_form_order", "width", "height", "frames", "mesh", a float
    for "tol", "fit_tol", "rel_tol_max", "time_limit_max", "point_tol",
    "azimuth", "elevation". A parameter given as None below takes it.
    KeyError for any other name."""
    if not isinstance(name, str):
        raise KeyError("a default's name is a string, not %r" % (name,))
    value = _lib.library().ic_default_value(name.encode())
    if value != value:  # NaN: the library does not know it
        raise KeyError("intercurve has no default called %r (docs/python.md lists them)" % name)
    return int(value) if name in _INT_DEFAULTS else value


def _or_default(value, name):
    """value, or the library's default `name` when value is None."""
    return default(name) if value is None else value


# a problem that cannot be read is the caller's input too; only running out
# of memory is not
_LOAD_INPUT_CODES = (_lib.IC_ERR_INVALID, _lib.IC_ERR_PARSE, _lib.IC_ERR_IO)


def _free_problem(handle):
    _lib.library().ic_problem_free(handle)


def _free_trace(res, pair):
    lib = _lib.library()
    lib.ic_trace_result_free(res)
    lib.ic_pair_free(pair)


class Problem:
    """Two surfaces, or one that crosses itself, with an optional box: a
    problem file of docs/problem-files.md. Make one with Problem.load(path),
    Problem.from_dict(dict) or Problem.from_json(text).

    Calls on one Problem are serialised (its surfaces keep evaluation
    workspaces); different Problems run in parallel in threads, and a
    Problem pickles (by its file's path, or by its text), so it travels to
    other processes (intercurve.batch)."""

    def __init__(self, handle, text, path=None, name=None):
        # use load, from_dict or from_json; the handle is owned from here
        self._handle = ctypes.c_void_p(handle)
        self._finalizer = weakref.finalize(self, _free_problem, self._handle)
        self._text = text
        self._path = path
        self._name = name or path or "<problem>"
        self._lock = threading.Lock()

    @classmethod
    def load(cls, path):
        """Reads and validates a problem file; InputError (with .path and
        .column) when it is malformed or cannot be read."""
        path = os.path.abspath(os.fspath(path))
        lib = _lib.library()
        handle, err = ctypes.c_void_p(), _lib.new_error()
        st = lib.ic_problem_load(ctypes.byref(handle), path.encode(), ctypes.byref(err))
        _lib.check(st, err, input_codes=_LOAD_INPUT_CODES)
        return cls(handle.value, None, path)

    @classmethod
    def from_json(cls, text, name="<json>"):
        """A problem from the text of a problem file."""
        data = text.encode("utf-8") if isinstance(text, str) else bytes(text)
        lib = _lib.library()
        handle, err = ctypes.c_void_p(), _lib.new_error()
        st = lib.ic_problem_parse(ctypes.byref(handle), data, len(data), ctypes.byref(err))
        _lib.check(st, err, input_codes=_LOAD_INPUT_CODES)
        return cls(handle.value, data.decode("utf-8"), None, name)

    @classmethod
    def from_dict(cls, problem):
        """A problem from a dict with the keys of a problem file
        ("surfaces", "box", "title", ...)."""
        try:
            text = json.dumps(problem)
        except (TypeError, ValueError) as e:
            raise _lib.InputError("the problem is not JSON data: %s" % e) from None
        return cls.from_json(text, "<dict>")

    # pickling: by path when loaded from a file, else by text
    def __reduce__(self):
        if self._path is not None:
            return (Problem.load, (self._path,))
        return (Problem.from_json, (self._text, self._name))

    @property
    def title(self):
        """The problem's title ("" when it has none)."""
        return _lib.library().ic_problem_title(self._handle).decode("utf-8")

    @property
    def surface_names(self):
        """The names of its surfaces (one for a self-intersection)."""
        lib = _lib.library()
        return [lib.ic_problem_surface_name(self._handle, i).decode("utf-8")
                for i in range(lib.ic_problem_num_surfaces(self._handle))]

    @property
    def is_self(self):
        """True for a self-intersection problem."""
        return bool(_lib.library().ic_problem_is_self(self._handle))

    def trace(self, tol=None, depth=None, fit_tol=None, time_limit=0.0, threads=None,
              certificate=False):
        """Traces the whole intersection, as `intercurve trace`: tol is the
        truncation error per step and fit_tol the B-splines' tolerance, both
        fractions of the problem's size (fit_tol 0: no B-splines); depth the
        start-point search (1..9); time_limit seconds (0: none); threads
        that search at once (0..256, 0: all the cores; the same result
        whatever the number); certificate True keeps the checker's cover as
        the result's `certificate` (the JSON text of `intercurve trace
        --certificate`, docs/output-formats.md). None takes the command's
        default (default()). Returns a TraceResult; InputError for values
        out of range, ComputationError when the trace fails."""
        tol, fit_tol = _or_default(tol, "tol"), _or_default(fit_tol, "fit_tol")
        depth, threads = _or_default(depth, "depth"), _or_default(threads, "threads")
        lib = _lib.library()
        res, pair, err = ctypes.c_void_p(), ctypes.c_void_p(), _lib.new_error()
        with self._lock:
            entry = lib.ic_problem_trace_keep_certificate if certificate else lib.ic_problem_trace
            st = entry(ctypes.byref(res), ctypes.byref(pair), self._handle, float(tol),
                       int(depth), float(time_limit), int(threads), float(fit_tol),
                       ctypes.byref(err))
            _lib.check(st, err)
            cert = None
            if certificate:
                text = lib.ic_trace_result_certificate(res)
                cert = text.decode() if text is not None else None
            try:
                buf, length = ctypes.c_void_p(), ctypes.c_size_t()
                st = lib.ic_trace_json_alloc(ctypes.byref(buf), ctypes.byref(length), res,
                                             pair, ctypes.byref(err))
                _lib.check(st, err)
                document = json.loads(_lib.take_text(buf, length))
            except BaseException:
                _free_trace(res, pair)
                raise
        options = dict(tol=tol, depth=depth, fit_tol=fit_tol, time_limit=time_limit,
                       threads=threads, certificate=bool(certificate))
        return TraceResult(document, self, options, (res, pair), cert)

    def verify(self, trace, certificate=None):
        """Checks a trace of this problem again with the independent checker,
        without the tracer, as `intercurve verify` (docs/tracing.md, "The
        certificate"): trace is a TraceResult, a trace document (dict) or
        its JSON text; certificate (None: the cover is grown afresh) a
        certificate file (dict or JSON text, as TraceResult.certificate)
        whose cover is replayed, every leaf proven again, as `intercurve
        verify --certificate`. Returns the checker's summary, the keys of
        report["certificate"]; its "accepted" is the verdict. InputError
        for a document that is not a trace of this problem's kind, or a
        certificate that is not one of this problem's region."""
        if isinstance(trace, TraceResult):
            trace = trace.document
        text = trace if isinstance(trace, str) else json.dumps(trace)
        cert = certificate
        if cert is not None and not isinstance(cert, str):
            cert = json.dumps(cert)
        lib = _lib.library()
        buf, length, err = ctypes.c_void_p(), ctypes.c_size_t(), _lib.new_error()
        with self._lock:
            st = lib.ic_problem_verify_certificate_json(
                ctypes.byref(buf), ctypes.byref(length), self._handle, text.encode(),
                cert.encode() if cert is not None else None, ctypes.byref(err))
            _lib.check(st, err)
        return json.loads(_lib.take_text(buf, length))["certificate"]

    def point(self, at=None, params=None, order=None, method="auto", point_tol=None):
        """The intersection's apparatus at one point, as `intercurve point`:
        the point by its coordinates `at` (x, y, z) or by `params` (the
        parametric surfaces' parameters, in problem order; for a
        self-intersection both preimages u, v, p, q); derivatives to `order`
        (1..16); method "auto", "jet", "closed-form", "perturbation" or
        "height-difference"; point_tol how far (a length) from the surfaces
        the search may start. Returns a PointResult. ComputationError when
        the point is not on the intersection (its message starts "not on the
        surfaces"), InputError for wrong values. None takes the command's
        default (default())."""
        # the closed forms stop at the third derivative: their default order
        order = _or_default(order, "point_closed_form_order" if method == "closed-form"
                            else "point_order")
        point_tol = _or_default(point_tol, "point_tol")
        if (at is None) == (params is None):
            raise _lib.InputError("give the point by `at` or by `params`, not both or neither")
        values = [float(x) for x in (at if at is not None else params)]
        arr = (ctypes.c_double * max(len(values), 1))(*values)
        lib = _lib.library()
        buf, length, err = ctypes.c_void_p(), ctypes.c_size_t(), _lib.new_error()
        with self._lock:
            st = lib.ic_problem_point_json(ctypes.byref(buf), ctypes.byref(length),
                                           self._handle, arr, len(values),
                                           int(params is not None), int(order),
                                           str(method).encode(), float(point_tol),
                                           ctypes.byref(err))
            _lib.check(st, err)
            text = _lib.take_text(buf, length)
        return PointResult(json.loads(text))

    def plot(self, path, result=None, surfaces_only=False, size=None, view=None, frames=None,
             chart=True, mesh=None, tol=None, depth=None, time_limit=0.0):
        """Draws the problem, as `intercurve plot`, into `path`; the format
        follows its extension (every format `intercurve plot` writes: .svg,
        .png, .pdf, ...; docs/plots.md). result: a TraceResult of this
        problem to draw; without one the problem is traced now with tol,
        depth and time_limit (as trace() takes them), or with
        surfaces_only=True not at all. size (width, height) in pixels (PNG)
        or points, view (azimuth, elevation) in degrees, frames: Frenet
        frames drawn along the curves (0..200), chart: the curvature and
        torsion panel, mesh: cells per parameter or box axis (4..200). None
        takes the command's default (default())."""
        if size is None:
            size = (default("width"), default("height"))
        if view is None:
            view = (default("azimuth"), default("elevation"))
        frames, mesh = _or_default(frames, "frames"), _or_default(mesh, "mesh")
        if result is None and not surfaces_only:
            result = self.trace(tol=tol, depth=depth, time_limit=time_limit, fit_tol=0.0)
        handle = None
        if result is not None and not surfaces_only:
            if result.problem is not self:
                raise _lib.InputError("the result is a trace of another problem")
            handle = result._native()[0]
        lib = _lib.library()
        err = _lib.new_error()
        with self._lock:
            st = lib.ic_problem_plot(os.fspath(path).encode(), self._handle, handle,
                                     int(size[0]), int(size[1]), float(view[0]),
                                     float(view[1]), int(frames), int(bool(chart)), int(mesh),
                                     ctypes.byref(err))
            _lib.check(st, err)

    def _repr_html_(self):
        """The interactive view in a notebook (the surfaces only: a trace is
        shown by the TraceResult's own view)."""
        return view_html(lambda path, **kw: self.plot(path, surfaces_only=True, **kw))

    def __repr__(self):
        return "Problem(%r%s)" % (self.title or self._name, ", self" if self.is_self else "")


class TraceResult:
    """The whole intersection: `curves` (Curve objects), `points`
    (SpecialPoint objects: tangential and singular points), `report` (a
    dict: what was proven, docs/output-formats.md), `complete` (the
    report's verdict), `document` (the whole trace document), `problem` and
    `options` (the trace's), `certificate` (the certificate file's JSON
    text when traced with certificate=True and the checker ran, else None).
    Pickles without its native handles (a plot of an unpickled result
    traces again with the same options)."""

    def __init__(self, document, problem, options, handles=None, certificate=None):
        self.document = document
        self.certificate = certificate
        self.problem = problem
        self.options = dict(options)
        self.curves = [Curve(c) for c in document["curves"]]
        self.points = [SpecialPoint(p) for p in document["points"]]
        self.report = document["report"]
        self.complete = bool(self.report["complete"])
        self._handles = None
        if handles is not None:
            self._handles = handles
            self._finalizer = weakref.finalize(self, _free_trace, *handles)

    def _native(self):
        """The library's result and pair, traced again if this result came
        through pickling."""
        if self._handles is None:
            again = self.problem.trace(**self.options)
            again._finalizer.detach()  # the handles are this result's from here
            self._handles = again._handles
            self._finalizer = weakref.finalize(self, _free_trace, *self._handles)
        return self._handles

    def __getstate__(self):
        return {"document": self.document, "problem": self.problem, "options": self.options,
                "certificate": self.certificate}

    def __setstate__(self, state):
        self.__init__(state["document"], state["problem"], state["options"],
                      certificate=state.get("certificate"))

    def __eq__(self, other):
        """Equal when the documents are (every number the same double)."""
        return isinstance(other, TraceResult) and self.document == other.document

    __hash__ = None

    def plot(self, path, **options):
        """Draws this result: Problem.plot(path, result=self, ...)."""
        self.problem.plot(path, result=self, **options)

    def _repr_html_(self):
        return view_html(lambda path, **kw: self.plot(path, **kw))

    def __repr__(self):
        return "TraceResult(%d curves, %d points, complete=%s)" % (
            len(self.curves), len(self.points), self.complete)
