"""Reading a daemon's MCAP recording back: ticks, raw frames, the model it ran.

A file cut short (daemon killed, disk full) has no summary; it is read with the non-seeking
reader up to the last complete chunk and reported as salvaged. Topics and fields are those of
:mod:`.format`.
"""

from __future__ import annotations

import json
import math
import struct
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ObserverError
from ..model.modelfile import ModelFile
from . import format as fmt


class RecordingError(ObserverError, ValueError):
    """A file that is not a readable recording; the message names it and why."""


@dataclass
class Recording:
    path: Path
    metadata: dict[str, dict[str, str]]
    model: ModelFile | None
    ticks: dict[str, np.ndarray]  # per tick, sorted by tick index: TickRow's columns
    frames: list[fmt.Frame]  # /can/frames messages (raw, in order)
    reference: dict[int, tuple[float, float]]
    salvaged: bool = False
    salvage_note: str = ""
    topics: dict[str, int] = field(default_factory=dict)

    @property
    def tick_rate_hz(self) -> float:
        return float(self.metadata.get(fmt.META_RUN, {}).get(fmt.RunMeta.TICK_RATE_HZ, "nan"))

    @property
    def event_s(self) -> float:
        """How long the daemon runs an event [s] (its ``core.event_s``); NaN when the
        recording does not say (an older or foreign file)."""
        try:
            cfg = json.loads(self.metadata[fmt.META_RUN][fmt.RunMeta.CONFIG])
            return float(cfg["core"]["event_s"])
        except (KeyError, TypeError, ValueError):
            return math.nan


# The writer's table read backwards: (message field, TickRow column) of each tick topic
_INPUT_KEYS = tuple((k, col) for k, (_, col) in fmt.TICK_TOPICS[fmt.INPUTS].items()
                    if k not in ("tick", "t"))
_EST_KEYS = tuple((k, col) for k, (_, col) in fmt.TICK_TOPICS[fmt.ESTIMATE].items()
                  if k != "tick")
_REF_CR, _REF_CD = ({col: k for k, (_, col) in fmt.TICK_TOPICS[fmt.REFERENCE].items()}[c]
                    for c in ("ref_cr_g", "ref_cd_mm"))


class Scan:
    """One sequential pass over an MCAP file, without seeking, so a file cut short reads up
    to its last complete chunk. Iterating yields ``(topic, log_time_ns, message bytes)``
    for messages, ``("#metadata", 0, (name, dict))`` and ``("#attachment", 0, (name,
    bytes))``; afterwards ``salvaged`` and ``note`` say whether and where it ended early."""

    def __init__(self, path: Path):
        self.path = check_mcap(path)
        self.salvaged = False
        self.note = ""
        self.messages = 0

    def __iter__(self) -> Iterator[tuple[str, int, Any]]:
        from mcap.exceptions import McapError
        from mcap.records import Attachment, Channel, Message, Metadata
        from mcap.stream_reader import StreamReader

        channels: dict[int, str] = {}
        with self.path.open("rb") as f:
            try:
                for rec in StreamReader(f, validate_crcs=True).records:
                    if isinstance(rec, Channel):
                        channels[rec.id] = rec.topic
                    elif isinstance(rec, Message):
                        self.messages += 1
                        yield channels.get(rec.channel_id, "?"), rec.log_time, rec.data
                    elif isinstance(rec, Metadata):
                        yield "#metadata", 0, (rec.name, dict(rec.metadata))
                    elif isinstance(rec, Attachment):
                        yield "#attachment", 0, (rec.name, rec.data)
            except (McapError, EOFError, ValueError, KeyError, struct.error) as e:
                self.salvaged = True
                self.note = (f"recording ends early ({type(e).__name__}: {e}); read "
                             f"{self.messages} messages up to the last complete chunk")


def check_mcap(path: str | Path) -> Path:
    """``path`` as a Path if it is a file that starts as an MCAP file does, else
    :class:`RecordingError` saying what it is instead."""
    path = Path(path)
    if not path.is_file():
        raise RecordingError(f"{path}: no such file" if not path.exists() else
                             f"{path}: not a file")
    with path.open("rb") as f:
        magic = f.read(len(fmt.MCAP_MAGIC))
    if magic != fmt.MCAP_MAGIC:
        what = "an empty file" if not magic else "no MCAP magic at its start"
        raise RecordingError(f"{path}: not an MCAP recording ({what})")
    return path


def read_recording(path: str | Path, frames: bool = True) -> Recording:
    """A daemon's recording: ticks by index (estimate and inputs), raw frames (unless
    ``frames`` is false), reference, metadata and the model it ran."""
    scan = Scan(Path(path))
    path = scan.path
    metadata: dict[str, dict[str, str]] = {}
    model = None
    inputs: dict[int, dict] = {}
    est: dict[int, dict] = {}
    ref: dict[int, tuple[float, float]] = {}
    raw: list[fmt.Frame] = []
    topics: dict[str, int] = {}
    try:
        for topic, _, data in scan:
            if topic == "#metadata":
                metadata[data[0]] = data[1]
                continue
            if topic == "#attachment":
                if data[0] == fmt.ATT_MODEL:
                    model = ModelFile.from_dict(json.loads(data[1]), f"{path}!{fmt.ATT_MODEL}")
                continue
            topics[topic] = topics.get(topic, 0) + 1
            if topic == fmt.ESTIMATE:
                m = json.loads(data)
                if m["tick"] >= 0:  # -1: watchdog publish between ticks
                    est[m["tick"]] = m
            elif topic == fmt.INPUTS:
                m = json.loads(data)
                inputs[m["tick"]] = m
            elif topic == fmt.REFERENCE:
                m = json.loads(data)
                ref[m["tick"]] = (m.get(_REF_CR, np.nan), m.get(_REF_CD, np.nan))
            elif topic == fmt.FRAMES and frames:
                raw.append(fmt.read_frame(data))
    except (ValueError, KeyError, TypeError) as e:  # a message not what the format says
        raise RecordingError(f"{path}: message {scan.messages}: not a chest-observer "
                             f"message ({type(e).__name__}: {e})") from None
    salvaged, note = scan.salvaged, scan.note
    if fmt.META_RUN not in metadata:
        if salvaged and not scan.messages:  # cut or corrupt before its first message
            raise RecordingError(f"{path}: an MCAP file that ends or breaks before anything "
                                 f"was recorded: {note}")
        raise RecordingError(f"{path}: an MCAP file, but not a chest-observer recording (no "
                             f"'{fmt.META_RUN}' metadata record)")
    if not est:
        raise RecordingError(f"{path}: holds no ticks (the daemon heard no accelerometer "
                             "frame before it stopped)" + (f"; {note}" if note else ""))
    if fmt.META_END not in metadata and not salvaged:
        salvaged, note = True, f"recording has no end record; read {sum(topics.values())} messages"
    ticks_idx = np.array(sorted(set(est) & set(inputs)), dtype=np.int64)
    ticks: dict[str, np.ndarray] = {"tick": ticks_idx}
    # a number left out of a message had no value (see format): NaN here
    for k, col in _EST_KEYS:  # columns named as TickRow's fields
        ticks[col] = np.array([est[i].get(k, np.nan) for i in ticks_idx], dtype=float)
    for k, col in _INPUT_KEYS:
        ticks[col] = np.array([inputs[i].get(k, np.nan) for i in ticks_idx], dtype=float)
    return Recording(path, metadata, model, ticks, raw, ref, salvaged, note, topics)
