from __future__ import annotations

import dataclasses
import re
import shutil
import zipfile
from pathlib import Path

import numpy as np
import pytest

from observer_node.data import (
    ChannelCodes,
    CrashDataError,
    bundled_campaign,
    find_tests,
    load_tests,
    read_isomme,
    write_isomme,
)

from .conftest import DATA


def _raw_values(path: Path) -> np.ndarray:
    lines = path.read_text(encoding="iso-8859-1").splitlines()
    return np.array([float(v) for v in lines if ":" not in v])


def test_reads_folder_in_model_convention():
    t = read_isomme(DATA / "R16_001")
    assert (t.name, t.setup, t.counts_per_rev) == ("R16_001", "R16", 96)
    assert t.fs_hz == pytest.approx(10_000) and t.t0_s == pytest.approx(-0.02) and t.n == 2200
    ch = DATA / "R16_001" / "Channel"
    # SAE J211 -> model convention: pulse, CR and CD are negated, BRS deg -> counts.
    np.testing.assert_allclose(t.pulse_g, -_raw_values(ch / "R16_001.001"))
    np.testing.assert_allclose(t.brs, _raw_values(ch / "R16_001.002") * 96 / 360)
    np.testing.assert_allclose(t.cr_g, -_raw_values(ch / "R16_001.003"))
    np.testing.assert_allclose(t.cd_mm, -_raw_values(ch / "R16_001.004"))
    assert t.pulse_g.max() > 20 and t.cd_mm.max() > 15  # a frontal crash is positive


def test_bundled_campaign_reads_from_zips():
    paths = find_tests([bundled_campaign()])
    assert len(paths) == 24 and all(p.suffix == ".zip" for p in paths)
    tests = load_tests(paths[:2])
    assert all(t.has_outputs for t in tests)


def test_zip_equals_folder():
    a = read_isomme(DATA / "R16_001")
    b = read_isomme(bundled_campaign() / "R16_001.zip")
    np.testing.assert_array_equal(a.cd_mm, b.cd_mm)


def test_a_zip_made_on_a_mac_reads_as_the_test(tmp_path: Path):
    """macOS's Finder writes __MACOSX/._* resource forks (binary) and .DS_Store into the zips
    it makes: they are skipped, not read as channel files."""
    src = bundled_campaign() / "R16_001.zip"
    mac = tmp_path / "R16_001.zip"
    with zipfile.ZipFile(src) as z, zipfile.ZipFile(mac, "w") as out:
        for n in z.namelist():
            out.writestr(n, z.read(n))
            base = n.rsplit("/", 1)
            if not n.endswith("/"):
                fork = f"__MACOSX/{base[0]}/._{base[1]}" if len(base) == 2 else f"__MACOSX/._{n}"
                out.writestr(fork, b"\x00\x05\x16\x07\x00\x02\x00\x00Mac OS X")
        out.writestr("R16_001/.DS_Store", b"\x00\x00\x00\x01Bud1")
    a, b = read_isomme(src), read_isomme(mac)
    np.testing.assert_array_equal(a.cd_mm, b.cd_mm)
    np.testing.assert_array_equal(a.brs, b.brs)


@pytest.mark.parametrize("encoding,bom,eol", [("utf-8", True, "\n"), ("cp1252", False, "\n"),
                                              ("utf-8", False, "\r\n")])
def test_encodings_and_line_ends(r16_folder: Path, encoding: str, bom: bool, eol: str):
    for p in r16_folder.rglob("*"):
        if p.is_file():
            text = p.read_text(encoding="iso-8859-1").replace("\r\n", "\n")
            text = text.replace("SLED X ACCELERATION", "SLED X ACCÉLÉRATION °")
            data = text.replace("\n", eol).encode(encoding)
            p.write_bytes((b"\xef\xbb\xbf" if bom else b"") + data)
    t = read_isomme(r16_folder)
    assert t.n == 2200 and t.counts_per_rev == 96


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_bytes().decode("iso-8859-1")
    assert old in text
    path.write_text(text.replace(old, new, 1), encoding="iso-8859-1", newline="")


def test_truncated_channel_names_file_and_key(r16_folder: Path):
    p = r16_folder / "Channel" / "R16_001.003"
    lines = p.read_text(encoding="iso-8859-1").splitlines(keepends=True)
    p.write_text("".join(lines[:-100]), encoding="iso-8859-1", newline="")
    with pytest.raises(CrashDataError,
                       match=r"R16_001\.003:\d+: key 'Number of samples'.*truncated"):
        read_isomme(r16_folder)


def test_non_numeric_value_names_line(r16_folder: Path):
    p = r16_folder / "Channel" / "R16_001.004"
    lines = p.read_text(encoding="iso-8859-1").splitlines(keepends=True)
    header = sum(1 for line in lines if ":" in line)
    lines[header + 9] = "1.0E-0x2\r\n"
    p.write_text("".join(lines), encoding="iso-8859-1", newline="")
    with pytest.raises(CrashDataError, match=rf"R16_001\.004:{header + 10}: non-numeric"):
        read_isomme(r16_folder)


