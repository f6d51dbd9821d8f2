"""One round of the loop: rank the library on the residual, cross-validate the best
candidates, let a transducer or a tie speak, and add the winner (or carry one side of a tie).

:func:`one_round` reads a :class:`Context` (the data and settings, fixed for the run) and
updates a :class:`State` (the model and what the report will say), in the order
``docs/loop.md`` gives: the rule (:mod:`.evidence`), then the sensor family, then scope and
ties (:mod:`.verdicts`), then the refit's own checks and the validation tests.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from typing import NamedTuple

import numpy as np

from ..ident.dataset import Dataset
from ..ident.metrics import Fits, FitTable
from ..ident.progress import Progress
from ..model.effects import EFFECTS, describe
from .analysis import (
    Candidate,
    CorrelationTests,
    candidates,
    correlation_tests,
    explained_share,
    force_signature,
    scope_label,
)
from .cluster import Runner
from .diagnosis import (
    FULLER,
    SHAPES,
    Unexplained,
    sensor_fold_scores,
    sensor_looks_like,
    sensor_shape,
    without_sensor,
)
from .evidence import (
    POSSIBLE_MIN,
    Evidence,
    PastTheTie,
    beats,
    judge,
    over_the_bar,
    past_the_tie,
    tell_apart,
)
from .refit import (
    Refit,
    finite,
    fold_scores,
    fold_scores_by_output,
    model,
    refit,
    score,
    stalled_in,
    where_stalled,
)
from .report import (
    AcceptedEffect,
    EffectEvidence,
    LoopStep,
    OtherScope,
    PossibleEffect,
    RankedCandidate,
    RunnerUp,
    SensorEffect,
    TriedCandidate,
)
from .verdicts import (
    at_the_edge,
    carry_refusal,
    defended_scope,
    nothing_left,
    output_lag,
    parameter_warnings,
    runner_up_of,
    tie_verdict,
    untold,
    untold_from_sensor,
    validation_by_setup,
    validation_refusal,
)

Folds = list[tuple[list[int], list[int]]]
Tried = tuple[float, Candidate, Evidence]  # mean cross-validated fit_TOT [%], candidate, rule


@dataclass(frozen=True)
class Context:
    """What every round reads: the data, the folds, the setups the rule judges and the
    settings."""

    runner: Runner
    est: Dataset
    val: Dataset
    folds: Folds
    test_setup: dict[str, str]  # judged estimation test -> its setup
    thin: set[str]  # setups too few estimation tests hold to be judged
    est_setups: list[str]
    scopes: dict[str, list[list[str] | None]]  # per kind, the scopes it may be tried on
    margin: float
    top_k: int | None  # kinds cross-validated per round (None: all)
    rate_hz: float
    prog: Progress


@dataclass
class State:
    """The model as the rounds leave it, and what the report will say of them."""

    base: dict
    base_se: dict[str, float]
    effects: list[dict]
    cv_now: dict[str, float]  # per test, the model's cross-validated fit_TOT [%]
    val_now: FitTable  # the validation tests' fits with the effects named so far
    history: list[LoopStep] = field(default_factory=list)
    accepted: list[AcceptedEffect] = field(default_factory=list)
    carried: list[AcceptedEffect] = field(default_factory=list)  # one side of a tie
    named_model: tuple[dict, list[dict]] | None = None  # the model without the carried one
    possible: list[PossibleEffect] = field(default_factory=list)
    sensors: list[SensorEffect] = field(default_factory=list)  # one, or two: cannot tell
    left_unexplained: list[Unexplained] = field(default_factory=list)  # no effect, no
    # transducer: what the rounds left
    first_ranking: list[RankedCandidate] = field(default_factory=list)
    # the other side of a tie both of whose effects the data defend, or of one looked past on
    # setups apart: tried again in the next round
    carry: list[Candidate] = field(default_factory=list)


class _Pick(NamedTuple):
    """The round's winner on its defended scope, and what it was weighed against."""

    cv: float
    best: Candidate
    ev: Evidence
    narrower: str | None  # the narrower scope given up for it
    runner_up: RunnerUp | None
    margin_points: float | None
    other_scope: OtherScope | None
    tie_note: str | None
    carrying: bool  # a tie neither side of which is named: the better one is carried
    # the tie's other side, for the validation tests to judge beside this one (``told``: the
    # side they told apart, named only if they rise with it)
    other_side: _Pick | None = None
    told: bool = False
    # the tie's two sides (kind, scope) as the possible list holds them, the named side first
    tie_sides: tuple[tuple[str, str], tuple[str, str]] | None = None

    @property
    def not_added(self) -> str:
        """How a refusal of a side of a tie reads in the step's decision."""
        return "is not named" if self.told else "is not carried"


def one_round(c: Context, st: State) -> bool:
    """Run one round on ``st``; True when an effect was named and another round follows."""
    c.prog.update(f"residual analysis with {len(st.effects)} effect(s)")
    ranked = candidates(model(st.base, st.effects, c.est), c.est,
                        {e["kind"] for e in st.effects}, c.scopes)
    ranking = [RankedCandidate(x.kind, round(x.explained, 4), scope_label(x.setups),
                               x.scope_shares, x.parameters) for x in ranked]
    if not st.first_ranking:
        st.first_ranking = ranking
    tried, per_test = _cross_validated(c, st, ranked)
    sensor_ev = _sensor_candidates(c.runner, st.base, st.effects, c.est, c.folds, st.cv_now,
                                   c.test_setup, c.margin)
    step = LoopStep([e["kind"] for e in st.effects], _mean(st.cv_now), ranking,
                    [TriedCandidate(x.kind, scope_label(x.setups), cv, ev)
                     for cv, x, ev in tried], sensor_ev)
    st.history.append(step)
    # "possible": what the data cannot defend against the model as it now stands
    st.possible = [PossibleEffect(x.kind, scope_label(x.setups), [e["kind"] for e in st.effects],
                                  ev, ev.reason)
                   for _, x, ev in tried if not ev.accepted and ev.gain_points >= POSSIBLE_MIN]
    passing = [t for t in tried if t[2].accepted]
    if _a_transducer_speaks(c, st, step, tried, passing, sensor_ev):
        return False
    if not passing:
        step.decision = ("no candidate passes the rule (mean paired gain >= "
                         f"{c.margin:g} points, above the scatter, no setup "
                         "lowered): " + "; ".join(f"{x.kind} on {scope_label(x.setups)}: "
                                                   f"{ev.reason}" for _, x, ev in tried[:4]))
        return False
    pick = _picked(c, st, step, tried, passing, per_test)
    return _added(c, st, step, pick, per_test)


