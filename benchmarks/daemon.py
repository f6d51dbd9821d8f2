"""Daemon benchmark: per-tick processing time, end-to-end latency, missed ticks and CPU share
at several tick rates on python-can's virtual bus, and the per-frame cost of cantools' own
encode/decode beside the codec precompiled from the DBC.

All in one process, as python-can's virtual bus requires: the main thread sends TunnelAccel
(+ BeltSpindle every 10th tick) on an absolute schedule, the daemon thread processes them and
sends ChestEstimate frames, which wait in the sender's bus queue until the run ends. End-to-end
latency is bus time to bus time: the estimate frame's timestamp (stamped by the virtual bus
when the daemon sends it) minus its input frame's, which is what a CAN logger on a real wire
would report. It includes the hand-off from the sender thread to the daemon thread. A tick is
missed when its input frame got no estimate, or the estimate reached the bus after the next
input frame was due. The interpreter's thread switch interval is set to 100 us (default 5 ms)
so that the two threads hand over the GIL quickly; the daemon itself runs single-threaded.

    python benchmarks/daemon.py [--ticks 10000] [--rates 1000 2000 5000 10000]
"""

from __future__ import annotations

import argparse
import contextlib
import queue
import sys
import tempfile
import threading
import time
import timeit
from pathlib import Path

import can
import numpy as np

from dbc import Codec, e2e_crc
from observer_node.daemon.node import NodeConfig, ObserverNode
from observer_node.daemon.ports import PythonCanPort
from observer_node.data import bundled_campaign, read_isomme
from observer_node.evaluation import identify
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
    rows = [
        ("cantools decode_message (TunnelAccel)",
         timeit.timeit(lambda: db.decode_message(acc.frame_id, data), number=n) / n),
        ("cantools encode_message (TunnelAccel)",
         timeit.timeit(lambda: db.encode_message(acc.frame_id, values), number=n) / n),
        ("precompiled FrameCodec.decode", timeit.timeit(lambda: acc.decode(data), number=n) / n),
        ("precompiled FrameCodec.encode (with E2E)",
         timeit.timeit(lambda: acc.encode({"TunnelAccelX": -12.34}, 3), number=n) / n),
        ("hot path: struct unpack + E2E check",
         timeit.timeit(lambda: (st.unpack_from(data), e2e_crc(acc.frame_id, data)),
                       number=n) / n),
    ]
    return rows


def _fine_timer_slack() -> None:
    """Linux rounds a thread's sleeps up by its timer slack (50 us by default); 1 ns makes
    ``time.sleep`` wake as early as the scheduler can."""
    import ctypes

    with contextlib.suppress(OSError, AttributeError):
        ctypes.CDLL(None, use_errno=True).prctl(29, 1, 0, 0, 0)  # PR_SET_TIMERSLACK


def handoff_floor(rate_hz: float, n: int = 5000) -> np.ndarray:
    """One-way hand-off between two threads of this interpreter (queue.Queue, as the virtual
    bus uses) at the tick rate, with nothing else to do: the floor under the e2e latency."""
    q: queue.Queue = queue.Queue()
    got = np.zeros(n)

    def receiver():
        for k in range(n):
            q.get()
            got[k] = time.perf_counter()

    th = threading.Thread(target=receiver)
    th.start()
    sent = np.zeros(n)
    start = time.perf_counter() + 0.01
    for k in range(n):
        remaining = start + k / rate_hz - time.perf_counter()
        if remaining > 0:
            time.sleep(remaining)
        sent[k] = time.perf_counter()
        q.put(k)
    th.join()
    return (got - sent) * 1e6


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
    counter = -1
    for k in range(n):
        t = clock()
        counter = node._on_accel(t, frames[k], counter)
        out[k] = clock() - t
    return out * 1e6


