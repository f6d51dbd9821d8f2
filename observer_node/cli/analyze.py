"""``observer-node analyze``: read a recording back: fits, offline check, plots."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from .. import options

if TYPE_CHECKING:
    from ..recording.analysis import EventAnalysis


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "analyze", help="read a recording back: fits, offline check, plots",
        description="Read an MCAP recording of observer-node run (a truncated one is "
        "salvaged), re-run the recorded model offline on the recorded inputs, compute the fit "
        "(eq. 3.15) of the estimates against the reference frames, and plot them.")
    s.add_argument("recording", help="MCAP file")
    s.add_argument("--out", help="output folder (default: next to the recording)")
    s.set_defaults(func=_do_analyze)


def _do_analyze(a: argparse.Namespace) -> int:
    from ..recording import analyze, read_recording
    from ..recording import format as fmt

    beside = str(Path(a.recording).with_suffix(""))  # the default: the recording less .mcap
    out = (options.out_folder(a.out) if a.out is not None else
           options.out_folder(beside, "--out (not given: the recording's path less .mcap)"))
    rec = read_recording(a.recording)
    with options.staged(out) as tmp:
        result = analyze(rec, out_dir=tmp)
    meta = rec.metadata.get(fmt.META_RUN, {})
    print(f"{rec.path}: {result.ticks} ticks, model {meta.get(fmt.RunMeta.MODEL_KIND, '?')} "
          f"{meta.get(fmt.RunMeta.MODEL_NAME, '?')!r} at "
          f"{meta.get(fmt.RunMeta.TICK_RATE_HZ, '?')} Hz; "
          f"valid {100 * result.valid_share:.1f} % of ticks; "
          f"max tick processing {result.max_proc_us:.0f} us")
    if rec.salvaged:
        print(f"  salvaged: {rec.salvage_note}")
    for ev in result.events:
        _print_event(ev)
    if not result.events:
        print("  no crash event in the recording (the observer never triggered)")
    print(f"wrote {out / 'analysis.json'} and plots in {out}")
    return 0


def _print_event(ev: EventAnalysis) -> None:
    line = (f"  event {ev.event} (onset tick {ev.onset_tick}, {ev.ticks} ticks): "
            f"max |daemon - offline| CR {ev.max_abs_diff_offline.cr_g:.2g} g, "
            f"CD {ev.max_abs_diff_offline.cd_mm:.2g} mm")
    print(line)
    if ev.cut_s is not None:
        print(f"    WARNING: cut after {ev.cut_s * 1000:.0f} ms: {ev.cut_why}; "
              f"{ev.cut_covers()}")
    if ev.fit_vs_reference is not None:
        f = ev.fit_vs_reference
        print(f"    fit vs reference (eq. 3.15): CR {f.cr:.1f} %  CD {f.cd:.1f} %  "
              f"TOT {f.total:.1f} %")
    c = ev.criteria.as_dict()  # the numbers as analysis.json has them
    est = c["estimate"]
    line = (f"    criteria: CD max {est['cd_max_mm']:.1f} mm, CR 3 ms {est['cr_3ms_g']:.1f} g,"
            f" VC max {est['vc_max_m_s']:.2f} m/s")
    if "reference" in c:
        r, d = c["reference"], c["error"]
        line += (f" (measured {r['cd_max_mm']:.1f} mm, {r['cr_3ms_g']:.1f} g, "
                 f"{r['vc_max_m_s']:.2f} m/s; error {d['cd_max_mm']:+.1f} mm, "
                 f"{d['cr_3ms_g']:+.1f} g, {d['vc_max_m_s']:+.2f} m/s)")
    print(line)
    if ev.iso18571 is not None:
        iso = ev.iso18571
        print(f"    ISO/TS 18571 overall rating: CR {iso.cr.overall:.3f}  "
              f"CD {iso.cd.overall:.3f} (0..1; corridor, phase, magnitude, slope "
              "in analysis.json)")
    if ev.invalid_ticks:
        v = ev.fit_vs_reference_valid
        print(f"    {ev.invalid_ticks} of {ev.ticks} ticks flagged invalid (gaps in the "
              "plots)" + (f"; on the valid ones: CR {v.cr:.1f} %  CD {v.cd:.1f} %"
                          if v else ""))
