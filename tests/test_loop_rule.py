"""The loop's rule for naming an effect, its screening for broken tests, its diagnosis of what
is left, and where its refits run (observer_node.loop.evidence, screening, diagnosis, cluster)."""

from __future__ import annotations

import dataclasses
import shutil
import subprocess
import sys

import numpy as np
import pytest
from scipy import signal, stats

from observer_node.data import read_isomme, write_isomme
from observer_node.data.csvio import read_csv, write_csv
from observer_node.data.filters import cfc_filter
from observer_node.data.setups import assign_setups
from observer_node.ident.dataset import make_dataset
from observer_node.ident.metrics import Fits, FitTable, OutputFits
from observer_node.loop import evidence
from observer_node.loop.diagnosis import (
    sensor_shape,
    shape_gains,
    unexplained,
    without_sensor,
)
from observer_node.loop.evidence import MAX_TESTS, Evidence, judge, needed_tests
from observer_node.loop.screening import (
    PAYOUT_GAP_MS,
    _payout_lag_ms,
    _poll_period,
    broken_before_fit,
    copied_channels,
    copied_pulses,
    held_end_outliers,
    judged_fits,
    low_with_rig,
    output_step_outliers,
    payout_outliers,
    polarity_outliers,
    polled_spools,
    pulse_step_outliers,
    residual_outliers,
    reversed_outputs,
    ringing_outliers,
    screen_channels,
    speed_share_outliers,
    spool_gain_outliers,
    velocity_outliers,
)
from tests.runners import InProcess, sigint_default

from .conftest import DATA

SETUPS = {f"T{i}": s for i, s in enumerate(["A", "A", "B", "B", "C", "C"])}


def _cv(gains: list[float], base: float = 90.0) -> tuple[dict, dict]:
    before = {n: base for n in SETUPS}
    return before, {n: base + g for n, g in zip(SETUPS, gains, strict=True)}


def test_a_consistent_gain_is_accepted_with_its_confidence():
    ev = judge(*_cv([1.4, 1.2, 1.6, 1.1, 1.5, 1.3]), SETUPS, None, 1.0)
    assert ev.accepted, ev.reason
    assert ev.ci95_points[0] > 0 and ev.tests_improved == 6
    assert "6/6 tests improved" in ev.confidence


def test_a_gain_carried_by_one_test_is_only_possible():
    # the mean clears the margin, but one test carries it: not above the scatter
    ev = judge(*_cv([9.0, -0.5, 0.2, -0.3, 0.1, -0.2]), SETUPS, None, 1.0)
    assert not ev.accepted and "scatter" in ev.reason
    assert ev.gain_points > 1.0


def _passes_interval(mean: float, sd: float, n: int, reps: int = 200_000) -> float:
    """How often n tests drawn normal(mean, sd) put the 95 % t-interval above zero (by
    simulation, apart from the formula under test)."""
    x = np.random.default_rng(1).normal(mean, sd, (reps, n))
    low = x.mean(1) - stats.t.ppf(0.975, n - 1) * x.std(1, ddof=1) / np.sqrt(n)
    return float(np.mean(low > 0))


@pytest.mark.parametrize("gains", [
    [-3.26, 5.19, 6.73, 9.41, 1.02, 1.06],  # set AA's bilinear ribs as a SLED rib stiffening
    [3.0, -1.0, 2.5, -0.5, 1.5, 2.0]])
def test_an_effect_failing_on_the_scatter_says_how_many_tests_would_pass_it(gains):
    ev = judge(*_cv(gains), SETUPS, None, 1.0)
    n = ev.tests_to_defend
    assert not ev.accepted and n is not None and n > len(gains)
    assert (f"about {n} judged estimation tests in all, 6 now, gaining and scattering as these "
            "did, would put the 95 % interval above zero 4 times in 5, the 1-point bar and the "
            "rule's other checks aside") in ev.reason
    assert "; " not in ev.reason  # the loop joins candidates' reasons with "; "
    mean, sd = float(np.mean(gains)), float(np.std(gains, ddof=1))
    assert _passes_interval(mean, sd, n) > 0.8 > _passes_interval(mean, sd, n - 1)
    # the number round-trips through report.json; a report written before it reads as None
    d = ev.as_dict()
    assert Evidence.from_dict(d).tests_to_defend == n
    assert Evidence.from_dict({k: v for k, v in d.items() if k != "tests_to_defend"}
                              ).tests_to_defend is None


def test_the_number_of_tests_stops_at_its_ceiling_and_says_so(monkeypatch):
    gains = np.array([3.0, -1.0, 2.5, -0.5, 1.5, 2.0])
    n = needed_tests(gains)
    assert n is not None
    monkeypatch.setattr(evidence, "MAX_TESTS", n)
    assert needed_tests(gains) == n
    monkeypatch.setattr(evidence, "MAX_TESTS", n - 1)
    assert needed_tests(gains) is None
    ev = judge(*_cv(list(gains)), SETUPS, None, 1.0)
    assert ev.tests_to_defend is None and f"even {n - 1} judged estimation tests" in ev.reason


def test_only_a_gain_failing_on_the_scatter_gets_a_number_of_tests():
    accepted = judge(*_cv([1.4, 1.2, 1.6, 1.1, 1.5, 1.3]), SETUPS, None, 1.0)
    small = judge(*_cv([0.5, 0.6, 0.4, 0.5, 0.6, 0.5]), SETUPS, None, 1.0)
    lowers = judge(*_cv([3.0, 3.2, 2.9, 3.1, -0.8, -0.6]), SETUPS, None, 1.0)
    assert accepted.tests_to_defend is small.tests_to_defend is lowers.tests_to_defend is None
    # a mean over the margin in a far wider scatter: beyond any campaign, said so
    hopeless = judge(*_cv([40.0, -36.0, 41.0, -37.0, 39.0, -38.4]), SETUPS, None, 1.0)
    assert hopeless.tests_to_defend is None
    assert f"even {MAX_TESTS} judged estimation tests" in hopeless.reason
    # nothing to say: one test, no spread, a mean not above zero, a gain not finite
    # (equal gains of 0.4 summed in floats spread by 7e-17: rounding, not scatter)
    for d in ([3.0], [2.0, 2.0, 2.0], [0.4, 0.4, 0.4], [-1.0, -2.0], [2.0, np.nan, 3.0]):
        assert needed_tests(np.array(d)) is None
    one = {"T0": "A"}
    alone = judge({"T0": 90.0}, {"T0": 95.0}, one, None, 1.0)
    flat = judge({"T0": 90.0, "T1": 90.0}, {"T0": 92.0, "T1": 92.0}, {"T0": "A", "T1": "A"},
                 None, 1.0)
    # a run-away fit's stand-in score (-1000 %) makes a gain of a thousand points: no figure
    before, after = _cv([0.0, 0.2, 0.2, -0.1, 0.2, -0.1], base=85.0)
    run_away = judge({**before, "T0": -1000.0}, {**after, "T0": 88.0}, SETUPS, None, 1.0)
    for ev in (alone, flat, run_away):
        assert not ev.accepted and ev.reason.endswith("not above test-to-test scatter"), ev.reason
        assert ev.tests_to_defend is None


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_a_gain_that_is_not_finite_is_never_accepted(bad):
    ev = judge(*_cv([2.0, bad, 3.0, 1.0, 4.0, 5.0]), SETUPS, None, 1.0)
    assert not ev.accepted and ev.reason == "a test's gain is not finite (a fit that ran away)"


def test_a_gain_that_lowers_one_setup_is_refused():
    ev = judge(*_cv([3.0, 3.2, 2.9, 3.1, -0.8, -0.6]), SETUPS, None, 1.0)
    assert not ev.accepted and "setup C" in ev.reason


def test_only_the_tests_of_judged_setups_are_judged():
    # C held by one estimation test (T5 only, not judged): its loss does not lower "a setup",
    # and its swing does not widen the interval (set M: one test of a rig not judged blocked
    # a rib stiffening that gained on 5 of 5 others)
    gains = [3.0, 3.2, 2.9, 3.1, -9.0]
    tests = {n: s for n, s in list(SETUPS.items())[:5]}
    before = dict.fromkeys(tests, 90.0)
    after = {n: 90.0 + g for n, g in zip(tests, gains, strict=True)}
    assert not judge(before, after, tests, None, 1.0).accepted
    judged = {n: s for n, s in tests.items() if s != "C"}
    ev = judge(before, after, judged, None, 1.0)
    assert ev.accepted and ev.tests == 4 and set(ev.setup_gain_points) == {"A", "B"}


def test_a_small_gain_is_refused():
    ev = judge(*_cv([0.5, 0.6, 0.4, 0.5, 0.6, 0.5]), SETUPS, None, 1.0)
    assert not ev.accepted and "< 1" in ev.reason


def test_the_gain_where_a_scoped_effect_acts_is_reported(campaign):
    ev = judge(*_cv([0.1, 0.0, 3.0, 3.2, 2.8, 3.1]), SETUPS, ["B", "C"], 1.0)
    assert ev.gain_in_scope_points == pytest.approx(3.025)
    assert ev.gain_points == pytest.approx(np.mean([0.1, 0.0, 3.0, 3.2, 2.8, 3.1]))


def test_the_bundled_campaign_has_no_broken_test(campaign):
    assert [b for t in campaign for b in screen_channels(t, 0.15)] == []


def _grouped(campaign):
    """Copies of the campaign's tests, each in its setup."""
    tests = [dataclasses.replace(t) for t in campaign]
    assign_setups(tests)
    return tests


def _broken(test, **arrays):
    return dataclasses.replace(test, **arrays)


@pytest.mark.parametrize("fault", ["frozen_brs", "nan_cd", "spike_cr", "saturated_cd",
                                   "frozen_cd", "zero_shift_pulse", "filtered_spikes_cd",
                                   "mains_hum_cr", "counter_reset_brs", "cable_break_cr",
                                   "wiper_off_cd", "cable_break_noisy_cr"])
def test_a_broken_channel_is_named(campaign, fault):
    t = next(x for x in campaign if x.name == "R16_003")
    i = t.index_of(0.030)
    if fault == "frozen_brs":  # the cable fails 30 ms into the crash
        brs = t.brs.copy()
        brs[i:] = brs[i]
        b = _broken(t, brs=brs)
        channel = "brs"
    elif fault == "nan_cd":
        cd = t.cd_mm.copy()
        cd[i:i + 50] = np.nan
        b, channel = _broken(t, cd_mm=cd), "cd"
    elif fault == "spike_cr":
        cr = t.cr_g.copy()
        cr[i] += 80.0
        b, channel = _broken(t, cr_g=cr), "cr"
    elif fault == "saturated_cd":
        cd = t.cd_mm.copy()
        lim = 0.7 * np.max(cd)  # the amplifier's range ends below the peak compression
        b, channel = _broken(t, cd_mm=np.minimum(cd, lim)), "cd"
    elif fault == "zero_shift_pulse":  # the accelerometer's zero moves by 3 g in the crash
        pulse = t.pulse_g.copy()
        pulse[t.index_of(0.012):] += 3.0
        b, channel = _broken(t, pulse_g=pulse), "pulse"
    elif fault == "filtered_spikes_cd":
        # an intermittent connector: 0.3 ms spikes of 35 mm in the raw channel, which the
        # lab's CFC 600 spreads over a millisecond or more (no longer single samples)
        raw = np.zeros_like(t.cd_mm)
        for k, sign in ((i, 1.0), (t.index_of(0.060), -1.0)):
            raw[k:k + round(3e-4 * t.fs_hz)] = 35.0 * sign
        b, channel = _broken(t, cd_mm=t.cd_mm + cfc_filter(raw, t.fs_hz, 600)), "cd"
    elif fault == "mains_hum_cr":
        # a ground loop: 3 g of 50 Hz on the spine accelerometer from before the crash on,
        # through the lab's CFC 180 (zero-mean: it costs the fit little, but the channel is bad)
        hum = 3.0 * np.sin(2 * np.pi * 50.0 * t.time_s)
        b, channel = _broken(t, cr_g=t.cr_g + cfc_filter(hum, t.fs_hz, 180)), "cr"
    elif fault == "counter_reset_brs":
        # a supply glitch resets the spindle's counter to zero at 70 ms; it counts on from there
        brs = t.brs.copy()
        k = t.index_of(0.070)
        brs[k:] -= brs[k]
        b, channel = _broken(t, brs=brs), "brs"
    elif fault == "cable_break_cr":
        # the spine accelerometer's cable parts at 30 ms: the amplifier reads a constant 0 g,
        # which the lab's CFC 180 turns into a decay, never the same value twice
        cut = np.where(t.time_s >= 0.030, 0.0, t.cr_g)
        b, channel = _broken(t, cr_g=cfc_filter(cut, t.fs_hz, 180)), "cr"
    elif fault == "cable_break_noisy_cr":
        # as above, but the amplifier reads its own noise, as large as the channel's at rest
        cut = cfc_filter(np.where(t.time_s >= 0.030, 0.0, t.cr_g), t.fs_hz, 180)
        rng = np.random.default_rng(3)
        hiss = cfc_filter(rng.standard_normal(t.cr_g.size), t.fs_hz, 180)
        hiss *= np.std(t.cr_g[t.time_s < 0.0]) / np.std(hiss)
        b, channel = _broken(t, cr_g=np.where(t.time_s >= 0.030, cut + hiss, t.cr_g)), "cr"
    elif fault == "wiper_off_cd":  # the pot's wiper off its track for 10 ms, through CFC 600
        off = (t.time_s >= 0.030) & (t.time_s < 0.040)
        b, channel = _broken(t, cd_mm=cfc_filter(np.where(off, 0.0, t.cd_mm), t.fs_hz, 600)), "cd"
    else:
        cd = t.cd_mm.copy()
        cd[i:i + 40] = cd[i]
        b, channel = _broken(t, cd_mm=cd), "cd"
    found = screen_channels(b, 0.15)
    assert [f.channel for f in found] == [channel], found
    assert found[0].test == "R16_003" and found[0].reason


def _lost_block(x, fs_hz, at_s=0.030, ms=6.0, cfc=180):
    """A recorder that lost ``ms`` of samples at ``at_s``: the rest arrives early, the record's
    end padded with its last sample, all through the lab's CFC filter."""
    i, n = round(at_s * fs_hz), round(ms * fs_hz / 1000)
    return cfc_filter(np.concatenate([x[:i], x[i + n:], np.full(n, x[-1])]), fs_hz, cfc)


@pytest.mark.parametrize("fault", ["lost_block_cr", "lost_block_cd", "late_cable_break_cr"])
def test_a_record_held_over_its_end_is_named(campaign, fault):
    t = next(x for x in campaign if x.name == "R16_003")
    if fault == "lost_block_cr":
        b = _broken(t, cr_g=_lost_block(t.cr_g, t.fs_hz))
    elif fault == "lost_block_cd":
        b = _broken(t, cd_mm=_lost_block(t.cd_mm, t.fs_hz, cfc=600))
    else:  # a cable break at 100 ms, after the pulse fell under a fifth of its peak
        assert np.max(np.abs(t.pulse_g[t.index_of(0.1):])) < 0.2 * np.max(np.abs(t.pulse_g))
        b = _broken(t, cr_g=cfc_filter(np.where(t.time_s >= 0.100, 0.0, t.cr_g), t.fs_hz, 180))
    found = broken_before_fit([b if x.name == "R16_003" else x for x in campaign], 0.15)
    assert [(f.test, f.channel, "held" in f.reason or "one value" in f.reason)
            for f in found] == [("R16_003", fault.split("_")[-1], True)], found


