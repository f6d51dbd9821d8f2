"""Recording a run to MCAP without delaying a tick.

The tick loop writes fixed-size rows into two rings in shared memory (raw CAN frames, and one
row per tick); a separate *process* drains them into an MCAP file. A process, not a thread:
a Python thread encoding JSON would hold the GIL for milliseconds at a time and delay ticks.

The writer flushes a chunk at least every ``flush_s`` (50 ms), so a daemon killed outright
loses at most ~100 ms of data and the file up to there is readable with a non-seeking reader
(see :mod:`observer_node.recording`). If the daemon dies but the writer survives, the writer
notices its parent is gone, drains what is in the rings and finishes the file properly.

Topics (JSON messages, JSON schemas, so Foxglove can plot every field):

``/can/frames``          every frame received and sent, raw, for exact replay
``/observer/inputs``     per tick: accelerometer (J211), deceleration, bias, BRS
``/observer/estimate``   per tick: CR, CD, valid, running, state, invalid cause
``/observer/reference``  per tick with reference frames: the dummy's measured CR, CD
``/observer/status``     the ObserverStatus and ObserverCounters frames, decoded
plus a ``chest-observer`` metadata record and the model file and DBC as attachments.
"""

from __future__ import annotations

import contextlib
import json
import multiprocessing as mp
import os
import struct
import time
from multiprocessing import shared_memory
from pathlib import Path

import numpy as np

FRAME_COLS = ("t", "id", "flags", "dlc")
TX = 4  # frame flag bit: sent by the daemon (bits 1, 2 are ports.FLAG_ERROR, FLAG_FD)
TICK_COLS = ("t", "tick", "accel_x_g", "decel_g", "bias_g", "brs_count", "brs_ref",
             "rad_per_count", "cr_g", "cd_mm", "valid", "running", "state", "cause", "event",
             "onset_tick", "ref_cr_g", "ref_cd_mm", "proc_us")
_CTRL = ("frames_head", "ticks_head", "stop", "done", "frames_lost", "ticks_lost", "ready")
FRAMES_HEAD, TICKS_HEAD, STOP, DONE, FRAMES_LOST, TICKS_LOST, READY = range(len(_CTRL))
_HEAD = struct.Struct("=q")
_FRAME_ROW = struct.Struct(f"={len(FRAME_COLS)}d")
_TICK_ROW = struct.Struct(f"={len(TICK_COLS)}d")


class Rings:
    """Shared-memory rings: frames (meta + 64 data bytes) and ticks (float64 rows)."""

    def __init__(self, capacity: int = 1 << 16, names: tuple[str, str, str] | None = None):
        create = names is None
        self.capacity = capacity
        sizes = (8 * len(_CTRL), capacity * (8 * len(FRAME_COLS) + 64),
                 capacity * 8 * len(TICK_COLS))
        self.shm = [shared_memory.SharedMemory(create=create, size=s if create else 0,
                                               name=None if create else names[k])
                    for k, s in enumerate(sizes)]
        if create:
            # Touch every page now: a page first written during a run is a page fault in the
            # middle of a tick (tens of microseconds, milliseconds on a busy VM).
            for seg in self.shm:
                np.ndarray((seg.size,), np.uint8, buffer=seg.buf).fill(0)
        self.ctrl = np.ndarray((len(_CTRL),), np.int64, buffer=self.shm[0].buf)
        self.frame_meta = np.ndarray((capacity, len(FRAME_COLS)), np.float64,
                                     buffer=self.shm[1].buf)
        self.frame_data = self.shm[1].buf[capacity * 8 * len(FRAME_COLS):]
        self.ticks = np.ndarray((capacity, len(TICK_COLS)), np.float64, buffer=self.shm[2].buf)
        # The producer's side: raw buffers and its own copy of the heads (it is their only
        # writer).
        self._ctrl_buf, self._meta_buf, self._ticks_buf = (s.buf for s in self.shm)
        self._frames_head = int(self.ctrl[FRAMES_HEAD])
        self._ticks_head = int(self.ctrl[TICKS_HEAD])

    @property
    def names(self) -> tuple[str, str, str]:
        return tuple(s.name for s in self.shm)  # type: ignore[return-value]

    # Hot path: pack one row straight into shared memory, then publish the head (the writer
    # reads rows below it). struct, not numpy item assignment: a third of the time.
    def put_frame(self, t: float, can_id: int, data: bytes, flags: int) -> None:
        head = self._frames_head
        i = head % self.capacity
        n = len(data)
        _FRAME_ROW.pack_into(self._meta_buf, i * _FRAME_ROW.size, t, can_id, flags, n)
        self.frame_data[i * 64:i * 64 + n] = data
        self._frames_head = head + 1
        _HEAD.pack_into(self._ctrl_buf, 8 * FRAMES_HEAD, head + 1)

    def put_tick(self, row: tuple) -> None:
        head = self._ticks_head
        _TICK_ROW.pack_into(self._ticks_buf, (head % self.capacity) * _TICK_ROW.size, *row)
        self._ticks_head = head + 1
        _HEAD.pack_into(self._ctrl_buf, 8 * TICKS_HEAD, head + 1)

    def close(self, unlink: bool = False) -> None:
        self.ctrl = self.frame_meta = self.ticks = None  # type: ignore[assignment]
        self._ctrl_buf = self._meta_buf = self._ticks_buf = None  # type: ignore[assignment]
        self.frame_data.release()
        for s in self.shm:
            s.close()
            if unlink:
                with contextlib.suppress(FileNotFoundError):
                    s.unlink()


