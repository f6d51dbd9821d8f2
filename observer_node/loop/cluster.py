"""Where the loop's refits run: Dask's distributed scheduler.

By default an in-process ``LocalCluster`` (one worker process per core, at most ``workers``,
one thread each: the models' matrices are small, and BLAS threads would only fight over the
cores); ``scheduler`` (an address such as ``tcp://10.0.0.5:8786``) joins a running cluster
instead, whose workers must have chest-observer installed at the same version.
"""

from __future__ import annotations

import logging
import os
import signal
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import CancelledError
from contextlib import contextmanager
from typing import Any

from ..errors import ObserverError

CONNECT_TIMEOUT_S = 10.0  # to reach a scheduler given by --scheduler
WORKERS_TIMEOUT_S = 30.0  # for a scheduler given by --scheduler to have a worker
NO_WORKERS_S = 60.0  # a cluster without a worker this long mid-run is given up on
POLL_S = 2.0  # how often a waiting map looks at the cluster
MAX_LOCAL_WORKERS = 4  # the local cluster's default: one worker per core, at most this many
# one BLAS thread per worker process, set before the workers import numpy
_WORKER_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


class ClusterError(ObserverError, RuntimeError):
    """The scheduler cannot be reached or the cluster cannot start."""


class Runner:
    """Runs calls of one function over argument tuples on the cluster, results in order."""

    def __init__(self, client: Any, where: str = "local") -> None:
        self.client = client
        self.where = where  # the scheduler's address, or "local"

    @property
    def workers(self) -> int:
        return len(self.client.scheduler_info().get("workers", {})) or 1

    def map(self, f: Callable[..., Any], args: list[tuple]) -> list[Any]:
        from distributed import KilledWorker
        from distributed.client import ClosedClientError

        if not args:
            return []
        futures: list[Any] = []
        try:
            futures = [self.client.submit(f, *a, pure=False) for a in args]
            self._wait(futures)
            return list(self.client.gather(futures))
        except KilledWorker as e:  # a refit that ended every worker it ran on (a crash)
            raise ClusterError(f"a refit ended the Dask worker it ran on, each time it was "
                               f"tried ({e}); the workers' logs say why") from None
        except KeyboardInterrupt:
            # Ctrl-C: the gather's waiting tasks end with an error nobody retrieves, which
            # asyncio would print as a page of tracebacks while the client closes
            logging.getLogger("asyncio").setLevel(logging.CRITICAL)
            raise
        except (OSError, CancelledError, ClosedClientError) as e:  # the scheduler gone?
            if self.client.status == "running":
                raise
            logging.getLogger("asyncio").setLevel(logging.CRITICAL)
            done = sum(f.status == "finished" for f in futures)
            raise ClusterError(f"lost the Dask scheduler ({self.where}), {done} of "
                               f"{len(args)} refits done: {type(e).__name__}") from None

    def _wait(self, futures: list[Any]) -> None:
        """Until every task is done, or one line when no worker has been able to run one
        for ``NO_WORKERS_S``: Dask would wait for ever (every worker gone, ending as it
        starts, or paused at its memory limit), and the loop would say nothing."""
        from distributed import wait

        since: float | None = None
        while True:
            try:
                wait(futures, timeout=POLL_S)
                return
            except TimeoutError:
                pass
            workers = self.client.scheduler_info(n_workers=-1).get("workers", {})
            status = [w.get("status") for w in workers.values()]
            if "running" in status:
                since = None
                continue
            now = time.monotonic()
            since = now if since is None else since
            if now - since >= NO_WORKERS_S:
                done = sum(f.done() for f in futures)
                self.client.cancel(futures)
                why = (f"every worker ({len(status)}) paused at its memory limit"
                       if status and set(status) == {"paused"} else
                       "no worker running" if status else "no worker")
                raise ClusterError(
                    f"the Dask cluster ({self.where}) has had {why} for {NO_WORKERS_S:g} s, "
                    f"{done} of {len(futures)} refits done: the workers' logs say why")


