"""``observer-node identify``: fit one model to crash tests, write its model file."""

from __future__ import annotations

import argparse
import time

from .. import options
from ..model.schema import MAX_STATES
from . import _data

MAX_NMAX = 20  # ARX orders past this many ticks fit noise, and take minutes to search


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "identify", help="fit a grey-box, ARX or N4SID model to crash tests",
        description="Fit one model to crash tests and write its JSON model file.")
    from ..model.kinds import MODEL_KINDS

    s.add_argument("--model", choices=tuple(MODEL_KINDS), required=True,
                   help="; ".join(f"{k}: {m.description}" for k, m in MODEL_KINDS.items()))
    _data.add_data_arguments(s, data="required")
    s.add_argument("--out", required=True, help="model file to write (JSON)")
    _data.add_rate_argument(s, " the model runs at")
    s.add_argument("--nmax", type=options.int_in(1, MAX_NMAX), default=6,
                   help=f"ARX: largest order searched, 1-{MAX_NMAX} (default %(default)s)")
    s.add_argument("--order", type=options.int_in(1, MAX_STATES), default=7,
                   help=f"N4SID: model order, 1-{MAX_STATES} (default %(default)s)")
    s.add_argument("--m1", type=options.positive, default=20.0,
                   help="grey-box: fixed spine mass in kg that sets the mass scale "
                   "(default %(default)g)")
    s.add_argument("--name", help="model name stored in the file")
    s.add_argument("--quiet", action="store_true", help="no progress display")
    s.set_defaults(func=_do_identify)


def _do_identify(a: argparse.Namespace) -> int:
    from ..data.setups import assign_setups
    from ..evaluation import identify
    from ..ident.dataset import make_dataset
    from ..ident.progress import Progress
    from ..model.modelfile import ModelFile, ModelFileError

    out = options.out_file(a.out)
    tests, left_out = _data.load(a)
    assign_setups(tests)  # as evaluate and the loop tell them: one grouping in every command
    data = make_dataset(tests, a.rate, _data.window(a))
    t0 = time.monotonic()
    mf = identify(a.model, data, nmax=a.nmax, order=a.order, m1_kg=a.m1,
                  progress=Progress(f"identify {a.model}", enabled=not a.quiet), name=a.name)
    try:  # what run and evaluate would refuse is not written (an unstable or oversized model)
        ModelFile.from_dict(mf.to_dict(), f"the identified {a.model} model")
    except ModelFileError as e:
        hint = " (fewer orders: --nmax, --order)" if a.model in ("arx", "n4sid") else ""
        raise ModelFileError(f"{e}; not written to {out}{hint}") from None
    if left_out:
        mf.fitted_on["left_out"] = left_out
    mf.save(out)
    f = mf.fits["fit"]
    print(f"{a.model} model on {len(tests)} test{'' if len(tests) == 1 else 's'} at "
          f"{a.rate:g} Hz "
          + (f"({len(left_out)} left out) " if left_out else "") +
          f"({time.monotonic() - t0:.1f} s) -> {a.out}")
    print(f"fit on its estimation tests: CR {f['cr']:.1f} %  CD {f['cd']:.1f} %  "
          f"TOT {f['total']:.1f} %  (not a validation fit)")
    from ..model.kinds import MODEL_KINDS

    for line in MODEL_KINDS[mf.kind].describe(mf):
        print(line)
    return 0
