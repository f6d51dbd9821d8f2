"""Setups from the tests' metadata, effects scoped to setups, fractional input delays: in the
model, the model file, the daemon's command line and the loop."""

from __future__ import annotations

import numpy as np
import pytest

from observer_node import cli
from observer_node.data import load_tests
from observer_node.data.crashtest import CrashDataError
from observer_node.data.setups import assign_setups, parse_groups, words
from observer_node.ident.dataset import make_dataset
from observer_node.loop.closed_loop import scope_options
from observer_node.model.chest import PARAM_NAMES, model_matrices
from observer_node.model.modelfile import ModelFile, ModelFileError
from observer_node.model.nonlinear import NonlinearGreyBox, ScopeError
from observer_node.simulator import ChestParams, PlantConfig, simulate_mixed

BASE = ChestParams().as_dict()
AIRBAG = {"kind": "airbag_contact", "parameters": {"kab": 5e4, "gap": 0.02, "cab": 600.0}}


def test_campaign_a_setups_come_from_its_metadata():
    tests = load_tests(["campaign-a"])
    setups = assign_setups(tests)
    assert [s.name for s in setups] == ["FULL", "R16", "SLED"]
    by = {s.name: s for s in setups}
    assert len(by["R16"].tests) == 12 and len(by["FULL"].tests) == 6
    assert "HARD SEAT" in by["R16"].how
    # the hard seat rules the airbag out on R16, nowhere else
    assert set(by["R16"].impossible) == {"airbag_contact"}
    assert not by["SLED"].impossible and not by["FULL"].impossible
    assert scope_options("airbag_contact", setups, ["R16", "SLED", "FULL"]) == [
        ["SLED"], ["FULL"], ["SLED", "FULL"]]
    assert None in scope_options("belt_unloading", setups, ["R16", "SLED", "FULL"])
    # unless the user says otherwise
    assert None in scope_options("airbag_contact", setups, ["R16", "SLED", "FULL"],
                                 anywhere=True)
    # R16 (a hard seat) with validation tests only: an airbag on both estimation setups is
    # named on them, not on every test, which would put it on R16's
    assert scope_options("airbag_contact", setups, ["SLED", "FULL"]) == [
        ["SLED"], ["FULL"], ["SLED", "FULL"]]
    assert scope_options("belt_unloading", setups, ["SLED", "FULL"]) == [
        None, ["SLED"], ["FULL"]]
    # no scope rests on rigs too thinly estimated to judge (FULL) alone
    assert scope_options("belt_unloading", setups, ["R16", "SLED", "FULL"],
                         judged=["R16", "SLED"]) == [
        None, ["R16"], ["SLED"], ["R16", "SLED"], ["R16", "FULL"], ["SLED", "FULL"]]


def test_a_title_punctuated_another_way_is_the_same_rig():
    # "3 POINT" for "3-POINT" on one test (a hostile user's typo): one rig, not two
    tests = load_tests(["campaign-a"])
    t = next(x for x in tests if x.name == "R16_002")
    t.meta["Title"] = t.meta["Title"].replace("3-POINT", "3  point")
    setups = assign_setups(tests)
    assert [s.name for s in setups] == ["FULL", "R16", "SLED"]
    assert t.setup == "R16" and "3-POINT" in next(s for s in setups if s.name == "R16").how
    t.meta["Title"] = t.meta["Title"].replace("HARD SEAT", "SOFT SEAT")  # words differ: apart
    assert len(assign_setups(tests)) == 4
    # what punctuation aside still tells apart: a sign, another script's words
    for a, b in (("SLED OBLIQUE +10 DEG", "SLED OBLIQUE -10 DEG"),
                 ("САНИ, ЖЁСТКОЕ СИДЕНЬЕ", "САНИ, ПОДУШКА БЕЗОПАСНОСТИ")):
        t.meta["Title"] = a
        next(x for x in tests if x.name == "R16_003").meta["Title"] = b
        assert len(assign_setups(tests)) == 5, (a, b)
    assert words("Test 5,5 ms; 3-POINT, FULL-56, 30°") == [
        "Test", "5.5", "ms", "3", "POINT", "FULL", "56", "30"]


def test_a_test_whose_metadata_says_another_rig_than_its_name_is_kept_and_said():
    """R16_005 with SLED's title (a copied .mme): the metadata decides, as the rule says,
    and the setup names the test for the report to ask about it (a hostile user's finding,
    session 56)."""
    tests = load_tests(["campaign-a"])
    sled = next(x for x in tests if x.name == "SLED_001").meta
    t = next(x for x in tests if x.name == "R16_005")
    t.meta.update({k: sled[k] for k in ("Type of the test", "Title", "Name of test object 1")})
    by = {s.name: s for s in assign_setups(tests)}
    sled_rig = next(x for x in tests if x.name == "SLED_001").setup  # its tests' prefixes differ
    assert t.setup == sled_rig and "R16_005" in by[sled_rig].tests
    assert by[sled_rig].named_elsewhere == {"R16_005": "R16"}
    assert by[sled_rig].as_dict()["named_like"] == {"R16_005": "R16"}
    assert not by["R16"].named_elsewhere and not by["FULL"].named_elsewhere
    # grouped by the user, nothing to ask
    by = {s.name: s for s in assign_setups(tests, [("R16", "R16_*")])}
    assert not any(s.named_elsewhere for s in by.values())


