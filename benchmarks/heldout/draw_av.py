"""Set AV's designer's choices, drawn rather than picked: ``numpy.random.default_rng(57000)`` draws
them by set W's process (``draw_w.drawn``, the order and pools its docstring gives: each kind's
form, rigs, counts and mix; the two-effect case; the late pulse's and late BRS's delays; the
transducer error's output, counts, mix and form; the broken test's channel, counts, mix, test and
form; the clean cases' mixes), the (estimation, validation) pairings of every case of sets A-AU
taken (any case left none free aside, below); then, each by the next seed's generator (57001, 57002,
...), a case again where its first draw proved impossible (``REDRAWN``). The sizes are not drawn:
they are set by costs, by the rule below (see ``cases_av.py``). Set AU's process and sizing rule
(set AT's, set AS's, set AR's, set AQ's, set AP's, set AO's, set AN's, set AM's, set AL's, set AK's,
set AJ's, set AI's, set AH's, set AG's, set AF's, set AE's, rule 4 as set AE mended it, with set
AL's change: any case left no free pairing reuses an earlier set's), taken exactly as they stand,
with sets A-AU (``sets.before("av")``: the sets by name, sets AA, AB, AC, AD, AE, AF, AG, AH, AI,
AJ, AK, AL, AM, AN, AO, AP, AQ, AR, AS, AT and AU one set each) as the earlier sets. NO change: set
AV changes none of set AU's rules.

The reuse (set AL's change, part of the rules since set AM, taken as it stands, written here before
the first draw): ANY case, not only the two-effect case, for which no pairing is free for its rigs
reuses a pairing an earlier set ran (``drawn(..., reuse_all=True)``: set Z's rule for the two-effect
case extended to every case by set AL). So for every case (each kind's one-effect case, the
two-effect case, the late pulse, the late BRS, the transducer error, the broken test, the two clean
cases), when no pairing is free for its rigs, its pairing is drawn by the same generator, uniformly,
among the pairings the rules allow that sets A-AU ran; every case still takes a free pairing when
one exists (free: run by no case of A-AU nor by an earlier draw of this set). Everything else
(kinds, forms, rigs, counts, the late pulse's and late BRS's delays, the transducer error, the
broken test, the clean cases, the sizing-by-cost rule and its band, a redraw on an impossibility) is
as set AU had it.

Read by these words (set AL's reading, set AM's, set AN's, set AO's, set AP's, set AQ's, set AR's,
set AS's, set AT's, set AU's, taken as it stands): the pool a case reuses from is the pairings sets
A-AU ran that its rules allow, as set Z's rule has it (``ran``: the earlier sets' alone), not
narrowed by this set's own draws, so two cases of AV may run the same earlier pairing; a pairing a
case of AV drew free is taken (no later case draws it free) but is not in that pool. A case whose
pairing is reused carries ``"reused": True`` in the draw (``False`` when a free one was drawn). With
a pairing always left to draw, no draw is impossible for want of one: a draw is impossible only by
the sizing rule (2, 3, 4 below), and is then drawn again by rule 6, its pairing by this same rule.

SIZING, written down before the first draw (set AU's rule, set AT's, set AS's, set AR's, set AQ's,
set AP's, set AO's, set AN's, set AM's, set AL's, set AK's, set AJ's, set AI's, set AH's, set AG's,
set AF's, set AE's, its rule 4 as mended there, taken as it stands; set AD's, set AC's, set AB's,
set AA's, set Z's, set Y's, set X's before it), with sets A-AU as the earlier sets:

1. A form with a size: its first size is the median of the sizes every case of sets A-AU gave that
   key (of their magnitudes for brs_swap, whose sign is only a direction; positive), to two
   significant figures (a median half-way rounded up, as sets Z, AA, AB, AC, AD, AE, AF, AG, AH, AI,
   AJ, AK, AL, AM, AN, AO, AP, AQ, AR, AS, AT and AU did); if A-AU used that value for the key, the
   next value up in the second figure A-AU did not use. A size that is a whole number (bits, counts,
   a test offset: brs_swap, brs_wrap, brs_quadrature, cd_stuck_bit) is rounded to one and stepped by
   1. A key no case of A-AU sized starts at its sibling's median on the other output (as set AC's
   cd_clock started at cr_clock's, 0.08).
2. Its cost is the thesis grey-box's validation fit (TOT) on the case's twin with every effect off
   less that on the case (``costs._fit`` on ``make_sets.make``'s folders). Band: 1.5-6 points (a
   delay 1-6). Out of band, the next size aims at 3.5 points: the size times (3.5 / cost), clipped
   to 1/3-3 times (a cost at or below 0: times 3), for a form whose effect grows with its size; the
   size times (cost / 3.5), clipped the same, for one whose effect shrinks as its size grows (a
   filter's corner, a time constant, a range, a rate limit, a slip force); once two sizes bracket
   the band, log-linear between them; each to two significant figures, stepped off A-AU's values as
   in 1. At most four sizes; none in band, or a size that runs away
   (``test_set_av_has_no_run_aways``'s limits, set AU's, set AT's, set AS's, set AR's, set AQ's, set
   AP's, set AO's, set AN's, set AM's, set AL's, set AK's, set AJ's, set AI's, set AH's, set AG's,
   set AF's, set AE's, set AD's, set AC's, set AB's and set AA's; the spool's radius below zero
   within 7 rad of pay-out), makes the draw impossible. As set AG judged by these words: a size that
   runs away makes the draw impossible whatever its cost; a slip force is stepped as a form whose
   effect shrinks as its size grows; a run-away's pay-out is judged against its rig's median over
   the set's other tests. As set AI judged by these words (written down by set AJ, as set AH wrote
   AG's): a draw whose next size by this rule runs away by the spool's radius is impossible without
   costing that size; "the order found" (6) is the order in which the impossibilities became known.
   As set AJ judged by these words (written down by set AK): the limits are strict, so a pay-out at
   exactly a third of its rig's median (or at three times it) is a run-away. As set AK judged by
   these words (written down by set AL): the band's edges are in it (a cost of 1.5 is in band);
   every size costed, kept or not, is checked against the run-away limits (a size that runs away
   makes the draw impossible whatever its cost); each case is sized on its own (the two-effect
   case's sizes are not its single's steps). As set AL judged by these words (written down by set
   AM, as set AK wrote AJ's): a redraw's pairing is drawn after the rest with every pairing drawn
   before taken, the rejected draw's among them, and, none being free for its rigs, reused by the
   reuse above; the run-away check of every costed size is against its rig's median over the set's
   other cases' tests at the first sizes (a rejected draw's tests left out for its redraw's); a
   redrawn case and the two-effect case sharing a key each start at that key's first size, each case
   sized on its own. As set AM judged by these words (written down by set AN, as set AL wrote AK's):
   a first size that runs away makes the draw impossible (costed for the record); a slip force is
   stepped as a form whose effect shrinks as its size grows, though its cost grew; two draws of the
   set may run the same earlier pairing (the pool A-AU's, not narrowed by this set's draws); a
   rejected delay is drawn again as a rejected one-effect draw is. As set AN judged by these words
   (written down by set AO, as set AM wrote AL's): in the two-effect case, a stepped effect's size
   that brings the two together into band with the stepped effect alone out of it ends the steps,
   and the draw is impossible (rule 4's words); a rejected two-effect case is drawn again, whole, as
   a rejected one-effect draw is (rule 6), its pairing drawn after the rest by the reuse above; the
   two-effect case and a one-effect case sharing a key each start at that key's first size and are
   sized on their own. As set AO judged by these words (written down by set AP, as set AN wrote
   AM's): "the order found" (6) is the order in which the impossibilities became known in the sizing
   as it ran: a run-away found by the test at the first sizes, before any cost; then the first sizes
   costed one at a time in ``cases_av.py``'s order (``costs --set av``'s), each impossibility known
   at the cost that made it so (a spool whose next size by this rule runs away by its radius known
   at the cost before that size, without costing it, as set AI judged); the redraws after the rest
   at their first sizes, then the steps. A rejected redraw is drawn again by the next seed, as set
   AM's belt unloading was. In the two-effect case the effect stepped by rule 4 is chosen once, when
   each alone is first in band and the two together are not (rule 4's: the higher alone when the two
   together are above the band, the lower when below), and stays the stepped effect through its
   steps even once its cost alone crosses the other's, as set AF's and set AI's toes were stepped;
   the size it had then is the first of its four. A cost just past an edge is out of band (6.02
   above 6; no rounding to the band). A transducer error whose size is a delay (cr_late) is banded
   as a transducer error, 1.5-6, not as one of the drawn delays. The run-away check of a redraw's
   sizes is against the set at the first sizes with each rejected draw's tests replaced by its
   redraw's. As set AP judged by these words (written down by set AQ, as set AO wrote AN's):
   run-aways found at the first sizes, before any cost, are found in ``cases_av.py``'s order, the
   order ``test_set_av_has_no_run_aways`` walks the cases (the test stops at its first; the same
   limits over the whole set give the rest), and are drawn again in that order; a run-away so found
   holds whether an earlier rejected draw's tests are in the set's other cases' tests or replaced by
   its redraw's. The redraws, after the rest, are checked against the run-away limits at their first
   sizes in the same order, each against the set at the first sizes with every rejected draw's tests
   replaced by its current redraw's, before any of them is costed; a redraw that runs away there is
   drawn again by the next seed (as set AM's belt unloading was). Then the steps, each case's in
   ``cases_av.py``'s order. In the two-effect case, one effect alone out of the band at the first
   sizes with the other alone and the two together in it: the one out of band is stepped by 1-2
   alone (rule 2's aim, 3.5 points, as set AK judged), the other keeping its size, then the two
   together and each alone costed again. A step clipped to a third (or to three times) is rounded to
   two significant figures after the clip. As set AQ judged by these words (written down by set AR,
   as set AP wrote AO's): a draw whose first size is out of band, with its next size by rule 2
   (clipped to three times, rounded after the clip) a run-away by the spool's radius, is impossible
   without costing that size, the impossibility known at the cost before it (as set AI judged), and
   a redraw so found is drawn again by the next seed likewise; a cost just past an edge is out of
   band and stepped (as set AO judged); two cases of the set that run the same earlier pairing are
   not drawn again for it (the reuse's pool A-AU's, not narrowed by this set's draws: set AL's
   reading, set AM's judgement). The steps of the cases out of band at their first sizes, each
   case's in ``cases_av.py``'s order, may be costed between one redraw's first cost and the next's;
   none of them proving impossible, that order changes no seed. Each costed size is checked against
   the run-away limits, each pay-out against its rig's median over the set's other cases' tests at
   the first sizes with every rejected draw's tests replaced by its redraw's as it stood then; the
   sizes kept are checked again against the final set. As set AR judged by these words (written down
   by set AS, as set AR wrote AQ's): in the two-effect case, a stepped effect whose next size by
   rule 4, stepped off A-AU's values by rule 1's words (the next value up in the second figure A-AU
   did not use, up whichever way the step aimed), is the size it had, whose costs are known (the
   same case, the same seed), has no size left that can bring the two together into band: the draw
   is impossible without costing that size again, the impossibility known at that cost (as set AI
   judged of a spool whose next size runs away by its radius); a redraw that runs away at its first
   size is costed for the record (as set AM judged) and drawn again by the next seed; the redraws,
   after the rest, are costed at their first sizes in ``cases_av.py``'s order, each impossibility so
   known drawn again by the next seed in the order found, before the steps; in the two-effect case,
   each effect alone out of the band at the first sizes: each is stepped by 1-2 alone (rule 2's aim,
   3.5 points, as set AK judged), then the two together and each alone costed again. As set AS
   judged by these words (written down by set AT, as set AS wrote AR's): in the two-effect case, one
   effect alone out of the band at the first sizes with the other alone and the two together in it
   is set AP's case, not rule 4's (each alone in band and the two together out): the one out of band
   is stepped by 1-2 alone, the other keeping its size, and the other alone at each step is the same
   run as at the first sizes (its partner's size 0 either way, the same case, the same seed), its
   cost known, not costed again; each case is sized on its own and stepped off A-AU's values by rule
   1's words (the earlier sets'), not this set's, so two cases of the set that step to the same size
   are not stepped again for it. As set AT judged by these words (written down by set AU, as set AT
   wrote AS's): a two-effect case that runs away at its first sizes, found by the test before any
   cost, is costed for the record, the two together, and drawn again by the next seed in the order
   found, as a one-effect case is; in the two-effect case, an effect that is a switch (rule 3:
   nothing to set) whose cost alone is out of the band makes the draw impossible, known at that
   cost, whatever the other alone and the two together cost (the two together costed for the record;
   the other alone need not be costed: the switch alone decides the draw); a redraw out of the band
   at its first size with a size to step to is not impossible there, but stepped with the steps,
   each case's in ``cases_av.py``'s order; in the two-effect case, one effect alone out of the band
   at the first sizes with the other alone in it and the two together out of it is stepped as set AR
   judged (the one out of band by 1-2 alone, the other keeping its size, its cost alone known from
   the first sizes, not costed again), then the two together and the stepped effect alone costed
   again; a step whose value A-AU used goes to the next value up in the second figure A-AU did not
   use, whichever way the step aimed (rule 1's words, as set AR judged). As set AU judged by these
   words (written here, as set AU wrote AT's, before the first draw; nothing new): a step is worked
   from the costs as written, to two decimals, and taken to two significant figures with a value
   half-way rounded up, as rule 1's median is (set AU's two-effect power: 1.3 x 3.5 / 6.84 = 0.665,
   0.67); a draw found impossible in the steps (four sizes, none in band) is known at its last
   size's cost, after the redraws' first costs, and is drawn again by the next seed after the
   impossibilities known before it (the order found); its redraw is checked against the run-away
   limits at its first size before it is costed, and one that runs away there is costed for the
   record (as set AM judged) and drawn again by the next seed.
3. A switch (size 1 = on) and a delay (its size is its draw) have nothing to set: out of band, the
   draw is impossible.
4. The two-effect case (as set AE mended it): each effect alone (the other's size 0, the same seed)
   and the two together in band; each effect's size by 1-2 alone. When each alone is in band but the
   two together are not, the effect whose cost alone lies toward the side the case left (the higher
   alone when the two together are above the band, the lower when below) is stepped; the other keeps
   its size. Each step moves its size the way that brings the two together toward the band, aiming
   the two together at the band's middle, 3.75 points: its size times (3.75 / together), clipped to
   1/3-3 times (together at or below 0: times 3), for a form whose effect grows with its size
   (smaller when the two together are above the band, larger when below); its size times (together /
   3.75), clipped the same, for one whose effect shrinks as its size grows (rule 2's; and a lock
   deflection, as set Z took rib_lock's: larger when the two together are above the band, smaller
   when below); once two of its sizes bracket the band by the two together's cost (one above it, one
   below), its log size linear in the two together's cost between them, aiming at 3.75; each to two
   significant figures, stepped off A-AU's values as in 1. Each of its sizes is costed together and
   alone (the other's size 0); the first at which each alone and the two together are in band is
   kept (one that brings the two together into band with the stepped effect alone out of it ends the
   steps). At most four sizes of the stepped effect (its first counted); none with all three in
   band, or a size that runs away (rule 2's limits), makes the draw impossible. As set AK judged by
   these words: the effect stepped by 1-2 alone is the one whose cost alone is out of band.
5. The broken test's size by 1 only, its cost written down, not banded (its verdict is a flag).
6. An impossible draw is drawn again, the whole case, by the next seed of the family (57001, 57002,
   ...) in the order found, after the rest, the pairings of everything drawn before still taken
   (``REDRAWN``; a case with none free, an earlier set's, by the reuse above).

Judged at the sizes by these words (written down with the sizes, after the draw, before any loop
run; no rule changed, the rules above as they were committed before the first draw): no run-away at
the first sizes before any cost (``test_set_av_has_no_run_aways``'s limits over the whole set). Then
the first sizes costed one at a time in ``cases_av.py``'s order, two impossibilities among them, in
that order: the two-effect case, the webbing slack on FULL beside the ribs' valve on R16 (2300), the
slack alone 13.50, a switch (rule 3) above the band, so impossible whatever the valve alone and the
two together cost (as set AT judged: the two together costed for the record, 16.18; the valve alone
not costed); the late BRS, 1.15 ms, 0.21, below the delay's 1 point (rule 3): drawn again by 57001
and 57002. No other first size impossible: the encoder ring (0.53, 5.04), CR's progressive over-read
(0.13, 3.10) and the late pulse (2.23 ms, 1.77) in their bands; the ribs' bumper on R16 (3.0e7,
0.46) below the band, the ribs' fluid damping (2600, 9.03), the webbing's hysteresis (0.66, 7.12),
the webbing's power (0.91, 6.03, a cost just past an edge, out of band as set AO judged), the vented
bag (0.63, 8.89) and the knee bolster path (0.17, 6.95) above it, each with a next size to step to;
the broken test's CR rail at 20 g, -0.97, not banded. The redraws, after the rest, checked against
the run-away limits at their first sizes in ``cases_av.py``'s order, each against the set at the
first sizes with every rejected draw's tests replaced by its redraw's, before any of them was costed
(none ran away); then costed in that order: 57001's two-effect case, the fabric bag on SLED (0.84)
beside the webbing's toe on R16+FULL (0.26), the two together 2.36, the bag alone 2.51, the toe
alone 4.58, all three in band at the first sizes; 57002's late BRS, 1.64 ms, 0.13, below the delay's
1 point: drawn again by 57003; 57003's late BRS, 4.36 ms, checked against the run-away limits before
it was costed (none ran away), 4.56, in band. Then the steps, each case's in ``cases_av.py``'s
order: the ribs' bumper, 3.0e7 x 3.5 / 0.46 = 2.3e8, clipped to three times, 9.0e7 (0.80); 9.0e7 x
3.5 / 0.80 = 3.9e8, clipped, 2.7e8 (0.96); 2.7e8 x 3.5 / 0.96 = 9.8e8, clipped, 8.1e8 (1.04): four
sizes, none in band, none a run-away: impossible (rule 2), known at the fourth size's cost, after
the redraws' first costs (as set AU judged), drawn again by 57004; the ribs' fluid damping 1100
(2600 x 3.5 / 9.03 = 1008, 1000, which A-AU used), 4.10; the webbing's hysteresis 0.32 (0.324),
2.62; the webbing's power 0.53 (0.528), 4.45; the vented bag 0.26 (0.63 x 3.5 / 8.89 = 0.248, 0.25,
which A-AU used), 3.65; the knee bolster path 0.087 (0.17 x 3.5 / 6.95 = 0.0856, 0.086, which A-AU
used), 3.16: each in band at its first step. 57004's ribs' hardening on R16+SLED (1.7e8), checked
against the run-away limits before it was costed (none ran away), 9.65, above the band, stepped
once: 1.7e8 x 3.5 / 9.65 = 6.2e7 (not clipped), 4.92, in band. None clipped save the bumper's steps;
one cost just past an edge (the webbing's power, 6.03, stepped). Two pairs of cases of AV run the
same earlier pairing (the belt's stiffening and the pelvis, est 4/2/0, val 1/4/1; the vented bag and
57001's two-effect case, est 2/2/2, val 4/2/0: the reuse's pool A-AU's, not narrowed by this set's
draws), neither drawn again for it (as set AQ judged). Each costed size checked against the run-away
limits, each pay-out against its rig's median over the set's other cases' tests at the first sizes
with the rejected draws' tests replaced by their redraws' then (the sizes kept checked again against
the final set); none of the sizes kept or stepped ran away.

    python -m benchmarks.heldout.draw_av [--seed 57000]
"""

