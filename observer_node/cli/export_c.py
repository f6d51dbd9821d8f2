"""``observer-node export-c``: a model file as a dependency-free C99 observer."""

from __future__ import annotations

import argparse

from .. import options


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "export-c", help="a model file as a dependency-free C99 observer",
        description="Write NAME.h and NAME.c: the model's per-tick step (input transform, "
        "discrete state space, and a grey-box's effects, delays and offsets) exactly as the "
        "daemon steps it, and the daemon's core (arming, trigger, bias, validity) around it, "
        "in double, or in float with -DCO_REAL=float. No heap, no library but fabs. Also the "
        "frame codec from the DBC (chest_observer_can.c/.h, by cantools' C generator).")
    s.add_argument("model", help="model file (JSON)")
    s.add_argument("--out", required=True, metavar="DIR", help="folder to write into")
    s.add_argument("--name", default="chest_observer",
                   help="file and guard name (default %(default)s)")
    s.add_argument("--setup", metavar="NAME",
                   help="the ECU's setup, for a model with effects scoped to setups (a setup "
                   "the model was not fitted on is refused)")
    s.set_defaults(func=_do_export_c)


def _do_export_c(a: argparse.Namespace) -> int:
    from ..export_c import ExportError, check_c_name, export_c, export_codec
    from ..model.modelfile import ModelFile

    check_c_name(a.name)
    out = options.out_folder(a.out)
    mf = ModelFile.load(a.model)
    try:
        mf = mf.for_setup(a.setup or "", a.model)
        with options.staged(out) as tmp:
            paths = [out / p.relative_to(tmp)
                     for p in export_c(mf, tmp, a.name) + export_codec(tmp)]
    except ExportError as e:  # it names the part of the model, not the file
        raise ExportError(f"{a.model}: {e}") from None
    print(f"wrote {', '.join(str(p) for p in paths)} ({mf.kind} {mf.name!r}, "
          f"{mf.tick_rate_hz:g} Hz); compile with any C99 compiler, -DCO_REAL=float for float")
    return 0
