"""Bus ports: the daemon's small view of a CAN bus, behind which any python-can interface or a
raw SocketCAN socket sits.

``recv(timeout_s)`` returns ``(t_s, can_id, data, flags)`` or ``None`` on timeout; ``t_s`` is
``time.perf_counter()`` at receipt, ``flags`` (:class:`~observer_node.recording.format.
FrameFlag`) has ERROR for error frames, FD for CAN FD frames and REMOTE for remote (RTR)
frames.
``send(can_id, data)`` transmits one frame. Errors of the bus itself (interface down, bus
gone) raise :class:`PortError`; the daemon then reconnects.

Why a raw SocketCAN port beside python-can's: python-can's socketcan receive costs a
``select`` and a ``recvmsg`` plus a Message object per frame, and it accepts no ancillary data
but the timestamp, so the kernel's drop counter (``SO_RXQ_OVFL``) cannot be read through it.
The raw port does one ``recvmsg`` per frame (the timeout is the socket's ``SO_RCVTIMEO``),
raises the receive buffer (the default holds a few hundred frames and drops silently beyond),
reads the drop counter, and receives error frames, which are the only sign of bus-off on
SocketCAN.
"""

from __future__ import annotations

import errno
import socket
import struct
import time
from typing import TYPE_CHECKING, Any, Protocol

from observer_node.dbc.bus import BusOpenError, open_bus

from ..recording.format import FrameFlag

if TYPE_CHECKING:  # python-can is imported when a port opens: the daemon starts faster
    import can
    from can.typechecking import CanFilter

# The flags of a received frame (recording.format.FrameFlag), as plain ints per frame
FLAG_ERROR, FLAG_FD, FLAG_REMOTE = (FrameFlag.ERROR.value, FrameFlag.FD.value,
                                    FrameFlag.REMOTE.value)

SOL_CAN_RAW = 101
CAN_RAW_FILTER = 1
CAN_RAW_ERR_FILTER = 2
CAN_RAW_FD_FRAMES = 5
SO_RXQ_OVFL = 40
SO_RCVBUFFORCE = 33
CAN_ERR_FLAG = 0x20000000
CAN_RTR_FLAG = 0x40000000
CAN_EFF_FLAG = 0x80000000
CAN_ERR_MASK = 0x1FFFFFFF
CANFD_MTU = 72
_FRAME = struct.Struct("=IB3x")
_FD_FRAME = struct.Struct("=IBB2x")
CANFD_BRS = 0x01  # bit-rate switch: the data phase at the fast rate


class PortError(OSError):
    """The bus is not usable now (interface down or gone); reconnecting may help."""


class Port(Protocol):
    dropped: int  # frames the kernel dropped (if the port can tell)

    def recv(self, timeout_s: float) -> tuple[float, int, bytes, int] | None: ...

    def send(self, can_id: int, data: bytes) -> bool: ...

    def close(self) -> None: ...


