"""The speed share (loop/screening.speed_share_outliers) on the bundled campaign and on 3000
campaigns of 3-8 tests of each rig drawn from it (seed 1): how many campaigns name a test.
Run from a checkout (its screening is the one judged: 1badf01 and 5bf9913 printed the same):
    PYTHONPATH=. python docs/records/session-41/speed_share_bundled.py"""
from collections import Counter

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import speed_share_outliers

tests = load_tests([bundled_campaign()])
assign_setups(tests)
print("whole campaign:", [b.test for b in speed_share_outliers(tests, 0.15)])
names = {s: [t for t in tests if t.setup == s] for s in ("R16", "SLED", "FULL")}
rng = np.random.default_rng(1)
count, who = 0, Counter()
for _ in range(3000):
    pick = []
    for ts in names.values():
        k = int(rng.integers(3, min(8, len(ts)) + 1))
        pick += [ts[i] for i in rng.choice(len(ts), k, replace=False)]
    named = [b.test for b in speed_share_outliers(pick, 0.15)]
    count += bool(named)
    who.update(named)
print(f"3-8 tests of each rig: {count} of 3000 campaigns name a test; {who.most_common(6)}")
