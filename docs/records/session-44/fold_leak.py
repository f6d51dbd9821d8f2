"""Offline check (session 44): where did set AC's belt stiffening, refitted on all tests to
6.3 N/m^3 (nothing), gain +1.5 points on 6 of 6 tests in cross-validation?

Each fold of the model without effects and of the model with the candidate (from its
all-test fit, as the loop's folds start) is refitted on the fold's five tests at 15
evaluations (the loop's) and at 200; printed per held-out test: the in-sample cost of each,
the held-out test's fit_TOT [%] of each, and two base parameters (m2 [kg], R [m]) of each.

    PYTHONPATH=. python docs/records/session-44/fold_leak.py SETS_DIR
"""
import sys
import tempfile
from pathlib import Path

from benchmarks.loop_heldout import load_tests
from observer_node.loop.closed_loop import run_loop
from observer_node.loop.refit import refit, refit_from, score

first: list = []


def _capture(c, st):
    first.append((c.est, dict(st.base), c.folds))
    return False  # no round: only the model as the loop starts its first


def main() -> None:
    sys.modules["observer_node.loop.closed_loop"].one_round = _capture
    d = Path(sys.argv[1]) / "hac_eccentric_sled"
    run_loop(load_tests([d / "est"]), load_tests([d / "val"]), Path(tempfile.mkdtemp()),
             verbose=False, plots=False, ratings=False, workers=1)
    est, base, folds = first[0]
    # the candidate as the residual ranked it (report.json's first_ranking), on every rig
    cand = refit(base, [{"kind": "belt_stiffening", "parameters": {"kb3": 2298934.0}}], est)
    print(f"all tests: without {score(base, [], est).fit.total:.3f} %, with "
          f"{score(cand.base, cand.effects, est).fit.total:.3f} % "
          f"(kb3 {cand.effects[-1]['parameters']['kb3']:.3g} N/m^3)")
    for train, test in folds:
        sub, held = est.subset(train), est.subset(test)
        for nfev in (15, 200):
            b = refit_from(base, [], sub, nfev)
            e = refit_from(cand.base, cand.effects, sub, nfev)
            print(f"{est.names[test[0]]} nfev {nfev:3d}: in-sample cost without {b.cost:.6f} "
                  f"with {e.cost:.6f}; held out without "
                  f"{score(b.base, [], held).fit.total:.2f} with "
                  f"{score(e.base, e.effects, held).fit.total:.2f} %; m2 {b.base['m2']:.3f} "
                  f"{e.base['m2']:.3f} kg, R {b.base['R']:.5f} {e.base['R']:.5f} m; kb3 "
                  f"{e.effects[-1]['parameters']['kb3']:.3g}", flush=True)


if __name__ == "__main__":
    main()
