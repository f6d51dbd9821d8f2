"""Re-estimating the grey-box parameters together with added effects (a non-linear model,
simulated as such, vectorised over tests), and cross-validation inside the estimation set.

Effects may be scoped to setups (``"setups"``): every simulation here runs each test with its
own setup (``Dataset.setups``)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np
from scipy import optimize

from ..ident.dataset import Dataset
from ..ident.greybox import FREE, STARTS
from ..ident.metrics import OUTPUT_NAMES, Fits, FitTable, fit_table
from ..model.effects import EFFECTS
from ..model.nonlinear import NonlinearGreyBox, simulate_many
from .analysis import weights, within_free, within_value


def model(base: dict, effects: list[dict], data: Dataset) -> NonlinearGreyBox:
    """The model with effects, set up to simulate ``data``'s tests each with its setup."""
    return NonlinearGreyBox(base, effects, data.fs_hz, list(data.setups))


@dataclass
class Refit:
    """A refit: base and effect parameters, the cost, standard errors (same shapes), and
    whether the optimiser took any step from its start (``moved``)."""

    base: dict[str, float]
    effects: list[dict]
    cost: float
    base_std_err: dict[str, float]
    effect_std_err: list[dict[str, float]]
    moved: bool = True


class _Slot(NamedTuple):
    """One fitted effect parameter: its effect's index, name, scale, whether it must be
    positive, and the range it must stay within (fitted as lo + (hi - lo) (1 + tanh) / 2).

    A positive size is fitted as v * scale with the optimiser's bound v >= 0, not as |v|: the
    kink of |v| at 0 made trf reject every step from a fit near it, so a fold's refit never
    left the all-test fit and scored its held-out test in-sample (docs/loop-evidence.md,
    "Folds that stall")."""

    i: int
    name: str
    scale: float
    positive: bool
    within: tuple[float, float] | None = None

    def value(self, v: float) -> float:
        if self.within is not None:
            return within_value(self.within, v)
        return v * self.scale

    @property
    def lower(self) -> float:
        """The fitted variable's lower bound."""
        return 0.0 if self.positive and self.within is None else -np.inf

    def free(self, value: float) -> float:
        """The fitted variable of ``value``."""
        if self.within is not None:
            return within_free(self.within, value)
        return value / self.scale

    def std_err(self, v: float, s: float) -> float:
        """The value's standard error from the fitted variable's ``s`` at ``v``."""
        if self.within is not None:
            lo, hi = self.within
            slope = (hi - lo) / 2 * (1 - np.tanh(v) ** 2)  # 0 at the edge, where s may be inf
            return float(slope * s) if slope > 0 or np.isfinite(s) else float("nan")
        return float(self.scale * s)


def _layout(effects: list[dict]) -> list[_Slot]:
    """Every fitted effect parameter."""
    out = []
    for i, e in enumerate(effects):
        effect = EFFECTS[e["kind"]]
        if effect.search.method == "sparse":  # the formula: its terms' coefficients
            for where in ("rib", "belt"):
                for term, v in e["parameters"].get(where, {}).items():
                    out.append(_Slot(i, f"{where}:{term}", max(abs(v), 1e-12), False))
            continue
        # every named parameter is fitted (delays too: fractional ticks)
        out += [_Slot(i, p.name, p.typical, p.positive, p.within) for p in effect.params]
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


def refit(base: dict, effects: list[dict], data: Dataset, max_nfev: int = 60) -> Refit:
    """:func:`refit_from` the current base parameters and from a typical chest (the grey-box's
    first start): an effect can need base parameters far from those the model without it
    chose (a one-sided belt wants a stiff belt, which a linear fit may have traded for a
    heavy sternum), a valley the optimiser does not cross from there. The lower cost wins."""
    first = refit_from(base, effects, data, max_nfev)
    if not effects:
        return first
    prior = {**base, **{n: v for n, v in STARTS[0].items() if n in FREE}}
    try:
        second = refit_from(prior, effects, data, max_nfev)
    except ValueError:  # the optimiser left the finite numbers from there: keep the first
        return first
    return first if first.cost <= second.cost else second


_TINY = np.finfo(float).tiny
#: a positive size's smallest start, in units of its typical size
_INSIDE = 1e-12


