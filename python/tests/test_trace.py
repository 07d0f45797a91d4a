"""Traces against closed forms: Viviani's curve (its length by quadrature,
its curvature and torsion from the parametrisation in conftest.py), the
numpy arrays' shapes, the B-spline on both surfaces."""

import json
import numpy as np
import pytest

import intercurve as ic
from conftest import example, viviani_kappa_tau, viviani_length, viviani_theta

# length: the traced points' apparatus is exact to rounding at the point
# (docs/local.md); 1e-9 leaves three digits for the curves' sizes (~2)
APPARATUS_TOL = 1e-9
# relative: the length is summed over the steps at --tol 1e-10
LENGTH_REL_TOL = 1e-8
# length: distance of a traced point from either surface
ON_SURFACE_TOL = 1e-10


def sphere(p):
    return np.sum(p * p, axis=-1) - 4


def cylinder(p):
    return (p[..., 0] - 1) ** 2 + p[..., 1] ** 2 - 1


def test_viviani_one_closed_curve(viviani_trace):
    r = viviani_trace
    # complete by the tracer's account and proven by the certificate, the
    # branch point in its singular box (docs/tracing.md)
    assert r.report["tracer_complete"] is True
    assert r.complete and r.report["complete"] is True
    assert r.report["certificate"]["checked"] is True
    assert r.report["certificate"]["accepted"] is True
    assert r.report["certificate"]["singular"] > 0
    assert r.report["certificate"]["reason"] is None
    assert len(r.curves) == 1
    c = r.curves[0]
    assert c.closed and c.type == "transversal" and c.ends == ["closed", "closed"]
    assert abs(c.length - viviani_length()) < LENGTH_REL_TOL * viviani_length()
    # the branch point (2, 0, 0) where the curve crosses itself
    assert [p.type for p in r.points] == ["branch-point"]
    assert np.allclose(r.points[0].xyz, [2, 0, 0], atol=1e-9)
    assert r.points[0].branches == 2


def test_arrays_shapes_and_frames(viviani_trace):
    c = viviani_trace.curves[0]
    n = len(c)
    assert n > 50
    for name in ("s", "kappa", "tau", "angle"):
        assert getattr(c, name).shape == (n,), name
    for name in ("xyz", "t", "n", "b"):
        assert getattr(c, name).shape == (n, 3), name
    assert c.params.shape == (n, 2, 2) and np.isnan(c.params).all()  # implicit surfaces
    assert np.all(np.diff(c.s) > 0)
    # points on both surfaces, t, n, b a right-handed orthonormal frame
    assert np.max(np.abs(sphere(c.xyz))) < ON_SURFACE_TOL
    assert np.max(np.abs(cylinder(c.xyz))) < ON_SURFACE_TOL
    for v in (c.t, c.n, c.b):
        assert np.allclose(np.linalg.norm(v, axis=1), 1, atol=1e-12)
    assert np.allclose(np.cross(c.t, c.n), c.b, atol=1e-12)


def test_viviani_curvature_and_torsion(viviani_trace):
    c = viviani_trace.curves[0]
    away = np.abs(c.xyz[:, 2]) > 0.1  # the branch point's two branches meet at z = 0
    assert away.sum() > 0.8 * len(c)
    kappa, tau = viviani_kappa_tau(viviani_theta(c.xyz[away]))
    assert np.max(np.abs(c.kappa[away] - kappa)) < APPARATUS_TOL
    assert np.max(np.abs(c.tau[away] - tau)) < APPARATUS_TOL


def test_parametric_viviani_matches_the_implicit_one(viviani_trace):
    r = ic.Problem.load(example("viviani.json")).trace(tol=1e-10)
    assert len(r.curves) == 1 and r.curves[0].closed
    c = r.curves[0]
    assert abs(c.length - viviani_trace.curves[0].length) < LENGTH_REL_TOL * c.length
    # the cylinder's parameters (v1, v2): R = (1 + sin v2, cos v2, v1)
    u = c.params[:, 0]
    assert np.allclose(np.stack([1 + np.sin(u[:, 1]), np.cos(u[:, 1]), u[:, 0]], axis=1),
                       c.xyz, atol=1e-9)


def test_bspline_interpolates_and_stays_on_the_surfaces(viviani_trace):
    c = viviani_trace.curves[0]
    fit_tol = viviani_trace.report["fit_tolerance"]
    assert c.bspline is not None and c.bspline.degree == 5
    # the piecewise quintic passes every traced point: through its nodes, and
    # within a tenth of the fit tolerance through those its merged stretches
    # bridge (docs/bspline.md)
    assert np.max(np.linalg.norm(c.bspline(c.s) - c.xyz, axis=1)) < 0.1 * fit_tol
    # between the nodes: on both surfaces within the fit tolerance (a length;
    # |grad| >= 2 on both near the curve, so |f| / 2 bounds the distance)
    mid = (c.s[:-1] + c.s[1:]) / 2
    x = c.bspline(mid)
    assert x.shape == (len(mid), 3)
    assert np.max(np.abs(sphere(x))) / 2 < fit_tol
    assert np.max(np.abs(cylinder(x))) / 2 < fit_tol


