"""observer-node loop: identify, find what the model lacks, add it, refit, report.

1. The thesis's grey-box model is identified on the estimation tests.
2. Its residual on the estimation tests is analysed (:mod:`.analysis`): whiteness, input
   cross-correlation with coloured bands, and every effect of the library scored by the share
   of the residual its propagated signature explains; a sparse regression over force terms
   stands in for effects the library does not name ("other").
3. Every candidate kind (the ranking orders them; it is a linearised guess and does not
   filter) is added and all parameters re-estimated (the model is
   non-linear, simulated as such); each is judged by leave-one-test-out cross-validation
   *inside* the estimation tests (at most six folds). The best is accepted only if it raises
   the cross-validated fit_TOT by at least ``margin`` points and, refitted on all estimation
   tests, its signature explains less of the new residual than of the old (or under 2 % of
   it). A narrower scope is named only if it beats the same effect on a wider passing scope
   above the scatter. Parameter-free
   effects are always tried: their linearised signature predicts a switching force badly.
   The residual's cross-correlation with the inputs (against Ljung's coloured band) is
   reported before and after, but does not decide: on simulator data it rose for true
   effects too. Repeat until no candidate helps.
4. The validation tests never choose an effect; they refuse one whose refit lowers their
   fit_TOT by more than 0.3 points, and give the fits before, after each effect and at the
   end. Everything is written to OUTDIR (report.json, report.md, model.json, plots).
"""

from __future__ import annotations

import dataclasses
import itertools
import json
import textwrap
import time
from pathlib import Path
from typing import NamedTuple

import numpy as np

from .. import __version__, plots
from ..data import CrashTest, check_distinct
from ..data.crashtest import THESIS_WINDOW_S, CrashDataError
from ..data.setups import Setup, allowed_setups, assign_setups
from ..ident import greybox
from ..ident.dataset import Dataset, make_dataset
from ..ident.metrics import Fits
from ..ident.progress import Progress
from ..model.chest import (
    PARAM_NAMES,
    PARAM_UNITS,
    STATES,
    THESIS_STATES,
    discrete,
    model_matrices,
)
from ..model.effects import EFFECTS
from ..model.modelfile import ModelFile
from ..scores import scores
from .analysis import correlation_tests
from .belt_check import belt_pushes, slack_gains
from .cluster import Runner, cluster
from .diagnosis import FULLER, Unexplained, unexplained
from .evidence import SETUP_TOLERANCE, SIGN_P
from .rate_limit import rate_limited_outputs
from .refit import MAX_FOLDS, folds, model, refit, score
from .report import (
    LeftOut,
    LoopReport,
    LoopSettings,
    LoopStep,
    ModelFit,
    NotJudged,
)
from .report_md import markdown
from .rounds import Context, State, cross_validate, fit3, one_round, residual
from .screening import (
    BrokenTest,
    broken_before_fit,
    judged_fits,
    low_with_rig,
    residual_outliers,
)

# Kinds whose force grows with the chest's rate: a rate cap they make reads as a slow
# transducer's (a hostile review's damped chest at 1 kHz)
RATE_KINDS = frozenset({"chest_rate_damping"})

# A rig with fewer estimation tests than this is not judged: with one test, an effect there
# cannot be told from that test's scatter, and no fold both fits and scores the rig (set L: a
# chest stiffening on R16 and SLED was named on all three rigs, FULL holding one estimation
# test; sets K and L: on rigs with validation tests only).
MIN_JUDGED = 2


def judged_setups(est: Dataset, val: Dataset) -> tuple[list[str], list[NotJudged]]:
    """The setups an effect can be named on (at least ``MIN_JUDGED`` estimation tests) and
    those that are not, with their counts."""
    every = list(dict.fromkeys([*est.setups, *val.setups]))
    n_est = {s: est.setups.count(s) for s in every}
    return ([s for s in every if n_est[s] >= MIN_JUDGED],
            [NotJudged(s, n_est[s], val.setups.count(s)) for s in every if n_est[s] < MIN_JUDGED])


