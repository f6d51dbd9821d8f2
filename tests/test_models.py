"""The grey-box, ARX and N4SID models against data with known truth."""

from __future__ import annotations

import numpy as np
import pytest

from observer_node.data import THESIS_WINDOW_S
from observer_node.ident import arx, greybox, n4sid
from observer_node.ident.dataset import Dataset, make_dataset
from observer_node.ident.metrics import fit_percent, fit_table
from observer_node.model import chest, simulate_ss
from observer_node.simulator import ChestParams, PlantConfig, simulate_campaign

TRUTH = ChestParams()


@pytest.fixture(scope="module")
def clean_r16() -> list:
    return simulate_campaign("R16", 6, seed=3, config=PlantConfig(noise=False))


def test_fit_measure_eq_3_15():
    y = np.array([1.0, 2.0, 3.0, 4.0])
    assert fit_percent(y, y) == 100.0
    assert fit_percent(y, np.full(4, y.mean())) == pytest.approx(0.0)
    # ||e|| = 1, ||y - mean|| = sqrt(5)
    assert fit_percent(y, y + np.array([1.0, 0, 0, 0])) == pytest.approx(100 * (1 - 1 / 5**0.5))
    t = fit_table(["a", "b"], np.stack([np.stack([y, y], -1)] * 2),
                  np.stack([np.stack([y, np.full(4, y.mean())], -1)] * 2))
    assert t.fit.as_dict() == {"cr": 100.0, "cd": pytest.approx(0.0), "total": pytest.approx(50.0)}


def test_zoh_is_exact_across_tick_rates():
    p = {**TRUTH.as_dict()}
    Ad1, Bd1, _, _ = chest.discrete_thesis(p, 1000.0)
    Ad10, Bd10, _, _ = chest.discrete_thesis(p, 10_000.0)
    # Ten steps at 10 kHz with a held input equal one step at 1 kHz.
    x1 = Ad1 @ np.ones(5) + Bd1 @ np.array([1.0, 2.0])
    x10 = np.ones(5)
    for _ in range(10):
        x10 = Ad10 @ x10 + Bd10 @ np.array([1.0, 2.0])
    np.testing.assert_allclose(x1, x10, rtol=1e-9, atol=1e-12)


def test_overall_mass_scale_is_not_identifiable(clean_r16):
    data = make_dataset(clean_r16[:2], 1000.0)
    p = TRUTH.as_dict()
    scaled = {k: (v * 3.0 if k != "R" else v) for k, v in p.items()}
    np.testing.assert_allclose(greybox.simulate(p, data), greybox.simulate(scaled, data),
                               rtol=1e-8, atol=1e-9)


def test_greybox_recovers_simulator_parameters(clean_r16):
    data = make_dataset(clean_r16, 10_000.0)
    fit = greybox.fit_greybox(data, m1_kg=TRUTH.m1)
    for name, tol in (("k1", 0.02), ("k2", 0.02), ("c2", 0.03), ("R", 0.02), ("c1", 0.05)):
        assert fit.params[name] == pytest.approx(getattr(TRUTH, name), rel=tol), name
        assert 0 < fit.std_err[name] < 0.1 * fit.params[name], name
    assert fit.fits.fit.total > 95


def test_greybox_fit_drops_with_unmodelled_effects(clean_r16):
    clean = greybox.fit_greybox(make_dataset(clean_r16, 1000.0))
    effects = simulate_campaign("R16", 6, seed=3, config=PlantConfig(
        noise=False, effects={"belt_unloading": 1.0, "chest_stiffening": 1.0}))
    dirty = greybox.fit_greybox(make_dataset(effects, 1000.0))
    assert clean.fits.fit.total - dirty.fits.fit.total > 5


def _random_dataset(seed: int, tests: int = 4, n: int = 151) -> Dataset:
    rng = np.random.default_rng(seed)
    # Smooth random inputs, a few crash-like bumps each.
    t = np.arange(n)
    pulse = np.stack([sum(rng.uniform(5, 30) * np.exp(-0.5 * ((t - rng.uniform(0, n)) / 8) ** 2)
                          for _ in range(4)) for _ in range(tests)])
    pulse += rng.normal(0, 1.0, pulse.shape)  # persistently exciting for the subspace method
    brs = np.cumsum(rng.normal(0, 0.05, (tests, n)), axis=1)
    return Dataset([f"T{i}" for i in range(tests)], ["SIM"] * tests, 1000.0, pulse, brs,
                   np.zeros((tests, n, 2)), slice(10, n), THESIS_WINDOW_S)


def test_arx_recovers_known_coefficients():
    data = _random_dataset(1)
    orders = arx.ArxOrders(np.array([[2, 1], [1, 2]]), np.array([[2, 1], [1, 2]]),
                           np.array([[1, 2], [0, 1]]))
    truth = arx.ArxModel(orders,
                         [[np.array([-1.5, 0.7]), np.array([0.1])],
                          [np.array([0.05]), np.array([-1.2, 0.4])]],
                         [[np.array([0.3, 0.1]), np.array([2.0])],
                          [np.array([0.5]), np.array([1.0, -0.5])]])
    data.y = truth.simulate(data)
    est = arx.estimate_arx(data, orders)
    for i in range(2):
        for j in range(2):
            np.testing.assert_allclose(est.a[i][j], truth.a[i][j], atol=1e-8)
            np.testing.assert_allclose(est.b[i][j], truth.b[i][j], atol=1e-8)


