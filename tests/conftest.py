from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from observer_node.data import bundled_campaign, load_tests

DATA = Path(__file__).parent / "data"


@pytest.fixture
def r16_folder(tmp_path: Path) -> Path:
    """A writable copy of the ISO-MME test folder R16_001 (CRLF, ISO-8859-1)."""
    dst = tmp_path / "R16_001"
    shutil.copytree(DATA / "R16_001", dst)
    return dst


@pytest.fixture(scope="session")
def campaign():
    return load_tests([bundled_campaign()])


@pytest.fixture(scope="session")
def model(campaign):
    """The grey-box model the daemon tests run: identified on R16_001, 003 and 005."""
    from observer_node.evaluation import identify
    from observer_node.ident.dataset import make_dataset

    est = [t for t in campaign if t.name in ("R16_001", "R16_003", "R16_005")]
    return identify("greybox", make_dataset(est, 1000.0))


@pytest.fixture(scope="session")
def model_path(model, tmp_path_factory):
    return model.save(tmp_path_factory.mktemp("m") / "model.json")
