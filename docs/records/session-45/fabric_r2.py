"""Session 45, offline: set Z's fabric case with the bound (d0897a1): round 2's formula
gains 1.35 (0.29 before). Are the folds of the airbag model (the round's base) or of the
candidate stalled?

    PYTHONPATH=. python docs/records/session-45/fabric_r2.py SETS/z \
        REPORTS/z/hz_fabric_sled/report.json
"""
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

from benchmarks.loop_heldout import load_tests
from observer_node.ident.greybox import FREE
from observer_node.loop import closed_loop as CL
from observer_node.loop.refit import FOLD_NFEV, refit, refit_from, score

seen = []
_orig = CL.one_round
def _capture(c, st):
    seen.append((c.est, dict(st.base), [dict(e) for e in st.effects], c.folds))
    if len(seen) == 2:
        return False
    return _orig(c, st)

def moved(a, b):
    return max(abs(a[n] / b[n] - 1) for n in FREE)

if __name__ == "__main__":
    CL.one_round = _capture
    d = Path(sys.argv[1]) / "hz_fabric_sled"
    CL.run_loop(load_tests([d / "est"]), load_tests([d / "val"]), Path(tempfile.mkdtemp()),
                verbose=False, plots=False, ratings=False, workers=1)
    est, base, effects, folds = seen[1]
    print("round-2 base effects", effects)
    rep = json.loads(Path(sys.argv[2]).read_text())
    other = next(e for e in rep["effects"] if e["kind"] == "other")
    cand = refit(base, [*effects, {"kind": "other", "parameters": other["parameters"]}], est)
    for label, b, eff in (("airbag", base, effects), ("airbag+other", cand.base, cand.effects)):
        tot = []
        for train, test in folds:
            r = refit_from(b, eff, est.subset(train), FOLD_NFEV)
            t = score(r.base, r.effects, est.subset(test)).tests
            tot += [v.total for v in t.values()]
            fits = [round(v.total, 2) for v in t.values()]
            print(f"  {label}: fold {test} moved {moved(r.base, b):.2e} fits {fits}")
        print(label, "mean cv", np.mean(tot))
