"""The bench pairs each replayed test with the event the daemon recorded during it, by the
event's onset tick, never by position: a test that does not trigger must not relabel the
tests after it."""

from __future__ import annotations

import dataclasses
import json
import time

import numpy as np
import pytest

import observer_node.bench as bench
import observer_node.replay.player as player
from observer_node.data import read_isomme

PRE_TICKS = 200  # the bench replays 0.2 s of rest before each crash, at 1 kHz


def _ticks(name: str) -> int:
    """The daemon ticks a bundled test spans in the bench's replay (its accelerometer
    frames, with the rest before the crash)."""
    from observer_node.data import bundled_campaign
    from observer_node.dbc import Codec
    from observer_node.replay.schedule import crash_test_schedule

    codec = Codec()
    sched = crash_test_schedule(read_isomme(bundled_campaign() / f"{name}.zip"), codec, 1000.0,
                                reference=True, pre_s=PRE_TICKS / 1000)
    return int(np.count_nonzero(sched.ids == codec["TunnelAccel"].frame_id))


def test_a_test_that_does_not_trigger_relabels_no_other(model_path, tmp_path, capsys,
                                                        monkeypatch):
    def quiet_first(path):  # R16_002's pulse held at its first sample: the observer stays armed
        t = read_isomme(path)
        if t.name == "R16_002":
            t = dataclasses.replace(t, pulse_g=t.pulse_g * 0 + t.pulse_g[0])
        return t

    monkeypatch.setattr(bench, "read_isomme", quiet_first)
    names = ("R16_002", "R16_004", "R16_006")
    result = bench.run_bench(tmp_path, str(model_path), interface="virtual", tests=names)
    assert list(result.events) == list(names)
    assert result.events["R16_002"] is None
    out, err = capsys.readouterr()
    starts = dict(zip(names, np.cumsum([0, *(_ticks(n) for n in names[:-1])]), strict=True))
    for name in names[1:]:
        event, off = result.events[name], result.offline[name]
        assert event is not None, name
        # whatever its fit, the event is this test's: its onset lies where this test's crash
        # starts in the replay (0.2 s of rest before it), not in another test's
        assert PRE_TICKS <= event.onset_tick - starts[name] <= PRE_TICKS + 60, name
        if event.cut_s is not None:  # a busy machine stalled the replay: said, not hidden
            assert f"{name}: the daemon's event was cut after" in err, name
        if event.cut_in_window:  # its fits cover only its start
            continue
        # the event is the one of this test: its fit is this test's offline fit
        assert abs(event.fit_vs_reference.cr - off.cr) < 2, name
        assert abs(event.fit_vs_reference.cd - off.cd) < 2, name
    assert "R16_002" in out and "did not trigger" in out


def test_an_event_cut_by_a_stalled_replay_is_marked_not_shown_as_a_fit(model_path, tmp_path,
                                                                       capsys, monkeypatch):
    # The replay stops for 0.5 s (longer than an event) 80 ms into the test, as a loaded
    # machine did in CI: the daemon's watchdog ends the event, and the bench must say so
    # rather than print the short event's fit as the test's.
    sender = player.bus_sender

    def stalling(bus, schedule, fd=False):
        send = sender(bus, schedule, fd)
        at = int(np.searchsorted(schedule.t_s, schedule.t_s[0] + 0.2 + 0.08))  # pre_s 0.2

        def stall_once(k):
            if k == at:
                time.sleep(0.5)
            return send(k)

        return stall_once

    monkeypatch.setattr(player, "bus_sender", stalling)
    result = bench.run_bench(tmp_path, str(model_path), interface="virtual",
                             tests=("R16_004",))
    event = result.events["R16_004"]
    assert event is not None and event.cut_s is not None
    assert 0.01 < event.cut_s < 0.15 and event.cut_in_window  # shorter than the window
    # the daemon still stepped exactly its inputs: the cut is the bus's, not a daemon fault
    assert bench._max_diff(event) < 1e-6
    out, err = capsys.readouterr()
    assert "R16_004: the daemon's event was cut after" in err
    assert "while the test's data went on (a stalled replay, bus or daemon)" in err
    rows = [line for line in out.splitlines() if line.lstrip().startswith("R16_004")]
    assert rows and all("cut after" in line for line in rows), rows  # in every table
    assert "watchdog" in event.cut_why  # the inputs resumed after the silence
    saved = json.loads((tmp_path / "analysis.json").read_text())["events"][0]
    assert saved["cut_s"] == pytest.approx(event.cut_s) and saved["cut_why"] == event.cut_why
    assert saved["cut_in_window"] is True


def test_an_event_longer_than_its_tests_data_is_noted_not_blamed_on_a_stall(
        model_path, tmp_path, capsys, monkeypatch):
    # The daemon configured for events of 0.25 s; the bundled tests' data end about 0.2 s
    # after the onset. Nothing stalled: the bench says the data end there (its criteria
    # cover that much, its fit window is whole), warns of no fault and marks no row.
    from observer_node.daemon import config
    from observer_node.daemon.core import CoreConfig

    node_config = config.NodeConfig
    monkeypatch.setattr(config, "NodeConfig",
                        lambda **kw: node_config(**kw, core=CoreConfig(event_s=0.25)))
    names = ("R16_002", "R16_004")
    result = bench.run_bench(tmp_path, str(model_path), interface="virtual", tests=names)
    out, err = capsys.readouterr()
    ran_out = 0
    for name in names:
        event = result.events[name]
        assert event is not None and event.cut_s is not None, name
        if event.cut_s < result.data_end_s[name] - 1e-6:  # a busy machine stalled the replay
            assert f"{name}: the daemon's event was cut after" in err, name
            continue
        ran_out += 1
        assert not event.cut_in_window
        assert f"bench: note: {name}: the test's data end" in err, err
        assert f"WARNING: {name}: the daemon's event was cut" not in err, err
        assert not [line for line in out.splitlines()
                    if line.lstrip().startswith(name) and ("cut" in line or "data end" in line)]
    assert ran_out  # at least one event ran to its data's end (both do on an idle machine)


def test_pairing_by_onset_tick_keeps_every_test_and_names_strays():
    spans = [("A", 100), ("B", 100), ("C", 100)]  # ticks 0..99, 100..199, 200..299
    events = [120, 150, 260, 400]  # onset ticks
    paired, stray = bench.pair_events(spans, events, lambda e: e)
    assert paired == {"A": None, "B": events[0], "C": events[2]}
    assert stray == [events[1], events[3]]  # a second trigger in B, one after the last test
