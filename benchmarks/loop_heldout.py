"""The loop on crash sets it was never built from: the independent held-out simulator's cases.

`benchmarks/heldout/` simulates crash tests from the physics in its own forms (a sternum on
more than one mass, D-ring friction, a torsion-bar retractor, barrier-crush pulses, lab noise,
quantisation, CFC filters, per-test scatter of the dummy), written without the loop's effect
library in view; its cases (`benchmarks/heldout/cases.py`) were committed with their expected
verdicts before the loop ran on them. Nothing in the loop is tuned on them.

Per case the loop runs blind at its defaults on 6 estimation + 6 validation tests (with
``--est-times K``, K times the estimation tests, every crash drawn from another seed). Printed:

- what it named (kind@scope, scopes as the simulator's setups), what passed the rule but the
  validation tests refused ("refused:"; "fell on unjudged rigs" when their fit fell on
  setups no estimation test judges and the effect does not act on, the rest holding,
  ``refused_unjudged`` in the JSON), the pair that passed the rule but the data cannot
  tell apart, so neither is named ("tied:"), the side of it carried in the model for its
  fit ("carried:"; not a name, the model's better observer), the tests it flagged, and
  whether that is the expected verdict (for the transducer case: nothing physical named and
  "unexplained" or a sensor effect on CD);
- the validation fit_TOT before and after;
- the reachable fit: the expected structure in the library's terms fitted offline at the
  loop's rate on the same estimation tests (the flagged broken tests left out), from typical
  starting values and, where the loop named the same structure, from the loop's own result;
  the better of the two, scored on the same validation tests;
- the gap (reachable - after) and the loop's time;
- whether the expected structure itself passes the loop's rule against the grey-box
  ("truth"): both cross-validated leave-one-test-out on the estimation tests as the loop does
  and judged by ``evidence.judge`` at the loop's margin ("pass", or "fail" with its mean gain
  and tests improved; "-" where nothing physical is expected). A miss whose truth fails is
  beyond any search over the library: the six estimation tests do not defend it;
- at the end: how many cases are right, and how many named effects are there and not there,
  and how many refused or tied effects are there and not there; how many sensor corrections
  were named where that output's transducer is not at fault (each makes its case wrong).

    python -m benchmarks.loop_heldout
        [--set a|b|...|z|aa|ab|ac|ad|ae|af|ag|ah|ai|aj|ak|al|am|an|ao|ap|aq|ar|as|at|au|av]
        [--cases NAME ...] [--sets DIR] [--out DIR] [--workers N]
        [--json FILE] [--est-times K] [--new-crashes]
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from benchmarks.heldout.cases import Case, more_tests
from benchmarks.heldout.make_sets import more_tests_options
from benchmarks.heldout.sets import SETS, select
from observer_node.data import CrashDataError, load_tests
from observer_node.ident.dataset import Dataset, make_dataset
from observer_node.loop.closed_loop import run_loop
from observer_node.loop.evidence import Evidence, judge
from observer_node.loop.refit import Refit, finite, fold_scores, folds, refit, score, where_stalled
from observer_node.loop.report import AcceptedEffect, LoopReport
from observer_node.model.effects import EFFECTS


def _sim_scope(setups: list[str], report: LoopReport) -> str:
    """A loop scope (its setup names) as the simulator's setups (the tests' name prefixes)."""
    if not setups:
        return "all"
    prefix = {s.name: sorted({t.split("_")[0] for t in s.tests}) for s in report.setups}
    return "+".join(sorted(p for s in setups for p in prefix[s]))


def _as_judged(kind_scope: str, judged: list[str], every: list[str]) -> str | None:
    """An expected ``kind@scope`` (simulator setups) restricted to the rigs that hold at least
    two estimation tests (``judged``): what the loop can be asked to name; None when the
    effect is on no such rig. A scope over ``every`` rig is "all"."""
    kind, scope = kind_scope.split("@")
    rigs = [r for r in (every if scope == "all" else scope.split("+")) if r in judged]
    if not rigs:
        return None
    return f"{kind}@{'all' if set(rigs) == set(every) else '+'.join(sorted(rigs))}"


def _there(kind_scope: str, row: dict) -> bool:
    """Whether a named ``kind@scope`` is there: expected, or expected on the judged rigs."""
    return kind_scope in row["expected"] or _as_judged(
        kind_scope, row["judged_rigs"], row["rigs"]) in row["expected_judged"]


def _expected_structure(case: Case, report: LoopReport, delays_ticks: dict[str, float]
                        ) -> list[dict]:
    """The expected effects in the library's terms, started from typical values."""
    by_sim = {p: s.name for s in report.setups for p in {t.split("_")[0] for t in s.tests}}
    out = []
    for kind, scope in case.expect:
        params = dict(EFFECTS[kind].typical)
        if kind == "input_delay":
            params = {"n_pulse": delays_ticks.get("pulse", 0.0),
                      "n_brs": delays_ticks.get("brs", 0.0)}
        if kind == "sensor_offset":
            params = {"cr_g": 0.0, "cd_mm": 0.0}
        e: dict = {"kind": kind, "parameters": params}
        if scope != "all":
            e["setups"] = sorted({by_sim[p] for p in scope.split("+") if p in by_sim})
        out.append(e)
    return out


