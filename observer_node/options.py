"""What both command lines (``observer-node``, ``crash-replay``) share in reading options:
a parser whose errors are one line, number types that refuse nan, inf and values out of
range where argparse reads them, and output paths checked before any work."""

from __future__ import annotations

import argparse
import errno
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

from .errors import ObserverError, UsageError


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


def number_in(low: float, high: float, unit: str = "") -> Callable[[str], float]:
    """An argparse type: a finite number from ``low`` to ``high`` (``unit`` said after)."""
    def parse(text: str) -> float:
        x = finite(text)
        if not low <= x <= high:
            raise argparse.ArgumentTypeError(f"wants {low:g} to {high:g}{unit}: {text!r}")
        return x
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
    if not path.strip():
        raise UsageError(f"{option}: empty (say '.' for the current folder)")
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise UsageError(f"{option} {path}: is a file")
    if p.is_symlink() and not p.exists():
        raise UsageError(f"{option} {path}: a link to {os.readlink(p)}, which does not exist")
    _can_make(p, f"{option} {path}")
    return p


class OutputClash(ObserverError):
    """The results cannot go into the output folder as they are (a folder where a file goes,
    a folder not writable): nothing was moved, the results wait in their hidden folder."""


@contextmanager
def staged(out: Path) -> Iterator[Path]:
    """A hidden folder inside ``out`` (``.partial-*``) that a command writes its results into,
    moved into ``out`` only when the command ends well. An interrupted or failed run (Ctrl-C,
    SIGTERM, a full disk, bad data found late) leaves ``out`` as it was, and folders made for
    it are removed: no half set of plots and models beside an older run's summary. Files of
    ``out`` the run does not write are kept; one it would write over with another kind (a
    folder where a file goes) stops the move before anything is moved, naming both."""
    out = Path(os.path.abspath(out))  # "new/.." is the folder itself, as mkdir reads it
    made = [p for p in (out, *out.parents) if not p.exists()]  # removed again on failure
    try:
        out.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=".partial-", dir=out))
    except OSError as e:  # named as the user wrote it, not as the hidden folder
        _remove_empty(made)
        raise OSError(e.errno, e.strerror, str(out)) from None
    try:
        yield tmp
    except BaseException as e:
        shutil.rmtree(tmp, ignore_errors=True)
        _remove_empty(made)
        _named_in_out(e, tmp, out)
        raise
    with _sigint_deferred():  # a Ctrl-C now would leave the move half done
        _check_fits(tmp, out, tmp)
        try:
            _merge(tmp, out)
        except OSError as e:
            raise OSError(e.errno, f"{e.strerror}; what was not moved is in {tmp}",
                          e.filename) from None
        shutil.rmtree(tmp, ignore_errors=True)


def _named_in_out(e: BaseException, tmp: Path, out: Path) -> None:
    """The error names the file it failed on as the user will look for it (in ``out``, not
    in the hidden folder that is gone), and a full disk whose write named no file names
    ``out`` (session 58's hostile user: "No space left on device", no file said)."""
    def moved(x: object) -> object:
        return x.replace(str(tmp), str(out)) if isinstance(x, str) else x
    if isinstance(e, OSError):
        if e.filename is None and e.errno is not None:
            e.filename = str(out)
        e.filename, e.filename2 = moved(e.filename), moved(e.filename2)
    elif isinstance(e, ObserverError):
        e.args = tuple(moved(a) for a in e.args)


def _remove_empty(folders: list[Path]) -> None:
    for p in folders:  # innermost first
        with suppress(OSError):
            p.rmdir()


def _check_fits(src: Path, dest: Path, tmp: Path) -> None:
    """OutputClash unless every result of ``src`` can go to its place in ``dest``."""
    if not os.access(dest, os.W_OK | os.X_OK):
        raise OutputClash(f"{dest}: cannot write in it (permission denied); the results are "
                          f"in {tmp}")
    for entry in src.iterdir():
        target = dest / entry.name
        if entry.is_dir() and not entry.is_symlink():
            if target.is_dir():  # a folder, or a link to one: the results go inside
                _check_fits(entry, target, tmp)
            elif target.exists():
                raise OutputClash(f"{target}: a file where this run writes a folder; nothing "
                                  f"was moved, the results are in {tmp}")
        elif target.is_dir():
            raise OutputClash(f"{target}: a folder where this run writes a file; nothing was "
                              f"moved, the results are in {tmp}")


def _merge(src: Path, dest: Path) -> None:
    for entry in src.iterdir():
        target = dest / entry.name
        if entry.is_dir() and target.is_dir():
            _merge(entry, target)
        else:
            _move(entry, target)


def _move(entry: Path, target: Path) -> None:
    """``entry`` to ``target`` (a file there replaced whole), across file systems too: a
    folder inside --out may be a link to another disk."""
    try:
        os.replace(entry, target)
        return
    except OSError as e:
        if e.errno != errno.EXDEV:
            raise
    if entry.is_dir():
        shutil.copytree(entry, target, symlinks=True)
        return
    fd, tmp_name = tempfile.mkstemp(prefix=".partial-", dir=target.parent)
    os.close(fd)
    try:  # copied beside, then renamed: a full disk keeps the old file whole
        shutil.copy2(entry, tmp_name)
        os.replace(tmp_name, target)
    except BaseException:
        with suppress(OSError):
            os.unlink(tmp_name)
        raise


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