def test_nan_value_is_rejected(r16_folder: Path):
    p = r16_folder / "Channel" / "R16_001.001"
    lines = p.read_text(encoding="iso-8859-1").splitlines(keepends=True)
    lines[-5] = "nan\r\n"
    p.write_text("".join(lines), encoding="iso-8859-1", newline="")
    # named by its line in the file, not its sample index
    line = len(lines) - 4
    with pytest.raises(CrashDataError, match=rf"R16_001\.001:{line}: value 'nan' is not a"):
        read_isomme(r16_folder)


def test_missing_channel_lists_what_is_there(r16_folder: Path):
    _edit(r16_folder / "Channel" / "R16_001.004", "11CHST0000H3DSXB", "11CHST0000H3DSYB")
    with pytest.raises(CrashDataError, match=r"missing CD channel.*11CHST0000H3DSYB"):
        read_isomme(r16_folder)
    # ... and a user override (with a wildcard) finds it.
    t = read_isomme(r16_folder, ChannelCodes(cd=("11CHST0000H3DS?B",)))
    assert t.cd_mm is not None


def test_inconsistent_sampling_interval(r16_folder: Path):
    _edit(r16_folder / "Channel" / "R16_001.003", "1.000000E-04", "2.000000E-04")
    with pytest.raises(CrashDataError, match=r"R16_001\.003:\d+: key 'Sampling interval'"):
        read_isomme(r16_folder)


def test_units_are_converted(r16_folder: Path):
    ref = read_isomme(DATA / "R16_001")
    p = r16_folder / "Channel" / "R16_001.004"
    lines = p.read_bytes().decode("iso-8859-1").splitlines()
    out = [line.replace(":mm", ":m") if line.startswith("Unit ") else line
           if ":" in line else f"{float(line) / 1000:.9E}" for line in lines]
    p.write_bytes("\r\n".join(out).encode("iso-8859-1"))
    t = read_isomme(r16_folder)
    np.testing.assert_allclose(t.cd_mm, ref.cd_mm, rtol=1e-6)


def test_unknown_unit_is_named(r16_folder: Path):
    _edit(r16_folder / "Channel" / "R16_001.001", "Unit                        :g",
          "Unit                        :furlong")
    with pytest.raises(CrashDataError, match=r"R16_001\.001:\d+: key 'Unit'.*furlong"):
        read_isomme(r16_folder)


def test_brs_needs_counts_per_rev(r16_folder: Path):
    _edit(r16_folder / "R16_001.mme", "96 counts/rev", "high resolution")
    _edit(r16_folder / "Channel" / "R16_001.002", "BRS, 96 counts/rev", "BRS")
    with pytest.raises(CrashDataError, match="counts/rev is unknown"):
        read_isomme(r16_folder)
    assert read_isomme(r16_folder, counts_per_rev=96).counts_per_rev == 96


def test_explicit_time_channel(r16_folder: Path):
    ch = r16_folder / "Channel"
    n = 2200
    times = -0.02 + np.arange(n) * 1e-4
    header = ("Channel code                :TIME\r\nReference channel           :implicit\r\n"
              f"Unit                        :s\r\nNumber of samples           :{n}\r\n")
    (ch / "R16_001.005").write_text(header + "".join(f"{t:.7E}\r\n" for t in times),
                                    encoding="iso-8859-1", newline="")
    for k in (1, 2, 3, 4):
        p = ch / f"R16_001.00{k}"
        _edit(p, "Reference channel           :implicit",
              "Reference channel           :explicit")
        _edit(p, "Reference channel name      :NOVALUE", "Reference channel name      :TIME")
        _edit(p, "Sampling interval           :1.000000E-04",
              "Sampling interval           :NOVALUE")
    t = read_isomme(r16_folder)
    assert t.fs_hz == pytest.approx(10_000) and t.t0_s == pytest.approx(-0.02)
    times[1000] += 5e-5
    (ch / "R16_001.005").write_text(header + "".join(f"{t:.7E}\r\n" for t in times),
                                    encoding="iso-8859-1", newline="")
    with pytest.raises(CrashDataError, match=r"R16_001\.005:\d+: inconsistent sampling"):
        read_isomme(r16_folder)


def test_write_read_roundtrip(tmp_path: Path):
    t = read_isomme(DATA / "R16_002")
    for zip_it in (False, True):
        out = write_isomme(t, tmp_path / str(zip_it), zip_it=zip_it)
        back = read_isomme(out)
        for a, b in ((t.pulse_g, back.pulse_g), (t.brs, back.brs), (t.cr_g, back.cr_g),
                     (t.cd_mm, back.cd_mm)):
            np.testing.assert_allclose(a, b, rtol=1e-6, atol=1e-9)
        assert back.velocity_ms == t.velocity_ms == pytest.approx(14.40)


@pytest.mark.parametrize("value, m_s", [("15.24", 15.24), ("15,24", 15.24),
                                        ("54.864 km/h", 15.24), ("-15.24 m/s", 15.24),
                                        ("NOVALUE", None), ("fast", None), ("56 furlongs", None),
                                        ("nan", None), ("0", None)])
