"""The lab: draws each test (dummy scatter, pulse, effects), runs the physics and records the
channels as a lab would (noise, BRS counts, CFC filters, SAE J211 signs), as ISO-MME tests."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import signal

from . import physics as ph
from .cases import Case, test_names
from .iso_mme import Channel, Test

# Rig metadata per setup; worded unlike campaign-a's. The R16 rig says why no airbag is there.
RIGS: dict[str, dict[str, str]] = {
    "R16": {"Title": "R16 CERTIFICATION SLED - RIGID SEAT, NO INTERIOR, 3-PT BELT",
            "Type of the test": "SLED TEST"},
    "SLED": {"Title": "SLED WITH BODY-IN-WHITE INTERIOR AND DRIVER AIRBAG",
             "Type of the test": "SLED TEST"},
    "FULL": {"Title": "FULL WIDTH FRONTAL IMPACT INTO RIGID WALL",
             "Type of the test": "FULL SCALE VEHICLE"},
}
PULSE_CHANNEL = {"R16": ("S0SLED000000ACXP", "Sled carriage X acc"),
                 "SLED": ("S0SLED000000ACXP", "Sled carriage X acc"),
                 "FULL": ("10TUNN000000ACXP", "Tunnel X acc below seat")}
DUMMY = "HYBRID III 50%ILE MALE, DRIVER SEAT"
DV_MS = {"R16": (13.6, 14.4), "SLED": (14.0, 15.6), "FULL": (14.3, 16.2)}
# stated exactly, no per-test scatter: times, ranges, and one transducer's calibration
EXACT = {"pulse_late", "brs_late", "brs_freeze", "cd_dropout", "pulse_rail", "pulse_gain",
         "cr_gain", "cd_knee", "pulse_zero_shift", "cd_spikes", "brs_reversed",
         "cr_soft_clip", "cr_cable_break", "cr_reversed", "cr_progressive", "brs_reset",
         "cr_hum", "cd_compress", "cd_rail", "pulse_sync", "cd_dead_band", "cd_stuck_bit",
         "brs_quadrature", "cr_ac_coupled", "brs_poll", "cr_lost_block", "cd_backlash",
         "cr_loose_mount", "brs_swap", "cd_arm_lift", "pulse_from", "cr_zero_shift",
         "pulse_rate", "cd_aa_filter", "dummy_scale", "cr_crosstalk", "dummy_soak", "cd_sag",
         "brs_counts", "cr_damped", "cr_late", "cd_rc_filter", "dummy_late",
         "cd_reversed", "cd_slew", "brs_wrap", "cr_creep", "pulse_ms2", "cd_arm_ring",
         "cr_drift", "pulse_cable_break", "cd_pot_loading", "cr_rail", "cr_clock",
         "cd_clock"}
DROPOUT_S = 0.010  # how long cd_dropout's wiper stays off the track
KNEE_SLOPE = 0.6  # cd_knee: the gain of the CD calibration's second segment
SHIFT_AT_S = 0.011  # pulse_zero_shift: when the zero shifts (in the crash-box spike)
# cd_spikes: an intermittent CD connector; when each spike starts (s), its sign, its width
# (samples of the raw 10 kHz channel, before CFC 600)
SPIKES_S = ((0.016, 1), (0.029, -1), (0.043, 1), (0.057, -1), (0.068, 1), (0.084, -1))
SPIKE_SAMPLES = 3
CABLE_BREAK_G = 0.0  # cr_cable_break: what the open bridge reads, constant (g)
CR_PROG_G = 25.0  # cr_progressive: the level (g) where CR over-reads by the effect's size
HUM_HZ = 50.0  # cr_hum: a ground loop picks up the mains (European lab)
# cd_stuck_bit: the CD digitiser's input range (+-, mm) over its 16 bits, offset binary
CD_ADC_MM, ADC_BITS = 100.0, 16
# cr_lost_block: when the CR recorder's lost block starts (mid-loading); what follows arrives
# that much early, the record's end padded with its last sample
LOST_AT_S = 0.030
# cr_loose_mount: the damping ratio of the loosened accelerometer on its mount (the block's
# screws backed off: it sits on its cable and a film of grease, little damping)
LOOSE_ZETA = 0.05
# cr_zero_shift: the shock level (g) at which the spine accelerometer's zero shifts (its
# sensing element's bond yields a little under the loading's first hard rise), and how long
# the shift takes to settle (s)
CR_SHIFT_G, CR_SHIFT_RISE_S = 20.0, 0.004
# dummy_scale: the dummy's own parameters, scaled by geometric similitude for a dummy of length
# scale s (same materials): masses by s^3, stiffnesses by s, dampings by s^2 (so times by s);
# the belt, retractor and airbag are the rig's and stay
DUMMY_MASS = ("m_sp", "m_a", "m_b", "m_p")
DUMMY_STIFF = ("k_ra", "k_rb", "k_ab", "k_l")
DUMMY_DAMP = ("c_ra", "c_rb", "c_ab", "c_l")
# dummy_soak: a Hybrid III's thorax is certified (and must be run) soaked at 20.6-22.2 C; its
# ribs' damping material is a viscoelastic polymer, so a thorax run colder answers stiffer and
# far more damped. Per kelvin below the band: the ribs' dampings x exp(SOAK_DAMP_PER_K), their
# stiffnesses x exp(SOAK_STIFF_PER_K) (the steel of the ribs is unchanged, the bonded damping
# layer carries part of the stiffness); a thorax run warmer (negative kelvin) the other way,
# softer and far less damped; masses, spine, pelvis, belt and bag as they were
SOAK_DAMP_PER_K, SOAK_STIFF_PER_K = 0.05, 0.015
SOAK_DAMP, SOAK_STIFF = ("c_ra", "c_rb", "c_ab"), ("k_ra", "k_rb", "k_ab")
# cd_sag: the chest pot's excitation is not read back by its conditioner (not ratiometric);
# when the on-board recorder starts writing at the trigger its battery sags, and the pot's
# excitation with it, settling with this time constant (s): CD reads d (1 - s (1 - e^(-t/tau)))
CD_SAG_TAU_S = 0.060
# cr_damped: the spine accelerometer is an oil-damped sensing element (a seismic mass on a
# spring in silicone oil) of too low a natural frequency for a crash: it reads its base's
# acceleration through a 2-pole low-pass of this damping ratio at its natural frequency (the
# effect's size, Hz), causal: it lags and rounds CR; the oil's damping is its design's (0.7)
CR_DAMPED_ZETA = 0.7
# cr_late: the CR channel goes through a digitiser module of another make (a delta-sigma
# converter and its decimation filter) whose pipeline delay the recorder does not take off its
# time stamps: CR is written this late (s) against every other channel; CR's values are right
# cd_slew: the CD conditioner's output amplifier (an op-amp of too low a slew rate for the
# channel's range and gain) moves no faster than the effect's size (mm/ms, i.e. m/s) either
# way: slower compression and opening read right, faster ones lag at that rate
# cd_rc_filter: the CD conditioner's output stage is a one-pole RC low-pass (its corner, the
# effect's size in Hz, set for a slow channel): causal, it lags CD by about 1 / (2 pi f) and
# rounds its peak; CD's static reading is right
# dummy_late: the dummy's own recorder (in the spine box: CR and CD) runs its time base this
# late (s) against the car's (pulse and BRS): what the chest did at t it writes at t + late,
# both channels alike. (The recorder's trigger, as it stamps it, comes that long before the
# car's: a recorder that took its trigger late would write the chest early instead, which no
# causal model can follow.) To the chest's model it is the same as both inputs leading by it
# brs_wrap: the spindle encoder's counter holds only the effect's size in bits, two's
# complement: once the spool has turned past half its range either way the count wraps round
# to the other end (what the file holds jumps by 2^bits counts, turns of the spool lost)
# cr_creep: the spine accelerometer's strain gauges creep in their adhesive (an old, overloaded
# sensing element): under a sustained load its reading grows by the effect's share of it with
# the adhesive's time constant CREEP_TAU_S (and falls back the same way once unloaded): CR
# reads cr + share x (cr through a one-pole low-pass of that time constant); CD, pulse, BRS right
CREEP_TAU_S = 0.015
# pulse_ms2: the pulse channel's export wrote m/s^2 where its header (and every other test's
# file) states g: the file reads G times the deceleration, its noise with it
# cd_arm_ring: the chest pot's arm (its slider and the rod to the sternum) is a mass on a
# spring, lightly damped by the wiper's friction: the pot reads the sternum through a 2-pole
# low-pass of this damping ratio at the arm's natural frequency (the effect's size, Hz),
# causal: CD overshoots a fast loading and rings about the sternum's motion
CD_RING_ZETA = 0.12
# cr_drift: the recorder switches the spine accelerometer's bridge excitation on only at the
# trigger (a battery-saving mode) and the bridge's zero drifts as its gauges warm: CR reads
# cr + r t from the trigger on (r, the effect's size, g/s), nothing before; CD, pulse, BRS right
# pulse_cable_break: the carriage (or tunnel) accelerometer's cable parts mid-crash (its
# connector pulled off the module as the rig decelerates): from the effect's time (s) on the
# channel's input is open and the amplifier reads its zero, 0 g, its own noise still on it
# (unlike cr_cable_break's constant: the pulse module's noise is its amplifier's); CR, CD, BRS
# right, and the physics ran on the true pulse
# cd_pot_loading: the chest pot (a linear potentiometer over a stroke of POT_STROKE_MM, the
# chest at rest POT_REST of the way along it) read by a conditioner whose input resistance is
# too low for it: the wiper's voltage is loaded, the textbook loading error, v(x) = x / (1 + r x
# (1 - x)) at the fraction x of the stroke (r = R_pot / R_in, the effect's size); the channel is
# calibrated over the full stroke (where the error vanishes) and zeroed at rest, so CD reads
# POT_STROKE_MM (v(x) - v(x_rest)): low over the middle of the stroke, by a share growing with
# r; CR, pulse, BRS right
POT_STROKE_MM, POT_REST = 100.0, 0.1
# cr_rail: the spine accelerometer's conditioner set to too small a range (a gain meant for a
# head or a pelvis channel of lower g, or a range switch left on its lower step): its output
# saturates, the raw channel flat at +-the effect's size (g) wherever the spine's deceleration
# is larger, its noise clipped with it, before the CFC 180 filter; CD, pulse, BRS right
# cr_clock: the CR channel's digitiser module (in the dummy's spine box) runs on its own
# crystal, slow by the effect's share, while it writes its samples at the stated rate from the
# common trigger: the sample the file stamps t was taken at t (1 + s), so CR's time base is
# stretched, its events written early by a share growing with the time since the trigger
# (5 ms at 50 ms for s = 0.1); CR's values are right; CD, pulse, BRS right
# cd_clock: the chest pot's channel is digitised by a module of its own (a separate bridge and
# potentiometer module in the spine box, beside CR's) on its own crystal, slow by the effect's
# share, while it writes its samples at the stated rate from the common trigger: the sample
# stamped t holds the sternum's deflection at t (1 + s), CD's time base stretched (its peak
# written early by a share of its time); CD's values are right, CR, pulse and BRS right
NOISE = {"pulse_g": 0.6, "cr_g": 0.55, "cd_mm": 0.10}  # white, before the CFC filters


@dataclass
class Drawn:
    """One test as drawn: where it goes, its setup, parameters and effect sizes."""

    case: str
    part: str  # "est" or "val"
    name: str
    setup: str
    dv_ms: float
    params: dict[str, float]
    effects: dict[str, float]
    brs_phase: float


def backlash(x: np.ndarray, width: float) -> np.ndarray:
    """A play of ``width`` between input and output, starting centred at rest: the output
    holds until the input has crossed the play, then follows it ``width / 2`` behind."""
    y = np.empty_like(x)
    h = 0.5 * width
    last = 0.0
    for i, v in enumerate(x):
        last = min(max(last, v - h), v + h)
        y[i] = last
    return y


def arm_lift(x: np.ndarray, rate: float) -> np.ndarray:
    """A follower pushed by ``x`` and pulled back by a weak spring: it follows ``x`` up at
    once, down no faster than ``rate`` per sample (so it may stand off ``x`` while it falls)."""
    y = np.empty_like(x)
    last = x[0]
    for i, v in enumerate(x):
        last = max(v, last - rate)
        y[i] = last
    return y


def slew(x: np.ndarray, rate: float) -> np.ndarray:
    """An amplifier whose output moves no faster than ``rate`` per sample, either way: it
    follows ``x`` where ``x`` is slower, and runs at ``rate`` towards it where it is faster."""
    y = np.empty_like(x)
    last = x[0]
    for i, v in enumerate(x):
        last = last + min(max(v - last, -rate), rate)
        y[i] = last
    return y


def wrap(counts: np.ndarray, bits: int) -> np.ndarray:
    """What a two's complement counter of ``bits`` bits holds of ``counts``: the same modulo
    2^bits, within -2^(bits-1) .. 2^(bits-1) - 1."""
    half = 2 ** (bits - 1)
    return np.mod(counts + half, 2 * half) - half


def creep(x: np.ndarray, share: float, tau_s: float = CREEP_TAU_S) -> np.ndarray:
    """A sensing element whose gauges creep: ``x`` plus ``share`` of ``x`` through a causal
    one-pole low-pass of time constant ``tau_s`` (a step reads 1, then 1 + share after a
    while, reached as 1 - e^(-t / tau_s))."""
    return x + share * rc_filter(x, 1.0 / (2 * np.pi * tau_s))


def drift(x: np.ndarray, rate_per_s: float) -> np.ndarray:
    """``x`` (sampled at ``physics.FS_HZ``, its first sample at ``physics.T0_S``) plus a zero
    growing at ``rate_per_s`` per second from the trigger (t = 0) on, nothing before."""
    t = ph.T0_S + np.arange(x.size) / ph.FS_HZ
    return x + rate_per_s * np.maximum(t, 0.0)


def pot_loading(cd_mm: np.ndarray, r: float) -> np.ndarray:
    """What a chest pot loaded by its conditioner (``r`` = R_pot / R_in) reads of the chest's
    deflection ``cd_mm``: POT_STROKE_MM (v(x) - v(x_rest)), v(x) = x / (1 + r x (1 - x)), x the
    fraction of the stroke (POT_REST at rest): 0 at rest, low over the stroke's middle."""
    def v(x: np.ndarray | float) -> np.ndarray | float:
        return x / (1.0 + r * x * (1.0 - x))
    x = np.clip(POT_REST + cd_mm / POT_STROKE_MM, 0.0, 1.0)
    return POT_STROKE_MM * (v(x) - v(POT_REST))