def _delays(case: Case, rate_hz: float) -> dict[str, float]:
    out = {}
    for e in case.effects:
        if e.key in ("pulse_late", "brs_late"):
            out[e.key.split("_")[0]] = e.size * rate_hz
    return out


def wrong_sensors(expect_note: str | None, sensor: list[str]) -> list[str]:
    """The outputs a sensor correction was named on whose transducer is not at fault: every
    one but the transducer case's own output ("... on cd"). A sensor correction is a finding
    about a transducer, so one named there makes the case wrong as a physical effect would."""
    own = expect_note.rsplit(" ", 1)[-1] if expect_note else None
    return [o for o in sensor if o != own]


def run_case(case: Case, sets: Path, work: Path, workers: int | None) -> dict:
    est = load_tests([sets / case.name / "est"])
    val = load_tests([sets / case.name / "val"])
    t0 = time.monotonic()
    r = run_loop(est, val, work / case.name, verbose=False, plots=False, ratings=False,
                 workers=workers)
    seconds = time.monotonic() - t0
    found = sorted(f"{e.kind}@{_sim_scope(e.setups or [], r)}" for e in r.effects)
    # passed the rule, not named: a rival of another kind passes too, not told apart
    tied = sorted(f"{p.kind}@{_sim_scope([] if p.scope == 'all' else p.scope.split('+'), r)}"
                  for p in r.possible if "cannot tell it from" in p.why_not)
    # passed the rule, refused because the validation tests do not confirm it
    refused = sorted(f"{p.kind}@{_sim_scope([] if p.scope == 'all' else p.scope.split('+'), r)}"
                     for p in r.possible if "do not confirm" in p.why_not)
    # of those, the ones whose validation fit fell on setups no estimation test judges and
    # the effect does not act on, the rest holding (report: "..., which no estimation test
    # judges")
    refused_unjudged = sorted(
        f"{p.kind}@{_sim_scope([] if p.scope == 'all' else p.scope.split('+'), r)}"
        for p in r.possible
        if "do not confirm" in p.why_not and "which no estimation test judges" in p.why_not)
    expected = sorted(f"{k}@{'+'.join(sorted(s.split('+')))}" for k, s in case.expect)
    # in the model for its fit, not named (the better side of a tie)
    carried = sorted(f"{e.kind}@{_sim_scope(e.setups or [], r)}" for e in r.carried)
    flagged = sorted({w.test for w in r.warnings})
    sensor = [s.output for s in r.sensor_effects]
    unexpl = [u.output for u in r.unexplained]
    right = found == expected and flagged == sorted(case.expect_broken)
    # Scored again on the rigs the estimation tests hold at least twice, counted here from
    # the tests themselves (the truly broken ones left out), not from the loop's report: a
    # rig held once or not at all cannot be judged, the loop claims nothing there
    # (closed_loop.MIN_JUDGED), and both the expected and the named scopes are cut to them.
    kept = [t.name.split("_")[0] for t in est if t.name not in case.expect_broken]
    every = sorted({t.name.split("_")[0] for t in (*est, *val)
                    if t.name not in case.expect_broken})
    judged = [rig for rig in every if kept.count(rig) >= 2]
    as_judged = sorted(e for e in (_as_judged(x, judged, every) for x in expected) if e)
    found_judged = sorted(e for e in (_as_judged(x, judged, every) for x in found) if e)
    right_judged = found_judged == as_judged and flagged == sorted(case.expect_broken)
    if case.expect_note:  # a transducer case: nothing physical, and its output called out
        output = case.expect_note.rsplit(" ", 1)[-1]  # "... on cd"
        right = right and (output in sensor or output in unexpl)
        right_judged = right_judged and (output in sensor or output in unexpl)
    # a rate limit read off a channel (.rate_limit) is a finding about a transducer too
    rate_limited = [u.output for u in r.unexplained if u.shape == "rate_limit"]
    wrong_sensor = wrong_sensors(case.expect_note, sensor)
    rate_limited_wrong = wrong_sensors(case.expect_note, rate_limited)
    wrong_sensor += [f"{o} rate limit" for o in rate_limited_wrong]
    right = right and not wrong_sensor
    right_judged = right_judged and not wrong_sensor
    row = {"case": case.name, "found": found, "expected": expected, "flagged": flagged,
           "rigs": every, "judged_rigs": judged, "expected_judged": as_judged,
           "right_judged": right_judged,
           "sensor": sensor, "wrong_sensor": wrong_sensor, "unexplained": unexpl,
           "rate_limited": rate_limited, "rate_limited_wrong": rate_limited_wrong,
           "right": right, "tied": tied,
           "carried": carried, "refused": refused, "refused_unjudged": refused_unjudged,
           "before": r.baseline.fit.total, "after": r.final.fit.total,
           "seconds": seconds, "possible": [f"{p.kind}@{p.scope}" for p in r.possible]}
    row["named"] = [_how_named(e, r) for e in r.effects]
    row["reachable"] = _reachable(case, r, est, val, found == expected)
    row["truth"] = _truth_by_the_rule(case, r, est)
    return row


