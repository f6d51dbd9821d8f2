"""The DBC and its precompiled codec against cantools, E2E and bus load; the states and
causes read from it."""

from __future__ import annotations

import random

import pytest

from observer_node.dbc import Codec, bus_load, crc8_j1850, frame_bits
from observer_node.dbc.codec import LayoutError
from observer_node.dbc.meanings import (
    CAUSE_SIGNALS,
    InvalidCause,
    ObserverState,
    RecorderState,
    value_table,
)

CODEC = Codec()


def test_crc_check_values_of_the_autosar_crc_specification():
    """The check values AUTOSAR's Specification of CRC Routines publishes for "123456789":
    CRC-8 SAE J1850 0x4B (P01's CRC) and CRC-16 CCITT-FALSE 0x29B1 (P05's), by the E2E
    library's CRCs and by our own CRC-8."""
    from e2e import crc

    assert crc8_j1850(b"123456789") ^ 0xFF == 0x4B
    assert crc.calculate_crc8(b"123456789") == 0x4B
    assert crc.calculate_crc16(b"123456789") == 0x29B1


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
    assert data[1] & 0xF == 7 and acc.e2e_check(data)
    assert not acc.e2e_check(bytes([data[0], data[1], data[2] ^ 1, data[3]]))
    # the data ID (the frame ID here) is in the CRC: the same payload under another is caught
    assert _p01_crc(acc.data_id + 1, data) != data[0]
    assert all(f.has_e2e for f in CODEC.frames.values())
    assert {f.e2e_profile for f in CODEC.frames.values()} == {"P01", "P05"}
    assert CODEC["InputBurst"].e2e_profile == "P05"


def _p01_crc(data_id: int, data: bytes) -> int:
    """AUTOSAR E2E P01 (data ID mode BOTH, CRC in byte 0), from the PRS's definition with our
    own CRC-8 J1850: start 0x00 over the data ID's low and high bytes, then the data bytes
    after the CRC, no final xor."""
    return crc8_j1850(bytes([data_id & 0xFF, data_id >> 8]) + bytes(data[1:]), 0x00)


def test_p01_of_the_library_equals_an_independent_implementation():
    # the vectors of the library's own test suite (data ID 0x123, data ID mode BOTH, 8 zero
    # bytes: CRC 0xCC; counter 1: 0x91), reproduced by our CRC-8 from the definition
    assert _p01_crc(0x123, bytes(8)) == 0xCC
    assert _p01_crc(0x123, b"\x00\x01" + bytes(6)) == 0x91
    rng = random.Random(1)
    for name, fc in CODEC.frames.items():
        if fc.e2e_profile != "P01":
            continue
        for k in range(50):
            raw = [rng.randint(*fc.raw_range(n)) for n in fc.signal_names]
            data = fc.with_counter(fc.pack(raw), k)
            assert data[0] == _p01_crc(fc.data_id, data), name
            assert fc.e2e_check(data)


def test_p01_counter_runs_0_to_14_and_15_is_refused():
    acc = CODEC["TunnelAccel"]
    assert [acc.encode({}, k)[1] & 0xF for k in range(13, 17)] == [13, 14, 0, 1]
    raw = acc.unpack(acc.encode({}, 0))
    raw[acc.signal_names.index("TunnelAccel_Counter")] = 15
    bad = bytearray(acc.pack(raw))
    bad[0] = _p01_crc(acc.data_id, bad)  # a right CRC, an impossible counter
    assert not acc.e2e_check(bytes(bad))


def test_p05_against_the_example_vectors_and_cantools():
    """The profile 5 example vectors of the library's test suite (data ID 0x1234, 8 zero
    bytes: CRC 0xCA1C, and with the counter at 1: 0x8DCF), and a second implementation
    (cantools.autosar) on the InputBurst frame."""
    from cantools.autosar import compute_profile5_crc
    from e2e.p05 import e2e_p05_protect

    data = bytearray(8)
    e2e_p05_protect(data, 0x1234, increment_counter=False)
    assert bytes(data[:2]) == b"\x1c\xca"
    e2e_p05_protect(data, 0x1234, increment_counter=True)
    assert bytes(data[:3]) == b"\xcf\x8d\x01"
    burst = CODEC["InputBurst"]
    rng = random.Random(2)
    for k in range(50):
        raw = [rng.randint(*burst.raw_range(n)) for n in burst.signal_names]
        frame = burst.with_counter(burst.pack(raw), k)
        assert int.from_bytes(frame[:2], "little") == compute_profile5_crc(frame, burst.data_id)
        assert frame[2] == k and burst.e2e_check(frame)
        assert not burst.e2e_check(frame[:5] + bytes([frame[5] ^ 0x40]) + frame[6:])


def test_an_e2e_header_that_does_not_fit_its_profile_is_refused(tmp_path):
    from observer_node.dbc.codec import LayoutError

    text = CODEC.path.read_text()
    bad = text.replace('BA_ "E2EProfile" BO_ 256 "P01";', 'BA_ "E2EProfile" BO_ 256 "P05";')
    (tmp_path / "bad.dbc").write_text(bad)
    with pytest.raises(LayoutError, match="TunnelAccel: P05 needs a 16-bit"):
        Codec(tmp_path / "bad.dbc")


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


def test_states_and_causes_are_the_dbcs():
    """Each enum has exactly the DBC's value table; each cause is the bit of its Invalid_
    signal in ObserverStatus, so a status frame's Invalid_ bits are the recorded cause."""
    assert {m.name: m.value for m in ObserverState} == \
        value_table("ObserverStatus", "ObserverState")
    assert {m.name: m.value for m in RecorderState} == \
        value_table("ObserverHealth", "RecorderState")
    status = CODEC["ObserverStatus"]
    invalid = [n for n in status.signal_names if n.startswith("Invalid_")]
    assert sorted(f"Invalid_{n}" for n in CAUSE_SIGNALS.values()) == sorted(invalid)
    assert set(CAUSE_SIGNALS) == set(InvalidCause)
    for cause, name in CAUSE_SIGNALS.items():
        values = {n: 0 for n in status.signal_names}
        values[f"Invalid_{name}"] = 1
        word = status.struct.unpack_from(status.encode(values))
        slot, shift, _ = status.locate(f"Invalid_{next(iter(CAUSE_SIGNALS.values()))}")
        assert word[slot] >> shift == cause.value, name


def test_a_signal_without_a_value_table_is_said_in_one_line():
    with pytest.raises(LayoutError, match=r"ObserverStatus\.ModelId has no value table"):
        value_table("ObserverStatus", "ModelId")
