"""Offline check (session 44): is the loop's model without effects at the best optimum its
refit can reach? A candidate's refit (``refit.refit``) also starts from a typical chest;
the model without effects is refitted from where the grey-box left it only. Where the
second start reaches a better fit of the base parameters alone, a candidate's cross-
validated gain holds that better optimum's gain too, credited to the effect (set AC's
eccentric ring: a belt stiffening refitted to nothing, named for +1.5 points).

Per case: the fit_TOT [%] of the estimation tests of the model without effects as the loop
starts its first round, refitted from there and from a typical chest (base only, 120
evaluations each, as the loop refits a named effect).

    PYTHONPATH=. python docs/records/session-44/base_starts.py SETS_DIR SET [CASE ...]
"""
import sys
import tempfile
from pathlib import Path

from benchmarks.heldout.sets import select
from benchmarks.loop_heldout import load_tests
from observer_node.ident.greybox import FREE, STARTS
from observer_node.loop import rounds
from observer_node.loop.closed_loop import run_loop
from observer_node.loop.refit import refit_from, score

first: list = []
_orig = rounds.one_round


def _capture(c, st):
    if not first:
        first.append((c.est, dict(st.base)))
    return _orig(c, st)


rounds.one_round = _capture
closed = sys.modules["observer_node.loop.closed_loop"]
closed.one_round = _capture  # imported by name there


def main() -> None:
    sets, name = Path(sys.argv[1]), sys.argv[2]
    for case in select(sys.argv[3:] or None, name):
        first.clear()
        run_loop(load_tests([sets / case.name / "est"]), load_tests([sets / case.name / "val"]),
                 Path(tempfile.mkdtemp()) / case.name, verbose=False, plots=False,
                 ratings=False, workers=1)
        est, base = first[0]
        now = score(base, [], est).fit.total
        here = refit_from(base, [], est, 120)
        typical = refit_from({**base, **{n: v for n, v in STARTS[0].items() if n in FREE}},
                             [], est, 120)
        f_here = score(here.base, [], est).fit.total
        f_typ = score(typical.base, [], est).fit.total
        print(f"{case.name:38s} as the loop starts {now:6.2f}  refitted from there "
              f"{f_here:6.2f}  from a typical chest {f_typ:6.2f}  better by "
              f"{f_typ - max(now, f_here):+.2f}", flush=True)


if __name__ == "__main__":
    main()
