"""Plots that scale to a campaign: a figure draws at most ``MAX_PANELS`` tests, the worst."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from observer_node import plots
from observer_node.ident.metrics import fit_table


def _tests(n: int) -> tuple[list[str], np.ndarray, np.ndarray, np.ndarray]:
    """n tests whose simulation is worse the higher the test's number."""
    t = np.linspace(0, 0.14, 141)
    y = np.stack([np.column_stack([np.sin(40 * t), 30 * t]) for _ in range(n)])
    y_hat = y + np.arange(n)[:, None, None] * 0.01 * np.stack([np.cos(40 * t), t], axis=1)
    return [f"T{k:03d}" for k in range(n)], t, y, y_hat


def test_a_campaign_figure_draws_the_worst_tests_and_says_so(tmp_path: Path):
    import matplotlib.image

    names, t, y, y_hat = _tests(60)
    fits = fit_table(names, y, y_hat)
    shown, words = plots._shown([-fits.tests[n].cr for n in names])
    assert shown == list(range(60 - plots.MAX_PANELS, 60))  # the lowest fits, in order
    assert words == f" ({plots.MAX_PANELS} worst of 60 tests)"
    png = plots.measured_vs_simulated(tmp_path / "fit_cr.png", "validation", names, t, y,
                                      y_hat, fits, 0)
    tall = matplotlib.image.imread(png).shape[0]
    few = plots.measured_vs_simulated(tmp_path / "few.png", "validation", names[:24], t,
                                      y[:24], y_hat[:24], fit_table(names[:24], y[:24],
                                                                    y_hat[:24]), 0)
    assert tall == matplotlib.image.imread(few).shape[0]  # 24 panels, not 60
    res = plots.residuals(tmp_path / "residuals.png", names, t, y - y, y - y_hat)
    assert matplotlib.image.imread(res).shape[0] < 4000
    # a small set is drawn whole
    assert plots._shown([1.0, 3.0, 2.0]) == ([0, 1, 2], "")
