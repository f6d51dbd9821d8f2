"""The loop's check after the fit (``loop.screening.residual_outliers``: a test the thesis
grey-box fits far worse than the others) on crash tests no one has looked at: the campaigns
of ``benchmarks.screen_faults`` (6 + 6 tests of drawn rigs, one physical effect of the
independent simulator half the time, one broken channel or none).

Per campaign, as the loop does: the checks before the fit leave their tests out; the grey-box
is fitted on the estimation tests left, each judged by the model fitted without it (the only
test of its rig in-sample); then each validation test by the model the estimation tests made.
A test is named by the check as shipped (far below the others' median, and below its setup's
other tests' when it has any) and, for comparison, by the others' median alone (the check
before session 47). Printed, per rule: the broken tests the check before the fit missed and
this one named, and the clean tests it named (with the campaign's physical effect, the case
a rig-wide effect the grey-box lacks could be taken for a broken test).

    python -m benchmarks.screen_residual [--campaigns 40] [--seed 60000] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import END_S, median_sizes
from benchmarks.screen_faults import draw_campaign as draw
from observer_node.data import CrashDataError, load_tests
from observer_node.data.setups import assign_setups
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop.cluster import Runner, cluster
from observer_node.loop.refit import folds, score
from observer_node.loop.rounds import cross_validate
from observer_node.loop.screening import broken_before_fit, judged_fits, residual_outliers

SEED = 60000  # the draws session 37 held out for the checks before the fit; the check after
# the fit never ran on them before session 47
BATCH = 10
RULES = ("shipped", "others only")


def judge(case_name: str, broken: tuple[str, ...], physics: list[str], folder: Path,
          runner: Runner) -> dict:
    files: list[str | Path] = [*sorted((folder / "est").iterdir()),
                               *sorted((folder / "val").iterdir())]
    try:
        tests = load_tests(files)
    except CrashDataError as err:
        return {"case": case_name, "refused": str(err)}
    assign_setups(tests)
    est_names = {p.name for p in (folder / "est").iterdir()}  # a folder per test
    before = {b.test for b in broken_before_fit(tests, END_S)}
    est = [t for t in tests if t.name in est_names and t.name not in before]
    val = [t for t in tests if t.name not in est_names and t.name not in before]
    row = {"case": case_name, "broken": list(broken), "physics": physics,
           "before_fit": sorted(before), "judged": len(est) >= 4 and bool(val)}
    if not row["judged"]:
        return row
    e, v = make_dataset(est), make_dataset(val)
    gb = greybox.fit_greybox(e)
    cv = cross_validate(runner, [(dict(gb.params), [])], e, folds(e))[0] or {}
    fitted = {n: s.total for n, s in score(dict(gb.params), [], e).tests.items()}
    setup_of = dict(zip(e.names, e.setups, strict=True))
    fits, lone = judged_fits(cv, fitted, setup_of)
    val_fits = {n: s.total for n, s in score(dict(gb.params), [], v).tests.items()}
    setup_of |= dict(zip(v.names, v.setups, strict=True))
    for rule, setups in zip(RULES, (setup_of, None), strict=True):
        named = [b.test for b in residual_outliers(fits, lone, setups)]
        named += [b.test for b in residual_outliers({**fits, **val_fits}, (), setups)
                  if b.test in val_fits]
        row[rule] = named
    row["fits"] = {**fits, **val_fits}
    row["setups"] = setup_of
    return row


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.screen_residual",
                                 description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--campaigns", type=int, default=40, help="how many (default 40)")
    ap.add_argument("--seed", type=int, default=SEED, help=f"the first seed (default {SEED})")
    ap.add_argument("--workers", type=int, default=1, help="Dask workers (default 1)")
    ap.add_argument("--json", type=Path, help="write every campaign's result here")
    args = ap.parse_args(argv)
    size = median_sizes()
    cases = [draw(k, args.seed, size) for k in range(args.campaigns)]
    rows: list[dict] = []
    t0 = time.perf_counter()
    with cluster(workers=args.workers) as runner:
        for b in range(0, len(cases), BATCH):
            batch = cases[b:b + BATCH]
            with tempfile.TemporaryDirectory() as tmp:
                make(batch, Path(tmp), log=False)
                for c in batch:
                    physics = [f"{x.key}@{'+'.join(x.setups)}" for x in c.effects
                               if not x.tests]
                    rows.append(judge(c.name, c.expect_broken, physics, Path(tmp) / c.name,
                                      runner))
                    print(f"  {len(rows)} of {len(cases)} campaigns, "
                          f"{time.perf_counter() - t0:.0f} s", file=sys.stderr, flush=True)
    report(rows)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1) + "\n")
    return 0


def report(rows: list[dict]) -> None:
    judged = [r for r in rows if r.get("judged")]
    print(f"{len(judged)} of {len(rows)} campaigns judged (the rest refused by the reader or "
          f"left with under 4 estimation tests)")
    missed = [(r, t) for r in judged for t in r["broken"] if t not in r["before_fit"]]
    clean = sum(12 - len(r["before_fit"]) - len(set(r["broken"]) - set(r["before_fit"]))
                for r in judged)
    print(f"broken tests the checks before the fit missed: {len(missed)}")
    print(f"{'rule':12s} {'missed, named here':>18s} {'clean named':>11s} "
          f"{'clean named, with physics':>25s}")
    for rule in RULES:
        found = sum(t in r[rule] for r, t in missed)
        wrong = [(r, t) for r in judged for t in r[rule] if t not in r["broken"]]
        print(f"{rule:12s} {found:18d} {len(wrong):5d} of {clean:<5d} "
              f"{sum(bool(r['physics']) for r, _ in wrong):25d}")
        for r, t in wrong:
            print(f"    {r['case']}: {t} ({r['setups'].get(t)}) {r['fits'][t]:.1f} %, "
                  f"physics {r['physics'] or 'none'}")
    for r, t in missed:
        print(f"  missed before the fit: {r['case']} {t} ({r['setups'].get(t)}) "
              f"{r['fits'].get(t, float('nan')):.1f} %: "
              + ", ".join(f"{rule} {'named' if t in r[rule] else 'not'}" for rule in RULES))


if __name__ == "__main__":
    sys.exit(main())
