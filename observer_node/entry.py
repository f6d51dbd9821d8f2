"""The entry points of the two commands, ``observer-node`` and ``crash-replay``.

Kept apart from the commands and light: the commands import numpy, scipy, numba and
python-can, a second or more on a bench PC, and a Ctrl-C or SIGTERM during that is one line
too, not a page of traceback from inside an import. SIGTERM is raised as
:class:`~observer_node.errors.Terminated` (a KeyboardInterrupt) so that it cleans up as
Ctrl-C does; once the command has returned, further signals are ignored while the process
winds down (threads and workers otherwise print "Exception ignored" pages as they stop).
"""

from __future__ import annotations

import signal
import sys
from collections.abc import Callable

from .errors import Terminated


def _terminate(_signum: int, _frame: object) -> None:
    raise Terminated


def _run(prog: str, load: Callable[[], Callable[[], int]]) -> int:
    signal.signal(signal.SIGTERM, _terminate)
    try:
        code = load()()
    except KeyboardInterrupt as e:  # while loading: the command's own main catches later
        code = stopped(prog, e)
    # Done, or stopped: a later signal would only break the wind-down, and in the
    # interpreter's teardown (handlers back at their defaults) a second SIGTERM after a
    # clean stop of `run` ended it with 143 and no line (a hostile user's find, session 59)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    return code


def stopped(prog: str, e: KeyboardInterrupt) -> int:
    """Say in one line that ``prog`` was stopped; its exit code, 130 on Ctrl-C, 143 on
    SIGTERM (128 + the signal, as a shell reports it)."""
    term = isinstance(e, Terminated)
    print(f"{prog}: {'terminated' if term else 'interrupted'}", file=sys.stderr)
    return 143 if term else 130


def observer_node() -> int:
    def load() -> Callable[[], int]:
        from .cli import main
        return main
    return _run("observer-node", load)


def crash_replay() -> int:
    def load() -> Callable[[], int]:
        from .replay.cli import entry
        return entry
    return _run("crash-replay", load)
