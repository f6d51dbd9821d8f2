"""After the run: each recorded event re-run offline on its recorded inputs, scored against
the reference frames (the thesis's fit, eq. 3.15), and plotted."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .. import iso18571
from ..criteria import EURO_NCAP_CD_LIMITS_MM, CriteriaComparison, chest_criteria, compare
from ..ident.metrics import Fits, OutputFits, fit_percent
from ..iso18571 import OutputRatings
from . import format as fmt
from .reader import Recording, RecordingError


def offline_estimates(rec: Recording, event: int) -> tuple[np.ndarray, np.ndarray]:
    """Re-run the recorded model offline on the recorded inputs of one event, from the same
    onset, bias and BRS reference. Returns (ticks, y (n, 2)) for the ticks the daemon ran."""
    if rec.model is None:
        raise RecordingError(f"{rec.path}: no {fmt.ATT_MODEL} attachment")
    T = rec.ticks
    run = (T["event"] == event) & (T["running"] > 0)
    if not run.any():
        raise RecordingError(f"{rec.path}: event {event} not in the recording")
    onset = int(T["onset_tick"][run][0])
    last = int(T["tick"][run][-1])
    sel = (T["tick"] >= onset) & (T["tick"] <= last)
    ticks = T["tick"][sel].astype(int)
    if len(ticks) != last - onset + 1:
        raise RecordingError(f"{rec.path}: event {event} has gaps in its ticks (lost frames): "
                             "the offline run would not see the same inputs")
    first_run = np.flatnonzero(run)[0]
    bias = T["bias_g"][first_run]
    brs_ref = T["brs_ref"][first_run]
    rpc = T["rad_per_count"][first_run]
    pulse = -T["accel_x_g"][sel] - bias
    brs_rad = (T["brs_count"][sel] - brs_ref) * rpc
    y = rec.model.observer().simulate(pulse, brs_rad)
    return ticks, y


@dataclass(frozen=True)
class OfflineDiff:
    """The largest |daemon estimate - offline re-run| over an event's running ticks."""

    cr_g: float
    cd_mm: float

    def as_dict(self) -> dict[str, float]:
        return {"cr_g": self.cr_g, "cd_mm": self.cd_mm}


@dataclass(frozen=True)
class ValidFits:
    """The fits [%] on the ticks the daemon flagged valid, and how many there were."""

    cr: float
    cd: float
    ticks: int

    def as_dict(self) -> dict[str, float | int]:
        return {"cr": self.cr, "cd": self.cd, "ticks": self.ticks}


# why an event ended before its length and the fit window (EventAnalysis.cut_why)
CUT_AT_END = "the recording ends there (or its inputs stop for good)"
CUT_BY_SILENCE = ("its inputs fell silent for longer than an event and the daemon's watchdog "
                  "ended it (the test's data end there, or a replay, bus or daemon stalled)")
#: an event that ran this much short of its length is still whole: a replayed test's data may
#: end a few ms before the event would (the bundled tests' 3 ms), and nothing of the crash is
#: missing then
CUT_TOLERANCE_S = 0.01


@dataclass(frozen=True)
class EventAnalysis:
    """One recorded event: its onset, the daemon against its own offline re-run, and with
    reference frames (else None) its fits [%] and criteria against the measured ones."""

    event: int
    onset_tick: int
    ticks: int  # from the onset to the event's last running tick
    invalid_ticks: int  # running ticks the daemon flagged invalid
    max_abs_diff_offline: OfflineDiff
    fit_vs_offline: OutputFits
    criteria: CriteriaComparison
    fit_vs_reference: Fits | None = None
    # the time [s] from the onset to its last running tick when the event ended before its
    # own length (``core.event_s``; unknown: before the fit window's end): its criteria cover
    # only what it ran, and its fits too when ``cut_in_window``. None: it ran its full
    # length. ``cut_why`` says why (the recording ends there, or the inputs fell silent for
    # longer than an event and the watchdog ended it: the data ended, or something stalled).
    cut_s: float | None = None
    cut_why: str = ""
    cut_in_window: bool = False  # cut before the fit window's end: the fits are partial too
    fit_vs_reference_valid: ValidFits | None = None  # None also when under 11 valid ticks
    offline_fit_vs_reference: OutputFits | None = None
    iso18571: OutputRatings | None = None  # against the reference on the window

    def cut_covers(self) -> str:
        """What of the event a cut leaves partial, for the warnings of analyze and bench."""
        if self.cut_in_window:
            return "its fits and criteria cover only that part"
        return "its fit window is whole; its criteria cover only that part"

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {
            "event": self.event, "onset_tick": self.onset_tick, "ticks": self.ticks,
            "invalid_ticks": self.invalid_ticks, "cut_s": self.cut_s, "cut_why": self.cut_why,
            "cut_in_window": self.cut_in_window,
            "max_abs_diff_offline": self.max_abs_diff_offline.as_dict(),
            "fit_vs_offline": self.fit_vs_offline.as_dict()}
        if self.fit_vs_reference is not None:
            out["fit_vs_reference"] = self.fit_vs_reference.as_dict()
        if self.fit_vs_reference_valid is not None:
            out["fit_vs_reference_valid"] = self.fit_vs_reference_valid.as_dict()
        if self.offline_fit_vs_reference is not None:
            out["offline_fit_vs_reference"] = self.offline_fit_vs_reference.as_dict()
        out["criteria"] = self.criteria.as_dict()
        if self.iso18571 is not None:
            out["iso18571"] = self.iso18571.as_dict()
        return out


