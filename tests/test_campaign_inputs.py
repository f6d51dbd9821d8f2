"""A campaign as analysts keep one, attacked by a hostile user (session 61): folders of
folders with litter in them, tests that cannot be read or fitted among good ones, names and
setups a test's metadata gives, and options that leave a model's rate or window behind. Each
case asserts what must hold: one line and exit 2, or the bad test left out and named, and
nothing written outside --out."""

from __future__ import annotations

import dataclasses
import json
import os
import shutil
from pathlib import Path

import numpy as np
import pytest

from observer_node import cli
from observer_node.data import CrashDataError, bundled_campaign, find_tests, load_test, load_tests
from observer_node.data.csvio import write_csv
from observer_node.data.isomme import setup_of
from observer_node.evaluation import evaluate_model, file_stem, file_stems, identify
from observer_node.ident.dataset import make_dataset
from observer_node.model.modelfile import ModelFile

from .test_setups import _scoped_model


def _zip(name: str) -> Path:
    return bundled_campaign() / f"{name}.zip"


def _one_line(code: int, err: str, says: str) -> None:
    assert code == 2, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert says in err, err


def test_n4sid_on_too_short_a_window_or_too_low_a_rate_is_one_line(tmp_path, capsys):
    """N4SID's 24 block rows need 143 ticks: a window ending at 0.1 s or a 500 Hz rate gave a
    ValueError traceback from the subspace step."""
    for extra in (["--rate", "500"], ["--window", "0.01", "0.1"]):
        code = cli.main(["identify", "--model", "n4sid", "--data", "campaign-a/R16_001",
                         "--out", str(tmp_path / "n.json"), "--quiet", *extra])
        _one_line(code, capsys.readouterr().err, "N4SID (24 block rows) needs at least 143")
    assert not (tmp_path / "n.json").exists()


def test_a_name_with_a_path_in_it_cannot_write_outside_out() -> None:
    """A test's name comes from its .mme ('Laboratory test ref. number'); its prefix was the
    setup, and the setup named the thesis comparison's files: '../../tmp/x/EVIL_001' wrote
    models outside --out."""
    assert setup_of("../../../tmp/pwn/EVIL_001", {"Type of the test": "SLED"}) == "SLED"
    assert setup_of("R16_001", {}) == "R16" and setup_of("2019_001", {}) == "UNKNOWN"
    assert file_stem("../../X/EVIL") == "x-evil" and file_stem("///") == "setup"


def test_a_campaign_folder_with_litter_reads_its_tests_and_names_the_rest(tmp_path, capsys):
    """A template .mme beside a year's zips swallowed the folder as one test; a Mac's
    __MACOSX folder was read as a test; a pipe named like a test would block the read for
    ever and a broken link stopped the campaign."""
    camp = tmp_path / "campaign"
    year = camp / "2019"
    year.mkdir(parents=True)
    for name in ("R16_001", "R16_003"):
        shutil.copy(_zip(name), year / f"{name}.zip")
    (year / "template.mme").write_text("Data format edition number  :1.6\n")
    mac = camp / "__MACOSX" / "R16_001"
    mac.mkdir(parents=True)
    (mac / "._R16_001.mme").write_bytes(b"\x00\x05\x16\x07")
    os.mkfifo(camp / "notes")  # not a test's name: not a test
    os.mkfifo(camp / "R16_009.csv")
    (camp / "R16_005.zip").symlink_to(tmp_path / "gone.zip")
    found = sorted(p.relative_to(camp).as_posix() for p in find_tests([camp]))
    assert found == ["2019/R16_001.zip", "2019/R16_003.zip", "2019/template.mme",
                     "R16_005.zip", "R16_009.csv"]
    with pytest.raises(CrashDataError, match=r"R16_009\.csv: not a file"):
        load_test(camp / "R16_009.csv")
    with pytest.raises(CrashDataError, match=r"R16_005\.zip: a broken link"):
        load_test(camp / "R16_005.zip")
    out = tmp_path / "m.json"
    assert cli.main(["identify", "--model", "greybox", "--data", str(camp), "--out", str(out),
                     "--quiet", "--skip-bad-tests"]) == 0
    err = capsys.readouterr().err
    assert "left out 3 of 5 test(s)" in err and "Traceback" not in err
    model = json.loads(out.read_text())
    assert model["fitted_on"]["tests"] == ["R16_001", "R16_003"]
    assert sorted(Path(p).name for p in model["fitted_on"]["left_out"]) == [
        "R16_005.zip", "R16_009.csv", "template.mme"]
    # given as --data itself, a pipe is one line, not a hang
    code = cli.main(["identify", "--model", "greybox", "--data", str(camp / "notes"), "--out",
                     str(out), "--quiet"])
    _one_line(code, capsys.readouterr().err, "notes: not a crash test")


