"""Round-1 sensor evidence per basis variant, from the loop's own baseline fit (no full loop)."""
import json
import sys
from pathlib import Path

import numpy as np

from observer_node.data import load_tests
from observer_node.ident.dataset import make_dataset
from observer_node.loop import diagnosis
from observer_node.loop.refit import fold_scores, folds
from observer_node.loop.rounds import _judge_folds

orig = diagnosis._basis

def make_basis(cols):
    def b(y_hat, shape, fs_hz, scale=0.0):
        if shape == "lag":
            return orig(y_hat, shape, fs_hz, scale)
        s = scale or float(np.max(np.abs(y_hat))) or 1.0
        u = y_hat / s
        n = y_hat.shape[1]
        tau = np.broadcast_to(np.arange(n) / n, y_hat.shape)
        du = np.gradient(u, axis=1) * n / 20.0
        allc = {"u2": u**2, "u3": u**3, "u": u, "tu": tau*u, "tdu": tau*du, "t": tau}
        return np.stack([allc[c] for c in cols], axis=-1)
    return b

VARIANTS = {
    "static": ["u2", "u3", "u"],
    "union": ["u2", "u3", "u", "tu", "tdu", "t"],
    "drift": ["tu", "tdu", "t"],
    "tu": ["tu"],
    "st+tu": ["u2", "u3", "u", "tu"],
    "st+tdu": ["u2", "u3", "u", "tdu"],
    "st+t": ["u2", "u3", "u", "t"],
}

def main(sets, s, case, report_dir):
    est_tests = load_tests([Path(sets) / s / case / "est"])
    data = make_dataset(est_tests, 1000.0)
    bm = Path(report_dir) / "baseline-model.json"
    if bm.exists():
        base = {k: v["value"] for k, v in json.loads(bm.read_text())["parameters"].items()}
    else:
        from observer_node.ident import greybox
        base = dict(greybox.fit_greybox(data).params)
    fl = folds(data)
    test_setup = dict(zip(data.names, data.setups, strict=False))
    with np.errstate(all="ignore"):
        now = {}
        for tr, te in fl:
            now.update(fold_scores(base, [], data, tr, te))
        out = []
        fits = [diagnosis.refit_from(base, [], data.subset(tr), diagnosis.FOLD_NFEV)
                for tr, _ in fl]
        real_refit = diagnosis.refit_from
        for name, cols in VARIANTS.items():
            diagnosis._basis = make_basis(cols)
            raw = {"cr": {}, "cd": {}}
            for (tr, te), f in zip(fl, fits, strict=False):
                diagnosis.refit_from = lambda *a, f=f, **k: f
                r = diagnosis.sensor_fold_scores(base, [], data, tr, te)
                diagnosis.refit_from = real_refit
                for o in raw:
                    raw[o].update(r[o])
            ev = {o: _judge_folds(now, raw[o], test_setup, None, 1.0) for o in raw}
            out.append(f"{name}: " + " ".join(
                f"{o}{e.gain_points:+.2f}{'*' if e.accepted else ''}" for o, e in ev.items()))
    print(f"{case:22s} " + " | ".join(out), flush=True)

if __name__ == "__main__":
    main(*sys.argv[1:])
