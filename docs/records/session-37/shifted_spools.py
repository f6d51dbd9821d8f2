"""A BRS recorded early or late on one test of the whole bundled campaign (each of the 24
tests in turn, shifted 10, 15, 20 or 25 ms either way): how many the pay-out check names,
as it was at ee0fc91 (read from git) and now. Run from the repository's clone:
    python docs/records/session-37/shifted_spools.py"""
import dataclasses
import subprocess
import sys
import types

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import payout_outliers

source = subprocess.run(["git", "show", "ee0fc91:observer_node/loop/screening.py"],
                        capture_output=True, text=True, check=True).stdout
before = types.ModuleType("observer_node.loop.screening_before")
before.__package__ = "observer_node.loop"
sys.modules[before.__name__] = before
exec(compile(source, "ee0fc91:observer_node/loop/screening.py", "exec"), before.__dict__)

tests = load_tests([bundled_campaign()])
assign_setups(tests)


def shifted(x: np.ndarray, ms: int, fs_hz: float) -> np.ndarray:
    k = round(abs(ms) * fs_hz / 1000.0)
    if ms > 0:  # recorded late
        return np.concatenate([np.full(k, x[0]), x[:-k]])
    return np.concatenate([x[k:], np.full(k, x[-1])])


for ms in (-25, -20, -15, -10, 10, 15, 20, 25):
    named = {"before": [], "now": []}
    for t in tests:
        faulty = [dataclasses.replace(u, brs=shifted(u.brs, ms, u.fs_hz)) if u is t else u
                  for u in tests]
        for label, check in (("before", before.payout_outliers), ("now", payout_outliers)):
            if t.name in {b.test for b in check(faulty, 0.15)}:
                named[label].append(t.name)
    print(f"BRS {ms:+d} ms: before {len(named['before'])} of 24 named, now {len(named['now'])}; "
          f"now {named['now']}; lost {sorted(set(named['before']) - set(named['now']))}")
