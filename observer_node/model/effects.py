"""Effects that can be added to the thesis's grey-box chest: one definition each, registered once.

An :class:`Effect` says everything the package needs to know of one kind: its family (physical
or sensor), its parameters (unit, sign, typical size, bounds), how it acts on the model (a force,
the slack-belt switch, an input delay, an output offset), its force as a closed-form formula,
the same formula in C, how the loop searches its starting parameters, the simulator's truth form
and its description. The model file's schema, the non-linear model, the C export, the loop's
candidate search, the simulator and the help texts read :data:`EFFECTS`, so a new effect is one
more ``register(Effect(...))`` below.

Forces act on the spine (m1) and/or the sternum (m2), computed from the state
z = (xdot, x, sdot, s, w, p) [SI; p = vehicle displacement, the double integral of the pulse],
the transformed inputs u1 = vehicle velocity change [m/s], u2 = BRS rate [rad/s], the BRS angle
theta [rad], and the base parameters (k2, c2, R). The formulas work on floats (the daemon, per
tick) and on numpy arrays (identification, vectorised over tests); there the effect's and
base parameters may be columns (models, 1) too (a fit's trial parameter sets run as one
simulation), so a formula uses numpy's arithmetic on them: no ``float()``, ``math`` or
``if``. A formula reads the kinematics by name (``k.d``), never writes into them or its
parameters (no ``+=`` or ``out=`` on what it reads): every formula of a tick, and the belt's
switch, read the same arrays.

Knows nothing about how an effect is fitted: ``search`` names a method the loop implements.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Literal, TypeAlias

import numpy as np

# A float (the daemon, per tick) or an array over tests (identification). Any, because
# numpy's stubs do not type arithmetic mixing the two.
Num: TypeAlias = Any


class Kinematics:
    """What a force formula may read, at one state (floats or arrays over tests).

    The derived quantities (d, dd, e, ed, zero) are worked out when a formula first reads
    them, once per state: a tick then pays only for what its effects read (a simulation
    spends its time in these few numpy calls per tick). Read by name; not a tuple."""

    __slots__ = ("_R", "_d", "_dd", "_e", "_ed", "_s", "_sd", "_w", "_zero", "pos", "theta",
                 "u1", "u2", "x", "xd")
    xd: Num  # spine velocity [m/s]
    x: Num  # spine displacement [m]
    pos: Num  # vehicle displacement p [m]
    u1: Num  # vehicle velocity change [m/s]
    u2: Num  # BRS rate [rad/s]
    theta: Num  # BRS angle [rad]

    def __init__(self, z: np.ndarray | Sequence[Num], u1: Num, u2: Num, theta: Num,
                 R: Num) -> None:
        self.xd, self.x, self._sd, self._s, self._w, self.pos = z
        self.u1, self.u2, self.theta, self._R = u1, u2, theta, R
        self._d: Num = None
        self._dd: Num = None
        self._e: Num = None
        self._ed: Num = None
        self._zero: Num = None

    @property
    def d(self) -> Num:
        """Chest compression s - x [m]."""
        if self._d is None:
            self._d = self._s - self.x
        return self._d

    @property
    def dd(self) -> Num:
        """Its rate [m/s]."""
        if self._dd is None:
            self._dd = self._sd - self.xd
        return self._dd

    @property
    def e(self) -> Num:
        """Belt penetration w - s [m]."""
        if self._e is None:
            self._e = self._w - self._s
        return self._e

    @property
    def ed(self) -> Num:
        """Its rate u1 + R u2 - sdot [m/s]."""
        if self._ed is None:
            self._ed = self.u1 + self._R * self.u2 - self._sd
        return self._ed

    @property
    def zero(self) -> Num:
        """0 shaped like d (NaN where d is: a trial that ran away stays visible)."""
        if self._zero is None:
            self._zero = 0.0 * self.d
        return self._zero


def kinematics(z: np.ndarray | Sequence[Num], u1: Num, u2: Num, theta: Num,
               base: Mapping[str, Any]) -> Kinematics:
    """The kinematics at state z = (xdot, x, sdot, s, w, p) and inputs u1, u2, theta."""
    return Kinematics(z, u1, u2, theta, base["R"])


# (parameters, kinematics, base parameters) -> (force on the spine, on the sternum) [N],
# + = rearward
Force: TypeAlias = Callable[[Mapping[str, Any], Kinematics, Mapping[str, float]],
                            tuple[Num, Num]]
# (parameters, a number as a C literal, the base's k2 c2 R as C literals) -> C lines adding
# the force to fs (spine) and fn (sternum). In scope: d, dd, e, ed, pos, z[0..5] (the state),
# u[0], u[1] (u1, u2), theta; libm's fabs.
CCode: TypeAlias = Callable[[Mapping[str, Any], Callable[[float], str], Mapping[str, str]], str]


@dataclass(frozen=True)
class Param:
    name: str
    unit: str
    typical: float  # a typical magnitude: where the search starts and its scale
    positive: bool = False  # must be > 0 to mean what its name says (fitted as a logarithm)
    required: bool = True  # the formula cannot do without it (else it defaults to 0)
    bounds: tuple[float, float] | None = None  # what a model file may hold
    # the values for which the effect is what its name says: fitted within them (lo +
    # (hi - lo) (1 + tanh t) / 2), and the model file's bounds
    within: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        if self.within is not None and self.bounds is None:
            object.__setattr__(self, "bounds", self.within)


@dataclass(frozen=True)
class Search:
    """How the loop finds an effect's starting parameters (each method is implemented once,
    in :mod:`observer_node.loop.analysis`):

    - ``scale``: the signature at typical parameters regressed on the residual scales every
      parameter (by its magnitude, at least 0.1, unless a parameter may take either sign),
      then a short fit of the effect's parameters;
    - ``grid``: as ``scale`` at each value in ``grid`` of the parameter ``over``, the best kept;
    - ``switch``: parameter-free, scored as it is (the loop always cross-validates it: its
      signature linearised along a trajectory that never switches predicts it badly);
    - ``delay``: each parameter an input delay in ticks, searched on a grid and refined;
    - ``offset``: each parameter a constant on one output (in the order CR, CD), read from
      the first samples after contact;
    - ``sparse``: a sparse regression over force terms (the formula "other")."""

    method: Literal["scale", "grid", "switch", "delay", "offset", "sparse"] = "scale"
    over: str = ""
    grid: tuple[float, ...] = ()


@dataclass(frozen=True)
class Effect:
    kind: str
    family: Literal["physical", "sensor"]
    description: str
    params: tuple[Param, ...] = ()
    # how the model applies it: a force held over the tick, the switch to the belt-free
    # matrices while the belt would push, a delay of the inputs, an offset of the outputs
    acts: Literal["force", "belt_slack", "input_delay", "output_offset"] = "force"
    force: Force | None = None  # also the signature of a switch
    c_code: CCode | None = None  # a force in C (the others are the export's own)
    search: Search = Search()
    plant: str | None = None  # the simulator's truth form at scale 1 (None: not simulated)
    # metadata words ruling the effect out on a setup, and why (see observer_node.data.setups)
    needs: tuple[re.Pattern[str], str] | None = None
    # the JSON schema of "parameters" when ``params`` cannot say it (the formula's terms)
    parameters_schema: Mapping[str, Any] | None = None
    explain: Callable[[Mapping[str, Any]], str] | None = None  # describe() of the parameters
    # a physical effect the library lacks whose signature on the rigs seen is this one's:
    # said beside the verdict, so a named effect is not read as the only reading
    looks_alike: str | None = None

    @property
    def units(self) -> dict[str, str]:
        return {p.name: p.unit for p in self.params}

    @property
    def typical(self) -> dict[str, float]:
        return {p.name: p.typical for p in self.params}

    def param(self, name: str) -> Param | None:
        return next((p for p in self.params if p.name == name), None)

    def positive(self, name: str) -> bool:
        p = self.param(name)
        return p is not None and p.positive


_REGISTRY: dict[str, Effect] = {}
EFFECTS: Mapping[str, Effect] = MappingProxyType(_REGISTRY)  # kind -> Effect, in order
_version = [0]  # bumped on every change, for readers that cache what they build from it


def register(effect: Effect) -> Effect:
    """Add ``effect`` to :data:`EFFECTS`; ValueError if its kind is taken or it is incomplete."""
    if effect.kind in _REGISTRY:
        raise ValueError(f"effect {effect.kind!r} is registered already")
    if effect.acts in ("force", "belt_slack") and effect.force is None:
        raise ValueError(f"effect {effect.kind!r} acts as a force but has no formula")
    if effect.search.method in ("scale", "grid") and not effect.params:
        raise ValueError(f"effect {effect.kind!r}: nothing to search (no parameters)")
    if (effect.acts in ("input_delay", "output_offset")
            or effect.search.method in ("delay", "offset")) and len(effect.params) != 2:
        raise ValueError(f"effect {effect.kind!r}: a delay or offset has one parameter per "
                         "input or output (two)")
    if effect.search.method == "grid" and effect.param(effect.search.over) is None:
        raise ValueError(f"effect {effect.kind!r}: grid over unknown parameter "
                         f"{effect.search.over!r}")
    _REGISTRY[effect.kind] = effect
    _version[0] += 1
    return effect


def unregister(kind: str) -> None:
    del _REGISTRY[kind]
    _version[0] += 1


@contextmanager
def registered(effect: Effect) -> Iterator[Effect]:
    """``effect`` registered for the duration of the block (tests, experiments)."""
    register(effect)
    try:
        yield effect
    finally:
        unregister(effect.kind)


def registry_version() -> int:
    return _version[0]


def effect_forces(kind: str, p: Mapping[str, Any], z: np.ndarray | Sequence[Num], u1: Num,
                  u2: Num, theta: Num, base: Mapping[str, float]) -> tuple[Num, Num]:
    """(force on the spine, force on the sternum) [N] of one effect, + = rearward; zero for
    effects that are not forces."""
    k = kinematics(z, u1, u2, theta, base)
    force = EFFECTS[kind].force
    return (k.zero, k.zero) if force is None else force(p, k, base)


def describe(kind: str, parameters: Mapping[str, Any]) -> str:
    e = EFFECTS[kind]
    return e.explain(parameters) if e.explain is not None else e.description


# ---------------------------------------------------------------------------- the effects
def _pair(f: Num) -> tuple[Num, Num]:
    """A force between spine and sternum: + on one, - on the other."""
    return f, -f


register(Effect(
    "chest_stiffening", "physical",
    "rib cage stiffness hardening: F = k3 d^3 between spine and sternum (d = s - x, chest "
    "compression)",
    (Param("k3", "N/m^3", 1e8, positive=True),),
    force=lambda p, k, b: _pair(p["k3"] * k.d * k.d * k.d),
    c_code=lambda p, num, b: f"    {{ co_real f = {num(p['k3'])} * d * d * d; fs += f; "
                             "fn -= f; }\n",
    plant="rib stiffness k1 (1 + (d/20 mm)^2): cubic hardening of the chest"))

register(Effect(
    "chest_rate_damping", "physical",
    "rate-dependent rib damping: F = c3 d' |d'| between spine and sternum",
    (Param("c3", "N s^2/m^2", 1e3, positive=True),),
    force=lambda p, k, b: _pair(p["c3"] * k.dd * abs(k.dd)),
    c_code=lambda p, num, b: f"    {{ co_real f = {num(p['c3'])} * dd * fabs(dd); fs += f; "
                             "fn -= f; }\n",
    plant="rib damping c1 (1 + |d'| / 1 m/s): rate-dependent viscera"))

register(Effect(
    "belt_unloading", "physical",
    "one-sided belt: the belt force k2 e + c2 e' (e = w - s) cannot push; its negative part is "
    "removed",
    acts="belt_slack",
    force=lambda p, k, b: (k.zero, -np.minimum(b["k2"] * k.e + b["c2"] * k.ed, 0.0)),
    search=Search("switch"),
    plant="the belt pulls, it never pushes (force clipped at zero)"))

# A cubic. A free exponent (kb3 E^3 |e/E|^n, n 2..16) was tried on the seen held-out sets
# (2026-11-25): a bilinear webbing's offline fit rose 1.7 -> 3.9 of its 4.3 points, but no
# verdict got right, and on set G's two-effect case the loop then named an airbag that was not
# there (the flexible form, scoped to FULL, failed the setup rule, so the airbag no longer tied).
register(Effect(
    "belt_stiffening", "physical",
    "belt/flesh stiffness hardening: F = kb3 e^3 on the sternum (e = w - s, belt penetration)",
    (Param("kb3", "N/m^3", 1e8, positive=True),),
    force=lambda p, k, b: (k.zero, p["kb3"] * k.e * k.e * k.e),
    c_code=lambda p, num, b: f"    fn += {num(p['kb3'])} * e * e * e;\n",
    plant="belt/flesh stiffness k2 (1 + (e/20 mm)^2)"))


def _airbag(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]) -> tuple[Num, Num]:
    ex = k.pos - k.x - p["gap"]
    f = np.maximum(p["kab"] * ex + p.get("cab", 0.0) * (k.u1 - k.xd), 0.0)
    return k.zero, f * (ex > 0.0)


register(Effect(
    "airbag_contact", "physical",
    "airbag: F = max(kab (p - x - gap) + cab (p' - x'), 0) on the sternum once the occupant's "
    "forward excursion p - x exceeds gap (the bag pushes, never pulls; cab: its venting)",
    # gap: where the occupant meets the bag, 5-400 mm of forward excursion; a bag pushing
    # from the start is a spring to the car, not an airbag (sets Y, AF: gap 0 named for a
    # knee path and a webbing hysteresis)
    (Param("kab", "N/m", 3e4, positive=True),
     Param("gap", "m", 0.1, positive=True, within=(0.005, 0.4)),
     Param("cab", "N s/m", 300.0, positive=True, required=False)),
    force=_airbag,
    c_code=lambda p, num, b: (f"    {{ co_real ex = pos - z[1] - {num(p['gap'])};\n"
                              f"      co_real f = {num(p['kab'])} * ex + "
                              f"{num(p.get('cab', 0.0))} * (u[0] - z[0]);\n"
                              "      if (f > 0 && ex > 0) fn += f; }\n"),
    search=Search("grid", "gap", (0.04, 0.07, 0.1, 0.13, 0.16, 0.2, 0.25)),
    plant="50 kN/m, 600 N s/m on the sternum beyond 110 mm forward excursion",
    needs=(re.compile(r"HARD SEAT|RIGID SEAT|NO INTERIOR|WITHOUT INTERIOR|NO AIRBAG|"
                      r"WITHOUT AIRBAG|AIRBAG DEACTIVATED", re.IGNORECASE),
           "an airbag needs an interior with an airbag"),
    # session 54's screen (docs/loop-evidence.md, "A webbing knee, screened"): a knee passed on
    # every bag case the bag passed on, within 0.6 points in 8 of 9; sets AK and AL named a bag
    # on SLED for a webbing knee
    looks_alike="a webbing that stiffens past a knee of its pay-out (not in the library) "
                "gives the same signature on sled and full-scale rigs: on the held-out bag "
                "cases screened it passed the rule wherever the airbag did, within 0.6 "
                "points of its gain in 8 of 9, and twice an airbag was named for such a "
                "webbing; check the rig has a bag that deployed"))

register(Effect(
    "pelvis_coupling", "physical",
    "extra load path spine-vehicle (pelvis, lap belt, seat): F = kp (p - x) + cp (p' - x') on "
    "the spine",
    (Param("kp", "N/m", 1e4, positive=True), Param("cp", "N s/m", 300.0, positive=True)),
    force=lambda p, k, b: (p["kp"] * (k.pos - k.x) + p["cp"] * (k.u1 - k.xd), k.zero),
    c_code=lambda p, num, b: (f"    fs += {num(p['kp'])} * (pos - z[1]) + {num(p['cp'])} * "
                              "(u[0] - z[0]);\n"),
    plant="20 kN/m, 400 N s/m between the spine and the vehicle (lap belt, seat)"))

_TICKS = (0, 1000)  # ints: the schema says "minimum of 0", not "0.0"
register(Effect(
    "input_delay", "sensor",
    "transport delay of the inputs: pulse by n_pulse ticks, BRS by n_brs ticks (fractions of a "
    "tick: linear between samples)",
    (Param("n_pulse", "ticks", 1.0, positive=True, required=False, bounds=_TICKS),
     Param("n_brs", "ticks", 1.0, positive=True, required=False, bounds=_TICKS)),
    acts="input_delay", search=Search("delay"),
    plant="transport delay: the chest feels the pulse and belt 2 ms after the sensors record "
          "them"))


def _input_gain(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]
                ) -> tuple[Num, Num]:
    dw = b["R"] * p["g"] * k.theta * k.theta / 2
    dwd = b["R"] * p["g"] * k.theta * k.u2
    return k.zero, b["k2"] * dw + b["c2"] * dwd


# A spool's radius changes by one webbing thickness (1.0-1.3 mm) per turn: its BRS gain by
# t / (2 pi r) per radian, 0.02 /rad for a 1.3 mm webbing on a 10 mm spool. Twice that is the
# most a retractor's spool can do; beyond, a fit is mimicking something else (held-out sets
# F and G: an airbag and a late pulse, at 0.07-0.20 /rad).
G_SPOOL_MAX = 0.04

register(Effect(
    "input_gain", "physical",
    "BRS gain changing with the spindle angle: belt travel R (theta + g theta^2 / 2), "
    f"|g| <= {G_SPOOL_MAX:g} /rad (a spool's webbing build-up)",
    (Param("g", "1/rad", 0.02, within=(-G_SPOOL_MAX, G_SPOOL_MAX)),),
    force=_input_gain,
    c_code=lambda p, num, b: (f"    fn += {b['k2']} * ({b['R']} * {num(p['g'])} * theta * "
                              f"theta / 2) + {b['c2']} * ({b['R']} * {num(p['g'])} * theta * "
                              "u[1]);\n"),
    plant="BRS gain grows 10 % per revolution paid out (webbing layers)"))

register(Effect(
    "sensor_offset", "sensor", "constant offsets on the measured outputs",
    (Param("cr_g", "g", 1.0, required=False), Param("cd_mm", "mm", 1.0, required=False)),
    acts="output_offset", search=Search("offset"),
    plant="+1.5 mm on CD and +1 g on CR channels"))

# The formula's candidate terms: name -> (Python form, C form) of the kinematic quantities
_TERMS: dict[str, tuple[Callable[[Num, Num, Num, Num], Num], str]] = {
    "d^2": (lambda d, dd, e, ed: d * d, "d * d"),
    "d^3": (lambda d, dd, e, ed: d * d * d, "d * d * d"),
    "d'|d'|": (lambda d, dd, e, ed: dd * abs(dd), "dd * fabs(dd)"),
    "e^2": (lambda d, dd, e, ed: e * e, "e * e"),
    "e^3": (lambda d, dd, e, ed: e * e * e, "e * e * e"),
    "e'|e'|": (lambda d, dd, e, ed: ed * abs(ed), "ed * fabs(ed)"),
    "d e": (lambda d, dd, e, ed: d * e, "d * e"),
    "d d'": (lambda d, dd, e, ed: d * dd, "d * dd"),
}
OTHER_TERMS = tuple(_TERMS)


def other_term(name: str, d: Num, dd: Num, e: Num, ed: Num) -> Num:
    return _TERMS[name][0](d, dd, e, ed)


def _other(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]) -> tuple[Num, Num]:
    f_rib = sum(c * other_term(n, k.d, k.dd, k.e, k.ed) for n, c in p.get("rib", {}).items())
    f_belt = sum(c * other_term(n, k.d, k.dd, k.e, k.ed) for n, c in p.get("belt", {}).items())
    return k.zero + f_rib, k.zero - f_rib + f_belt


def _other_c(p: Mapping[str, Any], num: Callable[[float], str], b: Mapping[str, str]) -> str:
    def terms(where: str) -> str:
        return " + ".join(f"{num(c)} * ({_TERMS[n][1]})"
                          for n, c in p.get(where, {}).items()) or "0"
    return (f"    {{ co_real f_rib = {terms('rib')};\n"
            f"      co_real f_belt = {terms('belt')};\n"
            "      fs += f_rib; fn += -f_rib + f_belt; }\n")


def _other_text(parameters: Mapping[str, Any]) -> str:
    rib = " + ".join(f"{c:.4g}·{n}" for n, c in parameters.get("rib", {}).items())
    belt = " + ".join(f"{c:.4g}·{n}" for n, c in parameters.get("belt", {}).items())
    parts = ([f"rib force += {rib}"] if rib else []) + ([f"belt force += {belt}"]
                                                        if belt else [])
    return "; ".join(parts) + " (d = s - x, e = w - s, SI units)"


_TERM_COEFS = {"type": "object", "additionalProperties": {"type": "number"}}
register(Effect(
    "other", "physical",
    "sparse combination of candidate forces found by regression on the residual (see the "
    "formula)",
    force=_other, c_code=_other_c, search=Search("sparse"),
    parameters_schema={"type": "object",
                       "properties": {"rib": _TERM_COEFS, "belt": _TERM_COEFS}},
    explain=_other_text))
