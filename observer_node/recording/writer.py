"""Recording a run to MCAP without delaying a tick, and without losing it silently.

The tick loop writes fixed-size rows into two rings in shared memory (raw CAN frames, and one
row per tick); a separate *process* drains them into an MCAP file. A process, not a thread:
a Python thread encoding JSON would hold the GIL for milliseconds at a time and delay ticks.

What the recorder promises (docs/daemon.md, "Faults"):

- **Nothing is overwritten.** The daemon creates the file itself, exclusively; if the name
  is taken it writes ``NAME.1.mcap``, ``NAME.2.mcap``, ... Path errors (a parent that is a
  file, no permission, a directory) are raised here, in the daemon, with their real cause.
- **A kill loses little.** The writer flushes a chunk every ``FLUSH_S`` (30 ms) and drains
  the rings in bounded batches; it runs at idle priority only while it keeps up
  (:meth:`Recorder.keep_up`), so a file cut by ``SIGKILL`` ends at most ~100 ms before the
  kill, even on a loaded machine, and reads with a non-seeking reader
  (:mod:`observer_node.recording`). If only the daemon dies, the writer notices, drains the
  rings and finishes the file.
- **Ctrl-C and SIGTERM are the daemon's.** A terminal and systemd signal the whole process
  group; the writer ignores SIGINT and SIGTERM (blocked from its start, ignored from its
  first line) and finishes the file when the daemon stops it, or when the daemon is gone.
- **Nothing leaks.** The rings are one anonymous ``memfd`` handed to the writer as a file
  descriptor: no named segment in ``/dev/shm`` survives any kill.
- **Writer trouble reaches the daemon.** The writer publishes what it has flushed and, when
  it fails, the errno and message. :meth:`Recorder.poll` (called at the status period) sees a
  dead writer, starts a new one on the next file part (``NAME.part2.mcap``, ...) from the
  last flushed row, so the rings' seconds of buffer bridge the restart; after
  ``max_parts`` or when no part can be created the recording has FAILED. Rows the rings no
  longer hold are counted as lost.
- **Every row in exactly one part.** Chunks end only where the writer flushes, after a
  whole row (every ``FLUSH_S``, or at ``CHUNK_BYTES``: the mcap writer never ends one on
  its own, between rows), and each flush is announced before it is written
  (its rows and file offset, ``*_PENDING``) and published after (``*_FLUSHED``). A
  successor starts from the announced rows if that chunk is complete in the dead writer's
  file (:func:`durable_tails`), else from the published ones: a kill between the two
  neither repeats nor drops a row.

Topics, fields and schemas are those of :mod:`.format`.
"""

from __future__ import annotations

import contextlib
import errno as errno_mod
import json
import mmap
import multiprocessing as mp
import os
import signal
import struct
import sys
import time
from collections.abc import Callable
from multiprocessing import reduction
from pathlib import Path
from typing import Any, NoReturn

import numpy as np

from observer_node.dbc.meanings import RecorderState

from . import format as fmt
from .format import TICK_COLS, TickRow

FRAME_COLS = ("t", "id", "flags", "dlc")  # a frame's row in the rings, its data beside
_CTRL = ("frames_head", "ticks_head", "stop", "done", "frames_lost", "ticks_lost", "ready",
         "frames_flushed", "ticks_flushed", "errno", "frames_pending", "ticks_pending",
         "pending_at")
FRAMES_HEAD, TICKS_HEAD, STOP, DONE, FRAMES_LOST, TICKS_LOST, READY, FRAMES_FLUSHED, \
    TICKS_FLUSHED, ERRNO, FRAMES_PENDING, TICKS_PENDING, PENDING_AT = range(len(_CTRL))
_NO_CHUNK = 1 << 62  # the mcap writer's chunk size: it never ends a chunk on its own
_MSG_BYTES = 512  # the writer's last error, UTF-8
_FRAME_ROW = struct.Struct(f"={len(FRAME_COLS)}d")
_TICK_ROW = struct.Struct(f"={len(TICK_COLS)}d")


