"""Progress for long fits, on stderr: one rewritten line on a terminal, a line every few
seconds in a log."""

from __future__ import annotations

import sys
import time


class Progress:
    def __init__(self, label: str, enabled: bool = True, every_s: float = 2.0):
        self.label = label
        self.enabled = enabled
        self.tty = sys.stderr.isatty()
        self.every_s = every_s if not self.tty else 0.1
        self.t0 = time.monotonic()
        self._last = 0.0

    def update(self, text: str) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if now - self._last < self.every_s:
            return
        self._last = now
        line = f"{self.label}: {text} [{now - self.t0:.1f} s]"
        if self.tty:
            sys.stderr.write("\r\033[K" + line)
        else:
            sys.stderr.write(line + "\n")
        sys.stderr.flush()

    def note(self, text: str) -> None:
        """A line that stays (a warning): never throttled, never overwritten."""
        if not self.enabled:
            return
        line = f"{self.label}: {text}"
        sys.stderr.write(("\r\033[K" if self.tty else "") + line + "\n")
        sys.stderr.flush()

    def done(self, text: str = "done") -> None:
        if not self.enabled:
            return
        line = f"{self.label}: {text} [{time.monotonic() - self.t0:.1f} s]"
        sys.stderr.write(("\r\033[K" if self.tty else "") + line + "\n")
        sys.stderr.flush()
