"""The checks before the fit (loop/screening.broken_before_fit) on every case of the held-out
sets A-AB, as at the start of session 38 (commit 6ab39f1, read from git) and now (a campaign
the reader now refuses is reported, not judged): which tests each names, the case's broken
tests apart from the rest, and what only one of the two names.
The sets are made with ``python -m benchmarks.heldout.make_sets --out SETS/<x> --set <x>``
(SETS defaults to /work/runs/s36/sets, or the first argument); the bundled campaign is judged
whole first. Run from the repository's clone:
    python docs/records/session-38/heldout_prefit.py [SETS]"""
import glob
import json
import os
import sys
from pathlib import Path

from before import screening_at

from observer_node.data import CrashDataError, bundled_campaign, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import broken_before_fit

BEFORE = os.environ.get("BEFORE", "6ab39f1")  # session 39 ran it with b8486ee
before = screening_at(BEFORE)

bundled = load_tests([bundled_campaign()])
assign_setups(bundled)
print("bundled campaign, now:", [(b.test, b.channel) for b in broken_before_fit(bundled, 0.15)])

sets = sys.argv[1] if len(sys.argv) > 1 else "/work/runs/s36/sets"
tally = {"before": [0, 0], "now": [0, 0]}
n_tests = n_broken = 0
for case in sorted(glob.glob(f"{sets}/*/*/")):
    truth = json.loads(Path(case, "truth.json").read_text())
    expected = set(truth["expected"]["broken_tests"])
    try:
        tests = load_tests(sorted(glob.glob(case + "est/*")) + sorted(glob.glob(case + "val/*")))
    except CrashDataError as e:
        print(f"{Path(case).name}: refused by the reader (broken {sorted(expected)}): {e}")
        continue
    assign_setups(tests)
    n_tests += len(tests)
    n_broken += len(expected)
    named = {}
    for label, check in (("before", before.broken_before_fit), ("now", broken_before_fit)):
        named[label] = {(b.test, b.channel): b.reason for b in check(tests, 0.15)}
        tests_named = {t for t, _ in named[label]}
        tally[label][0] += len(tests_named & expected)
        tally[label][1] += len(tests_named - expected)
    for key in sorted(set(named["now"]) ^ set(named["before"])):
        which = "now only" if key in named["now"] else "before only"
        kind = "broken" if key[0] in expected else "CLEAN"
        reason = named["now"].get(key) or named["before"][key]
        print(f"{Path(case).name}: {which}: {kind} {key[0]} {key[1]}: {reason[:100]}")
print(f"{n_tests} tests, {n_broken} broken (the cases' own)")
for label, (right, wrong) in tally.items():
    print(f"{label}: broken tests named {right} of {n_broken}; clean tests named {wrong}")
