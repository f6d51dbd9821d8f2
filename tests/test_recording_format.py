"""The recording format reads what it writes, and what it wrote before: tests/data holds a
run recorded before the format's names became types (recorded-before-enums.mcap, R16_002
on the virtual bus with the bundled baseline model); a run recorded now has the same
schemas, topics, metadata keys, attachments and message fields."""

from __future__ import annotations

import json
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from observer_node.daemon.harness import CODEC, Harness, r16_schedule
from observer_node.dbc.meanings import InvalidCause, ObserverState, RecorderState
from observer_node.model import ModelFile
from observer_node.recording import RecordingError, Scan, read_recording
from observer_node.recording import format as fmt
from observer_node.recording.export import export_frames
from observer_node.replay.sources import SourceError, load_source, read_mcap_frames

ROOT = Path(__file__).resolve().parents[1]
BEFORE = ROOT / "tests/data/recorded-before-enums.mcap"


def _shape(path: Path) -> dict:
    """What a reader relies on in a recording: schema records byte for byte, the channels'
    topics and encodings, metadata record names and keys, attachment names and media
    types, the field names of each topic's messages."""
    from mcap.reader import make_reader

    with path.open("rb") as f:
        r = make_reader(f)
        summary = r.get_summary()
        assert summary is not None
        schemas = {s.name: (s.encoding, s.data) for s in summary.schemas.values()}
        channels = {c.topic: (c.message_encoding, summary.schemas[c.schema_id].name)
                    for c in summary.channels.values()}
        meta = {m.name: sorted(m.metadata) for m in r.iter_metadata()}
        atts = {a.name: a.media_type for a in r.iter_attachments()}
        fields: dict[str, set[frozenset[str]]] = {}
        for _, channel, msg in r.iter_messages():
            fields.setdefault(channel.topic, set()).add(frozenset(json.loads(msg.data)))
    return {"schemas": schemas, "channels": channels, "metadata": meta, "attachments": atts,
            "fields": fields}


@pytest.fixture(scope="module")
def recorded_now(tmp_path_factory) -> Path:
    """R16_002 recorded by this code as the one in tests/data was by the code before."""
    model = ModelFile.load(ROOT / "observer_node/examples/bench-loop/baseline-model.json")
    record = tmp_path_factory.mktemp("format") / "now.mcap"
    sched = r16_schedule(pre_s=0.05)
    h = Harness(model, "format-now", record)
    h.thread = threading.Thread(target=h.node.run)  # no idle exit: starved is not idle
    with h:
        h.play(sched)
        deadline = time.monotonic() + 120
        while h.node.counters.rx < len(sched) and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.4)  # watchdog publishes after the last frame, as before
    return record


def test_a_recording_written_now_has_the_shape_of_one_written_before(recorded_now):
    before, now = _shape(BEFORE), _shape(recorded_now)
    assert now["schemas"] == before["schemas"]
    assert now["channels"] == before["channels"]
    assert now["metadata"] == before["metadata"]
    assert now["attachments"] == before["attachments"]
    # every kind of message written before is written now, and no other
    assert set(now["fields"]) == set(before["fields"])
    for topic, kinds in now["fields"].items():
        assert kinds <= before["fields"][topic] | {frozenset()}, topic
    assert set(before["metadata"][fmt.META_RUN]) == {k.value for k in fmt.RunMeta}
    assert set(before["metadata"][fmt.META_END]) == {k.value for k in fmt.EndMeta}
    assert set(before["attachments"]) == set(fmt.MEDIA)
    assert before["attachments"] == fmt.MEDIA