def _cross_validated(c: Context, st: State, ranked: list[Candidate]
                     ) -> tuple[list[Tried], dict[int, dict[str, float]]]:
    """The candidates tried this round, best cross-validated fit first, and each one's
    per-test cross-validated fit_TOT (by ``id``); the rivals the last round left in
    ``st.carry`` are among them, and the list is emptied."""
    # Named effects first, every kind however little its linearised signature explains (a
    # belt stiffening at -0.2 % gained 2 points cross-validated, set AL); the generic formula
    # only when none of them helps and it explains some of the residual.
    named = [x for x in ranked if x.kind != "other"][:c.top_k]
    # A parameter-free switching force (the one-sided belt) is predicted badly by its
    # signature linearised around a trajectory that never switches: always try it.
    named += [x for x in ranked if not x.parameters
              and EFFECTS[x.kind].search.method == "switch" and x not in named]
    named += [x for x in st.carry if x.kind not in {e["kind"] for e in st.effects}
              and all(n.kind != x.kind for n in named)]
    st.carry = []
    other = [x for x in ranked if x.kind == "other" and x.explained > 0.01]
    tried: list[Tried] = []
    per_test: dict[int, dict[str, float]] = {}
    for group in (named, other):
        # the scope the residual points to, and the widest scope it could have:
        # cross-validation chooses; each fold of each trial is a task on the cluster
        trials = [t for x in group for t in _with_widest_scope(x, c.scopes[x.kind])]
        if not trials:
            continue
        c.prog.update(f"cross-validating {len(trials)} candidate(s): "
                      + ", ".join(f"{t.kind} on {scope_label(t.setups)}" for t in trials))
        # a stalled fold's test gains nothing (the model's fit without the candidate there),
        # and the evidence says which tests stalled
        cvs = held_out_fits(c.runner, [(st.base, [*st.effects, t.effect()]) for t in trials],
                            c.est, c.folds)
        for (_, raw), t in zip(cvs, trials, strict=True):
            ev = _judge_folds(st.cv_now, raw, c.test_setup, t.setups, c.margin)
            cv = where_stalled(raw, st.cv_now)
            tried.append((_mean(cv), t, ev))
            per_test[id(t)] = cv
        if any(ev.accepted for _, _, ev in tried):
            break
    tried.sort(key=lambda t: -t[0])
    return tried, per_test


def _a_transducer_speaks(c: Context, st: State, step: LoopStep, tried: list[Tried],
                         passing: list[Tried], sensor_ev: dict[str, Evidence]) -> bool:
    """The sensor family's word on the round: one output's sensor correction beats physics
    (a sensor effect, or a residual in both outputs no library effect explains), or ties with
    the best physical effect. True when it ends the loop."""
    static = [(o, ev) for o, ev in sensor_ev.items() if not o.endswith(FULLER)]
    best_sensor = max(static, key=lambda kv: kv[1].gain_points, default=None)
    if best_sensor is None or not best_sensor[1].accepted:
        return False
    o, ev = best_sensor  # whether a transducer is at fault: the static correction says
    if not passing or ev.gain_points > passing[0][2].gain_points:
        # A transducer moves its own output only. If the strongest physical candidate also
        # passes the rule on the other output's fit alone, the residual is in both: physics
        # no library form fits, not this transducer.
        both = _other_output(c.runner, st.base, st.effects, c.est, c.folds, tried, o,
                             c.test_setup, c.margin)
        if both is not None:
            x, ev_other = both
            o2 = _other(o)
            step.decision = (
                f"a sensor correction of {o} gains most ({ev.gain_points:+.2f} points), "
                f"but {x.kind} on {scope_label(x.setups)} also gains "
                f"{ev_other.gain_points:+.2f} points on {o2}'s fit alone, which a "
                f"transducer of {o} cannot move: a physical effect in both outputs that "
                "no effect of the library explains: unexplained, nothing named")
            on_o = _own_points(ev)
            st.left_unexplained = [
                Unexplained(o, _gaining(on_o), SHAPES["both"].format(o=o.upper()), "both",
                            _rounded(on_o), round(ev_other.gain_points, 2)),
                Unexplained(o2, _gaining(ev_other.setup_gain_points),
                            SHAPES["both"].format(o=o2.upper()), "both",
                            _rounded(ev_other.setup_gain_points),
                            round(2.0 * ev.gain_points, 2))]
            st.possible += _all_possible(
                passing, st.effects, f"a sensor correction of {o} gains more "
                f"({ev.gain_points:+.2f} points) and the residual is in both outputs: no "
                "library effect explains it")
            return True
        blamed, versus = _which_transducer(o, sensor_ev)
        st.sensors = blamed_transducers(c.est, st, o, blamed, sensor_ev)
        which = ("" if blamed == [o] else
                 f", though {o}'s static correction found it: {versus}, above the scatter"
                 if len(blamed) == 1 else
                 f"; which transducer, the data cannot tell: {versus}")
        step.decision = (f"a sensor effect on {' or '.join(blamed)} explains the residual "
                         f"better than any physical effect{which}: reported, not added to "
                         "the model")
        return True
    # Physics wins, but one output's sensor correction passes too: as against a physical
    # rival, the effect is named only if it beats it test by test above the scatter; else
    # the chest or a transducer, the data cannot tell, and which transducer is asked as above.
    why = untold_from_sensor(passing[0][1], passing[0][2], o, ev)
    if why is None:
        return False
    blamed, versus = _which_transducer(o, sensor_ev)
    st.left_unexplained = untold_transducer(c.est, st, o, blamed, sensor_ev)
    which = ("" if blamed == [o] else
             f"; if a transducer, {blamed[0]}'s rather than {o}'s: {versus}, above the scatter"
             if len(blamed) == 1 else
             f"; if a transducer, {o}'s or {blamed[1]}'s, the data cannot tell: {versus}")
    step.decision = f"{why}{which}; nothing named"
    st.possible += _all_possible(
        passing, st.effects, f"the data cannot tell it from a sensor correction of "
        f"{' or '.join(blamed)} (its transducer's error), which passes the rule too")
    return True


