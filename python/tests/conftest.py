"""Shared pieces of the Python package's tests (docs/python.md, "Tests")."""

import os

import numpy as np
import pytest

EXAMPLES = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))


def example(name):
    return os.path.join(EXAMPLES, name)


def viviani_derivatives(theta):
    """Viviani's curve of the sphere x^2 + y^2 + z^2 = 4 and the cylinder
    (x - 1)^2 + y^2 = 1, r(theta) = (1 + cos theta, sin theta, 2 sin(theta/2)),
    theta in [0, 4 pi): r', r'', r''' by hand."""
    c, s = np.cos(theta), np.sin(theta)
    c2, s2 = np.cos(theta / 2), np.sin(theta / 2)
    d1 = np.stack([-s, c, c2], axis=-1)
    d2 = np.stack([-c, -s, -s2 / 2], axis=-1)
    d3 = np.stack([s, -c, -c2 / 4], axis=-1)
    return d1, d2, d3


def viviani_kappa_tau(theta):
    """Curvature |r' x r''| / |r'|^3 and torsion (r' x r'') . r''' / |r' x r''|^2
    of Viviani's curve at theta."""
    d1, d2, d3 = viviani_derivatives(theta)
    cr = np.cross(d1, d2)
    kappa = np.linalg.norm(cr, axis=-1) / np.linalg.norm(d1, axis=-1) ** 3
    tau = np.sum(cr * d3, axis=-1) / np.sum(cr * cr, axis=-1)
    return kappa, tau


def viviani_theta(xyz):
    """The parameter theta in [0, 4 pi) of points of Viviani's curve: the
    angle on the cylinder, plus 2 pi on the lower half (z = 2 sin(theta/2) < 0)."""
    xyz = np.asarray(xyz)
    theta = np.mod(np.arctan2(xyz[..., 1], xyz[..., 0] - 1), 2 * np.pi)
    return np.where(xyz[..., 2] < 0, theta + 2 * np.pi, theta)


def viviani_length():
    """The integral of |r'| = sqrt(1 + cos^2(theta/2)) over [0, 4 pi] by
    Gauss-Legendre on 64 panels of 20 nodes (the integrand is analytic)."""
    x, w = np.polynomial.legendre.leggauss(20)
    edges = np.linspace(0, 4 * np.pi, 65)
    total = 0.0
    for a, b in zip(edges[:-1], edges[1:]):
        th = (a + b) / 2 + (b - a) / 2 * x
        total += (b - a) / 2 * np.sum(w * np.sqrt(1 + np.cos(th / 2) ** 2))
    return total


@pytest.fixture(scope="session")
def viviani_trace():
    import intercurve as ic
    return ic.Problem.load(example("viviani-implicit.json")).trace(tol=1e-10)
