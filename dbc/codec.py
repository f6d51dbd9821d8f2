"""A codec precompiled from the DBC: struct layouts built once at start-up, checked against
cantools in the tests, and an order of magnitude cheaper per frame than cantools' own
encode/decode (see benchmarks/daemon.py).

Supported layouts are what this DBC uses: little-endian (Intel) integer signals that are either
byte-aligned 8/16/32-bit fields or sub-byte fields inside one byte. Anything else is refused at
load time, naming the signal, so the DBC stays the single source of the layout.

E2E protection (as in the DBC's comment): byte 0 is a CRC-8 SAE J1850 (poly 0x1D, init and
xor-out 0xFF) over the frame ID as two little-endian bytes followed by data bytes 1..DLC-1;
the low nibble of byte 1 is a 4-bit alive counter.
"""

from __future__ import annotations

import struct
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import cantools

DBC_PATH = Path(__file__).with_name("chest_observer.dbc")


def _crc8_table() -> list[int]:
    table = []
    for byte in range(256):
        crc = byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1D) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
        table.append(crc)
    return table


CRC8_TABLE = _crc8_table()


def crc8_j1850(data: bytes | bytearray | memoryview, crc: int = 0xFF) -> int:
    """CRC-8 SAE J1850 of ``data`` starting from ``crc`` (no final xor: see :func:`e2e_crc`)."""
    t = CRC8_TABLE
    for b in data:
        crc = t[crc ^ b]
    return crc


def e2e_crc(frame_id: int, data: bytes | bytearray | memoryview) -> int:
    """The E2E CRC byte of a frame: over the ID (2 bytes LE) and data bytes 1.."""
    t = CRC8_TABLE
    crc = t[0xFF ^ (frame_id & 0xFF)]
    crc = t[crc ^ ((frame_id >> 8) & 0xFF)]
    for b in data[1:]:
        crc = t[crc ^ b]
    return crc ^ 0xFF


class LayoutError(ValueError):
    """The DBC uses a layout this codec does not compile."""


_CODES = {(8, False): "B", (8, True): "b", (16, False): "H", (16, True): "h",
          (32, False): "I", (32, True): "i"}


@dataclass(frozen=True)
class _Field:
    name: str
    index: int  # position in the DBC's signal order
    slot: int  # index into the struct's unpacked tuple
    shift: int
    bits: int  # width in bits
    sub_byte: bool  # True: extracted from a shared byte with shift and mask
    signed: bool
    scale: float
    offset: float


