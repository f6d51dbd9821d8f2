"""The trial forms a screen judges (benchmarks/form_screen.py) and the belt diagnosis
(benchmarks/belt_push.py): a form with memory keeps the right memory through a simulation, and
bad arguments get one line and exit 2."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from benchmarks import belt_push
from benchmarks.form_screen import FORMS, _Peak, _set_memory
from observer_node.model.effects import kinematics, registered
from observer_node.model.nonlinear import NonlinearGreyBox, simulate_many

BASE = {"k1": 2e5, "c1": 900.0, "k2": 1e5, "c2": 1400.0, "m2": 6.0, "R": 0.016, "m1": 20.0}


def _state(s: float, w: float) -> np.ndarray:
    """A state (xdot, x, sdot, s, w, p) with the sternum at s and the belt at w [m]."""
    return np.array([0.1, 0.0, 0.0, s, w, 0.0])


def test_peak_holds_the_largest_penetration_and_restarts_at_rest() -> None:
    peak = _Peak()
    seen = [float(peak(kinematics(_state(0.0, e), 0.0, 0.0, 0.0, BASE)))
            for e in (0.01, 0.03, 0.02, 0.03, -0.01)]
    assert seen == [0.01, 0.03, 0.03, 0.03, 0.03]  # twice the same state changes nothing
    assert float(peak(kinematics(np.zeros(6), 0.0, 0.0, 0.0, BASE))) == 0.0  # a new run


def _moving(s: float, w: float, ed: float) -> np.ndarray:
    """A state whose belt penetration e = w - s [m] changes at ed [m/s] (inputs at zero)."""
    return np.array([0.1, 0.0, -ed, s, w, 0.0])


def test_the_unloading_line_runs_from_the_peak_to_zero_force_at_the_permanent_set() -> None:
    """h = 0.5, peak 40 mm: at 30 mm the spring is k2 (30 - 20) / 0.5 = k2 20 mm, half what
    the grey-box's k2 e gives; the clipped form never lets the force go below zero."""
    k2, c2, h = BASE["k2"], BASE["c2"], 0.5
    push, clip = _set_memory(clip=False), _set_memory(clip=True)
    for force in (push, clip):
        force({"h": h}, kinematics(_state(0.0, 0.04), 0.0, 0.0, 0.0, BASE), BASE)  # the peak
    unloading = kinematics(_moving(0.0, 0.03, -0.5), 0.0, 0.0, 0.0, BASE)  # e' = -0.5 m/s
    assert unloading.ed == pytest.approx(-0.5)
    _, extra = push({"h": h}, unloading, BASE)
    assert extra == pytest.approx(k2 * (0.02 - 0.03))  # the spring's line, damping unchanged
    # clipped: the belt's force k2 0.02 + c2 (-0.5) = 2000 - 700 N stays, as it pulls
    _, extra_clipped = clip({"h": h}, unloading, BASE)
    assert extra_clipped == pytest.approx(k2 * (0.02 - 0.03))
    fast = kinematics(_moving(0.0, 0.03, -2.0), 0.0, 0.0, 0.0, BASE)  # 2000 - 2800 N: pushes
    _, extra_fast = clip({"h": h}, fast, BASE)
    assert extra_fast == pytest.approx(-(k2 * 0.03 + c2 * -2.0))  # the whole force taken away
    loading = kinematics(_moving(0.0, 0.05, 0.5), 0.0, 0.0, 0.0, BASE)  # beyond the peak
    assert push({"h": h}, loading, BASE)[1] == pytest.approx(0.0)


def test_the_belt_off_the_chest_loses_its_whole_force_only_there() -> None:
    force = FORMS["belt_off_chest"][1].force
    assert force is not None
    off = kinematics(_moving(0.01, 0.0, 0.3), 0.0, 0.0, 0.0, BASE)  # e = -10 mm
    on = kinematics(_moving(0.0, 0.01, -3.0), 0.0, 0.0, 0.0, BASE)  # in contact, pushing
    assert force({}, off, BASE)[1] == pytest.approx(-(BASE["k2"] * -0.01 + BASE["c2"] * 0.3))
    assert force({}, on, BASE)[1] == 0.0


def test_the_webbing_knee_pulls_only_past_its_knee() -> None:
    """kbk max(e - e0, 0) on the sternum: nothing up to the knee, a straight line past it,
    nothing on the spine; the grid it starts from lies inside its range."""
    _, trial, _ = FORMS["belt_knee"]
    assert trial.force is not None
    p = {"kbk": 5e4, "e0": 0.02}
    below = kinematics(_state(0.0, 0.015), 0.0, 0.0, 0.0, BASE)
    past = kinematics(_state(0.0, 0.03), 0.0, 0.0, 0.0, BASE)
    assert trial.force(p, below, BASE) == (0.0, 0.0)
    spine, sternum = trial.force(p, past, BASE)
    assert spine == 0.0 and sternum == pytest.approx(5e4 * 0.01)
    lo, hi = next(q.within for q in trial.params if q.name == "e0") or (0.0, 0.0)
    assert trial.search.over == "e0" and all(lo <= v <= hi for v in trial.search.grid)


@pytest.mark.parametrize("form", ["belt_set_memory", "belt_set_memory_push"])
def test_a_memory_form_gives_each_run_the_same_outputs(form: str) -> None:
    """Run alone, run again, run stacked with other trial parameters (as a fit's Jacobian
    runs them): the memory restarts with each simulation and is kept per model, so the
    outputs are the same (a stale or shared peak would change them)."""
    _, trial, _ = FORMS[form]
    rng = np.random.default_rng(1)
    t = np.arange(150) / 1000.0
    pulse = -20.0 * np.sin(np.pi * t / 0.12).clip(0)[None] + 0.1 * rng.standard_normal((2, 150))
    brs = np.cumsum(np.abs(rng.standard_normal((2, 150))), axis=1) * 0.01
    with registered(trial):
        def of(h: float) -> NonlinearGreyBox:
            return NonlinearGreyBox(BASE, [{"kind": trial.kind, "parameters": {"h": h}}],
                                    1000.0)
        first = of(0.4).simulate(pulse, brs)
        again = of(0.4).simulate(pulse, brs)
        other = of(0.8).simulate(pulse, brs)
        stacked = simulate_many([of(0.4), of(0.8)], pulse, brs)
    assert np.isfinite(first).all()
    assert not np.array_equal(first, other)  # h matters: the belt unloads in these runs
    np.testing.assert_array_equal(first, again)
    np.testing.assert_array_equal(stacked[0], first)
    np.testing.assert_array_equal(stacked[1], other)


def test_belt_push_refuses_a_folder_without_tests_before_any_fit(
        capsys: pytest.CaptureFixture[str], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "empty" / "est").mkdir(parents=True)
    (tmp_path / "empty" / "val").mkdir()
    for argv, says in (([str(tmp_path / "missing")], "missing/est: no such file or folder"),
                       ([str(tmp_path / "empty")], "empty/est: no crash tests in it"),
                       ([str(tmp_path), "--forms", "brs_ring"], "unknown belt form 'brs_ring'")):
        monkeypatch.setattr("sys.argv", ["belt_push", *argv])
        with pytest.raises(SystemExit) as exit_:
            belt_push.main()
        assert exit_.value.code == 2
        err = capsys.readouterr().err
        assert err.startswith("belt_push: ") and says in err and err.count("\n") == 1
