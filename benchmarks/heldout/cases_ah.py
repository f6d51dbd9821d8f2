"""Held-out set AH: not yet drawn. ``draw_ah.py`` holds its rules (set AG's process and sizing
rule, rule 4 as set AE mended it, sets A-AG as the earlier sets,
``numpy.random.default_rng(43000)``), written down before the first draw; the cases will follow
the draw."""

from __future__ import annotations

from .cases import Case

SET_AH: list[Case] = []
