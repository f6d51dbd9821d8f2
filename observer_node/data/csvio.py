"""Plain CSV crash tests: ``# key: value`` comment lines, a header of ``name[unit]`` columns,
then one row per sample.

Example::

    # name: R16_001
    # counts_per_rev: 96
    # velocity_ms: 14.40     (optional: the stated impact velocity, m/s)
    # status: cd=defect      (optional: channels the lab did not pass as ok)
    # signs: model          (or: sae-j211)
    time[s],pulse[g],brs[counts],cr[g],cd[mm]
    -0.0200,0.0231,0,-0.011,0.002

Columns are found by name (``time``, ``pulse``, ``brs``, ``cr``, ``cd``; ``cr`` and ``cd`` are
optional) and converted from their unit (g or m/s^2; counts, deg or rad; mm or m). With
``signs: sae-j211`` the pulse, CR and CD are negated into model convention on reading.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..units import STANDARD_GRAVITY
from .crashtest import CrashDataError, CrashTest, brs_to_counts, velocity_of
from .isomme import decode_text

_UNITS = {
    "pulse": {"g": 1.0, "m/s^2": 1 / STANDARD_GRAVITY, "m/s2": 1 / STANDARD_GRAVITY},
    "cr": {"g": 1.0, "m/s^2": 1 / STANDARD_GRAVITY, "m/s2": 1 / STANDARD_GRAVITY},
    "cd": {"mm": 1.0, "m": 1000.0},
    "time": {"s": 1.0, "ms": 1e-3},
}


def write_csv(test: CrashTest, path: str | Path) -> Path:
    """Write ``test`` in model convention."""
    path = Path(path)
    cols = [test.time_s, test.pulse_g, test.brs]
    names = ["time[s]", "pulse[g]", "brs[counts]"]
    if test.cr_g is not None and test.cd_mm is not None:
        cols += [test.cr_g, test.cd_mm]
        names += ["cr[g]", "cd[mm]"]
    head = [f"# name: {test.name}", f"# setup: {test.setup}", "# signs: model"]
    if test.counts_per_rev:
        head.append(f"# counts_per_rev: {test.counts_per_rev}")
    if test.velocity_ms:
        head.append(f"# velocity_ms: {test.velocity_ms:.2f}")
    if test.status:  # kept, not laundered: the loop leaves such a test out
        head.append("# status: " + "; ".join(f"{k}={v}" for k, v in test.status.items()))
    data = np.column_stack(cols)
    with path.open("w", encoding="utf-8", newline="\n") as f:
        f.write("\n".join([*head, ",".join(names)]) + "\n")
        np.savetxt(f, data, delimiter=",", fmt="%.9g")
    return path


def read_csv(path: str | Path, counts_per_rev: int | None = None) -> CrashTest:
    path = Path(path)
    lines = decode_text(path.read_bytes()).splitlines()
    meta: dict[str, str] = {}
    said_at: dict[str, int] = {}
    k = 0
    while k < len(lines) and lines[k].lstrip().startswith("#"):
        if ":" in lines[k]:
            key, value = lines[k].lstrip("# ").split(":", 1)
            key = key.strip().lower()
            if key in _ONCE and key in said_at:  # which one is meant, only the author knows
                raise CrashDataError(f"{path}:{k + 1}: a second '{key}' line (the first is "
                                     f"line {said_at[key]})")
            if key in ("name", "setup") and not value.strip():
                raise CrashDataError(f"{path}:{k + 1}: the '{key}' line gives no {key}")
            said_at[key] = k + 1
            meta[key] = value.strip()
        k += 1
    if k >= len(lines):
        raise CrashDataError(f"{path}: no header row")
    header_line = k + 1
    columns: dict[str, tuple[int, str]] = {}
    for i, col in enumerate(lines[k].split(",")):
        m = re.fullmatch(r"\s*([A-Za-z_]+)\s*(?:\[(.*)\])?\s*", col)
        if not m:
            raise CrashDataError(f"{path}:{header_line}: bad column header {col!r}")
        name = m.group(1).lower()
        if name in columns:  # which of the two is the test's, only the file's author knows
            raise CrashDataError(f"{path}:{header_line}: column {name!r} appears twice")
        columns[name] = (i, (m.group(2) or "").strip())
    for need in ("time", "pulse", "brs"):
        if need not in columns:
            raise CrashDataError(f"{path}:{header_line}: missing column {need!r}")
    rows = []
    for j, line in enumerate(lines[k + 1:], start=header_line + 1):
        if not line.strip():
            continue
        if line.lstrip().startswith("#"):
            raise CrashDataError(f"{path}:{j}: a comment line among the data (comment lines, "
                                 "such as '# setup:', go above the header row)")
        parts = line.split(",")
        if len(parts) != len(columns):
            raise CrashDataError(
                f"{path}:{j}: {len(parts)} values, header has {len(columns)} columns"
            )
        try:
            rows.append([float(p) for p in parts])
        except ValueError:
            raise CrashDataError(f"{path}:{j}: non-numeric value in {line.strip()!r}") from None
    if len(rows) < 2:
        raise CrashDataError(f"{path}: fewer than two samples")
    data = np.asarray(rows)
    if not np.all(np.isfinite(data)):
        j = int(np.flatnonzero(~np.isfinite(data).all(axis=1))[0])
        raise CrashDataError(f"{path}: row {j + 1} of data has a value that is not finite")

    def column(name: str) -> np.ndarray | None:
        if name not in columns:
            return None
        i, unit = columns[name]
        if name == "brs":
            return _brs(data[:, i], unit, counts_per_rev or _int(meta.get("counts_per_rev")), path)
        factor = _UNITS[name].get(unit.lower() if unit != "m/s^2" else unit)
        if factor is None:
            raise CrashDataError(f"{path}:{header_line}: column {name!r} unit {unit!r} unknown")
        return data[:, i] * factor

    t = column("time")
    assert t is not None
    dt = np.diff(t)
    if np.any(dt <= 0) or np.ptp(dt) > 1e-3 * np.median(dt):
        j = int(np.argmax(np.abs(dt - np.median(dt))))
        raise CrashDataError(f"{path}:{header_line + 2 + j}: inconsistent sampling interval")
    sign = -1.0 if meta.get("signs", "model").lower().startswith("sae") else 1.0
    cr, cd = column("cr"), column("cd")
    pulse = column("pulse")
    brs = column("brs")
    assert pulse is not None and brs is not None
    return CrashTest(
        name=meta.get("name", path.stem), fs_hz=1.0 / float(np.median(dt)), t0_s=float(t[0]),
        pulse_g=sign * pulse, brs=brs,
        cr_g=None if cr is None else sign * cr, cd_mm=None if cd is None else sign * cd,
        setup=meta.get("setup", path.stem.split("_")[0].upper()),
        counts_per_rev=counts_per_rev or _int(meta.get("counts_per_rev")),
        velocity_ms=velocity_of(meta.get("velocity_ms", "")),
        status=dict(item.split("=", 1) for item in re.split(r"\s*;\s*", meta.get("status", ""))
                    if item.count("=") == 1),
        source=str(path), meta=meta,
    )


#: header keys a test has one of: a second line giving one is refused, not read over the first
_ONCE = frozenset({"name", "setup", "signs", "counts_per_rev", "velocity_ms", "status"})


def _int(v: str | None) -> int | None:
    return int(v) if v and v.isdigit() else None


def _brs(values: np.ndarray, unit: str, per_rev: int | None, path: Path) -> np.ndarray:
    return brs_to_counts(values, unit, per_rev, f"{path}: column brs", str(path),
                         "in a '# counts_per_rev: N' line or with --counts-per-rev")
