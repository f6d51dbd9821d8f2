"""SAE J211-1 channel frequency class (CFC) filter, as crash labs filter dummy channels."""

from __future__ import annotations

import numpy as np
from scipy import signal


def cfc_min_rate_hz(cfc: float) -> float:
    """The sample rate [Hz] a CFC ``cfc`` filter needs to exceed: twice its design frequency
    (SAE J211-1's 2.0775 * cfc), 748 Hz for CFC 180."""
    return 2 * 2.0775 * cfc


def cfc_filter(x: np.ndarray, fs_hz: float, cfc: float) -> np.ndarray:
    """Phaseless 4-pole CFC filter of SAE J211-1 (Appendix C): a 2-pole Butterworth-like
    section run forward and backward. ``cfc`` is the class (60, 180, 600, 1000). Its design
    frequency 2.0775 * cfc must lie below the Nyquist frequency (fs_hz above
    :func:`cfc_min_rate_hz`); above it the section is unstable: ValueError."""
    if fs_hz <= cfc_min_rate_hz(cfc):
        raise ValueError(f"a CFC {cfc:g} filter needs a sample rate above "
                         f"{cfc_min_rate_hz(cfc):.0f} Hz, not {fs_hz:g} Hz")
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
