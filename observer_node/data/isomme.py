"""ISO-MME (ISO/TS 13499) crash-test reader and writer.

A test is a folder (or a zip holding one)::

    <TEST>/<TEST>.mme            test information, ``key :value`` lines
    <TEST>/Channel/<TEST>.chn    channel list
    <TEST>/Channel/<TEST>.NNN    one channel: ``key :value`` header, then one value per line

Keys split on the first colon and are stripped; ``NOVALUE`` means missing. Files may be
ISO-8859-1, cp1252 or UTF-8 (with or without BOM), with CRLF or LF line ends. Time is implicit
(``Time of first sample`` + i * ``Sampling interval``) or explicit (``Reference channel
:explicit`` and ``Reference channel name`` naming the time channel's code).

Every error names the file, the line and the key at fault.
"""

from __future__ import annotations

import io
import math
import re
import zipfile
import zlib
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

import numpy as np

from ..units import STANDARD_GRAVITY
from .crashtest import CrashDataError, CrashTest, brs_to_counts, velocity_of

NOVALUE = "NOVALUE"
# Bounds of what a crash-test file can be: anything beyond is a broken or hostile file.
MAX_FILE_BYTES = 64 << 20  # one channel of 1 M samples at ~20 characters a line
MAX_ABS_VALUE = 1e6  # g, m/s^2, mm, deg, counts: no channel of a crash test reaches it
MIN_INTERVAL_S, MAX_INTERVAL_S = 1e-7, 1.0  # 10 MHz .. 1 Hz
MAX_COUNTS_PER_REV = 100_000
_STATUS_OK = {"ok", "okay", "valid", "good"}  # a channel's Data status, its letters only
VELOCITY_KEY = "Velocity test object 1"  # m/s; test object 1 is the vehicle or the sled


@dataclass(frozen=True)
class ChannelCodes:
    """Channel codes searched for each signal, the first code a test has wins; ``?`` matches any
    character, and a code that matches more than one of a test's channels is an error."""

    pulse: tuple[str, ...] = ("S0SLED000000ACXP", "10TUNN000000ACXP")
    brs: tuple[str, ...] = ("11RETR0000B1AN0P",)
    cr: tuple[str, ...] = ("11CHST0000H3ACXC",)
    cd: tuple[str, ...] = ("11CHST0000H3DSXB",)


@dataclass
class Channel:
    code: str
    header: dict[str, str]
    header_lines: dict[str, int]
    values: np.ndarray
    path: str

    def get(self, key: str) -> str | None:
        v = self.header.get(key)
        return None if v is None or v.upper() == NOVALUE else v

    def where(self, key: str) -> str:
        line = self.header_lines.get(key)
        return f"{self.path}:{line}: key '{key}'" if line else f"{self.path}: key '{key}'"

    def number(self, key: str) -> float:
        v = self.get(key)
        if v is None:
            raise CrashDataError(f"{self.where(key)}: missing (or NOVALUE)")
        try:
            x = float(v)
        except ValueError:
            raise CrashDataError(f"{self.where(key)}: not a number: {v!r}") from None
        if not math.isfinite(x):
            raise CrashDataError(f"{self.where(key)}: not a finite number: {v!r}")
        return x


# ---------------------------------------------------------------------------------- text files


def decode_text(raw: bytes) -> str:
    """Decode lab export text: UTF-8 (BOM or not) if valid, else cp1252, else ISO-8859-1."""
    if raw.startswith(b"\xef\xbb\xbf"):
        return raw[3:].decode("utf-8")
    for enc in ("utf-8", "cp1252"):
        try:
            return raw.decode(enc)
        except UnicodeDecodeError:
            pass
    return raw.decode("iso-8859-1")


