"""An x2 decoder (both edges of one track, the header keeping the spindle's own counts/rev:
the simulator's ``brs_quadrature`` at 2) on one test in each of N campaigns drawn afresh
from the independent held-out simulator (screen_faults' draw, seed SEED+k; its physical
effects kept, no other broken channel; the x2 test is the campaign's (k mod 12)-th). Counted:
the x2 tests the spool-gain check can judge (three or more rig-mates with a reading), how
many the checks before the fit name on the BRS, and the clean tests they name.
Run from a checkout (or with PYTHONPATH at another checkout, for a before/after):
    PYTHONPATH=. python docs/records/session-43/x2_decoder.py 490000 36"""
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
from observer_node.loop import screening as S

SEED, N = int(sys.argv[1]), int(sys.argv[2])
size = median_sizes()
cases = []
for k in range(N):
    c = draw_campaign(k, SEED, size)
    est, val = test_names(c)
    name = [*est, *val][k % 12]
    cases.append(dataclasses.replace(
        c, name=f"q{k}", expect_broken=(name,),
        effects=(*(e for e in c.effects if not e.tests),
                 Effect("brs_quadrature", 2.0, tests=(name,)))))
judged = named = clean = n_clean = 0
with tempfile.TemporaryDirectory() as tmp:
    make(cases, Path(tmp), log=False)
    for c in cases:
        d = Path(tmp) / c.name
        tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
        assign_setups(tests)
        (x,) = [t for t in tests if t.name in c.expect_broken]
        mates = [t for t in tests if t is not x and t.setup == x.setup
                 and np.isfinite(S._spool_reading(t, 0.15)[0])]
        ok = len(mates) >= 3 and np.isfinite(S._spool_reading(x, 0.15)[0])
        found = S.broken_before_fit(tests, 0.15)
        hit = any(b.test == x.name and b.channel == "brs" for b in found)
        judged += ok
        named += hit and ok
        n_clean += len(tests) - 1
        clean += len({b.test for b in found} - {x.name})
        print(f"{c.name} {c.counts_per_rev:3d}/rev {x.name:9s} {'judged' if ok else '      '} "
              f"{'NAMED' if hit else '     '} "
              + "; ".join(f"{b.test} {b.channel}: {b.reason[:70]}" for b in found))
print(f"seed {SEED}: x2 tests judged {judged} of {N}, named on BRS {named}; "
      f"clean tests named {clean} of {n_clean}")
