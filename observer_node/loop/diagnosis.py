"""What a residual looks like when no physical effect explains it, and the sensor family.

A transducer's error (a gain or a static non-linearity of one channel, or one drifting in time)
leaves its mark in one output only, as a function of that output; physics moves the chest, so
it shows in both CR and CD. Three shapes are looked for per output, each fitted by least
squares to the residual:

- ``static``: a static function of the output, y² and y³ of the model's own estimate (a
  transducer over- or under-reading at large values);
- ``lag``: the estimate's rate dy/dt (a time shift or a rate term the model lacks);
- ``drift``: t y, t dy/dt and t, with t the time since contact (a gain that sags or creeps,
  a slow clock, a zero that drifts: its error grows with time, not with the value).

Their size is given as the fit points [%, eq. 3.15] the correction would add. The sensor
candidate (:func:`sensor_fold_scores`) is the static correction of one output, fitted on
each cross-validation fold's training tests and scored on its held-out ones, so it competes
with physics under the same rule (:mod:`.evidence`). Beside it each fold fits the fuller
correction (``sensor``): the static function and a drift in time (``drift``: t y, t dy/dt and
t, with t the time since contact: a gain that sags or creeps, a slow clock, a zero that
drifts). The static correction says whether a transducer is at fault; the fuller one says
which, judged test by test: an error drifting in time on one output bends the chest model,
and a static correction of the *other*, healthy output wins back what it bent (held-out sets
W and AG: a CD pot's sagging excitation named CR's). The fuller correction does not decide
whether, since with its freedom it also takes up physics (set AH's Fung rib stiffening: +2.9
points on CD, where the static one gains 0.6). Before one is named, the loop checks the "one
output only" (:func:`without_sensor`, ``both``): if the strongest physical candidate still
passes the rule on the other output's fit once the correction is taken out of the data, the
residual is in both outputs, and it is physics no effect of the library explains.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..ident.dataset import Dataset
from ..ident.metrics import OUTPUT_NAMES, fit_percent
from .refit import FOLD_NFEV, model, refit_from, stalled_by_output

SHAPES = {"static": "a static function of {o} (a transducer's non-linearity: its error grows "
                    "with the value)",
          "lag": "a lag or rate term in {o} (proportional to its rate of change)",
          "drift": "a drift in time on {o} (its error grows with the time since contact: a "
                   "transducer's gain, zero or clock changing, or a term the model lacks)",
          "both": "a physical effect the library lacks: a static correction of one output "
                  "and the strongest physical candidate on the other both gain, so it is in "
                  "{o} and in the other output, not one transducer's error"}

FITTED = ("static", "lag", "drift")  # the shapes fitted to a residual ("both": the loop's)


def _basis(y_hat: np.ndarray, shape: str, fs_hz: float, scale: float = 0.0) -> np.ndarray:
    """Regressors (tests, n, m) of one output's estimate (tests, n) from contact (t = 0):
    ``static`` (y², y³, y), ``drift`` (t y, t dy/dt, t over the record's length: a gain,
    clock or zero changing in time), ``sensor`` (both) or ``lag`` (dy/dt). ``scale`` (the
    output's unit) keeps the powers well conditioned, default the largest |estimate|."""
    if shape == "lag":
        return np.gradient(y_hat, 1.0 / fs_hz, axis=1)[..., None]
    if shape not in ("static", "drift", "sensor"):
        raise ValueError(f"unknown shape {shape!r}")
    s = scale or float(np.max(np.abs(y_hat))) or 1.0
    u = y_hat / s
    static = [u ** 2, u ** 3, u]
    if shape == "static":
        return np.stack(static, axis=-1)
    n = y_hat.shape[1]
    t = np.broadcast_to(np.arange(n) / n, y_hat.shape)
    du = np.gradient(u, axis=1) * (n / 20.0)  # du/dt over the record (the scale is lstsq's)
    drift = [t * u, t * du, t]
    return np.stack(drift if shape == "drift" else static + drift, axis=-1)


def _solve(r: np.ndarray, X: np.ndarray) -> np.ndarray:
    coef, *_ = np.linalg.lstsq(X.reshape(-1, X.shape[-1]), r.ravel(), rcond=None)
    return coef


def _fits(y: np.ndarray, y_hat: np.ndarray) -> np.ndarray:
    return np.array([fit_percent(y[i], y_hat[i]) for i in range(len(y))])


def shape_gains(data: Dataset, y_hat: np.ndarray) -> dict[str, dict[str, np.ndarray]]:
    """Per output and shape, each test's fit gain [points] from that correction of the
    residual (in-sample; the corrections have 1-3 coefficients over thousands of samples)."""
    y, yh = data.y[:, data.win], y_hat[:, data.win]
    out: dict[str, dict[str, np.ndarray]] = {}
    for k, o in enumerate(OUTPUT_NAMES):
        base = _fits(y[..., k], yh[..., k])
        out[o] = {}
        for shape in FITTED:
            X = _basis(y_hat[..., k], shape, data.fs_hz)[:, data.win]
            corr = yh[..., k] + X @ _solve(y[..., k] - yh[..., k], X)
            out[o][shape] = _fits(y[..., k], corr) - base
    return out


@dataclass(frozen=True)
class Unexplained:
    """Structure left in one output's residual that no effect explains: the setups where a
    correction of its shape would add at least the minimum, what it looks like, the gain
    [fit points] per setup (rounded to 0.01) and the mean gain in the other output."""

    output: str  # "cr" or "cd"
    setups: list[str]
    looks_like: str
    shape: str  # a key of SHAPES, or "rate_limit" (read off the channel: .rate_limit)
    gain_points: dict[str, float]
    other_output_gain_points: float
    reading: dict[str, Any] | None = None  # a rate limit's figures (.rate_limit), no gains

    def as_dict(self) -> dict[str, Any]:
        head = {"output": self.output, "setups": self.setups, "looks_like": self.looks_like,
                "shape": self.shape}
        if self.reading is not None:  # read off the channel: no correction was fitted
            return {**head, "rate_limit": self.reading}
        return {**head, "gain_points": self.gain_points,
                "other_output_gain_points": self.other_output_gain_points}


def unexplained(data: Dataset, y_hat: np.ndarray, min_points: float = 1.0
                ) -> list[Unexplained]:
    """Structure left in the residual: per output, the shape whose correction would add at
    least ``min_points`` fit points on some setup, with the setups where it does."""
    gains = shape_gains(data, y_hat)
    setups = list(dict.fromkeys(data.setups))
    out = []
    for o, by_shape in gains.items():
        shape, g = max(by_shape.items(), key=lambda kv: float(np.mean(kv[1])))
        per_setup = {s: float(np.mean([g[i] for i, t in enumerate(data.setups) if t == s]))
                     for s in setups}
        where = [s for s, v in per_setup.items() if v >= min_points]
        if where:
            out.append(Unexplained(
                o, where, SHAPES[shape].format(o=o.upper()), shape,
                {s: round(v, 2) for s, v in per_setup.items()},
                round(float(np.mean(gains[_other(o)][shape])), 2)))
    return out


def without_sensor(data: Dataset, y_hat: np.ndarray, output: str, shape: str = "static"
                   ) -> Dataset:
    """``data`` with one output's correction of ``shape`` (``static`` or the fuller
    ``sensor``; fitted in-sample on the estimate ``y_hat``) taken out of its measurement: what
    the tests would read through a transducer without that error, so the model refitted on
    them no longer bends to it."""
    k = OUTPUT_NAMES.index(output)
    X = _basis(y_hat[..., k], shape, data.fs_hz)
    coef = _solve(data.y[:, data.win, k] - y_hat[:, data.win, k], X[:, data.win])
    y = data.y.copy()
    y[..., k] -= X @ coef
    return replace(data, y=y)


def sensor_shape(data: Dataset, y_hat: np.ndarray, output: str) -> str:
    """The shape of a sensor correction of ``output``, ``static`` or ``drift``: whichever
    alone wins more of its residual (in-sample, on the model's estimate ``y_hat``)."""
    gains = shape_gains(data, y_hat)[output]
    return max(("static", "drift"), key=lambda sh: float(np.mean(gains[sh])))


def sensor_looks_like(shape: str, output: str) -> str:
    """A sensor effect of ``shape`` on ``output`` in the report's words."""
    o = output.upper()
    if shape == "drift":
        return (f"a drift in time on {o}: the {o} transducer's gain, zero or clock changing "
                "during the crash (a sagging excitation, a creeping zero, a slow clock), not "
                "the chest's physics")
    return (f"a static function of {o}: the {o} transducer's gain or non-linearity, not the "
            "chest's physics")


def _other(o: str) -> str:
    return OUTPUT_NAMES[1 - OUTPUT_NAMES.index(o)]


FULLER = "+drift"  # the key suffix of an output's fuller correction (static and drift)


def sensor_fold_scores(base: dict, effects: list[dict], data: Dataset, train: list[int],
                       test: list[int], max_nfev: int = FOLD_NFEV) -> dict[str, dict[str, float]]:
    """One fold of the sensor candidates: refit the current model (fitted on all tests, the
    start) on ``train``, fit each output's static correction and its fuller one there, score
    each ``test`` test's fit_TOT [%] with it. Returns {output: {test: fit_TOT}} for the static
    correction and {output + FULLER: ...} for the fuller one; a stalled fold's tests NaN
    (``STALLED``), as :func:`~.refit.fold_scores` gives them: its correction would be judged on
    a model fitted on them too."""
    r = refit_from(base, effects, data.subset(train), max_nfev)
    if not r.moved:
        stalled = stalled_by_output(data.subset(test).names)
        return {**stalled, **{o + FULLER: v for o, v in stalled.items()}}
    tr, te = data.subset(train), data.subset(test)
    with np.errstate(all="ignore"):
        yh_tr = model(r.base, r.effects, tr).simulate(tr.pulse_g, tr.brs_rad)
        yh_te = model(r.base, r.effects, te).simulate(te.pulse_g, te.brs_rad)
    y = te.y[:, te.win]
    out: dict[str, dict[str, float]] = {}
    for k, o in enumerate(OUTPUT_NAMES):
        scale = float(np.max(np.abs(yh_tr[..., k]))) or 1.0
        for shape, key in (("static", o), ("sensor", o + FULLER)):
            X_tr = _basis(yh_tr[..., k], shape, tr.fs_hz, scale)[:, tr.win]
            coef = _solve(tr.y[:, tr.win, k] - yh_tr[:, tr.win, k], X_tr)
            corrected = yh_te[:, te.win].copy()
            corrected[..., k] += _basis(yh_te[..., k], shape, te.fs_hz, scale)[:, te.win] @ coef
            out[key] = {}
            for i, n in enumerate(te.names):
                f = np.mean([fit_percent(y[i, :, j], corrected[i, :, j]) for j in range(2)])
                out[key][n] = float(f) if np.isfinite(f) else -1e3
    return out
