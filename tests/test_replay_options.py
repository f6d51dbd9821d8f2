"""crash-replay refuses bad options and sources in one line naming the option or file, exit
code 2: never a traceback, never a meaningless value played."""

from __future__ import annotations

import gc
from pathlib import Path

import can
import pytest

from observer_node.data import read_isomme
from observer_node.dbc import Codec
from observer_node.replay.cli import main
from observer_node.replay.schedule import crash_test_schedule

from .conftest import DATA
from .runners import sigint_default

R16 = str(DATA / "R16_001")


def _one_line_error(capsys: pytest.CaptureFixture[str], argv: list[str]) -> str:
    """Run crash-replay, expect exit code 2 and return its one-line error."""
    try:
        code = main(argv)
    except SystemExit as e:  # argparse refuses while parsing
        code = e.code
    assert code == 2, argv
    err = capsys.readouterr().err.strip()
    assert err.startswith("crash-replay: error: ") and "\n" not in err, err
    return err


@pytest.mark.parametrize("option, value", [
    ("--rate", "0"), ("--rate", "nan"), ("--rate", "inf"), ("--rate", "-1"),
    ("--rate", "1e-9"), ("--rate", "1e6"),  # a test played over years, or in nanoseconds
    ("--gap", "nan"), ("--gap", "-1"), ("--gap", "inf"), ("--gap", "1e9"),
    ("--spin-us", "nan"), ("--spin-us", "-5"),
    ("--bitrate", "nan"), ("--bitrate", "0"), ("--data-bitrate", "-1"),
    ("--tick-rate", "0"), ("--tick-rate", "nan"),
    ("--start", "nan"), ("--end", "inf"),
    ("--pre", "nan"), ("--pre", "-1"), ("--pre", "1e12"),
    ("--loop", "0"), ("--counts-per-rev", "0"),
])
def test_meaningless_numbers_are_refused_naming_the_option(capsys, option, value):
    err = _one_line_error(capsys, [R16, "--dry-run", option, value])
    assert option in err


