"""observer-node: the chest observer for crash benches, after Blåberg (2008).

Estimates the dummy's chest acceleration (CR) and deflection (CD) from the crash pulse and the
belt spindle rotation (BRS): identify models from crash tests, score them as the thesis does,
close the loop on what they lack, and run them as a real-time CAN observer.

The 24 crash tests bundled with the package are named campaign-a wherever tests are asked
for: campaign-a (all), or campaign-a/PATTERN for those whose names match (R16_001-012 on the
sled rig, SLED_001-006 sled with interior, FULL_001-006 full vehicle; 'campaign-a/*[13579]'
are the odd-numbered ones). Any other argument is a path: an ISO-MME folder, .zip or .csv
test, or a folder of them.

Examples::

    observer-node bench                               # the whole bench on bundled data
    observer-node evaluate                            # thesis Tables 4.1-4.3, plots
    observer-node identify --model greybox --data 'campaign-a/R16_*[13579]' --out model.json
    observer-node evaluate --model model.json --data campaign-a/R16_002 --out out/eval
    observer-node loop --estimate 'campaign-a/*[13579]' --validate 'campaign-a/*[02468]' \\
        --out out/loop
    observer-node run --interface socketcan --channel vcan0 --model model.json --record run.mcap
    observer-node analyze run.mcap
    observer-node export run.mcap --to run.blf           # for CANoe; .mf4 .asc .log .trc
"""

from __future__ import annotations

import argparse
import sys

from .. import __version__
from ..entry import stopped
from ..errors import ObserverError, one_line
from ..options import OneLineParser
from . import analyze, bench, evaluate, export, export_c, identify, loop, run, simulate

# One module per command, each with add_subparser(subparsers) and its _do_COMMAND(args); in
# the order --help lists them.
COMMANDS = (bench, loop, identify, evaluate, simulate, run, analyze, export, export_c)


def build_parser() -> argparse.ArgumentParser:
    p = OneLineParser(prog="observer-node", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for command in COMMANDS:
        command.add_subparser(sub)
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except ObserverError as e:  # bad input and the like: one line, never a traceback
        print(f"observer-node: error: {one_line(str(e))}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt as e:  # Ctrl-C, or SIGTERM as the entry point raises it
        return stopped("observer-node", e)
    except BrokenPipeError:
        return 0
    except OSError as e:  # a disk full, a folder that cannot be made: one line naming it
        where = f"{e.filename}: " if e.filename else ""
        print(f"observer-node: error: {one_line(f'{where}{e.strerror or e}')}", file=sys.stderr)
        return 2