def parse_header(lines: list[str]) -> tuple[dict[str, str], dict[str, int], int]:
    """Parse leading ``key :value`` lines; return (values, 1-based line numbers, data start)."""
    header: dict[str, str] = {}
    where: dict[str, int] = {}
    i = 0
    for i, line in enumerate(lines):
        if ":" not in line:
            return header, where, i
        key, value = line.split(":", 1)
        key = key.strip()
        header.setdefault(key, value.strip())
        where.setdefault(key, i + 1)
    return header, where, len(lines)


def _is_os_litter(name: str) -> bool:
    """A file an operating system adds beside a test's own: macOS's ``__MACOSX/`` tree and
    ``._*`` resource forks (written into zips and onto FAT/exFAT sticks), ``.DS_Store``,
    Windows's ``Thumbs.db``. Not ISO-MME files: skipped, so a test zipped on a Mac reads."""
    parts = name.split("/")
    base = parts[-1]
    return ("__MACOSX" in parts or base.startswith("._")
            or base.lower() in (".ds_store", "thumbs.db", "desktop.ini"))


class _Source:
    """Files of one test, from a folder or a zip, looked up case-insensitively (an operating
    system's litter beside them skipped)."""

    def __init__(self, path: Path):
        self.path = path
        self.chosen: str | None = None  # the .mme the user named, when a .mme was given
        self.cut: set[str] = set()  # text files read whose last line has no line end
        self._zip: zipfile.ZipFile | None = None
        if path.is_file() and path.suffix.lower() == ".zip":
            try:
                self._zip = zipfile.ZipFile(path)
            except zipfile.BadZipFile as e:
                raise CrashDataError(f"{path}: not a readable zip: {e}") from None
            self.names = [n for n in self._zip.namelist() if not n.endswith("/")]
        elif path.is_dir():
            self.names = [p.relative_to(path).as_posix() for p in path.rglob("*") if p.is_file()]
        elif path.is_file() and path.suffix.lower() == ".mme":
            self.path, self.chosen = path.parent, path.name
            self.names = [
                str(p.relative_to(path.parent).as_posix())
                for p in path.parent.rglob("*") if p.is_file()
            ]
        else:
            raise CrashDataError(f"{path}: not an ISO-MME test folder, .mme file or .zip")
        self.names = [n for n in self.names if not _is_os_litter(n)]

    def label(self, name: str) -> str:
        return f"{self.path}!{name}" if self._zip else str(self.path / name)

    def read(self, name: str) -> list[str]:
        """A text file's lines; sizes are checked before reading (a zip bomb is refused by
        its declared size, a corrupt member by its CRC), each failure naming the file."""
        label = self.label(name)
        try:
            if self._zip:
                size = self._zip.getinfo(name).file_size
                if size > MAX_FILE_BYTES:
                    raise CrashDataError(f"{label}: {size / 2**20:.0f} MiB unpacked, more than "
                                         f"any crash-test file ({MAX_FILE_BYTES >> 20} MiB)")
                raw = self._zip.read(name)
            else:
                p = self.path / name
                if p.stat().st_size > MAX_FILE_BYTES:
                    raise CrashDataError(f"{label}: larger than any crash-test file "
                                         f"({MAX_FILE_BYTES >> 20} MiB)")
                raw = p.read_bytes()
        except (zipfile.BadZipFile, zlib.error, EOFError, NotImplementedError) as e:
            raise CrashDataError(f"{label}: corrupt zip member: {e}") from None
        except OSError as e:
            raise CrashDataError(f"{label}: cannot read: {e.strerror or e}") from None
        if raw and not raw.endswith((b"\n", b"\r")):
            self.cut.add(name)
        return decode_text(raw).splitlines()

    def find(self, suffix_pattern: str) -> list[str]:
        rx = re.compile(suffix_pattern, re.IGNORECASE)
        return sorted(n for n in self.names if rx.search(n))

    def close(self) -> None:
        if self._zip:
            self._zip.close()


def _match(code: str, pattern: str) -> bool:
    return len(code) == len(pattern) and all(
        p in ("?", c) for c, p in zip(code, pattern, strict=True))


