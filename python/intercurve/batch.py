"""Many problems at once: on the cores of this machine (processes) or on
a Dask cluster (docs/python.md, "Batches")."""

import concurrent.futures
import multiprocessing
import os

from .problem import Problem


def _as_problem(item):
    """A Problem from a Problem, a problem file's path or a dict."""
    if isinstance(item, Problem):
        return item
    if isinstance(item, dict):
        return Problem.from_dict(item)
    return Problem.load(item)


def _trace_one(item, options):
    """What a worker runs: one problem traced (a picklable TraceResult)."""
    return _as_problem(item).trace(**options)


def batch(problems, workers=None, client=None, tol=None, depth=None, fit_tol=None,
          time_limit=0.0, threads=1):
    """Traces many problems (Problem objects, problem files' paths or dicts)
    and returns their TraceResults in the same order, the same as
    [p.trace(...) for p in problems] would give, number for number.

    workers: processes on this machine (default: every core; 1: in this
    process). client: a dask.distributed Client instead: the problems go to
    its cluster (a LocalCluster, or one of dask-jobqueue on Slurm), whose
    workers must be able to import intercurve and load the library. The
    first problem that fails raises its InputError or ComputationError.
    threads: each trace's own (Problem.trace; default 1: the workers have
    the cores already). tol, depth and fit_tol as Problem.trace takes them
    (None: the command's defaults)."""
    items = list(problems)
    options = dict(tol=tol, depth=depth, fit_tol=fit_tol, time_limit=time_limit,
                   threads=threads)
    if client is not None:
        futures = client.map(_trace_one, items, options=options, pure=False)
        return client.gather(futures)
    workers = (os.cpu_count() or 1) if workers is None else int(workers)
    if workers < 1:
        raise ValueError("workers must be at least 1, got %d" % workers)
    if workers == 1 or len(items) <= 1:
        return [_trace_one(item, options) for item in items]
    # spawn: a fork would copy the locks of this process's threads
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(min(workers, len(items)),
                                                mp_context=context) as pool:
        return list(pool.map(_trace_one, items, [options] * len(items)))
