"""In-sample shape gains per output (max over setups) on the grey-box as fitted:
static, lag, drift."""
import sys
from pathlib import Path

import numpy as np

from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop import diagnosis
from observer_node.loop.refit import model


def main(sets, s, case):
    data = make_dataset(load_tests([Path(sets) / s / case / "est"]), 1000.0)
    base = dict(greybox.fit_greybox(data).params)
    with np.errstate(all="ignore"):
        yh = model(base, [], data).simulate(data.pulse_g, data.brs_rad)
    y, yw = data.y[:, data.win], yh[:, data.win]
    setups = list(dict.fromkeys(data.setups))
    out = []
    for k, o in enumerate(("cr", "cd")):
        b = diagnosis._fits(y[..., k], yw[..., k])
        parts = []
        for shape in ("static", "lag", "drift"):
            X = diagnosis._basis(yh[..., k], shape, data.fs_hz)[:, data.win]
            fix = X @ diagnosis._solve(y[..., k] - yw[..., k], X)
            g = diagnosis._fits(y[..., k], yw[..., k] + fix) - b
            per = max(float(np.mean([g[i] for i, t in enumerate(data.setups) if t == su]))
                      for su in setups)
            parts.append(f"{shape[:2]}{per:.2f}")
        out.append(o + ":" + ",".join(parts))
    print(f"{case:24s} " + "  ".join(out), flush=True)

if __name__ == "__main__":
    main(*sys.argv[1:])