def untold_transducer(est: Dataset, st: State, o: str, blamed: list[str],
                      sensor_ev: dict[str, Evidence]) -> list[Unexplained]:
    """What is left unexplained where physics cannot be told from ``o``'s static correction:
    the ``blamed`` transducer or transducers (``_which_transducer``), as where a transducer
    wins (set V's slow CR clock was left 'unexplained: CD' without it). ``o`` is described by
    its static correction; another output by its fuller one (static and drift together), the
    evidence that blamed it, its shape the one of the two that alone wins more of its
    residual in-sample."""
    left = []
    for x in blamed:
        key = x if x == o else x + FULLER
        shape = "static" if x == o else sensor_shape(est, _estimate(est, st), x)
        looks = SHAPES[shape].format(o=x.upper())
        if x != o:
            looks += ("; judged by a correction of the static function and a drift in time "
                      "together, whose gains these are")
        if len(blamed) > 1:
            looks += (f"; or the other output's transducer: which of {o.upper()} and "
                      f"{blamed[1].upper()}, the data cannot tell, check both")
        points = _own_points(sensor_ev[key])
        other = key.replace(x, _other(x), 1)  # the same correction on the other output
        left.append(Unexplained(x, _gaining(points), looks, shape, _rounded(points),
                                round(2.0 * sensor_ev[other].gain_points, 2)))
    return left


def _which_transducer(o: str, sensor_ev: dict[str, Evidence]) -> tuple[list[str], str]:
    """Which transducer a sensor correction found by ``o``'s static correction blames, and
    the fuller corrections' comparison in words ("" when they leave it on ``o``). An error
    drifting in time on one output bends the chest model so that the healthy output's static
    correction wins it back (sets W and AG: a CD pot's sagging excitation named CR's). So
    each output's fuller correction (static and drift) is judged too: when the other
    output's passes the rule and beats ``o``'s test by test above the scatter, the other
    output alone is blamed; when it passes but does not, the data cannot tell which (both,
    ``o`` first); else ``o``. The fuller corrections only say which: with their freedom they
    take up physics too, so the static one says whether."""
    o2 = _other(o)
    mine, theirs = sensor_ev.get(o + FULLER), sensor_ev.get(o2 + FULLER)
    if mine is None or theirs is None or not theirs.accepted:
        return [o], ""
    told, better = beats(theirs.test_gain_points, mine.test_gain_points)
    versus = (f"{o2}'s correction with a drift in time gains {theirs.gain_points:+.2f} "
              f"points against {o}'s {mine.gain_points:+.2f}, better on {better} of "
              f"{theirs.tests} tests")
    return ([o2] if told else [o, o2]), versus


def blamed_transducers(est: Dataset, st: State, o: str, blamed: list[str],
                       sensor_ev: dict[str, Evidence]) -> list[SensorEffect]:
    """The sensor effects a transducer that beats physics is reported as, one per ``blamed``
    output (``_which_transducer``). ``o``, found by its static correction, reads as a static
    function of it; another, blamed by its fuller correction, in whichever of the static
    function and a drift in time alone wins more of its residual in-sample."""
    kinds = [e["kind"] for e in st.effects]
    out = []
    for x in blamed:
        if x == o:
            out.append(SensorEffect(x, kinds, sensor_looks_like("static", x), sensor_ev[x]))
        else:
            shape = sensor_shape(est, _estimate(est, st), x)
            out.append(SensorEffect(x, kinds, sensor_looks_like(shape, x),
                                    sensor_ev[x + FULLER]))
    return out


def _estimate(est: Dataset, st: State) -> np.ndarray:
    """The model's estimate of the estimation tests' outputs, as the rounds leave it."""
    with np.errstate(all="ignore"):
        return model(st.base, st.effects, est).simulate(est.pulse_g, est.brs_rad)