def test_no_bsplines_without_fit():
    r = ic.Problem.load(example("viviani-implicit.json")).trace(fit_tol=0)
    assert r.curves[0].bspline is None and r.report["fit_tolerance"] is None


def test_sphere_and_plane_circle_from_a_dict():
    radius, height = 1.5, 0.4
    p = ic.Problem.from_dict({
        "title": "a sphere cut by a plane",
        "surfaces": [{"type": "implicit", "f": "x^2 + y^2 + z^2 - %r" % (radius ** 2)},
                     {"type": "implicit", "f": "z - %r" % height}],
        "box": [[-2, 2], [-2, 2], [-2, 2]]})
    assert p.title == "a sphere cut by a plane"
    r = p.trace()
    (c,) = r.curves
    rho = np.sqrt(radius ** 2 - height ** 2)
    assert c.shape == "circle" and c.closed
    assert abs(c.length - 2 * np.pi * rho) < 1e-9
    assert np.allclose(c.kappa, 1 / rho, atol=1e-9)
    assert np.allclose(c.xyz[:, 2], height, atol=1e-12)
    # a closed curve, smooth where it closes: one periodic B-spline, on the
    # circle within the fit tolerance, taken modulo its period
    b, fit_tol = c.bspline, r.report["fit_tolerance"]
    assert b.periodic and "periodic" in repr(b)
    s = np.linspace(0, c.length, 1001)
    x = b(s)
    assert np.max(np.abs(np.hypot(x[:, 0], x[:, 1]) - rho)) < fit_tol
    assert np.max(np.abs(x[:, 2] - height)) < fit_tol
    assert np.max(np.abs(b(s + c.length) - x)) < 1e-12
    assert np.max(np.abs(b(s - 3 * c.length) - x)) < 1e-12


def test_trace_options_out_of_range_are_input_errors():
    p = ic.Problem.load(example("viviani-implicit.json"))
    with pytest.raises(ic.InputError, match="depth"):
        p.trace(depth=12)
    with pytest.raises(ic.InputError, match="tol"):
        p.trace(tol=-1)
    with pytest.raises(ic.InputError, match="fit_tol"):
        p.trace(fit_tol=0.5)
    for threads in (-1, 257):
        with pytest.raises(ic.InputError, match="threads"):
            p.trace(threads=threads)


def test_trace_is_the_same_in_any_number_of_threads():
    # docs/tracing.md, "Threads": the documents equal, number for number
    p = ic.Problem.load(example("torus-sphere.json"))
    one = p.trace(depth=5, threads=1)
    for threads in (0, 2, 3):
        assert p.trace(depth=5, threads=threads) == one
    assert one.options["threads"] == 1


def test_implicit_pair_without_box_is_an_input_error():
    p = ic.Problem.from_dict({"surfaces": [{"type": "implicit", "f": "x^2 + y^2 + z^2 - 1"},
                                           {"type": "implicit", "f": "z"}]})
    with pytest.raises(ic.InputError, match="box"):
        p.trace()


def test_verify_again(viviani_trace):
    # the checker run again on the saved document, without the tracer: the
    # same verdict and the same cover (it is deterministic)
    p = ic.Problem.load(example("viviani-implicit.json"))
    again = p.verify(viviani_trace)
    assert again["accepted"] is True and again["reason"] is None
    assert again["cells"] == viviani_trace.report["certificate"]["cells"]
    # with its curve taken out the document is refused: an arc not traced
    doc = dict(viviani_trace.document, curves=[])
    refused = p.verify(doc)
    assert refused["accepted"] is False and "not traced" in refused["reason"]
    with pytest.raises(ic.InputError):
        p.verify("not a document")


def test_certificate_file():
    # trace(certificate=True) keeps the checker's cover; verify replays it
    # (every leaf proven again): the same verdict and cells, and a leaf
    # changed is refused with the node named; a file of another region is
    # bad input
    p = ic.Problem.load(example("cylinders.json"))
    t = p.trace(certificate=True)
    assert t.complete and t.certificate is not None
    cert = json.loads(t.certificate)
    assert cert["format"] == "intercurve-certificate" and cert["checked"] is True
    again = p.verify(t, certificate=t.certificate)
    assert again["accepted"] is True
    assert again["cells"] == t.report["certificate"]["cells"]
    k = next(i for i, n in enumerate(cert["cells"]) if n[0] == "regular")
    changed = dict(cert, cells=cert["cells"][:k] + [["empty"]] + cert["cells"][k + 1:])
    refused = p.verify(t, certificate=changed)
    assert refused["accepted"] is False
    assert "cells[%d]: the file says empty" % k in refused["reason"]
    other = dict(cert, region=dict(cert["region"], hi=[2, 2, 2]))
    with pytest.raises(ic.InputError, match="region"):
        p.verify(t, certificate=other)
    assert p.trace().certificate is None  # not kept unless asked for

