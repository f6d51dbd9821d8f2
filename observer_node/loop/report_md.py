"""report.md: the loop's report as an engineer reads it, written from :class:`.LoopReport`
(report.json holds the same, for tools)."""

from __future__ import annotations

import re

from ..ident.metrics import Fits
from ..model.effects import EFFECTS
from ..scores import mean_abs_errors
from .belt_check import BeltPush
from .report import AcceptedEffect, LoopReport, LoopStep, SensorEffect
from .screening import BrokenTest

_NUMBERED = re.compile(r"^(.*?)(\d+)$")
MOST_NAMES = 24  # a campaign's hundreds of names in a table cell are read by nobody


def names(tests: list[str]) -> str:
    """Test names for a reader: runs of consecutive numbers shortened (``R16_001..012``), and
    past :data:`MOST_NAMES` pieces the rest counted (report.json lists every name)."""
    pieces: list[str] = []
    run: list[tuple[str, str]] = []  # (prefix, digits) of consecutive names

    def close() -> None:
        if len(run) >= 3:
            pieces.append(f"{run[0][0]}{run[0][1]}..{run[-1][1]}")
        else:
            pieces.extend(p + d for p, d in run)
        run.clear()

    for t in tests:
        m = _NUMBERED.match(t)
        if m and run and m[1] == run[-1][0] and len(m[2]) == len(run[-1][1]) \
                and int(m[2]) == int(run[-1][1]) + 1:
            run.append((m[1], m[2]))
            continue
        close()
        if m:
            run.append((m[1], m[2]))
        else:
            pieces.append(t)
    close()
    if len(pieces) <= MOST_NAMES:
        return ", ".join(pieces)
    shown = ", ".join(pieces[:MOST_NAMES])
    return (f"{shown} and {len(pieces) - MOST_NAMES} more ({len(tests)} tests; report.json "
            "lists each)")


def markdown(r: LoopReport) -> str:
    b, f = r.baseline.fit, r.final.fit
    iso = r.iso18571
    lines = ["# Closed loop: residual, missing effect, refit", "",
             f"Estimation tests: {names(r.estimation)}  ",
             f"Validation tests: {names(r.validation)} (fits below are on these)", "",
             "## Setups", "", "| setup | tests | from | impossible here |", "|---|---|---|---|"]
    lines += [f"| {s.name} | {names(s.tests)} | {s.how} | "
              f"{'; '.join(f'{k} ({v})' for k, v in s.impossible.items()) or '-'} |"
              for s in r.setups]
    lines += [f"\n**Check the metadata:** {t} is named like setup {other}'s tests, but its "
              f".mme (type of test, title, test object) puts it in {s.name}, where it is "
              "kept; if its name is right, correct the .mme or use --group."
              for s in r.setups for t, other in s.named_elsewhere.items()]
    if r.not_judged:
        lines += ["", "**Not judged** (too few estimation tests to tell an effect there from "
                  "one test's scatter; nothing is claimed about them, and an effect named on "
                  "\"all\" acts there as the model's best guess): "
                  + "; ".join(f"{n.setup}, {n.why}" for n in r.not_judged) + "."]
    lines += ["", "## Fits", "",
              "| model | acts on | fit CR | fit CD | fit TOT |", "|---|---|---|---|---|",
              f"| thesis grey-box | all | {b.cr:.1f} | {b.cd:.1f} | {b.total:.1f} |"]
    for e in r.effects:
        lines.append(f"| + {e.kind} | {'+'.join(e.setups or ['all'])} | "
                     f"{e.fit.cr:.1f} | {e.fit.cd:.1f} | {e.fit.total:.1f} |")
    for e in r.carried:
        lines.append(f"| + {e.kind}, carried, not named | {'+'.join(e.setups or ['all'])} | "
                     f"{e.fit.cr:.1f} | {e.fit.cd:.1f} | {e.fit.total:.1f} |")
    lines += [f"| **final** | | **{f.cr:.1f}** | **{f.cd:.1f}** | **{f.total:.1f}** |", ""]
    if not r.effects:
        lines += [none_accepted(r.history, r.settings.rule, bool(r.carried)), ""]
    lines += _markdown_findings(r)
    lines += ["## Injury criteria on the validation tests", "",
              "Mean |estimate - measured| over the validation tests (peak chest deflection, "
              "chest X acceleration 3 ms clip, viscous criterion; per test in report.json)"
              + (" and the mean ISO/TS 18571 overall rating (0..1):" if iso is not None
                 else ":"), "",
              "| model | CD max [mm] | CR 3 ms [g] | VC max [m/s] |"
              + (" ISO 18571 CR | CD |" if iso is not None else ""),
              "|---|---|---|---|" + ("---|---|" if iso is not None else "")]
    for label in ("baseline", "final"):
        err = mean_abs_errors({n: c.as_dict() for n, c in r.criteria[label].items()})
        mean = iso[label].mean_overall if iso is not None else None
        lines.append(f"| {'thesis grey-box' if label == 'baseline' else 'final'} | "
                     f"{err['cd_max_mm']:.1f} | {err['cr_3ms_g']:.1f} | {err['vc_max_m_s']:.2f} |"
                     + (f" {mean.cr:.3f} | {mean.cd:.3f} |" if mean else ""))
    lines.append("")
    for e in r.effects:
        lines += _markdown_effect(e)
    for e in r.carried:
        lines += _markdown_effect(e, carried=True)
    lines += ["## First ranking of candidates (share of the residual explained)", "",
              "| effect | scope | explained |", "|---|---|---|"]
    lines += [f"| {c.kind} | {c.scope} | {100 * c.explained_share:.1f} % |"
              for c in r.first_ranking]
    rt = r.residual_tests
    lines += ["", "## Residual tests on the estimation tests", "",
              "| | lag-1 autocorr CR | CD | input xcorr / band CR | CD |", "|---|---|---|---|---|"]
    for label in ("baseline", "final"):
        t = rt[label]
        lines.append(f"| {label} | {t.cr.lag1_autocorrelation:.3f} | "
                     f"{t.cd.lag1_autocorrelation:.3f} | "
                     f"{t.cr.max_ratio:.2f} | {t.cd.max_ratio:.2f} |")
    lines += ["", "The residual stays far from white (lag-1 autocorrelation near 1: CFC "
              "filtering colours it), so whiteness cannot decide; the cross-validated fit and "
              "the input cross-correlation against Ljung's coloured band do.", "",
              "Plots: fit_before_*.png, fit_after_*.png, residuals.png, evidence.png (each "
              "round's candidates: the gain per test, its mean and interval, against the "
              "margin)"
              + (", broken.png (the tests left out)" if r.warnings else "")
              + f". Model: {r.model}. "
              f"Run time {r.seconds} s.", ""]
    return "\n".join(lines)