def test_what_the_held_end_leaves_alone(campaign):
    t = next(x for x in campaign if x.name == "R16_003")
    # a record whose end keeps the lab's noise is not held, however still the dummy is there
    rng = np.random.default_rng(5)
    hiss = cfc_filter(rng.standard_normal(t.cr_g.size), t.fs_hz, 180)
    hiss *= np.std(t.cr_g[t.time_s < 0.0]) / np.std(hiss)
    calm = np.where(t.time_s > 0.15, np.median(t.cr_g[t.time_s < 0.0]) + hiss, t.cr_g)
    assert broken_before_fit([_broken(t, cr_g=calm) if x is t else x for x in campaign],
                             0.15) == []
    # a lab that holds every record's end after the test (from 180 ms) is the lab's way
    held = [_broken(x, cr_g=np.where(x.time_s > 0.18, x.cr_g[x.index_of(0.18)], x.cr_g))
            for x in campaign]
    assert held_end_outliers(held, 0.15) == []
    # and so is one rig's recorder holding every one of its records' ends
    rigs = _grouped(campaign)
    sled = [_broken(x, cr_g=np.where(x.time_s > 0.18, x.cr_g[x.index_of(0.18)], x.cr_g))
            if x.setup == "SLED" else x for x in rigs]
    assert held_end_outliers(sled, 0.15) == []
    # a record cut short (nothing before contact) is not judged: no noise to compare with
    short = b = _broken(t, cr_g=_lost_block(t.cr_g, t.fs_hz))
    assert held_end_outliers([dataclasses.replace(
        short, t0_s=0.0, pulse_g=short.pulse_g[short.index_of(0.0):],
        brs=short.brs[short.index_of(0.0):], cr_g=short.cr_g[short.index_of(0.0):],
        cd_mm=short.cd_mm[short.index_of(0.0):])], 0.15) == []
    others = [x for x in campaign if x is not t]
    assert [f.test for f in held_end_outliers([b, *others], 0.15)] == ["R16_003"]


def test_a_record_that_ends_before_the_crash_is_named_not_a_traceback(campaign):
    t = next(x for x in campaign if x.name == "R16_003")
    k = t.index_of(0.0)
    early = dataclasses.replace(t, pulse_g=t.pulse_g[:k], brs=t.brs[:k], cr_g=t.cr_g[:k],
                                cd_mm=t.cd_mm[:k])
    assert [b.channel for b in screen_channels(early, 0.15)] == ["pulse"]


def _spool_read_at(test, gain):
    """The test with its BRS counting ``gain`` times the turns from its rest before contact."""
    rest = np.median(test.brs[test.time_s < 0.0])
    return _broken(test, brs=np.round(rest + gain * (test.brs - rest)))


@pytest.mark.parametrize("gain", [4, 2, 0.25])
def test_a_brs_read_at_another_gain_than_its_rigs_is_named(campaign, gain):
    # a decoder counting every edge of both tracks (x4) or both edges of one (x2) under the
    # header's counts/rev, or the other way round: the pull and the pay-out both read so
    def scaled(x):
        return _spool_read_at(x, gain)
    tests = _grouped(campaign)
    found = spool_gain_outliers([scaled(x) if x.name == "R16_003" else x for x in tests], 0.15)
    assert [(f.test, f.channel) for f in found] == [("R16_003", "brs")], found
    # a rig whose every spool reads so is its own (and a gain the loop may fit), not a test;
    # nor can the data tell which half of a rig is right when half reads so
    assert spool_gain_outliers([scaled(x) if x.setup == "R16" else x for x in tests], 0.15) == []
    half = {x.name for x in tests if x.setup == "R16"}
    half = set(sorted(half)[:6])
    assert spool_gain_outliers([scaled(x) if x.name in half else x for x in tests], 0.15) == []
    assert spool_gain_outliers(tests, 0.15) == []


def test_a_brs_reading_within_a_capstans_scatter_is_not_named(campaign):
    # a D-ring capstan's clean test read 1.5 times its rig's pull (held-out set P): not a decoder
    tests = _grouped(campaign)
    assert spool_gain_outliers([_spool_read_at(x, 1.5) if x.name == "R16_003" else x
                                for x in tests], 0.15) == []


def _loose_mount(a_g, fs_hz, f_hz=150.0, zeta=0.05):
    """What an accelerometer riding on a loosened mount (a spring and little damping, base
    feed-through) reads of its base's acceleration."""
    w = 2 * fs_hz * np.tan(np.pi * f_hz / fs_hz)
    b, a = signal.bilinear([2 * zeta * w, w * w], [1.0, 2 * zeta * w, w * w], fs=fs_hz)
    return signal.lfilter(b, a, a_g)


def test_a_cr_ringing_as_no_other_test_does_is_named(campaign):
    loose = [_broken(t, cr_g=_loose_mount(t.cr_g, t.fs_hz)) if t.name == "SLED_003" else t
             for t in campaign]
    found = broken_before_fit(loose, 0.15)
    assert [(f.test, f.channel) for f in found] == [("SLED_003", "cr")], found
    # two loose mounts (one dummy's, two tests running) do not hide each other
    two = [_broken(t, cr_g=_loose_mount(t.cr_g, t.fs_hz, 120.0)) if t.name == "R16_007" else t
           for t in loose]
    assert sorted(f.test for f in ringing_outliers(two, 0.15)) == ["R16_007", "SLED_003"]
    assert abs(float(found[0].reason.split(" Hz")[0].split()[-1]) - 150.0) < 5.0  # "rings at"
    # every test's CR ringing alike is the rig's (or the dummy's), not one broken test
    assert ringing_outliers([_broken(t, cr_g=_loose_mount(t.cr_g, t.fs_hz))
                             for t in campaign], 0.15) == []
    # nor is a test judged among fewer than five others
    few = sorted(loose, key=lambda x: x.name != "SLED_003")[:5]
    assert ringing_outliers(few, 0.15) == []


def test_a_channel_the_lab_marked_defect_is_named_in_its_words(tmp_path):
    # ISO-MME "Data status": the lab's own verdict on a channel, read from the file
    src = tmp_path / "R16_001"
    shutil.copytree(DATA / "R16_001", src)
    ch = src / "Channel" / "R16_001.004"  # CD
    ch.write_bytes(ch.read_bytes().replace(b"Data status                 :ok",
                                           b"Data status                 :defect"))
    found = screen_channels(read_isomme(src), 0.15)
    assert [(f.channel, f.reason) for f in found] == [
        ("cd", "the lab marked it 'defect' (its Data status)")], found
    assert screen_channels(read_isomme(DATA / "R16_001"), 0.15) == []
    for word in (b"OK.", b"o.k.", b"valid", b"Good"):  # the lab's other words for ok
        okay = src.parent / f"ok_{word.decode()}" / "R16_001"
        shutil.copytree(src, okay)
        p = okay / "Channel" / "R16_001.004"
        p.write_bytes(p.read_bytes().replace(b":defect", b":" + word))
        assert read_isomme(okay).status == {}, word
    # written out again (crash-replay's recordings, an export), the lab's word stays
    assert read_isomme(write_isomme(read_isomme(src), tmp_path / "again")).status == {
        "cd": "defect"}
    assert read_csv(write_csv(read_isomme(src), tmp_path / "again.csv")).status == {
        "cd": "defect"}


def test_a_brs_recorded_at_the_wrong_polarity_is_named(campaign):
    # the count direction set wrong: the pretensioner's pay-in reads as pay-out and the load
    # limiter's pay-out as pay-in, in one test of the campaign
    assert polarity_outliers(campaign, 0.15) == []
    t = next(x for x in campaign if x.name == "SLED_002")
    flipped = [_broken(x, brs=2 * x.brs[0] - x.brs) if x is t else x for x in campaign]
    found = polarity_outliers(flipped, 0.15)
    assert [(f.test, f.channel) for f in found] == [("SLED_002", "brs")], found
    assert "pay" in found[0].reason


@pytest.mark.parametrize("channel", ["cr_g", "cd_mm"])
def test_a_chest_channel_recorded_at_the_wrong_polarity_is_named(campaign, channel):
    assert reversed_outputs(campaign, 0.15) == []
    t = next(x for x in campaign if x.name == "FULL_004")
    flipped = [_broken(x, **{channel: -getattr(x, channel)}) if x is t else x for x in campaign]
    found = reversed_outputs(flipped, 0.15)
    assert [(f.test, f.channel) for f in found] == [("FULL_004", channel[:2])], found
    assert "wrong polarity" in found[0].reason
    # against its own pulse, whatever the other tests read: alone, and beside two others
    # reversed alike
    assert [(f.test, f.channel) for f in reversed_outputs([flipped[campaign.index(t)]], 0.15)
            ] == [("FULL_004", channel[:2])]
    four = [x for x in campaign if x.name in ("FULL_004", "R16_001", "R16_002", "SLED_001")]
    two = [_broken(x, **{channel: -getattr(x, channel)}) if x.name in ("R16_001", "FULL_004")
           else x for x in four]
    assert {f.test for f in reversed_outputs(two, 0.15)} == {"R16_001", "FULL_004"}


def test_a_test_all_the_other_way_names_its_channels_and_a_reversed_pulse_the_pulse(campaign):
    def flip(x, *chs):
        return _broken(x, **{c: -getattr(x, c) for c in chs})
    # one test's every channel the other way (its pulse, CR, CD agree with each other)
    whole = [flip(x, "pulse_g", "cr_g", "cd_mm") if x.name == "SLED_004" else x
             for x in campaign]
    assert sorted(f.channel for f in reversed_outputs(whole, 0.15)) == ["cd", "cr", "pulse"]
    # a whole campaign the other way is a convention, not a broken test; in it, one CR that
    # reads the model's way is named, and nothing else (its loading read either way)
    other = [flip(x, "pulse_g", "cr_g", "cd_mm") for x in campaign]
    assert reversed_outputs(other, 0.15) == []
    one = [flip(x, "cr_g") if x.name == "FULL_001" else x for x in other]
    assert [(f.test, f.channel) for f in broken_before_fit(one, 0.15)] == [("FULL_001", "cr")]
    # the pulse alone reversed: both dummy channels read against it, the pulse is named
    pulse = [flip(x, "pulse_g") if x.name == "SLED_004" else x for x in campaign]
    assert [(f.test, f.channel) for f in reversed_outputs(pulse, 0.15)] == [("SLED_004",
                                                                             "pulse")]
    # ... unless the other tests' pulses read as it does: then CR and CD are the odd ones
    chest = [flip(x, "cr_g", "cd_mm") if x.name == "SLED_004" else x for x in campaign]
    assert sorted(f.channel for f in reversed_outputs(chest, 0.15)) == ["cd", "cr"]


def test_a_clean_campaign_recorded_at_1_khz_is_not_named(campaign):
    # one sample at a channel's extreme is 1 ms at 1 kHz: a peak, not a flat top; and a CR
    # peak is a few samples wide, which no running median follows: not a spike
    k = 10
    slow = [dataclasses.replace(t, fs_hz=t.fs_hz / k, pulse_g=t.pulse_g[::k], brs=t.brs[::k],
                                cr_g=t.cr_g[::k], cd_mm=t.cd_mm[::k]) for t in campaign]
    assert broken_before_fit(slow, 0.15) == []


def test_a_quiet_pre_trigger_names_no_channel_quieter_than_at_rest(campaign):
    # a lab that zeroes its pre-trigger samples gives no noise to compare the crash with
    t = next(x for x in campaign if x.name == "R16_003")
    still = np.where(t.time_s < 0.0, 0.0, t.cr_g)
    assert screen_channels(_broken(t, cr_g=still), 0.15) == []


def _reads(n, every, phase=0.0):
    """The samples of a record of ``n`` at which a clock reading every ``every`` samples (a
    fraction where it does not divide the record's rate), first at ``phase``, reads."""
    at = np.unique(np.ceil(np.arange(phase, n, every) - 1e-9).astype(int))
    return at[at < n]


def _held(read, at, n):
    """A record of ``n`` samples holding ``read[j]`` from sample ``at[j]`` to the next read
    (the first read before ``at[0]``)."""
    return read[np.clip(np.searchsorted(at, np.arange(n), side="right") - 1, 0, None)]


def _polled(counts, every):
    """``counts`` as a quadrature decoder reads them polling its two tracks every ``every``
    samples (a fraction where its clock does not divide the record's rate): it sees only the
    tracks' phase (the count mod 4), so a move of one count reads as one, of three as one
    back, of two as none; held between polls."""
    c = np.asarray(counts, dtype=float)
    at = _reads(len(c), every)
    phase = np.diff(c[at]) % 4
    step = np.select([phase == 1, phase == 3], [1.0, -1.0], 0.0)
    return _held(np.concatenate([[c[0]], c[0] + np.cumsum(step)]), at, len(c))


@pytest.mark.parametrize("every, words", [(5, "multiples of 5 samples"),
                                          (10, "multiples of 10 samples"),
                                          (20, "multiples of 20 samples"),
                                          # 1024 Hz in a 10 kHz record: no divisor above 1
                                          (10000 / 1024, "one poll every 9.77 samples (1024 Hz"),
                                          (10000 / 800, "one poll every 12.50 samples (800 Hz")])
def test_a_spool_whose_decoder_polls_too_slowly_is_named(campaign, every, words):
    tests = _grouped(campaign)
    assert polled_spools(tests, 0.15) == []
    bad = [_broken(x, brs=_polled(x.brs, every)) if x.name == "R16_003" else x for x in tests]
    found = broken_before_fit(bad, 0.15)
    assert [(f.test, f.channel) for f in found] == [("R16_003", "brs")], found
    assert words in found[0].reason, found[0].reason
    # a counter read as coarsely (its steps of several counts kept) loses nothing: not named
    held = [_broken(x, brs=np.asarray(x.brs)[np.floor(np.floor(np.arange(len(x.brs)) / every)
                                                      * every).astype(int)])
            if x.name == "R16_003" else x for x in tests]
    assert broken_before_fit(held, 0.15) == []
    # every spool of the campaign polled so: no test's spool says how fast one turns
    assert polled_spools([_broken(x, brs=_polled(x.brs, every)) for x in tests], 0.15) == []


@pytest.mark.parametrize("hz", [1024.0, 1005.0])
def test_spools_read_without_loss_at_a_clock_that_does_not_divide_are_not_named(campaign, hz):
    # every spool read at this clock and held, no count lost; R16_003's turns at most one
    # count a read, its rig-mates' up to two. Over 10 samples a mate's reading may hold two
    # reads' moves (4 counts); inside one read (9 samples) it holds one (a hostile review's
    # whole campaigns: 32 clean tests named at 1024 Hz when measured over 10)
    def spool(x, peak):  # counts, at most ``peak`` a sample, over the first 100 ms
        u = np.clip(x.time_s / 0.1, 0.0, 1.0)
        return np.floor(np.cumsum(peak * np.sin(np.pi * u) ** 2) + 0.5)

    def held(x, b, phase):
        at = _reads(len(b), x.fs_hz / hz, phase)
        return _held(b[at], at, len(b))
    tests = _grouped(campaign)
    for phase in (3.3, 6.1):
        read = [_broken(x, brs=held(x, spool(x, 0.1 if x.name == "R16_003" else 0.2), phase))
                for x in tests]
        assert polled_spools(read, 0.15) == []


def test_a_rig_mate_whose_counter_wraps_does_not_vouch_for_a_fast_spool(campaign):
    # FULL_002's counter read at 5 kHz and held, nothing lost; of its two rig-mates, FULL_003's
    # counter wraps mid-crash (a jump of 128 counts): their median fastest turn would be 64
    tests = [t for t in _grouped(campaign) if t.setup != "FULL" or t.name in
             ("FULL_001", "FULL_002", "FULL_003")]
    def fixed(x):
        b = np.asarray(x.brs, dtype=float)
        if x.name == "FULL_002":
            return _broken(x, brs=np.repeat(b[::2], 2)[:len(b)])
        if x.name == "FULL_003":
            return _broken(x, brs=b - 128.0 * (x.time_s >= 0.03))
        return x
    read = [fixed(x) for x in tests]
    assert [f.test for f in polled_spools(read, 0.15)] == []


def test_a_spindle_read_at_the_records_rate_fits_no_poll_grid(campaign):
    # any samples lie within one sample of a grid of 2.0 (two residues, a sample apart): a
    # period that whole is the divisor's to judge (R16_004's grid read 2.0 in the first form)
    assert [(x.name, _poll_period(x, 0.15)[0]) for x in campaign
            if _poll_period(x, 0.15)[0] != 1.0] == []


def test_a_long_polled_record_is_read_on_its_crash(campaign):
    # a million samples: the grid is read on the crash's changes, not on the whole record's
    tests = _grouped(campaign)
    x = next(t for t in tests if t.name == "R16_003")
    n = 1_000_000
    def longer(a):
        return np.concatenate([a, np.full(n - len(a), a[-1])])
    brs = longer(_polled(x.brs, 10000 / 1024))
    brs[len(x.brs):] += np.floor(np.arange(n - len(x.brs)) / 10.3)  # and turning on and on
    long = _broken(x, pulse_g=longer(x.pulse_g), brs=brs, cr_g=longer(x.cr_g),
                   cd_mm=longer(x.cd_mm))
    found = polled_spools([long if t is x else t for t in tests], 0.15)
    assert [f.test for f in found] == ["R16_003"], found


