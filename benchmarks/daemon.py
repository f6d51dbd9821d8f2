"""Daemon benchmark: per-tick processing time, end-to-end latency, missed ticks and CPU share
at several tick rates on python-can's virtual bus, and the per-frame cost of cantools' own
encode/decode beside the codec precompiled from the DBC.

All in one process, as python-can's virtual bus requires: a sender thread sends
TunnelAccel (+ BeltSpindle every 10th tick) on an absolute schedule, the daemon thread
processes them, a listener thread timestamps the ChestEstimate frames. End-to-end latency is
listener receipt minus the sender's send call for the same tick (both perf_counter); it
includes the virtual bus's queue hand-offs between threads, which a real bus does not have.
The interpreter's thread switch interval is set to 100 us (default 5 ms) so that the three
threads can hand over the GIL quickly; the daemon itself runs single-threaded.

    python benchmarks/daemon.py [--ticks 10000] [--rates 1000 2000 5000 10000]
"""

from __future__ import annotations

import argparse
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
             record: bool = True) -> dict:
    model.tick_rate_hz = rate_hz  # the same matrices, re-labelled: timing only
    channel = f"bench{int(rate_hz)}"
    path = workdir / f"bench{int(rate_hz)}.mcap"
    node = ObserverNode(NodeConfig(interface="virtual", channel=channel,
                                   record=str(path) if record else ""),
                        model, codec,
                        port_factory=lambda ids: PythonCanPort("virtual", channel, ids))
    tx = can.Bus(interface="virtual", channel=channel)
    rx = can.Bus(interface="virtual", channel=channel, can_filters=[
        {"can_id": codec["ChestEstimate"].frame_id, "can_mask": 0x7FF}])
    acc, brs = codec["TunnelAccel"], codec["BeltSpindle"]
    rng = np.random.default_rng(1)
    pulse = np.concatenate([0.05 * rng.normal(size=ticks // 2),
                            -20 + rng.normal(size=ticks - ticks // 2)])
    frames = [acc.encode({"TunnelAccelX": float(p)}, k) for k, p in enumerate(pulse)]
    brs_frames = [brs.encode({"BrsCount": k // 50, "BrsCountsPerRev": 96}, k)
                  for k in range(ticks)]
    lat = np.full(ticks, np.nan)
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
    start = time.perf_counter() + 0.01
    # The sender is also the listener: after each accelerometer frame it waits (blocking,
    # GIL released) for that tick's estimate, like a ping; one thread hand-off each way.
    for k in range(ticks):
        target = start + k * period
        remaining = target - time.perf_counter()
        if remaining > 2e-4:
            time.sleep(remaining - 2e-4)
        while time.perf_counter() < target:
            pass
        if k % 10 == 0:
            tx.send(can.Message(arbitration_id=brs.frame_id, data=brs_frames[k],
                                is_extended_id=False))
        t_send = time.perf_counter()
        tx.send(can.Message(arbitration_id=acc.frame_id, data=frames[k], is_extended_id=False))
        while True:
            m = rx.recv(max(target + period - time.perf_counter(), 0.0))
            if m is None:
                break  # no estimate within the tick: counted as missing latency
            if m.data[1] & 0xF == k & 0xF:
                lat[k] = (time.perf_counter() - t_send) * 1e6
                break
    wall = time.perf_counter() - start
    td.join()
    tx.shutdown()
    rx.shutdown()
    c = node.counters
    proc = read_recording(path, frames=False).ticks["proc_us"] if record else np.full(1, np.nan)
    late = int(np.isnan(lat).sum())
    return {"rate": rate_hz, "ticks": c.ticks, "missed": ticks - c.ticks + c.overruns,
            "no_estimate_in_tick": late,
            "overruns": c.overruns, "lat": lat, "proc": proc,
            "cpu_share": cpu.get("daemon_s", float("nan")) / wall}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ticks", type=int, default=10_000)
    ap.add_argument("--rates", type=float, nargs="+", default=[1000, 2000, 5000, 10000])
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
    print(f"\nDaemon on python-can's virtual bus, {'not ' if a.no_record else ''}recording to "
          f"MCAP, {a.ticks} ticks per rate, "
          "grey-box model (5 states):")
    print(f"  {'rate':>7} {'ticks':>6} {'missed':>6} {'e2e p50':>8} {'p99':>7} {'max':>7}   "
          f"{'tick p50':>8} {'p99':>6} {'max':>7}  {'CPU':>5}")
    workdir = Path(tempfile.mkdtemp())
    for rate in a.rates:
        r = run_rate(model, codec, rate, a.ticks, workdir, not a.no_record)
        lat, proc = r["lat"][~np.isnan(r["lat"])], r["proc"]
        pp = [*np.percentile(proc, [50, 99]), proc.max()]
        p50, p99 = np.percentile(lat, [50, 99])
        print(f"  {rate:>5.0f}Hz {r['ticks']:>6} {r['missed']:>6} {p50:>6.0f}us {p99:>5.0f}us "
              f"{lat.max():>5.0f}us   {pp[0]:>6.1f}us {pp[1]:>4.0f}us {pp[2]:>5.0f}us  "
              f"{100 * r['cpu_share']:>4.0f}%  {r['no_estimate_in_tick']}")
    print("\n  e2e: send call of a TunnelAccel frame -> receipt of its ChestEstimate by the same "
          "thread; late: ticks whose estimate did not arrive within the tick period; tick: "
          "daemon's "
          "frame receipt -> estimate sent (its own measurement); missed: input frames with no "
          "tick plus ticks that took longer than the period; CPU: daemon thread CPU time / "
          "wall time.")


if __name__ == "__main__":
    main()