def check_address(scheduler: str) -> None:
    """One line for a scheduler address Dask cannot parse (``tcp://HOST:PORT``), before the
    tests are read."""
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import backends

    try:
        scheme, loc = parse_address(scheduler, strict=False)
        if scheme not in backends:
            raise ValueError(f"unknown scheme {scheme!r} (Dask knows {', '.join(backends)})")
        if scheme in ("tcp", "tls", "ws", "wss"):
            parse_host_port(loc)
    except (ValueError, TypeError) as e:
        raise ClusterError(f"--scheduler {scheduler}: not a Dask scheduler address "
                           f"(tcp://HOST:PORT): {e}") from None


def _connect(scheduler: str, timeout_s: float = CONNECT_TIMEOUT_S) -> Any:
    """A Client on the scheduler at ``scheduler``, or one line saying why not. Dask's own
    timeout covers the connection, not the handshake after it: a server that accepts and never
    answers (a web server on the port) would hold the loop forever, so the whole connection
    runs in a thread that is given up on after ``timeout_s``."""
    from dask.distributed import Client

    check_address(scheduler)
    got: dict[str, Any] = {}

    def connect() -> None:
        try:
            got["client"] = Client(scheduler, timeout=f"{timeout_s}s")
        except Exception as e:  # whatever stops the connection is reported below
            got["error"] = e

    t = threading.Thread(target=connect, name="dask-connect", daemon=True)
    t.start()
    t.join(timeout_s + 5)
    if "client" in got:
        return got["client"]
    why = got.get("error") or f"no answer within {timeout_s + 5:g} s (is it a Dask scheduler?)"
    raise ClusterError(f"cannot reach the Dask scheduler at {scheduler}: {why}")


def _check_workers(client: Any, scheduler: str,
                   timeout_s: float = WORKERS_TIMEOUT_S) -> None:
    """One line, before any fit, for a cluster that cannot run the refits: no worker within
    ``timeout_s``, or a scheduler or worker that cannot import chest-observer or has another
    version of it. Dask would send such a worker the first refit, which ends it (the task
    cannot be unpickled there), and then wait for ever for another; such a scheduler refuses
    every refit."""
    from .. import __version__

    try:
        client.wait_for_workers(1, timeout=timeout_s)
    except TimeoutError:
        raise ClusterError(f"the Dask scheduler at {scheduler} has no worker (waited "
                           f"{timeout_s:g} s): start one with `dask worker {scheduler}` "
                           f"where chest-observer {__version__} is installed") from None

    def version_there() -> str:  # local, so Dask ships it by value: it runs without the package
        import observer_node

        return observer_node.__version__

    # The scheduler unpickles each task too: without the package it refuses every one.
    try:
        got = {f"the scheduler {scheduler}": client.run_on_scheduler(version_there)}
    except Exception as e:  # whatever it raised is the reason given
        got = {f"the scheduler {scheduler}": e}
    got.update(client.run(version_there, on_error="return"))
    wrong = [f"{w}: cannot import chest-observer ({type(r).__name__}: {r})"
             if isinstance(r, BaseException) else f"{w}: chest-observer {r}"
             for w, r in sorted(got.items()) if r != __version__]
    if wrong:
        more = f" and {len(wrong) - 2} more" if len(wrong) > 2 else ""
        raise ClusterError(f"the Dask cluster at {scheduler} cannot run this version's "
                           f"refits (chest-observer {__version__}): "
                           f"{'; '.join(wrong[:2])}{more}")


@contextmanager
def cluster(scheduler: str | None = None, workers: int | None = None) -> Iterator[Runner]:
    """A :class:`Runner` on the cluster at ``scheduler``, or on a local one for this call."""
    from dask.distributed import Client, LocalCluster

    if scheduler:
        client = _connect(scheduler)
        try:
            _check_workers(client, scheduler)
            yield Runner(client, scheduler)
        finally:
            client.close()
        return
    n = workers or min(MAX_LOCAL_WORKERS, len(os.sched_getaffinity(0)))
    # Ctrl-C reaches every process of the terminal's group: the workers are started with it
    # ignored (Python keeps an ignored SIGINT ignored), so that this process alone stops
    # them, and the user sees one line rather than a traceback from each worker
    main = threading.current_thread() is threading.main_thread()  # where signals are set
    sigint = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    try:
        local = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                             dashboard_address=":0", silence_logs=logging.CRITICAL,
                             env=_WORKER_ENV)
    finally:
        if main:
            signal.signal(signal.SIGINT, sigint)
    client = Client(local)
    try:
        yield Runner(client)
    finally:
        client.close()
        local.close()
