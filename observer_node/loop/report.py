"""What observer-node loop reports (report.json, read back by the bench and the README
figures): typed, serialised by :meth:`LoopReport.as_dict` to the JSON the loop has always
written (the key order of each object is part of that: report.json is compared byte for byte).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..criteria import CriteriaComparison
from ..data.setups import Setup
from ..ident.metrics import Fits, OutputFits
from ..iso18571 import IsoRatings
from .analysis import CorrelationTests
from .belt_check import BeltPush
from .diagnosis import Unexplained
from .evidence import Evidence
from .screening import BrokenTest


@dataclass(frozen=True)
class RunnerUp:
    """The best cross-validated candidate of another kind than the accepted one."""

    kind: str
    scope: str  # its setups joined by "+", or "all"
    cv_fit: float  # its mean cross-validated fit_TOT [%] (rounded to 0.01)
    # Whether the accepted effect beats it test by test above the scatter (the rule's paired
    # interval or sign test), on how many estimation tests it fits better, and whether the
    # runner-up passes the rule itself; None in reports written before 2026-11-24.
    told_apart: bool | None = None
    tests_better: int | None = None
    passes_rule: bool | None = None
    # whether it failed the rule on the scatter alone, its mean over the bar
    # (evidence.over_the_bar); None in reports written before 2026-11-30
    over_bar: bool | None = None

    def as_dict(self) -> dict[str, Any]:
        return {"kind": self.kind, "scope": self.scope, "cv_fit": self.cv_fit,
                **({"told_apart": self.told_apart, "tests_better": self.tests_better,
                    "passes_rule": self.passes_rule} if self.told_apart is not None else {}),
                **({"over_bar": self.over_bar} if self.over_bar is not None else {})}

    @property
    def rival(self) -> bool:
        """The runner-up passes the rule too, or fails it on the scatter alone (since
        2026-11-30), and the data cannot tell it from the accepted effect: the accepted one is
        then one of two explanations, not a finding on its own."""
        return (bool(self.passes_rule) or bool(self.over_bar)) and self.told_apart is False

    @property
    def standing(self) -> str:
        """What the runner-up's own evidence is, in words."""
        return ("passes the rule too" if self.passes_rule else
                "gains over the bar too, failing the rule on the scatter alone" if self.over_bar
                else "does not pass the rule")


@dataclass(frozen=True)
class OtherScope:
    """The accepted effect on the other scope it was tried on."""

    scope: str
    cv_fit: float  # mean cross-validated fit_TOT [%] there
    margin_points: float  # accepted scope's cv fit minus this one's [fit points]

    def as_dict(self) -> dict[str, Any]:
        return {"scope": self.scope, "cv_fit": self.cv_fit, "margin_points": self.margin_points}


