"""The loop's checks before any fit (``loop.screening.broken_before_fit``) on crash tests no
one has looked at: campaigns drawn afresh from the independent held-out simulator
(``benchmarks/heldout``), one broken channel on one test each, or none.

Each campaign: 6 estimation + 6 validation tests, each of a rig drawn uniformly (R16, SLED,
FULL), BRS counts/rev drawn from 48, 64, 96 and 128, seed ``SEED + k`` (a family no held-out
set uses: theirs lie below 40000). With probability one half it carries one physical effect of
the simulator's own forms (a kind of the loop's library drawn uniformly, then its form, then
its rigs, as set V's process draws them), so the checks are judged on tests with physics the
thesis model lacks too. Then one broken-channel form is drawn uniformly among the simulator's
(``draw_w.BROKEN``, every channel), or none with the same chance as each form, on one test
drawn uniformly. A crossed BRS file (``brs_swap``) crosses it with one other test (of
another rig when there is one: the lab's export swapped two tests' files, both broken); a
copied pulse (``pulse_from``) takes another test's. Sizes are not drawn: each form's, and each
physical form's, is the median size sets A-AB gave it. Nothing here was tuned on the draws.

Printed: per broken form, how many were drawn, how many of those the fault changed by more than
the channel's own noise (``changed``: a counter of too few bits that never passed its half
range, a poll slow enough to lose no count or one, a rail above the channel's peak leave the
file as it would be without the fault, or within one count or the noise, and no check can see
them; the noise is the lab's white noise before the CFC filters, so on CR, filtered at 180
Hz, the bar is about four times the recorded noise, on CD about twice, on the unfiltered
pulse once), how often the broken test was named (and on the broken channel; of the changed
ones apart), and the clean tests named beside it; for all campaigns, how many clean tests
were named, by which check; and per form the campaigns the reader refused in one line naming
the broken test's file (a unit that cannot be right, say), which are not judged. The checks
that run after the fit (a residual far below the others') are not part of this: a broken
test not found here may still be found there.

    python -m benchmarks.screen_faults [--campaigns 300] [--seed 50000] [--json FILE]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
import tempfile
import time
from collections import Counter, defaultdict
from pathlib import Path

import numpy as np

from benchmarks.heldout import lab
from benchmarks.heldout.cases import ALL, Case, Effect, test_names
from benchmarks.heldout.draw_v import KINDS, forms, scopes
from benchmarks.heldout.draw_w import BROKEN
from benchmarks.heldout.make_sets import make
from benchmarks.heldout.sets import SETS, case_set
from observer_node.data import CrashDataError, load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import broken_before_fit

SEED = 50000
END_S = 0.15  # the loop's scoring window ends here
BY_PLACE = ("brs_swap", "pulse_from")  # sized by which test, not by how much
BATCH = 20  # campaigns simulated at once
CHANNEL_AT = {"pulse": 0, "brs": 1, "cr": 2, "cd": 3}  # lab.record's order of channels


def median_sizes() -> dict[str, float]:
    """The median magnitude each simulator key was given over every case of sets A-AB."""
    sizes: dict[str, list[float]] = defaultdict(list)
    for s in SETS:
        for c in case_set(s):
            for e in c.effects:
                if e.size:
                    sizes[e.key].append(abs(e.size))
    return {k: float(np.median(v)) for k, v in sizes.items()}


def draw_campaign(k: int, seed0: int, size: dict[str, float]) -> Case:
    rng = np.random.default_rng(seed0 + k)
    est = tuple(str(x) for x in rng.choice(ALL, 6))
    val = tuple(str(x) for x in rng.choice(ALL, 6))
    counts = int(rng.choice([48, 64, 96, 128]))
    effects: list[Effect] = []
    if rng.uniform() < 0.5:
        kind = str(rng.choice(KINDS))
        form = str(rng.choice([f for f in forms(kind) if f in size]))
        rigs = [s for s in scopes(kind) if all(r in est + val for r in s)]
        effects.append(Effect(form, size[form], rigs[int(rng.integers(len(rigs)))]))
    pool = [f for fs in BROKEN.values() for f in fs if f in size or f in BY_PLACE]
    pick = int(rng.integers(len(pool) + 1))
    est_names, val_names = test_names(Case("x", 0, est, val, counts))
    order = [*est_names, *val_names]  # lab.draw's order, which brs_swap's offset counts in
    broken: tuple[str, ...] = ()
    form = "clean"
    if pick < len(pool):
        form = pool[pick]
        i = int(rng.integers(12))
        rigs_of = [*est, *val]
        if form in BY_PLACE:
            other = [j for j in range(12) if j != i and rigs_of[j] != rigs_of[i]] or \
                [j for j in range(12) if j != i]
            j = int(rng.choice(other))
            effects.append(Effect(form, float(j - i), tests=(order[i],)))
            broken = (order[i],)
            if form == "brs_swap":
                effects.append(Effect(form, float(i - j), tests=(order[j],)))
                broken = (order[i], order[j])
        else:
            effects.append(Effect(form, size[form], tests=(order[i],)))
            broken = (order[i],)
    return Case(f"sf{k:04d}_{form}", seed0 + k, est, val, counts, tuple(effects),
                expect_broken=broken)


def changed(case: Case, drawn: list[lab.Drawn], first: int,
            sim: dict[str, np.ndarray]) -> list[str]:
    """The broken tests of ``case`` whose broken channel the fault moved, at some sample, by
    more than the channel's white noise (``lab.NOISE``, before the filters; one count on the
    spindle, so a poll that lost one count here and there is not counted): each
    recorded again as its twin with the broken form off. The lab's noise is drawn the same
    with or without a fault, and the fault is the recorder's, so the physics ``sim`` (of the
    batch, this case's tests from ``first`` on, as ``make`` drew them) serves both."""
    form = case.name.split("_", 1)[1]
    if not case.expect_broken:
        return []
    chan = next(ch for ch, fs in BROKEN.items() if form in fs)
    floor = {"pulse": lab.NOISE["pulse_g"], "cr": lab.NOISE["cr_g"],
             "cd": lab.NOISE["cd_mm"], "brs": 360.0 / case.counts_per_rev}[chan]
    twin = dataclasses.replace(case, effects=tuple(
        dataclasses.replace(e, size=0.0) if e.key == form else e for e in case.effects))
    twins, _ = lab.draw(twin)
    names = [d.name for d in twins]
    out = []
    for name in case.expect_broken:
        i = names.index(name)
        rng = np.random.default_rng([case.seed, 1])  # as make() draws the lab's noise
        for j in range(i):  # the tests before it, to the noise it was drawn with
            lab.record(twins[j], first + j, sim, case.counts_per_rev, rng)
        state = rng.bit_generator.state
        reads = []
        for d in (drawn[first + i], twins[i]):
            rng.bit_generator.state = state
            test, _ = lab.record(d, first + i, sim, case.counts_per_rev, rng)
            reads.append(np.asarray(test.channels[CHANNEL_AT[chan]].values))
        if np.max(np.abs(reads[0] - reads[1])) > floor:
            out.append(name)
    return out


