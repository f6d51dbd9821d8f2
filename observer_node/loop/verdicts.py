"""Whether an effect that passes the rule is named: its scope against a wider one, its
runner-up and a tie with it (looked past, :func:`~.evidence.past_the_tie`), a parameter held at
the edge of its physical range, the validation tests' refusal; and the warnings an accepted
effect's parameters carry. Plain functions over the rule's evidence: the loop
(:mod:`.closed_loop`) calls them in that order."""

from __future__ import annotations

from collections.abc import Set as AbstractSet

import numpy as np

from ..ident.metrics import Fits, FitTable
from ..model.effects import EFFECTS
from .analysis import DELAY_MAX_S, Candidate, scope_label
from .evidence import Evidence, PastTheTie, beats, over_the_bar
from .refit import finite
from .report import OtherScope, RunnerUp, SetupValidation


def defended_scope(passing: list[tuple[float, Candidate, Evidence]],
                   per_test: dict[int, dict[str, float]], thin: AbstractSet[str] = frozenset(),
                   est_setups: list[str] | None = None
                   ) -> tuple[tuple[float, Candidate, Evidence], str]:
    """The best passing candidate, or the same effect on a wider scope that passes too when
    the narrower one does not beat it test by test above the scatter: "on these setups only"
    is a claim the data must defend like the effect itself. Also the narrower scope given up
    ("" when none). ``passing``: (cv fit_TOT [%], candidate, evidence), best first;
    ``per_test``: each candidate's per-test cross-validated fit_TOT [%] by ``id``.

    Where the two scopes differ only on ``thin`` setups (too few estimation tests to judge,
    ``est_setups`` being every setup of them), neither claims anything the data can defend
    there: the better cross-validated fit keeps its scope (set L: the scatter test over one
    test of a rig kept a chest stiffening on it that the test's fit refused by 12 points)."""
    best = passing[0][1]
    for entry in passing[1:]:
        c = entry[1]
        wider = best.setups is not None and (c.setups is None or set(best.setups) < set(c.setups))
        if not wider or c.kind != best.kind:
            continue
        wide = (est_setups or []) if c.setups is None else c.setups
        extra = set(wide) - set(best.setups or [])
        if extra and extra <= thin:
            continue
        if not beats(per_test[id(best)], per_test[id(c)])[0]:
            return entry, scope_label(best.setups)
    return passing[0], ""


def runner_up_of(tried: list[tuple[float, Candidate, Evidence]],
                 per_test: dict[int, dict[str, float]], margin_points: float
                 ) -> tuple[RunnerUp | None, float | None, OtherScope | None]:
    """The runner-up (the best of another kind that passes the rule, else the best that fails
    it on the scatter alone, its mean over the bar ``margin_points``, else the best of another
    kind: a weaker one must not hide a rival), whether the winner beats it test by test above
    the scatter and whether it passes the rule itself, the margin
    [points] to it, and the winner on its other scope; ``tried``: (cv fit_TOT [%],
    candidate, its evidence), the winner first; ``per_test``: each candidate's per-test
    cross-validated fit_TOT [%] by ``id``."""
    cv_best, best, _ = tried[0]
    runner_up, margin, other_scope = None, None, None
    others = [(cv, c, ev) for cv, c, ev in tried if c.kind != best.kind]
    near = [o for o in others if over_the_bar(o[2], margin_points)]
    other = next((o for o in others if o[2].accepted),
                 near[0] if near else others[0] if others else None)
    if other is not None:
        told_apart, better = beats(per_test[id(best)], per_test[id(other[1])])
        runner_up = RunnerUp(other[1].kind, scope_label(other[1].setups), round(other[0], 2),
                             told_apart, better, other[2].accepted,
                             over_the_bar(other[2], margin_points))
        margin = round(cv_best - other[0], 2)
    scope = next(((cv, c) for cv, c, _ in tried if c.kind == best.kind and c is not best),
                 None)
    if scope is not None:
        other_scope = OtherScope(scope_label(scope[1].setups), round(scope[0], 2),
                                 round(cv_best - scope[0], 2))
    return runner_up, margin, other_scope


