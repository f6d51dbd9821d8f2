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

from observer_node.daemon.harness import Harness, r16_schedule
from observer_node.recording import format as fmt
from observer_node.recording import read_recording

pytest.importorskip("foxglove")
ws_client = pytest.importorskip("websockets.sync.client")
ws_exceptions = pytest.importorskip("websockets.exceptions")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_a_live_client_receives_the_recorded_estimates(model, tmp_path):
    port = _free_port()
    record = tmp_path / "run.mcap"
    got: list[dict] = []
    subscribed = threading.Event()
    done = threading.Event()

    def client() -> None:
        with ws_client.connect(f"ws://127.0.0.1:{port}", subprotocols=["foxglove.sdk.v1"],
                               open_timeout=30) as ws:
            channels: dict[str, dict] = {}
            while fmt.ESTIMATE not in channels:
                msg = json.loads(ws.recv(timeout=30))
                if msg["op"] == "advertise":
                    channels.update({c["topic"]: c for c in msg["channels"]})
            est = channels[fmt.ESTIMATE]
            schema = json.loads(est["schema"])
            assert set(schema["properties"]) == set(fmt.TOPIC_FIELDS[fmt.ESTIMATE])
            ws.send(json.dumps({"op": "subscribe",
                                "subscriptions": [{"id": 1, "channelId": est["id"]}]}))
            subscribed.set()
            while not done.is_set():
                try:
                    m = ws.recv(timeout=0.2)
                except TimeoutError:
                    continue
                except ws_exceptions.ConnectionClosed:
                    return  # the run ended
                if isinstance(m, bytes) and m[0] == 1:
                    _, sub, _ = struct.unpack_from("<BIQ", m)
                    assert sub == 1
                    got.append(json.loads(m[13:]))

    with Harness(model, "live", record, live=f"127.0.0.1:{port}") as h:
        reader = threading.Thread(target=client)
        reader.start()
        assert subscribed.wait(30), "no advertise from the live server"
        h.play(r16_schedule())
        time.sleep(0.5)
        done.set()
        reader.join(30)
    rec = read_recording(record)
    rows = {int(t): k for k, t in enumerate(rec.ticks["tick"])}
    # decimated to 100 Hz of a 1 kHz run: every tenth tick, each as recorded, none lost from
    # the moment the server took the subscription (the protocol does not acknowledge it, so on
    # a loaded machine the first few may go out before it: a live view joins a run anyway)
    want = [int(t) for t in rec.ticks["tick"] if t >= 0 and int(t) % 10 == 0]
    ticks = sorted(m["tick"] for m in got)
    assert ticks and ticks == want[want.index(ticks[0]):], ticks[:5]
    assert len(ticks) >= 0.8 * len(want), (len(ticks), len(want))
    for m in got:
        k = rows[m["tick"]]
        assert m["cr_g"] == rec.ticks["cr_g"][k] and m["cd_mm"] == rec.ticks["cd_mm"][k]
        assert m["running"] == bool(rec.ticks["running"][k])
    assert any(m["running"] and m["cd_mm"] > 5 for m in got)  # the crash was seen live


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
