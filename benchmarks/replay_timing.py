"""Replay timing: our player beside python-can's ``can.player`` pacing, same log, same bus,
one run, on an idle machine and (``--load N``) with N busy-looping processes started here.

``python -m can.player`` paces frames with ``can.MessageSync`` (it skips sleeps under 100 us
and then sends at once); it is used here in-process, as python-can's virtual bus cannot
cross processes, with exactly the loop ``can.player`` runs. Both send the same candump log
(``--log``, default: bundled R16_002 at 1 kHz with reference frames, ~2.1k frames/s) onto a
virtual bus with one listener; lateness = send time - due time, per frame. ``--repeat`` runs
alternate between the tools so machine noise hits both alike. crash-replay runs as a bench
would run it (``--rt-priority 80``: SCHED_FIFO, needs root or CAP_SYS_NICE), and at normal
scheduling; can.player as it runs (normal), and under ``chrt -f 80`` for comparison.

can-utils ``canplayer`` needs SocketCAN; run this script inside ``scripts/vcan-vm`` with
``--socketcan`` to add it (timings under emulation are only comparable within one run).

    python benchmarks/replay_timing.py [--repeat 3] [--accel-only] [--load 2]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import can
import numpy as np

from observer_node.data import bundled_campaign, read_isomme
from observer_node.dbc import Codec
from observer_node.realtime import restore_scheduling, set_rt_priority
from observer_node.replay.player import TimingReport, bus_sender, lateness_report, play
from observer_node.replay.schedule import Schedule, crash_test_schedule
from observer_node.replay.sources import read_candump


def write_candump(s: Schedule, path: Path) -> None:
    with path.open("w") as f:
        for t, cid, d in zip(s.t_s, s.ids.tolist(), s.data, strict=True):
            f.write(f"({1000 + t:.6f}) vcan0 {cid:03X}#{d.hex().upper()}\n")


RT = 80  # the SCHED_FIFO priority of the real-time rows


def ours(s: Schedule, bus: can.BusABC, spin_s: float = 3e-4, rt_priority: int = 0):
    return play(s, bus_sender(bus, s), spin_s=spin_s, rt_priority=rt_priority)


def under_fifo(run: Callable[[], TimingReport]) -> TimingReport:
    """``run()`` with this thread under SCHED_FIFO ``RT`` (as ``chrt -f`` would run it)."""
    old, said = set_rt_priority(RT)
    try:
        report = run()
    finally:
        restore_scheduling(old)
    report.scheduling = said
    return report


def python_can_player(log: Path, bus: can.BusABC):
    """The loop of ``python -m can.player`` (MessageSync over a LogReader), timed per frame."""
    msgs = list(can.LogReader(str(log)))
    t0 = msgs[0].timestamp
    lateness = np.zeros(len(msgs))
    start = None
    k = 0
    for m in can.MessageSync(msgs, timestamps=True):
        now = time.perf_counter()
        if start is None:
            start = now
        bus.send(m)
        lateness[k] = now - (start + m.timestamp - t0)
        k += 1
    return lateness_report(lateness[:k], 0, time.perf_counter() - start)


def canplayer(log: Path, channel: str) -> tuple[np.ndarray, np.ndarray]:
    """can-utils canplayer onto SocketCAN, timed by a listening candump -L (kernel times)."""
    with tempfile.NamedTemporaryFile(suffix=".log", delete=False) as tmp:
        out = Path(tmp.name)
    dump = subprocess.Popen(["candump", "-L", channel], stdout=out.open("w"))
    time.sleep(0.5)
    subprocess.run(["canplayer", "-I", str(log), f"{channel}=vcan0"], check=True)
    time.sleep(0.5)
    dump.terminate()
    dump.wait()
    got = read_candump(out)
    return got.t_s, read_candump(log).t_s


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--log", type=Path, help="candump -L log to play (default: made here)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--accel-only", action="store_true",
                    help="default log with the accelerometer frames only: 1 frame per 1 ms")
    ap.add_argument("--load", type=int, default=0, metavar="N",
                    help="then run everything again with N busy-looping processes (2: both "
                    "cores of this machine busy)")
    ap.add_argument("--socketcan", action="store_true",
                    help="on vcan0 (in the VM): all three tools, canplayer included")
    a = ap.parse_args()
    log = a.log
    if log is None:
        s = crash_test_schedule(read_isomme(bundled_campaign() / "R16_002.zip"), Codec(),
                                1000.0, reference=not a.accel_only, pre_s=0.3)
        if a.accel_only:
            from observer_node.replay.sources import filter_remap

            s = filter_remap(s, {Codec()["TunnelAccel"].frame_id}, {})
        from observer_node.replay.schedule import concat

        s = concat([s] * 5, gap_s=0.01)  # ~2.6 s: enough frames for a p99
        log = Path(tempfile.mkdtemp()) / "r16_002.log"
        write_candump(s, log)
    sched = read_candump(log)
    rate = len(sched) / sched.t_s[-1]
    print(f"log {log}: {len(sched)} frames over {sched.t_s[-1]:.3f} s ({rate:.0f} frames/s)")
    interface, channel = ("socketcan", "vcan0") if a.socketcan else ("virtual", "timing")
    print(f"bus: {interface}:{channel}; lateness = send time - due time; {a.repeat} runs each, "
          "alternating, median of the runs' p50 and p99, max of all\n")
    tools: dict[str, Callable[[can.BusABC], TimingReport]] = {
        f"crash-replay --rt-priority {RT}": lambda bus: ours(sched, bus, rt_priority=RT),
        "  same, --spin-us 0": lambda bus: ours(sched, bus, 0.0, rt_priority=RT),
        "crash-replay, normal scheduling": lambda bus: ours(sched, bus),
        "python-can can.player": lambda bus: python_can_player(log, bus),
        f"  same, under chrt -f {RT}": lambda bus: under_fifo(lambda: python_can_player(log, bus)),
    }
    conditions = ["idle"] + ([f"{a.load} busy processes"] if a.load else [])
    rows: dict[str, dict[str, list[TimingReport]]] = {c: {t: [] for t in tools}
                                                       for c in conditions}
    for cond in conditions:
        busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"])
                for _ in range(a.load if cond != "idle" else 0)]
        try:
            time.sleep(0.5 if busy else 0)
            # what else ran: "idle" means none of ours, not an idle machine
            print(f"{cond}: load average before {os.getloadavg()[0]:.1f} ({os.cpu_count()} CPUs)")
            for _ in range(a.repeat):
                with can.Bus(interface=interface, channel=channel) as bus, \
                        can.Bus(interface=interface, channel=channel):
                    for name, run in tools.items():
                        rows[cond][name].append(run(bus))
        finally:
            for b in busy:
                b.kill()
                b.wait()
    said = {r.scheduling for c in rows.values() for reps in c.values() for r in reps}
    print("scheduling: " + "; ".join(sorted(said)))
    head = "".join(f" | {c + ': p50':>22} {'p99':>7} {'max':>7}" for c in conditions)
    print(f"  {'tool':<34}{head}   [us]")
    for name in tools:
        cells = ""
        for cond in conditions:
            reps = rows[cond][name]
            cells += (f" | {np.median([r.p50_us for r in reps]):>22.1f}"
                      f" {np.median([r.p99_us for r in reps]):>7.1f}"
                      f" {max(r.max_us for r in reps):>7.0f}")
        print(f"  {name:<34}{cells}")
    for cond in conditions:
        p99 = {n: np.median([r.p99_us for r in reps]) for n, reps in rows[cond].items()}
        ours_p99, theirs = p99[f"crash-replay --rt-priority {RT}"], p99["python-can can.player"]
        print(f"  {cond}: p99 crash-replay --rt-priority {RT} / can.player = "
              f"{ours_p99 / theirs:.3f} (target <= 0.2: "
              f"{'met' if ours_p99 <= 0.2 * theirs else 'NOT met'})")
    if a.socketcan:
        t_rx, t_due = canplayer(log, "vcan0")
        n = min(len(t_rx), len(t_due))
        late = (t_rx[:n] - t_due[:n]) * 1e6
        late -= late.min()  # align the clocks on the earliest frame
        print(f"  can-utils canplayer, idle (kernel receive times; {len(t_rx)} of {len(t_due)} "
              f"frames seen): p50 {np.percentile(late, 50):.0f}, p99 "
              f"{np.percentile(late, 99):.0f}, max {late.max():.0f} us")


if __name__ == "__main__":
    main()
