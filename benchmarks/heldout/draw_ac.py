"""Set AC's designer's choices, drawn rather than picked: ``numpy.random.default_rng(38000)``
draws them by set W's process (``draw_w.drawn``, the order and pools its docstring gives:
each kind's form, rigs, counts and mix; the two-effect case; the late pulse's and late BRS's
delays; the transducer error's output, counts, mix and form; the broken test's channel,
counts, mix, test and form; the clean cases' mixes), the (estimation, validation) pairings of
every case of sets A-AB taken (the two-effect case's aside, below); then, each by the next
seed's generator (38001, 38002, ...), a case again where its first draw proved impossible
(``REDRAWN``). The sizes are not drawn: they are set by costs, by the rule below (see
``cases_ac.py``). Set AB's process and sizing rule, taken as they stand, with sets A-AB
(``sets.before("ac")``: the sets by name, sets AA and AB one set each) as the earlier sets.

The two-effect case may reuse a pairing an earlier set ran (``drawn(..., reuse_two=True)``,
set Z's rule, set AA's and set AB's, taken as it stands, written here before the first
draw): set W's rule that every rig of either effect is estimated twice or more leaves 12
pairings for a two-rig effect beside a one-rig effect and 24 for two one-rig effects, on each
of the six rig splits, and sets A-Y had run every one of them (``draw_z.py``'s docstring), so
none is free after A-AB either. So when no pairing is free for its rigs, the two-effect case's
pairing is drawn by the same generator, uniformly, among the pairings the rules allow that
sets A-AB ran; everything else about it (its kinds, forms, rigs, counts; every rig of either
effect estimated twice or more) is as before, and every other case still takes only a free
pairing.

SIZING, written down before the first draw (set AB's rule, set AA's, set Z's, set Y's, set
X's, with sets A-AB as the earlier sets):

1. A form with a size: its first size is the median of the sizes every case of sets A-AB gave
   that key (of their magnitudes for brs_swap, whose sign is only a direction; positive), to
   two significant figures (a median half-way rounded up, as sets Z, AA and AB did); if A-AB
   used that value for the key, the next value up in the second figure A-AB did not use. A
   size that is a whole number (bits, counts, a test offset: brs_swap, brs_wrap,
   brs_quadrature, cd_stuck_bit) is rounded to one and stepped by 1. A key no case of A-AB
   sized starts at its sibling's median on the other output (cd_clock: cr_clock's, 0.08).
2. Its cost is the thesis grey-box's validation fit (TOT) on the case's twin with every effect
   off less that on the case (``costs._fit`` on ``make_sets.make``'s folders). Band: 1.5-6
   points (a delay 1-6). Out of band, the next size aims at 3.5 points: the size times (3.5 /
   cost), clipped to 1/3-3 times (a cost at or below 0: times 3), for a form whose effect grows
   with its size; the size times (cost / 3.5), clipped the same, for one whose effect shrinks
   as its size grows (a filter's corner, a time constant, a range, a rate limit, a slip force);
   once two sizes bracket the band, log-linear between them; each to two significant figures,
   stepped off A-AB's values as in 1. At most four sizes; none in band, or a size that runs
   away (``test_set_ac_has_no_run_aways``'s limits, set AB's and set AA's; the spool's radius
   below zero within 7 rad of pay-out), makes the draw impossible.
3. A switch (size 1 = on) and a delay (its size is its draw) have nothing to set: out of band,
   the draw is impossible.
4. The two-effect case: each effect alone (the other's size 0, the same seed) and the two
   together in band; each effect's size by 1-2 alone. When each alone is in band but the two
   together are not, the effect whose cost alone lies toward the side the case left is stepped
   by 2 toward 3.5 (as sets Z, AA and AB did); the other keeps its size.
5. The broken test's size by 1 only, its cost written down, not banded (its verdict is a flag).
6. An impossible draw is drawn again, the whole case, by the next seed of the family (38001,
   38002, ...) in the order found, after the rest, the pairings of everything drawn before
   still taken (``REDRAWN``; the two-effect case, with none free, an earlier set's, above).

    python -m benchmarks.heldout.draw_ac [--seed 38000]
"""

from __future__ import annotations

import sys

from .draw_v import BRS_GAIN, KINDS, forms, scopes
from .draw_w import BROKEN, TRANSDUCER, cli, drawn
from .sets import before

SEED = 38000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# the input gain's first draw, spool_buildup on SLED (64 counts, est 0/4/2, val 4/2/0), cost the
# grey-box 0.62 points at the rule's first size, 13 mm per wrap (CR 0.45, CD 0.79), below the
# band; the rule's next, 39 mm (three times), leaves the spool's 17 mm radius below zero within
# 7 rad of pay-out (a run-away): impossible; the pelvis coupling's first draw, pelvis_submarine on
# R16 (64 counts, est 4/0/2, val 4/1/1), cost 8.83 at 5900 N, then by the rule's steps (a slip
# force: its effect taken to shrink as it grows) 12.82 at 15000 N, 13.32 at 45000 N and 13.40 at
# 135000 N: four sizes, none in band, impossible; every other draw found a size in band within
# the rule's four (see ``cases_ac.py``)
REDRAWN: tuple[tuple[str, int], ...] = (("input_gain", 38001), ("pelvis_coupling", 38002))
EARLIER = before("ac")
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "forms",
           "scopes"]


def draw(seed: int = SEED) -> dict:
    """Set AC's choices: set W's process (:func:`~.draw_w.drawn`) by ``seed``, after sets
    A-AB, its redraws at its own seed; the two-effect case, with no pairing free, reuses one of
    A-AB's (``reuse_two``)."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else (), reuse_two=True)


def main(argv: list[str] | None = None) -> int:
    return cli("draw_ac", __doc__ or "", draw, SEED, argv)


if __name__ == "__main__":
    sys.exit(main())
