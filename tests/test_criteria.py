"""Injury criteria against closed-form worked examples and an independent computation, and
the ISO/TS 18571 rating's wiring."""

from __future__ import annotations

import json

import numpy as np
import pytest

from observer_node.criteria import (
    chest_criteria,
    clip_3ms_g,
    criteria_table,
    peak_deflection_mm,
    viscous_criterion_m_s,
)

FS = 10_000.0


def test_3ms_clip_of_a_triangle_is_its_level_3_ms_wide():
    # A 50 g triangle 20 ms wide is above a level L for 20 ms * (1 - L / 50): 3 ms at 42.5 g.
    t = np.arange(0, 0.04, 1 / FS)
    a = np.clip(50 * (1 - np.abs(t - 0.02) / 0.01), 0, None)
    assert clip_3ms_g(a, FS) == pytest.approx(42.5, abs=0.05)
    assert clip_3ms_g(a, FS, cumulative=False) == pytest.approx(42.5, abs=0.05)


def test_3ms_clip_cumulative_and_continuous_differ_as_defined():
    # Two 2 ms spikes at 80 g on 10 g: 4 ms above 79 g in all, never 3 ms in a row.
    a = np.full(400, 10.0)
    a[100:120] = 80.0
    a[200:220] = 80.0
    assert clip_3ms_g(a, FS) == 80.0
    assert clip_3ms_g(a, FS, cumulative=False) == 10.0


def test_viscous_criterion_of_a_sine_compression():
    # D = A sin(w t): V D = A^2 w sin(2 w t) / 2, so VC max = SF A^2 w / (2 D0).
    A, w = 0.05, 2 * np.pi * 10
    t = np.arange(0, np.pi / w, 1 / FS)
    d_mm = 1000 * A * np.sin(w * t)
    expected = 1.3 * A**2 * w / (2 * 0.229)
    assert viscous_criterion_m_s(d_mm, FS, filtered=True) == pytest.approx(expected, rel=1e-4)
    # CFC 180 barely touches a 10 Hz compression
    assert viscous_criterion_m_s(d_mm, FS) == pytest.approx(expected, rel=0.01)


def test_viscous_criterion_agrees_with_an_independent_derivative(campaign):
    """On a real measured deflection: the five-point difference against numpy's gradient
    of the same CFC 180 curve."""
    from observer_node.data.filters import cfc_filter

    t = next(t for t in campaign if t.name == "R16_002")
    d = cfc_filter(t.cd_mm / 1000, t.fs_hz, 180)
    vc_independent = float(np.max(1.3 * np.gradient(d, 1 / t.fs_hz) * d / 0.229))
    assert viscous_criterion_m_s(t.cd_mm, t.fs_hz) == pytest.approx(vc_independent, rel=2e-3)
    assert 0.05 < vc_independent < 1.5  # a belted sled test's VC is tenths of m/s


def test_criteria_table_reports_errors_in_units():
    n = 1500
    t = np.arange(n) / 1000.0
    y = np.zeros((1, n, 2))
    y[0, :, 0] = 30 * np.sin(np.pi * t / 0.15).clip(0)
    y[0, :, 1] = 40 * np.sin(np.pi * t / 0.15).clip(0)
    y_hat = y.copy()
    y_hat[0, :, 1] *= 0.9
    table = criteria_table(["T1"], y, y_hat, 1000.0)
    c = table["T1"].as_dict()
    assert c["reference"]["cd_max_mm"] == pytest.approx(peak_deflection_mm(y[0, :, 1]))
    assert c["error"]["cd_max_mm"] == pytest.approx(-4.0, abs=0.01)
    assert c["error"]["cr_3ms_g"] == 0.0
    assert c["estimate"]["vc_max_m_s"] < c["reference"]["vc_max_m_s"]
    assert chest_criteria(y[0, :, 0], y[0, :, 1], 1000.0).as_dict() == c["reference"]


def test_iso18571_rates_identical_curves_one_and_a_shift_lower():
    pytest.importorskip("objective_rating_metrics")
    from observer_node import iso18571

    t = np.arange(0, 0.15, 1e-3)
    y = 30 * np.sin(np.pi * t / 0.15)
    same = iso18571.rate(y, y, 1000.0)
    shifted = iso18571.rate(y, np.interp(t - 0.005, t, y), 1000.0)
    assert same.overall == pytest.approx(1.0)
    assert 0.5 < shifted.overall < 0.99 and shifted.phase < 1.0
    assert iso18571.grade(same.overall) == "excellent"


RATING_KEYS = ["overall", "corridor", "phase", "magnitude", "slope"]


def test_iso18571_ratings_keep_the_json_keys_and_read_back_unchanged():
    """fits.json, evaluation.json, report.json and analysis.json have written the ratings
    with these keys in this order since before they were typed."""
    pytest.importorskip("objective_rating_metrics")
    from observer_node import iso18571
    from observer_node.iso18571 import IsoRatings, OutputRatings

    t = np.arange(0, 0.15, 1e-3)
    y = np.stack([np.column_stack([a * np.sin(np.pi * t / 0.15), 40 * np.sin(np.pi * t / 0.3)])
                  for a in (30.0, 20.0)])  # (tests, n, 2)
    y_hat = np.apply_along_axis(lambda c: np.interp(t - 0.004, t, c), 1, y)  # 4 ms late
    table = iso18571.rating_table(["A", "B"], y, y_hat, 1000.0)
    d = table.as_dict()
    assert list(d) == ["tests", "mean_overall"]
    assert list(d["tests"]) == ["A", "B"] and list(d["tests"]["A"]) == ["cr", "cd"]
    assert list(d["tests"]["A"]["cd"]) == RATING_KEYS
    assert list(d["mean_overall"]) == ["cr", "cd"]
    # each test's output rated as one curve; the mean is of the overall ratings, to 0.001
    assert table.tests["B"].cd == iso18571.rate(y[1, :, 1], y_hat[1, :, 1], 1000.0)
    assert table.mean_overall.cr == round((table.tests["A"].cr.overall
                                           + table.tests["B"].cr.overall) / 2, 3)
    text = json.dumps(d, indent=1)
    assert json.dumps(IsoRatings.from_dict(json.loads(text)).as_dict(), indent=1) == text
    one = json.dumps(table.tests["A"].as_dict(), indent=1)  # as analysis.json has an event's
    assert json.dumps(OutputRatings.from_dict(json.loads(one)).as_dict(), indent=1) == one


def test_vc_is_undefined_where_cfc_180_cannot_filter():
    """At 500 Hz CFC 180's design frequency (374 Hz) is above Nyquist and the filter blows up:
    VC read 1.7e120 m/s and the daemon sent it, saturated, as valid (a hostile user's
    finding, 2026-12-03). Now NaN (the daemon sends it invalid), and the filter refuses."""
    from observer_node.data.filters import cfc_filter, cfc_min_rate_hz

    assert cfc_min_rate_hz(180) == pytest.approx(748, abs=1)
    for fs in (500.0, 1000.0):
        t = np.arange(0, 0.1, 1 / fs)
        d = 40 * np.sin(np.pi * t / 0.1)  # 40 mm over 100 ms
        vc = viscous_criterion_m_s(d, fs)
        expected = 1.3 * 0.04**2 * (np.pi / 0.1) / (2 * 0.229)  # as the sine test above
        assert (np.isnan(vc) if fs < 748 else vc == pytest.approx(expected, rel=0.02)), (fs, vc)
    with pytest.raises(ValueError, match="above 748 Hz"):
        cfc_filter(np.zeros(100), 500.0, 180)
