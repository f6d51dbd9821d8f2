"""Crash tests turned into identification data: several experiments on one time base."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..data.crashtest import THESIS_WINDOW_S, CrashDataError, CrashTest


@dataclass
class Dataset:
    """Experiments resampled to ``fs_hz`` and cut to t = 0 .. window end.

    Simulations start from rest at t = 0 (first contact); the fit is scored on samples
    ``win`` (the thesis window, 0.01..0.15 s by default). Arrays are (tests, n).
    """

    names: list[str]
    setups: list[str]
    fs_hz: float
    pulse_g: np.ndarray
    brs_rad: np.ndarray
    y: np.ndarray  # (tests, n, 2): cr_g, cd_mm
    win: slice
    window_s: tuple[float, float]

    @property
    def n_tests(self) -> int:
        return len(self.names)

    def subset(self, idx: list[int]) -> Dataset:
        return Dataset([self.names[i] for i in idx], [self.setups[i] for i in idx], self.fs_hz,
                       self.pulse_g[idx], self.brs_rad[idx], self.y[idx], self.win, self.window_s)


def make_dataset(tests: list[CrashTest], fs_hz: float = 1000.0,
                 window_s: tuple[float, float] = THESIS_WINDOW_S) -> Dataset:
    """Resample each test as the bus would (causal anti-alias on the pulse, ZOH on the BRS),
    remove the pulse bias (pre-contact mean), convert BRS counts to spindle angle."""
    if not tests:
        raise CrashDataError("no crash tests given")
    start, end = 0.0, window_s[1]
    n = round((end - start) * fs_hz) + 1
    i0 = round((window_s[0] - start) * fs_hz)
    pulses, brss, ys = [], [], []
    for t in tests:
        if not t.has_outputs:
            raise CrashDataError(f"{t.source or t.name}: identification needs CR and CD channels")
        if t.counts_per_rev is None:
            raise CrashDataError(f"{t.source or t.name}: counts/rev of the BRS is unknown "
                                 "(its counts cannot be turned into an angle): give it with "
                                 "--counts-per-rev or in the .mme Comments ('96 counts/rev')")
        if t.t0_s > start + 1e-9 or t.time_s[-1] < end - 1e-9:
            raise CrashDataError(
                f"{t.source or t.name}: covers {t.t0_s:.3f}..{t.time_s[-1]:.3f} s, "
                f"needs {start:.3f}..{end:.3f} s"
            )
        bias = t.pulse_bias_g()
        if t.cr_g is None or t.cd_mm is None:
            raise CrashDataError(f"{t.source or t.name}: no CR/CD channels to identify on")
        r = t.resample(fs_hz)
        i = r.index_of(start)
        if r.n - i < n:
            raise CrashDataError(f"{t.source or t.name}: too short after resampling")
        sl = slice(i, i + n)
        pulses.append(r.pulse_g[sl] - bias)
        brss.append(r.brs[sl] * (2 * np.pi / t.counts_per_rev))
        assert r.cr_g is not None and r.cd_mm is not None  # resampled from t's outputs
        y = np.column_stack([r.cr_g[sl], r.cd_mm[sl]])
        inputs = (("crash pulse", pulses[-1][i0:]), ("BRS", brss[-1][i0:]))
        for label, out in (*inputs, *zip(("CR", "CD"), y[i0:].T, strict=True)):
            # an output: eq. 3.15 divides by its spread, every fit would be NaN; an input: no
            # crash drives the model, and a fit would keep its start values as a result
            if np.ptp(out) == 0:
                raise CrashDataError(
                    f"{t.source or t.name}: {label} is constant over the scoring window "
                    f"{window_s[0]:g}..{window_s[1]:g} s (a dead or disconnected channel): "
                    f"no fit can be made or scored on it: leave the test out "
                    "(--skip-bad-tests)")
        ys.append(y)
    return Dataset([t.name for t in tests], [t.setup for t in tests], fs_hz, np.array(pulses),
                   np.array(brss), np.array(ys), slice(i0, n), window_s)
