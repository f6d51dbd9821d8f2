"""The command lines as a whole: one error base with its exit codes, reported in one line;
the bus options declared once for every command that opens a bus; defaults shown in --help
are the ones the code uses; run's options map onto config keys by an explicit table."""

from __future__ import annotations

import argparse
import dataclasses
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from observer_node import cli
from observer_node.cli import run as run_cmd
from observer_node.daemon.config import ConfigError, NodeConfig
from observer_node.daemon.core import CoreConfig
from observer_node.data import CrashDataError
from observer_node.dbc.bus import BusOpenError
from observer_node.dbc.codec import LayoutError
from observer_node.errors import ObserverError, RecordingLostError, UsageError
from observer_node.export_c import ExportError as CExportError
from observer_node.loop.cluster import ClusterError
from observer_node.model.modelfile import ModelFileError
from observer_node.recording.export import ExportError
from observer_node.recording.reader import RecordingError
from observer_node.replay import cli as replay_cli
from observer_node.replay.sources import SourceError

ROOT = Path(__file__).resolve().parents[1]
USER_ERRORS = (CrashDataError, ModelFileError, ConfigError, RecordingError, ExportError,
               CExportError, ClusterError, UsageError, LayoutError, BusOpenError, SourceError)


@pytest.mark.parametrize("error", USER_ERRORS, ids=lambda e: e.__name__)
def test_every_user_error_derives_from_the_one_base_with_exit_code_2(error):
    assert issubclass(error, ObserverError) and error.exit_code == 2


def test_a_run_that_lost_recording_exits_3():
    assert issubclass(RecordingLostError, ObserverError) and RecordingLostError.exit_code == 3


def _parsed(argv: list[str]) -> argparse.Namespace:
    return cli.build_parser().parse_args(argv)


@pytest.mark.parametrize("code", [2, 3, 7])
def test_main_ends_any_observer_error_with_one_line_and_its_exit_code(code, monkeypatch,
                                                                      capsys):
    class Failed(ObserverError):
        exit_code = code

    def fail(path: str) -> None:
        raise Failed(f"{path}: what is wrong")

    import observer_node.recording

    monkeypatch.setattr(observer_node.recording, "read_recording", fail)
    assert cli.main(["analyze", "run.mcap"]) == code
    assert capsys.readouterr().err == "observer-node: error: run.mcap: what is wrong\n"


def test_crash_replay_ends_any_observer_error_with_one_line(monkeypatch, capsys):
    def fail(*args: object, **kwargs: object) -> None:
        raise CrashDataError("t.mme: line 3: what is wrong")

    monkeypatch.setattr(replay_cli, "load_source", fail)
    assert replay_cli.main(["t.mme", "--dry-run"]) == 2
    assert capsys.readouterr().err == "crash-replay: error: t.mme: line 3: what is wrong\n"


def _bus_actions(parser: argparse.ArgumentParser) -> dict[str, argparse.Action]:
    return {a.dest: a for a in parser._actions if a.dest in ("interface", "channel", "fd")}


def _subparser(name: str) -> argparse.ArgumentParser:
    return cli.build_parser()._subparsers._group_actions[0].choices[name]


def test_every_command_that_opens_a_bus_has_the_same_bus_options():
    run, bench, replay = _subparser("run"), _subparser("bench"), replay_cli.build_parser()
    helps = {}
    for parser in (run, bench, replay):
        for dest, action in _bus_actions(parser).items():
            # one declaration: the same wording, the default aside
            helps.setdefault(dest, set()).add(action.help.split(" (default")[0])
    assert set(helps) == {"interface", "channel", "fd"}
    assert helps["channel"] == {"bus channel"} and len(helps["fd"]) == 1
    assert {h.split(",")[0] for h in helps["interface"]} == {"python-can interface"}
    # the daemon's and crash-replay's defaults are one
    assert replay.get_default("channel") == NodeConfig().channel
    assert replay.get_default("interface") == NodeConfig().interface


def _all_parsers() -> list[argparse.ArgumentParser]:
    top = cli.build_parser()
    return [top, *top._subparsers._group_actions[0].choices.values(),
            replay_cli.build_parser()]


def test_help_takes_every_default_from_argparse():
    """An option with a default shows it with %(default)s: never restated by hand."""
    stated = []
    for parser in _all_parsers():
        for a in parser._actions:
            if a.default not in (None, False, argparse.SUPPRESS) and a.help and \
                    a.help != argparse.SUPPRESS and "%(default" not in a.help:
                stated.append(f"{parser.prog} {a.option_strings}: {a.help}")
    assert stated == []


