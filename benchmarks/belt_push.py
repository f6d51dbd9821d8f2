"""Where the thesis grey-box's belt pushes, and what a belt that cannot push costs it.

The grey-box's belt force k2 e + c2 e' (e = w - s, the belt penetration) is linear: it pushes
wherever that is negative. A real webbing cannot push, which is the library's
``belt_unloading``. On the independent held-out sets that effect never passes the loop's rule,
not even where the simulator's webbing has a hysteresis or a permanent set; this tool shows
why, case by case (cases already seen: a diagnosis, not evidence):

1. per estimation test, the grey-box identified on the case's estimation tests: the belt's
   peak force [N], how long it pushes [ms of the record's 151 samples] and by how much at most
   [N], and how many of the pushing milliseconds fall in each 10 ms of the record (the last
   window holding 11 samples), so when: loading or rebound;
2. each one-sided belt judged by the loop's rule against the grey-box (refitted, cross-validated
   leave-one-test-out, margin 1 point) on every setup (``form_screen`` judges a form on the
   truth's scope instead), alone and beside the library's ``pelvis_coupling`` (a two-sided
   spine-vehicle path that could hold a rebound in the belt's place): the mean gain [points],
   tests improved, the validation fit_TOT [%]. The forms: the library's switch
   (``belt_unloading``) and form_screen's trial forms of that kind (``belt_off_chest``,
   ``belt_set_memory``, ``belt_set_memory_push``, ``belt_unload_drop``).

    python -m benchmarks.belt_push CASE_DIR [CASE_DIR ...] [--forms belt_unloading,...]

A CASE_DIR holds ``est/`` and ``val/`` (``make_sets`` output: ``SETS_DIR/CASE``).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Mapping
from contextlib import ExitStack
from itertools import pairwise
from pathlib import Path
from typing import NoReturn

import numpy as np

from benchmarks.form_screen import FORMS
from benchmarks.loop_heldout import by_the_rule
from observer_node.data import CrashDataError, load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import Dataset, make_dataset
from observer_node.loop.refit import score
from observer_node.model.effects import registered
from observer_node.model.nonlinear import NonlinearGreyBox, belt_force_n

RATE_HZ = 1000.0
MARGIN = 1.0  # the loop's default margin [points]


BESIDE = {"pelvis_coupling": {"kind": "pelvis_coupling", "parameters": {"kp": 1e4, "cp": 300.0}}}
BELTS = ["belt_unloading", *(f for f, (kind, _, _) in FORMS.items() if kind == "belt_unloading")]


def _entry(form: str) -> dict:
    if form in FORMS:
        _, trial, start = FORMS[form]
        return {"kind": trial.kind, "parameters": dict(start)}
    return {"kind": form, "parameters": {}}


def pushes(base: Mapping[str, float], est: Dataset) -> None:
    """Part 1: the grey-box belt's force per estimation test."""
    force_n = belt_force_n(NonlinearGreyBox(dict(base), [], est.fs_hz), est.pulse_g,
                           est.brs_rad)
    win = round(0.010 * est.fs_hz)
    for name, f in zip(est.names, force_n, strict=True):
        # whole windows, the last one taking the samples left over (151: 10 ms + 1)
        edges = [*range(0, len(f) - win + 1, win), len(f)]
        by_window = " ".join(f"{int(np.sum(f[a:b] < 0)):2d}"
                             for a, b in pairwise(edges))
        print(f"  {name:<10} peak {f.max():6.0f} N; pushes {int(np.sum(f < 0)):3d} ms, at most "
              f"{-f.min():5.0f} N; pushing ms per 10 ms: {by_window}", flush=True)


def forms(base: dict, est: Dataset, val: Dataset, names: list[str]) -> None:
    """Part 2: each one-sided belt by the rule, alone and beside a rebound path."""
    with np.errstate(all="ignore"):
        print(f"  grey-box: validation {score(base, [], val).fit.total:.1f} %", flush=True)
    for form in names:
        for beside in ("", *BESIDE):
            effects = [_entry(form)] + ([BESIDE[beside]] if beside else [])
            ev, fit = by_the_rule(base, effects, est, MARGIN)
            with np.errstate(all="ignore"):
                val_fit = score(fit.base, fit.effects, val).fit.total
            label = form + (f" + {beside}" if beside else "")
            print(f"  {label:<36}{'passes' if ev.accepted else 'fails':<7}"
                  f"{ev.gain_points:+6.1f} {ev.tests_improved}/{ev.tests}  validation "
                  f"{val_fit:5.1f} %", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="+", type=Path, metavar="CASE_DIR")
    ap.add_argument("--forms", default="belt_unloading,belt_off_chest,belt_set_memory",
                    help="one-sided belts to judge, comma-separated, of: " + ", ".join(BELTS)
                    + " (default: %(default)s; empty: none)")
    a = ap.parse_args()
    names = [f for f in a.forms.split(",") if f]
    bad = [f for f in names if f not in BELTS]
    if bad:
        _refuse(f"unknown belt form {bad[0]!r} (one of {', '.join(BELTS)})")
    cases = []
    for case in a.cases:  # all read before any fit: a bad folder is said before minutes of work
        try:
            cases.append((case, make_dataset(load_tests([case / "est"]), RATE_HZ),
                          make_dataset(load_tests([case / "val"]), RATE_HZ)))
        except (CrashDataError, OSError) as e:
            _refuse(f"{case}: {e}")
    with ExitStack() as stack:
        for f in names:
            if f in FORMS:
                stack.enter_context(registered(FORMS[f][1]))
        for case, est, val in cases:
            base = dict(greybox.fit_greybox(est).params)
            print(case.name, flush=True)
            pushes(base, est)
            forms(base, est, val, names)


def _refuse(why: str) -> NoReturn:
    print(f"belt_push: {why}", file=sys.stderr)
    sys.exit(2)


if __name__ == "__main__":
    main()
