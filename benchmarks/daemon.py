"""Daemon benchmark: per-tick processing time, end-to-end latency, missed ticks and CPU share
at several tick rates on python-can's virtual bus, beside the same bus with a bare echo in
place of the daemon, and the per-frame cost of cantools' own encode/decode beside the codec
precompiled from the DBC.

All in one process, as python-can's virtual bus requires: the main thread sends TunnelAccel
(+ BeltSpindle every 10th tick) on an absolute schedule, the daemon thread processes them and
sends ChestEstimate frames, which wait in the sender's bus queue until the run ends. End-to-end
latency is bus time to bus time: the estimate frame's timestamp (stamped by the virtual bus
when the daemon sends it) minus its input frame's, which is what a CAN logger on a real wire
would report. It includes the hand-off from the sender thread to the daemon thread, which the
echo rows measure alone. A tick is missed when its input frame got no estimate, or the
estimate reached the bus after the next input frame was due. The interpreter's thread switch
interval is set to 100 us (default 5 ms) so that the two threads hand over the GIL quickly;
the daemon itself runs single-threaded. The CPU wake-up latency is held at 0 us (PM QoS, as
the daemon does by default; needs root) for the whole run, echo rows included.

    python benchmarks/daemon.py [--ticks 10000] [--rates 1000 2000 5000 10000]
                                [--cpu-latency-us -1]   # as on a machine without root
"""

from __future__ import annotations

import argparse
import contextlib
import subprocess
import sys
import tempfile
import threading
import time
import timeit
from pathlib import Path

import can
import numpy as np

from observer_node.daemon.config import NodeConfig
from observer_node.daemon.node import ObserverNode
from observer_node.daemon.ports import PythonCanPort
from observer_node.daemon.realtime import hold_cpu_latency
from observer_node.data import bundled_campaign, read_isomme
from observer_node.dbc import Codec
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.recording import read_recording


def codec_costs(codec: Codec) -> list[tuple[str, float]]:
    db = codec.db
    acc = codec["TunnelAccel"]
    msg = db.get_message_by_name("TunnelAccel")
    data = acc.encode({"TunnelAccelX": -12.34}, 3)
    values = msg.decode(data)
    n = 20000
    st = acc.struct
    check = acc.e2e_checker()
    rows = [
        ("cantools decode_message (TunnelAccel)",
         timeit.timeit(lambda: db.decode_message(acc.frame_id, data), number=n) / n),
        ("cantools encode_message (TunnelAccel)",
         timeit.timeit(lambda: db.encode_message(acc.frame_id, values), number=n) / n),
        ("precompiled FrameCodec.decode", timeit.timeit(lambda: acc.decode(data), number=n) / n),
        ("precompiled FrameCodec.encode (with E2E)",
         timeit.timeit(lambda: acc.encode({"TunnelAccelX": -12.34}, 3), number=n) / n),
        ("hot path: struct unpack + E2E check",
         timeit.timeit(lambda: (st.unpack_from(data), check(data)),
                       number=n) / n),
    ]
    return rows


def _fine_timer_slack() -> None:
    """Linux rounds a thread's sleeps up by its timer slack (50 us by default); 1 ns makes
    ``time.sleep`` wake as early as the scheduler can."""
    import ctypes

    with contextlib.suppress(OSError, AttributeError):
        ctypes.CDLL(None, use_errno=True).prctl(29, 1, 0, 0, 0)  # PR_SET_TIMERSLACK


def _paced(due_ticks: range, period_s: float, start: float):
    """Yield each tick index at its due time ``start + k * period_s`` (perf_counter). Sleep,
    never spin: a spinning sender would hold the GIL the thread under test needs; its
    wake-up jitter does not enter the latency, which starts at the send."""
    for k in due_ticks:
        remaining = start + k * period_s - time.perf_counter()
        if remaining > 0:
            time.sleep(remaining)
        yield k


def wake_floor(n: int = 20_000, sleep_s: float = 200e-6) -> np.ndarray:
    """How late a thread doing nothing else wakes from a short sleep, in us: the machine's
    own scheduling floor (on a VM it includes the hypervisor's)."""
    late = np.zeros(n)
    for k in range(n):
        t = time.perf_counter()
        time.sleep(sleep_s)
        late[k] = time.perf_counter() - t - sleep_s
    return late * 1e6


