"""``observer-node bench``: the whole bench in one command."""

from __future__ import annotations

import argparse

from observer_node.dbc.bus import add_bus_arguments

from .. import options
from ..data import BENCH_TESTS


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "bench", help="the whole bench: replay bundled tests into the daemon, record, analyse",
        description="Take the loop's model (shipped with this version, reused from an earlier "
        "bench, or made here with --rerun-loop) or --model, start the daemon on vcan0 if it "
        "exists (else on an in-process virtual bus), replay bundled crash tests with reference "
        "frames, record to MCAP and print the analysis beside the offline evaluation of the "
        "thesis grey-box and the loop's model.")
    s.add_argument("--model", help="model file (default: the loop's model on the bundled "
                   "campaign's odd-numbered tests)")
    s.add_argument("--rerun-loop", action="store_true",
                   help="run observer-node loop here (about 2 min) instead of reusing its "
                   "result from an earlier bench or the one shipped with this version")
    add_bus_arguments(s, interface="auto", fd=False,
                      interface_note=", or auto: socketcan if the channel exists, else "
                      "virtual")
    s.add_argument("--test", action="append", metavar="NAME",
                   help="bundled test to replay (repeatable; default "
                   f"{' '.join(BENCH_TESTS)})")
    s.add_argument("--rate", type=options.positive, default=1.0,
                   help="replay time scale (default %(default)g)")
    s.add_argument("--out", default="out/bench", help="output folder (default %(default)s)")
    s.set_defaults(func=_do_bench)


def _do_bench(a: argparse.Namespace) -> int:
    from ..bench import run_bench

    run_bench(options.out_folder(a.out), a.model, a.interface, a.channel,
              tuple(a.test or BENCH_TESTS), a.rate, rerun_loop=a.rerun_loop)
    return 0
