"""The pay-out check (loop/screening.payout_outliers) with and without the others' 99.9 %
prediction interval, its scatter read on the test's rig alone or pooled over every rig (each
with the crossed partner named only when the crossing is seen from both sides, as since
session 37): on 3000 campaigns drawn from the bundled tests (3-8 of
each rig, seed 1, rigs drawn in the order R16, SLED, FULL) and on the held-out sets' tests
that reach this check
(made with ``python -m benchmarks.heldout.make_sets --out SETS/<x> --set <x>``; SETS defaults
to /work/runs/s36/sets, or the first argument).
Run from the repository: python docs/records/session-37/payout_interval.py [SETS]"""
import glob
import json
import sys
from collections import Counter
from pathlib import Path
from unittest import mock

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening
from observer_node.loop.screening import (
    payout_outliers,
    polarity_outliers,
    screen_channels,
    velocity_outliers,
)


def _own_rig(name, lag):
    """The scatter of the test's own rig's other tests alone."""
    rest = [v for n, (s, v) in lag.items() if n != name and s == lag[name][0] and np.isfinite(v)]
    return float(np.std(rest, ddof=1)), len(rest) - 1


RULES = {"gap alone (before)": ("_outside_prediction", lambda own, rest, sd, dof: True),
         "gap and interval, its rig's scatter": ("_scatter", _own_rig),
         "gap and interval, pooled scatter (kept)": None}


def flags(tests, rule):
    if rule is None:
        return {b.test for b in payout_outliers(tests, 0.15)}
    with mock.patch.object(screening, *rule):
        return {b.test for b in payout_outliers(tests, 0.15)}


bundled = load_tests([bundled_campaign()])
assign_setups(bundled)
by_rig = {s: [t for t in bundled if t.setup == s] for s in ("R16", "SLED", "FULL")}
for label, rule in RULES.items():
    rng = np.random.default_rng(1)
    count, who, beside = 0, Counter(), Counter()
    for _ in range(3000):
        pick = []
        for rig in by_rig.values():
            k = int(rng.integers(3, min(8, len(rig)) + 1))
            pick += [rig[i] for i in rng.choice(len(rig), k, replace=False)]
        f = flags(pick, rule)
        count += bool(f)
        who.update(f)
        for n in f:
            setup = next(t.setup for t in pick if t.name == n)
            beside[sum(t.setup == setup for t in pick) - 1] += 1
    print(f"{label}: {count} of 3000 bundled campaigns flag a clean test; tests "
          f"{dict(who.most_common(6))}; others of its rig {dict(sorted(beside.items()))}; "
          f"the whole campaign: {sorted(flags(bundled, rule))}")

sets = sys.argv[1] if len(sys.argv) > 1 else "/work/runs/s36/sets"
found = {label: ([], []) for label in RULES}
n = 0
for case in sorted(glob.glob(f"{sets}/*/*/")):
    truth = json.loads(Path(case, "truth.json").read_text())
    tests = load_tests(sorted(glob.glob(case + "est/*")) + sorted(glob.glob(case + "val/*")))
    assign_setups(tests)
    gone = {b.test for t in tests for b in screen_channels(t, 0.15)}
    for check in (polarity_outliers, velocity_outliers):  # the loop's order before this check
        gone |= {b.test for b in check([t for t in tests if t.name not in gone], 0.15)}
    pool = [t for t in tests if t.name not in gone]
    n += len(pool)
    for label, rule in RULES.items():
        for name in sorted(flags(pool, rule)):
            broken = name in truth["expected"]["broken_tests"]
            found[label][0 if broken else 1].append(f"{Path(case).name}:{name}")
print(f"held-out: {n} tests reach the check")
for label, (right, wrong) in found.items():
    print(f"{label}: broken tests named {right}; others named {wrong}")
