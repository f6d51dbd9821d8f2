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
import time
from pathlib import Path

import jsonschema
import pytest

from observer_node.recording import read_recording

from .daemon_feed import CODEC, Harness

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
