"""The bad-input corpus: model files, daemon configs, ISO-MME tests and zips, recordings.

Every case is run through the command a user would type, in-process, and must end with exit
code 2 and one line on stderr that names the file (and where it can, the line or key), no
traceback, and nothing written. Each case is a small function that makes the bad file from a
good one, so the corpus reads as a list of what can go wrong.
"""

from __future__ import annotations

import io
import json
import shutil
import zipfile
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from observer_node import cli
from observer_node.data import CrashDataError, bundled_campaign
from observer_node.data.crashtest import brs_to_counts
from observer_node.evaluation import identify
from observer_node.ident.dataset import make_dataset
from observer_node.replay import cli as replay_cli

DATA = Path(__file__).parent / "data"


@pytest.fixture(scope="module")
def good_model(tmp_path_factory) -> dict:
    from observer_node.data import read_isomme

    mf = identify("greybox", make_dataset([read_isomme(DATA / "R16_001")], 1000.0))
    return mf.to_dict()


def _expect_one_line_error(code: int, err: str, says: str) -> None:
    assert code == 2, err
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert says in lines[0], lines[0]


# ---------------------------------------------------------------------------- model files
def _unstable(d):
    d.pop("parameters")  # a grey-box given by its matrices alone
    d["state_space"]["A"] = [[2.0 if i == j else 0.0 for j in range(5)] for i in range(5)]


def _not_its_parameters(d):
    d["state_space"]["A"][0][0] *= 1.01


def _set(key, value):
    def f(d):
        d[key] = value
    return f


def _effect(effect):
    def f(d):
        d["effects"] = [effect]
    return f


def _scoped(d):
    """A grey-box whose one effect acts on the SLED setup only (loop's model.json)."""
    from observer_node.model.chest import model_matrices

    base = {k: v["value"] for k, v in d["parameters"].items()}
    Ad, Bd, C, D = model_matrices(base, d["tick_rate_hz"], True)
    d["state_space"] = {"A": Ad.tolist(), "B": Bd.tolist(), "C": C.tolist(),
                        "D": D.tolist()}
    d["effects"] = [{"kind": "belt_unloading", "parameters": {}, "setups": ["SLED"]}]


MODEL_CASES: dict[str, tuple[Callable[[dict], object] | bytes, str]] = {
    "unstable A=2I": (_unstable, "unstable"),
    "A not the parameters'": (_not_its_parameters, "'state_space.A' disagrees with 'parameters'"),
    "negative stiffness": (lambda d: d["parameters"]["k1"].__setitem__("value", -1.0),
                           "parameters"),
    # a hostile user's (2026-12-03): each was run or scored as if fine
    "CR in m/s^2": (lambda d: d["outputs"][0].__setitem__("unit", "m/s^2"),
                    "'outputs[0].unit'"),
    "one input": (lambda d: d.__setitem__("inputs", d["inputs"][:1]), "'inputs'"),
    "k1 a string": (lambda d: d["parameters"]["k1"].__setitem__("value", "abc"),
                    "'parameters.k1.value'"),
    "tick rate 0": (_set("tick_rate_hz", 0), "tick_rate_hz"),
    "tick rate -1000": (_set("tick_rate_hz", -1000), "tick_rate_hz"),
    "tick rate 1e9": (_set("tick_rate_hz", 1e9), "tick_rate_hz"),
    "tick rate text": (_set("tick_rate_hz", "fast"), "tick_rate_hz"),
    "kind unknown": (_set("kind", "neural"), "kind"),
    "transform unknown": (_set("input_transform", "magic"), "input_transform"),
    "format version 2": (_set("format_version", 2), "format_version"),
    "no state space": (lambda d: d.pop("state_space"), "state_space"),
    "A not square": (lambda d: d["state_space"].__setitem__("A", [[1.0, 0.0]]), "state_space"),
    "B one input": (lambda d: d["state_space"].__setitem__("B", [[0.0]] * 5), "state_space.B"),
    "matrix text": (lambda d: d["state_space"]["D"].__setitem__(0, ["a", 0]), "state_space.D"),
    "stiffening without k3": (_effect({"kind": "chest_stiffening", "parameters": {}}), "k3"),
    "airbag without gap": (_effect({"kind": "airbag_contact",
                                    "parameters": {"kab": 3e4}}), "gap"),
    # a bag pushing from the start is no airbag (an earlier version could write one)
    "airbag gap 0": (_effect({"kind": "airbag_contact",
                              "parameters": {"kab": 3e4, "gap": 1e-9}}), "gap"),
    "pelvis without parameters": (_effect({"kind": "pelvis_coupling"}), "parameters"),
    "effect kind unknown": (_effect({"kind": "warp_drive", "parameters": {}}), "effects[0]"),
    "effect delay 1e6 ticks": (_effect({"kind": "input_delay",
                                        "parameters": {"n_pulse": 1e6}}), "n_pulse"),
    "scoped effect, bench setup not said": (_scoped, "--setup"),
    "scope not a list": (_effect({"kind": "belt_unloading", "setups": "SLED"}),
                         "effects[0].setups"),
    # a hostile user's (session 58): tracebacks in run and export-c, or a garbled message
    "fitted_on null": (_set("fitted_on", None), "'fitted_on'"),
    "fitted_on setups of numbers": (_set("fitted_on", {"setups": [1, None]}),
                                    "'fitted_on.setups["),
    "fitted_on setups a string": (_set("fitted_on", {"setups": "R16"}), "'fitted_on.setups'"),
    "fitted_on window of one": (_set("fitted_on", {"window_s": [0.01]}), "'fitted_on.window_s'"),
    "effects on ARX": (lambda d: (d.__setitem__("kind", "arx"),
                                  _effect({"kind": "belt_unloading"})(d)), "kind"),
    "effects without grey-box parameters": (lambda d: (d["parameters"].pop("k2"), _effect(
        {"kind": "belt_unloading"})(d)), "k2"),
    "a list": (b"[1, 2, 3]", "not a model file"),
    "null": (b"null", "not a model file"),
    "a string": (b'"model"', "not a model file"),
    "empty file": (b"", "not valid JSON"),
    "truncated JSON": (b'{"format": "chest-observer-model", "kind": "gre', "not valid JSON"),
    "NaN tick rate": (b'{"format": "chest-observer-model",\n "tick_rate_hz": NaN}',
                      "FILE:2: NaN"),
    "Infinity in A": (b'{"state_space": {"A": [[Infinity]]}}', "Infinity"),
    "not UTF-8": (b'{"name": "\xff\xfe\xfa"}', "not UTF-8"),
    "deeply nested": (b"[" * 100_000 + b"]" * 100_000, "nested too deeply"),
    "80 MB of JSON": (b'{"name": "' + b"x" * (5 << 20) + b'"}', "larger than"),
}