def test_a_pulse_copied_from_another_rigs_test_is_named(campaign):
    # SLED_002's folder holds FULL_003's carriage file: one crash's pulse on two rigs, and
    # the sled's is the one out of its rig's scatter
    tests = _grouped(campaign)
    assert copied_pulses(tests, 0.15) == []
    source = next(t for t in tests if t.name == "FULL_003")
    bad = [_broken(x, pulse_g=source.pulse_g.copy()) if x.name == "SLED_002" else x
           for x in tests]
    found = broken_before_fit(bad, 0.15)
    assert [(f.test, f.channel) for f in found] == [("SLED_002", "pulse")], found
    assert "FULL_003's" in found[0].reason and "the copy" in found[0].reason
    # two seats of one crash filed as two tests of one rig share its accelerometer: not named
    twin = next(t for t in tests if t.name == "SLED_003")
    same = [_broken(x, pulse_g=twin.pulse_g.copy()) if x.name == "SLED_002" else x
            for x in tests]
    assert copied_pulses(same, 0.15) == []
    # one sled's runs repeat within their noise: a sled's tests filed under two setups (belt
    # A and belt B on one sled program) are not copies, nor a copy with noise of its own
    split = [dataclasses.replace(x, setup=f"{x.setup}-B") if i % 2 else x
             for i, x in enumerate(tests)]
    assert copied_pulses(split, 0.15) == []
    noise = np.random.default_rng(5).standard_normal(len(source.pulse_g)) * 0.8
    noisy = [_broken(x, pulse_g=source.pulse_g + noise) if x.name == "SLED_002" else x
             for x in tests]
    assert copied_pulses(noisy, 0.15) == []


def test_crossed_brs_files_are_found_by_the_pay_out_against_the_pulse(campaign):
    # the lab's export crossed two tests' spindle files: the R16 test's BRS is a full-scale
    # car's spool, which pays out 20 ms later after the same free flight than any R16 spool;
    # the car's test has one spool that fits the R16 test's pulse as the R16 tests' do
    tests = _grouped(campaign)
    assert payout_outliers(tests, 0.15) == []
    r16 = next(t for t in tests if t.name == "R16_002")
    full = next(t for t in tests if t.name == "FULL_002")
    crossed = [_broken(t, brs=full.brs) if t is r16 else _broken(t, brs=r16.brs) if t is full
               else t for t in tests]
    found = payout_outliers(crossed, 0.15)
    assert [(f.test, f.channel) for f in found] == [("R16_002", "brs"), ("FULL_002", "brs")]
    assert "R16 tests" in found[0].reason and "crossed" in found[1].reason


def test_three_close_tests_do_not_make_a_fourth_clean_one_out_of_step(campaign):
    # R16_006's spool reaches half its pay-out 10.4 ms after the car's free flight, the other
    # R16 tests 15.8-26.3 ms: beside three of them that happen to lie within 2.6 ms it is
    # 9.2 ms from the nearest, which the gap alone took for two crashes (session 37: 538 of
    # 3000 campaigns drawn from the bundled tests named a clean test so); three tests say
    # too little of the rig's scatter for that
    picked = {"R16_002", "R16_004", "R16_012", "R16_006"}
    tests = [t for t in _grouped(campaign) if t.name in picked]
    lags = {t.name: _payout_lag_ms(t, 0.15) for t in tests}
    others = [v for n, v in lags.items() if n != "R16_006"]
    assert min(abs(v - lags["R16_006"]) for v in others) > PAYOUT_GAP_MS > np.ptp(others)
    assert payout_outliers(tests, 0.15) == []


def test_a_pulse_two_tests_share_is_not_a_copy(campaign):
    # a crash's driver and passenger filed as two tests share the car's one accelerometer
    src = next(t for t in campaign if t.name == "FULL_001")
    tests = [_broken(t, pulse_g=src.pulse_g.copy()) if t.name == "FULL_003" else t
             for t in _grouped(campaign)]
    assert copied_channels(tests, 0.15) == []


def test_a_spool_far_out_of_step_is_named_whatever_few_tests_say(campaign):
    # four R16 tests alone: the interval of three others is too wide to judge (Student's t on
    # 2 degrees of freedom), but a BRS 30 ms late lies further from them than any clean
    # test of a rig we hold lies from its nearest (a helper's attack, session 37)
    picked = ("R16_002", "R16_004", "R16_012", "R16_008")
    tests = [_broken(t, brs=_late(t.brs, 30, t.fs_hz)) if t.name == "R16_002" else t
             for t in _grouped(campaign) if t.name in picked]
    assert [f.test for f in payout_outliers(tests, 0.15)] == ["R16_002"]


def test_a_crossed_partner_alone_on_its_rig_is_named(campaign):
    # R16_002's and FULL_002's spool files crossed, FULL_002 the only FULL test: its side of
    # the crossing cannot be seen, and it is named as before (a helper's attack, session 37)
    tests = [t for t in _grouped(campaign) if t.setup != "FULL" or t.name == "FULL_002"]
    r16 = next(t for t in tests if t.name == "R16_002")
    full = next(t for t in tests if t.name == "FULL_002")
    crossed = [_broken(t, brs=full.brs) if t is r16 else _broken(t, brs=r16.brs) if t is full
               else t for t in tests]
    assert [f.test for f in payout_outliers(crossed, 0.15)] == ["R16_002", "FULL_002"]


@pytest.mark.parametrize("channel", ["brs", "cr_g", "cd_mm"])
def test_a_channel_copied_from_another_test_names_both(campaign, channel):
    # the lab copied R16_003's file of one channel into SLED_001's folder: which of the two
    # is the copy the samples cannot tell
    src = next(t for t in campaign if t.name == "R16_003")
    tests = [_broken(t, **{channel: getattr(src, channel).copy()}) if t.name == "SLED_001"
             else t for t in _grouped(campaign)]
    assert copied_channels(_grouped(campaign), 0.15) == []
    found = copied_channels(tests, 0.15)
    assert sorted(f.test for f in found) == ["R16_003", "SLED_001"], found
    assert all("same samples as" in f.reason for f in found)
    assert {b.test for b in broken_before_fit(tests, 0.15)} >= {"R16_003", "SLED_001"}
    # copied into a third folder too: each test named once
    thrice = [_broken(t, **{channel: getattr(src, channel).copy()}) if t.name == "FULL_001"
              else t for t in tests]
    found = copied_channels(thrice, 0.15)
    assert sorted(f.test for f in found) == ["FULL_001", "R16_003", "SLED_001"], found


def _late(x, ms, fs_hz):
    k = round(ms * fs_hz / 1000.0)
    return np.concatenate([np.full(k, x[0]), x[:-k]])


@pytest.mark.parametrize("channel", ["cr_g", "cd_mm"])
def test_a_chest_channel_recorded_late_is_named(campaign, channel):
    # one channel's time base shifted by 5 ms (a trigger or export offset on that channel):
    # CR and CD of that test are out of step as no other test of its rig is
    tests = _grouped(campaign)
    assert output_step_outliers(tests, 0.15) == []
    t = next(x for x in tests if x.name == "FULL_002")
    late = [_broken(x, **{channel: _late(getattr(x, channel), 5.0, x.fs_hz)}) if x is t else x
            for x in tests]
    found = output_step_outliers(late, 0.15)
    assert [(f.test, f.channel) for f in found] == [("FULL_002", channel[:2])], found
    assert "out of step" in found[0].reason and "FULL tests" in found[0].reason


def test_a_whole_test_recorded_late_is_not_called_out_of_step(campaign):
    # a late trigger moves every channel of the test alike: CR and CD stay in step
    tests = _grouped(campaign)
    t = next(x for x in tests if x.name == "FULL_002")
    late = [_broken(x, **{ch: _late(getattr(x, ch), 5.0, x.fs_hz)
                          for ch in ("pulse_g", "brs", "cr_g", "cd_mm")}) if x is t else x
            for x in tests]
    assert output_step_outliers(late, 0.15) == []


def test_a_pulse_out_of_step_with_all_three_channels_is_named_on_the_pulse(campaign):
    # SLED_003's pulse 10 ms late on its time base (another test's pulse, or its recorder's
    # own trigger), beside two other SLED tests: its CR, CD and spool all read early from it
    tests = _grouped(campaign)
    t = next(x for x in tests if x.name == "SLED_003")
    b = _broken(t, pulse_g=_late(t.pulse_g, 10.0, t.fs_hz))
    mates = [x for x in tests if x.setup == "SLED" and x is not t][:2]
    rest = [x for x in tests if x.setup != "SLED"]
    assert pulse_step_outliers([t, *mates, *rest], 0.15) == []
    found = pulse_step_outliers([b, *mates, *rest], 0.15)
    assert [(f.test, f.channel) for f in found] == [("SLED_003", "pulse")], found
    assert "2 other SLED tests" in found[0].reason and "CR, CD and spool" in found[0].reason
    # one other SLED test is too few to tell
    assert pulse_step_outliers([b, mates[0], *rest], 0.15) == []


def test_what_the_pulse_step_leaves_alone(campaign):
    tests = _grouped(campaign)
    assert pulse_step_outliers(tests, 0.15) == []
    t = next(x for x in tests if x.name == "SLED_003")
    mates = [x for x in tests if x.setup == "SLED" and x is not t][:2]
    # a whole test late (every channel alike), or its CR alone (output_step's): not the pulse
    whole = _broken(t, **{ch: _late(getattr(t, ch), 10.0, t.fs_hz)
                          for ch in ("pulse_g", "brs", "cr_g", "cd_mm")})
    cr = _broken(t, cr_g=_late(t.cr_g, 10.0, t.fs_hz))
    for b in (whole, cr):
        assert pulse_step_outliers([b, *mates], 0.15) == []


def _read_fast(x, fs_true_hz, fs_hz):
    """``x`` as a recorder at ``fs_true_hz`` wrote it, read at the ``fs_hz`` its header says."""
    t_true = np.arange(len(x)) / fs_true_hz
    return np.interp(t_true, np.arange(len(x)) / fs_hz, x)


@pytest.mark.parametrize("fault", ["rate", "gain"])
def test_a_pulse_at_odds_with_the_stated_velocity_is_named(campaign, fault):
    # recorded at 8 kHz under headers that say 10 kHz (every channel: the crash reads 1.25
    # times too fast, the pulse integrates to 0.8 of the speed), or a pulse sensitivity 1.3x
    tests = _grouped(campaign)
    assert velocity_outliers(tests, 0.15) == []
    t = next(x for x in tests if x.name == "SLED_003")
    if fault == "rate":
        b = _broken(t, **{ch: _read_fast(getattr(t, ch), 8000.0, t.fs_hz)
                          for ch in ("pulse_g", "brs", "cr_g", "cd_mm")})
    else:
        b = _broken(t, pulse_g=1.3 * t.pulse_g)
    found = velocity_outliers([b if x is t else x for x in tests], 0.15)
    assert [(f.test, f.channel) for f in found] == [("SLED_003", "pulse")], found
    assert ("x0.80" if fault == "rate" else "x1.31") in found[0].reason
    assert "SLED tests" in found[0].reason


def test_two_pulses_broken_alike_do_not_vouch_for_each_other(campaign):
    # two R16 tests recorded at 8 kHz under 10 kHz headers: each is judged against the median
    # of the others, not the nearest other
    tests = _grouped(campaign)
    bad = {"R16_001", "R16_002"}
    fast = [_broken(x, pulse_g=_read_fast(x.pulse_g, 8000.0, x.fs_hz)) if x.name in bad else x
            for x in tests]
    assert {f.test for f in velocity_outliers(fast, 0.15)} == bad


def test_what_the_velocity_check_leaves_alone(campaign):
    tests = _grouped(campaign)
    r16 = [t for t in tests if t.setup == "R16"]
    # half a rig's tests stating km/h: no majority to judge by, nothing named
    kmh = [_broken(t, velocity_ms=3.6 * t.velocity_ms) if t in r16[:6] else t for t in tests]
    assert velocity_outliers(kmh, 0.15) == []
    # a second of record after the crash with 0.3 g of offset at rest: the crash's integral
    # ends with the crash
    t = r16[0]
    rest_s = np.full(round(t.fs_hz), np.median(t.pulse_g[:t.index_of(0.0)]) + 0.3)
    longer = _broken(t, pulse_g=np.concatenate([t.pulse_g, rest_s]),
                     brs=np.concatenate([t.brs, np.full(len(rest_s), t.brs[-1])]),
                     cr_g=np.concatenate([t.cr_g, np.zeros(len(rest_s))]),
                     cd_mm=np.concatenate([t.cd_mm, np.zeros(len(rest_s))]))
    assert velocity_outliers([longer if x is t else x for x in tests], 0.15) == []
    # a record that ends at 70 ms is not judged here (the fit refuses it, saying why)
    k = t.index_of(0.070)
    short = _broken(t, pulse_g=t.pulse_g[:k], brs=t.brs[:k], cr_g=t.cr_g[:k], cd_mm=t.cd_mm[:k])
    assert velocity_outliers([short if x is t else x for x in tests], 0.15) == []


def test_a_pulse_gain_on_a_whole_rig_or_no_stated_velocity_is_no_broken_test(campaign):
    # every FULL pulse 8 % high is the rig's input_gain, for the loop to find, not a broken
    # test; a test that states no velocity is not judged
    tests = _grouped(campaign)
    gained = [_broken(x, pulse_g=1.08 * x.pulse_g) if x.setup == "FULL" else x for x in tests]
    assert velocity_outliers(gained, 0.15) == []
    t = next(x for x in tests if x.name == "SLED_003")
    silent = [_broken(x, pulse_g=1.3 * x.pulse_g, velocity_ms=None) if x is t else x
              for x in tests]
    assert velocity_outliers(silent, 0.15) == []


def _cut(x, fs_hz, at_s, t0_s):
    """``x`` reading 0 from ``at_s`` on (an open input), its noise gone with it."""
    y = np.array(x, dtype=float)
    y[round((at_s - t0_s) * fs_hz):] = 0.0
    return y


@pytest.mark.parametrize("fault", ["ms2", "ms2_no_velocity", "cable", "cr_gain"])
def test_a_dummy_that_does_not_change_speed_as_its_car_is_named(campaign, fault):
    # a pulse exported in m/s^2 under its g header (with or without a stated velocity to
    # referee), a pulse cable parted at 42 ms, or a CR at 0.6 of its sensitivity: the spine's
    # change of speed is no longer the car's, on one test of the campaign
    tests = _grouped(campaign)
    assert speed_share_outliers(tests, 0.15) == []
    t = next(x for x in tests if x.name == "SLED_003")
    b = {"ms2": lambda: _broken(t, pulse_g=9.80665 * t.pulse_g),
         "ms2_no_velocity": lambda: _broken(t, pulse_g=9.80665 * t.pulse_g, velocity_ms=None),
         "cable": lambda: _broken(t, pulse_g=_cut(t.pulse_g, t.fs_hz, 0.042, t.t0_s)),
         "cr_gain": lambda: _broken(t, cr_g=0.6 * t.cr_g)}[fault]()
    # another test's pulse not numbers after the window: not a referee, not a traceback
    other = next(x for x in tests if x.name == "SLED_004")
    tail = np.where(other.time_s > 0.18, np.nan, other.pulse_g)
    tests = [_broken(x, pulse_g=tail) if x is other else x for x in tests]
    found = speed_share_outliers([b if x is t else x for x in tests], 0.15)
    channel = "cr" if fault == "cr_gain" else "pulse"
    assert [(f.test, f.channel) for f in found] == [("SLED_003", channel)], found
    assert "moving with its car" in found[0].reason


@pytest.mark.parametrize("fault", ["two_pulses_ms2", "two_crs_per_ms2", "rig_pulses_ms2",
                                   "most_pulses_ms2"])
