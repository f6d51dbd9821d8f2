"""A pulse out of step with all three of its test's channels (CR's and CD's half rise, the
spool's half pay-out, each from the car's 50 mm free flight), against two or more other tests
of its rig: the rule as prototyped in session 40, fixed before seed 140000 was drawn. Per
broken form of ``benchmarks.screen_faults``' draws: how many drawn, found by the checks before
the fit, and found besides by this rule (on the tests they leave); and the clean tests it names.
    PYTHONPATH=. python docs/records/session-40/pulse_steps_proto.py SEED CAMPAIGNS"""
import sys
import tempfile
from collections import Counter
from pathlib import Path

import numpy as np

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import CrashDataError, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening as S

END = 0.15
GAP = 5.0


def lags(t):
    fl = S._flight_ms(t, END)
    return np.array([S._rise_ms(t, t.cr_g, END)[-1] - fl, S._rise_ms(t, t.cd_mm, END)[-1] - fl,
                     S._payout_lag_ms(t, END)])


def pulse_steps(tests):
    L = {t.name: (t.setup, lags(t)) for t in tests}
    out = []
    for n, (s, own) in L.items():
        mates = np.array([v for m, (r, v) in L.items()
                          if m != n and r == s and np.all(np.isfinite(v))])
        if not np.all(np.isfinite(own)) or len(mates) < 2:
            continue
        gap = np.min(np.abs(mates - own), axis=0)
        side = np.sign(own - np.median(mates, axis=0))
        spread = np.ptp(mates, axis=0)
        if np.all(gap > GAP) and np.all(gap > spread) and abs(side.sum()) == 3:
            out.append((n, np.round(own - np.median(mates, axis=0), 1).tolist()))
    return out


seed, n = int(sys.argv[1]), int(sys.argv[2])
size = median_sizes()
cases = [draw_campaign(k, seed, size) for k in range(n)]
drawn, found, newly, clean_named = Counter(), Counter(), Counter(), []
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
            assign_setups(tests)
            form = c.name.split("_", 1)[1]
            flagged = {f.test for f in S.broken_before_fit(tests, 0.15)}
            new = pulse_steps([t for t in tests if t.name not in flagged])
            for t in c.expect_broken:
                drawn[form] += 1
                found[form] += t in flagged
                newly[form] += any(m == t for m, _ in new)
            clean_named += [(c.name, m, o) for m, o in new if m not in c.expect_broken]
    print(f"{b + 20} done", file=sys.stderr, flush=True)
for f in sorted(drawn):
    print(f"{f:20s} drawn {drawn[f]:3d} found {found[f]:3d} +new {newly[f]:3d}")
print("clean named by the new check:", len(clean_named))
for x in clean_named:
    print("  ", x)
