"""Chest injury criteria of a frontal crash, as restraint engineers decide by.

Plain functions over arrays at a uniform sample rate ``fs_hz``, in the model's convention
(chest acceleration CR in g, deceleration positive; chest deflection CD in mm, compression
positive; see :mod:`observer_node.data.crashtest`):

- **peak chest deflection** [mm]: the largest compression, the Hybrid III 50th's frontal
  chest criterion in ECE R94 and Euro NCAP.
- **chest acceleration 3 ms clip** [g]: the highest level the acceleration exceeds for a
  cumulative 3 ms (FMVSS 208 S6.3: "except for intervals whose cumulative duration is not
  more than 3 milliseconds"), or, with ``cumulative=False``, for 3 ms without a break (the
  "continuous" variant some tools report). Here of the X acceleration CR, the one the
  observer estimates; the regulations apply it to the resultant.
- **viscous criterion VC max** [m/s] (Lau and Viano): the largest product of the
  compression velocity and the compression ratio, VC(t) = SF * V(t) * D(t) / D0, with the
  Hybrid III 50th's constants SF = 1.3 and D0 = 0.229 m (ECE R94 Annex 4 section 6 and SAE
  J1727; Euro NCAP Technical Bulletin TB 021). D is the deflection filtered with CFC 180 (SAE
  J211-1), V its derivative by the five-point central difference of ECE R94 Annex 4:
  V(t) = (8 (D[t+1] - D[t-1]) - (D[t+2] - D[t-2])) / (12 dt).

Limits (Hybrid III 50th, frontal): Euro NCAP's Adult Occupant Protection protocol (v8.0.3,
2018) scores chest compression from 22 mm (higher performance limit, full points) to 42 mm
(lower performance limit, none) and VC from 0.5 to 1.0 m/s; ECE R94 requires compression
<= 50 mm and VC <= 1.0 m/s. FMVSS 208 limits the 3 ms clip of the resultant to 60 g.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from .data.filters import cfc_filter, cfc_min_rate_hz

VC_SCALE_HIII50 = 1.3  # SF, ECE R94 Annex 4 / SAE J1727
VC_DEFORMATION_HIII50_M = 0.229  # D0 [m], ECE R94 Annex 4 / SAE J1727
EURO_NCAP_CD_LIMITS_MM = (22.0, 42.0)  # higher, lower performance limit (AOP v8.0.3)
EURO_NCAP_VC_LIMITS_M_S = (0.5, 1.0)
ECE_R94_CD_MAX_MM = 50.0
ECE_R94_VC_MAX_M_S = 1.0
FMVSS208_CLIP_MAX_G = 60.0


def peak_deflection_mm(cd_mm: np.ndarray) -> float:
    """The largest chest compression [mm] (0 if the chest never compresses)."""
    return max(float(np.max(cd_mm)), 0.0) if len(cd_mm) else math.nan


def clip_3ms_g(cr_g: np.ndarray, fs_hz: float, cumulative: bool = True,
               duration_s: float = 0.003) -> float:
    """The highest acceleration [g] exceeded for ``duration_s`` in all (``cumulative``) or
    without a break. Each sample stands for 1/fs_hz s, so a cumulative 3 ms is the
    round(3 ms * fs_hz)-th largest sample; a continuous 3 ms spans that many samples."""
    n = max(round(duration_s * fs_hz), 1)
    a = np.asarray(cr_g, dtype=float)
    if len(a) < n:
        return math.nan
    if cumulative:
        return float(np.partition(a, len(a) - n)[len(a) - n])
    return float(np.lib.stride_tricks.sliding_window_view(a, n).min(axis=1).max())


def viscous_criterion_m_s(cd_mm: np.ndarray, fs_hz: float, filtered: bool = False) -> float:
    """VC max [m/s] of a deflection [mm] at ``fs_hz``; ``filtered``: the deflection is
    already CFC 180 (else it is filtered here). NaN (undefined) under 5 samples, or at a rate
    CFC 180 cannot be applied at (748 Hz and below: the regulation's VC is not defined
    there, and the filter would be unstable)."""
    d_m = np.asarray(cd_mm, dtype=float) / 1000.0
    if len(d_m) < 5 or (not filtered and fs_hz <= cfc_min_rate_hz(180)):
        return math.nan
    if not filtered:
        d_m = cfc_filter(d_m, fs_hz, 180)
    v = np.zeros_like(d_m)
    v[2:-2] = (8 * (d_m[3:-1] - d_m[1:-3]) - (d_m[4:] - d_m[:-4])) * fs_hz / 12
    return max(float(np.max(VC_SCALE_HIII50 * v * d_m / VC_DEFORMATION_HIII50_M)), 0.0)


@dataclass(frozen=True)
class ChestCriteria:
    """The three chest criteria of one test (see the module docstring)."""

    cd_max_mm: float
    cr_3ms_g: float
    vc_max_m_s: float

    @property
    def complete(self) -> bool:
        """All three are defined (NaN: a window too short for one, e.g. under 5 samples)."""
        return all(math.isfinite(v) for v in (self.cd_max_mm, self.cr_3ms_g, self.vc_max_m_s))

    def as_dict(self) -> dict[str, float]:
        return {k: round(v, 4) for k, v in asdict(self).items()}


UNITS = {"cd_max_mm": "mm", "cr_3ms_g": "g", "vc_max_m_s": "m/s"}
LABELS = {"cd_max_mm": "CD max", "cr_3ms_g": "CR 3 ms", "vc_max_m_s": "VC max"}


def chest_criteria(cr_g: np.ndarray, cd_mm: np.ndarray, fs_hz: float) -> ChestCriteria:
    """The criteria of one test's CR [g] and CD [mm] at ``fs_hz``."""
    return ChestCriteria(peak_deflection_mm(cd_mm), clip_3ms_g(cr_g, fs_hz),
                         viscous_criterion_m_s(cd_mm, fs_hz))