def _picked(c: Context, st: State, step: LoopStep, tried: list[Tried], passing: list[Tried],
            per_test: dict[int, dict[str, float]]) -> _Pick:
    """The passing candidate on the scope the data defend, looked past a tie with a rival
    the data cannot tell it from."""
    on_judged = {k: {n: v for n, v in cv.items() if n in c.test_setup}
                 for k, cv in per_test.items()}  # scopes and rivals compared on these
    (cv_best, best, ev_best), narrower = defended_scope(passing, on_judged, c.thin,
                                                        c.est_setups)
    runner_up, margin_points, other_scope = runner_up_of(
        [(cv_best, best, ev_best), *(t for t in tried if t[1] is not best)], on_judged,
        c.margin)
    tie = untold(best.kind, runner_up, len(ev_best.test_gain_points))
    tie_note: str | None = None
    carrying = False
    other_side: _Pick | None = None
    if tie and runner_up is not None:
        rival = next(t for t in tried if t[1].kind == runner_up.kind
                     and scope_label(t[1].setups) == runner_up.scope)
        c.prog.update(f"looking past a tie: {best.kind} and {rival[1].kind} together")
        past = _look_past(c.runner, st.base, st.effects, c.est, c.folds, best, rival[1],
                          per_test, c.test_setup, c.margin, rival[2].accepted)
        tie_note = tie_verdict(best, rival[1], past)
        if not past.named:
            # two explanations the data defend equally are not a finding: both possible
            kinds = [e["kind"] for e in st.effects]
            a, b = on_judged[id(best)], on_judged[id(rival[1])]
            n_tell, more = tell_apart(np.array([a[n] - b[n] for n in a if n in b], float))
            st.possible += [
                PossibleEffect(best.kind, scope_label(best.setups), kinds, ev_best,
                               f"{tie}{more}; {tie_note}", tests_to_tell_apart=n_tell),
                PossibleEffect(runner_up.kind, runner_up.scope, kinds, rival[2],
                               f"the data cannot tell it from {best.kind} on "
                               f"{scope_label(best.setups)}, which passes the rule too{more}; "
                               f"{tie_note}", tests_to_tell_apart=n_tell)]
            step.decision = (f"{best.kind} on {scope_label(best.setups)} passes the rule, "
                             f"but {tie}; {tie_note}: neither is named")
            # Neither is a finding, but either predicts CR and CD better than none: the
            # better one is carried in the model for its fit if it passes the checks a named
            # effect must (set U: three ties left the model 2.2-4.2 points short of the true
            # structure's fit).
            carrying = True
            other_side = _other_side(c, tried, passing, rival, on_judged)
        # the side not named, when it acts on other setups: judged again beside it
        if past.apart and past.named in ("a", "b"):
            st.carry.append(rival[1] if past.named == "a" else best)
        if past.named == "b":  # the runner-up explains the winner's gain, not the reverse
            (cv_best, best, ev_best), narrower = defended_scope(
                [rival, *(t for t in passing if t[1].kind == rival[1].kind
                          and t[1] is not rival[1])], on_judged, c.thin, c.est_setups)
            runner_up, margin_points, other_scope = runner_up_of(
                [(cv_best, best, ev_best), *(t for t in tried if t[1] is not best)],
                on_judged, c.margin)
        elif past.named == "both":  # the other is tried again in the next round
            st.carry.append(rival[1])
    return _Pick(cv_best, best, ev_best, narrower, runner_up, margin_points, other_scope,
                 tie_note, carrying, other_side)


def _other_side(c: Context, tried: list[Tried], passing: list[Tried], rival: Tried,
                on_judged: dict[int, dict[str, float]]) -> _Pick:
    """The tie's side ranked second, on the scope the data defend, as a pick of its own."""
    (cv, best, ev), narrower = defended_scope(
        [rival, *(t for t in passing if t[1].kind == rival[1].kind and t[1] is not rival[1])],
        on_judged, c.thin, c.est_setups)
    runner_up, margin, other_scope = runner_up_of(
        [(cv, best, ev), *(t for t in tried if t[1] is not best)], on_judged, c.margin)
    return _Pick(cv, best, ev, narrower, runner_up, margin, other_scope, None, carrying=False)


def _added(c: Context, st: State, step: LoopStep, pick: _Pick,
           per_test: dict[int, dict[str, float]]) -> bool:
    """The pick refitted on all estimation tests and checked (a lag of one output, its
    signature, its parameters' range, the validation tests), then named (True: another round
    follows) or carried; else refused, the step's decision saying why. A tie neither side of
    which is named may first be told apart by the validation tests (:func:`_told`)."""
    best = pick.best
    c.prog.update(f"refitting with {best.kind} on all estimation tests")
    fit = refit(st.base, [*st.effects, best.effect()], c.est, max_nfev=120)
    if pick.carrying and pick.other_side is not None:
        told = _told(c, st, pick, fit)
        if isinstance(told, str):
            step.decision += f"; {told}"
        elif told is not None:  # named, or nothing: the other lost on the validation tests
            return _settled(c, st, step, *told, per_test)
    return _settled(c, st, step, pick, fit, per_test)


