"""Physical effects that can be added to the thesis's grey-box chest, as forces.

Each effect is a closed-form force on the spine (m1) and/or the sternum (m2) computed from the
state z = (xdot, x, sdot, s, w, p) [SI; p = vehicle displacement, the double integral of the
pulse], the transformed inputs u1 = vehicle velocity change [m/s], u2 = BRS rate [rad/s], the
BRS angle theta [rad], and the base parameters (k2, c2, R). Input delays and sensor offsets act
on the inputs and outputs instead. The formulas work on floats (the daemon, per tick) and on
numpy arrays (identification, vectorised over tests).

Knows nothing about how an effect was found or fitted.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, TypeAlias

import numpy as np

# A float (the daemon, per tick) or an array over tests (identification). Any, because
# numpy's stubs do not type arithmetic mixing the two.
Num: TypeAlias = Any

# kind -> (description, {parameter: (unit, typical magnitude)})
EFFECTS: dict[str, tuple[str, dict[str, tuple[str, float]]]] = {
    "chest_stiffening": ("rib cage stiffness hardening: F = k3 d^3 between spine and sternum "
                         "(d = s - x, chest compression)", {"k3": ("N/m^3", 1e8)}),
    "chest_rate_damping": ("rate-dependent rib damping: F = c3 d' |d'| between spine and "
                           "sternum", {"c3": ("N s^2/m^2", 1e3)}),
    "belt_unloading": ("one-sided belt: the belt force k2 e + c2 e' (e = w - s) cannot push; "
                       "its negative part is removed", {}),
    "belt_stiffening": ("belt/flesh stiffness hardening: F = kb3 e^3 on the sternum "
                        "(e = w - s, belt penetration)", {"kb3": ("N/m^3", 1e8)}),
    "airbag_contact": ("airbag: F = max(kab (p - x - gap) + cab (p' - x'), 0) on the sternum "
                       "once the occupant's forward excursion p - x exceeds gap (the bag "
                       "pushes, never pulls; cab: its venting)",
                       {"kab": ("N/m", 3e4), "gap": ("m", 0.1), "cab": ("N s/m", 300.0)}),
    "pelvis_coupling": ("extra load path spine-vehicle (pelvis, lap belt, seat): "
                        "F = kp (p - x) + cp (p' - x') on the spine",
                        {"kp": ("N/m", 1e4), "cp": ("N s/m", 300.0)}),
    "input_delay": ("transport delay of the inputs: pulse by n_pulse ticks, BRS by n_brs ticks "
                    "(fractions of a tick: linear between samples)",
                    {"n_pulse": ("ticks", 1.0), "n_brs": ("ticks", 1.0)}),
    "input_gain": ("BRS gain changing with the spindle angle: belt travel R (theta + g "
                   "theta^2 / 2)", {"g": ("1/rad", 0.02)}),
    "sensor_offset": ("constant offsets on the measured outputs", {"cr_g": ("g", 1.0),
                                                                    "cd_mm": ("mm", 1.0)}),
    "other": ("sparse combination of candidate forces found by regression on the residual "
              "(see the formula)", {}),
}
# Parameters that must be positive to mean what their name says (a hardening stiffness, a
# damping, a contact, a gap); the others (offsets, gain change, "other") may take any sign.
POSITIVE = frozenset({"k3", "c3", "kb3", "kab", "gap", "cab", "kp", "cp", "n_pulse", "n_brs"})
FORCE_KINDS = ("chest_stiffening", "chest_rate_damping", "belt_unloading", "belt_stiffening",
               "airbag_contact", "pelvis_coupling", "input_gain", "other")

# Candidate terms for "other": name -> (function of the kinematic quantities, applied to)
OTHER_TERMS = ("d^2", "d^3", "d'|d'|", "e^2", "e^3", "e'|e'|", "d e", "d d'")


def _kinematics(z: np.ndarray | Sequence[Num], u1: Num, u2: Num,
                base: dict[str, float]) -> tuple[Num, ...]:
    xd, x, sd, s, w, p = z
    d, dd = s - x, sd - xd
    e = w - s
    ed = u1 + base["R"] * u2 - sd
    return xd, x, p, d, dd, e, ed


def other_term(name: str, d: Num, dd: Num, e: Num, ed: Num) -> Num:
    return {"d^2": d * d, "d^3": d * d * d, "d'|d'|": dd * abs(dd), "e^2": e * e,
            "e^3": e * e * e, "e'|e'|": ed * abs(ed), "d e": d * e, "d d'": d * dd}[name]


def effect_forces(kind: str, p: dict, z: np.ndarray | Sequence[Num], u1: Num, u2: Num, theta: Num,
                  base: dict) -> tuple[Num, Num]:
    """(force on the spine, force on the sternum) [N] of one effect, + = rearward."""
    xd, x, pos, d, dd, e, ed = _kinematics(z, u1, u2, base)
    zero = 0.0 * d
    if kind == "chest_stiffening":
        f = p["k3"] * d * d * d
        return f, -f
    if kind == "chest_rate_damping":
        f = p["c3"] * dd * abs(dd)
        return f, -f
    if kind == "belt_unloading":
        belt = base["k2"] * e + base["c2"] * ed
        return zero, -np.minimum(belt, 0.0)
    if kind == "belt_stiffening":
        return zero, p["kb3"] * e * e * e
    if kind == "airbag_contact":
        ex = pos - x - p["gap"]
        f = np.maximum(p["kab"] * ex + p.get("cab", 0.0) * (u1 - xd), 0.0)
        return zero, f * (ex > 0.0)
    if kind == "pelvis_coupling":
        return p["kp"] * (pos - x) + p["cp"] * (u1 - xd), zero
    if kind == "input_gain":
        dw = base["R"] * p["g"] * theta * theta / 2
        dwd = base["R"] * p["g"] * theta * u2
        return zero, base["k2"] * dw + base["c2"] * dwd
    if kind == "other":
        f_rib = sum(c * other_term(n, d, dd, e, ed) for n, c in p.get("rib", {}).items())
        f_belt = sum(c * other_term(n, d, dd, e, ed) for n, c in p.get("belt", {}).items())
        return zero + f_rib, zero - f_rib + f_belt
    return zero, zero


def describe(kind: str, parameters: dict) -> str:
    if kind == "other":
        rib = " + ".join(f"{c:.4g}·{n}" for n, c in parameters.get("rib", {}).items())
        belt = " + ".join(f"{c:.4g}·{n}" for n, c in parameters.get("belt", {}).items())
        parts = ([f"rib force += {rib}"] if rib else []) + ([f"belt force += {belt}"]
                                                            if belt else [])
        return "; ".join(parts) + " (d = s - x, e = w - s, SI units)"
    return EFFECTS[kind][0]
