"""Replay sources, each turned into a :class:`Schedule` before anything is sent, so that a bad
source is an error naming the file and the place, never a half-played run.

- an ISO-MME test (folder, ``.mme`` or ``.zip``) or a CSV crash test: resampled to the bus
  rate and encoded with the DBC (:mod:`observer_node.replay.schedule`);
- an MCAP recording of ``observer-node run``: its raw frames (``/can/frames``) with their
  recorded timing; by default the frames the daemon received, so a run replays exactly; one
  made with another DBC (before the AUTOSAR E2E profiles, say) is translated into this one's;
- python-can logs: candump ``-L`` (``.log``, parsed here with line numbers), ASC, BLF, TRC.
"""

from __future__ import annotations

import gc
import logging
import re
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np

from observer_node.data import ChannelCodes, CrashDataError, find_tests, load_test
from observer_node.dbc import Codec
from observer_node.errors import ObserverError, UsageError

from .schedule import Schedule, check_window, crash_test_schedule, restamp_counters


class SourceError(ObserverError, ValueError):
    """A replay source that cannot be played; the message names the file and place."""


# (timestamp) interface id#data, optionally followed by a direction flag (python-can: R/T)
_CANDUMP = re.compile(r"^\((\d+(?:\.\d+)?)\)\s+(\S+)\s+([0-9A-Fa-f]{1,8})#(R?)([0-9A-Fa-f]*)"
                      r"(?:\s+[RT])?\s*$")
_CANDUMP_FD = re.compile(r"^\((\d+(?:\.\d+)?)\)\s+(\S+)\s+([0-9A-Fa-f]{1,8})##([0-9A-Fa-f])"
                         r"([0-9A-Fa-f]*)(?:\s+[RT])?\s*$")


