"""The thesis grey-box's judged fit of each test the pay-out check names, against the other
tests of its setup, with the pay-out check switched off so the named test stays in (an
estimation test: its left-out fit; a validation test: the estimation model's fit).

    python docs/records/session-36/suspect_fits.py CASE ... | bund:EST,EST,../VAL,VAL,..

CASE is a held-out case under /work/runs/s36/sets/<set>/ (made with
``python -m benchmarks.heldout.make_sets --out /work/runs/s36/sets/<set> --set <set>``);
``bund:`` names bundled tests."""

import glob
import sys

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.crashtest import THESIS_WINDOW_S
from observer_node.data.setups import assign_setups
from observer_node.ident.progress import Progress
from observer_node.loop import closed_loop as cl
from observer_node.loop import screening
from observer_node.loop.cluster import cluster
from observer_node.loop.refit import score

payout = screening.payout_outliers
cl.payout_outliers = lambda tests, end_s: []  # type: ignore[assignment]


def run(label, est, val, runner):
    tests = est + val
    assign_setups(tests)
    named = payout(tests, 0.15)
    if not named:
        print(label, "no test named")
        return
    scr = cl._screened(est, val, 1000.0, THESIS_WINDOW_S, runner, Progress("x", False))
    fits = dict(scr.cv_now)
    fits.update({n: v.total for n, v in score(dict(scr.gb.params), [], scr.val).tests.items()})
    setup = {t.name: t.setup for t in tests}
    for b in named:
        peers = [fits[n] for n in fits if setup[n] == setup[b.test] and n != b.test]
        print(label, b.test, "est" if b.test in {t.name for t in est} else "val",
              "fit", round(fits.get(b.test, float("nan")), 1),
              "setup others", np.round(sorted(peers), 1).tolist(),
              "all median", round(float(np.median([v for n, v in fits.items() if n != b.test])), 1),
              "left out by others:", [x.test for x in scr.broken], flush=True)


if __name__ == "__main__":
    bundled = {t.name: t for t in load_tests([bundled_campaign()])}
    with cluster(None, 1) as runner:
        for case in sys.argv[1:]:
            if case.startswith("bund:"):
                est_n, val_n = case[5:].split("/")
                run(case, [bundled[n] for n in est_n.split(",")],
                    [bundled[n] for n in val_n.split(",")], runner)
            else:
                d = glob.glob(f"/work/runs/s36/sets/*/{case}/")[0]
                run(case, load_tests(sorted(glob.glob(d + "est/*"))),
                    load_tests(sorted(glob.glob(d + "val/*"))), runner)
