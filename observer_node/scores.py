"""Everything a model's estimates are judged by, on a dataset: the thesis's fit (eq.
3.15-3.18), the chest injury criteria of estimate and reference with their errors
(:mod:`.criteria`) and the ISO/TS 18571 ratings (:mod:`.iso18571`, optional package)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import iso18571
from .criteria import CriteriaComparison, criteria_table
from .ident.dataset import Dataset
from .ident.metrics import FitTable, fit_table
from .iso18571 import IsoRatings


@dataclass(frozen=True)
class Scores(FitTable):
    """The fits (:class:`FitTable`), per test the chest criteria of estimate and reference,
    and the ISO/TS 18571 ratings (None: not asked for, or the package is not installed)."""

    criteria: dict[str, CriteriaComparison]
    iso18571: IsoRatings | None = None

    def as_dict(self) -> dict[str, dict]:
        out = {**super().as_dict(),
               "criteria": {n: c.as_dict() for n, c in self.criteria.items()}}
        if self.iso18571 is not None:
            out["iso18571"] = self.iso18571.as_dict()
        return out


def scores(data: Dataset, y_hat: np.ndarray, ratings: bool = True) -> Scores:
    """Everything a model's outputs ``y_hat`` (tests, n, 2) are judged by on ``data``: the fit
    (eq. 3.15-3.18) on the window, the chest injury criteria of estimate and reference with
    their errors (from t = 0, :mod:`.criteria`) and, with ``ratings`` and the optional package,
    the ISO/TS 18571 ratings on the window (:mod:`.iso18571`)."""
    fits = fit_table(data.names, data.y[:, data.win], y_hat[:, data.win])
    table = iso18571.rating_table(data.names, data.y[:, data.win], y_hat[:, data.win],
                                  data.fs_hz) if ratings else None
    return Scores(fits.fit, fits.tests, criteria_table(data.names, data.y, y_hat, data.fs_hz),
                  table)


def mean_abs_errors(criteria: dict) -> dict[str, float]:
    """Mean over tests of |estimate - reference| per criterion, of criteria as reported
    (:meth:`CriteriaComparison.as_dict` per test)."""
    keys = ("cd_max_mm", "cr_3ms_g", "vc_max_m_s")
    return {k: float(np.mean([abs(c["error"][k]) for c in criteria.values()])) for k in keys}
