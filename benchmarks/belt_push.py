"""Where the thesis grey-box's belt pushes, and what a belt that cannot push costs it.

The grey-box's belt force k2 e + c2 e' (e = w - s, the belt penetration) is linear: it pushes
wherever that is negative. A real webbing cannot push, which is the library's
``belt_unloading``. On the independent held-out sets that effect never passes the loop's rule,
not even where the simulator's webbing has a hysteresis or a permanent set; this tool shows
why, case by case (cases already seen: a diagnosis, not evidence):

1. per estimation test, the grey-box identified on the case's estimation tests: the belt's
   peak force [N], how long it pushes [ms] and by how much at most [N], and how many of the
   pushing milliseconds fall in each 10 ms window of the record (so when: loading or rebound);
2. each one-sided belt judged by the loop's rule against the grey-box (refitted, cross-validated
   leave-one-test-out, margin 1 point) on every setup, alone and beside a rebound path on the
   spine: the mean gain [points], tests improved, the validation fit_TOT [%]. The forms: the
   library's switch (``belt_unloading``), form_screen's trial forms (``belt_off_chest``,
   ``belt_set_memory``), and beside a ``seat_back`` (a one-sided spine-vehicle spring and
   damper acting only rearward of the start: what stops a rebound) or the library's
   ``pelvis_coupling``.

    python -m benchmarks.belt_push CASE_DIR [CASE_DIR ...] [--forms belt_unloading,...]

A CASE_DIR holds ``est/`` and ``val/`` (``make_sets`` output: ``SETS_DIR/CASE``).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Mapping
from contextlib import ExitStack
from pathlib import Path
from typing import Any

import numpy as np

from benchmarks.form_screen import FORMS
from benchmarks.loop_heldout import by_the_rule
from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import Dataset, make_dataset
from observer_node.loop.refit import score
from observer_node.model.effects import Effect, Kinematics, Param, registered
from observer_node.model.nonlinear import NonlinearGreyBox
from observer_node.model.observer import transform_inputs

RATE_HZ = 1000.0
MARGIN = 1.0  # the loop's default margin [points]


def _seat_back(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]
               ) -> tuple[Any, Any]:
    rel = k.pos - k.x  # the spine's forward excursion in the vehicle [m]
    f = p["ksb"] * rel + p["csb"] * (k.u1 - k.xd)
    return np.minimum(f, 0.0) * (rel < 0.0), k.zero


SEAT_BACK = Effect(
    "trial_seat_back", "physical", "seat back: pushes the spine forward once it is rearward "
    "of its start", (Param("ksb", "N/m", 2e4, positive=True),
                     Param("csb", "N s/m", 300.0, positive=True)), force=_seat_back)
BESIDE = {"seat_back": {"kind": SEAT_BACK.kind, "parameters": {"ksb": 2e4, "csb": 300.0}},
          "pelvis_coupling": {"kind": "pelvis_coupling",
                              "parameters": {"kp": 1e4, "cp": 300.0}}}


def _entry(form: str) -> dict:
    if form in FORMS:
        _, trial, start = FORMS[form]
        return {"kind": trial.kind, "parameters": dict(start)}
    return {"kind": form, "parameters": {}}


def pushes(base: Mapping[str, float], est: Dataset) -> None:
    """Part 1: the grey-box belt's force per estimation test."""
    model = NonlinearGreyBox(dict(base), [], est.fs_hz)
    u = transform_inputs("velocity_brs_rate", est.pulse_g, est.brs_rad, est.fs_hz)
    states = np.zeros((6, *est.pulse_g.shape))
    model.run_transformed(u[..., 0], u[..., 1], est.brs_rad, states)
    e = states[4] - states[3]
    force_n = base["k2"] * e + base["c2"] * (u[..., 0] + base["R"] * u[..., 1] - states[2])
    win = round(0.010 * est.fs_hz)
    for name, f in zip(est.names, force_n, strict=True):
        by_window = " ".join(f"{int(np.sum(f[j:j + win] < 0)):2d}"
                             for j in range(0, len(f) - win + 1, win))
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
                    help="one-sided belts to judge, comma-separated: belt_unloading and "
                         "form_screen's trial forms (default: %(default)s; empty: none)")
    a = ap.parse_args()
    names = [f for f in a.forms.split(",") if f]
    bad = [f for f in names if f != "belt_unloading" and f not in FORMS]
    missing = [c for c in a.cases if not (c / "est").is_dir() or not (c / "val").is_dir()]
    if bad or missing:
        print("belt_push: " + (f"unknown form {bad[0]!r}" if bad else
                               f"{missing[0]}: no est/ and val/ folders"), file=sys.stderr)
        sys.exit(2)
    with ExitStack() as stack:
        for eff in {SEAT_BACK, *(FORMS[f][1] for f in names if f in FORMS)}:
            stack.enter_context(registered(eff))
        for case in a.cases:
            est = make_dataset(load_tests([case / "est"]), RATE_HZ)
            val = make_dataset(load_tests([case / "val"]), RATE_HZ)
            base = dict(greybox.fit_greybox(est).params)
            print(case.name, flush=True)
            pushes(base, est)
            forms(base, est, val, names)


if __name__ == "__main__":
    main()
