"""Sending a schedule of frames with accurate timing.

Each frame has an absolute due time (start + t / rate), so errors never accumulate. The player
sleeps until ``spin_s`` before the due time and spins on ``perf_counter`` for the last
stretch (the OS wakes late by tens of microseconds). The sleep is to an absolute deadline
(``clock_nanosleep`` with ``TIMER_ABSTIME``, as cyclictest sleeps): a relative sleep computed
from a clock read loses whatever preemption falls between the read and the sleep. With
``rt_priority`` the playing thread runs SCHED_FIFO, so a frame falling due preempts every
normal process (:mod:`observer_node.realtime`, shared with the daemon). Lateness (send time
- due time) is measured for every frame and summarised at the end.
"""

from __future__ import annotations

import ctypes
import errno
import gc
import time
from collections.abc import Callable
from dataclasses import dataclass

import can
import numpy as np

from observer_node.realtime import restore_scheduling, set_rt_priority

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
    scheduling: str = "normal scheduling"  # what rt_priority got

    def summary(self) -> str:
        return (f"sent {self.sent} frames in {self.duration_s:.3f} s"
                f"{f', {self.failed} failed' if self.failed else ''}; lateness p50 "
                f"{self.p50_us:.0f} us, p99 {self.p99_us:.0f} us, max {self.max_us:.0f} us; "
                f"{self.late_frames} frames later than {self.late_threshold_us:.0f} us"
                + ("" if self.scheduling == "normal scheduling" else f"; {self.scheduling}"))


class _Timespec(ctypes.Structure):
    _fields_ = [("tv_sec", ctypes.c_long), ("tv_nsec", ctypes.c_long)]


_CLOCK_MONOTONIC, _TIMER_ABSTIME = 1, 1


def _absolute_sleeper() -> Callable[[float], None]:
    """``sleep_until(t_s)``: sleep until ``time.perf_counter()`` reads ``t_s`` (s). On Linux,
    where perf_counter is CLOCK_MONOTONIC, by ``clock_nanosleep(TIMER_ABSTIME)`` (retried
    after a signal: the deadline stays the same); elsewhere by a relative sleep."""
    try:
        nanosleep = ctypes.CDLL(None, use_errno=True).clock_nanosleep
        if "CLOCK_MONOTONIC)" not in time.get_clock_info("perf_counter").implementation:
            raise OSError("perf_counter is not CLOCK_MONOTONIC")
    except (OSError, AttributeError):
        def relative(t_s: float) -> None:
            remaining = t_s - time.perf_counter()
            if remaining > 0:
                time.sleep(remaining)
        return relative
    nanosleep.argtypes = [ctypes.c_int, ctypes.c_int, ctypes.POINTER(_Timespec),
                          ctypes.c_void_p]
    nanosleep.restype = ctypes.c_int
    ts = _Timespec()  # one, reused: a sleep allocates nothing but its integers
    ref = ctypes.byref(ts)
    eintr = errno.EINTR

    def absolute(t_s: float) -> None:
        ns = int(t_s * 1e9)
        ts.tv_sec = ns // 1_000_000_000
        ts.tv_nsec = ns % 1_000_000_000
        while nanosleep(_CLOCK_MONOTONIC, _TIMER_ABSTIME, ref, None) == eintr:
            pass  # a signal (Python raises its exception here, after the call)

    return absolute


sleep_until = _absolute_sleeper()


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
         should_stop: Callable[[], bool] | None = None, rt_priority: int = 0) -> TimingReport:
    """Send every frame of ``schedule`` at its due time scaled by 1/``rate``.

    ``send(k)`` sends frame ``k`` of the schedule (``schedule.ids[k]``, ``schedule.data[k]``)
    and returns False when it could not be sent (counted). ``rt_priority`` (1-99): the
    calling thread plays under SCHED_FIFO at that priority, if allowed (the report's
    ``scheduling`` says), and returns to its own scheduling afterwards.
    """
    n = len(schedule)
    due = schedule.t_s / rate
    if n:
        due = due - due[0]
    lateness = np.zeros(n)
    clock = time.perf_counter
    step = max(1, n // 200)
    # No garbage collection while playing: a collection pauses for up to milliseconds. The
    # loop allocates almost nothing; collect before and after instead.
    gc.collect()
    gc_was_enabled = gc.isenabled()
    gc.disable()
    old, said = set_rt_priority(rt_priority)
    try:
        report = _play(n, due.tolist(), lateness, send, clock, sleep_until, spin_s, step,
                       progress, should_stop)
    finally:
        restore_scheduling(old)
        if gc_was_enabled:
            gc.enable()
    report.scheduling = said
    return report


def _play(n: int, due: list[float], lateness: np.ndarray, send: Callable[[int], bool],
          clock: Callable[[], float], sleep_until: Callable[[float], None], spin_s: float,
          step: int, progress: Callable[[int, int], None] | None,
          should_stop: Callable[[], bool] | None) -> TimingReport:
    failed = 0
    start = clock() + 0.001
    for k in range(n):
        target = start + due[k]
        if target - clock() > spin_s:
            sleep_until(target - spin_s)
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
