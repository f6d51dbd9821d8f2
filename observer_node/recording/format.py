"""The recording's format: one MCAP file per run, its topics, their fields and JSON schemas.

This module is the contract between the daemon that writes a recording
(:mod:`.writer`), everything that reads one (:mod:`.reader`, ``analyze``, ``crash-replay``)
and any MCAP viewer: topic names, the fields of each message with their JSON types, the
metadata records and attachments. A field added here is added everywhere.

Topics (JSON messages, one message type per topic, every field declared in its schema so
Foxglove offers it):

``/can/frames``          every frame received and sent, raw, for exact replay
``/observer/inputs``     per tick: accelerometer (J211), deceleration, bias, BRS
``/observer/estimate``   per tick: CR, CD, valid, running, state, invalid cause
``/observer/reference``  per tick with reference frames: the dummy's measured CR, CD
``/observer/status``     the ObserverStatus frames, decoded (their signals by name);
``/observer/counters``   likewise ObserverCounters, ``/observer/health`` ObserverHealth
``/observer/criteria``   the ChestCriteria frame of each finished event, decoded

A number without a value (a watchdog publish's accelerometer sample) is left out of its
message, never written as NaN (not JSON); the schemas require every other field.

Metadata records: ``chest-observer`` (software, model, DBC hash, configuration, start time:
:class:`RunMeta`) at the start, ``chest-observer-recorder`` (what was written and lost:
:class:`EndMeta`) at a clean end; a file without the latter was cut short. Attachments:
``model.json`` and ``chest_observer.dbc``.
Times: ``t`` is seconds since the recorder started; the MCAP log time is wall-clock ns.
What ``state`` and ``cause`` mean is the DBC's (``observer_node.dbc.meanings``); a frame's
flags are :class:`FrameFlag`. Read back: :func:`read_frame` (a :class:`Frame`), the tick
topics' fields by :data:`TICK_TOPICS` (each names its :class:`TickRow` column).
"""

from __future__ import annotations

import dataclasses
import enum
import json
import math
import operator
from collections.abc import Callable
from typing import NamedTuple

MCAP_MAGIC = b"\x89MCAP0\r\n"
META_RUN = "chest-observer"
META_END = "chest-observer-recorder"
ATT_MODEL = "model.json"
ATT_DBC = "chest_observer.dbc"
# Attachments' media types
MEDIA = {ATT_MODEL: "application/json", ATT_DBC: "text/plain"}


class RunMeta(enum.StrEnum):
    """The keys of the ``chest-observer`` metadata record (every value a string)."""

    SOFTWARE_VERSION = "software_version"
    MODEL_NAME = "model_name"
    MODEL_KIND = "model_kind"
    MODEL_ID = "model_id"
    TICK_RATE_HZ = "tick_rate_hz"
    DBC_SHA256 = "dbc_sha256"
    CONFIG = "config"  # the daemon's NodeConfig as JSON
    CPU_LATENCY = "cpu_latency"
    SCHEDULING = "scheduling"
    STARTED_UTC = "started_utc"


class EndMeta(enum.StrEnum):
    """The keys of the ``chest-observer-recorder`` record written at a clean end."""

    FRAMES_LOST = "frames_lost"
    TICKS_LOST = "ticks_lost"
    FRAMES = "frames"
    TICKS = "ticks"

FRAMES = "/can/frames"
INPUTS = "/observer/inputs"
ESTIMATE = "/observer/estimate"
REFERENCE = "/observer/reference"
STATUS = "/observer/status"


class FrameFlag(enum.IntFlag):
    """A frame's flags in the rings (the bus port sets ERROR, FD and REMOTE, the daemon TX
    on what it sent); /can/frames keeps ERROR, FD and TX as ``error``, ``fd``, ``dir``."""

    ERROR = 1
    FD = 2
    TX = 4
    REMOTE = 8  # a remote (RTR) frame: no data, never an input


# Plain ints for per-frame code (an IntFlag's operators run Python code)
_ERROR, _FD, _TX = FrameFlag.ERROR.value, FrameFlag.FD.value, FrameFlag.TX.value


@dataclasses.dataclass(slots=True)
class TickRow:
    """One tick as the daemon hands it to the writer (floats in shared memory). The daemon
    keeps one and sets its fields each tick (no row built per tick); :data:`tick_values`
    gives them in column order for the rings."""

    t: float = math.nan
    tick: float = math.nan  # -1: a watchdog publish between ticks
    accel_x_g: float = math.nan
    decel_g: float = math.nan
    bias_g: float = math.nan
    brs_count: float = math.nan
    brs_ref: float = math.nan
    rad_per_count: float = math.nan
    cr_g: float = math.nan
    cd_mm: float = math.nan
    valid: float = math.nan
    running: float = math.nan
    state: float = math.nan  # ObserverState
    cause: float = math.nan  # InvalidCause bits
    event: float = math.nan
    onset_tick: float = math.nan
    ref_cr_g: float = math.nan  # NaN: no reference frame yet
    ref_cd_mm: float = math.nan
    proc_us: float = math.nan


TICK_COLS = tuple(f.name for f in dataclasses.fields(TickRow))
# A row's values in TICK_COLS order, one tuple (C: no Python code per tick)
tick_values: Callable[[TickRow], tuple[float, ...]] = operator.attrgetter(*TICK_COLS)

