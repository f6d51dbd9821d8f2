"""Set AD's designer's choices, drawn rather than picked: ``numpy.random.default_rng(39000)``
draws them by set W's process (``draw_w.drawn``, the order and pools its docstring gives:
each kind's form, rigs, counts and mix; the two-effect case; the late pulse's and late BRS's
delays; the transducer error's output, counts, mix and form; the broken test's channel,
counts, mix, test and form; the clean cases' mixes), the (estimation, validation) pairings of
every case of sets A-AC taken (the two-effect case's aside, below); then, each by the next
seed's generator (39001, 39002, ...), a case again where its first draw proved impossible
(``REDRAWN``). The sizes are not drawn: they are set by costs, by the rule below (see
``cases_ad.py``). Set AC's process and sizing rule, taken as they stand, with sets A-AC
(``sets.before("ad")``: the sets by name, sets AA, AB and AC one set each) as the earlier
sets.

The two-effect case may reuse a pairing an earlier set ran (``drawn(..., reuse_two=True)``,
set Z's rule, set AA's, set AB's and set AC's, taken as it stands, written here before the
first draw): set W's rule that every rig of either effect is estimated twice or more leaves 12
pairings for a two-rig effect beside a one-rig effect and 24 for two one-rig effects, on each
of the six rig splits, and sets A-Y had run every one of them (``draw_z.py``'s docstring), so
none is free after A-AC either. So when no pairing is free for its rigs, the two-effect case's
pairing is drawn by the same generator, uniformly, among the pairings the rules allow that
sets A-AC ran; everything else about it (its kinds, forms, rigs, counts; every rig of either
effect estimated twice or more) is as before, and every other case still takes only a free
pairing.

SIZING, written down before the first draw (set AC's rule, set AB's, set AA's, set Z's, set
Y's, set X's, with sets A-AC as the earlier sets):

1. A form with a size: its first size is the median of the sizes every case of sets A-AC gave
   that key (of their magnitudes for brs_swap, whose sign is only a direction; positive), to
   two significant figures (a median half-way rounded up, as sets Z, AA, AB and AC did); if
   A-AC used that value for the key, the next value up in the second figure A-AC did not use.
   A size that is a whole number (bits, counts, a test offset: brs_swap, brs_wrap,
   brs_quadrature, cd_stuck_bit) is rounded to one and stepped by 1. A key no case of A-AC
   sized starts at its sibling's median on the other output (as set AC's cd_clock started at
   cr_clock's, 0.08).
2. Its cost is the thesis grey-box's validation fit (TOT) on the case's twin with every effect
   off less that on the case (``costs._fit`` on ``make_sets.make``'s folders). Band: 1.5-6
   points (a delay 1-6). Out of band, the next size aims at 3.5 points: the size times (3.5 /
   cost), clipped to 1/3-3 times (a cost at or below 0: times 3), for a form whose effect grows
   with its size; the size times (cost / 3.5), clipped the same, for one whose effect shrinks
   as its size grows (a filter's corner, a time constant, a range, a rate limit, a slip force);
   once two sizes bracket the band, log-linear between them; each to two significant figures,
   stepped off A-AC's values as in 1. At most four sizes; none in band, or a size that runs
   away (``test_set_ad_has_no_run_aways``'s limits, set AC's, set AB's and set AA's; the
   spool's radius below zero within 7 rad of pay-out), makes the draw impossible.
3. A switch (size 1 = on) and a delay (its size is its draw) have nothing to set: out of band,
   the draw is impossible.
4. The two-effect case: each effect alone (the other's size 0, the same seed) and the two
   together in band; each effect's size by 1-2 alone. When each alone is in band but the two
   together are not, the effect whose cost alone lies toward the side the case left is stepped
   by 2 toward 3.5 (as sets Z, AA, AB and AC did); the other keeps its size.
5. The broken test's size by 1 only, its cost written down, not banded (its verdict is a flag).
6. An impossible draw is drawn again, the whole case, by the next seed of the family (39001,
   39002, ...) in the order found, after the rest, the pairings of everything drawn before
   still taken (``REDRAWN``; the two-effect case, with none free, an earlier set's, above).

    python -m benchmarks.heldout.draw_ad [--seed 39000]
"""

from __future__ import annotations

import sys

from .draw_v import BRS_GAIN, KINDS, forms, scopes
from .draw_w import BROKEN, TRANSDUCER, cli, drawn
from .sets import before

SEED = 39000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# the belt unloading's first draw, dring_capstan on SLED (96 counts, est 3/3/0, val 1/5/0), cost
# the grey-box 3.24 points at the rule's first size, mu theta 0.59 (CR 3.83, CD 2.65), in band,
# but ran away by test_set_ad_has_no_run_aways's limits: the capstan held the webbing, five of
# its eight SLED tests paid out less than a third of the set's SLED median (30-68 deg against
# 205): impossible; the input gain's first draw, spool_buildup on R16+FULL (96 counts, est
# 4/2/0, val 5/0/1), cost 0.53 at 13 mm per wrap (CR 1.10, CD -0.05), below the band; the
# rule's next, 39 mm (three times, the clip), leaves the spool's 17 mm radius below zero within
# 7 rad of pay-out (a run-away): impossible; the late BRS's first draw, 1.03 ms (48 counts, est
# 2/0/4, val 2/3/1), cost -0.24 (CR -0.33, CD -0.14), below the delay's 1 point, nothing to set:
# impossible; the two-effect case's first draw, webbing_knee on R16 beside rib_maxwell on FULL
# (96 counts, est 3/0/3, val 3/0/3, set O's pairing), cost 7.04 together at 2.4 and 0.76, each
# alone in band (the knee 3.13, the Maxwell branch 3.84); by rule 4 the Maxwell branch (its
# cost alone the higher) stepped by 2 toward 3.5: 0.69 (alone 3.25, together 6.54), 0.74 (3.65,
# 6.88), 0.71 (3.42, 6.68): four sizes, the two together never in band, impossible; every other
# draw found a size in band within the rule's four (see ``cases_ad.py``)
REDRAWN: tuple[tuple[str, int], ...] = (("belt_unloading", 39001), ("input_gain", 39002),
                                         ("brs_late", 39003), ("two", 39004))
EARLIER = before("ad")
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "forms",
           "scopes"]


def draw(seed: int = SEED) -> dict:
    """Set AD's choices: set W's process (:func:`~.draw_w.drawn`) by ``seed``, after sets
    A-AC, its redraws at its own seed; the two-effect case, with no pairing free, reuses one of
    A-AC's (``reuse_two``)."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else (), reuse_two=True)


def main(argv: list[str] | None = None) -> int:
    return cli("draw_ad", __doc__ or "", draw, SEED, argv)


if __name__ == "__main__":
    sys.exit(main())