@dataclass(frozen=True)
class EffectEvidence:
    """Why an effect was accepted: its share of the residual [0..1] in the ranking, the
    rule's verdict, its signature's share of the residual before and after the refit, the
    cross-validated fit_TOT [%] before and after, the runner-up and the margin [points], and
    the residual's input cross-correlation / coloured band (RMS and largest) before and after.
    Values are as reported (rounded)."""

    ranking_share: float
    scope_shares: dict[str, float] | None
    rule: Evidence
    explained_share_before: float
    explained_share_after: float
    cv_fit_before: float
    cv_fit_after: float
    runner_up: RunnerUp | None
    margin_points: float | None  # None with no runner-up
    other_scope: OtherScope | None
    input_xcorr_rms_ratio_before: float
    input_xcorr_rms_ratio_after: float
    input_xcorr_max_ratio_before: float
    input_xcorr_max_ratio_after: float
    # how a tie with a runner-up that passes the rule too was resolved (each judged beside
    # the other); None where there was none (and in reports before 2026-11-25)
    tie: str | None = None

    def as_dict(self) -> dict[str, Any]:
        return {
            "ranking_share": self.ranking_share, "scope_shares": self.scope_shares,
            "rule": self.rule.as_dict(),
            "explained_share_before": self.explained_share_before,
            "explained_share_after": self.explained_share_after,
            "cv_fit_before": self.cv_fit_before, "cv_fit_after": self.cv_fit_after,
            **({"runner_up": self.runner_up.as_dict(), "margin_points": self.margin_points}
               if self.runner_up is not None else {}),
            **({"other_scope": self.other_scope.as_dict()}
               if self.other_scope is not None else {}),
            "input_xcorr_rms_ratio_before": self.input_xcorr_rms_ratio_before,
            "input_xcorr_rms_ratio_after": self.input_xcorr_rms_ratio_after,
            "input_xcorr_max_ratio_before": self.input_xcorr_max_ratio_before,
            "input_xcorr_max_ratio_after": self.input_xcorr_max_ratio_after,
            **({"tie": self.tie} if self.tie is not None else {}),
        }

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> EffectEvidence:
        ru, os_ = d.get("runner_up"), d.get("other_scope")
        return cls(d["ranking_share"], d["scope_shares"], Evidence.from_dict(d["rule"]),
                   d["explained_share_before"], d["explained_share_after"],
                   d["cv_fit_before"], d["cv_fit_after"],
                   RunnerUp(**ru) if ru is not None else None, d.get("margin_points"),
                   OtherScope(**os_) if os_ is not None else None,
                   d["input_xcorr_rms_ratio_before"], d["input_xcorr_rms_ratio_after"],
                   d["input_xcorr_max_ratio_before"], d["input_xcorr_max_ratio_after"],
                   d.get("tie"))


@dataclass(frozen=True)
class AcceptedEffect:
    """An effect the loop added: its kind and one-line description, its parameters (units:
    the effect's definition, :mod:`observer_node.model.effects`) and their standard errors,
    the setups it acts on and those setups' estimation and validation tests (None: every
    test), warnings on its parameters, the rule's verdict in one line, the evidence, and the
    validation fits [%] of the model with it (rounded to 0.01)."""

    kind: str
    description: str
    parameters: dict[str, Any]
    std_err: dict[str, float]
    setups: list[str] | None
    applies_to: list[str] | None  # test names; None with setups None
    warnings: list[str]
    confidence: str
    evidence: EffectEvidence
    fit: Fits

    @property
    def scope(self) -> str:
        """The setups it acts on joined by "+", or "all"."""
        return "all" if self.setups is None else "+".join(self.setups)

    def model_entry(self) -> dict[str, Any]:
        """The effect as model.json and the refit take it."""
        return {"kind": self.kind, "parameters": self.parameters,
                **({"setups": self.setups} if self.setups is not None else {})}

    def as_dict(self) -> dict[str, Any]:
        return {"kind": self.kind, "description": self.description,
                "parameters": self.parameters, "std_err": self.std_err,
                **({"setups": self.setups, "applies_to": self.applies_to}
                   if self.setups is not None else {}),
                "warnings": self.warnings, "confidence": self.confidence,
                "evidence": self.evidence.as_dict(), "fit": self.fit.as_dict()}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> AcceptedEffect:
        """An entry of report.json's ``effects``, read back."""
        return cls(d["kind"], d["description"], d["parameters"], d["std_err"],
                   d.get("setups"), d.get("applies_to"), d["warnings"], d["confidence"],
                   EffectEvidence.from_dict(d["evidence"]), Fits(**d["fit"]))


@dataclass(frozen=True)
class ModelFit:
    """A model's validation fits [%] (rounded to 0.01), its base parameters (SI units, see
    :data:`observer_node.model.chest.PARAM_UNITS`) and their standard errors."""

    fit: Fits
    parameters: dict[str, float]
    std_err: dict[str, float]

    def as_dict(self) -> dict[str, Any]:
        return {"fit": self.fit.as_dict(), "parameters": self.parameters,
                "std_err": self.std_err}


