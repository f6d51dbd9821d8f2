"""CR's mean after the crash over its mean in it (loop/screening._tail_against_crash), the
reading the threshold LEAK_TAIL was set from: on the bundled campaign, and on campaigns of the
independent held-out simulator (the dev seed 420000) clean, with every CR leaking at 0.6, 0.2
and 0.1 s, and at 0.45 of its sensitivity. Run from a checkout:
    PYTHONPATH=. python docs/records/session-42/tail_ratio.py 420000 20"""
import dataclasses
import sys
import tempfile
from pathlib import Path

import numpy as np

from benchmarks.heldout.cases import Effect
from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import bundled_campaign, load_tests
from observer_node.loop.screening import _tail_against_crash

SEED, N = int(sys.argv[1]), int(sys.argv[2])
bundled = [_tail_against_crash(t, 0.15) for t in load_tests([bundled_campaign()])]
print(f"bundled, clean: {min(bundled):+.2f} to {max(bundled):+.2f} ({len(bundled)} tests)")
variants = {"clean": (), "leak 0.6 s": (Effect("cr_ac_coupled", 0.6),),
            "leak 0.2 s": (Effect("cr_ac_coupled", 0.2),),
            "leak 0.1 s": (Effect("cr_ac_coupled", 0.1),), "x0.45": (Effect("cr_gain", -0.55),)}
size = median_sizes()
cases = []
for k in range(N):
    c = draw_campaign(k, SEED, size)
    phys = tuple(e for e in c.effects if not e.tests)
    cases += [dataclasses.replace(c, name=f"c{k}_{i}", effects=phys + extra, expect_broken=())
              for i, extra in enumerate(variants.values())]
reads: dict[str, list[float]] = {v: [] for v in variants}
with tempfile.TemporaryDirectory() as tmp:
    make(cases, Path(tmp), log=False)
    for c in cases:
        d = Path(tmp) / c.name
        v = list(variants)[int(c.name.rsplit("_", 1)[1])]
        tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
        reads[v] += [_tail_against_crash(t, 0.15) for t in tests]
for v, r in reads.items():
    a = np.array(r)
    print(f"drawn, {v:11s}: {a.min():+.2f} to {a.max():+.2f} ({len(a)} tests; "
          f"{np.mean(a < -0.25):.0%} under -0.25)")