@dataclass(frozen=True)
class Analysis:
    """A recording read back (see :func:`analyze`)."""

    file: str
    salvaged: bool
    note: str  # what salvaging a cut file did ("" if nothing)
    ticks: int
    topics: dict[str, int]  # messages per topic
    valid_share: float  # share of ticks flagged valid, 0..1
    max_proc_us: float  # the longest tick processing [us]
    events: list[EventAnalysis]

    def as_dict(self) -> dict[str, Any]:
        return {"file": self.file, "salvaged": self.salvaged, "note": self.note,
                "ticks": self.ticks, "topics": self.topics, "valid_share": self.valid_share,
                "max_proc_us": self.max_proc_us, "events": [e.as_dict() for e in self.events]}


def analyze(rec: Recording, window_s: tuple[float, float] = (0.01, 0.15),
            out_dir: Path | None = None, ratings: bool = True) -> Analysis:
    """Per event: the fit (eq. 3.15) of the estimates against the reference and against the
    offline simulation of the same model, the largest difference from the offline run, the
    chest injury criteria of the estimates (beside the reference's, with their errors) over
    the event's ticks from the onset, and (``ratings``, optional package) the ISO/TS 18571
    ratings against the reference on the window; with ``out_dir``, analysis.json and plots."""
    T = rec.ticks
    fs = rec.model.tick_rate_hz if rec.model else rec.tick_rate_hz
    events = sorted({int(e) for e in T["event"][T["running"] > 0]})
    result = Analysis(str(rec.path), rec.salvaged, rec.salvage_note, len(T["tick"]),
                      rec.topics,
                      float(T["valid"].mean()) if len(T["tick"]) else 0.0,
                      float(T["proc_us"].max()) if len(T["tick"]) else 0.0, [])
    for e in events:
        entry, t_rel, y_est, y_off, r, shown = _event(rec, e, window_s, fs, ratings)
        if out_dir is not None:
            _plot_event(out_dir / f"event{e}.png", rec, e, t_rel, y_est, y_off, r, entry,
                        shown)
        result.events.append(entry)
    if out_dir is not None:
        out_dir.mkdir(parents=True, exist_ok=True)
        (out_dir / "analysis.json").write_text(json.dumps(result.as_dict(), indent=1) + "\n")
    return result