def none_accepted(history: list[LoopStep], rule: str, carried: bool = False) -> str:
    """report.md's line when no effect is named: why, as the loop decided (no candidate
    passed, the validation tests refused the one that did, a sensor, or a tie, whose better
    side may be ``carried`` in the model for its fit)."""
    why = history[-1].decision if history else ""
    if not why or why.startswith("no candidate passes"):
        return f"No effect was accepted: none passed the rule ({rule})."
    return f"No effect was {'named' if carried else 'accepted'}: {why}."


def _markdown_effect(e: AcceptedEffect, carried: bool = False) -> list[str]:
    """An accepted (or ``carried``) effect's section: scope, parameters, confidence,
    warnings, rivals."""
    ev, se = e.evidence, e.std_err
    params = ", ".join((f"{k} = {v:.4g}" + (f" ± {se[k]:.2g}" if k in se else ""))
                       if isinstance(v, float) else f"{k} = {v}"
                       for k, v in e.parameters.items())
    rival = ""
    if ev.runner_up is not None:
        ru = ev.runner_up
        rival = (f"- why this and not that: the runner-up, {ru.kind} on {ru.scope}, "
                 f"cross-validated {ru.cv_fit:.1f} %, {abs(ev.margin_points or 0.0):.1f} "
                 # the other side of a tie, named over it, may rank below its rival
                 f"points {'higher' if (ev.margin_points or 0.0) < 0 else 'lower'}")
        if ru.told_apart is not None:
            n = len(ev.rule.test_gain_points)
            rival += (f"; {e.kind} fits better on {ru.tests_better} of {n} estimation tests, "
                      + ("above the scatter" if ru.told_apart else "not above the scatter")
                      + (f"; {ru.kind} {ru.standing}, and the two were judged "
                         f"each beside the other: {ev.tie}" if ru.rival and ev.tie else
                         f"; **{ru.kind} {ru.standing}: the data cannot tell the two "
                         "apart**" if ru.rival else
                         "" if ru.passes_rule else f"; {ru.kind} {ru.standing}"))
    if ev.other_scope is not None:
        os_ = ev.other_scope
        rival += (("\n" if rival else "") + f"- on {os_.scope} instead it "
                  f"cross-validated {os_.cv_fit:.1f} % ({os_.margin_points:+.1f} "
                  "points from the accepted scope)")
    where = (f"acts on setups {', '.join(e.setups)}: {names(e.applies_to or [])}"
             if e.setups is not None else "acts on every test")
    head = [f"## {e.kind}", "", e.description, ""]
    if carried:
        head = [f"## {e.kind}: in the model for its fit, not a finding", "", e.description, "",
                "The data cannot tell it from its rival (below), so neither is named; it is in "
                "model.json because the validation tests' fit_TOT rises with it and neither "
                "output's falls. Read it as a better observer, not as a finding about the "
                "dummy or the car.", ""]
    return [*head,
            f"- {where}",
            f"- parameters (± standard error): {params or '(none)'}",
            f"- confidence (cross-validated, paired over tests): {e.confidence}",
            *(f"- **warning**: {w}" for w in e.warnings),
            *_looks_alike(e.kind),
            *([rival] if rival else []),
            f"- explained {100 * ev.explained_share_before:.1f} % of the residual before"
            f" the refit, {100 * ev.explained_share_after:.1f} % after",
            f"- cross-validated fit_TOT inside the estimation tests: "
            f"{ev.cv_fit_before:.1f} -> {ev.cv_fit_after:.1f} %",
            f"- input cross-correlation / coloured 99 % band, RMS over lags: "
            f"{ev.input_xcorr_rms_ratio_before:.2f} -> "
            f"{ev.input_xcorr_rms_ratio_after:.2f} (largest: "
            f"{ev.input_xcorr_max_ratio_before:.2f} -> "
            f"{ev.input_xcorr_max_ratio_after:.2f})",
            ""]


