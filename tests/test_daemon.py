"""The observer daemon on python-can's virtual bus (unit level; SocketCAN is tested on vcan
in test_vcan.py)."""

from __future__ import annotations

import itertools
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np

from observer_node.daemon.core import ACCEL_TIMEOUT
from observer_node.daemon.harness import CODEC, Harness, r16_schedule
from observer_node.daemon.ports import PortError, PythonCanPort
from observer_node.data import bundled_campaign, read_isomme
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.recording import analyze, read_recording
from observer_node.replay.schedule import crash_test_schedule

ROOT = Path(__file__).resolve().parents[1]


# ------------------------------------------------------------------ daemon on a virtual bus

def _play_recorded(model, channel: str, sched, record: Path, settle_s: float = 0.1):
    """Play ``sched`` into a recording daemon: its counters, the estimate frames heard on
    the bus, and the recording read back (``settle_s`` after the last frame)."""
    h = Harness(model, channel, record)
    # No idle exit: on a busy machine a starved daemon looks idle, and would stop between two
    # tests; it runs until every frame played has been read (or two minutes pass).
    h.thread = threading.Thread(target=h.node.run)
    with h:
        h.play(sched)
        deadline = time.monotonic() + 120
        while h.node.counters.rx < len(sched) and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(settle_s)
        est = h.estimates()
    return h.node.counters, est, read_recording(record)


def _assert_matches_offline(rec) -> None:
    """The recorded estimates are the offline simulation's, and fit the reference."""
    (event,) = analyze(rec, ratings=False).events
    assert event.max_abs_diff_offline.cr_g < 1e-9
    assert event.max_abs_diff_offline.cd_mm < 1e-9
    assert event.fit_vs_reference.total > 55


def test_every_frame_handled_and_estimates_equal_offline(model, tmp_path):
    sched = r16_schedule()
    n_accel = int((sched.ids == CODEC["TunnelAccel"].frame_id).sum())
    c, est, rec = _play_recorded(model, "e2e", sched, tmp_path / "run.mcap")
    assert c.ticks == n_accel and c.lost == c.rejected == c.bad_e2e == 0
    assert sum(1 for _, e in est if e["ChestEstimate_Running"]) > 150
    assert not rec.salvaged and rec.model is not None
    assert len(rec.ticks["tick"]) == n_accel
    _assert_matches_offline(rec)
    # raw frames for exact replay, the model and DBC as attachments, metadata
    assert rec.topics["/can/frames"] >= len(sched)
    assert rec.metadata["chest-observer"]["dbc_sha256"] == CODEC.sha256()


def test_input_bursts_carry_10_khz_ticks(campaign, tmp_path):
    """CAN FD InputBurst frames (eight samples each, with their BRS counts): every sample is
    a tick, recorded once, the estimates equal the offline simulation at 10 kHz, one
    estimate frame per burst. On a loaded machine the daemon falls behind and overruns
    (counted), never loses a sample: it is stopped only once it has read every frame (a
    generous bound). How many are processed on time: benchmarks/on_time.py."""

    from observer_node.recording import format as fmt

    est = [t for t in campaign if t.name in ("R16_001", "R16_003", "R16_005")]
    data = make_dataset(est, 1000.0)
    model = greybox.to_model_file(greybox.fit_greybox(data), data, tick_rate_hz=10_000.0)
    test = read_isomme(bundled_campaign() / "R16_002.zip")
    sched = crash_test_schedule(test, CODEC, 10_000.0, reference=True, pre_s=0.2, burst=True)
    n_frames = int((sched.ids == CODEC["InputBurst"].frame_id).sum())
    record = tmp_path / "run.mcap"
    # The watchdog times frames by their receipt: a stall of the machine looks like a silent
    # sensor (and ends the event); out of play here, its own tests cover it.
    h = Harness(model, "burst", record, accel_timeout_s=60.0, brs_timeout_s=60.0)
    h.thread = threading.Thread(target=h.node.run)  # no idle exit: starved is not idle
    with h:
        h.play(sched)
        deadline = time.monotonic() + 120
        while h.node.counters.rx < len(sched) and time.monotonic() < deadline:
            time.sleep(0.05)
    c = h.node.counters
    assert c.rx == len(sched), "frames left unread"
    assert c.ticks == 8 * n_frames and c.lost == c.rejected == c.bad_e2e == 0
    assert c.tx_dropped == 0 and 0 <= c.overruns <= n_frames  # late frames: counted
    rec = read_recording(record)
    # One estimate frame per burst (and per watchdog publish), each one counter step on
    # (tests/test_e2e_receiver.py rates them with an E2E receiver).
    est_codec = CODEC["ChestEstimate"]
    counters = [est_codec.decode(f.data)["ChestEstimate_Counter"]
                for f in rec.frames if f.tx and f.can_id == est_codec.frame_id]
    assert len(counters) >= n_frames
    assert all((b - a) % 15 == 1 for a, b in itertools.pairwise(counters))
    assert int((rec.ticks["tick"] >= 0).sum()) == 8 * n_frames  # every sample recorded
    # One estimate frame per burst; the others sent are the watchdog's, recorded with
    # tick -1 (every estimate message that is not one of the 8 * n_frames ticks).
    est_id = CODEC["ChestEstimate"].frame_id
    sent = sum(1 for f in rec.frames if f.tx and f.can_id == est_id)
    assert sent == n_frames + rec.topics[fmt.ESTIMATE] - 8 * n_frames
    _assert_matches_offline(rec)