def bus_floor(rate_hz: float, ticks: int) -> dict:
    """python-can's virtual bus alone, as the daemon rows use it: the rig thread sends a frame
    per tick, a thread that does nothing else answers each with one frame. Latency and missed
    ticks as for the daemon: the floor under the daemon's rows."""
    channel = f"floor{int(rate_hz)}"
    rig = can.Bus(interface="virtual", channel=channel,
                  can_filters=[{"can_id": 0x120, "can_mask": 0x7FF}])
    dut = can.Bus(interface="virtual", channel=channel,
                  can_filters=[{"can_id": 0x100, "can_mask": 0x7FF}])
    cpu = {}

    def echo():
        c0 = time.thread_time()
        for _ in range(ticks):
            m = dut.recv(0.5)
            if m is None:
                break
            dut.send(can.Message(arbitration_id=0x120, data=m.data, is_extended_id=False))
        cpu["s"] = time.thread_time() - c0

    th = threading.Thread(target=echo)
    th.start()
    time.sleep(0.2)
    period = 1.0 / rate_hz
    sent_at = np.zeros(ticks)
    start = time.perf_counter() + 0.01
    for k in _paced(range(ticks), period, start):
        sent_at[k] = time.time()
        rig.send(can.Message(arbitration_id=0x100, data=k.to_bytes(4, "little"),
                             is_extended_id=False, timestamp=sent_at[k]))
    wall = time.perf_counter() - start
    th.join()
    lat = np.full(ticks, np.nan)
    while (m := rig.recv(0.05)) is not None:
        k = int.from_bytes(m.data, "little")
        lat[k] = (m.timestamp - sent_at[k]) * 1e6
    rig.shutdown()
    dut.shutdown()
    return {"rate": rate_hz, "lat": lat, "missed": _missed(lat, period * 1e6),
            "cpu_share": cpu.get("s", float("nan")) / wall}


def _missed(lat_us: np.ndarray, deadline_us: float, per: int = 1) -> tuple[int, int, int]:
    """Ticks with no answer or one later than ``deadline_us``: how many, in how many
    stretches of consecutive frames, the longest stretch (in ticks)."""
    late = ~(lat_us < deadline_us)
    idx = np.flatnonzero(late)
    if not len(idx):
        return 0, 0, 0
    runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    return per * len(idx), len(runs), per * max(len(r) for r in runs)


class _NullPort:
    dropped = 0

    def send(self, can_id: int, data: bytes) -> bool:
        return True


def compute_per_tick(model, codec: Codec, n: int = 20000) -> np.ndarray:
    """Per-tick compute: frame validation, observer step, estimate encoding, no bus."""
    node = ObserverNode(NodeConfig(), model, codec)
    node.port = _NullPort()  # type: ignore[assignment]
    acc = codec["TunnelAccel"]
    frames = [acc.encode({"TunnelAccelX": -20.0 if k > 100 else 0.0}, k) for k in range(n)]
    out = np.zeros(n)
    clock = time.perf_counter
    accel = node.inputs.accel
    node.inputs.reset()
    for k in range(n):
        t = clock()
        accel(t, frames[k])
        out[k] = clock() - t
    return out * 1e6


