"""Crash-test plant simulator: data with known truth for tests and demonstrations.

A vehicle (or sled) pulse, a retractor with a pretensioner and a load limiter whose spindle
angle the BRS counts, and the thesis's two-mass chest (eq. 3.1-3.8). Physical effects beyond
the thesis model can be switched on, each with a scale (1.0 = its default magnitude): those of
the effect registry (:mod:`observer_node.model.effects`) that give a truth form (``plant``,
listed in ``EFFECTS`` below). The forms themselves are written here, apart from the model's
formulas, so that the loop is tested against a plant, not against itself.

The simulation runs in two passes at 10 kHz with RK4: the first, closed loop, gives the
spindle angle (pretensioner, then the load limiter paying out above its force); the second
drives the chest with that angle and the pulse, so that without effects the recorded outputs
are those of the thesis model on the true inputs. The BRS only *measures* the angle, in whole
counts: its quantisation is an error of the recorded input, as on a real belt, which moves
smoothly whatever the sensor's resolution. (Driving the chest with the quantised angle
instead would make the belt jerk at every count, and a slack belt chatter between counts.)
Outputs are filtered like a lab's (CR CFC 180, CD CFC 600); the pulse is left unfiltered.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from .data.crashtest import CrashTest
from .data.filters import cfc_filter
from .model.effects import EFFECTS as MODEL_EFFECTS
from .units import STANDARD_GRAVITY

# The effects the plant simulates, with their truth form at scale 1 (their ``plant`` in the
# registry; the forms themselves are this module's, written apart from the model's formulas).
EFFECTS = {k: e.plant for k, e in MODEL_EFFECTS.items() if e.plant is not None}

FS_HZ = 10_000.0
T0_S = -0.02
N_SAMPLES = 2200


@dataclass
class ChestParams:
    """Thesis parameters (SI; R in m per rad of spindle angle)."""

    k1: float = 2.0e5
    c1: float = 900.0
    k2: float = 1.2e5
    c2: float = 1500.0
    m1: float = 20.0
    m2: float = 2.5
    R: float = 0.02

    def as_dict(self) -> dict[str, float]:
        return dict(self.__dict__)


@dataclass
class PlantConfig:
    chest: ChestParams = field(default_factory=ChestParams)
    effects: dict[str, float] = field(default_factory=dict)
    noise: bool = True
    counts_per_rev: int = 96
    load_limit_n: float = 4000.0
    pretension_rad: float = 2.0
    # transport delays of one input only (a sensor ECU's filter, a slow BRS decoder), ms;
    # the effect ``input_delay`` delays both by 2 ms times its scale
    pulse_delay_ms: float = 0.0
    brs_delay_ms: float = 0.0

    def __post_init__(self) -> None:
        unknown = set(self.effects) - set(EFFECTS)
        if unknown:
            raise ValueError(f"unknown effects {sorted(unknown)}; known: {', '.join(EFFECTS)}")


def pulse_shape(setup: str, t_s: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Deceleration in m/s^2 (positive) for a setup, randomised per test."""
    t = t_s
    if setup == "R16":
        peak = rng.uniform(24, 29)
        t1, t2, t3 = rng.uniform(0.008, 0.012), rng.uniform(0.05, 0.062), rng.uniform(0.07, 0.08)
        g = np.interp(t, [0, t1, t2, t3], [0, peak, peak, 0], left=0, right=0)
        g = g * (1 + 0.04 * np.sin(2 * np.pi * rng.uniform(60, 120) * t)) * (g > 0)
    elif setup == "SLED":
        peak, dur = rng.uniform(27, 33), rng.uniform(0.09, 0.11)
        g = peak * np.sin(np.pi * np.clip(t / dur, 0, 1)) ** 1.5
    elif setup == "FULL":
        g = np.zeros_like(t)
        for c, w, h in ((0.006, 0.003, 20), (0.02, 0.008, 22), (0.035, 0.01, 28),
                        (0.05, 0.008, 40), (0.065, 0.008, 15)):
            centre = c * rng.uniform(0.9, 1.1)
            g += rng.uniform(0.8, 1.2) * h * np.exp(-0.5 * ((t - centre) / w) ** 2)
        g *= (t > 0) * (t < 0.09)
    else:
        raise ValueError(f"unknown setup {setup!r} (R16, SLED, FULL)")
    return g * STANDARD_GRAVITY


