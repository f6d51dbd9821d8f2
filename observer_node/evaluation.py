"""Identify and score models as the thesis does (chapter 4): five models per setup, estimated on
one half of the tests and scored with eq. 3.15-3.18 on the other half."""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any

import numpy as np

from . import plots
from .data import CrashDataError, CrashTest
from .data.crashtest import THESIS_WINDOW_S
from .data.setups import assign_setups
from .errors import one_line
from .ident import arx, greybox, n4sid
from .ident.dataset import Dataset, make_dataset
from .ident.kinds import IDENTIFY, N4SID_BLOCK_ROWS, IdentifyOptions
from .ident.metrics import FitTable, fit_table
from .ident.progress import Progress
from .iso18571 import IsoRatings
from .model.kinds import MODEL_KINDS
from .model.modelfile import ModelFile
from .scores import Scores, mean_abs_errors, scores

# Tables 4.1-4.3 of the thesis: (fit_CR,tot, fit_CD,tot, fit_TOT) on its validation tests.
THESIS_TABLES = {
    "R16": {"ARX Nmax=10": (50.5, 49.2, 49.9), "ARX Nmax=6": (44.8, 53.1, 48.9),
            "SS N=16": (51.4, 49.1, 50.2), "SS N=7": (46.5, 63.8, 55.1),
            "Grey-Box": (55.0, 74.3, 64.6)},
    "SLED": {"ARX Nmax=10": (38.8, 45.9, 42.3), "ARX Nmax=6": (25.7, 54.7, 40.2),
             "SS N=16": (70.7, 82.4, 76.5), "SS N=7": (62.2, 77.8, 70.0),
             "Grey-Box": (63.1, 59.1, 61.1)},
    "FULL": {"ARX Nmax=10": (49.0, 40.0, 44.5), "ARX Nmax=6": (42.6, 39.6, 41.1),
             "SS N=16": (50.0, 59.2, 54.6), "SS N=7": (59.5, 68.8, 64.1),
             "Grey-Box": (49.1, 47.2, 48.2)},
}
THESIS_TABLE_NO = {"R16": "4.1", "SLED": "4.2", "FULL": "4.3"}
MODELS = ("ARX Nmax=10", "ARX Nmax=6", "SS N=16", "SS N=7", "Grey-Box")


NOT_COMPARED = ("needs an odd-numbered test to estimate on and an even-numbered one to "
                "validate on: not compared")


def split_halves(tests: list[CrashTest]) -> tuple[list[CrashTest], list[CrashTest]]:
    """Odd-numbered tests estimate, even-numbered validate (alternating if unnumbered)."""
    def number(t: CrashTest) -> int | None:
        m = re.search(r"(\d+)\D*$", t.name)
        return int(m.group(1)) if m else None

    if all(number(t) is not None for t in tests):
        return ([t for t in tests if number(t) % 2 == 1],  # type: ignore[operator]
                [t for t in tests if number(t) % 2 == 0])  # type: ignore[operator]
    return tests[0::2], tests[1::2]


def identify(kind: str, data: Dataset, nmax: int = 6, order: int = 7,
             orders: arx.ArxOrders | None = None, m1_kg: float = greybox.DEFAULT_M1_KG,
             progress: Progress | None = None, name: str | None = None) -> ModelFile:
    """Identify one model of ``kind`` (one of :data:`IDENTIFY`) on ``data``."""
    if kind not in IDENTIFY:
        raise ValueError(f"unknown model kind {kind!r} ({', '.join(IDENTIFY)})")
    return IDENTIFY[kind](data, IdentifyOptions(nmax, order, orders, m1_kg, progress, name))


def simulate_model(mf: ModelFile, data: Dataset) -> np.ndarray:
    """Outputs (tests, n, 2) of a model file on a dataset made at the model's tick rate; a
    model with effects scoped to setups acts on each test as its setup says."""
    if abs(data.fs_hz - mf.tick_rate_hz) > 1e-9:
        raise ValueError(f"data at {data.fs_hz:g} Hz, model at {mf.tick_rate_hz:g} Hz")
    return mf.observer(list(data.setups) if mf.setups() else None).simulate(data.pulse_g,
                                                                             data.brs_rad)