def scope_options(kind: str, setups: list[Setup], est_setups: list[str],
                  anywhere: bool = False, judged: list[str] | None = None
                  ) -> list[list[str] | None]:
    """The scopes effect ``kind`` is tried on: every test (None) when every setup could have
    it, and the groups of setups that could (all of them for up to four setups, else each
    alone) and hold a ``judged`` one (default: all do); never a setup where it is physically
    impossible, those with validation tests only included (set N: an airbag named on every
    estimation setup acted on the hard-seat R16's validation tests)."""
    possible = set(allowed_setups(kind, setups, anywhere))
    allowed = [s for s in est_setups if s in possible]
    everywhere = allowed == est_setups and all(s.name in possible for s in setups)
    out: list[list[str] | None] = [None] if everywhere else []
    if len(est_setups) > 1:
        subsets = ([list(c) for n in range(1, len(allowed) + 1)
                    for c in itertools.combinations(allowed, n)] if len(allowed) <= 4
                   else [[s] for s in allowed] + [allowed])
        out += [c for c in subsets if (c != est_setups or not everywhere)
                and (judged is None or any(s in judged for s in c))]
    elif allowed and not out:
        out = [allowed]
    return out


class _Screened(NamedTuple):
    """The tests the loop fits and scores, once the broken ones are left out."""

    est: Dataset
    val: Dataset
    gb: greybox.GreyBoxFit  # the thesis grey-box on ``est``
    broken: list[BrokenTest]  # what was left out, and why
    est_kept: list[CrashTest]
    folds: list[tuple[list[int], list[int]]]
    cv_now: dict[str, float]  # the grey-box's cross-validated fit_TOT [%] per test
    low: list[BrokenTest]  # far below the others but low with their rig: kept, and said
    kept: list[BrokenTest]  # flagged, but too few tests would remain: kept, and said


def _screened(est_tests: list[CrashTest], val_tests: list[CrashTest], rate_hz: float,
              window_s: tuple[float, float], runner: Runner, prog: Progress) -> _Screened:
    """Broken channels left out, then tests the thesis grey-box fits far worse than the
    others (:mod:`.screening`); the grey-box identified on what is left."""
    # Broken channels are found on the recorded data, before anything is fitted on them.
    broken = broken_before_fit([*est_tests, *val_tests], window_s[1])
    left_out = {b.test for b in broken}
    est_kept = [t for t in est_tests if t.name not in left_out]
    val_kept = [t for t in val_tests if t.name not in left_out]
    if len(est_kept) < 2 or not val_kept:
        have = (f"{len(est_kept)} estimation and {len(val_kept)} validation test(s)"
                " (the loop needs two estimation tests, to cross-validate, and one validation "
                "test)")
        raise CrashDataError(
            f"too few tests: {have}"
            + ("; left out as broken: " + "; ".join(f"{b.test} {b.channel}: {b.reason}"
                                                     for b in broken) if broken else ""))
    est = make_dataset(est_kept, rate_hz, window_s)
    val = make_dataset(val_kept, rate_hz, window_s)
    prog.update(f"identifying the thesis grey-box model (using {runner.workers} worker(s))")
    gb = greybox.fit_greybox(est)
    # A test the thesis model fits far worse than every other is left out too, and the model
    # identified again without it. Each test is judged by the model fitted without it
    # (leave-one-test-out): in-sample, a broken test bends the fit towards itself (set H's
    # BRS read 4x: 81.7 % in-sample against the others' 86, 22.5 % left out); the only test
    # of its setup in-sample, since the model fitted without it never saw its rig.
    folds_ = folds(est)
    cv0: dict[str, float] | None = cross_validate(runner, [(dict(gb.params), [])], est,
                                                  folds_)[0]
    fitted = {n: v.total for n, v in score(dict(gb.params), [], est).tests.items()}
    setup_of = dict(zip(est.names, est.setups, strict=True))
    judged_est = judged_fits(cv0 or {}, fitted, setup_of)
    outliers = residual_outliers(*judged_est, setup_of)
    low = low_with_rig(judged_est[0], setup_of)
    kept: list[BrokenTest] = []
    # the grey-box needs two tests (a guard: a test far below the median of the others
    # leaves at least two, as the check stands)
    if outliers and est.n_tests - len(outliers) < 2:
        kept += _kept(outliers, "leaving out every flagged estimation test would leave "
                      f"{est.n_tests - len(outliers)}")
    elif outliers:
        broken += outliers
        left_out |= {b.test for b in outliers}
        est_kept = [t for t in est_kept if t.name not in left_out]
        est = make_dataset(est_kept, rate_hz, window_s)
        gb = greybox.fit_greybox(est)
        folds_, cv0 = folds(est), None
    cv_now = cv0 if cv0 is not None else cross_validate(runner, [(dict(gb.params), [])],
                                                        est, folds_)[0]
    # A validation test is judged the same way, by the model the estimation tests made,
    # against them (each as judged above: the only one of its setup in-sample) and the other
    # validation tests: it never chose anything, but a broken one would bend the fits the
    # report gives and the refusal reads.
    if cv0 is None:  # refitted without the outliers
        setup_of = dict(zip(est.names, est.setups, strict=True))
        fitted = {n: v.total for n, v in score(dict(gb.params), [], est).tests.items()}
    all_fits = {**judged_fits(cv_now or {}, fitted, setup_of)[0],
                **{n: v.total for n, v in score(dict(gb.params), [], val).tests.items()}}
    setup_of |= dict(zip(val.names, val.setups, strict=True))
    flagged = residual_outliers(all_fits, (), setup_of)
    val_out = [b for b in flagged if b.test in val.names]
    low += [b for b in low_with_rig(all_fits, setup_of) if b.test in val.names]
    # An estimation test first flagged here, beside the validation tests (with three
    # estimation tests the check above has too few others to judge): the model is fitted
    # with it, so it is said, not left out (a hostile review found it dropped in silence).
    kept += _kept([b for b in flagged if b.test in est.names and b.test not in left_out],
                  "flagged beside the validation tests, the estimation tests' model was "
                  "fitted with it")
    if val_out and val.n_tests == len(val_out):  # nothing would be left to score
        kept += _kept(val_out, "leaving out every flagged validation test would leave 0")
    elif val_out:
        broken += val_out
        left_out |= {b.test for b in val_out}
        val_kept = [t for t in val_kept if t.name not in left_out]
        val = make_dataset(val_kept, rate_hz, window_s)
    return _Screened(est, val, gb, broken, est_kept, folds_, cv_now, low, kept)