def _accel(value_g: float, counter: int) -> bytes:
    return CODEC["TunnelAccel"].encode({"TunnelAccelX": value_g}, counter)


def test_bad_input_is_counted_and_flagged_never_fatal(model):
    acc = CODEC["TunnelAccel"]
    brs = CODEC["BeltSpindle"]
    # Timeouts far above any scheduling hiccup: only the bad frames may flag the estimate.
    h = Harness(model, "bad", accel_timeout_s=1.0, brs_timeout_s=1.0)
    # No idle exit, and every frame read before the counters are: a busy machine starved the
    # daemon to one frame read of 124 in CI (session 55), which is not what this test asks.
    h.thread = threading.Thread(target=h.node.run)
    with h:
        k = kb = 0

        def good(n: int) -> None:
            nonlocal k, kb
            for _ in range(n):
                h.send(brs.frame_id, brs.encode({"BrsCount": 0, "BrsCountsPerRev": 96}, kb))
                h.send(acc.frame_id, _accel(0.0, k))
                k += 1
                kb += 1
                time.sleep(0.001)

        good(20)
        h.send(acc.frame_id, _accel(0.0, k)[:3])  # wrong DLC
        h.send(acc.frame_id, b"\x00" + _accel(0.0, k)[1:])  # bad CRC
        h.send(0x555, b"\x01\x02")  # unknown ID (python-can virtual does not filter in kernel)
        k += 2  # two frames lost by the counter
        good(20)
        h.send(acc.frame_id, _accel(-400.0, k))  # saturated sensor value
        k += 1
        good(20)
        sent = h.sent - 1  # the unknown ID is read only where the bus does not filter it
        deadline = time.monotonic() + 120
        while h.node.counters.rx < sent and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.1)
        est = h.estimates()
        assert h.thread.is_alive()
    c = h.node.counters
    assert c.rx >= sent, "frames left unread"
    assert c.rejected == 1 and c.bad_e2e == 1 and c.lost == 2 and c.unknown_id in (0, 1)
    valid = [e["ChestEstimate_Valid"] for _, e in est][:c.ticks]  # then the watchdog's
    assert valid[:20] == [1] * 20
    assert 0 in valid[20:30]  # flagged within two ticks of the bad frames
    assert valid[-1] == 1  # and recovered


def test_watchdog_flags_invalid_when_accel_stops(model):
    acc, brs = CODEC["TunnelAccel"], CODEC["BeltSpindle"]
    with Harness(model, "wd") as h:
        for k in range(30):
            h.send(brs.frame_id, brs.encode({"BrsCount": 0, "BrsCountsPerRev": 96}, k))
            h.send(acc.frame_id, _accel(0.0, k))
            time.sleep(0.001)
        time.sleep(0.05)  # accelerometer silent for 50 tick periods
        est = h.estimates()
    assert h.node.counters.accel_timeouts >= 1
    assert h.node.core.faults & ACCEL_TIMEOUT
    assert len(est) > 30 and est[-1][1]["ChestEstimate_Valid"] == 0