def _how_named(e: AcceptedEffect, r: LoopReport) -> dict:
    """How a named effect got its name, for counting mimics against truths across sets
    without rerunning them: the rule's paired gain [points], its 95 % interval, tests
    improved, the sign test's p, the mean gain [points] on the tests it acts on and on the
    others (a gain outside its scope is the shared base parameters'), its warnings (a tie
    told apart by the validation tests among them) and its runner-up."""
    ev = e.evidence.rule
    inside = set(e.applies_to or ev.test_gain_points)
    gains = ev.test_gain_points
    return {"effect": f"{e.kind}@{_sim_scope(e.setups or [], r)}",
            "gain_points": round(ev.gain_points, 2),
            "ci95_points": [round(v, 2) for v in ev.ci95_points],
            "tests_improved": ev.tests_improved, "tests": ev.tests,
            "sign_test_p": round(ev.sign_test_p, 3),
            "gain_in_scope_points": _mean_or_none([g for n, g in gains.items() if n in inside]),
            "gain_out_of_scope_points": _mean_or_none(
                [g for n, g in gains.items() if n not in inside]),
            "warnings": e.warnings,
            "told_by_validation": any("by the validation tests" in w for w in e.warnings),
            "runner_up": (None if e.evidence.runner_up is None
                          else f"{e.evidence.runner_up.kind}@{e.evidence.runner_up.scope}")}