def test_a_dead_input_channel_is_refused_like_a_dead_output() -> None:
    """An all-zero pulse or BRS was fitted: the model kept its start values (k1 = 200000)
    and scored 4.6 %; a dead CR or CD was already refused."""
    t = load_test(_zip("R16_001"))
    for field, label in (("pulse_g", "crash pulse"), ("brs", "BRS")):
        dead = dataclasses.replace(t, **{field: np.zeros_like(getattr(t, field))})
        with pytest.raises(CrashDataError, match=f"{label} is constant over the scoring"):
            make_dataset([dead])


def test_evaluate_model_skips_by_the_model_s_own_window(tmp_path, capsys):
    """--skip-bad-tests checked each test at --rate and the thesis's window, the model was
    scored at its own: a test too short for the model's window stopped the whole run."""
    tests = [load_test(_zip(n)) for n in ("R16_001", "R16_003")]
    mf = identify("greybox", make_dataset(tests, 1000.0, (0.01, 0.18)))
    model = tmp_path / "m.json"
    mf.save(model)
    data = tmp_path / "data"
    data.mkdir()
    for n in ("R16_002", "R16_004"):
        shutil.copy(_zip(n), data / f"{n}.zip")
    t = load_test(_zip("R16_006"))
    keep = t.index_of(0.17)
    short = dataclasses.replace(t, pulse_g=t.pulse_g[:keep], brs=t.brs[:keep],
                                cr_g=t.cr_g[:keep] if t.cr_g is not None else None,
                                cd_mm=t.cd_mm[:keep] if t.cd_mm is not None else None)
    write_csv(short, data / "R16_006.csv")
    out = tmp_path / "ev"
    assert cli.main(["evaluate", "--model", str(model), "--data", str(data), "--out",
                     str(out), "--quiet", "--skip-bad-tests"]) == 0
    cap = capsys.readouterr()
    assert "left out 1 of 3 test(s)" in cap.err and "needs 0.000..0.180 s" in cap.err
    fits = json.loads((out / "fits.json").read_text())
    assert sorted(fits["tests"]) == ["R16_002", "R16_004"]


def test_the_thesis_comparison_says_a_setup_it_cannot_compare(tmp_path, capsys):
    """A setup left one test (its other left out as bad) vanished from the tables in silence,
    and with none left the comparison exited 0 with empty tables."""
    out = tmp_path / "ev"
    code = cli.main(["evaluate", "--data", "campaign-a/R16_00[12]", "campaign-a/SLED_002",
                     "--out", str(out), "--quiet"])
    cap = capsys.readouterr()
    assert code == 0, cap.err
    assert "setup SLED (SLED_002)" in cap.err and "not compared" in cap.out
    result = json.loads((out / "evaluation.json").read_text())
    assert result["not_compared"] == {"SLED": ["SLED_002"]} and list(result["setups"]) == ["R16"]
    code = cli.main(["evaluate", "--data", "campaign-a/SLED_002", "campaign-a/R16_001",
                     "--out", str(tmp_path / "ev2"), "--quiet"])
    err = capsys.readouterr().err
    assert code == 2 and "no setup has tests to estimate on" in err and "Traceback" not in err
    assert not (tmp_path / "ev2").exists()


def test_evaluate_model_tells_setups_from_metadata_and_says_unknown_ones(tmp_path, capsys):
    """The per-setup fits grouped by the name's prefix: tests renamed 2019-001.. put an R16
    rig and a SLED with interior in one setup. And a model with effects scoped to SLED and
    FULL scored tests whose metadata names other setups with no word: its effects acted on
    none of them."""
    renamed = [dataclasses.replace(load_test(_zip(n)), name=f"2019-00{i}")
               for i, n in enumerate(("R16_002", "SLED_002", "R16_004", "SLED_004"), 1)]
    mf = ModelFile.from_dict(_scoped_model().to_dict())
    fits = evaluate_model(mf, renamed, tmp_path / "ev", ratings=False)
    setups = {t.name: t.setup for t in renamed}
    assert setups["2019-001"] == setups["2019-003"] != setups["2019-002"] == setups["2019-004"]
    written = json.loads((tmp_path / "ev" / "fits.json").read_text())
    assert {k: v["tests"] for k, v in written["setups"].items()} == {
        setups["2019-001"]: 2, setups["2019-002"]: 2}
    assert written["setups"][setups["2019-002"]]["test_names"] == ["2019-002", "2019-004"]
    assert fits.fit.total == pytest.approx(written["fit"]["total"])
    err = capsys.readouterr().err
    assert "is not one the model knows (FULL, R16, SLED)" in err
    assert written["setups_unknown_to_the_model"] == sorted(set(setups.values()))


