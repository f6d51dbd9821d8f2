"""The live view: a WebSocket client subscribed during a run receives the recording's
estimate messages, decimated, with the values the MCAP holds."""

from __future__ import annotations

import json
import re
import socket
import struct
import threading
import time
from pathlib import Path

import pytest

from observer_node.daemon.harness import CODEC, Harness, r16_schedule
from observer_node.recording import format as fmt
from observer_node.recording import read_recording

pytest.importorskip("foxglove")
ws_client = pytest.importorskip("websockets.sync.client")
ws_exceptions = pytest.importorskip("websockets.exceptions")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _free_run(h: Harness) -> Harness:
    """``h`` with its daemon running until stopped: the harness's idle exit would end a run
    whose loop was only starved of CPU on a loaded machine."""
    h.thread = threading.Thread(target=h.node.run)
    return h


def _wait(cond, timeout_s: float) -> bool:
    deadline = time.monotonic() + timeout_s
    while not cond():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.02)
    return True


def test_a_live_client_receives_the_recorded_estimates(model, tmp_path):
    """Every tenth tick's estimate reaches a subscribed client, each once and as the MCAP
    holds it. The server runs at idle priority, so on a busy machine it may deliver late:
    the run is held open until the client has them all (a generous bound), never cut at a
    fixed time. (How many arrive within a fixed time: benchmarks/on_time.py.)"""
    port = _free_port()
    record = tmp_path / "run.mcap"
    status_topic = fmt.STATUS_TOPICS["ObserverStatus"]
    got: list[dict] = []
    statuses = [0]
    done = threading.Event()
    sched = r16_schedule()
    n_ticks = int((sched.ids == CODEC["TunnelAccel"].frame_id).sum())
    last = (n_ticks - 1) // 10 * 10  # the last tick the live view carries (ticks from 0)

    def client() -> None:
        with ws_client.connect(f"ws://127.0.0.1:{port}", subprotocols=["foxglove.sdk.v1"],
                               open_timeout=60) as ws:
            channels: dict[str, dict] = {}
            while fmt.ESTIMATE not in channels or status_topic not in channels:
                msg = json.loads(ws.recv(timeout=60))
                if msg["op"] == "advertise":
                    channels.update({c["topic"]: c for c in msg["channels"]})
            est = channels[fmt.ESTIMATE]
            schema = json.loads(est["schema"])
            assert set(schema["properties"]) == set(fmt.TOPIC_FIELDS[fmt.ESTIMATE])
            ws.send(json.dumps({"op": "subscribe", "subscriptions": [
                {"id": 1, "channelId": est["id"]},
                {"id": 2, "channelId": channels[status_topic]["id"]}]}))
            while not done.is_set():
                try:
                    m = ws.recv(timeout=0.2)
                except TimeoutError:
                    continue
                except ws_exceptions.ConnectionClosed:
                    return  # the run ended
                if isinstance(m, bytes) and m[0] == 1:
                    _, sub, _ = struct.unpack_from("<BIQ", m)
                    if sub == 1:
                        got.append(json.loads(m[13:]))
                    else:
                        statuses[0] += 1

    # The watchdog (receipt times) out of play: a stall of a busy machine would look like a
    # silent sensor; its own tests cover it.
    with _free_run(Harness(model, "live", record, live=f"127.0.0.1:{port}",
                           accel_timeout_s=60.0, brs_timeout_s=60.0)) as h:
        reader = threading.Thread(target=client)
        reader.start()
        # The protocol does not acknowledge a subscription: status frames (10 Hz from the
        # start) arriving on it show the server has taken it, before any tick is sent.
        assert _wait(lambda: statuses[0] >= 2, 120), "no status on the live view"
        h.play(sched)
        assert _wait(lambda: h.node.core.tick_index >= n_ticks - 1, 120), "ticks not processed"
        _wait(lambda: any(m["tick"] == last for m in got), 120)
        done.set()
        reader.join(30)
    rec = read_recording(record)
    rows = {int(t): k for k, t in enumerate(rec.ticks["tick"])}
    want = [int(t) for t in rec.ticks["tick"] if t >= 0 and int(t) % 10 == 0]
    assert want[-1] == last
    ticks = [m["tick"] for m in got]
    assert sorted(ticks) == want, (len(ticks), len(want), sorted(set(want) - set(ticks))[:5])
    for m in got:
        k = rows[m["tick"]]
        assert m["cr_g"] == rec.ticks["cr_g"][k] and m["cd_mm"] == rec.ticks["cd_mm"][k]
        assert m["running"] == bool(rec.ticks["running"][k])
    assert any(m["running"] and m["cd_mm"] > 5 for m in got)  # the crash was seen live


def test_which_websocket_subprotocols_the_live_view_accepts(model, tmp_path):
    """foxglove-sdk's server speaks the Foxglove WebSocket protocol under the name
    ``foxglove.sdk.v1`` only (hard-coded in its handshake): a client offering it, alone or
    beside the older ``foxglove.websocket.v1``, connects and is sent the server's info; one
    offering only ``foxglove.websocket.v1`` (ws-protocol's clients, older viewers), or none,
    gets HTTP 400. Checked with the websockets package, no Foxglove code."""
    port = _free_port()
    url = f"ws://127.0.0.1:{port}"
    with Harness(model, "live-proto", tmp_path / "run.mcap", live=f"127.0.0.1:{port}"):
        for _ in range(600):  # the server starts with the recorder process
            try:
                with ws_client.connect(url, subprotocols=["foxglove.sdk.v1"], open_timeout=5):
                    break
            except OSError:
                time.sleep(0.05)
        for offered in (["foxglove.sdk.v1"], ["foxglove.websocket.v1", "foxglove.sdk.v1"]):
            with ws_client.connect(url, subprotocols=offered, open_timeout=30) as ws:
                assert ws.subprotocol == "foxglove.sdk.v1"
                assert json.loads(ws.recv(timeout=30))["op"] == "serverInfo"
        for offered in (["foxglove.websocket.v1"], None):
            with pytest.raises(ws_exceptions.InvalidStatus) as e:
                ws_client.connect(url, subprotocols=offered, open_timeout=30)
            assert e.value.response.status_code == 400, offered


def test_the_shipped_layout_is_built_from_the_recording_format():
    from observer_node.dbc import Codec
    from observer_node.recording.layout import LAYOUT_FILE, build_layout

    root = Path(__file__).resolve().parents[1]
    shipped = (root / LAYOUT_FILE).read_text(encoding="utf-8")
    assert shipped.strip() == build_layout().strip(), \
        "rebuild: python -m observer_node.recording.layout > " + LAYOUT_FILE
    fields = {**{t: set(f) for t, f in fmt.TOPIC_FIELDS.items()},
              fmt.STATUS_TOPICS["ObserverStatus"]: set(Codec()["ObserverStatus"].signal_names)}
    paths = re.findall(r'"value": "([^"]+)"', shipped)
    assert len(paths) > 10
    for p in paths:  # every series names a topic and a field the recording has
        topic, _, field = p.partition(".")
        assert field in fields[topic], p
