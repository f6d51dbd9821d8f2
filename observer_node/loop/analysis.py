"""Residual analysis of a grey-box model on measured data.

- whiteness: the residual's autocorrelation against the 99 % band 2.58/sqrt(N);
- input cross-correlation over lags -L..L, against Ljung's band for a coloured residual,
  2.58 sqrt(P/N) with P = sum_k R_e(k) R_u(k) (crash residuals are far from white: CFC
  filtering alone gives a lag-1 autocorrelation near 0.99, so the white-noise band would call
  everything significant);
- candidate signatures: each effect's force evaluated along the model's own trajectory and
  propagated through the model's linear part gives the output change a unit of that effect
  would cause; regressing the residual on it says how much of the residual the effect
  explains (its share of the residual's weighted variance).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import optimize

from ..ident.dataset import Dataset
from ..ident.greybox import FREE
from ..model.effects import EFFECTS, OTHER_TERMS, effect_forces, other_term
from ..model.nonlinear import NonlinearGreyBox, simulate_many
from ..model.observer import transform_inputs

MAX_LAG = 25


def weights(data: Dataset) -> np.ndarray:
    """1/||y - mean|| per test and output over the window (the fit's normalisation)."""
    y = data.y[:, data.win]
    return 1.0 / np.linalg.norm(y - y.mean(axis=1, keepdims=True), axis=1)  # (tests, 2)


def _xcorr(a: np.ndarray, b: np.ndarray, lag: int) -> float:
    if lag >= 0:
        return float(np.dot(a[lag:], b[:len(b) - lag])) / len(a)
    return float(np.dot(a[:lag], b[-lag:])) / len(a)


@dataclass(frozen=True)
class OutputCorrelation:
    """One output's residual: its lag-1 autocorrelation, the share of lags 1..L outside the
    white band, and with each input (the crash pulse, the BRS rate) the largest and the RMS
    over lags of the |cross-correlation| as a ratio to Ljung's coloured band (> 1 means
    significant)."""

    lag1_autocorrelation: float
    share_of_lags_outside_white_band: float
    xcorr_pulse_ratio: float
    xcorr_pulse_rms_ratio: float
    xcorr_brs_rate_ratio: float
    xcorr_brs_rate_rms_ratio: float

    @property
    def max_ratio(self) -> float:
        """The largest cross-correlation / band over the inputs."""
        return max(self.xcorr_pulse_ratio, self.xcorr_brs_rate_ratio)

    def as_dict(self) -> dict[str, float]:
        return {"lag1_autocorrelation": self.lag1_autocorrelation,
                "share_of_lags_outside_white_band": self.share_of_lags_outside_white_band,
                "xcorr_pulse_ratio": self.xcorr_pulse_ratio,
                "xcorr_pulse_rms_ratio": self.xcorr_pulse_rms_ratio,
                "xcorr_brs_rate_ratio": self.xcorr_brs_rate_ratio,
                "xcorr_brs_rate_rms_ratio": self.xcorr_brs_rate_rms_ratio}

    @classmethod
    def from_dict(cls, d: dict[str, float]) -> OutputCorrelation:
        return cls(d["lag1_autocorrelation"], d["share_of_lags_outside_white_band"],
                   d["xcorr_pulse_ratio"], d["xcorr_pulse_rms_ratio"],
                   d["xcorr_brs_rate_ratio"], d["xcorr_brs_rate_rms_ratio"])


@dataclass(frozen=True)
class CorrelationTests:
    """The residual's correlation tests per output: chest acceleration CR, deflection CD."""

    cr: OutputCorrelation
    cd: OutputCorrelation

    @property
    def max_ratio(self) -> float:
        """The largest cross-correlation / band over outputs and inputs."""
        return max(self.cr.xcorr_pulse_ratio, self.cr.xcorr_brs_rate_ratio,
                   self.cd.xcorr_pulse_ratio, self.cd.xcorr_brs_rate_ratio)

    @property
    def rms_ratio(self) -> float:
        """Mean over outputs and inputs of the RMS cross-correlation / band."""
        return float(np.mean([self.cr.xcorr_pulse_rms_ratio, self.cr.xcorr_brs_rate_rms_ratio,
                              self.cd.xcorr_pulse_rms_ratio, self.cd.xcorr_brs_rate_rms_ratio]))

    def as_dict(self) -> dict[str, Any]:
        return {"cr": self.cr.as_dict(), "cd": self.cd.as_dict()}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> CorrelationTests:
        """An entry of report.json's ``residual_tests``, read back."""
        return cls(OutputCorrelation.from_dict(d["cr"]), OutputCorrelation.from_dict(d["cd"]))


def correlation_tests(resid: np.ndarray, data: Dataset) -> CorrelationTests:
    """Autocorrelation and input cross-correlation of the residual ``resid`` (tests,
    n_window, 2), per output."""
    inputs = (data.pulse_g[:, data.win],
              np.diff(data.brs_rad, axis=1, prepend=data.brs_rad[:, :1])[:, data.win])
    out = []
    for k in range(2):
        e = resid[:, :, k]
        e = e - e.mean(axis=1, keepdims=True)
        N = e.size
        Re = np.array([np.mean([_xcorr(t, t, lag) for t in e]) for lag in range(MAX_LAG + 1)])
        rho = Re / Re[0] if Re[0] > 0 else Re
        white_band = 2.58 / np.sqrt(N)
        ratios: list[float] = []  # per input: the largest and the RMS ratio
        for u in inputs:
            u = u - u.mean(axis=1, keepdims=True)
            Ru = np.array([np.mean([_xcorr(t, t, lag) for t in u]) for lag in range(MAX_LAG + 1)])
            P = Re[0] * Ru[0] + 2 * np.sum(Re[1:] * Ru[1:])
            band = 2.58 * np.sqrt(max(P, 1e-30) / N)
            r = [np.mean([_xcorr(a, b, lag) for a, b in zip(e, u, strict=True)])
                 for lag in range(-MAX_LAG, MAX_LAG + 1)]
            ratios += [float(np.max(np.abs(r)) / band),
                       float(np.sqrt(np.mean(np.square(r))) / band)]
        out.append(OutputCorrelation(float(rho[1]),
                                     float(np.mean(np.abs(rho[1:]) > white_band)), *ratios))
    return CorrelationTests(*out)


@dataclass
class Trajectory:
    """The model's own states and inputs along each test (for candidate forces)."""

    z: np.ndarray  # (6, tests, n)
    u1: np.ndarray  # (tests, n)
    u2: np.ndarray
    theta: np.ndarray


def trajectory(model: NonlinearGreyBox, data: Dataset) -> Trajectory:
    """States of ``model`` on ``data`` (re-running its simulation and keeping the states)."""
    P, T = data.pulse_g, data.brs_rad
    u = transform_inputs("velocity_brs_rate", P, T, data.fs_hz)
    u1, u2 = u[..., 0], u[..., 1]
    zs = np.empty((6, *P.shape))
    model.run_transformed(u1, u2, T, states=zs)
    return Trajectory(zs, u1, u2, T)


def propagate(model: NonlinearGreyBox, f_spine: np.ndarray, f_sternum: np.ndarray) -> np.ndarray:
    """Output response (tests, n, 2) of the model's linear part to force signals (tests, n)."""
    ntest, n = f_spine.shape
    z = np.zeros((6, ntest))
    y = np.empty((ntest, n, 2))
    for k in range(n):
        f = np.vstack([f_spine[:, k], f_sternum[:, k]])
        if not model.after_input:
            y[:, k] = (model.C @ z + model.Df @ f).T
        z = model.Ad @ z + model.Gd @ f
        if model.after_input:  # the output of the state after the tick (see the model)
            j = min(k + 1, n - 1)
            y[:, k] = (model.C @ z + model.Df @ np.vstack([f_spine[:, j], f_sternum[:, j]])).T
    return y


def force_signature(model: NonlinearGreyBox, data: Dataset, kind: str, p: dict) -> np.ndarray:
    """Output change (tests, n, 2) that a force effect with parameters ``p`` would cause,
    evaluated along ``model``'s own trajectory and propagated through its linear part."""
    tr = trajectory(model, data)
    fs, fn = effect_forces(kind, p, tuple(tr.z), tr.u1, tr.u2, tr.theta, model.base)
    return propagate(model, np.asarray(np.broadcast_to(fs, tr.u1.shape), float),
                     np.asarray(np.broadcast_to(fn, tr.u1.shape), float))


def explained_share(resid: np.ndarray, signature: np.ndarray, data: Dataset) -> float:
    """Share of the (weighted) residual a signature explains with a free coefficient."""
    return _regress(resid, [signature], weights(data), data.win)[1]


@dataclass
class Candidate:
    kind: str
    explained: float  # share of the residual's weighted variance explained
    parameters: dict  # initial parameter values from the regression
    signature: np.ndarray | None = None
    setups: list[str] | None = None  # scope: the setups it acts on (None: every test)
    # share explained with each scope tried ("all" or setups joined by "+")
    scope_shares: dict[str, float] | None = None

    def effect(self) -> dict:
        """The effect as the model takes it."""
        return {"kind": self.kind, "parameters": self.parameters,
                **({"setups": self.setups} if self.setups is not None else {})}


def scope_label(setups: list[str] | None) -> str:
    return "all" if setups is None else "+".join(setups)


# Input delays searched: 0..10 ms, every half millisecond, then refined to 0.05 ms.
DELAY_MAX_S = 0.010
DELAY_STEP_S = 0.0005


def _regress(r: np.ndarray, sigs: list[np.ndarray], w: np.ndarray,
             win: slice) -> tuple[np.ndarray, float]:
    """Least squares of the weighted residual on weighted signatures; (coefs, explained)."""
    rw = (r * w[:, None, :]).ravel()
    S = np.stack([(s[:, win] * w[:, None, :]).ravel() for s in sigs], axis=1)
    if not np.any(S) or not np.all(np.isfinite(S)):  # a trial model that ran away
        return np.zeros(len(sigs)), 0.0
    coef = np.linalg.lstsq(S, rw, rcond=None)[0]
    rest = rw - S @ coef
    return coef, float(1 - rest @ rest / (rw @ rw))


def base_sensitivities(model: NonlinearGreyBox, data: Dataset, y_hat: np.ndarray
                       ) -> list[np.ndarray]:
    """Output change (tests, n, 2) per 1 % change of each free base parameter."""
    models = [NonlinearGreyBox({**model.base, name: model.base[name] * 1.01}, model.effects,
                               model.fs_hz, model.test_setups, after_input=model.after_input)
              for name in FREE]
    return list(simulate_many(models, data.pulse_g, data.brs_rad) - y_hat)


def candidates(model: NonlinearGreyBox, data: Dataset, present: set[str],
               scopes: dict[str, list[list[str] | None]] | None = None) -> list[Candidate]:
    """Every effect not yet in the model, scored on the residual, best first.

    ``scopes``: per effect, the scopes to try (None: every test; a list of setups); each
    candidate keeps the scope that explains most (default: every test only). An effect with
    no scope to try (impossible everywhere) is not a candidate.

    The refit re-estimates the base parameters with the effect, so each signature is
    regressed *together with* the base parameters' sensitivities: an effect the fitted
    linear model has half absorbed (a hardening belt makes the fit choose a stiffer k2)
    shows its true sign and size only beside them."""
    y_hat = model.simulate(data.pulse_g, data.brs_rad)
    r = (data.y - y_hat)[:, data.win]
    w = weights(data)
    tr = trajectory(model, data)
    out: list[Candidate] = []
    zt = tuple(tr.z)
    sens = base_sensitivities(model, data, y_hat)

    def regress(sigs: list[np.ndarray]) -> tuple[np.ndarray, float]:
        coef, ex = _regress(r, [*sigs, *sens], w, data.win)
        return coef[:len(sigs)], ex

    def force_sig(kind: str, p: dict) -> np.ndarray:
        fs, fn = effect_forces(kind, p, zt, tr.u1, tr.u2, tr.theta, model.base)
        fs = np.broadcast_to(fs, tr.u1.shape)
        fn = np.broadcast_to(fn, tr.u1.shape)
        return propagate(model, np.asarray(fs, float), np.asarray(fn, float))

    scorer = _Scorer(model, data, r, w, sens, y_hat)
    for kind, effect in EFFECTS.items():
        if kind in present or effect.search.method == "sparse":
            continue
        tried: list[Candidate] = []
        for scope in (scopes or {}).get(kind, [None]):
            mask = (np.ones(data.n_tests, bool) if scope is None else
                    np.array([s in scope for s in data.setups]))
            if not mask.any():
                continue
            c = _candidate(kind, scope, mask, scorer, data, regress, force_sig)
            if c is not None:
                tried.append(c)
        if tried:
            # the widest scope among those within 0.2 % of the best share: a wider scope is
            # the simpler claim (cross-validation still compares it with the rest)
            top = max(c.explained for c in tried)
            best = max((c for c in tried if c.explained >= top - 0.002),
                       key=lambda c: (len(c.setups) if c.setups is not None else 1e9,
                                      c.explained))
            best.scope_shares = {scope_label(c.setups): round(c.explained, 4) for c in tried}
            out.append(best)
    out += [_sparse_other(kind, model, data, r, w, tr) for kind, e in EFFECTS.items()
            if e.search.method == "sparse" and kind not in present]
    return sorted(out, key=lambda c: -c.explained)


def _candidate(kind: str, scope: list[str] | None, mask: np.ndarray, scorer: _Scorer,
               data: Dataset, regress: Callable[[list[np.ndarray]], tuple[np.ndarray, float]],
               force_sig: Callable[[str, dict], np.ndarray]) -> Candidate | None:
    """One effect on one scope: its initial parameters and the share it explains, searched
    as its definition says (:class:`observer_node.model.effects.Search`)."""
    effect = EFFECTS[kind]
    unit = effect.typical
    names = list(unit)
    method = effect.search.method
    m3 = mask[:, None, None]
    if method == "offset":
        n = data.y.shape[1]
        s_cr = np.zeros((data.n_tests, n, 2))
        s_cr[:, :, 0] = 1.0
        s_cd = np.zeros((data.n_tests, n, 2))
        s_cd[:, :, 1] = 1.0
        _, ex = regress([s_cr * m3, s_cd * m3])
        # A sensor offset is there at rest too: the first 2 ms after contact, before the
        # chest moves, must show it (> 1 % of the output's range); if they do not, what
        # looks like an offset in the window is something else.
        rest = data.y[mask, :max(2, round(0.002 * data.fs_hz))].mean(axis=(0, 1))
        span = np.ptp(data.y[mask][:, data.win], axis=1).mean(axis=0)
        if not np.any(np.abs(rest) > 0.01 * span):
            return None
        return Candidate(kind, ex, {names[0]: float(rest[0]), names[1]: float(rest[1])},
                         setups=scope)
    if method == "delay":
        ex, p, sig = _search_delay(scorer, kind, data.fs_hz, scope)
        return Candidate(kind, ex, p, sig, setups=scope)
    if method == "switch":
        ex, sig = scorer.share(kind, {}, scope)
        return Candidate(kind, ex, {}, sig, setups=scope)
    # Start from the linearised regression (its size, and on a grid the value of the
    # parameter searched, an airbag's gap), then let a short non-linear fit of the effect's
    # own parameters finish.
    if method == "grid":
        over = effect.search.over
        start, best_ex = dict(unit), -np.inf
        for v in effect.search.grid:
            coef, ex = regress([force_sig(kind, {**unit, over: v}) * m3])
            if ex > best_ex:
                best_ex, start = ex, {n: v if n == over else abs(coef[0]) * mag
                                      for n, mag in unit.items()}
    else:
        coef, _ = regress([force_sig(kind, unit) * m3])
        signed = not all(p.positive for p in effect.params)
        c = coef[0] if signed else max(abs(coef[0]), 0.1)
        start = {n: float(c * mag) for n, mag in unit.items()}
        if len(names) == 1 and not signed and effect.params[0].within is None:
            # the share over a size can have two valleys (set J's webbing toe: a belt
            # stiffening explains -115 % at its typical size, +17 % at 30 times it): the
            # short fit starts from the best of the regression's size and half decades
            # around the typical one
            sizes = [start[names[0]], *(unit[names[0]] * 10.0 ** (k / 2) for k in range(-4, 5))]
            got = scorer.shares(kind, [{names[0]: v} for v in sizes], scope)
            start = {names[0]: float(sizes[int(np.argmax(got))])}
    ex, p, sig = scorer.fit(kind, start, scope)
    return Candidate(kind, ex, p, sig, setups=scope)


def _search_delay(scorer: _Scorer, kind: str, fs_hz: float, scope: list[str] | None
                  ) -> tuple[float, dict, np.ndarray]:
    """The input delays (fractional ticks) that explain most: each input alone on a grid
    over 0..10 ms, then the other input given the better one, each refined around its best
    by golden-section search. The effect's parameters are the delays of the pulse and the
    BRS, in that order."""
    n_pulse, n_brs = (p.name for p in EFFECTS[kind].params)
    grid = np.arange(0.0, DELAY_MAX_S + 1e-12, DELAY_STEP_S) * fs_hz
    h = DELAY_STEP_S * fs_hz

    def share(p: dict) -> float:
        return scorer.share(kind, p, scope)[0]

    def best_along(which: str, fixed: dict) -> tuple[float, dict]:
        vals = scorer.shares(kind, [{**fixed, which: float(n)} for n in grid], scope)
        n0 = float(grid[int(np.argmax(vals))])
        res = optimize.minimize_scalar(lambda n: -share({**fixed, which: n}),
                                       bounds=(max(0.0, n0 - h), min(grid[-1], n0 + h)),
                                       method="bounded", options={"xatol": 0.05e-3 * fs_hz})
        n = float(res.x) if -res.fun > max(vals) else n0
        return max(-float(res.fun), max(vals)), {**fixed, which: round(n, 3)}

    zero = {n_pulse: 0.0, n_brs: 0.0}
    ex_p, p_p = best_along(n_pulse, zero)
    ex_b, p_b = best_along(n_brs, zero)
    first, other, ex1 = (p_p, n_brs, ex_p) if ex_p >= ex_b else (p_b, n_pulse, ex_b)
    ex2, both = best_along(other, first)
    p = both if ex2 > ex1 + 0.002 else first
    ex, sig = scorer.share(kind, p, scope)
    return ex, p, sig


def within_value(within: tuple[float, float], t: float) -> float:
    """A parameter kept within its range (lo, hi), from the unbounded variable ``t``."""
    lo, hi = within
    return float(lo + (hi - lo) * (1.0 + np.tanh(t)) / 2.0)


def within_free(within: tuple[float, float], value: float) -> float:
    """The unbounded variable of ``value``, clipped to the inner 95 % of the range: at its
    edge tanh is flat, and a fit started there could not leave it (a belt stiffening's
    ranking drove n to 1, and its refits stayed there)."""
    lo, hi = within
    return float(np.arctanh(np.clip(2.0 * (value - lo) / (hi - lo) - 1.0, -0.95, 0.95)))


class _Scorer:
    """Share of the residual an effect explains when simulated as it is (non-linear, on the
    current model), with the base parameters re-estimated to first order beside it."""

    def __init__(self, model: NonlinearGreyBox, data: Dataset, r: np.ndarray, w: np.ndarray,
                 sens: list[np.ndarray], y_hat: np.ndarray):
        self.model, self.data, self.y_hat = model, data, y_hat
        self.w = w
        self.rw = (r * w[:, None, :]).ravel()
        S = np.stack([(x[:, data.win] * w[:, None, :]).ravel() for x in sens], axis=1)
        self.Q = np.linalg.qr(S)[0]

    def _trial(self, kind: str, p: dict, scope: list[str] | None) -> NonlinearGreyBox:
        m = self.model
        effect = {"kind": kind, "parameters": p, **({"setups": scope} if scope else {})}
        return NonlinearGreyBox(m.base, [*m.effects, effect], m.fs_hz, m.test_setups,
                                after_input=m.after_input)

    def _rest_of(self, y_trial: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        sig = y_trial - self.y_hat
        v = self.rw - (sig[:, self.data.win] * self.w[:, None, :]).ravel()
        v = v - self.Q @ (self.Q.T @ v)
        return np.where(np.isfinite(v), v, 1e3), sig

    def _rest(self, kind: str, p: dict, scope: list[str] | None = None
              ) -> tuple[np.ndarray, np.ndarray]:
        with np.errstate(all="ignore"):
            return self._rest_of(self._trial(kind, p, scope).simulate(self.data.pulse_g,
                                                                      self.data.brs_rad))

    def _explained(self, v: np.ndarray) -> float:
        """Share of the residual explained when ``v`` is what is left of it."""
        return float(1 - v @ v / (self.rw @ self.rw))

    def share(self, kind: str, p: dict, scope: list[str] | None = None
              ) -> tuple[float, np.ndarray]:
        v, sig = self._rest(kind, p, scope)
        return self._explained(v), sig

    def rests(self, kind: str, ps: Iterable[dict], scope: list[str] | None = None
              ) -> list[np.ndarray]:
        """What :meth:`_rest` leaves of each parameter set, as one simulation."""
        trials = [self._trial(kind, p, scope) for p in ps]
        with np.errstate(all="ignore"):
            return [self._rest_of(y)[0] for y in
                    simulate_many(trials, self.data.pulse_g, self.data.brs_rad)]

    def shares(self, kind: str, ps: list[dict], scope: list[str] | None = None
               ) -> list[float]:
        """:meth:`share` of each parameter set (a search's grid), as one simulation."""
        return [self._explained(v) for v in self.rests(kind, ps, scope)]

    def fit(self, kind: str, start: dict, scope: list[str] | None = None,
            max_nfev: int = 12) -> tuple[float, dict, np.ndarray]:
        """Least squares over the effect's parameters (positive ones as logarithms)."""
        names = list(start)
        effect = EFFECTS[kind]
        pos = [effect.positive(n) for n in names]
        rng = [q.within if (q := effect.param(n)) is not None else None for n in names]
        scale = [abs(start[n]) or effect.typical[n] for n in names]

        def unpack(th: np.ndarray) -> dict[str, float]:
            return {n: within_value(r, t) if r is not None else
                    float(sc * (np.exp(t) if ps else t))
                    for n, t, ps, sc, r in zip(names, th, pos, scale, rng, strict=True)}

        # a parameter with a range starts inside it (the regression may overshoot it)
        th0 = np.array([within_free(r, start[n]) if r is not None
                        else 0.0 if ps else np.sign(start[n]) or 1.0
                        for n, ps, r in zip(names, pos, rng, strict=True)])

        def jacobian_points(_: object, ths: Iterable[np.ndarray]) -> list[np.ndarray]:
            """The rests at the finite-difference Jacobian's points, as one simulation."""
            return self.rests(kind, map(unpack, ths), scope)

        res = optimize.least_squares(lambda th: self._rest(kind, unpack(th), scope)[0], th0,
                                     max_nfev=max_nfev, diff_step=1e-3,
                                     workers=jacobian_points)
        p = unpack(res.x)
        ex, sig = self.share(kind, p, scope)
        return ex, p, sig


def _sparse_other(kind: str, model: NonlinearGreyBox, data: Dataset, r: np.ndarray,
                  w: np.ndarray, tr: Trajectory) -> Candidate:
    """Sequentially thresholded least squares over polynomial force terms (SINDy-style)."""
    xd, x, sd, s, wst, _p = tr.z
    d, dd = s - x, sd - xd
    e = wst - s
    ed = tr.u1 + model.base["R"] * tr.u2 - sd
    sigs, names = [], []
    for where in ("rib", "belt"):
        for term in OTHER_TERMS:
            f = other_term(term, d, dd, e, ed)
            scale = 1.0 / max(np.abs(f).max(), 1e-12)
            fs, fn = (f * scale, -f * scale) if where == "rib" else (0 * f, f * scale)
            sigs.append(propagate(model, fs, fn))
            names.append((where, term, scale))
    active = list(range(len(sigs)))
    coef = np.zeros(len(sigs))
    for _ in range(5):
        c, _ = _regress(r, [sigs[i] for i in active], w, data.win)
        coef[:] = 0
        coef[active] = c
        big = np.abs(coef) * np.array([np.abs(s[:, data.win]).max() for s in sigs])
        keep = [i for i in active if big[i] >= 0.1 * big.max()][:3]
        if keep == active:
            break
        active = keep
    c, ex = _regress(r, [sigs[i] for i in active], w, data.win)
    params: dict = {"rib": {}, "belt": {}}
    for i, ci in zip(active, c, strict=True):
        where, term, scale = names[i]
        params[where][term] = float(ci * scale)
    return Candidate(kind, ex, params)