def test_run_help_shows_the_config_defaults():
    node, core = NodeConfig(), CoreConfig()
    helps = {a.dest: a.help % vars(a) for a in _subparser("run")._actions if a.help}
    for dest, key in run_cmd.CONFIG_KEYS.items():
        table, _, name = key.rpartition(".")
        value = getattr(core if table == "core" else node, name)
        if isinstance(value, bool) or value == "":
            continue  # a flag, or a key that is empty unless given
        shown = f"{value:g}" if isinstance(value, float) else str(value)
        assert f"default {shown}" in helps[dest], (dest, helps[dest])


def test_every_run_option_is_a_config_key_or_the_commands_own():
    own = {"help", "config", "print_config", "quiet"}
    dests = {a.dest for a in _subparser("run")._actions}
    assert dests - own == set(run_cmd.CONFIG_KEYS)
    node = {f.name for f in dataclasses.fields(NodeConfig)}
    core = {f.name for f in dataclasses.fields(CoreConfig)}
    for key in run_cmd.CONFIG_KEYS.values():
        table, _, name = key.rpartition(".")
        assert name in (core if table == "core" else node), key


def test_run_command_line_overrides_the_config_file_key_by_key(tmp_path):
    toml = tmp_path / "c.toml"
    toml.write_text('[observer]\ninterface = "virtual"\nchannel = "from-file"\n'
                    'model = "file.json"\nrt_priority = 5\n'
                    "[observer.core]\ntrigger_g = 4.0\nevent_s = 0.3\n")
    cfg = run_cmd.config_from_args(_parsed(["run", "--config", str(toml), "--channel", "cli",
                                            "--trigger-g", "5", "--python-can-socketcan"]))
    assert (cfg.interface, cfg.channel, cfg.model, cfg.rt_priority) == \
        ("virtual", "cli", "file.json", 5)
    assert (cfg.core.trigger_g, cfg.core.event_s) == (5.0, 0.3)
    assert cfg.raw_socketcan is False and cfg.fd is False

    argv = ["run", "--interface", "i", "--channel", "c", "--fd", "--model", "m.json",
            "--setup", "SLED", "--record", "r.mcap", "--live", "--cpu-latency-us", "-1",
            "--rt-priority", "3", "--trigger-g", "6", "--event-s", "0.25",
            "--counts-per-rev", "48"]
    cfg = run_cmd.config_from_args(_parsed(argv))
    want = NodeConfig(interface="i", channel="c", fd=True, model="m.json", setup="SLED",
                      record="r.mcap", live="127.0.0.1:8765", cpu_latency_us=-1,
                      rt_priority=3, core=CoreConfig(trigger_g=6.0, event_s=0.25,
                                                     counts_per_rev=48))
    assert cfg == want
    assert run_cmd.config_from_args(_parsed(["run", "--model", "m.json"])) == \
        NodeConfig(model="m.json")


def _recorder_pid(daemon_pid: int) -> int:
    """The daemon's recorder process (a spawned multiprocessing child, not its tracker)."""
    for pid in Path(f"/proc/{daemon_pid}/task/{daemon_pid}/children").read_text().split():
        if "resource_tracker" not in Path(f"/proc/{pid}/cmdline").read_text():
            return int(pid)
    raise AssertionError("the daemon has no recorder process")


def test_run_whose_recording_is_not_the_whole_run_exits_3_in_one_line(model_path, tmp_path):
    """The daemon runs on when its writer dies; at the stop, run ends with exit code 3 and
    one error line that says so, after its counters."""
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "run", "--interface",
                          "virtual", "--channel", "lost3", "--model", str(model_path),
                          "--record", str(tmp_path / "run.mcap"), "--cpu-latency-us", "-1"],
                         cwd=ROOT, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        first = p.stderr.readline()
        assert "listening on" in first, first
        os.kill(_recorder_pid(p.pid), signal.SIGKILL)
        time.sleep(1.0)  # the daemon sees its writer gone
        p.send_signal(signal.SIGINT)
        _, rest = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    assert "Traceback" not in rest, rest
    assert p.returncode == RecordingLostError.exit_code == 3, rest
    lines = rest.strip().splitlines()
    assert lines[-2].startswith("observer-node: stopped; ")
    assert [x for x in lines if "error:" in x] == lines[-1:]
    assert lines[-1].startswith("observer-node: error: the recording is not the whole run: "
                                "parts "), rest
