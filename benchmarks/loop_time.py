"""How long one loop takes on 12 + 12 tests, at 1 and 2 Dask workers, idle and with both
cores busy (two spinning processes started here, beside it).

The tests are the bundled campaign's (odd numbers estimate, even validate). Target: under 3
minutes idle. The numbers are wall-clock seconds of one run each; the machine's other load
is not controlled beyond the spinners, so run it on a quiet machine.

    python benchmarks/loop_time.py [--workers 1 2] [--no-load | --loaded-only] [--out DIR]
"""

from __future__ import annotations

import argparse
import multiprocessing
import tempfile
import time
from pathlib import Path

from observer_node.data import bundled_campaign, load_tests
from observer_node.loop.closed_loop import run_loop


def _spin() -> None:
    while True:
        pass


def one_run(workers: int, loaded: bool, out: Path) -> tuple[float, list[str], float]:
    tests = load_tests([bundled_campaign()])
    est = [t for t in tests if int(t.name[-1]) % 2 == 1]
    val = [t for t in tests if int(t.name[-1]) % 2 == 0]
    spinners = [multiprocessing.Process(target=_spin, daemon=True) for _ in range(2 * loaded)]
    for p in spinners:
        p.start()
    try:
        t0 = time.monotonic()
        r = run_loop(est, val, out, verbose=False, plots=False, ratings=False, workers=workers)
        return time.monotonic() - t0, [e.kind for e in r.effects], \
            r.final.fit.total
    finally:
        for p in spinners:
            p.terminate()
            p.join()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--no-load", action="store_true", help="idle runs only")
    when.add_argument("--loaded-only", action="store_true",
                      help="runs with both cores busy only")
    ap.add_argument("--out", type=Path, help="keep the reports in OUT (default: temporary)")
    a = ap.parse_args()
    work = a.out or Path(tempfile.mkdtemp())
    print(f"{'workers':>8}{'cores busy':>12}{'seconds':>9}  effects (final fit_TOT %)",
          flush=True)
    for loaded in (False,) if a.no_load else (True,) if a.loaded_only else (False, True):
        for n in a.workers:
            s, kinds, fit = one_run(n, loaded, work / f"w{n}-{'load' if loaded else 'idle'}")
            print(f"{n:>8}{'2' if loaded else '0':>12}{s:9.0f}  {', '.join(kinds)} ({fit:.1f})",
                  flush=True)


if __name__ == "__main__":
    main()
