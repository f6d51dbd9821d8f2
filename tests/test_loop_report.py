"""The loop report's entries are types serialised to the JSON objects report.json has always
had: same keys, same order (report.json is compared byte for byte between versions)."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest

from observer_node import plots
from observer_node.ident.metrics import Fits
from observer_node.loop.analysis import CorrelationTests, OutputCorrelation
from observer_node.loop.closed_loop import _evidence_rounds
from observer_node.loop.diagnosis import Unexplained
from observer_node.loop.evidence import judge
from observer_node.loop.report import (
    AcceptedEffect,
    EffectEvidence,
    LeftOut,
    LoopSettings,
    LoopStep,
    OtherScope,
    PossibleEffect,
    RankedCandidate,
    RunnerUp,
    SensorEffect,
    SetupValidation,
    TriedCandidate,
)
from observer_node.loop.report_md import markdown, names
from observer_node.loop.screening import low_with_rig

EXAMPLE = Path(__file__).parent.parent / "observer_node" / "examples" / "bench-loop"

# report.json's keys, in order, as observer-node loop wrote them before the entries were typed
ACCEPTED_KEYS = ["kind", "description", "parameters", "std_err", "setups", "applies_to",
                 "warnings", "confidence", "evidence", "fit"]
EVIDENCE_KEYS = ["ranking_share", "scope_shares", "rule", "explained_share_before",
                 "explained_share_after", "cv_fit_before", "cv_fit_after", "runner_up",
                 "margin_points", "other_scope", "input_xcorr_rms_ratio_before",
                 "input_xcorr_rms_ratio_after", "input_xcorr_max_ratio_before",
                 "input_xcorr_max_ratio_after"]
RULE_KEYS = ["gain_points", "ci95_points", "gain_in_scope_points", "test_gain_points",
             "tests_improved", "tests", "sign_test_p", "setup_gain_points", "accepted",
             "reason", "tests_to_defend", "stalled_tests"]


def _rule():
    before = {"A": 80.0, "B": 82.0, "C": 79.0, "D": 81.0}
    after = {"A": 83.1, "B": 84.2, "C": 82.5, "D": 83.3}
    return judge(before, after, {"A": "R16", "B": "R16", "C": "SLED", "D": "SLED"}, ["SLED"],
                 1.0)


def _accepted(setups: list[str] | None, rivals: bool) -> AcceptedEffect:
    rule = _rule()
    runner_up = RunnerUp("pelvis_coupling", "all", 94.3, False, 4, True, False)
    ev = EffectEvidence(0.1234, {"SLED": 0.1234, "all": 0.05}, rule, 0.1834, 0.025, 94.0,
                        96.0, runner_up if rivals else None,
                        1.8 if rivals else None, OtherScope("all", 95.1, 0.9) if rivals else None,
                        0.28, 0.54, 0.79, 1.68)
    return AcceptedEffect("airbag_contact", "airbag", {"kab": 2.2e4, "gap": 0.09},
                          {"kab": 520.0, "gap": 0.00085}, setups,
                          ["C", "D"] if setups else None, [], rule.confidence, ev,
                          Fits(95.6, 96.7, 96.15))


def test_an_accepted_effect_is_written_with_the_keys_report_json_has():
    d = _accepted(["SLED"], rivals=True).as_dict()
    assert list(d) == ACCEPTED_KEYS
    assert list(d["evidence"]) == EVIDENCE_KEYS
    assert list(d["evidence"]["rule"]) == RULE_KEYS
    assert list(d["evidence"]["runner_up"]) == ["kind", "scope", "cv_fit", "told_apart",
                                                "tests_better", "passes_rule", "over_bar"]
    assert list(d["evidence"]["other_scope"]) == ["scope", "cv_fit", "margin_points"]
    assert list(d["fit"]) == ["cr", "cd", "total"]
    # on every test, without rivals: no setups, applies_to, runner-up, margin or other scope
    plain = _accepted(None, rivals=False).as_dict()
    assert list(plain) == [k for k in ACCEPTED_KEYS if k not in ("setups", "applies_to")]
    assert list(plain["evidence"]) == [k for k in EVIDENCE_KEYS if k not in (
        "runner_up", "margin_points", "other_scope")]


def test_an_accepted_effect_reads_back_from_report_json_unchanged():
    for e in (_accepted(["SLED"], rivals=True), _accepted(None, rivals=False)):
        text = json.dumps(e.as_dict(), indent=1)
        back = AcceptedEffect.from_dict(json.loads(text))
        assert json.dumps(back.as_dict(), indent=1) == text
        assert back.scope == e.scope and back.model_entry() == e.model_entry()
    assert _accepted(["SLED"], True).model_entry()["setups"] == ["SLED"]
    assert "setups" not in _accepted(None, False).model_entry()


def test_possible_sensor_and_unexplained_entries_keep_their_keys():
    rule = _rule()
    p = PossibleEffect("input_delay", "all", ["belt_unloading"], rule, "gains 0.43 < 1 points")
    assert list(p.as_dict()) == ["kind", "scope", "after", "evidence", "why_not",
                                 "validation_by_setup", "tests_to_tell_apart"]
    assert p.as_dict()["validation_by_setup"] is p.as_dict()["tests_to_tell_apart"] is None
    refused = PossibleEffect("chest_stiffening", "SLED", [], rule, "the validation tests ...",
                             [SetupValidation("FULL", 3, 88.14, 80.21, False, False)])
    assert refused.as_dict()["validation_by_setup"] == [
        {"setup": "FULL", "tests": 3, "before": 88.14, "after": 80.21, "judged": False,
         "in_scope": False, "ran_away": False}]
    assert list(p.as_dict()["evidence"]) == RULE_KEYS
    s = SensorEffect("cd", [], "a static function of CD", rule).as_dict()
    assert list(s) == ["output", "family", "after", "looks_like", "evidence", "confidence"]
    assert s["family"] == "sensor" and s["confidence"] == rule.confidence
    u = Unexplained("cd", ["R16"], "a lag", "lag", {"R16": 1.5, "SLED": 0.2}, 0.1).as_dict()
    assert list(u) == ["output", "setups", "looks_like", "shape", "gain_points",
                       "other_output_gain_points"]


def test_a_round_of_the_loop_keeps_its_keys():
    rule = _rule()
    ranked = RankedCandidate("pelvis_coupling", 0.256, "all", None, {"kp": 1.0e4})
    step = LoopStep(["belt_unloading"], 86.0, [ranked],
                    [TriedCandidate("chest_stiffening", "all", 94.0, rule)],
                    {"cr": rule, "cd": rule})
    step.decision = "accepted chest_stiffening on all"  # decided when the round ends
    d = step.as_dict()
    assert list(d) == ["effects_before", "cv_fit_before", "ranking", "tried", "sensor",
                       "decision"]
    assert list(d["ranking"][0]) == ["kind", "explained_share", "scope", "scope_shares",
                                     "initial_parameters"]
    assert list(d["tried"][0]) == ["kind", "scope", "cv_fit", "evidence"]
    assert list(d["tried"][0]["evidence"]) == RULE_KEYS
    assert list(d["sensor"]) == ["cr", "cd"] and d["decision"].startswith("accepted")


def test_the_fits_with_and_without_left_out_tests_keep_their_keys():
    without = Fits(94.85, 98.54, 96.69)
    both = LeftOut(["EST_001", "VAL_002"], without, Fits(94.0, 98.0, 96.0),
                   "cannot be scored: 50 samples missing").as_dict()
    assert list(both) == ["tests", "validation_fit_without",
                          "validation_fit_if_fitted_with_them", "validation_fit_with_them"]
    assert both["validation_fit_without"] == {"cr": 94.85, "cd": 98.54, "total": 96.69}
    assert both["validation_fit_with_them"] == "cannot be scored: 50 samples missing"
    # only validation tests left out: no refit with them
    assert list(LeftOut(["VAL_002"], without, None, without).as_dict()) == [
        "tests", "validation_fit_without", "validation_fit_with_them"]


def _correlation(scale: float) -> OutputCorrelation:
    return OutputCorrelation(0.98, 0.92, 1.9 * scale, 1.17 * scale, 1.96 * scale, 1.23 * scale)


def test_the_residual_tests_keep_their_keys_and_read_back_unchanged():
    t = CorrelationTests(_correlation(1.0), _correlation(0.5))
    d = t.as_dict()
    assert list(d) == ["cr", "cd"]
    assert list(d["cd"]) == ["lag1_autocorrelation", "share_of_lags_outside_white_band",
                             "xcorr_pulse_ratio", "xcorr_pulse_rms_ratio",
                             "xcorr_brs_rate_ratio", "xcorr_brs_rate_rms_ratio"]
    text = json.dumps(d, indent=1)
    assert json.dumps(CorrelationTests.from_dict(json.loads(text)).as_dict(), indent=1) == text
    # the largest ratio over the inputs (per output, and over both), the mean RMS ratio
    assert t.cr.max_ratio == 1.96 and t.cd.max_ratio == 0.98 and t.max_ratio == 1.96
    assert t.rms_ratio == pytest.approx((1.17 + 1.23) * 1.5 / 4)


def test_the_loop_settings_keep_their_keys_and_read_back_unchanged():
    s = LoopSettings(1000.0, (0.01, 0.15), 1.0, 5, ["rig=R16_*"], False, 2,
                     "two-fold inside estimation tests", "mean paired gain >= 1 points")
    d = s.as_dict()
    assert list(d) == ["rate_hz", "window_s", "margin", "top_k", "groups", "allow_anywhere",
                       "workers", "cross_validation", "rule"]
    assert d["window_s"] == [0.01, 0.15]  # a JSON array, as before
    text = json.dumps(d, indent=1)
    back = LoopSettings.from_dict(json.loads(text))
    assert back == s and json.dumps(back.as_dict(), indent=1) == text


def test_the_bundled_report_json_reads_back_to_the_same_text():
    """The example loop report's residual tests and settings, read back and written again,
    are the same JSON text."""
    report = json.loads((EXAMPLE / "report.json").read_text())
    for label, tests in report["residual_tests"].items():
        assert json.dumps(CorrelationTests.from_dict(tests).as_dict(), indent=1) == json.dumps(
            tests, indent=1), label
    assert json.dumps(LoopSettings.from_dict(report["settings"]).as_dict(), indent=1) == (
        json.dumps(report["settings"], indent=1))


def test_evidence_png_draws_each_round_as_the_rule_reads_it(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # a tie: two candidates pass the rule; a third does not; the sensor candidates follow
    rule, weak = _rule(), judge({"A": 80.0, "B": 82.0}, {"A": 80.2, "B": 81.9},
                                {"A": "R16", "B": "SLED"}, None, 1.0)
    step = LoopStep([], 86.0, [], [TriedCandidate("airbag_contact", "SLED", 94.0, rule),
                                   TriedCandidate("belt_stiffening", "SLED", 93.9, rule),
                                   TriedCandidate("pelvis_coupling", "all", 86.1, weak)],
                    {"cr": weak})
    step.decision = "airbag_contact on SLED passes the rule, but the data cannot tell it " * 4
    (title, rows), = _evidence_rounds([step])
    assert [(r[0], r[4]) for r in rows] == [("airbag_contact on SLED", True),
                                            ("belt_stiffening on SLED", True),
                                            ("pelvis_coupling on all", False),
                                            ("sensor: CR static", False)]
    assert rows[0][1] == rule.test_gain_points and rows[0][3] == rule.ci95_points
    # a long decision is shortened and wrapped, not run off the figure
    assert title.startswith("round 1 (model with no effect): airbag_contact")
    assert all(len(line) <= 100 for line in title.splitlines()) and len(title) <= 235
    png = plots.loop_evidence(tmp_path / "evidence.png", [(title, rows)],
                              {"A": "R16", "B": "R16", "C": "SLED", "D": "SLED"}, 1.0)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # a trial that ran away (-1000 %) is drawn at the floor, not across the whole axis
    ran_away = [("belt_unloading on all", {"A": -1090.0, "C": 2.0}, -544.0, (-9e3, 8e3), False)]
    drawn = []
    save = plots._save
    monkeypatch.setattr(plots, "_save", lambda fig, path: drawn.append(fig.axes[0].get_xlim())
                        or save(fig, path))
    plots.loop_evidence(tmp_path / "away.png", [("round 1", rows + ran_away)],
                        {"A": "R16", "C": "SLED"}, 1.0)
    assert plots.EVIDENCE_FLOOR_POINTS - 5 < drawn[0][0] < 0 < 2.0 < drawn[0][1] < 100
    # a loop that ran no round still gets its figure
    assert plots.loop_evidence(tmp_path / "none.png", [], {}, 1.0).stat().st_size > 0


def test_a_test_low_with_its_rig_is_said_and_kept(r16_loop) -> None:
    # far below the others but not below its rig's other tests: not left out (warnings),
    # but said in report.md and report.json, so the engineer looks before reading that rig
    _, r = r16_loop
    assert "low_with_rig" not in r.as_dict()
    (low,) = low_with_rig({"R16_001": 90.0, "R16_003": 89.0, "F1": 66.0, "F2": 70.0,
                           "S1": 91.0}, {"R16_001": "R16", "R16_003": "R16", "F1": "FULL",
                                         "F2": "FULL", "S1": "SLED"})
    assert low.test == "F1" and "its setup's other tests' 70.0 %" in low.reason
    said = dataclasses.replace(r, low_with_rig=[low])
    assert said.as_dict()["low_with_rig"] == [low.as_dict()]
    md = markdown(said)
    assert "## Tests far below the others, low with their rig (kept in the fits)" in md
    assert f"| F1 | {low.reason} |" in md and "kept in the fits" in low.reason


def test_a_named_airbag_says_a_webbing_knee_looks_alike(r16_loop) -> None:
    # sets AK and AL named an airbag on SLED for a webbing that stiffens past a knee, and
    # the knee passed the rule on every bag case the bag passed on (session 54's screen): the
    # report says so beside the airbag, and beside no effect without a look-alike
    _, r = r16_loop
    assert r.effects, "the fixture's loop names an effect"
    plain = markdown(r)
    assert all(e.kind != "airbag_contact" for e in r.effects) and "- looks alike:" not in plain
    bag = dataclasses.replace(r.effects[0], kind="airbag_contact")
    md = markdown(dataclasses.replace(r, effects=[bag]))
    assert md.count("- looks alike: a webbing that stiffens past a knee") == 1
    _, section = md.split("## airbag_contact\n", 1)
    assert "- looks alike:" in section.split("\n## ", 1)[0]  # in the bag's own section


def test_a_test_named_like_another_setup_is_asked_about(r16_loop) -> None:
    _, r = r16_loop
    assert "Check the metadata" not in markdown(r)
    odd = dataclasses.replace(r.setups[0], named_elsewhere={"SLED_009": "SLED"})
    md = markdown(dataclasses.replace(r, setups=[odd, *r.setups[1:]]))
    assert md.count("**Check the metadata:** SLED_009 is named like setup SLED's tests, but "
                    f"its .mme (type of test, title, test object) puts it in {odd.name}") == 1


def test_a_sensor_effect_says_the_other_transducer_can_read_alike(r16_loop) -> None:
    # held-out set V: CR's slow clock was named a sensor effect on CD; the report must not
    # send the engineer to one transducer only, whichever shape the correction took
    _, r = r16_loop
    cr = SensorEffect("cr", [], "a static function of CR: the CR transducer's gain", _rule())
    md = markdown(dataclasses.replace(r, sensor_effects=[cr]))
    assert "- **CR**: a static function of CR" in md
    assert "- and the CD transducer's too: an error on CD can bend the model" in md
    assert "a correction of CR wins it back" in md
    cd = SensorEffect("cd", [], "a drift in time on CD: the CD transducer's gain", _rule())
    assert "- and the CR transducer's too" in markdown(
        dataclasses.replace(r, sensor_effects=[cd]))
    # both named (the data cannot tell which): said once, for both, and no caveat
    both = markdown(dataclasses.replace(r, sensor_effects=[cr, cd]))
    assert "which transducer, the data cannot tell" in both and "- one of CR and CD" in both
    assert "transducer's too" not in both
    # a lag is read from an input delay, not a static correction: no such line
    lag = SensorEffect("cd", [], "a lag of about 1.5 ms on CD alone", _rule())
    assert "transducer's too" not in markdown(dataclasses.replace(r, sensor_effects=[lag]))


def test_a_campaign_s_test_names_are_shortened_in_report_md_not_lost() -> None:
    """Hundreds of test names were listed three times in report.md (header, setups, an effect's
    tests): runs of numbers are shortened and past two dozen pieces the rest counted."""
    assert names(["R16_001", "R16_002", "R16_003", "R16_005", "SLED_001", "SLED_002", "X"]) \
        == "R16_001..003, R16_005, SLED_001, SLED_002, X"
    assert names(["a9", "a10", "a11"]) == "a9, a10, a11"  # not one run: the widths differ
    odd = [f"T{i:03d}" for i in range(1, 200, 2)]
    text = names(odd)
    assert text.startswith("T001, T003, ") and text.count(",") == 23
    assert text.endswith("and 76 more (100 tests; report.json lists each)")
    campaign = [f"R16_{i:03d}" for i in range(1, 157)]
    assert names(campaign) == "R16_001..156"