def _kept(flagged: list[BrokenTest], why: str) -> list[BrokenTest]:
    """Tests the residual check flags that are not left out: said, never silent."""
    return [dataclasses.replace(b, reason=f"{b.reason}; kept in the fits: {why}")
            for b in flagged]


def run_loop(est_tests: list[CrashTest], val_tests: list[CrashTest], out: Path,
             rate_hz: float = 1000.0, window_s: tuple[float, float] = THESIS_WINDOW_S,
             margin: float = 1.0, top_k: int | None = None, max_effects: int = 4,
             verbose: bool = True, plots: bool = True, ratings: bool = True,
             groups: list[tuple[str, str]] | None = None, anywhere: bool = False,
             scheduler: str | None = None, workers: int | None = None,
             not_read: dict[str, str] | None = None) -> LoopReport:
    """Run the loop and write report.json, report.md, model.json and (``plots``) the plots of
    the validation tests before and after, into ``out``; returns the report. ``ratings``:
    ISO/TS 18571 ratings beside the fits (when the optional package is installed).
    ``top_k``: how many of the ranking's kinds are cross-validated each round (None: every
    kind; the ranking is a linearised guess, and it missed a belt stiffening's -0.2 % that
    cross-validation found worth 2 points, session 54).
    ``groups``: (setup name, test-name pattern) overrides of the setups the metadata gives;
    ``anywhere``: try effects on setups whose metadata rules them out, too. The refits run
    on Dask: the scheduler at ``scheduler``, else a local cluster of ``workers`` processes.
    ``not_read``: test files the caller left out unread (path: why), kept in the report.
    Raises :class:`CrashDataError` for one crash given twice (a test would score the fit it
    chose) and for too few tests once the broken ones are left out."""
    check_distinct(estimation=est_tests, validation=val_tests)
    with cluster(scheduler, workers) as runner:
        return _run(est_tests, val_tests, out, rate_hz, window_s, margin, top_k, max_effects,
                    verbose, plots, ratings, groups, anywhere, runner, not_read or {})