def _settled(c: Context, st: State, step: LoopStep, pick: _Pick, fit: Refit,
             per_test: dict[int, dict[str, float]]) -> bool:
    """The refitted pick checked, then named, carried or refused (see :func:`_added`)."""
    best = pick.best
    if _an_output_lag(c, st, step, pick, fit):
        return False
    checked = _checked(c, st, step, pick, fit)
    if checked is None:
        return False
    entry = _entry(c, st, step, pick, fit, checked)
    val_before = st.val_now.fit.total
    # the model, its cross-validated and its validation fits move together, carried or named
    st.base, st.effects, st.base_se = fit.base, fit.effects, fit.base_std_err
    st.cv_now, st.val_now = per_test[id(best)], checked.val_fit
    if pick.carrying:
        st.carried.append(entry)
        # its line among the possible says where it went
        st.possible = [replace(p, why_not=f"{p.why_not}; carried in model.json for its fit, "
                               "not named") if p.kind == best.kind
                       and p.scope == scope_label(best.setups) else p for p in st.possible]
        step.decision += (f"; {best.kind} on {scope_label(best.setups)}, the side ranked "
                          "first, is carried in the model for its fit, not named "
                          f"(validation fit_TOT {val_before:.1f} -> "
                          f"{checked.val_fit.fit.total:.1f} %)")
        c.prog.update(f"carried {best.kind} for its fit, not named: validation fit "
                      f"{checked.val_fit.fit.total:.1f} %")
        return False
    if pick.told and pick.tie_sides is not None:
        entry.warnings.append("named over a tie by the validation tests, test by test (its "
                              "runner-up, below): the estimation tests could not tell them "
                              "apart, and the validation fit that chose it is no longer "
                              "independent evidence for it")
        # the last round's list, if no round follows: it is named, its rival told apart
        won, lost = pick.tie_sides
        here = (best.kind, scope_label(best.setups))
        st.possible = [
            replace(p, why_not=f"{p.why_not}; the validation tests tell it apart, and "
                    f"{best.kind} is named") if (p.kind, p.scope) == lost else p
            for p in st.possible if (p.kind, p.scope) not in (won, here)]
    st.accepted.append(entry)
    accepted = f"accepted {best.kind} on {scope_label(best.setups)}" + (
        f" (on {pick.narrower} only it fits no better beyond the scatter)"
        if pick.narrower else "")
    # a side of a tie: the decision keeps the tie and how the validation tests told it
    step.decision = (f"{step.decision.removesuffix(': neither is named')}: the estimation "
                     f"tests name neither; {accepted}: the validation tests told the tie apart, "
                     "test by test" if pick.told else accepted)
    c.prog.update(f"accepted {best.kind} on {scope_label(best.setups)}: validation fit "
                  f"{checked.val_fit.fit.total:.1f} %")
    return True


#: validation tests a tie needs, on the judged rigs either side acts on, before they may tell
#: its sides apart: with fewer, no sign test reaches ``evidence.SIGN_P``
MIN_TELLING = 4


def _told(c: Context, st: State, pick: _Pick, fit: Refit
          ) -> tuple[_Pick, Refit] | str | None:
    """The side of a tie neither side of which is named that the validation tests tell
    apart, to be named if it passes a carried side's checks. Both sides are refitted on all
    estimation tests and scored per validation test, on the tests of the judged rigs (a rig
    too few estimation tests hold speaks for the base parameters all rigs share, not for the
    effect) that either side acts on. A side is told apart when it passes the rule against
    the other there (:func:`~.evidence.judge`: at least ``margin`` points better on the mean,
    above the scatter, no setup lower), the bar on which the loop names an effect at all;
    both sides are judged alike, whichever ranked first. When neither passes, or fewer than
    ``MIN_TELLING`` tests are left, why not, for the step's decision. A side told apart and
    refused by the checks leaves nothing carried (the validation tests have just preferred
    its rival)."""
    other = pick.other_side
    judged = set(c.est_setups) - c.thin
    if other is None or not judged:
        return None
    scopes = [pick.best.setups, other.best.setups]
    acts = None if None in scopes else {s for sc in scopes for s in sc or ()}
    val_setup = {n: s for n, s in zip(c.val.names, c.val.setups, strict=True)
                 if s in judged and (acts is None or s in acts)}
    if len(val_setup) < MIN_TELLING:
        return (f"the validation tests cannot judge the tie: {len(val_setup)} on the judged "
                f"rigs either acts on, fewer than {MIN_TELLING}")
    c.prog.update(f"refitting with {other.best.kind}, the tie's other side")
    fit_b = refit(st.base, [*st.effects, other.best.effect()], c.est, max_nfev=120)
    on_a, on_b = ({n: finite(t.total) for n, t in score(f.base, f.effects, c.val)
                   .tests.items() if n in val_setup} for f in (fit, fit_b))
    sides = ((pick.best.kind, scope_label(pick.best.setups)),
             (pick.runner_up.kind, pick.runner_up.scope) if pick.runner_up else ("", ""))
    # a side that acts on none of these tests gains there through the base parameters all
    # rigs share, not by its effect (set AH: a belt stiffening on R16 told apart on six FULL
    # tests from an input gain on FULL, for a webbing's hysteresis on FULL)
    blind = [p for p in (pick, other) if acts_on_none(p.best.setups, val_setup.values())]
    for won, won_fit, lost, x, y, recorded in ((pick, fit, other, on_a, on_b, sides),
                                               (other, fit_b, pick, on_b, on_a, sides[::-1])):
        ev = judge(y, x, val_setup, None, c.margin)
        if ev.accepted and not any(won is p for p in blind):
            note = (f"{pick.tie_note}; on the {ev.tests} validation tests of the judged rigs "
                    f"either acts on, {won.best.kind} on {scope_label(won.best.setups)} fits "
                    f"{ev.gain_points:.2f} points better than {lost.best.kind} on "
                    f"{scope_label(lost.best.setups)} (better on {ev.tests_improved}), "
                    "above the scatter")
            # on the estimation tests, as any runner-up (their gains share the model before)
            apart, better = beats(won.ev.test_gain_points, lost.ev.test_gain_points)
            runner_up = RunnerUp(lost.best.kind, scope_label(lost.best.setups),
                                 round(lost.cv, 2), apart, better, lost.ev.accepted,
                                 over_the_bar(lost.ev, c.margin))
            return won._replace(carrying=False, told=True, other_side=None, tie_note=note,
                                runner_up=runner_up,
                                margin_points=round(won.cv - lost.cv, 2),
                                tie_sides=recorded), won_fit
    d = np.array([on_a[n] - on_b[n] for n in val_setup])
    why = "".join(f"; {p.best.kind} on {scope_label(p.best.setups)} acts on none of them, "
                  "so they judge the base parameters, not it" for p in blind)
    return (f"the validation tests of the judged rigs either acts on do not tell them apart "
            f"either ({pick.best.kind} {float(np.mean(d)):+.2f} points against "
            f"{other.best.kind}, better on {int(np.sum(d > 0))} of {len(d)}{why})")


