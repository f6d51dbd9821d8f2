"""The daemon's inputs: the accelerometer, BRS, InputBurst and reference frames, checked and
handed to the observer core.

Every position (CRC, alive counter, fault flags, values) is looked up in the codec once, by
signal name, at start-up: the DBC is the only place that knows where a bit is, and the per-
frame work is an unpack, a few shifts and masks and the E2E check. Each received frame is
counted once in :class:`Counters`: accepted, rejected (length, remote frame, bad reference),
bad_e2e, unknown_id or error_frames.

The alive counter is checked as AUTOSAR's E2E receiver does (the PRS's check status, per
input frame ID; the CRC by the autosar-e2e library): the first frame is INITIAL; a step of
one is OK; a step of 2..``max_delta`` is OK_SOME_LOST (the frames between are lost, and the
accelerometer's are bridged so the observer keeps time); no step is REPEATED and more than
``max_delta`` is WRONG_SEQUENCE: both are rejected and counted and leave the last valid
counter where it was, so a stale or reordered frame is not read as frames lost (it used to
be: 14 "lost" frames bridged by phantom ticks). ``max_delta`` is half the counter's range
(P01 7, P05 128): a counter is read the shorter way round, ahead as frames lost, behind as
a stale frame. When the sender's sequence really moves on (a restart, an outage longer than
that), the second frame in sequence with a rejected one is followed (a resync: counted,
flagged as a loss, not bridged, since how many were lost is not known).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from observer_node.dbc import Codec, FrameCodec

from .core import BAD_E2E, LOST_FRAME, OUT_OF_RANGE, SENSOR_FAULT, ObserverCore


@dataclass
class Counters:
    """Every received frame is counted once as accepted, rejected, bad_e2e, unknown_id or
    error_frames (rx is their sum); the others count events (``repeated`` and
    ``wrong_sequence`` the frames of bad_e2e that were so, ``resyncs`` the E2E receiver
    following a sender's new sequence)."""

    rx: int = 0
    accepted: int = 0
    ticks: int = 0
    lost: int = 0
    rejected: int = 0
    bad_e2e: int = 0
    repeated: int = 0
    wrong_sequence: int = 0
    resyncs: int = 0
    unknown_id: int = 0
    error_frames: int = 0
    overruns: int = 0
    tx_dropped: int = 0
    reconnects: int = 0
    accel_timeouts: int = 0
    brs_timeouts: int = 0
    kernel_dropped: int = 0


class _Layout:
    """One input frame's positions, resolved from the codec."""

    def __init__(self, fc: FrameCodec, prefix: str, faults: tuple[str, ...]):
        self.id, self.length, self.struct = fc.frame_id, fc.length, fc.struct
        self.e2e_check = fc.e2e_checker()  # the DBC's profile, by the E2E library
        self.cnt_slot, self.cnt_shift, self.cnt_mask = fc.locate(f"{prefix}_Counter")
        self.cnt_modulus = fc.counter_modulus  # P01: 0..14, P05: 0..255
        self.max_delta = self.cnt_modulus // 2  # further ahead reads as behind: stale
        self.faults = tuple(fc.locate(f"{prefix}_{name}")[:2] for name in faults)
        self.last = -1  # the last valid alive counter, -1: none yet (wait for first data)
        self.rejected = -1  # the last WRONG_SEQUENCE counter: a new sequence may start there


# Publish one tick: (receive time, accelerometer g, send the estimate frame?, ticks in frame)
Publish = Callable[[float, float, bool, int], None]


class Inputs:
    """Decodes input frames for one :class:`ObserverCore`; ``publish`` is called once per
    tick the core makes."""

    def __init__(self, codec: Codec, core: ObserverCore, counters: Counters,
                 counts_per_rev: int, publish: Publish):
        self.core, self.counters, self.publish = core, counters, publish
        self.default_per_rev = counts_per_rev
        acc, brs, burst, ref = (codec["TunnelAccel"], codec["BeltSpindle"],
                                codec["InputBurst"], codec["ReferenceChest"])
        self.acc = _Layout(acc, "TunnelAccel", ("SensorFault",))
        self.acc_x = acc.locate("TunnelAccelX")[0]
        self.acc_scale = acc.scale("TunnelAccelX")
        self.acc_lo, self.acc_hi = acc.raw_range("TunnelAccelX")
        self.brs = _Layout(brs, "BeltSpindle", ("SensorFault",))
        self.brs_count = brs.locate("BrsCount")[0]
        self.brs_per_rev = brs.locate("BrsCountsPerRev")[0]
        self.burst = _Layout(burst, "InputBurst", ("AccelFault", "BrsFault"))
        self.burst_n = sum(1 for n in burst.signal_names if n.startswith("BurstAccelX"))
        self.burst_accel = tuple(burst.locate(f"BurstAccelX{j}")[0]
                                 for j in range(self.burst_n))
        self.burst_brs = tuple(burst.locate(f"BurstBrsCount{j}")[0]
                               for j in range(self.burst_n))
        self.burst_per_rev = burst.locate("BurstCountsPerRev")[0]
        self.ref_id, self.ref_len, self.ref_struct = ref.frame_id, ref.length, ref.struct
        self.ref_check = ref.e2e_checker()
        self.ref_cr_slot = ref.locate("RefChestAccelCR")[0]
        self.ref_cd_slot = ref.locate("RefChestDeflCD")[0]
        self.ref_scale_cr = ref.scale("RefChestAccelCR")
        self.ref_scale_cd = ref.scale("RefChestDeflCD")
        self.ids = [self.acc.id, self.burst.id, self.brs.id, self.ref_id]
        self.reset()

    def reset(self) -> None:
        """No alive counter seen yet (a new run, or the bus came back)."""
        for lay in (self.acc, self.brs, self.burst):
            lay.last = lay.rejected = -1
        self.ref_cr = self.ref_cd = math.nan

    # ------------------------------------------------------------------ per frame
    def _admit(self, lay: _Layout, data: bytes) -> tuple[tuple, int]:
        """Unpack and E2E-check an input frame of the right length (the receiver's check,
        see the module's docstring): its values and how many frames were lost before it
        (counted), or -1 for a frame rejected (bad CRC, REPEATED, WRONG_SEQUENCE: counted,
        flagged). An accepted frame's counter becomes the last valid one."""
        v = lay.struct.unpack_from(data)
        cnt = self.counters
        if not lay.e2e_check(data):
            cnt.bad_e2e += 1
            self.core.fault(BAD_E2E)
            return v, -1
        counter = v[lay.cnt_slot] >> lay.cnt_shift & lay.cnt_mask
        last, gap = lay.last, 0
        if last >= 0:  # else INITIAL
            delta = (counter - last) % lay.cnt_modulus
            if delta == 0:
                cnt.repeated += 1
                return self._reject(v)
            if delta > lay.max_delta:
                if lay.rejected < 0 or (counter - lay.rejected) % lay.cnt_modulus != 1:
                    lay.rejected = counter
                    cnt.wrong_sequence += 1
                    return self._reject(v)
                cnt.resyncs += 1  # in sequence with the frame rejected before: follow it
                cnt.lost += (lay.rejected - last - 1) % lay.cnt_modulus
                self.core.fault(LOST_FRAME)
            else:
                gap = delta - 1  # OK, or OK_SOME_LOST
                cnt.lost += gap
        cnt.accepted += 1
        lay.last, lay.rejected = counter, -1
        return v, gap

    def _reject(self, v: tuple) -> tuple[tuple, int]:
        self.counters.bad_e2e += 1
        self.core.fault(BAD_E2E)
        return v, -1

    def _flags(self, lay: _Layout, v: tuple) -> None:
        """The sensors' own fault flags."""
        for slot, shift in lay.faults:
            if v[slot] >> shift & 1:
                self.core.fault(SENSOR_FAULT)

    def _wrong_length(self) -> None:
        self.counters.rejected += 1
        self.core.fault(OUT_OF_RANGE)

    def accel(self, t: float, data: bytes) -> None:
        lay = self.acc
        if len(data) != lay.length:
            return self._wrong_length()
        v, gap = self._admit(lay, data)
        if gap < 0:
            return None
        core = self.core
        if gap:
            core.bridge(gap)
        self._flags(lay, v)
        raw = v[self.acc_x]
        if raw <= self.acc_lo or raw >= self.acc_hi:
            core.fault(OUT_OF_RANGE)  # saturated sensor: used, but flagged
        accel_g = raw * self.acc_scale
        core.tick(-accel_g)  # J211 X acceleration -> deceleration positive
        self.counters.ticks += 1
        self.publish(t, accel_g, True, 1)
        return None

    def burst_frame(self, t: float, data: bytes) -> None:
        """An InputBurst frame: ``burst_n`` ticks, each with its own BRS count; one estimate
        frame (the last tick's) goes out, every tick is recorded."""
        lay, n = self.burst, self.burst_n
        if len(data) != lay.length:
            return self._wrong_length()
        v, gap = self._admit(lay, data)
        if gap < 0:
            return None
        core = self.core
        if gap:
            core.bridge(gap * n)
        self._flags(lay, v)
        per_rev = v[self.burst_per_rev] or self.default_per_rev
        lo, hi, scale = self.acc_lo, self.acc_hi, self.acc_scale
        for j in range(n):
            raw = v[self.burst_accel[j]]
            if raw <= lo or raw >= hi:
                core.fault(OUT_OF_RANGE)
            core.set_brs(float(v[self.burst_brs[j]]), per_rev)
            accel_g = raw * scale
            core.tick(-accel_g)
            self.counters.ticks += 1
            self.publish(t, accel_g, j == n - 1, n)
        return None

    def brs_frame(self, data: bytes) -> None:
        lay = self.brs
        if len(data) != lay.length:
            return self._wrong_length()
        v, gap = self._admit(lay, data)
        if gap < 0:
            return None
        if gap:
            self.core.fault(LOST_FRAME)  # the count held meanwhile may have been stale
        self._flags(lay, v)
        self.core.set_brs(float(v[self.brs_count]), v[self.brs_per_rev] or self.default_per_rev)
        return None

    def reference(self, data: bytes) -> None:
        if len(data) != self.ref_len or not self.ref_check(data):
            self.counters.rejected += 1
            return
        self.counters.accepted += 1
        v = self.ref_struct.unpack_from(data)
        self.ref_cr = v[self.ref_cr_slot] * self.ref_scale_cr
        self.ref_cd = v[self.ref_cd_slot] * self.ref_scale_cd
