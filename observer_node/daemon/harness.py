"""The daemon in a thread of this process on python-can's virtual bus, with a sender and a
listener on its channel: what the tests and the benchmarks drive (``observer-node bench`` does
the same without this module's test hooks).

In-process (``Harness``), or as a script for tests and benchmarks that signal or kill a
daemon's process, fed R16_002 over and over:
    python -m observer_node.daemon.harness MODEL RECORD SECONDS
"""

from __future__ import annotations

import sys
import threading
import time
from pathlib import Path
from typing import Any

import can

from ..data import bundled_campaign, read_isomme
from ..dbc import Codec
from ..model import ModelFile
from ..replay.player import TimingReport, bus_sender, play
from ..replay.schedule import Schedule, crash_test_schedule
from .config import NodeConfig
from .node import ObserverNode
from .ports import PythonCanPort

CODEC = Codec()


def r16_schedule(name: str = "R16_002", reference: bool = True, pre_s: float = 0.2) -> Schedule:
    """A bundled crash test's frames at 1000 Hz, ``pre_s`` s of quiet bus before it."""
    test = read_isomme(bundled_campaign() / f"{name}.zip")
    return crash_test_schedule(test, CODEC, 1000.0, reference=reference, pre_s=pre_s)


class Harness:
    """A daemon on a virtual channel, a sender and a listener on the same channel."""

    def __init__(self, model: ModelFile, channel: str, record: Path | None = None,
                 port_class: type[PythonCanPort] = PythonCanPort, codec: Codec = CODEC,
                 **cfg: Any) -> None:
        """``cfg``: further NodeConfig fields (timeouts, ``live``, ...)."""
        self.cfg = NodeConfig(interface="virtual", channel=channel, record=str(record or ""),
                              **cfg)
        self.node = ObserverNode(self.cfg, model, codec, port_factory=lambda ids: port_class(
            "virtual", channel, ids))
        self.tx = can.Bus(interface="virtual", channel=channel)
        self.rx = can.Bus(interface="virtual", channel=channel)
        self.thread = threading.Thread(target=self.node.run, kwargs={"idle_exit_s": 0.3})
        self.sent = 0  # frames sent through :meth:`send`

    def __enter__(self) -> Harness:
        self.thread.start()
        deadline = time.monotonic() + 30
        while self.node.port is None and time.monotonic() < deadline:
            time.sleep(0.01)
        return self

    def send(self, can_id: int, data: bytes) -> bool:
        self.tx.send(can.Message(arbitration_id=can_id, data=data, is_extended_id=False))
        self.sent += 1
        return True

    def settle(self, timeout_s: float = 10.0) -> bool:
        """Wait until the node has received every frame sent (a loaded machine runs it
        late; leaving the harness stops it with frames still queued). False on timeout."""
        deadline = time.monotonic() + timeout_s
        while self.node.counters.rx < self.sent and time.monotonic() < deadline:
            time.sleep(0.005)
        return self.node.counters.rx >= self.sent

    def play(self, schedule: Schedule, rate: float = 1.0) -> TimingReport:
        return play(schedule, bus_sender(self.tx, schedule), rate=rate)

    def estimates(self) -> list[tuple[float, dict]]:
        """The ChestEstimate frames received since the last call: (receive time in s, signals)."""
        out = []
        est = CODEC["ChestEstimate"]
        while (m := self.rx.recv(0)) is not None:
            if m.arbitration_id == est.frame_id:
                out.append((m.timestamp, est.decode(m.data)))
        return out

    def __exit__(self, *exc: object) -> None:
        self.node.stop_event.set()
        self.thread.join(60)
        self.tx.shutdown()
        self.rx.shutdown()


def main() -> None:
    model, record, seconds = ModelFile.load(sys.argv[1]), Path(sys.argv[2]), float(sys.argv[3])
    sched = r16_schedule(reference=True, pre_s=0.2)
    with Harness(model, "feed", record) as h:
        h.node.install_signal_handlers()
        print("started", flush=True)
        t_end = time.monotonic() + seconds
        while time.monotonic() < t_end and not h.node.stop_event.is_set():
            h.play(sched)
            print(f"ticks {h.node.counters.ticks}", flush=True)


if __name__ == "__main__":
    main()
