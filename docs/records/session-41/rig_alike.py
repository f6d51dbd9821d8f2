"""Tests of one rig broken alike, on campaigns drawn afresh from the independent simulator
(``benchmarks.screen_faults.draw_campaign``, its own broken test left out: the campaign's
other tests only): in each, the rig with the most tests (two or more) gets, on two of its
tests or on all, a pulse exported in m/s^2 with no stated velocity, or a CR in m/s^2's
reciprocal with the velocity stated. Printed per fault: campaigns, tests broken, tests named
by the checks before the fit (``broken_before_fit``), on the broken channel, and clean tests
named. Run from a checkout (its own screening is the one judged: 0cad69e before, 1badf01 the
rule read against the other rigs, not kept; 5bf9913 the factor of two from the car's speed):
    PYTHONPATH=. python docs/records/session-41/rig_alike.py SEED CAMPAIGNS"""
import dataclasses
import sys
import tempfile
from collections import Counter
from pathlib import Path

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import CrashDataError, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import broken_before_fit

G = 9.80665
FAULTS = {"two pulses in m/s^2": (2, "pulse"), "every pulse in m/s^2": (0, "pulse"),
          "two CRs per m/s^2": (2, "cr")}
seed, n = int(sys.argv[1]), int(sys.argv[2])
size = median_sizes()
cases = [draw_campaign(k, seed, size) for k in range(n)]
tally = {f: Counter() for f in FAULTS}
for b in range(0, n, 20):
    batch = cases[b:b + 20]
    with tempfile.TemporaryDirectory() as tmp:
        make(batch, Path(tmp), log=False)
        for c in batch:
            d = Path(tmp) / c.name
            try:
                tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
            except CrashDataError:
                continue
            tests = [t for t in tests if t.name not in c.expect_broken]
            assign_setups(tests)
            rigs = Counter(t.setup for t in tests)
            rig, m = rigs.most_common(1)[0]
            if m < 2:
                continue
            mates = [t.name for t in tests if t.setup == rig]
            for fault, (k, channel) in FAULTS.items():
                hit = set(mates[:k] if k else mates)
                def brk(t, channel=channel):
                    if channel == "pulse":
                        return dataclasses.replace(t, pulse_g=G * t.pulse_g, velocity_ms=None)
                    return dataclasses.replace(t, cr_g=t.cr_g / G)
                found = broken_before_fit([brk(t) if t.name in hit else t for t in tests], 0.15)
                named = {f.test: f.channel for f in found}
                tl = tally[fault]
                tl["campaigns"] += 1
                tl["broken"] += len(hit)
                tl["named"] += sum(x in named for x in hit)
                tl["on channel"] += sum(named.get(x) == channel for x in hit)
                tl["clean named"] += sum(x not in hit for x in named)
for fault, tl in tally.items():
    print(f"{fault:22s}", dict(tl))
