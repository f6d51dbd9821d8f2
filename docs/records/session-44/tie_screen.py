"""Offline screen (session 44): does a tie's true side keep its parameters from test to test?

A physical effect of the dummy or the belt is the same in every crash (up to the dummy's
scatter, 3-10 %); a mimic stands in for it by an amount that depends on each crash. So
each side of a tie is fitted on each estimation test alone (base and effect parameters free,
from the all-test fit), and the spread of its effect parameters across the tests is read:
sd of log(value) for a positive parameter. Also the rank correlation of each parameter with
the crash's severity (the test's peak measured CD).

Runs the loop on the given cases with its tie look-past wrapped to capture the tie's model
and sides; prints one line per side.

    PYTHONPATH=. python docs/records/session-44/tie_screen.py SETS_DIR SET CASE [CASE ...]

SETS_DIR from ``python -m benchmarks.heldout.make_sets --set SET [--est-times 2]``; CASE
is a folder name there (``..._est12`` with ``--est-times 2``). About 2 min a case of six
tests on this machine, 4-6 min of twelve. The pooling gap per test, printed first: the
test's fit_TOT [%] with the side's effect parameters free on it alone, less that with them
held at the all-test fit (base parameters refitted on the test alone in both).
"""
import sys
import tempfile
from pathlib import Path

import numpy as np
from scipy import stats

from benchmarks.heldout.sets import select
from benchmarks.loop_heldout import load_tests
from observer_node.loop import rounds
from observer_node.loop.closed_loop import run_loop
from observer_node.loop.refit import refit, refit_from, score

captured: list = []
_orig = rounds._look_past


def _capture(runner, base, effects, data, folds_, a, b, per_test, test_setup, margin):
    captured.append((dict(base), [dict(e) for e in effects], data, a, b, dict(test_setup)))
    return _orig(runner, base, effects, data, folds_, a, b, per_test, test_setup, margin)


rounds._look_past = _capture


def base_only(base, effects, data, max_nfev=40):
    """The base parameters refitted on ``data`` with every effect held as given."""
    from scipy import optimize

    from observer_node.ident.greybox import FREE
    from observer_node.loop.analysis import weights
    from observer_node.loop.refit import model
    w = weights(data)
    y = data.y[:, data.win]

    def res(theta):
        b = dict(zip(FREE, np.exp(theta), strict=False))
        b["m1"] = base["m1"]
        with np.errstate(all="ignore"):
            yh = model(b, effects, data).simulate(data.pulse_g, data.brs_rad)
        r = ((yh[:, data.win] - y) * w[:, None, :]).ravel()
        return np.where(np.isfinite(r) & (np.abs(r) < 1e3), r, 1e3)
    th = optimize.least_squares(res, np.log(np.maximum([base[n] for n in FREE], 1e-300)),
                                method="trf", max_nfev=max_nfev).x
    b = dict(zip(FREE, np.exp(th), strict=False))
    b["m1"] = base["m1"]
    return b


def side_spread(base, effects, data, cand, judged):
    fit = refit(base, [*effects, cand.effect()], data, max_nfev=120)
    idx = [i for i, n in enumerate(data.names) if n in judged
           and (cand.setups is None or data.setups[i] in cand.setups)]
    pool_gap = []
    for i in idx:
        one = data.subset([i])
        b = base_only(fit.base, fit.effects, one)
        r = refit_from(fit.base, fit.effects, one, max_nfev=40)
        pool_gap.append(score(r.base, r.effects, one).fit.total
                        - score(b, fit.effects, one).fit.total)
    print(f"      pooling gap per test (free - pooled effect, base free both) "
          f"{np.round(pool_gap, 2).tolist()} mean {np.mean(pool_gap):.2f}", flush=True)
    per: dict[str, list[float]] = {}
    fits = []
    for i in idx:
        try:
            r = refit_from(fit.base, fit.effects, data.subset([i]), max_nfev=40)
        except ValueError:
            continue
        for k, v in r.effects[-1]["parameters"].items():
            if isinstance(v, (int, float)):
                per.setdefault(k, []).append(float(v))
        fits.append(score(r.base, r.effects, data.subset([i])).fit.total)
    sev = [float(np.nanmax(np.abs(data.y[i, 1]))) for i in idx][:len(fits)]
    out = {}
    for k, vals in per.items():
        v = np.array(vals)
        all_v = fit.effects[-1]["parameters"][k]
        lg = np.log(np.abs(v) + 1e-30)
        rho = stats.spearmanr(v, sev[:len(v)]).statistic if len(v) > 2 else float("nan")
        out[k] = {"all": all_v, "sd_log": float(np.std(lg, ddof=1)), "rho_sev": float(rho),
                  "vals": [float(f"{x:.3g}") for x in v]}
    return out


def main() -> None:
    sets, name, cases = Path(sys.argv[1]), sys.argv[2], sys.argv[3:]
    import re
    for folder in cases:
        case = select([re.sub(r"_est\d+(_new)?$", "", folder)], name)[0]
        captured.clear()
        est = load_tests([sets / folder / "est"])
        val = load_tests([sets / folder / "val"])
        run_loop(est, val, Path(tempfile.mkdtemp()) / folder, verbose=False,
                 plots=False, ratings=False, workers=1)
        print(f"== {folder}: {len(captured)} tie(s); expected {case.expect}", flush=True)
        for base, effects, data, a, b, test_setup in captured:
            for side in (a, b):
                s = side_spread(base, effects, data, side, test_setup)
                print(f"   {side.kind}@{'all' if side.setups is None else '+'.join(side.setups)}"
                      f" beside {[e['kind'] for e in effects]}: "
                      + "; ".join(f"{k} sd_log {v['sd_log']:.2f} rho {v['rho_sev']:+.2f} "
                                  f"{v['vals']}" for k, v in s.items()), flush=True)


if __name__ == "__main__":
    main()