def test_arx_order_search_stays_within_nmax_and_fits():
    data = _random_dataset(2, tests=6)
    orders = arx.ArxOrders(np.array([[2, 0], [0, 2]]), np.array([[2, 1], [1, 2]]),
                           np.array([[1, 1], [1, 1]]))
    truth = arx.ArxModel(orders, [[np.array([-1.2, 0.5]), np.array([])],
                                  [np.array([]), np.array([-0.9, 0.3])]],
                         [[np.array([0.3, 0.1]), np.array([2.0])],
                          [np.array([0.5]), np.array([1.0, -0.5])]])
    data.y = truth.simulate(data)
    found, history = arx.search_orders(data, nmax=4)
    assert found.na.max() <= 4 and found.nb.max() <= 4 and found.nb.min() >= 1
    assert history[-1]["fit_total"] > 99
    assert [h["fit_total"] for h in history] == sorted(h["fit_total"] for h in history)


def test_n4sid_identifies_a_known_system():
    rng = np.random.default_rng(4)
    data = _random_dataset(3, tests=5)
    A = np.diag([0.95, 0.8, 0.6]) + 0.02 * rng.normal(size=(3, 3))
    B, C, D = rng.normal(size=(3, 2)), rng.normal(size=(2, 3)), np.zeros((2, 2))
    data.y = simulate_ss(A, B, C, D, np.stack([data.pulse_g, data.brs_rad], -1))
    m = n4sid.n4sid(data, 3, block_rows=10)
    assert m.fits.fit.total > 99.5
    np.testing.assert_allclose(np.sort(np.abs(np.linalg.eigvals(m.A))),
                               np.sort(np.abs(np.linalg.eigvals(A))), atol=1e-3)
    rows = n4sid.order_scan(data, None, range(1, 5), block_rows=10)
    assert rows[2]["estimation_fit"] > rows[0]["estimation_fit"]


def test_nonlinear_model_without_effects_is_the_linear_greybox(clean_r16):
    from observer_node.model.nonlinear import NonlinearGreyBox

    data = make_dataset(clean_r16[:3], 1000.0)
    p = TRUTH.as_dict()
    np.testing.assert_allclose(NonlinearGreyBox(p, [], 1000.0).simulate(data.pulse_g,
                                                                        data.brs_rad),
                               greybox.simulate(p, data), atol=1e-9)
    # and each effect changes the answer
    for kind, params in (("chest_stiffening", {"k3": 5e8}), ("belt_unloading", {}),
                         ("sensor_offset", {"cr_g": 1.0, "cd_mm": 0.5})):
        m = NonlinearGreyBox(p, [{"kind": kind, "parameters": params}], 1000.0)
        assert np.abs(m.simulate(data.pulse_g, data.brs_rad) -
                      greybox.simulate(p, data)).max() > 0.1, kind


def test_the_output_is_the_state_after_the_ticks_input_and_old_files_keep_theirs(clean_r16):
    """Since 0.2 a grey-box publishes at tick k the state after tick k's inputs: the old
    output one tick later. A model file without ``output_timing`` is read as before."""
    from observer_node.evaluation import identify
    from observer_node.model.modelfile import ModelFile

    data = make_dataset(clean_r16[:2], 1000.0)
    new = identify("greybox", data)
    assert new.output_timing == "after_input"
    old_dict = new.to_dict()
    old_dict.pop("output_timing")
    p = {n: v["value"] for n, v in new.parameters.items()}
    _, _, C, D = chest.discrete_thesis(p, 1000.0, after_input=False)
    old_dict["state_space"].update(C=C.tolist(), D=D.tolist())
    old = ModelFile.from_dict(old_dict)
    assert old.output_timing == "state"
    y_new = new.observer().simulate(data.pulse_g, data.brs_rad)
    y_old = old.observer().simulate(data.pulse_g, data.brs_rad)
    np.testing.assert_allclose(y_new[:, :-1], y_old[:, 1:], atol=1e-9)
    # and the model with effects (stepped from its parameters) does the same
    from observer_node.model.nonlinear import NonlinearGreyBox

    effects = [{"kind": "chest_stiffening", "parameters": {"k3": 3e8}}]
    after = NonlinearGreyBox(p, effects, 1000.0).simulate(data.pulse_g, data.brs_rad)
    before = NonlinearGreyBox(p, effects, 1000.0, after_input=False).simulate(data.pulse_g,
                                                                              data.brs_rad)
    np.testing.assert_allclose(after[:, :-1], before[:, 1:], atol=1e-9)


