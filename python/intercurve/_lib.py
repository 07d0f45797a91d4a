"""Finding and loading the shared library, its functions' signatures, and
its errors as Python exceptions (docs/python.md, "The library")."""

import ctypes
import ctypes.util
import os
import threading

# include/intercurve/common.h: ic_status and the sizes of ic_error's buffers
IC_OK = 0
IC_ERR_INVALID = 1
IC_ERR_PARSE = 2
IC_ERR_NOMEM = 3
IC_ERR_DOMAIN = 4
IC_ERR_UNABLE = 5
IC_ERR_IO = 6
_ERROR_PATH_LEN = 160
_ERROR_MESSAGE_LEN = 320

_LIB_NAME = "libintercurve.so"


class Error(Exception):
    """An error of the library: `code` (the ic_status number), `status`
    (its name: "invalid argument", ...), `path` (the JSON path of the fault in
    a problem, or ""), `column` (1-based column in a formula, or 0) and
    `message` (the library's message)."""

    def __init__(self, message, code=IC_ERR_INVALID, status="", path="", column=0):
        self.message = message
        self.code = code
        self.status = status
        self.path = path
        self.column = column
        where = "".join(
            [path + ": " if path else "", "column %d: " % column if column else ""])
        super().__init__(where + message)

    def __reduce__(self):  # errors cross process boundaries (batch)
        return (type(self), (self.message, self.code, self.status, self.path, self.column))


class InputError(Error, ValueError):
    """The input is wrong: a malformed or invalid problem, an option out of
    range, a point given with the wrong number of values."""


class ComputationError(Error, RuntimeError):
    """The input is valid but the computation cannot be done: the point is
    not on the surfaces, a Newton iteration did not converge, a file could
    not be written, memory ran out."""


class _IcError(ctypes.Structure):
    # ic_error of include/intercurve/common.h
    _fields_ = [
        ("code", ctypes.c_int),
        ("column", ctypes.c_int),
        ("path", ctypes.c_char * _ERROR_PATH_LEN),
        ("message", ctypes.c_char * _ERROR_MESSAGE_LEN),
    ]


def _installed_library():
    """The library `make install` put beside this package: _installed.py,
    written by the install, records its path (absent in a source tree)."""
    try:
        from . import _installed
    except ImportError:
        return None
    return _installed.LIBRARY


def _candidates():
    """Where the library is looked for, in order: $INTERCURVE_LIB; the
    library installed with this package (make install); the build directory
    of the source tree this package sits in (python/intercurve ->
    build/libintercurve.so); the system's loader (ctypes.util.find_library)."""
    env = os.environ.get("INTERCURVE_LIB")
    if env:
        return [env]
    here = os.path.dirname(os.path.abspath(__file__))
    found = [_installed_library(),
             os.path.normpath(os.path.join(here, "..", "..", "build", _LIB_NAME))]
    system = ctypes.util.find_library("intercurve") or _LIB_NAME
    return [f for f in found if f and os.path.exists(f)] + [system]


def _declare(lib):
    c = ctypes
    vp, err, status = c.c_void_p, c.POINTER(_IcError), c.c_int
    pvp, pcp, psz = c.POINTER(c.c_void_p), c.POINTER(c.c_void_p), c.POINTER(c.c_size_t)
    sigs = {
        "ic_status_name": (c.c_char_p, [status]),
        "ic_problem_load": (status, [pvp, c.c_char_p, err]),
        "ic_problem_parse": (status, [pvp, c.c_char_p, c.c_size_t, err]),
        "ic_problem_free": (None, [vp]),
        "ic_problem_title": (c.c_char_p, [vp]),
        "ic_problem_num_surfaces": (c.c_int, [vp]),
        "ic_problem_surface_name": (c.c_char_p, [vp, c.c_int]),
        "ic_problem_is_self": (c.c_int, [vp]),
        "ic_problem_trace": (status, [pvp, pvp, vp, c.c_double, c.c_int, c.c_double,
                                      c.c_int, c.c_double, err]),
        "ic_problem_trace_keep_certificate": (status, [pvp, pvp, vp, c.c_double, c.c_int,
                                                       c.c_double, c.c_int, c.c_double, err]),
        "ic_trace_result_certificate": (c.c_char_p, [vp]),
        "ic_trace_result_free": (None, [vp]),
        "ic_pair_free": (None, [vp]),
        "ic_trace_json_alloc": (status, [pcp, psz, vp, vp, err]),
        "ic_problem_verify_json": (status, [pcp, psz, vp, c.c_char_p, err]),
        "ic_problem_verify_certificate_json": (status, [pcp, psz, vp, c.c_char_p, c.c_char_p,
                                                        err]),
        "ic_problem_point_json": (status, [pcp, psz, vp, c.POINTER(c.c_double), c.c_int,
                                           c.c_int, c.c_int, c.c_char_p, c.c_double, err]),
        "ic_problem_plot": (status, [c.c_char_p, vp, vp, c.c_int, c.c_int, c.c_double,
                                     c.c_double, c.c_int, c.c_int, c.c_int, err]),
        "ic_free": (None, [vp]),
        "ic_default_value": (c.c_double, [c.c_char_p]),
    }
    for name, (res, args) in sigs.items():
        f = getattr(lib, name)
        f.restype = res
        f.argtypes = args


_lock = threading.Lock()
_lib = None


def library():
    """The loaded library (ctypes.CDLL), loaded on first use."""
    global _lib
    with _lock:
        if _lib is None:
            tried = []
            for path in _candidates():
                try:
                    lib = ctypes.CDLL(path)
                except OSError as e:
                    tried.append("%s (%s)" % (path, e))
                    continue
                _declare(lib)
                _lib = lib
                break
            else:
                raise ImportError(
                    "intercurve: cannot load the shared library; tried " + "; ".join(tried)
                    + ". Build it (make) or set INTERCURVE_LIB to its path.")
        return _lib


def library_path():
    """The file the library was loaded from (for messages and tests)."""
    return library()._name


def new_error():
    return _IcError()


def check(status, err, input_codes=(IC_ERR_INVALID, IC_ERR_PARSE)):
    """Raises the Python exception of a failed call: InputError for the
    codes that are the caller's mistakes, ComputationError otherwise."""
    if status == IC_OK:
        return
    cls = InputError if status in input_codes else ComputationError
    raise cls(err.message.decode("utf-8", "replace"), status,
              library().ic_status_name(status).decode(), err.path.decode("utf-8", "replace"),
              err.column)


def take_text(buf, length):
    """The text of a document the library allocated, freed here."""
    try:
        return ctypes.string_at(buf, length.value).decode("utf-8")
    finally:
        library().ic_free(buf)