def test_tests_of_one_rig_broken_alike_are_named_by_the_speed_they_lose(campaign, fault):
    # two SLED pulses exported in m/s^2 with no stated velocity, two SLED CRs in m/s^2's
    # reciprocal (the stated velocity says the pulse is right), every SLED pulse in m/s^2, and
    # every R16 pulse (12 of the 24 tests): a dummy changing speed by a tenth or ten times its
    # car's is no rig's way, so rig-mates reading alike no longer vouch for each other (a
    # helper's attack, session 40), and a rig holding half the campaign names no other rig's
    # test (session 41's first form, read against the other rigs' tests, named them all)
    tests = _grouped(campaign)
    g = 9.80665
    sled = {x.name for x in tests if x.setup == "SLED"}
    names, channel = {"two_pulses_ms2": ({"SLED_003", "SLED_004"}, "pulse"),
                      "two_crs_per_ms2": ({"SLED_003", "SLED_004"}, "cr"),
                      "rig_pulses_ms2": (sled, "pulse"),
                      "most_pulses_ms2": ({x.name for x in tests if x.setup == "R16"},
                                          "pulse")}[fault]
    broken = {"two_pulses_ms2": lambda x: _broken(x, pulse_g=g * x.pulse_g, velocity_ms=None),
              "two_crs_per_ms2": lambda x: _broken(x, cr_g=x.cr_g / g),
              "rig_pulses_ms2": lambda x: _broken(x, pulse_g=g * x.pulse_g),
              "most_pulses_ms2": lambda x: _broken(x, pulse_g=g * x.pulse_g)}[fault]
    found = speed_share_outliers([broken(x) if x.name in names else x for x in tests], 0.15)
    assert sorted((f.test, f.channel) for f in found) == sorted((n, channel) for n in names)
    assert all("no rig's way" in f.reason for f in found)
    # a whole rig's pulses 2.2 times (its dummies at 0.53 of the car's speed): not absurd
    assert speed_share_outliers([_broken(x, pulse_g=2.2 * x.pulse_g) if x.setup == "FULL"
                                 else x for x in tests], 0.15) == []


def test_a_cr_read_ten_times_is_named_on_cr_where_every_velocity_is_in_km_h(campaign):
    # every test states its velocity as a bare km/h number: the pulse of SLED_003 integrates
    # to 1/3.6 of it, as every other test's does, so CR is the one read in another unit (a
    # helper's attack on the first form, which read the pulse against the stated speed alone)
    tests = [_broken(x, velocity_ms=3.6 * x.velocity_ms) for x in _grouped(campaign)]
    bad = [_broken(x, cr_g=9.80665 * x.cr_g) if x.name == "SLED_003" else x for x in tests]
    found = speed_share_outliers(bad, 0.15)
    assert [(f.test, f.channel) for f in found] == [("SLED_003", "cr")]


def _leaking(x, fs_hz, tau_s):
    """``x`` read through a charge amplifier whose charge leaks away in ``tau_s``: a
    first-order high-pass (an AC-coupled or piezoelectric accelerometer), from the record's
    first sample."""
    b, a = signal.bilinear([tau_s, 0.0], [tau_s, 1.0], fs=fs_hz)
    return signal.lfilter(b, a, x)


@pytest.mark.parametrize("which", ["one", "every"])
def test_a_cr_whose_charge_leaks_away_is_named_so_not_as_a_sensitivity(campaign, which):
    # a CR whose charge leaks away in 0.1 s loses over half its area, as a CR at 0.35 of its
    # sensitivity does; but after the crash it reads back against it, which no sensitivity
    # does (a helper found every leaking CR of a campaign named as a wrong sensitivity).
    # Every CR of the campaign at 0.08 s: at 0.1 s the SLED tests keep 0.49-0.51 of their
    # pulse's area, inside the factor of two a campaign broken alike is judged at, unnamed
    tests = _grouped(campaign)
    names = {"SLED_003"} if which == "one" else {x.name for x in tests}
    tau_s = 0.1 if which == "one" else 0.08
    leak = speed_share_outliers([_broken(x, cr_g=_leaking(x.cr_g, x.fs_hz, tau_s))
                                 if x.name in names else x for x in tests], 0.15)
    assert sorted((f.test, f.channel) for f in leak) == sorted((n, "cr") for n in names)
    # said outright where the tail reads beyond every clean test's; the bundled R16 tests'
    # tails (+0.08 to +0.34 clean) fall to -0.18 to -0.24 only, so there both are said
    firm = [f.test for f in leak if "charge leaks away (an AC-coupled" in f.reason]
    assert all("charge leaks away" in f.reason for f in leak), leak
    assert "SLED_003" in firm and len(firm) >= 2 * len(leak) / 3, leak
    # records that end at the window hold the rebound in their tail: the leak is not judged
    cut = [_broken(x, cr_g=_leaking(x.cr_g, x.fs_hz, tau_s)) if x.name in names else x
           for x in tests]
    cut = [_broken(x, pulse_g=x.pulse_g[:(n := x.index_of(0.15) + 1)], brs=x.brs[:n],
                   cr_g=x.cr_g[:n], cd_mm=x.cd_mm[:n]) for x in cut]
    assert not any("AC-coupled" in f.reason for f in speed_share_outliers(cut, 0.15))
    gain = speed_share_outliers([_broken(x, cr_g=0.35 * x.cr_g) if x.name in names else x
                                 for x in tests], 0.15)
    assert sorted((f.test, f.channel) for f in gain) == sorted((n, "cr") for n in names)
    assert not any("AC-coupled" in f.reason for f in gain), gain


def test_what_the_speed_share_leaves_alone(campaign):
    tests = _grouped(campaign)
    sled = next(x for x in tests if x.name == "SLED_003")
    # a pulse 10 % high on one test (under the gap; the velocity check's), and a whole rig's
    # pulses 1.6 times (a gain, for the loop's input_gain): nothing named
    assert speed_share_outliers([_broken(x, pulse_g=1.1 * x.pulse_g) if x is sled else x
                                 for x in tests], 0.15) == []
    assert speed_share_outliers([_broken(x, pulse_g=1.6 * x.pulse_g) if x.setup == "FULL"
                                 else x for x in tests], 0.15) == []
    # two tests of one rig read apart alike: a rig's way, which of them the data cannot tell
    two = {"SLED_003", "SLED_004"}
    assert speed_share_outliers([_broken(x, pulse_g=2 * x.pulse_g) if x.name in two else x
                                 for x in tests], 0.15) == []
    # a rig whose areas all lie low (its pulses 1.15 times: a physical effect or a gain), one
    # of its tests past the gap from the campaign's median but near its rig's others
    full = [x.name for x in tests if x.setup == "FULL"]
    low = [_broken(x, pulse_g=(1.3 if x.name == full[0] else 1.15) * x.pulse_g)
           if x.name in full else x for x in tests]
    assert speed_share_outliers(low, 0.15) == []
    # the only test of its rig, 1.3 times off the others (a physical effect on the other
    # rigs may move their areas so): named only at a factor of two
    lone = [x for x in tests if x.setup != "FULL" or x.name == full[0]]
    one = [_broken(x, pulse_g=1.3 * x.pulse_g) if x.name == full[0] else x for x in lone]
    assert speed_share_outliers(one, 0.15) == []
    far = [_broken(x, pulse_g=9.8 * x.pulse_g) if x.name == full[0] else x for x in lone]
    assert [f.test for f in speed_share_outliers(far, 0.15)] == [full[0]]
    # a record that ends at 70 ms is not judged, nor a test among four others
    k = sled.index_of(0.070)
    short = _broken(sled, pulse_g=9.8 * sled.pulse_g[:k], brs=sled.brs[:k], cr_g=sled.cr_g[:k],
                    cd_mm=sled.cd_mm[:k])
    assert speed_share_outliers([short if x is sled else x for x in tests], 0.15) == []
    few = [_broken(sled, pulse_g=9.8 * sled.pulse_g), *[x for x in tests if x is not sled][:4]]
    assert speed_share_outliers(few, 0.15) == []
    assert [f.test for f in speed_share_outliers([*few, *tests[-1:]], 0.15)] == ["SLED_003"]


def test_a_campaign_that_pays_in_more_than_out_is_not_called_reversed(campaign):
    # a polarity is judged against the other tests: when every test's spindle pays in most
    # (a strong pretensioner, a light load) none of them stands out
    flipped = [_broken(x, brs=2 * x.brs[0] - x.brs) for x in campaign]
    assert polarity_outliers(flipped, 0.15) == []


def test_a_pulse_recorded_from_before_contact_is_not_called_zero_shifted(campaign):
    # a late trigger: the recorded pulse starts 5 ms before the t = 0 the lab wrote, so the
    # pre-contact window holds the crash's onset; its zero is still right
    t = next(x for x in campaign if x.name == "FULL_002")
    k = round(0.005 * t.fs_hz)
    early = np.concatenate([t.pulse_g[k:], np.full(k, t.pulse_g[-1])])
    assert screen_channels(_broken(t, pulse_g=early), 0.15) == []


def test_a_pulse_still_decelerating_at_rest_needs_a_record_after_the_crash(campaign):
    # without samples well after the scoring window there is no rest to judge the zero by
    t = next(x for x in campaign if x.name == "R16_003")
    pulse = t.pulse_g.copy()
    pulse[t.index_of(0.012):] += 3.0
    end = t.index_of(0.16)
    short = _broken(t, pulse_g=pulse[:end], brs=t.brs[:end], cr_g=t.cr_g[:end],
                    cd_mm=t.cd_mm[:end])
    assert [f.channel for f in screen_channels(short, 0.15)] == []


def test_a_test_far_below_the_others_is_an_outlier():
    fits = {"A": 91.0, "B": 88.5, "C": 93.0, "D": 90.2, "E": 52.0, "F": 89.0}
    assert [b.test for b in residual_outliers(fits)] == ["E"]
    assert residual_outliers({**fits, "E": 84.0}) == []


def test_a_test_low_with_its_rig_is_not_an_outlier():
    # set AE's dual-stage airbag on FULL: FULL_001 fell 20.2 points under the others' median,
    # but its FULL mate fell too (an effect of the rig the grey-box lacks); set Z's swapped
    # spool, SLED_005, lay as far below its SLED mates as below everyone
    ae = {"FULL_001": 68.9, "FULL_003": 84.2, "R16_001": 89.8, "R16_003": 89.1,
          "R16_005": 90.8, "R16_007": 87.5}
    ae_rigs = {n: n.split("_")[0] for n in ae}
    assert [b.test for b in residual_outliers(ae)] == ["FULL_001"]
    assert residual_outliers(ae, (), ae_rigs) == []
    z = {"R16_001": 90.6, "R16_003": 83.3, "SLED_001": 90.8, "SLED_003": 88.5,
         "SLED_005": 65.6, "SLED_007": 83.6}
    (b,) = residual_outliers(z, (), {n: n.split("_")[0] for n in z})
    assert b.test == "SLED_005" and "its setup's other tests' 88.5 %" in b.reason


def test_a_broken_test_shelters_no_other_of_its_rig():
    # F1 and F2 broken, F3 clean on one rig: F2's mates' median (F1 50, F3 88) is 69, 7 over
    # it; once F1 is flagged it is no one's mate, and F2 lies 26 below F3. A rig whose two
    # tests are low alike keeps both, said as low with their rig (a hostile review's cases)
    fits = {"R1": 88.0, "R2": 89.0, "R3": 87.0, "R4": 90.0, "F1": 50.0, "F2": 62.0, "F3": 88.0}
    rigs = {n: n[0] for n in fits}
    assert [b.test for b in residual_outliers(fits, (), rigs)] == ["F1", "F2"]
    assert low_with_rig(fits, rigs) == []
    alike = {**fits, "F2": 55.0}
    del alike["F3"]
    assert residual_outliers(alike, (), rigs) == []
    assert [b.test for b in low_with_rig(alike, rigs)] == ["F1", "F2"]


def test_the_only_test_of_its_setup_is_judged_in_sample():
    # left out, the only R16 test is predicted by a model that never saw the R16 rig (set J:
    # 65.8 % against 87.7): judged by the fit made with it; a test whose rig the others share
    # is still judged left out
    setups = {"R1": "R16", "S1": "SLED", "S2": "SLED", "F1": "FULL", "F2": "FULL", "F3": "FULL"}
    left_out = {"R1": 65.8, "S1": 88.0, "S2": 87.5, "F1": 87.7, "F2": 86.9, "F3": 88.4}
    fitted = {**{n: f + 1.0 for n, f in left_out.items()}, "R1": 80.2}
    fits, lone = judged_fits(left_out, fitted, setups)
    assert lone == {"R1"} and fits["R1"] == 80.2 and fits["S1"] == 88.0
    # a broken R16 test is still caught in-sample, and says how it was judged
    (b,) = residual_outliers(*judged_fits({**left_out, "R1": 20.0}, {**fitted, "R1": 30.0},
                                          setups))
    assert b.test == "R1" and "in-sample (the only test of its setup)" in b.reason
    assert residual_outliers(fits, lone) == [] != residual_outliers(left_out)


def test_a_transducer_non_linearity_is_a_static_function_of_one_output(campaign):
    """CD over-reading at large deflection (CR untouched) shows as a static function of CD,
    and not of CR; the unmodified data show no such structure against themselves."""
    data = make_dataset([t for t in campaign if t.name.startswith("R16")][:4], 1000.0)
    y_hat = data.y.copy()  # a perfect model of the true chest...
    bent = dataclasses.replace(data, y=data.y.copy())
    cd = bent.y[..., 1]
    bent.y[..., 1] = cd + 0.02 * cd ** 2  # ...and a transducer over-reading 40 % at 20 mm
    gains = shape_gains(bent, y_hat)
    assert np.mean(gains["cd"]["static"]) > 5.0
    assert np.mean(gains["cr"]["static"]) < 0.5
    u = unexplained(bent, y_hat)
    assert [x.output for x in u] == ["cd"] and u[0].shape == "static"
    assert unexplained(data, y_hat) == []
    # taken out of the measurement, the over-reading leaves what a right transducer reads
    right = without_sensor(bent, y_hat, "cd")
    assert np.allclose(right.y, data.y, atol=1e-6 * np.max(np.abs(data.y)))
    assert sensor_shape(bent, y_hat, "cd") == "static"


def _sagging(cd_mm: np.ndarray, fs_hz: float, sag: float = 0.3) -> np.ndarray:
    """CD read through a pot whose excitation sags from contact on, as a recorder's battery
    does once it starts writing: the gain falls by ``sag`` with a 60 ms time constant."""
    t_s = np.arange(cd_mm.shape[1]) / fs_hz
    return cd_mm * (1.0 - sag * (1.0 - np.exp(-t_s / 0.06)))


def test_a_transducer_gain_sagging_in_time_is_a_drift_of_one_output(campaign):
    """CD's gain sagging in time (CR untouched) is no static function of CD: it looks like a
    drift in time of CD, and taking the fuller correction (static and drift) out of the
    measurement leaves nearly what a right transducer reads."""
    data = make_dataset([t for t in campaign if t.name.startswith("R16")][:4], 1000.0)
    y_hat = data.y.copy()  # a perfect model of the true chest
    sagged = dataclasses.replace(data, y=data.y.copy())
    sagged.y[..., 1] = _sagging(data.y[..., 1], data.fs_hz)
    assert sensor_shape(sagged, y_hat, "cd") == "drift"
    u = unexplained(sagged, y_hat)  # and, where nothing is named, said so in its own words
    assert [(x.output, x.shape) for x in u] == [("cd", "drift")]
    assert u[0].looks_like.startswith("a drift in time on CD")
    err = np.abs(sagged.y[:, data.win, 1] - data.y[:, data.win, 1]).max()
    left = np.abs(without_sensor(sagged, y_hat, "cd", "sensor").y[:, data.win, 1]
                  - data.y[:, data.win, 1]).max()
    assert left < 0.2 * err


@pytest.fixture(scope="module")
def chest(campaign):
    """Four R16 tests, the grey-box fitted on them, and what it reads: as it stands, with a
    rib damping it lacks (in both outputs), and through a CD transducer over-reading 40 % at
    20 mm (CD alone)."""
    from observer_node.ident.greybox import fit_greybox
    from observer_node.loop.refit import model

    data = make_dataset([t for t in campaign if t.name.startswith("R16")][:4], 1000.0)
    base = dict(fit_greybox(data).params)
    damping = {"kind": "chest_rate_damping", "parameters": {"c3": 4000.0}}
    with np.errstate(all="ignore"):
        damped = model(base, [damping], data).simulate(data.pulse_g, data.brs_rad)
        bent = model(base, [], data).simulate(data.pulse_g, data.brs_rad)
    bent[..., 1] += 0.02 * bent[..., 1] ** 2
    return data, base, damped, bent


def _one_passing(kind: str, parameters: dict) -> list:
    from observer_node.loop.analysis import Candidate
    return [(90.0, Candidate(kind, 0.3, parameters),
             judge({"T": 90.0}, {"T": 92.0}, {"T": "R16"}, None, 1.0))]


