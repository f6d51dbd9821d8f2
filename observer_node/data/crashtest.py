"""One crash test as the model sees it: four signals on one time base, in model convention.

Model convention (set once at the file-format edge, SAE J211 X is forward):

===========  ======  =========================================================
signal       unit    positive means
===========  ======  =========================================================
``pulse_g``  g       vehicle (sled, tunnel) *deceleration*   (= -J211 X accel)
``brs``      counts  belt webbing retracted into the retractor (as the BRS)
``cr_g``     g       chest (thoracic spine) retardation      (= -J211 X accel)
``cd_mm``    mm      chest compression                        (= -J211 deflection)
===========  ======  =========================================================

This is the thesis's convention (deceleration positive); the observer publishes CR and CD
in it too, so a frontal crash gives positive pulse, CR and CD.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

import numpy as np
from scipy import signal

from ..errors import ObserverError

# The thesis window (section 2.2): before 10 ms the pretensioner still takes slack, after
# 150 ms the crash is over.
THESIS_WINDOW_S = (0.01, 0.15)


class CrashDataError(ObserverError, ValueError):
    """A crash test that cannot be used; the message names the file, line and key at fault."""


@dataclass
class CrashTest:
    """Uniformly sampled crash test in model convention (see module docstring).

    ``t0_s`` is the time of the first sample relative to first contact (t = 0).
    ``cr_g`` and ``cd_mm`` are ``None`` when the test has no dummy measurement.
    ``velocity_ms`` is the test's stated impact velocity [m/s] (a speed trap's, not the
    pulse's), ``None`` when the file gives none. ``status`` holds the lab's word on a channel
    it did not pass as ok (ISO-MME ``Data status``), by role: pulse, brs, cr, cd.
    """

    name: str
    fs_hz: float
    t0_s: float
    pulse_g: np.ndarray
    brs: np.ndarray
    cr_g: np.ndarray | None = None
    cd_mm: np.ndarray | None = None
    setup: str = ""
    counts_per_rev: int | None = None
    velocity_ms: float | None = None
    status: dict[str, str] = field(default_factory=dict)
    source: str = ""
    meta: dict[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        n = len(self.pulse_g)
        for label, arr in (("brs", self.brs), ("cr_g", self.cr_g), ("cd_mm", self.cd_mm)):
            if arr is not None and len(arr) != n:
                raise CrashDataError(
                    f"{self.source or self.name}: {label} has {len(arr)} samples, pulse has {n}"
                )

    @property
    def n(self) -> int:
        return len(self.pulse_g)

    @property
    def last_s(self) -> float:
        """Time of the last sample [s] (relative to first contact)."""
        return self.t0_s + (self.n - 1) / self.fs_hz

    @property
    def time_s(self) -> np.ndarray:
        return self.t0_s + np.arange(self.n) / self.fs_hz

    @property
    def has_outputs(self) -> bool:
        return self.cr_g is not None and self.cd_mm is not None

    def inputs(self) -> np.ndarray:
        """Raw inputs as an (n, 2) array [pulse_g, brs counts]."""
        return np.column_stack([self.pulse_g, self.brs])

    def index_of(self, t_s: float) -> int:
        """Index of the first sample at or after ``t_s`` (clipped to the record)."""
        i = int(np.ceil((t_s - self.t0_s) * self.fs_hz - 1e-9))
        return min(max(i, 0), self.n)

    def pulse_bias_g(self) -> float:
        """Accelerometer bias [g]: the median pulse before first contact (0 if no pre-trigger
        data). The median, not the mean: a trigger that fires late puts the crash's onset into
        the pre-contact window (5 ms of onset move a 20 ms window's mean by 1-3 g)."""
        pre = self.pulse_g[self.time_s < 0.0]
        return float(np.median(pre)) if len(pre) else 0.0

    def resample(self, fs_hz: float) -> CrashTest:
        """Resample to ``fs_hz`` as the bus would carry it (see :func:`resample_inputs`)."""
        if abs(fs_hz - self.fs_hz) < 1e-9:
            return self
        pulse, brs, step = resample_inputs(self.pulse_g, self.brs, self.fs_hz, fs_hz)
        def ref(a: np.ndarray | None) -> np.ndarray | None:
            return (None if a is None else resample_reference(a, step))
        return replace(
            self, fs_hz=self.fs_hz / step, pulse_g=pulse, brs=brs,
            cr_g=ref(self.cr_g), cd_mm=ref(self.cd_mm),
        )


# BRS units a data file may use, as the fraction of a revolution per unit (counts need the
# sensor's resolution; "-" and "1" are how some ISO-MME writers mark a dimensionless count).
BRS_COUNT_UNITS = ("counts", "count", "cnt", "-", "1")
BRS_UNITS_PER_REV = {"deg": 360.0, "°": 360.0, "rad": 2 * np.pi, "rev": 1.0}


_SPEED_UNITS = {"": 1.0, "m/s": 1.0, "km/h": 1 / 3.6, "kph": 1 / 3.6, "mph": 0.44704}


def velocity_of(value: str) -> float | None:
    """A stated velocity [m/s] from its text ("15.24", "15,24", "56 km/h"), or None: only the
    loop's screening reads it (against the pulse), so a file without a usable one is read as
    a file without one."""
    m = re.fullmatch(r"\s*([+-]?\d+(?:[.,]\d*)?(?:[eE][+-]?\d+)?)\s*([a-zA-Z/]*)\s*", value)
    if not m or m.group(2).lower() not in _SPEED_UNITS:
        return None
    v = float(m.group(1).replace(",", ".")) * _SPEED_UNITS[m.group(2).lower()]
    return abs(v) if math.isfinite(v) and v != 0 else None  # a sign is a direction


def brs_to_counts(values: np.ndarray, unit: str, counts_per_rev: int | None, where: str,
                  source: str, how_to_give: str) -> np.ndarray:
    """BRS in ``unit`` (counts or an angle) as sensor counts; ``where`` names the file and key
    of the unit and ``source`` the file (for the messages), ``how_to_give`` where a user states
    the resolution."""
    unit = unit.strip().lower()
    if not unit:  # counts are whole numbers; an angle of 360/N-degree steps mostly is not
        finite = np.asarray(values, dtype=float)[np.isfinite(values)]
        odd = finite[np.abs(finite - np.round(finite)) > 1e-6]
        if len(odd):
            raise CrashDataError(f"{where}: BRS has no unit and reads {odd[0]:g}, not a whole "
                                 "count: give its unit (counts, deg, rad or rev)")
        step = 360.0 / counts_per_rev if counts_per_rev else 0.0
        if _on_steps(finite, step):
            raise CrashDataError(f"{where}: BRS has no unit and moves only in steps of "
                                 f"{step:g}" + ("" if step == round(step) else
                                                 " (rounded to whole numbers)")
                                 + f", as {counts_per_rev} counts/rev read in degrees would: "
                                 "give its unit (counts, deg, rad or rev)")
        unit = "counts"
    if unit in BRS_COUNT_UNITS:
        return np.array(values, dtype=float)
    per_rev = BRS_UNITS_PER_REV.get(unit)
    if per_rev is None:
        raise CrashDataError(f"{where}: BRS unit {unit!r} is not a count or angle unit "
                             f"({', '.join(BRS_COUNT_UNITS[:3] + tuple(BRS_UNITS_PER_REV))})")
    if counts_per_rev is None:
        raise CrashDataError(f"{source}: BRS is in {unit} but counts/rev is unknown: give it "
                             f"{how_to_give}")
    finite = np.asarray(values, dtype=float)[np.isfinite(values)]
    step = per_rev / counts_per_rev
    whole = bool(np.all(finite == np.round(finite)))
    # whole radians or turns at more than four levels are no angle a spindle reads
    coarse = per_rev < 10 and len(np.unique(finite)) > 5
    if whole and (coarse or _on_steps(finite, step) is False):
        raise CrashDataError(f"{where}: BRS in {unit} reads whole numbers that steps of "
                             f"{step:g} {unit} ({counts_per_rev} counts/rev) never land near, "
                             "as the spindle's raw counts would (or an angle rounded to whole "
                             f"{unit}): give its unit (counts, deg, rad or rev), or the "
                             "resolution it was recorded at")
    return np.round(values * counts_per_rev / per_rev)


def _on_steps(values: np.ndarray, step: float) -> bool | None:
    """Whether whole-number BRS ``values`` lie on steps of ``step`` from their first (each
    rounded to a whole number where ``step`` is not whole, from a zero that may itself lie off
    a step); None when they cannot say. Counts pass through every whole number they move by:
    under 2.5 a step, whole numbers can all lie near steps, and four levels or fewer say too
    little."""
    moved = values - values[0] if len(values) else values
    levels = np.unique(moved[moved != 0])
    if step == round(step):
        return bool(np.all(levels % step == 0)) if step > 1 and len(levels) else None
    if step < 2.5 or len(levels) <= 4:
        return None
    return any(bool(np.all(np.abs(levels - zero - step * np.round((levels - zero) / step))
                           <= 0.51)) for zero in np.linspace(-0.5, 0.5, 51))


def decimation_step(fs_in_hz: float, fs_out_hz: float) -> int:
    step = fs_in_hz / fs_out_hz
    if step < 1 or abs(step - round(step)) > 1e-6:
        raise CrashDataError(
            f"cannot resample {fs_in_hz:g} Hz to {fs_out_hz:g} Hz: need an integer decimation"
        )
    return round(step)


def resample_inputs(
    pulse_g: np.ndarray, brs: np.ndarray, fs_in_hz: float, fs_out_hz: float
) -> tuple[np.ndarray, np.ndarray, int]:
    """Inputs as a sensor ECU would put them on the bus at ``fs_out_hz``.

    The pulse goes through a causal 4th-order Butterworth anti-alias filter at 40 % of the
    output rate (causal, because the ECU cannot look ahead) and is then decimated; the BRS is a
    step signal and is sampled as held (zero-order hold). Identification and replay both call
    this so that a model sees the same inputs offline and on the bus.
    Returns (pulse_g, brs, decimation step).
    """
    step = decimation_step(fs_in_hz, fs_out_hz)
    if step == 1:
        return pulse_g.copy(), brs.copy(), 1
    sos = signal.butter(4, 0.4 * fs_out_hz, fs=fs_in_hz, output="sos")
    # Start the filter settled on the first value so that a bias does not ring at t0.
    zi = signal.sosfilt_zi(sos) * pulse_g[0]
    filtered, _ = signal.sosfilt(sos, pulse_g, zi=zi)
    return filtered[::step].copy(), brs[::step].copy(), step


def resample_reference(y: np.ndarray, step: int) -> np.ndarray:
    """Measured dummy responses (already CFC-filtered): zero-phase decimation, no delay."""
    if step == 1:
        return y.copy()
    return signal.decimate(y, step, ftype="fir", zero_phase=True)
