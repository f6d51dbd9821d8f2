"""The run's recording: its format (topics, fields, schemas: :mod:`.format`), the daemon's
writer (:mod:`.writer`), the reader (:mod:`.reader`) and the analysis after the run
(:mod:`.analysis`). Loaded lazily, so the daemon's import of the writer does not load the
analysis."""

from __future__ import annotations

from typing import Any

_WHERE = {"analyze": "analysis", "offline_estimates": "analysis", "Recording": "reader",
          "RecordingError": "reader", "Scan": "reader", "check_mcap": "reader",
          "read_recording": "reader"}
__all__ = sorted(_WHERE)


def __getattr__(name: str) -> Any:
    if name in _WHERE:
        import importlib

        return getattr(importlib.import_module(f".{_WHERE[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