def test_pre_says_its_limit_in_help(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    assert "at most 5" in capsys.readouterr().out


def test_a_loop_past_what_memory_holds_is_refused_before_it_is_built(capsys):
    """--loop 100000 built 50 million frames in memory before the first was sent."""
    err = _one_line_error(capsys, [R16, "--dry-run", "--loop", "100000"])
    assert "--loop 100000: 50,400,000 frames in all" in err and "shell loop" in err
    assert main([R16, "--dry-run", "--loop", "3"]) == 0
    first = capsys.readouterr().out.splitlines()[0]
    assert first.startswith(f"{3 * 504} frames") and first.endswith("from R16_001 x3")


def test_a_bus_load_past_what_the_bus_carries_is_said_and_the_gap_is_wall_time(capsys):
    assert main([R16, "--dry-run", "--rate", "1000"]) == 0
    assert "more than the bus carries" in capsys.readouterr().out
    assert main([R16, R16, "--dry-run", "--gap", "10", "--rate", "0.5"]) == 0
    first = capsys.readouterr().out.splitlines()[0]  # two 0.419 s tests at half speed, 10 s
    assert first.startswith("1008 frames over 11.68 s as played at --rate 0.5"), first


def test_the_dry_run_says_the_time_and_bus_load_as_played_at_the_rate(capsys):
    assert main([R16, "--dry-run"]) == 0
    one = capsys.readouterr().out.splitlines()
    assert main([R16, "--dry-run", "--rate", "0.01"]) == 0
    slow = capsys.readouterr().out.splitlines()
    assert one[0] == "504 frames over 0.419 s from R16_001"
    assert slow[0] == "504 frames over 41.9 s as played at --rate 0.01 from R16_001"
    assert float(one[5].split()[0]) * 100 == pytest.approx(float(slow[5].split()[0]))
    load = [float(x.split()[-2]) for x in (one[3], slow[3])]
    assert "bus load" in one[3] and load[1] == pytest.approx(load[0] / 100, abs=0.06)


def test_a_window_that_ends_before_it_starts_is_refused(capsys):
    err = _one_line_error(capsys, [R16, "--dry-run", "--start", "0.5", "--end", "0.1"])
    assert "--start 0.5" in err and "--end 0.1" in err


@pytest.mark.parametrize("window, said", [
    (["--start", "100"], "--start 100 s is after the end"),
    (["--end", "-5"], "--end -5 s is before the start"),
    (["--start", "0.1002", "--end", "0.1004"], "holds no sample"),  # 1 ms ticks
])
def test_a_window_beside_the_test_names_the_option_and_the_tests_span(capsys, window, said):
    err = _one_line_error(capsys, [R16, "--dry-run", *window])
    assert said in err and "R16_001" in err and " to 0." in err


def test_a_window_beside_a_bus_log_names_the_option_and_the_logs_span(capsys, tmp_path):
    log = tmp_path / "run.log"
    log.write_text("(1.000000) vcan0 100#0102\n(1.250000) vcan0 100#0304\n")
    err = _one_line_error(capsys, [str(log), "--dry-run", "--start", "3"])
    assert "--start 3 s is after the end: run.log runs from 0.000 to 0.250 s" in err


@pytest.mark.parametrize("option, value", [
    ("--remap", "0x100=-5"), ("--remap", "0x100=0x40000000"), ("--remap", "-1=0x101"),
    ("--remap", "0x100=x"), ("--only", "-1"), ("--only", "0x20000000"), ("--only", "one"),
])
def test_can_ids_out_of_range_are_refused_naming_the_option(capsys, option, value):
    err = _one_line_error(capsys, [R16, "--dry-run", option, value])
    assert option in err


@pytest.mark.parametrize("remaps, said", [
    (["0x100=0x110"], "--remap 0x100=0x110: the sources send 0x110 already"),
    (["0x100=0x120", "0x110=0x120"], "--remap 0x110=0x120: 0x100 goes out as 0x120 too"),
    (["0x100=0x120", "0x100=0x130"], "--remap 0x100 given twice"),
])
def test_remaps_that_would_mix_or_contradict_are_refused(capsys, remaps, said):
    argv = [R16, "--dry-run"] + [x for r in remaps for x in ("--remap", r)]
    assert said in _one_line_error(capsys, argv)


def test_remaps_that_swap_ids_are_fine_and_unmatched_ids_are_warned_of(capsys):
    assert main([R16, "--dry-run", "--remap", "0x100=0x110", "--remap", "0x110=0x100"]) == 0
    assert capsys.readouterr().err == ""
    assert main([R16, "--dry-run", "--remap", "0x123=0x124", "--only", "0x100",
                 "--only", "0x7FF"]) == 0
    err = capsys.readouterr().err
    assert "warning: --remap 0x123=0x124: no frames of 0x123" in err
    assert "warning: --only 0x7FF: no frames" in err


@pytest.mark.parametrize("name", ["plain.txt", "x.unknownext", "extensionless"])
def test_a_file_of_unknown_kind_says_what_sources_are_read(capsys, tmp_path, name):
    (tmp_path / name).write_text("hello\n")
    err = _one_line_error(capsys, [str(tmp_path / name), "--dry-run"])
    assert f"{name}: not a source crash-replay reads" in err and ".mcap recording" in err


def test_a_folder_named_like_a_log_is_said_to_be_a_folder(capsys, tmp_path):
    (tmp_path / "dir.log").mkdir()
    err = _one_line_error(capsys, [str(tmp_path / "dir.log"), "--dry-run"])
    assert "dir.log: is a folder, not a .log file" in err


def _bus_log(path: Path) -> int:
    """A bus log of R16_002's frames at ``path`` (its kind by suffix); the number of frames."""
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), Codec(), 1000.0)
    with can.Logger(str(path)) as w:
        for k, (cid, d) in enumerate(zip(s.ids.tolist(), s.data, strict=True)):
            w.on_message_received(can.Message(timestamp=1000 + s.t_s[k], arbitration_id=cid,
                                              data=d, is_extended_id=False))
    return len(s)


@pytest.mark.parametrize("suffix, cut", [
    (".blf", 0.5),  # shorter than its header says
    (".trc", 0.5),  # the last line cut
    (".asc", 0.5),
    (".mf4", 0.5),  # asammdf fails; its __del__ must not print a traceback after our line
])
def test_a_truncated_bus_log_is_refused_saying_what_was_read(capsys, tmp_path, suffix, cut):
    whole = tmp_path / f"whole{suffix}"
    _bus_log(whole)
    raw = whole.read_bytes()
    log = tmp_path / f"cut{suffix}"
    log.write_bytes(raw[:int(len(raw) * cut) + 7])
    err = _one_line_error(capsys, [str(log), "--dry-run"])
    assert f"cut{suffix}: truncated or corrupt after " in err and " frames (" in err
    gc.collect()  # a half-made reader collected late must say nothing either
    assert capsys.readouterr().err == ""


