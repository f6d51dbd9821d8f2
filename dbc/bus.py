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

The options that name a bus (``--interface``, ``--channel``, ``--fd``) are declared here once,
for every command that opens one (``observer-node run`` and ``bench``, ``crash-replay``).
"""

from __future__ import annotations

import argparse
import gc
import logging
import warnings
from typing import TYPE_CHECKING, Any

from observer_node.errors import ObserverError

if TYPE_CHECKING:  # python-can is imported when a bus opens: commands start faster
    import can


DEFAULT_INTERFACE = "socketcan"
DEFAULT_CHANNEL = "vcan0"


def add_bus_arguments(parser: argparse.ArgumentParser, *, interface: str = DEFAULT_INTERFACE,
                      channel: str = DEFAULT_CHANNEL, fd: bool = True, unset: bool = False,
                      interface_note: str = "") -> None:
    """``--interface`` and ``--channel`` (and ``--fd`` if ``fd``) in the group "CAN bus".

    ``interface``, ``channel``: the defaults. ``unset``: an option not given parses as None
    (a config file may set it; the caller applies the default), its help still shows the
    default. ``interface_note``: what else the command takes for an interface (", or ...")."""
    g = parser.add_argument_group("CAN bus")
    shown = {"interface": interface, "channel": channel} if unset else \
        {"interface": "%(default)s", "channel": "%(default)s"}
    g.add_argument("--interface", default=None if unset else interface,
                   help=f"python-can interface{interface_note} (default {shown['interface']})")
    g.add_argument("--channel", default=None if unset else channel,
                   help=f"bus channel (default {shown['channel']})")
    if fd:
        g.add_argument("--fd", action="store_true", default=None if unset else False,
                       help="a CAN FD bus (frames of up to 64 bytes)")


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