def test_a_physical_effect_in_both_outputs_is_not_one_transducers_error(chest):
    """The strongest physical candidate is judged by the rule on the other output's fit alone
    before a transducer of one output is named: a rib damping the model lacks moves CR as
    well as CD, so it passes there; a CD transducer's over-reading leaves CR nothing to gain."""
    from observer_node.loop.refit import folds
    from observer_node.loop.rounds import _other_output

    data, base, damped, bent = chest
    tried = _one_passing("chest_rate_damping", {"c3": 1000.0})
    setups = dict(zip(data.names, data.setups, strict=True))

    def other(y: np.ndarray) -> object:
        return _other_output(InProcess(), base, [], dataclasses.replace(data, y=y),
                             folds(data), tried, "cd", setups, 1.0)

    found = other(damped)
    assert found is not None and found[0] is tried[0][1] and found[1].gain_points >= 1.0
    assert other(bent) is None


def test_cross_validation_counts_a_stalled_fold_as_the_caller_says(chest, monkeypatch):
    """``held_out_fits`` leaves a stalled fold's tests NaN; ``cross_validate`` gives them
    ``instead``'s fit (a candidate's: the model's without it) or the model's own on all
    tests; ``stalled_in`` names them for the evidence."""
    from observer_node.loop import refit, rounds
    from observer_node.loop.refit import folds, score, stalled_in

    data, base, _, _ = chest
    real = refit.fold_scores
    monkeypatch.setattr(rounds, "fold_scores",
                        lambda b, e, d, tr, te: real(b, e, d, tr, te, max_nfev=1))
    [(start, raw)] = rounds.held_out_fits(InProcess(), [(base, [])], data, folds(data))
    assert stalled_in(raw) == list(data.names)
    instead = dict.fromkeys(data.names, 12.5)
    assert rounds.cross_validate(InProcess(), [(base, [])], data, folds(data),
                                 instead=instead) == [instead]
    own = {n: v.total for n, v in score(*start, data).tests.items()}
    assert rounds.cross_validate(InProcess(), [(base, [])], data, folds(data)) == [own]


def test_the_other_outputs_check_counts_a_stalled_fold_as_no_gain(chest, monkeypatch):
    """The one-output check refits too: where the candidate's fold took no step, its
    held-out test would score in-sample. Such folds count the model's own fit (no gain), as
    ``cross_validate`` counts them: the rib damping that passes on CR above, its every fold
    stalled here, gains nothing."""
    from observer_node.loop import refit, rounds
    from observer_node.loop.refit import folds

    data, base, damped, _ = chest
    tried = _one_passing("chest_rate_damping", {"c3": 1000.0})
    setups = dict(zip(data.names, data.setups, strict=True))
    real = refit.fold_scores_by_output
    stalls = real(base, [], data, [0, 1, 2], [3], max_nfev=1)  # one evaluation: no step
    assert all(np.isnan(v) for o in ("cr", "cd") for v in stalls[o].values())
    monkeypatch.setattr(rounds, "fold_scores_by_output",
                        lambda b, e, d, tr, te: real(b, e, d, tr, te, max_nfev=1 if e else 15))
    assert rounds._other_output(InProcess(), base, [], dataclasses.replace(data, y=damped),
                                folds(data), tried, "cd", setups, 1.0) is None


def test_a_transducers_correction_gains_nothing_on_a_fold_that_stalled(chest, monkeypatch):
    """The sensor family's folds refit the model before fitting their correction: a fold
    that took no step would judge the correction beside a model fitted on its held-out test
    too. A CD transducer's over-reading passes the rule when the folds move; with every fold
    stalled, its tests count the model's cross-validated fit (no gain) and it does not."""
    from observer_node.loop import diagnosis, rounds
    from observer_node.loop.refit import FOLD_NFEV, folds

    data, base, _, bent = chest
    data = dataclasses.replace(data, y=bent)
    setups = dict(zip(data.names, data.setups, strict=True))
    cv_now = rounds.cross_validate(InProcess(), [(base, [])], data, folds(data))[0]

    def sensor(nfev: int) -> object:
        real = diagnosis.sensor_fold_scores
        monkeypatch.setattr(rounds, "sensor_fold_scores",
                            lambda b, e, d, tr, te: real(b, e, d, tr, te, max_nfev=nfev))
        return rounds._sensor_candidates(InProcess(), base, [], data, folds(data), cv_now,
                                         setups, 1.0)["cd"]

    moving, stalled = sensor(FOLD_NFEV), sensor(1)  # one evaluation: no step
    assert moving.accepted and moving.gain_points >= 1.0
    assert not stalled.accepted and stalled.gain_points == 0.0
    # and the evidence says so, in report.json and in its one line for report.md
    assert moving.stalled_tests == () and "no step" not in moving.confidence
    assert stalled.stalled_tests == tuple(data.names)
    assert f"{len(data.names)} tests whose fold's refit took no step" in stalled.confidence
    assert Evidence.from_dict(stalled.as_dict()).stalled_tests == stalled.stalled_tests


def test_a_sagging_cd_is_blamed_on_cd_by_its_fuller_correction(chest):
    """A CD pot whose gain sags in time: each output's fuller correction (static and drift)
    is judged beside its static one, and CD's, which takes the sag itself, passes and gains
    more than CR's."""
    from observer_node.loop import rounds
    from observer_node.loop.diagnosis import FULLER
    from observer_node.loop.refit import folds, model

    data, base, _, _ = chest
    with np.errstate(all="ignore"):
        y = model(base, [], data).simulate(data.pulse_g, data.brs_rad)
    y[..., 1] = _sagging(y[..., 1], data.fs_hz)
    data = dataclasses.replace(data, y=y)
    setups = dict(zip(data.names, data.setups, strict=True))
    cv_now = rounds.cross_validate(InProcess(), [(base, [])], data, folds(data))[0]
    ev = rounds._sensor_candidates(InProcess(), base, [], data, folds(data), cv_now, setups,
                                   1.0)
    assert set(ev) == {"cr", "cd", "cr" + FULLER, "cd" + FULLER}
    cd, cr = ev["cd" + FULLER], ev["cr" + FULLER]
    assert cd.accepted and cd.gain_points > cr.gain_points + 0.5
    assert cd.gain_points > ev["cd"].gain_points  # the drift takes what the static cannot


def _on_six_full_tests(gains: list[float]) -> Evidence:
    """A correction's evidence under the rule from its fit gains [points] on six FULL tests."""
    names = [f"FULL_{i:03d}" for i in (1, 3, 5, 7, 9, 11)]
    return judge(dict.fromkeys(names, 85.0),
                 {n: 85.0 + g for n, g in zip(names, gains, strict=True)},
                 dict.fromkeys(names, "FULL"), None, 1.0)


def test_the_output_blamed_is_told_by_the_fuller_corrections_test_by_test():
    """The static correction says whether a transducer is at fault, the fuller ones which.
    The other output is blamed only when its fuller correction passes the rule and beats the
    blamed output's test by test above the scatter; passing without beating it, the data
    cannot tell which (set AG's CD sag: CR's static correction passed, +1.04 points; CD's
    fuller correction gained +1.66 against CR's +1.15, better on 4 of 6 tests)."""
    from observer_node.loop.diagnosis import FULLER
    from observer_node.loop.rounds import _which_transducer

    ev = _on_six_full_tests
    cr_full = ev([1.35, -0.06, 1.22, 1.43, 1.40, 1.57])
    cd_full = ev([1.52, 3.21, 1.23, 1.55, 1.24, 1.21])
    assert cd_full.accepted and cr_full.accepted
    sensor = {"cr": ev([1.0] * 6), "cd": ev([0.2] * 6), "cr" + FULLER: cr_full,
              "cd" + FULLER: cd_full}
    blamed, words = _which_transducer("cr", sensor)
    assert blamed == ["cr", "cd"]
    assert "+1.66 points against cr's +1.15, better on 4 of 6 tests" in words
    # CD's fuller correction better on every test, by more than the scatter: CD alone
    clear = ev([2.3, 2.6, 2.4, 2.7, 2.5, 2.8])
    blamed, words = _which_transducer("cr", {**sensor, "cd" + FULLER: clear})
    assert blamed == ["cd"] and "better on 6 of 6 tests" in words
    # CD's does not pass the rule: CR as its static correction found
    weak = ev([0.6, 0.4, 0.7, 0.5, 0.6, 0.5])
    assert not weak.accepted
    assert _which_transducer("cr", {**sensor, "cd" + FULLER: weak}) == (["cr"], "")


def _transducer_evidence() -> tuple[dict[str, Evidence], dict[str, Evidence]]:
    """Sensor evidence where CR's static correction passes (+1.05 points) and CD's fuller
    correction is told apart from CR's above the scatter, and the fuller ones of both outputs
    (``close``: CD's passing without beating CR's; ``weak``: CD's not passing)."""
    from observer_node.loop.diagnosis import FULLER

    ev = _on_six_full_tests
    sensor = {"cr": ev([1.0, 1.1, 0.9, 1.2, 1.0, 1.1]), "cd": ev([0.2] * 6),
              "cr" + FULLER: ev([1.35, -0.06, 1.22, 1.43, 1.40, 1.57]),
              "cd" + FULLER: ev([2.3, 2.6, 2.4, 2.7, 2.5, 2.8])}
    others = {"close": ev([1.52, 3.21, 1.23, 1.55, 1.24, 1.21]),
              "weak": ev([0.6, 0.4, 0.7, 0.5, 0.6, 0.5]),
              "physics": ev([1.2, 1.0, 1.3, 0.9, 1.4, 1.0])}
    return sensor, others


def _both_sagging(chest):
    """The chest fixture's tests as its grey-box reads them, CD through a sagging pot (30 %)
    and CR through a slightly sagging amplifier (10 %): in-sample, each output's residual
    looks like a drift in time."""
    from observer_node.loop.refit import model
    from observer_node.loop.rounds import State

    data, base, _, _ = chest
    with np.errstate(all="ignore"):
        y = model(base, [], data).simulate(data.pulse_g, data.brs_rad)
    y[..., 1] = _sagging(y[..., 1], data.fs_hz)
    y[..., 0] = _sagging(y[..., 0], data.fs_hz, sag=0.1)
    return dataclasses.replace(data, y=y), State(base, {}, [], {}, FitTable(Fits.of(0, 0), {}))


def test_what_is_left_unexplained_names_the_transducer_the_fuller_corrections_blame(chest):
    """Where a physical effect cannot be told from one output's static correction, what is
    left unexplained names the transducer the fuller corrections blame, as where a transducer
    wins the round (set V's slow CR clock was left 'unexplained: CD'): the other output,
    described by its fuller correction; both, each saying so, when they cannot tell; else the
    static one's."""
    from observer_node.loop.diagnosis import FULLER
    from observer_node.loop.rounds import untold_transducer

    data, st = _both_sagging(chest)
    sensor, other = _transducer_evidence()
    left = untold_transducer(data, st, "cr", ["cd"], sensor)
    assert [(u.output, u.shape) for u in left] == [("cd", "drift")]
    u = left[0]
    assert u.gain_points == {"FULL": round(2 * sensor["cd" + FULLER].gain_points, 2)}
    assert u.other_output_gain_points == round(2 * sensor["cr" + FULLER].gain_points, 2)
    assert "drift in time on CD" in u.looks_like and "together, whose gains" in u.looks_like
    left = untold_transducer(data, st, "cr", ["cr", "cd"],
                             {**sensor, "cd" + FULLER: other["close"]})
    assert [(u.output, u.shape) for u in left] == [("cr", "static"), ("cd", "drift")]
    assert all("which of CR and CD, the data cannot tell" in u.looks_like for u in left)
    left = untold_transducer(data, st, "cr", ["cr"], sensor)
    assert [(u.output, u.shape) for u in left] == [("cr", "static")]
    assert left[0].gain_points == {"FULL": round(2 * sensor["cr"].gain_points, 2)}
    assert left[0].other_output_gain_points == round(2 * sensor["cd"].gain_points, 2)


def test_a_transducer_found_by_its_static_correction_reads_static_beside_the_other(chest):
    """Where a transducer beats physics and both outputs are named, the one its static
    correction found reads as a static function of it, though its residual looks like a
    drift in time in-sample (here CR's does); the other as its fuller correction's shape."""
    from observer_node.loop.diagnosis import FULLER, sensor_shape
    from observer_node.loop.refit import model
    from observer_node.loop.rounds import blamed_transducers

    data, st = _both_sagging(chest)
    with np.errstate(all="ignore"):
        y_hat = model(st.base, [], data).simulate(data.pulse_g, data.brs_rad)
    assert sensor_shape(data, y_hat, "cr") == "drift"  # what the old words would have said
    sensor, other = _transducer_evidence()
    close = other["close"]
    sensors = blamed_transducers(data, st, "cr", ["cr", "cd"], {**sensor, "cd" + FULLER: close})
    assert [x.output for x in sensors] == ["cr", "cd"]
    assert sensors[0].looks_like.startswith("a static function of CR")
    assert sensors[0].evidence is sensor["cr"]
    assert sensors[1].looks_like.startswith("a drift in time on CD")
    assert sensors[1].evidence is close


def test_a_round_physics_cannot_win_from_a_transducer_asks_which_transducer(chest):
    """The round itself: a physical effect passes, gains more than CR's static correction on
    the mean but does not beat it test by test, and CD's fuller correction beats CR's: nothing
    named, CD left unexplained, the decision and the possible effect saying CD's."""
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.diagnosis import FULLER
    from observer_node.loop.report import LoopStep
    from observer_node.loop.rounds import Context, _a_transducer_speaks

    data, st = _both_sagging(chest)
    sensor, other = _transducer_evidence()
    pelvis = Candidate("pelvis_coupling", 0.3, {"kp": 1e-6, "cp": 500.0})
    phys = other["physics"]
    assert phys.accepted and phys.gain_points > sensor["cr"].gain_points
    c = Context(None, data, None, None, {}, set(), [], {}, 1.0, 1, 1000.0, None)  # type: ignore[arg-type]
    step = LoopStep([], 85.0, [], [], sensor)
    assert _a_transducer_speaks(c, st, step, [], [(86.2, pelvis, phys)], sensor)
    assert [u.output for u in st.left_unexplained] == ["cd"]
    assert "if a transducer, cd's rather than cr's" in step.decision
    assert step.decision.endswith("above the scatter; nothing named")
    assert [p.why_not for p in st.possible] == [
        "the data cannot tell it from a sensor correction of cd (its transducer's error), "
        "which passes the rule too"]
    # CD's fuller correction passing without beating CR's: both, said once in the decision
    st2 = dataclasses.replace(st, left_unexplained=[], possible=[])
    step2 = LoopStep([], 85.0, [], [], sensor)
    both = {**sensor, "cd" + FULLER: other["close"]}
    assert _a_transducer_speaks(c, st2, step2, [], [(86.2, pelvis, phys)], both)
    assert [u.output for u in st2.left_unexplained] == ["cr", "cd"]
    assert "if a transducer, cr's or cd's, the data cannot tell" in step2.decision
    assert "sensor correction of cr or cd" in st2.possible[0].why_not


def test_a_physical_effect_no_better_than_a_transducer_is_not_named():
    """A physical effect that wins a round where one output's static correction passes the
    rule too is named only if it beats that correction test by test above the scatter (set F:
    a rib stiffening +2.71 points against a CD correction's +2.69, better on 3 of 5 tests)."""
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.verdicts import untold_from_sensor

    stiff = Candidate("chest_stiffening", 0.3, {"k3": 1e8})
    sensor = judge(*_cv([2.6, 2.1, 3.0, 2.4, 2.9, 2.5]), SETUPS, None, 1.0)
    close = judge(*_cv([2.9, 1.8, 3.3, 2.2, 2.7, 2.8]), SETUPS, None, 1.0)
    why = untold_from_sensor(stiff, close, "cd", sensor)
    assert sensor.accepted and close.accepted and why is not None
    assert "sensor correction of cd" in why and "better on 3 of 6 tests" in why
    clear = judge(*_cv([4.1, 3.5, 4.6, 3.9, 4.0, 4.4]), SETUPS, None, 1.0)
    assert untold_from_sensor(stiff, clear, "cd", sensor) is None


