"""The package's defaults are the library's (include/intercurve/defaults.h,
through ic_default_value): the same values the command prints in its --help,
so Python, the command and docs/cli.md cannot drift apart."""

import json
import math
import os
import re
import subprocess

import pytest

import intercurve as ic


def command_defaults(command):
    """{option: default text} from `intercurve COMMAND --help`, the command
    next to the library under test."""
    lib = os.environ.get("INTERCURVE_LIB")
    if not lib:
        pytest.skip("INTERCURVE_LIB not set: no command to ask")
    exe = os.path.join(os.path.dirname(lib), "intercurve")
    text = subprocess.run([exe, command, "--help"], capture_output=True, text=True,
                          check=True).stdout
    out, option = {}, None
    for line in text.splitlines():
        m = re.match(r"  (--[a-z-]+)", line)
        if m:
            option = m.group(1)
        d = re.search(r"default (\S+)$", line)
        if option and d:
            out[option] = d.group(1)
    return out


def test_trace_defaults_match_the_command():
    d = command_defaults("trace")
    assert float(d["--tol"]) == ic.default("tol") == 1e-11
    assert int(d["--depth"]) == ic.default("depth") == 6
    assert float(d["--fit-tol"]) == ic.default("fit_tol") == 1e-9
    assert int(d["--threads"]) == ic.default("threads") == 0


def test_point_and_plot_defaults_match_the_command():
    p = command_defaults("point")
    assert int(p["--order"]) == ic.default("point_order") == 4
    assert float(p["--point-tol"]) == ic.default("point_tol") == 1e-6
    q = command_defaults("plot")
    assert q["--view"] == "%g,%g" % (ic.default("azimuth"), ic.default("elevation")) == "35,25"
    assert q["--size"] == "%gx%g" % (ic.default("width"), ic.default("height")) == "1400x800"
    assert int(q["--frames"]) == ic.default("frames") == 8
    assert int(q["--mesh"]) == ic.default("mesh") == 36


def test_unknown_default_is_an_error():
    for name in ("no-such-option", None, ""):
        with pytest.raises(KeyError):
            ic.default(name)


def test_integer_defaults_are_ints():
    assert isinstance(ic.default("depth"), int) and isinstance(ic.default("mesh"), int)
    assert isinstance(ic.default("tol"), float)


def test_closed_form_point_takes_its_order_as_the_command_does():
    """`intercurve point --method closed-form` without --order gives order 3
    (the closed forms' highest); so does the package."""
    p = ic.Problem.load(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                     "viviani.json"))
    r = p.point(at=(1.5, 0.8660254037844386, 1.0), method="closed-form")
    assert ic.default("point_closed_form_order") == 3
    assert r.order == 3


def test_trace_without_options_uses_the_defaults():
    p = ic.Problem.load(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                     "viviani-implicit.json"))
    r = p.trace()
    assert r.options["tol"] == 1e-11 and r.options["depth"] == 6
    assert r.options["fit_tol"] == 1e-9 and r.options["threads"] == 0


def test_report_says_which_size_each_stage_used():
    """Two implicit surfaces are searched at the box's diagonal L0 (docs/tracing.md,
    "Scale"); the rest of the trace and the fit at the found size L1 <= L0."""
    path = os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                        "viviani-implicit.json")
    with open(path) as f:
        box = json.load(f)["box"]
    diagonal = math.sqrt(sum((hi - lo) ** 2 for lo, hi in box))  # 5 sqrt(3)
    rep = ic.Problem.load(path).trace().report
    # the same few operations in another order: a few ulps
    assert rep["search_scale"] == pytest.approx(diagonal, rel=1e-15)
    assert 1e-3 * rep["search_scale"] <= rep["scale"] <= rep["search_scale"]
    assert rep["fit_tolerance"] == pytest.approx(1e-9 * rep["scale"], rel=1e-15)
