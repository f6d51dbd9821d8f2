"""The AUTOSAR E2E receiver's view, both ways.

What the daemon sends: a P01 receiver (the PRS's check, written here from the profile, the
CRC by the autosar-e2e library) listening to every frame the daemon sends over a bench-like
run rates each ChestEstimate OK: one counter step per frame sent, none REPEATED (watchdog
publishes used to repeat the counter), none WRONG_SEQUENCE (InputBurst used to step it by 8).

What the daemon receives: a stale frame mid-crash (an older counter with a valid CRC) is
rejected as WRONG_SEQUENCE and counted, not read as 14 lost frames bridged by phantom ticks:
the estimates equal the clean run's tick for tick and the ChestCriteria frame is the clean
run's. A repeated frame likewise; a reordered pair keeps the time (the frame that came too
early is read as one lost, the late one is rejected) and flags the event's criteria.
"""

from __future__ import annotations

import threading
import time
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from observer_node.daemon.core import LOST_FRAME, CoreConfig, ObserverCore
from observer_node.daemon.harness import CODEC, Harness, r16_schedule
from observer_node.daemon.inputs import Counters, Inputs
from observer_node.data import bundled_campaign, read_isomme
from observer_node.dbc import FrameCodec
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.recording import analyze, read_recording
from observer_node.replay.schedule import Schedule, concat, crash_test_schedule, restamp_counters

OK, INITIAL, REPEATED, OK_SOME_LOST, WRONG_SEQUENCE, WRONG_CRC = (
    "OK", "INITIAL", "REPEATED", "OK_SOME_LOST", "WRONG_SEQUENCE", "WRONG_CRC")
OUTPUTS = ("ChestEstimate", "ObserverStatus", "ObserverCounters", "ObserverHealth",
           "ChestCriteria")


class P01Receiver:
    """E2E_P01Check as the PRS defines it, one call per received frame: MaxDeltaCounter
    grows by one per call (to 14) and is reset to its initial value by an OK frame; a
    repeated or out-of-sequence frame leaves the last valid counter where it is."""

    def __init__(self, fc: FrameCodec, max_delta_counter_init: int = 1):
        assert fc.e2e_profile == "P01"
        self.fc, self.init = fc, max_delta_counter_init
        self.counter_name = next(n for n in fc.signal_names if n.endswith("_Counter"))
        self.last: int | None = None
        self.max_delta = max_delta_counter_init
        self.status: Counter[str] = Counter()

    def check(self, data: bytes) -> str:
        self.max_delta = min(self.max_delta + 1, 14)
        if not self.fc.e2e_check(data):  # the autosar-e2e library's CRC check
            return self._is(WRONG_CRC)
        c = int(self.fc.decode(data)[self.counter_name])
        if self.last is None:
            self.last, self.max_delta = c, self.init
            return self._is(INITIAL)
        delta = (c - self.last) % 15
        if delta == 0:
            return self._is(REPEATED)
        if delta > self.max_delta:
            return self._is(WRONG_SEQUENCE)
        self.last, self.max_delta = c, self.init
        return self._is(OK if delta == 1 else OK_SOME_LOST)

    def _is(self, status: str) -> str:
        self.status[status] += 1
        return status


def _play(model, channel: str, sched: Schedule, record: Path | None = None, events: int = 1,
          **cfg):
    """Play ``sched`` into a daemon and listen until ``events`` ChestCriteria frames went
    out; the daemon (its counters, its core), every frame it sent (id, data) in bus order,
    and the recording if any. The daemon runs until then, not until it has been idle for a
    while: a loaded machine may stall the sender longer than any idle limit."""
    h = Harness(model, channel, record, **cfg)
    h.thread = threading.Thread(target=h.node.run)
    crit = CODEC["ChestCriteria"].frame_id
    sent: list[tuple[int, bytes]] = []
    with h:
        h.play(sched)
        deadline = time.monotonic() + 30
        while sum(cid == crit for cid, _ in sent) < events and time.monotonic() < deadline:
            if (m := h.rx.recv(0.1)) is not None:
                sent.append((m.arbitration_id, bytes(m.data)))
        while (m := h.rx.recv(0.05)) is not None:  # and what followed it
            sent.append((m.arbitration_id, bytes(m.data)))
    return h.node, sent, read_recording(record) if record else None


def _rate_outputs(sent: list[tuple[int, bytes]]) -> dict[str, Counter[str]]:
    rx = {name: P01Receiver(CODEC[name]) for name in OUTPUTS}
    by_id = {CODEC[name].frame_id: r for name, r in rx.items()}
    for cid, data in sent:
        if cid in by_id:
            by_id[cid].check(data)
    return {name: r.status for name, r in rx.items()}


