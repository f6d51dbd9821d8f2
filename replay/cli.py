"""crash-replay: feed recorded crash tests onto a CAN bus with accurate timing.

Sources, played one after another: ISO-MME test folders or zips (or a folder of them), CSV
crash tests, MCAP recordings of observer-node run (their raw frames, exactly), and candump
-L, ASC, BLF, TRC or ASAM MDF4 (.mf4, CANape/CANoe/loggers; needs the mf4 extra) logs.
Every source is read and checked before the first frame is sent.
The crash tests bundled with the package are named campaign-a (all 24) or
campaign-a/PATTERN (by test name, e.g. campaign-a/R16_002 or 'campaign-a/SLED_*').

Examples::

    crash-replay campaign-a/R16_002 --reference --dry-run     # what would be sent
    crash-replay campaign-a/R16_002 --reference               # onto vcan0
    crash-replay run.mcap --interface socketcan --channel vcan0 --rate 0.1
    crash-replay 'campaign-a/FULL_*' --channel can0 --fd --burst --tick-rate 10000
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter

from observer_node.dbc import Codec, fd_frame_time_s, frame_bits
from observer_node.dbc.bus import add_bus_arguments, open_bus
from observer_node.entry import stopped
from observer_node.errors import ObserverError, UsageError, one_line
from observer_node.options import (
    OneLineParser,
    finite,
    non_negative,
    number_in,
    positive,
    positive_int,
)

from .player import bus_sender, play
from .schedule import Schedule, concat, restamp_counters
from .sources import filter_remap, load_source


def _can_id(s: str) -> int:
    """An argparse type: a CAN ID, 0x100 or 256; up to 0x7FF goes out standard, above as an
    extended ID (29 bits)."""
    try:
        n = int(s, 0)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a CAN ID (0x100 or 256): {s!r}") from None
    if not 0 <= n <= 0x1FFFFFFF:
        raise argparse.ArgumentTypeError(f"a CAN ID is 0..0x7FF (standard) or up to 0x1FFFFFFF "
                                         f"(extended): {s!r}")
    return n


def _priority(s: str) -> int:
    n = int(s) if s.strip().isdigit() else -1
    if not 0 <= n <= 99:
        raise argparse.ArgumentTypeError(f"wants 0..99 (SCHED_FIFO priority), got {s!r}")
    return n


PRE_MAX_S = 5.0  # --pre: the daemon's bias needs a fraction of a second; more is a typo
RATE_MIN, RATE_MAX = 1e-3, 1e3  # --rate: a 150 ms crash in 150 s, or 1000 tests a second
GAP_MAX_S = 3600.0  # --gap: an hour between sources; more is a typo
# Everything --loop plays is held in memory: ~280 MB at this many frames of one test; as
# many copies of a source --only leaves one frame of take ~520 MB (a hostile user's measure)
FRAMES_MAX = 1_000_000


def _remap(s: str) -> tuple[int, int]:
    a, _, b = s.partition("=")
    if not b:
        raise argparse.ArgumentTypeError(f"--remap wants FROM=TO, got {s!r}")
    return _can_id(a), _can_id(b)


def _remap_table(pairs: list[tuple[int, int]]) -> dict[int, int]:
    table: dict[int, int] = {}
    for a, b in pairs:
        if a in table:  # the later one would win unsaid
            raise UsageError(f"--remap 0x{a:X} given twice (=0x{table[a]:X}, =0x{b:X})")
        table[a] = b
    return table


def _warn(message: str) -> None:
    print(f"crash-replay: warning: {one_line(message)}", file=sys.stderr)


def build_parser() -> argparse.ArgumentParser:
    p = OneLineParser(prog="crash-replay", description=__doc__,
                      formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("sources", nargs="+", metavar="SOURCE",
                   help="crash test (ISO-MME folder, .zip, .mme, .csv), folder of tests, "
                   "campaign-a[/PATTERN], .mcap recording, or .log/.asc/.blf/.trc/.mf4 bus log")
    add_bus_arguments(p)
    p.add_argument("--burst", action="store_true",
                   help="lab data as InputBurst frames, eight samples each (CAN FD; for tick "
                   "rates a frame per sample cannot carry, e.g. --tick-rate 10000)")
    p.add_argument("--rate", type=number_in(RATE_MIN, RATE_MAX), default=1.0,
                   help="time scale: 2 plays twice as fast, 0.1 ten times slower "
                   f"({RATE_MIN:g} to {RATE_MAX:g}; default %(default)g)")
    p.add_argument("--tick-rate", type=positive, default=1000.0,
                   help="accelerometer frames per second for lab data (default %(default)g, the "
                   "DBC's)")
    p.add_argument("--reference", action="store_true",
                   help="also send ReferenceChest frames with the measured CR and CD")
    p.add_argument("--start", type=finite, help="start of the window to play, s (test time)")
    p.add_argument("--end", type=finite, help="end of the window to play, s (test time)")
    p.add_argument("--pre", type=number_in(0.0, PRE_MAX_S, " s"), default=0.2,
                   help="quiet signal before a lab test, s, for the daemon's bias "
                   f"(default %(default)g, at most {PRE_MAX_S:g})")
    p.add_argument("--loop", type=positive_int, default=1, metavar="N",
                   help="play everything N times (default %(default)s; at most "
                   f"{FRAMES_MAX:,} frames in all)")
    p.add_argument("--spin-us", type=non_negative, default=300.0,
                   help="busy-wait this long before each due time for accuracy (default "
                   "%(default)g); use 0 in an emulated VM, where spinning steals the "
                   "emulator's own CPU")
    p.add_argument("--rt-priority", type=_priority, default=0, metavar="N",
                   help="play under SCHED_FIFO at priority N (1-99; needs root, CAP_SYS_NICE "
                   "or RLIMIT_RTPRIO, else one line says so): due frames preempt every "
                   "normal process, as the daemon's run --rt-priority; default %(default)s: "
                   "normal")
    p.add_argument("--gap", type=number_in(0.0, GAP_MAX_S, " s"), default=0.5,
                   help="pause between sources, s of wall time whatever --rate (default "
                   f"%(default)g, at most {GAP_MAX_S:g})")
    p.add_argument("--only", type=_can_id, action="append", metavar="ID",
                   help="send only these CAN IDs (repeatable; 0x100 or 256)")
    p.add_argument("--remap", type=_remap, action="append", metavar="FROM=TO",
                   help="send frames of one ID under another (repeatable)")
    p.add_argument("--all-frames", action="store_true",
                   help="MCAP, and logs that keep the direction (ASC, BLF, TRC, MF4): also the "
                   "frames the recording node sent, not only those it received")
    p.add_argument("--counts-per-rev", type=positive_int,
                   help="BRS counts/rev if a test does not say")
    p.add_argument("--bitrate", type=positive, default=500_000,
                   help="for --dry-run's bus load (default %(default).0f)")
    p.add_argument("--data-bitrate", type=positive, default=2_000_000,
                   help="CAN FD data phase, for --dry-run's bus load with --fd "
                   "(default %(default).0f)")
    p.add_argument("--dry-run", action="store_true",
                   help="print what would be sent and the bus load, send nothing")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    return p


def describe(s: Schedule, bitrate: float, data_bitrate: float | None = None,
             rate: float = 1.0) -> str:
    """Frames per ID and the worst-case bus load (CAN FD timing with ``data_bitrate``), as
    played at ``rate`` (the time scale)."""
    dur = float(s.t_s[-1] - s.t_s[0]) / rate if len(s) else 0.0
    scaled = f" as played at --rate {rate:g}" if rate != 1.0 else ""
    lines = [f"{len(s)} frames over {dur:.4g} s{scaled} from {s.source}"]
    counts = Counter(s.ids.tolist())
    sizes: dict[int, int] = {}
    for cid, d in zip(s.ids.tolist(), s.data, strict=True):
        sizes.setdefault(cid, len(d))
    load = 0.0
    for cid, n in sorted(counts.items()):
        t_frame = (fd_frame_time_s(sizes[cid], bitrate, data_bitrate) if data_bitrate
                   else frame_bits(sizes[cid]) / bitrate)
        share = n * t_frame / max(dur, 1e-9)
        load += share
        lines.append(f"  0x{cid:03X}: {n:6d} frames, DLC {sizes[cid]}, {n / max(dur, 1e-9):7.1f}/s,"
                     f" {100 * share:5.1f} %")
    speed = f"{bitrate / 1000:g} kbit/s" + (f", FD data {data_bitrate / 1e6:g} Mbit/s"
                                            if data_bitrate else "")
    lines.append(f"  bus load (worst-case stuffing, {speed}): {100 * load:.1f} %")
    if load > 1.0:
        lines.append("  more than the bus carries: frames would be sent late (the timing "
                     "report counts them); a lower --rate or a faster bus")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    a = build_parser().parse_args(argv)
    try:
        return _play(a)
    except ObserverError as e:  # a source or bus that cannot be used: one line, no traceback
        print(f"crash-replay: error: {one_line(str(e))}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt as e:  # reading sources or playing; SIGTERM too (the entry's)
        if sys.stderr.isatty():
            sys.stderr.write("\r\033[K")  # off the progress bar's line, if one was drawn
        return stopped("crash-replay", e)


def _play(a: argparse.Namespace) -> int:
    if a.start is not None and a.end is not None and a.start >= a.end:
        raise UsageError(f"--start {a.start:g} is not before --end {a.end:g}: nothing to play")
    codec = Codec()
    parts: list[Schedule] = []
    for src in a.sources:
        parts += load_source(src, codec, a.tick_rate, a.reference, a.start, a.end, a.pre,
                             counts_per_rev=a.counts_per_rev, all_frames=a.all_frames,
                             burst=a.burst)
    if a.burst and not a.fd:
        raise UsageError("--burst sends 48-byte InputBurst frames: it needs --fd")
    only = set(a.only) if a.only else None
    remap = _remap_table(a.remap or [])
    if only is not None:  # before --loop repeats them: its limit counts what is sent
        parts = [x.only(only) for x in parts]
    total = sum(len(x) for x in parts) * a.loop
    if total == 0:  # said before --loop repeats nothing (a billion empty copies filled RAM)
        filter_remap(concat(parts), only, remap, warn=_warn)  # which IDs matched nothing
        print("crash-replay: nothing to send", file=sys.stderr)
        return 2
    copies = len(parts) * a.loop  # each held too, however few frames --only leaves it
    if total > FRAMES_MAX or copies > FRAMES_MAX:
        what = f"{total:,} frames" if total > FRAMES_MAX else f"{copies:,} copies of the sources"
        raise UsageError(f"--loop {a.loop}: {what} in all, more than crash-replay holds "
                         f"({FRAMES_MAX:,}); play it in a shell loop")
    sched = concat(parts * a.loop, a.gap * a.rate)  # --gap is wall time: unscaled by --rate
    if sched.synthetic and len(parts) * a.loop > 1:
        sched = restamp_counters(sched, codec)  # one sensor across tests: no counter restart
    sched = filter_remap(sched, only, remap, warn=_warn)
    if not len(sched):
        print("crash-replay: nothing to send", file=sys.stderr)
        return 2
    if a.dry_run:
        print(describe(sched, a.bitrate, a.data_bitrate if a.fd else None, a.rate))
        t0 = sched.t_s[0]  # the player sends the first frame at once
        for t, cid, d in list(zip(sched.t_s, sched.ids.tolist(), sched.data, strict=True))[:20]:
            print(f"  {(t - t0) / a.rate:10.6f}  0x{cid:03X}  {d.hex(' ')}")  # s, as played
        if len(sched) > 20:
            print(f"  ... {len(sched) - 20} more")
        return 0

    bus = open_bus(a.interface, a.channel, fd=a.fd)
    send = bus_sender(bus, sched, a.fd)

    tty = sys.stderr.isatty() and not a.quiet

    def progress(k: int, n: int) -> None:
        if tty:
            width = 30
            done = int(width * k / max(n, 1))
            sys.stderr.write(f"\r[{'#' * done}{'.' * (width - done)}] {k}/{n} frames")
            sys.stderr.flush()

    try:
        report = play(sched, send, rate=a.rate, spin_s=a.spin_us * 1e-6, progress=progress,
                      rt_priority=a.rt_priority)
    finally:
        bus.shutdown()
    if tty:
        sys.stderr.write("\r\033[K")
    print(f"crash-replay: {report.summary()}")
    return 0 if report.failed == 0 else 1


def entry() -> int:
    try:
        return main()
    except BrokenPipeError:  # e.g. --dry-run | head
        sys.stderr.close()
        return 0


if __name__ == "__main__":
    from observer_node.entry import crash_replay

    sys.exit(crash_replay())