def loose_mount(a: np.ndarray, f_hz: float, zeta: float = LOOSE_ZETA) -> np.ndarray:
    """What an accelerometer on a loosened mount reads of the acceleration ``a`` of its base:
    the block rides on the base through a spring (resonance ``f_hz``) and damper and reads its
    own acceleration, (2 zeta w s + w^2) / (s^2 + 2 zeta w s + w^2); bilinear, pre-warped so
    the resonance stays where the analog one is."""
    w = 2 * ph.FS_HZ * np.tan(np.pi * f_hz / ph.FS_HZ)
    bb, aa = signal.bilinear([2 * zeta * w, w * w], [1.0, 2 * zeta * w, w * w], fs=ph.FS_HZ)
    return np.asarray(signal.lfilter(bb, aa, a))


def aa_filter(x: np.ndarray, f_hz: float) -> np.ndarray:
    """An analog anti-alias filter ahead of the digitiser: a 4-pole Butterworth low-pass at
    ``f_hz``, causal (one pass: it delays as well as smooths, unlike the phaseless CFC filters
    run on the recorded file), from rest."""
    bb, aa = signal.butter(4, f_hz, fs=ph.FS_HZ)
    return np.asarray(signal.lfilter(bb, aa, x))


def damped_element(a: np.ndarray, f_hz: float, zeta: float = CR_DAMPED_ZETA) -> np.ndarray:
    """What a damped seismic sensing element of natural frequency ``f_hz`` and damping ratio
    ``zeta`` reads of its base's acceleration ``a``: w^2 / (s^2 + 2 zeta w s + w^2) from rest,
    bilinear, pre-warped at ``f_hz`` (unlike ``loose_mount``, no base feed-through: the element
    itself is the low-pass)."""
    w = 2 * ph.FS_HZ * np.tan(np.pi * f_hz / ph.FS_HZ)
    bb, aa = signal.bilinear([w * w], [1.0, 2 * zeta * w, w * w], fs=ph.FS_HZ)
    return np.asarray(signal.lfilter(bb, aa, a))