@pytest.mark.parametrize("case", sorted(MODEL_CASES))
def test_bad_model_file(case, good_model, tmp_path, capsys):
    make, says = MODEL_CASES[case]
    p = tmp_path / "model.json"
    if isinstance(make, bytes):
        p.write_bytes(make)
    else:
        d = json.loads(json.dumps(good_model))
        make(d)
        p.write_text(json.dumps(d))
    code = cli.main(["run", "--model", str(p), "--interface", "virtual", "--channel",
                     "bad-model", "--record", str(tmp_path / "run.mcap")])
    # the message, not the path (which holds the case's name), must say it
    _expect_one_line_error(code, capsys.readouterr().err.replace(str(p), "FILE"), says)
    assert not (tmp_path / "run.mcap").exists()


def test_missing_model_file_and_a_directory(tmp_path, capsys):
    for p in (tmp_path / "nosuch.json", tmp_path):
        code = cli.main(["run", "--model", str(p), "--interface", "virtual"])
        _expect_one_line_error(code, capsys.readouterr().err, str(p))


# ---------------------------------------------------------------------------- daemon config
CONFIG_CASES = {
    "syntax error": ("[observer\nchannel = 'vcan0'", "config.toml"),
    "unknown key": ("[observer]\nchanel = 'vcan0'", "unknown key 'chanel'"),
    "unknown core key": ("[observer.core]\ntriger_g = 3", "unknown key 'triger_g'"),
    "unknown table": ("[observr]\nchannel = 'x'", "unknown table or key 'observr'"),
    "recover_ticks text": ("[observer.core]\nrecover_ticks = 'x'", "recover_ticks"),
    "recover_ticks float": ("[observer.core]\nrecover_ticks = 2.5", "recover_ticks"),
    "status period 0": ("[observer]\nstatus_period_s = 0", "status_period_s"),
    "status period negative": ("[observer]\nstatus_period_s = -1", "status_period_s"),
    "trigger negative": ("[observer.core]\ntrigger_g = -3", "trigger_g"),
    "trigger nan": ("[observer.core]\ntrigger_g = nan", "not a finite number"),
    "event inf": ("[observer.core]\nevent_s = inf", "not a finite number"),
    "onset above trigger": ("[observer.core]\ntrigger_g = 3.0\nonset_g = 4.0", "onset_g"),
    "counts per rev 0": ("[observer.core]\ncounts_per_rev = 0", "counts_per_rev"),
    "fd a number": ("[observer]\nfd = 1", "fd"),
    "core not a table": ("[observer]\ncore = 3", "core"),
    "cpu latency text": ("[observer]\ncpu_latency_us = 'low'", "cpu_latency_us"),
    "rt priority 100": ("[observer]\nrt_priority = 100", "rt_priority"),
    "rt priority negative": ("[observer]\nrt_priority = -5", "rt_priority"),
    "hold max 0": ("[observer.core]\nhold_max_s = 0", "hold_max_s"),
    "interface empty": ("[observer]\ninterface = ''", "interface"),
}


@pytest.mark.parametrize("case", sorted(CONFIG_CASES))
def test_bad_config(case, good_model, tmp_path, capsys):
    text, says = CONFIG_CASES[case]
    model = tmp_path / "model.json"
    model.write_text(json.dumps(good_model))
    cfg = tmp_path / "config.toml"
    cfg.write_text(text)
    code = cli.main(["run", "--config", str(cfg), "--model", str(model), "--interface",
                     "virtual", "--channel", "bad-config", "--record", str(tmp_path / "r.mcap")])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not (tmp_path / "r.mcap").exists()


def test_bad_command_line_values(good_model, tmp_path, capsys):
    model = tmp_path / "model.json"
    model.write_text(json.dumps(good_model))
    for opt, value in (("--trigger-g", "-1"), ("--event-s", "0"), ("--counts-per-rev", "0"),
                       ("--trigger-g", "nan")):
        code = cli.main(["run", "--model", str(model), "--interface", "virtual", opt, value])
        _expect_one_line_error(code, capsys.readouterr().err, "command line")