def dataset_for(mf: ModelFile, tests: list[CrashTest],
                window_s: tuple[float, float] | None = None) -> Dataset:
    window = window_s or tuple(mf.fitted_on.get("window_s", THESIS_WINDOW_S))
    return make_dataset(tests, mf.tick_rate_hz, window)


def evaluate_model(mf: ModelFile, tests: list[CrashTest], out_dir: Path | None = None,
                   window_s: tuple[float, float] | None = None, title: str | None = None,
                   ratings: bool = True, progress: Progress | None = None,
                   left_out: dict[str, str] | None = None) -> Scores:
    """Fits (eq. 3.15-3.18), injury criteria and ISO/TS 18571 ratings (see :func:`scores`)
    of a model on ``tests``; with ``out_dir``, plots and fits.json (with ``left_out``, the tests
    left out as bad, path: why). The tests' setups are told from their metadata as the loop
    does (each test's ``setup`` set): for the per-setup fits, and for a model with effects
    scoped to setups; tests of a setup such a model does not know are said on stderr and
    listed in fits.json."""
    prog = progress or Progress("evaluate", enabled=False)
    assign_setups(tests)  # as the loop tells them: the per-setup fits and scoped effects
    scoped = mf.setups()
    known = set(scoped) | set(mf.fitted_on.get("setups", []))
    strangers = sorted({t.setup for t in tests} - known) if scoped else []
    for setup in strangers:  # a scoped effect acts on no test there: said, not silent
        names = [t.name for t in tests if t.setup == setup]
        print(one_line(f"evaluate: {', '.join(names)}: setup {setup} (from the tests' "
                       f"metadata) is not one the model knows ({', '.join(sorted(known))}); "
                       f"its effects scoped to {', '.join(scoped)} act on none of them "
                       "(rename the tests or check the model)"), file=sys.stderr)
    prog.update(f"simulating the model on {len(tests)} test(s)")
    data = dataset_for(mf, tests, window_s)
    y_hat = simulate_model(mf, data)
    prog.update(f"scoring {len(tests)} test(s): fits, injury criteria"
                + (", ISO/TS 18571 ratings" if ratings else ""))
    fits = scores(data, y_hat, ratings)
    if out_dir is not None:
        prog.update("drawing the plots")
        out_dir.mkdir(parents=True, exist_ok=True)
        group_of = dict(zip(data.names, data.setups, strict=True))
        by_setup = {g: {"tests": n, "test_names": [t for t, s in group_of.items() if s == g],
                        **f.as_dict()} for g, (n, f) in fits.by_group(group_of).items()}
        (out_dir / "fits.json").write_text(
            json.dumps({**fits.as_dict(), "setups": by_setup,
                        **({"setups_unknown_to_the_model": strangers} if strangers else {}),
                        **({"left_out": left_out} if left_out else {})}, indent=1) + "\n")
        _plot_pair(out_dir, title or f"{mf.kind} {mf.name}", data, y_hat, fits, "fit")
    return fits


def _plot_pair(out_dir: Path, title: str, data: Dataset, y_hat: np.ndarray, fits: FitTable,
               stem: str) -> list[str]:
    t = np.arange(data.y.shape[1])[data.win] / data.fs_hz
    return [
        plots.measured_vs_simulated(out_dir / f"{stem}_{key}.png", title, data.names, t,
                                    data.y[:, data.win], y_hat[:, data.win], fits, k).name
        for k, key in enumerate(("cr", "cd"))
    ]


def file_stem(setup: str) -> str:
    """A setup's name as the start of a file name: letters and digits only, so that no name a
    test's metadata gives can write outside the output folder, and at most 60 of them, so
    that a long one still makes a file name."""
    return re.sub(r"[^a-z0-9]+", "-", setup.lower()).strip("-")[:60].strip("-") or "setup"


def file_stems(setups: list[str]) -> dict[str, str]:
    """Each setup's :func:`file_stem`, those that would be the same ("Rig A" and "rig-a",
    "SLED" and "sled", two names in other scripts) told apart by -2, -3, ... in order, so
    that no setup's models and plots overwrite another's."""
    out: dict[str, str] = {}
    for setup in setups:
        stem = cand = file_stem(setup)
        n = 1
        while cand in out.values():
            n += 1
            cand = f"{stem}-{n}"
        out[setup] = cand
    return out


