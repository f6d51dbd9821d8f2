"""Held-out set AF: not yet drawn. ``draw_af.py`` holds its rules (set AE's process and sizing
rule, rule 4 as set AE mended it, sets A-AE as the earlier sets,
``numpy.random.default_rng(41000)``), written down before the first draw; the cases will follow
the draw."""

from __future__ import annotations

from .cases import Case

SET_AF: list[Case] = []
