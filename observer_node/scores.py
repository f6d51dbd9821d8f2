"""Everything a model's estimates are judged by, on a dataset: the thesis's fit (eq.
3.15-3.18), the chest injury criteria of estimate and reference with their errors
(:mod:`.criteria`) and the ISO/TS 18571 ratings (:mod:`.iso18571`, optional package)."""

from __future__ import annotations

import numpy as np

from . import iso18571
from .criteria import criteria_table
from .ident.dataset import Dataset
from .ident.metrics import fit_table


def scores(data: Dataset, y_hat: np.ndarray, ratings: bool = True) -> dict:
    """Everything a model's outputs ``y_hat`` (tests, n, 2) are judged by on ``data``: the fit
    (eq. 3.15-3.18) on the window, the chest injury criteria of estimate and reference with
    their errors (from t = 0, :mod:`.criteria`) and, with ``ratings`` and the optional package,
    the ISO/TS 18571 ratings on the window (:mod:`.iso18571`)."""
    fits = fit_table(data.names, data.y[:, data.win], y_hat[:, data.win])
    fits["criteria"] = criteria_table(data.names, data.y, y_hat, data.fs_hz)
    table = iso18571.rating_table(data.names, data.y[:, data.win], y_hat[:, data.win],
                                  data.fs_hz) if ratings else None
    if table is not None:
        fits["iso18571"] = {"tests": table, "mean_overall": iso18571.mean_overall(table)}
    return fits


def mean_abs_errors(criteria: dict) -> dict[str, float]:
    """Mean over tests of |estimate - reference| per criterion."""
    keys = ("cd_max_mm", "cr_3ms_g", "vc_max_m_s")
    return {k: float(np.mean([abs(c["error"][k]) for c in criteria.values()])) for k in keys}