def untold(kind: str, runner_up: RunnerUp | None, n_tests: int) -> str | None:
    """Why ``kind`` cannot be named on the test-by-test comparison alone: its runner-up of
    another kind passes the rule too, or fails it on the scatter alone (since 2026-11-30), and
    ``kind`` does not beat it above the scatter (None when it does, or the runner-up is
    weaker). Named with a "?" until 2026-11-25 (of
    five such names on held-out sets D and E, three were effects not there: a coin flip);
    then not named at all, which cost three right names on set G and two of the library's
    held-out cases (docs/loop-evidence.md). Since then the loop looks past the tie
    (:func:`~observer_node.loop.evidence.past_the_tie`): each effect beside the other."""
    if runner_up is None or not runner_up.rival:
        return None
    return (f"the data cannot tell it from {runner_up.kind} on {runner_up.scope}, which "
            f"{runner_up.standing} ({kind} fits better on {runner_up.tests_better} of {n_tests} "
            "estimation tests, not above the scatter)")


def untold_from_sensor(c: Candidate, ev: Evidence, output: str, sensor: Evidence
                       ) -> str | None:
    """Why the physical effect ``c`` (its evidence ``ev``) that wins a round cannot be named
    when a sensor correction of ``output`` (``sensor``) passes the rule too: it does not beat
    that correction test by test above the scatter, as it must beat a physical rival, so the
    data cannot tell the chest from that output's transducer (set F: a rib stiffening
    named for a CD transducer compressing, +2.71 against +2.69 points). None when it does."""
    told_apart, better = beats(ev.test_gain_points, sensor.test_gain_points)
    if told_apart:
        return None
    return (f"{c.kind} on {scope_label(c.setups)} passes the rule, but does not beat a sensor "
            f"correction of {output} test by test above the scatter ({ev.gain_points:+.2f} "
            f"against {sensor.gain_points:+.2f} points, better on {better} of {ev.tests} "
            f"tests): the chest or the {output} transducer, the data cannot tell")


def tie_verdict(a: Candidate, b: Candidate, past: PastTheTie) -> str:
    """One line on a tie looked past: what each effect adds beside the other, and what
    the data then defend."""
    def beside(x: Candidate, y: Candidate, ev: Evidence) -> str:
        return (f"beside {y.kind}, {x.kind} gains {ev.gain_points:+.2f} points "
                f"({ev.tests_improved} of {ev.tests} tests)"
                + (", passing the rule" if ev.accepted else ""))
    a_on, b_on = f"{a.kind} on {scope_label(a.setups)}", f"{b.kind} on {scope_label(b.setups)}"
    if past.over_bar:
        won, lost = (a_on, b.kind) if past.named == "a" else (b_on, a.kind)
        verdict = (f"{won} explains what {lost} did, not the reverse: over the bar beside it, "
                   f"though not above the scatter, where {lost} adds nothing beside it"
                   + (f"; {lost} acts on other setups and is judged again beside it"
                      if past.apart else ""))
    elif past.apart and past.named in ("a", "b"):
        won, lost = (a_on, b_on) if past.named == "a" else (b_on, a_on)
        verdict = (f"{won} passes beside {lost}, which acts on other setups and is judged "
                   "again beside it")
    else:
        verdict = {"a": f"{a_on} explains what {b.kind} did, not the reverse",
                   "b": f"{b_on} explains what {a.kind} did, not the reverse",
                   "both": "the data defend both",
                   "": "neither explains the other away"}[past.named]
    return (f"looked past the tie: {beside(a, b, past.a_beside_b)}; "
            f"{beside(b, a, past.b_beside_a)}: {verdict}")


