"""Set Y's designer's choices, drawn rather than picked: ``numpy.random.default_rng(34000)``
draws them by set W's process (``draw_w.drawn``, the order and pools its docstring gives:
each kind's form, rigs, counts and mix; the two-effect case; the late pulse's and late BRS's
delays; the transducer error's output, counts, mix and form; the broken test's channel,
counts, mix, test and form; the clean cases' mixes), the (estimation, validation) pairings of
every case of sets A-X taken; then, each by the next seed's generator (34001, 34002, ...), a
case again where its first draw proved impossible (``REDRAWN``). The sizes are not drawn: they
are set by costs, by the rule below (see ``cases_y.py``).

SIZING, written down before the first draw (set X's rule, with sets A-X as the earlier sets):

1. A form with a size: its first size is the median of the sizes every case of sets A-X gave
   that key (of their magnitudes for brs_swap, whose sign is only a direction; positive), to
   two significant figures; if A-X used that value for the key, the next value up in the
   second figure A-X did not use. A size that is a whole number (bits, counts, a test offset:
   brs_swap, brs_wrap, brs_quadrature, cd_stuck_bit) is rounded to one and stepped by 1. A key
   no case of A-X sized (cd_clock) starts at its sibling's median on the other output
   (cr_clock: 0.08).
2. Its cost is the thesis grey-box's validation fit (TOT) on the case's twin with every effect
   off less that on the case (``costs._fit`` on ``make_sets.make``'s folders). Band: 1.5-6
   points (a delay 1-6). Out of band, the next size aims at 3.5 points: the size times (3.5 /
   cost), clipped to 1/3-3 times (a cost at or below 0: times 3), for a form whose effect grows
   with its size; the size times (cost / 3.5), clipped the same, for one whose effect shrinks
   as its size grows (a filter's corner, a time constant, a range, a rate limit, a slip force);
   once two sizes bracket the band, log-linear between them; each to two significant figures,
   stepped off A-X's values as in 1. At most four sizes; none in band, or a size that runs
   away (``test_set_y_has_no_run_aways``'s limits; the spool's radius below zero within 7 rad
   of pay-out), makes the draw impossible.
3. A switch (size 1 = on) and a delay (its size is its draw) have nothing to set: out of band,
   the draw is impossible.
4. The two-effect case: each effect alone (the other's size 0, the same seed) and the two
   together in band; each effect's size by 1-2 alone.
5. The broken test's size by 1 only, its cost written down, not banded (its verdict is a flag).
6. An impossible draw is drawn again, the whole case, by the next seed of the family (34001,
   34002, ...) in the order found, after the rest, the pairings of everything drawn before
   still taken (``REDRAWN``).

    python -m benchmarks.heldout.draw_y [--seed 34000]
"""

from __future__ import annotations

import sys

from .draw_v import BRS_GAIN, KINDS, forms, scopes
from .draw_w import BROKEN, TRANSDUCER, cli, drawn
from .sets import before

SEED = 34000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# the two-effect case's first draw (rib_lock on R16 beside rib_foam on FULL) and the next
# thirteen (by 34001-34013) had no pairing left (sets A-X, and Y's draws before them, ran every
# pairing the rules allow for those rigs, each of either effect estimated twice or more);
# 34014's, webbing_knee on FULL beside airbag_fabric on SLED, is the case's. Each rejected
# draw is kept in ``draw()["rejected"]`` with the seed that drew it again (see ``cases_y.py``);
# belt_unloading's first draw, dring_capstan on FULL (128 counts), cost -0.65 points at the
# rule's first size (0.59), and at its second (1.8, three times) the car's webbing ran away (a
# channel past 1e6, overflow in the belt's force): impossible; 34015 drew webbing_set on FULL
REDRAWN: tuple[tuple[str, int], ...] = (*(("two", s) for s in range(34001, 34015)),
                                         ("belt_unloading", 34015))
EARLIER = before("y")
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "forms",
           "scopes"]


def draw(seed: int = SEED) -> dict:
    """Set Y's choices: set W's process (:func:`~.draw_w.drawn`) by ``seed``, after sets A-X,
    its redraws at its own seed."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else ())


def main(argv: list[str] | None = None) -> int:
    return cli("draw_y", __doc__ or "", draw, SEED, argv)


if __name__ == "__main__":
    sys.exit(main())
