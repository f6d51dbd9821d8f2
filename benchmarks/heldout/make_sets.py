"""Write the held-out crash sets: DIR/<case>/est/<TEST>/..., DIR/<case>/val/<TEST>/... and
DIR/<case>/truth.json (the case, the expected verdict, the true parameters of every test).
Deterministic from each case's seed.

    python -m benchmarks.heldout.make_sets --out DIR
        [--set a|b|...|z|aa|ab|ac|ad|ae|af|ag|ah|ai|aj|ak|al|am|an|ao|ap|aq|ar|as|at|au|av]
        [--case NAME ...] [--est-times K] [--new-crashes] [--no-effects]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from . import lab
from . import physics as ph
from .cases import CASES, Case, more_tests
from .iso_mme import write_test
from .sets import SETS, select


def expected(case: Case) -> dict:
    return {"effects": [{"effect": k, "setups": s} for k, s in case.expect],
            "broken_tests": list(case.expect_broken), "note": case.expect_note}


def make(cases: list[Case], out: Path, log: bool = True,
         effects_on: bool = True) -> tuple[list[lab.Drawn], dict[str, np.ndarray]]:
    """Simulate every test of ``cases`` in one batch and write them under ``out``; returns
    the tests as drawn and the batch's physics (``lab.run``), for a caller that records a
    test again (a twin without a recorder's fault)."""
    t_start = time.perf_counter()
    drawn: list[lab.Drawn] = []
    pulses = []
    for c in cases:
        tests, p = lab.draw(c, effects_on)
        drawn += tests
        pulses.append(p)
    if log:
        print(f"simulating {len(drawn)} tests of {len(cases)} cases ...", flush=True)
    sim = lab.run(drawn, np.concatenate(pulses))
    i = 0
    for c in cases:
        rng = np.random.default_rng([c.seed, 1])  # the lab's noise, apart from the draw
        truths = []
        for d in drawn[i:i + len(c.est) + len(c.val)]:
            test, truth = lab.record(d, i, sim, c.counts_per_rev, rng)
            write_test(test, out / c.name / d.part)
            truths.append(truth)
            i += 1
        doc = {"case": c.as_dict(), "effects_on": effects_on, "expected": expected(c),
               "library_name": {k: v for k, v in ph.EFFECTS.items() if v},
               "tests": truths}
        (out / c.name / "truth.json").write_text(json.dumps(doc, indent=1) + "\n")
        if log:
            print(f"  {c.name}: {len(c.est)} est + {len(c.val)} val -> {out / c.name}",
                  flush=True)
    if log:
        print(f"done in {time.perf_counter() - t_start:.1f} s")
    return drawn, sim


def more_tests_options(ap: argparse.ArgumentParser) -> None:
    """--est-times and --new-crashes (``cases.more_tests``), here and in loop_heldout."""
    ap.add_argument("--est-times", type=int, default=1, metavar="K",
                    help="each case on K times its estimation tests of each rig, every crash "
                         "drawn from another seed, named CASE_estN (cases.more_tests; "
                         "default 1: as written)")
    ap.add_argument("--new-crashes", action="store_true",
                    help="every crash drawn again from yet another seed, named CASE_estN_new "
                         "(with --est-times 1: the same design on new crashes, the control "
                         "for what more tests change)")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.heldout.make_sets",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, type=Path, help="folder to write the sets into")
    ap.add_argument("--set", dest="case_set", choices=SETS, default="a", type=str.lower,
                    help="set A (cases.py, default), set B (cases_b.py), set C (cases_c.py), "
                         "set D (cases_d.py), set E (cases_e.py), set F (cases_f.py), set G "
                         "(cases_g.py), set H (cases_h.py), set I (cases_i.py), set J "
                         "(cases_j.py), set K (cases_k.py), set L (cases_l.py), set M "
                         "(cases_m.py), set N (cases_n.py), set O (cases_o.py), set P "
                         "(cases_p.py), set Q (cases_q.py), set R (cases_r.py), set S "
                         "(cases_s.py), set T (cases_t.py), set U (cases_u.py), set V "
                         "(cases_v.py), set W (cases_w.py), set X (cases_x.py), set Y "
                         "(cases_y.py), set Z (cases_z.py), set AA (cases_aa.py), set AB "
                         "(cases_ab.py), set AC (cases_ac.py), set AD (cases_ad.py), set AE "
                         "(cases_ae.py), set AF (cases_af.py), set AG (cases_ag.py), set AH "
                         "(cases_ah.py), set AI (cases_ai.py), set AJ (cases_aj.py), set AK "
                         "(cases_ak.py), set AL (cases_al.py), set AM (cases_am.py), set AN "
                         "(cases_an.py), set AO (cases_ao.py), set AP (cases_ap.py), set AQ "
                         "(cases_aq.py), set AR (cases_ar.py), set AS (cases_as.py), set AT "
                         "(cases_at.py), set AU (cases_au.py) or set AV (cases_av.py, held out "
                         "from the loop's engineers)")
    ap.add_argument("--case", action="append", metavar="NAME",
                    help="only this case of the set (repeatable); default all, in set A: "
                         + ", ".join(c.name for c in CASES))
    more_tests_options(ap)
    ap.add_argument("--no-effects", action="store_true",
                    help="the same tests with every effect off (what the effects cost)")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return int(e.code or 0)
    try:
        cases = [more_tests(c, args.est_times, args.new_crashes)
                 for c in select(args.case, args.case_set)]
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    try:
        make(cases, args.out, effects_on=not args.no_effects)
    except OSError as e:
        print(f"error: cannot write {e.filename}: {e.strerror}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
