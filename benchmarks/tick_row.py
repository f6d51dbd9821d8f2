"""The cost of handing one tick to the recorder's rings: the row the daemon keeps and refills
by field name (``TickRow``, ``tick_values``) beside a 19-field NamedTuple built positionally
per tick, as the daemon did before. Time per tick (best of 5) and the memory blocks left per
tick (tracemalloc).

    python benchmarks/tick_row.py [--n 200000]
"""

from __future__ import annotations

import argparse
import timeit
import tracemalloc
from collections.abc import Callable
from typing import NamedTuple

from observer_node.recording.format import TICK_COLS, TickRow, tick_values
from observer_node.recording.writer import Rings

Before = NamedTuple("Before", [(c, float) for c in TICK_COLS])  # type: ignore[misc]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=200_000)
    n = ap.parse_args().n
    rings = Rings(capacity=1 << 12)
    put = rings.put_tick
    row = TickRow()

    def before() -> None:
        put(Before(1.0, 2, 0.5, -0.5, 0.1, 3.0, 1.0, 0.06, 2.0, 3.0, True, True, 2, 0, 1, 5,
                   0.1, 0.2, 12.0))

    def now() -> None:
        r = row
        r.t, r.tick = 1.0, 2
        r.accel_x_g, r.decel_g, r.bias_g = 0.5, -0.5, 0.1
        r.brs_count, r.brs_ref = 3.0, 1.0
        r.rad_per_count, r.cr_g, r.cd_mm = 0.06, 2.0, 3.0
        r.valid, r.running, r.state = True, True, 2
        r.cause, r.event, r.onset_tick = 0, 1, 5
        r.ref_cr_g, r.ref_cd_mm = 0.1, 0.2
        r.proc_us = 12.0
        put(tick_values(r))

    runs: list[tuple[str, Callable[[], None]]] = [
        ("NamedTuple built positionally (before)", before),
        ("TickRow refilled by name (now)", now)]
    for name, f in runs:
        ns = min(timeit.repeat(f, number=n, repeat=5)) / n * 1e9
        f()
        tracemalloc.start()
        snap = tracemalloc.take_snapshot()
        for _ in range(1000):
            f()
        kept = sum(s.count_diff for s in tracemalloc.take_snapshot().compare_to(snap, "lineno")
                   if s.count_diff > 0)
        tracemalloc.stop()
        print(f"{name:40s} {ns:7.0f} ns per tick, {kept / 1000:.2f} blocks kept per tick")
    rings.close()


if __name__ == "__main__":
    main()
