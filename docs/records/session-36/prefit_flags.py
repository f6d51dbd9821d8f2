"""Pre-fit flags (the loop's _screened order) on every held-out test of /work/runs/s36/sets
(made with ``python -m benchmarks.heldout.make_sets --out /work/runs/s36/sets/<x> --set <x>``
for sets a-ab): with tests already found broken left out of the later checks (as the loop
does since 2026-11-29) and kept in; the velocity check's flags; any clean test flagged."""
import glob
import json
from pathlib import Path

from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import (
    output_step_outliers,
    payout_outliers,
    polarity_outliers,
    screen_channels,
    velocity_outliers,
)


def pipeline(tests, exclude):
    broken = [b for t in tests for b in screen_channels(t, 0.15)]
    flagged = {b.test for b in broken}
    for check in (polarity_outliers, velocity_outliers, payout_outliers, output_step_outliers):
        pool = [t for t in tests if t.name not in flagged] if exclude else tests
        broken += [b for b in check(pool, 0.15) if b.test not in flagged]
        flagged = {b.test for b in broken}
    return {(b.test, b.channel, b.reason[:30]) for b in broken}
n, diffs, vflags, clean_flag = 0, [], [], []
for case in sorted(glob.glob('/work/runs/s36/sets/*/*/')):
    tr = json.loads(Path(case, 'truth.json').read_text())
    eff = {t['name']: t['effects'] for t in tr['tests']}
    tests = load_tests(sorted(glob.glob(case + 'est/*')) + sorted(glob.glob(case + 'val/*')))
    assign_setups(tests)
    n += len(tests)
    new, old = pipeline(tests, True), pipeline(tests, False)
    c = case.split('/')[-2]
    if new != old:
        diffs.append((c, sorted(new - old), sorted(old - new)))
    for t, ch, r in new:
        if r.startswith('integrates'):
            vflags.append((c, t, t in tr['expected']['broken_tests'], list(eff.get(t, {}))))
        if not eff.get(t):
            clean_flag.append((c, t, ch, r))
print(n, 'tests')
print('velocity flags', len(vflags))
for v in vflags:
    print(' ', v)
print('new vs old differences', diffs)
print('clean tests flagged (any pre-fit check, new):', clean_flag)
