"""Keeping the CPUs awake, and a timed loop ahead of other processes: the daemon's tick loop
and crash-replay's player both use it (neither imports the other's internals).

A tick starts with a wake-up: the daemon sleeps in ``recv`` until a frame arrives. When the
CPU it wakes on has gone into a deep idle state (or, in a VM, halted its virtual CPU), that
wake-up costs tens to hundreds of microseconds, more than the tick itself. Linux's PM QoS
interface lets a process cap the idle-state exit latency while it holds
``/dev/cpu_dma_latency`` open; real-time tools (cyclictest, EtherCAT masters) hold it at 0,
which keeps idle CPUs polling. It costs power, nothing else, and ends with the process.
"""

from __future__ import annotations

import contextlib
import os
import struct
from typing import BinaryIO

PM_QOS_DEVICE = "/dev/cpu_dma_latency"


def hold_cpu_latency(max_us: int, device: str = PM_QOS_DEVICE) -> tuple[BinaryIO | None, str]:
    """Ask the kernel to keep every CPU's wake-up latency at or below ``max_us``
    (microseconds) for as long as the returned file stays open. A negative ``max_us`` asks
    nothing. Returns ``(file or None, a line saying what happened)``; it fails soft, as the
    daemon works without it (only its wake-ups are slower): the device needs root."""
    if max_us < 0:
        return None, "CPU wake-up latency left to power management"
    try:
        # Write-only, never create: the device exists or PM QoS is not there.
        f = os.fdopen(os.open(device, os.O_WRONLY), "wb", buffering=0)
    except OSError as e:
        return None, (f"CPU wake-up latency not held ({device}: {e.strerror}); ticks wait "
                      "longer for idle CPUs to wake")
    try:
        f.write(struct.pack("=i", int(max_us)))
    except OSError as e:
        f.close()
        return None, f"CPU wake-up latency not held ({device}: {e.strerror})"
    return f, f"CPU wake-up latency held at {int(max_us)} us ({device})"


def set_rt_priority(priority: int) -> tuple[tuple[int, int] | None, str]:
    """Run the calling thread under ``SCHED_FIFO`` at ``priority`` (1-99), as real-time
    tools do (cyclictest, EtherCAT masters): a frame's arrival, or a frame falling due,
    then preempts every normal process at once, a Foxglove app or a browser on the same PC
    included. 0 asks nothing. ``SCHED_RESET_ON_FORK``: processes started later (the
    daemon's recorder) run at normal priority.
    Returns ``(the previous (policy, priority) or None, a line saying what happened)``; it
    fails soft, as :func:`hold_cpu_latency` does: it needs root, CAP_SYS_NICE or
    RLIMIT_RTPRIO >= ``priority``. The kernel's real-time throttling (95 % of each second
    by default) keeps a runaway thread from freezing the machine; the daemon's sleeps in
    recv, the player's until each frame's due time."""
    if priority <= 0:
        return None, "normal scheduling"
    old = os.sched_getscheduler(0), os.sched_getparam(0).sched_priority
    try:
        os.sched_setscheduler(0, os.SCHED_FIFO | os.SCHED_RESET_ON_FORK,
                              os.sched_param(priority))
    except OSError as e:
        return None, (f"real-time priority not set (SCHED_FIFO {priority}: {e.strerror}; needs "
                      "root, CAP_SYS_NICE or RLIMIT_RTPRIO); it shares the CPUs with "
                      "every other process")
    return old, f"SCHED_FIFO priority {priority}"


def restore_scheduling(old: tuple[int, int] | None) -> None:
    """Undo :func:`set_rt_priority` for the calling thread."""
    if old is not None:
        with contextlib.suppress(OSError):
            os.sched_setscheduler(0, old[0], os.sched_param(old[1]))
