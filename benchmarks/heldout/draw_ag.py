"""Set AG's designer's choices, drawn rather than picked: ``numpy.random.default_rng(42000)``
draws them by set W's process (``draw_w.drawn``, the order and pools its docstring gives:
each kind's form, rigs, counts and mix; the two-effect case; the late pulse's and late BRS's
delays; the transducer error's output, counts, mix and form; the broken test's channel,
counts, mix, test and form; the clean cases' mixes), the (estimation, validation) pairings of
every case of sets A-AF taken (the two-effect case's aside, below); then, each by the next
seed's generator (42001, 42002, ...), a case again where its first draw proved impossible
(``REDRAWN``). The sizes are not drawn: they are set by costs, by the rule below (see
``cases_ag.py``). Set AF's process and sizing rule (set AE's, rule 4 as set AE mended it),
taken exactly as they stand, with sets A-AF (``sets.before("ag")``: the sets by name, sets AA,
AB, AC, AD, AE and AF one set each) as the earlier sets.

The two-effect case may reuse a pairing an earlier set ran (``drawn(..., reuse_two=True)``,
set Z's rule, set AA's, set AB's, set AC's, set AD's, set AE's and set AF's, taken as it
stands, written here before the first draw): set W's rule that every rig of either effect is
estimated twice or more leaves 12 pairings for a two-rig effect beside a one-rig effect and 24
for two one-rig effects, on each of the six rig splits, and sets A-Y had run every one of them
(``draw_z.py``'s docstring), so none is free after A-AF either. So when no pairing is free for
its rigs, the two-effect case's pairing is drawn by the same generator, uniformly, among the
pairings the rules allow that sets A-AF ran; everything else about it (its kinds, forms, rigs,
counts; every rig of either effect estimated twice or more) is as before, and every other case
still takes only a free pairing.

SIZING, written down before the first draw (set AF's rule, set AE's, its rule 4 as mended
there, taken as it stands; set AD's, set AC's, set AB's, set AA's, set Z's, set Y's, set X's
before it), with sets A-AF as the earlier sets:

1. A form with a size: its first size is the median of the sizes every case of sets A-AF gave
   that key (of their magnitudes for brs_swap, whose sign is only a direction; positive), to
   two significant figures (a median half-way rounded up, as sets Z, AA, AB, AC, AD, AE and AF
   did); if A-AF used that value for the key, the next value up in the second figure A-AF did
   not use. A size that is a whole number (bits, counts, a test offset: brs_swap, brs_wrap,
   brs_quadrature, cd_stuck_bit) is rounded to one and stepped by 1. A key no case of A-AF
   sized starts at its sibling's median on the other output (as set AC's cd_clock started at
   cr_clock's, 0.08).
2. Its cost is the thesis grey-box's validation fit (TOT) on the case's twin with every effect
   off less that on the case (``costs._fit`` on ``make_sets.make``'s folders). Band: 1.5-6
   points (a delay 1-6). Out of band, the next size aims at 3.5 points: the size times (3.5 /
   cost), clipped to 1/3-3 times (a cost at or below 0: times 3), for a form whose effect grows
   with its size; the size times (cost / 3.5), clipped the same, for one whose effect shrinks
   as its size grows (a filter's corner, a time constant, a range, a rate limit, a slip force);
   once two sizes bracket the band, log-linear between them; each to two significant figures,
   stepped off A-AF's values as in 1. At most four sizes; none in band, or a size that runs
   away (``test_set_ag_has_no_run_aways``'s limits, set AF's, set AE's, set AD's, set AC's,
   set AB's and set AA's; the spool's radius below zero within 7 rad of pay-out), makes the
   draw impossible.
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
   significant figures, stepped off A-AF's values as in 1. Each of its sizes is costed
   together and alone (the other's size 0); the first at which each alone and the two together
   are in band is kept (one that brings the two together into band with the stepped effect
   alone out of it ends the steps). At most four sizes of the stepped effect (its first
   counted); none with all three in band, or a size that runs away (rule 2's limits), makes the
   draw impossible.
5. The broken test's size by 1 only, its cost written down, not banded (its verdict is a flag).
6. An impossible draw is drawn again, the whole case, by the next seed of the family (42001,
   42002, ...) in the order found, after the rest, the pairings of everything drawn before
   still taken (``REDRAWN``; the two-effect case, with none free, an earlier set's, above).

    python -m benchmarks.heldout.draw_ag [--seed 42000]
"""

from __future__ import annotations

import sys

from .draw_v import BRS_GAIN, KINDS, forms, scopes
from .draw_w import BROKEN, TRANSDUCER, cli, drawn
from .sets import before

SEED = 42000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# the belt unloading's first draw, dring_capstan on every rig at mu theta 0.59 (cost 0.53), ran
# away by test_set_ag_has_no_run_aways's limits (the capstan held the webbing); 42001's,
# dring_capstan on R16 at 0.59 (cost 0.07), ran away; 42002's, webbing_slack on R16 (a switch),
# cost 14.08, above the band; 42003's, dring_capstan on R16+SLED at 0.59 (cost 0.59), ran away;
# the two-effect case's first draw, pelvis_submarine on R16 beside rib_visco on SLED+FULL: the
# slip force (a form whose effect shrinks as its size grows, by the rule's words) alone at 6000,
# 17000, 51000, 150000 N cost 9.84, 14.60, 15.03, 15.08, none in band; 42004's belt unloading,
# webbing_slack on SLED+FULL, cost 12.72, above the band; 42006's, dring_capstan on SLED at
# 0.59 (cost 1.79), ran away; 42005's two-effect case, airbag_fabric on FULL beside
# spool_buildup on SLED: the spool alone 0.29 at 13 mm per wrap, its next (39 mm) leaving the
# spool's radius below zero within 7 rad of pay-out (a run-away); 42008's, spool_buildup on R16
# beside rib_squeeze on SLED+FULL: the spool alone 0.64, its next 39 mm, a run-away; 42009's,
# dring_capstan on FULL beside rib_lock on R16+SLED, the capstan at 0.59 ran away (FULL's
# pay-out held): each impossible; every other draw found a size in band within the rule's four
# (see ``cases_ag.py``)
REDRAWN: tuple[tuple[str, int], ...] = (("belt_unloading", 42001), ("belt_unloading", 42002),
                                       ("belt_unloading", 42003), ("belt_unloading", 42004),
                                       ("two", 42005), ("belt_unloading", 42006),
                                       ("belt_unloading", 42007), ("two", 42008), ("two", 42009),
                                       ("two", 42010))
EARLIER = before("ag")
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "forms",
           "scopes"]


def draw(seed: int = SEED) -> dict:
    """Set AG's choices: set W's process (:func:`~.draw_w.drawn`) by ``seed``, after sets
    A-AF, its redraws at its own seed; the two-effect case, with no pairing free, reuses one of
    A-AF's (``reuse_two``)."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else (), reuse_two=True)


def main(argv: list[str] | None = None) -> int:
    return cli("draw_ag", __doc__ or "", draw, SEED, argv)


if __name__ == "__main__":
    sys.exit(main())