def test_an_unreachable_scheduler_is_one_line_and_exit_2(tmp_path):
    p = subprocess.run([sys.executable, "-m", "observer_node", "loop", "--estimate",
                        "campaign-a/R16_00[13]", "--validate", "campaign-a/R16_002", "--out",
                        str(tmp_path), "--scheduler", "tcp://127.0.0.1:9", "--quiet"],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 2, p.stderr
    assert "Traceback" not in p.stderr and len(p.stderr.strip().splitlines()) == 1
    assert "tcp://127.0.0.1:9" in p.stderr


def test_a_server_that_never_answers_is_given_up_on(tmp_path):
    """A port that accepts and says nothing (a web server, a wrong port): Dask's timeout
    covers the connection, not its handshake, which would wait forever (a hostile user's
    finding, session 56)."""
    import socket
    import time

    from observer_node.loop.cluster import ClusterError, _connect

    with socket.socket() as silent:
        silent.bind(("127.0.0.1", 0))
        silent.listen()
        address = f"tcp://127.0.0.1:{silent.getsockname()[1]}"
        t0 = time.monotonic()
        with pytest.raises(ClusterError, match="no answer within 6 s"):
            _connect(address, timeout_s=1.0)
        assert time.monotonic() - t0 < 30


def test_ctrl_c_during_the_refits_ends_in_one_line_and_exit_130(tmp_path):
    """Ctrl-C while the refits run on Dask: "interrupted", exit 130, no page of tracebacks
    from the gather's waiting tasks nor from the workers (a hostile user's finding, session
    56)."""
    import os
    import signal

    out = tmp_path / "out"  # an older run's report, which the interrupted run must not touch
    out.mkdir()
    (out / "report.md").write_text("an older run\n")
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "loop", "--estimate",
                          "campaign-a/R16_00[135]", "--validate", "campaign-a/R16_002", "--out",
                          str(out), "--workers", "1"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         start_new_session=True, preexec_fn=sigint_default)
    assert p.stderr is not None
    seen = []
    for line in p.stderr:  # the progress lines; interrupt once the refits are under way
        seen.append(line)
        if "refitting with" in line or "cross-validating" in line:
            os.killpg(p.pid, signal.SIGINT)  # to the whole group, as a terminal's Ctrl-C
            break
    rest = p.stderr.read()
    assert p.wait(timeout=120) == 130, "".join(seen) + rest
    assert "Traceback" not in rest and "exception was never retrieved" not in rest, rest
    assert rest.strip().splitlines()[-1] == "observer-node: interrupted"
    assert [x.name for x in tmp_path.iterdir()] == ["out"]  # no half-written folder left
    assert [x.name for x in out.iterdir()] == ["report.md"]
    assert (out / "report.md").read_text() == "an older run\n"


def test_gains_of_varying_size_on_every_test_are_accepted():
    """A belt that unloads far more in two crashes than in the other two: the t-interval
    reaches below zero, but four of four tests improve (sign test p = 0.0625)."""
    setups = {f"T{i}": "A" for i in range(4)}
    before = dict.fromkeys(setups, 70.0)
    after = {n: 70.0 + g for n, g in zip(setups, [31.4, 28.7, 4.5, 2.4], strict=True)}
    ev = judge(before, after, setups, None, 1.0)
    assert ev.ci95_points[0] < 0 and ev.tests_improved == 4
    assert ev.accepted, ev.reason
    after["T3"] = 69.0  # three of four: chance
    assert not judge(before, after, setups, None, 1.0).accepted


def _passing(*entries: tuple[list[str] | None, list[float]]) -> tuple[list, dict]:
    """Passing candidates of one kind on the given scopes, best first, with their per-test
    cross-validated fits (90 % + gains)."""
    from observer_node.loop.analysis import Candidate
    passing, per_test = [], {}
    for scope, gains in entries:
        c = Candidate("sensor_offset", 0.5, {}, None, scope)
        before, after = _cv(gains)
        passing.append((float(np.mean(list(after.values()))), c,
                        judge(before, after, SETUPS, scope, 1.0)))
        per_test[id(c)] = after
    return passing, per_test


def test_a_narrower_scope_that_fits_no_better_gives_way_to_the_wider():
    from observer_node.loop.verdicts import defended_scope as _defended_scope
    # "on A and B only" gains a little more on average, but not test by test
    passing, per_test = _passing((["A", "B"], [2.5, 0.4, 2.9, 0.2, 1.2, 1.1]),
                                 (None, [1.1, 1.0, 1.3, 0.9, 1.2, 1.1]))
    (_, chosen, _), given_up = _defended_scope(passing, per_test)
    assert chosen.setups is None and given_up == "A+B"


def test_a_narrower_scope_that_beats_the_wider_test_by_test_is_kept():
    from observer_node.loop.verdicts import defended_scope as _defended_scope
    passing, per_test = _passing((["A", "B"], [2.5, 2.4, 2.9, 2.2, 1.2, 1.1]),
                                 (None, [1.1, 1.0, 1.3, 0.9, 1.0, 1.0]))
    (_, chosen, _), given_up = _defended_scope(passing, per_test)
    assert chosen.setups == ["A", "B"] and given_up == ""


def test_scopes_that_differ_only_on_a_rig_not_judged_keep_the_better_fit():
    from observer_node.loop.verdicts import defended_scope as _defended_scope
    # the same tests as above, where the wider scope wins; but here the wider scope adds only
    # C, held by too few estimation tests to judge (set L, hl_two_effects_same_a): no claim
    # is at stake there, so the better cross-validated fit keeps its scope
    passing, per_test = _passing((["A", "B"], [2.5, 0.4, 2.9, 0.2, 1.2, 1.1]),
                                 (None, [1.1, 1.0, 1.3, 0.9, 1.2, 1.1]))
    (_, chosen, _), given_up = _defended_scope(passing, per_test, {"C"}, ["A", "B", "C"])
    assert chosen.setups == ["A", "B"] and given_up == ""
    # a wider scope that adds a judged rig too is still preferred unless beaten
    (_, chosen, _), _ = _defended_scope(passing, per_test, {"B"}, ["A", "B", "C"])
    assert chosen.setups is None


def test_a_runner_up_the_data_cannot_tell_from_the_winner_is_said_so():
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.verdicts import runner_up_of as _rival
    win, rival = Candidate("chest_stiffening", 0.5, {}), Candidate("pelvis_coupling", 0.5, {})
    # the winner is ahead on average, but on 3 of 6 tests only
    per_test = {id(win): _cv([3.4, 3.0, 3.8, 4.1, 2.0, 3.6])[1],
                id(rival): _cv([4.6, 3.6, 1.6, 4.0, 3.4, 3.8])[1]}
    ev = judge(*_cv([4.6, 3.6, 1.6, 4.0, 3.4, 3.8]), SETUPS, None, 1.0)  # it passes too
    ru, margin, _ = _rival([(93.3, win, ev), (93.2, rival, ev)], per_test, 1.0)
    assert ru is not None and ru.kind == "pelvis_coupling"
    assert ru.told_apart is False and ru.tests_better == 2 and margin == 0.1
    assert ru.passes_rule and ru.rival
    # a runner-up far behind on every test is told apart, and one that fails the rule is
    # no rival whatever the paired test says
    per_test[id(rival)] = _cv([1.0, 1.2, 0.9, 1.1, 1.0, 1.3])[1]
    ru, _, _ = _rival([(93.3, win, ev), (91.1, rival, ev)], per_test, 1.0)
    assert ru is not None and ru.told_apart is True and ru.tests_better == 6 and not ru.rival
    weak = judge(*_cv([0.4, 0.2, -0.1, 0.3, 0.0, 0.2]), SETUPS, None, 1.0)
    per_test[id(rival)] = _cv([3.5, 3.1, 3.7, 4.0, 2.1, 3.5])[1]
    ru, _, _ = _rival([(93.3, win, ev), (93.2, rival, weak)], per_test, 1.0)
    assert ru is not None and ru.told_apart is False and not ru.passes_rule and not ru.rival


def test_a_passing_rival_is_not_hidden_behind_a_better_runner_up_that_fails_the_rule():
    # set D's stiffening webbing: input_gain cross-validated higher but lowered one setup
    # (fails), pelvis_coupling passed; the rival to report is the one that passes
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.verdicts import runner_up_of as _rival
    win = Candidate("chest_stiffening", 0.5, {})
    failing, passing = Candidate("input_gain", 0.5, {}), Candidate("pelvis_coupling", 0.5, {})
    per_test = {id(win): _cv([3.4, 3.0, 3.8, 4.1, 2.0, 3.6])[1],
                id(failing): _cv([4.9, 4.4, 4.5, 4.6, -0.5, -0.4])[1],
                id(passing): _cv([4.6, 3.6, 1.6, 4.0, 3.4, 3.8])[1]}
    ev_fail = judge(*_cv([4.9, 4.4, 4.5, 4.6, -0.5, -0.4]), SETUPS, None, 1.0)
    ev_pass = judge(*_cv([4.6, 3.6, 1.6, 4.0, 3.4, 3.8]), SETUPS, None, 1.0)
    assert not ev_fail.accepted and ev_pass.accepted
    ru, _, _ = _rival([(93.3, win, ev_pass), (93.5, failing, ev_fail),
                       (93.2, passing, ev_pass)], per_test, 1.0)
    assert ru is not None and ru.kind == "pelvis_coupling" and ru.rival


def test_a_runner_up_over_the_bar_that_fails_on_the_scatter_alone_is_a_rival():
    """A runner-up whose mean gain is over the bar, no setup lower, that fails the rule on
    the scatter alone explains the tests about as well as a winner that does not beat it test
    by test: a rival, the winner not named on its own (sets W and AD: a webbing's toe, its
    truth +1.5 and +5.9 points on 4 of 6 tests, lost to a rib stiffening and an input delay
    named). Under the bar, or lowering a setup, it is none; one that passes comes first."""
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.evidence import over_the_bar
    from observer_node.loop.verdicts import runner_up_of as _rival
    from observer_node.loop.verdicts import untold

    win, toe = Candidate("chest_stiffening", 0.5, {}), Candidate("belt_stiffening", 0.5, {})
    ev_win = judge(*_cv([2.6, 1.9, 2.4, 2.2, 1.8, 2.5]), SETUPS, None, 1.0)
    scattered = [4.0, -1.0, 3.0, 2.5, -0.5, 1.5]  # mean 1.58, 4 of 6, no setup lower
    ev_toe = judge(*_cv(scattered), SETUPS, None, 1.0)
    assert ev_win.accepted and not ev_toe.accepted and "scatter" in ev_toe.reason
    assert over_the_bar(ev_toe, 1.0) and not over_the_bar(ev_toe, 2.0)
    assert not over_the_bar(ev_win, 1.0)  # it passes
    per_test = {id(win): _cv([2.6, 1.9, 2.4, 2.2, 1.8, 2.5])[1], id(toe): _cv(scattered)[1]}
    ru, _, _ = _rival([(92.2, win, ev_win), (91.6, toe, ev_toe)], per_test, 1.0)
    assert ru is not None and ru.kind == "belt_stiffening" and ru.told_apart is False
    assert not ru.passes_rule and ru.over_bar and ru.rival
    why = untold("chest_stiffening", ru, 6)
    assert why is not None and "failing the rule on the scatter alone" in why
    # a setup lower by more than the tolerance, or a mean under the bar: no rival
    lowers = judge(*_cv([4.0, 3.0, -0.6, -0.4, 3.0, 2.5]), SETUPS, None, 1.0)
    under = judge(*_cv([1.5, -1.0, 1.0, 1.5, -0.5, 1.0]), SETUPS, None, 1.0)
    assert not lowers.accepted and not over_the_bar(lowers, 1.0)
    assert not under.accepted and not over_the_bar(under, 1.0)
    for ev in (lowers, under):
        ru, _, _ = _rival([(92.2, win, ev_win), (91.6, toe, ev)], per_test, 1.0)
        assert ru is not None and not ru.over_bar and not ru.rival
    # a rival that passes comes before one over the bar, whatever their fits
    passing = Candidate("pelvis_coupling", 0.5, {})
    per_test[id(passing)] = _cv([2.4, 2.0, 2.5, 2.1, 1.9, 2.6])[1]
    ru, _, _ = _rival([(92.2, win, ev_win), (91.6, toe, ev_toe),
                       (91.5, passing, judge(*_cv([2.4, 2.0, 2.5, 2.1, 1.9, 2.6]), SETUPS,
                                             None, 1.0))], per_test, 1.0)
    assert ru is not None and ru.kind == "pelvis_coupling" and ru.passes_rule


def test_an_effect_the_validation_tests_do_not_confirm_is_refused():
    from observer_node.loop.verdicts import validation_refusal
    assert "do not confirm" in (validation_refusal(88.5, 87.5) or "")
    assert "88.5 to 87.5" in (validation_refusal(88.5, 87.5) or "")
    assert validation_refusal(88.5, 88.3) is None  # refit noise
    assert validation_refusal(88.5, 92.0) is None


def _val_table(fits: dict[str, tuple[float, float]]) -> FitTable:
    tests = {n: OutputFits(cr, cd) for n, (cr, cd) in fits.items()}
    return FitTable(Fits.of(float(np.mean([t.cr for t in tests.values()])),
                            float(np.mean([t.cd for t in tests.values()]))), tests)


def _refusal(fits: dict[str, tuple[float, float]], scope: list[str] | None,
             thin: set[str]) -> tuple[list, str]:
    """Validation tests named SETUP_k, each (fit_TOT without, with) [%], judged by the words."""
    from observer_node.loop.verdicts import validation_by_setup, validation_refusal
    before = _val_table({n: (b, b) for n, (b, _) in fits.items()})
    after = _val_table({n: (a, a) for n, (_, a) in fits.items()})
    rows = validation_by_setup(before, after, {n: n.split("_")[0] for n in fits}, scope, thin)
    return rows, validation_refusal(before.fit.total, after.fit.total, rows) or ""


MIMIC_WORDS = "which no estimation test judges and the effect does not act on"


def test_a_validation_refusal_says_on_which_setups_the_fit_fell():
    # an effect on SLED alone; FULL has no estimation test, R16 is judged (3 tests to FULL's 2:
    # the means are over each setup's tests, the total over all five)
    rows, why = _refusal({"FULL_002": (88, 82), "FULL_004": (86, 81.5), "R16_002": (90, 90.2),
                          "R16_004": (89, 89), "R16_006": (91, 91)}, ["SLED"], {"FULL"})
    assert [(v.setup, v.tests, v.judged, v.in_scope, v.ran_away) for v in rows] == [
        ("FULL", 2, False, False, False), ("R16", 3, True, False, False)]  # largest fall first
    assert rows[0].before == pytest.approx(87.0) and rows[0].after == pytest.approx(81.75)
    assert rows[1].after - rows[1].before == pytest.approx(0.2 / 3)
    assert why.startswith("the validation tests do not confirm it: their fit_TOT falls from "
                          "88.8 to 86.7 %, per setup FULL 87.0 -> 81.8 % (2 tests, not judged),"
                          " R16 90.0 -> 90.1 % (3 tests)")
    assert (f"the fall is on FULL, {MIMIC_WORDS} (each setup judged or acted on holds "
            "within 0.3 points): FULL may have this effect too") in why
    assert "; " not in why and "|" not in why  # joined with "; " in a round's decision
    # the same fall with FULL judged, or with the effect acting on FULL: the effect's own
    assert MIMIC_WORDS not in _refusal({"FULL_002": (88, 82), "R16_002": (90, 90)}, ["SLED"],
                                       set())[1]
    rows, why = _refusal({"FULL_002": (88, 82), "R16_002": (90, 90)}, None, {"FULL"})
    assert all(v.in_scope for v in rows) and "the effect acts there" in why
    assert MIMIC_WORDS not in why
    # alone on an unjudged setup outside the scope (set W's bumper): said, with no "rest"
    why = _refusal({"SLED_002": (86, 78), "SLED_004": (87, 77)}, ["R16"], {"SLED"})[1]
    assert f"the fall is on SLED, {MIMIC_WORDS}: SLED may" in why