def _run(est_tests: list[CrashTest], val_tests: list[CrashTest], out: Path, rate_hz: float,
         window_s: tuple[float, float], margin: float, top_k: int | None, max_effects: int,
         verbose: bool, plots: bool, ratings: bool, groups: list[tuple[str, str]] | None,
         anywhere: bool, runner: Runner, not_read: dict[str, str]) -> LoopReport:
    t_start = time.monotonic()
    prog = Progress("loop", enabled=verbose)
    setups = assign_setups([*est_tests, *val_tests], groups)
    scr = _screened(est_tests, val_tests, rate_hz, window_s, runner, prog)
    out.mkdir(parents=True, exist_ok=True)  # after what can refuse the tests: none left behind
    est, val, gb, broken = scr.est, scr.val, scr.gb, scr.broken
    est_setups = list(dict.fromkeys(est.setups))
    rigs_judged, not_judged = judged_setups(est, val)
    thin = {n.setup for n in not_judged}
    scopes = {k: scope_options(k, setups, est_setups, anywhere, rigs_judged) for k in EFFECTS}
    if not_judged:
        prog.update("not judged: " + "; ".join(f"{n.setup} ({n.why})" for n in not_judged))
    # The rule reads the judged setups' tests only: one test of a setup cannot say whether an
    # effect helps there, nor may its scatter block one (no setup judged: every test).
    test_setup = ({n: s for n, s in zip(est.names, est.setups, strict=True) if s not in thin}
                  or dict(zip(est.names, est.setups, strict=True)))
    base = dict(gb.params)
    baseline_val = score(base, [], val)
    resid0 = residual(base, [], est)
    tests0 = correlation_tests(resid0, est)
    ctx = Context(runner, est, val, scr.folds, test_setup, thin, est_setups, scopes, margin, top_k,
                  rate_hz, prog)
    st = State(base, dict(gb.std_err), [], scr.cv_now, baseline_val)
    while len(st.accepted) < max_effects and one_round(ctx, st):
        pass
    base, effects, carried = st.base, st.effects, st.carried
    prog.update(f"scoring the final model on {len(val.names)} validation test(s)")
    final_val = score(base, effects, val)
    judged = {label: scores(val, model(b, e, val).simulate(val.pulse_g, val.brs_rad), ratings)
              for label, b, e in (("baseline", gb.params, []), ("final", base, effects))}
    in_file = effects
    if carried:  # model.json says of a carried effect what report.md does: it is no finding
        ru = carried[0].evidence.runner_up
        tied_with = f"{ru.kind} on {ru.scope}" if ru is not None else "a rival"
        in_file = [*effects[:-1], {**effects[-1], "note": "carried for its fit, not a "
                                   f"finding: {tied_with} fits alike (report.md)"}]
    mf = _model_file(base, in_file, est, rate_hz, gb, setups)
    mf.save(out / "model.json")
    # the thesis grey-box on the same tests, for a side-by-side run (observer-node bench)
    _model_file(dict(gb.params), [], est, rate_hz, gb, setups).save(out / "baseline-model.json")
    resid_final = residual(base, effects, est)
    # What no named effect explains is read without the carried one: it may be a mimic
    # of a form the library lacks, and in the model it would hide that form's trace.
    named_base, named_effects = st.named_model or (base, effects)
    y_named = model(named_base, named_effects, est).simulate(est.pulse_g, est.brs_rad)
    iso = {k: v.iso18571 for k, v in judged.items() if v.iso18571 is not None}
    left = {b.test for b in broken}
    # a chest whose damping grows with its rate caps that rate as a slow transducer does
    rate_named = sorted({e["kind"] for e in named_effects if e["kind"] in RATE_KINDS})
    limits = [Unexplained(r.output, r.setups, r.looks_like() + (
                  f"; or a chest whose damping caps its rate ({', '.join(rate_named)} is "
                  "named): check the transducer's slew rate before taking either"
                  if rate_named else ": not the chest's physics, and the fit on that output "
                  "is the transducer's too"), "rate_limit", {}, 0.0, r.reading())
              for r in rate_limited_outputs([t for t in [*est_tests, *val_tests]
                                             if t.name not in left], window_s[1])]
    for u in limits:
        prog.note(f"warning: {u.output.upper()} on {', '.join(u.setups)}: {u.looks_like}")
    report = LoopReport(
        baseline=ModelFit(Fits(**fit3(baseline_val)), gb.params, gb.std_err),
        effects=st.accepted,
        # by the gain as reported (rounded to 0.001 points): ties keep the order tried
        possible=sorted(st.possible, key=lambda p: -round(p.evidence.gain_points, 3)),
        sensor_effects=st.sensors,
        unexplained=[*limits, *(st.left_unexplained
                                 or ([] if st.sensors else unexplained(est, y_named)))],
        warnings=broken, low_with_rig=scr.low, flagged_kept=scr.kept,
        not_read=[BrokenTest(path, "file", why) for path, why in not_read.items()],
        left_out=_with_and_without(broken, base, effects, est_tests, val_tests, scr.est_kept,
                                   val, rate_hz, window_s),
        final=ModelFit(Fits(**fit3(final_val)), base, st.base_se),
        setups=setups, not_judged=not_judged,
        model="model.json", baseline_model="baseline-model.json",
        software_version=__version__,
        estimation=est.names, validation=val.names,
        residual_tests={"baseline": tests0, "final": correlation_tests(resid_final, est)},
        first_ranking=st.first_ranking,
        history=st.history,
        settings=LoopSettings(
            rate_hz=rate_hz, window_s=window_s, margin=margin, top_k=top_k,
            groups=[f"{n}={p}" for n, p in groups or []], allow_anywhere=anywhere,
            workers=runner.workers,
            cross_validation=f"leave-one-test-out inside the estimation tests (over "
            f"{MAX_FOLDS} tests: {MAX_FOLDS} folds, each setup's tests dealt round-robin), "
            "each fold refitted from the fit on all of them; per-test gains paired",
            rule=f"mean paired gain >= {margin:g} points over the estimation tests, its 95 % "
            f"t-interval above zero or a one-sided sign test p <= {SIGN_P:g}, no setup's "
            f"cross-validated fit lowered by more than {SETUP_TOLERANCE:g} points"),
        validation_tests={"baseline": baseline_val.tests, "final": final_val.tests},
        criteria={k: v.criteria for k, v in judged.items()},
        iso18571=iso if len(iso) == len(judged) else None,
        seconds=round(time.monotonic() - t_start, 1),
        carried=carried,
        belt_pushes=belt_pushes(base, effects, est, slack_gains(st.history), thin),
    )
    if plots:
        prog.update("drawing the plots")
        _plots(out, base, effects, gb.params, val, broken, [*est_tests, *val_tests])
        _evidence_plot(out, st.history, est, margin)
    # the run time the report gives is the whole run's, its plots included
    report = dataclasses.replace(report, seconds=round(time.monotonic() - t_start, 1))
    as_json = report.as_dict()
    (out / "report.json").write_text(json.dumps(as_json, indent=1, default=float) + "\n")
    (out / "report.md").write_text(markdown(report))
    prog.done(f"{len(st.accepted)} effect(s) accepted; validation fit "
              f"{baseline_val.fit.total:.1f} -> {final_val.fit.total:.1f} %")
    return report


