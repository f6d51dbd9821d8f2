"""The DBC and its precompiled codec against cantools, E2E and bus load."""

from __future__ import annotations

import random

import pytest

from observer_node.dbc import Codec, bus_load, crc8_j1850, e2e_crc, frame_bits

CODEC = Codec()


def test_crc8_j1850_check_value():
    assert crc8_j1850(b"123456789") ^ 0xFF == 0x4B  # the SAE J1850 check value


@pytest.mark.parametrize("name", sorted(CODEC.frames))
def test_precompiled_codec_equals_cantools(name):
    rng = random.Random(name)
    fc, msg = CODEC[name], CODEC.db.get_message_by_name(name)
    for _ in range(300):
        values = {}
        for s in msg.signals:
            lo, hi = fc.raw_range(s.name)
            values[s.name] = rng.randint(lo, hi) * s.scale + s.offset
        data = msg.encode(values, scaling=True, strict=False)
        assert fc.pack([fc.to_raw(n, values[n]) for n in fc.signal_names]) == data
        ours, theirs = fc.decode(data), msg.decode(data, decode_choices=False)
        assert ours == pytest.approx(theirs)


def test_e2e_protects_safety_frames():
    acc = CODEC["TunnelAccel"]
    data = acc.encode({"TunnelAccelX": -12.3}, counter=7)
    assert data[1] & 0xF == 7 and acc.check_e2e(data)
    assert data[0] == e2e_crc(acc.frame_id, data)
    assert not acc.check_e2e(bytes([data[0], data[1], data[2] ^ 1, data[3]]))
    # the ID is in the CRC: the same payload under another ID is caught
    assert e2e_crc(acc.frame_id + 1, data) != data[0]
    assert all(f.has_e2e for f in CODEC.frames.values())


def test_10_khz_fits_can_fd_only_as_bursts():
    per_sample = bus_load(CODEC, {"TunnelAccel": 10_000, "ChestEstimate": 10_000,
                                  "BeltSpindle": 10_000}, 500_000, 2_000_000)
    bursts = bus_load(CODEC, {"InputBurst": 1250, "ChestEstimate": 1250,
                              "ObserverStatus": 10, "ObserverCounters": 10}, 500_000, 2_000_000)
    assert per_sample["total"] > 1.0 and bursts["total"] < 0.6
    with pytest.raises(ValueError, match="InputBurst is a CAN FD frame"):
        bus_load(CODEC, {"InputBurst": 1250})


def test_default_rate_fits_a_500k_bus_with_margin():
    assert frame_bits(4) == 95 and frame_bits(8) == 135
    worst = bus_load(CODEC, {"TunnelAccel": 1000, "ChestEstimate": 1000, "BeltSpindle": 1000,
                             "ObserverStatus": 10, "ObserverCounters": 10})
    assert worst["total"] < 0.7
