"""The loop's runner (``observer_node.loop.cluster.Runner``) in the test's own process, and
how a test starts a command as a terminal would."""

from __future__ import annotations

import signal
from collections.abc import Callable
from typing import Any


class InProcess:
    """A cluster of one, each call in turn: one campaign needs no cluster, and an effect a
    test registers exists in its tasks too (a local cluster's worker processes would not
    have it)."""

    workers = 1

    @staticmethod
    def map(f: Callable[..., Any], args: list[tuple]) -> list[Any]:
        return [f(*a) for a in args]


def sigint_default() -> None:
    """A ``preexec_fn``: a terminal's program starts with SIGINT at its default and unblocked.
    A test worker need not be in that state (in a full CI run the loop, started from a worker
    that had run 1300 tests, ran on through the interrupt, which it never saw; alone, and
    after the in-process loop and bench tests, it stops), and an ignored or blocked SIGINT is
    inherited by the worker's children, as nohup wants."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
