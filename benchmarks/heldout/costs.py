"""What each held-out case's effects cost the thesis grey-box: the validation fit of
``observer-node identify --model greybox`` + ``evaluate`` (the project's CLI, nothing else)
on each case, and on its twin with every effect off (same dummies, pulses and noise).

    python -m benchmarks.heldout.costs
        [--set a|b|...|z|aa|ab|ac|ad|ae|af|ag|ah|ai|aj|ak|al|am|an|ao|ap|aq|ar|as|at|au|av]
        [--case NAME ...] [--work DIR]

About 40 s per case on this machine (two identifications, two evaluations).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from .make_sets import make
from .sets import SETS, select


def _fit(data: Path, out: Path) -> dict[str, float]:
    cli = [sys.executable, "-m", "observer_node"]
    for args in (["identify", "--model", "greybox", "--data", str(data / "est"),
                  "--out", str(out / "model.json")],
                 ["evaluate", "--model", str(out / "model.json"), "--data", str(data / "val"),
                  "--out", str(out / "ev")]):
        r = subprocess.run(cli + args, capture_output=True, text=True, check=False)
        if r.returncode:
            raise RuntimeError(f"{' '.join(args[:1])} on {data}: {r.stderr.strip()[-300:]}")
    fit: dict[str, float] = json.loads((out / "ev" / "fits.json").read_text())["fit"]
    return fit


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.heldout.costs",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("--set", dest="case_set", choices=SETS, default="a")
    ap.add_argument("--case", action="append", metavar="NAME")
    ap.add_argument("--work", type=Path, help="keep the sets and fits here (default: temporary)")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return int(e.code or 0)
    try:
        cases = select(args.case, args.case_set)
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        work = args.work or Path(tmp)
        make(cases, work / "on", log=False)
        make(cases, work / "off", log=False, effects_on=False)
        print(f"{'case':<20} {'CR':>6} {'CD':>6} {'TOT':>6} | {'TOT without':>11} | cost")
        for c in cases:
            try:
                on = _fit(work / "on" / c.name, work / "fit-on" / c.name)
                off = on if not c.effects else _fit(work / "off" / c.name,
                                                    work / "fit-off" / c.name)
            except RuntimeError as e:
                print(f"error: {e}", file=sys.stderr)
                return 1
            print(f"{c.name:<20} {on['cr']:6.1f} {on['cd']:6.1f} {on['total']:6.1f} | "
                  f"{off['total']:11.1f} | {off['total'] - on['total']:5.1f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
