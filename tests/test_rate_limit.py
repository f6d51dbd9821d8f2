"""An output read through a rate limit (a transducer or amplifier too slow for the chest):
found on the recorded channels, said as unexplained, never on a chest that is only fast."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from observer_node.data.filters import cfc_filter
from observer_node.loop.closed_loop import run_loop
from observer_node.loop.rate_limit import PLATEAU_MS, plateau, rate_limited_outputs
from observer_node.simulator import PlantConfig, simulate_campaign

END_S = 0.15
NOISE = {"cr": (0.3, 180), "cd": (0.05, 600)}  # the simulator's noise and CFC class


def _slewed(x: np.ndarray, fs_hz: float, per_ms: float) -> np.ndarray:
    """``x`` as a follower that moves at most ``per_ms`` [unit/ms] reads it."""
    step, y = per_ms * 1000.0 / fs_hz, np.empty_like(x)
    y[0] = x[0]
    for i in range(1, len(x)):
        y[i] = y[i - 1] + np.clip(x[i] - y[i - 1], -step, step)
    return y


def _limited(tests: list, output: str, per_ms: float, seed: int = 3) -> list:
    """``tests`` with ``output`` read through a rate limit, then the lab's noise and CFC
    filter (the limit sits in the amplifier, before the recorder)."""
    rng, (sd, cfc) = np.random.default_rng(seed), NOISE[output]
    key = "cr_g" if output == "cr" else "cd_mm"
    out = []
    for t in tests:
        x = _slewed(getattr(t, key), t.fs_hz, per_ms) + rng.normal(0, sd, len(t.time_s))
        out.append(dataclasses.replace(t, **{key: cfc_filter(x, t.fs_hz, cfc)}))
    return out


def _mixed(seed: int, n: int = 4) -> list:
    return [t for s in ("R16", "SLED", "FULL") for t in simulate_campaign(s, n, seed=seed)]


@pytest.mark.parametrize("seed", [7, 8])
def test_a_chest_that_is_only_fast_is_not_rate_limited(seed: int) -> None:
    tests = _mixed(seed, 6)
    assert rate_limited_outputs(tests, END_S) == []
    for t in tests:  # the margin the docstring gives: the simulator's plateaus stay short
        for x in (t.cr_g, t.cd_mm):
            assert plateau(x[t.index_of(0.0):t.index_of(END_S) + 1], t.fs_hz)[1] < 0.8 * PLATEAU_MS


def test_the_bundled_campaign_is_not_rate_limited(campaign) -> None:
    assert rate_limited_outputs(campaign, END_S) == []


@pytest.mark.parametrize(("output", "per_ms"), [("cd", 0.7), ("cd", 1.0), ("cd", 1.5)])
def test_an_output_read_through_a_rate_limit_is_found_with_its_rate(output: str,
                                                                    per_ms: float) -> None:
    tests = _limited(_mixed(11), output, per_ms)
    (found,) = rate_limited_outputs(tests, END_S)
    assert found.output == output and abs(found.rate_per_ms / per_ms - 1.0) < 0.05
    assert len(found.tests) >= len(tests) // 2
    assert found.plateau_ms[0] >= PLATEAU_MS
    assert set(found.setups) <= {"R16", "SLED", "FULL"}
    unit = "mm/ms" if output == "cd" else "g/ms"
    assert f"{output.upper()} climbs at a constant {found.rate_per_ms:.2f} {unit}" in (
        found.looks_like())


def test_one_test_s_limit_among_many_is_not_a_transducer_s() -> None:
    tests = _mixed(11)
    tests[2:3] = _limited(tests[2:3], "cd", 1.0)
    assert rate_limited_outputs(tests, END_S) == []


def test_a_channel_that_does_not_move_or_is_cut_short_has_no_plateau() -> None:
    assert plateau(np.zeros(500), 10_000.0) == (0.0, 0.0)
    assert plateau(np.arange(10.0), 10_000.0) == (0.0, 0.0)
    assert plateau(np.array([0.0, np.nan, *range(200)]), 10_000.0) == (0.0, 0.0)
    # a channel whose largest excursion is negative: its rate read in that direction
    t = np.arange(2000) / 10_000.0
    top, ms = plateau(-np.clip(t * 1000.0, 0.0, 50.0), 10_000.0)
    assert top == pytest.approx(1.0) and ms >= 40.0


def test_the_loop_says_a_rate_limited_cd_is_unexplained(tmp_path) -> None:
    cfg = PlantConfig()
    est = _limited(simulate_campaign("R16", 4, seed=31, config=cfg, prefix="EST"), "cd", 1.0)
    val = _limited(simulate_campaign("R16", 3, seed=32, config=cfg, prefix="VAL"), "cd", 1.0, 4)
    r = run_loop(est, val, tmp_path, verbose=False, plots=False, ratings=False)
    limits = [u for u in r.unexplained if u.shape == "rate_limit"]
    assert [(u.output, u.setups) for u in limits] == [("cd", ["ECE-R16"])]
    saved = json.loads((tmp_path / "report.json").read_text())["unexplained"]
    assert any(u["shape"] == "rate_limit" and u["output"] == "cd" for u in saved)
    md = (tmp_path / "report.md").read_text()
    assert "- **CD** on ECE-R16: a rate limit: in 7 of 7 tests CD climbs at a constant" in md