def _read_channel(src: _Source, name: str) -> Channel:
    label = src.label(name)
    lines = src.read(name)
    header, where, start = parse_header(lines)
    ch = Channel(header.get("Channel code", ""), header, where, np.empty(0), label)
    values = []
    for k, line in enumerate(lines[start:], start=start + 1):
        s = line.strip()
        if not s:
            continue
        try:
            v = float(s)
        except ValueError:
            raise CrashDataError(f"{label}:{k}: non-numeric value {s!r}") from None
        if not abs(v) <= MAX_ABS_VALUE:  # NaN too
            raise CrashDataError(f"{label}:{k}: value {s!r} is not a finite number within "
                                 f"+-{MAX_ABS_VALUE:g} (no crash channel reaches it)")
        values.append(v)
    arr = np.asarray(values)
    if not len(arr):
        raise CrashDataError(f"{label}: no samples")
    declared = ch.get("Number of samples")
    if declared is not None:
        x = ch.number("Number of samples")
        if not x.is_integer() or x < 1:
            raise CrashDataError(f"{ch.where('Number of samples')}: {declared!r} is not a "
                                 "positive whole number")
        n = int(x)
        if n != len(arr):
            what = "truncated" if len(arr) < n else "longer than declared"
            raise CrashDataError(
                f"{ch.where('Number of samples')}: declares {n} samples, file has {len(arr)} "
                f"({what})"
            )
    ch.values = arr
    return ch


def _counts_per_rev(texts: Iterable[str]) -> int | None:
    for text in texts:
        m = re.search(r"(\d+)\s*counts?\s*/\s*rev", text, re.IGNORECASE)
        if m:
            n = int(m.group(1))
            if not 1 <= n <= MAX_COUNTS_PER_REV:
                raise CrashDataError(f"BRS resolution {m.group(0)!r} in {text!r}: counts/rev "
                                     f"must be 1..{MAX_COUNTS_PER_REV}")
            return n
    return None


_ACCEL_TO_G = {"g": 1.0, "m/s^2": 1 / STANDARD_GRAVITY, "m/s**2": 1 / STANDARD_GRAVITY,
               "m/s2": 1 / STANDARD_GRAVITY, "m/s²": 1 / STANDARD_GRAVITY}
_LENGTH_TO_MM = {"mm": 1.0, "m": 1000.0, "cm": 10.0}


def _convert(ch: Channel, table: dict[str, float], quantity: str) -> np.ndarray:
    unit = (ch.get("Unit") or "").strip()
    factor = table.get(unit) or table.get(unit.lower())
    if factor is None:
        raise CrashDataError(
            f"{ch.where('Unit')}: unit {unit!r} is not a {quantity} unit "
            f"(expected one of {', '.join(table)}) for channel {ch.code}"
        )
    return ch.values * factor


def _brs_counts(ch: Channel, counts_per_rev: int | None, mme_note: str = "") -> np.ndarray:
    return brs_to_counts(ch.values, ch.get("Unit") or "", counts_per_rev, ch.where("Unit"),
                         str(ch.path), "on the command line (--counts-per-rev) or in the .mme "
                         "Comments ('96 counts/rev')" + mme_note)


def _mme_note(mme: dict[str, str], lines: int, cut: bool) -> str:
    """Why the .mme may not say the BRS resolution: no Comments line, or a file cut short
    (its last line without a line end), which a counts/rev message would otherwise hide."""
    if cut:
        return (f"; the .mme ends mid-line at line {lines} with no Comments line after it: "
                "cut short? (copy it again)" if "Comments" not in mme else
                f"; the .mme ends mid-line at line {lines}: cut short? (copy it again)")
    return "" if "Comments" in mme else "; the .mme has no Comments line"


