"""Held-out set AV: not yet drawn. ``draw_av.py`` holds its rules (set AU's process and sizing
rule taken as they stand, set AL's reuse among them: any case left no free pairing reuses one
an earlier set ran; rule 4 as set AE mended it, sets A-AU as the earlier sets,
``numpy.random.default_rng(57000)``; no change), written down before the first draw; the cases
will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AV: list[Case] = []
