"""A small ISO-MME (ISO/TS 13499) writer: ``<TEST>/<TEST>.mme``, ``Channel/<TEST>.chn`` and
``Channel/<TEST>.NNN``; ISO-8859-1, CRLF, keys padded to column 28, NOVALUE for missing."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


@dataclass
class Channel:
    code: str  # 16-character ISO code
    text: str  # name of the channel
    unit: str
    dimension: str  # AC, AN, DS
    direction: str
    cfc: str  # "180", "600" or "NOVALUE" (unfiltered)
    values: np.ndarray


@dataclass
class Test:
    name: str
    mme: dict[str, str]  # test-level keys in the order written (channels are appended)
    channels: list[Channel] = field(default_factory=list)
    t0_s: float = -0.020
    dt_s: float = 1e-4


def _line(key: str, value: str) -> str:
    return f"{key:<28}:{value}\r\n"


def _write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(text.encode("iso-8859-1"))


def write_test(test: Test, folder: Path) -> Path:
    """Write ``test`` under ``folder/<name>``; returns that folder."""
    root = folder / test.name
    head = "".join(_line(k, v) for k, v in test.mme.items())
    head += _line("Number of channels", str(len(test.channels)))
    names = "".join(_line(f"Name of channel {i:03d}", f"{c.code} / {c.text}")
                    for i, c in enumerate(test.channels, start=1))
    _write(root / f"{test.name}.mme", head + names)
    _write(root / "Channel" / f"{test.name}.chn",
           _line("Instrumentation standard", "SAEJ211") + names)
    for i, c in enumerate(test.channels, start=1):
        v = np.asarray(c.values, dtype=float)
        imax, imin = int(np.argmax(v)), int(np.argmin(v))
        hdr = {
            "Channel code": c.code, "Laboratory channel code": c.code,
            "Customer channel code": "NOVALUE", "Reference channel": "implicit",
            "Reference channel name": "NOVALUE", "Data source": "transducer",
            "Test object number": c.code[0] if c.code[0].isalpha() else "1",
            "Name of the channel": c.text, "Location": c.code, "Direction": c.direction,
            "Pre-filter type": "4000", "Channel frequency class": c.cfc,
            "Cut off frequency": "NOVALUE", "Reference system": "local",
            "Sampling interval": f"{test.dt_s:.6E}", "Unit": c.unit,
            "Time of first sample": f"{test.t0_s:.6E}", "Number of samples": str(len(v)),
            "First global maximum value": f"{v[imax]:.6E}",
            "Time of maximum value": f"{test.t0_s + imax * test.dt_s:.6E}",
            "First global minimum value": f"{v[imin]:.6E}",
            "Time of minimum value": f"{test.t0_s + imin * test.dt_s:.6E}",
            "Dimension": c.dimension, "Data status": "ok",
        }
        body = "".join(f"{x:.6E}\r\n" for x in v)
        _write(root / "Channel" / f"{test.name}.{i:03d}",
               "".join(_line(k, val) for k, val in hdr.items()) + body)
    return root