def acts_on_none(scope: list[str] | None, setups: Iterable[str]) -> bool:
    """Whether an effect on ``scope`` (None: every setup) acts on none of the tests of
    ``setups``."""
    return scope is not None and not set(scope) & set(setups)


def _an_output_lag(c: Context, st: State, step: LoopStep, pick: _Pick, fit: Refit) -> bool:
    """True when the pick is an input delay that helps one output alone (in-sample, per
    output): that output's lag, a sensor effect, not the inputs'."""
    best = pick.best
    was, now = score(st.base, st.effects, c.est).fit, score(fit.base, fit.effects, c.est).fit
    gains = {"cr": now.cr - was.cr, "cd": now.cd - was.cd}
    lag = output_lag(best.kind, fit.effects[-1]["parameters"], gains["cr"], gains["cd"])
    if lag is None:
        return False
    if pick.carrying or pick.told:
        step.decision += (f"; {best.kind} {pick.not_added}: it delays both inputs alike "
                          f"and helps {lag} alone")
        return True
    ms = 1000.0 * float(np.mean([fit.effects[-1]["parameters"][n]
                                 for n in ("n_pulse", "n_brs")])) / c.rate_hz
    rest = "cd" if lag == "cr" else "cr"
    st.sensors = [SensorEffect(
        lag, [e["kind"] for e in st.effects],
        f"a lag of about {ms:.1f} ms on {lag.upper()} alone: both inputs delayed alike "
        f"is the outputs' timing, and {lag.upper()} gained {gains[lag]:+.1f} points "
        f"where {rest.upper()} gained {gains[rest]:+.1f}: the {lag.upper()} "
        "transducer or its filter, not the inputs", pick.ev)]
    step.decision = (f"input_delay on {scope_label(best.setups)} passes the rule, but "
                     f"it delays both inputs alike and helps {lag} alone: reported as "
                     f"a lag of the {lag} transducer, not added to the model")
    return True


class _Checked(NamedTuple):
    """What the refit's checks measured, for the report."""

    share_before: float  # of the residual its signature explains, before the refit
    share_after: float  # and after
    xcorr_old: CorrelationTests
    xcorr_new: CorrelationTests
    val_fit: FitTable  # the validation tests' fits with it


def _checked(c: Context, st: State, step: LoopStep, pick: _Pick, fit: Refit
             ) -> _Checked | None:
    """The refit's checks: its signature explains less of the residual, its parameters are
    inside their range, the validation tests do not fall (and, to carry a side of a tie or
    name one the validation tests told apart, rise with no output falling). None when
    refused, the step's decision saying why."""
    best = pick.best
    resid_old = residual(st.base, st.effects, c.est)
    resid_new = residual(fit.base, fit.effects, c.est)
    share_before, share_after = _signature_shares(best, st.effects, st.base, fit.effects,
                                                  fit.base, resid_old, resid_new, c.est)
    tie_side = pick.carrying or pick.told
    # The input cross-correlation is reported, not decisive: on simulator data it rose for
    # true effects too (what remains is discretisation error correlated with the pulse).
    # Less correlated than before, or no longer worth mentioning (< 2 % of the residual).
    # Not for a parameter-free switch (the one-sided belt): its signature, linearised along
    # a trajectory that never switches, says little (why it is always tried).
    if best.parameters and share_after >= share_before and share_after >= 0.02:
        why = (f"the refitted residual is not less correlated with its signature "
               f"({share_before:.3f} -> {share_after:.3f})")
        step.decision = (f"{step.decision}; {best.kind} {pick.not_added}: {why}" if tie_side
                         else f"{best.kind}: {why}: not accepted")
        return None
    val_fit = score(fit.base, fit.effects, c.val)
    by_setup = validation_by_setup(st.val_now, val_fit, dict(zip(c.val.names, c.val.setups,
                                                                 strict=True)),
                                   best.setups, c.thin)
    edge = (at_the_edge(best.kind, fit.effects[-1]["parameters"], c.rate_hz)
            or nothing_left(best.kind, fit.effects[-1]["parameters"]))
    val_why = validation_refusal(st.val_now.fit.total, val_fit.fit.total, by_setup)
    refused = edge or val_why
    if tie_side:
        refused = refused or carry_refusal(Fits(**fit3(st.val_now)), Fits(**fit3(val_fit)))
        if refused:
            step.decision += f"; {best.kind} {pick.not_added}: {refused}"
            return None
        if pick.carrying:
            st.named_model = (st.base, st.effects)
    if refused:
        # a rival it explained away is otherwise said nowhere (set AG's toe: an input delay
        # that passed the rule on its own)
        tie_words = f" (before that, {pick.tie_note})" if pick.tie_note else ""
        st.possible.append(PossibleEffect(best.kind, scope_label(best.setups),
                                          [e["kind"] for e in st.effects], pick.ev,
                                          refused + tie_words, None if edge else by_setup))
        step.decision = (f"{best.kind} on {scope_label(best.setups)} passes the rule on "
                         f"the estimation tests, but {refused}: not accepted{tie_words}")
        return None
    return _Checked(share_before, share_after, correlation_tests(resid_old, c.est),
                    correlation_tests(resid_new, c.est), val_fit)


