"""What the daemon's values mean on the bus, read from the DBC: the observer's and the
recorder's states (their ``VAL_`` tables) and the causes of an invalid estimate (the one-bit
``Invalid_<Name>`` signals of ObserverStatus).

The names are written here, because the code says ``ObserverState.RUNNING``; their values
come from the DBC only, and a name the DBC does not have, or a value of the DBC's without a
name here, is a :class:`~.codec.LayoutError` at import. The recording stores these values as
they are (``state``, ``cause`` in ``/observer/estimate``).

The enum operators run Python code (an IntFlag ``|`` costs ~1 us, an int's ~10 ns): per-tick
code works on the members' plain ``.value`` ints, bound once.
"""

from __future__ import annotations

import enum
import functools
from collections.abc import Mapping

import cantools

from .codec import DBC_PATH, LayoutError


@functools.cache
def _database() -> cantools.database.can.Database:
    db = cantools.database.load_file(str(DBC_PATH))
    if not isinstance(db, cantools.database.can.Database):
        raise LayoutError(f"{DBC_PATH}: not a CAN database")
    return db


def value_table(message: str, signal: str) -> dict[str, int]:
    """A signal's ``VAL_`` table: name -> raw value."""
    sig = _database().get_message_by_name(message).get_signal_by_name(signal)
    if not sig.choices:
        raise LayoutError(f"{DBC_PATH}: {message}.{signal} has no value table (VAL_)")
    return {str(name): int(value) for value, name in sig.choices.items()}


def cause_bits(message: str = "ObserverStatus", prefix: str = "Invalid_") -> dict[str, int]:
    """The causes of an invalid estimate, ``<Name>`` -> bit: the ``Invalid_<Name>`` one-bit
    signals of ObserverStatus, bit k for the k-th bit after the first of them, so the
    recorded cause word is those signals' bits as the frame carries them."""
    sigs = [s for s in _database().get_message_by_name(message).signals
            if s.name.startswith(prefix)]
    if not sigs:
        raise LayoutError(f"{DBC_PATH}: {message} has no {prefix}* signals")
    first = min(s.start for s in sigs)
    for s in sigs:
        if s.length != 1 or s.start - first >= 31:
            raise LayoutError(f"{DBC_PATH}: {message}.{s.name}: a cause is one bit of the "
                              f"first 31 after {prefix}*'s first")
    return {s.name[len(prefix):]: 1 << (s.start - first) for s in sigs}


_OBSERVER = value_table("ObserverStatus", "ObserverState")
_RECORDER = value_table("ObserverHealth", "RecorderState")
_CAUSE = cause_bits()


class ObserverState(enum.IntEnum):
    """ObserverStatus.ObserverState (see daemon/core.py for what each state does)."""

    INIT = _OBSERVER["INIT"]
    ARMED = _OBSERVER["ARMED"]
    RUNNING = _OBSERVER["RUNNING"]
    HOLD = _OBSERVER["HOLD"]


class RecorderState(enum.IntEnum):
    """ObserverHealth.RecorderState (see recording/writer.py)."""

    OFF = _RECORDER["OFF"]
    RECORDING = _RECORDER["RECORDING"]
    RESTARTED = _RECORDER["RESTARTED"]
    FAILED = _RECORDER["FAILED"]


class InvalidCause(enum.IntFlag):
    """Why an estimate is invalid: ObserverStatus's Invalid_<Name> (and Fault_<Name>, the
    latched ones) bits. NOT_ARMED is a state, never latched."""

    ACCEL_TIMEOUT = _CAUSE["AccelTimeout"]
    BRS_TIMEOUT = _CAUSE["BrsTimeout"]
    BAD_E2E = _CAUSE["BadE2E"]
    LOST_FRAME = _CAUSE["LostFrame"]
    OUT_OF_RANGE = _CAUSE["OutOfRange"]
    BUS_ERROR = _CAUSE["BusError"]
    SENSOR_FAULT = _CAUSE["SensorFault"]
    NOT_ARMED = _CAUSE["NotArmed"]


# Each cause and the <Name> of its Invalid_/Fault_ signals
CAUSE_SIGNALS: dict[InvalidCause, str] = {InvalidCause(bit): name
                                          for name, bit in _CAUSE.items()}


def _complete(enum_cls: type[enum.Enum], table: Mapping[str, int], where: str) -> None:
    """Every value of the DBC's table has its member here (no value left unnamed)."""
    named = {m.value for m in enum_cls}
    missing = [n for n, v in table.items() if v not in named]
    if missing:
        raise LayoutError(f"{DBC_PATH}: {where} {', '.join(missing)} has no member in "
                          f"{enum_cls.__name__}")


_complete(ObserverState, _OBSERVER, "ObserverState")
_complete(RecorderState, _RECORDER, "RecorderState")
_complete(InvalidCause, _CAUSE, "Invalid_")