def test_a_recording_written_before_reads_with_the_typed_reader(tmp_path):
    """Its frames read as Frames (the same as their JSON says), its states and causes as the
    DBC's enums, and it exports and replays."""
    raw = [json.loads(d) for t, _, d in Scan(BEFORE) if t == fmt.FRAMES]
    frames = [fmt.read_frame(d) for t, _, d in Scan(BEFORE) if t == fmt.FRAMES]
    assert len(frames) == len(raw) > 1000
    for m, fr in zip(raw, frames, strict=True):
        assert (fr.t, fr.can_id, fr.data.hex()) == (m["t"], m["id"], m["data"])
        assert (fr.tx, fr.error, fr.fd) == (m["dir"] == "tx", m["error"], m["fd"])
        assert fmt.frame_message(fr.t, fr.can_id, fr.flags, fr.data) == m  # round trip
    assert any(fr.tx for fr in frames) and any(not fr.tx for fr in frames)
    rec = read_recording(BEFORE)
    assert rec.frames == frames and rec.tick_rate_hz == 1000.0
    states = {ObserverState(int(s)) for s in rec.ticks["state"]}
    assert {ObserverState.ARMED, ObserverState.RUNNING} <= states
    word = int(np.bitwise_or.reduce(rec.ticks["cause"].astype(int)))
    named = sum(c.value for c in InvalidCause)
    assert word and word & ~named == 0  # every recorded cause bit has its name
    health = [json.loads(d)["RecorderState"] for t, _, d in Scan(BEFORE)
              if t == fmt.STATUS_TOPICS["ObserverHealth"]]
    assert health and {RecorderState(h) for h in health} == {RecorderState.RECORDING}
    n, salvaged = export_frames(BEFORE, tmp_path / "before.log")
    assert n == len(frames) and salvaged is None
    (received,) = load_source(BEFORE, CODEC)
    assert received.data == [fr.data for fr in sorted(
        (fr for fr in frames if not fr.tx and not fr.error), key=lambda fr: fr.t)]
    (every,) = load_source(BEFORE, CODEC, all_frames=True)
    (log,) = load_source(tmp_path / "before.log", CODEC)  # candump keeps no direction
    assert sorted(zip(every.ids.tolist(), every.data, strict=True)) == \
        sorted(zip(log.ids.tolist(), log.data, strict=True))


def test_a_frame_whose_direction_is_neither_rx_nor_tx_is_refused(tmp_path):
    """Before, export took it for sent and replay for received: now both say it is not a
    frame."""
    from mcap.writer import Writer

    path = tmp_path / "bad.mcap"
    with path.open("wb") as f:
        w = Writer(f)
        w.start(profile="", library="test")
        w.add_metadata(fmt.META_RUN, {})
        sid = w.register_schema(fmt.TITLES[fmt.FRAMES], "jsonschema",
                                fmt.json_schema(fmt.FRAMES, fmt.FRAME_FIELDS))
        cid = w.register_channel(fmt.FRAMES, "json", sid)
        msg = fmt.frame_message(0.0, 0x100, 0, b"\x01\x02")
        w.add_message(cid, 1, json.dumps(msg).encode(), 1)
        w.add_message(cid, 2, json.dumps({**msg, "dir": "up"}).encode(), 2)
        w.finish()
    with pytest.raises(RecordingError, match=r"not a frame.*'up'"):
        export_frames(path, tmp_path / "bad.log")
    with pytest.raises(SourceError, match=r"not a frame.*'up'"):
        read_mcap_frames(path, codec=CODEC)


def test_a_recording_of_sent_frames_only_says_all_frames_replays_them(tmp_path):
    """A recording holding only the frames its node sent (a daemon that published, with its
    inputs on another bus) said "not a chest-observer recording?": it now says what it holds
    and the option that replays it."""
    from mcap.writer import Writer

    path = tmp_path / "sent.mcap"
    with path.open("wb") as f:
        w = Writer(f)
        w.start(profile="", library="test")
        w.add_metadata(fmt.META_RUN, {})
        sid = w.register_schema(fmt.TITLES[fmt.FRAMES], "jsonschema",
                                fmt.json_schema(fmt.FRAMES, fmt.FRAME_FIELDS))
        cid = w.register_channel(fmt.FRAMES, "json", sid)
        for k in range(3):
            msg = fmt.frame_message(k * 1e-3, 0x100, fmt.FrameFlag.TX, b"\x01\x02")
            w.add_message(cid, k, json.dumps(msg).encode(), k)
        w.finish()
    with pytest.raises(SourceError, match=r"sent.mcap: no frames received by the logging "
                                          r"node, only 3 it sent: --all-frames replays those"):
        read_mcap_frames(path, codec=CODEC)
    assert len(read_mcap_frames(path, all_frames=True, codec=CODEC)) == 3
