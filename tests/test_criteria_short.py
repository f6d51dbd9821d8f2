"""Criteria on short windows (issue 20, item 1): an accelerometer that falls silent a few
ticks after a trigger leaves an event of a handful of ticks. Its criteria must be defined
(or NaN: undefined, never a traceback) in the daemon's tick loop and in ``analyze``."""

from __future__ import annotations

import math
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from observer_node import cli
from observer_node.criteria import chest_criteria
from observer_node.daemon.harness import CODEC, Harness
from observer_node.data.filters import cfc_filter
from observer_node.recording import analyze, read_recording
from observer_node.recording.reader import Recording

ACC, BRS, CRIT = CODEC["TunnelAccel"], CODEC["BeltSpindle"], CODEC["ChestCriteria"]


@pytest.mark.parametrize("n", range(13))
def test_criteria_of_every_short_window_are_defined_or_nan(n):
    rng = np.random.default_rng(n)
    cr, cd = rng.normal(10, 5, n), np.cumsum(rng.uniform(0, 2, n))
    c = chest_criteria(cr, cd, 1000.0)  # the old CFC filter raised on 5..9 samples
    for v in (c.cd_max_mm, c.cr_3ms_g, c.vc_max_m_s):
        assert math.isnan(v) or math.isfinite(v)
    assert c.complete == (n >= 5)  # all three need at most five samples
    if n >= 5:  # the five-point difference has what it needs: VC is a number
        assert math.isfinite(c.vc_max_m_s) and c.vc_max_m_s >= 0
    if n >= 1:
        assert len(cfc_filter(cd, 1000.0, 180)) == n


def test_the_filter_on_short_inputs_passes_a_constant_unchanged():
    """A low-pass filter keeps DC: on every short length, a constant comes out the same."""
    for n in range(1, 12):
        assert cfc_filter(np.full(n, 5.0), 1000.0, 180) == pytest.approx(np.full(n, 5.0))


def _feed(h: Harness, k0: int, accel_g: list[float]) -> int:
    for k, a in enumerate(accel_g, k0):
        h.send(BRS.frame_id, BRS.encode({"BrsCount": 0, "BrsCountsPerRev": 96}, k))
        h.send(ACC.frame_id, ACC.encode({"TunnelAccelX": a}, k))
        time.sleep(0.001)
    return k0 + len(accel_g)


@pytest.mark.parametrize("silent_after", [2, 4, 6])
def test_accelerometer_silent_after_a_trigger_neither_kills_the_daemon_nor_analyze(
        model, tmp_path, capsys, silent_after):
    """Armed, then a crash pulse that stops ``silent_after`` ticks after the trigger: the
    watchdog ends the event, its criteria go out, and the daemon ticks on. ``analyze`` reads
    the recording of that event without a traceback."""
    path = tmp_path / "run.mcap"
    h = Harness(model, f"short{silent_after}", record=path)
    # the harness's thread ends after 0.3 s without input: longer here, to outlast the event
    h.thread = threading.Thread(target=h.node.run, kwargs={"idle_exit_s": 5.0})
    with h:
        k = _feed(h, 0, [0.0] * 300)  # quiet: the zero is learned, ARMED
        k = _feed(h, k, [-20.0] * (3 + silent_after))  # trigger on the 3rd tick, then silent
        time.sleep(0.5)  # longer than an event: the watchdog ends it
        assert h.thread.is_alive()
        k = _feed(h, k, [0.0] * 50)
        time.sleep(0.3)
        assert h.thread.is_alive()  # the tick loop survived the event's end
        crit = []
        while (m := h.rx.recv(0)) is not None:
            if m.arbitration_id == CRIT.frame_id:
                crit.append(CRIT.decode(m.data))
    c = h.node.counters
    assert h.node.core.events_cut == 1 and len(crit) == 1
    assert c.ticks == k and h.node.step_errors == 0
    result = analyze(read_recording(path))
    (event,) = result.events
    est = event.criteria.as_dict()["estimate"]
    assert all(math.isnan(v) or math.isfinite(v) for v in est.values())
    # ended long before the fit window does: said, in the analysis and by the CLI
    assert event.cut_s is not None and event.cut_s < 0.05 and "watchdog" in event.cut_why
    assert cli.main(["analyze", str(path), "--out", str(tmp_path / "an")]) == 0
    assert f"WARNING: cut after {event.cut_s * 1000:.0f} ms" in capsys.readouterr().out


