"""Crash tests turned into timed CAN frames, as the sensor ECUs would send them.

The accelerometer goes out once per tick at the DBC rate (``rate_hz``), resampled from the lab
rate with the causal anti-alias filter the identification also uses
(:func:`observer_node.data.resample_inputs`), in SAE J211 sign. The BRS goes out when its count
changes (at most once per tick) and every ``brs_heartbeat_s``. With ``reference``, the dummy's
measured CR and CD go out every tick (zero-phase decimated, model convention). Within a tick
the BRS and reference frames precede the accelerometer frame, so the observer ticks on fresh
values. Times are seconds from the first frame.

With ``burst`` (CAN FD, for tick rates a frame per sample cannot carry), eight consecutive
ticks go out as one InputBurst frame, each accelerometer sample paired with the BRS count held
at it, sent with the last of them; the reference, if any, goes once per burst (its last tick).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from observer_node.data import CrashTest
from observer_node.data.crashtest import resample_inputs, resample_reference
from observer_node.dbc import Codec
from observer_node.errors import UsageError


@dataclass
class Schedule:
    t_s: np.ndarray  # send times, non-decreasing
    ids: np.ndarray
    data: list[bytes]
    source: str = ""
    synthetic: bool = False  # encoded here from lab data (not a recorded log)
    # The frames the logging node sent, left out without --all-frames: their times [s] (this
    # schedule's time base) and IDs, so that --only one of them can name --all-frames
    sent: tuple[np.ndarray, np.ndarray] = (np.zeros(0), np.zeros(0, np.int64))
    # First and last send time [s] of the source as read, kept when --only leaves frames out:
    # looped copies and several sources are spaced as they are unfiltered
    span_s: tuple[float, float] | None = None

    def __len__(self) -> int:
        return len(self.data)

    @property
    def sent_ids(self) -> frozenset[int]:
        return frozenset(self.sent[1].tolist())

    @property
    def span(self) -> tuple[float, float] | None:
        """The time it covers [s]: its own, or the unfiltered source's (None: empty)."""
        if self.span_s is not None:
            return self.span_s
        return (float(self.t_s[0]), float(self.t_s[-1])) if len(self) else None

    def only(self, ids: set[int]) -> Schedule:
        """Its frames of the CAN IDs in ``ids``, the time it covers kept."""
        return self._take(np.isin(self.ids, sorted(ids)), self.span, self.sent)

    def within(self, keep: np.ndarray, sent_keep: np.ndarray) -> Schedule:
        """The frames where ``keep`` and the sent frames where ``sent_keep`` are True."""
        return self._take(keep, None, (self.sent[0][sent_keep], self.sent[1][sent_keep]))

    def _take(self, keep: np.ndarray, span_s: tuple[float, float] | None,
              sent: tuple[np.ndarray, np.ndarray]) -> Schedule:
        idx = np.flatnonzero(keep)
        return replace(self, t_s=self.t_s[idx], ids=self.ids[idx],
                       data=[self.data[i] for i in idx], sent=sent, span_s=span_s)

    def shifted(self, dt_s: float) -> Schedule:
        span = self.span_s
        return replace(self, t_s=self.t_s + dt_s, sent=(self.sent[0] + dt_s, self.sent[1]),
                       span_s=None if span is None else (span[0] + dt_s, span[1] + dt_s))


def restamp_counters(s: Schedule, codec: Codec) -> Schedule:
    """Number the E2E alive counters of each frame ID continuously (and redo the CRCs), as
    one sensor would over several tests played in a row."""
    counters: dict[int, int] = {}
    data = []
    for cid, d in zip(s.ids.tolist(), s.data, strict=True):
        fc = codec.by_id.get(cid)
        if fc is None or not fc.has_e2e or len(d) != fc.length:
            data.append(d)
            continue
        k = counters.get(cid, 0)
        counters[cid] = k + 1
        data.append(fc.with_counter(d, k))
    return replace(s, data=data)


def concat(schedules: list[Schedule], gap_s: float = 0.5) -> Schedule:
    """Play schedules one after another with ``gap_s`` between them, each over the time it
    covers (:attr:`Schedule.span`)."""
    parts, offset = [], 0.0
    for s in schedules:
        span = s.span
        if span is None:
            continue
        parts.append(s.shifted(offset - span[0]))
        offset += span[1] - span[0] + gap_s
    sent = (np.concatenate([np.zeros(0), *(p.sent[0] for p in parts)]),
            np.concatenate([np.zeros(0, np.int64), *(p.sent[1] for p in parts)]))
    if not any(len(p) for p in parts):
        return Schedule(np.zeros(0), np.zeros(0, int), [], sent=sent)
    parts = [p for p in parts if len(p)]
    return Schedule(np.concatenate([p.t_s for p in parts]),
                    np.concatenate([p.ids for p in parts]),
                    [d for p in parts for d in p.data], _names(parts),
                    all(p.synthetic for p in parts), sent)


def check_window(name: str, t: np.ndarray, start_s: float | None, end_s: float | None) -> None:
    """One line naming --start or --end and the span of ``t`` when the window holds none of
    its times: it would play nothing, or a lab test's quiet --pre signal alone."""
    inside = np.ones(len(t), bool)
    if start_s is not None:
        inside &= t >= start_s - 1e-9
    if end_s is not None:
        inside &= t <= end_s + 1e-9
    if not len(t) or inside.any():
        return
    span = f"{name} runs from {t[0]:.3f} to {t[-1]:.3f} s"
    if start_s is not None and start_s > t[-1]:
        raise UsageError(f"--start {start_s:g} s is after the end: {span}")
    if end_s is not None and end_s < t[0]:
        raise UsageError(f"--end {end_s:g} s is before the start: {span}")
    raise UsageError(f"--start {start_s:g} to --end {end_s:g} s holds no sample: {span}")


