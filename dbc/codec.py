"""A codec precompiled from the DBC: struct layouts built once at start-up, checked against
cantools in the tests, and an order of magnitude cheaper per frame than cantools' own
encode/decode (see benchmarks/daemon.py).

Supported layouts are what this DBC uses: little-endian (Intel) integer signals that are either
byte-aligned 8/16/32-bit fields or sub-byte fields inside one byte. Anything else is refused at
load time, naming the signal, so the DBC stays the single source of the layout.

E2E protection: standard AUTOSAR profiles, declared per message in the DBC by the attributes
``E2EProfile`` ("P01" for the 8-byte classic frames, "P05" for the CAN FD InputBurst) and
``E2EDataID``; the CRC and counter positions are the message's ``*_CRC`` and ``*_Counter``
signals, checked at load against the profile's header layout. The CRCs are computed by a kept
implementation, the ``autosar-e2e`` package (C); P01's alive counter runs 0..14, P05's 0..255.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import cantools
from e2e import p01, p05

from observer_node.errors import ObserverError

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
    """CRC-8 SAE J1850 (poly 0x1D) of ``data`` starting from ``crc``, no final xor: an
    implementation of our own, kept to cross-check the E2E library in the tests."""
    t = CRC8_TABLE
    for b in data:
        crc = t[crc ^ b]
    return crc


class LayoutError(ObserverError, ValueError):
    """The DBC uses a layout this codec does not compile."""


# profile -> (protect, check, CRC bits, counter bits, counter values)
E2E_PROFILES: dict[str, tuple[Callable[..., None], Callable[..., bool], int, int, int]] = {
    "P01": (p01.e2e_p01_protect, p01.e2e_p01_check, 8, 4, 15),
    "P05": (p05.e2e_p05_protect, p05.e2e_p05_check, 16, 8, 256),
}


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
        self.counter_index = next((i for i, n in enumerate(self.signal_names)
                                   if n.endswith("_Counter")), None)
        self._e2e_setup(message)

    def _e2e_setup(self, message: cantools.database.Message) -> None:
        """The message's E2E profile from its DBC attributes, its header checked against the
        *_CRC and *_Counter signals."""
        attrs = message.dbc.attributes if message.dbc is not None else {}
        profile = str(attrs["E2EProfile"].value) if "E2EProfile" in attrs else ""
        self.e2e_profile = profile
        self.has_e2e = bool(profile)
        self.data_id = int(attrs["E2EDataID"].value) if "E2EDataID" in attrs else 0
        cnt = self.counter_index
        self.counter_modulus = (1 << self._fields_by_index[cnt].bits) if cnt is not None else 1
        if not profile:
            return
        if profile not in E2E_PROFILES:
            raise LayoutError(f"{self.name}: E2EProfile {profile!r} is not one of "
                              f"{', '.join(E2E_PROFILES)}")
        protect, check, crc_bits, cnt_bits, modulus = E2E_PROFILES[profile]
        crc_sig = next((s for s in message.signals if s.name.endswith("_CRC")), None)
        cnt_sig = next((s for s in message.signals if s.name.endswith("_Counter")), None)
        if crc_sig is None or cnt_sig is None or crc_sig.length != crc_bits or \
                crc_sig.start % 8 or cnt_sig.length != cnt_bits or \
                cnt_sig.start != crc_sig.start + crc_bits:
            raise LayoutError(f"{self.name}: {profile} needs a {crc_bits}-bit *_CRC signal on a "
                              f"byte boundary followed by a {cnt_bits}-bit *_Counter")
        if not 0 <= self.data_id <= 0xFFFF:
            raise LayoutError(f"{self.name}: E2EDataID {self.data_id} is not 16-bit")
        self.counter_modulus = modulus
        self.e2e_offset = crc_sig.start // 8
        self._protect, self._check = protect, check

    def e2e_protect(self, buf: bytearray) -> None:
        """Write the E2E CRC of ``buf`` (its counter already in place) into ``buf``."""
        if self.has_e2e:
            self._protect(buf, self.data_id, offset=self.e2e_offset, increment_counter=False)

    def e2e_check(self, data: bytes | bytearray | memoryview) -> bool:
        """True when ``data`` (of the frame's length) passes the profile's CRC and counter
        checks (P01: counter 0..14)."""
        return self.e2e_checker()(data)

    def e2e_checker(self) -> Callable[[bytes | bytearray | memoryview], bool]:
        """:meth:`e2e_check` bound once for a hot path: one copy into a preallocated buffer
        (the library wants a mutable one) and one C call per frame, nothing looked up."""
        if not self.has_e2e:
            return lambda data: True
        buf, check, data_id, offset = bytearray(self.length), self._check, self.data_id, \
            self.e2e_offset

        def checked(data: bytes | bytearray | memoryview) -> bool:
            buf[:] = data
            return bool(check(buf, data_id, offset=offset) if offset else check(buf, data_id))

        return checked

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
        raw[self.counter_index] = counter % self.counter_modulus
        out = bytearray(self.pack(raw))
        self.e2e_protect(out)
        return bytes(out)

    def encode(self, values: Mapping[str, float], counter: int = 0) -> bytes:
        """Frame bytes from physical values (missing signals 0), with the E2E counter
        (modulo the profile's range) and CRC."""
        raw = [self.to_raw(n, values.get(n, 0.0)) for n in self.signal_names]
        if self.has_e2e and self.counter_index is not None:
            raw[self.counter_index] = counter % self.counter_modulus
        data = bytearray(self.pack(raw))
        self.e2e_protect(data)
        return bytes(data)

    def decode(self, data: bytes | bytearray | memoryview) -> dict[str, float]:
        """Physical values by signal name (off the hot path: analysis, tests)."""
        raw = self.unpack(data)
        return {f.name: raw[f.index] * f.scale + f.offset if (f.scale != 1 or f.offset)
                else raw[f.index] for f in self._fields}



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
