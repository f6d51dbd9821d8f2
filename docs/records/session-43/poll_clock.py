"""A spool decoder whose poll clock does not divide the record's rate, on campaigns drawn
afresh from the independent held-out simulator (screen_faults' draw, seed SEED+k; physical
effects only, no broken channel): each test in turn has its BRS read by a quadrature decoder
polling at RATE Hz (it sees only the tracks' phase: a move of 1 reads 1, of 2 none, of 3 one
back; held between polls; the first poll 0.37 ms into the record). Counted per rate: the
polled tests whose reading lost or reversed 2 counts or more in the window (damaged), and of
those how many the checks before the fit name on the BRS (polled_spools, and
broken_before_fit at all); and for every clean campaign, the tests polled_spools names.
Run from a checkout (or with PYTHONPATH at another checkout, for a before/after):
    PYTHONPATH=. python docs/records/session-43/poll_clock.py 480000 24"""
import dataclasses
import sys
import tempfile
from pathlib import Path

import numpy as np

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening as S

RATES = (800.0, 1005.0, 1024.0, 1500.0, 3000.0, 1000.0)  # 1000: divides, as the simulator's


def poll(b: np.ndarray, fs: float, rate: float, phase_s: float = 0.37e-3) -> np.ndarray:
    b = np.asarray(b, float)
    at = np.unique(np.minimum(np.floor(np.arange(phase_s, len(b) / fs, 1.0 / rate) * fs)
                              .astype(int), len(b) - 1))
    step = np.select([np.diff(b[at]) % 4 == 1, np.diff(b[at]) % 4 == 3], [1.0, -1.0], 0.0)
    read = np.concatenate([[b[at[0]]], b[at[0]] + np.cumsum(step)])
    out = read[np.clip(np.searchsorted(at, np.arange(len(b)), side="right") - 1, 0, None)]
    out[:at[0]] = b[0]
    return out


SEED, N = int(sys.argv[1]), int(sys.argv[2])
size = median_sizes()
cases = []
for k in range(N):
    c = draw_campaign(k, SEED, size)
    cases.append(dataclasses.replace(c, name=f"c{k}", expect_broken=(),
                                     effects=tuple(e for e in c.effects if not e.tests)))
res = {r: [0, 0, 0, 0] for r in RATES}
clean = [0, 0]
with tempfile.TemporaryDirectory() as tmp:
    make(cases, Path(tmp), log=False)
    for c in cases:
        d = Path(tmp) / c.name
        tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
        assign_setups(tests)
        clean[0] += len(tests)
        clean[1] += len(S.polled_spools(tests, 0.15))
        for rate in RATES:
            for i, x in enumerate(tests):
                y = dataclasses.replace(x, brs=poll(x.brs, x.fs_hz, rate))
                i0, i1 = x.index_of(0.0), x.index_of(0.15) + 1
                if np.max(np.abs(y.brs - x.brs)[i0:i1]) < 2:
                    continue
                ts = [*tests[:i], y, *tests[i + 1:]]
                r = res[rate]
                r[0] += 1
                r[1] += any(b.test == x.name for b in S.polled_spools(ts, 0.15))
                named = [b for b in S.broken_before_fit(ts, 0.15) if b.test == x.name]
                r[2] += any(b.channel == "brs" for b in named)
                r[3] += bool(named)
print(f"seed {SEED}, {N} campaigns, {clean[0]} tests")
for rate, (n, p, brs, anyn) in res.items():
    print(f"poll at {rate:6.0f} Hz ({10000 / rate:5.2f} samples): damaged {n:3d}; named by "
          f"polled_spools {p:3d}; named on brs {brs:3d}; named at all {anyn:3d}")
print(f"clean tests named by polled_spools: {clean[1]} of {clean[0]}")
