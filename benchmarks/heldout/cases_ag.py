"""Held-out set AG: not yet drawn. ``draw_ag.py`` holds its rules (set AF's process and sizing
rule, rule 4 as set AE mended it, sets A-AF as the earlier sets,
``numpy.random.default_rng(42000)``), written down before the first draw; the cases will follow
the draw."""

from __future__ import annotations

from .cases import Case

SET_AG: list[Case] = []
