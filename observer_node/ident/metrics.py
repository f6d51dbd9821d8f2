"""The thesis's fit measure, eq. 3.15-3.18."""

from __future__ import annotations

import numpy as np

OUTPUT_NAMES = ("cr", "cd")


def fit_percent(y: np.ndarray, y_hat: np.ndarray) -> float:
    """Eq. 3.15: 100 * (1 - ||y - y_hat|| / ||y - mean(y)||), 2-norms over the samples given."""
    denom = np.linalg.norm(y - np.mean(y))
    if denom == 0:
        return float("nan")
    return float(100.0 * (1.0 - np.linalg.norm(y - y_hat) / denom))


def fit_table(names: list[str], y: np.ndarray, y_hat: np.ndarray) -> dict:
    """Fits per test and output and the totals of eq. 3.16-3.18.

    ``y`` and ``y_hat`` are (tests, n, 2) already cut to the scoring window. Returns
    ``{"fit": {"cr", "cd", "total"}, "tests": {name: {"cr", "cd"}}}``.
    """
    tests = {
        name: {o: fit_percent(y[i, :, k], y_hat[i, :, k]) for k, o in enumerate(OUTPUT_NAMES)}
        for i, name in enumerate(names)
    }
    cr = float(np.mean([v["cr"] for v in tests.values()]))
    cd = float(np.mean([v["cd"] for v in tests.values()]))
    return {"fit": {"cr": cr, "cd": cd, "total": (cr + cd) / 2}, "tests": tests}