def _time_base(ch: Channel, channels: dict[str, Channel]) -> tuple[float, float]:
    """(t0_s, dt_s) of a channel, checking explicit time channels for a uniform interval."""
    if (ch.get("Reference channel") or "implicit").lower().startswith("explicit"):
        ref = ch.get("Reference channel name")
        tch = channels.get(ref or "")
        if tch is None:
            raise CrashDataError(
                f"{ch.where('Reference channel name')}: explicit time channel {ref!r} not found"
            )
        t = tch.values
        if len(t) != len(ch.values):
            raise CrashDataError(
                f"{tch.path}: time channel has {len(t)} samples, {ch.path} has {len(ch.values)}"
            )
        dt = np.diff(t)
        if len(dt) == 0 or np.ptp(dt) > 1e-6 * abs(np.median(dt)) + 1e-12:
            k = int(np.argmax(np.abs(dt - np.median(dt)))) if len(dt) else 0
            raise CrashDataError(
                f"{tch.path}:{k + 1}: inconsistent sampling interval in explicit time channel"
            )
        return float(t[0]), float(np.median(dt))
    return ch.number("Time of first sample"), ch.number("Sampling interval")


def read_isomme(
    path: str | Path,
    codes: ChannelCodes | None = None,
    counts_per_rev: int | None = None,
    require_outputs: bool = True,
) -> CrashTest:
    """Read one ISO-MME test (folder, ``.mme`` file or zip) into model convention."""
    codes = codes or ChannelCodes()
    src = _Source(Path(path))
    try:
        mmes = src.find(r"\.mme$")
        if not mmes:
            raise CrashDataError(f"{src.path}: no .mme file")
        if src.chosen is None and len(mmes) > 1:  # which test is meant, only the user knows
            raise CrashDataError(f"{src.path}: holds {len(mmes)} .mme files "
                                 f"({', '.join(mmes)}); give the .mme of the test to read")
        mme_name = src.chosen or mmes[0]
        mme_lines = src.read(mme_name)
        mme_cut = mme_name in src.cut
        mme, _, _ = parse_header(mme_lines)
        if not mme:
            raise CrashDataError(f"{src.label(mme_name)}: no 'key :value' lines (empty .mme)")
        if not src.find(r"\.chn$"):
            raise CrashDataError(f"{src.path}: no channel list (<TEST>/Channel/<TEST>.chn)")
        chan_files = src.find(r"\.\d{3}$")
        if len(mmes) > 1:  # another test's files beside it: its own channels only
            stem = PurePosixPath(mme_name).stem.lower()
            chan_files = [n for n in chan_files if PurePosixPath(n).stem.lower() == stem]
        if not chan_files:
            raise CrashDataError(f"{src.label(mme_name)}: no channel files (<TEST>.NNN)")
        channels: dict[str, Channel] = {}
        twins: dict[str, list[Channel]] = {}  # a code more than one file holds
        for name in chan_files:
            ch = _read_channel(src, name)
            if ch.code in channels:
                twins.setdefault(ch.code, [channels[ch.code]]).append(ch)
            channels.setdefault(ch.code, ch)
    finally:
        src.close()

    def pick(label: str, patterns: tuple[str, ...], required: bool) -> Channel | None:
        for p in patterns:
            hits = sorted(code for code in channels if _match(code, p))
            if len(hits) > 1:  # which one the user meant, only the user knows
                raise CrashDataError(f"{src.path}: {label} code {p} matches {len(hits)} "
                                     f"channels ({', '.join(hits)}); give one code")
            if hits:
                code = hits[0]
                if code in twins:  # a backup or a second sensor: which is the test's?
                    raise CrashDataError(
                        f"{src.path}: {len(twins[code])} channel files hold the {label} "
                        f"channel {code} ({', '.join(c.path for c in twins[code])}); "
                        "keep the one the test used")
                return channels[code]
        if required:
            raise CrashDataError(
                f"{src.path}: missing {label} channel (looked for {', '.join(patterns)}; "
                f"test has {', '.join(sorted(channels)) or 'none'})"
            )
        return None

    pulse_ch = pick("crash pulse", codes.pulse, True)
    brs_ch = pick("BRS", codes.brs, True)
    cr_ch = pick("CR", codes.cr, require_outputs)
    cd_ch = pick("CD", codes.cd, require_outputs)
    assert pulse_ch is not None and brs_ch is not None
    seen: dict[str, str] = {}
    for label, picked in (("crash pulse", pulse_ch), ("BRS", brs_ch), ("CR", cr_ch),
                          ("CD", cd_ch)):
        if picked is None:
            continue
        if picked.code in seen:  # one channel as input and output would fit 100 %
            raise CrashDataError(f"{src.path}: channel {picked.code} is given as both the "
                                 f"{seen[picked.code]} and the {label}; check the channel "
                                 "codes")
        seen[picked.code] = label

    used = [c for c in (pulse_ch, brs_ch, cr_ch, cd_ch) if c is not None]
    t0, dt = _time_base(pulse_ch, channels)
    for ch in used[1:]:
        t0c, dtc = _time_base(ch, channels)
        if abs(dtc - dt) > 1e-9 * max(dt, 1e-12) + 1e-12:
            raise CrashDataError(
                f"{ch.where('Sampling interval')}: inconsistent sampling interval {dtc:g} s, "
                f"pulse channel {pulse_ch.path} has {dt:g} s"
            )
        if abs(t0c - t0) > 0.5 * dt:
            raise CrashDataError(
                f"{ch.where('Time of first sample')}: starts at {t0c:g} s, pulse at {t0:g} s"
            )
        if len(ch.values) != len(pulse_ch.values):
            raise CrashDataError(
                f"{ch.path}: {len(ch.values)} samples, pulse channel has {len(pulse_ch.values)}"
            )
    if not MIN_INTERVAL_S <= dt <= MAX_INTERVAL_S:
        raise CrashDataError(f"{pulse_ch.where('Sampling interval')}: {dt:g} s is not a crash "
                             f"test's ({MIN_INTERVAL_S:g} to {MAX_INTERVAL_S:g} s)")
    if counts_per_rev is not None and not 1 <= counts_per_rev <= MAX_COUNTS_PER_REV:
        raise CrashDataError(f"--counts-per-rev {counts_per_rev}: must be "
                             f"1..{MAX_COUNTS_PER_REV}")

    # the lab's own verdict on a channel (ISO-MME "Data status"): anything but ok is kept, for
    # the loop's screening to leave the test out with the lab's words
    status = {role: st for role, ch in (("pulse", pulse_ch), ("brs", brs_ch), ("cr", cr_ch),
                                        ("cd", cd_ch))
              if ch is not None and (st := (ch.get("Data status") or "ok").strip())
              and re.sub(r"[^a-z]", "", st.lower()) not in _STATUS_OK}
    per_rev = counts_per_rev or _counts_per_rev(
        [mme.get("Comments", ""), brs_ch.get("Name of the channel") or "",
         *(v for k, v in mme.items() if k.startswith("Name of channel"))]
    )
    name = mme.get("Laboratory test ref. number") or PurePosixPath(mme_name).stem
    if name.upper() == NOVALUE:
        name = PurePosixPath(mme_name).stem
    # SAE J211 (X forward) -> model convention (deceleration, retardation, compression positive)
    return CrashTest(
        name=name,
        fs_hz=1.0 / dt,
        t0_s=t0,
        pulse_g=-_convert(pulse_ch, _ACCEL_TO_G, "acceleration"),
        brs=_brs_counts(brs_ch, per_rev, _mme_note(mme, len(mme_lines), mme_cut)),
        cr_g=None if cr_ch is None else -_convert(cr_ch, _ACCEL_TO_G, "acceleration"),
        cd_mm=None if cd_ch is None else -_convert(cd_ch, _LENGTH_TO_MM, "length"),
        setup=setup_of(name, mme),
        counts_per_rev=per_rev,
        velocity_ms=velocity_of(mme.get(VELOCITY_KEY, "")),
        status=status,
        source=str(path),
        meta={k: v for k, v in mme.items() if v.upper() != NOVALUE},
    )


