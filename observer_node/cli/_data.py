"""The options every command that reads crash tests shares: which tests, their channel codes,
the BRS resolution, the scoring window and the tick rate; the defaults are the data
module's."""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

from ..data import (
    BUNDLED_NAME,
    ChannelCodes,
    CrashTest,
    bundled_campaign,
    check_distinct,
    load_tests,
)
from ..data.crashtest import THESIS_WINDOW_S
from ..errors import UsageError

TESTS_HELP = (f"an ISO-MME test folder, .zip or .csv, a folder of them, or "
              f"{BUNDLED_NAME}[/PATTERN]")
RATE_HZ = 1000.0  # the DBC's sensor rate: one TunnelAccel frame, one tick per ms
MIN_WINDOW_S = 0.02  # a scoring window shorter than this holds too little of a crash to judge


def finite(text: str) -> float:
    """An argparse type: a finite number (nan and inf would pass ``float`` and fail far on)."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return x


def positive(text: str) -> float:
    """An argparse type: a finite number above zero."""
    x = finite(text)
    if x <= 0:
        raise argparse.ArgumentTypeError(f"must be above zero: {text!r}")
    return x


def non_negative(text: str) -> float:
    """An argparse type: a finite number, zero or above."""
    x = finite(text)
    if x < 0:
        raise argparse.ArgumentTypeError(f"must be zero or above: {text!r}")
    return x


def _whole(text: str, low: int) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if n < low:
        raise argparse.ArgumentTypeError(f"must be {low} or more: {text!r}")
    return n


def positive_int(text: str) -> int:
    """An argparse type: a whole number above zero."""
    return _whole(text, 1)


def non_negative_int(text: str) -> int:
    """An argparse type: a whole number, zero or above."""
    return _whole(text, 0)


def out_file(path: str, option: str = "--out") -> Path:
    """``path`` as an output file, checked before any work: not a folder, and its folder is
    one or can be made (see :func:`out_folder`)."""
    p = Path(path)
    if p.is_dir() or not p.name:
        raise UsageError(f"{option} {path}: is a folder; give a file name")
    _can_make(p.parent, f"{option} {path}")
    return p


def out_folder(path: str, option: str = "--out") -> Path:
    """``path`` as an output folder, checked before any work: it is a folder or can be made
    one (the nearest existing parent a writable folder). Not created here, so a command that
    fails on its input leaves nothing behind."""
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise UsageError(f"{option} {path}: is a file")
    _can_make(p, f"{option} {path}")
    return p


def _can_make(folder: Path, said: str) -> None:
    """One line, starting with ``said``, unless ``folder`` is a folder or can be made one."""
    probe = folder
    while not probe.exists() and probe != probe.parent:
        probe = probe.parent
    if not probe.is_dir():
        raise UsageError(f"{said}: cannot be made: {probe} is a file")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise UsageError(f"{said}: cannot write in {probe} (permission denied)")


def add_data_arguments(p: argparse.ArgumentParser, data: str | None) -> None:
    """Options that say how to read crash tests; ``data``: "required", "optional" (default the
    bundled campaign) or None (the command names its tests in other options)."""
    codes = ChannelCodes()
    g = p.add_argument_group("crash-test data")
    if data is not None:
        g.add_argument("--data", nargs="+", required=data == "required", metavar="TEST",
                       help="crash tests: " + TESTS_HELP
                       + ("" if data == "required" else f" (default: {BUNDLED_NAME})"))
    g.add_argument("--pulse-code", action="append", metavar="CODE",
                   help="channel code of the crash pulse ('?' matches any character; "
                   f"repeatable; default {', '.join(codes.pulse)})")
    g.add_argument("--brs-code", action="append", metavar="CODE",
                   help=f"BRS channel code (default {', '.join(codes.brs)})")
    g.add_argument("--cr-code", action="append", metavar="CODE",
                   help=f"chest acceleration channel code (default {', '.join(codes.cr)})")
    g.add_argument("--cd-code", action="append", metavar="CODE",
                   help=f"chest deflection channel code (default {', '.join(codes.cd)})")
    g.add_argument("--counts-per-rev", type=int, metavar="N",
                   help="BRS counts per spindle revolution (default: from the test's comments)")
    start, end = THESIS_WINDOW_S
    g.add_argument("--window", nargs=2, type=non_negative, metavar=("START", "END"),
                   help=f"scoring window in s from time zero, at least {MIN_WINDOW_S:g} s "
                   f"long (default {start:g} {end:g}, the thesis's)")


def add_rate_argument(p: argparse.ArgumentParser, what: str = "") -> None:
    p.add_argument("--rate", type=positive, default=RATE_HZ,
                   help=f"tick rate in Hz{what} (default %(default)g, the bus rate)")


def channel_codes(a: argparse.Namespace) -> ChannelCodes:
    d = ChannelCodes()
    return ChannelCodes(
        pulse=tuple(a.pulse_code or d.pulse), brs=tuple(a.brs_code or d.brs),
        cr=tuple(a.cr_code or d.cr), cd=tuple(a.cd_code or d.cd),
    )


def window(a: argparse.Namespace) -> tuple[float, float]:
    """The scoring window in s: --window, else the thesis's; one line for a window that ends
    before it starts or is too short to hold a crash."""
    if not a.window:
        return THESIS_WINDOW_S
    start, end = a.window
    if end - start < MIN_WINDOW_S:
        raise UsageError(f"--window {start:g} {end:g}: END must come at least {MIN_WINDOW_S:g} s "
                         "after START (a crash's chest response lasts about 0.1 s)")
    return (start, end)


def load(a: argparse.Namespace) -> list[CrashTest]:
    """The tests --data names, else the bundled campaign (each crash once)."""
    tests = load_tests(a.data or [bundled_campaign()], channel_codes(a), a.counts_per_rev)
    check_distinct(data=tests)
    return tests
