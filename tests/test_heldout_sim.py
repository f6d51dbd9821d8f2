"""The independent held-out simulator (benchmarks/heldout): deterministic, readable by the
project's reader with the right signs and units, BRS counts as a spindle encoder gives them,
and the broken test really broken."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from benchmarks.heldout import make_sets
from benchmarks.heldout.cases import BY_NAME
from observer_node.data.isomme import read_isomme


def _files(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


@pytest.fixture(scope="module")
def sets(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("heldout")
    make_sets.make([BY_NAME["h_clean48"], BY_NAME["h_broken_brs"]], out, log=False)
    make_sets.make([BY_NAME["h_broken_brs"]], out / "twin", log=False, effects_on=False)
    return out


def test_same_seed_same_bytes(sets: Path, tmp_path: Path) -> None:
    make_sets.make([BY_NAME["h_clean48"]], tmp_path, log=False)
    again, first = _files(tmp_path / "h_clean48"), _files(sets / "h_clean48")
    assert len(first) == 12 * 6 + 1  # 12 tests of .mme, .chn and 4 channels; truth.json
    assert again == first


def test_reader_gets_thesis_signs_and_units(sets: Path) -> None:
    truth = json.loads((sets / "h_clean48" / "truth.json").read_text())
    peaks = {t["name"]: t for t in truth["tests"]}
    for part in ("est", "val"):
        for folder in sorted((sets / "h_clean48" / part).iterdir()):
            t = read_isomme(folder)
            assert t.counts_per_rev == 48
            assert t.cr_g is not None and t.cd_mm is not None
            # model convention: deceleration, spine retardation and compression positive
            # while the crash loads the chest (20..70 ms); g and mm
            crash = slice(round((0.020 - t.t0_s) * t.fs_hz), round((0.070 - t.t0_s) * t.fs_hz))
            assert t.fs_hz == 10_000 and len(t.pulse_g) == 2200
            assert t.pulse_g[crash].mean() > 10
            assert t.cr_g[crash].mean() > 10
            assert t.cd_mm[crash].mean() > 10
            assert abs(t.cd_mm.max() - peaks[folder.name]["peak_cd_mm"]) < 1.5
            # pretensioner pulls webbing in (+) before the load limiter pays it out (-)
            assert t.brs.max() > 0 > t.brs.min()
            assert np.array_equal(t.brs, np.round(t.brs))


@pytest.mark.parametrize("case", ["h_clean48", "h_broken_brs"])
def test_brs_steps_are_one_count(sets: Path, case: str) -> None:
    n = BY_NAME[case].counts_per_rev
    for chn in sorted((sets / case).glob("*/*/Channel/*.002")):
        lines = chn.read_text(encoding="iso-8859-1").splitlines()
        deg = np.array([float(v) for v in lines if ":" not in v])
        steps = np.diff(deg)[np.diff(deg) != 0]
        counts = steps / (360.0 / n)
        assert np.allclose(counts, np.round(counts), atol=1e-4)
        assert np.abs(np.round(counts)).min() >= 1
        assert np.allclose(deg / (360.0 / n), np.round(deg / (360.0 / n)), atol=1e-4)


def test_broken_test_freezes_mid_crash(sets: Path) -> None:
    case = BY_NAME["h_broken_brs"]
    (broken,) = case.expect_broken
    bad = read_isomme(sets / case.name / "est" / broken)
    good = read_isomme(sets / "twin" / case.name / "est" / broken)
    t = bad.t0_s + np.arange(len(bad.brs)) / bad.fs_hz
    after = t >= case.effects[0].size
    assert np.ptp(bad.brs[after]) == 0  # frozen from the fault on
    assert np.ptp(good.brs[after]) > 10  # while the spindle really turned
    assert np.array_equal(bad.brs[~after], good.brs[~after])
    for other in sorted((sets / case.name / "est").iterdir()):
        if other.name != broken:
            o = read_isomme(other)
            assert np.ptp(o.brs[after]) > 0


def test_bad_arguments_exit_2(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    assert make_sets.main(["--out", str(tmp_path), "--case", "nope"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("error: unknown case 'nope'") and "\n" not in err
    assert make_sets.main([]) == 2
