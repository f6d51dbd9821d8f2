"""``observer-node export``: a recording's raw frames as a bus log."""

from __future__ import annotations

import argparse
import re
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
    s.add_argument("--channel", default="can0", type=_channel,
                   help="channel name written into the log: letters, digits, _ . - "
                   "(default %(default)s)")
    s.set_defaults(func=_do_export)


def _channel(text: str) -> str:
    """A channel name every log format can carry: a space or a line break would split a
    candump -L or .trc line, which no reader then takes."""
    if not re.fullmatch(r"[A-Za-z0-9_.\-]{1,32}", text):
        raise argparse.ArgumentTypeError(f"{text!r}: letters, digits, _ . - only (e.g. can0)")
    return text


def _do_export(a: argparse.Namespace) -> int:
    from ..recording.export import export_frames

    n, salvaged = export_frames(a.recording, a.to, a.channel)
    if salvaged:
        print(f"observer-node: warning: {a.recording} was cut short ({salvaged}); every frame "
              "before the cut was exported", file=sys.stderr)
    print(f"wrote {n} frames to {a.to}")
    return 0
