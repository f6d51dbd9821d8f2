"""Held-out set AD: not yet drawn. ``draw_ad.py`` holds its rules (set AC's process and sizing
rule, sets A-AC as the earlier sets, ``numpy.random.default_rng(39000)``), written down before
the first draw; the cases will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AD: list[Case] = []
