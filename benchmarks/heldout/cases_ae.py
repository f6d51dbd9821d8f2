"""Held-out set AE: not yet drawn. ``draw_ae.py`` holds its rules (set AD's process and sizing
rule, rule 4 mended, sets A-AD as the earlier sets, ``numpy.random.default_rng(40000)``),
written down before the first draw; the cases will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AE: list[Case] = []
