"""Model files, the stepping observer, CSV crash tests and the command line."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from observer_node.cli import main
from observer_node.data import CrashDataError, bundled_campaign, read_csv, read_isomme, write_csv
from observer_node.evaluation import identify, split_halves
from observer_node.ident.dataset import make_dataset
from observer_node.model import ModelFile, ModelFileError

from .conftest import DATA


@pytest.fixture(scope="module")
def r16_data():
    tests = [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3, 5)]
    return make_dataset(tests, 1000.0)


@pytest.mark.parametrize("kind", ["greybox", "arx", "n4sid"])
def test_model_file_roundtrip_and_step_equals_simulate(tmp_path: Path, r16_data, kind: str):
    mf = identify(kind, r16_data, nmax=4, order=5)
    path = mf.save(tmp_path / "m.json")
    back = ModelFile.load(path)
    assert back.kind == kind and back.tick_rate_hz == 1000.0
    np.testing.assert_array_equal(back.A, mf.A)
    obs = back.observer()
    offline = obs.simulate(r16_data.pulse_g[0], r16_data.brs_rad[0])
    online = np.array([obs.step(p, b).copy()
                       for p, b in zip(r16_data.pulse_g[0], r16_data.brs_rad[0], strict=False)])
    np.testing.assert_allclose(online, offline, rtol=1e-9, atol=1e-9)
    d = json.loads(path.read_text())
    assert d["inputs"][0]["unit"] == "g" and d["outputs"][1]["unit"] == "mm"
    assert d["fitted_on"]["tests"] == ["R16_001", "R16_003", "R16_005"]


def test_bad_model_files_are_named(tmp_path: Path):
    p = tmp_path / "m.json"
    p.write_text("{not json")
    with pytest.raises(ModelFileError, match=r"m\.json:1: not valid JSON"):
        ModelFile.load(p)
    p.write_text(json.dumps({"format": "chest-observer-model", "format_version": 1,
                             "kind": "greybox", "tick_rate_hz": 1000}))
    with pytest.raises(ModelFileError, match="missing key 'input_transform'"):
        ModelFile.load(p)


def test_csv_roundtrip_and_errors(tmp_path: Path):
    t = read_isomme(DATA / "R16_001")
    p = write_csv(t, tmp_path / "t.csv")
    back = read_csv(p)
    np.testing.assert_allclose(back.cd_mm, t.cd_mm, rtol=1e-8)
    assert back.fs_hz == pytest.approx(t.fs_hz) and back.counts_per_rev == 96
    lines = p.read_text().splitlines()
    lines[40] = lines[40].replace(",", ",x", 1)
    p.write_text("\n".join(lines))
    with pytest.raises(CrashDataError, match=r"t\.csv:41: non-numeric"):
        read_csv(p)
    # a column twice in the header: named as such, not as a row's width (session 56)
    header = next(i for i, line in enumerate(lines) if line.lower().startswith("time"))
    lines[header] += "," + lines[header].split(",")[1]
    p.write_text("\n".join(lines))
    with pytest.raises(CrashDataError, match=rf"t\.csv:{header + 1}: column '\w+' appears twice"):
        read_csv(p)


def test_split_halves_odd_estimates_even_validates(campaign):
    est, val = split_halves([t for t in campaign if t.setup == "R16"])
    assert [t.name for t in est][:2] == ["R16_001", "R16_003"]
    assert [t.name for t in val][:2] == ["R16_002", "R16_004"]


def test_cli_identify_then_evaluate(tmp_path: Path, capsys):
    camp = bundled_campaign()
    model = tmp_path / "gb.json"
    assert main(["identify", "--model", "greybox", "--data", str(camp / "R16_001.zip"),
                 str(camp / "R16_003.zip"), "--out", str(model), "--quiet"]) == 0
    out = tmp_path / "ev"
    assert main(["evaluate", "--model", str(model), "--data", str(DATA / "R16_002"),
                 "--out", str(out)]) == 0
    fits = json.loads((out / "fits.json").read_text())
    assert set(fits["fit"]) == {"cr", "cd", "total"}
    assert set(fits["tests"]) == {"R16_002"} and fits["fit"]["total"] > 50
    assert (out / "fit_cr.png").stat().st_size > 10_000
    assert "R16_002" in capsys.readouterr().out
    assert fits["setups"] == {"R16": {"tests": 1, "test_names": ["R16_002"], **fits["fit"]}}
    # two setups: each one's fit over its own tests, printed and in fits.json
    out2 = tmp_path / "ev2"
    assert main(["evaluate", "--model", str(model), "--data", str(camp / "R16_004.zip"),
                 str(camp / "R16_006.zip"), str(camp / "SLED_002.zip"), "--out", str(out2),
                 "--quiet"]) == 0
    fits2 = json.loads((out2 / "fits.json").read_text())
    r16 = fits2["setups"]["R16"]
    assert r16["tests"] == 2 and r16["cr"] == pytest.approx(
        (fits2["tests"]["R16_004"]["cr"] + fits2["tests"]["R16_006"]["cr"]) / 2)
    assert fits2["setups"]["SLED"]["tests"] == 1
    printed = capsys.readouterr().out
    assert "per setup:" in printed and "(2 tests)" in printed and "(1 test)" in printed


def test_cli_reports_bad_data_by_name(tmp_path: Path, capsys):
    (tmp_path / "x.csv").write_text("time[s],pulse[g]\n0,1\n")
    assert main(["identify", "--model", "arx", "--data", str(tmp_path / "x.csv"),
                 "--out", str(tmp_path / "m.json")]) == 2
    assert "x.csv" in capsys.readouterr().err


def test_cli_thesis_comparison_on_a_subset(tmp_path: Path, capsys):
    camp = bundled_campaign()
    data = [str(camp / f"{s}_00{i}.zip") for s in ("R16", "SLED") for i in range(1, 5)]
    assert main(["evaluate", "--data", *data, "--out", str(tmp_path), "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "thesis Table 4.1" in text and "thesis Table 4.2" in text
    result = json.loads((tmp_path / "evaluation.json").read_text())
    models = result["setups"]["R16"]["models"]
    assert set(models) == {"ARX Nmax=10", "ARX Nmax=6", "SS N=16", "SS N=7", "Grey-Box"}
    assert result["setups"]["R16"]["validation"] == ["R16_002", "R16_004"]
    for m in models.values():
        assert (tmp_path / m["model_file"]).exists()
        ModelFile.load(tmp_path / m["model_file"])
    assert (tmp_path / "plots" / "r16-n4sid-order-scan.png").exists()


def test_cli_simulate_writes_readable_tests(tmp_path: Path):
    assert main(["simulate", "--out", str(tmp_path), "--setup", "SLED", "--count", "2",
                 "--effect", "airbag_contact", "--zip"]) == 0
    t = read_isomme(tmp_path / "SLED_002.zip")
    assert t.setup == "SLED" and t.has_outputs and t.cd_mm.max() > 5


def test_simulate_help_names_every_effect_the_simulator_has(capsys):
    from observer_node.cli.simulate import SIM_EFFECTS
    from observer_node.simulator import EFFECTS

    assert set(SIM_EFFECTS) == set(EFFECTS)
    assert main(["simulate", "--out", "x", "--effect", "airbag"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "unknown effect 'airbag'" in err and "airbag_contact" in err
