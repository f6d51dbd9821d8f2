"""Fuzzed bus traffic (bounded here; ``benchmarks/fuzz.py`` sends a million frames): the
daemon survives, counts every frame once, keeps its memory flat, and detects a real crash
played afterwards exactly as the offline simulation steps it."""

from __future__ import annotations

import time

import numpy as np

from observer_node.daemon.fuzz import rss_mb, run_fuzz
from observer_node.daemon.harness import Harness, r16_schedule
from observer_node.recording import offline_estimates, read_recording


def test_fuzzed_frames_are_counted_and_a_later_crash_is_detected(model, tmp_path):
    rss: list[float] = []
    with Harness(model, "fuzz", record=tmp_path / "run.mcap") as h:
        passed = run_fuzz(h, 20_000, seed=11,
                          on_batch=lambda sent: rss.append(rss_mb()) if sent % 4000 == 0
                          else None)
        c = h.node.counters
        assert h.thread.is_alive()
        assert c.rx == passed > 5000
        # every frame counted exactly once
        assert c.rx == c.accepted + c.rejected + c.bad_e2e + c.unknown_id + c.error_frames
        assert c.rejected > 100 and c.bad_e2e > 100 and c.lost > 100 and c.accepted > 100
        events_after_fuzz = h.node.core.events
        h.play(r16_schedule(pre_s=0.6))  # quiet for a re-arm, then R16_002
        time.sleep(0.1)
    assert rss[-1] - rss[0] < 8, rss  # MB: flat, nothing accumulates per frame
    assert h.node.core.events == events_after_fuzz + 1
    rec = read_recording(tmp_path / "run.mcap")
    last = int(rec.ticks["event"].max())
    ticks, y_off = offline_estimates(rec, last)
    rows = np.searchsorted(rec.ticks["tick"], ticks)
    run = rec.ticks["running"][rows] > 0
    assert run.sum() > 150
    assert np.max(np.abs(rec.ticks["cr_g"][rows][run] - y_off[run, 0])) < 1e-9
    assert np.max(np.abs(rec.ticks["cd_mm"][rows][run] - y_off[run, 1])) < 1e-9
    assert np.max(rec.ticks["cd_mm"][rows][run]) > 10  # a real event
