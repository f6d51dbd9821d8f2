"""Opening a python-can bus, for the daemon and crash-replay alike: the bus, or one line
saying why not.

python-can's backends fail at open in their own ways: CanInterfaceNotImplementedError or
CanInitializationError as documented, but also an OSError for a missing vendor library
(pcan), a NameError (kvaser without canlib), a TypeError (socketcand without host and port),
an ImportError (neovi), a socket.gaierror (udp_multicast given a device name); several log a
warning of their own when imported, and a bus that failed half-way logs again when it is
collected. Whatever an interface's constructor raises means "this bus cannot be opened
here": it becomes a :class:`BusOpenError` whose message is one line, with what python-can
logged meanwhile folded in, so a command can end with that line and exit code 2.
"""

from __future__ import annotations

import gc
import logging
import warnings
from typing import TYPE_CHECKING, Any

from observer_node.errors import ObserverError

if TYPE_CHECKING:  # python-can is imported when a bus opens: commands start faster
    import can


class BusOpenError(ObserverError):
    """A bus that does not open; the message is one line naming interface and channel."""


class _Collect(logging.Handler):
    def __init__(self) -> None:
        super().__init__()
        self.records: list[logging.LogRecord] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.records.append(record)


def _one_line(text: str) -> str:
    return " ".join(text.split())


def open_bus(interface: str, channel: str, **kwargs: Any) -> can.BusABC:
    """``can.Bus(interface=interface, channel=channel, **kwargs)``, or :class:`BusOpenError`.
    Warnings python-can logs while opening are kept back and, when it opens, logged as
    usual; when it does not, they end the error's line."""
    import can

    # Backends log under can.* and names of their own ("seeedbus"): hold the root's
    # handlers back meanwhile, so that nothing reaches the terminal before we know.
    root = logging.getLogger()
    collect, handlers = _Collect(), root.handlers[:]
    root.handlers = [collect]
    why = ""
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                bus = can.Bus(interface=interface, channel=channel, **kwargs)
            except Exception as e:  # any backend's failure to open: see above
                said = "; ".join(dict.fromkeys(
                    [_one_line(r.getMessage()) for r in collect.records
                     if r.levelno >= logging.WARNING] +
                    [_one_line(str(w.message)) for w in caught]))
                text = _one_line(str(e)) or "failed"
                kind = "" if isinstance(e, can.CanError | OSError) else f"{type(e).__name__}: "
                why = f"{interface}:{channel}: cannot open: {kind}{text}" + \
                    (f" (python-can: {said})" if said else "")
        if why:
            gc.collect()  # a half-built bus logs from __del__: now, into ``collect``
            raise BusOpenError(why)
    finally:
        root.handlers = handlers
    for r in collect.records:  # it opened: what python-can said goes where it would have
        logging.getLogger(r.name).handle(r)
    for w in caught:
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return bus