def _assert_one_step_per_frame(rated: dict[str, Counter[str]], tx_dropped: int) -> None:
    for name, status in rated.items():
        assert status[REPEATED] == status[WRONG_SEQUENCE] == status[WRONG_CRC] == 0, \
            (name, status)
    est = rated["ChestEstimate"]
    assert est[OK_SOME_LOST] <= tx_dropped, est  # a frame the port refused is a lost one
    assert est[OK] > 100, est


# ------------------------------------------------------------------ what the daemon sends

def test_estimate_counter_steps_once_per_frame_over_a_bench_like_run(model):
    """Two crash tests 0.3 s apart with reference frames, as the bench plays them: between
    and after them the watchdog publishes an invalid estimate each tick period."""
    sched = restamp_counters(concat([r16_schedule(), r16_schedule()], gap_s=0.3), CODEC)
    node, sent, _ = _play(model, "e2e-rx-1k", sched, events=2)
    c = node.counters
    assert c.accel_timeouts >= 1  # the watchdog did publish
    rated = _rate_outputs(sent)
    _assert_one_step_per_frame(rated, c.tx_dropped)
    assert rated["ChestCriteria"][INITIAL] == 1 and rated["ChestCriteria"][OK] >= 1


def test_estimate_counter_steps_once_per_burst_frame(campaign):
    """InputBurst at 10 kHz: eight ticks, one estimate frame, one counter step."""
    est = [t for t in campaign if t.name in ("R16_001", "R16_003", "R16_005")]
    data = make_dataset(est, 1000.0)
    model = greybox.to_model_file(greybox.fit_greybox(data), data, tick_rate_hz=10_000.0)
    test = read_isomme(bundled_campaign() / "R16_002.zip")
    sched = crash_test_schedule(test, CODEC, 10_000.0, reference=True, pre_s=0.2, burst=True)
    node, sent, _ = _play(model, "e2e-rx-burst", sched)
    c = node.counters
    assert c.ticks == 8 * int((sched.ids == CODEC["InputBurst"].frame_id).sum())
    _assert_one_step_per_frame(_rate_outputs(sent), c.tx_dropped)


# ------------------------------------------------------------------ what the daemon receives

ACC = CODEC["TunnelAccel"]


def _accel_index(sched: Schedule, t_s: float) -> int:
    """The first accelerometer frame at or after ``t_s``."""
    return next(i for i, (t, cid) in enumerate(zip(sched.t_s, sched.ids, strict=True))
                if cid == ACC.frame_id and t >= t_s)


def _with_frame(sched: Schedule, after: int, data: bytes, dt_s: float) -> Schedule:
    """``sched`` with an accelerometer frame inserted ``dt_s`` after frame ``after``."""
    k = after + 1
    return Schedule(np.insert(sched.t_s, k, sched.t_s[after] + dt_s),
                    np.insert(sched.ids, k, ACC.frame_id),
                    [*sched.data[:k], data, *sched.data[k:]], sched.source, sched.synthetic)


MID_CRASH_S = 0.2 + 0.04  # 40 ms after the test's t = 0 (0.2 s of quiet lead-in)
# Timeouts far above the scheduling stalls of a loaded machine, so that only the frames
# under test flag an estimate or an event (the event then ends on its own or a second after
# the test's last frame, well within idle_after_s, the watchdog's span).
PATIENT = {"accel_timeout_s": 1.0, "brs_timeout_s": 1.0, "idle_after_s": 5.0}


@pytest.fixture(scope="module")
def clean_run(model, tmp_path_factory):
    rec = tmp_path_factory.mktemp("clean") / "run.mcap"
    return _play(model, "e2e-clean", r16_schedule(), rec, **PATIENT)


def _criteria(sent: list[tuple[int, bytes]]) -> dict:
    fc = CODEC["ChestCriteria"]
    (frame,) = [d for cid, d in sent if cid == fc.frame_id]
    got = fc.decode(frame)
    return {k: v for k, v in got.items() if not k.startswith("ChestCriteria_C")}  # CRC, counter


def _assert_same_ticks(rec, clean) -> np.ndarray:
    """Both runs stepped the same ticks to the same estimates; where their valid flags
    differ (indices)."""
    a, b = rec.ticks, clean.ticks
    ka, kb = a["tick"] >= 0, b["tick"] >= 0  # ticks, not the watchdog's publishes
    assert np.array_equal(a["tick"][ka], b["tick"][kb])
    for col in ("decel_g", "brs_count", "cr_g", "cd_mm"):
        assert np.max(np.abs(a[col][ka] - b[col][kb])) < 1e-9, col
    return np.flatnonzero(a["valid"][ka] != b["valid"][kb])


