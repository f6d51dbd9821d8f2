"""The observer every model becomes: an input transform followed by a discrete state space.

Raw inputs per tick are ``pulse_g`` (deceleration positive, bias removed) and ``brs_rad``
(spindle angle, + = webbing retracted); outputs are ``cr_g`` and ``cd_mm`` (model convention,
see :mod:`observer_node.data.crashtest`). Two input transforms exist:

``velocity_brs_rate`` (grey-box, thesis eq. 3.6)
    u1 = integral of the pulse [m/s], u2 = d/dt BRS [rad/s], both causal: the integral is a
    running sum and the rate a backward difference, held over the tick (zero-order hold).
``raw``
    u = [pulse_g, brs_rad] as they arrive (black-box models, thesis section 3.4).

This module knows nothing about how a model was fitted nor about CAN.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..units import STANDARD_GRAVITY

TRANSFORMS = ("velocity_brs_rate", "raw")


def transform_inputs(kind: str, pulse_g: np.ndarray, brs_rad: np.ndarray,
                     fs_hz: float) -> np.ndarray:
    """Apply an input transform to whole records. Arrays may be (n,) or (tests, n);
    returns (..., n, 2). The first sample's previous BRS is taken as itself (at rest)."""
    if kind == "raw":
        return np.stack([pulse_g, brs_rad], axis=-1)
    if kind == "velocity_brs_rate":
        velocity = np.cumsum(pulse_g, axis=-1) * (STANDARD_GRAVITY / fs_hz)
        rate = np.diff(brs_rad, axis=-1, prepend=brs_rad[..., :1]) * fs_hz
        return np.stack([velocity, rate], axis=-1)
    raise ValueError(f"unknown input transform {kind!r} (known: {', '.join(TRANSFORMS)})")


@dataclass
class LinearObserver:
    """Discrete state space x+ = A x + B u, y = C x + D u on transformed inputs."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    transform: str
    fs_hz: float

    def __post_init__(self) -> None:
        self.A, self.B, self.C, self.D = (np.asarray(m, dtype=float) for m in
                                          (self.A, self.B, self.C, self.D))
        nx = self.A.shape[0]
        if self.A.shape != (nx, nx) or self.B.shape != (nx, 2) or self.C.shape != (2, nx) \
                or self.D.shape != (2, 2):
            raise ValueError(
                f"state-space shapes A{self.A.shape} B{self.B.shape} C{self.C.shape} "
                f"D{self.D.shape} do not form a 2-input 2-output model"
            )
        if self.transform not in TRANSFORMS:
            raise ValueError(f"unknown input transform {self.transform!r}")
        self._dt_g = STANDARD_GRAVITY / self.fs_hz
        self.x = np.zeros(nx)
        self._xn = np.zeros(nx)
        self._bu = np.zeros(nx)
        self._u = np.zeros(2)
        self._y = np.zeros(2)
        self._du = np.zeros(2)
        self.reset()

    def reset(self) -> None:
        """Back to rest: zero state, zero integral, BRS reference taken at the next step."""
        self.x[:] = 0.0
        self._velocity = 0.0
        self._brs_prev: float | None = None

    def step(self, pulse_g: float, brs_rad: float) -> np.ndarray:
        """One tick: returns [cr_g, cd_mm] (a view of a preallocated array; copy to keep)."""
        u = self._u
        if self.transform == "raw":
            u[0] = pulse_g
            u[1] = brs_rad
        else:
            self._velocity += pulse_g * self._dt_g
            prev = brs_rad if self._brs_prev is None else self._brs_prev
            self._brs_prev = brs_rad
            u[0] = self._velocity
            u[1] = (brs_rad - prev) * self.fs_hz
        # Preallocated buffers only: no array is created per tick.
        y = self._y
        np.dot(self.C, self.x, out=y)
        np.dot(self.D, u, out=self._du)
        y += self._du
        np.dot(self.A, self.x, out=self._xn)
        np.dot(self.B, u, out=self._bu)
        self._xn += self._bu
        self.x, self._xn = self._xn, self.x
        return y

    def simulate(self, pulse_g: np.ndarray, brs_rad: np.ndarray) -> np.ndarray:
        """Simulate from rest over whole records, (n,) or (tests, n) -> (..., n, 2)."""
        u = transform_inputs(self.transform, pulse_g, brs_rad, self.fs_hz)
        return simulate_ss(self.A, self.B, self.C, self.D, u)


def simulate_ss(A: np.ndarray, B: np.ndarray, C: np.ndarray, D: np.ndarray,
                u: np.ndarray) -> np.ndarray:
    """Zero-initial-state response to u of shape (n, nu) or (tests, n, nu), vectorised over
    tests; returns (..., n, ny)."""
    squeeze = u.ndim == 2
    u3 = u[None] if squeeze else u
    ntest, n, _ = u3.shape
    bu = u3 @ B.T  # (tests, n, nx): input contribution, computed once
    x = np.zeros((ntest, A.shape[0]))
    xs = np.empty((ntest, n, A.shape[0]))
    At = A.T
    for k in range(n):
        xs[:, k] = x
        x = x @ At + bu[:, k]
    y = xs @ C.T + u3 @ D.T
    return y[0] if squeeze else y
