"""The bench pairs each replayed test with the event the daemon recorded during it, by the
event's onset tick, never by position: a test that does not trigger must not relabel the
tests after it."""

from __future__ import annotations

import dataclasses

import observer_node.bench as bench
from observer_node.data import read_isomme


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
    for name in names[1:]:
        event, off = result.events[name], result.offline[name]
        assert event is not None, name
        # the event is the one of this test: its fit is this test's offline fit
        assert abs(event.fit_vs_reference.cr - off.cr) < 2, name
        assert abs(event.fit_vs_reference.cd - off.cd) < 2, name
    out = capsys.readouterr().out
    assert "R16_002" in out and "did not trigger" in out


def test_pairing_by_onset_tick_keeps_every_test_and_names_strays():
    spans = [("A", 100), ("B", 100), ("C", 100)]  # ticks 0..99, 100..199, 200..299
    events = [120, 150, 260, 400]  # onset ticks
    paired, stray = bench.pair_events(spans, events, lambda e: e)
    assert paired == {"A": None, "B": events[0], "C": events[2]}
    assert stray == [events[1], events[3]]  # a second trigger in B, one after the last test
