"""Held-out set AC: not yet drawn. ``draw_ac.py`` holds its rules (set AB's process and sizing
rule, sets A-AB as the earlier sets, ``numpy.random.default_rng(38000)``), written down before
the first draw; the cases will follow the draw."""

from __future__ import annotations

from .cases import Case

SET_AC: list[Case] = []
