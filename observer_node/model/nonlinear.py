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
per-tick call. :func:`simulate_many` runs several models of one structure (a fit's trial
parameters) as one simulation: a simulation of a few tests spends its time on numpy's
per-call overhead, tick by tick, which the models then share.

An input delay may be a fraction of a tick: the delayed input is interpolated linearly between
the two samples around it (a sensor ECU's filter lag is rarely a whole tick).

Scope: an effect with ``"setups": [names]`` acts only on tests of those setups (an airbag on
the sled and full-vehicle tests, not on the hard-seat rig). The daemon builds the observer for
its bench's one setup (the other setups' effects are left out); identification simulates many
tests at once with each test's setup, and a scoped effect acts where its mask is true.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..units import STANDARD_GRAVITY
from .chest import discrete
from .effects import EFFECTS, Force, Kinematics, Num, kinematics
from .observer import transform_inputs

G0 = STANDARD_GRAVITY


class ScopeError(ValueError):
    """A model with effects scoped to setups, run without saying which setup."""


def applies(effect: dict, setup: str) -> bool:
    """Whether ``effect`` acts on a test of ``setup`` (unscoped effects act everywhere)."""
    return "setups" not in effect or setup in effect["setups"]


class NonlinearGreyBox:
    """Same interface as :class:`LinearObserver`: ``reset``, ``step``, ``simulate``.

    ``setups``: the bench's setup (a name: the observer of that setup, for ``step``), or each
    test's setup (a list, for ``simulate`` over that many tests); needed when an effect is
    scoped to setups."""

    def __init__(self, base: dict[str, float], effects: list[dict], fs_hz: float,
                 setups: str | list[str] | None = None, after_input: bool = True):
        scoped = sorted({s for e in effects for s in e.get("setups", ())})
        if scoped and setups is None:
            raise ScopeError("the model has effects scoped to setups " + ", ".join(scoped)
                             + ": say which setup this is")
        if isinstance(setups, str):
            effects = [e for e in effects if applies(e, setups)]
            setups = None
        self.base = dict(base)
        self.effects = [dict(e) for e in effects]
        self.fs_hz = fs_hz
        self.after_input = after_input
        # per effect: None (acts on every test) or a bool mask over the tests of simulate()
        self.test_setups = setups
        self.masks = [None if setups is None or "setups" not in e else
                      np.array([applies(e, s) for s in setups]) for e in self.effects]
        self.Ad, self.Bd, self.Gd, self.C, self.Df = discrete(self.base, fs_hz)
        # how each effect acts is its definition's (model.effects): held forces, the belt
        # switch, input delays, output offsets
        acts = [EFFECTS[e["kind"]].acts for e in self.effects]
        self.force_effects = [(e["kind"], e.get("parameters", {}), m)
                              for e, m, a in zip(self.effects, self.masks, acts, strict=True)
                              if a == "force"]
        self._force_fns: list[tuple[Force, dict, np.ndarray | None]] = [
            (_force_of(kind), p, m) for kind, p, m in self.force_effects]
        self.unloading = "belt_slack" in acts
        self.unloading_mask = next((m for m, a in zip(self.masks, acts, strict=True)
                                    if a == "belt_slack"), None)
        self._k2, self._c2, self._R = self.base["k2"], self.base["c2"], self.base["R"]
        slack = discrete({**self.base, "k2": 0.0, "c2": 0.0}, fs_hz)
        self.Ad_slack, self.Bd_slack, self.Gd_slack = slack[:3]
        # delays in ticks, possibly fractional: whole ticks i and the fraction f
        (self.n_pulse, self.n_brs), self.delay_mask = self._params_of("input_delay")
        self._ip, self._fp = _whole(self.n_pulse), self.n_pulse - _whole(self.n_pulse)
        self._ib, self._fb = _whole(self.n_brs), self.n_brs - _whole(self.n_brs)
        off, self.offset_mask = self._params_of("output_offset")
        self.offset = np.array(off)
        self._dt_g = G0 / fs_hz
        self.x = np.zeros(6)
        self._xn = np.zeros(6)
        self._tmp = np.zeros(6)
        self._y2 = np.zeros(2)
        self._y = np.zeros(2)
        self._u = np.zeros(2)
        self._f = np.zeros(2)
        self._pulse_ring = np.zeros(self._ip + 2)
        self._brs_ring = np.zeros(self._ib + 2)
        self.reset()

    @property
    def A(self) -> np.ndarray:
        """The discrete state matrix (as a linear observer's ``A``)."""
        return self.Ad

    def _params_of(self, acts: str) -> tuple[list[float], np.ndarray | None]:
        """Parameter values (in their definition's order: pulse and BRS for a delay, CR and
        CD for an offset; absent ones 0) and mask of the effect that acts as ``acts``."""
        for e, m in zip(self.effects, self.masks, strict=True):
            spec = EFFECTS[e["kind"]]
            if spec.acts == acts:
                return [float(e["parameters"].get(p.name, 0.0)) for p in spec.params], m
        return [0.0, 0.0], None

    # ------------------------------------------------------------------ per tick
    def reset(self) -> None:
        self.x[:] = 0.0
        self._velocity = 0.0
        self._theta_prev: float | None = None
        self._pulse_ring[:] = 0.0
        self._brs_ring[:] = math.nan
        self._brs_first = 0.0
        self._k = 0

    @staticmethod
    def _delayed(ring: np.ndarray, k: int, i: int, f: float, before: float) -> float:
        """The input ``i + f`` ticks ago from a ring holding sample j at j % len(ring);
        ``before``: its value before the first sample."""
        n = len(ring)
        a = ring[(k - i) % n] if k >= i else before
        b = ring[(k - i - 1) % n] if k >= i + 1 else before
        return float(a + f * (b - a))

    def step(self, pulse_g: float, brs_rad: float) -> np.ndarray:
        k = self._k
        self._k = k + 1
        if self.n_pulse:
            self._pulse_ring[k % len(self._pulse_ring)] = pulse_g
            pulse_g = self._delayed(self._pulse_ring, k, self._ip, self._fp, 0.0)
        if self.n_brs:
            if k == 0:
                self._brs_first = brs_rad
            self._brs_ring[k % len(self._brs_ring)] = brs_rad
            brs_rad = self._delayed(self._brs_ring, k, self._ib, self._fb, self._brs_first)
        self._velocity += pulse_g * self._dt_g
        prev = brs_rad if self._theta_prev is None else self._theta_prev
        self._theta_prev = brs_rad
        u = self._u
        u[0] = self._velocity
        u[1] = (brs_rad - prev) * self.fs_hz
        f = self._f
        z = self.x
        self._forces(z, u[0], u[1], brs_rad, f)
        # Preallocated buffers only: no array is created per tick (the effect forces are
        # floats).
        if not self.after_input:  # files before 0.2: the output of the state before the tick
            self._output(z, f)
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
        if self.after_input:  # the state after this tick's inputs, its forces evaluated there
            self._forces(xn, u[0], u[1], brs_rad, f)
            self._output(xn, f)
        return self._y

    def _output(self, z: np.ndarray, f: np.ndarray) -> None:
        """y = C z + Df f + offset, into the preallocated output."""
        y = self._y
        np.dot(self.C, z, out=y)
        np.dot(self.Df, f, out=self._y2)
        y += self._y2
        y += self.offset

    def _forces(self, z: np.ndarray, u1: float, u2: float, theta: float, f: np.ndarray) -> None:
        f[0] = f[1] = 0.0
        if not self._force_fns:
            return
        k = kinematics(z, u1, u2, theta, self.base)
        for force, p, _ in self._force_fns:
            fs, fn = force(p, k, self.base)
            f[0] += fs
            f[1] += fn

    def belt_slack(self, z: np.ndarray, u1: Num, u2: Num) -> Num:
        """True where the belt would push (force k2 e + c2 e' < 0): float or array."""
        return _pushes(self._k2, self._c2, z[4] - z[3], u1 + self._R * u2 - z[2])

    # ------------------------------------------------------------------ whole records
    def simulate(self, pulse_g: np.ndarray, brs_rad: np.ndarray) -> np.ndarray:
        """From rest, (n,) or (tests, n) -> (..., n, 2)."""
        y = simulate_many([self], np.atleast_2d(pulse_g), np.atleast_2d(brs_rad))[0]
        return y[0] if pulse_g.ndim == 1 else y

    def run_transformed(self, u1: np.ndarray, u2: np.ndarray, theta: np.ndarray,
                        states: np.ndarray | None = None) -> np.ndarray:
        """Outputs (tests, n, 2); the states (6, tests, n) go into ``states`` if given."""
        return _run([self], u1[None], u2[None], theta[None], states)[0]

    def _check_tests(self, ntest: int) -> None:
        if self.test_setups is not None and len(self.test_setups) != ntest:
            raise ScopeError(f"{ntest} tests simulated, setups given for "
                             f"{len(self.test_setups)}")


