"""What observer-node loop reports (report.json, read back by the bench and the README
figures): typed at its top level, serialised by :meth:`LoopReport.as_dict` to the JSON the
loop has always written. The effects, candidates and history inside stay the JSON objects
report.md documents."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..criteria import CriteriaComparison
from ..data.setups import Setup
from ..ident.metrics import Fits, OutputFits
from ..scores import IsoRatings
from .screening import BrokenTest


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
class LoopReport:
    """The thesis grey-box and the final model on the validation tests, the effects accepted
    (each with its evidence, scope, parameters and validation fit), those possible but not
    accepted, sensor effects, unexplained structure, tests left out and why, and how the
    loop got there."""

    baseline: ModelFit
    effects: list[dict[str, Any]]  # accepted, in order
    possible: list[dict[str, Any]]  # not accepted, largest gain first
    sensor_effects: list[dict[str, Any]]
    unexplained: list[dict[str, Any]]
    warnings: list[BrokenTest]  # tests left out of the fits
    left_out: dict[str, Any]  # the fits with and without them ({} when none)
    final: ModelFit
    setups: list[Setup]
    model: str  # file names in the output folder
    baseline_model: str
    software_version: str
    estimation: list[str]  # test names
    validation: list[str]
    residual_tests: dict[str, dict[str, dict[str, float]]]  # baseline, final: per output
    first_ranking: list[dict[str, Any]]
    history: list[dict[str, Any]]  # one step per round of candidates
    settings: dict[str, Any]
    validation_tests: dict[str, dict[str, OutputFits]]  # baseline, final: per test
    criteria: dict[str, dict[str, CriteriaComparison]]  # baseline, final: per test
    iso18571: dict[str, IsoRatings] | None  # baseline, final (None: not rated)
    seconds: float  # the loop's run time [s]

    def as_dict(self) -> dict[str, Any]:
        return {
            "baseline": self.baseline.as_dict(), "effects": self.effects,
            "possible": self.possible, "sensor_effects": self.sensor_effects,
            "unexplained": self.unexplained, "warnings": [w.as_dict() for w in self.warnings],
            "left_out": self.left_out, "final": self.final.as_dict(),
            "setups": [s.as_dict() for s in self.setups], "model": self.model,
            "baseline_model": self.baseline_model, "software_version": self.software_version,
            "estimation": self.estimation, "validation": self.validation,
            "residual_tests": self.residual_tests, "first_ranking": self.first_ranking,
            "history": self.history, "settings": self.settings,
            "validation_tests": {k: {n: f.as_dict() for n, f in v.items()}
                                 for k, v in self.validation_tests.items()},
            "criteria": {k: {n: c.as_dict() for n, c in v.items()}
                         for k, v in self.criteria.items()},
            **({"iso18571": {k: v.as_dict() for k, v in self.iso18571.items()}}
               if self.iso18571 is not None else {}),
            "seconds": self.seconds,
        }