def refit_from(base: dict, effects: list[dict], data: Dataset, max_nfev: int = 60) -> Refit:
    """Least squares over the free base parameters (as logs) and the effect parameters (scaled),
    output-error, weighted as the thesis's fit.

    Standard errors come from the Jacobian at the solution, s^2 (J'J)^-1 with s^2 the
    residual variance, as for the base parameters in identification; the residual of filtered
    crash data is coloured, so they are lower bounds."""
    effects = [_copy_effect(e) for e in effects]
    layout = _layout(effects)
    w = weights(data)
    y = data.y[:, data.win]
    m1 = base["m1"]

    def unpack(theta: np.ndarray) -> tuple[dict, list[dict]]:
        b = dict(zip(FREE, np.exp(theta[:len(FREE)]), strict=False))
        b["m1"] = m1
        for slot, v in zip(layout, theta[len(FREE):], strict=True):
            _set(effects, slot.i, slot.name, slot.value(v))
        return b, effects

    def misfit(y_hat: np.ndarray) -> np.ndarray:
        r = ((y_hat[:, data.win] - y) * w[:, None, :]).ravel()
        # a trial that ran away scores as a constant large misfit, not as an overflow
        return np.where(np.isfinite(r) & (np.abs(r) < 1e3), r, 1e3)

    def residual(theta: np.ndarray) -> np.ndarray:
        b, eff = unpack(theta)
        with np.errstate(all="ignore"):
            return misfit(model(b, eff, data).simulate(data.pulse_g, data.brs_rad))

    def jacobian_points(_: object, thetas: Iterable[np.ndarray]) -> list[np.ndarray]:
        """The residuals at the finite-difference Jacobian's points (scipy asks for them
        as a map), as one simulation: each the same as ``residual``'s, to the bit."""
        # copies: unpack() rewrites one list of effects in place, and a model holds its
        # effects' parameter dicts, not copies of them
        models = [model(b, [_copy_effect(e) for e in eff], data)
                  for b, eff in map(unpack, thetas)]
        with np.errstate(all="ignore"):
            return [misfit(y_hat) for y_hat in
                    simulate_many(models, data.pulse_g, data.brs_rad)]

    # a fit may have driven a parameter below exp(-745), to 0.0 (no damping): start from the
    # smallest positive float, not log(0) = -inf, on which the optimiser's SVD meets NaN
    theta0 = np.concatenate([np.log(np.maximum([base[n] for n in FREE], _TINY)),
                             [sl.free(_get(effects, sl.i, sl.name)) for sl in layout]])
    lower = np.concatenate([np.full(len(FREE), -np.inf), [sl.lower for sl in layout]])
    # a size at its bound of 0 is moved just inside it: trf starts strictly within its bounds
    theta0 = np.maximum(theta0, np.where(np.isfinite(lower), _INSIDE, -np.inf))
    res = optimize.least_squares(residual, theta0, method="trf", max_nfev=max_nfev,
                                 workers=jacobian_points, bounds=(lower, np.inf))
    b, eff = unpack(res.x)
    se = _std_errors(res.jac, res.fun)
    base_se = {n: float(b[n] * s) for n, s in zip(FREE, se[:len(FREE)], strict=True)}
    eff_se: list[dict[str, float]] = [{} for _ in eff]
    for slot, v, s in zip(layout, res.x[len(FREE):], se[len(FREE):], strict=True):
        eff_se[slot.i][slot.name] = slot.std_err(v, s)
    return Refit(b, [_copy_effect(e) for e in eff], float(2 * res.cost), base_se, eff_se,
                 moved=bool(np.any(res.x != theta0)))


def _std_errors(jac: np.ndarray, fun: np.ndarray) -> np.ndarray:
    """Standard errors of the fitted variables (inf where the Jacobian says nothing)."""
    m, n = jac.shape
    s2 = float(fun @ fun) / max(m - n, 1)
    with np.errstate(all="ignore"):
        cov = np.linalg.pinv(jac.T @ jac) * s2
    d = np.diag(cov)
    return np.where(d > 0, np.sqrt(np.abs(d)), np.inf)


def _copy(p: dict) -> dict:
    return {k: (dict(v) if isinstance(v, dict) else v) for k, v in p.items()}


def _copy_effect(e: dict) -> dict:
    return {"kind": e["kind"], "parameters": _copy(e["parameters"]),
            **({"setups": list(e["setups"])} if "setups" in e else {})}


