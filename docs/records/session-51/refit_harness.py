"""Which transducer, by a refit: correct one output's measurement by its static correction
(fitted on a fold's training tests), refit the chest model on the corrected training tests,
and score the held-out tests. The culprit's correction unbends the model, so the refit gains
in the OTHER output too; a healthy output's correction gains nothing more by a refit."""
import dataclasses
import sys
from pathlib import Path

import numpy as np

from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.ident.metrics import fit_percent
from observer_node.loop.diagnosis import FOLD_NFEV, _basis, _solve
from observer_node.loop.refit import folds, model, refit_from


def fits(y, yh):
    return np.array([[fit_percent(y[i, :, j], yh[i, :, j]) for j in range(2)]
                     for i in range(len(y))])


def main(sets, s, case):
    data = make_dataset(load_tests([Path(sets) / s / case / "est"]), 1000.0)
    base = dict(greybox.fit_greybox(data).params)
    rows = {o: {"static": [], "refit": [], "before": []} for o in ("cr", "cd")}
    with np.errstate(all="ignore"):
        for tr_i, te_i in folds(data):
            tr, te = data.subset(tr_i), data.subset(te_i)
            r = refit_from(base, [], tr, FOLD_NFEV)
            yh_tr = model(r.base, r.effects, tr).simulate(tr.pulse_g, tr.brs_rad)
            yh_te = model(r.base, r.effects, te).simulate(te.pulse_g, te.brs_rad)
            y_te = te.y[:, te.win]
            before = fits(y_te, yh_te[:, te.win])
            for k, o in enumerate(("cr", "cd")):
                scale = float(np.max(np.abs(yh_tr[..., k]))) or 1.0
                X_tr = _basis(yh_tr[..., k], "static", tr.fs_hz, scale)
                coef = _solve(tr.y[:, tr.win, k] - yh_tr[:, tr.win, k], X_tr[:, tr.win])
                corr = yh_te.copy()
                corr[..., k] += _basis(yh_te[..., k], "static", te.fs_hz, scale) @ coef
                static = fits(y_te, corr[:, te.win])
                # the transducer's reading without the error: y - correction(y_hat)
                y_tr2 = tr.y.copy()
                y_tr2[..., k] -= X_tr @ coef
                r2 = refit_from(r.base, [], dataclasses.replace(tr, y=y_tr2), FOLD_NFEV)
                yh2_tr = model(r2.base, r2.effects, tr).simulate(tr.pulse_g, tr.brs_rad)
                yh2_te = model(r2.base, r2.effects, te).simulate(te.pulse_g, te.brs_rad)
                # the correction as it reads through the refitted model
                X2 = _basis(yh2_tr[..., k], "static", tr.fs_hz, scale)
                coef2 = _solve(tr.y[:, tr.win, k] - yh2_tr[:, tr.win, k], X2[:, tr.win])
                c2 = yh2_te.copy()
                c2[..., k] += _basis(yh2_te[..., k], "static", te.fs_hz, scale) @ coef2
                refit = fits(y_te, c2[:, te.win])
                rows[o]["before"].append(before)
                rows[o]["static"].append(static)
                rows[o]["refit"].append(refit)
    out = []
    for k, o in enumerate(("cr", "cd")):
        b = np.concatenate(rows[o]["before"])
        st = np.concatenate(rows[o]["static"]) - b
        rf = np.concatenate(rows[o]["refit"]) - b
        out.append(f"{o}: static tot{st.mean():+.2f} | refit tot{rf.mean():+.2f} "
                   f"own{rf[:, k].mean():+.2f} other{rf[:, 1 - k].mean():+.2f} "
                   f"other>0 {int((rf[:, 1 - k] > 0).sum())}/{len(rf)}")
    print(f"{case:22s} " + " || ".join(out), flush=True)


if __name__ == "__main__":
    main(*sys.argv[1:])