def read_candump(path: Path) -> Schedule:
    times, ids, data = [], [], []
    for n, line in enumerate(path.read_text(encoding="ascii", errors="replace").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        m = _CANDUMP.match(line) or _CANDUMP_FD.match(line)
        payload = m.group(5) if m else ""
        if not m or len(payload) % 2 or len(payload) > 128:
            raise SourceError(f"{path}:{n}: not a candump -L line: {line.strip()[:80]!r}")
        times.append(float(m.group(1)))
        ids.append(int(m.group(3), 16))
        data.append(bytes.fromhex(payload))
    if not data:
        raise SourceError(f"{path}: no frames")
    t = np.array(times)
    if np.any(np.diff(t) < 0):
        k = int(np.argmax(np.diff(t) < 0)) + 2
        raise SourceError(f"{path}: frame {k}: timestamps go backwards")
    return Schedule(t - t[0], np.array(ids), data, path.name)


# Logs read through python-can (MF4 through asammdf, python-can's mf4 extra)
PYTHON_CAN_LOGS = (".asc", ".blf", ".trc", ".mf4")


def read_python_can_log(path: Path, all_frames: bool = False) -> Schedule:
    """Frames of an ASC, BLF, TRC or MF4 log; only those received by the logging node unless
    ``all_frames`` (in the formats that keep the direction). A log cut short or with a record
    python-can cannot parse is refused, as a truncated MCAP is: python-can itself logs such a
    record and goes on, so a cut log would replay part of a test unsaid."""
    import can

    if path.suffix.lower() == ".mf4":
        try:
            import asammdf  # noqa: F401
        except ImportError:
            raise SourceError(f"{path}: reading MDF4 needs asammdf: pip install "
                              "'chest-observer[mf4]'") from None
    times, ids, data = [], [], []
    sent_t: list[float] = []  # left out as sent by the logging node: named if nothing
    sent_ids: list[int] = []  # else is left, and when --only asks for one of them
    said = _Said()
    can_log = logging.getLogger("can")
    can_log.addHandler(said)
    propagate, can_log.propagate = can_log.propagate, False  # its lines become our one line
    try:
        with can.LogReader(str(path)) as reader:
            for m in reader:
                if m.is_error_frame or m.is_remote_frame:
                    continue
                if not (m.is_rx or all_frames):
                    sent_t.append(m.timestamp)
                    sent_ids.append(m.arbitration_id)
                    continue
                times.append(m.timestamp)
                ids.append(m.arbitration_id)
                data.append(bytes(m.data))
        why = said.first or _cut_short(path, reader)
    except Exception as e:  # python-can raises many kinds on bad logs
        why = f"{type(e).__name__}: {e}"
    finally:
        can_log.removeHandler(said)
        can_log.propagate = propagate
    if why:
        _collect_quietly()
        raise SourceError(f"{path}: truncated or corrupt after {len(data)} frames ({why})")
    if not data:
        raise SourceError(f"{path}: no frames" + _only_sent(len(sent_t)))
    t = np.array(times)
    return Schedule(t - t[0], np.array(ids), data, path.name,
                    sent=(np.array(sent_t, float) - t[0], np.array(sent_ids, np.int64)))


def _only_sent(sent: int) -> str:
    """What a log of the logging node's own frames only is missing, and the option for it."""
    return (f" received by the logging node, only {sent} it sent: --all-frames replays those"
            if sent else "")


class _Said(logging.Handler):
    """The first warning python-can logged (a record it could not parse and skipped)."""

    def __init__(self) -> None:
        super().__init__(logging.WARNING)
        self.first = ""

    def emit(self, record: logging.LogRecord) -> None:
        self.first = self.first or " ".join(record.getMessage().split())[:120]


def _cut_short(path: Path, reader: object) -> str:
    """Why the log ends early, or "": a BLF shorter than its header says, a text log whose
    last line is cut, an ASC without its closing line."""
    size = path.stat().st_size
    said_size = getattr(reader, "file_size", 0)  # a BLF's header, written when it was closed
    if said_size > size:
        return f"{size} of the {said_size} bytes its header gives"
    suffix = path.suffix.lower()
    if suffix in (".asc", ".trc"):
        with path.open("rb") as f:
            f.seek(max(0, size - 200))
            tail = f.read()
        if tail and not tail.endswith(b"\n"):
            return "the last line is cut"
        if suffix == ".asc" and b"end triggerblock" not in tail.lower():
            return "no 'End TriggerBlock' line"
    return ""


def _collect_quietly() -> None:
    """Collect a reader that failed half-way now, quietly: asammdf's MDF4 raises again in
    its ``__del__`` ("Exception ignored in ..."), a traceback after our one line."""
    hook = sys.unraisablehook
    sys.unraisablehook = lambda _: None
    try:
        gc.collect()
    finally:
        sys.unraisablehook = hook


def read_mcap_frames(path: Path, all_frames: bool = False, codec: Codec | None = None
                     ) -> Schedule:
    """The frames a recording's daemon received (``all_frames``: and sent), with their
    recorded times; errors name the file. With ``codec``: a recording made with another DBC
    (its own is attached) has its frames translated signal by signal into ``codec``'s layout
    and E2E protection, so recordings from before a DBC change still replay."""
    from observer_node.recording import RecordingError, Scan
    from observer_node.recording import format as fmt

    times, ids, data = [], [], []
    sent_t: list[float] = []
    sent_ids: list[int] = []
    translate = None
    try:
        scan = Scan(path)
        for topic, _, raw in scan:
            if topic == "#attachment":
                name, blob = raw
                if name == fmt.ATT_DBC and codec is not None:
                    translate = _translator(bytes(blob), codec)
                continue
            if topic != fmt.FRAMES:
                continue
            fr = fmt.read_frame(raw)
            if fr.error:
                continue
            if fr.tx and not all_frames:
                sent_t.append(fr.t)
                sent_ids.append(fr.can_id)
                continue
            times.append(fr.t)
            ids.append(fr.can_id)
            data.append(translate(fr.can_id, fr.data) if translate else fr.data)
    except RecordingError as e:
        raise SourceError(str(e)) from None
    except (ValueError, KeyError, TypeError) as e:
        raise SourceError(f"{path}: a {fmt.FRAMES} message that is not a frame "
                          f"({type(e).__name__}: {e})") from None
    if scan.salvaged:
        raise SourceError(f"{path}: truncated or corrupt MCAP after {len(data)} frames "
                          f"({scan.note})")
    if not data:
        raise SourceError(f"{path}: " + (f"no frames{_only_sent(len(sent_t))}" if sent_t else
                                         f"no {fmt.FRAMES} messages (not a chest-observer "
                                         "recording?)"))
    order = np.argsort(np.array(times), kind="stable")
    t = np.array(times)[order]
    s = Schedule(t - t[0], np.array(ids)[order], [data[i] for i in order], path.name,
                 sent=(np.array(sent_t, float) - t[0], np.array(sent_ids, np.int64)))
    # Translated frames carry the new profile's CRC; their counters are renumbered per ID
    # (the old ones may run past the new profile's range).
    return restamp_counters(s, codec) if translate and codec is not None else s


def _translator(old_dbc: bytes, codec: Codec) -> Callable[[int, bytes], bytes] | None:
    """None when the recording was made with ``codec``'s DBC; else a function re-encoding a
    frame of the old DBC's layout (by signal name) in ``codec``'s."""
    if old_dbc == codec.path.read_bytes():
        return None
    with tempfile.TemporaryDirectory() as tmp:
        old_path = Path(tmp) / "recorded.dbc"
        old_path.write_bytes(old_dbc)
        try:
            old = Codec(old_path)
        except Exception as e:  # a DBC this codec cannot compile: replay the frames as they are
            raise SourceError(f"the recording's own DBC cannot be read ({e}); replay it with "
                              "the DBC it was made with") from None
    pairs = {cid: (fc, codec.by_id[cid]) for cid, fc in old.by_id.items()
             if cid in codec.by_id and codec.by_id[cid].name == fc.name}

    def translate(cid: int, data: bytes) -> bytes:
        pair = pairs.get(cid)
        if pair is None or len(data) != pair[0].length:
            return data
        return pair[1].encode(pair[0].decode(data))

    return translate


# What a source can be, for the error on a file of another kind
KINDS = ("an ISO-MME test (folder, .mme or .zip), a .csv crash test, a folder of tests, "
         "campaign-a[/PATTERN], an .mcap recording, or a .log/.asc/.blf/.trc/.mf4 bus log")
TEST_FILES = (".zip", ".csv", ".mme")  # a crash test in one file (the rest are folders)


def load_source(path: str | Path, codec: Codec, rate_hz: float = 1000.0,
                reference: bool = False, start_s: float | None = None,
                end_s: float | None = None, pre_s: float = 0.2,
                codes: ChannelCodes | None = None, counts_per_rev: int | None = None,
                all_frames: bool = False, burst: bool = False) -> list[Schedule]:
    """Schedules for one source path (a folder of tests gives one schedule per test).
    ``burst``: lab data as InputBurst FD frames (eight samples each)."""
    p = Path(path)
    suffix = p.suffix.lower()
    try:
        if suffix in (".mcap", ".log", *PYTHON_CAN_LOGS):
            if p.is_dir():
                raise SourceError(f"{p}: is a folder, not a {suffix} file")
            if not p.is_file():
                raise SourceError(f"{p}: no such file")
        elif p.exists() and not p.is_dir() and suffix not in TEST_FILES:
            raise SourceError(f"{p}: not a source crash-replay reads: {KINDS}")
        if suffix == ".mcap":
            return [_window(read_mcap_frames(p, all_frames, codec), start_s, end_s)]
        if suffix == ".log":
            return [_window(read_candump(p), start_s, end_s)]
        if suffix in PYTHON_CAN_LOGS:
            return [_window(read_python_can_log(p, all_frames), start_s, end_s)]
        tests = [load_test(t, codes, counts_per_rev, require_outputs=reference)
                 for t in find_tests([str(path)])]  # a test, a folder, or campaign-a[/PATTERN]
    except CrashDataError as e:
        raise SourceError(str(e)) from None
    return [crash_test_schedule(t, codec, rate_hz, reference and t.has_outputs,
                                start_s=start_s, end_s=end_s, pre_s=pre_s, burst=burst)
            for t in tests]


def _window(s: Schedule, start_s: float | None, end_s: float | None) -> Schedule:
    check_window(s.source, s.t_s, start_s, end_s)  # times from the log's first frame
    def inside(t: np.ndarray) -> np.ndarray:
        keep = np.ones(len(t), bool)
        if start_s is not None:
            keep &= t >= start_s
        if end_s is not None:
            keep &= t <= end_s
        return keep
    return s.within(inside(s.t_s), inside(s.sent[0]))


def filter_remap(s: Schedule, only: set[int] | None, remap: dict[int, int],
                 warn: Callable[[str], None] | None = None) -> Schedule:
    """The frames of the IDs in ``only`` (all if None), with the IDs in ``remap`` renamed. A
    remap that would send two IDs' frames under one is an error (a receiver could not tell
    them apart); ``warn`` hears of --only and --remap IDs that match no frame."""
    if only is not None:
        s = s.only(only)
    sent = set(s.ids.tolist())
    if warn is not None:
        for cid in sorted((only or set()) - sent):
            warn(f"--only 0x{cid:X}: " + ("only the logging node sent that ID: --all-frames "
                                          "replays its frames" if cid in s.sent_ids
                                          else "no frames of that ID in the sources"))
        for cid in sorted(remap.keys() - sent):
            warn(f"--remap 0x{cid:X}=0x{remap[cid]:X}: no frames of 0x{cid:X} are sent")
    by_new: dict[int, int] = {}
    for cid in sorted(sent):
        new = remap.get(cid, cid)
        other = by_new.setdefault(new, cid)
        if other != cid:
            moved, kept = (cid, other) if cid != new else (other, cid)
            why = (f"the sources send 0x{new:X} already" if kept == new
                   else f"0x{kept:X} goes out as 0x{new:X} too")
            raise UsageError(f"--remap 0x{moved:X}=0x{new:X}: {why}; the two would mix")
    ids = np.array([remap.get(cid, cid) for cid in s.ids.tolist()], dtype=np.int64)
    return Schedule(s.t_s, ids, s.data, s.source)
