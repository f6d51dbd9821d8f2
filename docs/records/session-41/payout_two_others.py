"""The pay-out check on a rig of three tests (two others of the rig): how often it names a
clean bundled test, on campaigns drawn from the bundled tests, seed 1: 3000 with 3-8 tests of
each rig and 3000 with exactly 3 of each (every test then has two others), the check as
committed (loop/screening.payout_outliers); for the same draws, with the interval of three or
more others (PAYOUT_ALPHA) on two, and as before (three others or more only).
The rule was tried and not kept (docs/loop.md, "Since session 41"): run it on a checkout of
8cfe8b1, whose screening has PAYOUT_FEW_OTHERS and PAYOUT_FEW_ALPHA:
    git worktree add /tmp/c41 8cfe8b1 && cd /tmp/c41 &&
    PYTHONPATH=. python docs/records/session-41/payout_two_others.py"""
from collections import Counter

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening

tests = load_tests([bundled_campaign()])
assign_setups(tests)
names = {s: [t for t in tests if t.setup == s] for s in ("R16", "SLED", "FULL")}
print("whole campaign:", [b.test for b in screening.payout_outliers(tests, 0.15)])
for alpha, few in ((screening.PAYOUT_FEW_ALPHA, 2), (screening.PAYOUT_ALPHA, 2), (0.0, 3)):
    screening.PAYOUT_FEW_ALPHA, screening.PAYOUT_FEW_OTHERS = alpha, few
    for lo, hi in ((3, 8), (3, 3)):
        rng = np.random.default_rng(1)
        count, who = 0, Counter()
        for _ in range(3000):
            pick = []
            for ts in names.values():
                k = int(rng.integers(lo, min(hi, len(ts)) + 1))
                pick += [ts[i] for i in rng.choice(len(ts), k, replace=False)]
            named = [b.test for b in screening.payout_outliers(pick, 0.15)]
            count += bool(named)
            who.update(named)
        rule = f"two others at {alpha:g}" if few == 2 else "three others or more only"
        print(f"{rule}, {lo}-{hi} tests of each rig: {count} of 3000 "
              f"campaigns name a clean test; {who.most_common(6)}")
