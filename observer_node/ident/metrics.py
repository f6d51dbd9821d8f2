"""The thesis's fit measure, eq. 3.15-3.18."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

OUTPUT_NAMES = ("cr", "cd")


def fit_percent(y: np.ndarray, y_hat: np.ndarray) -> float:
    """Eq. 3.15: 100 * (1 - ||y - y_hat|| / ||y - mean(y)||), 2-norms over the samples given."""
    denom = np.linalg.norm(y - np.mean(y))
    if denom == 0:
        return float("nan")
    return float(100.0 * (1.0 - np.linalg.norm(y - y_hat) / denom))


@dataclass(frozen=True)
class OutputFits:
    """The fit [%] (eq. 3.15) of each output: chest acceleration CR, chest deflection CD."""

    cr: float
    cd: float

    @property
    def total(self) -> float:
        """fit_TOT [%]: CR and CD averaged (eq. 3.18)."""
        return (self.cr + self.cd) / 2

    def as_dict(self) -> dict[str, float]:
        return {"cr": self.cr, "cd": self.cd}


@dataclass(frozen=True)
class Fits:
    """The fits [%] of CR and CD and their mean fit_TOT (eq. 3.15-3.18)."""

    cr: float
    cd: float
    total: float

    @classmethod
    def of(cls, cr: float, cd: float) -> Fits:
        return cls(cr, cd, (cr + cd) / 2)

    def as_dict(self) -> dict[str, float]:
        return {"cr": self.cr, "cd": self.cd, "total": self.total}


@dataclass(frozen=True)
class FitTable:
    """The fits over a set of tests (eq. 3.16-3.18) and each test's (eq. 3.15)."""

    fit: Fits
    tests: dict[str, OutputFits]

    def as_dict(self) -> dict[str, dict]:
        return {"fit": self.fit.as_dict(),
                "tests": {n: v.as_dict() for n, v in self.tests.items()}}

    def by_group(self, group_of: dict[str, str]) -> dict[str, tuple[int, Fits]]:
        """Per group (a setup), its number of tests and its fits, eq. 3.16-3.18 over its tests
        alone; ``group_of`` maps each test's name to its group."""
        groups: dict[str, list[OutputFits]] = {}
        for name, v in self.tests.items():
            groups.setdefault(group_of[name], []).append(v)
        return {g: (len(vs), Fits.of(float(np.mean([v.cr for v in vs])),
                                      float(np.mean([v.cd for v in vs]))))
                for g, vs in groups.items()}


def fit_table(names: list[str], y: np.ndarray, y_hat: np.ndarray) -> FitTable:
    """Fits per test and output and the totals of eq. 3.16-3.18. ``y`` and ``y_hat`` are
    (tests, n, 2) (CR, CD) already cut to the scoring window."""
    tests = {name: OutputFits(fit_percent(y[i, :, 0], y_hat[i, :, 0]),
                              fit_percent(y[i, :, 1], y_hat[i, :, 1]))
             for i, name in enumerate(names)}
    cr = float(np.mean([v.cr for v in tests.values()]))
    cd = float(np.mean([v.cd for v in tests.values()]))
    return FitTable(Fits.of(cr, cd), tests)
