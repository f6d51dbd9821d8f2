"""observer-node: the chest observer for crash benches, after Blåberg (2008).

Estimates the dummy's chest acceleration (CR) and deflection (CD) from the crash pulse and the
belt spindle rotation (BRS): identify models from crash tests, score them as the thesis does,
close the loop on what they lack, and run them as a real-time CAN observer.

The 24 crash tests bundled with the package are named campaign-a wherever tests are asked
for: campaign-a (all), or campaign-a/PATTERN for those whose names match (R16_001-012 on the
sled rig, SLED_001-006 sled with interior, FULL_001-006 full vehicle; 'campaign-a/*[13579]'
are the odd-numbered ones). Any other argument is a path: an ISO-MME folder, .zip or .csv
test, or a folder of them.

Examples::

    observer-node bench                               # the whole bench on bundled data
    observer-node evaluate                            # thesis Tables 4.1-4.3, plots
    observer-node identify --model greybox --data 'campaign-a/R16_*[13579]' --out model.json
    observer-node evaluate --model model.json --data campaign-a/R16_002 --out out/eval
    observer-node loop --estimate 'campaign-a/*[13579]' --validate 'campaign-a/*[02468]' \
        --out out/loop
    observer-node run --interface socketcan --channel vcan0 --model model.json --record run.mcap
    observer-node analyze run.mcap
    observer-node export run.mcap --to run.blf           # for CANoe; .mf4 .asc .log .trc
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from . import __version__
from .data import ChannelCodes, CrashDataError, CrashTest, bundled_campaign, load_tests
from .data.crashtest import THESIS_WINDOW_S
from .data.setups import parse_groups
from .loop.cluster import ClusterError
from .model.effects import EFFECTS as MODEL_EFFECTS
from .model.kinds import MODEL_KINDS
from .model.modelfile import ModelFileError

# The effects the simulator can switch on: those with a truth form in the registry.
SIM_EFFECTS = tuple(k for k, e in MODEL_EFFECTS.items() if e.plant is not None)


class UsageError(ValueError):
    """A command-line value that cannot be used; the message names the option."""


_TESTS_HELP = "an ISO-MME test folder, .zip or .csv, a folder of them, or campaign-a[/PATTERN]"


def _data_options(p: argparse.ArgumentParser, data: str | None) -> None:
    """Options that say how to read crash tests; ``data``: "required", "optional" (default the
    bundled campaign) or None (the command names its tests in other options)."""
    g = p.add_argument_group("crash-test data")
    if data is not None:
        g.add_argument("--data", nargs="+", required=data == "required", metavar="TEST",
                       help="crash tests: " + _TESTS_HELP
                       + ("" if data == "required" else " (default: campaign-a)"))
    g.add_argument("--pulse-code", action="append", metavar="CODE",
                   help="channel code of the crash pulse ('?' matches any character; "
                   "repeatable; default S0SLED000000ACXP, 10TUNN000000ACXP)")
    g.add_argument("--brs-code", action="append", metavar="CODE",
                   help="BRS channel code (default 11RETR0000B1AN0P)")
    g.add_argument("--cr-code", action="append", metavar="CODE",
                   help="chest acceleration channel code (default 11CHST0000H3ACXC)")
    g.add_argument("--cd-code", action="append", metavar="CODE",
                   help="chest deflection channel code (default 11CHST0000H3DSXB)")
    g.add_argument("--counts-per-rev", type=int, metavar="N",
                   help="BRS counts per spindle revolution (default: from the test's comments)")
    g.add_argument("--window", nargs=2, type=float, metavar=("START", "END"),
                   default=None, help="scoring window in s (default 0.01 0.15, the thesis's)")


def _codes(a: argparse.Namespace) -> ChannelCodes:
    d = ChannelCodes()
    return ChannelCodes(
        pulse=tuple(a.pulse_code or d.pulse), brs=tuple(a.brs_code or d.brs),
        cr=tuple(a.cr_code or d.cr), cd=tuple(a.cd_code or d.cd),
    )


def _tests(a: argparse.Namespace) -> list[CrashTest]:
    paths = a.data or [bundled_campaign()]
    return load_tests(paths, _codes(a), a.counts_per_rev)


def cmd_identify(a: argparse.Namespace) -> int:
    from .evaluation import identify
    from .ident.dataset import make_dataset
    from .ident.progress import Progress

    tests = _tests(a)
    data = make_dataset(tests, a.rate, tuple(a.window or THESIS_WINDOW_S))
    t0 = time.monotonic()
    mf = identify(a.model, data, nmax=a.nmax, order=a.order, m1_kg=a.m1,
                  progress=Progress(f"identify {a.model}", enabled=not a.quiet), name=a.name)
    mf.save(a.out)
    f = mf.fits["fit"]
    print(f"{a.model} model on {len(tests)} tests at {a.rate:g} Hz "
          f"({time.monotonic() - t0:.1f} s) -> {a.out}")
    print(f"fit on its estimation tests: CR {f['cr']:.1f} %  CD {f['cd']:.1f} %  "
          f"TOT {f['total']:.1f} %  (not a validation fit)")
    for line in MODEL_KINDS[mf.kind].describe(mf):
        print(line)
    return 0


def cmd_evaluate(a: argparse.Namespace) -> int:
    from .criteria import format_criteria
    from .evaluation import evaluate_model, format_tables, thesis_comparison
    from .iso18571 import grade
    from .model.modelfile import ModelFile

    tests = _tests(a)
    window = tuple(a.window) if a.window else None
    out = Path(a.out)
    if a.model:
        mf = ModelFile.load(a.model)
        fits = evaluate_model(mf, tests, out, window)
        f = fits["fit"]
        print(f"{mf.kind} model {mf.name!r} on {len(tests)} tests:")
        for name, v in fits["tests"].items():
            print(f"  {name:<12} CR {v['cr']:6.1f} %  CD {v['cd']:6.1f} %")
        print(f"  {'total':<12} CR {f['cr']:6.1f} %  CD {f['cd']:6.1f} %  TOT {f['total']:.1f} %")
        print("\nchest injury criteria, estimate vs measured (from t = 0):")
        print(format_criteria(fits["criteria"]))
        iso = fits.get("iso18571")
        if iso:
            print("\nISO/TS 18571 overall rating (0..1) on the fit window:")
            for name, r in iso["tests"].items():
                print(f"  {name:<12} CR {r['cr']['overall']:.3f} ({grade(r['cr']['overall'])})"
                      f"  CD {r['cd']['overall']:.3f} ({grade(r['cd']['overall'])})")
        else:
            print("\n(ISO/TS 18571 ratings: pip install 'chest-observer[iso18571]')")
        print(f"wrote {out / 'fits.json'} and plots in {out}")
        return 0
    result = thesis_comparison(tests, out, a.rate, window or THESIS_WINDOW_S,
                               verbose=not a.quiet)
    print(format_tables(result))
    print(f"\nwrote {out / 'evaluation.json'}, models in {out / 'models'}, "
          f"plots in {out / 'plots'}")
    return 0


def cmd_simulate(a: argparse.Namespace) -> int:
    from .data import write_csv, write_isomme
    from .simulator import EFFECTS, PlantConfig, simulate_campaign

    effects = {}
    for spec in a.effect or []:
        name, _, value = spec.partition("=")
        if name not in EFFECTS:
            raise UsageError(f"--effect {spec}: unknown effect {name!r} (known: "
                             f"{', '.join(EFFECTS)})")
        try:
            effects[name] = float(value) if value else 1.0
        except ValueError:
            raise UsageError(f"--effect {spec}: SCALE {value!r} is not a number") from None
    tests = simulate_campaign(a.setup, a.count, seed=a.seed,
                              config=PlantConfig(effects=effects, noise=not a.no_noise))
    out = Path(a.out)
    for t in tests:
        path = write_csv(t, out / f"{t.name}.csv") if a.csv else write_isomme(t, out, a.zip)
        print(path)
    return 0


def cmd_run(a: argparse.Namespace) -> int:
    from dataclasses import fields

    from .daemon.config import ConfigError, NodeConfig, example_toml
    from .daemon.node import run_daemon

    if a.print_config:
        print(example_toml())
        return 0

    try:
        cfg = NodeConfig.from_toml(a.config) if a.config else NodeConfig()
    except ConfigError as e:
        print(f"observer-node: error: {e}", file=sys.stderr)
        return 2
    for f in fields(NodeConfig):
        v = getattr(a, f.name, None)
        if v is not None and f.name != "core":
            setattr(cfg, f.name, v)
    if a.python_can_socketcan:
        cfg.raw_socketcan = False
    for name in ("trigger_g", "event_s", "counts_per_rev"):
        v = getattr(a, name)
        if v is not None:
            setattr(cfg.core, name, v)
    if not cfg.model:
        print("observer-node: error: run needs --model (or model in the config file)",
              file=sys.stderr)
        return 2
    try:
        cfg.check("command line" if not a.config else f"{a.config} with the command line")
    except ConfigError as e:
        print(f"observer-node: error: {e}", file=sys.stderr)
        return 2
    return run_daemon(cfg, quiet=a.quiet)


def cmd_analyze(a: argparse.Namespace) -> int:
    from .recording import RecordingError, analyze, read_recording

    try:
        rec = read_recording(a.recording)
        out = Path(a.out) if a.out else Path(a.recording).with_suffix("")
        result = analyze(rec, out_dir=out)
    except RecordingError as e:
        print(f"observer-node: error: {e}", file=sys.stderr)
        return 2
    meta = rec.metadata.get("chest-observer", {})
    print(f"{rec.path}: {result['ticks']} ticks, model {meta.get('model_kind', '?')} "
          f"{meta.get('model_name', '?')!r} at {meta.get('tick_rate_hz', '?')} Hz; "
          f"valid {100 * result['valid_share']:.1f} % of ticks; "
          f"max tick processing {result['max_proc_us']:.0f} us")
    if rec.salvaged:
        print(f"  salvaged: {rec.salvage_note}")
    for ev in result["events"]:
        line = (f"  event {ev['event']} (onset tick {ev['onset_tick']}, {ev['ticks']} ticks): "
                f"max |daemon - offline| CR {ev['max_abs_diff_offline']['cr_g']:.2g} g, "
                f"CD {ev['max_abs_diff_offline']['cd_mm']:.2g} mm")
        print(line)
        if "fit_vs_reference" in ev:
            f = ev["fit_vs_reference"]
            print(f"    fit vs reference (eq. 3.15): CR {f['cr']:.1f} %  CD {f['cd']:.1f} %  "
                  f"TOT {f['total']:.1f} %")
        c = ev["criteria"]
        est = c["estimate"]
        line = (f"    criteria: CD max {est['cd_max_mm']:.1f} mm, CR 3 ms {est['cr_3ms_g']:.1f} g,"
                f" VC max {est['vc_max_m_s']:.2f} m/s")
        if "reference" in c:
            r, d = c["reference"], c["error"]
            line += (f" (measured {r['cd_max_mm']:.1f} mm, {r['cr_3ms_g']:.1f} g, "
                     f"{r['vc_max_m_s']:.2f} m/s; error {d['cd_max_mm']:+.1f} mm, "
                     f"{d['cr_3ms_g']:+.1f} g, {d['vc_max_m_s']:+.2f} m/s)")
        print(line)
        if "iso18571" in ev:
            iso = ev["iso18571"]
            print(f"    ISO/TS 18571 overall rating: CR {iso['cr']['overall']:.3f}  "
                  f"CD {iso['cd']['overall']:.3f} (0..1; corridor, phase, magnitude, slope "
                  "in analysis.json)")
        if ev["invalid_ticks"]:
            v = ev.get("fit_vs_reference_valid")
            print(f"    {ev['invalid_ticks']} of {ev['ticks']} ticks flagged invalid (gaps in the "
                  "plots)" + (f"; on the valid ones: CR {v['cr']:.1f} %  CD {v['cd']:.1f} %"
                              if v else ""))
    if not result["events"]:
        print("  no crash event in the recording (the observer never triggered)")
    print(f"wrote {out / 'analysis.json'} and plots in {out}")
    return 0


def cmd_export(a: argparse.Namespace) -> int:
    from .recording import RecordingError
    from .recording.export import ExportError, export_frames

    try:
        n, salvaged = export_frames(a.recording, a.to, a.channel)
    except (RecordingError, ExportError) as e:
        print(f"observer-node: error: {e}", file=sys.stderr)
        return 2
    if salvaged:
        print(f"observer-node: warning: {a.recording} was cut short ({salvaged}); every frame "
              "before the cut was exported", file=sys.stderr)
    print(f"wrote {n} frames to {a.to}")
    return 0


def cmd_export_c(a: argparse.Namespace) -> int:
    from .export_c import ExportError, export_c, export_codec
    from .model.modelfile import ModelFile

    mf = ModelFile.load(a.model)
    try:
        mf = mf.for_setup(a.setup or "", a.model)
        paths = export_c(mf, Path(a.out), a.name) + export_codec(Path(a.out))
    except ExportError as e:
        print(f"observer-node: error: {a.model}: {e}", file=sys.stderr)
        return 2
    print(f"wrote {', '.join(str(p) for p in paths)} ({mf.kind} {mf.name!r}, "
          f"{mf.tick_rate_hz:g} Hz); compile with any C99 compiler, -DCO_REAL=float for float")
    return 0


def cmd_loop(a: argparse.Namespace) -> int:
    from .loop.closed_loop import run_loop

    if a.workers is not None and a.workers < 1:
        raise UsageError(f"--workers {a.workers}: needs at least one worker")
    codes, cpr = _codes(a), a.counts_per_rev
    est = load_tests(a.estimate, codes, cpr)
    val = load_tests(a.validate, codes, cpr)
    r = run_loop(est, val, Path(a.out), a.rate, tuple(a.window or THESIS_WINDOW_S),
                 a.margin, verbose=not a.quiet, groups=parse_groups(a.group),
                 anywhere=a.allow_anywhere, scheduler=a.scheduler, workers=a.workers)
    print((Path(a.out) / "report.md").read_text())
    print(f"wrote {a.out}/report.json, report.md, model.json and plots "
          f"({r['seconds']} s)")
    return 0


def cmd_bench(a: argparse.Namespace) -> int:
    from .bench import DEFAULT_TESTS, run_bench

    run_bench(Path(a.out), a.model, a.interface, a.channel, tuple(a.test or DEFAULT_TESTS),
              a.rate, rerun_loop=a.rerun_loop)
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="observer-node", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    s = sub.add_parser(
        "bench", help="the whole bench: replay bundled tests into the daemon, record, analyse",
        description="Take the loop's model (shipped with this version, reused from an earlier "
        "bench, or made here with --rerun-loop) or --model, start the daemon on vcan0 if it "
        "exists (else on an in-process virtual bus), replay bundled crash tests with reference "
        "frames, record to MCAP and print the analysis beside the offline evaluation of the "
        "thesis grey-box and the loop's model.")
    s.add_argument("--model", help="model file (default: the loop's model on the bundled "
                   "campaign's odd-numbered tests)")
    s.add_argument("--rerun-loop", action="store_true",
                   help="run observer-node loop here (about 2 min) instead of reusing its "
                   "result from an earlier bench or the one shipped with this version")
    s.add_argument("--interface", default="auto",
                   help="auto (socketcan if the channel exists, else virtual), socketcan, ...")
    s.add_argument("--channel", default="vcan0")
    s.add_argument("--test", action="append", metavar="NAME",
                   help="bundled test to replay (repeatable; default R16_002 SLED_002 FULL_002)")
    s.add_argument("--rate", type=float, default=1.0, help="replay time scale (default 1)")
    s.add_argument("--out", default="out/bench", help="output folder (default out/bench)")
    s.set_defaults(func=cmd_bench)

    s = sub.add_parser(
        "loop", help="find what the grey-box model lacks, add it, refit, report",
        description="Identify the thesis grey-box model on the estimation tests, analyse its "
        "residual, trace it to a physical effect of the library (or a sparse formula), add it, "
        "refit, and name it only if it beats test-to-test scatter: each estimation test's "
        "cross-validated fit with and without it, paired, must gain --margin points on average "
        "with a 95 % interval above zero (or a sign test, p <= 0.0625), and no setup may lose; "
        "repeat; report fits before and after on the validation tests. Tests that look broken "
        "(missing, frozen, saturated or spiking channels, a fit far below the others') are "
        "named and left out; a one-output static error is reported as a sensor effect; what "
        "nothing explains is reported as unexplained. Tests are grouped in "
        "setups by their .mme metadata (or --group); each effect is tried on every test and on "
        "the setups that could have it (never an airbag on a hard-seat rig), and "
        "cross-validation chooses. The report gives each effect's scope, the runner-up and its "
        "margin, standard errors and warnings; model.json carries the scope (run --setup).")
    s.add_argument("--estimate", nargs="+", required=True, metavar="TEST",
                   help="tests to identify and cross-validate effects on: " + _TESTS_HELP)
    s.add_argument("--validate", nargs="+", required=True, metavar="TEST",
                   help="held-out tests the report scores before and after (never fitted on)")
    s.add_argument("--out", required=True, help="output folder")
    s.add_argument("--margin", type=float, default=1.0,
                   help="mean paired fit_TOT points an effect must add in cross-validation "
                   "(default 1)")
    s.add_argument("--group", action="append", metavar="NAME=PATTERN",
                   help="put tests whose name matches PATTERN in setup NAME (repeatable; "
                   "default: tests whose .mme has the same type of test, title and test object "
                   "share a setup)")
    s.add_argument("--allow-anywhere", action="store_true",
                   help="try effects on setups whose metadata rules them out too (an airbag "
                   "on a rig that says hard seat or no interior)")
    _data_options(s, data=None)
    s.add_argument("--rate", type=float, default=1000.0, help="tick rate in Hz (1000)")
    s.add_argument("--scheduler", metavar="ADDRESS",
                   help="run the refits on the Dask cluster at ADDRESS (tcp://HOST:8786); "
                   "default: a local cluster in this process, one worker per core")
    s.add_argument("--workers", type=int, metavar="N",
                   help="workers of the local cluster (default: one per core, at most 4)")
    s.add_argument("--quiet", action="store_true", help="no progress display")
    s.set_defaults(func=cmd_loop)

    s = sub.add_parser("identify", help="fit a grey-box, ARX or N4SID model to crash tests",
                       description="Fit one model to crash tests and write its JSON model file.")
    s.add_argument("--model", choices=tuple(MODEL_KINDS), required=True,
                   help="; ".join(f"{k}: {m.description}" for k, m in MODEL_KINDS.items()))
    _data_options(s, data="required")
    s.add_argument("--out", required=True, help="model file to write (JSON)")
    s.add_argument("--rate", type=float, default=1000.0,
                   help="tick rate in Hz the model runs at (default 1000, the bus rate)")
    s.add_argument("--nmax", type=int, default=6, help="ARX: largest order searched (default 6)")
    s.add_argument("--order", type=int, default=7, help="N4SID: model order (default 7)")
    s.add_argument("--m1", type=float, default=20.0,
                   help="grey-box: fixed spine mass in kg that sets the mass scale (default 20)")
    s.add_argument("--name", help="model name stored in the file")
    s.add_argument("--quiet", action="store_true", help="no progress display")
    s.set_defaults(func=cmd_identify)

    s = sub.add_parser(
        "evaluate", help="score models with the thesis's fit (tables, plots, JSON)",
        description="Without --model: the thesis's chapter 4 on the data (default: bundled "
        "campaign): per setup, estimate ARX Nmax 10 and 6, N4SID 16 and 7 and the grey-box on "
        "the odd-numbered tests, score them on the even-numbered ones, print Tables 4.1-4.3 "
        "with the thesis's numbers beside them, and write plots and evaluation.json. "
        "With --model: score that model on the data and write OUT/fits.json and plots.")
    s.add_argument("--model", help="model file to score (default: identify and compare all)")
    _data_options(s, data="optional")
    s.add_argument("--out", default="out/evaluate", help="output folder (default out/evaluate)")
    s.add_argument("--rate", type=float, default=1000.0, help="tick rate in Hz (default 1000)")
    s.add_argument("--quiet", action="store_true", help="no progress display")
    s.set_defaults(func=cmd_evaluate)

    s = sub.add_parser("simulate", help="write synthetic crash tests from the plant simulator",
                       description="Simulate crash tests with known truth (the thesis model, "
                       "optionally with extra physical effects) and write them as ISO-MME.")
    s.add_argument("--out", required=True, help="folder to write tests into")
    s.add_argument("--setup", choices=("R16", "SLED", "FULL"), default="R16",
                   help="R16 sled rig (hard seat), SLED sled with interior, FULL full vehicle "
                   "(default R16)")
    s.add_argument("--count", type=int, default=4, help="number of tests (default 4)")
    s.add_argument("--seed", type=int, default=1,
                   help="random seed of pulses, dummies and noise (default 1)")
    s.add_argument("--effect", action="append", metavar="NAME[=SCALE]",
                   help="switch on a physical effect beyond the thesis model, its magnitude "
                   "scaled by SCALE (repeatable); NAME is one of: " + ", ".join(SIM_EFFECTS))
    s.add_argument("--no-noise", action="store_true", help="no sensor noise or CFC filtering")
    s.add_argument("--zip", action="store_true", help="write each test as a .zip")
    s.add_argument("--csv", action="store_true", help="write CSV instead of ISO-MME")
    s.set_defaults(func=cmd_simulate)

    s = sub.add_parser(
        "run", help="run the real-time observer daemon on a CAN bus",
        description="Read TunnelAccel and BeltSpindle frames, step the model once per "
        "accelerometer frame, publish ChestEstimate every tick and the status at 10 Hz, and "
        "record the run to MCAP. Stops cleanly on SIGINT/SIGTERM.",
        epilog="A recording never overwrites a file: if --record names one that exists, the "
        "run goes to NAME.1.mcap, NAME.2.mcap, ... If the MCAP writer fails, the daemon "
        "keeps estimating, says so on the bus (ObserverHealth) and in the log, and records "
        "on in NAME.part2.mcap. Exit codes: 0 a clean stop; 2 it could not start (bad model "
        "file or config, a port or record path that cannot be opened); 3 it ran, but the "
        "recording is not the whole run. --print-config prints every config key with its "
        "default and range.")
    s.add_argument("--interface", help="python-can interface (default socketcan)")
    s.add_argument("--channel", help="bus channel (default vcan0)")
    s.add_argument("--model", help="model file (JSON) from identify, evaluate or loop")
    s.add_argument("--setup", metavar="NAME",
                   help="this bench's setup (R16, SLED, ...): needed for a model whose effects "
                   "act on some setups only (loop's model.json says which); the daemon runs "
                   "that setup's effects")
    s.add_argument("--record", help="MCAP file to record the run to")
    s.add_argument("--live", nargs="?", const="127.0.0.1:8765", metavar="HOST:PORT",
                   help="serve the run live to the Foxglove app (its WebSocket protocol; "
                   "default 127.0.0.1:8765; needs --record: the recorder process serves it, "
                   "so a slow viewer never delays a tick): the recording's topics and "
                   "schemas, per-tick topics at about 100 Hz; layout in docker/foxglove/")
    s.add_argument("--config", help="TOML file with an [observer] table of these options")
    s.add_argument("--print-config", action="store_true",
                   help="print every config key with its default and range, and exit")
    s.add_argument("--fd", action="store_true", default=None, help="CAN FD bus")
    s.add_argument("--python-can-socketcan", action="store_true",
                   help="use python-can's socketcan backend instead of the raw socket port")
    s.add_argument("--cpu-latency-us", type=int, metavar="US",
                   help="hold every CPU's wake-up latency at most US microseconds while running "
                   "(Linux PM QoS, needs root; default 0, as cyclictest does; -1: leave "
                   "power management alone)")
    s.add_argument("--rt-priority", type=int, metavar="N",
                   help="run the tick loop under SCHED_FIFO at priority N (1-99), so a viewer "
                   "or any other process on the bench PC never delays a tick (needs root, "
                   "CAP_SYS_NICE or RLIMIT_RTPRIO; said at start-up when refused; default 0: "
                   "normal scheduling)")
    s.add_argument("--trigger-g", type=float, help="crash trigger threshold in g (default 3)")
    s.add_argument("--event-s", type=float, help="observer run time after trigger (0.2 s)")
    s.add_argument("--counts-per-rev", type=int,
                   help="BRS counts/rev if the BRS frame does not say (default 96)")
    s.add_argument("--quiet", action="store_true", help="log warnings and errors only")
    s.set_defaults(func=cmd_run)

    s = sub.add_parser("analyze", help="read a recording back: fits, offline check, plots",
                       description="Read an MCAP recording of observer-node run (a truncated "
                       "one is salvaged), re-run the recorded model offline on the recorded "
                       "inputs, compute the fit (eq. 3.15) of the estimates against the "
                       "reference frames, and plot them.")
    s.add_argument("recording", help="MCAP file")
    s.add_argument("--out", help="output folder (default: next to the recording)")
    s.set_defaults(func=cmd_analyze)

    s = sub.add_parser("export", help="a recording's raw frames as MF4, BLF, ASC, candump or TRC",
                       description="Write every CAN frame a recording holds (received and "
                       "sent, with the recorded times and direction) in a bus-log format, by "
                       "the file's suffix: .mf4 (ASAM MDF4: CANape, CANoe, loggers; needs the "
                       "mf4 extra), .blf and .asc (Vector), .log (can-utils candump -L), .trc "
                       "(PEAK). crash-replay plays the file back.")
    s.add_argument("recording", help="MCAP file of observer-node run")
    s.add_argument("--to", required=True, metavar="FILE", help="log file to write")
    s.add_argument("--channel", default="can0", help="channel name written into the log")
    s.set_defaults(func=cmd_export)

    s = sub.add_parser("export-c", help="a model file as a dependency-free C99 observer",
                       description="Write NAME.h and NAME.c: the model's per-tick step (input "
                       "transform, discrete state space, and a grey-box's effects, delays and "
                       "offsets) exactly as the daemon steps it, and the daemon's core "
                       "(arming, trigger, bias, validity) around it, in double, or in float with "
                       "-DCO_REAL=float. No heap, no library but fabs. Also the frame codec "
                       "from the DBC (chest_observer_can.c/.h, by cantools' C generator).")
    s.add_argument("model", help="model file (JSON)")
    s.add_argument("--out", required=True, metavar="DIR", help="folder to write into")
    s.add_argument("--name", default="chest_observer", help="file and guard name")
    s.add_argument("--setup", metavar="NAME",
                   help="the ECU's setup, for a model with effects scoped to setups")
    s.set_defaults(func=cmd_export_c)
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except (CrashDataError, ModelFileError, UsageError, ClusterError) as e:
        print(f"observer-node: error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0


if __name__ == "__main__":
    sys.exit(main())
