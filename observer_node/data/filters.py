"""SAE J211-1 channel frequency class (CFC) filter, as crash labs filter dummy channels."""

from __future__ import annotations

import numpy as np
from scipy import signal


def cfc_filter(x: np.ndarray, fs_hz: float, cfc: float) -> np.ndarray:
    """Phaseless 4-pole CFC filter of SAE J211-1 (Appendix C): a 2-pole Butterworth-like
    section run forward and backward. ``cfc`` is the class (60, 180, 600, 1000)."""
    T = 1.0 / fs_hz
    wd = 2 * np.pi * cfc * 2.0775
    wa = np.sin(wd * T / 2) / np.cos(wd * T / 2)
    den = 1 + np.sqrt(2) * wa + wa**2
    a0 = wa**2 / den
    b = [a0, 2 * a0, a0]
    # J211 writes y[n] = a0 x[n] + a1 x[n-1] + a2 x[n-2] + b1 y[n-1] + b2 y[n-2];
    # scipy's denominator is [1, -b1, -b2].
    a = [1.0, 2 * (wa**2 - 1) / den, (1 - np.sqrt(2) * wa + wa**2) / den]
    # filtfilt pads each end with 3 * 3 samples by default and refuses anything not longer:
    # a short record (an event cut after a few ticks) is padded with what it has.
    n = len(x)
    return signal.filtfilt(b, a, x, padtype="constant" if n < 10 else "odd",
                           padlen=min(9, max(n - 1, 0)))
