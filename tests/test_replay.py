"""crash-replay: sources, errors before sending, schedules, timing."""

from __future__ import annotations

import time
from pathlib import Path

import can
import numpy as np
import pytest

from observer_node.data import bundled_campaign, read_isomme, write_csv
from observer_node.dbc import Codec
from observer_node.replay.cli import main
from observer_node.replay.player import play
from observer_node.replay.schedule import concat, crash_test_schedule, restamp_counters
from observer_node.replay.sources import SourceError, load_source, read_candump

from .conftest import DATA

CODEC = Codec()


def test_lab_test_becomes_bus_frames_in_dbc_layout():
    t = read_isomme(DATA / "R16_002")
    s = crash_test_schedule(t, CODEC, 1000.0, reference=True)
    acc = CODEC["TunnelAccel"]
    is_acc = s.ids == acc.frame_id
    assert is_acc.sum() == 220  # 0.22 s at 1 kHz
    assert np.all(np.diff(s.t_s[is_acc]) == pytest.approx(1e-3))
    values = np.array([acc.decode(d)["TunnelAccelX"] for d, a in zip(s.data, is_acc,
                                                                     strict=True) if a])
    assert values.min() < -20  # J211 sign on the bus: negative in a frontal crash
    assert all(CODEC.by_id[i].e2e_check(d) for i, d in zip(s.ids, s.data, strict=True))
    brs = s.ids == CODEC["BeltSpindle"].frame_id
    assert 22 <= brs.sum() <= 220  # heartbeat every 10 ms plus changes
    assert (s.ids == CODEC["ReferenceChest"].frame_id).sum() == 220


def test_bursts_carry_the_same_samples_as_single_frames():
    """--burst: eight (acceleration, BRS count) pairs per InputBurst frame, the same values
    the per-sample frames carry, sent with the last sample of each eight."""
    t = read_isomme(DATA / "R16_002")
    single = crash_test_schedule(t, CODEC, 10_000.0)
    burst = crash_test_schedule(t, CODEC, 10_000.0, burst=True)
    acc, brs, fc = CODEC["TunnelAccel"], CODEC["BeltSpindle"], CODEC["InputBurst"]
    pulse, counts, held = [], [], 0
    for cid, d in zip(single.ids.tolist(), single.data, strict=True):
        if cid == brs.frame_id:
            held = brs.decode(d)["BrsCount"]
        elif cid == acc.frame_id:
            pulse.append(acc.decode(d)["TunnelAccelX"])
            counts.append(held)
    assert set(burst.ids.tolist()) == {fc.frame_id} and all(map(fc.e2e_check, burst.data))
    n = len(burst)
    assert n == len(pulse) // 8
    dec = [fc.decode(d) for d in burst.data]
    np.testing.assert_allclose([v[f"BurstAccelX{j}"] for v in dec for j in range(8)],
                               pulse[:8 * n])
    assert [v[f"BurstBrsCount{j}"] for v in dec for j in range(8)] == counts[:8 * n]
    assert np.allclose(np.diff(burst.t_s), 8e-4)
    assert main([str(DATA / "R16_002"), "--burst", "--dry-run"]) == 2  # needs --fd


def test_concatenated_tests_keep_counting_like_one_sensor():
    t = read_isomme(DATA / "R16_002")
    s = restamp_counters(concat([crash_test_schedule(t, CODEC, 1000.0)] * 2), CODEC)
    acc = CODEC["TunnelAccel"]
    counters = [d[1] & 0xF for i, d in zip(s.ids, s.data, strict=True) if i == acc.frame_id]
    assert counters == [k % 15 for k in range(440)]  # AUTOSAR E2E P01: 0..14
    assert all(CODEC.by_id[i].e2e_check(d) for i, d in zip(s.ids, s.data, strict=True))