class RecorderError(OSError):
    """The recording cannot be started; the message names the file and the cause."""


class _Fd:
    """An open file descriptor handed to the spawned writer: multiprocessing passes it to
    the child as it does sockets and pipes (``reduction.DupFd``), same number, no name."""

    def __init__(self, fd: int):
        self.fd = fd

    def __reduce__(self) -> tuple[Callable[[Any], _Fd], tuple[Any]]:
        return _Fd._rebuild, (reduction.DupFd(self.fd),)

    @staticmethod
    def _rebuild(dup: Any) -> _Fd:
        return _Fd(dup.detach())


class Rings:
    """Shared-memory rings in one memfd: control words, the writer's error message, frames
    (meta + 64 data bytes) and ticks (float64 rows)."""

    def __init__(self, capacity: int = 1 << 16, fd: int | None = None):
        self.capacity = capacity
        ctrl_b = 8 * len(_CTRL)
        meta_b = capacity * 8 * len(FRAME_COLS)
        data_b = capacity * 64
        tick_b = capacity * 8 * len(TICK_COLS)
        size = ctrl_b + _MSG_BYTES + meta_b + data_b + tick_b
        create = fd is None
        if fd is None:
            fd = os.memfd_create("chest-observer-rings", os.MFD_CLOEXEC)
            os.ftruncate(fd, size)
        self.fd = fd
        self.mm = mmap.mmap(fd, size)
        if create:
            # Touch every page now: a page first written during a run is a page fault in the
            # middle of a tick (tens of microseconds, milliseconds on a busy VM).
            np.ndarray((size,), np.uint8, buffer=self.mm).fill(0)
        # Layout: control words | error message | frame meta | frame data | ticks
        self._msg_off = ctrl_b
        self._meta_off = self._msg_off + _MSG_BYTES
        self._data_off = self._meta_off + meta_b
        self._ticks_off = self._data_off + data_b
        mm = self.mm
        self.ctrl = np.ndarray((len(_CTRL),), np.int64, buffer=mm)
        self.frame_meta = np.ndarray((capacity, len(FRAME_COLS)), np.float64, buffer=mm,
                                     offset=self._meta_off)
        self.ticks = np.ndarray((capacity, len(TICK_COLS)), np.float64, buffer=mm,
                                offset=self._ticks_off)
        # The heads are published through this view: one aligned 8-byte store each, which the
        # writer never reads half-done (none in 3 million stores here). struct.pack_into's
        # stores were read torn 1446 times in as many: a smaller head, and the writer went
        # back and wrote rows a second time.
        self._ctrl_words = memoryview(mm)[:8 * len(_CTRL)].cast("q")
        self._frames_head = int(self.ctrl[FRAMES_HEAD])
        self._ticks_head = int(self.ctrl[TICKS_HEAD])

    # Hot path: pack one row straight into shared memory, then publish the head (the writer
    # reads rows below it). struct, not numpy item assignment: a third of the time.
    def put_frame(self, t: float, can_id: int, data: bytes, flags: int) -> None:
        head = self._frames_head
        i = head % self.capacity
        n = len(data)
        mm = self.mm
        _FRAME_ROW.pack_into(mm, self._meta_off + i * _FRAME_ROW.size, t, can_id, flags, n)
        d = self._data_off + i * 64
        mm[d:d + n] = data
        self._frames_head = head + 1
        self._ctrl_words[FRAMES_HEAD] = head + 1

    def put_tick(self, row: tuple[float, ...]) -> None:
        """``row``: a tick's values in TICK_COLS order (``format.tick_values``)."""
        head = self._ticks_head
        _TICK_ROW.pack_into(self.mm, self._ticks_off + (head % self.capacity) * _TICK_ROW.size,
                            *row)
        self._ticks_head = head + 1
        self._ctrl_words[TICKS_HEAD] = head + 1

    def frame_data(self, i: int, n: int) -> bytes:
        d = self._data_off + i * 64
        return self.mm[d:d + n]

    def set_error(self, err: int, message: str) -> None:
        raw = message.encode("utf-8", "replace")[:_MSG_BYTES - 1]
        self.mm[self._msg_off:self._msg_off + _MSG_BYTES] = raw.ljust(_MSG_BYTES, b"\0")
        self.ctrl[ERRNO] = err or errno_mod.EIO

    def error(self) -> str:
        raw = self.mm[self._msg_off:self._msg_off + _MSG_BYTES]
        return raw.split(b"\0", 1)[0].decode("utf-8", "replace")

    def close(self) -> None:
        self._ctrl_words.release()
        self.ctrl = self.frame_meta = self.ticks = None  # type: ignore[assignment]
        with contextlib.suppress(BufferError):
            self.mm.close()
        with contextlib.suppress(OSError):
            os.close(self.fd)


