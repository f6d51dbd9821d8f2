"""One BRS polled at the median rate of sets A-AB (1 kHz, in a 10 kHz record) in each of N
campaigns of the independent held-out simulator (screen_faults' draw, seed SEED+k): per
campaign the polled test and any test whose BRS changes only on every k-th sample (k the
greatest common divisor of the intervals between its changes), whether the checks before the
fit name it, how many changes, the largest step, and the other tests' fastest turn over k
samples in counts (median; of its rig). Run from a checkout:
    PYTHONPATH=. python docs/records/session-42/poll_probe.py 100000 16"""
import dataclasses
import sys
import tempfile
from pathlib import Path

import numpy as np

from benchmarks.heldout.cases import Effect, test_names
from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import broken_before_fit


def fastest(t, k: int) -> float:
    b = np.asarray(t.brs, float)
    i0, i1 = t.index_of(0.0), t.index_of(0.15) + 1
    return float(np.max(np.abs(b[i0 + k:i1] - b[i0:i1 - k])))


size = median_sizes()
print("poll rate (Hz):", size["brs_poll"])
SEED, N = int(sys.argv[1]), int(sys.argv[2])
cases = []
for k in range(N):
    c = draw_campaign(k, SEED, size)
    phys = tuple(e for e in c.effects if not e.tests)
    est, val = test_names(c)
    name = [*est, *val][k % 12]
    cases.append(dataclasses.replace(
        c, name=f"p{k}", effects=(*phys, Effect("brs_poll", size["brs_poll"], tests=(name,))),
        expect_broken=(name,)))
with tempfile.TemporaryDirectory() as tmp:
    make(cases, Path(tmp), log=False)
    for c in cases:
        d = Path(tmp) / c.name
        tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
        assign_setups(tests)
        named = {b.test for b in broken_before_fit(tests, 0.15)}
        for t in tests:
            b = np.asarray(t.brs, float)
            at = np.flatnonzero(np.diff(b))
            g = int(np.gcd.reduce(np.diff(at))) if len(at) > 1 else 1
            if t.name not in c.expect_broken and g < 2:
                continue
            rig = [fastest(u, g) for u in tests if u is not t and u.setup == t.setup]
            print(f"{c.name} {c.counts_per_rev:3d}/rev {t.name:9s} "
                  f"{'POLLED' if t.name in c.expect_broken else 'clean '} "
                  f"{'named' if t.name in named else '     '} divisor {g:2d} changes {len(at):3d} "
                  f"largest step {np.abs(np.diff(b)).max():.0f}; the others' fastest over "
                  f"{g} samples: {np.median(rig) if rig else float('nan'):.1f} counts (rig)")