def clock(x: np.ndarray, share: float) -> np.ndarray:
    """``x`` (sampled at ``physics.FS_HZ``, its first sample at ``physics.T0_S``) as a module
    whose clock runs slow by ``share`` writes it from the common trigger (t = 0) on: the
    sample stamped t holds what was at t (1 + share), the record's end held."""
    t = ph.T0_S + np.arange(x.size) / ph.FS_HZ
    return np.interp(t * (1.0 + share), t, x)


def late(x: np.ndarray, seconds: float) -> np.ndarray:
    """``x`` (sampled at ``physics.FS_HZ``) written ``seconds`` late: what it was at t is read
    at t + seconds, its first sample held before (a transport lag)."""
    n = np.arange(x.size, dtype=float)
    return np.interp(n - seconds * ph.FS_HZ, n, x)


def rc_filter(x: np.ndarray, f_hz: float) -> np.ndarray:
    """A one-pole RC low-pass at ``f_hz``, causal, from rest (bilinear, pre-warped): unit
    gain at rest, a lag of about 1 / (2 pi f_hz) at low frequency."""
    bb, aa = signal.butter(1, f_hz, fs=ph.FS_HZ)
    return np.asarray(signal.lfilter(bb, aa, x))


def scale_dummy(params: dict[str, float], s: float) -> dict[str, float]:
    """``params`` of a dummy ``s`` times the size (length scale, same materials: geometric
    similitude): masses x s^3, stiffnesses x s, dampings x s^2, the rest as it was."""
    power = {**dict.fromkeys(DUMMY_MASS, 3), **dict.fromkeys(DUMMY_STIFF, 1),
             **dict.fromkeys(DUMMY_DAMP, 2)}
    return {k: v * s ** power.get(k, 0) for k, v in params.items()}


