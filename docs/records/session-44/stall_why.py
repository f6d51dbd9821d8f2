"""Offline check (session 44): why does set AC's belt stiffening's fold refit never leave its
start? scipy's least_squares is wrapped (in refit's module) to print how it ended, on the
first fold (R16_001 left out): with the candidate as its all-test fit left it (kb3 7.33
N/m^3), with the same model at kb3 = 1e6, and without the effect.

    PYTHONPATH=. python docs/records/session-44/stall_why.py SETS_DIR
"""
import sys
import tempfile
from pathlib import Path

import numpy as np
from scipy import optimize

from benchmarks.loop_heldout import load_tests
from observer_node.loop import refit as R
from observer_node.loop.closed_loop import run_loop

first: list = []
_least_squares = optimize.least_squares


def _capture(c, st):
    first.append((c.est, dict(st.base), c.folds))
    return False


def _told(*a, **k):
    res = _least_squares(*a, **k)
    print(f"   status {res.status} nfev {res.nfev} njev {res.njev} {res.message!r} "
          f"optimality {res.optimality:.3g} |x - x0| {np.max(np.abs(res.x - a[1])):.3g} "
          f"last two x0 {np.round(a[1][-2:], 10)}", flush=True)
    return res


def main() -> None:
    sys.modules["observer_node.loop.closed_loop"].one_round = _capture
    d = Path(sys.argv[1]) / "hac_eccentric_sled"
    run_loop(load_tests([d / "est"]), load_tests([d / "val"]), Path(tempfile.mkdtemp()),
             verbose=False, plots=False, ratings=False, workers=1)
    est, base, folds = first[0]
    cand = R.refit(base, [{"kind": "belt_stiffening", "parameters": {"kb3": 2298934.0}}], est)
    R.optimize.least_squares = _told
    train, _ = folds[0]
    print(f"with the candidate (kb3 {cand.effects[-1]['parameters']['kb3']:.3g}):")
    R.refit_from(cand.base, cand.effects, est.subset(train), R.FOLD_NFEV)
    print("with kb3 = 1e6 instead:")
    R.refit_from(cand.base, [dict(cand.effects[-1], parameters={"kb3": 1e6})],
                 est.subset(train), R.FOLD_NFEV)
    print("without:")
    R.refit_from(base, [], est.subset(train), R.FOLD_NFEV)


if __name__ == "__main__":
    main()