def test_bad_sources_fail_before_sending(tmp_path: Path):
    log = tmp_path / "run.log"
    log.write_text("(1.000000) vcan0 100#0102\n(1.001000) vcan0 100#01020\n")
    with pytest.raises(SourceError, match=r"run\.log:2: not a candump -L line"):
        read_candump(log)
    (tmp_path / "bad.mcap").write_bytes(b"\x89MCAP0\r\n" + b"\x01" * 50)
    with pytest.raises(SourceError, match=r"bad\.mcap: truncated or corrupt"):
        load_source(tmp_path / "bad.mcap", CODEC)
    csv = tmp_path / "t.csv"
    csv.write_text("time[s],pulse[g]\n0,1\n0.001,2\n")
    with pytest.raises(SourceError, match=r"t\.csv.*missing column 'brs'"):
        load_source(csv, CODEC)
    assert main([str(log), "--dry-run"]) == 2


def test_candump_and_python_can_logs_replay_their_frames(tmp_path: Path):
    t = read_isomme(DATA / "R16_002")
    s = crash_test_schedule(t, CODEC, 1000.0)
    for suffix in (".log", ".asc", ".blf"):
        path = tmp_path / f"run{suffix}"
        with can.Logger(str(path)) as w:
            for k, (cid, d) in enumerate(zip(s.ids.tolist(), s.data, strict=True)):
                w.on_message_received(can.Message(timestamp=1000 + s.t_s[k],
                                                  arbitration_id=cid, data=d,
                                                  is_extended_id=False))
        (back,) = load_source(path, CODEC)
        assert back.data == s.data and back.ids.tolist() == s.ids.tolist(), suffix
        np.testing.assert_allclose(back.t_s, s.t_s - s.t_s[0], atol=1e-5)


def test_csv_source_and_dry_run(tmp_path: Path, capsys):
    t = read_isomme(bundled_campaign() / "SLED_002.zip")
    write_csv(t, tmp_path / "sled.csv")
    assert main([str(tmp_path / "sled.csv"), "--reference", "--dry-run",
                 "--start", "0", "--end", "0.15"]) == 0
    out = capsys.readouterr().out
    assert "0x100:" in out and "0x310:" in out and "bus load" in out


def test_player_keeps_an_absolute_schedule():
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), CODEC, 1000.0)
    sent: list[float] = []
    rep = play(s, lambda k: sent.append(time.perf_counter()) or True)
    assert rep.sent == len(s) and rep.failed == 0
    # no drift: the last frame leaves at its due time after the first, not later by the sum
    # of per-frame errors (a generous bound: this is a correctness check, not a benchmark)
    assert sent[-1] - sent[0] == pytest.approx(s.t_s[-1] - s.t_s[0], abs=0.02)


def test_replay_cli_onto_a_virtual_bus(capsys):
    rx = can.Bus(interface="virtual", channel="replaycli")
    assert main([str(DATA / "R16_002"), "--interface", "virtual", "--channel", "replaycli",
                 "--only", "0x100", "--remap", "0x100=0x101", "--rate", "4", "--quiet",
                 "--pre", "0"]) == 0
    got = []
    while (m := rx.recv(0.1)) is not None:
        got.append(m.arbitration_id)
    rx.shutdown()
    assert got == [0x101] * 220
    assert "lateness p50" in capsys.readouterr().out


