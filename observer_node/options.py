"""What both command lines (``observer-node``, ``crash-replay``) share in reading options:
a parser whose errors are one line, number types that refuse nan, inf and values out of
range where argparse reads them, and output paths checked before any work."""

from __future__ import annotations

import argparse
import math
import os
from collections.abc import Callable
from pathlib import Path
from typing import NoReturn

from .errors import UsageError


class OneLineParser(argparse.ArgumentParser):
    """argparse's parser with its errors one line, ``PROG: error: MESSAGE``, exit code 2, as
    every other error of the command (no usage block above it: --help has that)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def finite(text: str) -> float:
    """An argparse type: a finite number (nan and inf would pass ``float`` and fail far on)."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return x


def positive(text: str) -> float:
    """An argparse type: a finite number above zero."""
    x = finite(text)
    if x <= 0:
        raise argparse.ArgumentTypeError(f"must be above zero: {text!r}")
    return x


def non_negative(text: str) -> float:
    """An argparse type: a finite number, zero or above."""
    x = finite(text)
    if x < 0:
        raise argparse.ArgumentTypeError(f"must be zero or above: {text!r}")
    return x


def _whole(text: str, low: int) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if n < low:
        raise argparse.ArgumentTypeError(f"must be {low} or more: {text!r}")
    return n


def int_in(low: int, high: int) -> Callable[[str], int]:
    """An argparse type: a whole number from ``low`` to ``high``."""
    def parse(text: str) -> int:
        n = _whole(text, low)
        if n > high:
            raise argparse.ArgumentTypeError(f"must be {high} or less: {text!r}")
        return n
    return parse


def positive_int(text: str) -> int:
    """An argparse type: a whole number above zero."""
    return _whole(text, 1)


def non_negative_int(text: str) -> int:
    """An argparse type: a whole number, zero or above."""
    return _whole(text, 0)


def out_file(path: str, option: str = "--out") -> Path:
    """``path`` as an output file, checked before any work: not a folder, and its folder is
    one or can be made (see :func:`out_folder`)."""
    p = Path(path)
    if p.is_dir() or not p.name:
        raise UsageError(f"{option} {path}: is a folder; give a file name")
    _can_make(p.parent, f"{option} {path}")
    return p


def out_folder(path: str, option: str = "--out") -> Path:
    """``path`` as an output folder, checked before any work: it is a folder or can be made
    one (the nearest existing parent a writable folder). Not created here, so a command that
    fails on its input leaves nothing behind."""
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise UsageError(f"{option} {path}: is a file")
    _can_make(p, f"{option} {path}")
    return p


def _can_make(folder: Path, said: str) -> None:
    """One line, starting with ``said``, unless ``folder`` is a folder or can be made one."""
    probe = folder
    while not probe.exists() and probe != probe.parent:
        probe = probe.parent
    if not probe.is_dir():
        raise UsageError(f"{said}: cannot be made: {probe} is a file")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise UsageError(f"{said}: cannot write in {probe} (permission denied)")
