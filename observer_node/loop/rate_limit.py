"""An output whose transducer cannot follow the chest: a reading limited in rate.

An amplifier with too low a slew rate, a tracking converter, or a string pot whose spring
cannot keep its string taut reads a channel that never changes faster than a fixed rate: while
the chest loads faster, the reading climbs as a straight line. The lab's CFC filter, applied
after it, rounds the corners and keeps the flat top of the rate. No effect of the model bends
an output so (its outputs are the chest's), so the fit either takes it as physics or says
nothing of it; added after a held-out set's rate-limited CD got no word at all.

Read on each output of the tests not found broken, from first contact to the scoring window's
end: the rate [unit/ms] as the change over 2 ms, averaged over 2 ms more (else the lab's noise
sets the top), in the direction of the channel's largest excursion; its top; the longest time
it stays within 10 % of that top (the *plateau*, n samples spanning n - 1 intervals). A
chest's rate peaks and falls: on the bundled campaign the plateau lasts at most 3.2 ms (CR)
and 2.5 ms (CD), on the project's simulator (54 clean tests, three seeds) at most 1.3 and
5.7 ms; but a chest whose damping grows with its rate caps it too (a hostile review: 7.5-7.8
ms at 10 kHz, every test of a repeatable series at one rate), so the bar is 10 ms. There a
rate limit of 0.7 mm/ms on CD holds 12.9-24.0 ms, of 1 mm/ms 10.8-16.4 ms, of 1.5 mm/ms
8.3-11.8 ms (found on 8 of 12 tests), of 2 mm/ms 4.2-9.2 (not found); one of 2 g/ms on CR
7.3-9.2 ms (not found) (``tests/test_rate_limit.py``). An output is rate-limited where half
its tests or more, and two or more, hold a plateau of 10 ms or more at tops within 5 % of
their median: one transducer's limit, the same in every test. Where the loop names a kind
whose force grows with the chest's rate, the report says that chest reads alike. Not found:
a limit above most of the chest's rates (a few milliseconds clipped, which also cost the fit
little), or one test's own limit among many (its plateau alone proves little: nothing to
compare it with); a limit on one setup of several, or two amplifiers at different limits
(tops more than 5 % apart); a limit on the channel's fall alone; a limit under noise that
lifts the top rate (twice the simulator's noise on CR at 1.5 g/ms) (a hostile review,
session 64).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..data.crashtest import CrashTest

RATE_MS = 2.0  # the rate is the change over this, averaged over as long again
PLATEAU_BAND = 0.10  # within this share of the top
PLATEAU_MS = 10.0  # held at least this long: a limit, not a peak (a chest's damper: 7.8)
SAME_TOP = 0.05  # the limited tests' tops within this share of their median
UNITS = {"cr": "g", "cd": "mm"}


@dataclass
class RateLimit:
    """An output read through a rate limit: its rate [unit/ms], the tests that show it, the
    setups they belong to, and the shortest and longest plateau [ms]."""

    output: str  # "cr" or "cd"
    rate_per_ms: float
    tests: list[str]
    of_tests: int  # the tests read
    setups: list[str]
    plateau_ms: tuple[float, float]

    def looks_like(self) -> str:
        """The finding in the report's words."""
        o, u = self.output.upper(), UNITS[self.output]
        return (f"a rate limit: in {len(self.tests)} of {self.of_tests} tests {o} climbs at "
                f"a constant {self.rate_per_ms:.2f} {u}/ms for {self.plateau_ms[0]:.0f}-"
                f"{self.plateau_ms[1]:.0f} ms, where a chest's rate peaks and falls: its "
                "transducer or amplifier cannot follow the chest (a slew rate)")

    def reading(self) -> dict:
        """The figures, for report.json."""
        return {"rate_per_ms": round(self.rate_per_ms, 4), "unit": f"{UNITS[self.output]}/ms",
                "tests": self.tests, "of_tests": self.of_tests,
                "plateau_ms": [round(v, 1) for v in self.plateau_ms]}


def plateau(x: np.ndarray, fs_hz: float) -> tuple[float, float]:
    """The top rate [unit/ms] of ``x`` (samples at ``fs_hz``) in the direction of its
    largest excursion, and the longest time [ms] its rate stays within ``PLATEAU_BAND`` of
    it. (0, 0) where ``x`` is too short or does not move."""
    k = max(1, round(RATE_MS * fs_hz / 1000.0))
    if len(x) < 3 * k or not np.all(np.isfinite(x)) or np.ptp(x) == 0:
        return 0.0, 0.0
    sign = np.sign(x[int(np.argmax(np.abs(x - x[0])))] - x[0])
    rate = sign * (x[k:] - x[:-k]) * fs_hz / 1000.0 / k
    rate = np.convolve(rate, np.ones(k) / k, mode="valid")
    top = float(np.max(rate))
    if top <= 0:
        return 0.0, 0.0
    near = np.concatenate([[False], rate >= (1.0 - PLATEAU_BAND) * top, [False]])
    edges = np.flatnonzero(np.diff(near.astype(np.int8)))
    longest = int(np.max(edges[1::2] - edges[::2])) if len(edges) else 0
    # n samples span n - 1 intervals (at 1 kHz, counting n had read a 7.6 ms peak as 8 ms)
    return top, max(longest - 1, 0) * 1000.0 / fs_hz


def rate_limited_outputs(tests: list[CrashTest], end_s: float) -> list[RateLimit]:
    """The outputs of ``tests`` read through one rate limit (see the module's docstring),
    each judged from first contact to ``end_s``."""
    out = []
    for o in ("cr", "cd"):
        seen: list[tuple[CrashTest, float, float]] = []
        for t in tests:
            x = t.cr_g if o == "cr" else t.cd_mm
            if x is None:
                continue
            top, ms = plateau(x[t.index_of(0.0):t.index_of(end_s) + 1], t.fs_hz)
            seen.append((t, top, ms))
        flat = [(t, top, ms) for t, top, ms in seen if ms >= PLATEAU_MS]
        if len(flat) < max(2, (len(seen) + 1) // 2):
            continue
        median = float(np.median([top for _, top, _ in flat]))
        same = [(t, top, ms) for t, top, ms in flat if abs(top / median - 1.0) <= SAME_TOP]
        if len(same) < max(2, (len(seen) + 1) // 2):
            continue
        ms_ = [ms for _, _, ms in same]
        out.append(RateLimit(o, median, [t.name for t, _, _ in same], len(seen),
                             list(dict.fromkeys(t.setup for t, _, _ in same)),
                             (min(ms_), max(ms_))))
    return out