def _entry(c: Context, st: State, step: LoopStep, pick: _Pick, fit: Refit,
           checked: _Checked) -> AcceptedEffect:
    """The report's entry for the pick, named or carried, with its evidence."""
    best, ev_best = pick.best, pick.ev
    params, se = fit.effects[-1]["parameters"], fit.effect_std_err[-1]
    ct_old, ct_new = checked.xcorr_old, checked.xcorr_new
    return AcceptedEffect(
        kind=best.kind, description=describe(best.kind, params), parameters=params,
        std_err=se, setups=best.setups, applies_to=_applies_to(best.setups, c.est, c.val),
        warnings=parameter_warnings(best.kind, params, se, c.rate_hz),
        confidence=ev_best.confidence,
        evidence=EffectEvidence(
            ranking_share=round(best.explained, 4), scope_shares=best.scope_shares,
            rule=ev_best, explained_share_before=round(checked.share_before, 4),
            explained_share_after=round(checked.share_after, 4),
            cv_fit_before=round(step.cv_fit_before, 2), cv_fit_after=round(pick.cv, 2),
            runner_up=pick.runner_up, margin_points=pick.margin_points,
            other_scope=pick.other_scope,
            input_xcorr_rms_ratio_before=round(ct_old.rms_ratio, 2),
            input_xcorr_rms_ratio_after=round(ct_new.rms_ratio, 2),
            input_xcorr_max_ratio_before=round(ct_old.max_ratio, 2),
            input_xcorr_max_ratio_after=round(ct_new.max_ratio, 2), tie=pick.tie_note),
        fit=Fits(**fit3(checked.val_fit)))


# ------------------------------------------------------------------ fits, folds and signatures
def fit3(t: FitTable) -> dict[str, float]:
    """A fit table's CR, CD and TOT fits [%], rounded as the report gives them."""
    return {k: round(float(v), 2) for k, v in t.fit.as_dict().items()}


def _judge_folds(before: dict[str, float], raw: dict[str, float], setups: dict[str, str],
                 scope: list[str] | None, margin: float) -> Evidence:
    """:func:`~.evidence.judge` on a candidate's per-test held-out fits as its folds gave
    them: a stalled fold's tests (NaN) count ``before``'s fit, no gain, and are listed."""
    return judge(before, where_stalled(raw, before), setups, scope, margin, stalled_in(raw))


def _mean(per_test: dict[str, float]) -> float:
    return float(np.mean(list(per_test.values())))


def _all_tests(base: dict, effects: list[dict], data: Dataset) -> tuple[dict, list[dict]]:
    """A trial fitted on all estimation tests, where each of its folds starts: a task."""
    with np.errstate(all="ignore"):
        r = refit(base, effects, data)
    return r.base, r.effects


def _fold(base: dict, effects: list[dict], data: Dataset, train: list[int],
          test: list[int]) -> dict[str, float]:
    """One fold of one model: a task on the cluster (quiet about overflowing trials)."""
    with np.errstate(all="ignore"):
        return fold_scores(base, effects, data, train, test)


def _sensor_fold(base: dict, effects: list[dict], data: Dataset, train: list[int],
                 test: list[int]) -> dict[str, dict[str, float]]:
    with np.errstate(all="ignore"):
        return sensor_fold_scores(base, effects, data, train, test)


def _fold_by_output(base: dict, effects: list[dict], data: Dataset, train: list[int],
                    test: list[int]) -> dict[str, dict[str, float]]:
    with np.errstate(all="ignore"):
        return fold_scores_by_output(base, effects, data, train, test)


def held_out_fits(runner: Runner, models: list[tuple[dict, list[dict]]], data: Dataset,
                  folds_: Folds) -> list[tuple[tuple[dict, list[dict]], dict[str, float]]]:
    """Per-test cross-validated fit_TOT [%] of each (base, effects): each fitted on all tests,
    then refitted from there without each fold's held-out tests; every fit a task. Returns
    each model's fit on all tests (the folds' start) and its per-test fits, NaN where the
    fold stalled (:func:`~.refit.fold_scores`)."""
    starts = runner.map(_all_tests, [(b, e, data) for b, e in models])
    res = runner.map(_fold, [(b, e, data, tr, te) for b, e in starts for tr, te in folds_])
    k = len(folds_)
    return [(start, {n: v for r in res[i * k:(i + 1) * k] for n, v in r.items()})
            for i, start in enumerate(starts)]


def cross_validate(runner: Runner, models: list[tuple[dict, list[dict]]], data: Dataset,
                   folds_: Folds, instead: dict[str, float] | None = None
                   ) -> list[dict[str, float]]:
    """:func:`held_out_fits`, a test whose fold stalled counting ``instead``'s fit (the model
    without the candidate's: no gain), or, without it, the model's own fit on all tests."""
    out = []
    for (b, e), cv in held_out_fits(runner, models, data, folds_):
        if stalled_in(cv):
            fits = instead or {n: finite(v.total) for n, v in score(b, e, data).tests.items()}
            cv = where_stalled(cv, fits)
        out.append(cv)
    return out


def _other_output(runner: Runner, base: dict, effects: list[dict], data: Dataset,
                  folds_: Folds, tried: list[Tried], o: str, test_setup: dict[str, str],
                  margin: float) -> tuple[Candidate, Evidence] | None:
    """The strongest physical candidate (the first of ``tried``) judged by the rule on the fit
    of the output other than ``o`` alone, against the model as it stands, both refitted on
    the tests with ``o``'s static correction taken out; it and that evidence when it passes
    there, else None. Taken out, because a transducer's error bends the fit of the parameters
    both outputs share, and any effect that frees them then gains on the other output too."""
    if not tried:
        return None
    c = tried[0][1]
    o2 = _other(o)
    with np.errstate(all="ignore"):
        data = without_sensor(data, model(base, effects, data).simulate(data.pulse_g,
                                                                         data.brs_rad), o)
    starts = runner.map(_all_tests, [(base, effects, data), (base, [*effects, c.effect()], data)])
    res = runner.map(_fold_by_output, [(b, e, data, tr, te) for b, e in starts
                                       for tr, te in folds_])
    k = len(folds_)
    now, with_c = ({n: v for r in res[i * k:(i + 1) * k] for n, v in r[o2].items()}
                   for i in range(2))
    # a stalled fold (refit.fold_scores) counts as cross_validate counts it: the model's own
    # test at its fit on all tests, the candidate's at the model's (no gain)
    if stalled_in(now):
        b0, e0 = starts[0]
        own = score(b0, e0, data).tests
        now = where_stalled(now, {n: finite(getattr(v, o2)) for n, v in own.items()})
    ev = _judge_folds(now, with_c, test_setup, c.setups, margin)
    return (c, ev) if ev.accepted else None


