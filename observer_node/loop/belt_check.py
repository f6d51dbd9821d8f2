"""Whether the final model's belt pushes the sternum, which a belt cannot do.

The thesis grey-box's belt force k2 e + c2 e' (e = w - s) is linear: fitted to a crash whose
rebound it cannot otherwise follow, it may push the chest back by kilonewtons after the peak.
The library's slack belt (``belt_unloading``) stops that; where the loop did not accept it,
this check says how far the model leans on a pushing belt, per judged setup, and what the
slack belt scored there when it was tried, so an engineer reads the model's rebound with
care. It reads the linear belt's force, as the slack belt's switch does: a belt stiffening or
a spool's gain adds to it and is not counted. On the independent held-out sets the identified
belt pushed for 25-59 of a test's 151 ms, by 1.5-3.3 kN, most of it in the rebound, and the
slack belt cost 4-23 points (docs/loop-evidence.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..ident.dataset import Dataset
from ..model.nonlinear import applies, belt_force_n
from .refit import model

if TYPE_CHECKING:  # the report holds the check's results: no import at run time
    from .report import LoopStep

#: a push is reported when on a setup it reaches this share of the belt's largest pull ...
MIN_PUSH_SHARE = 0.10
#: ... for at least this long in each test's fit window on average [ms]
MIN_PUSHING_MS = 5.0
SLACK = "belt_unloading"


@dataclass(frozen=True)
class BeltPush:
    """On one setup's estimation tests: how long the model's belt pushes per test (mean, in
    the fit window) [ms], by how much at most [N], its largest pull [N], the share of the
    pushing time after each test's largest pull (the rebound), and the slack belt's best
    cross-validated gain when the loop tried it [points] (None: not tried there)."""

    setup: str
    tests: int
    pushing_ms: float
    push_n: float
    pull_n: float
    rebound_share: float
    slack_gain_points: float | None

    def as_dict(self) -> dict[str, Any]:
        return {"setup": self.setup, "tests": self.tests, "pushing_ms": self.pushing_ms,
                "push_n": self.push_n, "pull_n": self.pull_n,
                "rebound_share": self.rebound_share,
                "slack_gain_points": self.slack_gain_points}


def belt_pushes(base: dict, effects: list[dict], data: Dataset,
                slack_gains: dict[str, float], skip: set[str] | None = None) -> list[BeltPush]:
    """The setups of ``data`` (but those in ``skip``: the setups the loop does not judge)
    where the model (``base`` and ``effects``) has no slack belt and its belt pushes at least
    ``MIN_PUSH_SHARE`` of its largest pull for at least ``MIN_PUSHING_MS`` per test on
    average, in the fit window. ``slack_gains``: the slack belt's best cross-validated gain
    [points] on each setup's tests. A setup whose simulation ran away is left out (the fits
    say so). The force at sample k is the one acting over tick k, at the state before it."""
    slack = [e for e in effects if e["kind"] == SLACK]
    with np.errstate(all="ignore"):
        force = belt_force_n(model(base, effects, data), data.pulse_g, data.brs_rad)
    win = force[:, data.win]
    ms = 1000.0 / data.fs_hz
    out = []
    for setup in dict.fromkeys(data.setups):
        if setup in (skip or set()) or any(applies(e, setup) for e in slack):
            continue
        rows = [i for i, s in enumerate(data.setups) if s == setup]
        f = win[rows]
        if not np.isfinite(f).all():
            continue
        pushing = f < 0.0
        push, pull = float(-f.min()), float(f.max())
        pushing_ms = float(pushing.sum(axis=1).mean() * ms)
        if pull <= 0.0 or push < MIN_PUSH_SHARE * pull or pushing_ms < MIN_PUSHING_MS:
            continue
        after = sum(int(p[int(np.argmax(x)):].sum()) for p, x in zip(pushing, f, strict=True))
        out.append(BeltPush(setup, len(rows), round(pushing_ms, 1), round(push, 0),
                            round(pull, 0), round(after / max(int(pushing.sum()), 1), 2),
                            slack_gains.get(setup)))
    return out


def slack_gains(history: list[LoopStep]) -> dict[str, float]:
    """The slack belt's best cross-validated gain [points] on each setup's judged tests (the
    mean over that setup's tests, not over all), over every scope and round it was tried."""
    best: dict[str, float] = {}
    for step in history:
        for t in step.tried:
            if t.kind != SLACK:
                continue
            for s, g in t.evidence.setup_gain_points.items():
                best[s] = max(best.get(s, -np.inf), round(g, 2))
    return best