def soak_dummy(params: dict[str, float], kelvin: float) -> dict[str, float]:
    """``params`` of a dummy whose thorax was run ``kelvin`` K below its certification band
    (negative: above it): the ribs' dampings x exp(SOAK_DAMP_PER_K K), stiffnesses x
    exp(SOAK_STIFF_PER_K K)."""
    gain: dict[str, float] = {
        **dict.fromkeys(SOAK_DAMP, float(np.exp(SOAK_DAMP_PER_K * kelvin))),
        **dict.fromkeys(SOAK_STIFF, float(np.exp(SOAK_STIFF_PER_K * kelvin)))}
    return {k: v * gain.get(k, 1.0) for k, v in params.items()}


def draw(case: Case, effects_on: bool = True) -> tuple[list[Drawn], np.ndarray]:
    """Every test of ``case`` and its crash pulses (deceleration, m/s^2, stage grid).
    ``effects_on=False``: the same tests (same dummies, pulses, noise) with every effect off,
    the twin that tells what the effects cost."""
    rng = np.random.default_rng(case.seed)
    est, val = test_names(case)
    m = (ph.N_SAMPLES - 1) * ph.GRID + 1
    t = ph.T0_S + np.arange(m) / (ph.FS_HZ * ph.GRID)
    out, pulses = [], []
    for part, names, setups in (("est", est, case.est), ("val", val, case.val)):
        for name, setup in zip(names, setups, strict=True):
            params = {}
            for k, v in ph.NOMINAL.items():
                z = 0.0 if k in ph.NO_SCATTER else float(np.clip(rng.normal(), -2, 2))
                params[k] = v * (1.0 + ph.SCATTER * z)
            effects = dict.fromkeys(ph.EFFECTS, 0.0)
            for e in case.effects:
                z = float(np.clip(rng.normal(), -2, 2))  # drawn always: the twin keeps its dummy
                if effects_on and setup in e.setups and (not e.tests or name in e.tests):
                    effects[e.key] = e.size * (1.0 + (0.0 if e.key in EXACT else 0.04 * z))
            if effects["dummy_scale"]:  # another dummy in the seat than the file names
                params = scale_dummy(params, effects["dummy_scale"])
            if effects["dummy_soak"]:  # the dummy run off its temperature band, unsaid
                params = soak_dummy(params, effects["dummy_soak"])
            dv = float(rng.uniform(*DV_MS[setup]))
            pulses.append(ph.pulse_shape(setup, rng, t, dv))
            out.append(Drawn(case.name, part, name, setup, dv, params, effects,
                             float(rng.uniform())))
    return out, np.stack(pulses)