def thesis_comparison(tests: list[CrashTest], out_dir: Path, rate_hz: float = 1000.0,
                      window_s: tuple[float, float] = THESIS_WINDOW_S,
                      verbose: bool = True, left_out: dict[str, str] | None = None) -> dict:
    """Chapter 4 on ``tests``: per setup, estimate five models on one half, score on the
    other. ARX orders are searched on R16 estimation data (as the thesis did) when there is
    any, else per setup. Writes models, plots and evaluation.json to ``out_dir``."""
    out_dir.mkdir(parents=True, exist_ok=True)
    assign_setups(tests)  # as the loop tells them, from the metadata: not by name alone
    setups: dict[str, list[CrashTest]] = {}
    for t in tests:
        setups.setdefault(t.setup, []).append(t)
    prog = Progress("evaluate", enabled=verbose)
    arx_orders: dict[int, arx.ArxOrders] = {}
    scans: dict[str, dict] = {}
    # a setup without both an odd- and an even-numbered test has nothing to estimate on or to
    # score on: said and kept in the result, never dropped in silence
    alone = {s: [t.name for t in ts] for s, ts in setups.items()
             if not all(split_halves(ts))}
    for s, names in alone.items():
        print(f"evaluate: setup {s} ({', '.join(names)}): {NOT_COMPARED}", file=sys.stderr)
    setups = {s: ts for s, ts in setups.items() if s not in alone}
    if not setups:
        raise CrashDataError("no setup has tests to estimate on (odd-numbered) and to validate "
                             "on (even-numbered): " + "; ".join(
                                 f"{s}: {', '.join(n)}" for s, n in alone.items()))
    order_setup = "R16" if "R16" in setups else None
    result: dict = {"rate_hz": rate_hz, "window_s": list(window_s), "setups": {}}
    if left_out:  # the tests left out as bad (path: why), kept beside the result
        result["left_out"] = left_out
    if alone:
        result["not_compared"] = alone
    order = {"R16": 0, "SLED": 1, "FULL": 2}
    stems = file_stems(sorted(setups, key=lambda s: (order.get(s, 3), s)))
    for setup, stem in stems.items():
        est_tests, val_tests = split_halves(setups[setup])
        est = make_dataset(est_tests, rate_hz, window_s)
        val = make_dataset(val_tests, rate_hz, window_s)
        entry: dict = {"estimation": est.names, "validation": val.names, "models": {}}
        if order_setup in (None, setup):
            for nmax in (6, 10):
                prog.update(f"{setup}: ARX order search Nmax={nmax}")
                arx_orders[nmax], _ = arx.search_orders(est, nmax, progress=prog)
            scans[setup] = _order_scans(est, val, out_dir, setup, stem, prog)
        specs: dict[str, dict[str, Any]] = {
            "ARX Nmax=10": dict(kind="arx", nmax=10, orders=arx_orders[10]),
            "ARX Nmax=6": dict(kind="arx", nmax=6, orders=arx_orders[6]),
            "SS N=16": dict(kind="n4sid", order=16),
            "SS N=7": dict(kind="n4sid", order=7),
            "Grey-Box": dict(kind="greybox"),
        }
        for label, spec in specs.items():
            prog.update(f"{setup}: {label}")
            slug = re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-")
            mf = identify(data=est, name=f"{stem}-{slug}", **spec)
            mf.save(out_dir / "models" / f"{stem}-{slug}.json")
            y_hat = simulate_model(mf, val)
            fits = scores(val, y_hat)
            pngs = _plot_pair(out_dir / "plots", f"{setup} {label} (validation)", val, y_hat,
                              fits, f"{stem}-{slug}")
            entry["models"][label] = {
                "validation": fits.as_dict(), "estimation_fit": mf.fits["fit"],
                "model_file": f"models/{stem}-{slug}.json", "plots": pngs,
                **MODEL_KINDS[mf.kind].summary(mf),
            }
        if setup in THESIS_TABLES:
            entry["thesis"] = {m: dict(zip(("cr", "cd", "total"), v, strict=False))
                               for m, v in THESIS_TABLES[setup].items()}
        result["setups"][setup] = entry
    result["order_scans"] = scans
    prog.done()
    (out_dir / "evaluation.json").write_text(json.dumps(result, indent=1) + "\n")
    return result