class _FlakyPort(PythonCanPort):
    fail_after = 40

    def recv(self, timeout_s):
        _FlakyPort.fail_after -= 1
        if _FlakyPort.fail_after == 0:
            raise PortError(100, "vcan0: Network is down")
        return super().recv(timeout_s)


def test_reconnects_when_the_bus_goes_away(model):
    acc = CODEC["TunnelAccel"]
    with Harness(model, "flaky", port_class=_FlakyPort, reconnect_s=0.01) as h:
        for k in range(100):
            h.send(acc.frame_id, _accel(0.0, k))
            time.sleep(0.001)
        time.sleep(0.05)
    assert h.node.counters.reconnects >= 1 and h.node.counters.ticks > 40


class _DownOnSendPort(PythonCanPort):
    """An interface that goes down while the daemon is sending (its estimate or status)."""

    fail_sends = 3

    def send(self, can_id, data):
        if _DownOnSendPort.fail_sends > 0 and can_id == CODEC["ChestEstimate"].frame_id:
            _DownOnSendPort.fail_sends -= 1
            raise PortError(100, "vcan0: Network is down")
        return super().send(can_id, data)


def test_bus_gone_while_sending_reconnects_and_keeps_the_tick(model, tmp_path):
    acc = CODEC["TunnelAccel"]
    with Harness(model, "downsend", record=tmp_path / "run.mcap", port_class=_DownOnSendPort,
                 reconnect_s=0.01) as h:
        for k in range(60):
            h.send(acc.frame_id, _accel(0.0, k))
            time.sleep(0.002)
        time.sleep(0.1)
    c = h.node.counters
    assert h.thread.is_alive() is False and c.reconnects >= 3 and c.tx_dropped >= 3
    # Every tick the daemon stepped is in the recording, sent or not (frames sent while no
    # port was open are gone: the virtual bus keeps nothing for absent receivers).
    assert len(read_recording(tmp_path / "run.mcap").ticks["tick"]) == c.ticks > 20


def _spawn_feeder(model_path: Path, record: Path, seconds: float) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "observer_node.daemon.harness",
                             str(model_path), str(record), str(seconds)], cwd=ROOT,
                            stdout=subprocess.PIPE, text=True, start_new_session=True)


def test_sigterm_finishes_the_recording(model_path, tmp_path):
    rec_path = tmp_path / "run.mcap"
    p = _spawn_feeder(model_path, rec_path, 30)
    assert p.stdout.readline().strip() == "started"
    p.stdout.readline()  # one replay done
    p.send_signal(signal.SIGTERM)
    # The feeder's daemon thread stops via the same stop_event a signal handler sets.
    p.wait(60)
    rec = read_recording(rec_path)
    assert "chest-observer-recorder" in rec.metadata and len(rec.ticks["tick"]) > 400


def _shared_memory_of_group(pgid: int) -> tuple[set[str], bool]:
    """The /dev/shm files the processes of group ``pgid`` map or hold open, and whether any
    maps a memfd. Judged per process, not by listing /dev/shm: on a busy bench other
    programs (a Dask cluster's semaphores) come and go there while the test runs."""
    named, memfd = set(), False
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            if int(Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[2]) != pgid:
                continue
            maps = Path(f"/proc/{pid}/maps").read_text()
            fds = [os.readlink(f"/proc/{pid}/fd/{fd}") for fd in os.listdir(f"/proc/{pid}/fd")]
        except OSError:  # the process ended meanwhile
            continue
        memfd = memfd or "/memfd:" in maps
        named |= {w for w in maps.split() if w.startswith("/dev/shm/")}
        named |= {f for f in fds if f.startswith("/dev/shm/")}
    return named, memfd


