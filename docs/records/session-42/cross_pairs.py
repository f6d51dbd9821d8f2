"""Crossed BRS files on the bundled campaign: every pair of tests of different rigs with their
BRS files swapped, in the whole campaign and in SUBS sub-campaigns of 3-8 tests of each rig
holding the pair (seed 1), judged by the checks before the fit: in how many crossings both,
one or neither crossed test is named, and the clean tests named (by the first words of their
reason: "its spool, read against" is a crossing's partner, "reaches half its pay-out" the
pay-out check). Run from a checkout (about 13 min):
    PYTHONPATH=. python docs/records/session-42/cross_pairs.py 23"""
import dataclasses
import sys
from collections import Counter

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import broken_before_fit

tests = load_tests([bundled_campaign()])
assign_setups(tests)
by = {s: [t for t in tests if t.setup == s] for s in ("R16", "SLED", "FULL")}
pairs = [(a, b) for i, a in enumerate(tests) for b in tests[i + 1:] if a.setup != b.setup]
rng = np.random.default_rng(1)
SUBS = int(sys.argv[1]) if len(sys.argv) > 1 else 23
count: Counter = Counter()
why: Counter = Counter()
for a, b in pairs:
    for r in range(SUBS + 1):
        pick = tests
        if r:
            pick = []
            for ts in by.values():
                k = int(rng.integers(3, min(8, len(ts)) + 1))
                must = [t for t in ts if t is a or t is b]
                rest = [t for t in ts if t not in must]
                pick += must + [rest[i] for i in rng.choice(len(rest), k - len(must),
                                                            replace=False)]
        camp = [dataclasses.replace(t, brs=b.brs) if t is a else
                dataclasses.replace(t, brs=a.brs) if t is b else t for t in pick]
        found = broken_before_fit(camp, 0.15)
        n = len({a.name, b.name} & {f.test for f in found})
        count["crossings"] += 1
        count[{2: "both named", 1: "one named", 0: "neither named"}[n]] += 1
        clean = [f for f in found if f.test not in (a.name, b.name)]
        count["clean tests named"] += len(clean)
        count["crossings naming a clean test"] += bool(clean)
        for f in clean:
            why[" ".join(f.reason.split()[:4])] += 1
            print(f"clean: {a.name} x {b.name}, sub-campaign {r}: {f.test}: {f.reason}",
                  flush=True)
print(dict(count))
print("clean tests named, by the reason's first words:", dict(why))