def test_a_validation_refusal_blames_no_unjudged_setup_when_the_rest_fall():
    # a review's case: ten tests of a judged setup where the effect acts each 0.35 lower
    # (pooled, past the tolerance), one unjudged FULL test 0.5 lower: the fall is mostly R16's
    fits = {f"R16_{k:03d}": (90.0, 89.65) for k in range(10)} | {"FULL_002": (90.0, 89.5)}
    why = _refusal(fits, ["R16"], {"FULL"})[1]
    assert "do not confirm" in why and MIMIC_WORDS not in why
    # R16 within the tolerance: the words say it holds
    fits = {f"R16_{k:03d}": (90.0, 89.75) for k in range(2)} | {"FULL_002": (90.0, 88.5)}
    assert "holds within 0.3 points" in _refusal(fits, ["R16"], {"FULL"})[1]
    # set AB's lumbar path: a judged clean R16 falls 8 points, FULL (where the effect acts)
    # rises 12, SLED (unjudged, outside) falls 11: pooled, the first two would hold; R16 does
    # not, so SLED is not blamed
    fits = {"R16_002": (92.3, 84.3), "FULL_002": (79.5, 91.3)} | {
        f"SLED_{k:03d}": (85.8, 74.7) for k in range(4)}
    why = _refusal(fits, ["FULL"], {"SLED"})[1]
    assert "do not confirm" in why and MIMIC_WORDS not in why
    # two unjudged setups outside the scope, both falling: both named
    fits = {"FULL_002": (88, 82), "SLED_002": (88, 84), "R16_002": (90, 90.5)}
    assert "the fall is on FULL and SLED, " in _refusal(fits, ["R16"], {"FULL", "SLED"})[1]


def test_a_validation_refusal_with_a_test_that_ran_away_says_so_and_blames_no_setup():
    fits = {"FULL_002": (88, 87), "FULL_004": (88, float("nan")), "R16_002": (90, 90)}
    rows, why = _refusal(fits, ["SLED"], {"FULL"})
    worst = rows[0]
    assert worst.setup == "FULL" and worst.ran_away and not rows[1].ran_away
    assert worst.after == pytest.approx((87 - 1000) / 2)  # -1000 % for the run-away test
    assert "FULL 88.0 -> -456.5 % (2 tests, not judged, a test ran away)" in why
    assert MIMIC_WORDS not in why


@pytest.mark.parametrize("setups", [["R16"] * 3 + ["SLED"] * 3,
                                    ["R16"] * 5 + ["SLED"] * 4 + ["FULL"] * 3])
def test_cross_validation_leaves_one_test_out_and_every_fold_trains_on_every_setup(setups):
    from observer_node.ident.dataset import Dataset
    from observer_node.loop.refit import MAX_FOLDS, folds

    n = len(setups)
    z = np.zeros((n, 10))
    data = Dataset([f"T{i}" for i in range(n)], setups, 1000.0, z, z, np.zeros((n, 10, 2)),
                   slice(0, 10), (0.0, 0.01))
    fs = folds(data)
    assert len(fs) == min(n, MAX_FOLDS)
    held = sorted(i for _, test in fs for i in test)
    assert held == list(range(n))  # every test scored once, by a model that never saw it
    for train, test in fs:
        assert not set(train) & set(test) and sorted(train + test) == list(range(n))
        assert {setups[i] for i in train} == set(setups)
    if n <= MAX_FOLDS:
        assert all(len(test) == 1 for _, test in fs)


def test_the_report_says_the_validation_tests_refused_an_effect_when_nothing_was_named():
    from observer_node.loop.report import LoopStep
    from observer_node.loop.report_md import none_accepted

    step = LoopStep([], 88.0, [], [], {})
    step.decision = ("airbag_contact on FULL passes the rule on the estimation tests, but the "
                     "validation tests do not confirm it: their fit_TOT falls from 88.5 to "
                     "87.5 %: not accepted")
    line = none_accepted([step], "RULE")
    assert line.startswith("No effect was accepted: airbag_contact") and "do not confirm" in line
    step.decision = "no candidate passes the rule (...)"
    assert none_accepted([step], "RULE") == "No effect was accepted: none passed the rule (RULE)."


def test_a_fold_starts_from_a_fit_that_drove_a_parameter_to_zero(campaign):
    # held-out set E: the fit on all tests drove the chest damping c1 below exp(-745): 0.0;
    # each fold then started at log(0) = -inf and the optimiser's SVD met NaN (a traceback)
    from observer_node.ident import greybox
    from observer_node.loop.refit import fold_scores
    data = make_dataset([t for t in campaign if t.name in ("R16_001", "R16_003", "R16_005")])
    base = {**greybox.fit_greybox(data).params, "c1": 0.0}
    effects = [{"kind": "pelvis_coupling", "parameters": {"kp": 1.3e3, "cp": 340.0}}]
    with np.errstate(all="ignore"):
        got = fold_scores(base, effects, data, [0, 1], [2])
    assert list(got) == ["R16_005"] and np.isfinite(got["R16_005"])


def test_an_effect_the_data_cannot_tell_from_a_passing_rival_is_not_named():
    from observer_node.loop.report import RunnerUp
    from observer_node.loop.verdicts import untold
    tie = RunnerUp("input_delay", "all", 90.7, told_apart=False, tests_better=2,
                   passes_rule=True)
    why = untold("airbag_contact", tie, 6)
    assert why is not None and "input_delay on all" in why and "2 of 6" in why
    # told apart, or a runner-up that fails the rule: the winner is named
    assert untold("airbag_contact", dataclasses.replace(tie, told_apart=True), 6) is None
    assert untold("airbag_contact", dataclasses.replace(tie, passes_rule=False), 6) is None
    assert untold("airbag_contact", None, 6) is None


def test_a_tie_says_how_many_tests_would_tell_its_sides_apart():
    d = np.array([0.9, -0.4, 1.6, 0.2, 1.1, -0.2])  # the first side fits better on 4 of 6
    n, words = evidence.tell_apart(d)
    assert n == needed_tests(d) and n is not None and n > len(d)
    assert words == (f" (about {n} judged estimation tests in all, 6 now, differing as these "
                     "did, would put the 95 % interval of the difference above zero 4 times "
                     "in 5)")
    # the side ranked second may fit better on the judged tests: the same question
    assert evidence.tell_apart(-d) == evidence.tell_apart(d)
    # a mean difference small against its scatter: more tests like these would not tell
    n, words = evidence.tell_apart(np.array([0.05, -0.9, 1.0, -0.8, 0.9, -0.2]))
    assert n is None and "more tests like these would not tell the two apart" in words
    for nothing in ([0.5], [0.4, 0.4, 0.4], [0.5, -0.5], [np.nan, 1.0, 2.0]):
        assert evidence.tell_apart(np.array(nothing)) == (None, "")
    assert "; " not in words and "|" not in words  # a reason is joined with "; "


def _fits(gains: list[float], base: float = 90.0) -> dict[str, float]:
    return {n: base + g for n, g in zip(SETUPS, gains, strict=True)}


def test_a_tie_is_looked_past_by_judging_each_effect_beside_the_other():
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.evidence import past_the_tie
    from observer_node.loop.verdicts import tie_verdict
    a = _fits([2.6, 2.4, 2.9, 2.1, 2.5, 2.7])  # a pulse delay, say
    b = _fits([1.1, 1.0, 1.3, 0.9, 1.0, 1.4])  # an airbag that mimics part of it
    # with both, the fit is the delay's: the airbag adds nothing beside it, not the reverse
    both = _fits([2.7, 2.5, 2.9, 2.2, 2.6, 2.7])
    past = past_the_tie(a, b, both, SETUPS, None, None, 1.0)
    assert past.named == "a" and past.a_beside_b.accepted and not past.b_beside_a.accepted
    assert past_the_tie(b, a, both, SETUPS, None, None, 1.0).named == "b"
    # each adds beyond the other: both are there
    both = _fits([4.9, 4.5, 5.3, 4.0, 4.6, 5.1])
    assert past_the_tie(a, b, both, SETUPS, None, None, 1.0).named == "both"
    # a passes beside b, but b still adds most of a point on every test beside a: b is not
    # explained away (set I's relief airbag beside a belt stiffening), a true tie
    both = _fits([3.5, 3.3, 3.8, 3.0, 3.4, 3.6])
    past = past_the_tie(a, b, both, SETUPS, None, None, 1.0)
    assert past.a_beside_b.accepted and 0.25 < past.b_beside_a.gain_points < 1.0
    assert past.named == ""
    # two explanations of one thing: neither adds beyond the other, a true tie
    b = _fits([2.8, 2.1, 3.1, 1.9, 2.6, 2.5])
    past = past_the_tie(a, b, _fits([2.9, 2.5, 3.1, 2.2, 2.7, 2.8]), SETUPS, None, None, 1.0)
    assert past.named == ""
    line = tie_verdict(Candidate("input_delay", 0.5, {}), Candidate("airbag_contact", 0.5, {}),
                       past)
    assert "beside airbag_contact, input_delay gains +0.20 points (5 of 6 tests);" in line
    assert line.endswith("neither explains the other away")


def test_of_two_effects_tied_on_setups_apart_the_one_that_passes_beside_the_other_is_named():
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.evidence import past_the_tie
    from observer_node.loop.verdicts import tie_verdict
    a = _fits([3.6, 3.4, 3.9, 3.1, 3.5, 3.7])  # rib damping on setup A, say
    b = _fits([2.4, 2.6, 2.7, 2.2, 2.6, 2.5])  # an airbag on setup B
    # beside b, a passes; beside a, b still adds half a point on every test (set R)
    both = _fits([4.0, 4.1, 4.4, 3.5, 4.2, 4.0])
    one_thing = past_the_tie(a, b, both, SETUPS, ["A", "B"], ["B"], 1.0)
    assert one_thing.a_beside_b.accepted and 0.25 < one_thing.b_beside_a.gain_points < 1.0
    assert one_thing.named == "" and not one_thing.apart  # scopes share B: a true tie
    past = past_the_tie(a, b, both, SETUPS, ["A"], ["B"], 1.0)
    assert past.apart and past.named == "a"
    assert past_the_tie(b, a, both, SETUPS, ["B"], ["A"], 1.0).named == "b"
    line = tie_verdict(Candidate("chest_rate_damping", 0.5, {}, setups=["A"]),
                       Candidate("airbag_contact", 0.5, {}, setups=["B"]), past)
    assert line.endswith("chest_rate_damping on A passes beside airbag_contact on B, which "
                         "acts on other setups and is judged again beside it")
    # neither passes beside the other: apart or not, nothing is named
    assert past_the_tie(a, b, _fits([2.9, 2.5, 3.1, 2.2, 2.7, 2.8]), SETUPS, ["A"], ["B"],
                        1.0).named == ""
    # an effect on every setup is never apart
    assert not past_the_tie(a, b, both, SETUPS, None, ["B"], 1.0).apart


def test_a_side_over_the_bar_beside_a_rival_that_adds_nothing_beside_it_is_named():
    from observer_node.loop.analysis import Candidate
    from observer_node.loop.evidence import past_the_tie
    from observer_node.loop.verdicts import tie_verdict
    a = _fits([6.0, 5.9, 1.7, 1.6, 16.7, 7.9])  # a webbing's toe on setups B and C, say
    b = _fits([2.2, 3.5, 0.4, 2.7, 7.9, 3.3])  # an input delay on setup A
    # beside b, a gains +3.4 points on 5 of 6 tests: over the bar, not above the scatter;
    # beside a, b adds nothing (set AG's toe beside an input delay)
    both = _fits([6.9, 6.0, 1.6, 1.5, 16.8, 7.8])
    past = past_the_tie(a, b, both, SETUPS, ["B", "C"], ["A"], 1.0)
    assert not past.a_beside_b.accepted and past.a_beside_b.gain_points >= 1.0
    assert past.b_beside_a.gain_points < 0.25
    assert past.named == "a" and past.over_bar and past.apart
    assert past_the_tie(b, a, both, SETUPS, ["A"], ["B", "C"], 1.0).named == "b"
    # ... but only one that passes the rule on its own: a rival over the bar alone is not
    # named for explaining the winner away (set W's toe, 4 of 6 tests on its own)
    assert past_the_tie(b, a, both, SETUPS, ["A"], ["B", "C"], 1.0, b_passes=False).named == ""
    line = tie_verdict(Candidate("belt_stiffening", 0.5, {}, setups=["B", "C"]),
                       Candidate("input_delay", 0.5, {}, setups=["A"]), past)
    assert line.endswith("belt_stiffening on B+C explains what input_delay did, not the "
                         "reverse: over the bar beside it, though not above the scatter, "
                         "where input_delay adds nothing beside it; input_delay acts on other "
                         "setups and is judged again beside it")
    # the same on one scope: an encompassing test, apart or not
    assert past_the_tie(a, b, both, SETUPS, None, None, 1.0).named == "a"
    # the rival still adds half a point beside it: not explained away, a true tie (a over the
    # bar beside it, not passing there)
    both_b = _fits([6.9, 6.0, 1.6, 1.5, 16.8, 7.8])
    b_more = _fits([6.4, 5.5, 1.1, 1.0, 16.3, 7.3])
    past = past_the_tie(b_more, b, both_b, SETUPS, None, None, 1.0)
    assert not past.a_beside_b.accepted and past.a_beside_b.gain_points >= 1.0
    assert 0.25 <= past.b_beside_a.gain_points < 1.0 and past.named == ""
    # at a margin set under 0.25, two sides adding alike beside each other are a tie
    even = {n: 90.4 for n in SETUPS}
    alike = dict(zip(SETUPS, [91.12, 90.12] * 3, strict=True))
    assert past_the_tie(even, even, alike, SETUPS, None, None, 0.2).named == ""
    # a rival that fails the rule on its own is not named on any path, passing beside the
    # winner or not (a review's case: +5.00 on its own, its interval below zero)
    win = {n: 93.0 for n in SETUPS}
    rival = dict(zip(SETUPS, [100.0, 90.0] * 3, strict=True))
    both_r = {n: 95.0 for n in SETUPS}
    assert past_the_tie(win, rival, both_r, SETUPS, None, None, 1.0).named == "b"
    assert past_the_tie(win, rival, both_r, SETUPS, None, None, 1.0, b_passes=False).named == ""
    # under the bar beside the rival: a true tie, however little the rival adds
    weak = {n: b[n] + g for n, g in zip(b, [0.9, 0.8, 0.7, 0.6, 0.9, 0.8], strict=True)}
    past = past_the_tie(a, b, weak, SETUPS, None, None, 1.0)
    assert past.a_beside_b.gain_points < 1.0 and past.named == "" and not past.over_bar
    # over the bar, but one setup lower beside the rival: not over the bar by the rule
    low = dict(both, T2=a["T2"] - 1.0, T3=a["T3"] - 1.0)
    assert past_the_tie(a, b, low, SETUPS, None, None, 1.0).named == ""


def test_the_tests_left_out_are_drawn_against_the_others(campaign, tmp_path):
    # report.md points a reviewer to broken.png: one panel per test left out, its channel
    from matplotlib.image import imread

    from observer_node.plots import broken_tests
    t = next(x for x in campaign if x.name == "R16_003")
    hum = _broken(t, cr_g=t.cr_g + 3.0 * np.sin(2 * np.pi * 50.0 * t.time_s))
    tests = [hum if x is t else x for x in campaign]
    found = screen_channels(hum, 0.15)
    one = broken_tests(tmp_path / "one.png", [(b.test, b.channel, b.reason) for b in found],
                       tests)
    two = broken_tests(tmp_path / "two.png", [(b.test, b.channel, b.reason) for b in found]
                       + [("SLED_002", "residual", "fit_TOT far below the others'")], tests)
    assert [b.channel for b in found] == ["cr"]
    assert imread(two).shape[0] > 1.8 * imread(one).shape[0] > 0


def test_a_delay_held_at_the_largest_searched_is_not_named():
    # set J's crossed BRS file, left in, fitted as a BRS 10.5 ms late on its rig: the data
    # wanted more delay than was searched, a mimic's gain
    from observer_node.loop.verdicts import at_the_edge

    why = at_the_edge("input_delay", {"n_pulse": 0.0, "n_brs": 10.54}, 1000.0)
    assert why is not None and "n_brs = 10.54 ms" in why and "largest delay searched" in why
    assert at_the_edge("input_delay", {"n_pulse": 0.0, "n_brs": 4.5}, 1000.0) is None
    assert at_the_edge("input_delay", {"n_pulse": 45.0, "n_brs": 0.0}, 10_000.0) is None