def run_rate(model, codec: Codec, rate_hz: float, ticks: int, workdir: Path,
             record: bool = True, burst: bool = False) -> dict:
    """With ``burst``: InputBurst frames of eight samples (CAN FD layout) every eight ticks;
    the latency is per frame, and a late frame misses its eight ticks."""
    model.tick_rate_hz = rate_hz  # the same matrices, re-labelled: timing only
    channel = f"bench{int(rate_hz)}{'b' if burst else ''}"
    path = workdir / f"{channel}.mcap"
    node = ObserverNode(NodeConfig(interface="virtual", channel=channel,
                                   record=str(path) if record else ""),
                        model, codec,
                        port_factory=lambda ids: PythonCanPort("virtual", channel, ids))
    # One bus object sends the inputs and hears the estimates, as a test rig's single
    # interface would (a second virtual bus would cost the daemon a deep copy per frame).
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
    time.sleep(0.2)
    period = 1.0 / rate_hz
    sent_at = np.zeros(ticks)  # bus timestamp of each TunnelAccel frame (time.time())
    start = time.perf_counter() + 0.01
    for f in range(len(frames)):
        k = f * n_per + n_per - 1  # the frame's last tick
        # Sleep, never spin: a spinning sender would hold the GIL the daemon thread needs.
        # Its wake-up jitter does not enter the latency, which starts at the send.
        remaining = start + k * period - time.perf_counter()
        if remaining > 0:
            time.sleep(remaining)
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
    # The estimates waited in this bus's queue, each stamped when the daemon sent it: the
    # latency is bus time to bus time, as a CAN logger on the wire would measure it.
    lat = np.full(ticks, np.nan)
    k, prev = -1, -1
    while (m := rx.recv(0.05)) is not None:  # 0 would stop at the first filtered-out frame
        counter = m.data[1] & 0xF
        if counter == prev:
            continue  # a watchdog publish between ticks repeats the last tick's counter
        k += (counter - prev) & 0xF if k >= 0 else counter + 1  # skips inputs with none
        prev = counter
        if k < ticks:
            lat[k] = (m.timestamp - sent_at[k]) * 1e6
    tx.shutdown()
    c = node.counters
    proc = read_recording(path, frames=False).ticks["proc_us"] if record else np.full(1, np.nan)
    # Missed: no estimate for the frame, or the estimate reached the bus after the next
    # input frame was due (the daemon fell a tick behind).
    last = lat[n_per - 1::n_per]  # per frame
    missed = n_per * int(np.sum(~(last < n_per * period * 1e6)))
    lat = last
    return {"rate": rate_hz, "ticks": c.ticks, "missed": missed,
            "overruns": c.overruns, "lat": lat, "proc": proc,
            "cpu_share": cpu.get("daemon_s", float("nan")) / wall}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ticks", type=int, default=10_000)
    ap.add_argument("--rates", type=float, nargs="+", default=[1000, 2000, 5000, 10000])
    ap.add_argument("--burst-rates", type=float, nargs="*", default=[5000, 10000],
                    help="tick rates to run again as InputBurst frames (8 samples each)")
    ap.add_argument("--no-record", action="store_true", help="run the daemon without MCAP")
    a = ap.parse_args()
    sys.setswitchinterval(1e-4)
    codec = Codec()
    tests = [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3, 5)]
    model = identify("greybox", make_dataset(tests, 1000.0))

    print("Per-frame codec cost (median of 20,000 calls, this machine):")
    for name, t in codec_costs(codec):
        print(f"  {name:<44}{t * 1e6:8.2f} us")
    c = compute_per_tick(model, codec)
    print(f"\nPer-tick compute (validate, step, encode, no bus), 20,000 ticks: p50 "
          f"{np.percentile(c, 50):.1f} us, p99 {np.percentile(c, 99):.1f} us, max {c.max():.0f} us")
    _fine_timer_slack()
    print("\nThread hand-off alone (queue.Queue between two threads, 5,000 at the rate):")
    for rate in a.rates:
        h = handoff_floor(rate)
        print(f"  {rate:>5.0f}Hz  p50 {np.percentile(h, 50):.0f} us, "
              f"p99 {np.percentile(h, 99):.0f} us, max {h.max():.0f} us")
    print(f"\nDaemon on python-can's virtual bus, {'not ' if a.no_record else ''}recording to "
          f"MCAP, {a.ticks} ticks per rate, "
          "grey-box model (5 states):")
    print(f"  {'rate':>9} {'ticks':>6} {'missed':>6} {'e2e p50':>8} {'p99':>7} "
          f"{'max':>7}   "
          f"{'tick p50':>8} {'p99':>6} {'max':>7}  {'CPU':>5}")
    workdir = Path(tempfile.mkdtemp())
    for rate, burst in [(r, False) for r in a.rates] + [(r, True) for r in a.burst_rates]:
        r = run_rate(model, codec, rate, a.ticks, workdir, not a.no_record, burst)
        lat, proc = r["lat"][~np.isnan(r["lat"])], r["proc"]
        pp = [*np.percentile(proc, [50, 99]), proc.max()]
        p50, p99 = np.percentile(lat, [50, 99])
        label = f"{rate:.0f}Hz" + ("/8" if burst else "")
        print(f"  {label:>9} {r['ticks']:>6} {r['missed']:>6} "
              f"{p50:>6.0f}us {p99:>5.0f}us "
              f"{lat.max():>5.0f}us   {pp[0]:>6.1f}us {pp[1]:>4.0f}us {pp[2]:>5.0f}us  "
              f"{100 * r['cpu_share']:>4.0f}%")
    print("\n  e2e: bus timestamp of a TunnelAccel frame -> bus timestamp of its ChestEstimate; "
          "missed: input frames with no estimate, or an estimate later than the next input; "
          "tick: daemon's frame receipt -> estimate sent (its own measurement, in the MCAP); "
          "CPU: daemon thread CPU time / wall time; /8: InputBurst frames of eight samples "
          "(latency per frame; a frame later than eight periods misses its eight ticks).")


if __name__ == "__main__":
    main()