def _looks_alike(kind: str) -> list[str]:
    """What the library lacks that the data reads as ``kind`` (the effect's ``looks_alike``)."""
    e = EFFECTS.get(kind)
    return [f"- looks alike: {e.looks_alike}"] if e is not None and e.looks_alike else []


_OTHER = {"cr": "CD", "cd": "CR"}


def _other_transducer(s: SensorEffect, named: list[str]) -> list[str]:
    """The caveat a correction of one output needs (not said of a lag, which is read from an
    input delay, nor when both outputs are named): an error on the other output can bend the
    chest model so that this output's correction wins it back. The loop checks the other
    output with a drift in time (sets W and AG: a CD pot's sagging excitation had been named
    CR's); that tells set V's CR clock only as "CR or CD" and missed set AI's CD pot
    non-linearity."""
    if not s.looks_like.startswith(("a static function", "a drift in time")):
        return []
    o, other = s.output.upper(), _OTHER[s.output]
    if other.lower() in named:
        return []
    return [f"- and the {other} transducer's too: an error on {other} can bend the model so "
            f"that a correction of {o} wins it back; the loop checked {other} with a drift "
            f"in time, which finds a sagging gain, not every such error (a slow clock, a "
            f"static non-linearity)"]


def _kept_table(kept: list[BrokenTest], title: str, note: str, why: str) -> list[str]:
    """A section for tests far below the others that the fits keep (none: nothing)."""
    if not kept:
        return []
    return ["## " + title, "", note, "", f"| test | {why} |", "|---|---|",
            *(f"| {w.test} | {w.reason} |" for w in kept), ""]


