"""What both command lines (``observer-node``, ``crash-replay``) share in reading options:
a parser whose errors are one line, number types that refuse nan, inf and values out of
range where argparse reads them, and output paths checked before any work."""

from __future__ import annotations

import argparse
import math
import os
import shutil
import signal
import tempfile
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager, suppress
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


@contextmanager
def staged(out: Path) -> Iterator[Path]:
    """A hidden folder beside ``out`` that a command writes its results into, moved into
    ``out`` only when the command ends well. An interrupted or failed run (Ctrl-C, a full
    disk, bad data found late) leaves ``out`` as it was: no half set of plots and models
    beside an older run's summary. Files of ``out`` the run does not write are kept."""
    out = out.absolute()
    made = [p for p in out.parents if not p.exists()]  # left as they were on failure
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".partial", dir=out.parent))
    except OSError as e:  # named as the user wrote it, not as the hidden folder
        raise OSError(e.errno, e.strerror, str(out)) from None
    try:
        yield tmp
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        for p in made:  # innermost first
            with suppress(OSError):
                p.rmdir()
        raise
    with _sigint_deferred():  # a Ctrl-C now would leave the move half done
        _merge(tmp, out)
        shutil.rmtree(tmp, ignore_errors=True)


def _merge(src: Path, dest: Path) -> None:
    dest.mkdir(parents=True, exist_ok=True)
    for entry in src.iterdir():
        target = dest / entry.name
        if entry.is_dir() and target.is_dir() and not target.is_symlink():
            _merge(entry, target)
            continue
        if target.is_dir() and not target.is_symlink():
            shutil.rmtree(target)  # a folder where this run writes a file (or the reverse)
        elif target.is_symlink() or target.exists():
            target.unlink()
        os.replace(entry, target)


@contextmanager
def _sigint_deferred() -> Iterator[None]:
    """Ctrl-C is held until the block ends, then raised (only the main thread sets it)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pending: list[int] = []
    old = signal.signal(signal.SIGINT, lambda sig, frame: pending.append(sig))
    try:
        yield
    finally:
        if old is not None:
            signal.signal(signal.SIGINT, old)
    if pending:
        raise KeyboardInterrupt


def _can_make(folder: Path, said: str) -> None:
    """One line, starting with ``said``, unless ``folder`` is a folder or can be made one."""
    probe = folder
    while not probe.exists() and probe != probe.parent:
        probe = probe.parent
    if not probe.is_dir():
        raise UsageError(f"{said}: cannot be made: {probe} is a file")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise UsageError(f"{said}: cannot write in {probe} (permission denied)")
