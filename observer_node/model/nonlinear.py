"""The grey-box chest with added physical effects, as a real-time observer.

The linear part (:mod:`.chest`: thesis eq. 3.7 plus the vehicle displacement p as a sixth
state, so effects can use the forward excursion) is discretised exactly (zero-order hold); the
effects' forces enter as extra inputs held over the tick:

    z[k+1] = Ad z[k] + Bd u[k] + Gd f(z[k], u[k], theta[k])
    y[k]   = C z[k] + Df f(z[k], u[k], theta[k]) + offsets

With no effects this is the linear grey-box model exactly. A slack belt (``belt_unloading``)
is not a force but a switch: in a tick that starts with the belt force k2 e + c2 e' < 0 the
state moves with the belt-free matrices (k2 = c2 = 0), which is exact within the tick, where
cancelling the belt force with a held force lags a stiff spring by a tick.
``simulate`` runs many tests at once (numpy over the test axis); ``step`` is the daemon's
per-tick call.
"""

from __future__ import annotations

import math

import numpy as np

from ..units import STANDARD_GRAVITY
from .chest import discrete
from .effects import FORCE_KINDS, Num, effect_forces
from .observer import transform_inputs

G0 = STANDARD_GRAVITY


class NonlinearGreyBox:
    """Same interface as :class:`LinearObserver`: ``reset``, ``step``, ``simulate``."""

    def __init__(self, base: dict[str, float], effects: list[dict], fs_hz: float):
        self.base = dict(base)
        self.effects = [dict(e) for e in effects]
        self.fs_hz = fs_hz
        self.Ad, self.Bd, self.Gd, self.C, self.Df = discrete(self.base, fs_hz)
        self.force_effects = [(e["kind"], e.get("parameters", {})) for e in self.effects
                              if e["kind"] in FORCE_KINDS and e["kind"] != "belt_unloading"]
        self.unloading = any(e["kind"] == "belt_unloading" for e in self.effects)
        self._k2, self._c2, self._R = self.base["k2"], self.base["c2"], self.base["R"]
        slack = discrete({**self.base, "k2": 0.0, "c2": 0.0}, fs_hz)
        self.Ad_slack, self.Bd_slack, self.Gd_slack = slack[:3]
        delay: dict[str, float] = next((e["parameters"] for e in self.effects
                                        if e["kind"] == "input_delay"), {})
        self.n_pulse = round(delay.get("n_pulse", 0))
        self.n_brs = round(delay.get("n_brs", 0))
        off: dict[str, float] = next((e["parameters"] for e in self.effects
                                      if e["kind"] == "sensor_offset"), {})
        self.offset = np.array([off.get("cr_g", 0.0), off.get("cd_mm", 0.0)])
        self._dt_g = G0 / fs_hz
        self.x = np.zeros(6)
        self._xn = np.zeros(6)
        self._tmp = np.zeros(6)
        self._y2 = np.zeros(2)
        self._y = np.zeros(2)
        self._u = np.zeros(2)
        self._f = np.zeros(2)
        self._pulse_ring = np.zeros(self.n_pulse + 1)
        self._brs_ring = np.zeros(self.n_brs + 1)
        self.reset()

    # ------------------------------------------------------------------ per tick
    def reset(self) -> None:
        self.x[:] = 0.0
        self._velocity = 0.0
        self._theta_prev: float | None = None
        self._pulse_ring[:] = 0.0
        self._brs_ring[:] = math.nan
        self._k = 0

    def step(self, pulse_g: float, brs_rad: float) -> np.ndarray:
        k = self._k
        self._k = k + 1
        if self.n_pulse:
            self._pulse_ring[k % (self.n_pulse + 1)] = pulse_g
            pulse_g = self._pulse_ring[(k + 1) % (self.n_pulse + 1)] if k >= self.n_pulse else 0.0
        if self.n_brs:
            self._brs_ring[k % (self.n_brs + 1)] = brs_rad
            old = self._brs_ring[(k + 1) % (self.n_brs + 1)]
            brs_rad = old if k >= self.n_brs else self._brs_ring[0]
        self._velocity += pulse_g * self._dt_g
        prev = brs_rad if self._theta_prev is None else self._theta_prev
        self._theta_prev = brs_rad
        u = self._u
        u[0] = self._velocity
        u[1] = (brs_rad - prev) * self.fs_hz
        f = self._f
        f[0] = f[1] = 0.0
        z = self.x
        for kind, p in self.force_effects:
            fs, fn = effect_forces(kind, p, z, u[0], u[1], brs_rad, self.base)
            f[0] += fs
            f[1] += fn
        # Preallocated buffers only: no array is created per tick (the effect forces are
        # floats).
        y = self._y
        np.dot(self.C, z, out=y)
        np.dot(self.Df, f, out=self._y2)
        y += self._y2
        y += self.offset
        Ad, Bd, Gd = self.Ad, self.Bd, self.Gd
        if self.unloading and self.belt_slack(z, u[0], u[1]):
            Ad, Bd, Gd = self.Ad_slack, self.Bd_slack, self.Gd_slack
        xn, tmp = self._xn, self._tmp
        np.dot(Ad, z, out=xn)
        np.dot(Bd, u, out=tmp)
        xn += tmp
        np.dot(Gd, f, out=tmp)
        xn += tmp
        self.x, self._xn = xn, z
        return y

    def belt_slack(self, z: np.ndarray, u1: Num, u2: Num) -> Num:
        """True where the belt would push (force k2 e + c2 e' < 0): float or array."""
        return self._k2 * (z[4] - z[3]) + self._c2 * (u1 + self._R * u2 - z[2]) < 0.0

    # ------------------------------------------------------------------ whole records
    def simulate(self, pulse_g: np.ndarray, brs_rad: np.ndarray) -> np.ndarray:
        """From rest, (n,) or (tests, n) -> (..., n, 2)."""
        squeeze = pulse_g.ndim == 1
        P = np.atleast_2d(pulse_g).astype(float)
        T = np.atleast_2d(brs_rad).astype(float)
        if self.n_pulse:
            P = np.concatenate([np.zeros((P.shape[0], self.n_pulse)), P[:, :-self.n_pulse]], 1)
        if self.n_brs:
            T = np.concatenate([np.repeat(T[:, :1], self.n_brs, 1), T[:, :-self.n_brs]], 1)
        u = transform_inputs("velocity_brs_rate", P, T, self.fs_hz)
        y = self.run_transformed(u[..., 0], u[..., 1], T)
        return y[0] if squeeze else y

    def run_transformed(self, u1: np.ndarray, u2: np.ndarray, theta: np.ndarray,
             states: np.ndarray | None = None) -> np.ndarray:
        """Outputs (tests, n, 2); the states (6, tests, n) go into ``states`` if given."""
        ntest, n = u1.shape
        z = np.zeros((6, ntest))
        y = np.empty((ntest, n, 2))
        Ad, Bd, Gd, C, Df = self.Ad, self.Bd, self.Gd, self.C, self.Df
        for k in range(n):
            if states is not None:
                states[:, :, k] = z
            a, b, th = u1[:, k], u2[:, k], theta[:, k]
            fs = np.zeros(ntest)
            fn = np.zeros(ntest)
            for kind, p in self.force_effects:
                s1, s2 = effect_forces(kind, p, z, a, b, th, self.base)
                fs = fs + s1
                fn = fn + s2
            f = np.vstack([fs, fn])
            ab = np.vstack([a, b])
            y[:, k] = (C @ z + Df @ f).T
            zn = Ad @ z + Bd @ ab + Gd @ f
            if self.unloading:
                slack = self.belt_slack(z, a, b)
                if slack.any():
                    z_slack = self.Ad_slack @ z + self.Bd_slack @ ab + self.Gd_slack @ f
                    zn = np.where(slack, z_slack, zn)
            z = zn
        return y + self.offset
