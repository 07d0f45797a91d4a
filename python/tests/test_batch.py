"""Batches: 50 problems on a local Dask cluster of two processes and on a
pool of two processes, each result the same, number for number, as the
single-process trace; and every one a circle of the right size."""

import numpy as np
import pytest

import intercurve as ic
from conftest import example

NPROBLEMS = 50


def sphere_and_plane(k):
    """Problem k: a sphere of radius r cut by the plane n . X = d (n a unit
    normal tilted by phi from z): a circle of radius sqrt(r^2 - d^2)."""
    r, phi, d = 1 + 0.01 * k, 0.03 * k, 0.2 + 0.005 * k
    problem = {
        "title": "sphere and plane %d" % k,
        "surfaces": [{"type": "implicit", "f": "x^2 + y^2 + z^2 - %r" % (r * r)},
                     {"type": "implicit", "f": "%r*x + %r*z - %r" % (np.sin(phi), np.cos(phi), d)}],
        "box": [[-2, 2], [-2, 2], [-2, 2]]}
    return problem, np.sqrt(r * r - d * d)


@pytest.fixture(scope="module")
def problems():
    return [sphere_and_plane(k) for k in range(NPROBLEMS)]


@pytest.fixture(scope="module")
def single(problems):
    return [ic.Problem.from_dict(p).trace(depth=4) for p, _ in problems]


def test_single_process_results_are_the_circles(problems, single):
    for (_, rho), r in zip(problems, single):
        (c,) = r.curves
        assert c.shape == "circle" and c.closed
        assert abs(c.length - 2 * np.pi * rho) < 1e-9 * rho
        assert np.allclose(c.kappa, 1 / rho, atol=1e-9)


def test_batch_in_one_process_is_the_loop(problems, single):
    got = ic.batch([p for p, _ in problems[:5]], workers=1, depth=4)
    assert got == single[:5]


def test_batch_on_a_local_dask_cluster(problems, single):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        got = ic.batch([p for p, _ in problems], client=client, depth=4)
    assert len(got) == NPROBLEMS
    for k, (g, s) in enumerate(zip(got, single)):
        assert g == s, "problem %d differs from the single-process trace" % k
        assert g.curves[0].xyz.tobytes() == s.curves[0].xyz.tobytes()


def test_batch_on_a_pool_of_processes(single, problems):
    items = [ic.Problem.from_dict(p) for p, _ in problems[:6]]
    items += [example("viviani-implicit.json"), example("cusp.json")]
    got = ic.batch(items, workers=2, depth=4)
    assert got[:6] == single[:6]
    assert got[6] == ic.Problem.load(example("viviani-implicit.json")).trace(depth=4)
    assert got[7] == ic.Problem.load(example("cusp.json")).trace(depth=4)


def test_batch_raises_the_failure():
    bad = {"surfaces": [{"type": "implicit", "f": "z"}, {"type": "implicit", "f": "x + ("}]}
    with pytest.raises(ic.InputError) as e:
        ic.batch([sphere_and_plane(0)[0], bad], workers=2)
    assert e.value.path == "surfaces[1].f"


def test_threads_on_separate_and_shared_problems(problems, single):
    """ctypes lets the GIL go during a call: separate Problems trace at once
    in threads, and calls on one Problem wait for each other (its lock)."""
    import concurrent.futures
    separate = [ic.Problem.from_dict(p) for p, _ in problems[:8]]
    shared = ic.Problem.from_dict(problems[0][0])
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        got = list(pool.map(lambda q: q.trace(depth=4), separate))
        again = list(pool.map(lambda _: shared.trace(depth=4), range(4)))
    assert got == single[:8]
    assert all(r == single[0] for r in again)
