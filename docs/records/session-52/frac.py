"""Each test's spool read at a fifth to four fifths of its pay-out [ms after the car's 50 mm
free flight]. python frac.py CASE_FOLDER ..."""

import sys
from pathlib import Path

import numpy as np

from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening as sc

END_S = 0.15
SHARES = (0.2, 0.35, 0.5, 0.65, 0.8)


def lags(t):
    i0, i1 = t.index_of(0.0), t.index_of(END_S) + 1
    flight = sc._flight_ms(t, END_S)
    paid = sc._paid_counts(np.asarray(t.brs[i0:i1], float))
    at = [int(np.argmax(paid >= f * paid.max())) * 1000 / t.fs_hz - flight for f in SHARES]
    return at, paid.max()


for arg in sys.argv[1:]:
    folder = Path(arg)
    tests = load_tests([*sorted((folder / "est").iterdir()), *sorted((folder / "val").iterdir())])
    assign_setups(tests)
    print(folder.name)
    for t in sorted(tests, key=lambda t: (t.setup, t.name)):
        at, most = lags(t)
        print(f"  {t.setup:5s} {t.name:9s} max {most:6.0f}  " + " ".join(f"{x:6.1f}" for x in at))
