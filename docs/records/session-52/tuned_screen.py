"""The loop's checks before the fit on every tuned and library held-out case of
benchmarks/loop.py. python tuned_screen.py CHECKOUT"""

import sys

sys.path.insert(0, sys.argv[1])
sys.path.insert(0, sys.argv[1] + "/benchmarks")
import loop as L

from observer_node.data.setups import assign_setups
from observer_node.loop.screening import broken_before_fit
from observer_node.simulator import simulate_mixed

for case in L.CASES + L.HELD_OUT:
    cfg = case.configs()
    est = simulate_mixed(case.counts, case.seed, cfg, "E", case.meta)
    val = simulate_mixed(case.counts, case.seed + 1000, cfg, "V", case.meta)
    assign_setups([*est, *val])
    print(
        case.name,
        sorted((b.test, b.channel) for b in broken_before_fit([*est, *val], 0.15)),
        flush=True,
    )
