"""Held-out set AK: not yet drawn. ``draw_ak.py`` holds its rules (set AJ's process and sizing
rule, rule 4 as set AE mended it, sets A-AJ as the earlier sets,
``numpy.random.default_rng(46000)``), written down before the first draw; the cases will follow
the draw."""

from __future__ import annotations

from .cases import Case

SET_AK: list[Case] = []