def _markdown_findings(r: LoopReport) -> list[str]:
    """Warnings (broken tests), sensor effects, unexplained structure and possible effects."""
    lines: list[str] = []
    if r.not_read:
        lines += ["## Test files not read (left out by --skip-bad-tests)", "",
                  "| file | why |", "|---|---|"]
        lines += [f"| {w.test} | {w.reason} |" for w in r.not_read]
        lines.append("")
    if r.warnings:
        lines += ["## Warnings: tests left out of the fits", "",
                  "| test | channel | why |", "|---|---|---|"]
        lines += [f"| {w.test} | {w.channel} | {w.reason} |" for w in r.warnings]
        lo = r.left_out
        if lo is not None:  # always, with warnings
            lines += ["", "- validation fit_TOT without them: "
                      + _pct(lo.validation_fit_without)]
            if lo.validation_fit_if_fitted_with_them is not None:
                lines.append("- with the left-out estimation tests fitted too: "
                             + _pct(lo.validation_fit_if_fitted_with_them))
            if lo.validation_fit_with_them is not None:
                lines.append("- scored on the left-out validation tests too: "
                             + _pct(lo.validation_fit_with_them))
        lines.append("")
    lines += _kept_table(r.low_with_rig, "Tests far below the others, low with their rig (kept "
                         "in the fits)", "The grey-box may lack something on that rig; or its "
                         "tests are broken alike. Look at them before reading an effect on "
                         "that rig.", "why kept")
    lines += _kept_table(r.flagged_kept, "Warnings: tests far below the others, kept in the "
                         "fits", "Too few tests would remain without them: every fit and "
                         "verdict below includes them. Look at them first.", "why")
    named = [s.output for s in r.sensor_effects]
    if len(named) > 1:
        lines += ["## Sensor effect (not physics): which transducer, the data cannot tell",
                  "", f"- one of {' and '.join(o.upper() for o in named)}: check both; each "
                  "correction passes the rule, and neither beats the other test by test "
                  "above the scatter", ""]
    for s in r.sensor_effects:
        lines += ["## Sensor effect (not physics)", "",
                  f"- **{s.output.upper()}**: {s.looks_like}",
                  f"- confidence: {s.confidence}",
                  "- not added to model.json: check the transducer's calibration",
                  *_other_transducer(s, named), ""]
    for u in r.unexplained:
        if u.shape == "rate_limit":  # read off the recorded channel, not off a residual
            lines += ["## Unexplained", "", f"- **{u.output.upper()}** on {', '.join(u.setups)}"
                      f": {u.looks_like}", ""]
            continue
        gains = ", ".join(f"{k} {v:+.1f}" for k, v in u.gain_points.items())
        lines += ["## Unexplained", "",
                  f"- the residual of **{u.output.upper()}** on {', '.join(u.setups)} "
                  f"is structured and no effect of the library explains it under the rule; "
                  f"it looks like {u.looks_like}",
                  f"- a correction of that shape would add (fit points per setup): {gains}; "
                  f"the same in the other output: {u.other_output_gain_points:+.1f}", ""]
    if r.belt_pushes:
        lines += _markdown_belt(r.belt_pushes)
    if r.possible:
        lines += ["## Possible, not accepted", "",
                  "| effect | scope | after | gain (95 % CI), tests improved | why not |",
                  "|---|---|---|---|---|"]
        for p in r.possible:  # the gain as report.json rounds it (to 0.001 points)
            ev = p.evidence
            low, high = ev.ci95_points
            lines.append(f"| {p.kind} | {p.scope} | {'+'.join(p.after) or '-'} | "
                         f"{round(ev.gain_points, 3):+.2f} ({low:+.2f}..{high:+.2f}), "
                         f"{ev.tests_improved}/{ev.tests} | {p.why_not} |")
        lines.append("")
    return lines


def _markdown_belt(pushes: list[BeltPush]) -> list[str]:
    """Where the model's belt pushes the chest, and what the slack belt scored."""
    rebound = all(b.rebound_share >= 0.5 for b in pushes)
    lines = ["## The model's belt pushes the chest", "",
             "The linear belt's force k2 e + c2 e' goes negative in these setups' estimation "
             "tests (on average as long as below): the belt pushes the sternum back, which a "
             "belt cannot do."
             + (" Most of it comes after the pull's peak: the model follows these tests' "
                "rebound with it; read its CR and CD after the peak with care." if rebound
                else "")
             + " A slack belt (belt_unloading) would stop it; where the loop tried it, its "
             "best cross-validated gain on the setup's tests is below.", "",
             "| setup | tests | pushing, ms per test | largest push [N] | largest pull [N] | "
             "after the pull's peak | slack belt's gain [points] |",
             "|---|---|---|---|---|---|---|"]
    lines += [f"| {b.setup} | {b.tests} | {b.pushing_ms:.0f} | {b.push_n:.0f} | "
              f"{b.pull_n:.0f} | {b.rebound_share:.0%} | "
              f"{'not tried' if b.slack_gain_points is None else f'{b.slack_gain_points:+.2f}'}"
              " |" for b in pushes]
    return [*lines, ""]


def _pct(f: Fits | str) -> str:
    return f"{f.total:.1f} %" if isinstance(f, Fits) else f
