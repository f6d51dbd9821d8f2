"""Held-out set AU: not yet drawn. ``draw_au.py`` holds its rules (set AT's process and sizing
rule taken as they stand, set AL's reuse among them: any case left no free pairing reuses one
an earlier set ran; rule 4 as set AE mended it, sets A-AT as the earlier sets,
``numpy.random.default_rng(56000)``; no change), written down before the first draw; the cases
will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AU: list[Case] = []
