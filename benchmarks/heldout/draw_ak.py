"""Set AK's designer's choices, drawn rather than picked: ``numpy.random.default_rng(46000)``
draws them by set W's process (``draw_w.drawn``, the order and pools its docstring gives:
each kind's form, rigs, counts and mix; the two-effect case; the late pulse's and late BRS's
delays; the transducer error's output, counts, mix and form; the broken test's channel,
counts, mix, test and form; the clean cases' mixes), the (estimation, validation) pairings of
every case of sets A-AJ taken (the two-effect case's aside, below); then, each by the next
seed's generator (46001, 46002, ...), a case again where its first draw proved impossible
(``REDRAWN``). The sizes are not drawn: they are set by costs, by the rule below (see
``cases_ak.py``). Set AJ's process and sizing rule (set AI's, set AH's, set AG's, set AF's,
set AE's, rule 4 as set AE mended it), taken exactly as they stand, with sets A-AJ
(``sets.before("ak")``: the sets by name, sets AA, AB, AC, AD, AE, AF, AG, AH, AI and AJ one
set each) as the earlier sets.

The two-effect case may reuse a pairing an earlier set ran (``drawn(..., reuse_two=True)``,
set Z's rule, set AA's, set AB's, set AC's, set AD's, set AE's, set AF's, set AG's, set AH's,
set AI's and set AJ's, taken as it stands, written here before the first draw): set W's rule
that every rig of either effect is estimated twice or more leaves 12 pairings for a two-rig
effect beside a one-rig effect and 24 for two one-rig effects, on each of the six rig splits,
and sets A-Y had run every one of them (``draw_z.py``'s docstring), so none is free after A-AJ
either. So when no pairing is free for its rigs, the two-effect case's pairing is drawn by the
same generator, uniformly, among the pairings the rules allow that sets A-AJ ran; everything
else about it (its kinds, forms, rigs, counts; every rig of either effect estimated twice or
more) is as before, and every other case still takes only a free pairing.

SIZING, written down before the first draw (set AJ's rule, set AI's, set AH's, set AG's, set
AF's, set AE's, its rule 4 as mended there, taken as it stands; set AD's, set AC's, set AB's,
set AA's, set Z's, set Y's, set X's before it), with sets A-AJ as the earlier sets:

1. A form with a size: its first size is the median of the sizes every case of sets A-AJ gave
   that key (of their magnitudes for brs_swap, whose sign is only a direction; positive), to
   two significant figures (a median half-way rounded up, as sets Z, AA, AB, AC, AD, AE, AF,
   AG, AH, AI and AJ did); if A-AJ used that value for the key, the next value up in the
   second figure A-AJ did not use. A size that is a whole number (bits, counts, a test offset:
   brs_swap, brs_wrap, brs_quadrature, cd_stuck_bit) is rounded to one and stepped by 1. A key
   no case of A-AJ sized starts at its sibling's median on the other output (as set AC's
   cd_clock started at cr_clock's, 0.08).
2. Its cost is the thesis grey-box's validation fit (TOT) on the case's twin with every effect
   off less that on the case (``costs._fit`` on ``make_sets.make``'s folders). Band: 1.5-6
   points (a delay 1-6). Out of band, the next size aims at 3.5 points: the size times (3.5 /
   cost), clipped to 1/3-3 times (a cost at or below 0: times 3), for a form whose effect grows
   with its size; the size times (cost / 3.5), clipped the same, for one whose effect shrinks
   as its size grows (a filter's corner, a time constant, a range, a rate limit, a slip force);
   once two sizes bracket the band, log-linear between them; each to two significant figures,
   stepped off A-AJ's values as in 1. At most four sizes; none in band, or a size that runs
   away (``test_set_ak_has_no_run_aways``'s limits, set AJ's, set AI's, set AH's, set AG's, set
   AF's, set AE's, set AD's, set AC's, set AB's and set AA's; the spool's radius below zero
   within 7 rad of pay-out), makes the draw impossible. As set AG judged by these words: a size
   that runs away makes the draw impossible whatever its cost; a slip force is stepped as a
   form whose effect shrinks as its size grows; a run-away's pay-out is judged against its
   rig's median over the set's other tests. As set AI judged by these words (written down by
   set AJ, as set AH wrote AG's): a draw whose next size by this rule runs away by the spool's
   radius is impossible without costing that size; "the order found" (6) is the order in which
   the impossibilities became known. As set AJ judged by these words (written here, as set AJ
   wrote AI's, before the first draw; nothing new): the limits are strict, so a pay-out at
   exactly a third of its rig's median (or at three times it) is a run-away.
3. A switch (size 1 = on) and a delay (its size is its draw) have nothing to set: out of band,
   the draw is impossible.
4. The two-effect case (as set AE mended it): each effect alone (the other's size 0, the same
   seed) and the two together in band; each effect's size by 1-2 alone. When each alone is in
   band but the two together are not, the effect whose cost alone lies toward the side the
   case left (the higher alone when the two together are above the band, the lower when
   below) is stepped; the other keeps its size. Each step moves its size the way that brings
   the two together toward the band, aiming the two together at the band's middle, 3.75
   points: its size times (3.75 / together), clipped to 1/3-3 times (together at or below 0:
   times 3), for a form whose effect grows with its size (smaller when the two together are
   above the band, larger when below); its size times (together / 3.75), clipped the same, for
   one whose effect shrinks as its size grows (rule 2's; and a lock deflection, as set Z took
   rib_lock's: larger when the two together are above the band, smaller when below); once two
   of its sizes bracket the band by the two together's cost (one above it, one below), its log
   size linear in the two together's cost between them, aiming at 3.75; each to two
   significant figures, stepped off A-AJ's values as in 1. Each of its sizes is costed
   together and alone (the other's size 0); the first at which each alone and the two together
   are in band is kept (one that brings the two together into band with the stepped effect
   alone out of it ends the steps). At most four sizes of the stepped effect (its first
   counted); none with all three in band, or a size that runs away (rule 2's limits), makes the
   draw impossible.
5. The broken test's size by 1 only, its cost written down, not banded (its verdict is a flag).
6. An impossible draw is drawn again, the whole case, by the next seed of the family (46001,
   46002, ...) in the order found, after the rest, the pairings of everything drawn before
   still taken (``REDRAWN``; the two-effect case, with none free, an earlier set's, above).

    python -m benchmarks.heldout.draw_ak [--seed 46000]
"""

