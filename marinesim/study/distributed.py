"""Many independent tasks, each returning a short vector of numbers, run serially or on Dask, their results
kept in a Zarr store so that an interrupted study resumes with only what is missing.

The store is a Zarr group: ``values`` (tasks, values) float64, NaN until a task's row is written; ``done``
(tasks,) bool; the attribute ``fingerprint`` names the study (inputs and settings) the rows belong to. Only
this process writes the store: results come back to it and are flushed every :data:`FLUSH_S` and at the end
(a kill loses at most that much work). A store with another fingerprint or shape is refused, never mixed.

On Dask each task is one function call in a worker process with one thread; BLAS, OpenMP and FFTW are
pinned to one thread per worker (:data:`ONE_THREAD`), so a task computes the same bits on a cluster as in
this process. Dask, distributed and Zarr are the optional extra ``cluster``.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from contextlib import ExitStack
from pathlib import Path

import numpy as np

from marinesim import progress
from marinesim.atomic import signals_held
from marinesim.errors import MarinesimError, ParameterError

FLUSH_S = 2.0
"""Seconds between two writes of finished rows to the store."""
IN_FLIGHT_PER_WORKER = 64
"""Tasks handed to the scheduler ahead of the results, per worker (a whole study is never submitted at once)."""
ROWS_PER_CHUNK = 4096
ONE_THREAD = {name: "1" for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                                     "NUMBA_NUM_THREADS")}
"""Environment of a worker process: one thread for every numeric library (a task's ocean asks FFTW for one itself)."""


def _import_cluster():
    try:
        import zarr
        from dask import distributed
    except ImportError as error:
        raise MarinesimError(f"the time-domain study needs the optional extra: pip install 'marinesim[cluster]' "
                             f"({error.name} is missing)") from None
    return zarr, distributed


def open_store(path: Path, tasks: int, values: int, fingerprint: str):
    """The Zarr group at ``path`` for ``tasks`` rows of ``values`` numbers: created if absent, reopened if it
    holds the same study (``fingerprint`` and shape), refused otherwise."""
    zarr, _ = _import_cluster()
    path = Path(path)
    if path.exists():
        try:
            group = zarr.open_group(str(path), mode="r+")
            same = (group.attrs.get("fingerprint") == fingerprint and group["values"].shape == (tasks, values))
        except Exception as error:  # any damage: the store is not one we can trust
            raise MarinesimError(f"{path}: not a marinesim study store ({type(error).__name__}); "
                                 f"remove it or give another --out") from None
        if not same:
            raise MarinesimError(f"{path} holds another study (other inputs or settings); remove it or give "
                                 f"another --out")
        return group
    group = zarr.open_group(str(path), mode="w")
    chunk = min(tasks, ROWS_PER_CHUNK)
    group.create_array("values", shape=(tasks, values), chunks=(chunk, values), dtype="f8", fill_value=np.nan)
    group.create_array("done", shape=(tasks,), chunks=(chunk,), dtype="bool", fill_value=False)
    group.attrs["fingerprint"] = fingerprint
    return group


def run_tasks(function: Callable[[int], np.ndarray], tasks: int, values: int, store: Path, fingerprint: str,
              scheduler: str | None = None, workers: int | None = None, serial: bool = False) -> np.ndarray:
    """``function(i)`` (a picklable top-level function returning ``values`` floats) for every task ``i`` not
    yet in ``store``; returns all rows (tasks, values). ``serial`` runs here; else on the Dask scheduler at
    ``scheduler`` (``tcp://host:port``) or on a new LocalCluster of ``workers`` processes (default: the CPUs
    this process may use). Shows a progress bar counting tasks."""
    if tasks < 1 or values < 1:
        raise ParameterError(f"a study needs at least one task and one value, got {tasks} x {values}")
    group = open_store(store, tasks, values, fingerprint)
    missing = np.flatnonzero(~group["done"][:])
    rows = np.array(group["values"][:])
    if missing.size == 0:
        return rows
    pending: dict[int, np.ndarray] = {}
    last = time.monotonic()

    def keep(index: int, row: np.ndarray) -> None:
        nonlocal last
        row = np.asarray(row, dtype=float).reshape(-1)
        if row.size != values:
            raise MarinesimError(f"task {index} returned {row.size} values, expected {values}")
        rows[index] = pending[index] = row
        if time.monotonic() - last >= FLUSH_S:
            _flush(group, pending)
            last = time.monotonic()

    try:
        with progress.task("time-domain tasks", int(missing.size), "task") as bar:
            if serial:
                for index in missing:
                    keep(int(index), function(int(index)))
                    bar.update(1)
            else:
                _run_on_dask(function, missing, scheduler, workers, keep, bar)
    finally:
        _flush(group, pending)
    return rows


def _flush(group, pending: dict[int, np.ndarray]) -> None:
    """Write the finished rows in ``pending`` (then forget them): values first, then their done flags."""
    if not pending:
        return
    index = np.fromiter(sorted(pending), dtype=np.int64)
    lo, hi = int(index[0]), int(index[-1]) + 1
    block = np.array(group["values"][lo:hi])
    done = np.array(group["done"][lo:hi])
    block[index - lo] = np.stack([pending[i] for i in index.tolist()])
    done[index - lo] = True
    group["values"][lo:hi] = block
    group["done"][lo:hi] = done
    pending.clear()


def _run_on_dask(function, missing: np.ndarray, scheduler: str | None, workers: int | None, keep, bar) -> None:
    _, distributed = _import_cluster()
    with ExitStack() as stack:
        if scheduler is None:
            count = workers or len(os.sched_getaffinity(0))
            with signals_held():  # a Ctrl-C inside Dask's start-up is swallowed there and the study then hangs
                cluster = stack.enter_context(distributed.LocalCluster(
                    n_workers=count, threads_per_worker=1, processes=True, dashboard_address=None,
                    scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},  # its health/metrics HTTP server:
                    env=ONE_THREAD, silence_logs=40))  # the loopback, any free port (8787 taken: a warning)
                client = stack.enter_context(distributed.Client(cluster))
        else:
            try:
                client = stack.enter_context(distributed.Client(scheduler, timeout=30))
            except (OSError, TimeoutError) as error:
                raise MarinesimError(f"cannot reach the Dask scheduler at {scheduler}: {error}") from None
        window = IN_FLIGHT_PER_WORKER * max(len(client.scheduler_info()["workers"]), 1)
        queue = iter(missing.tolist())
        running = distributed.as_completed()
        for index in queue:
            running.add(client.submit(function, index, key=f"task-{index}", pure=False))
            if running.count() >= window:
                break
        for future in running:
            keep(int(future.key.rpartition("-")[2]), future.result())
            bar.update(1)
            future.release()
            nxt = next(queue, None)
            if nxt is not None:
                running.add(client.submit(function, nxt, key=f"task-{nxt}", pure=False))