def test_names_without_a_separator_are_grouped_by_metadata_and_overridden_by_group():
    cfg = {s: PlantConfig(noise=False) for s in ("R16", "SLED", "FULL")}
    tests = simulate_mixed({"R16": 2, "SLED": 2, "FULL": 2}, 3, cfg, prefix="T")
    assert [t.name for t in tests] == ["T01", "T02", "T03", "T04", "T05", "T06"]
    setups = assign_setups(tests)
    assert [(s.name, s.tests) for s in setups] == [
        ("ECE-R16", ["T01", "T02"]), ("SLED-TEST", ["T03", "T04"]),
        ("FULL-FRONTAL", ["T05", "T06"])]
    assert [t.setup for t in tests] == ["ECE-R16"] * 2 + ["SLED-TEST"] * 2 + ["FULL-FRONTAL"] * 2
    setups = assign_setups(tests, parse_groups(["RIG=T0[12]", "CAR=T0*"]))
    assert [(s.name, s.tests, s.how) for s in setups] == [
        ("RIG", ["T01", "T02"], "--group T0[12]"),
        ("CAR", ["T03", "T04", "T05", "T06"], "--group T0*")]
    for t in tests:  # no metadata at all: one setup, not one per test
        t.meta = {}
    assert [s.name for s in assign_setups(tests)] == ["UNKNOWN"]
    for t, rig in zip(tests, ["RIG A"] * 3 + ["CAR"] * 3, strict=True):
        t.meta = {"setup": rig}  # a CSV's "# setup:" line: said by the file, not guessed
    assert [(s.name, s.tests, s.how) for s in assign_setups(tests)] == [
        ("RIG A", ["T01", "T02", "T03"], "the file's setup line"),
        ("CAR", ["T04", "T05", "T06"], "the file's setup line")]
    tests[3].meta = {"setup": "rig a"}  # one rig however its setup line is cased
    assert [(s.name, s.tests) for s in assign_setups(tests)] == [
        ("RIG A", ["T01", "T02", "T03", "T04"]), ("CAR", ["T05", "T06"])]
    with pytest.raises(CrashDataError, match="NAME=PATTERN"):
        parse_groups(["R16"])


def test_a_csv_that_names_a_metadata_setup_joins_it_and_leaves_its_name_alone():
    # a hostile analyst's SLED_101.csv beside the bundled SLED tests had moved them to a setup
    # called SLED-TEST, where the model's SLED effects no longer acted, and lowered their fits
    tests = load_tests(["campaign-a"])
    sleds = [t.name for t in tests if t.name.startswith("SLED")]
    extra = simulate_mixed({"SLED": 3}, 5, {"SLED": PlantConfig(noise=False)}, prefix="X")
    for t, meta in zip(extra, [{"setup": "sled"}, {}, {"setup": "Rig B"}], strict=True):
        t.meta = meta
    extra[1].name = "SLED_101"  # no setup line: the name's prefix says SLED
    setups = {s.name: s for s in assign_setups([*tests, *extra])}
    assert set(setups) == {"FULL", "R16", "SLED", "Rig B"}
    assert setups["SLED"].tests == [*sleds, extra[0].name, "SLED_101"]
    assert "metadata" in setups["SLED"].how and setups["Rig B"].how == "the file's setup line"
    assert [t.setup for t in extra] == ["SLED", "SLED", "Rig B"]


def _inputs(n_tests: int = 2) -> tuple[np.ndarray, np.ndarray]:
    tests = simulate_mixed({"R16": 1, "SLED": n_tests - 1}, 7,
                           {s: PlantConfig(noise=False) for s in ("R16", "SLED")})
    d = make_dataset(tests, 1000.0)
    return d.pulse_g, d.brs_rad


def test_a_scoped_effect_acts_on_its_setups_tests_only():
    P, T = _inputs()
    scoped = [{**AIRBAG, "setups": ["SLED"]}]
    y = NonlinearGreyBox(BASE, scoped, 1000.0, ["R16", "SLED"]).simulate(P, T)
    plain = NonlinearGreyBox(BASE, [], 1000.0).simulate(P, T)
    everywhere = NonlinearGreyBox(BASE, [AIRBAG], 1000.0).simulate(P, T)
    assert np.max(np.abs(everywhere[1] - plain[1])) > 1.0  # the airbag acts in this test
    np.testing.assert_array_equal(y[0], plain[0])
    np.testing.assert_array_equal(y[1], everywhere[1])
    # the daemon's observer of one setup steps as the simulation of that setup's test
    for row, setup in enumerate(("R16", "SLED")):
        obs = NonlinearGreyBox(BASE, scoped, 1000.0, setup)
        stepped = np.array([obs.step(p, b).copy() for p, b in zip(P[row], T[row], strict=True)])
        np.testing.assert_allclose(stepped, y[row], atol=1e-9)
    with pytest.raises(ScopeError, match="say which setup"):
        NonlinearGreyBox(BASE, scoped, 1000.0)


