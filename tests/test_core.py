"""The observer core without a bus: arming, bias, trigger, hold, validity, faults.

Crash sequences are built from the bundled R16_002 pulse and BRS at the tick rate; every
event the core runs is compared with the offline simulation of the same model on the same
inputs from the same onset, bias and BRS reference (``recording.offline_estimates``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from observer_node.daemon.core import (
    ARMED,
    BAD_E2E,
    HOLD,
    LOST_FRAME,
    NOT_ARMED,
    RUNNING,
    SENSOR_FAULT,
    CoreConfig,
    ObserverCore,
)
from observer_node.data import bundled_campaign, read_isomme
from observer_node.data.crashtest import resample_inputs
from observer_node.recording import Recording, offline_estimates

FS = 1000.0


@pytest.fixture(scope="module")
def crash():
    """R16_002 from first contact at the tick rate: (deceleration g, BRS counts)."""
    t = read_isomme(bundled_campaign() / "R16_002.zip")
    p, b, step = resample_inputs(t.pulse_g, t.brs, t.fs_hz, FS)
    after = t.t0_s + np.arange(len(p)) * step / t.fs_hz >= 0
    return p[after], b[after].astype(float)


def run_core(core: ObserverCore, decel_g: np.ndarray, brs: np.ndarray) -> dict[str, np.ndarray]:
    """Tick the core through a sequence, one row per tick as the daemon records it."""
    cols = ("tick", "accel_x_g", "bias_g", "brs_count", "brs_ref", "rad_per_count", "cr_g",
            "cd_mm", "valid", "running", "state", "event", "onset_tick", "cause")
    rows = []
    for d, b in zip(decel_g, brs, strict=True):
        core.set_brs(b, 96)
        core.tick(d)
        rows.append((core.tick_index, -d, core.bias_g, core.brs_count, core.brs_ref,
                     core.rad_per_count, core.cr_g, core.cd_mm, core.valid,
                     core.state == RUNNING, core.state, core.event, core.onset_tick,
                     core.invalid_cause))
    a = np.array(rows, dtype=float)
    return {c: a[:, k] for k, c in enumerate(cols)}


def assert_events_equal_offline(model, ticks: dict[str, np.ndarray], n_events: int) -> None:
    rec = Recording(Path("core"), {}, model, ticks, [], {})
    events = sorted({int(e) for e in ticks["event"][ticks["running"] > 0]})
    assert events == list(range(n_events))
    for e in events:
        idx, y_off = offline_estimates(rec, e)
        rows = idx - int(ticks["tick"][0])
        run = ticks["running"][rows] > 0  # ticks before the trigger are stepped at it
        assert np.max(np.abs(ticks["cr_g"][rows][run] - y_off[run, 0])) < 1e-9
        assert np.max(np.abs(ticks["cd_mm"][rows][run] - y_off[run, 1])) < 1e-9
        assert np.max(np.abs(y_off[:, 1])) > 10  # a real event, not zeros


def quiet(rng, n: int, level_g: float) -> np.ndarray:
    return level_g + 0.2 * rng.normal(size=n)


@pytest.mark.parametrize("shift_g", [0.0, 0.9, 1.5, 5.0])
def test_every_crash_detected_after_a_zero_shift(model, crash, shift_g):
    """The first crash leaves the accelerometer with a zero shift; the next two crashes (on
    the shifted zero) are detected and stepped exactly as offline, with the new bias."""
    rng = np.random.default_rng(int(shift_g * 10))
    pulse, counts = crash
    parts_p, parts_b = [quiet(rng, 300, 0.2)], [np.zeros(300)]
    zero, brs0 = 0.2, 0.0
    for _ in range(3):
        parts_p += [pulse + zero, quiet(rng, 400, zero + shift_g)]
        parts_b += [brs0 + counts, np.full(400, brs0 + counts[-1])]
        zero += shift_g
        brs0 += counts[-1]
    core = ObserverCore(model.observer())
    ticks = run_core(core, np.concatenate(parts_p), np.concatenate(parts_b))
    assert core.events == 3 and core.hold_timeouts == 0
    assert_events_equal_offline(model, ticks, 3)
    # the bias of each event is the zero it happened on
    for e, z in enumerate((0.2, 0.2 + shift_g, 0.2 + 2 * shift_g)):
        first = np.flatnonzero(ticks["event"] == e)[0]
        assert ticks["bias_g"][first] == pytest.approx(z, abs=0.08)
    # valid only while armed or running: never while holding
    hold = ticks["state"] == HOLD
    assert hold.any() and not ticks["valid"][hold].any()
    assert (ticks["cause"][hold].astype(int) & NOT_ARMED).all()
    assert ticks["valid"][ticks["running"] > 0].all()


def test_pulse_that_never_goes_quiet_rearms_flagged(model, crash):
    """After the event the pulse keeps shaking (std 3 g): HOLD ends after ``hold_max_s``, a
    sensor fault is counted and the estimate stays invalid while it shakes; a crash during
    it is still detected, and once the pulse settles the estimate is valid again."""
    rng = np.random.default_rng(7)
    pulse, counts = crash
    cfg = CoreConfig(hold_max_s=0.5)
    core = ObserverCore(model.observer(), cfg)
    shake = 1.0 + 3.0 * np.sin(np.arange(1500) * 2 * np.pi * 40 / FS)  # never quiet
    p = np.concatenate([quiet(rng, 300, 0.0), pulse, shake, pulse + 1.0, quiet(rng, 600, 1.0)])
    b = np.concatenate([np.zeros(300), counts, np.full(1500, counts[-1]),
                        counts[-1] + counts, np.full(600, 2 * counts[-1])])
    ticks = run_core(core, p, b)
    assert core.hold_timeouts >= 1 and core.faults & SENSOR_FAULT
    assert core.events >= 2  # the second crash was not missed
    shaking = slice(300 + len(pulse) + 700, 300 + len(pulse) + 1500)
    assert not ticks["valid"][shaking].any()
    assert core.state == ARMED and ticks["valid"][-50:].all()
    assert ticks["bias_g"][-1] == pytest.approx(1.0, abs=0.1)


def test_bias_step_while_armed_is_followed(model, crash):
    """A 2 g step of the zero while armed (below the trigger): no event, the bias follows
    within one window, and the next crash is stepped on the new zero."""
    rng = np.random.default_rng(3)
    pulse, counts = crash
    core = ObserverCore(model.observer())
    p = np.concatenate([quiet(rng, 300, 0.0), quiet(rng, 300, 2.0), pulse + 2.0])
    b = np.concatenate([np.zeros(600), counts])
    ticks = run_core(core, p, b)
    assert core.events == 1 and int(ticks["event"][599]) == -1
    assert ticks["bias_g"][599] == pytest.approx(2.0, abs=0.08)
    assert_events_equal_offline(model, ticks, 1)


def test_implausible_bias_is_a_sensor_fault(model):
    core = ObserverCore(model.observer(), CoreConfig(bias_max_g=10.0))
    for _ in range(200):
        core.tick(-55.0)
    assert core.bias_faults == 1 and not core.valid
    assert core.invalid_cause & SENSOR_FAULT and core.faults & SENSOR_FAULT
    assert core.events == 0


def test_brs_jump_no_belt_can_make_is_a_fault_not_an_input(model, crash):
    """A BRS counter reset (-218 counts to 0) inside an event: flagged, and the spindle angle
    the observer steps on stays continuous (the reference moves with the jump)."""
    rng = np.random.default_rng(5)
    pulse, counts = crash
    core = ObserverCore(model.observer())
    b = np.concatenate([np.zeros(300), counts])
    p = np.concatenate([quiet(rng, 300, 0.0), pulse])
    jump_at = 300 + 150
    b[jump_at:] -= counts[-1]  # the next test's reset arrives early
    ticks = run_core(core, p, b)
    assert core.brs_jumps == 1 and core.faults & SENSOR_FAULT
    assert not ticks["valid"][jump_at]
    angle = (ticks["brs_count"] - ticks["brs_ref"])[300:]
    assert np.max(np.abs(np.diff(angle))) <= 20  # no 218-count step in what is stepped


def test_core_arms_triggers_runs_and_rearms(model):
    core = ObserverCore(model.observer(), CoreConfig(event_s=0.05, rearm_s=0.02))
    rng = np.random.default_rng(0)
    for v in 0.4 + 0.05 * rng.normal(size=200):  # 0.4 g accelerometer bias
        core.tick(v)
    assert core.state == ARMED and core.bias_g == pytest.approx(0.4, abs=0.02)
    ramp = 0.4 + np.linspace(0, 20, 10)
    for v in ramp:
        core.tick(v)
    assert core.state == RUNNING and core.event == 0
    # onset: the last quiet sample before the ramp crossed bias + 0.5 g
    first_above = 200 + int(np.argmax(ramp - 0.4 >= 0.5))
    assert core.onset_tick == first_above
    for _ in range(60):
        core.tick(20.4)
    assert core.state == HOLD and core.cr_g == 0.0 and not core.valid
    for _ in range(core.n_bias):  # one quiet window, on the new zero
        core.tick(0.9)
    assert core.state == ARMED and core.bias_g == pytest.approx(0.9) and core.valid


def test_core_validity_recovers_after_faults(model):
    core = ObserverCore(model.observer(), CoreConfig(recover_ticks=3))
    core.tick(0.0)
    assert core.valid
    core.fault(BAD_E2E)
    assert not core.valid and core.cause & BAD_E2E
    for _ in range(3):  # invalid for the next three ticks
        core.tick(0.0)
        assert not core.valid
    core.tick(0.0)
    assert core.valid and core.cause == 0 and core.faults & BAD_E2E
    core.bridge(2)  # two lost samples are stepped with the held pulse
    assert core.tick_index == 6 and core.faults & LOST_FRAME


@pytest.mark.parametrize("name", sorted(p.stem for p in bundled_campaign().glob("*.zip")))
def test_every_bundled_test_is_stepped_as_offline_with_no_fault(model, name):
    """Real belts move fast (load limiters pay out at ~2000 rad/s in FULL_002): no bundled
    test may trip a sensor fault, and every one is stepped exactly as offline."""
    t = read_isomme(bundled_campaign() / f"{name}.zip")
    p, b, step = resample_inputs(t.pulse_g, t.brs, t.fs_hz, FS)
    after = t.t0_s + np.arange(len(p)) * step / t.fs_hz >= 0
    rng = np.random.default_rng(7)
    core = ObserverCore(model.observer())
    ticks = run_core(core, np.concatenate([quiet(rng, 300, 0.0), p[after]]),
                     np.concatenate([np.full(300, b[after][0]), b[after]]))
    assert core.faults == 0 and core.brs_jumps == 0, core.faults
    assert ticks["valid"][300:].all()
    assert_events_equal_offline(model, ticks, 1)
