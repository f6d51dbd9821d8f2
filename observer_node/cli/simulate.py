"""``observer-node simulate``: synthetic crash tests with known truth, from the plant
simulator."""

from __future__ import annotations

import argparse

from .. import options
from ..errors import UsageError
from ..model.effects import EFFECTS as MODEL_EFFECTS

# The effects the simulator can switch on: those with a truth form in the registry.
SIM_EFFECTS = tuple(k for k, e in MODEL_EFFECTS.items() if e.plant is not None)
MAX_SCALE = 10.0  # ten times an effect's magnitude is already far past any crash test's
MAX_COUNT = 1000  # tests per call; a campaign of 1e8 would only fill the disk


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "simulate", help="write synthetic crash tests from the plant simulator",
        description="Simulate crash tests with known truth (the thesis model, optionally with "
        "extra physical effects) and write them as ISO-MME.")
    s.add_argument("--out", required=True, help="folder to write tests into")
    s.add_argument("--setup", choices=("R16", "SLED", "FULL"), default="R16",
                   help="R16 sled rig (hard seat), SLED sled with interior, FULL full vehicle "
                   "(default %(default)s)")
    s.add_argument("--count", type=options.int_in(1, MAX_COUNT), default=4,
                   help=f"number of tests, 1-{MAX_COUNT} (default %(default)s)")
    s.add_argument("--seed", type=options.non_negative_int, default=1,
                   help="random seed of pulses, dummies and noise (default %(default)s)")
    s.add_argument("--effect", action="append", metavar="NAME[=SCALE]",
                   help="switch on a physical effect beyond the thesis model, its magnitude "
                   f"scaled by SCALE, 0-{MAX_SCALE:g} (repeatable); NAME is one of: "
                   + ", ".join(SIM_EFFECTS))
    s.add_argument("--no-noise", action="store_true", help="no sensor noise or CFC filtering")
    form = s.add_mutually_exclusive_group()
    form.add_argument("--zip", action="store_true", help="write each test as a .zip")
    form.add_argument("--csv", action="store_true", help="write CSV instead of ISO-MME")
    s.set_defaults(func=_do_simulate)


def _effects(specs: list[str]) -> dict[str, float]:
    """{effect: scale} from NAME[=SCALE] options."""
    from ..simulator import EFFECTS

    effects = {}
    for spec in specs:
        name, sep, value = spec.partition("=")
        if name not in EFFECTS:
            raise UsageError(f"--effect {spec}: unknown effect {name!r} (known: "
                             f"{', '.join(EFFECTS)})")
        try:
            scale = options.non_negative(value) if sep else 1.0
        except argparse.ArgumentTypeError as e:
            raise UsageError(f"--effect {spec}: SCALE {e}") from None
        if scale > MAX_SCALE:  # a delay of 1e9 ticks, an offset past any channel's range
            raise UsageError(f"--effect {spec}: SCALE must be {MAX_SCALE:g} or less")
        if name in effects:
            raise UsageError(f"--effect {spec}: {name} is given twice")
        effects[name] = scale
    return effects


def _do_simulate(a: argparse.Namespace) -> int:
    from ..data import write_csv, write_isomme
    from ..simulator import PlantConfig, simulate_campaign

    out = options.out_folder(a.out)
    config = PlantConfig(effects=_effects(a.effect or []), noise=not a.no_noise)
    tests = simulate_campaign(a.setup, a.count, seed=a.seed, config=config)
    # never over another test: --out may be a folder of real crash tests
    there = [p.name for t in tests for p in (out / t.name, out / f"{t.name}.zip",
                                             out / f"{t.name}.csv") if p.exists()]
    if there:
        raise UsageError(f"--out {a.out}: already holds {', '.join(there)}; simulate writes "
                         "into a new or empty folder and never over a test")
    out.mkdir(parents=True, exist_ok=True)
    for t in tests:
        path = write_csv(t, out / f"{t.name}.csv") if a.csv else write_isomme(t, out, a.zip)
        print(path)
    return 0