class _Chest:
    """Forces of the chest with the switched-on effects; state (x, xd, s, sd)."""

    def __init__(self, p: ChestParams, effects: dict[str, float]):
        self.p = p
        self.e = effects

    def accel(self, x: float, xd: float, s: float, sd: float, w: float, wd: float, pcar: float,
              vcar: float) -> tuple[float, float, float]:
        p, e = self.p, self.e
        d, dd = s - x, sd - xd  # chest compression and its rate
        k1 = p.k1 * (1 + e.get("chest_stiffening", 0.0) * (d / 0.02) ** 2)
        c1 = p.c1 * (1 + e.get("chest_rate_damping", 0.0) * abs(dd) / 1.0)
        f_rib = k1 * d + c1 * dd
        pen, pen_d = w - s, wd - sd  # belt penetration into the chest
        k2 = p.k2 * (1 + e.get("belt_stiffening", 0.0) * (pen / 0.02) ** 2)
        f_belt = k2 * pen + p.c2 * pen_d
        if e.get("belt_unloading", 0.0) > 0 and f_belt < 0:
            f_belt = 0.0
        f_spine = f_rib
        f_sternum = f_belt - f_rib
        if e.get("airbag_contact"):
            ex, exd = pcar - x, vcar - xd  # forward excursion relative to the vehicle
            if ex > 0.11:
                f_bag = e["airbag_contact"] * (5e4 * (ex - 0.11) + 600 * exd)
                f_sternum += max(f_bag, 0.0)
        if e.get("pelvis_coupling"):
            f_spine += e["pelvis_coupling"] * (2e4 * (pcar - x) + 400 * (vcar - xd))
        return f_spine / p.m1, f_sternum / p.m2, f_belt


def _rk4(f: Callable[[float, np.ndarray], np.ndarray], y: np.ndarray, t: float,
         h: float) -> np.ndarray:
    k1 = f(t, y)
    k2 = f(t + h / 2, y + h / 2 * k1)
    k3 = f(t + h / 2, y + h / 2 * k2)
    k4 = f(t + h, y + h * k3)
    return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)


def simulate_test(setup: str, name: str, rng: np.random.Generator,
                  config: PlantConfig | None = None) -> CrashTest:
    cfg = config or PlantConfig()
    p, eff = cfg.chest, cfg.effects
    t = T0_S + np.arange(N_SAMPLES) / FS_HZ
    h = 1.0 / FS_HZ
    a = pulse_shape(setup, t, rng)
    v = np.concatenate([[0.0], np.cumsum((a[1:] + a[:-1]) / 2) * h])
    pcar = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2) * h])
    chest = _Chest(p, eff)
    gain_growth = 0.1 * eff.get("input_gain", 0.0) / (2 * np.pi)

    def belt_disp(theta: float) -> float:
        # Effective belt travel for spindle angle theta; payout (theta < 0) winds off layers.
        return p.R * (theta - gain_growth * min(theta, 0.0) ** 2 / 2)

    def lin(arr: np.ndarray, tt: float) -> float:
        k = (tt - T0_S) * FS_HZ
        i = min(max(int(k), 0), N_SAMPLES - 2)
        f = k - i
        return arr[i] * (1 - f) + arr[i + 1] * f

    # Pass 1: closed loop for the spindle angle.
    t_fire = rng.uniform(0.002, 0.004)
    t_lock = t_fire + 0.010
    c_ll = 800.0  # N s/m: payout speed per newton over the load limit

    def f1(tt: float, y: np.ndarray) -> np.ndarray:
        x, xd, s, sd, th = y
        if tt < t_fire:
            thd = 0.0
        elif tt < t_lock:
            thd = cfg.pretension_rad / (t_lock - t_fire)
        else:
            thd = 0.0
        w = lin(pcar, tt) + belt_disp(th)
        wd = lin(v, tt) + p.R * thd
        xdd, sdd, f_belt = chest.accel(x, xd, s, sd, w, wd, lin(pcar, tt), lin(v, tt))
        if tt >= t_lock and f_belt > cfg.load_limit_n:
            thd = -(f_belt - cfg.load_limit_n) / (c_ll * p.R)
        return np.array([xd, xdd, sd, sdd, thd])

    y = np.zeros(5)
    theta = np.zeros(N_SAMPLES)
    for k in range(N_SAMPLES - 1):
        y = _rk4(f1, y, t[k], h)
        theta[k + 1] = y[4]
    counts = np.round(theta * cfg.counts_per_rev / (2 * np.pi))

    # Pass 2: the chest driven by the spindle angle (linear between samples) and the pulse.
    def f2(tt: float, y2: np.ndarray) -> np.ndarray:
        x, xd, s, sd = y2
        k = min(max(int((tt - T0_S) * FS_HZ + 1e-9), 0), N_SAMPLES - 2)
        th = lin(theta, tt)
        thd = (theta[k + 1] - theta[k]) * FS_HZ
        w = lin(pcar, tt) + belt_disp(th)
        slope = 1 - gain_growth * min(th, 0.0)
        wd = lin(v, tt) + p.R * slope * thd
        xdd, sdd, _ = chest.accel(x, xd, s, sd, w, wd, lin(pcar, tt), lin(v, tt))
        return np.array([xd, xdd, sd, sdd])

    y2 = np.zeros(4)
    cr = np.zeros(N_SAMPLES)
    cd = np.zeros(N_SAMPLES)
    for k in range(N_SAMPLES - 1):
        y2 = _rk4(f2, y2, t[k], h)
        xdd, _, _ = chest.accel(y2[0], y2[1], y2[2], y2[3],
                                lin(pcar, t[k + 1]) + belt_disp(theta[k + 1]),
                                v[k + 1] + p.R * (theta[k + 1] - theta[k]) * FS_HZ,
                                pcar[k + 1], v[k + 1])
        cr[k + 1] = xdd / STANDARD_GRAVITY
        cd[k + 1] = (y2[2] - y2[0]) * 1000.0

    pulse_g = a / STANDARD_GRAVITY
    brs = counts
    both_ms = 2.0 * eff.get("input_delay", 0.0)
    # The physics above ran on delayed inputs: record them as they were before the delay.
    lag = round((both_ms + cfg.pulse_delay_ms) * 1e-3 * FS_HZ)
    if lag:
        pulse_g = np.concatenate([pulse_g[lag:], np.full(lag, pulse_g[-1])])
    lag = round((both_ms + cfg.brs_delay_ms) * 1e-3 * FS_HZ)
    if lag:
        brs = np.concatenate([brs[lag:], np.full(lag, brs[-1])])
    if eff.get("sensor_offset"):
        cr = cr + 1.0 * eff["sensor_offset"]
        cd = cd + 1.5 * eff["sensor_offset"]
    if cfg.noise:
        pulse_g = pulse_g + rng.normal(0, 0.5, N_SAMPLES) + rng.uniform(-0.1, 0.1)
        cr = cfc_filter(cr + rng.normal(0, 0.3, N_SAMPLES), FS_HZ, 180)
        cd = cfc_filter(cd + rng.normal(0, 0.05, N_SAMPLES), FS_HZ, 600)
    return CrashTest(
        name=name, fs_hz=FS_HZ, t0_s=T0_S, pulse_g=pulse_g, brs=brs, cr_g=cr, cd_mm=cd,
        setup=setup, counts_per_rev=cfg.counts_per_rev, source=f"simulator:{name}",
        meta=dict(METADATA[setup]),
    )


