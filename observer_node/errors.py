"""The one base of every error a user can cause: bad input (a test, model, config or recording
that cannot be used), an option that cannot be used, a bus or cluster that cannot be had.

Each command line (``observer-node``, ``crash-replay``) catches :class:`ObserverError` once and
ends with its message as one line, ``PROG: error: MESSAGE``, and its ``exit_code``: never a
traceback. The specific errors also keep the built-in base they had (``ValueError``, ...), so
code that catches those still does.
"""

from __future__ import annotations


def one_line(text: str) -> str:
    """``text`` as one printable line: a control character (a newline or a carriage return in
    a file's name, say) written as its escape, so that no name can forge a line of its own."""
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii")
                   for c in text)


class ObserverError(Exception):
    """An error the command reports as one line; the message names the file or option."""

    exit_code: int = 2  # bad input, or what the command needs cannot be had


class UsageError(ObserverError, ValueError):
    """A command-line value that cannot be used; the message names the option."""


class RecordingLostError(ObserverError):
    """``run`` ran, but its recording is not the whole run (parts, ticks and frames lost)."""

    exit_code = 3


class Terminated(KeyboardInterrupt):
    """SIGTERM (systemd, ``kill``, a CI's timeout) raised as Ctrl-C is, so that what an
    interrupted command cleans up (a half-written output folder) is cleaned up on it too;
    the command ends with one line, exit code 143 (128 + 15), as a shell reports it."""