from __future__ import annotations

import sys

from .draw_v import BRS_GAIN, KINDS, forms, scopes
from .draw_w import BROKEN, TRANSDUCER, cli, drawn
from .sets import before

SEED = 57000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# none at the draw (every case, none free for its rigs, drew a pairing one of A-AU ran); at the
# sizes, four, in the order found: the two-effect case's first draw (webbing_slack on FULL
# beside rib_valve on R16), its switch alone 13.50, above the band; the late BRS's (1.15 ms)
# cost 0.21, below the delay's 1 point; its redraw (1.64 ms) cost 0.13; the chest's
# stiffening's first draw (rib_bumper on R16) below the band at all four of its sizes (0.46,
# 0.80, 0.96, 1.04); airbag_fabric on SLED beside webbing_toe on R16+FULL, the late BRS at
# 4.36 ms and rib_hardening on R16+SLED (its second size) came in band (see ``cases_av.py``)
REDRAWN: tuple[tuple[str, int], ...] = (("two", 57001), ("brs_late", 57002),
                                         ("brs_late", 57003), ("chest_stiffening", 57004))
EARLIER = before("av")
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "forms",
           "scopes"]


def draw(seed: int = SEED) -> dict:
    """Set AV's choices: set W's process (:func:`~.draw_w.drawn`) by ``seed``, after sets
    A-AU, its redraws at its own seed; any case with no pairing free reuses one of A-AU's
    (``reuse_all``, set AL's rule, taken as it stands)."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else (), reuse_all=True)


def main(argv: list[str] | None = None) -> int:
    return cli("draw_av", __doc__ or "", draw, SEED, argv)


if __name__ == "__main__":
    sys.exit(main())
