"""The loop on a running Dask cluster (`--scheduler`), as a campaign past one machine uses it:
a scheduler and its workers in processes of their own, started with Dask's own `dask`
command. A cluster whose workers cannot run the refits must be one line, never a loop that
waits for ever."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

from observer_node.loop import cluster as cl

SMALL = ["--estimate", "campaign-a/R16_00[13]", "--validate", "campaign-a/R16_002", "--quiet"]


def _start(*args: str, log: Path, env: dict[str, str] | None = None) -> subprocess.Popen:
    # run from the log's folder: from the checkout, `-m` would import its package first
    return subprocess.Popen([sys.executable, "-m", "dask", *args], stdout=log.open("wb"),
                            stderr=subprocess.STDOUT, env=env, cwd=log.parent,
                            start_new_session=True)


def _stop(p: subprocess.Popen) -> None:
    if p.poll() is None:
        os.killpg(p.pid, signal.SIGKILL)  # the worker's nanny and its child too
    p.wait(30)


def _shadow(tmp_path: Path) -> dict[str, str]:
    """The environment of a machine where chest-observer cannot be imported."""
    shadow = tmp_path / "shadow" / "observer_node"
    shadow.mkdir(parents=True, exist_ok=True)
    (shadow / "__init__.py").write_text('raise ImportError("not installed here")\n')
    return {**os.environ, "PYTHONPATH": str(shadow.parent)}


@pytest.fixture
def scheduler(tmp_path: Path, request) -> Iterator[tuple[str, Path, subprocess.Popen]]:
    """A scheduler on a free port of this host, with no worker yet: (address, its file);
    indirect ``"shadow"``: one where chest-observer cannot be imported."""
    info = tmp_path / "scheduler.json"
    env = _shadow(tmp_path) if getattr(request, "param", None) == "shadow" else None
    p = _start("scheduler", "--host", "127.0.0.1", "--port", "0", "--dashboard-address", ":0",
               "--scheduler-file", str(info), log=tmp_path / "scheduler.log", env=env)
    try:
        deadline = time.monotonic() + 60
        while not info.exists() or not info.read_text().strip():
            assert p.poll() is None and time.monotonic() < deadline, \
                (tmp_path / "scheduler.log").read_text()
            time.sleep(0.2)
        yield json.loads(info.read_text())["address"], info, p
    finally:
        _stop(p)


def _worker(info: Path, log: Path, env: dict[str, str] | None = None,
            *more: str) -> subprocess.Popen:
    return _start("worker", "--scheduler-file", str(info), "--nthreads", "1", "--nworkers", "1",
                  "--no-dashboard", *more, log=log, env=env)


def _wait_for_workers(address: str, n: int) -> None:
    from dask.distributed import Client

    with Client(address, timeout="30s") as c:
        c.wait_for_workers(n, timeout=120)


@contextmanager
def _client_and_worker(address: str, info: Path, log: Path, env: dict[str, str] | None = None,
                       *more: str, timeout: str = "30s"
                       ) -> Iterator[tuple[Any, subprocess.Popen]]:
    """A Client on the scheduler and one worker of its own, both ended after."""
    from dask.distributed import Client

    worker = _worker(info, log, env, *more)
    client = Client(address, timeout=timeout)
    try:
        client.wait_for_workers(1, timeout=60)
        yield client, worker
    finally:
        client.close()
        _stop(worker)


def _loop(address: str, out: Path, timeout_s: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "observer_node", "loop", *SMALL, "--out",
                           str(out), "--scheduler", address],
                          capture_output=True, text=True, timeout=timeout_s)


def _one_line(p: subprocess.CompletedProcess) -> str:
    assert p.returncode == 2, p.stderr
    assert "Traceback" not in p.stderr and len(p.stderr.strip().splitlines()) == 1, p.stderr
    return p.stderr


def test_the_loop_on_a_running_cluster_refuses_bad_workers_and_matches_the_local_one(
        scheduler, tmp_path):
    address, info, _ = scheduler
    # No worker: said after the wait, not waited on for ever.
    t0 = time.monotonic()
    line = _one_line(_loop(address, tmp_path / "none"))
    assert f"has no worker (waited {cl.WORKERS_TIMEOUT_S:g} s)" in line and address in line
    assert time.monotonic() - t0 < cl.WORKERS_TIMEOUT_S + 60
    assert not (tmp_path / "none").exists()
    # A worker that cannot import chest-observer (another environment): before, the first
    # refit ended it and the loop waited for ever on a cluster with no worker.
    bad = _worker(info, tmp_path / "bad.log", env=_shadow(tmp_path))
    good = _worker(info, tmp_path / "good.log")
    try:
        _wait_for_workers(address, 2)
        line = _one_line(_loop(address, tmp_path / "mixed"))
        assert "cannot import chest-observer (ImportError: not installed here)" in line, line
        assert bad.poll() is None  # asked, not ended
        _stop(bad)
        # The good worker alone: the same verdict as the in-process cluster's.
        there = _loop(address, tmp_path / "there")
        assert there.returncode == 0, there.stderr
    finally:
        _stop(bad)
        _stop(good)
    here = subprocess.run([sys.executable, "-m", "observer_node", "loop", *SMALL, "--out",
                           str(tmp_path / "here"), "--workers", "1"],
                          capture_output=True, text=True, timeout=300)
    assert here.returncode == 0, here.stderr

    def verdict(d: Path) -> tuple:
        """What the loop found and the fit it ended on: refits on the cluster or here."""
        r = json.loads((d / "report.json").read_text())
        return ([e["kind"] for e in r["effects"]], [e["kind"] for e in r["possible"]],
                r["final"]["fit"], r["first_ranking"])
    assert verdict(tmp_path / "there") == verdict(tmp_path / "here")


def test_a_cluster_that_loses_every_worker_mid_run_is_given_up_on(scheduler, tmp_path,
                                                                   monkeypatch):
    """Every worker gone while refits wait (killed, out of memory): one line after
    ``NO_WORKERS_S``, not a wait for ever."""
    address, info, _ = scheduler
    monkeypatch.setattr(cl, "NO_WORKERS_S", 3.0)
    with _client_and_worker(address, info, tmp_path / "w.log") as (client, worker):
        runner = cl.Runner(client, address)
        t0 = time.monotonic()
        threading.Timer(3.0, _stop, (worker,)).start()
        with pytest.raises(cl.ClusterError, match=r"has had no worker for 3 s, 0 of 2 refits"):
            runner.map(time.sleep, [(30,), (30,)])
        assert time.monotonic() - t0 < 25


@pytest.mark.parametrize("scheduler", ["shadow"], indirect=True)
def test_a_scheduler_that_cannot_import_chest_observer_is_one_line(scheduler, tmp_path):
    """The scheduler unpickles every task: without the package it refused each refit with
    a RuntimeError the loop did not expect."""
    address, info, _ = scheduler
    worker = _worker(info, tmp_path / "w.log")
    try:
        _wait_for_workers(address, 1)
        line = _one_line(_loop(address, tmp_path / "out"))
    finally:
        _stop(worker)
    assert f"the scheduler {address}: cannot import chest-observer" in line, line


def test_a_refit_that_ends_every_worker_it_runs_on_is_one_line(scheduler, tmp_path,
                                                               monkeypatch):
    """A crash inside a refit (a segfault in a compiled library) ends the worker; its nanny
    starts another, Dask tries the refit again and gives up after a few: one line, where
    Dask's KilledWorker was a traceback."""
    address, info, _ = scheduler
    with _client_and_worker(address, info, tmp_path / "w.log") as (client, _):
        time.sleep(1.0)  # a worker ended before its nanny has started ends the nanny too
        monkeypatch.setattr(cl, "NO_WORKERS_S", 5.0)  # ... so the cluster has none
        with pytest.raises(cl.ClusterError, match=r"ended the Dask worker it ran on, each time"
                                                  r"|has had no worker for 5 s"):
            cl.Runner(client, address).map(os._exit, [(1,)])