def test_stale_frame_mid_crash_is_rejected_not_bridged(model, clean_run, tmp_path):
    """An older accelerometer frame (the one before the last, its CRC valid) arrives between
    two frames mid-crash: rejected as WRONG_SEQUENCE and counted, no frame read as lost, no
    phantom tick; the estimates are the clean run's (the next ticks flagged invalid, as for
    any bad frame) and so is ChestCriteria, flagged valid."""
    sched = r16_schedule()
    k = _accel_index(sched, MID_CRASH_S)
    stale = sched.data[_accel_index(sched, MID_CRASH_S - 0.001)]  # counter one behind
    assert stale != sched.data[k] and ACC.e2e_check(stale)
    node, sent, rec = _play(model, "e2e-stale", _with_frame(sched, k, stale, 0.0003),
                            tmp_path / "run.mcap",
                            **PATIENT)
    node0, sent0, rec0 = clean_run
    c = node.counters
    assert node.core.tick_index == node0.core.tick_index  # no phantom tick
    assert c.ticks == node0.counters.ticks and c.lost == 0
    assert c.bad_e2e == c.wrong_sequence == 1 and c.repeated == 0
    (event,) = analyze(rec, ratings=False).events
    assert event.max_abs_diff_offline.cd_mm < 1e-9
    differ = _assert_same_ticks(rec, rec0)
    assert 0 < len(differ) <= CoreConfig().recover_ticks + 1
    assert _criteria(sent) == _criteria(sent0) and _criteria(sent)["ChestCriteria_Valid"] == 1


def test_repeated_frame_mid_crash_is_rejected(model, clean_run, tmp_path):
    sched = r16_schedule()
    k = _accel_index(sched, MID_CRASH_S)
    node, sent, rec = _play(model, "e2e-repeat", _with_frame(sched, k, sched.data[k], 0.0003),
                            tmp_path / "run.mcap",
                            **PATIENT)
    node0, sent0, rec0 = clean_run
    c = node.counters
    assert node.core.tick_index == node0.core.tick_index
    assert c.ticks == node0.counters.ticks and c.lost == 0 and c.bad_e2e == c.repeated == 1
    _assert_same_ticks(rec, rec0)
    assert _criteria(sent) == _criteria(sent0)


def test_reordered_pair_keeps_time_and_flags_the_criteria(model, clean_run):
    """Two frames mid-crash swapped on the bus: the early one is read as one frame lost
    (bridged by one held tick), the late one is rejected: the tick count is kept, the
    event's criteria say invalid."""
    sched = r16_schedule()
    k = _accel_index(sched, MID_CRASH_S)
    j = _accel_index(sched, sched.t_s[k] + 1e-6)  # the next accelerometer frame
    sched.data[k], sched.data[j] = sched.data[j], sched.data[k]
    node, sent, _ = _play(model, "e2e-reorder", sched, **PATIENT)
    node0, _, _ = clean_run
    c = node.counters
    assert node.core.tick_index == node0.core.tick_index  # one tick bridged, one rejected
    assert c.lost == 1 and c.bad_e2e == c.wrong_sequence == 1
    assert _criteria(sent)["ChestCriteria_Valid"] == 0


# ------------------------------------------------------------------ the receiver itself

class _Feed:
    """Inputs on a core, frames fed by hand (P01 TunnelAccel or P05 InputBurst)."""

    def __init__(self, model, name: str):
        self.core = ObserverCore(model.observer())
        self.counters = Counters()
        self.inputs = Inputs(CODEC, self.core, self.counters, 96, lambda *a: None)
        self.fc = CODEC[name]
        self.feed = self.inputs.accel if name == "TunnelAccel" else self.inputs.burst_frame

    def send(self, *counters: int) -> None:
        for n in counters:
            self.feed(0.0, self.fc.encode({}, n))


@pytest.mark.parametrize(("name", "modulus"), [("TunnelAccel", 15), ("InputBurst", 256)])
def test_receiver_states(model, name, modulus):
    f = _Feed(model, name)
    per = 1 if name == "TunnelAccel" else 8  # ticks per frame
    f.send(5, 6, 7)  # INITIAL, OK, OK
    assert f.counters.accepted == 3 and f.core.tick_index + 1 == 3 * per
    f.send(7)  # REPEATED
    f.send(5)  # two behind: WRONG_SEQUENCE
    assert f.counters.repeated == f.counters.wrong_sequence == 1 and f.counters.bad_e2e == 2
    assert f.core.tick_index + 1 == 3 * per and f.counters.lost == 0
    f.send(10)  # two lost: OK_SOME_LOST, bridged
    assert f.counters.lost == 2 and f.core.faults & LOST_FRAME
    assert f.core.tick_index + 1 == min(5 * per, 3 * per + f.core.cfg.max_bridge_ticks) + per
    # The sender's sequence moves beyond what a loss explains (a restart, a long outage):
    # the first frame is rejected, the second, in sequence with it, is followed.
    start = (10 + modulus // 2 + 3) % modulus
    f.send(start, start + 1, start + 2)
    assert f.counters.wrong_sequence == 2 and f.counters.resyncs == 1
    assert f.counters.accepted == 4 + 2
