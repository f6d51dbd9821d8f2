"""Crash-test data: readers, writers and the model's sign convention (see :mod:`.crashtest`)."""

from __future__ import annotations

import fnmatch
import hashlib
from pathlib import Path

from ..errors import one_line
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
    "check_distinct",
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


TEST_SUFFIXES = (".zip", ".csv", ".mme")


def _is_test(p: Path) -> bool:
    """A test's file by its name (a pipe or a broken link so named too: read, it is refused
    by name), or an ISO-MME test folder: a .mme beside its channel list (``.chn``, in it or
    in its Channel folder). A .mme alone in a folder of tests is a test of its own, not the
    folder's (a template beside a campaign)."""
    if not p.is_dir():
        return p.suffix.lower() in TEST_SUFFIXES
    try:
        files = [c for c in p.iterdir() if c.is_file()]
        if not any(c.suffix.lower() == ".mme" for c in files):
            return False
        return any(c.suffix.lower() == ".chn" for c in files) or any(
            c.suffix.lower() == ".chn" for d in p.iterdir() if d.is_dir() for c in d.iterdir())
    except OSError as e:
        raise CrashDataError(f"{e.filename or p}: cannot read: {e.strerror or e}") from None


def find_tests(paths: list[str | Path]) -> list[Path]:
    """Expand each path to crash tests: a test (folder, zip, csv, .mme), a folder of tests or
    of folders of tests (at any depth), or the bundled campaign by name (see
    :func:`bundled_campaign`; a local file of that name wins)."""
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
        if not p.is_dir():
            raise CrashDataError(f"{p}: not a crash test (an ISO-MME folder, .zip, .csv or "
                                 ".mme) nor a folder of them")
        inner = _tests_under(p)
        if not inner:
            raise CrashDataError(f"{p}: no crash tests in it or in its folders (ISO-MME "
                                 "folders, .zip or .csv)")
        found.extend(inner)
    return found


def _tests_under(folder: Path, seen: set[Path] | None = None) -> list[Path]:
    """The tests in a folder and, for a folder that is not a test, in its folders (a campaign
    kept by year or by setup), in name order; hidden files and folders skipped, a folder
    reached twice (a link back up) read once."""
    seen = set() if seen is None else seen
    real = folder.resolve()
    if real in seen:
        return []
    seen.add(real)
    found: list[Path] = []
    try:
        for c in sorted(folder.iterdir()):
            if c.name.startswith(".") or c.name == "__MACOSX":  # hidden, or a Mac's litter
                continue
            if _is_test(c):
                found.append(c)
            elif c.is_dir():
                found.extend(_tests_under(c, seen))
    except OSError as e:
        raise CrashDataError(f"{e.filename or folder}: cannot read: {e.strerror or e}") from None
    return found


def load_test(path: str | Path, codes: ChannelCodes | None = None,
              counts_per_rev: int | None = None, require_outputs: bool = True) -> CrashTest:
    p = Path(path)
    if not (p.is_file() or p.is_dir()):  # a pipe would block the read for ever
        raise CrashDataError(f"{p}: " + ("a broken link" if p.is_symlink() else
                                         "not a file (a pipe, socket or device)"))
    if p.suffix.lower() == ".csv":
        test = read_csv(p, counts_per_rev)
        if require_outputs and not test.has_outputs:
            raise CrashDataError(f"{p}: needs cr and cd columns")
    else:
        test = read_isomme(p, codes, counts_per_rev, require_outputs)
    # A name is printed in tables, reports and plots: a control character in a file's name
    # (an ESC that clears the terminal, a newline that splits a row) is kept as its escape.
    test.name = one_line(test.name)
    return test


def load_tests(paths: list[str | Path], codes: ChannelCodes | None = None,
               counts_per_rev: int | None = None, require_outputs: bool = True) -> list[CrashTest]:
    """Read every crash test under ``paths`` (see :func:`find_tests`)."""
    return [load_test(p, codes, counts_per_rev, require_outputs) for p in find_tests(paths)]


def _fingerprint(t: CrashTest) -> str:
    """A digest of a test's recorded samples (not its name or metadata)."""
    h = hashlib.sha1(usedforsecurity=False)
    for a in (t.pulse_g, t.brs, t.cr_g, t.cd_mm):
        h.update(b"-" if a is None else a.tobytes())
    return h.hexdigest()


def check_distinct(**roles: list[CrashTest]) -> None:
    """Refuse the same crash twice among tests given in roles (``estimation=[...],
    validation=[...]``): one name twice (a test in both roles, or an .mme naming itself as
    another test), or one recording under two names (a copied file). Either would let a test
    score the fit it was part of, or count one crash as two in the rule's scatter. Raises
    :class:`CrashDataError` naming both files."""
    seen_name: dict[str, tuple[str, CrashTest]] = {}
    seen_data: dict[str, tuple[str, CrashTest]] = {}
    for role, tests in roles.items():
        for t in tests:
            where = f"{t.source or t.name} ({role})"
            if t.name in seen_name:
                r0, t0 = seen_name[t.name]
                raise CrashDataError(f"{where}: test {t.name} is given twice, also as "
                                     f"{t0.source or t0.name} ({r0}): each crash once")
            fp = _fingerprint(t)
            if fp in seen_data:
                r0, t0 = seen_data[fp]
                raise CrashDataError(f"{where}: test {t.name} holds the same samples as "
                                     f"{t0.name}, {t0.source or t0.name} ({r0}): one crash "
                                     "under two names (a copied file?)")
            seen_name[t.name], seen_data[fp] = (role, t), (role, t)