def test_a_fractional_delay_is_linear_between_whole_ticks():
    P, T = _inputs()

    def run(n_pulse: float, n_brs: float = 0.0) -> np.ndarray:
        effect = {"kind": "input_delay", "parameters": {"n_pulse": n_pulse, "n_brs": n_brs}}
        return NonlinearGreyBox(BASE, [effect], 1000.0).simulate(P, T)

    # the model is linear in the pulse: half a tick more is the mean of the two whole ticks
    np.testing.assert_allclose(run(2.5), (run(2.0) + run(3.0)) / 2, atol=1e-9)
    assert np.max(np.abs(run(2.5) - run(2.0))) > 0.01
    obs = NonlinearGreyBox(BASE, [{"kind": "input_delay",
                                   "parameters": {"n_pulse": 1.3, "n_brs": 2.7}}], 1000.0)
    stepped = np.array([obs.step(p, b).copy() for p, b in zip(P[1], T[1], strict=True)])
    np.testing.assert_allclose(stepped, run(1.3, 2.7)[1], atol=1e-9)


def _scoped_model() -> ModelFile:
    Ad, Bd, C, D = model_matrices(BASE, 1000.0, True)
    return ModelFile(kind="greybox", name="loop", tick_rate_hz=1000.0,
                     input_transform="velocity_brs_rate", A=Ad, B=Bd, C=C, D=D,
                     parameters={n: {"value": BASE[n]} for n in PARAM_NAMES},
                     effects=[{"kind": "belt_unloading", "parameters": {}},
                              {**AIRBAG, "setups": ["SLED", "FULL"]}],
                     fitted_on={"setups": ["FULL", "R16", "SLED"]})


def test_the_model_file_carries_the_scope_and_a_bench_runs_its_setups_effects(tmp_path):
    mf = ModelFile.from_dict(_scoped_model().to_dict())
    assert mf.setups() == ["FULL", "SLED"]
    assert [e["kind"] for e in mf.for_setup("R16").effects] == ["belt_unloading"]
    sled = mf.for_setup("SLED")
    assert [e["kind"] for e in sled.effects] == ["belt_unloading", "airbag_contact"]
    assert not sled.setups() and sled.fitted_on["setup"] == "SLED"
    with pytest.raises(ModelFileError, match="--setup"):
        mf.for_setup("")
    with pytest.raises(ModelFileError, match="'HIII' is not one the model knows"):
        mf.for_setup("HIII")


def test_run_refuses_a_scoped_model_without_its_setup(tmp_path, capsys):
    path = tmp_path / "model.json"
    _scoped_model().save(path)
    code = cli.main(["run", "--model", str(path), "--interface", "virtual", "--channel", "x",
                     "--setup", "R17"])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and "'R17'" in err, err


def test_a_setup_the_model_does_not_know_is_refused_when_no_effect_is_scoped(tmp_path, capsys):
    """--setup MARS on a model whose effects act everywhere ran silently; a typo is now
    refused in one line, and a setup the model was fitted on runs the model as it is."""
    plain = ModelFile.from_dict({**_scoped_model().to_dict(),
                                 "effects": [{"kind": "belt_unloading", "parameters": {}}]})
    assert not plain.setups()
    assert plain.for_setup("SLED") is plain and plain.for_setup("") is plain
    with pytest.raises(ModelFileError, match="'MARS' is not one the model was fitted on"):
        plain.for_setup("MARS")
    path = tmp_path / "model.json"
    plain.save(path)
    for argv in (["run", "--model", str(path), "--interface", "virtual", "--channel", "x",
                  "--setup", "MARS"],
                 ["export-c", str(path), "--out", str(tmp_path / "c"), "--setup", "MARS"]):
        code = cli.main(argv)
        err = capsys.readouterr().err
        assert code == 2 and len(err.strip().splitlines()) == 1 and "'MARS'" in err, err
        assert "left out" in err
    assert not (tmp_path / "c").exists()
    unknown = ModelFile.from_dict({**plain.to_dict(), "fitted_on": {}})
    assert unknown.for_setup("MARS") is unknown  # no setups recorded: nothing to check against


def test_export_c_of_a_scoped_model_needs_the_setup(tmp_path, capsys):
    path = tmp_path / "model.json"
    _scoped_model().save(path)
    assert cli.main(["export-c", str(path), "--out", str(tmp_path / "c")]) == 2
    assert "--setup" in capsys.readouterr().err
    assert cli.main(["export-c", str(path), "--out", str(tmp_path / "c"), "--setup", "SLED"]) == 0
    assert "@SLED" in (tmp_path / "c" / "chest_observer.h").read_text()

