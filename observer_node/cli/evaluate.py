"""``observer-node evaluate``: the thesis's chapter 4, or one model file scored on tests."""

from __future__ import annotations

import argparse

from .. import options
from . import _data


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "evaluate", help="score models with the thesis's fit (tables, plots, JSON)",
        description="Without --model: the thesis's chapter 4 on the data (default: bundled "
        "campaign): per setup, estimate ARX Nmax 10 and 6, N4SID 16 and 7 and the grey-box on "
        "the odd-numbered tests, score them on the even-numbered ones, print Tables 4.1-4.3 "
        "with the thesis's numbers beside them, and write plots and evaluation.json. "
        "With --model: score that model on the data and write OUT/fits.json and plots.")
    s.add_argument("--model", help="model file to score (default: identify and compare all)")
    _data.add_data_arguments(s, data="optional")
    s.add_argument("--out", default="out/evaluate", help="output folder (default %(default)s)")
    _data.add_rate_argument(s)
    s.add_argument("--quiet", action="store_true", help="no progress display")
    s.set_defaults(func=_do_evaluate)


def _do_evaluate(a: argparse.Namespace) -> int:
    from ..criteria import format_criteria
    from ..data.crashtest import THESIS_WINDOW_S
    from ..evaluation import evaluate_model, format_tables, thesis_comparison
    from ..ident.progress import Progress
    from ..iso18571 import grade
    from ..model.modelfile import ModelFile

    out = options.out_folder(a.out)
    if a.model:
        mf = ModelFile.load(a.model)
        # the tests are checked as they will be scored: at the model's rate and window
        tests, left_out = _data.load(a, mf.tick_rate_hz, _data.window(a) if a.window else
                                     tuple(mf.fitted_on.get("window_s", THESIS_WINDOW_S)))
        with options.staged(out) as tmp:  # without --window, the model's own window
            fits = evaluate_model(mf, tests, tmp, _data.window(a) if a.window else None,
                                  progress=Progress("evaluate", enabled=not a.quiet,
                                                    every_s=0.0), left_out=left_out)
        f = fits.fit
        print(f"{mf.kind} model {mf.name!r} on {len(tests)} tests"
              + (f" ({len(left_out)} left out, named in fits.json)" if left_out else "") + ":")
        setups = fits.by_group({t.name: t.setup for t in tests})
        w = max([12, *map(len, [*fits.tests, *setups])])  # a long name widens the column
        for name, v in fits.tests.items():
            print(f"  {name:<{w}} CR {v.cr:6.1f} %  CD {v.cd:6.1f} %")
        print(f"  {'total':<{w}} CR {f.cr:6.1f} %  CD {f.cd:6.1f} %  TOT {f.total:.1f} %")
        if len(setups) > 1:
            print("per setup:")
            for setup, (n, sf) in sorted(setups.items()):
                print(f"  {setup:<{w}} CR {sf.cr:6.1f} %  CD {sf.cd:6.1f} %  TOT {sf.total:.1f} %"
                      f"  ({n} test{'' if n == 1 else 's'})")
        print("\nchest injury criteria, estimate vs measured (from t = 0):")
        print(format_criteria(fits.criteria))
        iso = fits.iso18571
        if iso:
            print("\nISO/TS 18571 overall rating (0..1) on the fit window:")
            for name, r in iso.tests.items():
                print(f"  {name:<{w}} CR {r.cr.overall:.3f} ({grade(r.cr.overall)})"
                      f"  CD {r.cd.overall:.3f} ({grade(r.cd.overall)})")
        else:
            print("\n(ISO/TS 18571 ratings: pip install 'chest-observer[iso18571]')")
        print(f"wrote {out / 'fits.json'} and plots in {out}")
        return 0
    tests, left_out = _data.load(a)
    with options.staged(out) as tmp:
        result = thesis_comparison(tests, tmp, a.rate, _data.window(a), verbose=not a.quiet,
                                   left_out=left_out)
    print(format_tables(result))
    print(f"\nwrote {out / 'evaluation.json'}, models in {out / 'models'}, "
          f"plots in {out / 'plots'}")
    return 0