def run_rate(model, codec: Codec, rate_hz: float, ticks: int, workdir: Path,
             record: bool = True, burst: bool = False, cpu_latency_us: int = 0,
             live: str = "", rt_priority: int = 0) -> dict:
    """With ``burst``: InputBurst frames of eight samples (CAN FD layout) every eight ticks;
    the latency is per frame, and a late frame misses its eight ticks. ``live``: serve the
    live view, with a client in its own process ("read": reading, "stall": subscribed and
    never reading)."""
    channel = f"bench{int(rate_hz)}{'b' if burst else ''}{live}"
    path = workdir / f"{channel}.mcap"
    port = 18765 + len(live)
    node = ObserverNode(NodeConfig(interface="virtual", channel=channel,
                                   record=str(path) if record else "",
                                   live=f"127.0.0.1:{port}" if live else "",
                                   cpu_latency_us=cpu_latency_us, rt_priority=rt_priority),
                        model, codec,
                        port_factory=lambda ids: PythonCanPort("virtual", channel, ids))
    # One bus object sends the inputs and hears the estimates, as a test rig's single
    # interface would (every further bus on the channel is one more queue per send).
    tx = rx = can.Bus(interface="virtual", channel=channel, can_filters=[
        {"can_id": codec["ChestEstimate"].frame_id, "can_mask": 0x7FF}])
    acc, brs = codec["TunnelAccel"], codec["BeltSpindle"]
    rng = np.random.default_rng(1)
    pulse = np.concatenate([0.05 * rng.normal(size=ticks // 2),
                            -20 + rng.normal(size=ticks - ticks // 2)])
    frames = [acc.encode({"TunnelAccelX": float(p)}, k) for k, p in enumerate(pulse)]
    brs_frames = [brs.encode({"BrsCount": k // 50, "BrsCountsPerRev": 96}, k)
                  for k in range(ticks)]
    n_per = 8 if burst else 1
    if burst:
        ib = codec["InputBurst"]
        frames = [ib.encode({"BurstCountsPerRev": 96,
                             **{f"BurstAccelX{j}": float(pulse[f * 8 + j]) for j in range(8)},
                             **{f"BurstBrsCount{j}": (f * 8 + j) // 50 for j in range(8)}}, f)
                  for f in range(ticks // 8)]
    cpu = {}

    def daemon():
        c0 = time.thread_time()
        node.run(idle_exit_s=0.5)
        cpu["daemon_s"] = time.thread_time() - c0

    td = threading.Thread(target=daemon)
    td.start()
    while node.port is None:  # recorder process up, bus open
        time.sleep(0.01)
    client = None
    if live:
        client = subprocess.Popen(
            [sys.executable, str(Path(__file__).with_name("live_client.py")), str(port),
             str(ticks / rate_hz + 3), *(["--stall"] if live == "stall" else [])],
            stdout=subprocess.PIPE, text=True)
        assert client.stdout is not None and client.stdout.readline().strip() == "subscribed"
    time.sleep(0.2)
    period = 1.0 / rate_hz
    sent_at = np.zeros(ticks)  # bus timestamp of each TunnelAccel frame (time.time())
    start = time.perf_counter() + 0.01
    for k in _paced(range(n_per - 1, len(frames) * n_per, n_per), period, start):
        f = k // n_per  # k: the frame's last tick
        if burst:
            sent_at[k] = time.time()
            tx.send(can.Message(arbitration_id=ib.frame_id, data=frames[f], is_fd=True,
                                is_extended_id=False,
                                timestamp=sent_at[k]))
            continue
        if k % 10 == 0:
            tx.send(can.Message(arbitration_id=brs.frame_id, data=brs_frames[k],
                                is_extended_id=False))
        sent_at[k] = time.time()
        tx.send(can.Message(arbitration_id=acc.frame_id, data=frames[f], is_extended_id=False,
                            timestamp=sent_at[k]))
    wall = time.perf_counter() - start
    td.join()
    live_got = int(client.communicate(timeout=30)[0].split()[-1]) if client else None
    # The estimates waited in this bus's queue, each stamped when the daemon sent it: the
    # latency is bus time to bus time, as a CAN logger on the wire would measure it.
    # A frame's estimate is the first estimate on the bus after it was sent (its counter
    # steps once per estimate frame, so it names no tick); one sent before the oldest
    # unanswered frame was is a watchdog publish (the daemon heard nothing for two periods).
    lat = np.full(ticks, np.nan)
    due = iter(range(n_per - 1, ticks, n_per))  # each frame's last tick, oldest first
    k = next(due, None)
    while (m := rx.recv(0.05)) is not None:  # 0 would stop at the first filtered-out frame
        if k is None or m.timestamp < sent_at[k]:
            continue
        lat[k] = (m.timestamp - sent_at[k]) * 1e6
        k = next(due, None)
    tx.shutdown()
    c = node.counters
    proc = read_recording(path, frames=False).ticks["proc_us"] if record else np.full(1, np.nan)
    # Missed: no estimate for the frame, or the estimate reached the bus after the next
    # input frame was due (the daemon fell a tick behind).
    lat = lat[n_per - 1::n_per]  # per frame
    return {"rate": rate_hz, "ticks": c.ticks, "missed": _missed(lat, n_per * period * 1e6, n_per),
            "overruns": c.overruns, "timeouts": c.accel_timeouts, "lat": lat, "proc": proc,
            "cpu_share": cpu.get("daemon_s", float("nan")) / wall, "live_got": live_got}


def _row(label: str, r: dict, proc: np.ndarray | None = None) -> str:
    lat = r["lat"][~np.isnan(r["lat"])]
    p50, p99 = np.percentile(lat, [50, 99])
    n, runs, longest = r["missed"]
    tick = "" if proc is None else (f"{np.percentile(proc, 50):>6.1f}us "
                                    f"{np.percentile(proc, 99):>4.0f}us {proc.max():>5.0f}us")
    return (f"  {label:>9} {n:>6} {runs:>4} {longest:>4}  {p50:>5.0f}us {p99:>5.0f}us "
            f"{lat.max():>5.0f}us  {100 * r['cpu_share']:>4.0f}%   {tick}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ticks", type=int, default=10_000)
    ap.add_argument("--rates", type=float, nargs="+", default=[1000, 2000, 5000, 10000])
    ap.add_argument("--burst-rates", type=float, nargs="*", default=[5000, 10000],
                    help="tick rates to run again as InputBurst frames (8 samples each)")
    ap.add_argument("--no-record", action="store_true", help="run the daemon without MCAP")
    ap.add_argument("--live-rates", type=float, nargs="*", default=[1000],
                    help="tick rates to run again with the live view served and a Foxglove "
                    "client connected (reading, then stalled)")
    ap.add_argument("--cpu-latency-us", type=int, default=0,
                    help="PM QoS CPU wake-up latency held during the whole benchmark, floor "
                    "rows included, as the daemon holds it by default (-1: none)")
    ap.add_argument("--rt-priority", type=int, default=0,
                    help="the daemon's tick loop under SCHED_FIFO at this priority in every "
                    "daemon row (0: normal scheduling, the default)")
    a = ap.parse_args()
    sys.setswitchinterval(1e-4)
    _qos, qos_said = hold_cpu_latency(a.cpu_latency_us)
    codec = Codec()
    tests = [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3, 5)]
    data = make_dataset(tests, 1000.0)
    fit = greybox.fit_greybox(data)
    model = greybox.to_model_file(fit, data)

    print("Per-frame codec cost (median of 20,000 calls, this machine):")
    for name, t in codec_costs(codec):
        print(f"  {name:<44}{t * 1e6:8.2f} us")
    c = compute_per_tick(model, codec)
    print(f"\nPer-tick compute (validate, step, encode, no bus), 20,000 ticks: p50 "
          f"{np.percentile(c, 50):.1f} us, p99 {np.percentile(c, 99):.1f} us, max {c.max():.0f} us")
    _fine_timer_slack()
    w = wake_floor()
    print(f"\nA thread sleeping 200 us, 20,000 times ({qos_said}): wakes late by p50 "
          f"{np.percentile(w, 50):.0f} us, p99 {np.percentile(w, 99):.0f} us, max "
          f"{w.max():.0f} us; {np.sum(w > 1000)} times over 1 ms (the machine's floor).")
    print(f"\n{a.ticks} ticks per row; {qos_said}. missed: ticks with no estimate or one later "
          "than the next input, in how many stretches, the longest.")
    print(f"  {'rate':>9} {'missed':>6} {'str.':>4} {'long':>4}  {'e2e p50':>7} {'p99':>7} "
          f"{'max':>7}  {'CPU':>5}   {'tick p50':>8} {'p99':>6} {'max':>7}")
    print("  python-can virtual bus alone (a thread echoing each frame):")
    for rate in a.rates:
        print(_row(f"{rate:.0f}Hz", bus_floor(rate, a.ticks)))
    print(f"  observer daemon ({'not ' if a.no_record else ''}recording to MCAP), grey-box "
          "model (5 states)" + (f", tick loop SCHED_FIFO {a.rt_priority}" if a.rt_priority
                                else "") + ":")
    workdir = Path(tempfile.mkdtemp())
    for rate, burst in [(r, False) for r in a.rates] + [(r, True) for r in a.burst_rates]:
        r = run_rate(greybox.to_model_file(fit, data, tick_rate_hz=rate), codec, rate,
                     a.ticks, workdir, not a.no_record, burst,
                     a.cpu_latency_us, rt_priority=a.rt_priority)
        print(_row(f"{rate:.0f}Hz" + ("/8" if burst else ""), r,
                   None if a.no_record else r["proc"]))
    if not a.no_record:
        for rate in a.live_rates:
            for mode in ("read", "stall"):
                r = run_rate(greybox.to_model_file(fit, data, tick_rate_hz=rate), codec, rate,
                             a.ticks, workdir, True, False,
                             a.cpu_latency_us, live=mode, rt_priority=a.rt_priority)
                print(_row(f"{rate:.0f}Hz+{mode}", r, r["proc"])
                      + f"  live client got {r['live_got']} messages")
    print("\n  e2e: bus timestamp of a TunnelAccel frame -> bus timestamp of its ChestEstimate "
          "(the echo's answer); tick: daemon's frame receipt -> estimate sent (its own "
          "measurement, in the MCAP); CPU: the answering thread's CPU time / wall time; /8: "
          "InputBurst frames of eight samples (latency per frame; a frame later than eight "
          "periods misses its eight ticks); +read / +stall: the live view served by the "
          "recorder process (--live) with a Foxglove WebSocket client in another process "
          "reading everything, or subscribed and never reading.")


if __name__ == "__main__":
    main()
