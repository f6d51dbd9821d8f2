"""Held-out set AL: not yet drawn. ``draw_al.py`` holds its rules (set AK's process and sizing
rule, rule 4 as set AE mended it, sets A-AK as the earlier sets,
``numpy.random.default_rng(47000)``, with one change: any case left no free pairing reuses one
an earlier set ran), written down before the first draw; the cases will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AL: list[Case] = []
