"""ISO/TS 18571 objective rating of an estimated curve against the measured one, beside the
thesis's fit.

The fit of eq. 3.15 is one number for the whole error's size. ISO/TS 18571, the standard crash
simulation is validated by, rates four things from 0 (no match) to 1 (identical): the
**corridor** score (how much of the estimate stays inside corridors around the measurement),
**phase** (the time shift that best aligns the two), **magnitude** (the amplitude error once
aligned, by dynamic time warping) and **slope** (the shape of the derivative); the overall
rating weights them 0.4 / 0.2 / 0.2 / 0.2. ISO/TS 18571 grades an overall rating above 0.94
"excellent", above 0.8 "good", above 0.58 "fair", else "poor".

The rating is the `objective-rating-metrics` package's implementation (TU Graz; an optional
extra: ``pip install chest-observer[iso18571]``). It wants both curves at 10 kHz; curves at
the tick rate are interpolated linearly onto a 10 kHz grid. Its first rating in a process
compiles (numba), which takes some seconds.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

FS_HZ = 10_000.0  # the standard's sample rate
GRADES = ((0.94, "excellent"), (0.8, "good"), (0.58, "fair"), (0.0, "poor"))


def available() -> bool:
    """True when the optional package is installed."""
    try:
        import objective_rating_metrics.rating  # noqa: F401
    except ImportError:
        return False
    return True


def grade(rating: float) -> str:
    return next(name for low, name in GRADES if rating > low or low == 0.0)


@dataclass(frozen=True)
class Rating:
    """The ISO/TS 18571 ratings of one estimated curve against the measured one, each 0..1."""

    overall: float
    corridor: float
    phase: float
    magnitude: float
    slope: float

    def as_dict(self) -> dict[str, float]:
        return {"overall": self.overall, "corridor": self.corridor, "phase": self.phase,
                "magnitude": self.magnitude, "slope": self.slope}

    @classmethod
    def from_dict(cls, d: dict[str, float]) -> Rating:
        return cls(d["overall"], d["corridor"], d["phase"], d["magnitude"], d["slope"])


@dataclass(frozen=True)
class OutputRatings:
    """The ratings of each output: chest acceleration CR, chest deflection CD."""

    cr: Rating
    cd: Rating

    def as_dict(self) -> dict[str, dict[str, float]]:
        return {"cr": self.cr.as_dict(), "cd": self.cd.as_dict()}

    @classmethod
    def from_dict(cls, d: dict[str, dict[str, float]]) -> OutputRatings:
        return cls(Rating.from_dict(d["cr"]), Rating.from_dict(d["cd"]))


@dataclass(frozen=True)
class MeanOverall:
    """The mean overall rating (0..1, rounded to 0.001) of each output over a set of tests."""

    cr: float
    cd: float

    def as_dict(self) -> dict[str, float]:
        return {"cr": self.cr, "cd": self.cd}


@dataclass(frozen=True)
class IsoRatings:
    """The ratings of each test's outputs, and the mean overall rating per output."""

    tests: dict[str, OutputRatings]
    mean_overall: MeanOverall

    @classmethod
    def of(cls, tests: dict[str, OutputRatings]) -> IsoRatings:
        return cls(tests, MeanOverall(
            round(float(np.mean([t.cr.overall for t in tests.values()])), 3),
            round(float(np.mean([t.cd.overall for t in tests.values()])), 3)))

    def as_dict(self) -> dict[str, Any]:
        return {"tests": {n: t.as_dict() for n, t in self.tests.items()},
                "mean_overall": self.mean_overall.as_dict()}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> IsoRatings:
        """The ``iso18571`` object of fits.json, evaluation.json or report.json, read back."""
        return cls({n: OutputRatings.from_dict(t) for n, t in d["tests"].items()},
                   MeanOverall(d["mean_overall"]["cr"], d["mean_overall"]["cd"]))


def rate(reference: np.ndarray, estimate: np.ndarray, fs_hz: float) -> Rating:
    """ISO/TS 18571 ratings of ``estimate`` against ``reference`` (1-D, same length, at
    ``fs_hz``): overall, corridor, phase, magnitude, slope, each 0..1."""
    from objective_rating_metrics.rating import ISO18571

    n = len(reference)
    t = np.arange(n) / fs_hz
    t10 = np.arange(round((n - 1) * FS_HZ / fs_hz) + 1) / FS_HZ
    ref = np.column_stack([t10, np.interp(t10, t, reference)])
    est = np.column_stack([t10, np.interp(t10, t, estimate)])
    r = ISO18571(ref, est)
    return Rating(float(r.overall_rating()), float(r.corridor_rating()),
                  float(r.phase_rating()), float(r.magnitude_rating()), float(r.slope_rating()))


def rate_outputs(y: np.ndarray, y_hat: np.ndarray, fs_hz: float) -> OutputRatings:
    """The ratings of ``y_hat`` against ``y`` (n, 2: CR, CD)."""
    return OutputRatings(rate(y[:, 0], y_hat[:, 0], fs_hz), rate(y[:, 1], y_hat[:, 1], fs_hz))


def rating_table(names: list[str], y: np.ndarray, y_hat: np.ndarray,
                 fs_hz: float) -> IsoRatings | None:
    """Per test: the ratings of ``y_hat`` against ``y`` (tests, n, 2) on the scored window,
    and their mean overall rating per output; None when the package is not installed."""
    if not available():
        return None
    return IsoRatings.of({name: rate_outputs(y[k], y_hat[k], fs_hz)
                          for k, name in enumerate(names)})