@dataclass(frozen=True)
class SetupValidation:
    """One setup's validation tests with an effect the validation tests refused and without
    it: where their fit fell, and whether the estimation tests judge the setup and the effect
    acts there (a fall on a setup neither holds says little of the effect itself)."""

    setup: str
    tests: int
    before: float  # their mean fit_TOT [%] without the effect
    after: float  # and with it
    judged: bool  # estimation tests enough to judge an effect there
    in_scope: bool  # the effect acts on the setup
    ran_away: bool = False  # a test's fit was not finite (counted -1000 % in the means)

    def as_dict(self) -> dict[str, Any]:
        return {"setup": self.setup, "tests": self.tests, "before": round(self.before, 2),
                "after": round(self.after, 2), "judged": self.judged,
                "in_scope": self.in_scope, "ran_away": self.ran_away}


@dataclass(frozen=True)
class PossibleEffect:
    """A candidate that gained something but failed the rule: reported, never a finding."""

    kind: str
    scope: str  # its setups joined by "+", or "all"
    after: list[str]  # the effects the model had when it was tried
    evidence: Evidence
    why_not: str
    # refused by the validation tests: their fit per setup, without and with it
    validation_by_setup: list[SetupValidation] | None = None
    # a side of a tie: the judged estimation tests that would tell the two apart, a planning
    # figure (evidence.tell_apart; None: past its ceiling, or nothing can be said)
    tests_to_tell_apart: int | None = None

    def as_dict(self) -> dict[str, Any]:
        by_setup = self.validation_by_setup
        return {"kind": self.kind, "scope": self.scope, "after": self.after,
                "evidence": self.evidence.as_dict(), "why_not": self.why_not,
                "validation_by_setup": (None if by_setup is None
                                        else [v.as_dict() for v in by_setup]),
                "tests_to_tell_apart": self.tests_to_tell_apart}


@dataclass(frozen=True)
class SensorEffect:
    """A sensor correction of one output (a static function of it, or a drift in time) that
    beat every physical effect under the rule: the transducer's error, reported and not added
    to the model."""

    output: str  # "cr" or "cd"
    after: list[str]  # the effects the model had when it was tried
    looks_like: str
    evidence: Evidence

    family = "sensor"

    @property
    def confidence(self) -> str:
        return self.evidence.confidence

    def as_dict(self) -> dict[str, Any]:
        return {"output": self.output, "family": self.family, "after": self.after,
                "looks_like": self.looks_like, "evidence": self.evidence.as_dict(),
                "confidence": self.confidence}


@dataclass(frozen=True)
class RankedCandidate:
    """An effect as the residual analysis ranks it: the share [0..1] of the residual its
    signature explains (rounded to 0.0001) on its scope, the shares on the scopes tried, and
    the initial parameters the regression gives it (the effect's units)."""

    kind: str
    explained_share: float
    scope: str  # its setups joined by "+", or "all"
    scope_shares: dict[str, float] | None
    initial_parameters: dict[str, Any]

    def as_dict(self) -> dict[str, Any]:
        return {"kind": self.kind, "explained_share": self.explained_share,
                "scope": self.scope, "scope_shares": self.scope_shares,
                "initial_parameters": self.initial_parameters}


@dataclass(frozen=True)
class TriedCandidate:
    """A candidate cross-validated in a round: its mean cross-validated fit_TOT [%] with it
    and the rule's verdict."""

    kind: str
    scope: str
    cv_fit: float
    evidence: Evidence

    def as_dict(self) -> dict[str, Any]:
        return {"kind": self.kind, "scope": self.scope, "cv_fit": self.cv_fit,
                "evidence": self.evidence.as_dict()}