def _schema(title: str, props: dict[str, str]) -> bytes:
    return json.dumps({"title": title, "type": "object",
                       "properties": {k: {"type": v} for k, v in props.items()}}).encode()


_TOPICS = {
    "/can/frames": ("chest_observer.CanFrame", {
        "t": "number", "id": "integer", "dir": "string", "error": "boolean", "fd": "boolean",
        "dlc": "integer", "data": "string"}),
    "/observer/inputs": ("chest_observer.Inputs", {
        "tick": "integer", "t": "number", "accel_x_g": "number", "decel_g": "number",
        "bias_g": "number", "brs_count": "number", "brs_ref": "number",
        "rad_per_count": "number"}),
    "/observer/estimate": ("chest_observer.Estimate", {
        "tick": "integer", "t": "number", "cr_g": "number", "cd_mm": "number",
        "valid": "boolean", "running": "boolean", "state": "integer", "cause": "integer",
        "event": "integer", "onset_tick": "integer", "proc_us": "number"}),
    "/observer/reference": ("chest_observer.Reference", {
        "tick": "integer", "t": "number", "cr_g": "number", "cd_mm": "number"}),
    "/observer/status": ("chest_observer.Status", {
        "t": "number", "frame": "string"}),
}


def writer_main(names: tuple[str, str, str], capacity: int, path: str, clock: tuple[int, float],
                metadata: dict[str, str], attachments: list[tuple[str, str, bytes]],
                dbc_path: str, flush_s: float = 0.05, ppid: int | None = None) -> None:
    """The recorder process: drain the rings into ``path`` until told to stop."""
    from mcap.writer import CompressionType, Writer

    # The rings hold seconds of data: the writer takes only CPU time nobody else wants, and
    # a waking daemon preempts it at once (SCHED_IDLE; nice 19 where that is refused).
    try:
        os.sched_setscheduler(0, os.SCHED_IDLE, os.sched_param(0))
    except (OSError, AttributeError):
        with contextlib.suppress(OSError):
            os.nice(19)

    from dbc import Codec

    rings = Rings(capacity, names)
    codec = Codec(dbc_path)
    status_ids = {codec["ObserverStatus"].frame_id: codec["ObserverStatus"],
                  codec["ObserverCounters"].frame_id: codec["ObserverCounters"]}
    wall0_ns, perf0 = clock
    f = open(path, "wb")  # noqa: SIM115 - closed in finally
    w = Writer(f, chunk_size=64 * 1024, compression=CompressionType.ZSTD)
    w.start(profile="", library="chest-observer")
    chan = {}
    for topic, (title, props) in _TOPICS.items():
        sid = w.register_schema(title, "jsonschema", _schema(title, props))
        chan[topic] = w.register_channel(topic, "json", sid)
    w.add_metadata("chest-observer", metadata)
    for name, media, data in attachments:
        w.add_attachment(wall0_ns, wall0_ns, name, media, data)
    w.flush()
    rings.ctrl[READY] = 1
    seq = dict.fromkeys(chan, 0)

    def emit(topic: str, t: float, msg: dict) -> None:
        ns = wall0_ns + int((t - perf0) * 1e9)
        w.add_message(chan[topic], ns, json.dumps(msg, separators=(",", ":")).encode(), ns,
                      seq[topic])
        seq[topic] += 1

    tail_f = tail_t = 0
    last_flush = time.monotonic()
    try:
        while True:
            stop = bool(rings.ctrl[STOP])
            head_f, head_t = int(rings.ctrl[FRAMES_HEAD]), int(rings.ctrl[TICKS_HEAD])
            if head_f - tail_f > capacity:
                rings.ctrl[FRAMES_LOST] += head_f - tail_f - capacity
                tail_f = head_f - capacity
            if head_t - tail_t > capacity:
                rings.ctrl[TICKS_LOST] += head_t - tail_t - capacity
                tail_t = head_t - capacity
            wrote = head_f > tail_f or head_t > tail_t
            for k in range(tail_f, head_f):
                i = k % capacity
                t, cid, flags, n = rings.frame_meta[i]
                cid, flags, n = int(cid), int(flags), int(n)
                data = bytes(rings.frame_data[i * 64:i * 64 + n])
                emit("/can/frames", t, {"t": t - perf0, "id": cid,
                                        "dir": "tx" if flags & TX else "rx",
                                        "error": bool(flags & 1), "fd": bool(flags & 2),
                                        "dlc": n, "data": data.hex()})
                fc = status_ids.get(cid)
                if fc is not None and n == fc.length:
                    emit("/observer/status", t, {"t": t - perf0, "frame": fc.name,
                                                 **fc.decode(data)})
            tail_f = head_f
            for k in range(tail_t, head_t):
                r = dict(zip(TICK_COLS, rings.ticks[k % capacity].tolist(), strict=True))
                t = r["t"]
                rel = t - perf0
                tick = int(r["tick"])
                emit("/observer/inputs", t, {
                    "tick": tick, "t": rel, "accel_x_g": r["accel_x_g"], "decel_g": r["decel_g"],
                    "bias_g": r["bias_g"], "brs_count": r["brs_count"], "brs_ref": r["brs_ref"],
                    "rad_per_count": r["rad_per_count"]})
                emit("/observer/estimate", t, {
                    "tick": tick, "t": rel, "cr_g": r["cr_g"], "cd_mm": r["cd_mm"],
                    "valid": bool(r["valid"]), "running": bool(r["running"]),
                    "state": int(r["state"]), "cause": int(r["cause"]),
                    "event": int(r["event"]), "onset_tick": int(r["onset_tick"]),
                    "proc_us": r["proc_us"]})
                if r["ref_cr_g"] == r["ref_cr_g"]:  # not NaN
                    emit("/observer/reference", t, {"tick": tick, "t": rel,
                                                    "cr_g": r["ref_cr_g"],
                                                    "cd_mm": r["ref_cd_mm"]})
            tail_t = head_t
            now = time.monotonic()
            if wrote and now - last_flush >= flush_s:
                w.flush()
                last_flush = now
            orphaned = ppid is not None and os.getppid() != ppid
            if (stop or orphaned) and tail_f == int(rings.ctrl[FRAMES_HEAD]) and \
                    tail_t == int(rings.ctrl[TICKS_HEAD]):
                break
            if not wrote:
                time.sleep(0.005)
        w.add_metadata("chest-observer-recorder", {
            "frames_lost": str(int(rings.ctrl[FRAMES_LOST])),
            "ticks_lost": str(int(rings.ctrl[TICKS_LOST])),
            "frames": str(seq["/can/frames"]), "ticks": str(seq["/observer/estimate"])})
        w.finish()
    finally:
        f.close()
        rings.ctrl[DONE] = 1
        rings.close()