# An input delay with both inputs late alike is the same, to the model, as both outputs early:
# the dummy's own timing, not the car's sensors. When only one output gains from it, that
# output's transducer (or its filter) lags (set O: an oil-damped spine accelerometer, CR 4 ms
# late, fitted as both inputs 2.7 and 2.4 ticks late; CR gained 2.4 points in-sample, CD 0.4).
# A real input delay is on one input: on sets G-O the other input's fitted delay stayed under
# 0.4 ticks, and CD gained 0.24-0.72 of CR's gain (half, typically); a lone output's lag
# leaves the other nothing but the refit's spill-over.
COMMON_TICKS = 0.5  # both inputs delayed within this of each other: alike
ONE_OUTPUT = 0.25  # the other output gains less than this share of the first's: one output


def output_lag(kind: str, params: dict, gain_cr: float, gain_cd: float) -> str | None:
    """The output ("cr" or "cd") whose transducer lags, when the effect that passed is an input
    delay of both inputs alike (at least one tick each) whose fit gained [points] in that output
    only; None otherwise."""
    if kind != "input_delay":
        return None
    n_pulse, n_brs = (float(params.get(n, 0.0)) for n in ("n_pulse", "n_brs"))
    if min(n_pulse, n_brs) < 1.0 or abs(n_pulse - n_brs) > COMMON_TICKS:
        return None
    out, hi, lo = ("cr", gain_cr, gain_cd) if gain_cr >= gain_cd else ("cd", gain_cd, gain_cr)
    return out if hi > 0 and lo < ONE_OUTPUT * hi else None


EDGE = 0.01  # of a parameter's physical range: a fit this near its edge is held there


def at_delay_bound(ms: float) -> bool:
    """A delay [ms] at the largest searched (within the refinement's 0.05 ms)."""
    return ms >= 1000.0 * DELAY_MAX_S - 0.05


def at_the_edge(kind: str, params: dict, rate_hz: float = 1000.0) -> str | None:
    """Why an effect that passed the rule is still not named: a parameter ended at the edge
    of its physical range (``Param.within``), or a delay [ticks at ``rate_hz``] at the largest
    searched, held there by the fit. The data want more than the effect can be; what it
    gained there is a mimic's, not the named physics' (held-out set H: a spool's gain at 0.04
    /rad stood in for an airbag; set J: a BRS 10.5 ms late for another test's spool)."""
    spec = EFFECTS[kind]
    if spec.acts == "input_delay":
        for name, v in params.items():
            ms = 1000.0 * float(v) / rate_hz
            if at_delay_bound(ms):
                return (f"{name} = {ms:.2f} ms is held at the largest delay searched "
                        f"({1000 * DELAY_MAX_S:g} ms): the data want something else")
        return None
    for name, v in params.items():
        p = spec.param(name)
        if p is None or p.within is None or not isinstance(v, float | int):
            continue
        lo, hi = p.within
        if min(v - lo, hi - v) < EDGE * (hi - lo):
            return (f"{name} = {v:.3g} {p.unit} is held at the edge of what {kind} can be "
                    f"({lo:g}..{hi:g}): the data want something else")
    return None


#: of a parameter's typical size: smaller is physically nothing (a parameter warning, and
#: an effect every size of which is this small is not named, :func:`nothing_left`)
NOTHING = 1e-3
#: parameters that say where an effect acts, not how much: never "nothing" (a gap of zero is
#: a bag already touching the chest)
WHERE = frozenset({"gap"})


