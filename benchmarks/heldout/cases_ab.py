"""Held-out set AB: not yet drawn. ``draw_ab.py`` holds its rules (set AA's process and sizing
rule, sets A-AA as the earlier sets, ``numpy.random.default_rng(37000)``), written down before
the first draw; the cases will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AB: list[Case] = []