def test_killed_daemon_loses_at_most_100_ms(model_path, tmp_path):
    rec_path = tmp_path / "run.mcap"
    p = _spawn_feeder(model_path, rec_path, 30)
    assert p.stdout.readline().strip() == "started"
    line = p.stdout.readline()
    ticks_done = int(line.split()[1])
    named, memfd = _shared_memory_of_group(p.pid)
    time.sleep(0.3)
    os.killpg(p.pid, signal.SIGKILL)  # daemon and recorder process, no chance to finish
    p.wait(10)
    rec = read_recording(rec_path)
    assert rec.salvaged
    recorded = len(rec.ticks["tick"])
    assert recorded >= ticks_done  # everything up to the last report, at least
    # ~1 tick per ms: what was sent in the last 0.3 s minus at most 100 ms
    assert recorded >= ticks_done + 300 * 0.5 - 100
    # the rings are an anonymous memfd, which dies with the processes: nothing named to leak
    assert memfd and not [n for n in named if os.path.exists(n)], named


def test_cpu_latency_is_held_while_open_and_fails_soft(tmp_path):
    from observer_node.daemon.realtime import hold_cpu_latency

    dev = tmp_path / "cpu_dma_latency"
    dev.write_bytes(b"")
    f, said = hold_cpu_latency(0, str(dev))
    assert f is not None and not f.closed and dev.read_bytes() == (0).to_bytes(4, sys.byteorder)
    assert "held at 0 us" in said
    f.close()
    f, said = hold_cpu_latency(0, str(tmp_path / "missing"))
    assert f is None and "missing" in said and "not held" in said
    assert hold_cpu_latency(-1, str(dev))[0] is None


def test_rt_priority_is_the_tick_threads_only_and_fails_soft():
    """SCHED_FIFO for the calling thread, normal scheduling for processes it starts later
    (the recorder), restored on close; without the right to it, one line and no change."""
    import os
    import resource
    import subprocess
    import threading

    from observer_node.daemon.realtime import restore_scheduling, set_rt_priority

    may = os.geteuid() == 0 or resource.getrlimit(resource.RLIMIT_RTPRIO)[0] >= 10
    seen: dict[str, object] = {}

    def tick_thread() -> None:
        old, said = set_rt_priority(10)
        seen["said"], seen["policy"] = said, os.sched_getscheduler(0) & ~os.SCHED_RESET_ON_FORK
        seen["child"] = subprocess.run(
            [sys.executable, "-c", "import os; print(os.sched_getscheduler(0))"],
            capture_output=True, text=True, check=True).stdout.strip()
        restore_scheduling(old)
        seen["after"] = os.sched_getscheduler(0)

    t = threading.Thread(target=tick_thread)
    t.start()
    t.join()
    assert os.sched_getscheduler(0) == os.SCHED_OTHER  # the test's own thread: untouched
    assert seen["child"] == str(os.SCHED_OTHER) and seen["after"] == os.SCHED_OTHER
    if may:
        assert seen["said"] == "SCHED_FIFO priority 10" and seen["policy"] == os.SCHED_FIFO
    else:
        assert "not set" in str(seen["said"]) and seen["policy"] == os.SCHED_OTHER
    assert set_rt_priority(0) == (None, "normal scheduling")


def test_virtual_port_frames_are_not_aliased():
    # The port hands its frames to python-can's virtual bus without the bus's defensive copy:
    # each send must still arrive as its own frame with its own data and bus timestamp.
    import can

    port = PythonCanPort("virtual", "alias", [0x100])
    listeners = [can.Bus(interface="virtual", channel="alias") for _ in range(2)]
    try:
        port.send(0x120, b"\x01\x02")
        port.send(0x121, b"\x03")
        for bus in listeners:
            a, b = bus.recv(1), bus.recv(1)
            assert (a.arbitration_id, bytes(a.data)) == (0x120, b"\x01\x02")
            assert (b.arbitration_id, bytes(b.data)) == (0x121, b"\x03")
            assert a is not b and a.is_rx and 0 < a.timestamp <= b.timestamp
    finally:
        port.close()
        for bus in listeners:
            bus.shutdown()