def nothing_left(kind: str, params: dict) -> str | None:
    """Why an effect that passed the rule is still not named: refitted on all estimation
    tests, every size it has (``params``, as the fit left them) is under ``NOTHING`` of its
    typical one, so the model it would be named in is the model without it: its
    cross-validated gain was made in the folds' refits, not by an effect the estimation
    tests hold (held-out set AC: a belt stiffening of 6.3 N/m^3, typical 1e8, named on
    every rig for a BRS read through an eccentric ring, +1.5 points on 6 of 6 tests, while
    its all-test fit was the model without it's to 0.001 points; its folds' refits never
    left that fit, so each scored its held-out test in-sample, docs/loop-evidence.md). That stall
    was the refit's (a positive size fitted as |v|, a kink at 0), mended in session 45 (a
    bound, and a stalled fold counts no gain: ``refit.fold_scores``); on set AC this check
    has not fired since. It stays as a backstop: an effect refitted to nothing is never a
    finding, however it passed. None when one size is more, or the kind has none (the
    formula, a switch)."""
    spec = EFFECTS[kind]
    sizes = [(p, params[p.name]) for p in spec.params
             if p.name not in WHERE and p.typical and isinstance(params.get(p.name), float | int)]
    if not sizes or any(abs(v) >= NOTHING * p.typical for p, v in sizes):
        return None
    what = ", ".join(f"{p.name} = {v:.3g} {p.unit}" for p, v in sizes)
    return (f"refitted on all estimation tests it is physically nothing ({what}; under "
            f"{NOTHING:g} of typical): the model it would be named in is the model without "
            "it, and its gain was made in the folds' refits, not by the effect")


VALIDATION_TOLERANCE = 0.3  # fit points: as SETUP_TOLERANCE, refit noise


def validation_refusal(fit_before: float, fit_after: float,
                       by_setup: list[SetupValidation] | None = None) -> str | None:
    """Why an effect that passed the rule on the estimation tests is still not named: the
    validation tests' fit_TOT [%] falls with it. They never choose an effect, they can only
    refuse one: a finding about the dummy must hold on the tests it was not fitted to (on
    every benchmark set before 2026-11-25, only wrong effects lowered it). ``by_setup``
    (:func:`validation_by_setup`) says where it fell."""
    if fit_after >= fit_before - VALIDATION_TOLERANCE:
        return None
    why = (f"the validation tests do not confirm it: their fit_TOT falls from "
           f"{fit_before:.1f} to {fit_after:.1f} %")
    return why if not by_setup else f"{why}, {where_it_falls(by_setup)}"


def validation_by_setup(before: FitTable, after: FitTable, setup_of: dict[str, str],
                        scope: list[str] | None, thin: AbstractSet[str]
                        ) -> list[SetupValidation]:
    """The validation tests' mean fit_TOT [%] per setup without an effect (``before``) and
    with it (``after``), largest fall first; ``setup_of``: validation test -> its setup,
    ``scope``: the setups the effect acts on (None: all), ``thin``: setups the estimation
    tests do not judge. A test that ran away (not finite) counts -1000 % in its setup's mean
    and marks the setup (:func:`~.refit.score` puts the whole table at -1000 % then)."""
    rows = []
    for s in dict.fromkeys(setup_of.values()):
        names = [n for n, t in setup_of.items() if t == s]
        raw = [[t.tests[n].total for n in names] for t in (before, after)]
        fit_before, fit_after = (float(np.mean([finite(x) for x in r])) for r in raw)
        rows.append(SetupValidation(s, len(names), fit_before, fit_after, s not in thin,
                                    scope is None or s in scope,
                                    not all(np.isfinite(x) for r in raw for x in r)))
    return sorted(rows, key=lambda v: v.after - v.before)