@dataclass(frozen=True)
class CriteriaComparison:
    """The criteria of an estimate beside the reference's (None: no reference frames)."""

    estimate: ChestCriteria
    reference: ChestCriteria | None = None

    @property
    def error(self) -> ChestCriteria:
        """Estimate - reference in each criterion's unit, of the rounded values reported."""
        if self.reference is None:
            raise ValueError("no reference: no error")
        e, r = self.estimate.as_dict(), self.reference.as_dict()
        return ChestCriteria(**{k: round(e[k] - r[k], 4) for k in e})

    def as_dict(self) -> dict[str, dict[str, float]]:
        if self.reference is None:
            return {"estimate": self.estimate.as_dict()}
        return {"estimate": self.estimate.as_dict(), "reference": self.reference.as_dict(),
                "error": asdict(self.error)}


def compare(estimate: ChestCriteria, reference: ChestCriteria) -> CriteriaComparison:
    """Estimate, reference and error (estimate - reference, in each criterion's unit)."""
    return CriteriaComparison(estimate, reference)


def criteria_table(names: list[str], y: np.ndarray, y_hat: np.ndarray,
                   fs_hz: float) -> dict[str, CriteriaComparison]:
    """Per test: the criteria of the estimate ``y_hat`` beside the reference ``y`` and their
    errors. y, y_hat: (tests, n, 2) with CR [g] and CD [mm], from t = 0."""
    return {name: compare(chest_criteria(y_hat[k, :, 0], y_hat[k, :, 1], fs_hz),
                          chest_criteria(y[k, :, 0], y[k, :, 1], fs_hz))
            for k, name in enumerate(names)}


def format_criteria(table: dict[str, CriteriaComparison], indent: str = "  ") -> str:
    """A text table: per test, each criterion estimated, measured, and the error."""
    w = max([12, *map(len, table)])  # a long test name widens the column
    head = f"{indent}{'test':<{w}}" + "".join(
        f"{LABELS[k] + ' [' + u + ']':>26}" for k, u in UNITS.items())
    sub = f"{indent}{'':<{w}}" + "".join(f"{'est':>9}{'ref':>8}{'err':>9}" for _ in UNITS)
    lines = [head, sub]
    for name, comparison in table.items():
        c = comparison.as_dict()
        lines.append(f"{indent}{name:<{w}}" + "".join(
            f"{c['estimate'][k]:>9.{p}f}{c['reference'][k]:>8.{p}f}{c['error'][k]:>+9.{p}f}"
            for k, p in (("cd_max_mm", 1), ("cr_3ms_g", 1), ("vc_max_m_s", 2))))
    return "\n".join(lines)
