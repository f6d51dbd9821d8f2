"""Crash-test data: readers, writers and the model's sign convention (see :mod:`.crashtest`)."""

from __future__ import annotations

import fnmatch
from pathlib import Path

from ..units import STANDARD_GRAVITY
from .crashtest import (
    THESIS_WINDOW_S,
    CrashDataError,
    CrashTest,
    resample_inputs,
)
from .csvio import read_csv, write_csv
from .isomme import ChannelCodes, read_isomme, write_isomme

__all__ = [
    "BENCH_TESTS",
    "BUNDLED_NAME",
    "STANDARD_GRAVITY",
    "THESIS_WINDOW_S",
    "ChannelCodes",
    "CrashDataError",
    "CrashTest",
    "bundled_campaign",
    "find_tests",
    "load_test",
    "load_tests",
    "read_csv",
    "read_isomme",
    "resample_inputs",
    "write_csv",
    "write_isomme",
]


BUNDLED_NAME = "campaign-a"
# The bundled tests `observer-node bench` replays by default: one of each setup.
BENCH_TESTS = ("R16_002", "SLED_002", "FULL_002")


def bundled_campaign() -> Path:
    """Folder of the example crash tests shipped with the package: campaign A, 24 zipped
    ISO-MME tests (R16_001-012 sled rig, SLED_001-006 sled with interior, FULL_001-006 full
    vehicle). Data arguments name it ``campaign-a``, or ``campaign-a/PATTERN`` for the tests
    whose names match a shell pattern (``campaign-a/*[13579]``: the odd-numbered ones)."""
    return Path(__file__).resolve().parent.parent / "examples"


def _bundled(raw: str) -> list[Path] | None:
    """The bundled tests ``raw`` names (``campaign-a`` or ``campaign-a/PATTERN``), else None."""
    name, _, pattern = raw.replace("\\", "/").partition("/")
    if name != BUNDLED_NAME:
        return None
    tests = sorted(bundled_campaign().glob("*.zip"))
    if not pattern:
        return tests
    chosen = [t for t in tests if fnmatch.fnmatchcase(t.stem, pattern.removesuffix(".zip"))]
    if not chosen:
        raise CrashDataError(f"{raw}: no bundled test matches {pattern!r} (tests: "
                             f"{tests[0].stem} .. {tests[-1].stem})")
    return chosen


def _is_test(p: Path) -> bool:
    if p.is_file():
        return p.suffix.lower() in (".zip", ".csv", ".mme")
    return any(c.suffix.lower() == ".mme" for c in p.iterdir() if c.is_file())


def find_tests(paths: list[str | Path]) -> list[Path]:
    """Expand each path to crash tests: a test (folder, zip, csv, .mme), a folder of tests, or
    the bundled campaign by name (see :func:`bundled_campaign`; a local file of that name wins).
    """
    found: list[Path] = []
    for raw in paths:
        p = Path(raw)
        if not p.exists():
            bundled = _bundled(str(raw))
            if bundled is not None:
                found.extend(bundled)
                continue
            raise CrashDataError(f"{p}: no such file or folder")
        if _is_test(p):
            found.append(p)
            continue
        inner = sorted(c for c in p.iterdir() if not c.name.startswith(".") and _is_test(c))
        if not inner:
            raise CrashDataError(f"{p}: no crash tests in it (ISO-MME folders, .zip or .csv)")
        found.extend(inner)
    return found


def load_test(path: str | Path, codes: ChannelCodes | None = None,
              counts_per_rev: int | None = None, require_outputs: bool = True) -> CrashTest:
    p = Path(path)
    if p.suffix.lower() == ".csv":
        test = read_csv(p, counts_per_rev)
        if require_outputs and not test.has_outputs:
            raise CrashDataError(f"{p}: needs cr and cd columns")
        return test
    return read_isomme(p, codes, counts_per_rev, require_outputs)


def load_tests(paths: list[str | Path], codes: ChannelCodes | None = None,
               counts_per_rev: int | None = None, require_outputs: bool = True) -> list[CrashTest]:
    """Read every crash test under ``paths`` (see :func:`find_tests`)."""
    return [load_test(p, codes, counts_per_rev, require_outputs) for p in find_tests(paths)]