@dataclass
class LoopStep:
    """One round of the loop: the effects the model had and its mean cross-validated
    fit_TOT [%], the ranking, the candidates tried (best first), the sensor candidates per
    output, and what was decided (set when the round ends)."""

    effects_before: list[str]
    cv_fit_before: float
    ranking: list[RankedCandidate]
    tried: list[TriedCandidate]
    sensor: dict[str, Evidence]
    decision: str = ""

    def as_dict(self) -> dict[str, Any]:
        return {"effects_before": self.effects_before, "cv_fit_before": self.cv_fit_before,
                "ranking": [c.as_dict() for c in self.ranking],
                "tried": [t.as_dict() for t in self.tried],
                "sensor": {o: ev.as_dict() for o, ev in self.sensor.items()},
                "decision": self.decision}


@dataclass(frozen=True)
class NotJudged:
    """A setup the data cannot judge an effect on: fewer than ``MIN_JUDGED`` (in
    :mod:`.closed_loop`) of its tests estimate the model, so an effect there cannot be told
    from one test's scatter. Nothing is claimed about it: an effect named on every setup
    ("all") acts there too, as the model's best guess; one named on some setups does not, and
    no scope is tried on such setups alone."""

    setup: str
    estimation_tests: int
    validation_tests: int

    @property
    def why(self) -> str:
        n = self.estimation_tests
        return ("no estimation test" if n == 0 else f"{n} estimation test") + (
            f", {self.validation_tests} validation test(s)")

    def as_dict(self) -> dict[str, Any]:
        return {"setup": self.setup, "estimation_tests": self.estimation_tests,
                "validation_tests": self.validation_tests, "why": self.why}


@dataclass(frozen=True)
class LeftOut:
    """The validation fits [%] (rounded to 0.01) with the tests left out and without them:
    the final model as fitted; its structure refitted with the left-out estimation tests back
    in; scored on the left-out validation tests too. A text says why one could not be had;
    None: no such tests."""

    tests: list[str]
    validation_fit_without: Fits
    validation_fit_if_fitted_with_them: Fits | str | None = None
    validation_fit_with_them: Fits | str | None = None

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"tests": self.tests,
                               "validation_fit_without": self.validation_fit_without.as_dict()}
        for key, f in (("validation_fit_if_fitted_with_them",
                        self.validation_fit_if_fitted_with_them),
                       ("validation_fit_with_them", self.validation_fit_with_them)):
            if f is not None:
                out[key] = f if isinstance(f, str) else f.as_dict()
        return out


@dataclass(frozen=True)
class LoopSettings:
    """How the loop was run: the tick rate [Hz], the fit window [s], the margin an effect must
    add [fit_TOT points], how many candidates a round tries, the --group patterns, whether
    effects were tried where the setups' metadata rule them out, the worker processes, and the
    cross-validation and the rule in words."""

    rate_hz: float
    window_s: tuple[float, float]
    margin: float
    top_k: int | None
    groups: list[str]  # NAME=PATTERN
    allow_anywhere: bool
    workers: int
    cross_validation: str
    rule: str

    def as_dict(self) -> dict[str, Any]:
        return {"rate_hz": self.rate_hz, "window_s": list(self.window_s),
                "margin": self.margin, "top_k": self.top_k, "groups": self.groups,
                "allow_anywhere": self.allow_anywhere, "workers": self.workers,
                "cross_validation": self.cross_validation, "rule": self.rule}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> LoopSettings:
        """report.json's ``settings``, read back."""
        return cls(d["rate_hz"], (d["window_s"][0], d["window_s"][1]), d["margin"],
                   d["top_k"], d["groups"], d["allow_anywhere"], d["workers"],
                   d["cross_validation"], d["rule"])


