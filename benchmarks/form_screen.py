"""Screen a trial effect form before building it: does the held-out cases' truth pass the
loop's rule with it, where the library's form of the same kind does not?

For each case (of the independent held-out sets), the thesis grey-box is identified on its
estimation tests; then the expected structure is judged by the loop's rule against it
(``loop_heldout.by_the_rule``: refitted, cross-validated leave-one-test-out, judged at the
loop's margin of 1 point) twice: with the library's form of the expected kind, and with the
trial form in its place, on the same scope. Printed per form: passes or fails, the mean gain
[points] and tests improved, the validation fit_TOT [%] of the refit, and the trial form's
fitted parameters. Run on cases already seen, a screen says only whether a form is worth
building; held-out sets judge it once built.

Trial forms (registered for the run only, never in the library):

- ``brs_ring``: belt travel R (theta + g theta^2/2 + a sin theta + b (1 - cos theta)): the
  spool's gain with a once-per-revolution error of the BRS ring (an eccentric code ring reads
  the angle off by e/r sin(theta + phi); a, b within +-0.1), for ``input_gain`` cases;
- ``belt_unload_drop``: the one-sided belt whose force also drops by a fraction h (0..0.95)
  while the webbing shortens (a memoryless webbing hysteresis), for ``belt_unloading`` cases;
- ``belt_set_memory``: a webbing with memory: below the largest penetration so far, e_peak,
  the belt's spring follows an unloading line from (e_peak, k2 e_peak) down to zero force at
  the permanent set h e_peak (h 0..0.9), k2 (e - h e_peak) / (1 - h); the belt force (that
  spring plus c2 e') never pushes. For ``belt_unloading`` cases;
- ``belt_set_memory_push``: the same unloading line, the belt force not clipped (a
  diagnostic: does the clip or the memory cost the fit?);
- ``belt_off_chest``: the belt leaves the chest: its whole force k2 e + c2 e' is gone where
  the penetration e < 0 (the webbing off the sternum), whatever its sign where e > 0 (the
  flesh under the belt damps either way while in contact). For ``belt_unloading`` cases;
- ``belt_knee``: a webbing whose stiffness steps up past a knee: kbk max(e - e0, 0) on the
  sternum (e = w - s, the belt penetration; e0 within 5-80 mm, started from the best of a
  grid by the in-sample fit), a bilinear load-elongation curve, for ``belt_stiffening``
  cases. Screened with ``--against airbag_contact`` too: on a bag's cases, does the knee
  pass as the bag does (a mimic in waiting)?

The memory forms keep e_peak across a simulation's ticks in the screen's own closure (one
per form), reset where a simulation starts (the state at rest): the library's forces have no
memory. That holds only where the force is evaluated tick by tick, one simulation at a time,
in one thread: the rule's refits and folds here (``model.nonlinear``'s simulation and
``step``). The loop's candidate signature reads a whole trajectory at once and would see no
memory, and two models stepped side by side would share one peak: these forms are for this
screen, never the loop's rounds. ``belt_set_memory_push`` is not the memory form without its
clip alone: below the peak its spring lies under the grey-box's k2 e by k2 h (e_peak - e) /
(1 - h), so it also pulls less there.

    python -m benchmarks.form_screen --form brs_ring --set z --case hz_eccentric_r16_sled \\
        [--sets DIR] [--against KIND]

``--against KIND`` judges the trial form on the scope of the case's expected KIND instead of
the kind the form stands in for (the library's KIND form beside it).
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from benchmarks.heldout.sets import SETS, select
from benchmarks.loop_heldout import by_the_rule, cases_and_sets
from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop.refit import refit, score
from observer_node.model.effects import EFFECTS, Effect, Kinematics, Param, Search, registered

MARGIN = 1.0  # the loop's default margin [points]


def _ring(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]) -> tuple[Any, Any]:
    th = k.theta
    dw = b["R"] * (p["g"] * th * th / 2 + p["a"] * np.sin(th) + p["b"] * (1 - np.cos(th)))
    dwd = b["R"] * (p["g"] * th + p["a"] * np.cos(th) + p["b"] * np.sin(th)) * k.u2
    return k.zero, b["k2"] * dw + b["c2"] * dwd


def _unload_drop(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]) -> tuple[Any, Any]:
    f = b["k2"] * k.e + b["c2"] * k.ed
    return k.zero, -np.minimum(f, 0.0) - p["h"] * np.maximum(f, 0.0) * (k.ed < 0)


class _Peak:
    """The largest belt penetration e [m] so far in the simulation under way (0 at rest):
    read at every state a tick evaluates, twice the same state changes nothing. Tick by tick
    only (see the module's docstring)."""

    def __init__(self) -> None:
        self.peak: Any = None

    def __call__(self, k: Kinematics) -> Any:
        e = k.e
        at_rest = not (np.any(k.xd) or np.any(k.x) or np.any(k.pos) or np.any(k.d)
                       or np.any(k.dd) or np.any(e))
        if at_rest or self.peak is None or np.shape(self.peak) != np.shape(e):
            self.peak = np.zeros(np.shape(e))
        self.peak = np.maximum(self.peak, e)
        return self.peak


def _set_memory(clip: bool) -> Any:
    peak_of = _Peak()

    def force(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]) -> tuple[Any, Any]:
        peak, e, h = peak_of(k), k.e, p["h"]
        spring = np.where(e < peak, (e - h * peak) / (1 - h), e)
        f = b["k2"] * spring + b["c2"] * k.ed
        if clip:
            f = np.maximum(f, 0.0)
        return k.zero, f - (b["k2"] * e + b["c2"] * k.ed)
    return force


