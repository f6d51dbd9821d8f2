"""The fresh draws of benchmarks/screen_faults.py: a crossed pair is crossed both ways, and a
drawn campaign goes through the files and the loop's checks to a verdict on its broken test."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import SEED, changed, draw_campaign, judge, median_sizes, report

ROOT = Path(__file__).resolve().parents[1]


def test_crossed_spool_files_cross_two_tests_of_two_rigs_both_ways() -> None:
    case = draw_campaign(38, SEED, median_sizes())
    assert case.name.endswith("brs_swap")
    (a, b) = [e for e in case.effects if e.key == "brs_swap"]
    assert a.size == -b.size != 0 and set(case.expect_broken) == {*a.tests, *b.tests}
    assert a.tests[0].split("_")[0] != b.tests[0].split("_")[0]  # of two rigs


def test_a_drawn_campaign_is_judged_from_its_files(tmp_path: Path) -> None:
    case = draw_campaign(19, SEED, median_sizes())  # a pulse clipped at its rails, R16_001
    make([case], tmp_path, log=False)
    row = judge(case, tmp_path / case.name)
    assert row["broken"] == ["R16_001"] == row["found"] == row["on_channel"]
    assert row["clean_named"] == [] and row["clean_tests"] == 11


def test_bad_arguments_get_one_line_and_exit_2() -> None:
    run = subprocess.run([sys.executable, "-m", "benchmarks.screen_faults", "--campaigns",
                          "many"], cwd=ROOT, capture_output=True, text=True, check=False)
    assert run.returncode == 2 and "invalid int value" in run.stderr


def test_raw_counts_under_a_degree_header_are_refused_naming_their_file(tmp_path: Path) -> None:
    case = draw_campaign(8, SEED, median_sizes())  # FULL_001's spindle in counts, "deg"
    make([case], tmp_path, log=False)
    row = judge(case, tmp_path / case.name)
    assert row["form"] == "brs_counts" and row["refused_broken"], row
    assert "FULL_001" in row["refused"] and "whole numbers" in row["refused"]


def test_a_cable_break_and_a_reversed_channel_are_named_on_their_channel(
        tmp_path: Path) -> None:
    cases = [draw_campaign(k, SEED, median_sizes()) for k in (2, 3)]
    make(cases, tmp_path, log=False)
    for case, channel in zip(cases, ("cr", "cd"), strict=True):
        row = judge(case, tmp_path / case.name)
        assert row["found"] == row["on_channel"] == list(case.expect_broken), row
        assert row["clean_named"] == [], row
        assert channel in case.name


def test_a_fault_that_left_its_channel_as_it_was_is_counted_apart(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # two counters of too few bits (seed 100000): R16_003's count passes its half range and
    # wraps, FULL_004's never does, so its file is its twin's and no check could name it
    cases = [draw_campaign(k, 100000, median_sizes()) for k in (62, 71)]
    assert all(c.name.endswith("brs_wrap") for c in cases)
    drawn, sim = make(cases, tmp_path, log=False)
    assert changed(cases[0], drawn, 0, sim) == ["R16_003"] == list(cases[0].expect_broken)
    assert changed(cases[1], drawn, 12, sim) == [] and cases[1].expect_broken == ("FULL_004",)
    rows = []
    for k, c in enumerate(cases):
        rows.append(judge(c, tmp_path / c.name) | {"changed": changed(c, drawn, 12 * k, sim)})
    report(rows)
    line = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("brs_wrap"))
    drawn_n, moved, found, _, seen = (int(x) for x in line.split()[1:6])
    assert (drawn_n, moved) == (2, 1) and seen == found == 1, line
