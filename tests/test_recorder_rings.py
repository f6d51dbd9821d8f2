"""The recorder's shared-memory rings: the writer process must see every row once.

A ring's head is published after its row; the writer drains up to the head it reads. A head
read half-written (a torn store) looked smaller than the last one, the writer moved back and
wrote rows a second time: on vcan0 under load, 895 InputBurst frames in a recording of 525.
"""

from __future__ import annotations

import json
import multiprocessing as mp
import time
from pathlib import Path

from observer_node.dbc import Codec
from observer_node.recording import format as fmt
from observer_node.recording.reader import Scan
from observer_node.recording.writer import FRAMES_HEAD, TICKS_HEAD, Recorder, Rings

STORES = 2_000_000  # struct.pack_into's heads: 1 torn read in 1M of these, 1446 in 3M bare stores


def _watch_heads(fd: int, capacity: int, stores: int, out: mp.Queue) -> None:
    rings = Rings(capacity, fd)
    last = backwards = 0
    while last < stores:
        head = int(rings.ctrl[TICKS_HEAD])
        backwards += head < last
        last = max(last, head)
    out.put(backwards)


def test_a_reader_never_sees_a_head_go_back():
    ctx = mp.get_context("fork")
    rings = Rings(capacity=1024)
    out: mp.Queue = ctx.Queue()
    reader = ctx.Process(target=_watch_heads, args=(rings.fd, 1024, STORES, out))
    reader.start()
    try:
        time.sleep(0.2)  # the reader is polling
        row = (0.0,) * rings.ticks.shape[1]
        for _ in range(STORES):
            rings.put_tick(row)
        assert out.get(timeout=60) == 0
    finally:
        reader.join(10)
        rings.close()


def test_the_writer_never_writes_a_row_twice_when_a_head_seems_to_go_back(tmp_path: Path):
    codec = Codec()
    rec = Recorder(tmp_path / "run.mcap", {"software_version": "test"}, [], codec.path)
    rec.wait_ready()
    acc = codec["TunnelAccel"]
    for k in range(300):
        rec.put_frame(float(k), acc.frame_id, acc.encode({"TunnelAccelX": 0.0}, k), 0)
    time.sleep(0.2)  # drained
    ctrl = rec.rings.ctrl
    ctrl[FRAMES_HEAD] = 5  # what a torn read of 300 could look like
    time.sleep(0.1)  # the writer polls every 5 ms when idle
    ctrl[FRAMES_HEAD] = 300
    for k in range(300, 400):
        rec.put_frame(float(k), acc.frame_id, acc.encode({"TunnelAccelX": 0.0}, k), 0)
    rec.close()
    frames = [json.loads(m) for topic, _, m in Scan(tmp_path / "run.mcap")
              if topic == fmt.FRAMES]
    assert [f["data"] for f in frames] == [acc.encode({"TunnelAccelX": 0.0}, k).hex()
                                           for k in range(400)]


def _hog() -> None:
    while True:
        pass


def test_a_writer_at_idle_priority_finishes_the_file_at_close_beside_busy_processes(
        tmp_path: Path):
    """The writer runs SCHED_IDLE while it keeps up. Closed like that on a busy machine, it
    got almost no CPU: under load average 8-13 the bench's writers missed the 30 s close
    timeout and were killed, each file without its footer. The close must give it normal
    priority first."""
    import os

    import pytest
    from mcap.reader import make_reader

    codec = Codec()
    rec = Recorder(tmp_path / "run.mcap", {"software_version": "test"}, [], codec.path)
    rec.wait_ready()
    if not rec.can_boost:
        rec.close()
        pytest.skip("may not raise a process from SCHED_IDLE here (needs CAP_SYS_NICE)")
    pid = rec.proc.pid
    assert pid is not None
    rec.keep_up()  # nothing lags: the writer goes idle
    assert os.sched_getscheduler(pid) == os.SCHED_IDLE
    # Three busy processes and the writer on one core: a nice-0 process gets a third of it,
    # an idle one next to nothing.
    cpu = min(os.sched_getaffinity(0))
    os.sched_setaffinity(pid, {cpu})
    ctx = mp.get_context("fork")
    hogs = [ctx.Process(target=_hog, daemon=True) for _ in range(3)]
    for h in hogs:
        h.start()
        assert h.pid is not None
        os.sched_setaffinity(h.pid, {cpu})
    acc = codec["TunnelAccel"]
    n = 3000
    try:
        for k in range(n):
            rec.put_frame(float(k), acc.frame_id, acc.encode({"TunnelAccelX": 0.0}, k % 256), 0)
        said = rec.close(timeout_s=10.0)
    finally:
        for h in hogs:
            h.kill()
            h.join()
    assert said is None and rec.proc.exitcode == 0, said
    with (tmp_path / "run.mcap").open("rb") as f:  # the footer and summary are there
        summary = make_reader(f).get_summary()
    assert summary is not None and summary.statistics is not None
    assert rec.lost_frames == 0
    frames = [m for topic, _, m in Scan(tmp_path / "run.mcap") if topic == fmt.FRAMES]
    assert len(frames) == n


def _writer_whose_disk_fails_at_write_back(*args: object) -> None:
    """The writer as Recorder spawns it, on a disk whose write-back fails (a failing disk,
    a full NFS share): the data reached the page cache, the disk refuses it at fsync."""
    import errno
    import os

    from observer_node.recording import writer as wr

    def fail(fd: int) -> None:
        raise OSError(errno.EIO, os.strerror(errno.EIO))
    wr.os.fsync = fail  # type: ignore[attr-defined]
    wr.writer_main(*args)  # type: ignore[arg-type]


def test_a_write_back_error_at_the_end_is_said_not_swallowed(tmp_path: Path):
    """The file written and finished in the page cache is not yet recorded: the writer syncs
    it, and an error there ends it with exit code 1 and the file's name and the cause in the
    error slot, so the daemon says the recording is not whole (exit code 3)."""
    import os

    from observer_node.recording import writer as wr

    codec = Codec()
    rings = Rings(64)
    rings.ctrl[wr.STOP] = 1  # start, write the header, finish at once
    path = tmp_path / "run.mcap"
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
    proc = mp.get_context("spawn").Process(
        target=_writer_whose_disk_fails_at_write_back,
        args=(wr._Fd(rings.fd), 64, wr._Fd(fd), str(path), (time.time_ns(), time.perf_counter()),
              {"software_version": "test"}, [], str(codec.path), 0.05, os.getpid()))
    proc.start()
    os.close(fd)
    proc.join(60)
    assert proc.exitcode == 1
    assert rings.ctrl[wr.ERRNO] == 5 and rings.error() == f"{path}: Input/output error"
    rings.close()