@pytest.mark.parametrize("event_s", [0.2, 0.1])
def test_an_event_that_runs_its_full_length_is_not_marked_cut(model, tmp_path, event_s):
    """Inputs without a gap through an event of the configured length, shorter than the fit
    window (0.1 s) or not: the analysis marks nothing cut (a false alarm would hide a real
    one among many)."""
    from observer_node.daemon.core import CoreConfig

    path = tmp_path / "run.mcap"
    h = Harness(model, f"full{event_s}", record=path, core=CoreConfig(event_s=event_s))
    with h:
        k = _feed(h, 0, [0.0] * 300)
        _feed(h, k, [-20.0] * round(event_s * 1000 + 50))  # the pulse outlasts the event
    assert h.node.core.events_cut == 0
    (event,) = analyze(read_recording(path), ratings=False).events
    assert event.ticks >= event_s * 1000 - 10
    assert event.cut_s is None and event.cut_why == ""


@pytest.mark.parametrize(("short_ms", "cut"), [(5, False), (15, True)])
def test_an_event_short_of_its_length_by_more_than_10_ms_is_cut(model, tmp_path, short_ms,
                                                                 cut):
    """The threshold, pinned: an event of 0.2 s whose data end 5 ms before it would is whole
    (a replayed test's file may end so, nothing of the crash missing); 15 ms short, cut."""
    from observer_node.daemon.core import CoreConfig

    path = tmp_path / "run.mcap"
    h = Harness(model, f"short{short_ms}", record=path, core=CoreConfig(event_s=0.2))
    with h:
        k = _feed(h, 0, [0.0] * 300)
        _feed(h, k, [-20.0] * (200 - short_ms))  # the onset: the first frame of the pulse
    (event,) = analyze(read_recording(path), ratings=False).events
    # a busy machine may drop a few of the harness's frames: the event only gets shorter
    assert 200 - short_ms - 10 < event.ticks <= 200 - short_ms
    # whole down to 10 ms short of its last tick (199 ms after the onset), cut below
    assert (event.cut_s is not None) == (event.ticks - 1 < 199 - 10) and not event.cut_in_window
    if event.ticks == 200 - short_ms:  # nothing dropped: the case this test is about
        assert (event.cut_s is not None) == cut


def test_an_event_cut_after_the_fit_window_says_its_criteria_are_partial(model, tmp_path,
                                                                         capsys, monkeypatch):
    """An event of 0.4 s whose recording ends 0.2 s after the trigger: its fit window
    (to 0.15 s) is whole, but its injury criteria cover only half the event, and the
    analysis says so rather than passing them as the event's."""
    from observer_node.daemon.core import CoreConfig

    path = tmp_path / "run.mcap"
    h = Harness(model, "long", record=path, core=CoreConfig(event_s=0.4))
    with h:  # the harness's thread ends 0.3 s after its last input, inside the event
        k = _feed(h, 0, [0.0] * 300)
        _feed(h, k, [-20.0] * 200)
    (event,) = analyze(read_recording(path), ratings=False).events
    assert event.cut_s is not None and 0.15 < event.cut_s < 0.2
    assert not event.cut_in_window and event.cut_why.startswith("the recording ends there")
    assert cli.main(["analyze", str(path), "--out", str(tmp_path / "an")]) == 0
    out = capsys.readouterr().out
    assert f"WARNING: cut after {event.cut_s * 1000:.0f} ms" in out
    assert "its fit window is whole; its criteria cover only that part" in out
    # of a recording that does not say its events' length, only a cut inside the window
    monkeypatch.setattr(Recording, "event_s", property(lambda self: math.nan))
    (event,) = analyze(read_recording(path), ratings=False).events
    assert event.cut_s is None


def test_a_step_that_raises_is_counted_flagged_invalid_and_survived(model, tmp_path,
                                                                    monkeypatch):
    """Whatever fails inside the loop (here the criteria of an event) is counted in
    ``step_errors``, logged once, flags the estimate invalid, and the ticks go on."""
    import observer_node.daemon.node as node_mod

    def broken(*_a: object) -> None:
        raise ZeroDivisionError("a criterion that fails")

    monkeypatch.setattr(node_mod, "chest_criteria", broken)
    logs: list[str] = []
    st = CODEC["ObserverStatus"]
    h = Harness(model, "stepfail", record=tmp_path / "run.mcap")
    h.thread = threading.Thread(target=h.node.run, kwargs={"idle_exit_s": 5.0})
    with h:
        h.node.log = logs.append
        k = _feed(h, 0, [0.0] * 300)
        k = _feed(h, k, [-20.0] * 8)
        time.sleep(0.5)  # the watchdog ends the event: its criteria fail
        k = _feed(h, k, [0.0] * 50)
        assert h.settle()
        time.sleep(0.2)  # a status period
        assert h.thread.is_alive()
        status = [st.decode(m.data) for m in iter(lambda: h.rx.recv(0), None)
                  if m.arbitration_id == st.frame_id]
    assert h.node.step_errors == 1 and h.node.counters.ticks == k
    # flagged (the only out-of-range cause in this run: the inputs are all in range)
    assert status and status[-1]["Fault_OutOfRange"] == 1
    assert sum("ZeroDivisionError" in line and "step_errors" in line for line in logs) == 1