from __future__ import annotations

import sys

from .draw_v import BRS_GAIN, KINDS, forms, scopes
from .draw_w import BROKEN, TRANSDUCER, cli, drawn
from .sets import before

SEED = 46000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# found at the draw, before any size or cost: a one-effect case takes only a free pairing, and
# chest_rate_damping's first draw (rib_maxwell on FULL), airbag_contact's (airbag_sealed on
# FULL) and input_gain's (brs_eccentric on R16+SLED) had none left (``drawn`` gives them none),
# impossible as drawn, as set W's and set Y's two-effect draws without a pairing were; 46002's
# bag (airbag_relief on SLED+FULL) and 46004-46009's (each on FULL) none either; every draw
# then found a size in band within the rule's four, none running away (see ``cases_ak.py``)
REDRAWN: tuple[tuple[str, int], ...] = (
    ("chest_rate_damping", 46001), ("airbag_contact", 46002), ("input_gain", 46003),
    *(("airbag_contact", s) for s in range(46004, 46011)))
EARLIER = before("ak")
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "forms",
           "scopes"]


def draw(seed: int = SEED) -> dict:
    """Set AK's choices: set W's process (:func:`~.draw_w.drawn`) by ``seed``, after sets
    A-AJ, its redraws at its own seed; the two-effect case, with no pairing free, reuses one of
    A-AJ's (``reuse_two``)."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else (), reuse_two=True)


def main(argv: list[str] | None = None) -> int:
    return cli("draw_ak", __doc__ or "", draw, SEED, argv)


if __name__ == "__main__":
    sys.exit(main())
