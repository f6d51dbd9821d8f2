"""The recording under faults (issue 20): what other tools read in it (strict JSON against
the declared schemas), every tick in exactly one part across writer kills, and a recorder
that finishes its file when Ctrl-C or a SIGTERM reaches the whole process group."""

from __future__ import annotations

import json
import math
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import jsonschema
import pytest

from observer_node.daemon.harness import CODEC, Harness
from observer_node.recording import read_recording

ROOT = Path(__file__).resolve().parents[1]
ACC, BRS = CODEC["TunnelAccel"], CODEC["BeltSpindle"]


def _feed(h: Harness, ticks: range, accel_g: float = 0.0) -> None:
    for k in ticks:
        h.send(BRS.frame_id, BRS.encode({"BrsCount": 0, "BrsCountsPerRev": 96}, k))
        h.send(ACC.frame_id, ACC.encode({"TunnelAccelX": accel_g}, k))
        time.sleep(0.001)


def _strict(text: bytes) -> dict:
    """JSON as JSON.parse reads it: NaN, Infinity and -Infinity are not JSON."""
    def refuse(name: str) -> None:
        raise ValueError(f"{name} is not JSON")
    return json.loads(text, parse_constant=refuse)


def _messages_with_schemas(path: Path) -> list[tuple[str, dict, dict]]:
    """(topic, schema, message) of every message, by the mcap library's own reader."""
    from mcap.reader import make_reader

    out = []
    with path.open("rb") as f:
        for schema, channel, message in make_reader(f).iter_messages():
            out.append((channel.topic, _strict(schema.data), _strict(message.data)))
    return out


def test_every_message_is_strict_json_valid_against_its_schema(model, tmp_path):
    """Watchdog publishes (the accelerometer silent between ticks) have no accelerometer
    value: the field is left out, never written as NaN, which JSON.parse (and so Foxglove)
    refuses. Every message of every topic validates against the schema its channel
    declares."""
    path = tmp_path / "run.mcap"
    with Harness(model, "strictjson", record=path) as h:
        _feed(h, range(200))
        time.sleep(0.1)  # ~100 watchdog publishes
        _feed(h, range(200, 260))
        assert h.settle()  # a loaded machine runs the node late: leaving would cut it short
    msgs = _messages_with_schemas(path)
    topics = {t for t, _, _ in msgs}
    assert {"/observer/inputs", "/observer/estimate", "/can/frames",
            "/observer/status"} <= topics
    watchdog = [m for t, _, m in msgs if t == "/observer/inputs" and m["tick"] == -1]
    assert len(watchdog) > 10  # the rows that carried NaN
    assert all("accel_x_g" not in m for m in watchdog)
    for _topic, schema, m in msgs:
        jsonschema.validate(m, schema)
    # our own reader still has every tick, with its accelerometer value
    rec = read_recording(path)
    assert rec.ticks["tick"].tolist() == list(range(h.node.counters.ticks))
    assert h.node.counters.ticks > 250
    assert all(math.isfinite(v) for v in rec.ticks["accel_x_g"])


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_to_the_process_group_finishes_the_recording(model_path, tmp_path, sig):
    """Ctrl-C in a terminal and systemd's stop signal the whole process group, the recorder
    process too: it ignores them and finishes the file on the daemon's stop, so the file
    has its footer (read by the mcap library's seeking reader) and the exit code is 0."""
    from mcap.reader import make_reader

    path = tmp_path / "run.mcap"
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "run", "--interface",
                          "virtual", "--channel", "pgroup", "--model", str(model_path),
                          "--record", str(path), "--cpu-latency-us", "-1"],
                         cwd=ROOT, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        line = p.stderr.readline()  # the start-up line: the recorder has written the header
        assert "listening on virtual:pgroup" in line, line
        time.sleep(0.5)  # status frames: a few chunks
        os.killpg(p.pid, sig)
        _, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
    assert p.returncode == 0, err
    with path.open("rb") as f:
        reader = make_reader(f)
        summary = reader.get_summary()
        assert summary is not None and summary.statistics is not None
        assert summary.statistics.message_count > 0
        names = [m.name for m in reader.iter_metadata()]
    assert "chest-observer-recorder" in names  # the writer's own end record
    with path.open("rb") as f:  # and the file ends as an MCAP file does: footer, magic
        f.seek(-8, os.SEEK_END)
        assert f.read() == b"\x89MCAP0\r\n"


def _part_ticks(path: Path) -> list[int]:
    """Tick indices of every estimate message in one part, repeats included (a part cut
    before its first chunk holds none)."""
    from observer_node.recording.reader import Scan

    return [m["tick"] for topic, _, data in Scan(path) if topic == "/observer/estimate"
            for m in (json.loads(data),) if m["tick"] >= 0]