def test_a_trc_log_cut_at_a_line_end_or_with_a_bad_line_is_refused(capsys, tmp_path):
    whole = tmp_path / "whole.trc"
    _bus_log(whole)
    lines = whole.read_bytes().splitlines(keepends=True)
    bad = tmp_path / "bad.trc"
    bad.write_bytes(b"".join([*lines[:-5], lines[-5][:30] + b"\r\n", *lines[-4:]]))
    err = _one_line_error(capsys, [str(bad), "--dry-run"])
    assert "bad.trc: truncated or corrupt after " in err and "Failed to parse" in err
    asc = tmp_path / "whole.asc"
    _bus_log(asc)
    cut = tmp_path / "cut.asc"
    cut.write_bytes(b"".join(asc.read_bytes().splitlines(keepends=True)[:-3]))
    assert "no 'End TriggerBlock' line" in _one_line_error(capsys, [str(cut), "--dry-run"])


@pytest.mark.parametrize("suffix", [".asc", ".blf", ".trc", ".mf4"])
def test_whole_bus_logs_still_replay(capsys, tmp_path, suffix):
    n = _bus_log(tmp_path / f"run{suffix}")
    assert main([str(tmp_path / f"run{suffix}"), "--dry-run"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith(f"{n} frames") and err == ""


@pytest.mark.parametrize("suffix", [".asc", ".blf"])
def test_a_log_of_sent_frames_only_says_all_frames_replays_them(capsys, tmp_path, suffix):
    """A logger's own frames only (every frame Tx): "no frames" did not say why."""
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), Codec(), 1000.0)
    log = tmp_path / f"sent{suffix}"
    with can.Logger(str(log)) as w:
        for k in range(10):
            w.on_message_received(can.Message(timestamp=1000 + s.t_s[k],
                                              arbitration_id=int(s.ids[k]), data=s.data[k],
                                              is_extended_id=False, is_rx=False))
    err = _one_line_error(capsys, [str(log), "--dry-run"])
    assert f"sent{suffix}: no frames received by the logging node, only 10 it sent: " \
           "--all-frames replays those" in err
    assert main([str(log), "--dry-run", "--all-frames"]) == 0
    assert capsys.readouterr().out.startswith("10 frames")


def test_ctrl_c_while_the_frames_are_built_is_one_line():
    """crash-replay caught Ctrl-C only while playing: while it read and built a long --loop
    it printed a traceback (session 58)."""
    import os
    import signal
    import subprocess
    import sys
    import time

    run = ("import sys; from observer_node.entry import crash_replay; "
           f"sys.argv = ['crash-replay', {R16!r}, '--dry-run', '--loop', '1900']; "
           "sys.exit(crash_replay())")  # as the installed command starts
    p = subprocess.Popen([sys.executable, "-c", run], stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True, start_new_session=True,
                         preexec_fn=sigint_default)
    time.sleep(3.0)  # loading or building: both are one line now
    os.killpg(p.pid, signal.SIGINT)
    assert p.stderr is not None
    err = p.stderr.read()
    assert p.wait(timeout=60) == 130, err
    assert err.strip() == "crash-replay: interrupted"


def test_only_an_id_the_logging_node_sent_names_all_frames(capsys, tmp_path):
    """--only an ID the log holds among the logger's own frames said "no frames of that ID"
    (session 58's hostile user): the frames are there, left out as sent."""
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), Codec(), 1000.0)
    log = tmp_path / "mixed.asc"
    with can.Logger(str(log)) as w:
        for k in range(40):
            cid = int(s.ids[k])
            w.on_message_received(can.Message(timestamp=1000 + s.t_s[k], arbitration_id=cid,
                                              data=s.data[k], is_extended_id=False,
                                              is_rx=cid != 0x110))  # 0x110: sent only
    assert main([str(log), "--dry-run", "--only", "0x110"]) == 2
    err = capsys.readouterr().err
    assert "--only 0x110: only the logging node sent that ID: --all-frames replays" in err
    assert main([str(log), "--dry-run", "--only", "0x110", "--all-frames"]) == 0
    assert capsys.readouterr().out.startswith(f"{int((s.ids[:40] == 0x110).sum())} frames")


