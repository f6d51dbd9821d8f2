"""Session 45, offline: is the fold cost rough in the base parameters? On set AC's clock
case, a fold of the belt stiffening's refit, with and without the effect (at d0897a1).

    PYTHONPATH=. python docs/records/session-45/noise.py SETS/ac REPORTS/ac/hac_cd_clock
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


def _probe(fun, x0, **k):
    f0 = fun(x0)
    c0 = 0.5 * f0 @ f0
    print(f" cost {c0:.6g} n {len(x0)}")
    for i in (0, 1, 3):
        row = []
        for h in (1e-12, 1e-10, 1e-8, 1e-6):
            e = np.zeros_like(x0)
            e[i] = h
            f = fun(x0 + e)
            d = f - f0
            j = int(np.argmax(np.abs(d)))
            row.append(f"h={h:g}: dcost {0.5 * f @ f - c0:+.2e} max|dr| "
                       f"{np.abs(d).max():.2e} at {j} ({j / len(f0):.3f})")
        print(f"  d{i}: " + "; ".join(row))
    return _ls(fun, x0, **k)


if __name__ == "__main__":
    sys.modules["observer_node.loop.closed_loop"].one_round = _capture
    d = Path(sys.argv[1]) / "hac_cd_clock"
    run_loop(load_tests([d / "est"]), load_tests([d / "val"]), Path(tempfile.mkdtemp()),
             verbose=False, plots=False, ratings=False, workers=1)
    est, base, folds = first[0]
    rep = json.loads((Path(sys.argv[2]) / "report.json").read_text())
    start = {x["kind"]: x["initial_parameters"] for x in rep["first_ranking"]}
    cand = R.refit(base, [{"kind": "belt_stiffening",
                           "parameters": start["belt_stiffening"]}], est)
    R.optimize.least_squares = _probe
    train, _ = folds[0]
    print("with belt stiffening:")
    R.refit_from(cand.base, cand.effects, est.subset(train), 1)
    print("without, at the same base:")
    R.refit_from(cand.base, [], est.subset(train), 1)
    print("without, at its own fit:")
    R.refit_from(base, [], est.subset(train), 1)