def test_two_tests_back_to_back_are_two_events_without_spikes(model, tmp_path):
    """The bench replays tests 0.3 s apart: the silence between them ends the first event,
    the second test's BRS reset (-218 counts to 0) is a sensor fault, not a belt movement,
    and each event equals the offline simulation; no valid estimate is a spike."""
    from observer_node.replay.schedule import concat, restamp_counters

    sched = restamp_counters(concat([r16_schedule(), r16_schedule()], gap_s=0.3), CODEC)
    c, _, rec = _play_recorded(model, "b2b", sched, tmp_path / "run.mcap")
    result = analyze(rec, ratings=False)
    assert c.ticks == int((sched.ids == CODEC["TunnelAccel"].frame_id).sum())
    assert [e.event for e in result.events] == [0, 1]
    for e in result.events:
        assert e.max_abs_diff_offline.cr_g < 1e-9
        assert e.max_abs_diff_offline.cd_mm < 1e-9
        assert e.fit_vs_reference.total > 55
    T = rec.ticks
    shown = (T["valid"] > 0) & (T["running"] > 0)
    assert np.max(np.abs(T["cd_mm"][shown])) < 60 and np.max(np.abs(T["cr_g"][shown])) < 60


def test_invalid_ticks_are_marked_not_scored_as_valid(model, tmp_path):
    """A BRS sensor-fault flag mid-event: those ticks are flagged invalid, analyze counts
    them, scores the valid ones apart, and the plot shows them as a shaded gap."""
    sched = r16_schedule()
    brs = CODEC["BeltSpindle"]
    t_event = 0.2 + 0.05  # 50 ms into the test
    k = next(i for i, (t, cid) in enumerate(zip(sched.t_s, sched.ids, strict=True))
             if cid == brs.frame_id and t >= t_event)
    values = brs.decode(sched.data[k])
    sched.data[k] = brs.encode({**values, "BeltSpindle_SensorFault": 1},
                               int(values["BeltSpindle_Counter"]))
    _, _, rec = _play_recorded(model, "flagged", sched, tmp_path / "run.mcap")
    (event,) = analyze(rec, out_dir=tmp_path / "an").events
    assert event.invalid_ticks >= 5
    assert event.fit_vs_reference_valid.ticks < event.ticks
    assert event.max_abs_diff_offline.cd_mm < 1e-9
    assert (tmp_path / "an" / "event0.png").stat().st_size > 10_000
    # criteria of estimate and reference with their errors, and the ISO/TS 18571 rating
    c = event.criteria.as_dict()
    assert abs(c["error"]["cd_max_mm"]) < 10 and c["reference"]["cd_max_mm"] > 10
    assert 0.3 < event.iso18571.cd.overall <= 1.0


def test_every_message_matches_its_topics_schema(model, tmp_path):
    """One message type per topic, every field declared in the topic's JSON schema (so a
    viewer such as Foxglove offers them all), the schemas those of recording.format."""
    import json

    import jsonschema
    from mcap.reader import make_reader

    from observer_node.recording import format as fmt

    # long enough after the last frame for the event to end and its criteria to go out
    _play_recorded(model, "schemas", r16_schedule(), tmp_path / "run.mcap", settle_s=0.5)
    seen: dict[str, int] = {}
    with (tmp_path / "run.mcap").open("rb") as f:
        for schema, channel, message in make_reader(f).iter_messages():
            s = json.loads(schema.data)
            msg = json.loads(message.data)
            # every field declared; a number without a value is left out (not NaN)
            assert set(s["required"]) <= set(msg) <= set(s["properties"]), channel.topic
            if seen.get(channel.topic, 0) < 50:
                jsonschema.validate(msg, s)
            seen[channel.topic] = seen.get(channel.topic, 0) + 1
            assert s["title"] == fmt.TITLES[channel.topic]
    assert set(seen) == set(fmt.TITLES)  # every topic of the format is written


