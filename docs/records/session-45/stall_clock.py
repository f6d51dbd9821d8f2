"""Session 45, offline: why the clock case's belt stiffening folds stall with scipy's bounds
(set AC, at d0897a1): how each least-squares run ended.

    PYTHONPATH=. python docs/records/session-45/stall_clock.py SETS/ac REPORTS/ac/hac_cd_clock
"""
import json
import sys
import tempfile
from pathlib import Path

import numpy as np
from scipy import optimize

from benchmarks.loop_heldout import load_tests
from observer_node.loop import refit as R
from observer_node.loop.closed_loop import run_loop

first = []
_ls = optimize.least_squares


def _capture(c, st):
    first.append((c.est, dict(st.base), c.folds))
    return False


def _told(*a, **k):
    res = _ls(*a, **k)
    print(f"   status {res.status} nfev {res.nfev} njev {res.njev} {res.message!r} "
          f"opt {res.optimality:.3g} |x-x0| {np.max(np.abs(res.x - a[1])):.3g} "
          f"x0 tail {a[1][-1]:.3g} x tail {res.x[-1]:.3g} active {res.active_mask[-1]}",
          flush=True)
    return res


if __name__ == "__main__":
    sys.modules["observer_node.loop.closed_loop"].one_round = _capture
    d = Path(sys.argv[1]) / "hac_cd_clock"
    run_loop(load_tests([d / "est"]), load_tests([d / "val"]), Path(tempfile.mkdtemp()),
             verbose=False, plots=False, ratings=False, workers=1)
    est, base, folds = first[0]
    rep = json.loads((Path(sys.argv[2]) / "report.json").read_text())
    start = {x["kind"]: x["initial_parameters"] for x in rep["first_ranking"]}
    print("start", start.get("belt_stiffening"))
    R.optimize.least_squares = _told
    print("all-test fit:")
    cand = R.refit(base, [{"kind": "belt_stiffening",
                           "parameters": start["belt_stiffening"]}], est)
    print("kb3", cand.effects[-1]["parameters"], "cost", cand.cost)
    for train, _ in folds:
        R.refit_from(cand.base, cand.effects, est.subset(train), R.FOLD_NFEV)
