"""Where the loop's refits run: Dask's distributed scheduler.

By default an in-process ``LocalCluster`` (one worker process per core, at most ``workers``,
one thread each: the models' matrices are small, and BLAS threads would only fight over the
cores); ``scheduler`` (an address such as ``tcp://10.0.0.5:8786``) joins a running cluster
instead, whose workers must have chest-observer installed at the same version.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from ..errors import ObserverError

MAX_LOCAL_WORKERS = 4  # the local cluster's default: one worker per core, at most this many
# one BLAS thread per worker process, set before the workers import numpy
_WORKER_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


class ClusterError(ObserverError, RuntimeError):
    """The scheduler cannot be reached or the cluster cannot start."""


class Runner:
    """Runs calls of one function over argument tuples on the cluster, results in order."""

    def __init__(self, client: Any) -> None:
        self.client = client

    @property
    def workers(self) -> int:
        return len(self.client.scheduler_info().get("workers", {})) or 1

    def map(self, f: Callable[..., Any], args: list[tuple]) -> list[Any]:
        if not args:
            return []
        futures = [self.client.submit(f, *a, pure=False) for a in args]
        return list(self.client.gather(futures))


@contextmanager
def cluster(scheduler: str | None = None, workers: int | None = None) -> Iterator[Runner]:
    """A :class:`Runner` on the cluster at ``scheduler``, or on a local one for this call."""
    from dask.distributed import Client, LocalCluster

    if scheduler:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as e:
            raise ClusterError(f"cannot reach the Dask scheduler at {scheduler}: {e}") from e
        try:
            yield Runner(client)
        finally:
            client.close()
        return
    n = workers or min(MAX_LOCAL_WORKERS, len(os.sched_getaffinity(0)))
    local = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                         dashboard_address=":0", silence_logs=logging.CRITICAL,
                         env=_WORKER_ENV)
    client = Client(local)
    try:
        yield Runner(client)
    finally:
        client.close()
        local.close()