def _knee(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]) -> tuple[Any, Any]:
    return k.zero, p["kbk"] * np.maximum(k.e - p["e0"], 0.0)


def _off_chest(p: Mapping[str, Any], k: Kinematics, b: Mapping[str, float]
               ) -> tuple[Any, Any]:
    return k.zero, -(b["k2"] * k.e + b["c2"] * k.ed) * (k.e < 0.0)


# trial form -> (the library kind it stands in for, its definition, its starting parameters)
FORMS: dict[str, tuple[str, Effect, dict[str, float]]] = {
    "brs_ring": ("input_gain", Effect(
        "trial_brs_ring", "physical", "spool gain with a once-per-revolution BRS ring error",
        (Param("g", "1/rad", 0.02, within=(-0.04, 0.04)),
         Param("a", "1", 0.02, within=(-0.1, 0.1)), Param("b", "1", 0.02, within=(-0.1, 0.1))),
        force=_ring), {"g": 0.0, "a": 0.0, "b": 0.0}),
    "belt_unload_drop": ("belt_unloading", Effect(
        "trial_belt_unload_drop", "physical", "one-sided belt, force lower while unloading",
        (Param("h", "1", 0.3, within=(0.0, 0.95)),), force=_unload_drop), {"h": 0.3}),
    "belt_set_memory": ("belt_unloading", Effect(
        "trial_belt_set_memory", "physical", "webbing unloading to a permanent set, one-sided",
        (Param("h", "1", 0.3, within=(0.0, 0.9)),), force=_set_memory(clip=True)), {"h": 0.3}),
    "belt_set_memory_push": ("belt_unloading", Effect(
        "trial_belt_set_memory_push", "physical", "webbing unloading to a permanent set",
        (Param("h", "1", 0.3, within=(0.0, 0.9)),), force=_set_memory(clip=False)),
        {"h": 0.3}),
    "belt_off_chest": ("belt_unloading", Effect(
        "trial_belt_off_chest", "physical", "no belt force while the belt is off the chest",
        force=_off_chest, search=Search("switch")), {}),
    "belt_knee": ("belt_stiffening", Effect(
        "trial_belt_knee", "physical", "webbing stiffer past a knee in its penetration",
        (Param("kbk", "N/m", 3e4, positive=True),
         Param("e0", "m", 0.03, positive=True, within=(0.005, 0.08))),
        force=_knee, search=Search("grid", "e0", (0.01, 0.02, 0.03, 0.045, 0.06))),
        {"kbk": 3e4, "e0": 0.03}),
}