def simulate_many(models: Sequence[NonlinearGreyBox], pulse_g: np.ndarray,
                  brs_rad: np.ndarray) -> np.ndarray:
    """Models of one structure (the same effects with the same parameter names, scopes, tests
    and output timing; the parameter values may differ) on the same records (tests, n), from
    rest -> (models, tests, n, 2). ValueError for models of different structures.

    Each model's outputs are those it gives alone, to the bit: the forces are the same
    elementwise arithmetic, and each stacked matrix product equals the product alone on
    OpenBLAS, which packs its operands (tests/test_models.py checks every effect). The
    ticks' numpy calls are shared, which is where a simulation of a few tests spends its
    time."""
    if not models:
        raise ValueError("simulate_many: no models")
    first = models[0]
    shape = _structure(first)
    if any(_structure(m) != shape for m in models[1:]):
        raise ValueError("simulate_many: the models differ in structure (effects, parameter "
                         "names, scopes, tests or output timing)")
    P = np.asarray(pulse_g, float)
    T = np.asarray(brs_rad, float)
    if P.ndim != 2 or P.shape != T.shape:
        raise ValueError("simulate_many: records as (tests, n), the pulse's and BRS's alike")
    first._check_tests(P.shape[0])
    keys = [(m.n_pulse, m.n_brs) for m in models]
    inputs: dict[tuple[float, float], tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
    for m, key in zip(models, keys, strict=True):  # each delay's inputs, worked out once
        if key not in inputs:
            inputs[key] = _inputs_of(m, P, T)
    u1, u2, th = (np.stack([inputs[key][i] for key in keys]) for i in range(3))
    return _run(models, u1, u2, th)


def _inputs_of(m: NonlinearGreyBox, P: np.ndarray, T: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The inputs the model's state equations see, (tests, n) each: u1, u2 and theta after
    the model's input delays."""
    Pm = _shift(P, m.n_pulse, np.zeros((P.shape[0], 1)), m.delay_mask) if m.n_pulse else P
    Tm = _shift(T, m.n_brs, T[:, :1], m.delay_mask) if m.n_brs else T
    u = transform_inputs("velocity_brs_rate", Pm, Tm, m.fs_hz)
    return u[..., 0], u[..., 1], Tm


def belt_force_n(m: NonlinearGreyBox, pulse_g: np.ndarray, brs_rad: np.ndarray) -> np.ndarray:
    """The belt's force k2 e + c2 e' [N] (+ = the belt pulls the sternum; e = w - s) along the
    model's simulation of records (tests, n), from rest -> (tests, n): the linear belt's
    force, whether or not a slack belt (``belt_unloading``) switches it off there."""
    P = np.atleast_2d(np.asarray(pulse_g, float))
    T = np.atleast_2d(np.asarray(brs_rad, float))
    m._check_tests(P.shape[0])
    u1, u2, th = _inputs_of(m, P, T)
    states = np.zeros((6, *P.shape))
    _run([m], u1[None], u2[None], th[None], states)
    k = kinematics(states, u1, u2, th, m.base)
    return np.asarray(m.base["k2"] * k.e + m.base["c2"] * k.ed)


def _names(p: Mapping[str, Any]) -> tuple[object, ...]:
    """A parameter dict's names in order, nested dicts (the formula's terms) as their own."""
    return tuple((k, _names(v)) if isinstance(v, Mapping) else k for k, v in p.items())


def _structure(m: NonlinearGreyBox) -> tuple[object, ...]:
    """What models run together must share: values are stacked by the first model's names,
    and a formula sums its terms in their order."""
    return (tuple((e["kind"], _names(e.get("parameters", {}))) for e in m.effects),
            tuple(None if k is None else tuple(k.tolist()) for k in m.masks),
            None if m.test_setups is None else tuple(m.test_setups),
            _names(m.base), m.after_input, m.fs_hz)


def _pushes(k2: Num, c2: Num, e: Num, ed: Num) -> Num:
    """Whether the belt force k2 e + c2 e' would be negative (it would push), at belt
    penetrations e = w - s [m] and their rates e' = u1 + R u2 - sdot [m/s]."""
    return k2 * e + c2 * ed < 0.0


def _stacked(values: Sequence[Any]) -> Any:
    """One parameter (or base) value per model -> a column (models, 1) broadcasting over the
    tests; nested dicts (the formula's terms) leaf by leaf, by the first model's names (the
    same in every model: :func:`_structure`)."""
    if isinstance(values[0], Mapping):
        return {k: _stacked([v[k] for v in values]) for k in values[0]}
    return np.array(values, float)[:, None]


def _run(models: Sequence[NonlinearGreyBox], u1: np.ndarray, u2: np.ndarray,
         theta: np.ndarray, states: np.ndarray | None = None) -> np.ndarray:
    """The models (of one structure) on transformed inputs (models, tests, n) -> outputs
    (models, tests, n, 2); ``states`` (6, tests, n): the one model's states.

    One model runs on arrays without the models' axis (a tick's products are then plain
    matrix products, a third cheaper than stacked ones of one); several on stacked matrices
    and parameter columns. The same code serves both: the models' axis, when there, leads."""
    first = models[0]
    nm, ntest, n = u1.shape
    if states is not None and nm != 1:
        raise ValueError("the states are kept for one model only")
    lead = () if nm == 1 else (nm,)

    def per_model(values: list[Any]) -> Any:
        return values[0] if nm == 1 else _stacked(values)

    Ad, Bd, Gd, C, Df, Ad_s, Bd_s, Gd_s = (
        getattr(first, a) if nm == 1 else np.stack([getattr(m, a) for m in models])
        for a in ("Ad", "Bd", "Gd", "C", "Df", "Ad_slack", "Bd_slack", "Gd_slack"))
    base = per_model([m.base for m in models])
    # the forces: one formula each, its parameters (a column per model), its scope's mask
    forces = [(fn, per_model([m._force_fns[j][1] for m in models]), mask)
              for j, (fn, _, mask) in enumerate(first._force_fns)]
    z = np.zeros((*lead, 6, ntest))
    yt = np.empty((n, *lead, 2, ntest))  # by tick, as the products come; turned once at the end
    # each tick's inputs as contiguous ([models,] 2, tests), laid out once: a tick reads views
    inputs = np.ascontiguousarray(np.stack([u1, u2], axis=1).transpose(3, 0, 1, 2))
    theta_t = np.ascontiguousarray(theta.transpose(2, 0, 1))
    if nm == 1:
        inputs, theta_t = inputs[:, 0], theta_t[:, 0]
    # without force effects the force is zero at every tick: one array, read only
    no_force = None if forces else np.zeros((*lead, 2, ntest))
    # what every tick reads, looked up once
    after_input, unloading, unloading_mask = first.after_input, first.unloading, \
        first.unloading_mask
    k2, c2 = base["k2"], base["c2"]
    reads_state = no_force is None or unloading

    f_now = np.zeros((*lead, 2, ntest))  # the forces of the tick, rewritten each time

    def forces_at(k: Kinematics) -> np.ndarray:
        f = f_now
        for j, (force, p, mask) in enumerate(forces):
            s1, s2 = force(p, k, base)
            if mask is not None:
                s1, s2 = s1 * mask, s2 * mask
            if j:
                f[..., 0, :] += s1
                f[..., 1, :] += s2
            else:  # 0 + s: what adding to zeros gives, to the bit (-0 becomes +0)
                np.add(s1, 0.0, out=f[..., 0, :])
                np.add(s2, 0.0, out=f[..., 1, :])
        return f

    for tick in range(n):
        if states is not None:
            states[:, :, tick] = z
        ab = inputs[tick]
        a, b, th = ab[..., 0, :], ab[..., 1, :], theta_t[tick]
        # the state's rows first; read by the forces and the belt switch alike
        k = kinematics(z.swapaxes(0, -2), a, b, th, base) if reads_state else None
        slack = None
        if unloading and k is not None:  # before the forces, which read the same k
            slack = _pushes(k2, c2, k.e, k.ed)
            if unloading_mask is not None:
                slack = slack & unloading_mask
        f = no_force if no_force is not None or k is None else forces_at(k)
        if not after_input:
            np.add(C @ z, Df @ f, out=yt[tick])
        zn = Ad @ z + Bd @ ab + Gd @ f
        if slack is not None and slack.any():
            zn = np.where(slack[..., None, :], Ad_s @ z + Bd_s @ ab + Gd_s @ f, zn)
        z = zn
        if after_input:
            if no_force is None:
                f = forces_at(kinematics(z.swapaxes(0, -2), a, b, th, base))
            np.add(C @ z, Df @ f, out=yt[tick])
    y = np.moveaxis(yt, (0, -2, -1), (-2, -1, -3))  # ([models,] tests, n, 2), a view
    offset = first.offset if nm == 1 else np.stack([m.offset for m in models])[:, None, None]
    if first.offset_mask is not None:
        y = np.add(y, first.offset_mask[:, None, None] * offset, order="C")
    else:
        y = np.add(y, offset, order="C")
    return y[None] if nm == 1 else y


def _force_of(kind: str) -> Force:
    force = EFFECTS[kind].force
    assert force is not None  # register() refuses a force without its formula
    return force


def _whole(n_ticks: float) -> int:
    """Whole ticks of a delay; a negative delay (down to -1 tick) extrapolates linearly from
    the last two samples: i = 0, f < 0."""
    return max(math.floor(n_ticks), 0)


def _shift(X: np.ndarray, n_ticks: float, before: np.ndarray,
           mask: np.ndarray | None) -> np.ndarray:
    """Rows of ``X`` delayed by ``n_ticks`` (fractional: linear between samples), ``before``
    (a column) filling the start; only the rows where ``mask`` is true when it is given."""
    i = _whole(n_ticks)
    f = n_ticks - i
    n = X.shape[1]
    padded = np.concatenate([np.repeat(before, i + 1, axis=1), X], axis=1)
    out = (1 - f) * padded[:, 1:1 + n] + f * padded[:, :n]
    return out if mask is None else np.where(mask[:, None], out, X)
