"""Replay timing: our player beside python-can's ``can.player`` pacing, same log, same bus,
one run.

``python -m can.player`` paces frames with ``can.MessageSync`` (it skips sleeps under 100 us
and then sends at once); it is used here in-process, as python-can's virtual bus cannot
cross processes, with exactly the loop ``can.player`` runs. Both send the same candump log
(``--log``, default: bundled R16_002 at 1 kHz with reference frames, ~2.1k frames/s) onto a
virtual bus with one listener; lateness = send time - due time, per frame. ``--repeat`` runs
alternate between the tools so machine noise hits both alike.

can-utils ``canplayer`` needs SocketCAN; run this script inside ``scripts/vcan-vm`` with
``--socketcan`` to add it (timings under emulation are only comparable within one run).

    python benchmarks/replay_timing.py [--repeat 3] [--rate 1.0]
"""

from __future__ import annotations

import argparse
import subprocess
import tempfile
import time
from pathlib import Path

import can
import numpy as np

from observer_node.data import bundled_campaign, read_isomme
from observer_node.dbc import Codec
from observer_node.replay.player import bus_sender, lateness_report, play
from observer_node.replay.schedule import Schedule, crash_test_schedule
from observer_node.replay.sources import read_candump


def write_candump(s: Schedule, path: Path) -> None:
    with path.open("w") as f:
        for t, cid, d in zip(s.t_s, s.ids.tolist(), s.data, strict=True):
            f.write(f"({1000 + t:.6f}) vcan0 {cid:03X}#{d.hex().upper()}\n")


def ours(s: Schedule, bus: can.BusABC, spin_s: float = 3e-4):
    return play(s, bus_sender(bus, s), spin_s=spin_s)


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
          "alternating\n")
    rows: dict[str, list] = {"ours (crash-replay)": [], "ours, --spin-us 0": [],
                             "python-can can.player": []}
    for _ in range(a.repeat):
        with can.Bus(interface=interface, channel=channel) as bus, \
                can.Bus(interface=interface, channel=channel):
            rows["ours (crash-replay)"].append(ours(sched, bus))
            rows["ours, --spin-us 0"].append(ours(sched, bus, 0.0))
            rows["python-can can.player"].append(python_can_player(log, bus))
    print(f"  {'tool':<24}{'p50 us':>8}{'p99 us':>8}{'max us':>8}   runs (p99)")
    summary = {}
    for name, reps in rows.items():
        p50 = np.median([r.p50_us for r in reps])
        p99 = np.median([r.p99_us for r in reps])
        mx = max(r.max_us for r in reps)
        summary[name] = p99
        print(f"  {name:<24}{p50:>8.0f}{p99:>8.0f}{mx:>8.0f}   "
              + " ".join(f"{r.p99_us:.0f}" for r in reps))
    if a.socketcan:
        t_rx, t_due = canplayer(log, "vcan0")
        n = min(len(t_rx), len(t_due))
        late = (t_rx[:n] - t_due[:n]) * 1e6
        late -= late.min()  # align the clocks on the earliest frame
        print(f"  {'can-utils canplayer':<24}{np.percentile(late, 50):>8.0f}"
              f"{np.percentile(late, 99):>8.0f}{late.max():>8.0f}   "
              f"(kernel receive times; {len(t_rx)} of {len(t_due)} frames seen)")
    ratio = summary["ours (crash-replay)"] / summary["python-can can.player"]
    print(f"\n  p99 ratio ours / can.player, same run: {ratio:.2f}")


if __name__ == "__main__":
    main()
