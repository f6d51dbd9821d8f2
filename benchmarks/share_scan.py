"""How much of the thesis grey-box's residual one effect explains, by its size: the loop's
first ranking (``observer_node.loop.analysis``) scores each effect by this share after a short
local fit from a start the linearised regression gives. Where the share is not one hill over
the effect's size, that fit can end in the wrong valley and the effect is never tried.

Found on held-out set J's webbing toe (2026-11-26): `belt_stiffening` explains -115 % at
kb3 = 1e8 N/m^3 (its typical size) and +17 % at 3e9, and the ranking's fit ended at kb3 ~ 1
(0.0 %), so only `chest_stiffening` (21 %) was cross-validated and named.

    python benchmarks/share_scan.py CASE_DIR [--effect belt_stiffening] [--decades 2 2]

CASE_DIR holds ``est/`` (a generated held-out case, or any folder of tests in ``est/``). Prints
the ranking as the loop makes it, then the share at the typical size times 10^k of each
single-parameter effect asked for.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from observer_node.data import load_tests
from observer_node.data.crashtest import CrashDataError
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop import analysis
from observer_node.loop.refit import model
from observer_node.model.effects import EFFECTS


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", type=Path, help="a folder with the estimation tests in est/")
    ap.add_argument("--effect", nargs="+", default=["belt_stiffening", "chest_stiffening"],
                    help="single-parameter effects to scan (default: both stiffenings)")
    ap.add_argument("--decades", nargs=2, type=int, default=(2, 2), metavar=("BELOW", "ABOVE"),
                    help="decades below and above the typical size (default 2 2)")
    a = ap.parse_args()
    bad = [k for k in a.effect if k not in EFFECTS or len(EFFECTS[k].params) != 1]
    if bad:
        ap.error(f"not a single-parameter effect: {bad[0]!r}")
    try:
        est = make_dataset(load_tests([a.case / "est"]), 1000.0)
    except CrashDataError as e:
        ap.exit(2, f"share_scan: {e}\n")
    m = model(dict(greybox.fit_greybox(est).params), [], est)
    print("the loop's first ranking (share %, start of its refit):")
    for c in analysis.candidates(m, est, set()):
        print(f"  {c.kind:20s}{100 * c.explained:8.1f}  {c.parameters}")
    y_hat = m.simulate(est.pulse_g, est.brs_rad)
    scorer = analysis._Scorer(m, est, (est.y - y_hat)[:, est.win], analysis.weights(est),
                              analysis.base_sensitivities(m, est, y_hat), y_hat)
    steps = np.arange(-2 * a.decades[0], 2 * a.decades[1] + 1) / 2  # half decades
    for kind in a.effect:
        (p,) = EFFECTS[kind].params
        print(f"{kind}: share % at {p.name} [{p.unit}] =")
        for k in steps:
            v = p.typical * 10.0 ** k
            print(f"  {v:9.2e}{100 * scorer.share(kind, {p.name: v})[0]:9.1f}")


if __name__ == "__main__":
    main()