_GROUP_SIGNALS = {signal.SIGINT, signal.SIGTERM}  # what a terminal or systemd sends a group
_BATCH = 250  # rows per drain step: a writer that is behind still flushes every ~flush_s


def writer_main(rings_fd: _Fd, capacity: int, file_fd: _Fd, path: str, clock: tuple[int, float],
                metadata: dict[str, str], attachments: list[tuple[str, str, bytes]],
                dbc_path: str, flush_s: float = 0.05, ppid: int | None = None,
                live: str = "", live_every: int = 1) -> NoReturn:
    """The recorder process: drain the rings into the open file ``file_fd`` until told to
    stop, finish the file and end the process (exit code 0; 1 after a failure, which is
    written to the rings' error slot first)."""
    # The daemon stops us (STOP, or its death): a signal to the process group must not cut
    # the file short. Blocked since the spawn (Recorder._spawn), ignored from here on.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _GROUP_SIGNALS)
    rings = Rings(capacity, rings_fd.fd)
    f = None
    code = 0
    try:
        f = os.fdopen(file_fd.fd, "wb")
        _write(rings, capacity, f, clock, metadata, attachments, dbc_path, flush_s, ppid,
               live, live_every)
        _durable(f, path)
    except BaseException as e:
        err = e.errno if isinstance(e, OSError) and e.errno else errno_mod.EIO
        why = e.strerror if isinstance(e, OSError) and e.strerror else f"{type(e).__name__}: {e}"
        rings.set_error(err, f"{path}: {why}")
        code = 1
    finally:
        if f is not None:
            try:
                f.close()
            except OSError as e:  # a write-back error the last fsync did not see (NFS)
                if not code:
                    rings.set_error(e.errno or errno_mod.EIO, f"{path}: cannot finish the "
                                    f"file: {e.strerror or e}")
                    code = 1
        rings.ctrl[DONE] = 1
        rings.close()
    # The file is whole: end now. The interpreter's own teardown (a last garbage collection
    # over every module) took 3-60 s of a core shared with three busy processes, past the
    # daemon's close timeout: the writer was killed after its file was finished.
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(code)