def judge(case: Case, folder: Path) -> dict:
    files: list[str | Path] = [*sorted((folder / "est").iterdir()),
                               *sorted((folder / "val").iterdir())]
    form = case.name.split("_", 1)[1]
    try:
        tests = load_tests(files)
    except CrashDataError as e:  # the reader refuses a file (a mislabelled unit, a run-away)
        return {"case": case.name, "form": form, "refused": str(e),
                "refused_broken": any(f"/{t}/" in str(e) for t in case.expect_broken)}
    assign_setups(tests)
    found = broken_before_fit(tests, END_S)
    channel = next((ch for ch, fs in BROKEN.items() if form in fs), "")
    named = {b.test: b for b in found}
    return {"case": case.name, "form": form, "broken": list(case.expect_broken),
            "found": [t for t in case.expect_broken if t in named],
            "on_channel": [t for t in case.expect_broken
                           if t in named and named[t].channel == channel],
            "clean_named": [[b.test, b.channel, b.reason] for b in found
                            if b.test not in case.expect_broken],
            "clean_tests": 12 - len(case.expect_broken)}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.screen_faults",
                                 description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--campaigns", type=int, default=300, help="how many (default 300)")
    ap.add_argument("--seed", type=int, default=SEED, help=f"the first seed (default {SEED})")
    ap.add_argument("--json", type=Path, help="write every campaign's result here")
    args = ap.parse_args(argv)
    size = median_sizes()
    cases = [draw_campaign(k, args.seed, size) for k in range(args.campaigns)]
    rows = []
    t0 = time.perf_counter()
    for b in range(0, len(cases), BATCH):
        batch = cases[b:b + BATCH]
        with tempfile.TemporaryDirectory() as tmp:  # a batch's files, gone once judged
            drawn, sim = make(batch, Path(tmp), log=False)
            first = 0
            for c in batch:
                row = judge(c, Path(tmp) / c.name)
                if "refused" not in row:
                    row["changed"] = changed(c, drawn, first, sim)
                rows.append(row)
                first += len(c.est) + len(c.val)
        print(f"  {len(rows)} of {len(cases)} campaigns judged, "
              f"{time.perf_counter() - t0:.0f} s", file=sys.stderr, flush=True)
    report(rows)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1) + "\n")
    return 0


def report(rows: list[dict]) -> None:
    refused: Counter[str] = Counter()
    for r in rows:
        if "refused" in r:
            print(f"  {r['case']}: not judged, the reader refused it: {r['refused']}")
            refused[r["form"]] += bool(r.get("refused_broken"))
    rows = [r for r in rows if "refused" not in r]
    by_form: dict[str, list[dict]] = defaultdict(list)
    for r in rows:
        by_form[r["form"]].append(r)
    # refused: campaigns the reader refused in one line naming the broken test's file (not
    # judged by the checks, not counted as drawn)
    print(f"{'form':22s} {'drawn':>5s} {'changed':>7s} {'found':>5s} {'on its channel':>14s} "
          f"{'found of changed':>16s} {'clean tests named':>17s} {'refused':>7s}")
    for form in sorted(set(by_form) | set(refused), key=lambda f: (f == "clean", f)):
        rs = by_form[form]
        n = sum(len(r["broken"]) for r in rs)
        moved = sum(len(r.get("changed", r["broken"])) for r in rs)
        seen = sum(len(set(r["found"]) & set(r.get("changed", r["broken"]))) for r in rs)
        print(f"{form:22s} {n:5d} {moved:7d} {sum(len(r['found']) for r in rs):5d} "
              f"{sum(len(r['on_channel']) for r in rs):14d} {seen:16d} "
              f"{sum(len(r['clean_named']) for r in rs):17d} {refused[form]:7d}")
    clean = sum(r["clean_tests"] for r in rows)
    wrong = [c for r in rows for c in r["clean_named"]]
    print(f"clean tests named: {len(wrong)} of {clean} "
          f"({100.0 * len(wrong) / max(clean, 1):.2f} %), by what they were named for: "
          f"{dict(Counter(_check(c[2]) for c in wrong))}")
    for r in rows:
        for c in r["clean_named"]:
            print(f"  {r['case']}: {c[0]} {c[1]}: {c[2][:110]}")


def _check(reason: str) -> str:
    """Which check wrote a reason (its first words)."""
    return " ".join(reason.split()[:3])


if __name__ == "__main__":
    sys.exit(main())