def test_a_brs_in_counts_without_its_resolution_says_how_to_give_it() -> None:
    """A .mme cut before its Comments line leaves a BRS in counts without counts/rev: the
    message said only that it was unknown."""
    t = dataclasses.replace(load_test(_zip("R16_001")), counts_per_rev=None)
    with pytest.raises(CrashDataError, match=r"counts/rev of the BRS is unknown .*"
                                             r"--counts-per-rev or in the \.mme Comments"):
        make_dataset([t])


def test_a_file_name_cannot_forge_a_line_on_stderr(tmp_path, capsys):
    """A newline in a file's name was printed as is: a bad test could write a line of its own,
    'left out: ...' followed by whatever the name said."""
    from observer_node.errors import one_line

    assert one_line("a\nb\r\tc\x1b[2Jd\u2028e") == "a\\nb\\r\\tc\\x1b[2Jd\\u2028e"
    camp = tmp_path / "campaign"
    camp.mkdir()
    for name in ("R16_001", "R16_003"):
        shutil.copy(_zip(name), camp / f"{name}.zip")
    (camp / "R16_005\nidentify: all 3 tests good.csv").write_text("not a test\n")
    assert cli.main(["identify", "--model", "greybox", "--data", str(camp), "--out",
                     str(tmp_path / "m.json"), "--quiet", "--skip-bad-tests"]) == 0
    lines = capsys.readouterr().err.splitlines()
    assert not any(line.startswith("identify: all") for line in lines), lines
    assert any(line.startswith("left out: ") and "R16_005\\nidentify" in line for line in lines)


def test_a_long_test_or_setup_name_widens_its_column(tmp_path, capsys):
    """A setup or test name longer than twelve characters pushed its row's figures right."""
    tests = [load_test(_zip(n)) for n in ("R16_001", "R16_003")]
    model = tmp_path / "m.json"
    identify("greybox", make_dataset(tests, 1000.0, (0.01, 0.18))).save(model)
    data = tmp_path / "data"
    data.mkdir()
    long_name = "CAMPAIGN2019_FRONTAL_R16_002"
    write_csv(dataclasses.replace(load_test(_zip("R16_002")), name=long_name,
                                  setup="SLED_WITH_INTERIOR_2019"), data / "a.csv")
    write_csv(load_test(_zip("R16_004")), data / "b.csv")
    assert cli.main(["evaluate", "--model", str(model), "--data", str(data), "--out",
                     str(tmp_path / "ev"), "--quiet"]) == 0
    out = capsys.readouterr().out
    fits, criteria = out.split("chest injury criteria")
    rows = [line for line in fits.splitlines() if " CR " in line]
    assert any(long_name in r for r in rows) and any("SLED_WITH_INTERIOR_2019" in r for r in rows)
    assert len({r.index(" CR ") for r in rows}) == 1, out  # the figures in one column
    table = criteria.split("\n\n")[0].splitlines()[1:]  # head, sub-head, a row per test
    assert len(table) == 4 and len({len(r.rstrip()) for r in table[1:]}) == 1, out


def test_setups_whose_file_names_would_clash_get_files_of_their_own() -> None:
    """'SLED' and 'sled', 'Rig A' and 'rig-a', two names in other scripts made the same file
    name: the second setup's models and plots overwrote the first's, evaluation.json pointing
    both at one file. A 300-letter setup name failed to write its plots after the whole fit."""
    names = ["Rig A", "rig-a", "\u5317\u4eac", "\u6771\u4eac", "setup-2", "L" * 300]
    stems = file_stems(names)
    assert len(set(stems.values())) == len(names)
    assert stems["Rig A"] == "rig-a" and stems["rig-a"] == "rig-a-2"
    assert all(len(s) <= 64 for s in stems.values())