def _write(rings: Rings, capacity: int, f: Any, clock: tuple[int, float],
           metadata: dict[str, str], attachments: list[tuple[str, str, bytes]], dbc_path: str,
           flush_s: float, ppid: int | None, live_addr: str, live_every: int) -> None:
    # Imports and set-up at normal priority: on a slow machine they take seconds, and the
    # daemon waits for READY.
    from mcap.writer import CompressionType, Writer

    from observer_node.dbc import Codec

    codec = Codec(dbc_path)
    status = {codec[name].frame_id: (codec[name], topic)
              for name, topic in fmt.STATUS_TOPICS.items()}
    wall0_ns, perf0 = clock
    # Chunks end only at flush(): a chunk the library ended on its own between two flushes
    # was in the file before its rows were published, and a successor wrote them again.
    w = Writer(f, chunk_size=_NO_CHUNK, compression=CompressionType.ZSTD)
    w.start(profile="", library="chest-observer")
    fields = {fmt.FRAMES: fmt.FRAME_FIELDS, **fmt.TOPIC_FIELDS}
    for fc, topic in status.values():
        fields[topic] = fmt.status_fields(fc.signal_names, fc.unscaled_signals)
    chan = {}
    for topic, f_ in fields.items():
        sid = w.register_schema(fmt.TITLES[topic], "jsonschema", fmt.json_schema(topic, f_))
        chan[topic] = w.register_channel(topic, "json", sid)
    # The live view: the same topics and schemas, served from here, off the tick path.
    live = _start_live(live_addr, fields) if live_addr else None
    w.add_metadata(fmt.META_RUN, metadata)
    for name, media, data in attachments:
        w.add_attachment(wall0_ns, wall0_ns, name, media, data)
    w.flush()
    ctrl = rings.ctrl
    ctrl[READY] = 1  # from here the daemon sets this process's priority (Recorder.keep_up)
    seq = dict.fromkeys(chan, 0)
    in_chunk = [0]  # message bytes since the last flush

    def emit(topic: str, t: float, msg: dict) -> None:
        ns = wall0_ns + int((t - perf0) * 1e9)
        raw = json.dumps(msg, separators=(",", ":")).encode()
        w.add_message(chan[topic], ns, raw, ns, seq[topic])
        seq[topic] += 1
        in_chunk[0] += len(raw)

    # A restarted writer goes on from what the last one flushed (durable_tails).
    tail_f, tail_t = int(ctrl[FRAMES_FLUSHED]), int(ctrl[TICKS_FLUSHED])

    def flush() -> None:
        """One chunk with every row drained so far: announced, written, published."""
        ctrl[PENDING_AT] = f.tell()  # everything before is in the file already
        ctrl[FRAMES_PENDING], ctrl[TICKS_PENDING] = tail_f, tail_t
        w.flush()  # the chunk, its message indexes, then the file object's flush
        ctrl[FRAMES_FLUSHED], ctrl[TICKS_FLUSHED] = tail_f, tail_t
        in_chunk[0] = 0

    last_flush = time.monotonic()
    while True:
        stop = bool(ctrl[STOP])
        head_f, head_t = int(ctrl[FRAMES_HEAD]), int(ctrl[TICKS_HEAD])
        if head_f - tail_f > capacity:
            ctrl[FRAMES_LOST] += head_f - tail_f - capacity
            tail_f = head_f - capacity
        if head_t - tail_t > capacity:
            ctrl[TICKS_LOST] += head_t - tail_t - capacity
            tail_t = head_t - capacity
        # Never behind the tail: a head that seemed to go back would write rows twice.
        head_f = min(max(head_f, tail_f), tail_f + _BATCH)
        head_t = min(max(head_t, tail_t), tail_t + _BATCH)
        wrote = head_f > tail_f or head_t > tail_t
        for k in range(tail_f, head_f):
            i = k % capacity
            t, cid, flags, n = rings.frame_meta[i]
            cid, flags, n = int(cid), int(flags), int(n)
            data = rings.frame_data(i, n)
            emit(fmt.FRAMES, t, fmt.frame_message(t - perf0, cid, flags, data))
            st = status.get(cid)
            if st is not None and n == st[0].length:
                msg = {"t": t - perf0, **st[0].decode(data)}
                emit(st[1], t, msg)
                if live is not None:
                    live[st[1]].log(msg, log_time=wall0_ns + int((t - perf0) * 1e9))
            if in_chunk[0] >= CHUNK_BYTES:  # a writer behind: chunks of bounded size
                tail_f = k + 1
                flush()
        tail_f = head_f
        for k in range(tail_t, head_t):
            row = TickRow(*rings.ticks[k % capacity].tolist())
            for topic, msg in fmt.tick_messages(row, perf0):
                emit(topic, row.t, msg)
                if live is not None and int(row.tick) % live_every == 0:
                    live[topic].log(msg, log_time=wall0_ns + int((row.t - perf0) * 1e9))
            if in_chunk[0] >= CHUNK_BYTES:
                tail_t = k + 1
                flush()
        tail_t = head_t
        now = time.monotonic()
        if wrote and now - last_flush >= flush_s:
            flush()
            last_flush = now
        orphaned = ppid is not None and os.getppid() != ppid
        if (stop or orphaned) and tail_f == int(ctrl[FRAMES_HEAD]) and \
                tail_t == int(ctrl[TICKS_HEAD]):
            break
        if not wrote:
            time.sleep(0.005)
    flush()  # the last rows in a chunk of their own, published before the end record
    w.add_metadata(fmt.META_END, {
        fmt.EndMeta.FRAMES_LOST.value: str(int(ctrl[FRAMES_LOST])),
        fmt.EndMeta.TICKS_LOST.value: str(int(ctrl[TICKS_LOST])),
        fmt.EndMeta.FRAMES.value: str(seq[fmt.FRAMES]),
        fmt.EndMeta.TICKS.value: str(seq[fmt.ESTIMATE])})
    w.finish()


