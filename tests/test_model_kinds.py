"""Model kinds: a kind registered once for the model file and once for identification is
identified, written, loaded and evaluated, with nothing else edited."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from observer_node.data import bundled_campaign, read_isomme
from observer_node.evaluation import evaluate_model, identify
from observer_node.ident.dataset import make_dataset
from observer_node.ident.kinds import IDENTIFY, IdentifyOptions, registered_identify
from observer_node.model.kinds import MODEL_KINDS, ModelKind, registered_kind
from observer_node.model.modelfile import ModelFile, ModelFileError


@pytest.fixture(scope="module")
def r16():
    return [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3)]


def _arx_as_toy(data, o: IdentifyOptions) -> ModelFile:
    """A toy kind: an ARX model by another name (so its outputs are known)."""
    return replace(IDENTIFY["arx"](data, o), kind="toy_arx", name=o.name or "toy")


TOY = ModelKind("toy_arx", "an ARX model by another name",
                summary=lambda mf: {"toy": True}, describe=lambda mf: ["a toy"])


def test_a_registered_kind_is_identified_loaded_and_evaluated(r16):
    data = make_dataset(r16, 1000.0)
    ref = identify("arx", data, nmax=3)
    with pytest.raises(ValueError, match="toy_arx"):
        identify("toy_arx", data)
    with registered_kind(TOY), registered_identify("toy_arx", _arx_as_toy):
        mf = identify("toy_arx", data, nmax=3)
        loaded = ModelFile.from_dict(mf.to_dict(), "toy")  # the schema and loader take it
        assert loaded.kind == "toy_arx"
        np.testing.assert_array_equal(loaded.observer().simulate(data.pulse_g, data.brs_rad),
                                      ref.observer().simulate(data.pulse_g, data.brs_rad))
        assert evaluate_model(loaded, r16, ratings=False).fit == \
            evaluate_model(ref, r16, ratings=False).fit
        with pytest.raises(ModelFileError, match=r"k1|kind|grey-box"):  # no effects on it
            ModelFile.from_dict({**mf.to_dict(),
                                 "effects": [{"kind": "belt_unloading"}]}, "toy")
    with pytest.raises(ModelFileError, match="kind"):
        ModelFile.from_dict(mf.to_dict(), "toy")
    assert "toy_arx" not in MODEL_KINDS


def test_identify_prints_what_its_kind_describes(r16, tmp_path, capsys):
    from observer_node.cli import main

    out = tmp_path / "m.json"
    assert main(["identify", "--model", "arx", "--nmax", "3", "--data",
                 str(bundled_campaign() / "R16_001.zip"), "--out", str(out), "--quiet"]) == 0
    mf = ModelFile.load(out)
    assert all(line in capsys.readouterr().out for line in MODEL_KINDS["arx"].describe(mf))