def test_the_loop_limit_counts_the_frames_only_leaves(capsys):
    """The --loop limit counted every frame before --only filtered them: 2000 plays of a test
    with --only its 101 BRS frames (202,000 sent) were refused as 1,042,000."""
    assert main([str(DATA / "R16_002"), "--dry-run", "--loop", "2000", "--only", "0x110"]) == 0
    assert capsys.readouterr().out.startswith("202000 frames")
    err = _one_line_error(capsys, [str(DATA / "R16_002"), "--dry-run", "--loop", "2000"])
    assert "1,042,000 frames in all" in err


def _mixed_log(path, s):
    """An ASC log of R16_002's first 40 frames at +0 s, 0x110 among them sent by the logging
    node, then a sent 0x300 at 0.5 s and a received 0x100 at 5 s."""
    with can.Logger(str(path)) as w:
        for k in range(40):
            cid = int(s.ids[k])
            w.on_message_received(can.Message(timestamp=1000 + s.t_s[k], arbitration_id=cid,
                                              data=s.data[k], is_extended_id=False,
                                              is_rx=cid != 0x110))
        w.on_message_received(can.Message(timestamp=1000.5, arbitration_id=0x300,
                                          data=b"\0", is_extended_id=False, is_rx=False))
        w.on_message_received(can.Message(timestamp=1005.0, arbitration_id=0x100,
                                          data=s.data[1], is_extended_id=False))


def test_only_with_nothing_left_says_so_before_looping(capsys, tmp_path):
    """--only an ID with no frames and a huge --loop built a billion empty copies before
    saying "nothing to send" (MemoryError traceback; session 59's hostile user)."""
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), Codec(), 1000.0)
    _mixed_log(tmp_path / "mix.asc", s)
    for cid, why in (("0x999", "no frames of that ID"), ("0x110", "--all-frames replays")):
        assert main([str(tmp_path / "mix.asc"), "--only", cid, "--loop", "1000000000",
                     "--dry-run"]) == 2
        err = capsys.readouterr().err
        assert why in err and err.endswith("crash-replay: nothing to send\n"), err
    err = _one_line_error(capsys, [str(tmp_path / "mix.asc"), "--only", "0x100", "--loop",
                                   "999999", "--dry-run"])
    n_100 = int((s.ids[:40] == 0x100).sum()) + 1  # and the one at 5 s
    assert f"--loop 999999: {n_100 * 999999:,} frames in all" in err


def test_the_all_frames_hint_reads_the_window(capsys, tmp_path):
    """With --start after the only 0x300 the node sent, the hint sent the user to
    --all-frames, which then found none (session 59's hostile user)."""
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), Codec(), 1000.0)
    _mixed_log(tmp_path / "mix.asc", s)
    assert main([str(tmp_path / "mix.asc"), "--start", "4", "--only", "0x300",
                 "--dry-run"]) == 2
    assert "--only 0x300: no frames of that ID" in capsys.readouterr().err
    assert main([str(tmp_path / "mix.asc"), "--end", "1", "--only", "0x300",
                 "--dry-run"]) == 2
    assert "--only 0x300: only the logging node sent that ID" in capsys.readouterr().err


def test_only_keeps_the_spacing_of_looped_copies(capsys, tmp_path):
    """--only filters each source before --loop repeats it, but the copies stay as far apart
    as unfiltered: 0x100's last frame at 5 s keeps the next copy 5 s + --gap later."""
    s = crash_test_schedule(read_isomme(DATA / "R16_002"), Codec(), 1000.0)
    _mixed_log(tmp_path / "mix.asc", s)
    assert main([str(tmp_path / "mix.asc"), "--only", "0x110", "--all-frames", "--loop", "2",
                 "--gap", "0.5", "--dry-run"]) == 0
    out = capsys.readouterr().out
    n = int((s.ids[:40] == 0x110).sum())
    assert out.startswith(f"{2 * n} frames over ")
    times = [float(line.split()[0]) for line in out.splitlines()
             if line.split()[1:2] == ["0x110"]]  # the frames listed, as played
    first_110 = float(s.t_s[:40][s.ids[:40] == 0x110][0])
    assert times[0] == 0.0  # as played: the first frame at once
    assert times[n] == pytest.approx(5.0 - first_110 + 0.5 + times[0], abs=1e-6)