def _durable(f: Any, path: str) -> None:
    """The finished file on the disk, and its name in its folder, before the run says it
    is recorded: a power cut seconds after the run ends loses nothing, and a write-back
    error (a failing disk, a full NFS share) is said here instead of never."""
    f.flush()
    os.fsync(f.fileno())
    try:
        folder = os.open(os.path.dirname(path) or ".", os.O_RDONLY | os.O_DIRECTORY)
    except OSError:
        return  # the file itself is on the disk; its folder is the filesystem's to keep
    try:
        os.fsync(folder)
    except OSError as e:
        if e.errno not in (errno_mod.EINVAL, errno_mod.ENOTSUP):  # folders it cannot sync
            raise
    finally:
        os.close(folder)


def durable_tails(ctrl: np.ndarray, path: Path) -> None:
    """After a writer of ``path`` ended: make ``*_FLUSHED`` the rows that are in its file.
    The chunk it announced (``*_PENDING`` at ``PENDING_AT``) is there if the file holds the
    whole record (opcode, 8-byte length, content); its message indexes may be cut, the
    rows read all the same. Called with no writer running."""
    pending = int(ctrl[FRAMES_PENDING]), int(ctrl[TICKS_PENDING])
    at = int(ctrl[PENDING_AT])
    if at < 0 or pending == (int(ctrl[FRAMES_FLUSHED]), int(ctrl[TICKS_FLUSHED])):
        return
    from mcap.opcode import Opcode

    try:
        with path.open("rb") as f:
            f.seek(at)
            head = f.read(9)
            size = os.fstat(f.fileno()).st_size
    except OSError:
        return  # unreadable: the published rows are the safe side (written again)
    if len(head) == 9 and head[0] == Opcode.CHUNK and \
            size >= at + 9 + int.from_bytes(head[1:], "little"):
        ctrl[FRAMES_FLUSHED], ctrl[TICKS_FLUSHED] = pending


def _start_live(addr: str, fields: dict[str, dict[str, str]]) -> dict[str, Any] | None:
    """A Foxglove WebSocket server on ``addr`` (HOST:PORT) with a channel per topic but the
    raw frames (too many for a screen); None, said in one line, if it cannot start: the
    recording goes on without it. A client that stops reading loses its oldest messages
    (the server's per-client backlog), never this process's time."""
    host, _, port = addr.rpartition(":")
    # The server's threads start now and inherit this thread's policy: idle, always, so a
    # viewer's traffic never competes with the daemon (the main thread's own priority is
    # moved by Recorder.keep_up, which reaches this thread only).
    policy, param = os.sched_getscheduler(0), os.sched_getparam(0)
    try:
        import foxglove

        with contextlib.suppress(OSError):
            os.sched_setscheduler(0, os.SCHED_IDLE, os.sched_param(0))
        foxglove.start_server(name="chest-observer", host=host, port=int(port))
        return {topic: foxglove.Channel(topic, message_encoding="json", schema=foxglove.Schema(
                    name=fmt.TITLES[topic], encoding="jsonschema",
                    data=fmt.json_schema(topic, f)))
                for topic, f in fields.items() if topic != fmt.FRAMES}
    except Exception as e:  # ImportError, address in use, ...: the view is optional
        print(f"observer-node: warning: live view on {addr} not started: {e}", file=sys.stderr,
              flush=True)
        return None
    finally:
        with contextlib.suppress(OSError):
            os.sched_setscheduler(0, policy, param)


