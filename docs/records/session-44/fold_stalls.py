"""Offline check (session 44): how often does a candidate's fold refit stay where its
all-test fit started it? Such a fold scores its held-out test with a model fitted on that
test too: in-sample, not cross-validated (``fold_leak.py``: set AC's belt stiffening).

Per case of a set, the first round's candidates as the loop tried them (report.json's
history, their starting parameters from its first ranking), each fitted on all estimation
tests as the loop's folds start (``rounds._all_tests``), then refitted on each fold's
training tests at the loop's 15 evaluations. A fold **stalls** when no base parameter
moved by 1e-6 of itself. Printed per candidate: folds stalled of folds, and the mean paired
gain [points] over the held-out tests of stalled and of moving folds.

    PYTHONPATH=. python docs/records/session-44/fold_stalls.py SETS_DIR SET REPORTS_DIR
"""
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

from benchmarks.heldout.sets import select
from benchmarks.loop_heldout import load_tests
from observer_node.ident.greybox import FREE
from observer_node.loop.closed_loop import run_loop
from observer_node.loop.refit import FOLD_NFEV, refit, refit_from, score

first: list = []


def _capture(c, st):
    first.append((c.est, dict(st.base), c.folds))
    return False


def _moved(a: dict, b: dict) -> bool:
    return any(abs(a[n] - b[n]) > 1e-6 * abs(b[n]) for n in FREE)


def _fold_fits(base, effects, est, folds):
    out = []
    for train, test in folds:
        r = refit_from(base, effects, est.subset(train), FOLD_NFEV)
        fits = score(r.base, r.effects, est.subset(test)).tests
        out.append((_moved(r.base, base), {n: v.total for n, v in fits.items()}))
    return out


def main() -> None:
    sys.modules["observer_node.loop.closed_loop"].one_round = _capture
    sets, name, reports = Path(sys.argv[1]), sys.argv[2], Path(sys.argv[3])
    total = {"stalled": 0, "folds": 0}
    for case in select(None, name):
        rep = json.loads((reports / case.name / "report.json").read_text())
        first.clear()
        run_loop(load_tests([sets / case.name / "est"]), load_tests([sets / case.name / "val"]),
                 Path(tempfile.mkdtemp()), verbose=False, plots=False, ratings=False, workers=1)
        est, base, folds = first[0]
        start = {x["kind"]: x["initial_parameters"] for x in rep["first_ranking"]}
        without = _fold_fits(base, [], est, folds)
        b_cv = {n: v for _, f in without for n, v in f.items()}
        print(f"== {case.name}: the model without effects, folds moved "
              f"{sum(m for m, _ in without)} of {len(without)}", flush=True)
        for t in rep["history"][0]["tried"]:
            eff = {"kind": t["kind"], "parameters": start.get(t["kind"], {})}
            if t["scope"] != "all":
                eff["setups"] = t["scope"].split("+")
            with np.errstate(all="ignore"):
                fit = refit(base, [eff], est)
                folds_c = _fold_fits(fit.base, fit.effects, est, folds)
            stalled = [b for m, f in folds_c if not m for b in
                       [f[n] - b_cv[n] for n in f]]
            moving = [b for m, f in folds_c if m for b in [f[n] - b_cv[n] for n in f]]
            total["stalled"] += sum(not m for m, _ in folds_c)
            total["folds"] += len(folds_c)
            print(f"   {t['kind']}@{t['scope']}: stalled {sum(not m for m, _ in folds_c)} of "
                  f"{len(folds_c)}; gain stalled "
                  f"{np.mean(stalled) if stalled else float('nan'):+.2f}, moving "
                  f"{np.mean(moving) if moving else float('nan'):+.2f}", flush=True)
    print(f"stalled folds: {total['stalled']} of {total['folds']}")


if __name__ == "__main__":
    main()