def run(drawn: list[Drawn], pulses: np.ndarray) -> dict[str, np.ndarray]:
    """The physics for all ``drawn`` tests at once (one column each)."""
    n = len(drawn)
    p = {k: np.array([[d.params[k]] for d in drawn]) for k in ph.NOMINAL}
    eff = {k: np.array([[d.effects[k]] for d in drawn]) for k in ph.EFFECTS}
    vv, xv = ph.kinematics(pulses, 1.0 / (ph.FS_HZ * ph.GRID))
    out = ph.simulate(ph.Batch(p, eff, xv, vv))
    out["pulse"] = pulses
    assert out["cr"].shape == (n, ph.N_SAMPLES)
    return out


def record(d: Drawn, i: int, sim: dict[str, np.ndarray], counts_per_rev: int,
           rng: np.random.Generator) -> tuple[Test, dict[str, Any]]:
    """The channels of test ``i`` of ``sim`` as the lab writes them, and what is true."""
    t = ph.T0_S + np.arange(ph.N_SAMPLES) / ph.FS_HZ
    tg = ph.T0_S + np.arange(sim["pulse"].shape[1]) / (ph.FS_HZ * ph.GRID)
    e = d.effects
    # pulse: unfiltered accelerometer; with pulse_late the chest feels it that long after the
    # channel records it (a transport delay, as the loop's input_delay means): the recorded
    # channel leads the pulse the physics ran on. The other way round (a channel recorded
    # after the chest moved) no causal observer can model.
    # pulse_sync: the pulse's recorder started on its own trigger, its time base this early
    # pulse_from: this test's pulse channel is another test's (of the same case, e["pulse_from"]
    # places on in the batch): the carriage file of another run written into this test's folder
    src_p = i + round(e["pulse_from"]) if e["pulse_from"] else i
    # pulse_rate: the carriage module sampled at e["pulse_rate"] x the rate the file states
    # (its samples counted from the trigger): the file's time t is the crash's t / rate
    tp = t / e["pulse_rate"] if e["pulse_rate"] else t
    pulse = np.interp(tp + e["pulse_late"] + e["pulse_sync"], tg, sim["pulse"][src_p]) / ph.G
    if e["pulse_gain"]:  # the accelerometer's sensitivity entered wrong
        pulse = pulse * (1.0 + e["pulse_gain"])
    if e["pulse_zero_shift"]:  # a shock shifts the sensor's zero: it stays shifted
        pulse = pulse + e["pulse_zero_shift"] * (t >= SHIFT_AT_S)
    if e["pulse_cable_break"]:  # the cable parts: the open input reads 0 g from then on
        pulse = np.where(t >= e["pulse_cable_break"], 0.0, pulse)
    pulse = pulse + NOISE["pulse_g"] * rng.standard_normal(t.size)
    if e["pulse_rail"]:  # amplifier range set too low: the channel clips at its rails
        pulse = np.clip(pulse, -e["pulse_rail"], e["pulse_rail"])
    if e["pulse_ms2"]:  # the export wrote m/s^2 under the header's g (noise and all)
        pulse = pulse * ph.G
    # BRS: the spindle's counts, leading the belt the chest feels by brs_late (as the pulse),
    # maybe frozen by a cable fault
    # brs_swap: this test's BRS channel is another test's (of the same case, e["brs_swap"]
    # places on in the batch): the two tests' spindle files crossed in the lab's export
    src = i + round(e["brs_swap"]) if e["brs_swap"] else i
    th = np.interp(t + e["brs_late"], t, sim["th"][src])
    th = th + e["brs_eccentric"] * np.sin(th + 2 * np.pi * d.brs_phase)
    # brs_quadrature: the decoder counts every edge of both tracks (4 a step) while the header
    # keeps the spindle's own counts per rev: finer steps, the angle read 4 x
    edges = round(e["brs_quadrature"]) if e["brs_quadrature"] else 1
    counts = ph.quantise_brs(th[None, :], edges * counts_per_rev, np.array([d.brs_phase]))[0]
    if e["brs_poll"]:  # the spindle's electronics poll its two tracks too slowly: a quadrature
        every = round(ph.FS_HZ / e["brs_poll"])  # decoder sees only the tracks' phase
        moved = np.diff(counts[::every]) % 4  # (mod 4): 1 step on, 3 back, 2 steps invalid
        seen = np.select([moved == 1, moved == 3], [1.0, -1.0], 0.0)  # (dropped): it aliases
        polled = np.concatenate([[counts[0]], counts[0] + np.cumsum(seen)])
        counts = np.repeat(polled, every)[:counts.size]  # held between polls
    if e["brs_freeze"] > 0:
        k = int(np.searchsorted(t, e["brs_freeze"]))
        counts[k:] = counts[k]
    if e["brs_reset"]:  # a supply glitch resets the counter: it counts on from zero
        k = int(np.searchsorted(t, e["brs_reset"]))
        counts[k:] = counts[k:] - counts[k]
    if e["brs_wrap"]:  # a counter of too few bits: the count wraps round past its half range
        counts = wrap(counts, round(e["brs_wrap"]))
    if e["brs_reversed"]:  # the recorder's count direction set wrong: pay-in reads as pay-out
        counts = -counts
    # CR (CFC 180), CD (CFC 600, maybe a non-linear pot, maybe zeroed off)
    cr_read = sim["cr"][i] / ph.G
    if e["dummy_late"]:  # the dummy's recorder's time base late against the car's
        cr_read = late(cr_read, e["dummy_late"])
    if e["cr_gain"]:  # the accelerometer's sensitivity error
        cr_read = cr_read * (1.0 + e["cr_gain"])
    if e["cr_soft_clip"]:  # a conditioner near its output range: reads low, more so at peaks
        cr_read = e["cr_soft_clip"] * np.tanh(cr_read / e["cr_soft_clip"])
    if e["cr_progressive"]:  # a sensing element stiffening less than its calibration says
        cr_read = cr_read * (1.0 + e["cr_progressive"] * (cr_read / CR_PROG_G) ** 2)
    if e["cr_ac_coupled"]:  # a piezoelectric sensing element: its charge leaks away through
        tau = e["cr_ac_coupled"]  # the amplifier's input, a first-order high-pass of time tau
        bb, aa = signal.bilinear([tau, 0.0], [tau, 1.0], fs=ph.FS_HZ)
        cr_read = signal.lfilter(bb, aa, cr_read)
    if e["cr_loose_mount"]:  # the accelerometer's block loosened on the spine box: it rides
        cr_read = loose_mount(cr_read, e["cr_loose_mount"])  # on a spring, a resonance
    if e["cr_damped"]:  # an oil-damped sensing element, its natural frequency too low
        cr_read = damped_element(cr_read, e["cr_damped"])
    if e["cr_creep"]:  # the sensing element's gauges creep in their adhesive under load
        cr_read = creep(cr_read, e["cr_creep"])
    if e["cr_drift"]:  # the bridge's zero drifts as its gauges warm from the trigger on
        cr_read = drift(cr_read, e["cr_drift"])
    if e["cr_clock"]:  # the CR module's own clock slow: its time base stretched from trigger
        cr_read = clock(cr_read, e["cr_clock"])
    if e["cr_late"]:  # the CR digitiser's pipeline delay, not taken off its time stamps
        cr_read = late(cr_read, e["cr_late"])
    if e["cr_zero_shift"]:  # the sensing element's zero shifts under the shock: once the
        k = int(np.argmax(cr_read >= CR_SHIFT_G))  # reading first passes CR_SHIFT_G it moves
        if cr_read[k] >= CR_SHIFT_G:  # by the size (g) over CR_SHIFT_RISE_S and stays there
            ramp = np.clip((t - t[k]) / CR_SHIFT_RISE_S, 0.0, 1.0)
            cr_read = cr_read + e["cr_zero_shift"] * ramp
    if e["cr_crosstalk"]:  # the recorder's multiplexed digitiser samples CR right after CD and
        # its sample-and-hold has too little time to settle: CR keeps a share of CD's voltage,
        # read in CR's units (g per mm of CD); CD itself reads right
        cr_read = cr_read + e["cr_crosstalk"] * sim["cd"][i] * 1e3
    cr_raw = cr_read + NOISE["cr_g"] * rng.standard_normal(t.size)
    if e["cr_hum"]:  # a ground loop: mains hum on the bridge, from before the crash on
        cr_raw = cr_raw + e["cr_hum"] * np.sin(2 * np.pi * HUM_HZ * t + 2 * np.pi * d.brs_phase)
    if e["cr_lost_block"]:  # the recorder's buffer overruns: a block of samples is lost, the
        k = int(np.searchsorted(t, LOST_AT_S))  # rest arrives that much early, the end padded
        nb = round(e["cr_lost_block"] * ph.FS_HZ)
        cr_raw = np.concatenate([cr_raw[:k], cr_raw[k + nb:], np.full(nb, cr_raw[-1])])
    if e["cr_rail"]:  # the conditioner's range too small: the raw channel flat at its rails
        cr_raw = np.clip(cr_raw, -e["cr_rail"], e["cr_rail"])
    if e["cr_cable_break"]:  # the cable parts: the amplifier reads a constant from then on
        cr_raw[t >= e["cr_cable_break"]] = CABLE_BREAK_G
    cr = ph.cfc(cr_raw, 180)
    if e["cr_reversed"]:  # the channel's polarity set wrong in the recorder
        cr = -cr
    cd_true = sim["cd"][i] * 1e3
    if e["dummy_late"]:  # as CR: the same recorder
        cd_true = late(cd_true, e["dummy_late"])
    cd = cd_true * (1.0 + e["cd_pot_nonlinear"] * (np.maximum(cd_true, 0) / 25.0) ** 2)
    if e["cd_pot_loading"]:  # the pot's wiper loaded by a low conditioner input: reads low
        cd = pot_loading(cd, e["cd_pot_loading"])  # over its stroke's middle
    if e["cd_knee"]:  # two-segment calibration, the second segment's slope entered wrong
        cd = np.where(cd > e["cd_knee"], e["cd_knee"] + KNEE_SLOPE * (cd - e["cd_knee"]), cd)
    if e["cd_compress"]:  # the pot's linkage reads low at large deflection, smoothly
        cd = e["cd_compress"] * np.tanh(cd / e["cd_compress"])
    if e["cd_dead_band"]:  # slack in the pot's linkage, held one way by its return spring
        b = e["cd_dead_band"]
        cd = np.sign(cd) * np.maximum(np.abs(cd) - b, 0.0)
    if e["cd_backlash"]:  # play in the pot arm's worn slot: the arm moves only once the
        cd = backlash(cd, e["cd_backlash"])  # sternum has taken up the play (a play operator)
    if e["cd_arm_lift"]:  # the pot arm's return spring gone weak: pushed in by the sternum,
        cd = arm_lift(cd, e["cd_arm_lift"] * 1e3 / ph.FS_HZ)  # it lifts off as the chest opens
    if e["cd_sag"]:  # the pot's excitation sags from the trigger on, its gain with it
        cd = cd * (1.0 - e["cd_sag"] * (1.0 - np.exp(-np.maximum(t, 0.0) / CD_SAG_TAU_S)))
    if e["cd_aa_filter"]:  # the CD module's analog anti-alias filter set for a slow channel:
        cd = aa_filter(cd, e["cd_aa_filter"])  # a causal low-pass ahead of the digitiser
    if e["cd_rc_filter"]:  # the conditioner's one-pole RC output stage, set for a slow channel
        cd = rc_filter(cd, e["cd_rc_filter"])
    if e["cd_slew"]:  # the conditioner's output amplifier slew-limited (a slow op-amp): CD
        cd = slew(cd, e["cd_slew"] * 1e3 / ph.FS_HZ)  # follows no faster, either way
    if e["cd_arm_ring"]:  # the pot's arm a lightly damped mass on a spring: CD rings
        cd = damped_element(cd, e["cd_arm_ring"], CD_RING_ZETA)
    if e["cd_clock"]:  # the CD module's own clock slow: its time base stretched from trigger
        cd = clock(cd, e["cd_clock"])
    cd = cd + NOISE["cd_mm"] * rng.standard_normal(t.size)
    if e["cd_stuck_bit"]:  # one data line of the digitiser stuck at 1: the recorded channel
        raw = -cd  # (J211 sign) reads one bit's weight high wherever that bit should be 0
        lsb = 2.0 * CD_ADC_MM / 2 ** ADC_BITS
        weight = lsb * 2 ** round(e["cd_stuck_bit"])
        bit = np.floor((raw + CD_ADC_MM) / weight) % 2
        cd = -(raw + (1.0 - bit) * weight)
    if e["cd_rail"]:  # the conditioner's output saturates: the raw channel flat at its range
        cd = np.clip(cd, -e["cd_rail"], e["cd_rail"])
    if e["cd_spikes"]:  # the connector opens and closes: short spikes
        for t_s, sign in SPIKES_S:
            k = int(np.searchsorted(t, t_s - 1e-9))
            cd[k:k + SPIKE_SAMPLES] += sign * e["cd_spikes"]
    if e["cd_dropout"]:  # the wiper lifts off its track: the raw channel reads zero
        cd[(t >= e["cd_dropout"]) & (t < e["cd_dropout"] + DROPOUT_S)] = 0.0
    cd = ph.cfc(cd, 600) + e["zero_offset"]
    if e["cd_reversed"]:  # the channel's polarity set wrong in the recorder (as cr_reversed)
        cd = -cd
    rig = RIGS[d.setup]
    code, text = PULSE_CHANNEL[d.setup]
    n = counts_per_rev
    # brs_counts: the export wrote the spindle's raw counts where its header (and every other
    # test's file) has degrees: the channel reads n / 360 of the spool's turn
    brs = counts if e["brs_counts"] else counts * 360.0 / n
    chans = [
        Channel(code, text, "g", "AC", "X", "NOVALUE", -pulse),
        Channel("11RETR0000B1AN0P", f"Retractor spindle angle, + = pay-in ({n} counts/rev)",
                "deg", "AN", "0", "NOVALUE", brs),
        Channel("11CHST0000H3ACXC", "Thorax spine accel X", "g", "AC", "X", "180", -cr),
        Channel("11CHST0000H3DSXB", "Sternum deflection X", "mm", "DS", "X", "600", -cd),
    ]
    mme = {
        "Data format edition number": "1.6",
        "Laboratory name": "INDEPENDENT HELD-OUT LAB",
        "Laboratory test ref. number": d.name,
        "Customer name": "NOVALUE",
        "Title": rig["Title"],
        "Type of the test": rig["Type of the test"],
        "Date of the test": "2026-11-24",
        "Number of test objects": "1",
        "Name of test object 1": DUMMY,
        "Velocity test object 1": f"{d.dv_ms:.2f}",
        "Comments": f"Spindle encoder {n} counts/rev, both directions; pulse unfiltered",
        "Instrumentation standard": "SAEJ211",
    }
    truth = {"name": d.name, "part": d.part, "setup": d.setup, "dv_ms": round(d.dv_ms, 4),
             "params": {k: round(v, 6) for k, v in d.params.items()},
             "effects": {k: v for k, v in d.effects.items() if v},
             "peak_cd_mm": round(float(cd_true.max()), 2),
             "peak_cr_g": round(float(sim["cr"][i].max() / ph.G), 2)}
    return Test(d.name, mme, chans), truth
