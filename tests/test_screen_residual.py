"""The check after the fit, on a drawn campaign of ``benchmarks.screen_residual``."""

from __future__ import annotations

from pathlib import Path

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from benchmarks.screen_residual import SEED, judge
from tests.runners import InProcess


def test_a_rig_with_an_airbag_is_not_taken_for_two_broken_tests(tmp_path: Path) -> None:
    # an airbag on FULL lowers both FULL tests by 15-20 points: by the others' median alone
    # both were named; beside each other they are a rig, not two broken tests
    case = draw_campaign(270, SEED, median_sizes())
    make([case], tmp_path, log=False)
    row = judge(case.name, case.expect_broken, ["airbag@FULL"], tmp_path / case.name,
                InProcess())
    assert row["judged"] and row["setups"]["FULL_002"] == row["setups"]["FULL_004"] == "FULL"
    assert row["others only"] == ["FULL_002", "FULL_004"]
    assert row["shipped"] == []
