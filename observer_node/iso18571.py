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


def rate(reference: np.ndarray, estimate: np.ndarray, fs_hz: float) -> dict[str, float]:
    """ISO/TS 18571 ratings of ``estimate`` against ``reference`` (1-D, same length, at
    ``fs_hz``): overall, corridor, phase, magnitude, slope, each 0..1."""
    from objective_rating_metrics.rating import ISO18571

    n = len(reference)
    t = np.arange(n) / fs_hz
    t10 = np.arange(round((n - 1) * FS_HZ / fs_hz) + 1) / FS_HZ
    ref = np.column_stack([t10, np.interp(t10, t, reference)])
    est = np.column_stack([t10, np.interp(t10, t, estimate)])
    r = ISO18571(ref, est)
    return {"overall": float(r.overall_rating()), "corridor": float(r.corridor_rating()),
            "phase": float(r.phase_rating()), "magnitude": float(r.magnitude_rating()),
            "slope": float(r.slope_rating())}


def rating_table(names: list[str], y: np.ndarray, y_hat: np.ndarray,
                 fs_hz: float) -> dict[str, dict[str, dict[str, float]]] | None:
    """Per test and output (cr, cd): the ratings of ``y_hat`` against ``y`` (tests, n, 2) on
    the scored window; None when the package is not installed."""
    if not available():
        return None
    return {name: {key: rate(y[k, :, j], y_hat[k, :, j], fs_hz)
                   for j, key in enumerate(("cr", "cd"))}
            for k, name in enumerate(names)}


def mean_overall(table: dict[str, dict[str, dict[str, float]]]) -> dict[str, float]:
    """Mean overall rating per output over the tests."""
    return {key: round(float(np.mean([t[key]["overall"] for t in table.values()])), 3)
            for key in ("cr", "cd")}