class FrameCodec:
    """Pack and unpack one frame's raw signal values, in the DBC's signal order."""

    def __init__(self, message: cantools.database.Message):
        self.name = message.name
        self.frame_id = message.frame_id
        self.length = message.length
        self.fd_only = bool(message.is_fd) or message.length > 8
        self.signal_names = [s.name for s in message.signals]
        fmt, pos, slot = "<", 0, -1
        byte_slot: dict[int, int] = {}
        fields: list[_Field] = []
        # One pass in byte order: whole-byte fields become struct codes, sub-byte fields
        # share one "B" slot per byte.
        for s in sorted(message.signals, key=lambda s: s.start):
            if s.byte_order != "little_endian" or s.is_float:
                raise LayoutError(f"{message.name}.{s.name}: only little-endian integers")
            first, last = s.start // 8, (s.start + s.length - 1) // 8
            whole = s.start % 8 == 0 and (s.length, s.is_signed) in _CODES
            if not whole and first != last:
                raise LayoutError(f"{message.name}.{s.name}: straddles bytes without alignment")
            if whole or first not in byte_slot:
                if first < pos:
                    raise LayoutError(f"{message.name}.{s.name}: overlaps another signal")
                fmt += "x" * (first - pos)
                fmt += _CODES[(s.length, s.is_signed)] if whole else "B"
                pos = last + 1 if whole else first + 1
                slot += 1
                if not whole:
                    byte_slot[first] = slot
            fields.append(_Field(s.name, self.signal_names.index(s.name),
                                 slot if whole else byte_slot[first], s.start % 8, s.length,
                                 not whole, s.is_signed, s.scale, s.offset))
        fmt += "x" * (message.length - pos)
        self._struct = struct.Struct(fmt)
        self._fields = fields
        self._by_name = {f.name: f for f in fields}
        self._fields_by_index = {f.index: f for f in fields}
        self._message = message
        self._nslots = slot + 1
        self.has_e2e = self.signal_names[0].endswith("_CRC") and any(
            n.endswith("_Counter") for n in self.signal_names)
        self.counter_index = next((i for i, n in enumerate(self.signal_names)
                                   if n.endswith("_Counter")), None)

    @property
    def unscaled_signals(self) -> set[str]:
        """Signals whose physical value is the raw integer (scale 1, offset 0)."""
        return {f.name for f in self._fields if f.scale == 1 and not f.offset}

    @property
    def struct(self) -> struct.Struct:
        return self._struct

    def unpack(self, data: bytes | bytearray | memoryview) -> list[int]:
        """Raw signal values in DBC signal order. ``data`` must have the frame's length."""
        slots = self._struct.unpack_from(data)
        out = [0] * len(self._fields)
        for f in self._fields:
            v = slots[f.slot]
            if f.sub_byte:
                v = (v >> f.shift) & ((1 << f.bits) - 1)
                if f.signed and v >= 1 << (f.bits - 1):
                    v -= 1 << f.bits
            out[f.index] = v
        return out

    def pack(self, raw: Sequence[int]) -> bytes:
        """Frame bytes from raw values in DBC signal order (no CRC computed: see encode)."""
        slots = [0] * self._nslots
        for f in self._fields:
            v = int(raw[f.index])
            if f.sub_byte:
                slots[f.slot] |= (v & ((1 << f.bits) - 1)) << f.shift
            else:
                slots[f.slot] = v
        return self._struct.pack(*slots)

    def to_raw(self, name: str, physical: float) -> int:
        """Raw value of a physical one, rounded and saturated to the signal's range."""
        f = self._by_name[name]
        lo, hi = self.raw_range(name)
        return min(max(round((physical - f.offset) / f.scale), lo), hi)

    def raw_range(self, name: str) -> tuple[int, int]:
        f = self._by_name[name]
        if f.signed:
            return -(1 << (f.bits - 1)), (1 << (f.bits - 1)) - 1
        return 0, (1 << f.bits) - 1

    def scale(self, name: str) -> float:
        return self._by_name[name].scale

    @property
    def slots(self) -> int:
        """How many values ``struct`` packs: whole fields, and one per byte of sub-byte
        fields."""
        return self._nslots

    def locate(self, name: str) -> tuple[int, int, int]:
        """Where a signal is in ``struct.unpack_from(data)``'s tuple: ``(slot, shift,
        mask)``; its raw value is ``v[slot] >> shift & mask`` (for a whole field shift is 0
        and the struct already gives the signed value). For hot paths that must not look
        anything up per frame: the DBC stays the only place that knows where a bit is."""
        f = self._by_name.get(name)
        if f is None:
            raise LayoutError(f"{self.name} has no signal {name!r} (the DBC has "
                              f"{', '.join(self.signal_names)})")
        return f.slot, f.shift if f.sub_byte else 0, (1 << f.bits) - 1

    def choices(self, name: str) -> dict[str, int]:
        """A signal's value table from the DBC (VAL_): name -> raw value."""
        sig = self._message.get_signal_by_name(name)
        return {str(v): int(k) for k, v in (sig.choices or {}).items()}

    def with_counter(self, data: bytes, counter: int) -> bytes:
        """The same frame with another alive counter and its CRC redone."""
        raw = self.unpack(data)
        if self.counter_index is None:
            raise LayoutError(f"{self.name} has no alive counter")
        raw[self.counter_index] = counter & ((1 << self._fields_by_index[
            self.counter_index].bits) - 1)
        out = bytearray(self.pack(raw))
        if self.has_e2e:
            out[0] = e2e_crc(self.frame_id, out)
        return bytes(out)

    def encode(self, values: Mapping[str, float], counter: int = 0) -> bytes:
        """Frame bytes from physical values (missing signals 0), with E2E CRC and counter."""
        raw = [self.to_raw(n, values.get(n, 0.0)) for n in self.signal_names]
        if self.has_e2e and self.counter_index is not None:
            raw[self.counter_index] = counter & ((1 << self._fields_by_index[
                self.counter_index].bits) - 1)
        data = bytearray(self.pack(raw))
        if self.has_e2e:
            data[0] = e2e_crc(self.frame_id, data)
        return bytes(data)

    def decode(self, data: bytes | bytearray | memoryview) -> dict[str, float]:
        """Physical values by signal name (off the hot path: analysis, tests)."""
        raw = self.unpack(data)
        return {f.name: raw[f.index] * f.scale + f.offset if (f.scale != 1 or f.offset)
                else raw[f.index] for f in self._fields}

    def check_e2e(self, data: bytes | bytearray | memoryview) -> bool:
        return not self.has_e2e or data[0] == e2e_crc(self.frame_id, data)