def _event(rec: Recording, e: int, window_s: tuple[float, float], fs: float, ratings: bool
           ) -> tuple[EventAnalysis, np.ndarray, np.ndarray, np.ndarray, np.ndarray | None,
                      np.ndarray]:
    """One event's analysis, and what its plot draws: time since onset [s], the daemon's and
    the offline estimates (n, 2), the reference (None without) and the ticks shown."""
    T = rec.ticks
    ticks, y_off = offline_estimates(rec, e)
    idx = {int(k): i for i, k in enumerate(T["tick"])}
    rows = np.array([idx[int(k)] for k in ticks])
    y_est = np.column_stack([T["cr_g"][rows], T["cd_mm"][rows]])
    running = T["running"][rows] > 0
    valid = T["valid"][rows] > 0
    onset = int(ticks[0])
    t_rel = (ticks - onset) / fs
    win = (t_rel >= window_s[0] - 1e-9) & (t_rel <= window_s[1] + 1e-9) & running
    ran_s = float(t_rel[running][-1])
    # a full event's last tick is n_event - 1 ticks after its onset (the daemon counts the
    # onset's tick); of an unknown length, only a cut inside the fit window can be told
    full_s = ((round(rec.event_s * fs) - 1) / fs - CUT_TOLERANCE_S
              if math.isfinite(rec.event_s) else window_s[1])
    cut_s = ran_s if ran_s < full_s - 1e-9 else None
    cut_why = "" if cut_s is None else (
        CUT_AT_END if int(ticks[-1]) >= int(T["tick"][-1]) else CUT_BY_SILENCE)
    in_window = cut_s is not None and cut_s < window_s[1] - 1e-9
    head = (e, onset, len(ticks), int((running & ~valid).sum()),
            OfflineDiff(float(np.max(np.abs(y_est[running, 0] - y_off[running, 0]))),
                        float(np.max(np.abs(y_est[running, 1] - y_off[running, 1])))),
            OutputFits(fit_percent(y_off[win, 0], y_est[win, 0]),
                       fit_percent(y_off[win, 1], y_est[win, 1])))
    have_ref = np.array([int(k) in rec.reference for k in ticks])
    if not (have_ref & win).sum() > 10:
        entry = EventAnalysis(*head, cut_s=cut_s, cut_why=cut_why, cut_in_window=in_window,
                              criteria=CriteriaComparison(
            chest_criteria(y_est[running, 0], y_est[running, 1], fs)))
        return entry, t_rel, y_est, y_off, None, running & valid
    r = np.array([rec.reference.get(int(k), (np.nan, np.nan)) for k in ticks])
    w = win & have_ref
    # The same on the ticks the daemon flagged valid only: what a consumer of the bus would
    # have used (input faults, late frames, sensor faults left out).
    wv = w & valid
    m = running & have_ref
    entry = EventAnalysis(
        *head,
        cut_s=cut_s,
        cut_why=cut_why,
        cut_in_window=in_window,
        fit_vs_reference=Fits.of(fit_percent(r[w, 0], y_est[w, 0]),
                                 fit_percent(r[w, 1], y_est[w, 1])),
        fit_vs_reference_valid=ValidFits(fit_percent(r[wv, 0], y_est[wv, 0]),
                                         fit_percent(r[wv, 1], y_est[wv, 1]),
                                         int(wv.sum())) if wv.sum() > 10 else None,
        offline_fit_vs_reference=OutputFits(fit_percent(r[w, 0], y_off[w, 0]),
                                            fit_percent(r[w, 1], y_off[w, 1])),
        criteria=compare(chest_criteria(y_est[m, 0], y_est[m, 1], fs),
                         chest_criteria(r[m, 0], r[m, 1], fs)),
        iso18571=iso18571.rate_outputs(r[w], y_est[w], fs)
        if ratings and iso18571.available() else None)
    return entry, t_rel, y_est, y_off, r, running & valid


def _plot_event(path: Path, rec: Recording, e: int, t: np.ndarray, y_est: np.ndarray,
                y_off: np.ndarray, ref: np.ndarray | None, entry: EventAnalysis,
                shown: np.ndarray) -> None:
    """The estimate is drawn only where the daemon flagged it valid and running: elsewhere a
    gap, with invalid stretches shaded, so nothing the daemon disowned reads as data."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for k, (ax, label) in enumerate(zip(axes, ("CR [g]", "CD [mm]"), strict=True)):
        if ref is not None:
            ax.plot(t * 1000, ref[:, k], "k-", lw=1.2, label="reference (measured)")
        ax.plot(t * 1000, np.where(shown, y_est[:, k], np.nan), "r--", lw=1.2,
                label="daemon estimate (valid)")
        tick_ms = (t[1] - t[0]) * 1000 if len(t) > 1 else 1.0
        for j, (a, b) in enumerate(_runs(~shown)):
            ax.axvspan(t[a] * 1000, t[b - 1] * 1000 + tick_ms, color="0.85", lw=0,
                       label="estimate invalid or not running" if j == 0 else None)
        ax.plot(t * 1000, y_off[:, k], "b:", lw=1.5, label="offline simulation")
        if k == 1:  # what a restraint engineer reads the deflection against
            for limit, colour in zip(EURO_NCAP_CD_LIMITS_MM, ("tab:green", "tab:red"),
                                     strict=True):
                ax.axhline(limit, color=colour, ls=":", lw=0.9,
                           label=f"Euro NCAP {limit:g} mm" if colour == "tab:green" else None)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("t since onset [ms]")
    axes[0].legend(fontsize=8)
    fit = entry.fit_vs_reference
    title = f"{rec.path.name} event {e}"
    if fit:
        title += f": fit CR {fit.cr:.1f} %, CD {fit.cd:.1f} %"
    if entry.invalid_ticks:
        title += f"; {entry.invalid_ticks} ticks flagged invalid (shaded)"
    if entry.cut_s is not None:
        title += (f"\ncut after {entry.cut_s * 1000:.0f} ms: "
                  + ("the recording ends there" if entry.cut_why == CUT_AT_END
                     else "its inputs fell silent for longer than an event"))
    fig.suptitle(title)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=80)
    plt.close(fig)


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """[start, end) index ranges where ``mask`` is true."""
    d = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return list(zip(np.flatnonzero(d == 1).tolist(), np.flatnonzero(d == -1).tolist(),
                    strict=True))
