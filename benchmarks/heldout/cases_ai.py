"""Held-out set AI: not yet drawn. ``draw_ai.py`` holds its rules (set AH's process and sizing
rule, rule 4 as set AE mended it, sets A-AH as the earlier sets,
``numpy.random.default_rng(44000)``), written down before the first draw; the cases will follow
the draw."""

from __future__ import annotations

from .cases import Case

SET_AI: list[Case] = []