# one parameter set per effect kind (the formula: two terms on the rib, one on the belt)
_EFFECT_CASES = {
    "chest_stiffening": {"k3": 3e8}, "chest_rate_damping": {"c3": 300.0},
    "belt_unloading": {}, "belt_stiffening": {"kb3": 2e8},
    "airbag_contact": {"kab": 5e4, "gap": 0.05, "cab": 600.0},
    "pelvis_coupling": {"kp": 2e4, "cp": 400.0},
    "input_delay": {"n_pulse": 2.3, "n_brs": 0.7}, "input_gain": {"g": 0.02},
    "sensor_offset": {"cr_g": 1.0, "cd_mm": 1.5},
    "other": {"rib": {"d^3": 1e8, "d'|d'|": 500.0}, "belt": {"e^2": 1e6}},
}


def _scaled(params: dict, f: float) -> dict:
    return {k: _scaled(v, f) if isinstance(v, dict) else v * f for k, v in params.items()}


def test_every_effect_has_a_case_for_simulate_many():
    from observer_node.model.effects import EFFECTS

    assert set(_EFFECT_CASES) == set(EFFECTS)


@pytest.mark.parametrize("after_input", [True, False])
@pytest.mark.parametrize("kind", sorted(_EFFECT_CASES))
def test_simulate_many_gives_each_models_own_outputs_to_the_bit(clean_r16, kind, after_input):
    """The fits' Jacobians run their trial parameters as one simulation: each model's outputs
    must be exactly those it gives alone (scoped to one setup, beside a one-sided belt, with
    another model's parameters, delays included, differing)."""
    from observer_node.model.nonlinear import NonlinearGreyBox, simulate_many

    tests = clean_r16[:3]
    data = make_dataset(tests, 1000.0)
    setups = ["R16", "SLED", "R16"]
    p = TRUTH.as_dict()
    models = [NonlinearGreyBox({**p, "k2": p["k2"] * s}, [
        {"kind": kind, "parameters": _scaled(_EFFECT_CASES[kind], s), "setups": ["R16"]},
        {"kind": "belt_unloading", "parameters": {}}] if kind != "belt_unloading" else
        [{"kind": kind, "parameters": {}, "setups": ["SLED"]}], 1000.0, setups,
        after_input=after_input) for s in (1.0, 1.3, 0.8)]
    many = simulate_many(models, data.pulse_g, data.brs_rad)
    assert many.shape == (3, 3, data.pulse_g.shape[1], 2)
    assert np.isfinite(many).all()  # none ran away here (a fit's trial may: NaN matches NaN)
    for m, y in zip(models, many, strict=True):
        alone = m.simulate(data.pulse_g, data.brs_rad)
        assert np.array_equal(y, alone, equal_nan=True)
    # the parameters changed the outputs (the check is not of three copies of one model)
    assert not np.array_equal(many[0], many[1])


def test_simulate_many_keeps_a_run_away_apart_and_runs_one_test(clean_r16):
    """A fit's trial may run away (NaN): the models beside it keep their own outputs."""
    from observer_node.model.nonlinear import NonlinearGreyBox, simulate_many

    data = make_dataset(clean_r16[:1], 1000.0)
    p = TRUTH.as_dict()
    models = [NonlinearGreyBox(p, [{"kind": "chest_stiffening", "parameters": {"k3": k3}}],
                               1000.0) for k3 in (3e8, -1e14, 1e8)]
    with np.errstate(all="ignore"):
        many = simulate_many(models, data.pulse_g, data.brs_rad)
        alone = [m.simulate(data.pulse_g, data.brs_rad) for m in models]
    assert not np.isfinite(many[1]).all() and np.isfinite(many[[0, 2]]).all()
    for y, y_alone in zip(many, alone, strict=True):
        assert np.array_equal(y, y_alone, equal_nan=True)


@pytest.mark.parametrize("second", [
    [{"kind": "chest_stiffening", "parameters": {"k3": 3e8}}],  # another effect
    [{"kind": "airbag_contact", "parameters": {"kab": 5e4, "gap": 0.05}}],  # without cab
    [{"kind": "airbag_contact", "parameters": {"gap": 0.05, "kab": 5e4, "cab": 600.0}}],
    [{"kind": "airbag_contact", "parameters": {"kab": 5e4, "gap": 0.05, "cab": 600.0},
      "setups": ["SLED"]}],  # another scope
])
def test_simulate_many_refuses_models_of_different_structure(clean_r16, second):
    """Values are stacked by the first model's parameter names: a model with other names
    (an optional one left out, the same in another order) or another scope is refused,
    never run with the first model's."""
    from observer_node.model.nonlinear import NonlinearGreyBox, simulate_many

    data = make_dataset(clean_r16[:2], 1000.0)
    p = TRUTH.as_dict()
    a = NonlinearGreyBox(p, [{"kind": "airbag_contact", "parameters": {
        "kab": 5e4, "gap": 0.05, "cab": 600.0}}], 1000.0, ["R16", "SLED"])
    b = NonlinearGreyBox(p, second, 1000.0, ["R16", "SLED"])
    with pytest.raises(ValueError, match="differ in structure"):
        simulate_many([a, b], data.pulse_g, data.brs_rad)