class Codec:
    """All frames of the DBC, compiled once."""

    def __init__(self, path: str | Path = DBC_PATH):
        self.path = Path(path)
        db = cantools.database.load_file(str(self.path))
        if not isinstance(db, cantools.database.can.Database):
            raise LayoutError(f"{self.path}: not a CAN database")
        self.db = db
        self.frames = {m.name: FrameCodec(m) for m in self.db.messages}
        self.by_id = {c.frame_id: c for c in self.frames.values()}

    def __getitem__(self, name: str) -> FrameCodec:
        return self.frames[name]

    def sha256(self) -> str:
        import hashlib

        return hashlib.sha256(self.path.read_bytes()).hexdigest()


def frame_bits(dlc: int, extended: bool = False) -> int:
    """Worst-case bits on the wire of one classic data frame including stuff bits and the
    3-bit interframe space."""
    stuffable = (34 if not extended else 54) + 8 * dlc
    return (47 if not extended else 67) + 8 * dlc + (stuffable - 1) // 4


def fd_frame_time_s(length: int, bitrate: float, data_bitrate: float) -> float:
    """Worst-case time of one CAN FD frame (11-bit ID, bit-rate switch): the arbitration and
    end of frame at ``bitrate``, from the BRS bit to the CRC delimiter at ``data_bitrate``.
    Counts stuff bits as one per four in the dynamically stuffed fields, the fixed stuff
    bits and stuff count of the CRC field, ACK, EOF and the interframe space."""
    crc = 17 if length <= 16 else 21
    nominal = 1 + 11 + 3 + 1 + (16 - 1) // 4 + 1 + 2 + 7 + 3  # SOF ID r1 IDE FDF res, ACK EOF IFS
    dynamic = 1 + 4 + 8 * length  # ESI, DLC, data
    data = 1 + dynamic + (dynamic - 1) // 4 + 4 + crc + (crc + 4) // 4 + 1
    return nominal / bitrate + data / data_bitrate


def bus_load(codec: Codec, rates_hz: dict[str, float], bitrate: float = 500_000,
             data_bitrate: float | None = None) -> dict:
    """Worst-case bus load of the given frames at the given rates. Classic CAN, or with
    ``data_bitrate`` CAN FD for every frame (frames the DBC marks FD-only need it)."""
    rows = []
    for name, rate in rates_hz.items():
        f = codec[name]
        if data_bitrate:
            t = fd_frame_time_s(f.length, bitrate, data_bitrate)
        elif f.fd_only:
            raise ValueError(f"{name} is a CAN FD frame ({f.length} bytes): give data_bitrate")
        else:
            t = frame_bits(f.length) / bitrate
        rows.append({"frame": name, "id": f"0x{f.frame_id:03X}", "dlc": f.length,
                     "rate_hz": rate, "time_us": t * 1e6, "load": t * rate})
    return {"bitrate": bitrate, "data_bitrate": data_bitrate, "frames": rows,
            "total": sum(r["load"] for r in rows)}
