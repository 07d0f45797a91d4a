"""The apparatus at one point against Viviani's parametrisation
(conftest.py) and the Frenet equations."""

import numpy as np
import pytest

import intercurve as ic
from conftest import example, viviani_derivatives, viviani_kappa_tau

# exact to rounding at a located point (docs/local.md): a few ulps of the
# values (~1), left three digits
POINT_TOL = 1e-12
# against central differences of step 1e-5: their h^2 error, ~1e-10, and
# rounding eps/h ~ 1e-11
DIFFERENCE_TOL = 1e-8


@pytest.fixture(scope="module")
def viviani():
    return ic.Problem.load(example("viviani.json"))


def test_branch_point(viviani):
    q = viviani.point(at=(2, 0, 0), order=4)
    assert q.type == "branch-point"
    assert np.allclose(q.xyz, [2, 0, 0], atol=1e-12)
    assert len(q.branches) == 2
    # theta = 0 and 2 pi: the two branches of the figure-eight
    expected = sorted(viviani_kappa_tau(np.array([0.0, 2 * np.pi]))[1])
    assert sorted(b.tau for b in q.branches) == pytest.approx(expected, abs=1e-9)
    for br in q.branches:
        assert br.kappa == pytest.approx(viviani_kappa_tau(0.0)[0], abs=1e-9)
        assert br.derivatives.shape == (4, 3)
        # t = r'/|r'| = (0, 1, +-1)/sqrt(2), up to orientation
        assert abs(br.t[0]) < 1e-9 and abs(abs(br.t[1]) - np.sqrt(0.5)) < 1e-9


@pytest.mark.parametrize("by", ["at", "params"])
def test_transversal_point(viviani, by):
    theta = np.pi / 3  # (1.5, sqrt(3)/2, 1): cylinder (v1, v2) = (1, pi/6), sphere (pi/6, pi/6)
    X = np.array([1 + np.cos(theta), np.sin(theta), 2 * np.sin(theta / 2)])
    q = (viviani.point(at=X, order=4) if by == "at"
         else viviani.point(params=(1, np.pi / 6, np.pi / 6, np.pi / 6), order=4))
    assert q.type == "transversal" and len(q.branches) == 1
    assert np.allclose(q.xyz, X, atol=POINT_TOL)
    assert q.params.shape == (2, 2)
    assert np.allclose(q.params, [[1, np.pi / 6], [np.pi / 6, np.pi / 6]], atol=1e-12)
    br = q.branches[0]
    kappa, tau = viviani_kappa_tau(theta)
    assert br.kappa == pytest.approx(kappa, abs=POINT_TOL)
    assert br.tau == pytest.approx(tau, abs=POINT_TOL)
    d1, d2, _ = viviani_derivatives(theta)
    speed = np.linalg.norm(d1)
    t = d1 / speed
    sign = np.sign(np.dot(br.t, t))  # the library orients by N_A x N_B
    assert np.allclose(br.t, sign * t, atol=POINT_TOL)
    c = br.derivatives
    assert c.shape == (4, 3)
    assert np.allclose(c[0], br.t, atol=POINT_TOL)
    # c'' = (r'' - (r'' . t) t) / |r'|^2, whichever the orientation
    assert np.allclose(c[1], (d2 - np.dot(d2, t) * t) / speed ** 2, atol=POINT_TOL)
    # Frenet: c''' = -kappa^2 t + kappa' n + kappa tau b
    assert np.dot(c[2], br.t) == pytest.approx(-kappa ** 2, abs=POINT_TOL)
    assert np.dot(c[2], br.b) == pytest.approx(kappa * tau, abs=POINT_TOL)
    # kappa' and tau' by central differences of the closed forms in theta
    # (error ~h^2 = 1e-10 times the third derivative), over ds/dtheta = |r'|
    h = 1e-5
    kp, tp = (np.array(viviani_kappa_tau(theta + h)) - viviani_kappa_tau(theta - h)) / (2 * h)
    kp, tp = sign * kp / speed, sign * tp / speed  # s along the library's t
    assert br.kappa_prime == pytest.approx(kp, abs=DIFFERENCE_TOL)
    assert br.tau_prime == pytest.approx(tp, abs=DIFFERENCE_TOL)
    assert np.dot(c[2], br.n) == pytest.approx(kp, abs=DIFFERENCE_TOL)
    # the fourth derivative: -3 kappa kappa' t + (...) n + (2 kappa' tau + kappa tau') b
    assert np.dot(c[3], br.t) == pytest.approx(-3 * kappa * kp, abs=DIFFERENCE_TOL)
    assert np.dot(c[3], br.b) == pytest.approx(2 * kp * tau + kappa * tp, abs=DIFFERENCE_TOL)


def test_order_sets_the_derivatives(viviani):
    q = viviani.point(at=(1.5, np.sqrt(3) / 2, 1), order=7)
    assert q.order == 7 and q.branches[0].derivatives.shape == (7, 3)
    assert np.isfinite(q.branches[0].derivatives).all()


def test_not_on_the_surfaces(viviani):
    with pytest.raises(ic.ComputationError) as e:
        viviani.point(at=(1.5, np.sqrt(3) / 2, 1.2))
    assert e.value.message.startswith("not on the surfaces: residual")
    assert e.value.code == 5  # IC_ERR_UNABLE
    # a wide search (point_tol 10) from the origin ends on neither surface: the
    # residual test refuses it whatever point_tol allowed (docs/local.md)
    with pytest.raises(ic.ComputationError) as e:
        viviani.point(at=(0, 0, 0), point_tol=10)
    first, why = e.value.message.split("\n", 1)
    assert first.startswith("not on the surfaces: residual") and "only widens" in why


@pytest.mark.parametrize("kwargs, match", [
    (dict(at=(1, 2)), "three coordinates"),
    (dict(at=(2, 0, 0), order=17), "order"),
    (dict(at=(2, 0, 0), method="newton"), "unknown method"),
    (dict(at=(2, 0, 0), params=(0, 0, 0, 0)), "not both"),
    (dict(), "not both or neither"),
    (dict(params=(0, 1)), "param"),
])
def test_wrong_point_values_are_input_errors(viviani, kwargs, match):
    with pytest.raises(ic.InputError, match=match):
        viviani.point(**kwargs)