def crash_test_schedule(test: CrashTest, codec: Codec, rate_hz: float = 1000.0,
                        reference: bool = False, brs_heartbeat_s: float = 0.01,
                        start_s: float | None = None, end_s: float | None = None,
                        pre_s: float = 0.0, burst: bool = False) -> Schedule:
    """Frames for one crash test between ``start_s`` and ``end_s`` (test time, default all).
    ``pre_s`` prepends that much quiet signal (the mean pulse before first contact, held)
    so a daemon can estimate the accelerometer bias before the crash."""
    if test.counts_per_rev is None:
        raise ValueError(f"{test.source or test.name}: BRS counts/rev unknown")
    pulse, brs, step = resample_inputs(test.pulse_g, test.brs, test.fs_hz, rate_hz)
    t = test.t0_s + np.arange(len(pulse)) * step / test.fs_hz
    cr = cd = None
    if reference and test.has_outputs:
        cr = resample_reference(test.cr_g, step)[:len(pulse)]  # type: ignore[arg-type]
        cd = resample_reference(test.cd_mm, step)[:len(pulse)]  # type: ignore[arg-type]
    check_window(test.source or test.name, t, start_s, end_s)
    lo = 0 if start_s is None else int(np.searchsorted(t, start_s - 1e-9))
    hi = len(t) if end_s is None else int(np.searchsorted(t, end_s + 1e-9))
    n_pre = round(pre_s * rate_hz)
    quiet = t < 0
    pulse = np.append(pulse, pulse[quiet].mean() if quiet.any() else 0.0)  # index -1: padding
    idx = np.concatenate([np.full(n_pre, -1), np.arange(lo, hi)])
    acc, bfc, ref = codec["TunnelAccel"], codec["BeltSpindle"], codec["ReferenceChest"]
    if burst:
        return _burst_schedule(test, codec, rate_hz, idx, lo, pulse, brs, cr, cd)
    heartbeat = max(1, round(brs_heartbeat_s * rate_hz))
    times, ids, data = [], [], []
    last_brs = None
    n_brs = 0
    for k, i in enumerate(idx):
        tk = k / rate_hz
        count = int(brs[max(i, lo)] if i < 0 else brs[i])
        if count != last_brs or k % heartbeat == 0:
            times.append(tk)
            ids.append(bfc.frame_id)
            data.append(bfc.encode({"BrsCount": count, "BrsCountsPerRev": test.counts_per_rev,
                                    "BeltSpindle_Bidirectional": 1}, n_brs))
            n_brs += 1
            last_brs = count
        if cr is not None and cd is not None:
            times.append(tk)
            ids.append(ref.frame_id)
            j = lo if i < 0 else i
            data.append(ref.encode({"RefChestAccelCR": cr[j], "RefChestDeflCD": cd[j]}, k))
        times.append(tk)
        ids.append(acc.frame_id)
        data.append(acc.encode({"TunnelAccelX": -pulse[i]}, k))  # model -> J211 sign
    return Schedule(np.array(times), np.array(ids), data, test.name, synthetic=True)


BURST_SAMPLES = 8  # samples per InputBurst frame (the DBC's layout)


def _burst_schedule(test: CrashTest, codec: Codec, rate_hz: float, idx: np.ndarray, lo: int,
                    pulse: np.ndarray, brs: np.ndarray, cr: np.ndarray | None,
                    cd: np.ndarray | None) -> Schedule:
    fc, ref = codec["InputBurst"], codec["ReferenceChest"]
    times, ids, data = [], [], []
    n_frames = len(idx) // BURST_SAMPLES  # a partial last burst is not sent
    for f in range(n_frames):
        values: dict[str, float] = {"BurstCountsPerRev": test.counts_per_rev or 0,
                                    "InputBurst_Bidirectional": 1}
        for j in range(BURST_SAMPLES):
            i = idx[f * BURST_SAMPLES + j]
            values[f"BurstAccelX{j}"] = -pulse[i]  # model -> J211 sign
            values[f"BurstBrsCount{j}"] = int(brs[lo] if i < 0 else brs[i])
        tk = ((f + 1) * BURST_SAMPLES - 1) / rate_hz
        if cr is not None and cd is not None:
            j = max(int(idx[(f + 1) * BURST_SAMPLES - 1]), lo)
            times.append(tk)
            ids.append(ref.frame_id)
            data.append(ref.encode({"RefChestAccelCR": cr[j], "RefChestDeflCD": cd[j]}, f))
        times.append(tk)
        ids.append(fc.frame_id)
        data.append(fc.encode(values, f))
    return Schedule(np.array(times), np.array(ids), data, test.name, synthetic=True)


def _names(parts: list[Schedule]) -> str:
    """The sources' names, "A+B", a run of one repeated as "A x3" (--loop 3838 wrote the
    name 3838 times)."""
    names = [p.source for p in parts]
    k = len(names)
    for n in range(1, k // 2 + 1):  # the shortest period that repeats to the whole
        if k % n == 0 and names == names[:n] * (k // n):
            return f"{'+'.join(names[:n])} x{k // n}"
    return "+".join(names)