def test_an_effect_refitted_to_physically_nothing_is_not_named():
    # set AC's eccentric ring: a belt stiffening of 6.3 N/m^3 (typical 1e8) named on every
    # rig, its gain made in folds whose refits never left the all-test fit
    from observer_node.loop.verdicts import nothing_left

    why = nothing_left("belt_stiffening", {"kb3": 6.33})
    assert why is not None and "kb3 = 6.33 N/m^3" in why and "physically nothing" in why
    assert nothing_left("pelvis_coupling", {"kp": 2e-4, "cp": 3e-6}) is not None
    assert nothing_left("input_gain", {"g": -1e-6}) is not None
    # one size left is an effect: named effects of sets W-AA with one size at nothing (a
    # spring-only pelvis path, an undamped bag touching the chest, a BRS-only delay)
    assert nothing_left("pelvis_coupling", {"kp": 6457.0, "cp": 3.5e-6}) is None
    assert nothing_left("airbag_contact", {"kab": 20971.0, "gap": 4e-9, "cab": 5.3e-5}) is None
    assert nothing_left("input_delay", {"n_pulse": 2.9e-8, "n_brs": 2.44}) is None
    # a gap says where a bag acts, not how much; a switch and the formula have no size
    assert nothing_left("airbag_contact", {"kab": 1e-3, "gap": 0.05, "cab": 1e-5}) is not None
    assert nothing_left("belt_unloading", {}) is None
    assert nothing_left("other", {"rib": {"x3": 0.0}}) is None


def test_the_held_out_benchmark_scores_scopes_on_the_rigs_held_twice():
    from benchmarks.loop_heldout import _as_judged

    every = ["FULL", "R16", "SLED"]
    # FULL holds one estimation test: an effect "everywhere" is asked on R16 and SLED only
    assert _as_judged("belt_unloading@all", ["R16", "SLED"], every) == \
        "belt_unloading@R16+SLED"
    assert _as_judged("airbag_contact@FULL+SLED", ["R16", "SLED"], every) == \
        "airbag_contact@SLED"
    assert _as_judged("airbag_contact@FULL", ["R16", "SLED"], every) is None
    # every rig judged: the scope is unchanged, "all" when it covers them
    assert _as_judged("chest_stiffening@FULL+R16+SLED", every, every) == "chest_stiffening@all"
    assert _as_judged("chest_stiffening@R16", every, every) == "chest_stiffening@R16"


def test_an_input_delay_of_both_inputs_alike_that_helps_one_output_is_that_outputs_lag():
    from observer_node.loop.verdicts import output_lag

    # set O's oil-damped spine accelerometer: both inputs 2.7 and 2.4 ticks late, CR +3.2
    assert output_lag("input_delay", {"n_pulse": 2.7, "n_brs": 2.4}, 3.2, 0.5) == "cr"
    assert output_lag("input_delay", {"n_pulse": 2.0, "n_brs": 2.2}, 0.1, 2.0) == "cd"
    # a late pulse or BRS: one input (the other's fitted delay stays small)
    assert output_lag("input_delay", {"n_pulse": 3.9, "n_brs": 0.2}, 3.7, 0.4) is None
    assert output_lag("input_delay", {"n_pulse": 0.0, "n_brs": 2.7}, 4.0, 0.1) is None
    # both inputs alike and both outputs gain: the outputs' common timing, not one transducer
    assert output_lag("input_delay", {"n_pulse": 3.0, "n_brs": 3.1}, 3.0, 1.5) is None
    assert output_lag("input_delay", {"n_pulse": 3.0, "n_brs": 4.0}, 3.0, 0.1) is None  # apart
    assert output_lag("chest_stiffening", {"k3": 1e8}, 3.0, 0.1) is None


def test_a_tie_is_carried_only_when_the_validation_fit_rises_and_no_output_falls():
    """Fit is a carried effect's only reason to be in the model: the validation tests'
    fit_TOT must rise with it, and neither output's fall by more than the tolerance."""
    from observer_node.ident.metrics import Fits
    from observer_node.loop.verdicts import VALIDATION_TOLERANCE, carry_refusal

    before = Fits(cr=90.0, cd=88.0, total=89.0)
    assert carry_refusal(before, Fits(cr=91.0, cd=89.0, total=90.0)) is None
    assert carry_refusal(before, Fits(cr=91.0, cd=88.0 - VALIDATION_TOLERANCE / 2,
                                      total=89.4)) is None
    flat = carry_refusal(before, Fits(cr=90.0, cd=88.0, total=89.0))
    assert flat is not None and "does not rise" in flat and "89.0 -> 89.0" in flat
    cd = carry_refusal(before, Fits(cr=94.0, cd=87.0, total=90.5))
    assert cd is not None and "CD fit falls" in cd and "88.0 -> 87.0" in cd


def test_a_model_file_note_is_a_string():
    """An effect's note (the loop's word on a carried effect) is text, and nothing else."""
    import json

    from observer_node.bench import SHIPPED_LOOP
    from observer_node.model import ModelFile
    from observer_node.model.modelfile import ModelFileError

    d = json.loads((SHIPPED_LOOP / "model.json").read_text())
    d["effects"][-1]["note"] = "carried for its fit, not a finding: x on all fits alike"
    assert ModelFile.from_dict(d, "m.json").effects[-1]["note"].startswith("carried")
    d["effects"][-1]["note"] = 12
    with pytest.raises(ModelFileError, match="note"):
        ModelFile.from_dict(d, "m.json")


def test_a_scoped_carried_effect_runs_on_its_setups_bench_only_with_its_note():
    """A bench of one setup runs the effects that act there: a carried side of a tie scoped
    to some setups keeps its note on those and is absent from the others' models."""
    import json

    import numpy as np

    from observer_node.bench import SHIPPED_LOOP
    from observer_node.loop.closed_loop import model_name
    from observer_node.model import ModelFile

    d = json.loads((SHIPPED_LOOP / "model.json").read_text())
    bag = d["effects"][-1]
    assert bag["kind"] == "airbag_contact" and bag["setups"] == ["SLED", "FULL"]
    bag["note"] = "carried for its fit, not a finding: pelvis_coupling on SLED+FULL fits alike"
    d["name"] = model_name(d["effects"])
    mf = ModelFile.from_dict(d, "m.json")
    assert mf.name == ("greybox+belt_unloading+chest_stiffening (carries airbag_contact for "
                       "its fit, not a finding)")
    sled, r16 = mf.for_setup("SLED"), mf.for_setup("R16")
    assert [e["kind"] for e in sled.effects][-1] == "airbag_contact"
    assert sled.effects[-1]["note"] == bag["note"] and "setups" not in sled.effects[-1]
    assert "airbag_contact" not in [e["kind"] for e in r16.effects]
    assert not any("note" in e for e in r16.effects)
    for one in (sled, r16):
        y = one.observer().simulate(np.ones((1, 50)), np.zeros((1, 50)))
        assert y.shape == (1, 50, 2) and np.isfinite(y).all()


def test_a_refit_with_its_jacobian_run_as_one_simulation_is_the_refit_run_one_by_one(
        campaign, monkeypatch):
    """The refits hand scipy's finite-difference Jacobian its trial points as one simulation
    (``simulate_many``); the fit must be the one the trials simulated one by one give, to the
    bit (and so the loop's verdicts those of the loop before the change)."""
    from observer_node.ident import greybox
    from observer_node.loop import refit as refit_module

    data = make_dataset([t for t in campaign if t.name in ("R16_001", "R16_003", "FULL_001")])
    base = greybox.fit_greybox(data).params
    effects = [{"kind": "belt_unloading", "parameters": {}},
               {"kind": "airbag_contact", "parameters": {"kab": 3e4, "gap": 0.1, "cab": 300.0},
                "setups": ["FULL"]}]
    batched = refit_module.refit_from(base, effects, data, max_nfev=8)
    scipy_own = refit_module.optimize.least_squares  # scipy's map over the residual
    monkeypatch.setattr(refit_module.optimize, "least_squares",
                        lambda *a, workers=None, **k: scipy_own(*a, **k))
    one_by_one = refit_module.refit_from(base, effects, data, max_nfev=8)
    assert batched.cost == one_by_one.cost
    assert batched.base == one_by_one.base and batched.effects == one_by_one.effects
    assert batched.effects[1]["parameters"] != effects[1]["parameters"]  # it did fit


def test_a_fold_refit_leaves_a_positive_size_fitted_near_nothing(campaign):
    """A positive size near 0 (set AC's eccentric ring: a belt stiffening refitted to 6.3
    N/m^3) was fitted as |v|, whose kink made trf reject every step: the all-test refit and
    its folds never left their start, so a fold scored its held-out test in-sample. Fitted
    with scipy's bound v >= 0, the fold's refit moves and the size stays >= 0."""
    from observer_node.ident import greybox
    from observer_node.loop.refit import FOLD_NFEV, refit_from

    data = make_dataset([t for t in campaign
                         if t.name in ("R16_001", "R16_003", "FULL_001", "SLED_001")])
    base = greybox.fit_greybox(data).params
    stiff = [{"kind": "belt_stiffening", "parameters": {"kb3": 6.33}}]
    every = refit_from(base, stiff, data, 60)
    fold = refit_from(every.base, every.effects, data.subset([0, 1, 2]), FOLD_NFEV)
    assert every.base != base and fold.base != every.base  # neither stalled at its start
    moved = max(abs(fold.base[n] / every.base[n] - 1) for n in greybox.FREE)
    assert moved > 1e-3
    assert every.effects[0]["parameters"]["kb3"] >= 0 <= fold.effects[0]["parameters"]["kb3"]
    start = refit_from(every.base, every.effects, data.subset([0, 1, 2]), 1)  # one evaluation
    assert fold.cost < start.cost


def test_a_fold_whose_refit_never_moved_counts_as_no_gain(campaign):
    """A fold whose refit took no step scores its held-out test in-sample (set Z's fabric
    case: a formula's stalled fold gained 2.4 points the folds that moved did not): its tests
    are NaN, and the rule counts the model without the candidate's fit there instead."""
    import math

    from observer_node.ident import greybox
    from observer_node.loop.refit import fold_scores, where_stalled

    data = make_dataset([t for t in campaign
                         if t.name in ("R16_001", "R16_003", "FULL_001", "SLED_001")])
    base = greybox.fit_greybox(data).params
    stalled = fold_scores(base, [], data, [0, 1, 2], [3], max_nfev=1)  # one evaluation: no step
    moved = fold_scores(base, [], data, [0, 1, 2], [3])
    assert list(stalled) == list(moved) == ["SLED_001"]
    assert math.isnan(stalled["SLED_001"]) and 0 < moved["SLED_001"] <= 100
    assert where_stalled({"a": math.nan, "b": 90.0}, {"a": 88.0, "b": 1.0}) == \
        {"a": 88.0, "b": 90.0}


def test_a_search_grid_scored_as_one_simulation_scores_each_point_as_alone(campaign):
    """The delay grid and a size's half decades are scored in one simulation
    (``_Scorer.shares``): each share must be the one the point scores alone."""
    from observer_node.ident import greybox
    from observer_node.loop import analysis
    from observer_node.loop.analysis import _Scorer, base_sensitivities, weights
    from observer_node.model.nonlinear import NonlinearGreyBox

    data = make_dataset([t for t in campaign if t.name in ("R16_001", "R16_003", "FULL_001")])
    m = NonlinearGreyBox(greybox.fit_greybox(data).params, [], data.fs_hz, list(data.setups))
    y_hat = m.simulate(data.pulse_g, data.brs_rad)
    scorer = _Scorer(m, data, (data.y - y_hat)[:, data.win], weights(data),
                     base_sensitivities(m, data, y_hat), y_hat)
    for kind, ps, scope in (
            ("input_delay", [{"n_pulse": n, "n_brs": 1.5} for n in (0.0, 0.5, 2.0, 7.25)],
             None),
            ("chest_stiffening", [{"k3": v} for v in (1e7, 1e8, 1e9)], ["R16"])):
        together = scorer.shares(kind, ps, scope)
        alone = [scorer.share(kind, p, scope)[0] for p in ps]
        assert together == alone and len(set(alone)) == len(ps), kind
    # and an effect's short fit, its Jacobian's points as one simulation, is scipy's own
    batched = scorer.fit("airbag_contact", {"kab": 3e4, "gap": 0.1, "cab": 300.0}, ["FULL"])
    scipy_own = analysis.optimize.least_squares
    analysis.optimize.least_squares = lambda *a, workers=None, **k: scipy_own(*a, **k)
    try:
        one_by_one = scorer.fit("airbag_contact", {"kab": 3e4, "gap": 0.1, "cab": 300.0},
                                ["FULL"])
    finally:
        analysis.optimize.least_squares = scipy_own
    assert batched[:2] == one_by_one[:2] and np.array_equal(batched[2], one_by_one[2])
    assert batched[1] != {"kab": 3e4, "gap": 0.1, "cab": 300.0}  # it did fit


def test_the_heldout_benchmark_says_how_an_effect_was_named() -> None:
    """The held-out benchmark's JSON keeps, per named effect, the rule's numbers, its gain on
    the tests it acts on apart from the others' (which only the shared base parameters can
    give), and whether the validation tests told a tie apart for it: set AK's webbing knee,
    an airbag on SLED whose FULL tests gained 2.4 points through the base."""
    from types import SimpleNamespace

    from benchmarks.loop_heldout import _how_named
    from observer_node.loop.report import AcceptedEffect

    gains = {"FULL_001": 2.13, "FULL_003": -0.24, "FULL_005": 2.89, "FULL_007": 4.64,
             "SLED_001": 6.28, "SLED_003": 6.87}
    rule = {"gain_points": 3.76, "ci95_points": [0.94, 6.58], "gain_in_scope_points": 6.572,
            "test_gain_points": gains, "tests_improved": 5, "tests": 6, "sign_test_p": 0.109,
            "setup_gain_points": {"FULL": 2.35, "SLED": 6.57}, "accepted": True, "reason": "",
            "tests_to_defend": None, "stalled_tests": []}
    runner_up = {"kind": "belt_stiffening", "scope": "SLED", "cv_fit": 91.57,
                 "told_apart": False, "tests_better": 5, "passes_rule": True, "over_bar": False}
    evidence = {"ranking_share": 0.545, "scope_shares": None, "rule": rule,
                "explained_share_before": 0.36, "explained_share_after": 0.0,
                "cv_fit_before": 88.25, "cv_fit_after": 92.01, "runner_up": runner_up,
                "margin_points": 0.44, "other_scope": None,
                "input_xcorr_rms_ratio_before": 0.22, "input_xcorr_rms_ratio_after": 0.4,
                "input_xcorr_max_ratio_before": 0.78, "input_xcorr_max_ratio_after": 1.58}
    told = ("named over a tie by the validation tests, test by test (its runner-up, below): "
            "the estimation tests could not tell them apart")
    e = AcceptedEffect.from_dict({
        "kind": "airbag_contact", "description": "", "std_err": {},
        "parameters": {"kab": 1.8e4, "gap": 0.083, "cab": 373.0}, "setups": ["SLED"],
        "applies_to": ["SLED_001", "SLED_003", "SLED_002"], "warnings": [told],
        "confidence": "", "evidence": evidence, "fit": {"cr": 89.8, "cd": 90.4, "total": 90.1}})
    report = SimpleNamespace(setups=[SimpleNamespace(name="SLED", tests=["SLED_001"])])
    row = _how_named(e, report)  # type: ignore[arg-type]
    assert row["effect"] == "airbag_contact@SLED"
    assert row["gain_in_scope_points"] == pytest.approx(6.58, abs=0.01)
    assert row["gain_out_of_scope_points"] == pytest.approx(2.36, abs=0.01)
    assert row["told_by_validation"] and row["runner_up"] == "belt_stiffening@SLED"
    assert (row["tests_improved"], row["tests"], row["sign_test_p"]) == (5, 6, 0.109)
    assert row["ci95_points"] == [0.94, 6.58]


def test_the_held_out_benchmark_counts_a_sensor_correction_where_no_transducer_is_at_fault():
    """A sensor correction is a finding about a transducer: the held-out benchmark made a case
    wrong for a physical effect named and not there, but not for a CR correction named on a
    BRS encoder's fault (set AR's eccentric ring). Now it is counted, and the case is wrong."""
    from benchmarks.heldout.cases_aq import UNEXPLAINED_CD
    from benchmarks.loop_heldout import wrong_sensors

    assert wrong_sensors("", ["cr"]) == ["cr"]  # a physical or clean case
    assert wrong_sensors("", []) == []
    assert wrong_sensors(UNEXPLAINED_CD, ["cd"]) == []  # the transducer case's own output
    assert wrong_sensors(UNEXPLAINED_CD, ["cr", "cd"]) == ["cr"]
