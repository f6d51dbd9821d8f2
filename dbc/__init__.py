"""The CAN database: one DBC file (``chest_observer.dbc``) and the codec compiled from it.

Both the daemon and the replay tool use this package; neither knows the other's internals.
The codec (and with it cantools and python-can) loads when first used, so a command line that
only declares its bus options (:mod:`.bus`) starts without them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .codec import (
        DBC_PATH,
        Codec,
        FrameCodec,
        bus_load,
        crc8_j1850,
        fd_frame_time_s,
        frame_bits,
    )

__all__ = ["DBC_PATH", "Codec", "FrameCodec", "bus_load", "crc8_j1850", "fd_frame_time_s",
           "frame_bits"]


def __getattr__(name: str) -> Any:
    if name in __all__:
        from . import codec

        return getattr(codec, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