def test_a_stated_velocity_reads_in_its_unit_or_as_none(r16_folder: Path, value: str,
                                                        m_s: float | None):
    # only the loop's screening reads it (against the pulse): a file without a usable one is
    # a file without one, not a broken file
    mme = r16_folder / "R16_001.mme"
    text = mme.read_text(encoding="iso-8859-1")
    assert "Velocity test object 1" in text
    mme.write_text(re.sub(r"(Velocity test object 1\s*:)[^\r\n]*", rf"\g<1>{value}", text),
                   encoding="iso-8859-1", newline="")
    assert read_isomme(r16_folder).velocity_ms == (None if m_s is None else pytest.approx(m_s))


def test_bad_zip_and_missing_paths(tmp_path: Path):
    bad = tmp_path / "broken.zip"
    bad.write_bytes(b"PK\x03\x04 not really")
    with pytest.raises(CrashDataError, match=r"broken\.zip"):
        read_isomme(bad)
    with pytest.raises(CrashDataError, match="no such file"):
        find_tests([tmp_path / "nowhere"])
    (tmp_path / "empty").mkdir()
    with pytest.raises(CrashDataError, match="no crash tests"):
        find_tests([tmp_path / "empty"])
    z = tmp_path / "empty.zip"
    with zipfile.ZipFile(z, "w") as f:
        f.writestr("readme.txt", "nothing")
    with pytest.raises(CrashDataError, match=r"no \.mme"):
        read_isomme(z)


@pytest.mark.parametrize("unit, per_rev", [("counts", None), ("cnt", None), ("deg", 360.0),
                                           ("°", 360.0), ("rad", 2 * np.pi), ("rev", 1.0)])
def test_csv_and_isomme_read_the_same_brs_units(unit, per_rev, tmp_path):
    """One conversion serves both readers: a CSV in any BRS unit gives the ISO-MME counts."""
    from observer_node.data.csvio import read_csv, write_csv

    test = read_isomme(DATA / "R16_002")
    text = write_csv(test, tmp_path / "t.csv").read_text(encoding="utf-8")
    head, rows = text.split("brs[counts]", 1)
    lines = rows.splitlines()
    data = np.loadtxt(lines[1:], delimiter=",")
    if per_rev is not None:
        data[:, 2] *= per_rev / test.counts_per_rev
    out = tmp_path / f"brs_{unit}.csv"
    with out.open("w", encoding="utf-8") as f:
        f.write(head + f"brs[{unit}]" + lines[0] + "\n")
        np.savetxt(f, data, delimiter=",", fmt="%.12g")
    np.testing.assert_array_equal(read_csv(out).brs, test.brs)
    assert read_csv(out).velocity_ms == test.velocity_ms  # the stated velocity kept too


def test_a_late_trigger_does_not_move_the_pulse_bias(campaign):
    # the recorded pulse starts 5 ms before the t = 0 the lab wrote: the crash's onset lies in
    # the pre-contact window the bias is taken from, and must not shift the zero the fits use
    t = next(x for x in campaign if x.name == "FULL_002")
    k = round(0.005 * t.fs_hz)
    early = dataclasses.replace(t, pulse_g=np.concatenate([t.pulse_g[k:], t.pulse_g[-k:]]))
    assert early.pulse_bias_g() == pytest.approx(t.pulse_bias_g(), abs=0.3)


def test_mme_cut_short_is_said(r16_folder: Path):
    """A .mme cut mid-file (a copy stopped early) loses its Comments line and with it the BRS
    resolution: the message says the file ends mid-line rather than only asking for counts."""
    _edit(r16_folder / "Channel" / "R16_001.002", "BRS, 96 counts/rev", "BRS")
    mme = r16_folder / "R16_001.mme"
    mme.write_bytes(mme.read_bytes()[:150])
    with pytest.raises(CrashDataError,
                       match=r"counts/rev is unknown.*ends mid-line at line \d+ with no "
                             r"Comments line after it: cut short\?"):
        read_isomme(r16_folder)


def test_a_campaign_kept_in_folders_is_read_at_any_depth(tmp_path: Path):
    """A campaign kept by year and setup (campaign/2026/R16/R16_001.zip ...) is read whole, in
    name order, hidden folders skipped and a link back up read once."""
    zips = sorted(bundled_campaign().glob("*.zip"))[:3]
    root = tmp_path / "campaign"
    for z, sub in zip(zips, ("2025/R16", "2026/FULL", "2026/SLED/night"), strict=True):
        (root / sub).mkdir(parents=True)
        shutil.copy(z, root / sub / z.name)
    (root / ".trash").mkdir()
    shutil.copy(zips[0], root / ".trash" / "old.zip")
    (root / "2026" / "up").symlink_to(root)
    found = find_tests([root])
    assert [p.relative_to(root).as_posix() for p in found] == [
        f"2025/R16/{zips[0].name}", f"2026/FULL/{zips[1].name}",
        f"2026/SLED/night/{zips[2].name}"]
    (root / "2026" / "up").unlink()
    for z in root.rglob("*.zip"):
        z.unlink()
    with pytest.raises(CrashDataError, match="no crash tests in it or in its folders"):
        find_tests([root])
