"""A recording's raw CAN frames in the log formats bench tools open, written by python-can.

    .mf4   ASAM MDF4 bus logging (CANape, CANoe, data loggers; needs asammdf:
           ``pip install 'chest-observer[mf4]'``)
    .blf   Vector binary logging format      .asc   Vector ASCII
    .log   can-utils candump -L              .trc   PEAK trace

Every frame the daemon received and sent is written with its recorded time (seconds from the
start of the run) and direction (where the format keeps one: ASC, BLF, MF4, TRC), error
frames as error frames. crash-replay plays such a file back, received frames only unless
``--all-frames``.
"""

from __future__ import annotations

import heapq
import json
from pathlib import Path

from . import format as fmt
from .reader import RecordingError, Scan

FORMATS = {".mf4": "ASAM MDF4", ".blf": "Vector BLF", ".asc": "Vector ASC",
           ".log": "candump -L", ".trc": "PEAK TRC"}


REORDER = 4096  # frames held back to put the log in time order


class ExportError(ValueError):
    """An export that cannot be made; the message names the file."""


def export_frames(recording: str | Path, out: str | Path,
                  channel: str = "can0") -> tuple[int, str | None]:
    """Write the raw frames of ``recording`` to ``out`` (format from its suffix); returns the
    number of frames written and, for a recording cut short (a killed run), what was salvaged
    (every frame up to the cut is written)."""
    import can

    recording, out = Path(recording), Path(out)
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
    try:
        writer = can.Logger(str(out))
    except OSError as e:
        raise ExportError(f"{out}: cannot write: {e.strerror}") from None
    # The recording holds frames in the order the daemon handed them over: a sent estimate
    # can follow a later-stamped received frame. Logs are in time order: a small heap
    # restores it (the disorder spans a few frames, never REORDER).
    heap: list[tuple[float, int, can.Message]] = []
    n = 0
    try:
        for topic, _, raw in scan:
            if topic != fmt.FRAMES:
                continue
            m = json.loads(raw)
            msg = can.Message(
                timestamp=float(m["t"]), arbitration_id=int(m["id"]),
                is_extended_id=int(m["id"]) > 0x7FF, data=bytes.fromhex(m["data"]),
                is_fd=bool(m["fd"]), bitrate_switch=bool(m["fd"]),
                is_error_frame=bool(m["error"]), is_rx=m["dir"] == "rx", channel=channel)
            heapq.heappush(heap, (msg.timestamp, n, msg))
            n += 1
            if len(heap) > REORDER:
                writer.on_message_received(heapq.heappop(heap)[2])
        while heap:
            writer.on_message_received(heapq.heappop(heap)[2])
    except (ValueError, KeyError) as e:
        raise RecordingError(f"{recording}: a {fmt.FRAMES} message that is not a frame "
                             f"({type(e).__name__}: {e})") from None
    finally:
        writer.stop()
    if n == 0:
        out.unlink(missing_ok=True)
        raise RecordingError(f"{recording}: no {fmt.FRAMES} messages to export")
    return n, scan.note if scan.salvaged else None
