"""The CAN database: one DBC file (``chest_observer.dbc``) and the codec compiled from it.

Both the daemon and the replay tool use this package; neither knows the other's internals.
"""

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
