"""Prediction-error estimation of the thesis's grey-box chest (eq. 3.12-3.14).

The model itself (eq. 3.1-3.8: states, matrices, discretisation) is
:mod:`observer_node.model.chest`.

Identifiability: multiplying every mass, stiffness and damping by the same factor leaves both
outputs unchanged, so only six of the seven parameters can be estimated. m1 is fixed (default
20 kg, an effective upper-torso mass) and the other five mechanical parameters are estimated
relative to it, with R; standard errors come from the Jacobian of the weighted residual.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import optimize

from ..model.chest import PARAM_NAMES, PARAM_UNITS, THESIS_STATES, discrete_thesis
from ..model.modelfile import ModelFile
from ..model.observer import simulate_ss, transform_inputs
from .dataset import Dataset
from .metrics import FitTable, fit_table
from .progress import Progress

FREE = ("k1", "c1", "k2", "c2", "m2", "R")
DEFAULT_M1_KG = 20.0
TRANSFORM = "velocity_brs_rate"


def simulate(p: dict[str, float], data: Dataset) -> np.ndarray:
    """Outputs (tests, n, 2) of the grey-box model on ``data`` from rest at t = 0."""
    Ad, Bd, C, D = discrete_thesis(p, data.fs_hz)
    u = transform_inputs(TRANSFORM, data.pulse_g, data.brs_rad, data.fs_hz)
    return simulate_ss(Ad, Bd, C, D, u)


@dataclass
class GreyBoxFit:
    params: dict[str, float]
    std_err: dict[str, float]
    cost: float
    n_eval: int
    fits: FitTable  # on the data it was fitted on


# Several starts because the cost has local minima (the two modes can swap roles).
STARTS = (
    {"k1": 2e5, "c1": 1e3, "k2": 5e5, "c2": 2e3, "m2": 2.0, "R": 0.03},
    {"k1": 5e4, "c1": 300.0, "k2": 2e5, "c2": 500.0, "m2": 0.5, "R": 0.02},
    {"k1": 8e5, "c1": 4e3, "k2": 1e6, "c2": 8e3, "m2": 8.0, "R": 0.05},
)


def fit_greybox(data: Dataset, m1_kg: float = DEFAULT_M1_KG,
                starts: tuple[dict[str, float], ...] = STARTS,
                progress: Progress | None = None, max_nfev: int = 400) -> GreyBoxFit:
    """Output-error (simulation) prediction-error fit, eq. 3.12-3.14, over all experiments.

    Each test's output is weighted by 1/||y - mean(y)|| over the window, so the cost is the
    sum of (1 - fit/100)^2 of eq. 3.15 and CR in g and CD in mm weigh alike (Q of eq. 3.13).
    Parameters are estimated as logarithms (they are all positive).
    """
    y = data.y[:, data.win]
    scale = 1.0 / np.linalg.norm(y - y.mean(axis=1, keepdims=True), axis=1)  # (tests, 2)
    evals = [0]
    best = [np.inf]

    def unpack(theta: np.ndarray) -> dict[str, float]:
        p = dict(zip(FREE, np.exp(theta), strict=False))
        p["m1"] = m1_kg
        return p

    def residual(theta: np.ndarray) -> np.ndarray:
        evals[0] += 1
        # a trial step may make the chest unstable: its run-away is refused below, quietly
        # (numpy's overflow warnings said nothing to the user but alarm)
        with np.errstate(over="ignore", invalid="ignore"):
            y_hat = simulate(unpack(theta), data)[:, data.win]
            r = ((y_hat - y) * scale[:, None, :]).ravel()
        if not np.all(np.isfinite(r)):
            return np.full(r.shape, 1e3)
        c = float(r @ r)
        if c < best[0]:
            best[0] = c
        if progress:
            progress.update(f"{evals[0]} simulations, best cost {best[0]:.4g}")
        return r

    results = []
    for s in starts:
        theta0 = np.log([s[n] for n in FREE])
        results.append(optimize.least_squares(residual, theta0, method="trf", x_scale=1.0,
                                              max_nfev=max_nfev))
    res = min(results, key=lambda r: r.cost)
    params = unpack(res.x)
    # Standard errors from the Jacobian (Gauss-Newton covariance), log-parameters -> delta method
    J = res.jac
    dof = max(J.shape[0] - J.shape[1], 1)
    s2 = 2 * res.cost / dof
    cov = s2 * np.linalg.pinv(J.T @ J)
    se = {n: float(params[n] * np.sqrt(max(cov[i, i], 0.0))) for i, n in enumerate(FREE)}
    se["m1"] = 0.0
    fits = fit_table(data.names, y, simulate(params, data)[:, data.win])
    if progress:
        progress.done(f"{evals[0]} simulations, fit total {fits.fit.total:.1f} %")
    return GreyBoxFit(params, se, float(2 * res.cost), evals[0], fits)


def to_model_file(fit: GreyBoxFit, data: Dataset, name: str = "greybox",
                  tick_rate_hz: float | None = None) -> ModelFile:
    """Model file at ``tick_rate_hz`` (default: the rate it was fitted at)."""
    rate = tick_rate_hz or data.fs_hz
    Ad, Bd, C, D = discrete_thesis(fit.params, rate)
    return ModelFile(
        kind="greybox", name=name, tick_rate_hz=rate, input_transform=TRANSFORM,
        A=Ad, B=Bd, C=C, D=D,
        parameters={n: {"value": fit.params[n], "std_err": fit.std_err[n],
                        "unit": PARAM_UNITS[n], "fixed": n == "m1"} for n in PARAM_NAMES},
        structure={"states": list(THESIS_STATES), "equations": "thesis eq. 3.1-3.8, CD = s - x",
                   "fixed": {"m1": "overall mass scale is not identifiable from CR and CD"}},
        fitted_on=_fitted_on(data),
        fits=fit.fits.as_dict(), output_timing="after_input",
    )


def _fitted_on(data: Dataset) -> dict:
    return {"tests": data.names, "setups": sorted(set(data.setups)), "rate_hz": data.fs_hz,
            "window_s": list(data.window_s), "simulation_start_s": 0.0}
