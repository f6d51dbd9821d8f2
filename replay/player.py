"""Sending a schedule of frames with accurate timing.

Each frame has an absolute due time (start + t / rate), so errors never accumulate. The player
sleeps until ``spin_s`` before the due time (the OS wakes late by tens of microseconds) and
spins on ``perf_counter`` for the last stretch. Lateness (send time - due time) is measured
for every frame and summarised at the end.
"""

from __future__ import annotations

import gc
import time
from collections.abc import Callable
from dataclasses import dataclass

import can
import numpy as np

from .schedule import Schedule


@dataclass
class TimingReport:
    sent: int
    failed: int
    late_frames: int  # later than ``late_threshold_us``
    late_threshold_us: float
    p50_us: float
    p99_us: float
    max_us: float
    duration_s: float

    def summary(self) -> str:
        return (f"sent {self.sent} frames in {self.duration_s:.3f} s"
                f"{f', {self.failed} failed' if self.failed else ''}; lateness p50 "
                f"{self.p50_us:.0f} us, p99 {self.p99_us:.0f} us, max {self.max_us:.0f} us; "
                f"{self.late_frames} frames later than {self.late_threshold_us:.0f} us")


def lateness_report(lateness_s: np.ndarray, failed: int, duration_s: float,
                    late_threshold_us: float = 100.0) -> TimingReport:
    us = lateness_s * 1e6
    if len(us) == 0:
        return TimingReport(0, failed, 0, late_threshold_us, 0.0, 0.0, 0.0, duration_s)
    return TimingReport(len(us), failed, int((us > late_threshold_us).sum()), late_threshold_us,
                        float(np.percentile(us, 50)), float(np.percentile(us, 99)),
                        float(us.max()), duration_s)


def bus_sender(bus: can.BusABC, schedule: Schedule, fd: bool = False) -> Callable[[int], bool]:
    """A ``send(k)`` for :func:`play` that sends frame ``k`` of ``schedule`` onto a python-can
    bus: every message is built before playing, so sending allocates nothing."""
    msgs = [can.Message(arbitration_id=cid, data=d, is_extended_id=cid > 0x7FF,
                        is_fd=fd, bitrate_switch=fd)
            for cid, d in zip(schedule.ids.tolist(), schedule.data, strict=True)]

    def send(k: int) -> bool:
        try:
            bus.send(msgs[k])
            return True
        except can.CanError:
            return False

    return send


def play(schedule: Schedule, send: Callable[[int], bool], rate: float = 1.0,
         spin_s: float = 0.0003, progress: Callable[[int, int], None] | None = None,
         should_stop: Callable[[], bool] | None = None) -> TimingReport:
    """Send every frame of ``schedule`` at its due time scaled by 1/``rate``.

    ``send(k)`` sends frame ``k`` of the schedule (``schedule.ids[k]``, ``schedule.data[k]``)
    and returns False when it could not be sent (counted).
    """
    n = len(schedule)
    due = schedule.t_s / rate
    if n:
        due = due - due[0]
    lateness = np.zeros(n)
    clock = time.perf_counter
    sleep = time.sleep
    step = max(1, n // 200)
    # No garbage collection while playing: a collection pauses for up to milliseconds. The
    # loop allocates almost nothing; collect before and after instead.
    gc.collect()
    gc_was_enabled = gc.isenabled()
    gc.disable()
    try:
        return _play(n, due, lateness, send, clock, sleep, spin_s, step, progress, should_stop)
    finally:
        if gc_was_enabled:
            gc.enable()


def _play(n: int, due: np.ndarray, lateness: np.ndarray, send: Callable[[int], bool],
          clock: Callable[[], float], sleep: Callable[[float], None], spin_s: float, step: int,
          progress: Callable[[int, int], None] | None,
          should_stop: Callable[[], bool] | None) -> TimingReport:
    failed = 0
    start = clock() + 0.001
    for k in range(n):
        target = start + due[k]
        remaining = target - clock()
        if remaining > spin_s:
            sleep(remaining - spin_s)
        while clock() < target:
            pass
        lateness[k] = clock() - target  # when the frame is handed to the bus
        if not send(k):
            failed += 1
        if progress is not None and k % step == 0:
            progress(k, n)
            if should_stop is not None and should_stop():
                lateness = lateness[:k + 1]
                break
    return lateness_report(lateness, failed, clock() - start)