def _mean_or_none(xs: list[float]) -> float | None:
    return round(float(np.mean(xs)), 2) if xs else None


def _truth_by_the_rule(case: Case, r: LoopReport, est_tests: list) -> dict | None:
    """The expected structure judged by the loop's own rule against the grey-box, both
    cross-validated leave-one-test-out on the estimation tests (the truly broken left out)
    as the loop does; the rule reads the setups held by at least two estimation tests. None
    when nothing physical is expected (clean, broken-test and transducer cases)."""
    effects = _expected_structure(case, r, _delays(case, r.settings.rate_hz))
    if not effects:
        return None
    keep = [t for t in est_tests if t.name not in case.expect_broken]
    est = make_dataset(keep, r.settings.rate_hz)
    ev, _ = by_the_rule(dict(r.baseline.parameters), effects, est, r.settings.margin)
    return {"passes": ev.accepted, "gain": ev.gain_points, "improved": ev.tests_improved,
            "tests": ev.tests, "reason": ev.reason}


def by_the_rule(base: dict, effects: list[dict], est: Dataset, margin: float
                ) -> tuple[Evidence, Refit]:
    """``effects`` judged by the loop's rule against the grey-box ``base``: both refitted on
    the estimation tests and cross-validated leave-one-test-out as the loop does, the rule
    reading the setups held by at least two tests; and the effects' refit."""
    held = {s: est.setups.count(s) for s in est.setups}
    setup_of = ({n: s for n, s in zip(est.names, est.setups, strict=True) if held[s] >= 2}
                or dict(zip(est.names, est.setups, strict=True)))
    cv: list[dict[str, float]] = []
    with np.errstate(all="ignore"):
        for eff in ([], effects):
            fit = refit(base, eff, est, max_nfev=150 if eff else 60)
            # a stalled fold's tests as the loop counts them (rounds.cross_validate)
            instead = cv[0] if cv else {n: finite(v.total) for n, v in
                                        score(fit.base, fit.effects, est).tests.items()}
            cv.append(where_stalled({n: v for tr, te in folds(est) for n, v in
                                     fold_scores(fit.base, fit.effects, est, tr, te).items()},
                                    instead))
    return judge(cv[0], cv[1], setup_of, None, margin), fit


def _truth_cell(t: dict | None) -> str:
    if t is None:
        return "-"
    return "pass" if t["passes"] else f"fail {t['gain']:+.1f} {t['improved']}/{t['tests']}"


def _reachable(case: Case, r: LoopReport, est_tests: list, val_tests: list, same: bool) -> float:
    keep = [t for t in est_tests if t.name not in case.expect_broken]
    est = make_dataset(keep, r.settings.rate_hz)
    val = make_dataset([t for t in val_tests if t.name not in case.expect_broken],
                       r.settings.rate_hz)
    base = dict(r.baseline.parameters)
    effects = _expected_structure(case, r, _delays(case, r.settings.rate_hz))
    with np.errstate(all="ignore"):
        fit = refit(base, effects, est, max_nfev=150)
        best = score(fit.base, fit.effects, val).fit.total
        if same and r.effects:
            loop_fit = refit(r.final.parameters, [e.model_entry() for e in r.effects], est,
                             max_nfev=60)
            best = max(best, score(loop_fit.base, loop_fit.effects, val).fit.total)
    return float(best)


def generate(case_set: str, cases: list[Case], out: Path, est_times: int = 1,
             new_crashes: bool = False) -> Path:
    """The cases' crash tests (named as written; ``est_times``, ``new_crashes``: see
    ``cases.more_tests``), simulated into ``out`` by ``benchmarks.heldout.make_sets``."""
    subprocess.run([sys.executable, "-m", "benchmarks.heldout.make_sets", "--out", str(out),
                    "--set", case_set, "--est-times", str(est_times),
                    *(["--new-crashes"] if new_crashes else []),
                    *[x for c in cases for x in ("--case", c.name)]], check=True)
    return out