def _grid_start(form: Effect, start: dict[str, float], where: dict, base: dict,
                est: Any) -> dict[str, float]:
    """A form's start: as given, or the best in-sample of its grid (a knee or a gap fitted
    from one start stays where the gradient is flat; the library's airbag too)."""
    if form.search.method != "grid":
        return start
    best: tuple[float, dict[str, float]] = (-np.inf, start)
    for v in form.search.grid:
        eff = {"kind": form.kind, "parameters": {**start, form.search.over: v}, **where}
        with np.errstate(all="ignore"):
            fit = refit(base, [eff], est, max_nfev=40)
            total = score(fit.base, fit.effects, est).fit.total
        if np.isfinite(total) and total > best[0]:
            best = (total, dict(fit.effects[0]["parameters"]))
    return best[1]


def screen(form: str, case_set: str, names: list[str], sets: Path,
           against: str | None = None) -> None:
    kind, trial, start = FORMS[form]
    kind = against or kind
    print(f"{'case':<28}{'form':<24}{'rule':<18}{'val %':>7}  parameters", flush=True)
    for case in select(names, case_set):
        expected = [(k, s) for k, s in case.expect if k == kind]
        if not expected:
            print(f"{case.name:<28}expects no {kind}: skipped", flush=True)
            continue
        est = make_dataset([t for t in load_tests([sets / case.name / "est"])
                            if t.name not in case.expect_broken], 1000.0)
        val = make_dataset(load_tests([sets / case.name / "val"]), 1000.0)
        base = dict(greybox.fit_greybox(est).params)
        rig_setup = dict(zip([n.split("_")[0] for n in est.names], est.setups, strict=True))
        scope = expected[0][1]
        where = {} if scope == "all" else {
            "setups": sorted({rig_setup[r] for r in scope.split("+") if r in rig_setup})}
        with registered(trial):
            first = _grid_start(trial, start, where, base, est)
            lib = _grid_start(EFFECTS[kind], dict(EFFECTS[kind].typical), where, base, est)
            for label, effect in ((kind, {"kind": kind, "parameters": lib, **where}),
                                  (form, {"kind": trial.kind, "parameters": first, **where})):
                ev, fit = by_the_rule(base, [effect], est, MARGIN)
                with np.errstate(all="ignore"):
                    val_fit = score(fit.base, fit.effects, val).fit.total
                rule = ("passes" if ev.accepted else "fails") + \
                    f" {ev.gain_points:+.1f} {ev.tests_improved}/{ev.tests}"
                params = {k: round(float(v), 4) for k, v in fit.effects[0]["parameters"].items()}
                print(f"{case.name:<28}{label:<24}{rule:<18}{val_fit:7.1f}  {params or ''}",
                      flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--form", choices=FORMS, required=True, help="the trial form")
    ap.add_argument("--set", dest="case_set", choices=SETS, required=True)
    ap.add_argument("--case", dest="cases", action="append", metavar="NAME", required=True)
    ap.add_argument("--sets", type=Path, help="the generated sets (default: generated into a "
                    "temporary folder)")
    ap.add_argument("--against", choices=sorted(EFFECTS), help="judge the form on this "
                    "expected kind's scope instead (a rival's cases)")
    a = ap.parse_args()
    _, sets = cases_and_sets("form_screen", a.case_set, a.cases, a.sets)
    screen(a.form, a.case_set, a.cases, sets, a.against)


if __name__ == "__main__":
    main()