def score(base: dict, effects: list[dict], data: Dataset) -> FitTable:
    """The thesis's fit (eq. 3.15-3.18) of a model on ``data``; a total that ran away
    (not finite) scores -1000 %."""
    with np.errstate(all="ignore"):
        y_hat = model(base, effects, data).simulate(data.pulse_g, data.brs_rad)
    t = fit_table(data.names, data.y[:, data.win], y_hat[:, data.win])
    f = t.fit
    return replace(t, fit=Fits(finite(f.cr), finite(f.cd), finite(f.total)))


#: leave one test out up to this many estimation tests; beyond, this many folds
MAX_FOLDS = 6
#: iterations a fold's refit gets from the all-test fit: leaving a test or two out moves
#: the solution a little, so it converges in a few (checked against cold folds,
#: docs/loop-evidence.md)
FOLD_NFEV = 15


def folds(data: Dataset, k_max: int = MAX_FOLDS) -> list[tuple[list[int], list[int]]]:
    """(train, test) test indices of each fold: leave one test out when there are at most
    ``k_max`` tests, else ``k_max`` folds, each setup's tests dealt round-robin over them (so
    every fold trains on every setup with ``k_max`` tests or fewer left out)."""
    n = data.n_tests
    if n < 2:
        return [(list(range(n)), list(range(n)))]
    order = [i for setup in dict.fromkeys(data.setups)
             for i, s in enumerate(data.setups) if s == setup]
    k = min(n, k_max)
    held = [sorted(order[j::k]) for j in range(k)]
    return [([i for i in range(n) if i not in h], h) for h in held]


#: a held-out test's fit when its fold's refit stalled (:func:`fold_scores`)
STALLED = float("nan")


def fold_scores(base: dict, effects: list[dict], data: Dataset, train: list[int],
                test: list[int], max_nfev: int = FOLD_NFEV) -> dict[str, float]:
    """Refit on tests ``train``, starting at ``base``/``effects`` (the fit on all tests), then
    fit_TOT (eq. 3.15, CR and CD averaged) of each test in ``test``: one fold of the
    cross-validation, one task for the cluster.

    A fold whose refit never left its start (scipy rejected every step: a cost rough or
    kinked there) would score its tests with a model fitted on them too, in-sample: they are
    NaN (``STALLED``) instead, for the caller to say what they count (:func:`where_stalled`).
    On set AC such folds gained more than the folds that moved, in 4 of 5 candidates."""
    r = refit_from(base, effects, data.subset(train), max_nfev)
    if not r.moved:
        return {n: STALLED for n in data.subset(test).names}
    t = score(r.base, r.effects, data.subset(test)).tests
    return {n: finite(v.total) for n, v in t.items()}


def where_stalled(cv: dict[str, float], instead: dict[str, float]) -> dict[str, float]:
    """Per-test cross-validated fits with a stalled fold's tests (NaN) given ``instead``'s:
    a candidate's, the model's without it (no gain, no loss: a stalled fold says nothing
    of the candidate); the model's own, its fit on all tests (in-sample, as before)."""
    return {n: instead[n] if np.isnan(v) else v for n, v in cv.items()}


def stalled_in(cv: dict[str, float]) -> list[str]:
    """The tests of per-test fits whose fold stalled (NaN, :func:`fold_scores`)."""
    return [n for n, v in cv.items() if np.isnan(v)]


def fold_scores_by_output(base: dict, effects: list[dict], data: Dataset, train: list[int],
                          test: list[int], max_nfev: int = FOLD_NFEV
                          ) -> dict[str, dict[str, float]]:
    """As :func:`fold_scores`, each output's fit [%] apart: {"cr": {test: fit}, "cd": ...};
    a stalled fold's tests NaN (``STALLED``) in both, as there."""
    r = refit_from(base, effects, data.subset(train), max_nfev)
    if not r.moved:
        return stalled_by_output(data.subset(test).names)
    t = score(r.base, r.effects, data.subset(test)).tests
    return {"cr": {n: finite(v.cr) for n, v in t.items()},
            "cd": {n: finite(v.cd) for n, v in t.items()}}


def stalled_by_output(names: Iterable[str]) -> dict[str, dict[str, float]]:
    """Each output's fits of a stalled fold's tests: NaN (``STALLED``), as
    :func:`fold_scores` gives them."""
    names = list(names)
    return {o: dict.fromkeys(names, STALLED) for o in OUTPUT_NAMES}


def finite(v: float) -> float:
    """A fit [%] as scored, a run-away's (not finite) as -1000 %."""
    return float(v) if np.isfinite(v) else -1e3