class Recorder:
    """Owns the rings and the writer process."""

    def __init__(self, path: str | Path, metadata: dict[str, str],
                 attachments: list[tuple[str, str, bytes]], dbc_path: str | Path,
                 capacity: int = 1 << 16):
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.rings = Rings(capacity)
        self.clock = (time.time_ns(), time.perf_counter())
        ctx = mp.get_context("spawn")
        self.proc = ctx.Process(
            target=writer_main, name="chest-observer-recorder", daemon=False,
            args=(self.rings.names, capacity, str(self.path), self.clock, metadata,
                  attachments, str(dbc_path), 0.05, os.getpid()))
        self.proc.start()
        self.put_frame = self.rings.put_frame
        self.put_tick = self.rings.put_tick

    def wait_ready(self, timeout_s: float = 30.0) -> bool:
        """Wait until the writer process has the file open (it buffers meanwhile anyway)."""
        deadline = time.monotonic() + timeout_s
        while not self.rings.ctrl[READY] and self.proc.is_alive() and time.monotonic() < deadline:
            time.sleep(0.01)
        return bool(self.rings.ctrl[READY])

    @property
    def lost(self) -> tuple[int, int]:
        return int(self.rings.ctrl[FRAMES_LOST]), int(self.rings.ctrl[TICKS_LOST])

    def close(self, timeout_s: float = 30.0) -> None:
        """Stop after everything written so far is in the file, and finish it."""
        self.rings.ctrl[STOP] = 1
        self.proc.join(timeout_s)
        if self.proc.is_alive():
            self.proc.terminate()
            self.proc.join(5)
        self.rings.close(unlink=True)