def _chunk_ends(data: bytes) -> list[int]:
    """Where each chunk record of an MCAP file ends (opcode, 8-byte length, body)."""
    ends, at = [], 8  # after the magic
    while at + 9 <= len(data):
        end = at + 9 + int.from_bytes(data[at + 1:at + 9], "little")
        if data[at] == 0x06:
            ends.append(end)
        at = end
    return ends


def _one_chunk_per_tick(src: Path, dst: Path) -> None:
    """``src`` rewritten by the mcap library with a chunk ending after every estimate: a
    file that can be cut after any tick, as a kill cuts it (after a complete chunk)."""
    from mcap.reader import make_reader
    from mcap.writer import Writer

    with src.open("rb") as f, dst.open("wb") as g:
        reader = make_reader(f)
        w = Writer(g, chunk_size=1 << 62)
        w.start(profile="", library="test")
        for m in reader.iter_metadata():
            w.add_metadata(m.name, m.metadata)
        for a in reader.iter_attachments():
            w.add_attachment(a.create_time, a.log_time, a.name, a.media_type, a.data)
        channels: dict[int, int] = {}
        for schema, channel, msg in reader.iter_messages(log_time_order=False):
            if channel.id not in channels:
                sid = w.register_schema(schema.name, schema.encoding, schema.data)
                channels[channel.id] = w.register_channel(channel.topic,
                                                          channel.message_encoding, sid)
            w.add_message(channels[channel.id], msg.log_time, msg.data, msg.publish_time,
                          msg.sequence)
            if channel.topic == "/observer/estimate":
                w.flush()
        w.finish()


def test_analyze_reads_a_recording_cut_after_any_tick(model, tmp_path):
    """A crash recorded, then cut after every tick of its start, as a kill cuts a file
    (after its last complete chunk): some cuts end the event 5-9 ticks after its trigger,
    the lengths the CFC filter refused. ``analyze`` reports every cut (criteria numbers or
    NaN), never a traceback."""
    from observer_node.recording import RecordingError

    path = tmp_path / "run.mcap"
    h = Harness(model, "cutanalyze", record=path)
    h.thread = threading.Thread(target=h.node.run, kwargs={"idle_exit_s": 5.0})
    with h:
        k = _feed(h, 0, [0.0] * 300)
        k = _feed(h, k, [-20.0] * 40)
        k = _feed(h, k, [0.0] * 20)
        time.sleep(0.2)
    rechunked = tmp_path / "rechunked.mcap"
    _one_chunk_per_tick(path, rechunked)
    data = rechunked.read_bytes()
    cut = tmp_path / "cut.mcap"

    def cut_at(end: int) -> Recording | None:
        cut.write_bytes(data[:end])
        try:
            return read_recording(cut)
        except RecordingError:  # cut before the first tick: one line, no traceback
            return None

    def running(rec: Recording | None) -> int:
        return 0 if rec is None else int((rec.ticks["running"] > 0).sum())

    ends = _chunk_ends(data)
    lo, hi = 0, len(ends) - 1  # the first cut that holds a running tick
    while lo < hi:
        mid = (lo + hi) // 2
        lo, hi = (mid + 1, hi) if running(cut_at(ends[mid])) == 0 else (lo, mid)
    seen: set[int] = set()
    for end in ends[lo:lo + 40]:
        rec = cut_at(end)
        assert rec is not None and running(rec) > 0
        seen.add(running(rec))
        (event,) = analyze(rec, ratings=False).events
        for v in event.criteria.as_dict()["estimate"].values():
            assert math.isnan(v) or math.isfinite(v)
        assert event.cut_s is not None and event.cut_s < 0.15  # the file ends mid-event
        assert event.cut_why.startswith("the recording ends there")
    assert set(range(5, 10)) <= seen  # the lengths the CFC filter refused