def _with_and_without(broken: list[BrokenTest], base: dict, effects: list[dict],
                      est_tests: list[CrashTest], val_tests: list[CrashTest],
                      est_kept: list[CrashTest], val: Dataset, rate_hz: float,
                      window_s: tuple[float, float]) -> LeftOut | None:
    """What the fits are with the left-out tests and without: the final structure refitted
    with the left-out estimation tests back in, scored on the validation tests; and the final
    model scored on the validation tests with the left-out ones back in."""
    names = {b.test for b in broken}
    if not names:
        return None
    fitted_with: Fits | str | None = None
    scored_with: Fits | str | None = None
    back_est = [t for t in est_tests if t.name in names]
    if back_est:
        try:
            est_all = make_dataset([*est_kept, *back_est], rate_hz, window_s)
            with np.errstate(all="ignore"):
                r = refit(base, effects, est_all, max_nfev=60)
            fitted_with = Fits(**fit3(score(r.base, r.effects, val)))
        except (CrashDataError, ValueError) as e:  # missing samples: not fittable at all
            fitted_with = f"cannot be fitted: {e}"
    back_val = [t for t in val_tests if t.name in names]
    if back_val:
        try:
            val_all = make_dataset([*[t for t in val_tests if t.name not in names],
                                    *back_val], rate_hz, window_s)
            scored_with = Fits(**fit3(score(base, effects, val_all)))
        except (CrashDataError, ValueError) as e:
            scored_with = f"cannot be scored: {e}"
    return LeftOut(sorted(names), Fits(**fit3(score(base, effects, val))), fitted_with,
                   scored_with)


def model_name(effects: list[dict]) -> str:
    """The model's name: the grey-box and its named effects; an effect carried for its fit
    (it has a note) is said to be no finding, since most tools show the name alone."""
    return ("greybox" + "".join(f"+{e['kind']}" for e in effects if "note" not in e)
            + "".join(f" (carries {e['kind']} for its fit, not a finding)"
                      for e in effects if "note" in e))