def test_every_tick_in_exactly_one_part_across_writer_kills(model, tmp_path, monkeypatch):
    """Writer killed, then its successor killed after it has written chunks of its own
    between two published flushes (the second writer flushes every 10 s here: whatever its
    file holds, the mcap library wrote on its own). The third goes on from what is durably
    in the files: no tick in two parts, none missing."""
    from observer_node.recording import writer

    h = Harness(model, "parts", record=tmp_path / "run.mcap")
    # the harness's thread ends after 0.3 s without input: longer here, for the pauses
    h.thread = threading.Thread(target=h.node.run, kwargs={"idle_exit_s": 5.0})
    with h:
        rec = h.node.recorder
        rec.restart_after_s = 0.0
        _feed(h, range(300))
        time.sleep(0.1)
        monkeypatch.setattr(writer, "FLUSH_S", 10.0)  # the next writer: no flush of its own
        os.kill(rec.proc.pid, signal.SIGKILL)
        deadline = time.monotonic() + 30
        k = 300  # one alive counter after another: a repeated one would be a fault
        while (len(rec.parts) < 2 or not rec.rings.ctrl[writer.READY]) and \
                time.monotonic() < deadline:
            _feed(h, range(k, k + 5))
            k += 5
        assert len(rec.parts) == 2
        _feed(h, range(k, k + 1500))  # ~1 MB of messages: the old writer wrote 64 KiB chunks
        k += 1500
        time.sleep(0.2)
        monkeypatch.setattr(writer, "FLUSH_S", 0.03)
        assert rec.proc.is_alive(), rec.errors
        os.kill(rec.proc.pid, signal.SIGKILL)
        _feed(h, range(k, k + 600))
        k += 600
        assert h.settle()
        time.sleep(0.3)  # the writer's restart
    assert len(rec.parts) == 3 and not h.node.recorder.lost_ticks
    per_part = [_part_ticks(p) for p in rec.parts]
    everything = sorted(t for ticks in per_part for t in ticks)
    assert h.node.counters.ticks == k and h.node.counters.lost == 0
    assert everything == list(range(k)), [
        (len(t), min(t, default=None), max(t, default=None)) for t in per_part]


@pytest.mark.parametrize("cut", ["none", "in_chunk", "after_chunk"])
def test_a_kill_between_a_chunk_and_its_publication_neither_repeats_nor_drops(tmp_path, cut):
    """The writer announces a flush (rows, offset), writes the chunk, then publishes it. Killed
    after the chunk reached the file but before it was published, its successor must start
    after the chunk's rows; killed inside the chunk, from the last published rows."""
    from mcap.writer import Writer

    from observer_node.recording import writer as wr
    from observer_node.recording.reader import Scan

    rings = wr.Rings(capacity=64)
    ctrl = rings.ctrl
    path = tmp_path / "part.mcap"
    with path.open("wb") as f:
        w = Writer(f, chunk_size=wr._NO_CHUNK)
        w.start(profile="", library="test")
        w.add_metadata("chest-observer", {})
        cid = w.register_channel("/observer/estimate", "json",
                                 w.register_schema("s", "jsonschema", b"{}"))
        w.flush()
        ctrl[wr.FRAMES_FLUSHED], ctrl[wr.TICKS_FLUSHED] = 5, 7  # the last publication
        for k in range(7, 17):
            w.add_message(cid, k, json.dumps({"tick": k}).encode(), k)
        # the announcement, the chunk written, then killed before the publication
        ctrl[wr.PENDING_AT] = at = f.tell()
        ctrl[wr.FRAMES_PENDING], ctrl[wr.TICKS_PENDING] = 5, 17
        w.flush()
        end_of_chunk = at + 9 + int.from_bytes(path.read_bytes()[at + 1:at + 9], "little")
    if cut == "in_chunk":
        os.truncate(path, end_of_chunk - 1)
    elif cut == "after_chunk":  # the chunk whole, its message indexes cut
        os.truncate(path, end_of_chunk + 3)
    wr.durable_tails(ctrl, path)
    in_file = [json.loads(d)["tick"] for t, _, d in Scan(path) if t == "/observer/estimate"]
    # the successor starts at the published tick row: right after the last one in the file
    assert int(ctrl[wr.TICKS_FLUSHED]) == 7 + len(in_file)
    assert int(ctrl[wr.FRAMES_FLUSHED]) == 5
    assert len(in_file) == (0 if cut == "in_chunk" else 10)
    rings.close()