def test_bundled_campaign_by_name(tmp_path: Path, monkeypatch, capsys):
    """An installed user has no repository: campaign-a[/PATTERN] names the bundled tests."""
    from observer_node.data import find_tests

    monkeypatch.chdir(tmp_path)  # no local file called campaign-a
    assert len(find_tests(["campaign-a"])) == 24
    odd = find_tests(["campaign-a/*[13579]"])
    assert [p.stem for p in odd][:3] == ["FULL_001", "FULL_003", "FULL_005"] and len(odd) == 12
    assert main(["campaign-a/R16_002", "--reference", "--dry-run"]) == 0
    out = capsys.readouterr().out
    assert "from R16_002" in out and "0x310:" in out
    assert main(["campaign-a/R99_*", "--dry-run"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "no bundled test matches 'R99_*'" in err


def test_a_recording_from_before_the_autosar_profiles_still_replays(model, tmp_path):
    """tests/data holds a run recorded with the earlier DBC (our own CRC, counters 0..15): its
    frames are translated by signal name into the current DBC's layout and E2E profiles, and
    the daemon accepts every one and steps the crash as the old daemon did."""
    import time as _time

    from observer_node.daemon.harness import Harness
    from observer_node.recording import read_recording

    old = DATA / "recorded-before-autosar-e2e.mcap"
    (sched,) = load_source(old, CODEC)
    assert all(CODEC.by_id[i].e2e_check(d) for i, d in zip(sched.ids, sched.data, strict=True))
    with Harness(model, "old-recording", tmp_path / "again.mcap") as h:
        h.play(sched)
        _time.sleep(0.3)
    c = h.node.counters
    assert c.bad_e2e == c.rejected == c.lost == 0 and c.ticks == 420
    before, again = read_recording(old), read_recording(tmp_path / "again.mcap")
    # the same inputs reached the observer (its model differs: compare what it was given)
    for key in ("accel_x_g", "brs_count"):
        np.testing.assert_array_equal(again.ticks[key], before.ticks[key], err_msg=key)


def test_player_sleeps_to_absolute_deadlines():
    """A deadline is absolute (clock_nanosleep TIMER_ABSTIME on perf_counter's clock): time
    lost before the sleep starts (a preemption, here 30 ms of other work) is not slept
    again, and a deadline already past returns at once."""
    from observer_node.replay.player import sleep_until

    t0 = time.perf_counter()
    time.sleep(0.03)  # the thread is held up after reading the clock
    sleep_until(t0 + 0.05)
    woke = time.perf_counter() - t0
    assert 0.05 <= woke < 0.07, woke  # a relative 50 ms sleep would end at >= 80 ms
    t1 = time.perf_counter()
    sleep_until(t1 - 1.0)
    assert time.perf_counter() - t1 < 0.01


def test_player_runs_at_the_real_time_priority_asked_for_and_fails_soft():
    """--rt-priority N: the sending thread runs SCHED_FIFO N while it plays (where allowed:
    root, CAP_SYS_NICE or RLIMIT_RTPRIO; else one line says why not), normal afterwards."""
    import os
    import resource

    may = os.geteuid() == 0 or resource.getrlimit(resource.RLIMIT_RTPRIO)[0] >= 10
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), CODEC, 1000.0)
    policies: set[int] = set()
    rep = play(s, lambda k: policies.add(os.sched_getscheduler(0) & ~os.SCHED_RESET_ON_FORK)
               or True, rate=8.0, rt_priority=10)
    assert rep.sent == len(s) and os.sched_getscheduler(0) == os.SCHED_OTHER
    if may:
        assert policies == {os.SCHED_FIFO} and rep.scheduling == "SCHED_FIFO priority 10"
    else:
        assert policies == {os.SCHED_OTHER} and "not set" in rep.scheduling
    assert play(s, lambda k: True, rate=8.0).scheduling == "normal scheduling"


def test_replay_cli_rt_priority(capsys):
    rx = can.Bus(interface="virtual", channel="replayrt")
    assert main([str(DATA / "R16_002"), "--interface", "virtual", "--channel", "replayrt",
                 "--rate", "8", "--quiet", "--pre", "0", "--rt-priority", "10"]) == 0
    rx.shutdown()
    out = capsys.readouterr().out
    assert "lateness p50" in out and ("SCHED_FIFO priority 10" in out or "not set" in out)
    with pytest.raises(SystemExit) as e:
        main([str(DATA / "R16_002"), "--rt-priority", "100"])
    assert e.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert "--rt-priority" in err[-1] and "Traceback" not in "".join(err)