def _model_file(base: dict, effects: list[dict], est: Dataset, rate_hz: float,
                gb: greybox.GreyBoxFit, setups: list[Setup]) -> ModelFile:
    """The model file the daemon runs: with effects the 6-state chest and its force input,
    without them the thesis's 5-state grey-box."""
    if effects:
        _, _, Gd, _, Df = discrete(base, rate_hz)
        structure = {"states": list(STATES),
                     "equations": "thesis eq. 3.1-3.8 plus effect forces held over the tick; "
                     "a slack belt switches to the belt-free matrices for the tick; the output "
                     "is the state's after the tick's inputs, effect forces evaluated there",
                     "force_input_matrix_G": Gd.tolist(), "force_output_matrix_Df": Df.tolist()}
    else:
        structure = {"states": list(THESIS_STATES), "equations": "thesis eq. 3.1-3.8, CD = s - x"}
    Ad, Bd, C, D = model_matrices(base, rate_hz, bool(effects))
    return ModelFile(
        kind="greybox", name=model_name(effects), tick_rate_hz=rate_hz,
        input_transform="velocity_brs_rate",
        A=Ad, B=Bd, C=C, D=D,
        parameters={n: {"value": float(base[n]), "std_err": float(gb.std_err.get(n, 0.0))
                        if not effects else None, "unit": PARAM_UNITS[n],
                        "fixed": n == "m1"} for n in PARAM_NAMES},
        structure=structure,
        fitted_on={"tests": est.names, "setups": sorted(set(est.setups)),
                   "setup_rules": [s.as_dict() for s in setups if s.name in est.setups],
                   "rate_hz": rate_hz,
                   "window_s": list(est.window_s), "simulation_start_s": 0.0},
        fits=score(base, effects, est).as_dict(), effects=effects, output_timing="after_input",
    )


#: candidates per round drawn in evidence.png (the best by cross-validated fit)
EVIDENCE_ROWS = 6


def _sensor_label(key: str) -> str:
    """A sensor candidate's row: "CR static", or "CR static+drift" (which output only)."""
    o = key.removesuffix(FULLER).upper()
    return f"{o} static+drift (which output)" if key.endswith(FULLER) else f"{o} static"


def _evidence_rounds(history: list[LoopStep]) -> list[tuple[str, list[plots.EvidenceRow]]]:
    """Each round's candidates and sensor candidates, as evidence.png draws them."""
    rounds = []
    for i, step in enumerate(history):
        rows: list[plots.EvidenceRow] = [
            (f"{t.kind} on {t.scope}", t.evidence.test_gain_points, t.evidence.gain_points,
             t.evidence.ci95_points, t.evidence.accepted) for t in step.tried[:EVIDENCE_ROWS]]
        rows += [(f"sensor: {_sensor_label(o)}", ev.test_gain_points, ev.gain_points,
                  ev.ci95_points, ev.accepted) for o, ev in step.sensor.items()]
        had = ", ".join(step.effects_before) or "no effect"
        title = textwrap.shorten(f"round {i + 1} (model with {had}): {step.decision}", 230)
        rounds.append((textwrap.fill(title, 100), rows))
    return rounds


def _evidence_plot(out: Path, history: list[LoopStep], est: Dataset, margin: float) -> None:
    plots.loop_evidence(out / "evidence.png", _evidence_rounds(history),
                        dict(zip(est.names, est.setups, strict=True)), margin)


def _plots(out: Path, base: dict, effects: list[dict], base0: dict, val: Dataset,
           broken: list[BrokenTest], tests: list[CrashTest]) -> None:
    t = np.arange(val.y.shape[1])[val.win] / val.fs_hz
    y = val.y[:, val.win]
    before = model(base0, [], val).simulate(val.pulse_g, val.brs_rad)[:, val.win]
    after = model(base, effects, val).simulate(val.pulse_g, val.brs_rad)[:, val.win]
    from ..ident.metrics import fit_table

    for label, y_hat in (("before", before), ("after", after)):
        fits = fit_table(val.names, y, y_hat)
        for k, key in enumerate(("cr", "cd")):
            plots.measured_vs_simulated(out / f"fit_{label}_{key}.png",
                                        f"validation, {label} the loop", val.names, t, y, y_hat,
                                        fits, k)
    plots.residuals(out / "residuals.png", val.names, t, y - before, y - after)
    if broken:
        plots.broken_tests(out / "broken.png", [(b.test, b.channel, b.reason) for b in broken],
                           tests)
