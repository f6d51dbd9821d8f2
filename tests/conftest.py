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
