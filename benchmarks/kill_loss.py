"""Kill benchmark: how much of a run a recording loses when the daemon's whole process group
(daemon and MCAP writer) is killed with SIGKILL at a random moment.

Each run starts a recording daemon on python-can's virtual bus fed with R16_002 over and over
at 1 kHz (``python -m observer_node.daemon.harness``, its own session), kills the group
0.05-2 s after the daemon is ready, then reads the cut recording. The loss is the kill's wall
time minus the last recorded tick's (an upper bound: it includes any lag of the daemon
itself). It also checks that no shared-memory segment is left in /dev/shm. ``--load N`` keeps
N busy-looping processes running meanwhile (a loaded bench PC: the writer must not starve).

    python benchmarks/kill_loss.py [--runs 20] [--seed 1] [--load 2]
"""

from __future__ import annotations

import argparse
import os
import random
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np


def last_log_time_ns(path: Path) -> int:
    """The newest message time in a (possibly cut) MCAP file, read without seeking."""
    from observer_node.recording import Scan

    return max((t for topic, t, _ in Scan(path) if not topic.startswith("#")), default=0)


def one_run(model: Path, record: Path, delay_s: float) -> float:
    p = subprocess.Popen([sys.executable, "-m", "observer_node.daemon.harness", str(model),
                          str(record), "60"], stdout=subprocess.PIPE, text=True,
                         start_new_session=True)
    assert p.stdout is not None
    if p.stdout.readline().strip() != "started":
        p.kill()
        raise SystemExit("kill_loss: the feeder did not start")
    started_ns = time.time_ns()
    time.sleep(delay_s)
    kill_ns = time.time_ns()
    os.killpg(p.pid, signal.SIGKILL)
    p.wait(10)
    last = last_log_time_ns(record) or started_ns  # nothing recorded: all of it lost
    return (kill_ns - last) / 1e6


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--load", type=int, default=0, help="busy processes running meanwhile")
    a = ap.parse_args()
    from observer_node.data import bundled_campaign, load_tests
    from observer_node.evaluation import identify
    from observer_node.ident.dataset import make_dataset

    rng = random.Random(a.seed)
    shm_before = set(os.listdir("/dev/shm"))
    with tempfile.TemporaryDirectory() as tmp:
        tests = [t for t in load_tests([bundled_campaign()])
                 if t.name in ("R16_001", "R16_003", "R16_005")]
        model = identify("greybox", make_dataset(tests, 1000.0)).save(Path(tmp) / "model.json")
        busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"])
                for _ in range(a.load)]
        losses = []
        try:
            for k in range(a.runs):
                delay = rng.uniform(0.05, 2.0)
                loss = one_run(model, Path(tmp) / f"run{k}.mcap", delay)
                losses.append(loss)
                print(f"run {k + 1:2d}: killed {delay:5.2f} s after start, lost {loss:6.1f} ms",
                      flush=True)
        finally:
            for b in busy:
                b.kill()
                b.wait()
    leaked = set(os.listdir("/dev/shm")) - shm_before
    v = np.array(losses)
    print(f"loss over {len(v)} kills with {a.load} busy processes [ms]: min {v.min():.1f}, "
          f"median {np.median(v):.1f}, p90 {np.percentile(v, 90):.1f}, max {v.max():.1f}; "
          f"{int((v <= 100).sum())} of {len(v)} within 100 ms")
    print(f"/dev/shm entries left behind: {len(leaked)}" + (f" {sorted(leaked)}" if leaked
                                                            else ""))


if __name__ == "__main__":
    main()
