"""Fuzzed CAN traffic for the daemon: random IDs, DLCs and payloads, valid-CRC frames with wild
values, bad alive counters, error and remote frames. Used by the bounded fuzz test
(tests/test_fuzz.py) and by ``benchmarks/fuzz.py`` (a million frames)."""

from __future__ import annotations

import os
import time
from collections.abc import Callable

import can
import numpy as np

from .harness import CODEC, Harness

INPUTS = ("TunnelAccel", "BeltSpindle", "ReferenceChest", "InputBurst")


def fuzz_frame(rng: np.random.Generator, counters: dict[int, int]) -> can.Message:
    """One frame of a mix of the ways a bus can lie."""
    kind = rng.integers(8)
    if kind == 0:  # any ID, any DLC, any bytes
        n = int(rng.integers(0, 9))
        return can.Message(arbitration_id=int(rng.integers(0x800)), data=rng.bytes(n),
                           is_extended_id=False)
    if kind == 1:  # an error frame
        return can.Message(arbitration_id=0, is_error_frame=True, data=rng.bytes(8))
    if kind == 2:  # a remote frame on an input ID
        fc = CODEC[INPUTS[int(rng.integers(2))]]
        return can.Message(arbitration_id=fc.frame_id, is_remote_frame=True, dlc=fc.length,
                           is_extended_id=False)
    fc = CODEC[INPUTS[int(rng.integers(3 if kind < 7 else 4))]]
    if kind == 3:  # right ID, wrong length
        n = int(rng.integers(0, 9))
        n = n if n != fc.length else n - 1
        return can.Message(arbitration_id=fc.frame_id, data=rng.bytes(n), is_extended_id=False)
    # right ID and length, random payload; with a valid CRC and counter in kinds 5..7
    data = bytearray(rng.bytes(fc.length))
    if kind >= 5:
        k = counters.get(fc.frame_id, 0)
        if kind == 6:
            k += int(rng.integers(0, 16))  # a counter that repeats or jumps
        counters[fc.frame_id] = k + 1
        raw = fc.unpack(bytes(data))
        for i, name in enumerate(fc.signal_names):  # sensor faults mostly clear
            if "Fault" in name:
                raw[i] = int(rng.random() < 0.1)
        data = bytearray(fc.with_counter(fc.pack(raw), k))  # the DBC's profile and CRC
    return can.Message(arbitration_id=fc.frame_id, data=bytes(data), is_extended_id=False,
                       is_fd=fc.length > 8)


def run_fuzz(h: Harness, n: int, seed: int, batch: int = 200,
             on_batch: Callable[[int], object] | None = None) -> int:
    """Send ``n`` fuzzed frames into the harness's daemon, ``batch`` at a time, each batch
    only once the daemon has received what passes its port's filter (its input IDs), so
    nothing piles up in the virtual bus's queues; drain the listener as it goes. Returns
    how many frames passed the filter."""
    rng = np.random.default_rng(seed)
    counters: dict[int, int] = {}
    ids = set(h.node.input_ids)
    sent = passed = 0
    base = h.node.counters.rx
    while sent < n:
        k = min(batch, n - sent)
        for _ in range(k):
            m = fuzz_frame(rng, counters)
            passed += m.arbitration_id in ids and not m.is_error_frame
            h.tx.send(m)
        sent += k
        deadline = time.monotonic() + 30
        while h.node.counters.rx < base + passed and time.monotonic() < deadline:
            time.sleep(0.0005)
        for bus in (h.rx, h.tx):  # the sender's queue gets the daemon's frames too
            while bus.recv(0) is not None:
                pass
        if on_batch is not None:
            on_batch(sent)
    return passed


def rss_mb() -> float:
    """This process's resident memory in MB (Linux)."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20
