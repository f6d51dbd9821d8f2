"""The check of the loop's final model for a belt that pushes the chest
(observer_node.loop.belt_check) and the belt force it reads (model.nonlinear.belt_force_n)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from observer_node.ident import greybox
from observer_node.ident.dataset import Dataset, make_dataset
from observer_node.loop.belt_check import BeltPush, belt_pushes, slack_gains
from observer_node.loop.report_md import _markdown_belt
from observer_node.model.nonlinear import NonlinearGreyBox, belt_force_n
from observer_node.simulator import PlantConfig, simulate_campaign


@pytest.fixture(scope="module")
def two_rigs() -> tuple[dict, Dataset]:
    """Clean R16 and sled tests of the library's simulator (a linear belt that pushes in the
    rebound) and the grey-box identified on them."""
    tests = [*simulate_campaign("R16", 3, seed=11, config=PlantConfig(noise=False)),
             *simulate_campaign("SLED", 3, seed=12, config=PlantConfig(noise=False))]
    data = make_dataset(tests, 1000.0)
    return dict(greybox.fit_greybox(data).params), data


def test_the_belt_force_is_the_one_the_daemon_steps_with(two_rigs: tuple[dict, Dataset]
                                                         ) -> None:
    """Along a model with a fractional input delay and a force effect: the force read from
    the simulation's states equals k2 e + c2 e' at the state and inputs of each daemon tick."""
    base, data = two_rigs
    effects = [{"kind": "input_delay", "parameters": {"n_pulse": 1.5, "n_brs": 2.25}},
               {"kind": "chest_stiffening", "parameters": {"k3": 2e8}}]
    whole = belt_force_n(NonlinearGreyBox(base, effects, 1000.0, ["R16"] * 2),
                         data.pulse_g[:2], data.brs_rad[:2])
    for i in range(2):
        m = NonlinearGreyBox(base, effects, 1000.0, "R16")
        by_tick = []
        for p, th in zip(data.pulse_g[i], data.brs_rad[i], strict=True):
            z = m.x.copy()  # the state the tick's forces act at
            m.step(float(p), float(th))
            u1, u2 = m._u
            by_tick.append(base["k2"] * (z[4] - z[3]) + base["c2"] * (u1 + base["R"] * u2 - z[2]))
        np.testing.assert_allclose(whole[i], by_tick, rtol=1e-9, atol=1e-6)


def test_a_pushing_belt_is_reported_on_each_setup_a_slack_belt_does_not_act_on(
        two_rigs: tuple[dict, Dataset]) -> None:
    base, data = two_rigs
    found = belt_pushes(base, [], data, {"R16": -3.5})
    assert [b.setup for b in found] == ["R16", "SLED"]
    for b in found:
        assert b.tests == 3 and b.push_n >= 0.1 * b.pull_n > 0 and b.pushing_ms >= 5
        assert 0.5 < b.rebound_share <= 1  # after the pull's peak: the rebound
    assert found[0].slack_gain_points == -3.5 and found[1].slack_gain_points is None
    slack_on_sled = [{"kind": "belt_unloading", "parameters": {}, "setups": ["SLED"]}]
    assert [b.setup for b in belt_pushes(base, slack_on_sled, data, {})] == ["R16"]
    assert belt_pushes(base, [{"kind": "belt_unloading", "parameters": {}}], data, {}) == []


def test_a_belt_that_only_pulls_is_not_reported(two_rigs: tuple[dict, Dataset]) -> None:
    """A crash without rebound (the deceleration still rising at the end, the spindle still
    paying out): the belt never pushes, so nothing is reported."""
    base, data = two_rigs
    n = data.pulse_g.shape[1]
    held = Dataset(data.names, data.setups, data.fs_hz,
                   np.tile(np.linspace(0.0, 20.0, n), (data.n_tests, 1)),
                   np.tile(np.linspace(0.0, 3.0, n), (data.n_tests, 1)), data.y, data.win,
                   data.window_s)
    force = belt_force_n(NonlinearGreyBox(base, [], 1000.0, list(held.setups)),
                         held.pulse_g, held.brs_rad)[:, held.win]
    assert force.min() > 0  # the precondition: it pulls throughout
    assert belt_pushes(base, [], held, {}) == []


def test_the_slack_belts_gain_is_its_best_per_setup_over_scopes_and_rounds() -> None:
    """Each setup's own mean gain (not the mean over all tests, which a narrow scope pulls
    towards zero), the best of every scope and round, whichever comes first."""
    def tried(kind: str, scope: str, per_setup: dict[str, float]) -> SimpleNamespace:
        mean = float(np.mean(list(per_setup.values())))
        return SimpleNamespace(kind=kind, scope=scope, evidence=SimpleNamespace(
            gain_points=mean, setup_gain_points=per_setup))
    history = [SimpleNamespace(tried=[tried("belt_unloading", "SLED",
                                            {"R16": -1.3, "SLED": -13.3}),
                                      tried("chest_stiffening", "all",
                                            {"R16": 4.0, "SLED": 4.0})]),
               SimpleNamespace(tried=[tried("belt_unloading", "all",
                                            {"R16": -20.47, "SLED": -12.7})])]
    assert slack_gains(history) == {"R16": -1.3, "SLED": -12.7}  # type: ignore[arg-type]


def test_a_setup_not_judged_or_run_away_is_left_out(two_rigs: tuple[dict, Dataset]) -> None:
    base, data = two_rigs
    assert [b.setup for b in belt_pushes(base, [], data, {}, skip={"SLED"})] == ["R16"]
    broken = Dataset(data.names, data.setups, data.fs_hz, data.pulse_g.copy(),
                     data.brs_rad.copy(), data.y, data.win, data.window_s)
    broken.brs_rad[4, 60] = np.nan  # a SLED test
    assert [b.setup for b in belt_pushes(base, [], broken, {})] == ["R16"]


def test_the_numbers_are_read_in_the_fit_window_per_test(two_rigs: tuple[dict, Dataset]
                                                         ) -> None:
    """The pushing time is the mean over a setup's tests, in the fit window; the largest push
    and pull are over its tests there."""
    base, data = two_rigs
    force = belt_force_n(NonlinearGreyBox(base, [], 1000.0, list(data.setups)),
                         data.pulse_g, data.brs_rad)[:3, data.win]
    r16 = belt_pushes(base, [], data, {})[0]
    assert r16.pushing_ms == round(float(np.mean(np.sum(force < 0, axis=1))), 1)
    assert r16.push_n == round(float(-force.min())) and r16.pull_n == round(float(force.max()))
    # a window that ends before the rebound: no push to report, though the record has one
    early = Dataset(data.names, data.setups, data.fs_hz, data.pulse_g, data.brs_rad, data.y,
                    slice(10, 60), data.window_s)
    assert belt_pushes(base, [], early, {}) == []


def test_report_md_tables_each_setup_the_belt_pushes_on() -> None:
    lines = _markdown_belt([BeltPush("FULL", 3, 38.2, 3186.0, 10862.0, 0.96, -19.89),
                            BeltPush("R16", 3, 50.0, 3070.0, 10144.0, 0.97, None)])
    assert lines[0] == "## The model's belt pushes the chest"
    assert "Most of it comes after the pull's peak" in lines[2]
    assert "| FULL | 3 | 38 | 3186 | 10862 | 96% | -19.89 |" in lines
    assert "| R16 | 3 | 50 | 3070 | 10144 | 97% | not tried |" in lines
    early = _markdown_belt([BeltPush("FULL", 3, 38.2, 3186.0, 10862.0, 0.3, None)])
    assert "after the pull's peak" not in early[2]
    b = BeltPush("FULL", 3, 38.2, 3186.0, 10862.0, 0.96, None)
    assert list(b.as_dict()) == ["setup", "tests", "pushing_ms", "push_n", "pull_n",
                                 "rebound_share", "slack_gain_points"]
