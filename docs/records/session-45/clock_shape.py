"""Would a clock shape (t * dy/dt: a digitiser's time base off) say more than static and lag?
Per case of the stored reports: the final model on the estimation tests, each shape's in-sample
gain per output and setup (max over setups) [points]. Session 45, measurement only."""
import json
import sys
from pathlib import Path

import numpy as np

from benchmarks.loop_heldout import load_tests
from observer_node.ident.dataset import make_dataset
from observer_node.ident.metrics import OUTPUT_NAMES
from observer_node.loop import diagnosis as D
from observer_node.loop.refit import model


def gains(data, y_hat, X_of):
    y, yh = data.y[:, data.win], y_hat[:, data.win]
    out = {}
    for k, o in enumerate(OUTPUT_NAMES):
        base = D._fits(y[..., k], yh[..., k])
        X = X_of(y_hat[..., k], data)[:, data.win]
        corr = yh[..., k] + X @ D._solve(y[..., k] - yh[..., k], X)
        g = D._fits(y[..., k], corr) - base
        out[o] = max(np.mean([g[i] for i, s in enumerate(data.setups) if s == t])
                     for t in set(data.setups))
    return out

def clock(yk, data):
    t = np.arange(yk.shape[1]) / data.fs_hz
    return (t * np.gradient(yk, 1.0 / data.fs_hz, axis=1))[..., None]

for reports, sets in zip(sys.argv[1::2], sys.argv[2::2], strict=True):
    for rep in sorted(Path(reports).glob("*/report.json")):
        case = rep.parent.name
        r = json.loads(rep.read_text())
        m = json.loads((rep.parent / "model.json").read_text())
        base = r["final"]["parameters"]
        est = make_dataset(load_tests([Path(sets) / case / "est"]))
        with np.errstate(all="ignore"):
            yh = model(base, m.get("effects", []), est).simulate(est.pulse_g, est.brs_rad)
        row = {s: gains(est, yh, (lambda yk, d, s=s: D._basis(yk, s, d.fs_hz)))
               for s in ("static", "lag")}
        row["clock"] = gains(est, yh, clock)
        cols = ("  ".join(f"{o}: " + " ".join(f"{s[:2]} {row[s][o]:5.2f}" for s in row)
                          for o in OUTPUT_NAMES))
        print(f"{case:42s} m2 {base['m2']:7.4f} {cols}", flush=True)
