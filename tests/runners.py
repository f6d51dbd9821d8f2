"""The loop's runner (``observer_node.loop.cluster.Runner``) in the test's own process."""

from __future__ import annotations

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
