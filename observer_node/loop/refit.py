"""Re-estimating the grey-box parameters together with added effects (a non-linear model,
simulated as such, vectorised over tests), and cross-validation inside the estimation set."""

from __future__ import annotations

import numpy as np
from scipy import optimize

from ..ident.dataset import Dataset
from ..ident.greybox import FREE
from ..ident.metrics import fit_table
from ..model.effects import EFFECTS, POSITIVE
from ..model.nonlinear import NonlinearGreyBox
from .analysis import weights

# Parameters not fitted by least squares (integers, set by the candidate search)
FIXED = {"input_delay": ("n_pulse", "n_brs")}


def _layout(effects: list[dict]) -> list[tuple[int, str, float]]:
    """(effect index, parameter, scale) of every fitted effect parameter."""
    out = []
    for i, e in enumerate(effects):
        if e["kind"] == "other":
            for where in ("rib", "belt"):
                for term, v in e["parameters"].get(where, {}).items():
                    out.append((i, f"{where}:{term}", max(abs(v), 1e-12)))
            continue
        for name, (_, mag) in EFFECTS[e["kind"]][1].items():
            if name not in FIXED.get(e["kind"], ()):
                out.append((i, name, mag))
    return out


def _set(effects: list[dict], i: int, name: str, value: float) -> None:
    if ":" in name:
        where, term = name.split(":", 1)
        effects[i]["parameters"][where][term] = value
    else:
        effects[i]["parameters"][name] = value


def _get(effects: list[dict], i: int, name: str) -> float:
    if ":" in name:
        where, term = name.split(":", 1)
        return effects[i]["parameters"][where][term]
    return effects[i]["parameters"][name]


def refit(base: dict, effects: list[dict], data: Dataset, max_nfev: int = 60
          ) -> tuple[dict, list[dict], float]:
    """Least squares over the free base parameters (as logs) and the effect parameters (scaled),
    output-error, weighted as the thesis's fit. Returns (base, effects, cost)."""
    effects = [{"kind": e["kind"], "parameters": _copy(e["parameters"])} for e in effects]
    layout = _layout(effects)
    w = weights(data)
    y = data.y[:, data.win]
    m1 = base["m1"]

    def unpack(theta: np.ndarray) -> tuple[dict, list[dict]]:
        b = dict(zip(FREE, np.exp(theta[:len(FREE)]), strict=False))
        b["m1"] = m1
        for (i, name, scale), v in zip(layout, theta[len(FREE):], strict=True):
            _set(effects, i, name, abs(v * scale) if name in POSITIVE else v * scale)
        return b, effects

    def residual(theta: np.ndarray) -> np.ndarray:
        b, eff = unpack(theta)
        with np.errstate(all="ignore"):
            y_hat = NonlinearGreyBox(b, eff, data.fs_hz).simulate(data.pulse_g, data.brs_rad)
        r = ((y_hat[:, data.win] - y) * w[:, None, :]).ravel()
        return np.where(np.isfinite(r), r, 1e3)

    theta0 = np.concatenate([np.log([base[n] for n in FREE]),
                             [_get(effects, i, n) / s for i, n, s in layout]])
    res = optimize.least_squares(residual, theta0, method="trf", max_nfev=max_nfev)
    b, eff = unpack(res.x)
    return b, [{"kind": e["kind"], "parameters": _copy(e["parameters"])} for e in eff], \
        float(2 * res.cost)


def _copy(p: dict) -> dict:
    return {k: (dict(v) if isinstance(v, dict) else v) for k, v in p.items()}


def score(base: dict, effects: list[dict], data: Dataset) -> dict:
    """The thesis's fit (eq. 3.15-3.18) of a model on ``data``."""
    with np.errstate(all="ignore"):
        y_hat = NonlinearGreyBox(base, effects, data.fs_hz).simulate(data.pulse_g, data.brs_rad)
    t = fit_table(data.names, data.y[:, data.win], y_hat[:, data.win])
    for k in ("cr", "cd", "total"):
        if not np.isfinite(t["fit"][k]):
            t["fit"][k] = -1e3
    return t


def cross_validate(base: dict, effects: list[dict], data: Dataset, max_nfev: int = 60) -> float:
    """Two-fold cross-validation inside the estimation tests (alternating split): fit on one
    half, score fit_TOT on the other, both ways; the mean."""
    idx = list(range(data.n_tests))
    folds = [idx[0::2], idx[1::2]] if len(idx) >= 2 else [idx, idx]
    scores = []
    for train, test in ((folds[0], folds[1]), (folds[1], folds[0])):
        b, eff, _ = refit(base, effects, data.subset(train), max_nfev)
        scores.append(score(b, eff, data.subset(test))["fit"]["total"])
    return float(np.mean(scores))