# What a lab's .mme says of each setup (the loop groups tests by it, and rules the airbag
# out where it says hard seat); the effects simulated are not written anywhere.
METADATA = {
    "R16": {"Title": "ECE R16 SLED RIG, HARD SEAT, 3-POINT BELT", "Type of the test": "SLED",
            "Name of test object 1": "HYBRID III 50TH MALE, DRIVER"},
    "SLED": {"Title": "SLED TEST WITH INTERIOR AND DRIVER AIRBAG", "Type of the test": "SLED",
             "Name of test object 1": "HYBRID III 50TH MALE, DRIVER"},
    "FULL": {"Title": "FULL FRONTAL RIGID BARRIER", "Type of the test": "VEHICLE INTO BARRIER",
             "Name of test object 1": "HYBRID III 50TH MALE, DRIVER"},
}


def simulate_mixed(counts: dict[str, int], seed: int, configs: dict[str, PlantConfig],
                   prefix: str = "T", meta: dict[str, dict[str, str]] | None = None
                   ) -> list[CrashTest]:
    """A mixed campaign: ``counts[setup]`` tests of each setup, each setup with its own plant
    (``configs[setup]``: an effect on some setups only), named ``<prefix>01``, ... in order,
    without the setup in the name; ``meta`` replaces a setup's metadata."""
    rng = np.random.default_rng(seed)
    out: list[CrashTest] = []
    for setup, n in counts.items():
        for _ in range(n):
            t = simulate_test(setup, f"{prefix}{len(out) + 1:02d}", rng, configs[setup])
            if meta and setup in meta:
                t.meta = dict(meta[setup])
            out.append(t)
    return out


def simulate_campaign(setup: str, count: int, seed: int = 1,
                      config: PlantConfig | None = None, prefix: str | None = None
                      ) -> list[CrashTest]:
    """``count`` tests named ``<prefix>_001`` ... with independent random pulses."""
    rng = np.random.default_rng(seed)
    return [simulate_test(setup, f"{prefix or setup}_{i:03d}", rng, config)
            for i in range(1, count + 1)]