FLUSH_S = 0.03  # the writer flushes a chunk this often
CHUNK_BYTES = 64 * 1024  # and when a chunk holds this many message bytes (a writer behind)
LIVE_HZ = 100.0  # per-tick topics reach the live view at about this rate
BOOST_LAG_S = 0.05  # flushed rows this far behind: normal priority
CALM_LAG_S = 0.01  # caught up: idle priority again


def may_raise_priority() -> bool:
    """Whether this process may move another of its own from SCHED_IDLE back to
    SCHED_OTHER at nice 0 (root, CAP_SYS_NICE, or RLIMIT_NICE >= 20)."""
    import resource

    if os.geteuid() == 0 or resource.getrlimit(resource.RLIMIT_NICE)[0] >= 20:
        return True
    with contextlib.suppress(OSError, ValueError):
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("CapEff:"):
                return bool(int(line.split()[1], 16) >> 23 & 1)  # CAP_SYS_NICE
    return False


def create_exclusive(path: Path) -> tuple[Path, int]:
    """Create ``path`` for writing, never over an existing file: a taken name becomes
    ``NAME.1.mcap``, ``NAME.2.mcap``, ... Raises :class:`RecorderError` naming the cause."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise RecorderError(e.errno, f"{path}: cannot create its folder {path.parent}: "
                            f"{e.strerror or e}") from None
    if path.is_dir():
        raise RecorderError(errno_mod.EISDIR, f"{path}: is a directory (give a file name)")
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC
    for k in range(10_000):
        p = path if k == 0 else path.with_name(f"{path.stem}.{k}{path.suffix}")
        try:
            return p, os.open(p, flags, 0o644)
        except FileExistsError:
            continue
        except OSError as e:
            raise RecorderError(e.errno, f"{p}: {e.strerror}") from None
    raise RecorderError(errno_mod.EEXIST, f"{path}: 10,000 numbered recordings exist already")


class Recorder:
    """Owns the rings and the writer process, restarts it into a new part when it dies."""

    def __init__(self, path: str | Path, metadata: dict[str, str],
                 attachments: list[tuple[str, str, bytes]], dbc_path: str | Path,
                 capacity: int = 1 << 16, rows_per_s: float = 1000.0, max_parts: int = 5,
                 restart_after_s: float = 1.0, live: str = ""):
        self.path, fd = create_exclusive(Path(path))
        self.parts = [self.path]
        self.rings = Rings(capacity)
        self.clock = (time.time_ns(), time.perf_counter())
        self._args = (capacity, metadata, attachments, str(dbc_path))
        self._live = (live, max(1, round(rows_per_s / LIVE_HZ)))
        # Writer priority (keep_up): idle while it keeps up, normal while it lags.
        self.can_boost = may_raise_priority()
        self._boost_rows = int(BOOST_LAG_S * rows_per_s)
        self._calm_rows = int(CALM_LAG_S * rows_per_s)
        self._idle = False
        self.boosts = 0
        self.max_parts = max_parts
        self.restart_after_s = restart_after_s
        self.state: RecorderState = RecorderState.RECORDING
        self.errors: list[str] = []
        self._final: tuple[int, int] | None = None  # (frames, ticks) lost, once closed
        self._started = 0.0
        self.put_frame = self.rings.put_frame
        self.put_tick = self.rings.put_tick
        try:
            self._spawn(fd, self.path)
        except OSError as e:  # no process could be started (limits, memory)
            self.rings.close()
            raise RecorderError(e.errno, f"{self.path}: cannot start the recorder process: "
                                f"{e.strerror or e}") from None

    def _spawn(self, fd: int, path: Path) -> None:
        capacity, metadata, attachments, dbc_path = self._args
        ctrl = self.rings.ctrl
        ctrl[READY] = ctrl[DONE] = ctrl[ERRNO] = 0
        # nothing announced yet in this part (durable_tails)
        ctrl[FRAMES_PENDING], ctrl[TICKS_PENDING] = ctrl[FRAMES_FLUSHED], ctrl[TICKS_FLUSHED]
        ctrl[PENDING_AT] = -1
        ctx = mp.get_context("spawn")
        self.proc = ctx.Process(
            target=writer_main, name="chest-observer-recorder", daemon=False,
            args=(_Fd(self.rings.fd), capacity, _Fd(fd), str(path), self.clock, metadata,
                  attachments, dbc_path, FLUSH_S, os.getpid(), *self._live))
        # The child inherits this thread's signal mask: a Ctrl-C during its start-up (before
        # writer_main ignores it) stays pending instead of killing it.
        old_mask = signal.pthread_sigmask(signal.SIG_BLOCK, _GROUP_SIGNALS)
        try:
            self.proc.start()
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, old_mask)
            os.close(fd)  # the child has its own copy
        self._started = time.monotonic()
        self._idle = False

    def wait_ready(self, timeout_s: float = 120.0) -> None:
        """Wait until the writer has the file's header written, however slow the machine;
        raise :class:`RecorderError` with the writer's own reason if it cannot."""
        deadline = time.monotonic() + timeout_s
        ctrl = self.rings.ctrl
        while not ctrl[READY]:
            if not self.proc.is_alive():
                self.proc.join()
                raise RecorderError(int(ctrl[ERRNO]) or errno_mod.EIO, self.rings.error() or
                                    f"{self.path}: the recorder process ended with exit code "
                                    f"{self.proc.exitcode} before writing")
            if time.monotonic() > deadline:
                self._stop_writer()
                raise RecorderError(errno_mod.ETIMEDOUT, f"{self.path}: the recorder process "
                                    f"did not write the file's header within {timeout_s:g} s")
            time.sleep(0.01)

    # ------------------------------------------------------------------ health
    def keep_up(self) -> None:
        """Called every few ms by the tick loop (two reads, a syscall only on a change).
        The writer runs SCHED_IDLE while it keeps up, so a waking daemon preempts it at
        once; when what it has flushed lags ``BOOST_LAG_S`` behind, it gets normal priority
        until it has caught up, so a kill never loses more than ~100 ms. Raising it back
        needs root, CAP_SYS_NICE or RLIMIT_NICE >= 20; without, it stays at normal
        priority: a safe recording comes before the last microseconds of tick latency."""
        if not self.can_boost or not self.rings.ctrl[READY]:
            return
        ctrl = self.rings.ctrl
        lag = int(ctrl[TICKS_HEAD]) - int(ctrl[TICKS_FLUSHED])
        policy = None
        if self._idle and lag > self._boost_rows:
            policy, self._idle = os.SCHED_OTHER, False
            self.boosts += 1
        elif not self._idle and lag < self._calm_rows:
            policy, self._idle = os.SCHED_IDLE, True
        if policy is not None:
            try:
                os.sched_setscheduler(self.proc.pid or 0, policy, os.sched_param(0))
            except OSError:  # gone (poll sees it) or refused: leave it at normal priority
                self.can_boost = self._idle = False

    @property
    def lost_ticks(self) -> int:
        """Ticks that are in no part: overwritten in the rings before a writer drained them,
        or never written after the recording FAILED."""
        return self._final[1] if self._final is not None else \
            self._lost(TICKS_LOST, TICKS_HEAD, TICKS_FLUSHED)

    @property
    def lost_frames(self) -> int:
        return self._final[0] if self._final is not None else \
            self._lost(FRAMES_LOST, FRAMES_HEAD, FRAMES_FLUSHED)

    def _lost(self, lost: int, head: int, flushed: int) -> int:
        ctrl = self.rings.ctrl
        failed = self.state == RecorderState.FAILED
        unwritten = int(ctrl[head] - ctrl[flushed]) if failed else 0
        return int(ctrl[lost]) + unwritten

    @property
    def degraded(self) -> bool:
        """The recording is not the whole run: a writer failed or rows were lost."""
        return self.state != RecorderState.RECORDING or self.lost_ticks > 0 or \
            self.lost_frames > 0

    def poll(self) -> str | None:
        """Check the writer (at the status period, off the per-frame path). A dead writer
        is restarted on a new part; returns a line to log when something happened."""
        if self.state == RecorderState.FAILED or self.proc.is_alive():
            return None
        if self.rings.ctrl[STOP]:
            return None
        ctrl = self.rings.ctrl
        why = self.rings.error() or f"{self.parts[-1]}: the recorder process ended (exit code " \
            f"{self.proc.exitcode})"
        if not self.errors or self.errors[-1] != why:
            self.errors.append(why)
        if len(self.parts) >= self.max_parts:
            return self._fail(why, f"{len(self.parts)} parts written")
        if not ctrl[READY]:  # it could not even write a header: another would not either
            return self._fail(why, self._drop_unstarted_part())
        if time.monotonic() - self._started < self.restart_after_s:
            return None  # a writer that dies at once is not restarted in a spin
        base = self.parts[0]
        part = base.with_name(f"{base.stem}.part{len(self.parts) + 1}{base.suffix}")
        try:
            part, fd = create_exclusive(part)
        except RecorderError as e:
            return self._fail(why, str(e))
        self.proc.join()
        durable_tails(ctrl, self.parts[-1])  # the successor starts after what is in it
        self.parts.append(part)
        self.state = RecorderState.RESTARTED
        ctrl[STOP] = 0
        self._spawn(fd, part)
        return f"recorder: {why}; recording goes on in {part}"

    def _drop_unstarted_part(self) -> str:
        """A restarted part whose writer never wrote its header holds no row (rows are
        announced only after it): removed, so no empty or header-less file is left beside
        the recording; the first part is the caller's to keep or remove."""
        part = self.parts[-1]
        if len(self.parts) == 1:
            return f"{part} could not be started"
        try:
            part.unlink()
        except OSError as e:
            return f"{part} could not be started, and not removed: {e.strerror or e}"
        self.parts.pop()
        return f"{part} could not be started; removed, it held nothing"

    def _fail(self, why: str, detail: str) -> str:
        self.proc.join()
        durable_tails(self.rings.ctrl, self.parts[-1])  # what is lost starts after the file
        self.state = RecorderState.FAILED
        return f"recorder: {why}; recording stopped ({detail}), estimates go on unrecorded"

    def _stop_writer(self, timeout_s: float = 30.0) -> None:
        self.rings.ctrl[STOP] = 1
        if self._idle and self.proc.pid:
            # Left at SCHED_IDLE, a writer on a busy machine gets next to no CPU and missed
            # the timeout: killed, its file without a footer. Nobody waits on ticks now.
            with contextlib.suppress(OSError):
                os.sched_setscheduler(self.proc.pid, os.SCHED_OTHER, os.sched_param(0))
            self._idle = False
        self.proc.join(timeout_s)
        if self.proc.is_alive():
            self.proc.kill()  # it ignores SIGTERM
            self.proc.join(5)

    def close(self, timeout_s: float = 30.0, discard: bool = False) -> str | None:
        """Stop after everything written so far is in the file, and finish it. ``discard``:
        the run never started (the bus did not open), remove the files. Returns a line to
        log when the last writer failed."""
        if self._final is not None:
            return None
        self._stop_writer(timeout_s)
        if discard:
            for p in self.parts:
                with contextlib.suppress(OSError):
                    p.unlink()
        said = None
        if self.proc.exitcode != 0:
            durable_tails(self.rings.ctrl, self.parts[-1])
        if self.proc.exitcode != 0 and self.state != RecorderState.FAILED:
            why = self.rings.error() or f"{self.parts[-1]}: the recorder process ended " \
                f"(exit code {self.proc.exitcode})"
            self.errors.append(why)
            said = self._fail(why, "at the end of the run")
        # What no writer flushed is lost (a failed writer, or one killed on close).
        self._final = (self.lost_frames, self.lost_ticks)
        self.rings.close()
        return said
