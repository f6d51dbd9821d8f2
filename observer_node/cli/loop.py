"""``observer-node loop``: find what the grey-box model lacks, add it, refit, report."""

from __future__ import annotations

import argparse
import os

from .. import options
from ..errors import UsageError
from ..loop.cluster import MAX_LOCAL_WORKERS
from . import _data


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "loop", help="find what the grey-box model lacks, add it, refit, report",
        description="Identify the thesis grey-box model on the estimation tests, analyse its "
        "residual, trace it to a physical effect of the library (or a sparse formula), add it, "
        "refit, and name it only if it beats test-to-test scatter: each estimation test's "
        "cross-validated fit with and without it, paired, must gain --margin points on average "
        "with a 95 % interval above zero (or a sign test, p <= 0.0625), and no setup may lose; "
        "repeat; report fits before and after on the validation tests, which are never fitted "
        "on and refuse an effect whose fit they lower. Two effects the estimation tests cannot "
        "tell apart (a tie) are both listed, neither named, the better carried in model.json "
        "for its fit, unless the validation tests tell them apart by the same rule. Tests that "
        "look broken "
        "(missing, frozen, saturated or spiking channels; a channel copied from another "
        "test; against the other tests of their "
        "setup, a BRS paying out out of step with its pulse, CR and CD out of step, a pulse "
        "at odds with the velocity the test states; a fit far below the others') are "
        "named and left out (docs/loop.md, 'Broken tests'); a one-output static error is "
        "reported as a sensor effect; what nothing explains is reported as unexplained. Tests "
        "are grouped in "
        "setups by their .mme metadata (or --group); each effect is tried on every test and on "
        "the setups that could have it (never an airbag on a hard-seat rig), and "
        "cross-validation chooses. The report gives each effect's scope, the runner-up and its "
        "margin, standard errors and warnings; model.json carries the scope (run --setup).")
    s.add_argument("--estimate", nargs="+", required=True, metavar="TEST",
                   help="tests to identify and cross-validate effects on: " + _data.TESTS_HELP)
    s.add_argument("--validate", nargs="+", required=True, metavar="TEST",
                   help="held-out tests the report scores before and after (never fitted on; "
                   "they refuse an effect whose fit they lower and may tell a tie apart)")
    s.add_argument("--out", required=True, help="output folder")
    s.add_argument("--margin", type=options.non_negative, default=1.0,
                   help="mean paired fit_TOT points an effect must add in cross-validation "
                   "(default %(default)g)")
    s.add_argument("--group", action="append", metavar="NAME=PATTERN",
                   help="put tests whose name matches PATTERN in setup NAME (repeatable; "
                   "default: tests whose .mme has the same type of test, title and test object "
                   "share a setup)")
    s.add_argument("--allow-anywhere", action="store_true",
                   help="try effects on setups whose metadata rules them out too (an airbag "
                   "on a rig that says hard seat or no interior)")
    _data.add_data_arguments(s, data=None, skip=True)
    _data.add_rate_argument(s)
    s.add_argument("--scheduler", metavar="ADDRESS",
                   help="run the refits on the Dask cluster at ADDRESS (tcp://HOST:8786); "
                   "default: a local cluster in this process, one worker per core")
    s.add_argument("--workers", type=int, metavar="N",
                   help="workers of the local cluster (default: one per core, at most "
                   f"{MAX_LOCAL_WORKERS}; four per core at most); not with --scheduler")
    s.add_argument("--quiet", action="store_true", help="no progress display")
    s.set_defaults(func=_do_loop)


def _do_loop(a: argparse.Namespace) -> int:
    from ..data import check_distinct
    from ..data.setups import check_groups, parse_groups
    from ..loop.closed_loop import run_loop
    from ..loop.cluster import check_address

    if a.workers is not None and a.workers < 1:
        raise UsageError(f"--workers {a.workers}: needs at least one worker")
    cores = len(os.sched_getaffinity(0))
    if a.workers is not None and a.workers > 4 * cores:
        # each worker is a process of about 150 MB that would only wait for a core
        raise UsageError(f"--workers {a.workers}: at most {4 * cores} on this machine's "
                         f"{cores} core(s); for more, a Dask cluster (--scheduler)")
    out = options.out_folder(a.out)
    window_s, groups = _data.window(a), parse_groups(a.group)
    if a.scheduler:
        check_address(a.scheduler)
    if a.workers is not None and a.scheduler:
        raise UsageError("--workers sets the local cluster's size; a cluster given by "
                         "--scheduler has the workers it has")
    # the loop screens a test's channels itself (left out with the fits with and without it);
    # --skip-bad-tests leaves out here only what cannot be read
    est, est_out = _data.load_from(a.estimate, a, fit_check=False)
    val, val_out = _data.load_from(a.validate, a, fit_check=False)
    check_distinct(estimation=est, validation=val)
    check_groups(groups, [t.name for t in (*est, *val)])
    with options.staged(out) as tmp:  # an interrupted loop leaves an older report whole
        r = run_loop(est, val, tmp, a.rate, window_s, a.margin,
                     verbose=not a.quiet, groups=groups,
                     anywhere=a.allow_anywhere, scheduler=a.scheduler, workers=a.workers,
                     not_read={**est_out, **val_out})
    print((out / "report.md").read_text())
    print(f"wrote {a.out}/report.json, report.md, model.json and plots "
          f"({r.seconds} s)")
    return 0