def test_a_live_address_that_cannot_be_listened_on_is_refused_before_the_run(
        good_model, tmp_path, capsys):
    """The recorder process opens --live after the daemon has started: a bad one was only
    warned about and the run went on, exit 0 (a hostile user's finding, 2026-12-03)."""
    model = tmp_path / "model.json"
    model.write_text(json.dumps(good_model))
    for live, says in (("127.0.0.1:99999", "port must be 1-65535"),
                       ("127.0.0.1:0", "port must be 1-65535"),
                       ("256.1.1.1:8765", "not an IPv4 address"),
                       ("no-such-host.invalid:8765", "cannot resolve"),
                       ("nohost", "expected HOST:PORT")):  # quoted the schema's regex
        code = cli.main(["run", "--model", str(model), "--interface", "virtual", "--record",
                         str(tmp_path / "r.mcap"), "--live", live])
        _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not (tmp_path / "r.mcap").exists()


# ---------------------------------------------------------------------------- ISO-MME tests
def _edit_key(rel: str, key: str, value: str):
    def f(d: Path) -> None:
        p = d / rel
        lines = p.read_text(encoding="iso-8859-1").splitlines(keepends=True)
        for i, line in enumerate(lines):
            if line.startswith(key):
                lines[i] = f"{line.split(':', 1)[0]}:{value}\r\n"
        p.write_text("".join(lines), encoding="iso-8859-1", newline="")
    return f


def _edit_value(rel: str, index: int, value: str):
    def f(d: Path) -> None:
        p = d / rel
        lines = p.read_text(encoding="iso-8859-1").splitlines(keepends=True)
        lines[index] = f"{value}\r\n"
        p.write_text("".join(lines), encoding="iso-8859-1", newline="")
    return f


def _truncate(rel: str, keep: int):
    def f(d: Path) -> None:
        p = d / rel
        lines = p.read_text(encoding="iso-8859-1").splitlines(keepends=True)
        p.write_text("".join(lines[:keep]), encoding="iso-8859-1", newline="")
    return f


def _backup(d: Path, rel: str) -> None:
    """An older copy of a channel kept in a subfolder (the reader must not pick one)."""
    (d / "Channel" / "OLD").mkdir()
    shutil.copy(d / rel, d / "Channel" / "OLD" / Path(rel).name)


CH1, CH2 = "Channel/R16_001.001", "Channel/R16_001.002"


def _whole_degrees(d: Path) -> None:
    """A 24 counts/rev spindle in whole degrees (15 a count), its Unit missing."""
    _edit_key("R16_001.mme", "Comments", "BRS resolution 24 counts/rev")(d)
    _edit_key(CH2, "Unit", "NOVALUE")(d)
    p = d / CH2
    lines = p.read_text(encoding="iso-8859-1").splitlines()
    lines = [f"{15 * round(float(v) / 15):.1f}" if v and ":" not in v else v for v in lines]
    p.write_text("\r\n".join(lines) + "\r\n", encoding="iso-8859-1", newline="")


def _rounded_degrees(d: Path) -> None:
    """The 96 counts/rev spindle in degrees (3.75 a count) rounded to whole degrees by an
    export, its Unit missing: 4, 8, 11, 15 ... read as counts would be 3.75 times the turn."""
    _edit_key(CH2, "Unit", "NOVALUE")(d)
    p = d / CH2
    lines = p.read_text(encoding="iso-8859-1").splitlines()
    lines = [f"{round(float(v)):d}" if v and ":" not in v else v for v in lines]
    p.write_text("\r\n".join(lines) + "\r\n", encoding="iso-8859-1", newline="")


def _counts_as_degrees(d: Path) -> None:
    """The 96 counts/rev spindle's raw counts written under its "deg" Unit by an export: 1, 2,
    3 ... degrees would read as a 3.75th of the turn."""
    p = d / CH2
    lines = p.read_text(encoding="iso-8859-1").splitlines()
    lines = [f"{round(float(v) / 3.75):d}" if v and ":" not in v else v for v in lines]
    p.write_text("\r\n".join(lines) + "\r\n", encoding="iso-8859-1", newline="")