def test_moving_bits_in_the_dbc_needs_no_other_edit(model, tmp_path):
    """The DBC is the only place that knows where a bit is and how a frame is protected:
    move the flags of the accelerometer, BRS and estimate frames, swap the estimate's CR and
    CD and the BRS count and resolution, move two invalid-cause bits, give the accelerometer
    another E2E data ID, and replay and daemon follow without another edit."""
    from observer_node.dbc import DBC_PATH, Codec
    from observer_node.replay.schedule import crash_test_schedule

    text = DBC_PATH.read_text()
    for old, new in (
            ("TunnelAccel_SensorFault : 12|1", "TunnelAccel_SensorFault : 15|1"),
            ("BeltSpindle_SensorFault : 12|1", "BeltSpindle_SensorFault : 14|1"),
            ("BeltSpindle_Bidirectional : 13|1", "BeltSpindle_Bidirectional : 15|1"),
            ("BrsCount : 16|16", "BrsCount : 24|16"),
            ("BrsCountsPerRev : 32|8", "BrsCountsPerRev : 16|8"),
            ("ChestEstimate_Valid : 12|1", "ChestEstimate_Valid : 13|1"),
            ("ChestEstimate_Running : 13|1", "ChestEstimate_Running : 12|1"),
            ("ChestAccelCR : 16|16", "ChestAccelCR : 32|16"),
            ("ChestDeflCD : 32|16", "ChestDeflCD : 16|16"),
            ("Invalid_AccelTimeout : 48|1", "Invalid_AccelTimeout : 55|1"),
            ("Invalid_NotArmed : 55|1", "Invalid_NotArmed : 48|1"),
            ('BA_ "E2EDataID" BO_ 256 256;', 'BA_ "E2EDataID" BO_ 256 4660;')):
        assert old in text
        text = text.replace(old, new)
    moved_path = tmp_path / "moved.dbc"
    moved_path.write_text(text)
    moved = Codec(moved_path)
    sched = crash_test_schedule(read_isomme(bundled_campaign() / "R16_002.zip"), moved, 1000.0,
                                reference=True, pre_s=0.2)
    est = moved["ChestEstimate"]
    # Timeouts far above any scheduling hiccup: validity here is about where its bit is.
    with Harness(model, "moved", tmp_path / "run.mcap", codec=moved, accel_timeout_s=1.0,
                 brs_timeout_s=1.0) as h:
        h.play(sched)
        time.sleep(0.1)
        frames = []
        while (m := h.rx.recv(0)) is not None:
            frames.append(m)
    c = h.node.counters
    n_accel = int((sched.ids == moved["TunnelAccel"].frame_id).sum())
    assert c.ticks == n_accel and c.bad_e2e == c.lost == c.rejected == 0
    decoded = [est.decode(m.data) for m in frames if m.arbitration_id == est.frame_id]
    assert sum(d["ChestEstimate_Running"] for d in decoded) > 150
    assert all(d["ChestEstimate_Valid"] for d in decoded if d["ChestEstimate_Running"])
    status = [moved["ObserverStatus"].decode(m.data) for m in frames
              if m.arbitration_id == moved["ObserverStatus"].frame_id]
    assert any(s["Invalid_NotArmed"] for s in status)  # holding after the event
    assert not any(s["Invalid_AccelTimeout"] for s in status[:-3])
    _assert_matches_offline(read_recording(tmp_path / "run.mcap"))


def test_each_event_ends_with_its_criteria_on_the_bus(model, tmp_path):
    """ChestCriteria: once per event, E2E-protected, the criteria of the event's estimates
    from the onset (as an offline run of the recorded inputs gives them), recorded."""
    from observer_node.criteria import chest_criteria
    from observer_node.recording import offline_estimates

    fc = CODEC["ChestCriteria"]
    record = tmp_path / "run.mcap"
    with Harness(model, "criteria", record) as h:
        h.play(r16_schedule())
        time.sleep(0.5)  # the event ends event_s after the trigger, or on the silence
        frames = []
        while (m := h.rx.recv(0)) is not None:
            if m.arbitration_id == fc.frame_id:
                frames.append(bytes(m.data))
    assert len(frames) == 1, frames
    data = frames[0]
    assert fc.e2e_check(data)
    got = fc.decode(data)
    rec = read_recording(record)
    _, y = offline_estimates(rec, 0)
    want = chest_criteria(y[:, 0], y[:, 1], model.tick_rate_hz)
    assert got["CriteriaEvent"] == 0
    assert abs(got["ChestDeflMax"] - want.cd_max_mm) <= 0.005 + 1e-9
    assert abs(got["ChestAccel3ms"] - want.cr_3ms_g) <= 0.005 + 1e-9
    assert abs(got["ViscousCritMax"] - want.vc_max_m_s) <= 0.00005 + 1e-9
    assert 10 < got["ChestDeflMax"] < 80 and got["ViscousCritMax"] > 0.01
    assert rec.topics["/observer/criteria"] == 1
