"""PNG plots in the style of the thesis's Appendix A: measured (solid) against simulated
(dashed) per test, the fit of eq. 3.15 in each title."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from .criteria import EURO_NCAP_CD_LIMITS_MM
from .data import CrashTest
from .ident.metrics import FitTable


def _save(fig: Figure, path: Path, dpi: int = 80) -> Path:
    """Lay out, write (making its folder) and close ``fig``."""
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


OUTPUT_LABELS = (("cr", "Chest acceleration CR [g]"), ("cd", "Chest deflection CD [mm]"))
MAX_PANELS = 24  # tests drawn in one figure at most


def _shown(badness: list[float]) -> tuple[list[int], str]:
    """The tests a figure draws: all of them, or past ``MAX_PANELS`` (a campaign: a figure
    of 180 panels is 19,000 pixels tall and takes minutes) the worst, in their order, and
    the words for the title that say so."""
    n = len(badness)
    if n <= MAX_PANELS:
        return list(range(n)), ""
    worst = np.argsort(-np.nan_to_num(np.asarray(badness, float), nan=np.inf), kind="stable")
    return sorted(worst[:MAX_PANELS].tolist()), f" ({MAX_PANELS} worst of {n} tests)"


def measured_vs_simulated(path: Path, title: str, names: list[str], t_s: np.ndarray,
                          y: np.ndarray, y_hat: np.ndarray, fits: FitTable, output: int) -> Path:
    """One figure, one panel per test (at most ``MAX_PANELS``: the lowest fits), for output 0
    (CR) or 1 (CD). y, y_hat: (tests, n, 2)."""
    key, label = OUTPUT_LABELS[output]
    shown, some = _shown([-getattr(fits.tests[name], key) for name in names])
    n = len(shown)
    cols = 2 if n > 1 else 1
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(6 * cols, 2.6 * rows), squeeze=False)
    for at, k in enumerate(shown):
        name = names[k]
        ax = axes[at // cols][at % cols]
        ax.plot(t_s * 1000, y[k, :, output], "k-", lw=1.2, label="measured")
        ax.plot(t_s * 1000, y_hat[k, :, output], "r--", lw=1.2, label="simulated")
        if key == "cd":  # what a restraint engineer reads the deflection against
            for limit, colour in zip(EURO_NCAP_CD_LIMITS_MM, ("tab:green", "tab:red"),
                                     strict=True):
                ax.axhline(limit, color=colour, ls=":", lw=0.9)
        ax.set_title(f"{name}: fit {getattr(fits.tests[name], key):.1f} %", fontsize=9)
        ax.set_xlabel("t [ms]")
        ax.set_ylabel(label, fontsize=8)
        ax.grid(alpha=0.3)
    for k in range(n, rows * cols):
        axes[k // cols][k % cols].axis("off")
    axes[0][0].legend(fontsize=8)
    limits = (f"; dotted: Euro NCAP chest compression limits {EURO_NCAP_CD_LIMITS_MM[0]:g} / "
              f"{EURO_NCAP_CD_LIMITS_MM[1]:g} mm" if key == "cd" else "")
    fig.suptitle(f"{title} — {label.split(' [')[0]}, fit {getattr(fits.fit, key):.1f} %{some}"
                 f"{limits}", fontsize=10)
    return _save(fig, path)


def residuals(path: Path, names: list[str], t_s: np.ndarray, before: np.ndarray,
              after: np.ndarray) -> Path:
    """Residuals (measured - simulated) before and after the loop, per test and output (at
    most ``MAX_PANELS`` tests: the largest residuals after)."""
    rms = np.sqrt(np.mean(after ** 2, axis=1))  # (tests, 2)
    shown, some = _shown((rms / np.maximum(rms.max(axis=0), 1e-12)).sum(axis=1).tolist())
    n = len(shown)
    fig, axes = plt.subplots(n, 2, figsize=(11, 1.9 * n + 0.6), squeeze=False, sharex=True)
    if some:
        fig.suptitle(f"residuals{some}", fontsize=10)
    for i, j in enumerate(shown):
        name = names[j]
        for k, (key, _) in enumerate(OUTPUT_LABELS):
            ax = axes[i][k]
            ax.plot(t_s * 1000, before[j, :, k], color="0.6", lw=1, label="before")
            ax.plot(t_s * 1000, after[j, :, k], "r-", lw=1, label="after")
            ax.axhline(0, color="k", lw=0.5)
            ax.set_title(f"{name} {key.upper()} residual", fontsize=8)
            ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    for k, (_, label) in enumerate(OUTPUT_LABELS):
        axes[-1][k].set_xlabel("t [ms]")
        axes[n // 2][k].set_ylabel(label, fontsize=8)
    return _save(fig, path, dpi=70)


# a test's channels as the screening names them; a residual outlier is shown on CR
CHANNELS = {"pulse": ("pulse_g", "pulse [g]"), "brs": ("brs", "BRS [counts]"),
            "cr": ("cr_g", "CR [g]"), "cd": ("cd_mm", "CD [mm]"), "residual": ("cr_g", "CR [g]")}


def broken_tests(path: Path, flagged: list[tuple[str, str, str]], tests: list[CrashTest]
                 ) -> Path:
    """One panel per test left out (name, channel, reason): its faulty channel (red) over the
    same channel of every other test (grey), the reason in the title, so a reviewer sees the
    fault as the screening did."""
    n = len(flagged)
    fig, axes = plt.subplots(n, 1, figsize=(9, 2.4 * n + 0.4), squeeze=False)
    for ax, (name, channel, reason) in zip(axes[:, 0], flagged, strict=True):
        attr, label = CHANNELS[channel]
        for t in tests:
            x = getattr(t, attr)
            if x is not None and t.name != name:
                ax.plot(t.time_s * 1000, x, color="0.75", lw=0.8)
        bad = next(t for t in tests if t.name == name)
        ax.plot(bad.time_s * 1000, getattr(bad, attr), "r-", lw=1.1, label=name)
        ax.set_title(f"{name} {channel}: {reason}", fontsize=8, wrap=True)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper right")
    axes[-1][0].set_xlabel("t [ms] (grey: the other tests)")
    return _save(fig, path)


def order_scan(path: Path, title: str, xlabel: str, rows: list[dict], x_key: str) -> Path:
    """fit_TOT against model order (thesis Figures 3.6 and 3.7)."""
    fig, ax = plt.subplots(figsize=(6, 3.5))
    x = [r[x_key] for r in rows]
    for key, style, label in (("estimation_fit", "o-", "estimation tests"),
                              ("validation_fit", "s--", "validation tests")):
        if all(key in r for r in rows):
            ax.plot(x, [r[key] for r in rows], style, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("fit_TOT [%]")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend()
    return _save(fig, path)


#: the lowest gain evidence.png draws where it is [fit points]
EVIDENCE_FLOOR_POINTS = -20.0
#: (label, per-test gains [fit points], mean gain, its 95 % interval, passes the rule)
EvidenceRow = tuple[str, dict[str, float], float, tuple[float, float], bool]


def loop_evidence(path: Path, rounds: list[tuple[str, list[EvidenceRow]]],
                  setup_of: dict[str, str], margin_points: float) -> Path:
    """The loop's evidence, one panel per round: each candidate's paired cross-validated gain
    per estimation test [fit points] (dots, coloured by setup), their mean (diamond) and its
    95 % interval (bar), against zero and the rule's margin. A candidate that passes the rule
    is drawn in black, one that does not in grey: a tie is two black rows, and a "possible"
    one is a grey row whose bar reaches past zero or whose mean falls short of the margin.
    Gains below ``EVIDENCE_FLOOR_POINTS`` (a trial that ran away scores -1000 %) are drawn at
    the floor as a left-pointing triangle, so one such test does not squash the rest."""
    rounds = rounds or [("the loop ran no round", [])]
    setups = list(dict.fromkeys(setup_of.values()))
    colours = {s: plt.get_cmap("tab10")(i % 10) for i, s in enumerate(setups)}
    heights = [max(len(rows), 1) * 0.42 + 0.75 + 0.18 * title.count("\n")
               for title, rows in rounds] or [1.0]
    fig, axes = plt.subplots(len(heights), 1, figsize=(8.5, sum(heights) + 0.4),
                             gridspec_kw={"height_ratios": heights}, squeeze=False)
    floor = EVIDENCE_FLOOR_POINTS
    for ax, (title, rows) in zip(axes[:, 0], rounds, strict=True):
        # an interval is drawn up to the largest gain shown (a run-away's spans thousands)
        top = max([margin_points, *(g for r in rows for g in (r[2], *r[1].values()))]) + 2.0
        for y, (_label, per_test, mean, (lo, hi), passes) in enumerate(reversed(rows)):
            ink = "black" if passes else "0.6"
            for test, g in per_test.items():
                ax.plot(max(g, floor), y, "o" if g >= floor else "<", ms=4, alpha=0.8,
                        mec="none", color=colours.get(setup_of.get(test, ""), "0.4"))
            ax.plot([max(lo, floor), min(max(hi, floor), top)], [y, y], "-", color=ink, lw=2)
            ax.plot(max(mean, floor), y, "D" if mean >= floor else "<", color=ink, ms=6)
        ax.set_yticks(range(len(rows)), [r[0] for r in reversed(rows)], fontsize=8)
        for r, tick in zip(reversed(rows), ax.get_yticklabels(), strict=True):
            tick.set_color("black" if r[4] else "0.45")
        ax.axvline(0.0, color="0.3", lw=0.8)
        ax.axvline(margin_points, color="tab:red", ls="--", lw=0.9)
        ax.set_ylim(-0.7, max(len(rows), 1) - 0.3)
        ax.set_title(title, fontsize=9, loc="left")
        ax.grid(axis="x", alpha=0.3)
    axes[-1][0].set_xlabel("paired cross-validated gain per estimation test [fit points]; "
                           f"dashed: the margin ({margin_points:g})")
    handles = [plt.Line2D([], [], ls="", marker="o", color=c, label=s)
               for s, c in colours.items()]
    if handles:
        axes[0][0].legend(handles=handles, fontsize=7, loc="best", title="setup",
                          title_fontsize=7)
    return _save(fig, path)
