"""A recording's frames exported in bus-log formats and replayed: the same estimates."""

from __future__ import annotations

import json
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from observer_node.cli import main
from observer_node.daemon.harness import CODEC, Harness, r16_schedule
from observer_node.recording import read_recording
from observer_node.replay.sources import load_source


def _play_all(h: Harness, sched) -> None:
    """Play ``sched`` and stop the daemon only once it has read every frame (a generous
    bound): on a busy machine it falls behind, and a fixed wait would cut the run."""
    h.play(sched)
    deadline = time.monotonic() + 120
    while h.node.counters.rx < len(sched) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert h.node.counters.rx == len(sched), "frames left unread"


def _harness(*args, **kwargs) -> Harness:
    # The watchdog times frames by their receipt: a busy machine that stalls the daemon
    # for 200 ms looks like a silent sensor and ends the event. Out of play here (its own
    # tests cover it): the estimates then depend on the frames alone.
    h = Harness(*args, accel_timeout_s=60.0, brs_timeout_s=60.0, **kwargs)
    h.thread = threading.Thread(target=h.node.run)  # no idle exit: starved is not idle
    return h


@pytest.fixture(scope="module")
def recorded(model, tmp_path_factory) -> Path:
    record = tmp_path_factory.mktemp("export") / "run.mcap"
    with _harness(model, "export-src", record) as h:
        _play_all(h, r16_schedule())
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
    with _harness(model, f"export-{suffix[1:]}", again) as h:
        _play_all(h, sched)
    second = read_recording(again)
    for key in ("cr_g", "cd_mm", "running"):
        np.testing.assert_array_equal(second.ticks[key], first.ticks[key], err_msg=key)


def test_export_refuses_an_unknown_format_in_one_line(recorded, tmp_path, capsys):
    assert main(["export", str(recorded), "--to", str(tmp_path / "run.xyz")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "unknown log format '.xyz'" in err


@pytest.mark.parametrize("channel", ["my can", "can0\nx", ""])
def test_a_channel_name_no_log_line_can_carry_is_refused(recorded, tmp_path, channel, capsys):
    out = tmp_path / "run.log"
    with pytest.raises(SystemExit) as e:
        main(["export", str(recorded), "--to", str(out), "--channel", channel])
    err = capsys.readouterr().err.strip()
    assert e.value.code == 2 and err.count("\n") == 0 and "--channel" in err, err
    assert not out.exists()


def test_export_to_a_folder_says_so(recorded, tmp_path, capsys):
    assert main(["export", str(recorded), "--to", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "is a folder; give the log file's name" in err, err


@pytest.mark.parametrize("suffix", [".mf4", ".blf", ".asc"])
def test_export_to_an_unwritable_path_says_so_in_one_line(recorded, tmp_path, suffix, capsys):
    out = tmp_path / "missing" / f"run{suffix}"
    assert main(["export", str(recorded), "--to", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and f"error: {out}: cannot write" in err, err


@pytest.mark.parametrize("suffix", [".blf", ".asc"])
def test_an_export_the_disk_cuts_short_leaves_the_old_log_whole(recorded, tmp_path, suffix):
    """A file-size limit (a full disk's stand-in) mid-export: one line, exit 2, and no
    truncated log: the file that was there stays as it was (a hostile user's finding,
    2026-12-03: a traceback and a cut .asc a tool would read as the whole run)."""
    import resource
    import subprocess
    import sys

    out = tmp_path / f"run{suffix}"
    out.write_text("the last run's log\n")
    limit = 4096  # bytes: the recording's frames take more in every format

    def small_disk() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    p = subprocess.run([sys.executable, "-m", "observer_node", "export", str(recorded),
                        "--to", str(out)], capture_output=True, text=True, timeout=120,
                       preexec_fn=small_disk)
    assert p.returncode == 2 and "Traceback" not in p.stderr, p.stderr
    assert len(p.stderr.strip().splitlines()) == 1 and f"{out}: cannot write" in p.stderr
    assert out.read_text() == "the last run's log\n"
    assert sorted(f.name for f in tmp_path.iterdir()) == [out.name]


def _wall_clock(recording: Path) -> tuple[float, float, float]:
    """The recording's wall-clock start and its first and last frame's wall-clock times, in
    s since the epoch, read with the ``mcap`` library: a frame's MCAP log time is wall-clock
    ns, its ``t`` seconds since the recorder started."""
    from mcap.reader import make_reader

    start, times = None, []
    with recording.open("rb") as f:
        for _, _channel, msg in make_reader(f).iter_messages(topics=["/can/frames"]):
            times.append(msg.log_time / 1e9)
            if start is None:
                start = msg.log_time / 1e9 - json.loads(msg.data)["t"]
    assert start is not None and times
    return start, min(times), max(times)


def _first_last(msgs) -> tuple[float, float]:
    ts = [m.timestamp for m in msgs]
    return min(ts), max(ts)


@pytest.mark.parametrize("suffix", [".mf4", ".blf", ".asc", ".log", ".trc"])
def test_exports_carry_the_recordings_wall_clock_time(recorded, suffix, tmp_path):
    import can

    start, first, last = _wall_clock(recorded)
    assert abs(start - time.time()) < 3600  # the fixture's run, just now
    log = tmp_path / f"run{suffix}"
    assert main(["export", str(recorded), "--to", str(log)]) == 0
    if suffix == ".mf4":  # asammdf: header start + the time axis = each frame's wall clock
        from asammdf import MDF

        with MDF(str(log)) as mdf:
            head = mdf.header.start_time.timestamp()
            ts = mdf.get("CAN_DataFrame", group=0).timestamps
            assert abs(head - start) < 2e-6, (head, start)
            assert abs(head + ts[0] - first) < 1e-5 and abs(head + ts[-1] - last) < 1e-5
        return
    # python-can's readers, each with the format's own resolution
    tol = {".blf": 1e-5, ".asc": 1e-3, ".log": 1e-5, ".trc": 1e-3}[suffix]
    if suffix == ".blf":
        reader = can.BLFReader(str(log))
        assert abs(reader.start_timestamp - first) < 1e-3, (reader.start_timestamp, first)
    elif suffix == ".asc":
        reader = can.ASCReader(str(log), relative_timestamp=False)
        date = next(line for line in log.read_text().splitlines() if line.startswith("date "))
        # the header's date: when the recording started (python-can writes the export's time)
        assert abs(reader._datetime_to_timestamp(date.split(None, 2)[2]) - start) < 1e-3, date
    elif suffix == ".trc":
        reader = can.TRCReader(str(log))
    else:
        reader = can.CanutilsLogReader(str(log))
    t0, t1 = _first_last(reader)
    assert abs(t0 - first) < tol and abs(t1 - last) < tol, (t0, first, t1, last)
