"""A recording's frames exported in bus-log formats and replayed: the same estimates."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest

from observer_node.cli import main
from observer_node.daemon.harness import CODEC, Harness, r16_schedule
from observer_node.recording import read_recording
from observer_node.replay.sources import load_source


@pytest.fixture(scope="module")
def recorded(model, tmp_path_factory) -> Path:
    record = tmp_path_factory.mktemp("export") / "run.mcap"
    with Harness(model, "export-src", record) as h:
        h.play(r16_schedule())
        time.sleep(0.1)
    return record


@pytest.mark.parametrize("suffix", [".mf4", ".blf", ".asc", ".log", ".trc"])
def test_export_then_replay_gives_the_same_estimates(model, recorded, suffix, tmp_path, capsys):
    log = tmp_path / f"run{suffix}"
    assert main(["export", str(recorded), "--to", str(log)]) == 0
    assert "frames to" in capsys.readouterr().out
    (sched,) = load_source(log, CODEC)
    if suffix == ".log":  # candump -L keeps no direction: drop what the daemon sent
        sent = {CODEC[m].frame_id for m in ("ChestEstimate", "ObserverStatus",
                                            "ObserverCounters", "ObserverHealth")}
        keep = [k for k, i in enumerate(sched.ids.tolist()) if i not in sent]
        sched = type(sched)(sched.t_s[keep], sched.ids[keep], [sched.data[k] for k in keep],
                            sched.source)
    first = read_recording(recorded)
    again = tmp_path / "again.mcap"
    with Harness(model, f"export-{suffix[1:]}", again) as h:
        h.play(sched)
        time.sleep(0.1)
    second = read_recording(again)
    for key in ("cr_g", "cd_mm", "running"):
        np.testing.assert_array_equal(second.ticks[key], first.ticks[key], err_msg=key)


def test_export_refuses_an_unknown_format_in_one_line(recorded, tmp_path, capsys):
    assert main(["export", str(recorded), "--to", str(tmp_path / "run.xyz")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "unknown log format '.xyz'" in err
