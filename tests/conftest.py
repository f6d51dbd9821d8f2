from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from observer_node.data import bundled_campaign, load_tests

if TYPE_CHECKING:
    from observer_node.loop.report import LoopReport

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


R16_LOOP_EST = ("R16_001", "R16_003", "R16_005", "R16_007")


@pytest.fixture(scope="session")
def r16_loop(campaign, tmp_path_factory) -> tuple[Path, LoopReport]:
    """observer-node loop on four odd R16 tests, validated on three even ones, with plots and
    ratings: its folder and report, shared by the loop, export-c and bench tests."""
    from observer_node.bench import STAMP, loop_stamp
    from observer_node.loop.closed_loop import run_loop

    out = tmp_path_factory.mktemp("r16-loop")
    est = [t for t in campaign if t.name in R16_LOOP_EST]
    val = [t for t in campaign if t.name in ("R16_002", "R16_004", "R16_006")]
    r = run_loop(est, val, out, verbose=False)
    (out / STAMP).write_text(json.dumps(loop_stamp(R16_LOOP_EST)))  # as the bench stamps it
    return out, r
