"""How long the non-linear model takes to simulate: the loop's inner cost.

The loop spends nine tenths of its time simulating the non-linear model tick by tick over a
few tests (its refits, their Jacobians, the cross-validation folds). Printed: milliseconds per
simulation of the bundled campaign's 12 estimation tests (odd numbers) at 1 kHz, one model
alone (``simulate``) and a batch of ``--batch`` models of one structure (``simulate_many``, as
a fit's Jacobian runs), for the grey-box alone and for structures the loop builds; the best of
``--repeat`` runs, each structure's, in one process.

    python benchmarks/simulation.py [--batch 20] [--repeat 15]
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

from observer_node.data import bundled_campaign, load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.model.effects import EFFECTS
from observer_node.model.nonlinear import NonlinearGreyBox, simulate_many


def _effect(kind: str, setups: list[str] | None = None) -> dict:
    e: dict = {"kind": kind, "parameters": dict(EFFECTS[kind].typical)}
    if setups:
        e["setups"] = setups
    return e


STRUCTURES = {
    "grey-box": [],
    "belt unloading + chest stiffening + airbag on SLED, FULL": [
        _effect("belt_unloading"), _effect("chest_stiffening"),
        _effect("airbag_contact", ["FULL", "SLED"])],
    "chest stiffening + airbag": [_effect("chest_stiffening"), _effect("airbag_contact")],
    "pelvis on SLED + spool gain + belt stiffening + rib damping on R16": [
        _effect("pelvis_coupling", ["SLED"]), _effect("input_gain"),
        _effect("belt_stiffening"), _effect("chest_rate_damping", ["R16"])],
}


def _best_ms(models: list[NonlinearGreyBox], pulse_g: np.ndarray, brs_rad: np.ndarray,
             repeat: int) -> tuple[float, bool]:
    """The best time [ms] of ``repeat`` simulations of the models, and whether every output
    is finite (a model that runs away is no measure of the work)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        y = simulate_many(models, pulse_g, brs_rad) if len(models) > 1 else \
            models[0].simulate(pulse_g, brs_rad)
        times.append(time.perf_counter() - t0)
    return min(times) * 1e3, bool(np.isfinite(y).all())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--batch", type=int, default=20, help="models in a batch (default 20)")
    ap.add_argument("--repeat", type=int, default=15, help="runs of each, the best kept")
    args = ap.parse_args()
    if args.batch < 2 or args.repeat < 1:
        ap.error("--batch must be at least 2 and --repeat at least 1")
    tests = load_tests([bundled_campaign()])
    est = make_dataset([t for t in tests if int(t.name[-1]) % 2 == 1], 1000.0)
    base = dict(greybox.fit_greybox(est).params)
    print(f"{est.n_tests} tests x {est.pulse_g.shape[1]} ticks; ms per simulation "
          f"(best of {args.repeat})")
    print(f"{'structure':68s}{'one':>8s}{f'{args.batch} models':>12s}")
    for name, effects in STRUCTURES.items():
        # the batch as a Jacobian's trial points: each model's values a little apart
        models = [NonlinearGreyBox({k: v * (1 + 1e-3 * j) for k, v in base.items()},
                                   effects, est.fs_hz, est.setups)
                  for j in range(args.batch)]
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            one, ok1 = _best_ms(models[:1], est.pulse_g, est.brs_rad, args.repeat)
            many, ok = _best_ms(models, est.pulse_g, est.brs_rad, args.repeat)
        print(f"{name:68s}{one:8.2f}{many:12.2f}"
              + ("" if ok1 and ok else "  (ran away: not a fair measure)"), flush=True)


if __name__ == "__main__":
    main()