def setup_of(name: str, mme: dict[str, str]) -> str:
    """Setup family (R16, SLED, FULL, ...) from the test name prefix when it is a word of
    letters and digits (not a number, not a path: a setup names output files), else the test
    type."""
    prefix = re.split(r"[_\-\s]", name)[0].upper()
    if re.fullmatch(r"[A-Z0-9]+", prefix) and not prefix.isdigit():
        return prefix
    return (mme.get("Type of the test") or "UNKNOWN").upper()


# ---------------------------------------------------------------------------------- writer

_CODES_OUT = {
    "pulse": ("S0SLED000000ACXP", "SLED X ACCELERATION", "g", "AC"),
    "brs": ("11RETR0000B1AN0P", "Belt spindle rotation, + = retraction", "deg", "AN"),
    "cr": ("11CHST0000H3ACXC", "Chest acceleration X", "g", "AC"),
    "cd": ("11CHST0000H3DSXB", "Chest deflection X", "mm", "DS"),
}


def write_isomme(test: CrashTest, folder: str | Path, zip_it: bool = False) -> Path:
    """Write ``test`` as an ISO-MME folder ``folder/<name>`` (SAE J211 signs, BRS in deg, CRLF,
    ISO-8859-1), or as ``folder/<name>.zip`` when ``zip_it``. Returns the path written."""
    if test.counts_per_rev is None:
        raise CrashDataError(f"{test.name}: counts_per_rev is needed to write BRS in degrees")
    files: dict[str, str] = {}
    signals = {
        "pulse": -test.pulse_g,
        "brs": test.brs * 360.0 / test.counts_per_rev,
        "cr": None if test.cr_g is None else -test.cr_g,
        "cd": None if test.cd_mm is None else -test.cd_mm,
    }
    present = [(k, v) for k, v in signals.items() if v is not None]
    mme = {
        "Data format edition number": "1.6",
        "Laboratory test ref. number": test.name,
        "Title": test.meta.get("Title", "SIMULATED CRASH TEST"),
        "Comments": f"BRS resolution {test.counts_per_rev} counts/rev, bidirectional",
        **({VELOCITY_KEY: f"{test.velocity_ms:.2f}"} if test.velocity_ms else {}),
        "Number of channels": str(len(present)),
    }
    chn = {}
    for i, (key, values) in enumerate(present, start=1):
        code, text, unit, dim = _CODES_OUT[key]
        mme[f"Name of channel {i:03d}"] = f"{code} / {text}"
        chn[f"Name of channel {i:03d}"] = f"{code} / {text}"
        header = {
            "Channel code": code, "Name of the channel": text, "Reference channel": "implicit",
            "Sampling interval": f"{1.0 / test.fs_hz:.6E}", "Unit": unit,
            "Time of first sample": f"{test.t0_s:.6E}", "Number of samples": str(len(values)),
            "Dimension": dim, "Data status": test.status.get(key, "ok"),  # not laundered
        }
        body = "".join(f"{v:.6E}\r\n" for v in values)
        files[f"Channel/{test.name}.{i:03d}"] = _kv(header) + body
    files[f"{test.name}.mme"] = _kv(mme)
    files[f"Channel/{test.name}.chn"] = _kv(chn)

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    if zip_it:
        out = folder / f"{test.name}.zip"
        with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
            for rel, text in files.items():
                z.writestr(f"{test.name}/{rel}", text.encode("iso-8859-1"))
        return out
    out = folder / test.name
    for rel, text in files.items():
        p = out / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(text.encode("iso-8859-1"))
    return out


def _kv(d: dict[str, str]) -> str:
    buf = io.StringIO()
    for k, v in d.items():
        buf.write(f"{k:<28}:{v}\r\n")
    return buf.getvalue()
