"""The options every command that reads crash tests shares: which tests, their channel codes,
the BRS resolution, the scoring window and the tick rate; the defaults are the data
module's."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..data import (
    BUNDLED_NAME,
    ChannelCodes,
    CrashDataError,
    CrashTest,
    bundled_campaign,
    check_distinct,
    find_tests,
    load_test,
    load_tests,
)
from ..data.crashtest import THESIS_WINDOW_S
from ..data.isomme import MAX_COUNTS_PER_REV
from ..errors import UsageError, one_line
from ..options import int_in, non_negative, positive

TESTS_HELP = (f"an ISO-MME test folder, .zip or .csv, a folder of them, or "
              f"{BUNDLED_NAME}[/PATTERN]")
RATE_HZ = 1000.0  # the DBC's sensor rate: one TunnelAccel frame, one tick per ms
MIN_WINDOW_S = 0.02  # a scoring window shorter than this holds too little of a crash to judge


def add_data_arguments(p: argparse.ArgumentParser, data: str | None, skip: bool = False
                       ) -> None:
    """Options that say how to read crash tests; ``data``: "required", "optional" (default the
    bundled campaign) or None (the command names its tests in other options); ``skip``:
    offer --skip-bad-tests without --data."""
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
    g.add_argument("--counts-per-rev", type=int_in(1, MAX_COUNTS_PER_REV), metavar="N",
                   help="BRS counts per spindle revolution (default: from the test's comments)")
    if data is not None or skip:
        g.add_argument("--skip-bad-tests", action="store_true",
                       help="leave out each test that cannot be read or fitted (a damaged "
                       "file, a dead channel, too short), name it and why on stderr and in "
                       "the output's JSON, and go on with the rest (default: the first such "
                       "test stops the run, exit 2)")
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
    if end - start < MIN_WINDOW_S - 1e-9:  # 0.03 - 0.01 is 0.0199999... in binary
        raise UsageError(f"--window {start:g} {end:g}: END must come at least {MIN_WINDOW_S:g} s "
                         "after START (a crash's chest response lasts about 0.1 s)")
    return (start, end)


def load(a: argparse.Namespace, rate_hz: float | None = None,
         window_s: tuple[float, float] | None = None) -> tuple[list[CrashTest], dict[str, str]]:
    """The tests --data names, else the bundled campaign (each crash once), and those left out
    by --skip-bad-tests (path: why; each also said on stderr), checked at ``rate_hz`` and
    ``window_s`` (default --rate and --window: a model file's own when it is scored)."""
    tests, left_out = load_from(a.data or [bundled_campaign()], a, fit_check=True,
                                rate_hz=rate_hz, window_s=window_s)
    check_distinct(data=tests)  # one crash twice: which copy to keep, only the user knows
    return tests, left_out


def load_from(paths: list[str | Path], a: argparse.Namespace, fit_check: bool,
              rate_hz: float | None = None, window_s: tuple[float, float] | None = None
              ) -> tuple[list[CrashTest], dict[str, str]]:
    """The tests under ``paths``; with --skip-bad-tests, those that cannot be read (and, with
    ``fit_check``, cannot be fitted or scored: a dead channel, too short) left out and
    returned as path: why, each said on stderr and counted. Without it the first bad test
    raises :class:`CrashDataError`."""
    if not a.skip_bad_tests:
        return load_tests(paths, channel_codes(a), a.counts_per_rev), {}
    from ..ident.dataset import make_dataset

    found = find_tests(paths)
    tests: list[CrashTest] = []
    left_out: dict[str, str] = {}
    for p in found:
        try:
            t = load_test(p, channel_codes(a), a.counts_per_rev)
            if fit_check:
                # what a fit or a score checks of a test
                make_dataset([t], rate_hz or a.rate, window_s or window(a))
        except CrashDataError as e:
            left_out[str(p)] = str(e)
            said = str(e) if str(p) in str(e) else f"{p}: {e}"  # each line names its file
            print(f"left out: {one_line(said)}", file=sys.stderr)
            continue
        tests.append(t)
    if not tests:
        raise CrashDataError(f"every one of the {len(found)} test(s) is bad (each named above): "
                             "nothing left to work on")
    if left_out:
        print(f"left out {len(left_out)} of {len(found)} test(s) (--skip-bad-tests; each named "
              "above)", file=sys.stderr)
    return tests, left_out