# Per-tick topics: field -> (JSON type, the TickRow column it comes from). ``t`` is made
# relative to the recorder's start.
TICK_TOPICS: dict[str, dict[str, tuple[str, str]]] = {
    INPUTS: {"tick": ("integer", "tick"), "t": ("number", "t"),
             "accel_x_g": ("number", "accel_x_g"), "decel_g": ("number", "decel_g"),
             "bias_g": ("number", "bias_g"), "brs_count": ("number", "brs_count"),
             "brs_ref": ("number", "brs_ref"), "rad_per_count": ("number", "rad_per_count")},
    ESTIMATE: {"tick": ("integer", "tick"), "t": ("number", "t"), "cr_g": ("number", "cr_g"),
               "cd_mm": ("number", "cd_mm"), "valid": ("boolean", "valid"),
               "running": ("boolean", "running"), "state": ("integer", "state"),
               "cause": ("integer", "cause"), "event": ("integer", "event"),
               "onset_tick": ("integer", "onset_tick"), "proc_us": ("number", "proc_us")},
    REFERENCE: {"tick": ("integer", "tick"), "t": ("number", "t"),
                "cr_g": ("number", "ref_cr_g"), "cd_mm": ("number", "ref_cd_mm")},
}
TOPIC_FIELDS = {topic: {k: v[0] for k, v in f.items()} for topic, f in TICK_TOPICS.items()}
FRAME_FIELDS = {"t": "number", "id": "integer", "dir": "string", "error": "boolean",
                "fd": "boolean", "dlc": "integer", "data": "string"}
# The daemon's status frames, decoded: one topic and one message type per frame; the
# fields are the frame's signals in the DBC (see :func:`status_fields`).
STATUS_TOPICS = {"ObserverStatus": "/observer/status", "ObserverCounters": "/observer/counters",
                 "ObserverHealth": "/observer/health", "ChestCriteria": "/observer/criteria"}
TITLES = {FRAMES: "chest_observer.CanFrame", INPUTS: "chest_observer.Inputs",
          ESTIMATE: "chest_observer.Estimate", REFERENCE: "chest_observer.Reference",
          **{topic: f"chest_observer.{name}" for name, topic in STATUS_TOPICS.items()}}
_CAST = {"integer": int, "boolean": bool, "number": float}


def status_fields(signal_names: list[str], integer: set[str]) -> dict[str, str]:
    """Fields of a status frame's topic: ``t`` and every signal (``integer`` names those
    without a scale)."""
    return {"t": "number", **{n: "integer" if n in integer else "number"
                              for n in signal_names}}


def json_schema(topic: str, fields: dict[str, str]) -> bytes:
    """The JSON schema of a topic's messages: every field declared; all required but the
    numbers after ``t``, which are left out when they have no value (NaN is not JSON:
    JSON.parse, and so Foxglove, refuses it)."""
    return json.dumps({"title": TITLES[topic], "type": "object",
                       "properties": {k: {"type": v} for k, v in fields.items()},
                       "required": [k for k, v in fields.items()
                                    if v != "number" or k == "t"]}).encode()


def tick_messages(row: TickRow, t0: float) -> list[tuple[str, dict]]:
    """The messages of one tick: inputs, estimate, and the reference when there is one. A
    number without a value (NaN or infinite: a watchdog publish has no accelerometer
    sample) is left out of its message."""
    out = []
    for topic, fields in TICK_TOPICS.items():
        if topic == REFERENCE and row.ref_cr_g != row.ref_cr_g:  # NaN: none yet
            continue
        msg = {}
        for k, (kind, col) in fields.items():
            v = getattr(row, col)
            if kind != "number":
                msg[k] = _CAST[kind](v)
            elif v - v == 0:  # finite (NaN - NaN and inf - inf are NaN)
                msg[k] = v
        msg["t"] = row.t - t0
        out.append((topic, msg))
    return out


def frame_message(t_rel: float, can_id: int, flags: int, data: bytes) -> dict:
    """A /can/frames message: a raw frame as received or sent (``flags``: FrameFlag)."""
    return {"t": t_rel, "id": can_id, "dir": "tx" if flags & _TX else "rx",
            "error": bool(flags & _ERROR), "fd": bool(flags & _FD), "dlc": len(data),
            "data": data.hex()}


class Frame(NamedTuple):
    """A /can/frames message read back."""

    t: float  # s since the recorder started
    can_id: int
    flags: FrameFlag  # ERROR, FD, TX (REMOTE is not recorded)
    data: bytes

    @property
    def tx(self) -> bool:
        """Sent by the daemon (else received)."""
        return bool(self.flags & _TX)

    @property
    def error(self) -> bool:
        return bool(self.flags & _ERROR)

    @property
    def fd(self) -> bool:
        return bool(self.flags & _FD)

    @property
    def extended(self) -> bool:
        """A 29-bit identifier (the message keeps the number only)."""
        return self.can_id > 0x7FF


def read_frame(raw: bytes | str) -> Frame:
    """A /can/frames message as a :class:`Frame`; ValueError, KeyError or TypeError when it
    is not one."""
    m = json.loads(raw)
    if not isinstance(m, dict):
        raise ValueError(f"not a JSON object: {str(m)[:40]}")
    if m["dir"] not in ("rx", "tx"):
        raise ValueError(f"dir {m['dir']!r} is neither rx nor tx")
    flags = (_TX if m["dir"] == "tx" else 0) | (_ERROR if m["error"] else 0) | \
        (_FD if m["fd"] else 0)
    return Frame(float(m["t"]), int(m["id"]), FrameFlag(flags), bytes.fromhex(m["data"]))