def _other(o: str) -> str:
    return "cd" if o == "cr" else "cr"


def _all_possible(passing: list[Tried], effects: list[dict], why: str) -> list[PossibleEffect]:
    """Every passing candidate, listed as possible for the same reason."""
    kinds = [e["kind"] for e in effects]
    return [PossibleEffect(c.kind, scope_label(c.setups), kinds, ev, why)
            for _, c, ev in passing]


def _own_points(sensor: Evidence) -> dict[str, float]:
    """A sensor candidate's gain per setup in its output's own fit points: its folds score
    fit_TOT, the mean of the corrected output and the other, which the correction leaves as
    is."""
    return {s: 2.0 * v for s, v in sensor.setup_gain_points.items()}


def _gaining(per_setup: dict[str, float]) -> list[str]:
    """The setups where a gain is positive (all of them when none is)."""
    return [s for s, v in per_setup.items() if v > 0] or list(per_setup)


def _rounded(per_setup: dict[str, float]) -> dict[str, float]:
    return {s: round(v, 2) for s, v in per_setup.items()}


def _look_past(runner: Runner, base: dict, effects: list[dict], data: Dataset, folds_: Folds,
               a: Candidate, b: Candidate, per_test: dict[int, dict[str, float]],
               test_setup: dict[str, str], margin: float, b_passes: bool) -> PastTheTie:
    """A tie between ``a`` and ``b`` looked past: the model with both cross-validated, and
    each judged by the rule beside the other (``b_passes``: ``b`` passes the rule on its
    own, as ``a``, the round's winner, does)."""
    better = {n: max(v, per_test[id(b)][n]) for n, v in per_test[id(a)].items()}
    cv_both = cross_validate(runner, [(base, [*effects, a.effect(), b.effect()])], data, folds_,
                             instead=better)[0]
    return past_the_tie(per_test[id(a)], per_test[id(b)], cv_both, test_setup, a.setups,
                        b.setups, margin, b_passes)


def _sensor_candidates(runner: Runner, base: dict, effects: list[dict], data: Dataset,
                       folds_: Folds, cv_now: dict[str, float], test_setup: dict[str, str],
                       margin: float) -> dict[str, Evidence]:
    """The sensor family: a sensor correction (static and drift) of one output, judged by
    the same rule (a stalled fold's tests at ``cv_now``: no gain)."""
    res = runner.map(_sensor_fold, [(base, effects, data, tr, te) for tr, te in folds_])
    raw = {o: {n: v for r in res for n, v in r[o].items()} for o in res[0]}
    return {o: _judge_folds(cv_now, cv, test_setup, None, margin) for o, cv in raw.items()}


def _with_widest_scope(c: Candidate, options: list[list[str] | None]) -> list[Candidate]:
    """``c`` on the scope the residual chose, and on the widest scope it is allowed."""
    widest = options[0] if None in options else max(options, key=lambda o: len(o or []))
    if c.setups == widest or (c.setups is not None and widest is not None
                              and sorted(c.setups) == sorted(widest)):
        return [c]
    return [c, Candidate(c.kind, c.explained, c.parameters, None, widest, c.scope_shares)]


def _applies_to(scope: list[str] | None, est: Dataset, val: Dataset) -> list[str] | None:
    """The estimation and validation tests a scoped effect acts on (None: every test)."""
    if scope is None:
        return None
    return [n for d in (est, val) for n, s in zip(d.names, d.setups, strict=True) if s in scope]


def residual(base: dict, effects: list[dict], data: Dataset) -> np.ndarray:
    """Measured minus simulated outputs inside the fit window, per test."""
    y_hat = model(base, effects, data).simulate(data.pulse_g, data.brs_rad)
    return (data.y - y_hat)[:, data.win]


def _signature_shares(c: Candidate, effects: list[dict], base: dict[str, float],
                      new_effects: list[dict], new_base: dict[str, float],
                      resid_old: np.ndarray, resid_new: np.ndarray,
                      data: Dataset) -> tuple[float, float]:
    """How much of the residual the candidate's signature explains before and after the
    refit, each along its own model's trajectory (would more of the effect still help?).
    Effects that are not forces (delay, offset) are judged by the input correlation alone."""
    effect = EFFECTS[c.kind]
    if effect.force is None or effect.search.method == "sparse":
        return 1.0, 0.0
    params = new_effects[-1]["parameters"]
    if effect.acts == "belt_slack":
        params = {}
    elif not any(params.values()):
        return 1.0, 0.0
    old = model(base, effects, data)
    new = model(new_base, new_effects[:-1], data)
    mask = (np.ones(data.n_tests) if c.setups is None else
            np.array([s in c.setups for s in data.setups], float))[:, None, None]
    before = explained_share(resid_old, mask * force_signature(old, data, c.kind, params),
                             data)
    after = explained_share(resid_new, mask * force_signature(new, data, c.kind, params),
                            data)
    return before, after
