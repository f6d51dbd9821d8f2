"""After the run: each recorded event re-run offline on its recorded inputs, scored against
the reference frames (the thesis's fit, eq. 3.15), and plotted."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .. import iso18571
from ..criteria import EURO_NCAP_CD_LIMITS_MM, chest_criteria, compare
from ..ident.metrics import fit_percent
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


def analyze(rec: Recording, window_s: tuple[float, float] = (0.01, 0.15),
            out_dir: Path | None = None, ratings: bool = True) -> dict:
    """Per event: the fit (eq. 3.15) of the estimates against the reference and against the
    offline simulation of the same model, the largest difference from the offline run, the
    chest injury criteria of the estimates (beside the reference's, with their errors) over
    the event's ticks from the onset, and (``ratings``, optional package) the ISO/TS 18571
    ratings against the reference on the window."""
    T = rec.ticks
    fs = rec.model.tick_rate_hz if rec.model else rec.tick_rate_hz
    events = sorted({int(e) for e in T["event"][T["running"] > 0]})
    result: dict = {"file": str(rec.path), "salvaged": rec.salvaged, "note": rec.salvage_note,
                    "ticks": len(T["tick"]), "topics": rec.topics,
                    "valid_share": float(T["valid"].mean()) if len(T["tick"]) else 0.0,
                    "max_proc_us": float(T["proc_us"].max()) if len(T["tick"]) else 0.0,
                    "events": []}
    for e in events:
        ticks, y_off = offline_estimates(rec, e)
        idx = {int(k): i for i, k in enumerate(T["tick"])}
        rows = np.array([idx[int(k)] for k in ticks])
        y_est = np.column_stack([T["cr_g"][rows], T["cd_mm"][rows]])
        running = T["running"][rows] > 0
        valid = T["valid"][rows] > 0
        onset = int(ticks[0])
        t_rel = (ticks - onset) / fs
        win = (t_rel >= window_s[0] - 1e-9) & (t_rel <= window_s[1] + 1e-9) & running
        entry: dict = {"event": e, "onset_tick": onset, "ticks": len(ticks),
                       "invalid_ticks": int((running & ~valid).sum()),
                       "max_abs_diff_offline": {
                           "cr_g": float(np.max(np.abs(y_est[running, 0] - y_off[running, 0]))),
                           "cd_mm": float(np.max(np.abs(y_est[running, 1] - y_off[running, 1])))},
                       "fit_vs_offline": {
                           "cr": fit_percent(y_off[win, 0], y_est[win, 0]),
                           "cd": fit_percent(y_off[win, 1], y_est[win, 1])}}
        have_ref = np.array([int(k) in rec.reference for k in ticks])
        if (have_ref & win).sum() > 10:
            r = np.array([rec.reference.get(int(k), (np.nan, np.nan)) for k in ticks])
            w = win & have_ref
            entry["fit_vs_reference"] = {"cr": fit_percent(r[w, 0], y_est[w, 0]),
                                         "cd": fit_percent(r[w, 1], y_est[w, 1])}
            entry["fit_vs_reference"]["total"] = (entry["fit_vs_reference"]["cr"]
                                                  + entry["fit_vs_reference"]["cd"]) / 2
            # The same on the ticks the daemon flagged valid only: what a consumer of the
            # bus would have used (input faults, late frames, sensor faults left out).
            wv = w & valid
            if wv.sum() > 10:
                entry["fit_vs_reference_valid"] = {"cr": fit_percent(r[wv, 0], y_est[wv, 0]),
                                                   "cd": fit_percent(r[wv, 1], y_est[wv, 1]),
                                                   "ticks": int(wv.sum())}
            entry["offline_fit_vs_reference"] = {"cr": fit_percent(r[w, 0], y_off[w, 0]),
                                                 "cd": fit_percent(r[w, 1], y_off[w, 1])}
            m = running & have_ref
            entry["criteria"] = compare(chest_criteria(y_est[m, 0], y_est[m, 1], fs),
                                        chest_criteria(r[m, 0], r[m, 1], fs))
            if ratings and iso18571.available():
                entry["iso18571"] = {key: iso18571.rate(r[w, j], y_est[w, j], fs)
                                     for j, key in enumerate(("cr", "cd"))}
        else:
            r = None
            entry["criteria"] = {"estimate": chest_criteria(y_est[running, 0],
                                                            y_est[running, 1], fs).as_dict()}
        if out_dir is not None:
            _plot_event(out_dir / f"event{e}.png", rec, e, t_rel, y_est, y_off, r, entry,
                        running & valid)
        result["events"].append(entry)
    if out_dir is not None:
        out_dir.mkdir(parents=True, exist_ok=True)
        (out_dir / "analysis.json").write_text(json.dumps(result, indent=1) + "\n")
    return result


def _plot_event(path: Path, rec: Recording, e: int, t: np.ndarray, y_est: np.ndarray,
                y_off: np.ndarray, ref: np.ndarray | None, entry: dict,
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
    fit = entry.get("fit_vs_reference")
    title = f"{rec.path.name} event {e}"
    if fit:
        title += f": fit CR {fit['cr']:.1f} %, CD {fit['cd']:.1f} %"
    if entry["invalid_ticks"]:
        title += f"; {entry['invalid_ticks']} ticks flagged invalid (shaded)"
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