@dataclass(frozen=True)
class LoopReport:
    """The thesis grey-box and the final model on the validation tests, the effects accepted
    (each with its evidence, scope, parameters and validation fit), those possible but not
    accepted, sensor effects, unexplained structure, tests left out and why, how the loop
    got there, and the effect carried in the model for its fit when a tie named neither."""

    baseline: ModelFit
    effects: list[AcceptedEffect]  # in the order accepted
    possible: list[PossibleEffect]  # largest gain first
    sensor_effects: list[SensorEffect]
    unexplained: list[Unexplained]
    warnings: list[BrokenTest]  # tests left out of the fits
    left_out: LeftOut | None  # the fits with and without them (None: none left out)
    final: ModelFit
    setups: list[Setup]
    not_judged: list[NotJudged]  # setups too thinly estimated to name an effect on
    model: str  # file names in the output folder
    baseline_model: str
    software_version: str
    estimation: list[str]  # test names
    validation: list[str]
    residual_tests: dict[str, CorrelationTests]  # baseline, final (on the estimation tests)
    first_ranking: list[RankedCandidate]
    history: list[LoopStep]  # one per round of candidates
    settings: LoopSettings
    validation_tests: dict[str, dict[str, OutputFits]]  # baseline, final: per test
    criteria: dict[str, dict[str, CriteriaComparison]]  # baseline, final: per test
    iso18571: dict[str, IsoRatings] | None  # baseline, final (None: not rated)
    seconds: float  # the loop's run time [s]
    # In the model for its fit, not named: the better side of a tie neither side of which
    # the data defend as a finding (absent from report.json when none).
    carried: list[AcceptedEffect] = field(default_factory=list)
    # Setups where the final model's belt pushes the chest (absent from report.json when none)
    belt_pushes: list[BeltPush] = field(default_factory=list)
    # Tests far below the others whose rig is low with them: kept in the fits (absent from
    # report.json when none)
    low_with_rig: list[BrokenTest] = field(default_factory=list)
    # Tests flagged far below the others that could not be left out (too few would remain):
    # kept in the fits (absent from report.json when none)
    flagged_kept: list[BrokenTest] = field(default_factory=list)
    # Test files left out unread by --skip-bad-tests, path and why (absent from report.json
    # when none)
    not_read: list[BrokenTest] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return {
            "baseline": self.baseline.as_dict(), "effects": [e.as_dict() for e in self.effects],
            **({"carried": [e.as_dict() for e in self.carried]} if self.carried else {}),
            "possible": [p.as_dict() for p in self.possible],
            "sensor_effects": [s.as_dict() for s in self.sensor_effects],
            "unexplained": [u.as_dict() for u in self.unexplained],
            **({"belt_pushes": [b.as_dict() for b in self.belt_pushes]}
               if self.belt_pushes else {}),
            "warnings": [w.as_dict() for w in self.warnings],
            **({"low_with_rig": [w.as_dict() for w in self.low_with_rig]}
               if self.low_with_rig else {}),
            **({"flagged_kept": [w.as_dict() for w in self.flagged_kept]}
               if self.flagged_kept else {}),
            **({"not_read": [w.as_dict() for w in self.not_read]} if self.not_read else {}),
            "left_out": self.left_out.as_dict() if self.left_out is not None else {},
            "final": self.final.as_dict(),
            "setups": [s.as_dict() for s in self.setups],
            "not_judged": [n.as_dict() for n in self.not_judged], "model": self.model,
            "baseline_model": self.baseline_model, "software_version": self.software_version,
            "estimation": self.estimation, "validation": self.validation,
            "residual_tests": {k: t.as_dict() for k, t in self.residual_tests.items()},
            "first_ranking": [c.as_dict() for c in self.first_ranking],
            "history": [s.as_dict() for s in self.history],
            "settings": self.settings.as_dict(),
            "validation_tests": {k: {n: f.as_dict() for n, f in v.items()}
                                 for k, v in self.validation_tests.items()},
            "criteria": {k: {n: c.as_dict() for n, c in v.items()}
                         for k, v in self.criteria.items()},
            **({"iso18571": {k: v.as_dict() for k, v in self.iso18571.items()}}
               if self.iso18571 is not None else {}),
            "seconds": self.seconds,
        }