def cases_and_sets(prog: str, case_set: str, names: list[str] | None, sets: Path | None,
                   est_times: int = 1, new_crashes: bool = False) -> tuple[list[Case], Path]:
    """The cases named from ``case_set`` (on ``est_times`` as many estimation tests, on new
    crashes: ``cases.more_tests``) and the folder of their generated tests (``sets``, else
    generated into a temporary folder); an unknown case, a bad count, or a case ``sets`` does
    not hold: one line, exit 2."""
    try:
        written = select(names, case_set)
        cases = [more_tests(c, est_times, new_crashes) for c in written]
    except ValueError as e:
        print(f"{prog}: {e}", file=sys.stderr)
        sys.exit(2)
    if sets is None:
        return cases, generate(case_set, written, Path(tempfile.mkdtemp()) / "sets",
                               est_times, new_crashes)
    missing = [(w, c) for w, c in zip(written, cases, strict=True)
               if not all((sets / c.name / part).is_dir() for part in ("est", "val"))]
    if missing:
        w, c = missing[0]
        flags = (f" --est-times {est_times}" if est_times != 1 else "") + (
            " --new-crashes" if new_crashes else "")
        print(f"{prog}: {sets} holds no tests of {c.name} (make them with python -m "
              f"benchmarks.heldout.make_sets --set {case_set} --case {w.name}{flags} "
              f"--out {sets})", file=sys.stderr)
        sys.exit(2)
    return cases, sets


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--set", dest="case_set", choices=SETS, default="a",
                    help="set A (cases.py, default), or B ... Z, AA, AB, AC, AD, AE, AF, AG, "
                         "AH, AI, AJ, AK, AL, AM, AN, AO, AP, AQ, AR, AS, AT, AU, AV "
                         "(cases_b.py ... cases_z.py, cases_aa.py, cases_ab.py, cases_ac.py, "
                         "cases_ad.py, cases_ae.py, cases_af.py, cases_ag.py, cases_ah.py, "
                         "cases_ai.py, cases_aj.py, cases_ak.py, cases_al.py, cases_am.py, "
                         "cases_an.py, cases_ao.py, cases_ap.py, cases_aq.py, cases_ar.py, "
                         "cases_as.py, cases_at.py, cases_au.py, cases_av.py)")
    ap.add_argument("--cases", nargs="+", metavar="NAME", help="only these cases of the set")
    ap.add_argument("--sets", type=Path, help="the generated sets (default: generate them "
                    "into a temporary folder with benchmarks.heldout.make_sets)")
    ap.add_argument("--out", type=Path, help="keep each case's loop report in OUT/CASE")
    ap.add_argument("--workers", type=int, help="Dask workers per loop (default: one per core)")
    ap.add_argument("--json", type=Path, help="also write the rows as JSON")
    more_tests_options(ap)  # --sets must then hold make_sets run with the same two
    a = ap.parse_args()
    cases, sets = cases_and_sets("loop_heldout", a.case_set, a.cases, a.sets, a.est_times,
                                 a.new_crashes)
    w = max(20, *(len(c.name) + 1 for c in cases))
    work = a.out or Path(tempfile.mkdtemp())
    print(f"loop reports in {work}/CASE/report.md", flush=True)
    print(f"{'case':<{w}}{'named (kind@scope)':<46}{'flagged':<10}{'right':>6}{'judged':>7}"
          f"{'before':>8}"
          f"{'after':>7}{'reach':>7}{'gap':>6}{'time s':>8}  truth", flush=True)
    rows = []
    refusals = []  # (case, names an expected broken test's file)
    for case in cases:
        try:
            row = run_case(case, sets, work, a.workers)
        except CrashDataError as e:  # the reader refuses a file, as the loop's CLI would
            named = any(f"/{t}/" in str(e) for t in case.expect_broken)
            refusals.append((case.name, named))
            print(f"{case.name:<{w}}refused by the reader"
                  f"{' (the broken test expected)' if named else ''}: {e}", flush=True)
            continue
        rows.append(row)
        reach = row.get("reachable", math.nan)
        named = ", ".join(row["found"]) or "(none)"
        if row["tied"]:
            named += f"; tied: {'|'.join(row['tied'])}"
        if row["carried"]:
            named += f"; carried: {','.join(row['carried'])}"
        if row["refused"]:
            named += "; refused: " + ",".join(
                f"{x} (fell on unjudged rigs)" if x in row.get("refused_unjudged", []) else x
                for x in row["refused"])
        if row["sensor"]:
            named += f"; sensor: {','.join(row['sensor'])}"
        if row["unexplained"]:
            named += f"; unexplained: {','.join(row['unexplained'])}"
        print(f"{case.name:<{w}}{named:<46}{','.join(row['flagged']) or '-':<10}"
              f"{'yes' if row['right'] else 'NO':>6}{'yes' if row['right_judged'] else 'NO':>7}"
              f"{row['before']:8.1f}{row['after']:7.1f}"
              f"{reach:7.1f}{reach - row['after']:6.1f}{row['seconds']:8.1f}  "
              f"{_truth_cell(row['truth'])}", flush=True)
        if not row["right"] or not row["right_judged"]:
            print(f"{'':<{w}}expected: {', '.join(row['expected']) or '(none)'}"
                  + (f" (on the rigs held at least twice, {'+'.join(row['judged_rigs'])}: "
                     f"{', '.join(row['expected_judged']) or '(none)'})"
                     if row["expected_judged"] != row["expected"] else "")
                  + (f"; flag {', '.join(case.expect_broken)}" if case.expect_broken else "")
                  + (f"; {case.expect_note}" if case.expect_note else ""), flush=True)
        if a.json:
            a.json.write_text(json.dumps(rows, indent=1))
    if refusals:
        print(f"refused by the reader, not judged: {len(refusals)} (naming an expected broken "
              f"test's file: {sum(n for _, n in refusals)})", flush=True)
    ok = sum(r["right"] for r in rows)
    close = sum(r["reachable"] - r["after"] <= 2.0 for r in rows)
    both = sum(r["right"] and r["reachable"] - r["after"] <= 2.0 for r in rows)
    judged_ok = sum(r["right_judged"] for r in rows)
    print(f"right: {ok}/{len(rows)}; right on the judged rigs: {judged_ok}/{len(rows)}; "
          f"within 2 points of reach: {close}/{len(rows)}; both: {both}/{len(rows)}",
          flush=True)
    truths = [r["truth"] for r in rows if r["truth"] is not None]
    print(f"the expected structure passes the rule against the grey-box in "
          f"{sum(t['passes'] for t in truths)} of the {len(truths)} cases that expect one; "
          f"right in {sum(r['right'] for r in rows if r['truth'] and r['truth']['passes'])} "
          "of those", flush=True)
    for there in (False, True):
        n_named = sum(_there(f, r) == there for r in rows for f in r["found"])
        refused = sum(_there(f, r) == there for r in rows for f in r["refused"])
        tied = sum(_there(f, r) == there for r in rows for f in r["tied"])
        where = "there" if there else "not there"
        print(f"named and {where}: {n_named}; refused by the validation tests and {where}: "
              f"{refused}; tied (not named) and {where}: {tied}", flush=True)
    print("sensor corrections named where that output's transducer is not at fault: "
          f"{sum(len(r['wrong_sensor']) - len(r.get('rate_limited_wrong', [])) for r in rows)}",
          flush=True)
    limits = [f"{r['case']} ({','.join(r['rate_limited'])})" for r in rows
              if r.get("rate_limited")]
    print(f"rate limits read off an output: {len(limits)}"
          + (f" ({'; '.join(limits)})" if limits else "") + "; where that output's "
          f"transducer is not at fault: {sum(len(r.get('rate_limited_wrong', [])) for r in rows)}",
          flush=True)

if __name__ == "__main__":
    main()