class SocketCanPort:
    """Raw AF_CAN socket with kernel ID filters, a big receive buffer and drop counting."""

    def __init__(self, channel: str, ids: list[int], fd: bool = False,
                 rcvbuf_bytes: int = 4 << 20, timeout_s: float = 0.001):
        self.channel = channel
        self.fd = fd
        self.dropped = 0
        self._timeout = -1.0
        try:
            s = socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW)
        except OSError as e:  # EAFNOSUPPORT: this kernel has no CAN (no can-raw module)
            raise PortError(e.errno, f"{channel}: cannot open a CAN socket: {e.strerror} "
                            "(does this kernel have SocketCAN? try: modprobe can_raw)") from None
        try:
            try:
                s.setsockopt(socket.SOL_SOCKET, SO_RCVBUFFORCE, rcvbuf_bytes)
            except OSError:  # not root: capped by net.core.rmem_max
                s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf_bytes)
            s.setsockopt(socket.SOL_SOCKET, SO_RXQ_OVFL, 1)
            filters = b"".join(struct.pack("=II", i, 0x7FF | CAN_EFF_FLAG) for i in ids)
            s.setsockopt(SOL_CAN_RAW, CAN_RAW_FILTER, filters)
            s.setsockopt(SOL_CAN_RAW, CAN_RAW_ERR_FILTER, CAN_ERR_MASK)
            if fd:
                s.setsockopt(SOL_CAN_RAW, CAN_RAW_FD_FRAMES, 1)
            s.bind((channel,))
        except OSError as e:
            s.close()
            raise PortError(e.errno, f"{channel}: {e.strerror}") from None
        self.sock = s
        self._ancbuf = socket.CMSG_SPACE(4)
        self._set_timeout(timeout_s)

    def _set_timeout(self, timeout_s: float) -> None:
        if timeout_s != self._timeout:
            sec = int(timeout_s)
            usec = max(1, int((timeout_s - sec) * 1e6))
            self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVTIMEO,
                                 struct.pack("ll", sec, usec))
            self._timeout = timeout_s

    def recv(self, timeout_s: float) -> tuple[float, int, bytes, int] | None:
        self._set_timeout(timeout_s)
        try:
            cf, anc, _, _ = self.sock.recvmsg(CANFD_MTU, self._ancbuf)
        except (BlockingIOError, TimeoutError):
            return None
        except InterruptedError:
            return None
        except OSError as e:
            raise PortError(e.errno, f"{self.channel}: {e.strerror}") from None
        t = time.perf_counter()
        for level, kind, value in anc:
            if level == socket.SOL_SOCKET and kind == SO_RXQ_OVFL and len(value) >= 4:
                self.dropped = struct.unpack_from("=I", value)[0]
        can_id, length = _FRAME.unpack_from(cf)
        flags = FLAG_FD if len(cf) == CANFD_MTU else 0
        if can_id & CAN_ERR_FLAG:
            flags |= FLAG_ERROR
        if can_id & CAN_RTR_FLAG:
            flags |= FLAG_REMOTE
        return t, can_id & CAN_ERR_MASK, cf[8:8 + length], flags

    def send(self, can_id: int, data: bytes) -> bool:
        n = len(data)
        if self.fd:  # CAN FD is a configuration: the same layouts, sent as FD frames
            frame = _FD_FRAME.pack(can_id, n, CANFD_BRS) + data.ljust(64, b"\0")
        else:
            frame = _FRAME.pack(can_id, n) + data.ljust(8, b"\0")
        try:
            self.sock.send(frame)
            return True
        except BlockingIOError:
            return False  # transmit queue full: counted by the caller
        except OSError as e:
            if e.errno == errno.ENOBUFS:
                return False
            raise PortError(e.errno, f"{self.channel}: {e.strerror}") from None

    def close(self) -> None:
        self.sock.close()


class PythonCanPort:
    """Any python-can interface (virtual, socketcan, pcan, kvaser, ...)."""

    def __init__(self, interface: str, channel: str, ids: list[int], fd: bool = False,
                 bus: can.BusABC | None = None, **kwargs: Any):
        import can

        self.dropped = 0
        self._can = can
        self.fd = fd
        filters: list[CanFilter] = [{"can_id": i, "can_mask": 0x7FF, "extended": False}
                                    for i in ids]
        try:
            self.bus = bus or open_bus(interface, channel, can_filters=filters, fd=fd,
                                       **kwargs)
        except BusOpenError as e:
            raise PortError(errno.ENODEV, str(e)) from None
        if bus is not None:
            bus.set_filters(filters)

        class _Sent(can.Message):
            """A frame built for one send and never touched again: python-can's virtual bus
            deep-copies every sent message for its receivers (5 us, more than the observer's
            step); this one is handed over as it is. Other interfaces never copy."""

            __slots__ = ()

            def __deepcopy__(self, memo: dict[int, Any] | None = None) -> can.Message:
                return self

        self._message = _Sent

    def recv(self, timeout_s: float) -> tuple[float, int, bytes, int] | None:
        try:
            m = self.bus.recv(timeout_s)
        except self._can.CanError as e:
            raise PortError(errno.EIO, str(e)) from None
        if m is None:
            return None
        flags = (FLAG_ERROR if m.is_error_frame else 0) | (FLAG_FD if m.is_fd else 0) | \
            (FLAG_REMOTE if m.is_remote_frame else 0)
        return time.perf_counter(), m.arbitration_id, bytes(m.data), flags

    def send(self, can_id: int, data: bytes) -> bool:
        msg = self._message(arbitration_id=can_id, data=data, is_extended_id=False,
                            is_fd=self.fd, bitrate_switch=self.fd)
        try:
            self.bus.send(msg)
            return True
        except self._can.CanError as e:
            raise PortError(errno.EIO, str(e)) from None

    def close(self) -> None:
        self.bus.shutdown()


def open_port(interface: str, channel: str, ids: list[int], fd: bool = False,
              raw_socketcan: bool = True) -> Port:
    if interface == "socketcan" and raw_socketcan:
        return SocketCanPort(channel, ids, fd)
    return PythonCanPort(interface, channel, ids, fd)