ISO_CASES: dict[str, tuple[Callable[[Path], None], str]] = {
    "interval NaN": (_edit_key(CH1, "Sampling interval", "NaN"), "Sampling interval"),
    "interval 0": (_edit_key(CH1, "Sampling interval", "0"), "Sampling interval"),
    "interval 1e-300": (_edit_key(CH1, "Sampling interval", "1e-300"), "Sampling interval"),
    "interval negative": (_edit_key(CH1, "Sampling interval", "-0.0001"), "Sampling interval"),
    "interval text": (_edit_key(CH1, "Sampling interval", "fast"), "Sampling interval"),
    "samples 0": (_edit_key(CH1, "Number of samples", "0"), "Number of samples"),
    "samples 2200.7": (_edit_key(CH1, "Number of samples", "2200.7"), "Number of samples"),
    "samples negative": (_edit_key(CH1, "Number of samples", "-5"), "Number of samples"),
    "0 counts/rev": (_edit_key("R16_001.mme", "Comments", "BRS 0 counts/rev"), "counts/rev"),
    "value 1e308": (_edit_value(CH1, 100, "1e308"), "R16_001.001:101"),
    "value nan": (_edit_value(CH1, 100, "nan"), "R16_001.001:101"),
    "value -inf": (_edit_value(CH2, 200, "-inf"), "R16_001.002:201"),
    "value text": (_edit_value(CH1, 100, "1,5"), "R16_001.001:101"),
    "truncated channel": (_truncate(CH1, 500), "truncated"),
    "header only": (_truncate(CH1, 20), "R16_001.001"),
    "no .chn": (lambda d: (d / "Channel" / "R16_001.chn").unlink(), ".chn"),
    "empty .mme": (lambda d: (d / "R16_001.mme").write_bytes(b""), "empty .mme"),
    "no .mme": (lambda d: (d / "R16_001.mme").unlink(), "R16_001"),
    "unit unknown": (_edit_key(CH1, "Unit", "furlong"), "Unit"),
    # degrees of 3.75 would read as 3.75 times as many counts (a hostile user's finding)
    "BRS unit NOVALUE": (_edit_key(CH2, "Unit", "NOVALUE"), "BRS has no unit and reads"),
    "BRS unit NOVALUE, whole degrees": (_whole_degrees, "moves only in steps of 15"),
    "BRS unit NOVALUE, degrees rounded": (_rounded_degrees,
                                          "steps of 3.75 (rounded to whole numbers)"),
    "BRS raw counts under a deg Unit": (_counts_as_degrees,
                                        "whole numbers that steps of 3.75 deg"),
    "pulse channel missing": (_edit_key(CH1, "Channel code", "XXXXXXXXXXXXXXXX"), "crash pulse"),
    "a backup of CR beside it": (lambda d: _backup(d, "Channel/R16_001.003"),
                                 "2 channel files hold the CR channel"),
}


