"""Closed-loop benchmark: for each effect of the library, 12 estimation and 12 validation
tests from the plant simulator with that effect only (sensor noise and CFC filtering on),
the loop run blind; printed: what it accepted, the validation fit_TOT before and after, and
the run time. Then the same on campaign-a (odd tests estimate, even validate).
Targets: final validation fit_TOT >= 95 % when the only missing effect is one of the library's;
the whole loop over 12 + 12 tests in under 3 minutes on these 2-core machines.

    python benchmarks/loop.py [--effects belt_unloading ...] [--no-campaign]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from observer_node.data import bundled_campaign, load_tests
from observer_node.evaluation import split_halves
from observer_node.loop.closed_loop import run_loop
from observer_node.simulator import EFFECTS, PlantConfig, simulate_campaign

SETUP = {"airbag_contact": "SLED"}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--effects", nargs="+", default=sorted(EFFECTS))
    ap.add_argument("--no-campaign", action="store_true")
    ap.add_argument("--rate", type=float, default=1000.0, help="tick rate in Hz (1000)")
    a = ap.parse_args()
    work = Path(tempfile.mkdtemp())
    print(f"tick rate {a.rate:g} Hz")
    print(f"{'hidden effect':<20}{'setup':<6}{'accepted':<48}{'before':>8}{'after':>8}"
          f"{'time s':>8}")
    for kind in a.effects:
        setup = SETUP.get(kind, "R16")
        cfg = PlantConfig(effects={kind: 1.0})
        est = simulate_campaign(setup, 12, seed=31, config=cfg, prefix="EST")
        val = simulate_campaign(setup, 12, seed=32, config=cfg, prefix="VAL")
        t0 = time.monotonic()
        r = run_loop(est, val, work / kind, rate_hz=a.rate, verbose=False)
        found = ", ".join(e["kind"] for e in r["effects"]) or "(none)"
        print(f"{kind:<20}{setup:<6}{found:<48}{r['baseline']['fit']['total']:>8.1f}"
              f"{r['final']['fit']['total']:>8.1f}{time.monotonic() - t0:>8.1f}", flush=True)
    if not a.no_campaign:
        est, val = split_halves(load_tests([bundled_campaign()]))
        t0 = time.monotonic()
        r = run_loop(est, val, work / "campaign", rate_hz=a.rate, verbose=False)
        found = ", ".join(e["kind"] for e in r["effects"]) or "(none)"
        print(f"{'campaign-a':<20}{'all':<6}{found:<48}{r['baseline']['fit']['total']:>8.1f}"
              f"{r['final']['fit']['total']:>8.1f}{time.monotonic() - t0:>8.1f}")


if __name__ == "__main__":
    main()