def _csv_with_head(tmp_path: Path, head: list[str], extra_row: str = "") -> Path:
    src = tmp_path / "src.csv"
    write_csv(load_test(_zip("R16_001")), src)
    lines = src.read_text().splitlines()
    body = [line for line in lines if not line.startswith("#")]
    path = tmp_path / "R16_009.csv"
    rows = [*head, body[0], body[1], *([extra_row] if extra_row else []), *body[2:]]
    path.write_text("\n".join(rows) + "\n")
    return path


@pytest.mark.parametrize(("head", "row", "says"), [
    (["# setup: SLED", "# setup: R16"], "", ":2: a second 'setup' line (the first is line 1)"),
    (["# name: A", "# setup:   "], "", ":2: the 'setup' line gives no setup"),
    (["# setup: R16"], "# setup: SLED", ":4: a comment line among the data"),
])
def test_a_csv_header_that_says_two_things_or_nothing_is_one_line(tmp_path, capsys, head, row,
                                                                   says):
    """Two setup lines: the last won, unsaid. An empty one: identify fitted the whole model,
    then refused to write it ("fitted_on.setups[0] should be non-empty ... fewer orders").
    A setup line among the data rows: '1 values, header has 5 columns'."""
    path = _csv_with_head(tmp_path, head, row)
    with pytest.raises(CrashDataError, match="R16_009.csv" + says.replace("(", r"\(")
                       .replace(")", r"\)")):
        load_test(path)
    code = cli.main(["identify", "--model", "greybox", "--data", str(path), "--out",
                     str(tmp_path / "m.json"), "--quiet"])
    _one_line(code, capsys.readouterr().err, says)
    assert not (tmp_path / "m.json").exists()


def test_identify_tells_setups_as_evaluate_and_the_loop_do(tmp_path, capsys):
    """identify wrote fitted_on.setups from each test's own setup (its name's prefix), evaluate
    from the metadata: the same tests were R16 to one and ECE-R16 beside R16 to the other."""
    data = tmp_path / "data"
    data.mkdir()
    for name in ("SLED_001", "SLED_003"):
        shutil.copy(_zip(name), data / f"{name}.zip")
    t = load_test(_zip("SLED_005"))
    write_csv(dataclasses.replace(t, name="X_105", setup="sled"), data / "x.csv")
    model = tmp_path / "m.json"
    assert cli.main(["identify", "--model", "greybox", "--data", str(data), "--out",
                     str(model), "--quiet"]) == 0
    assert ModelFile.load(model).fitted_on["setups"] == ["SLED"]


def test_a_name_s_control_characters_reach_no_table_or_report(tmp_path, capsys):
    """A test named with an ESC sequence and a tab (in its file's name or its name line) was
    printed raw in evaluate's table: the ESC cleared the terminal, the tab broke the columns.
    The name is kept as its escape from reading on, in every table, file and plot."""
    tests = [load_test(_zip(n)) for n in ("R16_001", "R16_003")]
    model = tmp_path / "m.json"
    identify("greybox", make_dataset(tests, 1000.0, (0.01, 0.18))).save(model)
    data = tmp_path / "data"
    data.mkdir()
    write_csv(dataclasses.replace(load_test(_zip("R16_002")), name="R16_002\x1b[2J\tX"),
              data / "a.csv")
    shutil.copy(_zip("R16_004"), data / "R16_004\x1b[31m.zip")
    read = sorted(t.name for t in load_tests([data]))
    assert read == ["R16_002\\x1b[2J\\tX", "R16_004"], read  # a zip's name is its .mme's
    assert cli.main(["evaluate", "--model", str(model), "--data", str(data), "--out",
                     str(tmp_path / "ev"), "--quiet"]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "\t" not in out
    assert "R16_002\\x1b[2J\\tX" in out
    written = (tmp_path / "ev" / "fits.json").read_text()
    assert "R16_002\\\\x1b[2J\\\\tX" in written  # the escape, itself escaped by JSON


def test_a_grey_box_fit_whose_trial_step_runs_away_warns_nothing(tmp_path) -> None:
    """identify on four simulated SLED CSVs (seed 2) printed numpy's overflow warnings: a
    trial step made the chest unstable, which the fit refuses anyway."""
    import warnings

    from observer_node.ident.greybox import fit_greybox

    assert cli.main(["simulate", "--out", str(tmp_path), "--setup", "SLED", "--count", "4",
                     "--seed", "2", "--csv"]) == 0
    data = make_dataset(load_tests([tmp_path]), 1000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        fit = fit_greybox(data)
    assert fit.fits.fit.total > 90.0