@pytest.mark.parametrize("case", sorted(ISO_CASES))
def test_bad_isomme_test(case, tmp_path, capsys):
    make, says = ISO_CASES[case]
    d = tmp_path / "R16_001"
    shutil.copytree(DATA / "R16_001", d)
    make(d)
    out = tmp_path / "out"
    code = cli.main(["identify", "--model", "greybox", "--data", str(d), "--out",
                     str(out / "m.json"), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not out.exists()
    # crash-replay reads the same files with the same verdict, and sends nothing
    code = replay_cli.main([str(d), "--dry-run"])
    _expect_one_line_error(code, capsys.readouterr().err, says)


@pytest.mark.parametrize("output, rel", [("CR", "Channel/R16_001.003"),
                                         ("CD", "Channel/R16_001.004")])
def test_an_output_constant_over_the_window_is_refused_not_fitted_to_nan(
        output, rel, tmp_path, good_model, capsys):
    """A dead output channel (all zeros: unplugged) among good tests: identify wrote a model
    whose every parameter stayed at its start, fit "nan %", exit 0; evaluate scored it "nan %"
    (a hostile user's campaign of 60 tests)."""
    d = tmp_path / "R16_001"
    shutil.copytree(DATA / "R16_001", d)
    p = d / rel
    lines = p.read_text(encoding="iso-8859-1").splitlines()
    lines = [v if ":" in v or not v else "0.000000E+00" for v in lines]
    p.write_text("\r\n".join(lines) + "\r\n", encoding="iso-8859-1", newline="")
    says = f"R16_001: {output} is constant over the scoring window 0.01..0.15 s"
    out = tmp_path / "out"
    code = cli.main(["identify", "--model", "greybox", "--data", str(d), "--out",
                     str(out / "m.json"), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    model = tmp_path / "model.json"
    model.write_text(json.dumps(good_model))
    code = cli.main(["evaluate", "--model", str(model), "--data", str(d), "--out",
                     str(out / "ev"), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not out.exists()


def _zip_of(folder: Path, dest: Path) -> Path:
    with zipfile.ZipFile(dest, "w", zipfile.ZIP_DEFLATED) as z:
        for p in sorted(folder.rglob("*")):
            if p.is_file():
                z.write(p, p.relative_to(folder.parent).as_posix())
    return dest


def _corrupt_member(zpath: Path) -> None:
    raw = bytearray(zpath.read_bytes())
    with zipfile.ZipFile(zpath) as z:
        info = z.getinfo("R16_001/Channel/R16_001.001")
    start = info.header_offset + 30 + len(info.filename) + 10
    for k in range(start, start + 200):
        raw[k] ^= 0x5A
    zpath.write_bytes(bytes(raw))


def _bomb(zpath: Path) -> None:
    with zipfile.ZipFile(zpath, "a", zipfile.ZIP_DEFLATED) as z, \
            z.open("R16_001/Channel/R16_001.009", "w", force_zip64=True) as f:
        block = b"0\r\n" * (1 << 20)
        for _ in range(24):  # 72 MiB of zeros, a few hundred kB packed
            f.write(block)


ZIP_CASES: dict[str, tuple[Callable[[Path], None], str]] = {
    "corrupt member": (_corrupt_member, "R16_001.001"),
    "zip bomb member": (_bomb, "MiB"),
    "not a zip": (lambda z: z.write_bytes(b"PK\x03\x04 this is no zip"), "not a readable zip"),
    "empty zip": (lambda z: zipfile.ZipFile(z, "w").close(), "no .mme"),
}


@pytest.mark.parametrize("case", sorted(ZIP_CASES))
def test_bad_zip(case, tmp_path, capsys):
    make, says = ZIP_CASES[case]
    z = _zip_of(DATA / "R16_001", tmp_path / "R16_001.zip")
    make(z)
    code = cli.main(["identify", "--model", "greybox", "--data", str(z), "--out",
                     str(tmp_path / "out" / "m.json"), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not (tmp_path / "out").exists()


def test_a_test_given_as_estimation_and_validation_is_refused(tmp_path, capsys):
    """A validation test must never be fitted on: one given in both roles is refused before
    any fit, naming the test and both roles."""
    out = tmp_path / "out"
    code = cli.main(["loop", "--estimate", str(DATA / "R16_001"), str(DATA / "R16_002"),
                     "--validate", str(DATA / "R16_002"), "--out", str(out), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err, "R16_002 is given twice")
    assert not out.exists()


# Options of the loop a hostile user tried (session 56): each one line and exit 2, before any
# fit or cluster, naming the option, and no output folder left behind.
LOOP_OPTION_CASES: dict[str, tuple[list[str], str]] = {
    "rate 0": (["--rate", "0"], "--rate"),
    "rate nan": (["--rate", "nan"], "--rate"),
    "window nan": (["--window", "nan", "0.15"], "--window"),
    "window reversed": (["--window", "0.1", "0.05"], "--window 0.1 0.05"),
    "window negative": (["--window", "-0.1", "0.15"], "--window"),
    "window 5 ms": (["--window", "0.01", "0.015"], "--window"),
    "margin nan": (["--margin", "nan"], "--margin"),
    "margin inf": (["--margin", "inf"], "--margin"),
    "margin negative": (["--margin", "-5"], "--margin"),
    "scheduler not a url": (["--scheduler", "not a url"], "--scheduler"),
    "scheduler http": (["--scheduler", "http://localhost:8786"], "unknown scheme 'http'"),
    "scheduler no port": (["--scheduler", "tcp://localhost"], "--scheduler"),
    "group matching nothing": (["--group", "X=NOPE_*"], "--group X=NOPE_*: matches none"),
    "workers past four a core": (["--workers", "100000"], "--workers 100000: at most"),
    "workers for a running cluster": (["--scheduler", "tcp://127.0.0.1:9"],
                                      "--workers sets the local cluster's size"),
    "pulse code is the CR's": (["--pulse-code", "11CHST0000H3ACXC"],
                               "11CHST0000H3ACXC is given as both the crash pulse and the CR"),
    "pulse code matching two": (["--pulse-code", "11CHST0000H3????"], "matches 2 channels"),
}


def _exit_code(argv: list[str]) -> int:
    """``observer-node ARGV``'s exit code, argparse's own refusals (SystemExit) included."""
    try:
        return cli.main(argv)
    except SystemExit as e:
        return int(e.code or 0)


@pytest.mark.parametrize("case", sorted(LOOP_OPTION_CASES))
def test_bad_loop_option(case, tmp_path, capsys):
    extra, says = LOOP_OPTION_CASES[case]
    out = tmp_path / "out"
    code = _exit_code(["loop", "--estimate", "campaign-a/R16_00[13]", "--validate",
                     "campaign-a/R16_002", "--out", str(out), "--quiet", "--workers", "1",
                     *extra])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not out.exists()


def test_an_output_folder_that_cannot_be_one_is_refused_before_any_work(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("not a folder")
    for out, says in ((afile, "is a file"), (afile / "x", "cannot be made: ")):
        for command in (["loop", "--estimate", "campaign-a/R16_00[13]", "--validate",
                         "campaign-a/R16_002", "--quiet"], ["evaluate", "--quiet"], ["bench"]):
            code = cli.main([*command, "--out", str(out)])
            _expect_one_line_error(code, capsys.readouterr().err, says)
    assert afile.read_text() == "not a folder"


# identify and simulate, as a hostile user tried them (2026-12-03): one line, exit 2, before
# any work, nothing left behind
OTHER_OPTION_CASES: dict[str, tuple[list[str], str]] = {
    "identify --nmax 0": (["identify", "--model", "arx", "--nmax", "0"], "--nmax"),
    "identify --order 0": (["identify", "--model", "n4sid", "--order", "0"], "--order"),
    "identify --order 5000": (["identify", "--model", "n4sid", "--order", "5000"],
                              "must be 64 or less"),
    "identify --nmax 100000": (["identify", "--model", "arx", "--nmax", "100000"],
                               "must be 20 or less"),
    # a model run and evaluate would refuse (more states than a model file holds)
    "identify --nmax 16": (["identify", "--model", "arx", "--nmax", "16"], "not written to"),
    "identify --m1 nan": (["identify", "--model", "greybox", "--m1", "nan"], "--m1"),
    "identify --out a folder": (["identify", "--model", "arx", "--out", "{tmp}"],
                                "is a folder; give a file name"),
    "identify --out under a file": (["identify", "--model", "arx", "--out",
                                     "{tmp}/afile/m.json"], "cannot be made: "),
    "simulate --count 0": (["simulate", "--count", "0"], "--count"),
    "simulate --seed -1": (["simulate", "--seed", "-1"], "--seed"),
    "simulate --effect nan": (["simulate", "--effect", "chest_stiffening=nan"], "SCALE"),
    "simulate --effect -1": (["simulate", "--effect", "chest_stiffening=-1"], "SCALE"),
    "simulate --effect 1e9": (["simulate", "--effect", "input_delay=1e9"], "10 or less"),
    "simulate --effect empty": (["simulate", "--effect", "chest_stiffening="], "SCALE"),
    "simulate --count 1e8": (["simulate", "--count", "100000000"], "1000 or less"),
    "simulate --effect twice": (["simulate", "--effect", "chest_stiffening",
                                 "--effect", "chest_stiffening=2"], "given twice"),
    "simulate --zip --csv": (["simulate", "--zip", "--csv"], "not allowed with"),
    "simulate --out a file": (["simulate", "--out", "{tmp}/afile"], "is a file"),
}


@pytest.mark.parametrize("case", sorted(OTHER_OPTION_CASES))
def test_bad_identify_and_simulate_options(case, tmp_path, capsys):
    argv, says = OTHER_OPTION_CASES[case]
    (tmp_path / "afile").write_text("not a folder")
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    if "--out" not in argv:
        argv += ["--out", str(tmp_path / ("m.json" if argv[0] == "identify" else "sim"))]
    if argv[0] == "identify":
        argv += ["--data", "campaign-a/R16_001", "--quiet"]
    _expect_one_line_error(_exit_code(argv), capsys.readouterr().err, says)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


def test_simulate_never_writes_over_a_test(tmp_path, capsys):
    """--out may be a folder of real crash tests: simulate refuses, naming what is there."""
    assert _exit_code(["simulate", "--out", str(tmp_path), "--count", "1", "--csv"]) == 0
    before = (tmp_path / "R16_001.csv").read_bytes()
    capsys.readouterr()
    code = _exit_code(["simulate", "--out", str(tmp_path), "--count", "1", "--seed", "2",
                       "--csv"])
    _expect_one_line_error(code, capsys.readouterr().err, "already holds R16_001.csv")
    assert (tmp_path / "R16_001.csv").read_bytes() == before


def test_a_model_file_that_cannot_be_written_leaves_nothing(tmp_path, good_model,
                                                            monkeypatch):
    """A full disk or a folder in the way: one line naming the file, and no half-written
    model (written beside, then renamed): the model that was there stays whole."""
    from observer_node.model.modelfile import ModelFile, ModelFileError

    mf = ModelFile.from_dict(good_model)
    (tmp_path / "m.json").mkdir()
    with pytest.raises(ModelFileError, match="is a folder"):
        mf.save(tmp_path / "m.json")
    mf.save(tmp_path / "ok.json")
    whole = (tmp_path / "ok.json").read_bytes()

    def disk_full(self: Path, text: str, **kw) -> int:
        with open(self, "w", **kw) as f:  # the real write, half of it
            f.write(text[: len(text) // 2])
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Path, "write_text", disk_full)
    with pytest.raises(ModelFileError, match=r"ok\.json: cannot write the model file: No space"):
        mf.save(tmp_path / "ok.json")
    monkeypatch.undo()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.json", "ok.json"]
    assert (tmp_path / "ok.json").read_bytes() == whole
    assert ModelFile.load(tmp_path / "ok.json").kind == mf.kind


def test_an_output_folder_the_system_refuses_late_is_one_line(good_model, tmp_path, capsys):
    """/proc passes every check a path can be given beforehand (as root) and refuses the
    folder only when it is made: one line naming it (not the hidden folder the results are
    written into first), exit 2."""
    model = tmp_path / "model.json"
    model.write_text(json.dumps(good_model))
    code = _exit_code(["evaluate", "--model", str(model), "--data", "campaign-a/R16_002",
                       "--out", "/proc/chest-observer-x"])
    _expect_one_line_error(code, capsys.readouterr().err, "/proc/chest-observer-x")


def test_one_estimation_test_is_refused_saying_what_the_loop_needs(tmp_path, capsys):
    out = tmp_path / "out"
    code = cli.main(["loop", "--estimate", str(DATA / "R16_001"), "--validate",
                     str(DATA / "R16_002"), "--out", str(out), "--quiet", "--workers", "1"])
    _expect_one_line_error(code, capsys.readouterr().err,
                           "too few tests: 1 estimation and 1 validation test(s)")
    assert not out.exists()


def test_an_mme_file_reads_its_own_test_and_a_folder_of_two_is_refused(tmp_path, capsys):
    """Two tests' files in one folder: the .mme named on the command line is read, with its
    own channels (the folder's first .mme was read instead, in silence: a hostile user's
    finding, 2026-12-03); the folder itself is refused, naming both."""
    from observer_node.data import load_tests

    both = tmp_path / "both"
    shutil.copytree(DATA / "R16_002", both)
    shutil.copytree(DATA / "R16_001", both, dirs_exist_ok=True)
    one = load_tests([both / "R16_002.mme"])[0]
    alone = load_tests([DATA / "R16_002"])[0]
    assert one.name == "R16_002"
    np.testing.assert_array_equal(one.cd_mm, alone.cd_mm)
    code = _exit_code(["identify", "--model", "arx", "--data", str(both), "--out",
                       str(tmp_path / "m.json"), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err,
                           "holds 2 .mme files (R16_001.mme, R16_002.mme)")


def test_one_crash_under_two_names_is_refused(tmp_path, capsys):
    """A copied test renamed (another name, the same samples) would count one crash twice."""
    copy = tmp_path / "R16_009"
    shutil.copytree(DATA / "R16_001", copy)
    mme = copy / "R16_001.mme"
    mme.write_bytes(mme.read_bytes().replace(b"ref. number :R16_001", b"ref. number :R16_009"))
    out = tmp_path / "out"
    code = cli.main(["identify", "--model", "greybox", "--data", str(DATA / "R16_001"),
                     str(copy), "--out", str(out / "m.json"), "--quiet"])
    err = capsys.readouterr().err
    _expect_one_line_error(code, err, "holds the same samples as R16_001")
    assert str(copy) in err
    assert not out.exists()


# ---------------------------------------------------------------------------- recordings
def _mcap_without_our_metadata(p: Path) -> None:
    from mcap.writer import Writer

    buf = io.BytesIO()
    w = Writer(buf)
    w.start()
    w.finish()
    p.write_bytes(buf.getvalue())


REC_CASES: dict[str, tuple[Callable[[Path], object], str]] = {
    "empty file": (lambda p: p.write_bytes(b""), "empty file"),
    "random bytes": (lambda p: p.write_bytes(bytes(range(256)) * 40), "not an MCAP"),
    "a JSON file": (lambda p: p.write_text('{"ticks": []}'), "not an MCAP"),
    "someone else's MCAP": (_mcap_without_our_metadata, "not a chest-observer recording"),
    "magic only": (lambda p: p.write_bytes(b"\x89MCAP0\r\n"), "ends or breaks before anything"),
    # 20 bytes of a real recording: it said "not a chest-observer recording"
    "magic and a cut header": (lambda p: p.write_bytes(b"\x89MCAP0\r\n\x01" + bytes(11)),
                               "ends or breaks before anything was recorded"),
}


@pytest.mark.parametrize("case", sorted(REC_CASES))
def test_bad_recording(case, tmp_path, capsys):
    make, says = REC_CASES[case]
    p = tmp_path / "run.mcap"
    make(p)
    out = tmp_path / "analysis"
    code = cli.main(["analyze", str(p), "--out", str(out)])
    _expect_one_line_error(code, capsys.readouterr().err, says)
    assert not out.exists()


def test_printed_example_config_is_a_valid_config(tmp_path, capsys):
    from observer_node.daemon.config import NodeConfig

    assert cli.main(["run", "--print-config"]) == 0
    p = tmp_path / "observer.toml"
    p.write_text(capsys.readouterr().out)
    assert NodeConfig.from_toml(p) == NodeConfig()


def test_slow_replay_config_is_accepted(tmp_path):
    """The vcan tests replay at 1/20 speed under emulation with timeouts to match."""
    from observer_node.daemon.config import NodeConfig

    p = tmp_path / "observer.toml"
    p.write_text("[observer]\naccel_timeout_s = 2.0\nbrs_timeout_s = 5.0\nidle_after_s = 10.0\n"
                 "cpu_latency_us = -1\n")
    cfg = NodeConfig.from_toml(p)
    assert (cfg.accel_timeout_s, cfg.brs_timeout_s, cfg.idle_after_s) == (2.0, 5.0, 10.0)


@pytest.mark.parametrize(("values", "per_rev", "refused"), [
    (np.round(0.4 + 3.75 * np.arange(40)), 96, True),  # degrees from a zero off a step
    (np.round(-5.625 * np.arange(40)), 64, True),
    (-np.arange(40.0), 96, False),  # counts pass through every whole number
    ([0, 0, -3, -3], 128, False),  # a few levels say too little
    ([0, 3, 6, 8], 128, False),
    ([100, 104, 100], 96, False),
])
def test_a_brs_without_a_unit_is_read_as_counts_unless_it_moves_in_degree_steps(
        values, per_rev, refused) -> None:
    def read() -> np.ndarray:
        return brs_to_counts(np.asarray(values, float), "", per_rev, "T.002:7 Unit", "T.002",
                             "in the .mme")
    if refused:
        with pytest.raises(CrashDataError, match=r"T\.002:7 Unit: BRS has no unit and moves"):
            read()
    else:
        assert np.array_equal(read(), np.asarray(values, float))


@pytest.mark.parametrize(("values", "per_rev", "refused"), [
    (-np.arange(40.0), 96, True),  # raw counts under a degree header
    (-np.arange(40.0), 72, True),  # (5 degrees a count: whole steps)
    (-3.75 * np.arange(40), 96, False),  # degrees, some of them whole numbers
    (-15.0 * np.arange(40), 48, False),  # degrees, every one a whole number
    (np.round(0.4 - 3.75 * np.arange(40)), 96, False),  # rounded to whole degrees by an export
    (-0.37 * np.arange(40), 96, False),  # an analogue angle, not a counter's
    ([0, -1, -2, -3, -2], 96, False),  # a few levels say too little
    (-np.arange(40.0), 360, False),  # one degree a count: counts and degrees agree
    (np.round(22.5 - 7.5 * np.arange(40)), 48, False),  # x.5 rounded half to even
])
def test_a_brs_in_degrees_that_no_count_of_its_resolution_lands_near_is_refused(
        values, per_rev, refused) -> None:
    def read() -> np.ndarray:
        return brs_to_counts(np.asarray(values, float), "deg", per_rev, "T.002:7 Unit",
                             "T.002", "in the .mme")
    if refused:
        with pytest.raises(CrashDataError, match=r"T\.002:7 Unit: BRS in deg reads whole"):
            read()
    else:
        assert np.array_equal(read(), np.round(np.asarray(values, float) * per_rev / 360.0))


@pytest.mark.parametrize("unit", ["rev", "rad"])
def test_a_brs_of_whole_turns_or_radians_is_refused_as_counts(unit) -> None:
    with pytest.raises(CrashDataError, match=rf"BRS in {unit} reads whole numbers"):
        brs_to_counts(-np.arange(40.0), unit, 96, "T.002:7 Unit", "T.002", "in the .mme")
    turns = -np.arange(40.0) / 96 * (1.0 if unit == "rev" else 2 * np.pi)
    assert np.array_equal(brs_to_counts(turns, unit, 96, "T.002:7 Unit", "T.002", "in the .mme"),
                          -np.arange(40.0))


def test_skip_bad_tests_leaves_each_bad_one_out_named_and_goes_on(tmp_path, good_model,
                                                                  capsys):
    """A campaign with a dead channel and a file cut short among good tests: by default one
    stops the run (exit 2, one line); with --skip-bad-tests each is named with its cause on
    stderr and in the output's JSON, counted, and the rest are fitted and scored."""
    camp = tmp_path / "campaign"
    camp.mkdir()
    for name in ("R16_003", "R16_005", "R16_007"):
        shutil.copy(bundled_campaign() / f"{name}.zip", camp / f"{name}.zip")
    dead = camp / "R16_001"
    shutil.copytree(DATA / "R16_001", dead)
    p = dead / "Channel/R16_001.004"
    lines = p.read_text(encoding="iso-8859-1").splitlines()
    p.write_text("\r\n".join(v if ":" in v or not v else "0.000000E+00" for v in lines)
                 + "\r\n", encoding="iso-8859-1", newline="")
    cut = camp / "R16_009.zip"
    cut.write_bytes((bundled_campaign() / "R16_009.zip").read_bytes()[:3000])
    out = tmp_path / "out"
    code = cli.main(["identify", "--model", "greybox", "--data", str(camp), "--out",
                     str(out / "m.json"), "--quiet"])
    _expect_one_line_error(code, capsys.readouterr().err, "R16_009.zip: not a readable zip")
    assert not out.exists()

    code = cli.main(["identify", "--model", "greybox", "--data", str(camp), "--out",
                     str(out / "m.json"), "--quiet", "--skip-bad-tests"])
    cap = capsys.readouterr()
    assert code == 0 and "Traceback" not in cap.err
    said = [line for line in cap.err.splitlines() if line.startswith("left out")]
    assert len(said) == 3 and "R16_001: CD is constant" in said[0] and "R16_009.zip" in said[1]
    assert said[2].startswith("left out 2 of 5 test(s)")
    model = json.loads((out / "m.json").read_text())
    assert sorted(model["fitted_on"]["tests"]) == ["R16_003", "R16_005", "R16_007"]
    assert sorted(Path(k).name for k in model["fitted_on"]["left_out"]) == ["R16_001",
                                                                             "R16_009.zip"]
    assert "(2 left out)" in cap.out

    good = tmp_path / "good.json"
    good.write_text(json.dumps(good_model))
    code = cli.main(["evaluate", "--model", str(good), "--data", str(camp), "--out",
                     str(out / "ev"), "--quiet", "--skip-bad-tests"])
    cap = capsys.readouterr()
    assert code == 0 and "left out 2 of 5 test(s)" in cap.err
    fits = json.loads((out / "ev" / "fits.json").read_text())
    assert sorted(fits["tests"]) == ["R16_003", "R16_005", "R16_007"]
    assert len(fits["left_out"]) == 2 and "2 left out" in cap.out

    every = tmp_path / "all-bad"
    every.mkdir()
    shutil.copy(cut, every / cut.name)
    code = cli.main(["identify", "--model", "greybox", "--data", str(every), "--out",
                     str(out / "m2.json"), "--quiet", "--skip-bad-tests"])
    err = capsys.readouterr().err
    assert code == 2 and "every one of the 1 test(s) is bad" in err and "Traceback" not in err


def test_the_loop_skip_bad_tests_leaves_an_unreadable_file_out_and_reports_it(tmp_path,
                                                                              capsys):
    """One estimation file cut short among a campaign's: the loop stops on it by default (one
    line, exit 2); with --skip-bad-tests it is named on stderr and under not_read in
    report.json and report.md, and the loop runs on the rest."""
    est = tmp_path / "est"
    est.mkdir()
    for name in ("R16_001", "R16_003", "R16_005", "R16_007"):
        shutil.copy(bundled_campaign() / f"{name}.zip", est / f"{name}.zip")
    cut = est / "R16_009.zip"
    cut.write_bytes((bundled_campaign() / "R16_009.zip").read_bytes()[:3000])
    out = tmp_path / "out"
    argv = ["loop", "--estimate", str(est), "--validate", "campaign-a/R16_00[24]", "--out",
            str(out), "--quiet", "--workers", "1"]
    _expect_one_line_error(_exit_code(argv), capsys.readouterr().err, "R16_009.zip: not a")
    assert not out.exists()
    assert _exit_code([*argv, "--skip-bad-tests"]) == 0
    cap = capsys.readouterr()
    assert "left out 1 of 5 test(s)" in cap.err and "Traceback" not in cap.err
    report = json.loads((out / "report.json").read_text())
    assert [w["test"] for w in report["not_read"]] == [str(cut)]
    assert "not a readable zip" in report["not_read"][0]["reason"]
    assert report["estimation"] == ["R16_001", "R16_003", "R16_005", "R16_007"]
    assert "## Test files not read (left out by --skip-bad-tests)" in (
        out / "report.md").read_text()
