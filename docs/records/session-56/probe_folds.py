"""Probe (session 56): does an effect on SLED only move R16's cross-validated fits because the
folds' refits (FOLD_NFEV iterations from the all-test fit) are unfinished? Per-test gains of a
candidate at several fold budgets, on one case's estimation tests.

    python probe_folds.py CASE_DIR KIND SCOPE PARAMS_JSON BUDGETS
    python probe_folds.py SETS/ham_bilinear_sled chest_stiffening SLED '{"k3": 3.127e8}' 15,60,200
"""
import json
import sys
from pathlib import Path

import numpy as np

from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop.closed_loop import THESIS_WINDOW_S
from observer_node.loop.refit import fold_scores, folds, refit

if __name__ == "__main__":
    case_dir, kind, scope = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
    params = json.loads(sys.argv[4])
    budgets = [int(x) for x in sys.argv[5].split(",")]
    est = make_dataset(load_tests([case_dir / "est"]), 1000.0, THESIS_WINDOW_S)
    print("setups", list(zip(est.names, est.setups, strict=True)))
    gb = greybox.fit_greybox(est)
    eff = {"kind": kind, "parameters": params,
           **({} if scope == "all" else {"setups": scope.split("+")})}
    with np.errstate(all="ignore"):
        r0 = refit(dict(gb.params), [], est)
        r1 = refit(dict(gb.params), [eff], est)
        print("all-test fitted effect", r1.effects)
        for nfev in budgets:
            cv0: dict[str, float] = {}
            cv1: dict[str, float] = {}
            for tr, te in folds(est):
                cv0 |= fold_scores(r0.base, r0.effects, est, tr, te, nfev)
                cv1 |= fold_scores(r1.base, r1.effects, est, tr, te, nfev)
            print(f"nfev {nfev}: " + "  ".join(
                f"{n} {cv0[n]:.1f}->{cv1[n]:.1f} ({cv1[n] - cv0[n]:+.1f})" for n in est.names),
                flush=True)
