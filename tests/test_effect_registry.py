"""The effect registry: an effect registered in one place is in the model file's schema, the
C export, the non-linear model and the loop's candidates, with nothing else edited."""

from __future__ import annotations

import numpy as np
import pytest

from observer_node.data import bundled_campaign, read_isomme
from observer_node.ident.dataset import make_dataset
from observer_node.model.chest import PARAM_NAMES, model_matrices
from observer_node.model.effects import EFFECTS, Effect, Param, kinematics, register, registered
from observer_node.model.modelfile import ModelFile, ModelFileError
from observer_node.model.nonlinear import NonlinearGreyBox

BASE = {"k1": 2.0e5, "c1": 900.0, "k2": 1.2e5, "c2": 1500.0, "m1": 20.0, "m2": 2.5, "R": 0.02}

# A toy: a damper between the spine and the vehicle, F = ct (p' - x') on the spine. It is
# pelvis_coupling with kp = 0, which says what the model must compute for it.
TOY = Effect(
    "toy_spine_damper", "physical", "toy: a damper between the spine and the vehicle",
    (Param("ct", "N s/m", 300.0, positive=True),),
    force=lambda p, k, b: (p["ct"] * (k.u1 - k.xd), k.zero),
    c_code=lambda p, num, b: f"    fs += {num(p['ct'])} * (u[0] - z[0]);\n")


def _model_file(effects: list[dict]) -> dict:
    Ad, Bd, C, D = model_matrices(BASE, 1000.0, True)
    mf = ModelFile(kind="greybox", name="toy", tick_rate_hz=1000.0,
                   input_transform="velocity_brs_rate", A=Ad, B=Bd, C=C, D=D,
                   parameters={n: {"value": BASE[n]} for n in PARAM_NAMES}, effects=effects)
    return mf.to_dict()


@pytest.fixture(scope="module")
def data():
    tests = [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3)]
    return make_dataset(tests, 1000.0)


def test_a_registered_effect_is_in_the_schema_model_c_export_and_candidates(data, tmp_path):
    toy = {"kind": TOY.kind, "parameters": {"ct": 250.0}}
    with pytest.raises(ModelFileError, match="toy_spine_damper"):
        ModelFile.from_dict(_model_file([toy]), "before")
    with registered(TOY):
        # the schema takes it, with the parameter its formula needs
        mf = ModelFile.from_dict(_model_file([toy]), "toy")
        with pytest.raises(ModelFileError, match="ct"):
            ModelFile.from_dict(_model_file([{"kind": TOY.kind, "parameters": {}}]), "toy")
        # the non-linear model simulates it as the built-in effect it equals
        y = mf.observer().simulate(data.pulse_g, data.brs_rad)
        same = NonlinearGreyBox(BASE, [{"kind": "pelvis_coupling",
                                        "parameters": {"kp": 0.0, "cp": 250.0}}], 1000.0)
        np.testing.assert_array_equal(y, same.simulate(data.pulse_g, data.brs_rad))
        plain = NonlinearGreyBox(BASE, [], 1000.0).simulate(data.pulse_g, data.brs_rad)
        assert np.abs(y - plain).max() > 0.1  # it acts
        # the C export writes its force
        from observer_node.export_c import export_c, supported_effects

        assert TOY.kind in supported_effects()
        export_c(mf, tmp_path)
        assert "fs += 250 * (u[0] - z[0]);" in (tmp_path / "chest_observer.c").read_text()
        # the loop's residual analysis searches it as its definition says
        from observer_node.loop.analysis import candidates

        ranked = {c.kind: c for c in candidates(NonlinearGreyBox(BASE, [], 1000.0), data,
                                                set())}
        assert TOY.kind in ranked
        assert set(ranked[TOY.kind].parameters) == {"ct"}
        assert ranked[TOY.kind].parameters["ct"] > 0  # a positive parameter stays positive
    assert TOY.kind not in EFFECTS


def test_the_c_export_of_a_registered_effect_steps_as_python(data, tmp_path):
    from .test_export_c import CC, run_c

    if CC is None:
        pytest.skip("no C compiler")
    with registered(TOY):
        mf = ModelFile.from_dict(_model_file([{"kind": TOY.kind,
                                               "parameters": {"ct": 250.0}}]))
        pulse, brs = data.pulse_g[0], data.brs_rad[0]
        y_py = mf.observer().simulate(pulse, brs)
        y_c = run_c(mf, tmp_path, "double", pulse, brs)
    scale = np.max(np.abs(y_py), axis=0)
    assert np.max(np.abs(y_c - y_py) / scale) < 1e-9


