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
from observer_node.model.nonlinear import NonlinearGreyBox

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


def test_the_unloading_line_meets_zero_force_at_the_permanent_set() -> None:
    push, clip = _set_memory(clip=False), _set_memory(clip=True)
    k2 = BASE["k2"]
    for force in (push, clip):
        force({"h": 0.5}, kinematics(_state(0.0, 0.04), 0.0, 0.0, 0.0, BASE), BASE)  # peak
    at_set = kinematics(_state(0.0, 0.02), 0.0, 0.0, 0.0, BASE)  # e = 20 mm = h * peak
    ed = at_set.ed  # the belt's damping part, as the grey-box has it
    # the belt force there is its damping alone: the extra force takes the spring's k2 e away
    _, extra = push({"h": 0.5}, at_set, BASE)
    assert extra == pytest.approx(-k2 * 0.02)
    _, extra_clipped = clip({"h": 0.5}, at_set, BASE)
    assert extra_clipped == pytest.approx(max(BASE["c2"] * ed, 0.0) - (k2 * 0.02
                                                                       + BASE["c2"] * ed))


@pytest.mark.parametrize("form", ["belt_set_memory", "belt_set_memory_push"])
def test_a_memory_form_gives_each_run_the_same_outputs(form: str) -> None:
    """Run alone, run again, run among other trial parameters: the memory restarts with each
    simulation, so the outputs are the same (a stale peak would change the second run)."""
    _, trial, _ = FORMS[form]
    rng = np.random.default_rng(1)
    t = np.arange(150) / 1000.0
    pulse = -20.0 * np.sin(np.pi * t / 0.12).clip(0)[None] + 0.1 * rng.standard_normal((2, 150))
    brs = np.cumsum(np.abs(rng.standard_normal((2, 150))), axis=1) * 0.01
    with registered(trial):
        model = NonlinearGreyBox(BASE, [{"kind": trial.kind, "parameters": {"h": 0.4}}],
                                 1000.0)
        first = model.simulate(pulse, brs)
        again = model.simulate(pulse, brs)
    assert np.isfinite(first).all()
    np.testing.assert_array_equal(first, again)


def test_belt_push_refuses_a_folder_without_tests(capsys: pytest.CaptureFixture[str],
                                                  tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("sys.argv", ["belt_push", str(tmp_path)])
    with pytest.raises(SystemExit) as exit_:
        belt_push.main()
    assert exit_.value.code == 2
    assert capsys.readouterr().err.strip() == f"belt_push: {tmp_path}: no est/ and val/ folders"
    monkeypatch.setattr("sys.argv", ["belt_push", str(tmp_path), "--forms", "belt_fancy"])
    with pytest.raises(SystemExit) as exit_:
        belt_push.main()
    assert exit_.value.code == 2
    assert "unknown form 'belt_fancy'" in capsys.readouterr().err
