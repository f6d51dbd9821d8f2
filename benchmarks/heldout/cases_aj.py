"""Held-out set AJ: not yet drawn. ``draw_aj.py`` holds its rules (set AI's process and sizing
rule, rule 4 as set AE mended it, sets A-AI as the earlier sets,
``numpy.random.default_rng(45000)``), written down before the first draw; the cases will follow
the draw."""

from __future__ import annotations

from .cases import Case

SET_AJ: list[Case] = []
