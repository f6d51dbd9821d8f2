"""How often the pay-out check (loop/screening.payout_outliers' rule) names a clean bundled test:
3000 campaigns drawn from the bundled tests, 3-8 of each rig, seed 1; the rule with the gap to
the nearest other test of the rig over 8 ms and over 1, 2 or 3 times the others' spread.
Run from the repository: python docs/records/session-36/payout_false_flags.py"""
import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import PAYOUT_GAP_MS, PAYOUT_MIN_OTHERS, _payout_lag_ms

tests = load_tests([bundled_campaign()])
assign_setups(tests)
lag = {t.name: (t.setup, _payout_lag_ms(t, 0.15)) for t in tests}
print({n: round(v, 1) for n, (_, v) in lag.items()})
names = {s: [n for n, (t, _) in lag.items() if t == s] for s in ("R16", "SLED", "FULL")}


def flagged(pick: dict, times_spread: float) -> list[str]:
    out = []
    for n, (s, v) in pick.items():
        rest = np.array([w for k, (t, w) in pick.items() if k != n and t == s])
        if len(rest) < PAYOUT_MIN_OTHERS:
            continue
        gap = np.min(np.abs(rest - v))
        if gap > PAYOUT_GAP_MS and gap > times_spread * np.ptp(rest):
            out.append(str(n))
    return out


for m in (1, 2, 3):
    rng = np.random.default_rng(1)
    count, who = 0, {}
    for _ in range(3000):
        pick = {}
        for ns in names.values():
            k = int(rng.integers(3, min(8, len(ns)) + 1))
            for n in rng.choice(ns, k, replace=False):
                pick[str(n)] = lag[n]
        f = flagged(pick, m)
        count += bool(f)
        for n in f:
            who[n] = who.get(n, 0) + 1
    print(f"gap > {m} x spread: {count} of 3000 campaigns flag a clean test;",
          sorted(who.items(), key=lambda x: -x[1])[:6])
