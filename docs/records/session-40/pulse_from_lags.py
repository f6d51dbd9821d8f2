"""A pulse copied from another test (``pulse_from``), which the checks before the fit mostly miss
(8 of 26 at seed 130000, none on the pulse channel): how far each test's CR, CD and BRS lie out
of step with its own pulse, against the clean tests of its rig in its campaign. Diagnosis for
a later check, nothing built on it. The fresh draws of seed 100000 (seen in sessions 39-40).

Per test: CR's and CD's half rise and the spool's half pay-out, each in ms after the car's 50 mm
free flight (loop.screening's _rise_ms, _payout_lag_ms), less the median of the clean tests of
its rig (two or more); printed for the clean tests (their range and 1-99 % spread) and for
each copied pulse (found or not before the fit). Run from the repository's clone (about 2 min):
    python docs/records/session-40/pulse_from_lags.py"""
import tempfile
from collections import defaultdict
from pathlib import Path

import numpy as np

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening as s

SEED, CAMPAIGNS, END_S = 100000, 600, 0.15
size = median_sizes()
cases = [c for c in (draw_campaign(k, SEED, size) for k in range(CAMPAIGNS))
         if c.name.endswith("_pulse_from")]
clean, broken = defaultdict(list), defaultdict(list)
for b in range(0, len(cases), 20):
    batch = cases[b:b + 20]
    with tempfile.TemporaryDirectory() as tmp:
        make(batch, Path(tmp), log=False)
        for c in batch:
            d = Path(tmp) / c.name
            tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
            assign_setups(tests)
            found = {f.test for f in s.broken_before_fit(tests, END_S)}
            lags = {}
            for t in tests:
                fl = s._flight_ms(t, END_S)
                lags[t.name] = (t.setup, {"cr": s._rise_ms(t, t.cr_g, END_S)[-1] - fl,
                                          "cd": s._rise_ms(t, t.cd_mm, END_S)[-1] - fl,
                                          "brs": s._payout_lag_ms(t, END_S)})
            for name, (setup, own) in lags.items():
                mates = [v for n, (r, v) in lags.items()
                         if r == setup and n != name and n not in c.expect_broken]
                if len(mates) < 2:
                    continue
                off = {ch: own[ch] - float(np.median([m[ch] for m in mates])) for ch in own}
                if name in c.expect_broken:
                    broken["found" if name in found else "missed"].append(off)
                else:
                    for ch, v in off.items():
                        clean[ch].append(v)
for ch, v in clean.items():
    v = np.array(v)[np.isfinite(v)]
    print(f"clean {ch:3s} ({len(v)} tests): {v.min():+.1f} to {v.max():+.1f} ms, 1-99 %: "
          f"{np.percentile(v, 1):+.1f} to {np.percentile(v, 99):+.1f}")
for what, offs in broken.items():
    for o in sorted(offs, key=lambda o: o["cr"]):
        print(f"copied pulse, {what:6s}: CR {o['cr']:+6.1f}  CD {o['cd']:+6.1f}  "
              f"BRS {o['brs']:+6.1f} ms")
