"""Every independent set's cases made once and screened before any fit; each flag tagged by
the check that raised it. python screen_all.py OUTDIR JSON [letters...]"""

import json
import sys
from pathlib import Path

from benchmarks.heldout.make_sets import make
from benchmarks.heldout.sets import SETS, case_set
from observer_node.data import CrashDataError, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening as sc

END_S = 0.15
CHECKS = (
    "copied_channels",
    "copied_pulses",
    "polled_spools",
    "held_end_outliers",
    "polarity_outliers",
    "reversed_outputs",
    "velocity_outliers",
    "speed_share_outliers",
    "payout_outliers",
    "output_step_outliers",
    "spool_gain_outliers",
    "ringing_outliers",
    "pulse_step_outliers",
)


def tagged(tests):
    broken = [("channel", b) for t in tests for b in sc.screen_channels(t, END_S)]
    flagged = {b.test for _, b in broken}
    for name in CHECKS:
        broken += [
            (name, b) for b in getattr(sc, name)([t for t in tests if t.name not in flagged], END_S)
        ]
        flagged = {b.test for _, b in broken}
    return broken


out, js = Path(sys.argv[1]), Path(sys.argv[2])
letters = sys.argv[3:] or list(SETS)
rows = []
for s in letters:
    cases = case_set(s)
    if not (out / cases[-1].name / "truth.json").exists():
        make(cases, out, log=False)
    for c in cases:
        folder = out / c.name
        files = [*sorted((folder / "est").iterdir()), *sorted((folder / "val").iterdir())]
        try:
            tests = load_tests(files)
        except CrashDataError as e:
            rows.append({"set": s, "case": c.name, "refused": str(e)})
            continue
        assign_setups(tests)
        found = tagged(tests)
        rows.append(
            {
                "set": s,
                "case": c.name,
                "broken": list(c.expect_broken),
                "flags": [[chk, b.test, b.channel, b.reason] for chk, b in found],
            }
        )
    print(s, flush=True)
js.write_text(json.dumps(rows, indent=1))