def _order_scans(est: Dataset, val: Dataset, out_dir: Path, setup: str, stem: str,
                 prog: Progress) -> dict:
    """Figures 3.6 (ARX fit against Nmax) and 3.7 (N4SID fit against order)."""
    arx_rows = []
    for nmax in range(2, 13):
        prog.update(f"{setup}: ARX scan Nmax={nmax}")
        orders, _ = arx.search_orders(est, nmax)
        m = arx.estimate_arx(est, orders)
        row = {"nmax": nmax, "estimation_fit": fit_table(
            est.names, est.y[:, est.win], m.simulate(est)[:, est.win]).fit.total}
        row["validation_fit"] = fit_table(val.names, val.y[:, val.win],
                                          m.simulate(val)[:, val.win]).fit.total
        arx_rows.append(row)
    ss_rows = n4sid.order_scan(est, val, range(1, 21), N4SID_BLOCK_ROWS, prog)
    plots_dir = out_dir / "plots"
    plots_dir.mkdir(parents=True, exist_ok=True)
    plots.order_scan(plots_dir / f"{stem}-arx-nmax-scan.png",
                     f"{setup}: iterated ARX, fit_TOT against Nmax (Fig. 3.6)", "Nmax",
                     arx_rows, "nmax")
    plots.order_scan(plots_dir / f"{stem}-n4sid-order-scan.png",
                     f"{setup}: N4SID, fit_TOT against order (Fig. 3.7)", "order N",
                     ss_rows, "order")
    return {"arx": arx_rows, "n4sid": ss_rows}


def format_tables(result: dict) -> str:
    """Tables 4.1-4.3 with the thesis's numbers beside ours."""
    lines = [f"Validation fit (eq. 3.15-3.18) at {result['rate_hz']:g} Hz, window "
             f"{result['window_s'][0]:g}..{result['window_s'][1]:g} s; "
             "thesis = Blåberg (2008) on its own data, for reference"]
    for setup, names in result.get("not_compared", {}).items():
        lines.append(f"{setup} setup ({', '.join(names)}): {NOT_COMPARED}")
    for setup, entry in result["setups"].items():
        no = THESIS_TABLE_NO.get(setup)
        lines.append("")
        lines.append(f"{setup} setup{f' (thesis Table {no})' if no else ''}: estimated on "
                     f"{', '.join(entry['estimation'])}; validated on "
                     f"{', '.join(entry['validation'])}")
        lines.append(f"  {'model':<13}{'fit_CR':>8}{'fit_CD':>8}{'fit_TOT':>9}   "
                     f"{'thesis CR':>9}{'CD':>6}{'TOT':>6}   {'mean |error| CDmax':>18}"
                     f"{'CR3ms':>7}{'VCmax':>7}   {'ISO 18571 CR':>12}{'CD':>6}")
        for label in MODELS:
            m = entry["models"].get(label)
            if m is None:
                continue
            v = m["validation"]
            f = v["fit"]
            ref = entry.get("thesis", {}).get(label)
            ref_s = (f"{ref['cr']:>9.1f}{ref['cd']:>6.1f}{ref['total']:>6.1f}" if ref
                     else " " * 21)
            err = mean_abs_errors(v["criteria"])
            # the ratings as evaluation.json has them, read back
            iso = IsoRatings.from_dict(v["iso18571"]).mean_overall if "iso18571" in v else None
            iso_s = f"{iso.cr:>12.3f}{iso.cd:>6.3f}" if iso else f"{'(not installed)':>18}"
            lines.append(f"  {label:<13}{f['cr']:>8.1f}{f['cd']:>8.1f}{f['total']:>9.1f}   "
                         f"{ref_s}   {err['cd_max_mm']:>15.1f} mm{err['cr_3ms_g']:>5.1f} g"
                         f"{err['vc_max_m_s']:>5.2f}m/s {iso_s}")
    lines.append("")
    lines.append("  Criteria (validation tests, estimate vs measured, from t = 0): peak chest "
                 "deflection, chest X acceleration 3 ms clip, viscous criterion (HIII 50th). "
                 "ISO 18571: mean overall rating, 0..1, on the fit window.")
    return "\n".join(lines)