def where_it_falls(by_setup: list[SetupValidation]) -> str:
    """The refusal's words on where the validation fit fell, per setup; and, when it fell on
    setups the estimation tests do not judge and the effect does not act on while every setup
    judged or acted on holds (each within ``VALIDATION_TOLERANCE``: set AB's lumbar path had
    a judged clean rig fall 8 points, hidden in a pool by the rise where it acts), that those
    setups' tests cannot tell the effect from a mimic. Nothing of the kind when a test ran away: its
    -1000 % says nothing of an effect. On the independent held-out sets' stored refusals
    (docs/loop-evidence.md, "Where the validation fit falls") each setup so named lacked an
    effect in the model: the refused kind or one it mimics; their designs put one there."""
    def label(v: SetupValidation) -> str:
        notes = [f"{v.tests} test{'s' if v.tests != 1 else ''}",
                 *(["not judged"] if not v.judged else []),
                 *(["the effect acts there"] if v.in_scope else []),
                 *(["a test ran away"] if v.ran_away else [])]
        return f"{v.setup} {v.before:.1f} -> {v.after:.1f} % ({', '.join(notes)})"

    parts = ["per setup " + ", ".join(label(v) for v in by_setup)]
    if any(v.ran_away for v in by_setup):
        return ", ".join(parts)
    rest = [v for v in by_setup if v.judged or v.in_scope]
    fell = [v for v in by_setup if not v.judged and not v.in_scope
            and v.after < v.before - VALIDATION_TOLERANCE]
    if fell and all(v.after >= v.before - VALIDATION_TOLERANCE for v in rest):
        names = " and ".join(v.setup for v in fell)
        held = (f" (each setup judged or acted on holds within {VALIDATION_TOLERANCE:g} points)"
                if rest else "")
        parts.append(f"the fall is on {names}, which no estimation test judges and the "
                     f"effect does not act on{held}: {names} may have this effect too, or "
                     f"another that it mimics, which the shared base parameters stood in for "
                     f"there: estimation tests of {names} would tell")
    return ", ".join(parts)


def carry_refusal(before: Fits, after: Fits) -> str | None:
    """Why the better side of a tie is not carried in the model for its fit: fit is its only
    reason to be there, so the validation tests' fit_TOT [%] must rise with it, and neither
    output's fall by more than ``VALIDATION_TOLERANCE`` (None: it is carried)."""
    if after.total <= before.total:
        return (f"the validation tests' fit_TOT does not rise with it ({before.total:.1f} -> "
                f"{after.total:.1f} %)")
    for o in ("cr", "cd"):
        if getattr(after, o) < getattr(before, o) - VALIDATION_TOLERANCE:
            return (f"the validation tests' {o.upper()} fit falls with it "
                    f"({getattr(before, o):.1f} -> {getattr(after, o):.1f} %)")
    return None


def parameter_warnings(kind: str, params: dict, std_err: dict[str, float],
                       rate_hz: float) -> list[str]:
    """Warnings an engineer should read before trusting an accepted effect's parameters: a
    value at the edge of what was searched, a physically negligible or absurd size, or one the
    data do not determine (standard error above the value)."""
    out = []
    spec = EFFECTS[kind]
    for name, v in params.items():
        if not isinstance(v, float | int):
            continue
        p = spec.param(name)
        unit, typical = (p.unit, p.typical) if p is not None else ("", 0.0)
        se = std_err.get(name)
        if spec.acts == "input_delay":
            ms = 1000.0 * v / rate_hz
            if at_delay_bound(ms):
                out.append(f"{name} = {ms:.2f} ms is at the searched bound "
                           f"({1000 * DELAY_MAX_S:g} ms)")
            continue
        if p is not None and p.within is not None and not p.within[0] <= v <= p.within[1]:
            out.append(f"{name} = {v:.3g} {unit} is outside what {kind} can be "
                       f"({p.within[0]:g}..{p.within[1]:g})")
        elif spec.positive(name) and typical and abs(v) < NOTHING * typical:
            out.append(f"{name} = {v:.3g} {unit} is physically nothing (typical {typical:g})")
        elif typical and abs(v) > 1e3 * typical:
            out.append(f"{name} = {v:.3g} {unit} is over 1000 times a typical {typical:g}")
        if se is not None and np.isfinite(se) and abs(v) > 0 and se > abs(v):
            out.append(f"{name} is not determined by the data: std err {se:.3g} > |value| "
                       f"{abs(v):.3g}")
        elif se is not None and not np.isfinite(se):
            out.append(f"{name}: the data say nothing about it (singular Jacobian)")
    return out