def test_an_incomplete_or_second_definition_is_refused():
    with pytest.raises(ValueError, match="registered already"):
        register(Effect("chest_stiffening", "physical", "again",
                        (Param("k3", "N/m^3", 1.0),), force=lambda p, k, b: (k.zero, k.zero)))
    with pytest.raises(ValueError, match="no formula"):
        register(Effect("toy_no_force", "physical", "a force without its formula"))
    with pytest.raises(ValueError, match="nothing to search"):
        register(Effect("toy_no_params", "physical", "searched by scale, nothing to scale",
                        force=lambda p, k, b: (k.zero, k.zero)))
    assert "toy_no_force" not in EFFECTS and "toy_no_params" not in EFFECTS


def test_every_effect_the_simulator_names_is_registered_with_its_family():
    from observer_node.simulator import EFFECTS as SIMULATED

    assert set(SIMULATED) <= set(EFFECTS)
    assert {e.family for e in EFFECTS.values()} == {"physical", "sensor"}
    # a sensor effect acts on the inputs or outputs, never as a force on the chest
    assert all(e.acts in ("input_delay", "output_offset")
               for e in EFFECTS.values() if e.family == "sensor")


def test_a_parameter_with_a_physical_range_is_fitted_and_filed_within_it(data):
    # a spool's BRS gain changes by at most 0.04 /rad
    from observer_node.loop.refit import refit

    assert EFFECTS["input_gain"].param("g").bounds == (-0.04, 0.04)
    with pytest.raises(ModelFileError, match="g"):
        ModelFile.from_dict(_model_file([{"kind": "input_gain", "parameters": {"g": 0.1}}]))
    # data made with a BRS gain far beyond the range: the fit stays inside it
    truth = NonlinearGreyBox(BASE, [{"kind": "input_gain", "parameters": {"g": 0.3}}], 1000.0)
    y = truth.simulate(data.pulse_g, data.brs_rad)
    from dataclasses import replace
    fake = replace(data, y=y)
    r = refit(BASE, [{"kind": "input_gain", "parameters": {"g": 0.01}}], fake, max_nfev=40)
    g = r.effects[0]["parameters"]["g"]
    assert 0.03 < g <= 0.04  # pushed towards the edge, never past it
    # a fit held at the edge is refused: the data want more than a spool can do
    from observer_node.loop.verdicts import at_the_edge
    why = at_the_edge("input_gain", {"g": -0.0399})
    assert why is not None and "held at the edge of what input_gain can be" in why
    assert at_the_edge("input_gain", {"g": 0.02}) is None
    assert at_the_edge("chest_stiffening", {"k3": 1e12}) is None  # no range: the warnings'


def test_kinematics_read_in_any_order_give_their_formulas() -> None:
    """A formula reads the kinematics it needs, in any order, and gets the same numbers
    (worked out on first reading); on arrays, NaN where a state ran away stays in ``zero``."""
    z = np.array([[0.5, 0.2], [0.01, 0.03], [1.5, np.nan], [0.04, 0.05], [0.06, 0.02],
                  [0.1, 0.2]])
    u1, u2, theta = np.array([2.0, 3.0]), np.array([10.0, 20.0]), np.array([0.3, 0.4])
    first = kinematics(z, u1, u2, theta, BASE)
    fields = (first.ed, first.zero, first.e, first.dd, first.d)
    again = kinematics(z, u1, u2, theta, BASE)
    np.testing.assert_array_equal(again.d, z[3] - z[1])
    np.testing.assert_array_equal(again.dd, z[2] - z[0])
    np.testing.assert_array_equal(again.e, z[4] - z[3])
    np.testing.assert_array_equal(again.ed, u1 + BASE["R"] * u2 - z[2])
    for a, b in zip(fields, (again.ed, again.zero, again.e, again.dd, again.d), strict=True):
        np.testing.assert_array_equal(a, b)
    assert again.zero[0] == 0.0 and not np.isnan(again.zero[0])
    # d is finite in both columns here; a NaN spine displacement runs into d and zero
    z[1, 1] = np.nan
    ran_away = kinematics(z, u1, u2, theta, BASE)
    assert np.isnan(ran_away.zero[1]) and ran_away.zero[0] == 0.0
    assert (ran_away.pos == z[5]).all() and (ran_away.theta == theta).all()