def test_workers_paused_at_their_memory_limit_are_given_up_on(scheduler, tmp_path, monkeypatch):
    """A worker at 80 % of its memory limit pauses and runs nothing: it is there, so a
    check for workers alone waited for ever (a hostile user's loop, 11 minutes silent)."""
    address, info, _ = scheduler
    # a pause threshold its own start-up passes: it pauses at once (and is never ended)
    small = {**os.environ, "DASK_DISTRIBUTED__WORKER__MEMORY__PAUSE": "0.01",
             "DASK_DISTRIBUTED__WORKER__MEMORY__TERMINATE": "False",
             "DASK_DISTRIBUTED__WORKER__MEMORY__TARGET": "False",
             "DASK_DISTRIBUTED__WORKER__MEMORY__SPILL": "False"}
    monkeypatch.setattr(cl, "NO_WORKERS_S", 3.0)
    with _client_and_worker(address, info, tmp_path / "w.log", small,
                            "--memory-limit", "1GB") as (client, _):
        deadline = time.monotonic() + 60
        while [w["status"] for w in client.scheduler_info(n_workers=-1)["workers"].values()] \
                != ["paused"]:
            assert time.monotonic() < deadline
            time.sleep(0.1)
        with pytest.raises(cl.ClusterError, match=r"every worker \(1\) paused at its memory "
                                                  r"limit for 3 s, 0 of 1 refits done"):
            cl.Runner(client, address).map(time.sleep, [(1,)])


def test_a_scheduler_lost_mid_run_is_one_line(scheduler, tmp_path):
    """The scheduler killed while refits run: three chained tracebacks before."""
    address, info, sched = scheduler
    with _client_and_worker(address, info, tmp_path / "w.log", timeout="5s") as (client, _):
        threading.Timer(3.0, _stop, (sched,)).start()
        t0 = time.monotonic()
        with pytest.raises(cl.ClusterError, match=r"lost the Dask scheduler \(tcp://.*\), "
                                                  r"0 of 2 refits done"):
            cl.Runner(client, address).map(time.sleep, [(60,), (60,)])
        assert time.monotonic() - t0 < 45
