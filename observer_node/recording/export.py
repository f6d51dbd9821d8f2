"""A recording's raw CAN frames in the log formats bench tools open, written by python-can.

    .mf4   ASAM MDF4 bus logging (CANape, CANoe, data loggers; needs asammdf:
           ``pip install 'chest-observer[mf4]'``)
    .blf   Vector binary logging format      .asc   Vector ASCII
    .log   can-utils candump -L              .trc   PEAK trace

Every frame the daemon received and sent is written with its recorded time and direction
(where the format keeps one: ASC, BLF, MF4, TRC), error frames as error frames. Times are
wall-clock, as a logger on the bus would have stamped them: the recording's start (the MCAP log
time of a frame less its ``t``) plus ``t``. MF4's header holds that start and its time axis is
``t``; BLF, ASC and TRC start at the first frame; candump logs are absolute. crash-replay plays
such a file back, received frames only unless ``--all-frames``.
"""

from __future__ import annotations

import heapq
import os
from datetime import datetime
from pathlib import Path
from typing import Any

import can
from can.io.asc import ASCWriter
from can.io.mf4 import MF4Writer

from ..errors import ObserverError
from . import format as fmt
from .reader import RecordingError, Scan

FORMATS = {".mf4": "ASAM MDF4", ".blf": "Vector BLF", ".asc": "Vector ASC",
           ".log": "candump -L", ".trc": "PEAK TRC"}


REORDER = 4096  # frames held back to put the log in time order


class ExportError(ObserverError, ValueError):
    """An export that cannot be made; the message names the file."""


def export_frames(recording: str | Path, out: str | Path,
                  channel: str = "can0") -> tuple[int, str | None]:
    """Write the raw frames of ``recording`` to ``out`` (format from its suffix); returns the
    number of frames written and, for a recording cut short (a killed run), what was salvaged
    (every frame up to the cut is written)."""
    recording, out = Path(recording), Path(out)
    if out.is_dir():
        raise ExportError(f"{out}: is a folder; give the log file's name (e.g. {out / 'run.blf'})")
    if out.suffix.lower() not in FORMATS:
        raise ExportError(f"{out}: unknown log format {out.suffix!r} (known: "
                          f"{', '.join(FORMATS)})")
    if out.suffix.lower() == ".mf4":
        try:
            import asammdf  # noqa: F401
        except ImportError:
            raise ExportError(f"{out}: MDF4 needs asammdf: pip install "
                              "'chest-observer[mf4]'") from None
    scan = Scan(recording)
    # written beside under a hidden name, renamed when whole: a full disk or a bad recording
    # leaves no truncated log that a tool would read as the whole run
    part = out.with_name(f".{out.stem}.partial{out.suffix}")
    try:
        n = _write(scan, recording, part, channel, shown=out)
        os.replace(part, out)
    except OSError as e:
        raise ExportError(f"{out}: cannot write: {e.strerror or e}") from None
    finally:
        part.unlink(missing_ok=True)
    return n, scan.note if scan.salvaged else None


def _write(scan: Scan, recording: Path, out: Path, channel: str, shown: Path) -> int:
    """Write the frames ``scan`` reads to ``out`` (``shown`` in messages); returns how
    many."""
    writer: Any = None
    # The recording holds frames in the order the daemon handed them over: a sent estimate
    # can follow a later-stamped received frame. Logs are in time order: a small heap
    # restores it (the disorder spans a few frames, never REORDER).
    heap: list[tuple[float, int, can.Message]] = []
    n = 0
    try:
        for topic, log_ns, raw in scan:
            if topic != fmt.FRAMES:
                continue
            fr = fmt.read_frame(raw)
            if writer is None:  # the wall clock at the recorder's start, from the first frame
                start_s = (log_ns - round(fr.t * 1e9)) / 1e9
                writer = _open_writer(out, start_s, shown)
            msg = can.Message(
                timestamp=start_s + fr.t, arbitration_id=fr.can_id, is_extended_id=fr.extended,
                data=fr.data, is_fd=fr.fd, bitrate_switch=fr.fd, is_error_frame=fr.error,
                is_rx=not fr.tx, channel=channel)
            heapq.heappush(heap, (msg.timestamp, n, msg))
            n += 1
            if len(heap) > REORDER:
                writer.on_message_received(heapq.heappop(heap)[2])
        while heap:
            writer.on_message_received(heapq.heappop(heap)[2])
    except ExportError:
        raise
    except (ValueError, KeyError, TypeError) as e:
        raise RecordingError(f"{recording}: a {fmt.FRAMES} message that is not a frame "
                             f"({type(e).__name__}: {e})") from None
    finally:
        if writer is not None:
            writer.stop()
    if n == 0:
        raise RecordingError(f"{recording}: no {fmt.FRAMES} messages to export")
    return n


def _open_writer(out: Path, start_s: float, shown: Path) -> Any:
    """python-can's writer for ``out``'s suffix, its header dated ``start_s`` (s since the
    epoch) where python-can would date it at the export."""
    try:
        if out.suffix.lower() == ".mf4":
            return _Mf4Writer(out, start_s)
        if out.suffix.lower() == ".asc":
            return _AscWriter(out, start_s)
        return can.Logger(str(out))
    except OSError as e:
        raise ExportError(f"{shown}: cannot write: {e.strerror}") from None


class _Mf4Writer(MF4Writer):
    """python-can's MF4 writer with the measurement start at ``start_s`` (python-can 4.6 takes
    the time of the export and has no parameter for another): the header's start plus the
    time axis is each frame's wall clock, as asammdf, CANape and CANoe read it."""

    def __init__(self, out: Path, start_s: float):
        super().__init__(str(out))
        start = datetime.fromtimestamp(start_s).astimezone()  # local, with its UTC offset
        self._mdf.header.start_time = start
        self.last_timestamp = self._start_time = start.timestamp()


class _AscWriter(ASCWriter):
    """python-can's ASC writer with the ``date`` line at the recording's start (python-can
    dates it at the export) and the header's milliseconds as three digits (4.6 writes 5 ms
    as ``.5``, which its own reader takes for 500 ms). Local time, as Vector's tools write
    it."""

    def __init__(self, out: Path, start_s: float):
        self._date: datetime | None = datetime.fromtimestamp(start_s)
        super().__init__(str(out))

    def _format_header_datetime(self, dt: datetime) -> str:
        if self._date is not None:  # the first call, from __init__, dates the file
            dt, self._date = self._date, None
        return dt.strftime(f"%a %b %d %H:%M:%S.{dt.microsecond // 1000:03d} %Y")
