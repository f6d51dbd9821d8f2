"""``observer-node export``: a recording's raw frames as a bus log."""

from __future__ import annotations

import argparse
import sys


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "export", help="a recording's raw frames as MF4, BLF, ASC, candump or TRC",
        description="Write every CAN frame a recording holds (received and sent, with the "
        "recorded times and direction) in a bus-log format, by the file's suffix: .mf4 (ASAM "
        "MDF4: CANape, CANoe, loggers; needs the mf4 extra), .blf and .asc (Vector), .log "
        "(can-utils candump -L), .trc (PEAK). crash-replay plays the file back.")
    s.add_argument("recording", help="MCAP file of observer-node run")
    s.add_argument("--to", required=True, metavar="FILE", help="log file to write")
    s.add_argument("--channel", default="can0",
                   help="channel name written into the log (default %(default)s)")
    s.set_defaults(func=_do_export)


def _do_export(a: argparse.Namespace) -> int:
    from ..recording.export import export_frames

    n, salvaged = export_frames(a.recording, a.to, a.channel)
    if salvaged:
        print(f"observer-node: warning: {a.recording} was cut short ({salvaged}); every frame "
              "before the cut was exported", file=sys.stderr)
    print(f"wrote {n} frames to {a.to}")
    return 0
